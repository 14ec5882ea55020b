//! Primitive assembly for the primitives core GL lacks: QUADS, QUAD_STRIP and POLYGON become
//! triangles here, split the way Mesa's native path splits them, each polygon remembering its
//! provoking vertex.
//!
//! **Provoking vertex** (flat shading, GL 1.5 Table 2.8): point i → i; independent line i →
//! 2i; line strip and line loop → i+1, the closing segment of a loop → vertex 1; independent
//! triangle i → 3i; triangle strip and fan → i+2; independent quad i → 4i; quad strip → 2i+2;
//! polygon → vertex 1 (1-based). Core GL 3.3's default LAST_VERTEX_CONVENTION gives exactly
//! this for every type core GL has, LINE_LOOP's closing segment included. A split polygon
//! takes its provoking vertex's colour over all of its triangles, whatever the split (GL 1.5
//! §2.13.7: one colour per polygon) — which no vertex order of two triangles can give for
//! the v0–v2 split of a quad (the first triangle lacks v3) — so each corner of a split
//! polygon also carries its polygon's provoking vertex as the *shade* attributes the vertex
//! shader lights under flat shading (`shadergen::vertex`).
//!
//! **The split, measured** on Mesa 22.3.6 llvmpipe through DrawArrays, DrawElements and
//! glBegin/glEnd, smooth and flat, lit and unlit (`tests/native_primitives.rs`):
//!
//! - QUAD_STRIP quad i (polygon order 2i, 2i+1, 2i+3, 2i+2) is split along 2i–(2i+3), and a
//!   POLYGON is fanned from its first vertex, always.
//! - QUADS depend on how the draw reached the rasteriser. Drawn with indices, every quad is
//!   (v0,v1,v3),(v1,v2,v3) — the v1–v3 diagonal. Drawn without (DrawArrays or glBegin/glEnd),
//!   complete quads go in chunks of 1024 (4096 vertices): a chunk in which no vertex lies
//!   outside the clip volume (|x|, |y|, |z| > w in clip coordinates; no guard band, a tenth
//!   of a pixel out is enough) is split (v0,v1,v2),(v0,v2,v3) — the v0–v2 diagonal — and a
//!   chunk with a vertex outside, v1–v3 like indexed quads. Outside an enabled user clip
//!   plane counts as outside (its eye-space equation · the vertex's eye position < 0):
//!   measured, a smooth quad whose first corner a plane cuts off is drawn v1–v3. So is
//!   every quad while a face that is not culled has a polygon mode other than FILL, or
//!   while POLYGON_STIPPLE is on (the module's stages then run for every triangle;
//!   measured: a filled front quad drawn while back faces are LINE, and a stippled quad,
//!   are v1–v3; the POLYGON_OFFSET_LINE and _POINT enables change nothing). Under FLAT
//!   shading every quad is v1–v3 (a non-convex or non-planar quad shows it; a convex planar one looks the same
//!   either way). Lighting, textures,
//!   two-sided lighting, culling and the polygon offset enables change nothing; the vertices
//!   of a trailing partial quad are not looked at. The chunks were measured with arrays
//!   (glBegin/glEnd gave the same images for every draw tried, up to 11 vertices). In
//!   Gallium's terms: an unclipped linear draw reaches llvmpipe's setup as quads, split
//!   v0–v2 there; an indexed draw takes the element path and a clipped chunk the draw
//!   module's pipeline stages, which both split v1–v3 (last vertex provoking).

use std::ops::Range;

use glam::{Mat4, Vec4};

use crate::ff::{Face, FixedState, Geometry, PolygonMode, PolygonModes, Primitive, ShadeModel};

/// The diagonal a quad is split along.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Diagonal {
    /// (v0,v1,v2),(v0,v2,v3).
    V0V2,
    /// (v0,v1,v3),(v1,v2,v3).
    V1V3,
}

/// Complete quads Mesa decides the diagonal for at once in a non-indexed draw.
pub const QUAD_CHUNK: usize = 1024;

/// One polygon of a split primitive: its vertex indices in polygon order and the position
/// of its provoking vertex in that list.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Polygon {
    pub vertices: Vec<u32>,
    pub provoking: usize,
}

