//! glSampleCoverage (GL 1.3 §3.2.1): the coverage value and its inversion, with the
//! SAMPLE_COVERAGE, SAMPLE_ALPHA_TO_COVERAGE and SAMPLE_ALPHA_TO_ONE enables. They act only
//! on multisample buffers (SAMPLE_BUFFERS = 1); the layer's buffers have none, as Mesa's
//! OSMesa buffer has none, so they are state: the value clamped to [0, 1] (NaN: 0), as
//! Mesa keeps it, in the MULTISAMPLE attribute group, the enables in ENABLE too.

/// The sample-coverage state. GL default: value 1, not inverted, all three disabled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SampleCoverage {
    pub value: f32,
    pub invert: bool,
    pub coverage: bool,
    pub alpha_to_coverage: bool,
    pub alpha_to_one: bool,
}

impl SampleCoverage {
    pub const DEFAULT: Self = Self {
        value: 1.0,
        invert: false,
        coverage: false,
        alpha_to_coverage: false,
        alpha_to_one: false,
    };

    /// glSampleCoverage(value, invert): the value clamped to [0, 1], NaN as 0.
    pub fn set(&mut self, value: f32, invert: bool) {
        self.value = if value.is_nan() {
            0.0
        } else {
            value.clamp(0.0, 1.0)
        };
        self.invert = invert;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_value_is_clamped_and_nan_is_zero() {
        let mut s = SampleCoverage::DEFAULT;
        s.set(1.7, true);
        assert_eq!((s.value, s.invert), (1.0, true));
        s.set(-1.0, false);
        assert_eq!(s.value, 0.0);
        s.set(f32::NAN, false);
        assert_eq!(s.value, 0.0);
        s.set(0.3, false);
        assert_eq!(s.value, 0.3);
    }
}
