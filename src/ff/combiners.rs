//! NV_register_combiners state (rules: `notes/register-combiners.md`).
//!
//! When REGISTER_COMBINERS_NV is enabled it replaces texture environments, colour sum and
//! fog. This module holds the state and validates it as the extension does; the arithmetic
//! lives in [`Mapping::apply`] and [`output`], shared by the shader generator's CPU oracle
//! and the tests. Registers hold values in [−1, 1].

use glam::Vec4;

use super::error::{GlError, GlResult};

/// GL_MAX_GENERAL_COMBINERS_NV modelled here.
pub const MAX_GENERAL_COMBINERS: usize = 8;

/// Combiner registers, including the output-only DISCARD and the final-combiner-only
/// pseudo-registers E_TIMES_F and SPARE0_PLUS_SECONDARY_COLOR.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Register {
    Zero,
    ConstantColor0,
    ConstantColor1,
    Fog,
    PrimaryColor,
    SecondaryColor,
    Spare0,
    Spare1,
    /// TEXTUREn_ARB.
    Texture(u8),
    Discard,
    ETimesF,
    Spare0PlusSecondaryColor,
}

impl Register {
    /// Readable by a general stage.
    pub fn is_general_input(self) -> bool {
        !matches!(
            self,
            Register::Discard | Register::ETimesF | Register::Spare0PlusSecondaryColor
        )
    }

    /// Writable by a general stage's outputs (DISCARD included).
    pub fn is_output(self) -> bool {
        matches!(
            self,
            Register::Discard
                | Register::PrimaryColor
                | Register::SecondaryColor
                | Register::Spare0
                | Register::Spare1
                | Register::Texture(_)
        )
    }
}

/// The RGB or the ALPHA portion of a general stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Portion {
    Rgb,
    Alpha,
}

/// Which components an input reads: RGB, ALPHA (replicated) or BLUE (alpha portion only).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ComponentUsage {
    Rgb,
    Alpha,
    Blue,
}

/// General-stage variables A–D.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Variable {
    A,
    B,
    C,
    D,
}

impl Variable {
    pub fn index(self) -> usize {
        match self {
            Variable::A => 0,
            Variable::B => 1,
            Variable::C => 2,
            Variable::D => 3,
        }
    }
}

/// Final-combiner variables A–G.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FinalVariable {
    A,
    B,
    C,
    D,
    E,
    F,
    G,
}

impl FinalVariable {
    pub fn index(self) -> usize {
        match self {
            FinalVariable::A => 0,
            FinalVariable::B => 1,
            FinalVariable::C => 2,
            FinalVariable::D => 3,
            FinalVariable::E => 4,
            FinalVariable::F => 5,
            FinalVariable::G => 6,
        }
    }
}

/// Input mappings, applied per component e.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Mapping {
    UnsignedIdentity,
    UnsignedInvert,
    ExpandNormal,
    ExpandNegate,
    HalfBiasNormal,
    HalfBiasNegate,
    SignedIdentity,
    SignedNegate,
}

impl Mapping {
    /// UNSIGNED_IDENTITY max(0,e); UNSIGNED_INVERT 1 − clamp(e,0,1); EXPAND_NORMAL
    /// 2·max(0,e) − 1; EXPAND_NEGATE −2·max(0,e) + 1; HALF_BIAS_NORMAL max(0,e) − ½;
    /// HALF_BIAS_NEGATE −max(0,e) + ½; SIGNED_IDENTITY e; SIGNED_NEGATE −e.
    pub fn apply(self, e: f32) -> f32 {
        match self {
            Mapping::UnsignedIdentity => e.max(0.0),
            Mapping::UnsignedInvert => 1.0 - e.clamp(0.0, 1.0),
            Mapping::ExpandNormal => 2.0 * e.max(0.0) - 1.0,
            Mapping::ExpandNegate => -2.0 * e.max(0.0) + 1.0,
            Mapping::HalfBiasNormal => e.max(0.0) - 0.5,
            Mapping::HalfBiasNegate => -e.max(0.0) + 0.5,
            Mapping::SignedIdentity => e,
            Mapping::SignedNegate => -e,
        }
    }
}

/// Output scale.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CombinerScale {
    None,
    ByTwo,
    ByFour,
    ByOneHalf,
}

impl CombinerScale {
    pub fn factor(self) -> f32 {
        match self {
            CombinerScale::None => 1.0,
            CombinerScale::ByTwo => 2.0,
            CombinerScale::ByFour => 4.0,
            CombinerScale::ByOneHalf => 0.5,
        }
    }
}

