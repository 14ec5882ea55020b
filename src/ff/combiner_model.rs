//! A CPU model of NV_register_combiners (Float precision): the oracle for the emulated
//! path, since Mesa has no native register combiners. It follows `notes/register-combiners`:
//! registers start as the primary and secondary colours, the texels, FOG = (fog colour, 1)
//! with fog off, SPARE0.a = texture 0's alpha (when unit 0 textures), everything else 0.
//! Each general stage reads the registers as they were when it began, computes AB, CD and
//! SUM or MUX per portion, maps each through clamp((r + bias)·scale, −1, 1) and writes the
//! named registers; the final combiner computes min(A·B + (1 − A)·C + D, 1) and alpha G.

use glam::{Vec3, Vec4};

use super::combiners::{
    output, CombinerInput, ComponentUsage, Product, Register, RegisterCombiners, StagePortion,
    SumOrMux,
};
use super::precision::{quantise, quantise9};
use super::state::MAX_TEXTURE_UNITS;
use crate::vocab::Precision;

/// Fixed8: q9 after every mapping, product and output (ff::precision); Float: identity.
fn q(p: Precision, v: f32) -> f32 {
    match p {
        Precision::Float => v,
        Precision::Fixed8 => quantise9(v) as f32 / 255.0,
    }
}

fn q3(p: Precision, v: Vec3) -> Vec3 {
    Vec3::new(q(p, v.x), q(p, v.y), q(p, v.z))
}

/// clamp((r + bias)·scale, −1, 1); in Fixed8 the −½ bias is −128/255 and q9 clamps.
fn out(p: Precision, o: &super::combiners::CombinerOutput, r: f32) -> f32 {
    match p {
        Precision::Float => output(r, o.scale, o.bias),
        Precision::Fixed8 => {
            let bias = if o.bias.value() == 0.0 {
                0.0
            } else {
                -128.0 / 255.0
            };
            q(p, (r + bias) * o.scale.factor())
        }
    }
}

/// What the combiners start from at one fragment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CombinerInputs {
    pub primary: Vec4,
    pub secondary: Vec4,
    /// The texel of each unit that textures (in register form, see the notes).
    pub textures: [Option<Vec4>; MAX_TEXTURE_UNITS],
    /// (fog colour, fog factor or 1).
    pub fog: Vec4,
}

/// The register file of one fragment.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Registers {
    primary: Vec4,
    secondary: Vec4,
    spare0: Vec4,
    spare1: Vec4,
    textures: [Vec4; MAX_TEXTURE_UNITS],
    fog: Vec4,
    constant: [Vec4; 2],
}

impl Registers {
    fn read(&self, r: Register) -> Vec4 {
        match r {
            Register::Zero | Register::Discard => Vec4::ZERO,
            Register::ConstantColor0 => self.constant[0],
            Register::ConstantColor1 => self.constant[1],
            Register::Fog => self.fog,
            Register::PrimaryColor => self.primary,
            Register::SecondaryColor => self.secondary,
            Register::Spare0 => self.spare0,
            Register::Spare1 => self.spare1,
            Register::Texture(n) => self.textures.get(n as usize).copied().unwrap_or(Vec4::ZERO),
            // Final-combiner pseudo-registers are resolved by `final_combiner`.
            Register::ETimesF | Register::Spare0PlusSecondaryColor => Vec4::ZERO,
        }
    }

    fn slot(&mut self, r: Register) -> Option<&mut Vec4> {
        match r {
            Register::PrimaryColor => Some(&mut self.primary),
            Register::SecondaryColor => Some(&mut self.secondary),
            Register::Spare0 => Some(&mut self.spare0),
            Register::Spare1 => Some(&mut self.spare1),
            Register::Texture(n) => self.textures.get_mut(n as usize),
            _ => None,
        }
    }
}

/// An RGB-portion input: the register's RGB or its alpha replicated, then the mapping.
fn rgb_input(regs: &Registers, p: Precision, i: CombinerInput) -> Vec3 {
    let v = regs.read(i.register);
    let e = match i.usage {
        ComponentUsage::Rgb => v.truncate(),
        ComponentUsage::Alpha => Vec3::splat(v.w),
        ComponentUsage::Blue => Vec3::splat(v.z),
    };
    q3(
        p,
        Vec3::new(
            i.mapping.apply(e.x),
            i.mapping.apply(e.y),
            i.mapping.apply(e.z),
        ),
    )
}

