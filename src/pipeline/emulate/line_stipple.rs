//! Line stipple (GL 1.5 §3.4.2) cut on the CPU into the dashes Mesa draws. A fragment of a
//! line is drawn iff bit ⌊s/factor⌋ mod 16 of the pattern is set, s counting window pixels
//! along the line. Mesa (Gallium's draw module, which llvmpipe uses) implements this by
//! cutting each line into "on" runs *after clipping* and rasterising every run as a line of
//! its own, whose ends take the diamond-exit decisions of llvmpipe's line setup. A
//! fragment-shader counter on the whole line cannot reproduce those decisions at every
//! dash end, so the emulated path does what Mesa does: it computes the runs here, in f32
//! with Mesa's formulas, and draws each run as a line whose window coordinates are the
//! ones Mesa computed (the vertex shader places them exactly, `PositionSource::Window`).
//!
//! The rule, step by step, as Mesa computes it (`draw_pipe_clip.c`, `draw_pipe_stipple.c`):
//!
//! 1. **Segments.** GL_LINES: pairs, the counter reset at each. LINE_STRIP: consecutive
//!    vertices, reset at the first segment only. LINE_LOOP: as the strip, plus the segment
//!    from the last vertex back to the first, the counter running on.
//! 2. **Clipping first.** In clip coordinates c, a segment is cut by every plane with a
//!    distance d: the six of the view volume (w ± x, w ± y, w ± z) and the enabled user
//!    planes (p′·eye). An end outside a plane (d < 0) moves to t = d₀/(d₀ − d₁) along the
//!    segment (the largest t over the planes, from each end); a segment outside one plane
//!    at both ends, or whose cuts meet (t₀ + t₁ ≥ 1), is dropped — its counter reset
//!    passing to the next segment drawn, which counts the same. So a line crossing the near plane (w ≤ 0 at one end) is
//!    counted from where it enters the view volume, never from its invisible vertex.
//! 3. **Window coordinates**: x_w = (x_c · (1/w_c)) · (width/2) + (x + width/2) (a fused
//!    multiply-add for a vertex, llvmpipe's generated code; unfused for a clipped end), the same
//!    for y, and z_w = (z_c · (1/w_c)) · (f − n)/2 + (n + f)/2.
//! 4. **Runs.** length L = max(|Δx_w|, |Δy_w|) (√(Δx_w² + Δy_w²) for LINE_SMOOTH,
//!    [`LineLength`]); for i in 0..⌈L⌉ pixel i is on iff bit
//!    ((counter + i) / factor) mod 16 is set; each maximal on-run [a, b) becomes a dash from
//!    t = a/L to t = b/L (1 for a run reaching the end), its ends at W₀ + t·(W₁ − W₀) (the
//!    clipped ends themselves at t = 0 and 1). Then counter += ⌈L⌉ — an integer count,
//!    measured on Mesa 22.3.6: after segments of 69.25 and 52.5 pixels the next one starts
//!    at 123, not ⌊121.75⌋ (`tests/fidelity_line_stipple.rs`,
//!    `a_strip_counts_whole_pixels_per_segment`).
//!
//! A dash's attributes are the segment's, interpolated at the same screen parameter
//! (Mesa interpolates the vertex outputs linearly in window space); the emulated path
//! interpolates the vertex *inputs*, which is the same for every vertex stage linear in
//! its inputs (unlit colours, texture coordinates without texgen or with linear texgen)
//! and differs by rounding-sized amounts along lit lines.
//!
//! Known deviations, none seen in `tests/fidelity_line_stipple.rs`: Mesa's counter lives
//! across draws, so a strip whose first segment is culled runs on from the previous
//! draw's count, where here it starts at 0; a dash is drawn with w = 1, so attributes
//! along one dash of a perspective line are interpolated in window space (Mesa's are
//! perspective-correct within a dash); a dash end's depth goes through z_c = 2·z_w − 1,
//! which may round by one step of a 24-bit buffer; user clip distances are p′·eye here and
//! Mesa's own arithmetic there.

use glam::{Mat4, Vec4};

