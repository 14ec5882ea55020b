//! The decomposition `outline_dashes` follows: each primitive's triangles, their polygon
//! edges and resets, as Mesa's draw module makes them (last vertex last).

use super::*;

fn edges(p: Primitive, n: u32) -> Vec<(u32, u32, bool)> {
    let order: Vec<u32> = (0..n).collect();
    let mut out = Vec::new();
    for t in triangles(p, &order) {
        let mut reset = t.reset;
        for k in [2usize, 0, 1] {
            if t.edges[k] {
                out.push((t.v[k], t.v[(k + 1) % 3], std::mem::take(&mut reset)));
            }
        }
    }
    out
}

#[test]
fn quads_run_round_from_their_last_vertex() {
    assert_eq!(
        edges(Primitive::Quads, 4),
        [(3, 0, true), (0, 1, false), (1, 2, false), (2, 3, false)]
    );
}

#[test]
fn polygons_run_round_from_their_first_vertex() {
    assert_eq!(
        edges(Primitive::Polygon, 5),
        [
            (0, 1, true),
            (1, 2, false),
            (2, 3, false),
            (3, 4, false),
            (4, 0, false)
        ]
    );
}

#[test]
fn quad_strips_and_strips_reset_per_quad_and_per_triangle() {
    assert_eq!(
        edges(Primitive::QuadStrip, 4),
        [(3, 2, true), (2, 0, false), (0, 1, false), (1, 3, false)]
    );
    let strip = edges(Primitive::TriangleStrip, 4);
    assert_eq!(strip.len(), 6);
    assert_eq!(strip[3], (3, 2, true), "the odd triangle is (2, 1, 3)");
    assert_eq!(
        triangles(Primitive::TriangleFan, &[0, 1, 2, 3])[1].v,
        [0, 2, 3]
    );
    assert!(triangles(Primitive::LineLoop, &[0, 1, 2]).is_empty());
}
