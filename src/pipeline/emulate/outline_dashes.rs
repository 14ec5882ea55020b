//! Stippled outlines: polygons in LINE mode while LINE_STIPPLE is on (GL 1.5 §3.5.4 with
//! §3.4.2), cut into the dashes Mesa draws. Mesa's draw module decomposes each primitive
//! into triangles (last vertex last, `draw_decompose_tmp.h`), and its unfilled stage draws
//! a LINE-mode triangle's flagged edges as lines — in the order v2→v0, v0→v1, v1→v2 —
//! through the stipple stage, whose counter is reset at every triangle that starts a
//! polygon. The outlines therefore run, counter and all:
//!
//! - a triangle (v0, v1, v2): v2→v0, v0→v1, v1→v2, reset at each triangle, strips and fans
//!   alike (strip triangle i is (i + i mod 2, i + 1 − i mod 2, i + 2), fan triangle i is
//!   (0, i + 1, i + 2); their inner edges are drawn by both triangles);
//! - a quad q0..q3: q3→q0, q0→q1, q1→q2, q2→q3 (the triangles (q0, q1, q3), (q1, q2, q3),
//!   the q1–q3 edge not drawn), reset once;
//! - a quad-strip quad (q0, q1, q2, q3) = (2i, 2i+1, 2i+2, 2i+3): q3→q2, q2→q0, q0→q1,
//!   q1→q3, reset once;
//! - a polygon p0..pn−1: p0→p1, p1→p2, …, pn−1→p0, reset once.
//!
//! A triangle is drawn when its face is not culled and that face's mode is LINE; the face
//! is the sign of the window-space area, which for vertices in front of the eye is the
//! sign of det(x_c, y_c, w_c) (FrontFace CCW: positive is front). Edge flags hide the edges
//! from vertices whose flag is FALSE for TRIANGLES, QUADS and POLYGON (§2.6.2; the layer
//! ignores them for strips and fans, as the filled path does). The segments are then cut
//! into dashes by `line_stipple` — clipped as lines, where Mesa clips the triangles before
//! the unfilled stage: an outline crossing the view volume loses the edges the clipper
//! would add along it, and its counter may run differently there.

use glam::{Mat3, Vec3, Vec4};

use super::line_stipple::{clip_coordinates, Segment};
use crate::ff::{Face, FixedState, FrontFace, Geometry, PolygonMode, Primitive};

/// One triangle of the decomposition: its vertices (indices into the arrays), which of
/// its edges are polygon edges (EDGE_0 = v0→v1, EDGE_1 = v1→v2, EDGE_2 = v2→v0) and
/// whether it starts a polygon (the stipple counter's reset).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Triangle {
    pub v: [u32; 3],
    pub edges: [bool; 3],
    pub reset: bool,
}

/// Mesa's decomposition of `primitive` over `order` (the vertices in submission order).
pub fn triangles(primitive: Primitive, order: &[u32]) -> Vec<Triangle> {
    let tri = |v: [u32; 3], edges: [bool; 3], reset: bool| Triangle { v, edges, reset };
    const ALL: [bool; 3] = [true; 3];
    let n = order.len();
    let at = |i: usize| order[i];
    let mut out = Vec::new();
    match primitive {
        Primitive::Triangles => {
            for t in order.chunks_exact(3) {
                out.push(tri([t[0], t[1], t[2]], ALL, true));
            }
        }
        Primitive::TriangleStrip => {
            for i in 0..n.saturating_sub(2) {
                let odd = i & 1;
                out.push(tri([at(i + odd), at(i + 1 - odd), at(i + 2)], ALL, true));
            }
        }
        Primitive::TriangleFan => {
            for i in 0..n.saturating_sub(2) {
                out.push(tri([at(0), at(i + 1), at(i + 2)], ALL, true));
            }
        }
        Primitive::Quads => {
            for q in order.chunks_exact(4) {
                out.push(tri([q[0], q[1], q[3]], [true, false, true], true));
                out.push(tri([q[1], q[2], q[3]], [true, true, false], false));
            }
        }
        Primitive::QuadStrip => {
            let mut i = 0;
            while i + 3 < n {
                let q = [at(i), at(i + 1), at(i + 2), at(i + 3)];
                out.push(tri([q[2], q[0], q[3]], [true, false, true], true));
                out.push(tri([q[0], q[1], q[3]], [true, true, false], false));
                i += 2;
            }
        }
        Primitive::Polygon => {
            for i in 0..n.saturating_sub(2) {
                let first = i == 0;
                let last = i + 3 == n;
                out.push(tri(
                    [at(i + 1), at(i + 2), at(0)],
                    [true, last, first],
                    first,
                ));
            }
        }
        Primitive::Points | Primitive::Lines | Primitive::LineStrip | Primitive::LineLoop => {}
    }
    out
}

/// The outline segments of the LINE-mode faces of `g` under `state`, in Mesa's order.
pub fn outline_segments(g: &Geometry, state: &FixedState) -> Vec<Segment> {
    let order: Vec<u32> = match &g.indices {
        Some(i) => i.clone(),
        None => (0..g.positions.len() as u32).collect(),
    };
    let mvp = state.projection_matrix() * state.modelview_matrix();
    let clip: Vec<Vec4> = g
        .positions
        .iter()
        .map(|&p| clip_coordinates(mvp, p))
        .collect();
    let flagged = g.reads_edge_flags();
    let current = state.current.edge_flag;
    let mut out = Vec::new();
    let mut carry = false;
    for t in triangles(g.primitive, &order) {
        let Some(c) =
            t.v.iter()
                .map(|&v| clip.get(v as usize).copied())
                .collect::<Option<Vec<_>>>()
        else {
            continue;
        };
        let det = Mat3::from_cols(
            Vec3::new(c[0].x, c[0].y, c[0].w),
            Vec3::new(c[1].x, c[1].y, c[1].w),
            Vec3::new(c[2].x, c[2].y, c[2].w),
        )
        .determinant();
        let ccw = det > 0.0;
        let front = ccw == (state.front_face == FrontFace::Ccw);
        if !draws_lines(state, front) {
            continue;
        }
        // A triangle whose edges are all hidden still resets the counter (Mesa's stipple
        // stage): the reset waits for the next edge drawn.
        let mut reset = t.reset || std::mem::take(&mut carry);
        // v2→v0 (EDGE_2), v0→v1 (EDGE_0), v1→v2 (EDGE_1).
        for k in [2usize, 0, 1] {
            let (from, to) = (t.v[k], t.v[(k + 1) % 3]);
            if t.edges[k] && (!flagged || g.edge_flag(from, current)) {
                out.push(Segment {
                    from,
                    to,
                    reset: std::mem::take(&mut reset),
                    // The triangle's last vertex: its polygon's provoking vertex.
                    provoking: t.v[2],
                });
            }
        }
        carry = reset;
    }
    out
}

/// Whether a face (`front` or not) is drawn in LINE mode, culling considered.
fn draws_lines(state: &FixedState, front: bool) -> bool {
    if let Some(cull) = state.cull_face.get() {
        let culled = match cull {
            Face::Front => front,
            Face::Back => !front,
            Face::FrontAndBack => true,
        };
        if culled {
            return false;
        }
    }
    let mode = if front {
        state.polygon_mode.front
    } else {
        state.polygon_mode.back
    };
    mode == PolygonMode::Line
}

#[cfg(test)]
#[path = "outline_dashes_tests.rs"]
mod tests;