/// Output bias.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CombinerBias {
    None,
    ByNegativeOneHalf,
}

impl CombinerBias {
    pub fn value(self) -> f32 {
        match self {
            CombinerBias::None => 0.0,
            CombinerBias::ByNegativeOneHalf => -0.5,
        }
    }
}

/// Component-wise product or dot product (replicated) for AB and CD.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Product {
    Componentwise,
    Dot,
}

/// The third output: AB + CD, or MUX = (SPARE0.a ≥ ½) ? CD : AB.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SumOrMux {
    Sum,
    Mux,
}

/// r ↦ clamp((r + bias)·scale, −1, 1): each of AB, CD and SUM/MUX.
pub fn output(r: f32, scale: CombinerScale, bias: CombinerBias) -> f32 {
    ((r + bias.value()) * scale.factor()).clamp(-1.0, 1.0)
}

/// glCombinerInputNV / glFinalCombinerInputNV arguments.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct CombinerInput {
    pub register: Register,
    pub mapping: Mapping,
    pub usage: ComponentUsage,
}

/// glCombinerOutputNV arguments.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct CombinerOutput {
    pub ab: Register,
    pub cd: Register,
    pub sum: Register,
    pub scale: CombinerScale,
    pub bias: CombinerBias,
    pub ab_product: Product,
    pub cd_product: Product,
    pub sum_or_mux: SumOrMux,
}

impl CombinerOutput {
    /// GL default: AB and CD discarded, SUM to SPARE0, no scale, no bias, products, sum.
    pub const DEFAULT: Self = Self {
        ab: Register::Discard,
        cd: Register::Discard,
        sum: Register::Spare0,
        scale: CombinerScale::None,
        bias: CombinerBias::None,
        ab_product: Product::Componentwise,
        cd_product: Product::Componentwise,
        sum_or_mux: SumOrMux::Sum,
    };
}

/// glCombinerParameterNV.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CombinerParam {
    /// 1..=MAX_GENERAL_COMBINERS, else INVALID_VALUE.
    NumGeneralCombiners(i32),
    ColorSumClamp(bool),
    /// Clamped to [0, 1].
    ConstantColor0(Vec4),
    ConstantColor1(Vec4),
}

/// One portion (RGB or alpha) of a general stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct StagePortion {
    /// A, B, C, D.
    pub inputs: [CombinerInput; 4],
    pub output: CombinerOutput,
}

impl StagePortion {
    /// GL default: A = PRIMARY_COLOR, B = ZERO inverted (1), C = D = ZERO, so an untouched
    /// stage writes the primary colour to SPARE0.
    pub const fn default_for(usage: ComponentUsage) -> Self {
        const fn input(
            register: Register,
            mapping: Mapping,
            usage: ComponentUsage,
        ) -> CombinerInput {
            CombinerInput {
                register,
                mapping,
                usage,
            }
        }
        Self {
            inputs: [
                input(Register::PrimaryColor, Mapping::UnsignedIdentity, usage),
                input(Register::Zero, Mapping::UnsignedInvert, usage),
                input(Register::Zero, Mapping::UnsignedIdentity, usage),
                input(Register::Zero, Mapping::UnsignedIdentity, usage),
            ],
            output: CombinerOutput::DEFAULT,
        }
    }
}

/// One general combiner stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct GeneralStage {
    pub rgb: StagePortion,
    pub alpha: StagePortion,
}

impl GeneralStage {
    pub const DEFAULT: Self = Self {
        rgb: StagePortion::default_for(ComponentUsage::Rgb),
        alpha: StagePortion::default_for(ComponentUsage::Alpha),
    };

    pub fn portion_mut(&mut self, portion: Portion) -> &mut StagePortion {
        match portion {
            Portion::Rgb => &mut self.rgb,
            Portion::Alpha => &mut self.alpha,
        }
    }
}

/// The whole register-combiner state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegisterCombiners {
    /// GL default: 1.
    pub num_general: usize,
    /// GL default: FALSE.
    pub color_sum_clamp: bool,
    /// GL default: (0, 0, 0, 0) both.
    pub constant_color: [Vec4; 2],
    /// GL default: [`GeneralStage::DEFAULT`] each.
    pub stages: [GeneralStage; MAX_GENERAL_COMBINERS],
    /// A–G. GL default: A = FOG.a, B = SPARE0_PLUS_SECONDARY_COLOR, C = FOG.rgb,
    /// D = E = F = ZERO, G = SPARE0.a, all UNSIGNED_IDENTITY.
    pub final_inputs: [CombinerInput; 7],
}

