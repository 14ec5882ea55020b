//! Register combiners on the emulated path against the CPU model of the NV spec
//! (`ff::combiner_model`), over a table of mappings, products, MUX/SUM, scales and biases.
//! Mesa has no native register combiners, so the CPU model is the oracle. Tolerance: one
//! 8-bit step per channel (Float precision rounds once, on the framebuffer write).

mod support;

use fixedfunc::vocab::{DepthBits, Precision};
use std::sync::Arc;

use fixedfunc::ff::combiner_model::{evaluate, CombinerInputs};
use fixedfunc::ff::TexData;
use fixedfunc::ff::{
    Capability, CombinerBias, CombinerInput, CombinerOutput, CombinerParam, CombinerScale, Command,
    ComponentUsage, Filter, FinalVariable, FixedState, Geometry, Mapping, PixelFormat, PixelType,
    Portion, Primitive, Product, Register, SumOrMux, TexFormat, TexImage, TexParam, TextureTarget,
    Variable, MAX_TEXTURE_UNITS,
};
use fixedfunc::gpu::Profile;
use fixedfunc::pipeline::emulate::EmulatedPipeline;
use fixedfunc::pipeline::Pipeline;
use glam::Vec4;

const PRIMARY: Vec4 = Vec4::new(0.2, 0.6, 0.9, 0.4);
const TEX0: [u8; 4] = [200, 40, 120, 180];
const TEX1: [u8; 4] = [30, 250, 90, 60];
const CONST0: Vec4 = Vec4::new(0.5, 0.25, 0.75, 0.1);

const MAPPINGS: [Mapping; 8] = [
    Mapping::UnsignedIdentity,
    Mapping::UnsignedInvert,
    Mapping::ExpandNormal,
    Mapping::ExpandNegate,
    Mapping::HalfBiasNormal,
    Mapping::HalfBiasNegate,
    Mapping::SignedIdentity,
    Mapping::SignedNegate,
];

fn input(register: Register, mapping: Mapping, usage: ComponentUsage) -> CombinerInput {
    CombinerInput {
        register,
        mapping,
        usage,
    }
}

fn texture(unit: u8, texel: [u8; 4]) -> Vec<Command> {
    vec![
        Command::ActiveTexture(unit),
        Command::BindTexture {
            target: TextureTarget::Texture2D,
            name: 10 + u32::from(unit),
        },
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::Rgba8,
            width: 1,
            height: 1,
            depth: 1,
            border: 0,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            data: TexData::Bytes(Arc::from(&texel[..])),
        }),
        Command::TexParameter {
            target: TextureTarget::Texture2D,
            param: TexParam::MinFilter(Filter::Nearest),
        },
        Command::Enable(Capability::Texture2D),
    ]
}

/// Two stages: stage 0 RGB is (A·B, C·D, third) with the case's mapping on A and C and
/// its output settings, alpha likewise; stage 1 MUXes SPARE0 and SPARE1 by SPARE0.a.
fn case(
    mapping: Mapping,
    product: Product,
    third: SumOrMux,
    scale: CombinerScale,
    bias: CombinerBias,
) -> Vec<Command> {
    let mut cmds = texture(0, TEX0);
    cmds.extend(texture(1, TEX1));
    cmds.push(Command::CombinerParameter(
        CombinerParam::NumGeneralCombiners(2),
    ));
    cmds.push(Command::CombinerParameter(CombinerParam::ConstantColor0(
        CONST0,
    )));
    let rgb_inputs = [
        input(Register::Texture(0), mapping, ComponentUsage::Rgb),
        input(
            Register::PrimaryColor,
            Mapping::SignedIdentity,
            ComponentUsage::Rgb,
        ),
        input(Register::Texture(1), mapping, ComponentUsage::Rgb),
        input(
            Register::ConstantColor0,
            Mapping::UnsignedIdentity,
            ComponentUsage::Alpha,
        ),
    ];
    let alpha_inputs = [
        input(Register::Texture(0), mapping, ComponentUsage::Alpha),
        input(
            Register::PrimaryColor,
            Mapping::UnsignedInvert,
            ComponentUsage::Blue,
        ),
        input(Register::Texture(1), mapping, ComponentUsage::Alpha),
        input(
            Register::Zero,
            Mapping::UnsignedInvert,
            ComponentUsage::Alpha,
        ),
    ];
    for (portion, inputs) in [(Portion::Rgb, rgb_inputs), (Portion::Alpha, alpha_inputs)] {
        for (v, i) in [Variable::A, Variable::B, Variable::C, Variable::D]
            .into_iter()
            .zip(inputs)
        {
            cmds.push(Command::CombinerInput {
                stage: 0,
                portion,
                variable: v,
                input: i,
            });
        }
        cmds.push(Command::CombinerOutput {
            stage: 0,
            portion,
            output: CombinerOutput {
                ab: Register::Spare1,
                cd: Register::Discard,
                sum: Register::Spare0,
                scale,
                bias,
                ab_product: if portion == Portion::Rgb {
                    product
                } else {
                    Product::Componentwise
                },
                cd_product: Product::Componentwise,
                sum_or_mux: third,
            },
        });
    }
    for (portion, usage) in [
        (Portion::Rgb, ComponentUsage::Rgb),
        (Portion::Alpha, ComponentUsage::Alpha),
    ] {
        let ins = [
            input(Register::Spare0, Mapping::SignedIdentity, usage),
            input(Register::Zero, Mapping::UnsignedInvert, usage),
            input(Register::Spare1, Mapping::SignedIdentity, usage),
            input(Register::Zero, Mapping::UnsignedInvert, usage),
        ];
        for (v, i) in [Variable::A, Variable::B, Variable::C, Variable::D]
            .into_iter()
            .zip(ins)
        {
            cmds.push(Command::CombinerInput {
                stage: 1,
                portion,
                variable: v,
                input: i,
            });
        }
        cmds.push(Command::CombinerOutput {
            stage: 1,
            portion,
            output: CombinerOutput {
                sum_or_mux: SumOrMux::Mux,
                ..CombinerOutput::DEFAULT
            },
        });
    }
    // Final: RGB = A·B + (1 − A)·C + D with A = 0, C = SPARE0 … the default passes SPARE0.
    cmds.push(Command::FinalCombinerInput {
        variable: FinalVariable::G,
        input: input(
            Register::Spare0,
            Mapping::UnsignedIdentity,
            ComponentUsage::Alpha,
        ),
    });
    cmds.push(Command::Enable(Capability::RegisterCombiners));
    cmds.push(Command::Color(PRIMARY));
    cmds.push(Command::Draw(Arc::new(Geometry::new(
        Primitive::Quads,
        vec![
            Vec4::new(-1.0, -1.0, 0.0, 1.0),
            Vec4::new(1.0, -1.0, 0.0, 1.0),
            Vec4::new(1.0, 1.0, 0.0, 1.0),
            Vec4::new(-1.0, 1.0, 0.0, 1.0),
        ],
    ))));
    cmds
}