use crate::ff::{DepthRange, LineStipple, Primitive, Viewport};

/// One end of a dash: the point at parameter `s` from vertex `from` to vertex `to` of the
/// draw (object space, attributes alike), placed at `window`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DashEnd {
    pub from: u32,
    pub to: u32,
    pub s: f32,
    pub window: Vec4,
}

/// One drawn run of a stippled line, and the vertex whose values flat shading uses (the
/// segment's second vertex, GL 1.5 Table 2.8).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dash {
    pub ends: [DashEnd; 2],
    pub provoking: u32,
}

/// Mesa's viewport transform: window = ndc · scale + translate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WindowTransform {
    pub scale: [f32; 3],
    pub translate: [f32; 3],
}

impl WindowTransform {
    /// From glViewport and glDepthRange (`_mesa_get_viewport_xform`).
    pub fn new(v: Viewport, d: DepthRange) -> WindowTransform {
        let (hw, hh) = (0.5 * v.width as f32, 0.5 * v.height as f32);
        let (n, f) = (f64::from(d.near), f64::from(d.far));
        WindowTransform {
            scale: [hw, hh, (0.5 * (f - n)) as f32],
            translate: [hw + v.x as f32, hh + v.y as f32, (0.5 * (n + f)) as f32],
        }
    }

    /// The window coordinates of clip coordinates `c` (w kept as 1/w_c).
    pub fn window(&self, c: Vec4) -> Vec4 {
        if !fused() {
            return self.window_unfused(c);
        }
        let oow = 1.0 / c.w;
        let [sx, sy, sz] = self.scale;
        let [tx, ty, tz] = self.translate;
        Vec4::new(
            (c.x * oow).mul_add(sx, tx),
            (c.y * oow).mul_add(sy, ty),
            (c.z * oow).mul_add(sz, tz),
            oow,
        )
    }

    /// The window coordinates of a point the clipper made (`draw_pipe_clip.c`, compiled C:
    /// no fused multiply-add).
    pub fn window_unfused(&self, c: Vec4) -> Vec4 {
        let oow = 1.0 / c.w;
        let [sx, sy, sz] = self.scale;
        let [tx, ty, tz] = self.translate;
        Vec4::new(
            c.x * oow * sx + tx,
            c.y * oow * sy + ty,
            c.z * oow * sz + tz,
            oow,
        )
    }
}

/// Whether llvmpipe's generated code fuses its multiply-adds: it emits `llvm.fmuladd`,
/// which becomes one FMA instruction where the CPU has one.
fn fused() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("fma")
    }
    #[cfg(target_arch = "aarch64")]
    {
        true
    }
    #[cfg(not(any(target_arch = "x86_64", target_arch = "aarch64")))]
    {
        false
    }
}

/// Clip coordinates as Mesa's fixed-function vertex program computes them on llvmpipe:
/// MVP = P·MV formed on the CPU, then c = MVP₀·x, c = MVP₁·y + c, … with each MAD a fused
/// multiply-add (`llvm.fmuladd` on a CPU with FMA).
pub fn clip_coordinates(mvp: Mat4, p: Vec4) -> Vec4 {
    let [c0, c1, c2, c3] = [mvp.x_axis, mvp.y_axis, mvp.z_axis, mvp.w_axis];
    let mad = |col: Vec4, v: f32, acc: Vec4| match fused() {
        false => col * v + acc,
        true => Vec4::new(
            col.x.mul_add(v, acc.x),
            col.y.mul_add(v, acc.y),
            col.z.mul_add(v, acc.z),
            col.w.mul_add(v, acc.w),
        ),
    };
    mad(c3, p.w, mad(c2, p.z, mad(c1, p.y, c0 * p.x)))
}

/// What the dashes of one draw depend on besides its vertices.
pub struct StippleInputs<'a> {
    pub modelview: Mat4,
    pub projection: Mat4,
    pub transform: WindowTransform,
    /// The enabled user clip planes, in eye coordinates.
    pub clip_planes: &'a [Vec4],
    pub stipple: LineStipple,
    pub length: LineLength,
}

