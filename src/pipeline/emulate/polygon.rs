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
//!   unshared triangle corners (split as Mesa splits them: `assembly`), each with an edge attribute e (vec4): for the edge opposite
//!   corner m, e[m] is 1 at corner m and 0 at the other two when that edge is a boundary
//!   edge, and 1 at all three corners when it is a split edge. A boundary edge rasterised
//!   as a line therefore interpolates e[m] between two zeros — exactly 0 — while a split
//!   edge has no component that stays 0, so LINE mode keeps a fragment iff some component
//!   of e.xyz is exactly 0 (not the minimum: past a line's ends the varying components
//!   extrapolate below 0).
//!   e.w is 1 on the one corner that owns each polygon vertex, so POINT mode keeps a point
//!   iff e.w ≠ 0 and a vertex shared by the two triangles of a quad is drawn once.
//! - **Edge flags ride on the same attribute**, for every polygon type as on Mesa (§2.6.2
//!   names TRIANGLES, QUADS and POLYGON only; Mesa's draw module flags the strips' and
//!   fans' triangles and the quad strip's quads too, `Geometry::reads_edge_flags`). The
//!   polygon edge from vertex k to k+1 is a boundary edge only if k's flag is TRUE, so a
//!   FALSE flag makes it a split edge (1 at every corner); a strip's or fan's triangle is a
//!   polygon of its own, its vertices in the draw module's order (`assembly::polygons`).
//!   POINT mode draws a vertex only if its flag is TRUE, as Mesa's draw module does
//!   (`draw_pipe_unfilled.c` tests the vertex's flag for points as for lines; measured in
//!   tests/fidelity_edge_flags.rs), once per polygon that has it, as there. The triangle
//!   types with an edge-flag array holding a FALSE are uploaded as corners too
//!   ([`Outline::Corners`]); without an array every vertex has the current flag, and a
//!   FALSE one leaves nothing to draw in LINE or POINT mode ([`hides_outline`]).
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

use super::assembly::{self, Diagonal};
use super::key::PositionSource;
use crate::ff::{Face, Geometry, OffsetEnables, PolygonMode, PolygonModes, Primitive};

/// How a draw's polygons reach core GL.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outline {
    /// As core GL primitives, every edge a boundary edge.
    Core,
    /// As unshared triangle corners with the edge attribute.
    Corners,
}

impl Outline {
    /// QUADS, QUAD_STRIP and POLYGON, and the triangle types whose edge-flag array has a
    /// FALSE.
    pub fn of(g: &Geometry) -> Outline {
        let triangles = matches!(
            g.primitive,
            Primitive::Triangles | Primitive::TriangleStrip | Primitive::TriangleFan
        );
        let flagged = triangles && g.edge_flags.as_ref().is_some_and(|f| f.contains(&false));
        if is_split(g.primitive) || flagged {
            Outline::Corners
        } else {
            Outline::Core
        }
    }
}

/// True when `g` has no edge-flag array, reads edge flags, and the current flag is FALSE:
/// no edge is a boundary edge and no vertex a point, so LINE and POINT modes draw nothing.
pub fn hides_outline(g: &Geometry, current_flag: bool) -> bool {
    !current_flag && g.edge_flags.is_none() && g.reads_edge_flags()
}

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
    /// The pass rasterises polygons filled: the only fragments POLYGON_STIPPLE applies to
    /// (§3.5.2; a polygon drawn in LINE or POINT mode is stippled as lines or not at all).
    pub fills_polygons: bool,
    /// The pass rasterises lines: line primitives, or polygons in LINE mode.
    pub draws_lines: bool,
    /// Where the pass's clip coordinates come from; `Window` passes draw with the fixed
    /// viewport of `shadergen::WINDOW_SPAN` and depth range [0, 1].
    pub positions: PositionSource,
}

