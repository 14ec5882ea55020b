//! `multidigit16-combine`: the 16-bit multi-digit comparison of `multidigit16` without
//! register combiners — ARB_texture_env_combine, DOT3 and the stencil buffer alone, so that
//! it also runs on Mesa's native fixed-function path. It pays for that in passes: the
//! tests write stencil tags with colour writes off, and one last pass draws the lit colour
//! where the tags say lit.
//!
//! ```text
//! maps   as multidigit16 (UNSIGNED_SHORT readback into LUMINANCE8_ALPHA8)
//! frame  dim:           clear stencil to 0; the shadowing light off; draw everything
//!        big-lit:       colour off; unit 0 map alpha REPLACE(TEXTURE); unit 1 big ramp
//!                       alpha SUBTRACT(PREVIOUS, TEXTURE) = big(map) − big(frag);
//!                       AlphaFunc(GREATER, 0); stencil ALWAYS, REPLACE 1
//!        big-shadowed:  unit 1 alpha SUBTRACT(TEXTURE, PREVIOUS) = big(frag) − big(map);
//!                       stencil EQUAL 0, REPLACE 2
//!        little-lit:    stencil EQUAL 0 (equal big digits); unit 0 rgb REPLACE(TEXTURE) =
//!                       little(map); unit 1 little ramp rgb ADD_SIGNED(PREVIOUS, 1 − TEXTURE)
//!                       = ½ + little(map) − little(frag); unit 2 DOT3_RGBA(PREVIOUS,
//!                       CONSTANT (1,1,1,1)); AlphaFunc(GREATER, 0); REPLACE 1
//!        lit:           colour on; stencil EQUAL 1; every light on; no textures
//! ```
//! **Why DOT3.** Combine's alpha operands read only alpha, and the little digit of a
//! LUMINANCE8_ALPHA8 texel is its luminance: DOT3_RGBA is the one combine function that
//! moves an RGB result into alpha. With e = ½ + d (d = little(map) − little(frag)) on every
//! channel and the constant 1: 4·Σ(e − ½)(1 − ½) = 6·d, clamped to [0, 1]: > 0 iff d > 0.
//! Unit 2 must have a texture enabled for its environment to apply; it is bound to the
//! repeat ramp, whose texel it never reads.
//!
//! Differences run in the combine stages' arithmetic: in `Float` every d ≠ 0 keeps its
//! sign (6/255 > 0); in `Fixed8`, ADD_SIGNED computes a + b − 128 (`ff::precision`), so
//! d = +1/255 lands on exactly 128 and DOT3 makes 0 of it: a 1-LSB little-digit lead is
//! lost — the same 1-LSB fragility as `dual8`'s tie, at 16 bits.

use glam::Vec4;

use crate::ff::{
    Capability, ColorMask, CombineArg, CombineFunc, CombineOperand, CombineSource, Command,
    CompareFunc, StencilOp, TexEnvMode, TexEnvParam, TextureTarget,
};
use crate::scene::Scene;
use crate::vocab::TechniqueId;

use super::map::REPEAT_RAMP_TEXTURE;
use super::multidigit16::{digit_unit, map_unit, Digit};
use super::parts::{
    dim_pass, lighting, objects, receives, reset, texturing_off, LightSet, Look, Paint, ShadowLight,
};
use super::{Pass, Plan, Prepared, Technique, TechniqueError};

pub const ID: TechniqueId = TechniqueId::Multidigit16Combine;

pub const TECHNIQUE: Technique = Technique {
    summary: "the 16-bit two-digit comparison with ARB combine, DOT3 and stencil (runs natively)",
    plan,
};

pub fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, TechniqueError> {
    super::multidigit16::digit_plan(ID, scene, prepared, eye_passes)
}

fn env(params: &[TexEnvParam]) -> Vec<Command> {
    std::iter::once(Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Combine)))
        .chain(params.iter().map(|&p| Command::TexEnv(p)))
        .collect()
}

