//! The 16-bit digit carry (hard case of the multi-digit comparison): the map's number and
//! the fragment's number differ where one digit carries into the other. Each case puts a
//! map texel (L = little digit, A = big digit, LUMINANCE8_ALPHA8) on unit 0 and the
//! fragment's big and little digits on units 1 and 2 (INTENSITY8), then runs exactly the
//! setups `multidigit16` uses and the ones `multidigit16-combine` uses, and asks whether
//! the 16-bit comparison said lit.
//!
//! - Register combiners (emulated; oracle = the CPU model of the NV spec): lit iff the big
//!   pass or the little pass writes, in both precisions, for every case here. The GPU
//!   agrees with the model's alpha on every case.
//!
//! `multidigit16-combine`, the ARB combine version, is checked against this one on whole
//! scenes in `tests/shadow_maps.rs`.

mod support;

use fixedfunc::vocab::{DepthBits, Precision};
use std::sync::Arc;

use fixedfunc::ff::combiner_model::{evaluate, CombinerInputs};
use fixedfunc::ff::{
    Capability, ClearMask, Command, CompareFunc, Filter, FixedState, Geometry, PixelFormat,
    PixelType, Primitive, TexData, TexFormat, TexImage, TexParam, TextureTarget, MAX_TEXTURE_UNITS,
};
use fixedfunc::gpu::{GpuContext, Profile, RenderTarget};
use fixedfunc::pipeline::emulate::EmulatedPipeline;
use fixedfunc::pipeline::Pipeline;
use fixedfunc::techniques::multidigit16::{big_digit_combiners, little_digit_combiners};
use glam::Vec4;

/// (map D, fragment D, lit?) as 16-bit numbers.
const CASES: [(u16, u16, bool); 8] = [
    // Big digits equal, little digits 255 vs 0: the little digit decides.
    (0x12FF, 0x1200, true),
    (0x1200, 0x12FF, false),
    // Big digits differ by one, little digits reversed: the carry.
    (0x1300, 0x12FF, true),
    (0x12FF, 0x1300, false),
    // Equal numbers: shadowed (the comparison is strict, like the ADD_SIGNED tie).
    (0x1234, 0x1234, false),
    // A lead of one in the little digit, and of one in the big digit.
    (0x1235, 0x1234, true),
    (0x1334, 0x1234, true),
    // The ends of the range.
    (0xFFFF, 0x0000, true),
];

fn texture(unit: u8, target: TextureTarget, format: TexFormat, texel: &[u8]) -> Vec<Command> {
    let pixel_format = match format {
        TexFormat::Luminance8Alpha8 => PixelFormat::LuminanceAlpha,
        _ => PixelFormat::Luminance,
    };
    vec![
        Command::ActiveTexture(unit),
        Command::BindTexture {
            target,
            name: 20 + u32::from(unit),
        },
        Command::TexImage(TexImage {
            requested: None,
            target,
            level: 0,
            internal_format: format,
            width: 1,
            height: 1,
            depth: 1,
            border: 0,
            format: pixel_format,
            ty: PixelType::UnsignedByte,
            data: TexData::Bytes(Arc::from(texel)),
        }),
        Command::TexParameter {
            target,
            param: TexParam::MinFilter(Filter::Nearest),
        },
        Command::Enable(match target {
            TextureTarget::Texture1D => Capability::Texture1D,
            TextureTarget::Texture2D => Capability::Texture2D,
            TextureTarget::Texture3D => Capability::Texture3D,
            TextureTarget::CubeMap | TextureTarget::CubeFace(_) => Capability::TextureCubeMap,
        }),
    ]
}

/// The three units of a case: the map texel and the fragment's two digits.
fn units(map: u16, fragment: u16) -> Vec<Command> {
    let [map_little, map_big] = map.to_le_bytes();
    let [frag_little, frag_big] = fragment.to_le_bytes();
    let mut c = texture(
        0,
        TextureTarget::Texture2D,
        TexFormat::Luminance8Alpha8,
        &[map_little, map_big],
    );
    c.extend(texture(
        1,
        TextureTarget::Texture1D,
        TexFormat::Intensity8,
        &[frag_big],
    ));
    c.extend(texture(
        2,
        TextureTarget::Texture1D,
        TexFormat::Intensity8,
        &[frag_little],
    ));
    c
}

