//! Depth readback conversions, owned and named (the rules: `vocab::DepthRule`).
//!
//! A depth value z ∈ [0, 1] becomes an n-bit unsigned integer by one of two rules, with
//! M = 2^n − 1 and z clamped to [0, 1] first:
//! - `DepthRule::Truncate`: ⌊z·M⌋. Mesa 22.3 llvmpipe does this for GL_UNSIGNED_BYTE:
//!   z = 0.25 → 63, z = 0.5 → 127, z = 128.5/255 → 128.
//! - `DepthRule::Round`: ⌊z·M + ½⌋ (round half up). Mesa does (almost) this for
//!   GL_UNSIGNED_SHORT: z = 0.25 → 16384, z = 0.5 → 32768.
//!
//! The driver's own conversion (`ReadbackRule::Driver`) is not a rule here: it is read
//! from GL (`RenderTarget::read_depth_*`), never imitated on the CPU.
//!
//! The products are taken in f64, so z·M is exact for every f32 z and M < 2^32.

use crate::vocab::DepthRule;

fn convert(z: f32, max: f64, rule: DepthRule) -> f64 {
    let scaled = f64::from(z.clamp(0.0, 1.0)) * max;
    match rule {
        DepthRule::Truncate => scaled.floor(),
        DepthRule::Round => (scaled + 0.5).floor(),
    }
    .min(max)
}

/// z → u8 by `rule`: ⌊255z⌋ (Truncate) or ⌊255z + ½⌋ (Round). NaN becomes 0.
pub fn depth_to_u8(z: f32, rule: DepthRule) -> u8 {
    let z = if z.is_nan() { 0.0 } else { z };
    convert(z, 255.0, rule) as u8
}

/// z → u16 by `rule`: ⌊65535z⌋ or ⌊65535z + ½⌋. NaN becomes 0.
pub fn depth_to_u16(z: f32, rule: DepthRule) -> u16 {
    let z = if z.is_nan() { 0.0 } else { z };
    convert(z, 65535.0, rule) as u16
}

/// z → u32 by `rule`: ⌊(2³²−1)z⌋ or ⌊(2³²−1)z + ½⌋. NaN becomes 0.
pub fn depth_to_u32(z: f32, rule: DepthRule) -> u32 {
    let z = if z.is_nan() { 0.0 } else { z };
    convert(z, u32::MAX as f64, rule) as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn byte_boundaries() {
        let cases = [
            (0.0, 0, 0),
            (0.25, 63, 64),
            (0.5, 127, 128),
            // The f32 nearest 128.5/255 lies just below the tie, so both rules give 128.
            (128.5 / 255.0, 128, 128),
            (128.6 / 255.0, 128, 129),
            (1.0, 255, 255),
            (1.5, 255, 255),
            (-0.5, 0, 0),
        ];
        for (z, trunc, round) in cases {
            assert_eq!(depth_to_u8(z, DepthRule::Truncate), trunc, "truncate {z}");
            assert_eq!(depth_to_u8(z, DepthRule::Round), round, "round {z}");
        }
    }

    #[test]
    fn short_and_int_boundaries() {
        assert_eq!(depth_to_u16(0.25, DepthRule::Round), 16384);
        assert_eq!(depth_to_u16(0.25, DepthRule::Truncate), 16383);
        assert_eq!(depth_to_u16(0.5, DepthRule::Round), 32768);
        assert_eq!(depth_to_u16(1.0, DepthRule::Round), 65535);
        assert_eq!(depth_to_u32(1.0, DepthRule::Truncate), u32::MAX);
        assert_eq!(depth_to_u32(0.5, DepthRule::Round), 2147483648);
        assert_eq!(depth_to_u8(f32::NAN, DepthRule::Round), 0);
    }

    #[test]
    fn every_16_bit_value_round_trips() {
        for n in 0..=u16::MAX {
            let z = n as f32 / 65535.0;
            assert_eq!(depth_to_u16(z, DepthRule::Round), n);
        }
    }
}
