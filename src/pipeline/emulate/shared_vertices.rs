//! Vertices a non-indexed draw repeats, uploaded once and drawn through indices — what
//! Mesa's display-list compiler does with a list's glBegin/glEnd vertices (since Mesa 21 a
//! list is drawn indexed, each distinct vertex once).
//!
//! llvmpipe runs the vertex shader once per vertex it fetches: a sphere of 48 × 24 quads
//! sent as TRIANGLES is 6912 vertices but 1225 distinct ones, and drawn indexed the shader
//! runs for the 1225 (the draw module caches by index). Two vertices are the same when
//! every attribute the geometry has is the same bit for bit (so −0.0 and 0.0, or two NaNs
//! of different payloads, stay apart); the shader's output is a function of its inputs,
//! so the image is the one the non-indexed draw gives. Only the types core GL draws itself
//! are shared: QUADS, QUAD_STRIP and POLYGON are split into corners (`assembly`), and
//! Mesa's split of QUADS depends on whether the draw is indexed.

use std::collections::HashMap;

use crate::ff::Geometry;

/// The share of repeated vertices below which sharing is not worth its upload: a draw is
/// indexed only when its distinct vertices are at most 3/4 of its vertices.
const WORTH: (usize, usize) = (3, 4);

/// A non-indexed geometry's distinct vertices and the indices that draw it.
#[derive(Debug, PartialEq, Eq)]
pub struct Shared {
    /// The first vertex of each distinct kind, in order of first use.
    pub vertices: Vec<u32>,
    /// For each vertex in order, its kind's place in `vertices`.
    pub indices: Vec<u32>,
}

/// `g`'s vertices shared, or `None` when `g` is indexed already or repeats too few.
pub fn of(g: &Geometry) -> Option<Shared> {
    // Per-vertex materials are not in a vertex's bits: such a draw keeps its vertices.
    if g.indices.is_some() || g.positions.is_empty() || g.materials.is_some() {
        return None;
    }
    let n = g.positions.len();
    let mut kinds: HashMap<Vec<u32>, u32> = HashMap::with_capacity(n);
    let mut key = Vec::new();
    let mut vertices = Vec::new();
    let mut indices = Vec::with_capacity(n);
    for i in 0..n {
        key.clear();
        bits_of(g, i, &mut key);
        let kind = match kinds.get(key.as_slice()) {
            Some(&k) => k,
            None => {
                let k = vertices.len() as u32;
                vertices.push(i as u32);
                kinds.insert(key.clone(), k);
                k
            }
        };
        indices.push(kind);
    }
    (vertices.len() * WORTH.1 <= n * WORTH.0).then_some(Shared { vertices, indices })
}

/// Every attribute of vertex `i`, as bits.
fn bits_of(g: &Geometry, i: usize, key: &mut Vec<u32>) {
    let mut floats = |v: &[f32]| key.extend(v.iter().map(|x| x.to_bits()));
    floats(&g.positions[i].to_array());
    if let Some(n) = &g.normals {
        floats(&n[i].to_array());
    }
    for c in [&g.colors, &g.secondary_colors].into_iter().flatten() {
        floats(&c[i].to_array());
    }
    if let Some(f) = &g.fog_coords {
        floats(&[f[i]]);
    }
    for t in g.texcoords.iter().flatten() {
        floats(&t[i].to_array());
    }
    if let Some(e) = &g.edge_flags {
        key.push(u32::from(e[i]));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::Primitive;
    use glam::{Vec3, Vec4};

    fn strip_of_quads_as_triangles() -> Geometry {
        // Two quads side by side as four triangles: 12 vertices, 6 distinct.
        let p = |x: f32, y: f32| Vec4::new(x, y, 0.0, 1.0);
        let quad = |x: f32| {
            [
                p(x, 0.),
                p(x + 1., 0.),
                p(x + 1., 1.),
                p(x, 0.),
                p(x + 1., 1.),
                p(x, 1.),
            ]
        };
        let positions: Vec<Vec4> = quad(0.0).into_iter().chain(quad(1.0)).collect();
        Geometry::new(Primitive::Triangles, positions)
    }

    #[test]
    fn repeated_vertices_are_drawn_through_indices_in_the_same_order() {
        let g = strip_of_quads_as_triangles();
        let s = of(&g).expect("6 of 12 distinct");
        assert_eq!(s.vertices, [0, 1, 2, 5, 7, 8]);
        assert_eq!(s.indices, [0, 1, 2, 0, 2, 3, 1, 4, 5, 1, 5, 2]);
        for (k, &v) in s.indices.iter().enumerate() {
            assert_eq!(g.positions[s.vertices[v as usize] as usize], g.positions[k]);
        }
    }

    #[test]
    fn vertices_that_differ_in_any_attribute_or_in_their_bits_stay_apart() {
        let mut g = strip_of_quads_as_triangles();
        let mut normals = vec![Vec3::Z; 12];
        normals[3] = Vec3::new(0.0, 0.0, -0.0); // −0 is not +0
        g.normals = Some(normals);
        let s = of(&g).expect("7 of 12 distinct");
        assert_eq!(s.vertices.len(), 7);
        assert_eq!(s.indices[3], 3);
        // Vertices 0 and 3 are one vertex; as NaNs they are one only with the same bits.
        let with_x = |a: u32, b: u32| {
            let mut g = strip_of_quads_as_triangles();
            g.positions[0].x = f32::from_bits(a);
            g.positions[3].x = f32::from_bits(b);
            of(&g).map(|s| s.vertices.len())
        };
        assert_eq!(with_x(0x7fc0_0001, 0x7fc0_0001), Some(6));
        assert_eq!(with_x(0x7fc0_0001, 0x7fc0_0002), Some(7));
    }

    #[test]
    fn a_draw_of_distinct_vertices_or_an_indexed_one_is_left_as_it_is() {
        let distinct = Geometry::new(
            Primitive::Triangles,
            (0..9).map(|i| Vec4::new(i as f32, 0.0, 0.0, 1.0)).collect(),
        );
        assert_eq!(of(&distinct), None);
        let mut indexed = strip_of_quads_as_triangles();
        indexed.indices = Some((0..12).collect());
        assert_eq!(of(&indexed), None);
        assert_eq!(of(&Geometry::new(Primitive::Points, vec![])), None);
    }
}