fn quad() -> Command {
    Command::Draw(Arc::new(Geometry::new(
        Primitive::Quads,
        vec![
            Vec4::new(-1.0, -1.0, 0.0, 1.0),
            Vec4::new(1.0, -1.0, 0.0, 1.0),
            Vec4::new(1.0, 1.0, 0.0, 1.0),
            Vec4::new(-1.0, 1.0, 0.0, 1.0),
        ],
    )))
}

/// Clears to black, draws a white quad through `setup` with AlphaFunc(GREATER, 0), and
/// reports whether the pixel was written (and the alpha written).
fn written(
    ctx: &GpuContext,
    target: &RenderTarget,
    pipeline: &mut dyn Pipeline,
    setup: &[Command],
) -> (bool, u8) {
    let mut c = vec![
        Command::ClearColor(Vec4::ZERO),
        Command::Clear(ClearMask {
            color: true,
            depth: false,
            stencil: false,
            accum: false,
        }),
        Command::Enable(Capability::AlphaTest),
        Command::AlphaFunc {
            func: CompareFunc::Greater,
            reference: 0.0,
        },
        Command::Color(Vec4::ONE),
    ];
    c.extend_from_slice(setup);
    c.push(quad());
    c.push(Command::Disable(Capability::RegisterCombiners));
    pipeline.execute(ctx, &c).expect("execute");
    assert_eq!(pipeline.take_gl_error(), None);
    let px = target.read_color(ctx).expect("colour").get_pixel(0, 0).0;
    (px[0] == 255, px[3])
}

/// The CPU model's final alpha for `setup` on the case's texels.
fn model_alpha(map: u16, fragment: u16, setup: &[Command], precision: Precision) -> f32 {
    let mut state = FixedState::new();
    for c in units(map, fragment).iter().chain(setup) {
        state.apply(c).expect("the model accepts the setup");
    }
    let [ml, mb] = map.to_le_bytes();
    let [fl, fb] = fragment.to_le_bytes();
    let v = |b: u8| f32::from(b) / 255.0;
    let mut textures = [None; MAX_TEXTURE_UNITS];
    textures[0] = Some(Vec4::new(v(ml), v(ml), v(ml), v(mb)));
    textures[1] = Some(Vec4::splat(v(fb)));
    textures[2] = Some(Vec4::splat(v(fl)));
    evaluate(
        &state.register_combiners.value,
        &CombinerInputs {
            primary: Vec4::ONE,
            secondary: Vec4::ZERO,
            textures,
            fog: Vec4::new(0.0, 0.0, 0.0, 1.0),
        },
        precision,
    )
    .w
}

#[test]
fn register_combiners_carry_the_digits_in_both_precisions() {
    let ctx = support::context(support::HEADLESS[0], Profile::Core33);
    let target = support::target(&ctx, 1, 1, DepthBits::D24, false);
    for precision in [Precision::Float, Precision::Fixed8] {
        let mut p = EmulatedPipeline::new(&ctx)
            .expect("pipeline")
            .with_precision(precision);
        for (map, fragment, lit) in CASES {
            let mut big = units(map, fragment);
            big.extend(big_digit_combiners());
            let mut little = units(map, fragment);
            little.extend(little_digit_combiners());
            let (big_pass, big_alpha) = written(&ctx, &target, &mut p, &big);
            let (little_pass, little_alpha) = written(&ctx, &target, &mut p, &little);
            // The technique's stencil keeps the little pass off pixels the big pass lit.
            let got = big_pass || little_pass;
            assert_eq!(
                got, lit,
                "{precision:?} map {map:#06x} fragment {fragment:#06x}: big {big_pass}, little {little_pass}"
            );
            // The GPU agrees with the model (alpha within one step in Float, exact in Fixed8).
            let tol = if precision == Precision::Float { 1 } else { 0 };
            for (setup, alpha, passed) in [
                (big_digit_combiners(), big_alpha, big_pass),
                (little_digit_combiners(), little_alpha, little_pass),
            ] {
                let model = model_alpha(map, fragment, &setup, precision);
                let model8 = (model.clamp(0.0, 1.0) * 255.0).round() as u8;
                assert_eq!(
                    passed,
                    model8 > 0,
                    "{precision:?} {map:#06x}/{fragment:#06x}"
                );
                if passed {
                    assert!(
                        alpha.abs_diff(model8) <= tol,
                        "{precision:?} {map:#06x}/{fragment:#06x}: GPU alpha {alpha}, model {model8}"
                    );
                }
            }
        }
    }
}