/// The polygons of `primitive` over `indices` (the vertices in submission order); empty for
/// points and lines. The triangle types give one polygon per triangle (their corners carry
/// edge flags, `polygon`): a strip's triangle i as Mesa's draw module orders it for the
/// last vertex provoking, (i, i+1, i+2) for even i and (i+1, i, i+2) for odd, a fan's as
/// (0, i+1, i+2). Incomplete trailing polygons are dropped (GL 1.5 §2.6.1).
pub fn polygons(primitive: Primitive, indices: &[u32]) -> Vec<Polygon> {
    match primitive {
        Primitive::TriangleStrip => (0..indices.len().saturating_sub(2))
            .map(|i| {
                let odd = i % 2;
                Polygon {
                    vertices: vec![indices[i + odd], indices[i + 1 - odd], indices[i + 2]],
                    provoking: 2,
                }
            })
            .collect(),
        Primitive::TriangleFan => (0..indices.len().saturating_sub(2))
            .map(|i| Polygon {
                vertices: vec![indices[0], indices[i + 1], indices[i + 2]],
                provoking: 2,
            })
            .collect(),
        // Triangle i: 3i, 3i+1, 3i+2; provoking 3i+2 (the last).
        Primitive::Triangles => indices
            .chunks_exact(3)
            .map(|t| Polygon {
                vertices: t.to_vec(),
                provoking: 2,
            })
            .collect(),
        // Quad i: 4i, 4i+1, 4i+2, 4i+3; provoking 4i+3 (the last).
        Primitive::Quads => indices
            .chunks_exact(4)
            .map(|q| Polygon {
                vertices: q.to_vec(),
                provoking: 3,
            })
            .collect(),
        // Quad i: 2i, 2i+1, 2i+3, 2i+2 in polygon order; provoking 2i+3.
        Primitive::QuadStrip => (0..indices.len().saturating_sub(2) / 2)
            .map(|i| Polygon {
                vertices: [0, 1, 3, 2].iter().map(|k| indices[2 * i + k]).collect(),
                provoking: 2,
            })
            .collect(),
        Primitive::Polygon if indices.len() >= 3 => vec![Polygon {
            vertices: indices.to_vec(),
            provoking: 0,
        }],
        _ => Vec::new(),
    }
}

/// The triangles of one polygon of `primitive` with `n` vertices, as positions in its
/// vertex list, in the polygon's winding. `diagonal` matters for QUADS only.
pub fn triangles(primitive: Primitive, n: usize, diagonal: Diagonal) -> Vec<[usize; 3]> {
    match (primitive, diagonal) {
        (Primitive::Quads, Diagonal::V1V3) => vec![[0, 1, 3], [1, 2, 3]],
        // QUAD_STRIP along 2i–(2i+3) is polygon positions 0–2: the fan from position 0.
        _ => (0..n.saturating_sub(2))
            .map(|i| [0, i + 1, i + 2])
            .collect(),
    }
}

/// True when a vertex with object position `p` lies outside the clip volume under `mvp`
/// (−w ≤ x, y, z ≤ w, GL 1.5 §2.11; no guard band).
pub fn clipped(mvp: Mat4, p: Vec4) -> bool {
    let c = mvp * p;
    c.x.abs() > c.w || c.y.abs() > c.w || c.z.abs() > c.w || c.w.is_nan()
}

/// How Mesa's draw module routes a non-indexed QUADS draw: through its pipeline stages,
/// which split v1–v3, when `staged` (a face that is not culled has a polygon mode other
/// than FILL, or POLYGON_STIPPLE is on) or when a vertex of the chunk is clipped —
/// outside the clip volume under `mvp`, or outside an enabled user clip plane (eye-space
/// equation P; outside where P · (modelview · p) < 0, GL 1.5 §2.12 — false for NaN, as
/// the module's compare).
pub struct DrawRoute {
    pub mvp: Mat4,
    pub modelview: Mat4,
    /// The enabled planes' eye-space equations.
    pub planes: Vec<Vec4>,
    pub staged: bool,
}

impl DrawRoute {
    /// The route under `state`'s matrices, enabled clip planes, polygon modes and stipple.
    pub fn of(state: &FixedState) -> DrawRoute {
        let modelview = state.modelview_matrix();
        // A culled face takes the other face's mode, as Mesa's state tracker sets the
        // rasteriser's fill modes (front first, then back).
        let PolygonModes {
            mut front,
            mut back,
        } = state.polygon_mode;
        if state.cull_face.enabled {
            let culled = state.cull_face.value;
            if matches!(culled, Face::Front | Face::FrontAndBack) {
                front = back;
            }
            if matches!(culled, Face::Back | Face::FrontAndBack) {
                back = front;
            }
        }
        DrawRoute {
            mvp: state.projection_matrix() * modelview,
            modelview,
            planes: state
                .clip_planes
                .iter()
                .filter(|p| p.enabled)
                .map(|p| p.value)
                .collect(),
            staged: front != PolygonMode::Fill
                || back != PolygonMode::Fill
                || state.polygon_stipple.enabled,
        }
    }

