//! Texture environments (GL 1.5 §3.8.13, ARB_texture_env_combine, ARB_texture_env_dot3,
//! ARB_texture_env_crossbar).
//!
//! Each unit holds a mode, an env colour, and the COMBINE setup for RGB and alpha: a function,
//! three sources with operands, and a scale. Every stage's result is clamped to [0, 1] after
//! scaling (the Regal bug that skips this clamp is hard case H14).

use glam::{Vec3, Vec4};

use super::error::{GlError, GlResult};

/// TEXTURE_ENV_MODE.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TexEnvMode {
    Modulate,
    Replace,
    Decal,
    Blend,
    Add,
    Combine,
}

/// COMBINE_RGB / COMBINE_ALPHA functions. DOT3 is valid for COMBINE_RGB only.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CombineFunc {
    Replace,
    Modulate,
    Add,
    AddSigned,
    Interpolate,
    Subtract,
    Dot3Rgb,
    Dot3Rgba,
}

impl CombineFunc {
    /// The unscaled, unclamped result per component (ARB_texture_env_combine Table 3.19a):
    /// REPLACE a0; MODULATE a0·a1; ADD a0 + a1; ADD_SIGNED a0 + a1 − ½;
    /// INTERPOLATE a0·a2 + a1·(1 − a2) (not mix(a0, a1, a2): hard case H13);
    /// SUBTRACT a0 − a1. DOT3 is vector-valued: see [`dot3`].
    pub fn eval(self, a: [f32; 3]) -> f32 {
        match self {
            CombineFunc::Replace => a[0],
            CombineFunc::Modulate => a[0] * a[1],
            CombineFunc::Add => a[0] + a[1],
            CombineFunc::AddSigned => a[0] + a[1] - 0.5,
            CombineFunc::Interpolate => a[0] * a[2] + a[1] * (1.0 - a[2]),
            CombineFunc::Subtract => a[0] - a[1],
            CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => 0.0,
        }
    }
}

/// DOT3_RGB(A): 4·((r0−½)(r1−½) + (g0−½)(g1−½) + (b0−½)(b1−½)), replicated to RGB (and
/// to alpha for DOT3_RGBA). RGB_SCALE still applies (ARB_texture_env_dot3).
pub fn dot3(a0: Vec3, a1: Vec3) -> f32 {
    4.0 * (a0 - Vec3::splat(0.5)).dot(a1 - Vec3::splat(0.5))
}

/// SOURCEn_RGB / SOURCEn_ALPHA.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CombineSource {
    /// This unit's texel.
    Texture,
    /// Unit n's texel (crossbar). INVALID_ENUM for n ≥ MAX_TEXTURE_UNITS.
    TextureUnit(u8),
    /// The env colour.
    Constant,
    /// The fragment's primary colour.
    PrimaryColor,
    /// The previous unit's result (the primary colour for unit 0).
    Previous,
}

/// OPERANDn_RGB / OPERANDn_ALPHA. Alpha operands accept SRC_ALPHA and ONE_MINUS_SRC_ALPHA only.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CombineOperand {
    SrcColor,
    OneMinusSrcColor,
    SrcAlpha,
    OneMinusSrcAlpha,
}

impl CombineOperand {
    pub fn is_alpha(self) -> bool {
        matches!(
            self,
            CombineOperand::SrcAlpha | CombineOperand::OneMinusSrcAlpha
        )
    }

    /// The operand applied to a source colour: C, 1 − C, (A,A,A), (1 − A, …).
    pub fn apply(self, source: Vec4) -> Vec3 {
        match self {
            CombineOperand::SrcColor => source.truncate(),
            CombineOperand::OneMinusSrcColor => Vec3::ONE - source.truncate(),
            CombineOperand::SrcAlpha => Vec3::splat(source.w),
            CombineOperand::OneMinusSrcAlpha => Vec3::splat(1.0 - source.w),
        }
    }
}

/// Argument 0, 1 or 2 of a combine function.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CombineArg {
    Arg0,
    Arg1,
    Arg2,
}

impl CombineArg {
    pub const ALL: [CombineArg; 3] = [CombineArg::Arg0, CombineArg::Arg1, CombineArg::Arg2];