/// An alpha-portion input: the register's alpha or blue, then the mapping.
fn alpha_input(regs: &Registers, p: Precision, i: CombinerInput) -> f32 {
    let v = regs.read(i.register);
    let e = match i.usage {
        ComponentUsage::Blue => v.z,
        ComponentUsage::Alpha | ComponentUsage::Rgb => v.w,
    };
    q(p, i.mapping.apply(e))
}

fn rgb_portion(regs: &Registers, pr: Precision, p: &StagePortion) -> [Vec3; 3] {
    let [a, b, c, d] = p.inputs.map(|i| rgb_input(regs, pr, i));
    let product = |x: Vec3, y: Vec3, kind| match kind {
        Product::Componentwise => q3(pr, x * y),
        Product::Dot => q3(pr, Vec3::splat(x.dot(y))),
    };
    let ab = product(a, b, p.output.ab_product);
    let cd = product(c, d, p.output.cd_product);
    let third = match p.output.sum_or_mux {
        SumOrMux::Sum => ab + cd,
        SumOrMux::Mux if regs.spare0.w >= 0.5 => cd,
        SumOrMux::Mux => ab,
    };
    let o = |v: Vec3| v.to_array().map(|e| out(pr, &p.output, e)).into();
    [o(ab), o(cd), o(third)]
}

fn alpha_portion(regs: &Registers, pr: Precision, p: &StagePortion) -> [f32; 3] {
    let [a, b, c, d] = p.inputs.map(|i| alpha_input(regs, pr, i));
    let (ab, cd) = (q(pr, a * b), q(pr, c * d));
    let third = match p.output.sum_or_mux {
        SumOrMux::Sum => ab + cd,
        SumOrMux::Mux if regs.spare0.w >= 0.5 => cd,
        SumOrMux::Mux => ab,
    };
    [ab, cd, third].map(|e| out(pr, &p.output, e))
}

/// The fragment colour the combiners produce. In Fixed8 the inputs are first quantised to
/// 8 bits (the texels and colours the stages receive) and the result to 8 bits.
pub fn evaluate(rc: &RegisterCombiners, inputs: &CombinerInputs, precision: Precision) -> Vec4 {
    let inputs = &match precision {
        Precision::Float => *inputs,
        Precision::Fixed8 => {
            let q8 =
                |v: Vec4| Vec4::from_array(v.to_array().map(|c| f32::from(quantise(c)) / 255.0));
            CombinerInputs {
                primary: q8(inputs.primary),
                secondary: inputs.secondary,
                textures: inputs.textures.map(|t| t.map(q8)),
                fog: inputs.fog,
            }
        }
    };
    let mut regs = Registers {
        primary: inputs.primary,
        secondary: inputs.secondary,
        spare0: Vec4::new(0.0, 0.0, 0.0, inputs.textures[0].map_or(0.0, |t| t.w)),
        spare1: Vec4::ZERO,
        textures: inputs.textures.map(|t| t.unwrap_or(Vec4::ZERO)),
        fog: inputs.fog,
        constant: rc.constant_color,
    };
    for stage in rc.active_stages() {
        let rgb = rgb_portion(&regs, precision, &stage.rgb);
        let alpha = alpha_portion(&regs, precision, &stage.alpha);
        let o = &stage.rgb.output;
        for (reg, v) in [(o.ab, rgb[0]), (o.cd, rgb[1]), (o.sum, rgb[2])] {
            if let Some(slot) = regs.slot(reg) {
                *slot = v.extend(slot.w);
            }
        }
        let o = &stage.alpha.output;
        for (reg, v) in [(o.ab, alpha[0]), (o.cd, alpha[1]), (o.sum, alpha[2])] {
            if let Some(slot) = regs.slot(reg) {
                slot.w = v;
            }
        }
    }
    let result = final_combiner(rc, &regs, precision);
    match precision {
        Precision::Float => result,
        Precision::Fixed8 => {
            Vec4::from_array(result.to_array().map(|c| f32::from(quantise(c)) / 255.0))
        }
    }
}

