//! How a float argument that holds a GL token (`glTexParameterf(…, GL_LINEAR)`,
//! `glFogfv(GL_FOG_MODE, &mode)`) or a count becomes an integer. C programs pass tokens
//! through the float forms exactly, but a computed value can carry a fraction, and Mesa
//! 22.3's entry points convert it in three ways (measured with the values E ± 0.25, 0.5,
//! 0.75 of each token, `tests/c/float_params.c`):
//!
//! - glTexParameterf rounds, halves away from zero (`IROUND`): WRAP_S = CLAMP_TO_EDGE + 0.5
//!   is 0x8130, not a wrap mode, INVALID_ENUM; BASE_LEVEL 2.5 is 3;
//! - glLightModelf and glLightModelfv compare with the token's float exactly: COLOR_CONTROL =
//!   SEPARATE_SPECULAR_COLOR + 0.25 is INVALID_ENUM;
//! - every other call truncates, as C converts a float to GLint: glTexParameterfv (BASE_LEVEL
//!   2.5 is 2), glTexEnvf{,v}, glTexGen{f,d}{,v}, glFog{f,fv}, glPointParameterf{,v}.

use super::api::Entry;

/// The conversion a call applies; [`FloatToken::of`] gives a call's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FloatToken {
    /// Towards zero (C's float → int).
    Truncated,
    /// To the nearest integer, halves away from zero.
    Rounded,
    /// Only an integral value; a fraction names no token.
    Exact,
}

impl FloatToken {
    /// The conversion of `entry`'s float arguments.
    pub fn of(entry: Entry) -> Self {
        match entry {
            Entry::TexParameterf => FloatToken::Rounded,
            Entry::LightModelf | Entry::LightModelfv => FloatToken::Exact,
            _ => FloatToken::Truncated,
        }
    }

    /// The integer `v` converts to, or None (a fraction under `Exact`).
    pub fn integer(self, v: f64) -> Option<f64> {
        match self {
            FloatToken::Truncated => Some(v.trunc()),
            FloatToken::Rounded => Some(v.round()),
            FloatToken::Exact => (v.fract() == 0.0).then_some(v),
        }
    }

    /// The token `v` converts to: None for a NaN, ±∞, a negative value or one beyond 32
    /// bits (no GLenum has it: INVALID_ENUM).
    pub fn token(self, v: f64) -> Option<u32> {
        let t = self.integer(v)?;
        (0.0..4_294_967_296.0).contains(&t).then_some(t as u32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_rule_converts_the_fractions_mesa_measured() {
        let linear = 0x2601 as f64;
        assert_eq!(FloatToken::Truncated.token(linear + 0.75), Some(0x2601));
        assert_eq!(FloatToken::Truncated.token(linear - 0.25), Some(0x2600));
        assert_eq!(FloatToken::Rounded.token(linear + 0.5), Some(0x2602));
        assert_eq!(FloatToken::Rounded.token(linear - 0.5), Some(0x2601));
        assert_eq!(FloatToken::Rounded.token(-0.4), Some(0));
        assert_eq!(FloatToken::Exact.token(linear + 0.25), None);
        assert_eq!(FloatToken::Exact.token(linear), Some(0x2601));
        for rule in [
            FloatToken::Truncated,
            FloatToken::Rounded,
            FloatToken::Exact,
        ] {
            for v in [f64::NAN, f64::INFINITY, -1.0, 5e9] {
                assert_eq!(rule.token(v), None, "{rule:?} {v}");
            }
        }
    }

    #[test]
    fn calls_take_their_measured_rule() {
        assert_eq!(FloatToken::of(Entry::TexParameterf), FloatToken::Rounded);
        assert_eq!(FloatToken::of(Entry::TexParameterfv), FloatToken::Truncated);
        assert_eq!(FloatToken::of(Entry::LightModelfv), FloatToken::Exact);
        assert_eq!(FloatToken::of(Entry::Fogfv), FloatToken::Truncated);
    }
}