    pub fn index(self) -> usize {
        match self {
            CombineArg::Arg0 => 0,
            CombineArg::Arg1 => 1,
            CombineArg::Arg2 => 2,
        }
    }
}

/// RGB_SCALE / ALPHA_SCALE: 1, 2 or 4 (anything else is INVALID_VALUE).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CombineScale {
    One,
    Two,
    Four,
}

impl CombineScale {
    pub fn from_f32(v: f32) -> GlResult<Self> {
        match v {
            1.0 => Ok(CombineScale::One),
            2.0 => Ok(CombineScale::Two),
            4.0 => Ok(CombineScale::Four),
            _ => Err(GlError::invalid_value(
                "RGB_SCALE and ALPHA_SCALE must be 1, 2 or 4",
            )),
        }
    }

    pub fn factor(self) -> f32 {
        match self {
            CombineScale::One => 1.0,
            CombineScale::Two => 2.0,
            CombineScale::Four => 4.0,
        }
    }
}

/// One glTexEnv parameter (target TEXTURE_ENV).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TexEnvParam {
    Mode(TexEnvMode),
    /// TEXTURE_ENV_COLOR, clamped to [0, 1].
    Color(Vec4),
    CombineRgb(CombineFunc),
    /// DOT3 functions: INVALID_ENUM.
    CombineAlpha(CombineFunc),
    SourceRgb(CombineArg, CombineSource),
    SourceAlpha(CombineArg, CombineSource),
    OperandRgb(CombineArg, CombineOperand),
    /// SRC_COLOR / ONE_MINUS_SRC_COLOR: INVALID_ENUM.
    OperandAlpha(CombineArg, CombineOperand),
    /// 1, 2 or 4.
    RgbScale(f32),
    AlphaScale(f32),
    /// GL 1.4's TEXTURE_LOD_BIAS of target TEXTURE_FILTER_CONTROL: added to the level of
    /// detail of every texture the unit samples (§3.8.8), the sum with the texture's own
    /// bias clamped to ±MAX_TEXTURE_LOD_BIAS. Kept as given.
    LodBias(f32),
    /// COORD_REPLACE of target POINT_SPRITE (ARB_point_sprite): the active unit's, kept
    /// with the point state (`point::PointSprite`), not the environment.
    CoordReplace(bool),
}

/// MAX_TEXTURE_LOD_BIAS: Mesa 22.3.6 llvmpipe's (measured).
pub const MAX_TEXTURE_LOD_BIAS: f32 = 16.0;

/// The combine setup of the RGB or the alpha portion.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Combine {
    pub func: CombineFunc,
    pub sources: [CombineSource; 3],
    pub operands: [CombineOperand; 3],
    pub scale: CombineScale,
}

/// One unit's texture environment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TexEnv {
    /// GL default: MODULATE.
    pub mode: TexEnvMode,
    /// GL default: (0, 0, 0, 0).
    pub color: Vec4,
    /// GL default: MODULATE; sources TEXTURE, PREVIOUS, CONSTANT; operands SRC_COLOR,
    /// SRC_COLOR, SRC_ALPHA; scale 1.
    pub rgb: Combine,
    /// GL default: MODULATE; sources TEXTURE, PREVIOUS, CONSTANT; operands SRC_ALPHA ×3;
    /// scale 1.
    pub alpha: Combine,
    /// TEXTURE_LOD_BIAS (TEXTURE_FILTER_CONTROL). GL default: 0.
    pub lod_bias: f32,
}

impl TexEnv {
    pub const DEFAULT: Self = Self {
        mode: TexEnvMode::Modulate,
        color: Vec4::ZERO,
        rgb: Combine {
            func: CombineFunc::Modulate,
            sources: [
                CombineSource::Texture,
                CombineSource::Previous,
                CombineSource::Constant,
            ],
            operands: [
                CombineOperand::SrcColor,
                CombineOperand::SrcColor,
                CombineOperand::SrcAlpha,
            ],
            scale: CombineScale::One,
        },
        alpha: Combine {
            func: CombineFunc::Modulate,
            sources: [
                CombineSource::Texture,
                CombineSource::Previous,
                CombineSource::Constant,
            ],
            operands: [CombineOperand::SrcAlpha; 3],
            scale: CombineScale::One,
        },
        lod_bias: 0.0,
    };

