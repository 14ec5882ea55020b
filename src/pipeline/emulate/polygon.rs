//! Polygon modes on a core context. GL 1.x rasterises each polygon by its own facing: the
//! front mode for front faces, the back mode for back faces (GL 1.5 §3.5.4), and a
//! polygon in LINE or POINT mode shows only its own boundary edges and vertices — the
//! edges a quad or polygon gains when split into triangles are not drawn (edge flags,
//! §2.6.2). Core GL 3.3 has one mode for both faces and no edge flags, so:
//!
//! - **Separate modes → two passes.** With front ≠ back and neither face culled, a draw runs
//!   twice: cull BACK with the front mode, then cull FRONT with the back mode. GL's own
//!   culling picks the faces, so facing follows FrontFace exactly. Deviation, documented:
//!   all front faces of the draw reach the framebuffer before its back faces, so only an
//!   order-dependent operation (blending, stencil ops, LEQUAL/EQUAL ties) between a front
//!   and a back face of the *same* draw that overlap can differ from GL's polygon order.
//! - **Split polygons keep their outline.** QUADS, QUAD_STRIP and POLYGON are uploaded as
//!   unshared triangle corners, each with an edge attribute e (vec4): for the edge opposite
//!   corner m, e[m] is 1 at corner m and 0 at the other two when that edge is a boundary
//!   edge, and 1 at all three corners when it is a split edge. A boundary edge rasterised
//!   as a line therefore interpolates e[m] between two zeros — exactly 0 — while a split
//!   edge has no component that stays 0, so LINE mode keeps a fragment iff some component
//!   of e.xyz is exactly 0 (not the minimum: past a line's ends the varying components
//!   extrapolate below 0).
//!   e.w is 1 on the one corner that owns each polygon vertex, so POINT mode keeps a point
//!   iff e.w ≠ 0 and a vertex shared by the two triangles of a quad is drawn once.
//!
//! - **One offset enable per pass.** Each pass rasterises in one mode, so only that mode's
//!   enable is sent (all three on or all off). This also keeps llvmpipe from offsetting
//!   filled polygons when only POLYGON_OFFSET_LINE or _POINT is on (Mesa 22.3 does, on
//!   core and compatibility contexts alike; pinned in tests/fidelity_polygon_mode.rs).
//!
//! The rule (`EdgeRule`) is a key predicate: it changes the code of the fragment shader.
//! Polygon offset for LINE and POINT, line width and point size stay GL state (core GL has
//! POLYGON_OFFSET_LINE/POINT, and a context that is not forward-compatible accepts wide
//! lines).

use crate::ff::{Face, OffsetEnables, PolygonMode, PolygonModes, Primitive};

/// Which rasterised fragments of split polygons are kept (`None` in the key: all).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EdgeRule {
    /// LINE mode: only fragments on boundary edges (some e.xyz component exactly 0).
    BoundaryEdges,
    /// POINT mode: only the corner that owns each polygon vertex (e.w ≠ 0).
    OwnedVertices,
}

/// One rasterisation pass of a draw: the core polygon mode and cull face to send, whether
/// polygon offset is on, and the edge rule the program needs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PolygonPass {
    pub mode: PolygonMode,
    pub cull: Option<Face>,
    /// The enable of this pass's mode (POLYGON_OFFSET_FILL for FILL, …); off for points
    /// and lines, which polygon offset never moves (§3.5.5).
    pub offset: bool,
    pub edges: Option<EdgeRule>,
}

/// True for the primitives GL rasterises as polygons.
fn is_polygonal(p: Primitive) -> bool {
    !matches!(
        p,
        Primitive::Points | Primitive::Lines | Primitive::LineStrip | Primitive::LineLoop
    )
}

/// True for the primitives the core path splits into more triangles than GL's polygons.
pub fn is_split(p: Primitive) -> bool {
    matches!(
        p,
        Primitive::Quads | Primitive::QuadStrip | Primitive::Polygon
    )
}

