//! `multidigit16`: Kilgard's 16-bit multi-digit comparison (GeForce/Quadro, McCool's idea):
//! the depth map read back as UNSIGNED_SHORT and kept as two 8-bit digits, compared digit by
//! digit with stencil and NV_register_combiners.
//!
//! ```text
//! maps   light:    depth only, polygon offset; draw the casters
//!        readback: glReadPixels(0, 0, map, map, DEPTH_COMPONENT, UNSIGNED_SHORT, buf)
//!        upload:   glTexImage2D(TEXTURE_2D, 0, LUMINANCE8_ALPHA8, map, map, 0,
//!                               LUMINANCE_ALPHA, UNSIGNED_BYTE, buf)
//! frame  dim:      clear stencil to 0; the shadowing light off; draw everything
//!        big:      DepthFunc(EQUAL); combiners: alpha = big(T0) − big(T1);
//!                  AlphaFunc(GREATER, 0); stencil ALWAYS, REPLACE 1; draw receivers lit
//!        little:   combiners: alpha = big(T1) > big(T0) ? 0 : little(T0) − little(T2);
//!                  AlphaFunc(GREATER, 0); stencil NOTEQUAL 1; draw receivers lit
//! ```
//! **Digits** (notes H5, H16). The map holds D = round(65535·z) (Mesa's UNSIGNED_SHORT
//! readback; the scene's `readback` rule can impose either rule, `map::DepthTransfer`); on a little-endian machine its bytes load as L = D & 255 (the little digit)
//! and A = D >> 8 (the big digit) of T0. The fragment's digits come from two 256-texel
//! ramps: big = texel ⌊256·s⌋ of the CLAMP_TO_EDGE ramp at s = r/q (unit 1), little = texel
//! ⌊256·s'⌋ mod 256 of the REPEAT ramp at s' = 256·r/q (unit 2). Lit iff the map's 16-bit
//! number is greater: big(T0) > big(T1), or equal big digits and little(T0) > little(T2).
//!
//! **The combiner setups, register by register** (`ff::combiners`, notes
//! `register-combiners.md`):
//! - *big* (one stage): alpha A = T0.a, B = ZERO inverted (1), C = T1.a, D = ZERO expanded
//!   (−1): SUM = big(T0) − big(T1) → SPARE0.a. Final: G = SPARE0.a (clamped to [0, 1]), RGB
//!   = D = PRIMARY_COLOR (A = B = C = ZERO). Alpha > 0 iff big(T0) > big(T1).
//! - *little* (two stages): stage 0 alpha A = T0.a, B = 1, C = HALF_BIAS_NEGATE(T1.a) =
//!   ½ − big(T1), D = 1: SPARE0.a = big(T0) + ½ − big(T1); stage 0 RGB A = T0.rgb, B = 1,
//!   C = T2.rgb, D = −1: SPARE1.rgb = little(T0) − little(T2). Stage 1 alpha: AB = ZERO·ZERO,
//!   CD = SPARE1.b (SIGNED_IDENTITY, BLUE usage) · 1, MUX → SPARE0.a: (SPARE0.a ≥ ½) ?
//!   little difference : 0. Final as above. Since pixels with big(T0) > big(T1) already
//!   hold stencil 1, a fragment reaching the MUX with SPARE0.a ≥ ½ has equal big digits.
//!
//! **Equal big digits must land on the ≥ ½ side, in both precisions.** The obvious setup,
//! big(T0) + (1 − big(T1)) with the −½ output bias, fails in `Fixed8`: 1 is 255 and −½ is
//! −128, so a tie gives 127 < 128 and the little digits are never consulted (the digit
//! carry test caught it). HALF_BIAS_NEGATE puts the ½ inside the mapping, where `Fixed8`
//! makes it 128 − big(T1): a tie gives exactly 128. In `Float`, ½ − f is exact for
//! f ≥ ¼ and within 2⁻²⁶ below, and f + (½ − f) rounds to exactly ½ either way.
//!
//! The slide writes pass 2 as "α = bigDigit(Tex0) < bigDigit(Tex1)"; that contradicts its
//! own pass 3 and the lit test, so the sense here is the consistent one (T0 the map, T1
//! the fragment: lit where the map's big digit is the greater).
//!
//! Register combiners have no native path on Mesa: this technique runs on the emulated
//! pipeline only; `multidigit16-combine` is the same comparison with ARB combine.

use crate::ff::{
    Capability, CombinerInput, CombinerOutput, CombinerParam, Command, CompareFunc, ComponentUsage,
    FinalVariable, Mapping, PixelFormat, PixelType, Portion, Register, StencilOp, SumOrMux,
    TexCoord, TexFormat, TextureTarget, Variable, Wrap,
};
use crate::scene::Scene;
use crate::vocab::TechniqueId;

