//! Depth buffers and how their values become integers.
//!
//! A depth value z ∈ [0, 1] becomes an n-bit unsigned integer, M = 2ⁿ − 1, z clamped to
//! [0, 1] first, by a [`DepthRule`] computed on the CPU — or by the driver itself, when a
//! program asks glReadPixels for the integer type ([`ReadbackRule::Driver`]). The two are
//! different things: a rule is arithmetic this crate performs and tests; the driver's
//! conversion is whatever Mesa does (measured: UNSIGNED_BYTE truncates, UNSIGNED_SHORT
//! rounds), which is why no CPU function ever takes "the driver" as a rule.

use serde::{Deserialize, Serialize};

use super::Named;

/// The depth buffer format of a target (and of a light's shadow-map pass).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum DepthBits {
    /// 16-bit unsigned normalised; no stencil.
    D16,
    /// 24-bit unsigned normalised, always packed with 8 stencil bits (DEPTH24_STENCIL8).
    D24,
    /// 32-bit float; packed with 8 stencil bits (DEPTH32F_STENCIL8) when stencil is asked for.
    D32F,
}

impl DepthBits {
    pub const ALL: [DepthBits; 3] = [DepthBits::D16, DepthBits::D24, DepthBits::D32F];

    /// The number of depth bits the format names.
    pub fn bits(self) -> u32 {
        match self {
            DepthBits::D16 => 16,
            DepthBits::D24 => 24,
            DepthBits::D32F => 32,
        }
    }

    /// Whether the format stores depth as a float.
    pub fn is_float(self) -> bool {
        matches!(self, DepthBits::D32F)
    }

    /// What `units` of glPolygonOffset move a depth by on llvmpipe, in the format's own
    /// steps: one unit is two LSBs of a 16- or 24-bit buffer (measured at 24 bits: ±1 unit
    /// → ±2 LSB, `../notes` H7; a 16-bit buffer needs 1/256 of the units a 24-bit one
    /// does for the same shift), and 2⁻²⁴ of a 32-bit float buffer at depths in
    /// [0.5, 1) (GL: r = 2^(e − 23) for the largest exponent e of the primitive's depths;
    /// twice the units a 24-bit buffer needs).
    pub fn offset_units_in_steps(self, units: f32) -> String {
        let steps = 2.0 * f64::from(units);
        match self {
            DepthBits::D16 => format!("{} LSB of 16-bit depth", short(steps)),
            DepthBits::D24 => format!("{} LSB of 24-bit depth", short(steps)),
            DepthBits::D32F => format!(
                "{} × 2⁻²⁴ of 32-bit float depth in [0.5, 1)",
                short(f64::from(units))
            ),
        }
    }
}

/// A number with at most 4 decimals, no trailing zeros (`-0` printed as `0`).
pub fn short(x: f64) -> String {
    let t = format!("{x:.4}");
    let t = t.trim_end_matches('0').trim_end_matches('.');
    if t == "-0" {
        "0".to_string()
    } else {
        t.to_string()
    }
}

impl Named for DepthBits {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("16", DepthBits::D16),
        ("24", DepthBits::D24),
        ("32f", DepthBits::D32F),
    ];

    fn help(self) -> &'static str {
        match self {
            DepthBits::D16 => "16-bit unsigned normalised; no stencil",
            DepthBits::D24 => "24-bit unsigned normalised, with 8 stencil bits",
            DepthBits::D32F => "32-bit float (8 stencil bits when asked for)",
        }
    }
}

/// A CPU rule from z ∈ [0, 1] to an n-bit integer (M = 2ⁿ − 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DepthRule {
    /// ⌊z·M⌋.
    Truncate,
    /// ⌊z·M + ½⌋ (round half up).
    Round,
}

impl DepthRule {
    /// The rule Mesa's native path follows for an n-bit readback (measured on llvmpipe):
    /// truncation for bytes, rounding for shorts and ints.
    pub fn mesa_native(bits: u32) -> DepthRule {
        if bits <= 8 {
            DepthRule::Truncate
        } else {
            DepthRule::Round
        }
    }
}

/// How an integer depth map is read back: by the driver (glReadPixels with the integer
/// type, as the era's programs did) or as FLOAT converted on the CPU by a [`DepthRule`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ReadbackRule {
    /// glReadPixels with the integer type: the driver's own conversion.
    Driver,
    /// glReadPixels(FLOAT), then the rule on the CPU.
    Cpu(DepthRule),
}

impl Named for ReadbackRule {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("driver", ReadbackRule::Driver),
        ("truncate", ReadbackRule::Cpu(DepthRule::Truncate)),
        ("round", ReadbackRule::Cpu(DepthRule::Round)),
    ];

    fn help(self) -> &'static str {
        match self {
            ReadbackRule::Driver => {
                "glReadPixels with the integer type (Mesa truncates bytes, rounds shorts)"
            }
            ReadbackRule::Cpu(DepthRule::Truncate) => "FLOAT read back, then ⌊z·M⌋ on the CPU",
            ReadbackRule::Cpu(DepthRule::Round) => "FLOAT read back, then ⌊z·M + ½⌋ on the CPU",
        }
    }
}

impl Serialize for ReadbackRule {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl<'de> Deserialize<'de> for ReadbackRule {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        ReadbackRule::from_name(&name).ok_or_else(|| {
            serde::de::Error::unknown_variant(&name, &["driver", "truncate", "round"])
        })
    }
}

#[cfg(test)]
mod offset_unit_tests {
    use super::DepthBits;

    #[test]
    fn a_unit_is_two_lsbs_of_a_fixed_point_buffer_and_one_2_to_the_minus_24_of_a_float_one() {
        assert_eq!(
            DepthBits::D24.offset_units_in_steps(4.0),
            "8 LSB of 24-bit depth"
        );
        assert_eq!(
            DepthBits::D16.offset_units_in_steps(0.5),
            "1 LSB of 16-bit depth"
        );
        assert_eq!(
            DepthBits::D32F.offset_units_in_steps(1.25),
            "1.25 × 2⁻²⁴ of 32-bit float depth in [0.5, 1)"
        );
    }
}