impl PolygonPass {
    /// The pass rasterises points: point primitives, or polygons in POINT mode.
    pub fn draws_points(&self) -> bool {
        !self.fills_polygons && !self.draws_lines
    }
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

/// The passes that draw `primitive`, reaching core GL as `outline`, under the GL 1.x
/// `modes`, `cull` and offset state.
pub fn passes(
    modes: PolygonModes,
    cull: Option<Face>,
    enables: OffsetEnables,
    primitive: Primitive,
    outline: Outline,
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
            _ if outline == Outline::Core => None,
            PolygonMode::Fill => None,
            PolygonMode::Line => Some(EdgeRule::BoundaryEdges),
            PolygonMode::Point => Some(EdgeRule::OwnedVertices),
        },
        fills_polygons: mode == PolygonMode::Fill,
        draws_lines: mode == PolygonMode::Line,
        positions: PositionSource::Transformed,
    };
    if !is_polygonal(primitive) {
        return vec![PolygonPass {
            mode: PolygonMode::Fill,
            cull,
            offset: false,
            edges: None,
            fills_polygons: false,
            draws_lines: primitive != Primitive::Points,
            positions: PositionSource::Transformed,
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

/// One triangle corner of a split primitive: the vertex it is, the provoking vertex of its
/// polygon (`assembly`), and its edge attribute.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Corner {
    pub vertex: u32,
    pub provoking: u32,
    pub edge: [f32; 4],
}

/// The triangle corners of the polygons of a split primitive (or of TRIANGLES), split as
/// `assembly` says (`diagonal` for QUADS), with their edge attributes; `None` for the other
/// primitives. An edge of a triangle is a boundary edge iff its two vertices are neighbours
/// in the polygon (positions k and k+1 mod n) and the flag of the first, `flag(vertex)`, is
/// TRUE (read for TRIANGLES, QUADS and POLYGON only); a vertex is owned by the first corner
/// it has, and drawn as a point only if its flag is TRUE.
pub fn split_corners(
    primitive: Primitive,
    indices: &[u32],
    diagonal: Diagonal,
    flag: impl Fn(u32) -> bool,
) -> Option<Vec<Corner>> {
    let triangles = matches!(
        primitive,
        Primitive::Triangles | Primitive::TriangleStrip | Primitive::TriangleFan
    );
    if !is_split(primitive) && !triangles {
        return None;
    }
    let mut out = Vec::new();
    for poly in assembly::polygons(primitive, indices) {
        let n = poly.vertices.len();
        let mut owned = vec![false; n];
        let provoking = poly.vertices[poly.provoking];
        let flags: Vec<bool> = poly.vertices.iter().map(|&v| flag(v)).collect();
        for tri in assembly::triangles(primitive, n, diagonal) {
            for (c, &k) in tri.iter().enumerate() {
                let mut e = [0.0; 4];
                for m in 0..3 {
                    // The edge opposite corner m joins the other two corners; it is the
                    // polygon edge a → a+1 (or b → b+1), which a's flag marks.
                    let (a, b) = (tri[(m + 1) % 3], tri[(m + 2) % 3]);
                    let boundary = ((a + 1) % n == b && flags[a]) || ((b + 1) % n == a && flags[b]);
                    e[m] = if !boundary || m == c { 1.0 } else { 0.0 };
                }
                e[3] = if owned[k] || !flags[k] { 0.0 } else { 1.0 };
                owned[k] = true;
                out.push(Corner {
                    vertex: poly.vertices[k],
                    provoking,
                    edge: e,
                });
            }
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The passes of `p` reaching core GL as its type does without edge flags.
    fn passes_of(
        modes: PolygonModes,
        cull: Option<Face>,
        enables: OffsetEnables,
        p: Primitive,
    ) -> Vec<PolygonPass> {
        let outline = if is_split(p) {
            Outline::Corners
        } else {
            Outline::Core
        };
        passes(modes, cull, enables, p, outline)
    }

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
    fn separate_modes_take_two_culled_passes_of() {
        let p = passes_of(FILL_LINE, None, OFFSETS, Primitive::Polygon);
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
        assert!(!passes_of(FILL_LINE, None, OFFSETS, Primitive::Lines)[0].offset);
        // Culling one face leaves one pass in the other face's mode.
        let back_culled = passes_of(FILL_LINE, Some(Face::Back), OFFSETS, Primitive::Quads);
        assert_eq!(back_culled.len(), 1);
        assert_eq!(back_culled[0].mode, PolygonMode::Fill);
        let front_culled = passes_of(FILL_LINE, Some(Face::Front), OFFSETS, Primitive::Triangles);
        assert_eq!(front_culled[0].mode, PolygonMode::Line);
        // Triangles are not split: every edge is a boundary, no rule needed.
        assert_eq!(front_culled[0].edges, None);
        // Lines and points ignore polygon modes.
        assert_eq!(
            passes_of(FILL_LINE, None, OFFSETS, Primitive::Lines).len(),
            1
        );
    }

    /// The edges of each triangle whose attribute component is 0 at both ends (drawn in
    /// LINE mode), as vertex pairs.
    fn boundary_edges(c: &[Corner]) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        for tri in c.chunks_exact(3) {
            for m in 0..3 {
                let (a, b) = (tri[(m + 1) % 3], tri[(m + 2) % 3]);
                if a.edge[m] == 0.0 && b.edge[m] == 0.0 {
                    out.push((a.vertex.min(b.vertex), a.vertex.max(b.vertex)));
                }
            }
        }
        out.sort_unstable();
        out
    }

    fn owned(c: &[Corner]) -> Vec<u32> {
        c.iter()
            .filter(|c| c.edge[3] != 0.0)
            .map(|c| c.vertex)
            .collect()
    }

    #[test]
    fn a_quad_marks_its_diagonal_and_owns_each_vertex_once() {
        for (diagonal, order, split) in [
            (Diagonal::V0V2, [0, 1, 2, 0, 2, 3], (0, 2)),
            (Diagonal::V1V3, [0, 1, 3, 1, 2, 3], (1, 3)),
        ] {
            let c = split_corners(Primitive::Quads, &[0, 1, 2, 3], diagonal, |_| true).unwrap();
            let got: Vec<u32> = c.iter().map(|c| c.vertex).collect();
            assert_eq!(got, order);
            assert_eq!(boundary_edges(&c), [(0, 1), (0, 3), (1, 2), (2, 3)]);
            // The split edge has no component that is 0 at both of its ends.
            assert!(!boundary_edges(&c).contains(&split));
            let mut o = owned(&c);
            o.sort_unstable();
            assert_eq!(o, [0, 1, 2, 3]);
            // Every corner carries the quad's provoking vertex, v3.
            assert!(c.iter().all(|c| c.provoking == 3));
        }
    }

    #[test]
    fn a_polygon_fan_has_boundary_only_on_its_outline() {
        let c = split_corners(Primitive::Polygon, &[0, 1, 2, 3, 4], Diagonal::V0V2, |_| {
            true
        })
        .unwrap();
        assert_eq!(c.len(), 9);
        assert_eq!(boundary_edges(&c).len(), 5, "a pentagon has five edges");
        assert_eq!(owned(&c).len(), 5);
        assert!(c.iter().all(|c| c.provoking == 0));
        let strip = split_corners(
            Primitive::QuadStrip,
            &[0, 1, 2, 3, 4, 5],
            Diagonal::V0V2,
            |_| true,
        )
        .unwrap();
        let order: Vec<u32> = strip.iter().map(|c| c.vertex).collect();
        assert_eq!(order, [0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4]);
        let provoking: Vec<u32> = strip.iter().map(|c| c.provoking).collect();
        assert_eq!(provoking, [3, 3, 3, 3, 3, 3, 5, 5, 5, 5, 5, 5]);
        assert_eq!(
            boundary_edges(&strip),
            [
                (0, 1),
                (0, 2),
                (1, 3),
                (2, 3),
                (2, 3),
                (2, 4),
                (3, 5),
                (4, 5)
            ]
        );
        // A fan's triangles (0, i+1, i+2), each its own polygon; vertex 2's FALSE flag
        // hides the edges that start at it, 2→0 and 2→3.
        let fan = split_corners(Primitive::TriangleFan, &[0, 1, 2, 3], Diagonal::V0V2, |v| {
            v != 2
        })
        .unwrap();
        let order: Vec<u32> = fan.iter().map(|c| c.vertex).collect();
        assert_eq!(order, [0, 1, 2, 0, 2, 3]);
        assert_eq!(boundary_edges(&fan), [(0, 1), (0, 2), (0, 3), (1, 2)]);
        assert_eq!(
            split_corners(Primitive::LineStrip, &[0, 1, 2], Diagonal::V0V2, |_| true),
            None
        );
    }
}