/// How a segment's length in window pixels is measured for the counter (step 4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LineLength {
    /// Aliased lines: max(|Δx|, |Δy|), the pixels along the major axis (GL 1.5 §3.4.2).
    MajorAxis,
    /// LINE_SMOOTH: √(Δx² + Δy²), the distance along the line, as Mesa's stipple stage
    /// measures an antialiased line (GL 1.5 §3.4.4 counts its fragments in unit lengths).
    Euclidean,
}

impl LineLength {
    /// The length of a segment whose window ends differ by `dx` and `dy`.
    pub fn of(self, dx: f32, dy: f32) -> f32 {
        match self {
            LineLength::MajorAxis => dx.abs().max(dy.abs()),
            LineLength::Euclidean => (dx * dx + dy * dy).sqrt(),
        }
    }
}

/// One segment of a line primitive: its vertex indices, whether it resets the counter, and
/// the vertex whose values flat shading gives its dashes (a line's second vertex, GL 1.5
/// Table 2.8; a polygon edge's polygon's).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Segment {
    pub from: u32,
    pub to: u32,
    pub reset: bool,
    pub provoking: u32,
}

/// The segments of a line primitive over `indices` (step 1); none for other primitives.
pub fn segments(primitive: Primitive, indices: &[u32]) -> Vec<Segment> {
    let seg = |from: u32, to: u32, reset: bool| Segment {
        from,
        to,
        reset,
        provoking: to,
    };
    match primitive {
        Primitive::Lines => indices
            .chunks_exact(2)
            .map(|p| seg(p[0], p[1], true))
            .collect(),
        Primitive::LineStrip | Primitive::LineLoop => {
            let mut out: Vec<Segment> = indices
                .windows(2)
                .enumerate()
                .map(|(i, p)| seg(p[0], p[1], i == 0))
                .collect();
            if let (Primitive::LineLoop, [first, .., last]) = (primitive, indices) {
                out.push(seg(*last, *first, false));
            }
            out
        }
        _ => Vec::new(),
    }
}

/// A segment after clipping: each end's parameter along the segment, clip coordinates,
/// and whether the clipper made it.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Clipped {
    s: [f32; 2],
    clip: [Vec4; 2],
    moved: [bool; 2],
}

/// Step 2 for the segment from clip coordinates `c0` to `c1` with the per-plane distances
/// `d0`, `d1` (equal lengths); `None` when nothing is left.
fn clip_segment(c0: Vec4, c1: Vec4, d0: &[f32], d1: &[f32]) -> Option<Clipped> {
    let (mut t0, mut t1) = (0.0f32, 0.0f32);
    let (mut out0, mut out1) = (false, false);
    for (&a, &b) in d0.iter().zip(d1) {
        if !(a.is_finite() && b.is_finite()) || (a < 0.0 && b < 0.0) {
            return None;
        }
        if b < 0.0 {
            t1 = t1.max(b / (b - a));
            out1 = true;
        }
        if a < 0.0 {
            t0 = t0.max(a / (a - b));
            out0 = true;
        }
        if t0 + t1 >= 1.0 {
            return None;
        }
    }
    Some(Clipped {
        s: [
            if out0 { t0 } else { 0.0 },
            if out1 { 1.0 - t1 } else { 1.0 },
        ],
        clip: [
            if out0 { lerp(t0, c0, c1) } else { c0 },
            if out1 { lerp(t1, c1, c0) } else { c1 },
        ],
        moved: [out0, out1],
    })
}

/// The longest segment counted, in pixels.
const MAX_RUN_PIXELS: f32 = 16_777_216.0;

