//! Fog (GL 1.5 §3.10): the fragment's RGB blended towards the fog colour by a factor of its
//! eye distance, after texturing and the colour sum and before the per-fragment tests.
//!
//! C' = f·C_r + (1 − f)·C_f on R, G and B (alpha unchanged), with f clamped to [0, 1]:
//! LINEAR f = (e − z)/(e − s); EXP f = exp(−d·z); EXP2 f = exp(−(d·z)²). The distance z is
//! what FOG_COORDINATE_SOURCE = FRAGMENT_DEPTH (the default) gives on Mesa: |z_eye| of each
//! vertex (`ffvertex_prog.c`, FDM_EYE_PLANE_ABS), interpolated, with f computed per fragment
//! — not the radial distance the spec also allows (measured, `tests/fidelity_fog.rs`).
//! Under FOG_COORD_SRC = FOG_COORD (GL 1.4) z is each vertex's fog coordinate instead, and
//! Mesa takes its magnitude too: a coordinate of −5 fogs as 5 (measured,
//! `tests/c/secondary.c`).

use glam::Vec4;

use super::error::{GlError, GlResult};

/// FOG_MODE. GL default: EXP.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FogMode {
    /// f = (end − z)/(end − start).
    Linear,
    /// f = exp(−density·z).
    Exp,
    /// f = exp(−(density·z)²).
    Exp2,
}

/// FOG_COORD_SRC (GL 1.4 §3.10; GL 1.4's FOG_COORDINATE_SOURCE). GL default:
/// FRAGMENT_DEPTH.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FogCoordSource {
    /// z = |z_eye| of each vertex.
    FragmentDepth,
    /// z = |c| of each vertex's fog coordinate c (glFogCoord, FOG_COORD_ARRAY).
    FogCoord,
}

/// One glFog parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FogParam {
    Mode(FogMode),
    /// ≥ 0, else INVALID_VALUE.
    Density(f32),
    Start(f32),
    End(f32),
    /// Clamped to [0, 1] when set.
    Color(Vec4),
    /// FOG_INDEX: the colour-index mode's fog index; kept and answered in RGBA, where
    /// nothing draws with it.
    Index(f32),
    CoordSource(FogCoordSource),
}

/// The fog parameters (the enable is FOG, a [`Toggle`](super::Toggle) around this).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fog {
    /// GL default: EXP.
    pub mode: FogMode,
    /// GL default: 1.
    pub density: f32,
    /// GL default: 0.
    pub start: f32,
    /// GL default: 1.
    pub end: f32,
    /// GL default: (0, 0, 0, 0); clamped to [0, 1] when set.
    pub color: Vec4,
    /// GL default: FRAGMENT_DEPTH.
    pub coord_source: FogCoordSource,
    /// FOG_INDEX, as set (glGetIntegerv rounds it). GL default: 0.
    pub index: f32,
}

impl Fog {
    pub const DEFAULT: Self = Self {
        mode: FogMode::Exp,
        density: 1.0,
        start: 0.0,
        end: 1.0,
        color: Vec4::ZERO,
        coord_source: FogCoordSource::FragmentDepth,
        index: 0.0,
    };

    /// glFog: a negative density is INVALID_VALUE (GL 1.5 §3.10) and changes nothing.
    pub fn set(&mut self, p: FogParam) -> GlResult {
        match p {
            FogParam::Mode(m) => self.mode = m,
            FogParam::Density(d) => {
                // `d < 0` as Mesa tests it: a NaN density is accepted.
                if d < 0.0 {
                    return Err(GlError::invalid_value("FOG_DENSITY must be ≥ 0"));
                }
                self.density = d;
            }
            FogParam::Start(s) => self.start = s,
            FogParam::End(e) => self.end = e,
            FogParam::Color(c) => self.color = c.clamp(Vec4::ZERO, Vec4::ONE),
            FogParam::Index(i) => self.index = i,
            FogParam::CoordSource(s) => self.coord_source = s,
        }
        Ok(())
    }

    /// (a, b, d·log₂e, d/√ln 2): LINEAR f = z·a + b, EXP f = 2^(−z·d·log₂e),
    /// EXP2 f = 2^(−(z·d/√ln 2)²) — the same values by exp2 instead of exp. Mesa's
    /// STATE_FOG_PARAMS_OPTIMIZED rule: a = −1/(e − s), b = e/(e − s); when e = s,
    /// a = 1 and b = −e.
    pub fn factor_params(&self) -> Vec4 {
        let a = if self.end == self.start {
            1.0
        } else {
            -1.0 / (self.end - self.start)
        };
        Vec4::new(
            a,
            -self.end * a,
            self.density * std::f32::consts::LOG2_E,
            self.density / std::f32::consts::LN_2.sqrt(),
        )
    }

    /// The fog factor f of eye distance `z`, clamped to [0, 1] (the formulas above).
    pub fn factor(&self, z: f32) -> f32 {
        let p = self.factor_params();
        let f = match self.mode {
            FogMode::Linear => z * p.x + p.y,
            FogMode::Exp => (-(z * p.z)).exp2(),
            FogMode::Exp2 => (-(z * p.w) * (z * p.w)).exp2(),
        };
        f.clamp(0.0, 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn factors_follow_the_spec_formulas() {
        let mut f = Fog::DEFAULT;
        assert!((f.factor(2.0) - (-2.0f32).exp()).abs() < 1e-6);
        f.mode = FogMode::Exp2;
        f.density = 0.5;
        assert!((f.factor(2.0) - (-1.0f32).exp()).abs() < 1e-6);
        f.mode = FogMode::Linear;
        f.start = 2.0;
        f.end = 10.0;
        assert!((f.factor(6.0) - 0.5).abs() < 1e-6);
        assert_eq!(f.factor(20.0), 0.0);
        assert_eq!(f.factor(0.0), 1.0);
    }

    #[test]
    fn negative_density_is_rejected_and_colour_clamped() {
        let mut f = Fog::DEFAULT;
        assert!(f.set(FogParam::Density(-0.1)).is_err());
        assert_eq!(f.density, 1.0);
        f.set(FogParam::Color(Vec4::new(2.0, -1.0, 0.5, 1.0)))
            .unwrap();
        assert_eq!(f.color, Vec4::new(1.0, 0.0, 0.5, 1.0));
        // FOG_INDEX is kept, and changes nothing else.
        f.set(FogParam::Index(3.0)).unwrap();
        assert_eq!(
            f,
            Fog {
                color: f.color,
                index: 3.0,
                ..Fog::DEFAULT
            }
        );
    }
}