impl RegisterCombiners {
    pub const DEFAULT: Self = {
        const fn input(register: Register, usage: ComponentUsage) -> CombinerInput {
            CombinerInput {
                register,
                mapping: Mapping::UnsignedIdentity,
                usage,
            }
        }
        Self {
            num_general: 1,
            color_sum_clamp: false,
            constant_color: [Vec4::ZERO; 2],
            stages: [GeneralStage::DEFAULT; MAX_GENERAL_COMBINERS],
            final_inputs: [
                input(Register::Fog, ComponentUsage::Alpha),
                input(Register::Spare0PlusSecondaryColor, ComponentUsage::Rgb),
                input(Register::Fog, ComponentUsage::Rgb),
                input(Register::Zero, ComponentUsage::Rgb),
                input(Register::Zero, ComponentUsage::Rgb),
                input(Register::Zero, ComponentUsage::Rgb),
                input(Register::Spare0, ComponentUsage::Alpha),
            ],
        }
    };

    /// The stages that run: `stages[..num_general]`.
    pub fn active_stages(&self) -> &[GeneralStage] {
        &self.stages[..self.num_general.min(MAX_GENERAL_COMBINERS)]
    }

    /// glCombinerParameterNV.
    pub fn set_parameter(&mut self, param: CombinerParam) -> GlResult {
        match param {
            CombinerParam::NumGeneralCombiners(n) => {
                let n = usize::try_from(n)
                    .ok()
                    .filter(|n| (1..=MAX_GENERAL_COMBINERS).contains(n))
                    .ok_or(GlError::invalid_value(
                        "NUM_GENERAL_COMBINERS must be in [1, MAX_GENERAL_COMBINERS]",
                    ))?;
                self.num_general = n;
            }
            CombinerParam::ColorSumClamp(b) => self.color_sum_clamp = b,
            CombinerParam::ConstantColor0(c) => {
                self.constant_color[0] = c.clamp(Vec4::ZERO, Vec4::ONE)
            }
            CombinerParam::ConstantColor1(c) => {
                self.constant_color[1] = c.clamp(Vec4::ZERO, Vec4::ONE)
            }
        }
        Ok(())
    }

    /// glCombinerInputNV. `units` bounds TEXTUREn registers.
    pub fn set_input(
        &mut self,
        stage: u8,
        portion: Portion,
        variable: Variable,
        input: CombinerInput,
        units: usize,
    ) -> GlResult {
        let stage = check_stage(stage)?;
        check_texture_register(input.register, units)?;
        if !input.register.is_general_input() {
            return Err(GlError::invalid_enum(
                "DISCARD, E_TIMES_F and SPARE0_PLUS_SECONDARY_COLOR are not general-stage inputs",
            ));
        }
        match (portion, input.usage) {
            (Portion::Rgb, ComponentUsage::Blue) => {
                return Err(GlError::invalid_operation("BLUE usage in the RGB portion"));
            }
            (Portion::Alpha, ComponentUsage::Rgb) => {
                return Err(GlError::invalid_operation("RGB usage in the ALPHA portion"));
            }
            _ => {}
        }
        if input.register == Register::Fog && input.usage == ComponentUsage::Alpha {
            return Err(GlError::invalid_operation(
                "FOG alpha is only readable by the final combiner",
            ));
        }
        self.stages[stage].portion_mut(portion).inputs[variable.index()] = input;
        Ok(())
    }

    /// glCombinerOutputNV.
    pub fn set_output(
        &mut self,
        stage: u8,
        portion: Portion,
        output: CombinerOutput,
        units: usize,
    ) -> GlResult {
        let stage = check_stage(stage)?;
        for r in [output.ab, output.cd, output.sum] {
            check_texture_register(r, units)?;
            if !r.is_output() {
                return Err(GlError::invalid_enum(
                    "outputs must be DISCARD or a read/write register",
                ));
            }
        }
        if portion == Portion::Alpha
            && (output.ab_product == Product::Dot || output.cd_product == Product::Dot)
        {
            return Err(GlError::invalid_value("dot products are RGB-portion only"));
        }
        if output.bias == CombinerBias::ByNegativeOneHalf
            && matches!(
                output.scale,
                CombinerScale::ByFour | CombinerScale::ByOneHalf
            )
        {
            return Err(GlError::invalid_operation(
                "BIAS_BY_NEGATIVE_ONE_HALF with SCALE_BY_FOUR or SCALE_BY_ONE_HALF",
            ));
        }
        let named = [output.ab, output.cd, output.sum];
        for (i, a) in named.iter().enumerate() {
            if *a != Register::Discard && named[i + 1..].contains(a) {
                return Err(GlError::invalid_operation(
                    "two outputs name the same register",
                ));
            }
        }
        self.stages[stage].portion_mut(portion).output = output;
        Ok(())
    }