/// Step 4: the on-runs of a segment of window length `length` with the counter at
/// `counter`, as (t_start, t_end) fractions; `counter` moves on by ⌈length⌉.
pub fn runs(stipple: LineStipple, counter: &mut i64, length: f32) -> Vec<(f32, f32)> {
    // ⌈L⌉, or 0 for an infinite or NaN length; a clipped line is never longer than the
    // viewport bounds, far below the cap.
    let int_length = if length.is_finite() {
        length.ceil().min(MAX_RUN_PIXELS) as i64
    } else {
        0
    };
    let base = *counter;
    let factor = i64::from(stipple.factor);
    let mut out = Vec::new();
    let (mut start, mut on) = (0.0f32, false);
    for i in 0..int_length {
        // stipple_test: bit ((counter + i) / factor) & 15.
        let bit = stipple.pattern >> (((base + i) / factor) & 15) & 1 == 1;
        if bit != on {
            if on {
                out.push((start / length, i as f32 / length));
            } else {
                start = i as f32;
            }
            on = bit;
        }
    }
    if on && start < length {
        out.push((start / length, 1.0));
    }
    *counter += int_length;
    out
}

/// The dashes of a line draw over `positions` (object coordinates) in the vertex order
/// `indices`: steps 1 to 4.
pub fn dashes(
    primitive: Primitive,
    positions: &[Vec4],
    indices: &[u32],
    inputs: &StippleInputs,
) -> Vec<Dash> {
    dashes_of_segments(&segments(primitive, indices), positions, inputs)
}

/// The dashes of `segments` in order over `positions`. A reset carried by a segment that
/// clipping drops passes to the next segment drawn (for a line draw the same counter as
/// dropping it: nothing was counted between; for a polygon's outline the reset of its
/// first edge).
pub fn dashes_of_segments(
    segments: &[Segment],
    positions: &[Vec4],
    inputs: &StippleInputs,
) -> Vec<Dash> {
    let eye: Vec<Vec4> = positions.iter().map(|&p| inputs.modelview * p).collect();
    let mvp = inputs.projection * inputs.modelview;
    let clip: Vec<Vec4> = positions
        .iter()
        .map(|&p| clip_coordinates(mvp, p))
        .collect();
    let distances = |i: usize| -> Vec<f32> {
        let c = clip[i];
        let mut d = vec![
            c.x + c.w,
            c.w - c.x,
            c.y + c.w,
            c.w - c.y,
            c.z + c.w,
            c.w - c.z,
        ];
        d.extend(inputs.clip_planes.iter().map(|p| p.dot(eye[i])));
        d
    };
    let mut counter = 0i64;
    let mut reset = false;
    let mut out = Vec::new();
    for &seg in segments {
        reset |= seg.reset;
        let (a, b) = (seg.from as usize, seg.to as usize);
        if a >= clip.len() || b >= clip.len() {
            continue;
        }
        let Some(cut) = clip_segment(clip[a], clip[b], &distances(a), &distances(b)) else {
            continue;
        };
        if std::mem::take(&mut reset) {
            counter = 0;
        }
        let window = |k: usize| match cut.moved[k] {
            true => inputs.transform.window_unfused(cut.clip[k]),
            false => inputs.transform.window(cut.clip[k]),
        };
        let w = [window(0), window(1)];
        let length = inputs.length.of(w[0].x - w[1].x, w[0].y - w[1].y);
        let at = |t: f32, end: usize| -> DashEnd {
            let (window, s) = if (end == 0 && t > 0.0) || (end == 1 && t < 1.0) {
                (lerp(t, w[0], w[1]), cut.s[0] + t * (cut.s[1] - cut.s[0]))
            } else {
                (w[end], cut.s[end])
            };
            DashEnd {
                from: seg.from,
                to: seg.to,
                s,
                window,
            }
        };
        for (t0, t1) in runs(inputs.stipple, &mut counter, length) {
            out.push(Dash {
                ends: [at(t0, 0), at(t1, 1)],
                provoking: seg.provoking,
            });
        }
    }
    out
}

/// LINTERP(t, a, b) = a + t·(b − a), per component, in Mesa's order of operations.
fn lerp(t: f32, a: Vec4, b: Vec4) -> Vec4 {
    Vec4::new(
        a.x + t * (b.x - a.x),
        a.y + t * (b.y - a.y),
        a.z + t * (b.z - a.z),
        a.w + t * (b.w - a.w),
    )
}

#[cfg(test)]
#[path = "line_stipple_tests.rs"]
mod tests;
