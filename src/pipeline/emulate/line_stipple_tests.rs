//! The CPU half of the line stipple: segments, clipping, the counter and the runs.

use glam::{Mat4, Vec4};

use super::*;
use crate::ff::{DepthRange, LineStipple, Primitive, Viewport};

/// A 64×16 window with glOrtho(0, 64, 0, 16, −1, 1): object x, y are window x, y (exactly:
/// the scales are powers of two).
fn inputs(stipple: LineStipple) -> StippleInputs<'static> {
    StippleInputs {
        modelview: Mat4::IDENTITY,
        // glOrtho(0, 80, 0, 16, −1, 1).
        projection: Mat4::from_cols(
            Vec4::new(2.0 / 64.0, 0.0, 0.0, 0.0),
            Vec4::new(0.0, 2.0 / 16.0, 0.0, 0.0),
            Vec4::new(0.0, 0.0, -1.0, 0.0),
            Vec4::new(-1.0, -1.0, 0.0, 1.0),
        ),
        transform: WindowTransform::new(
            Viewport {
                x: 0,
                y: 0,
                width: 64,
                height: 16,
            },
            DepthRange::DEFAULT,
        ),
        clip_planes: &[],
        stipple,
        length: LineLength::MajorAxis,
    }
}

fn p(x: f32, y: f32) -> Vec4 {
    Vec4::new(x, y, 0.0, 1.0)
}

#[test]
fn segments_reset_per_line_and_per_strip_and_the_loop_closes() {
    let s = segments(Primitive::Lines, &[0, 1, 2, 3, 4]);
    assert_eq!(s.len(), 2, "the odd vertex is dropped");
    assert!(s.iter().all(|s| s.reset));
    let s = segments(Primitive::LineStrip, &[0, 1, 2]);
    assert_eq!(
        s.iter()
            .map(|s| (s.from, s.to, s.reset))
            .collect::<Vec<_>>(),
        [(0, 1, true), (1, 2, false)]
    );
    let s = segments(Primitive::LineLoop, &[0, 1, 2]);
    assert_eq!(
        s.last().map(|s| (s.from, s.to, s.reset)),
        Some((2, 0, false))
    );
    assert_eq!(segments(Primitive::LineLoop, &[0, 1]).len(), 2);
    assert!(segments(Primitive::LineLoop, &[0]).is_empty());
    assert!(segments(Primitive::Triangles, &[0, 1, 2]).is_empty());
}

#[test]
fn runs_follow_the_pattern_bit_by_bit_and_carry_the_counter() {
    // 0x00FF: 8 on, 8 off; a 20-pixel line is on for [0, 8) and [16, 20).
    let mut counter = 0;
    let r = runs(LineStipple::new(1, 0x00FF), &mut counter, 20.0);
    assert_eq!(r, [(0.0, 0.4), (0.8, 1.0)]);
    assert_eq!(counter, 20);
    // The next segment of a strip starts at bit 20 mod 16 = 4: on for 4 more pixels.
    let r = runs(LineStipple::new(1, 0x00FF), &mut counter, 10.0);
    assert_eq!(r, [(0.0, 0.4)]);
    // Factor 3 repeats each bit: 0b10 is off for 3 pixels, on for 3.
    let mut counter = 0;
    let r = runs(LineStipple::new(3, 0b10), &mut counter, 6.0);
    assert_eq!(r, [(0.5, 1.0)]);
    // A partial last pixel is counted (⌈L⌉ pixels) and the counter moves on by whole
    // pixels: after 2.5 pixels the next segment starts at bit 3.
    let mut counter = 0;
    assert_eq!(runs(LineStipple::DEFAULT, &mut counter, 2.5), [(0.0, 1.0)]);
    assert_eq!(counter, 3);
    let r = runs(LineStipple::new(1, 0b1000), &mut counter, 2.0);
    assert_eq!(r, [(0.0, 0.5)]);
    // The run [1, 2) of a 1.5-pixel segment ends at the segment's end, t = 1.
    let mut counter = 0;
    assert_eq!(
        runs(LineStipple::new(1, 0b10), &mut counter, 1.5),
        [(1.0 / 1.5, 1.0)]
    );
    assert!(runs(LineStipple::new(1, 0), &mut counter, 9.0).is_empty());
    assert!(runs(LineStipple::DEFAULT, &mut counter, f32::NAN).is_empty());
}

