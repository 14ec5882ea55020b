//! Each technique's default polygon offset, and where a run's offset came from.
//!
//! A run takes the offset the command line gives (`--offset`), else the scene's
//! (`[shadow] polygon_offset`), else its technique's default below — so a technique renders
//! with the bias that works for it unless asked otherwise (`--offset none` shows the acne on
//! purpose).
//!
//! - `depth-compare`: Kilgard's "usually works" (1, 4) — four steps of the map's own depth
//!   format (r = 1/2ⁿ for n bits) and one slope unit.
//! - `dual8`: the 8-bit map holds ⌊255·z⌋ (Mesa's UNSIGNED_BYTE readback truncates) and the
//!   ramp gives ⌊256·s⌋, so between map and ramp lie up to two whole 8-bit steps; three
//!   steps of bias clear them: units = 3 · (2²⁴ − 1)/255/2 in a 24-bit buffer.
//! - `multidigit16` and `multidigit16-combine`: one 16-bit step, 256 units of a 24-bit
//!   buffer.
//! - `linear8`: (1, 4), which it reads as four ramp steps of its distance plane (polygon
//!   offset moves depths, not the colour its map is made of).
//! - `planar`, `projective`, `none`: no map of depths to compare, no offset.
//!
//! The 8- and 16-bit steps are depth distances, so their units follow the buffer: a 16-bit
//! buffer needs 1/256 of a 24-bit one's units, a 32-bit float buffer twice as many (both
//! measured, `tests/shadow_maps.rs`).

use std::fmt;

use super::{DepthBits, PolygonOffset, TechniqueId};

/// Where a run's polygon offset came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum OffsetSource {
    /// Neither the scene nor the command line gave one ([`default_offset`]).
    TechniqueDefault,
    /// The scene file's `[shadow] polygon_offset`.
    Scene,
    /// `--offset` (or a sweep's grid).
    CommandLine,
}

impl fmt::Display for OffsetSource {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(match self {
            OffsetSource::TechniqueDefault => "technique default",
            OffsetSource::Scene => "scene",
            OffsetSource::CommandLine => "command line",
        })
    }
}

/// The offset a technique renders with when none is given, for a light pass of `depth`.
pub fn default_offset(technique: TechniqueId, depth: DepthBits) -> Option<PolygonOffset> {
    let in_24_bit_units = |units: f32| match depth {
        DepthBits::D16 => units / 256.0,
        DepthBits::D24 => units,
        DepthBits::D32F => units * 2.0,
    };
    let units = match technique {
        TechniqueId::None
        | TechniqueId::Planar
        | TechniqueId::Projective
        | TechniqueId::OccluderPlanes
        | TechniqueId::OcclusionTextures => return None,
        TechniqueId::DepthCompare | TechniqueId::Accumulate | TechniqueId::Linear8 => 4.0,
        TechniqueId::Dual8 => in_24_bit_units(3.0 * 16_777_215.0 / 255.0 / 2.0),
        TechniqueId::Multidigit16 | TechniqueId::Multidigit16Combine => in_24_bit_units(256.0),
    };
    Some(PolygonOffset { factor: 1.0, units })
}

/// An offset as `FACTOR,UNITS`, or `none`.
pub fn offset_text(offset: Option<PolygonOffset>) -> String {
    offset.map_or("none".to_string(), |o| format!("{},{}", o.factor, o.units))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_8_and_16_bit_steps_follow_the_buffer_and_kilgards_rule_does_not() {
        let units = |t, d| default_offset(t, d).map(|o| o.units);
        let dual8 = units(TechniqueId::Dual8, DepthBits::D24).expect("dual8 has a bias");
        assert!((dual8 - 98_689.5).abs() < 0.5, "{dual8}");
        assert_eq!(
            units(TechniqueId::Dual8, DepthBits::D16),
            Some(dual8 / 256.0)
        );
        assert_eq!(
            units(TechniqueId::Dual8, DepthBits::D32F),
            Some(dual8 * 2.0)
        );
        assert_eq!(units(TechniqueId::Multidigit16, DepthBits::D16), Some(1.0));
        assert_eq!(
            units(TechniqueId::Multidigit16Combine, DepthBits::D32F),
            Some(512.0)
        );
        for d in DepthBits::ALL {
            assert_eq!(
                default_offset(TechniqueId::DepthCompare, d),
                Some(PolygonOffset {
                    factor: 1.0,
                    units: 4.0
                })
            );
            assert_eq!(default_offset(TechniqueId::Planar, d), None);
        }
        assert_eq!(
            offset_text(default_offset(TechniqueId::Linear8, DepthBits::D24)),
            "1,4"
        );
        assert_eq!(offset_text(None), "none");
    }
}