    /// True when the vertex at object position `p` is clipped (and its chunk staged).
    pub fn clipped(&self, p: Vec4) -> bool {
        if clipped(self.mvp, p) {
            return true;
        }
        if self.planes.is_empty() {
            return false;
        }
        let eye = self.modelview * p;
        self.planes.iter().any(|plane| plane.dot(eye) < 0.0)
    }
}

/// Mesa's diagonal for the complete quads of the QUADS draw `g` under `clip` and `shading`,
/// as ranges of quad numbers: an indexed or flat-shaded draw is all v1–v3; otherwise each
/// chunk of `QUAD_CHUNK` quads is v0–v2 unless one of its vertices is clipped. Adjacent
/// chunks with the same diagonal are merged.
pub fn quad_diagonals(
    g: &Geometry,
    clip: &DrawRoute,
    shading: ShadeModel,
) -> Vec<(Range<usize>, Diagonal)> {
    let quads = g.vertex_count() / 4;
    if quads == 0 {
        return Vec::new();
    }
    if g.indices.is_some() || shading == ShadeModel::Flat || clip.staged {
        return vec![(0..quads, Diagonal::V1V3)];
    }
    let mut out: Vec<(Range<usize>, Diagonal)> = Vec::new();
    for (c, chunk) in g.positions[..4 * quads].chunks(4 * QUAD_CHUNK).enumerate() {
        let diagonal = if chunk.iter().any(|&p| clip.clipped(p)) {
            Diagonal::V1V3
        } else {
            Diagonal::V0V2
        };
        let range = c * QUAD_CHUNK..c * QUAD_CHUNK + chunk.len() / 4;
        match out.last_mut() {
            Some((r, d)) if *d == diagonal => r.end = range.end,
            _ => out.push((range, diagonal)),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polygons_follow_table_2_8() {
        let q = polygons(Primitive::Quads, &[0, 1, 2, 3, 4, 5, 6, 7, 8]);
        assert_eq!(q.len(), 2, "the partial third quad is dropped");
        assert_eq!(q[1].vertices[q[1].provoking], 7);
        let s = polygons(Primitive::QuadStrip, &[0, 1, 2, 3, 4, 5, 6]);
        assert_eq!(s.len(), 2, "the odd trailing vertex is dropped");
        assert_eq!(s[1].vertices, [2, 3, 5, 4]);
        assert_eq!(
            s[1].vertices[s[1].provoking], 5,
            "quad strip: 2i+2 (1-based)"
        );
        let p = polygons(Primitive::Polygon, &[4, 5, 6, 7]);
        assert_eq!(
            p[0].vertices[p[0].provoking], 4,
            "polygon: its first vertex"
        );
        assert!(polygons(Primitive::Polygon, &[0, 1]).is_empty());
        assert!(polygons(Primitive::LineLoop, &[0, 1, 2]).is_empty());
        let strip = polygons(Primitive::TriangleStrip, &[5, 6, 7, 8, 9]);
        let order: Vec<Vec<u32>> = strip.iter().map(|p| p.vertices.clone()).collect();
        assert_eq!(order, [vec![5, 6, 7], vec![7, 6, 8], vec![7, 8, 9]]);
        let fan = polygons(Primitive::TriangleFan, &[5, 6, 7, 8]);
        let order: Vec<Vec<u32>> = fan.iter().map(|p| p.vertices.clone()).collect();
        assert_eq!(order, [vec![5, 6, 7], vec![5, 7, 8]]);
        assert!(strip.iter().chain(&fan).all(|p| p.provoking == 2));
    }

    #[test]
    fn quads_split_along_either_diagonal_strips_and_polygons_fan() {
        assert_eq!(
            triangles(Primitive::Quads, 4, Diagonal::V0V2),
            [[0, 1, 2], [0, 2, 3]]
        );
        assert_eq!(
            triangles(Primitive::Quads, 4, Diagonal::V1V3),
            [[0, 1, 3], [1, 2, 3]]
        );
        // Strip quad (2i, 2i+1, 2i+3, 2i+2): split along 2i–(2i+3) either way.
        assert_eq!(
            triangles(Primitive::QuadStrip, 4, Diagonal::V1V3),
            [[0, 1, 2], [0, 2, 3]]
        );
        assert_eq!(triangles(Primitive::Polygon, 5, Diagonal::V0V2).len(), 3);
    }

    #[test]
    fn a_clipped_vertex_turns_its_chunk_of_quads_to_v1_v3() {
        let inside = Vec4::new(0.5, 0.5, 0.0, 1.0);
        let outside = Vec4::new(1.001, 0.0, 0.0, 1.0);
        let mvp = Mat4::IDENTITY;
        let clip = DrawRoute {
            mvp,
            modelview: mvp,
            planes: Vec::new(),
            staged: false,
        };
        let mut g = Geometry::new(Primitive::Quads, vec![inside; 4 * (QUAD_CHUNK + 2) + 3]);
        assert_eq!(
            quad_diagonals(&g, &clip, ShadeModel::Smooth),
            [(0..QUAD_CHUNK + 2, Diagonal::V0V2)]
        );
        // Outside only in the trailing partial quad: not looked at.
        *g.positions.last_mut().unwrap() = outside;
        assert_eq!(quad_diagonals(&g, &clip, ShadeModel::Smooth).len(), 1);
        g.positions[4 * QUAD_CHUNK + 5] = outside;
        assert_eq!(
            quad_diagonals(&g, &clip, ShadeModel::Smooth),
            [
                (0..QUAD_CHUNK, Diagonal::V0V2),
                (QUAD_CHUNK..QUAD_CHUNK + 2, Diagonal::V1V3)
            ]
        );
        // Flat shading: v1–v3 whatever the positions.
        assert_eq!(
            quad_diagonals(&g, &clip, ShadeModel::Flat),
            [(0..QUAD_CHUNK + 2, Diagonal::V1V3)]
        );
        // Indexed: v1–v3 whatever the positions.
        g.indices = Some(vec![0, 1, 2, 3, 4, 5, 6, 7, 8]);
        assert_eq!(
            quad_diagonals(&g, &clip, ShadeModel::Smooth),
            [(0..2, Diagonal::V1V3)]
        );
        g.indices = Some(vec![0, 1, 2]);
        assert!(quad_diagonals(&g, &clip, ShadeModel::Smooth).is_empty());
        // Behind the eye (w < 0) is outside; on the boundary is inside.
        assert!(clipped(mvp, Vec4::new(0.0, 0.0, 0.0, -1.0)));
        assert!(!clipped(mvp, Vec4::new(1.0, -1.0, 1.0, 1.0)));
    }

    #[test]
    fn a_vertex_outside_a_user_clip_plane_is_clipped() {
        // x + y + 0.25 ≥ 0 in eye space, the modelview a translation by (0.5, 0, 0).
        let modelview = Mat4::from_translation(glam::Vec3::new(0.5, 0.0, 0.0));
        let clip = DrawRoute {
            mvp: modelview,
            modelview,
            planes: vec![Vec4::new(1.0, 1.0, 0.0, 0.25)],
            staged: false,
        };
        // Eye (−0.4, −0.9): −1.05 < 0, outside; eye (0.1, −0.2): 0.15, inside; on the
        // plane (eye (−0.125, −0.125): exactly 0) is inside.
        assert!(clip.clipped(Vec4::new(-0.9, -0.9, 0.0, 1.0)));
        assert!(!clip.clipped(Vec4::new(-0.4, -0.2, 0.0, 1.0)));
        assert!(!clip.clipped(Vec4::new(-0.625, -0.125, 0.0, 1.0)));
        let quad = |a: Vec4| {
            let rest = [
                Vec4::new(0.3, -0.5, 0.0, 1.0),
                Vec4::new(0.3, 0.3, 0.0, 1.0),
            ];
            Geometry::new(Primitive::Quads, vec![a, rest[0], rest[1], rest[1]])
        };
        let cut = quad(Vec4::new(-0.9, -0.9, 0.0, 1.0));
        assert_eq!(
            quad_diagonals(&cut, &clip, ShadeModel::Smooth),
            [(0..1, Diagonal::V1V3)]
        );
        // The same quad without the plane stays v0–v2, unless the module's stages run.
        let open = DrawRoute {
            planes: Vec::new(),
            ..clip
        };
        assert_eq!(
            quad_diagonals(&cut, &open, ShadeModel::Smooth),
            [(0..1, Diagonal::V0V2)]
        );
        let staged = DrawRoute {
            staged: true,
            ..open
        };
        assert_eq!(
            quad_diagonals(&cut, &staged, ShadeModel::Smooth),
            [(0..1, Diagonal::V1V3)]
        );
    }
}
