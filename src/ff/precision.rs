//! Arithmetic precision of the texture environment, the register combiners and the alpha
//! test — a mode, not an accident (DESIGN "Precision is a mode").
//!
//! `Precision::Float` follows Mesa's native path on llvmpipe: fp32 with a clamp per stage,
//! the alpha test on unorm8 values rounded half to even.
//!
//! `Precision::Fixed8` models 8-bit combiners of the era (Dolphin's TEV emulation is the
//! model): every value is an integer 0..=255 standing for v/255, every stage clamps and
//! re-quantises. The rules, each with a worked example:
//! - quantise: q(v) = ⌊255·clamp(v, 0, 1) + ½⌋ — q(0.5) = 128 (127.5 rounds up).
//! - widen a factor: c' = c + (c >> 7), so 255 → 256 and multiplying by it is exact.
//! - MODULATE: (a·b' + 127) >> 8 — 128·128 → (16512 + 127) >> 8 = 64; a·255 → a.
//! - ADD: min(a + b, 255); SUBTRACT: max(a − b, 0).
//! - ADD_SIGNED: clamp(a + b − 128, 0, 255) — equal 8-bit depths k and 255 − k give 127
//!   (the ½ is 128, not 127.5), which GREATER 128 rejects: a tie shadows.
//! - INTERPOLATE: (a0·a2' + a1·(256 − a2') + 127) >> 8 — a0 = 255, a1 = 0, a2 = 64 → 64.
//! - DOT3: clamp(Σ (a−128)(b−128) >> 6, 0, 255) (4/255 ≈ 1/64, the era's shift).
//! - scale 2 or 4: clamp(v·s, 0, 255) — the same as scaling the unclamped result and
//!   clamping once, which is what the shader does.
//! - a stage: the function, then the scale, then the clamp (`combine_rgb`; checked against
//!   the GPU op by op in tests/emulate_fixed8_ops.rs).
//! - alpha test: q(alpha) against q(ref) as integers — GREATER 0.5 passes from 129.
//!
//! Register combiners in `Fixed8` use 9-bit signed values k ∈ [−256, 255] standing for
//! k/255, quantised after each mapping and each output with q9(v) = clamp(⌊255v + ½⌋,
//! −256, 255); products are ⌊a·b/255 + ½⌋; the −½ bias is −128.

use super::texenv::CombineFunc;

/// q(v) = ⌊255·clamp(v, 0, 1) + ½⌋.
pub fn quantise(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0 + 0.5).floor() as u8
}

fn widen(c: u8) -> u32 {
    u32::from(c) + (u32::from(c) >> 7)
}

/// (a·b' + 127) >> 8.
pub fn modulate(a: u8, b: u8) -> u8 {
    ((u32::from(a) * widen(b) + 127) >> 8) as u8
}

pub fn add(a: u8, b: u8) -> u8 {
    (u32::from(a) + u32::from(b)).min(255) as u8
}

/// clamp(a + b − 128, 0, 255).
pub fn add_signed(a: u8, b: u8) -> u8 {
    (i32::from(a) + i32::from(b) - 128).clamp(0, 255) as u8
}

pub fn subtract(a: u8, b: u8) -> u8 {
    a.saturating_sub(b)
}

/// (a0·a2' + a1·(256 − a2') + 127) >> 8.
pub fn interpolate(a0: u8, a1: u8, a2: u8) -> u8 {
    let w = widen(a2);
    ((u32::from(a0) * w + u32::from(a1) * (256 - w) + 127) >> 8) as u8
}

/// clamp(Σ (a−128)(b−128) >> 6, 0, 255).
pub fn dot3(a: [u8; 3], b: [u8; 3]) -> u8 {
    let s: i32 = a
        .iter()
        .zip(b)
        .map(|(&x, y)| (i32::from(x) - 128) * (i32::from(y) - 128))
        .sum();
    (s >> 6).clamp(0, 255) as u8
}

/// clamp(v·s, 0, 255) for RGB_SCALE / ALPHA_SCALE s ∈ {1, 2, 4}.
pub fn scale(v: u8, s: u32) -> u8 {
    (u32::from(v) * s).min(255) as u8
}

/// One Fixed8 combine stage on one component: the function's rule above, then the scale,
/// then the clamp to 0..=255 — what the generated shader computes per channel. DOT3 needs
/// the three components (`combine_rgb`); given one, it dots the splatted arguments.
pub fn combine_component(func: CombineFunc, a: [u8; 3], s: u32) -> u8 {
    let v = match func {
        CombineFunc::Replace => a[0],
        CombineFunc::Modulate => modulate(a[0], a[1]),
        CombineFunc::Add => add(a[0], a[1]),
        CombineFunc::AddSigned => add_signed(a[0], a[1]),
        CombineFunc::Interpolate => interpolate(a[0], a[1], a[2]),
        CombineFunc::Subtract => subtract(a[0], a[1]),
        CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => dot3([a[0]; 3], [a[1]; 3]),
    };
    scale(v, s)
}