/// Combine alpha = SUBTRACT(`a`, `b`), RGB passed through.
fn subtract_alpha(a: CombineSource, b: CombineSource) -> Vec<Command> {
    env(&[
        TexEnvParam::CombineRgb(CombineFunc::Replace),
        TexEnvParam::SourceRgb(CombineArg::Arg0, CombineSource::Previous),
        TexEnvParam::OperandRgb(CombineArg::Arg0, CombineOperand::SrcColor),
        TexEnvParam::CombineAlpha(CombineFunc::Subtract),
        TexEnvParam::SourceAlpha(CombineArg::Arg0, a),
        TexEnvParam::OperandAlpha(CombineArg::Arg0, CombineOperand::SrcAlpha),
        TexEnvParam::SourceAlpha(CombineArg::Arg1, b),
        TexEnvParam::OperandAlpha(CombineArg::Arg1, CombineOperand::SrcAlpha),
    ])
}

/// A tagging pass: colour off, depth EQUAL, alpha GREATER 0, then glStencilFunc(`func`,
/// `reference`, `mask`) with REPLACE on depth pass — the tag written is the reference.
fn tag_start(func: CompareFunc, reference: i32, mask: u32) -> Vec<Command> {
    vec![
        Command::ColorMask(ColorMask::NONE),
        Command::DepthFunc(CompareFunc::Equal),
        Command::DepthMask(false),
        Command::Disable(Capability::Lighting),
        Command::Enable(Capability::AlphaTest),
        Command::AlphaFunc {
            func: CompareFunc::Greater,
            reference: 0.0,
        },
        Command::Enable(Capability::StencilTest),
        Command::StencilFunc {
            func,
            reference,
            mask,
        },
        Command::StencilOp {
            fail: StencilOp::Keep,
            depth_fail: StencilOp::Keep,
            depth_pass: StencilOp::Replace,
        },
    ]
}

/// The stencil tags: 0 undecided, [`LIT_TAG`] lit, [`SHADOWED_TAG`] shadowed by the big
/// digits. The EQUAL tests read one bit of the tag through the stencil mask, so a pass
/// can test "not yet decided" and write its own tag with one reference — glStencilFunc
/// compares (ref & mask) with (stencil & mask) and REPLACE writes the whole reference.
const LIT_TAG: i32 = 1;
const SHADOWED_TAG: i32 = 2;