/// RGB = min(A·B + (1 − A)·C + D, 1), alpha = G; inputs mapped by unsigned identity or
/// invert; E_TIMES_F = E·F, SPARE0_PLUS_SECONDARY_COLOR = spare0 + secondary (clamped to
/// [0,1] with COLOR_SUM_CLAMP); both with alpha 0.
fn final_combiner(rc: &RegisterCombiners, regs: &Registers, p: Precision) -> Vec4 {
    let fi = &rc.final_inputs;
    let plain = |i: CombinerInput| rgb_input(regs, p, i);
    let (e, f) = (plain(fi[4]), plain(fi[5]));
    let sum = {
        let s = regs.spare0.truncate().max(Vec3::ZERO) + regs.secondary.truncate().max(Vec3::ZERO);
        if rc.color_sum_clamp {
            s.clamp(Vec3::ZERO, Vec3::ONE)
        } else {
            s
        }
    };
    let value = |i: CombinerInput| -> Vec3 {
        let raw = match i.register {
            Register::ETimesF => (e * f).extend(0.0),
            Register::Spare0PlusSecondaryColor => sum.extend(0.0),
            r => regs.read(r),
        };
        let comp = match i.usage {
            ComponentUsage::Rgb => raw.truncate(),
            ComponentUsage::Alpha => Vec3::splat(raw.w),
            ComponentUsage::Blue => Vec3::splat(raw.z),
        };
        Vec3::new(
            i.mapping.apply(comp.x),
            i.mapping.apply(comp.y),
            i.mapping.apply(comp.z),
        )
    };
    let (a, b, c, d) = (value(fi[0]), value(fi[1]), value(fi[2]), value(fi[3]));
    let rgb = (a * b + (Vec3::ONE - a) * c + d).min(Vec3::ONE);
    let g = {
        let i = fi[6];
        let raw = match i.register {
            Register::ETimesF | Register::Spare0PlusSecondaryColor => 0.0,
            r => {
                let v = regs.read(r);
                if i.usage == ComponentUsage::Blue {
                    v.z
                } else {
                    v.w
                }
            }
        };
        i.mapping.apply(raw)
    };
    rgb.extend(g)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::combiners::{CombinerBias, Mapping};

    fn inputs(primary: Vec4) -> CombinerInputs {
        CombinerInputs {
            primary,
            secondary: Vec4::ZERO,
            textures: [None; MAX_TEXTURE_UNITS],
            fog: Vec4::new(0.0, 0.0, 0.0, 1.0),
        }
    }

    /// The initial state passes the primary colour through: stage 0 writes A·B =
    /// primary·1 to SPARE0 as the sum; the final combiner (A = fog alpha 1, B = spare0 +
    /// secondary) gives spare0, alpha G = SPARE0.a.
    #[test]
    fn untouched_combiners_pass_the_primary_colour() {
        let rc = RegisterCombiners::DEFAULT;
        let c = Vec4::new(0.25, 0.5, 0.75, 0.6);
        assert_eq!(evaluate(&rc, &inputs(c), Precision::Float), c);
    }

    /// A stage that puts ½ + (x − y) into SPARE0.a: SUM of x·1 and (1 − y)·1, bias −½.
    #[test]
    fn biased_difference_in_spare0_alpha() {
        let mut rc = RegisterCombiners::DEFAULT;
        let p = &mut rc.stages[0].alpha;
        p.inputs[0] = CombinerInput {
            register: Register::PrimaryColor,
            mapping: Mapping::UnsignedIdentity,
            usage: ComponentUsage::Alpha,
        };
        p.inputs[1] = CombinerInput {
            register: Register::Zero,
            mapping: Mapping::UnsignedInvert,
            usage: ComponentUsage::Alpha,
        };
        p.inputs[2] = CombinerInput {
            register: Register::PrimaryColor,
            mapping: Mapping::UnsignedInvert,
            usage: ComponentUsage::Blue,
        };
        p.inputs[3] = CombinerInput {
            register: Register::Zero,
            mapping: Mapping::UnsignedInvert,
            usage: ComponentUsage::Alpha,
        };
        p.output.bias = CombinerBias::ByNegativeOneHalf;
        let out = evaluate(
            &rc,
            &inputs(Vec4::new(0.0, 0.0, 0.25, 0.75)),
            Precision::Float,
        );
        // ½ + 0.75 − 0.25 = 1.0, then the bias: (0.75 + 0.75 − 0.5) → clamp to 1.
        assert!((out.w - 1.0).abs() < 1e-6, "{out}");
        let out = evaluate(
            &rc,
            &inputs(Vec4::new(0.0, 0.0, 0.5, 0.4)),
            Precision::Float,
        );
        assert!((out.w - 0.4).abs() < 1e-6, "{out}");
    }
}