#[test]
fn a_dash_ends_where_mesa_puts_it_and_strips_run_on() {
    let input = inputs(LineStipple::new(2, 0x0F0F));
    // Along x from 0.5: on for 8, off for 8 (factor 2 of 4-bit groups).
    let d = dashes(
        Primitive::LineStrip,
        &[p(0.5, 2.5), p(20.5, 2.5), p(20.5, 12.5)],
        &[0, 1, 2],
        &input,
    );
    let ends: Vec<(f32, f32)> = d
        .iter()
        .map(|d| (d.ends[0].window.x, d.ends[1].window.x))
        .collect();
    assert_eq!(ends[..2], [(0.5, 8.5), (16.5, 20.5)]);
    // The vertical segment starts at counter 20: bits 10..: on for 4 more, off for 8.
    let last = d[2];
    assert_eq!(last.ends[0].window.y, 2.5);
    assert_eq!(last.ends[1].window.y, 6.5);
    assert_eq!(last.provoking, 2);
    // Each end's parameter along its segment, for the attributes.
    assert_eq!((d[1].ends[0].s, d[1].ends[1].s), (0.8, 1.0));
    // GL_LINES restarts: the same two segments as lines start the vertical one at bit 0.
    let d = dashes(
        Primitive::Lines,
        &[p(0.5, 2.5), p(20.5, 2.5), p(20.5, 2.5), p(20.5, 12.5)],
        &[0, 1, 2, 3],
        &input,
    );
    assert_eq!(
        d.last().map(|d| (d.ends[0].window.y, d.ends[1].window.y)),
        Some((2.5, 10.5))
    );
}

#[test]
fn a_line_crossing_the_near_plane_counts_from_where_it_enters() {
    // Perspective: the line from behind the eye (w < 0) to the front is clipped at the
    // near plane first, so its first dash starts at the clipped end, not at the vertex.
    let mut input = inputs(LineStipple::new(1, 0x0001));
    // glFrustum(−1, 1, −1, 1, 1, 10).
    input.projection = Mat4::from_cols(
        Vec4::new(1.0, 0.0, 0.0, 0.0),
        Vec4::new(0.0, 1.0, 0.0, 0.0),
        Vec4::new(0.0, 0.0, -11.0 / 9.0, -1.0),
        Vec4::new(0.0, 0.0, -20.0 / 9.0, 0.0),
    );
    let behind = Vec4::new(0.0, 0.0, 2.0, 1.0);
    let front = Vec4::new(0.5, 0.2, -5.0, 1.0);
    let d = dashes(Primitive::Lines, &[behind, front], &[0, 1], &input);
    assert!(!d.is_empty());
    let c = input.projection * front;
    let w1 = input.transform.window(c);
    let first = d[0].ends[0];
    // The clipped end is on the near plane: window z = 0 (depth range [0, 1]).
    assert!(first.window.z.abs() < 1e-5, "{first:?}");
    assert!(first.s > 0.0 && first.s < 1.0);
    assert!(first.window.x.is_finite() && first.window.y.is_finite());
    // Every dash lies between the clipped end and the visible vertex.
    for dash in &d {
        for e in dash.ends {
            assert!((e.window.x - w1.x).abs() <= (first.window.x - w1.x).abs() + 1e-3);
        }
    }
    // Entirely behind the eye: nothing, and no reset either (the counter is untouched).
    assert!(dashes(
        Primitive::Lines,
        &[behind, behind * Vec4::new(1.0, 1.0, 2.0, 1.0)],
        &[0, 1],
        &input
    )
    .is_empty());
}

#[test]
fn a_culled_segment_does_not_advance_the_counter() {
    // The middle segment of the strip lies wholly left of the view volume: the clipper
    // drops it before the stipple counts, so the third segment runs on from the first.
    let input = inputs(LineStipple::new(1, 0x00FF));
    let v = [
        p(0.5, 2.5),
        p(4.5, 2.5),
        p(-5.0, 9.5),
        p(-3.0, 12.5),
        p(20.0, 12.5),
    ];
    let d = dashes(Primitive::LineStrip, &v, &[0, 1, 2, 3, 4], &input);
    // Segment 0: 4 pixels, bits 0–3 on. Segment 1, clipped at x = 0, is x-major from 4.5
    // to 0: ⌈4.5⌉ = 5 pixels, bits 4–7 on, 8 off. Segment 2 is dropped and counts
    // nothing; segment 3, clipped to x from 0 to 20, starts at counter 9: bits 9–15 off,
    // then 16–23 (0–7 again) on.
    assert_eq!(d.len(), 3, "{d:?}");
    let xs: Vec<(f32, f32)> = d
        .iter()
        .map(|d| (d.ends[0].window.x, d.ends[1].window.x))
        .collect();
    assert_eq!(xs, [(0.5, 4.5), (4.5, 0.5), (7.0, 15.0)]);
}