use super::map::{
    bind_map, map_parameters, ramp, upload_map, DepthTransfer, MapSettings, MAP_SLOT, RAMP_TEXTURE,
    REPEAT_RAMP_TEXTURE,
};
use super::parts::{
    dim_pass, does_not_receive, eye_linear, light_pass, lighting, objects, receives, reset,
    LightSet, Look, ShadowLight,
};
use super::{
    check_light_count, colour_mask, MapImagePlan, MapImageSource, Pass, Plan, Prepared, Technique,
    TechniqueError,
};

pub const ID: TechniqueId = TechniqueId::Multidigit16;

pub const TECHNIQUE: Technique = Technique {
    summary: "Kilgard's 16-bit multi-digit map: two 8-bit digits, stencil, register combiners",
    plan,
};

pub fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, TechniqueError> {
    digit_plan(ID, scene, prepared, eye_passes)
}

/// The plan of a two-digit technique: its digit map (light pass, UNSIGNED_SHORT readback,
/// LUMINANCE8_ALPHA8 upload), both ramps, stencil, and `eye` in both looks — what
/// `multidigit16` and `multidigit16-combine` share; only their eye passes differ.
pub fn digit_plan(
    id: TechniqueId,
    scene: &Scene,
    prepared: &Prepared,
    eye: fn(&Scene, &Prepared, &ShadowLight, Look) -> Vec<Pass>,
) -> Result<Plan, TechniqueError> {
    check_light_count(scene)?;
    let light = ShadowLight::of(scene, id)?;
    let map = MapSettings::of(scene);
    map.check_stencil(id)?;
    Ok(Plan {
        setup: setup(),
        maps: digit_map_passes(scene, prepared, &light, &map),
        passes: eye(scene, prepared, &light, Look::Shaded),
        mask: colour_mask(scene, eye(scene, prepared, &light, Look::Mask)),
        framebuffer: map.framebuffer(scene, true),
        map_image: Some(digit_map_image(&map)),
        notes: filter_note(&map),
    })
}

/// A LINEAR filter would blend digits into meaningless numbers: digit maps are NEAREST.
pub fn filter_note(map: &MapSettings) -> Vec<String> {
    match map.filter {
        crate::vocab::MapFilter::Nearest => Vec::new(),
        crate::vocab::MapFilter::Linear => vec![
            "the digit map is sampled NEAREST: interpolating two 8-bit digits separately \
             does not interpolate the 16-bit depth"
                .to_string(),
        ],
    }
}

/// The map's parameters (NEAREST) and both ramps.
pub fn setup() -> Vec<Command> {
    let mut c = vec![Command::ActiveTexture(0), bind_map()];
    c.extend(map_parameters(crate::ff::Filter::Nearest));
    c.push(Command::ActiveTexture(1));
    c.extend(ramp(RAMP_TEXTURE, Wrap::ClampToEdge));
    c.push(Command::ActiveTexture(2));
    c.extend(ramp(REPEAT_RAMP_TEXTURE, Wrap::Repeat));
    c.push(Command::ActiveTexture(0));
    c
}

/// Light pass, UNSIGNED_SHORT readback, LUMINANCE8_ALPHA8 upload.
pub fn digit_map_passes(
    scene: &Scene,
    prepared: &Prepared,
    light: &ShadowLight,
    map: &MapSettings,
) -> Vec<Pass> {
    let transfer = digit_transfer(map);
    vec![
        light_pass(scene, prepared, light, map.size, map.offset, false),
        Pass {
            name: "readback",
            commands: vec![transfer.read(map.size)],
        },
        Pass {
            name: "upload",
            commands: vec![
                Command::ActiveTexture(0),
                bind_map(),
                upload_map(
                    map.size,
                    TexFormat::Luminance8Alpha8,
                    PixelFormat::LuminanceAlpha,
                    transfer.data(),
                ),
            ],
        },
    ]
}

/// UNSIGNED_SHORT by the scene's readback rule.
pub fn digit_transfer(map: &MapSettings) -> DepthTransfer {
    DepthTransfer {
        ty: PixelType::UnsignedShort,
        rule: map.readback,
    }
}

/// Both digits of the read-back map, for `--depth-map`.
pub fn digit_map_image(map: &MapSettings) -> MapImagePlan {
    MapImagePlan {
        commands: Vec::new(),
        source: MapImageSource::Digits {
            slot: MAP_SLOT,
            size: map.size,
            from_float: digit_transfer(map).conversion(),
        },
    }
}