/// The passes that draw `primitive` under the GL 1.x `modes`, `cull` and offset state.
pub fn passes(
    modes: PolygonModes,
    cull: Option<Face>,
    enables: OffsetEnables,
    primitive: Primitive,
) -> Vec<PolygonPass> {
    let pass = |mode: PolygonMode, cull: Option<Face>| PolygonPass {
        mode,
        cull,
        offset: match mode {
            PolygonMode::Fill => enables.fill,
            PolygonMode::Line => enables.line,
            PolygonMode::Point => enables.point,
        },
        edges: match mode {
            _ if !is_split(primitive) => None,
            PolygonMode::Fill => None,
            PolygonMode::Line => Some(EdgeRule::BoundaryEdges),
            PolygonMode::Point => Some(EdgeRule::OwnedVertices),
        },
    };
    if !is_polygonal(primitive) {
        return vec![PolygonPass {
            mode: PolygonMode::Fill,
            cull,
            offset: false,
            edges: None,
        }];
    }
    match cull {
        // Only front faces survive: the back mode never applies, and the reverse.
        Some(Face::Back) => vec![pass(modes.front, cull)],
        Some(Face::Front) => vec![pass(modes.back, cull)],
        Some(Face::FrontAndBack) => vec![pass(modes.front, cull)],
        None if modes.front == modes.back => vec![pass(modes.front, None)],
        None => vec![
            pass(modes.front, Some(Face::Back)),
            pass(modes.back, Some(Face::Front)),
        ],
    }
}

/// The polygons of a split primitive, each as its vertex indices in polygon order
/// (QUAD_STRIP quad i is 2i, 2i+1, 2i+3, 2i+2: GL 1.5 §2.6.1).
fn polygons(primitive: Primitive, indices: &[u32]) -> Vec<Vec<u32>> {
    match primitive {
        Primitive::Quads => indices.chunks_exact(4).map(<[u32]>::to_vec).collect(),
        Primitive::QuadStrip => (0..indices.len().saturating_sub(2) / 2)
            .map(|i| [0, 1, 3, 2].iter().map(|k| indices[2 * i + k]).collect())
            .collect(),
        Primitive::Polygon if indices.len() >= 3 => vec![indices.to_vec()],
        _ => Vec::new(),
    }
}