fn eye_passes(scene: &Scene, prepared: &Prepared, light: &ShadowLight, look: Look) -> Vec<Pass> {
    let tags = Paint::Flat(Vec4::ONE);
    let receivers = objects(scene, prepared, receives, tags);

    // big-lit: LIT where big(map) > big(frag) (ALWAYS: every tag is 0 after the clear).
    let mut big_lit = tag_start(CompareFunc::Always, LIT_TAG, 0xff);
    big_lit.extend(map_unit(light));
    big_lit.extend(env(&[
        TexEnvParam::CombineRgb(CombineFunc::Replace),
        TexEnvParam::SourceRgb(CombineArg::Arg0, CombineSource::PrimaryColor),
        TexEnvParam::OperandRgb(CombineArg::Arg0, CombineOperand::SrcColor),
        TexEnvParam::CombineAlpha(CombineFunc::Replace),
        TexEnvParam::SourceAlpha(CombineArg::Arg0, CombineSource::Texture),
        TexEnvParam::OperandAlpha(CombineArg::Arg0, CombineOperand::SrcAlpha),
    ]));
    big_lit.extend(digit_unit(light, 1, Digit::Big));
    big_lit.extend(subtract_alpha(
        CombineSource::Previous,
        CombineSource::Texture,
    ));
    big_lit.extend(receivers.iter().cloned());

    // big-shadowed: SHADOWED where big(frag) > big(map), among pixels whose LIT bit is
    // clear: (2 & 1) = 0 = (stencil & 1).
    let mut big_shadowed = tag_start(CompareFunc::Equal, SHADOWED_TAG, LIT_TAG as u32);
    big_shadowed.push(Command::ActiveTexture(1));
    big_shadowed.extend(subtract_alpha(
        CombineSource::Texture,
        CombineSource::Previous,
    ));
    big_shadowed.extend(receivers.iter().cloned());

    // little-lit: LIT where little(map) > little(frag), among pixels not SHADOWED (the
    // undecided ones have equal big digits).
    // (1 & 2) = 0 = (stencil & 2): the SHADOWED bit clear (a LIT pixel is rewritten LIT).
    let mut little_lit = tag_start(CompareFunc::Equal, LIT_TAG, SHADOWED_TAG as u32);
    little_lit.push(Command::ActiveTexture(0));
    little_lit.extend(env(&[
        TexEnvParam::CombineRgb(CombineFunc::Replace),
        TexEnvParam::SourceRgb(CombineArg::Arg0, CombineSource::Texture),
        TexEnvParam::OperandRgb(CombineArg::Arg0, CombineOperand::SrcColor),
    ]));
    little_lit.extend(digit_unit(light, 1, Digit::Little));
    little_lit.extend(env(&[
        TexEnvParam::CombineRgb(CombineFunc::AddSigned),
        TexEnvParam::SourceRgb(CombineArg::Arg0, CombineSource::Previous),
        TexEnvParam::OperandRgb(CombineArg::Arg0, CombineOperand::SrcColor),
        TexEnvParam::SourceRgb(CombineArg::Arg1, CombineSource::Texture),
        TexEnvParam::OperandRgb(CombineArg::Arg1, CombineOperand::OneMinusSrcColor),
    ]));
    little_lit.extend([
        Command::ActiveTexture(2),
        Command::BindTexture {
            target: TextureTarget::Texture1D,
            name: REPEAT_RAMP_TEXTURE,
        },
        Command::Enable(Capability::Texture1D),
        Command::TexEnv(TexEnvParam::Color(Vec4::ONE)),
    ]);
    little_lit.extend(env(&[
        TexEnvParam::CombineRgb(CombineFunc::Dot3Rgba),
        TexEnvParam::SourceRgb(CombineArg::Arg0, CombineSource::Previous),
        TexEnvParam::OperandRgb(CombineArg::Arg0, CombineOperand::SrcColor),
        TexEnvParam::SourceRgb(CombineArg::Arg1, CombineSource::Constant),
        TexEnvParam::OperandRgb(CombineArg::Arg1, CombineOperand::SrcColor),
    ]));
    little_lit.extend(receivers.iter().cloned());
    for unit in [2, 1, 0] {
        little_lit.push(Command::ActiveTexture(unit));
        little_lit.extend(texturing_off());
    }

    // lit: the lit colour on receivers tagged LIT; non-receivers lit without the test.
    let mut lit = vec![
        Command::ColorMask(ColorMask::ALL),
        Command::Disable(Capability::AlphaTest),
        Command::StencilFunc {
            func: CompareFunc::Equal,
            reference: LIT_TAG,
            mask: 0xff,
        },
        Command::StencilOp {
            fail: StencilOp::Keep,
            depth_fail: StencilOp::Keep,
            depth_pass: StencilOp::Keep,
        },
    ];
    lit.extend(lighting(scene, look, LightSet::All));
    lit.extend(objects(scene, prepared, receives, look.paint(true)));
    lit.push(Command::Disable(Capability::StencilTest));
    lit.extend(objects(
        scene,
        prepared,
        super::parts::does_not_receive,
        look.paint(true),
    ));
    lit.extend(reset(&[0, 1, 2]));
    vec![
        dim_pass(scene, prepared, look, true),
        Pass {
            name: "big-lit",
            commands: big_lit,
        },
        Pass {
            name: "big-shadowed",
            commands: big_shadowed,
        },
        Pass {
            name: "little-lit",
            commands: little_lit,
        },
        Pass {
            name: "lit",
            commands: lit,
        },
    ]
}