/// Which fragment digit a ramp unit produces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Digit {
    /// ⌊256·r/q⌋, clamped: the CLAMP_TO_EDGE ramp at s = r/q.
    Big,
    /// ⌊256·(256·r/q)⌋ mod 256: the REPEAT ramp at s = 256·r/q.
    Little,
}

/// The map on unit 0 with projective S, T, Q; texturing enabled, env untouched.
pub fn map_unit(light: &ShadowLight) -> Vec<Command> {
    let mut c = vec![
        Command::ActiveTexture(0),
        bind_map(),
        Command::Enable(Capability::Texture2D),
    ];
    c.extend(eye_linear(&[
        (TexCoord::S, light.plane(0)),
        (TexCoord::T, light.plane(1)),
        (TexCoord::Q, light.plane(3)),
    ]));
    c
}

/// A ramp on `unit` producing the fragment's `digit`; texturing enabled, env untouched.
pub fn digit_unit(light: &ShadowLight, unit: u8, digit: Digit) -> Vec<Command> {
    let (name, s) = match digit {
        Digit::Big => (RAMP_TEXTURE, light.plane(2)),
        Digit::Little => (REPEAT_RAMP_TEXTURE, 256.0 * light.plane(2)),
    };
    let mut c = vec![
        Command::ActiveTexture(unit),
        Command::BindTexture {
            target: TextureTarget::Texture1D,
            name,
        },
        Command::Enable(Capability::Texture1D),
    ];
    c.extend(eye_linear(&[
        (TexCoord::S, s),
        (TexCoord::Q, light.plane(3)),
    ]));
    c
}

fn input(register: Register, mapping: Mapping, usage: ComponentUsage) -> CombinerInput {
    CombinerInput {
        register,
        mapping,
        usage,
    }
}

fn general(stage: u8, portion: Portion, inputs: [CombinerInput; 4]) -> Vec<Command> {
    [Variable::A, Variable::B, Variable::C, Variable::D]
        .into_iter()
        .zip(inputs)
        .map(|(variable, input)| Command::CombinerInput {
            stage,
            portion,
            variable,
            input,
        })
        .collect()
}

/// Final combiner: RGB = PRIMARY_COLOR (A = B = C = ZERO, D = primary), alpha G = SPARE0.a.
fn final_primary_rgb_spare0_alpha() -> Vec<Command> {
    let rgb = ComponentUsage::Rgb;
    let zero = input(Register::Zero, Mapping::UnsignedIdentity, rgb);
    [
        (FinalVariable::A, zero),
        (FinalVariable::B, zero),
        (FinalVariable::C, zero),
        (
            FinalVariable::D,
            input(Register::PrimaryColor, Mapping::UnsignedIdentity, rgb),
        ),
        (FinalVariable::E, zero),
        (FinalVariable::F, zero),
        (
            FinalVariable::G,
            input(
                Register::Spare0,
                Mapping::UnsignedIdentity,
                ComponentUsage::Alpha,
            ),
        ),
    ]
    .into_iter()
    .map(|(variable, input)| Command::FinalCombinerInput { variable, input })
    .collect()
}

/// The *big* setup (module note): alpha = big(T0) − big(T1), RGB the primary colour.
pub fn big_digit_combiners() -> Vec<Command> {
    let a = ComponentUsage::Alpha;
    let mut c = vec![
        Command::Enable(Capability::RegisterCombiners),
        Command::CombinerParameter(CombinerParam::NumGeneralCombiners(1)),
    ];
    c.extend(general(
        0,
        Portion::Alpha,
        [
            input(Register::Texture(0), Mapping::UnsignedIdentity, a),
            input(Register::Zero, Mapping::UnsignedInvert, a),
            input(Register::Texture(1), Mapping::UnsignedIdentity, a),
            input(Register::Zero, Mapping::ExpandNormal, a),
        ],
    ));
    c.push(Command::CombinerOutput {
        stage: 0,
        portion: Portion::Alpha,
        output: CombinerOutput::DEFAULT,
    });
    c.extend(final_primary_rgb_spare0_alpha());
    c
}