/// The triangle corners of a split primitive — each polygon fanned from its first vertex,
/// as Mesa splits it ((p0, p1, p2), (p0, p2, p3), …) — as (vertex index, edge attribute).
/// `None` for primitives that are not split.
pub fn split_corners(primitive: Primitive, indices: &[u32]) -> Option<Vec<(u32, [f32; 4])>> {
    if !is_split(primitive) {
        return None;
    }
    let mut out = Vec::new();
    for poly in polygons(primitive, indices) {
        let n = poly.len();
        for i in 0..n - 2 {
            // Corners p0, p(i+1), p(i+2). Edge opposite corner 0 (p(i+1)–p(i+2)) is always
            // a boundary; opposite corner 1 (p(i+2)–p0) only in the last triangle;
            // opposite corner 2 (p0–p(i+1)) only in the first.
            let boundary = [true, i == n - 3, i == 0];
            for (c, &v) in [poly[0], poly[i + 1], poly[i + 2]].iter().enumerate() {
                let mut e = [0.0; 4];
                for m in 0..3 {
                    e[m] = if !boundary[m] || m == c { 1.0 } else { 0.0 };
                }
                // p0 is owned by the first triangle, p1 too; every later vertex by the
                // triangle it first appears in as corner 2.
                let owns = match c {
                    0 | 1 => i == 0,
                    _ => true,
                };
                e[3] = if owns { 1.0 } else { 0.0 };
                out.push((v, e));
            }
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const FILL_LINE: PolygonModes = PolygonModes {
        front: PolygonMode::Fill,
        back: PolygonMode::Line,
    };

    const OFFSETS: OffsetEnables = OffsetEnables {
        fill: false,
        line: true,
        point: false,
    };

    #[test]
    fn separate_modes_take_two_culled_passes() {
        let p = passes(FILL_LINE, None, OFFSETS, Primitive::Polygon);
        assert_eq!(p.len(), 2);
        assert_eq!(
            (p[0].mode, p[0].cull),
            (PolygonMode::Fill, Some(Face::Back))
        );
        assert_eq!(
            (p[1].mode, p[1].cull),
            (PolygonMode::Line, Some(Face::Front))
        );
        assert_eq!(p[1].edges, Some(EdgeRule::BoundaryEdges));
        // Only the LINE pass is offset; lines themselves never are.
        assert_eq!((p[0].offset, p[1].offset), (false, true));
        assert!(!passes(FILL_LINE, None, OFFSETS, Primitive::Lines)[0].offset);
        // Culling one face leaves one pass in the other face's mode.
        let back_culled = passes(FILL_LINE, Some(Face::Back), OFFSETS, Primitive::Quads);
        assert_eq!(back_culled.len(), 1);
        assert_eq!(back_culled[0].mode, PolygonMode::Fill);
        let front_culled = passes(FILL_LINE, Some(Face::Front), OFFSETS, Primitive::Triangles);
        assert_eq!(front_culled[0].mode, PolygonMode::Line);
        // Triangles are not split: every edge is a boundary, no rule needed.
        assert_eq!(front_culled[0].edges, None);
        // Lines and points ignore polygon modes.
        assert_eq!(passes(FILL_LINE, None, OFFSETS, Primitive::Lines).len(), 1);
    }

    #[test]
    fn a_quad_marks_its_diagonal_and_owns_each_vertex_once() {
        let c = split_corners(Primitive::Quads, &[0, 1, 2, 3]).unwrap();
        let order: Vec<u32> = c.iter().map(|(v, _)| *v).collect();
        assert_eq!(order, [0, 1, 2, 0, 2, 3]);
        // Triangle (0,1,2): the split edge 2–0 is opposite corner 1, so e.y = 1 throughout.
        assert!(c[..3].iter().all(|(_, e)| e[1] == 1.0));
        // Triangle (0,2,3): the split edge 0–2 is opposite corner 2, so e.z = 1 throughout.
        assert!(c[3..].iter().all(|(_, e)| e[2] == 1.0));
        // Boundary edge 0–1 (opposite corner 2 of the first triangle): zero at both ends.
        assert_eq!((c[0].1[2], c[1].1[2]), (0.0, 0.0));
        let owned: Vec<u32> = c
            .iter()
            .filter(|(_, e)| e[3] != 0.0)
            .map(|(v, _)| *v)
            .collect();
        assert_eq!(owned, [0, 1, 2, 3]);
    }

    #[test]
    fn a_polygon_fan_has_boundary_only_on_its_outline() {
        let c = split_corners(Primitive::Polygon, &[0, 1, 2, 3, 4]).unwrap();
        assert_eq!(c.len(), 9);
        // Count, per triangle, which edges have a component that is 0 at both ends.
        let mut boundary_edges = 0;
        for tri in c.chunks_exact(3) {
            for m in 0..3 {
                let ends: Vec<f32> = (0..3).filter(|&k| k != m).map(|k| tri[k].1[m]).collect();
                if ends.iter().all(|&x| x == 0.0) {
                    boundary_edges += 1;
                }
            }
        }
        assert_eq!(boundary_edges, 5, "a pentagon has five edges");
        let owned = c.iter().filter(|(_, e)| e[3] != 0.0).count();
        assert_eq!(owned, 5);
        let strip = split_corners(Primitive::QuadStrip, &[0, 1, 2, 3, 4, 5]).unwrap();
        let order: Vec<u32> = strip.iter().map(|(v, _)| *v).collect();
        assert_eq!(order, [0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4]);
        assert_eq!(split_corners(Primitive::TriangleFan, &[0, 1, 2]), None);
    }
}