    /// glTexEnv: validates, then sets. `units` bounds TEXTUREn sources.
    pub fn set(&mut self, param: TexEnvParam, units: usize) -> GlResult {
        let check_source = |s: CombineSource| match s {
            CombineSource::TextureUnit(n) if usize::from(n) >= units => Err(GlError::invalid_enum(
                "TEXTUREn source beyond MAX_TEXTURE_UNITS",
            )),
            _ => Ok(s),
        };
        match param {
            TexEnvParam::Mode(m) => self.mode = m,
            // ±∞ → 1, 0; NaN → 0 (glam's clamp is max then min, and Rust's max drops a NaN);
            // Mesa's native path draws the same (`tests/fidelity_nonfinite.rs`).
            TexEnvParam::Color(c) => self.color = c.clamp(Vec4::ZERO, Vec4::ONE),
            TexEnvParam::CombineRgb(f) => self.rgb.func = f,
            TexEnvParam::CombineAlpha(CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba) => {
                return Err(GlError::invalid_enum("COMBINE_ALPHA does not accept DOT3"));
            }
            TexEnvParam::CombineAlpha(f) => self.alpha.func = f,
            TexEnvParam::SourceRgb(a, s) => self.rgb.sources[a.index()] = check_source(s)?,
            TexEnvParam::SourceAlpha(a, s) => self.alpha.sources[a.index()] = check_source(s)?,
            TexEnvParam::OperandRgb(a, o) => self.rgb.operands[a.index()] = o,
            TexEnvParam::OperandAlpha(a, o) => {
                if !o.is_alpha() {
                    return Err(GlError::invalid_enum(
                        "alpha operands must be (ONE_MINUS_)SRC_ALPHA",
                    ));
                }
                self.alpha.operands[a.index()] = o;
            }
            TexEnvParam::RgbScale(s) => self.rgb.scale = CombineScale::from_f32(s)?,
            TexEnvParam::AlphaScale(s) => self.alpha.scale = CombineScale::from_f32(s)?,
            TexEnvParam::LodBias(b) => self.lod_bias = b,
            // The point state's, which `FixedState::apply` sets instead.
            TexEnvParam::CoordReplace(_) => {}
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolate_argument_order_h13() {
        // Arg0 = 1, Arg1 = 0, Arg2 = 0.25 → 0.25 (Regal's mix(a0, a1, a2) gives 0.75).
        assert_eq!(CombineFunc::Interpolate.eval([1.0, 0.0, 0.25]), 0.25);
    }

    #[test]
    fn combine_table() {
        use CombineFunc::*;
        let a = [0.75, 0.5, 0.25];
        let table = [
            (Replace, 0.75),
            (Modulate, 0.375),
            (Add, 1.25),
            (AddSigned, 0.75),
            (Subtract, 0.25),
            (Interpolate, 0.75 * 0.25 + 0.5 * 0.75),
        ];
        for (f, want) in table {
            assert_eq!(f.eval(a), want, "{f:?}");
        }
        assert_eq!(dot3(Vec3::ONE, Vec3::ONE), 3.0);
        assert_eq!(dot3(Vec3::splat(0.5), Vec3::ONE), 0.0);
    }

    #[test]
    fn invalid_combine_alpha_keeps_the_state() {
        let mut env = TexEnv::DEFAULT;
        env.set(TexEnvParam::Mode(TexEnvMode::Replace), 8).unwrap();
        let before = env;
        let errors = [
            TexEnvParam::CombineAlpha(CombineFunc::Dot3Rgba),
            TexEnvParam::OperandAlpha(CombineArg::Arg1, CombineOperand::SrcColor),
            TexEnvParam::RgbScale(3.0),
            TexEnvParam::SourceRgb(CombineArg::Arg0, CombineSource::TextureUnit(8)),
        ];
        for p in errors {
            assert!(env.set(p, 8).is_err(), "{p:?}");
        }
        assert_eq!(env, before);
        assert_eq!(env.mode, TexEnvMode::Replace);
    }
}