/// The *little* setup (module note): alpha = big(T1) > big(T0) ? 0 : little(T0) − little(T2).
pub fn little_digit_combiners() -> Vec<Command> {
    let (a, rgb, blue) = (
        ComponentUsage::Alpha,
        ComponentUsage::Rgb,
        ComponentUsage::Blue,
    );
    let mut c = vec![
        Command::Enable(Capability::RegisterCombiners),
        Command::CombinerParameter(CombinerParam::NumGeneralCombiners(2)),
    ];
    // Stage 0 alpha: SPARE0.a = big(T0)·1 + HALF_BIAS_NEGATE(big(T1))·1 = big(T0) + ½ − big(T1).
    c.extend(general(
        0,
        Portion::Alpha,
        [
            input(Register::Texture(0), Mapping::UnsignedIdentity, a),
            input(Register::Zero, Mapping::UnsignedInvert, a),
            input(Register::Texture(1), Mapping::HalfBiasNegate, a),
            input(Register::Zero, Mapping::UnsignedInvert, a),
        ],
    ));
    c.push(Command::CombinerOutput {
        stage: 0,
        portion: Portion::Alpha,
        output: CombinerOutput::DEFAULT,
    });
    // Stage 0 RGB: SPARE1.rgb = little(T0) − little(T2).
    c.extend(general(
        0,
        Portion::Rgb,
        [
            input(Register::Texture(0), Mapping::UnsignedIdentity, rgb),
            input(Register::Zero, Mapping::UnsignedInvert, rgb),
            input(Register::Texture(2), Mapping::UnsignedIdentity, rgb),
            input(Register::Zero, Mapping::ExpandNormal, rgb),
        ],
    ));
    c.push(Command::CombinerOutput {
        stage: 0,
        portion: Portion::Rgb,
        output: CombinerOutput {
            sum: Register::Spare1,
            ..CombinerOutput::DEFAULT
        },
    });
    // Stage 1 alpha: SPARE0.a = (SPARE0.a ≥ ½) ? SPARE1.b · 1 : 0 · 0.
    c.extend(general(
        1,
        Portion::Alpha,
        [
            input(Register::Zero, Mapping::UnsignedIdentity, a),
            input(Register::Zero, Mapping::UnsignedIdentity, a),
            input(Register::Spare1, Mapping::SignedIdentity, blue),
            input(Register::Zero, Mapping::UnsignedInvert, a),
        ],
    ));
    c.push(Command::CombinerOutput {
        stage: 1,
        portion: Portion::Alpha,
        output: CombinerOutput {
            sum_or_mux: SumOrMux::Mux,
            ..CombinerOutput::DEFAULT
        },
    });
    // Stage 1 RGB: untouched stages pass the primary colour to SPARE0; the final
    // combiner reads the primary colour directly.
    c.extend(final_primary_rgb_spare0_alpha());
    c
}

fn eye_passes(scene: &Scene, prepared: &Prepared, light: &ShadowLight, look: Look) -> Vec<Pass> {
    let paint = look.paint(true);
    let start = |c: &mut Vec<Command>| {
        c.extend([
            Command::DepthFunc(CompareFunc::Equal),
            Command::DepthMask(false),
            Command::Enable(Capability::AlphaTest),
            Command::AlphaFunc {
                func: CompareFunc::Greater,
                reference: 0.0,
            },
            Command::Enable(Capability::StencilTest),
        ]);
        c.extend(lighting(scene, look, LightSet::All));
    };
    // Pass 2: the big digits say lit → draw lit, stencil 1.
    let mut big = Vec::new();
    start(&mut big);
    big.extend([
        Command::StencilFunc {
            func: CompareFunc::Always,
            reference: 1,
            mask: 0xff,
        },
        Command::StencilOp {
            fail: StencilOp::Keep,
            depth_fail: StencilOp::Keep,
            depth_pass: StencilOp::Replace,
        },
    ]);
    big.extend(map_unit(light));
    big.extend(digit_unit(light, 1, Digit::Big));
    big.extend(big_digit_combiners());
    big.extend(objects(scene, prepared, receives, paint));
    // Non-receivers are lit: no combiners, no textures, alpha 1.
    big.push(Command::Disable(Capability::RegisterCombiners));
    for unit in [1, 0] {
        big.push(Command::ActiveTexture(unit));
        big.push(Command::Disable(Capability::Texture1D));
        big.push(Command::Disable(Capability::Texture2D));
    }
    big.extend(objects(scene, prepared, does_not_receive, paint));

    // Pass 3: equal big digits, the little digits decide; pixels of pass 2 rejected.
    let mut little = Vec::new();
    start(&mut little);
    little.extend([
        Command::StencilFunc {
            func: CompareFunc::Notequal,
            reference: 1,
            mask: 0xff,
        },
        Command::StencilOp {
            fail: StencilOp::Keep,
            depth_fail: StencilOp::Keep,
            depth_pass: StencilOp::Keep,
        },
    ]);
    little.extend(map_unit(light));
    little.extend(digit_unit(light, 1, Digit::Big));
    little.extend(digit_unit(light, 2, Digit::Little));
    little.extend(little_digit_combiners());
    little.extend(objects(scene, prepared, receives, paint));
    little.extend(reset(&[0, 1, 2]));
    vec![
        dim_pass(scene, prepared, look, true),
        Pass {
            name: "big",
            commands: big,
        },
        Pass {
            name: "little",
            commands: little,
        },
    ]
}