/// One Fixed8 combine stage on RGB: arguments `args[i]` are (r, g, b); DOT3 gives the same
/// dot product (rule above) in all three channels, the other functions work per channel.
/// Example: DOT3_RGB of (255, 128, 128) with itself is 252, scale 2 → 255.
pub fn combine_rgb(func: CombineFunc, args: [[u8; 3]; 3], s: u32) -> [u8; 3] {
    match func {
        CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => [scale(dot3(args[0], args[1]), s); 3],
        _ => std::array::from_fn(|c| combine_component(func, args.map(|a| a[c]), s)),
    }
}

/// q9(v) = clamp(⌊255v + ½⌋, −256, 255).
pub fn quantise9(v: f32) -> i32 {
    ((v * 255.0 + 0.5).floor() as i32).clamp(-256, 255)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn worked_examples() {
        assert_eq!(quantise(0.5), 128);
        assert_eq!(quantise(127.4 / 255.0), 127);
        assert_eq!(modulate(128, 128), 64);
        assert_eq!(modulate(77, 255), 77);
        assert_eq!(modulate(255, 0), 0);
        assert_eq!(add(200, 100), 255);
        assert_eq!(subtract(10, 20), 0);
        assert_eq!(interpolate(255, 0, 64), 64);
        assert_eq!(interpolate(0, 255, 64), 191);
        assert_eq!(interpolate(255, 0, 255), 255);
        // 127² >> 6 = 252: the largest 8-bit signed value is 127/128, not 1.
        assert_eq!(dot3([255, 128, 128], [255, 128, 128]), 252);
        assert_eq!(dot3([192, 128, 128], [192, 128, 128]), 64);
        assert_eq!(scale(100, 4), 255);
        assert_eq!(quantise9(-1.5), -256);
        assert_eq!(quantise9(0.5), 128);
    }

    #[test]
    fn combine_stage_rules() {
        let f = |func, a, s| combine_component(func, a, s);
        assert_eq!(f(CombineFunc::Replace, [77, 0, 0], 4), 255);
        assert_eq!(f(CombineFunc::Replace, [63, 0, 0], 4), 252);
        assert_eq!(f(CombineFunc::Modulate, [128, 128, 0], 2), 128);
        assert_eq!(f(CombineFunc::Add, [200, 100, 0], 1), 255);
        // ADD_SIGNED's ½ is 128: 127 + 128 − 128 = 127; below zero clamps before scaling.
        assert_eq!(f(CombineFunc::AddSigned, [127, 128, 0], 2), 254);
        assert_eq!(f(CombineFunc::AddSigned, [0, 1, 0], 4), 0);
        assert_eq!(f(CombineFunc::Subtract, [1, 0, 0], 4), 4);
        // INTERPOLATE: a2 = 128 widens to 129: (255·129 + 127) >> 8 = 128 and
        // (255·127 + 127) >> 8 = 127 — the two halves of the tie land on either side.
        assert_eq!(f(CombineFunc::Interpolate, [255, 0, 128], 1), 128);
        assert_eq!(f(CombineFunc::Interpolate, [0, 255, 128], 1), 127);
        let up = [255, 128, 128];
        assert_eq!(combine_rgb(CombineFunc::Dot3Rgb, [up, up, up], 1), [252; 3]);
        assert_eq!(
            combine_rgb(CombineFunc::Dot3Rgba, [up, up, up], 2),
            [255; 3]
        );
        // Opposite vectors: the negative dot clamps to 0.
        let down = [0, 128, 128];
        assert_eq!(combine_rgb(CombineFunc::Dot3Rgb, [up, down, up], 4), [0; 3]);
        let c = combine_rgb(
            CombineFunc::Modulate,
            [[255, 128, 0], [255, 128, 255], [0; 3]],
            1,
        );
        assert_eq!(c, [255, 64, 0]);
    }

    /// Kilgard's 8-bit comparison in Fixed8: α = ADD_SIGNED(map, 255 − frag); lit iff
    /// α > 128 (ref 0.5). A tie and a 1-LSB-deeper map shadow; two LSB light — for every k.
    #[test]
    fn add_signed_tie_and_one_lsb_are_deterministic() {
        let reference = quantise(0.5);
        for k in 2u8..=253 {
            let alpha = |map: u8| add_signed(map, 255 - k);
            assert!(alpha(k) <= reference, "tie at {k}");
            assert!(alpha(k + 1) <= reference, "1 LSB at {k}");
            assert!(alpha(k + 2) > reference, "2 LSB at {k}");
        }
    }
}