fn expected(cmds: &[Command], precision: Precision) -> [u8; 4] {
    let mut state = FixedState::new();
    for c in cmds {
        state.apply(c).expect("the model accepts the case");
    }
    let texel = |t: [u8; 4]| Vec4::from_array(t.map(|v| f32::from(v) / 255.0));
    let mut textures = [None; MAX_TEXTURE_UNITS];
    textures[0] = Some(texel(TEX0));
    textures[1] = Some(texel(TEX1));
    let out = evaluate(
        &state.register_combiners.value,
        &CombinerInputs {
            primary: PRIMARY,
            secondary: Vec4::ZERO,
            textures,
            fog: Vec4::new(0.0, 0.0, 0.0, 1.0),
        },
        precision,
    );
    out.to_array()
        .map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8)
}

/// Float: within one 8-bit step (one rounding, on the framebuffer write). Fixed8: the
/// 9-bit integer arithmetic is exact, so GPU and model agree bit for bit.
#[test]
fn gpu_register_combiners_match_the_cpu_model() {
    for (precision, tolerance) in [(Precision::Float, 1), (Precision::Fixed8, 0)] {
        check_table(precision, tolerance);
    }
}

fn check_table(precision: Precision, tolerance: u8) {
    let ctx = support::context(support::HEADLESS[0], Profile::Core33);
    let t = support::target(&ctx, 2, 2, DepthBits::D24, false);
    let mut seen = std::collections::HashSet::new();
    for mapping in MAPPINGS {
        for (product, third, scale, bias) in [
            (
                Product::Componentwise,
                SumOrMux::Sum,
                CombinerScale::None,
                CombinerBias::None,
            ),
            (
                Product::Dot,
                SumOrMux::Sum,
                CombinerScale::ByTwo,
                CombinerBias::ByNegativeOneHalf,
            ),
            (
                Product::Componentwise,
                SumOrMux::Mux,
                CombinerScale::ByOneHalf,
                CombinerBias::None,
            ),
            (
                Product::Dot,
                SumOrMux::Mux,
                CombinerScale::ByFour,
                CombinerBias::None,
            ),
        ] {
            let cmds = case(mapping, product, third, scale, bias);
            let mut p = EmulatedPipeline::new(&ctx)
                .expect("pipeline")
                .with_precision(precision);
            p.execute(&ctx, &cmds).expect("execute");
            assert_eq!(p.take_gl_error(), None);
            let got = t.read_color(&ctx).expect("colour").get_pixel(0, 0).0;
            let want = expected(&cmds, precision);
            let ok = got
                .iter()
                .zip(want)
                .all(|(g, w)| g.abs_diff(w) <= tolerance);
            assert!(
                ok,
                "{precision:?} {mapping:?} {product:?} {third:?} {scale:?} {bias:?}: GPU {got:?}, model {want:?}"
            );
            p.release(&ctx);
            seen.insert(want);
        }
    }
    // The table exercises the arithmetic: most cases give different colours.
    assert!(
        seen.len() >= 20,
        "only {} distinct results: {seen:?}",
        seen.len()
    );
    support::assert_no_gl_error(&ctx);
}