    /// glFinalCombinerInputNV: mappings UNSIGNED_IDENTITY/INVERT only (INVALID_ENUM), BLUE
    /// usage INVALID_ENUM; G must read ALPHA, and E_TIMES_F / SPARE0_PLUS_SECONDARY_COLOR are
    /// not allowed in E, F or G or with ALPHA usage (INVALID_OPERATION).
    pub fn set_final_input(
        &mut self,
        variable: FinalVariable,
        input: CombinerInput,
        units: usize,
    ) -> GlResult {
        check_texture_register(input.register, units)?;
        if input.register == Register::Discard {
            return Err(GlError::invalid_enum("DISCARD is not an input"));
        }
        if !matches!(
            input.mapping,
            Mapping::UnsignedIdentity | Mapping::UnsignedInvert
        ) {
            return Err(GlError::invalid_enum(
                "final combiner mappings are UNSIGNED_IDENTITY or UNSIGNED_INVERT",
            ));
        }
        if input.usage == ComponentUsage::Blue {
            return Err(GlError::invalid_enum(
                "final combiner usage is RGB or ALPHA",
            ));
        }
        if variable == FinalVariable::G && input.usage == ComponentUsage::Rgb {
            return Err(GlError::invalid_operation("VARIABLE_G reads ALPHA"));
        }
        let pseudo = matches!(
            input.register,
            Register::ETimesF | Register::Spare0PlusSecondaryColor
        );
        if pseudo
            && (matches!(
                variable,
                FinalVariable::E | FinalVariable::F | FinalVariable::G
            ) || input.usage == ComponentUsage::Alpha)
        {
            return Err(GlError::invalid_operation(
                "E_TIMES_F and SPARE0_PLUS_SECONDARY_COLOR: RGB of A–D only",
            ));
        }
        self.final_inputs[variable.index()] = input;
        Ok(())
    }
}

fn check_stage(stage: u8) -> GlResult<usize> {
    let s = usize::from(stage);
    if s >= MAX_GENERAL_COMBINERS {
        return Err(GlError::invalid_enum(
            "COMBINERn_NV beyond MAX_GENERAL_COMBINERS",
        ));
    }
    Ok(s)
}

fn check_texture_register(r: Register, units: usize) -> GlResult {
    match r {
        Register::Texture(n) if usize::from(n) >= units => Err(GlError::invalid_enum(
            "TEXTUREn register beyond MAX_TEXTURE_UNITS",
        )),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::GlErrorKind;

    const UNITS: usize = 8;

    #[test]
    fn mapping_table() {
        use Mapping::*;
        let table = [
            (UnsignedIdentity, -0.5, 0.0),
            (UnsignedIdentity, 0.25, 0.25),
            (UnsignedInvert, 1.5, 0.0),
            (UnsignedInvert, 0.25, 0.75),
            (ExpandNormal, 0.75, 0.5),
            (ExpandNegate, 0.75, -0.5),
            (HalfBiasNormal, 0.25, -0.25),
            (HalfBiasNegate, 0.25, 0.25),
            (SignedIdentity, -0.5, -0.5),
            (SignedNegate, -0.5, 0.5),
        ];
        for (m, e, want) in table {
            assert_eq!(m.apply(e), want, "{m:?}({e})");
        }
        assert_eq!(output(0.9, CombinerScale::ByTwo, CombinerBias::None), 1.0);
        assert_eq!(
            output(0.25, CombinerScale::ByTwo, CombinerBias::ByNegativeOneHalf),
            -0.5
        );
    }

    #[test]
    fn num_general_combiners_out_of_range_is_invalid_value() {
        let mut rc = RegisterCombiners::DEFAULT;
        for n in [0, -1, 9] {
            let e = rc
                .set_parameter(CombinerParam::NumGeneralCombiners(n))
                .unwrap_err();
            assert_eq!(e.kind, GlErrorKind::InvalidValue, "{n}");
        }
        assert_eq!(rc.num_general, 1);
        rc.set_parameter(CombinerParam::NumGeneralCombiners(8))
            .unwrap();
        assert_eq!(rc.active_stages().len(), 8);
    }

    #[test]
    fn output_rules() {
        let mut rc = RegisterCombiners::DEFAULT;
        let ok = CombinerOutput {
            ab: Register::Spare1,
            ..CombinerOutput::DEFAULT
        };
        let cases = [
            (
                Portion::Rgb,
                CombinerOutput {
                    scale: CombinerScale::ByFour,
                    bias: CombinerBias::ByNegativeOneHalf,
                    ..ok
                },
                Some(GlErrorKind::InvalidOperation),
            ),
            (
                Portion::Rgb,
                CombinerOutput {
                    scale: CombinerScale::ByOneHalf,
                    bias: CombinerBias::ByNegativeOneHalf,
                    ..ok
                },
                Some(GlErrorKind::InvalidOperation),
            ),
            (
                Portion::Rgb,
                CombinerOutput {
                    scale: CombinerScale::ByTwo,
                    bias: CombinerBias::ByNegativeOneHalf,
                    ..ok
                },
                None,
            ),
            (
                Portion::Alpha,
                CombinerOutput {
                    ab_product: Product::Dot,
                    ..ok
                },
                Some(GlErrorKind::InvalidValue),
            ),
            (
                Portion::Rgb,
                CombinerOutput {
                    ab_product: Product::Dot,
                    ..ok
                },
                None,
            ),
            (
                Portion::Rgb,
                CombinerOutput {
                    cd: Register::Spare1,
                    ..ok
                },
                Some(GlErrorKind::InvalidOperation),
            ),
            (
                Portion::Rgb,
                CombinerOutput {
                    sum: Register::Zero,
                    ..ok
                },
                Some(GlErrorKind::InvalidEnum),
            ),
        ];
        for (portion, out, want) in cases {
            let before = rc;
            let got = rc.set_output(0, portion, out, UNITS).err().map(|e| e.kind);
            assert_eq!(got, want, "{portion:?} {out:?}");
            if want.is_some() {
                assert_eq!(rc, before);
            }
        }
        assert_eq!(
            rc.set_output(8, Portion::Rgb, ok, UNITS).unwrap_err().kind,
            GlErrorKind::InvalidEnum
        );
    }

    #[test]
    fn input_rules() {
        let mut rc = RegisterCombiners::DEFAULT;
        let input = |register, mapping, usage| CombinerInput {
            register,
            mapping,
            usage,
        };
        let cases = [
            (
                Portion::Rgb,
                input(
                    Register::Texture(0),
                    Mapping::ExpandNormal,
                    ComponentUsage::Rgb,
                ),
                None,
            ),
            (
                Portion::Rgb,
                input(
                    Register::Texture(0),
                    Mapping::ExpandNormal,
                    ComponentUsage::Blue,
                ),
                Some(GlErrorKind::InvalidOperation),
            ),
            (
                Portion::Alpha,
                input(
                    Register::Texture(1),
                    Mapping::SignedIdentity,
                    ComponentUsage::Rgb,
                ),
                Some(GlErrorKind::InvalidOperation),
            ),
            (
                Portion::Alpha,
                input(
                    Register::Fog,
                    Mapping::SignedIdentity,
                    ComponentUsage::Alpha,
                ),
                Some(GlErrorKind::InvalidOperation),
            ),
            (
                Portion::Rgb,
                input(
                    Register::ETimesF,
                    Mapping::SignedIdentity,
                    ComponentUsage::Rgb,
                ),
                Some(GlErrorKind::InvalidEnum),
            ),
            (
                Portion::Rgb,
                input(
                    Register::Texture(9),
                    Mapping::SignedIdentity,
                    ComponentUsage::Rgb,
                ),
                Some(GlErrorKind::InvalidEnum),
            ),
        ];
        for (portion, inp, want) in cases {
            let got = rc
                .set_input(1, portion, Variable::C, inp, UNITS)
                .err()
                .map(|e| e.kind);
            assert_eq!(got, want, "{portion:?} {inp:?}");
        }
        let g = input(
            Register::Spare0,
            Mapping::UnsignedIdentity,
            ComponentUsage::Rgb,
        );
        assert_eq!(
            rc.set_final_input(FinalVariable::G, g, UNITS)
                .unwrap_err()
                .kind,
            GlErrorKind::InvalidOperation
        );
        let e = input(Register::Spare0, Mapping::ExpandNormal, ComponentUsage::Rgb);
        assert_eq!(
            rc.set_final_input(FinalVariable::E, e, UNITS)
                .unwrap_err()
                .kind,
            GlErrorKind::InvalidEnum
        );
    }
}
