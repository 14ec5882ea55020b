//! Texture formats and depth compares on the native path (EGL and OSMesa): the legacy base
//! formats under REPLACE (GL 1.5 Table 3.23) and ARB_shadow compares on the three depth
//! formats, with the ARB_shadow_ambient fail value recorded in the model and ignored by
//! Mesa, as documented.

mod support;

use fixedfunc::vocab::DepthBits;
use std::sync::Arc;

use fixedfunc::ff::{
    Capability, ClearMask, Command, CompareFunc, CompareMode, DepthTextureMode, Filter, Geometry,
    MatrixMode, PixelFormat, PixelType, Primitive, TexData, TexEnvMode, TexEnvParam, TexFormat,
    TexImage, TexParam, TextureTarget, ViewVolume, Wrap,
};
use fixedfunc::gpu::Profile;
use fixedfunc::pipeline::native::NativePipeline;
use fixedfunc::pipeline::Pipeline;
use glam::Vec4;
use support::{assert_no_gl_error, context, target};

fn ortho(w: f32) -> Vec<Command> {
    vec![
        Command::ClearColor(Vec4::new(0.0, 0.0, 0.0, 1.0)),
        Command::Clear(ClearMask::ALL),
        Command::MatrixMode(MatrixMode::Projection),
        Command::LoadIdentity,
        Command::Ortho(ViewVolume {
            left: 0.0,
            right: w,
            bottom: 0.0,
            top: 1.0,
            near: -1.0,
            far: 1.0,
        }),
        Command::MatrixMode(MatrixMode::Modelview),
        Command::LoadIdentity,
    ]
}

fn column(x: f32) -> Command {
    Command::Draw(Arc::new(Geometry::new(
        Primitive::Quads,
        vec![
            Vec4::new(x, 0.0, 0.0, 1.0),
            Vec4::new(x + 1.0, 0.0, 0.0, 1.0),
            Vec4::new(x + 1.0, 1.0, 0.0, 1.0),
            Vec4::new(x, 1.0, 0.0, 1.0),
        ],
    )))
}

fn param(p: TexParam) -> Command {
    Command::TexParameter {
        target: TextureTarget::Texture2D,
        param: p,
    }
}

/// Binds `name`, uploads a `w × 1` image and sets NEAREST / CLAMP_TO_EDGE.
fn texture(
    name: u32,
    w: i32,
    internal: TexFormat,
    format: PixelFormat,
    ty: PixelType,
    bytes: Vec<u8>,
) -> Vec<Command> {
    vec![
        Command::BindTexture {
            target: TextureTarget::Texture2D,
            name,
        },
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: internal,
            width: w,
            height: 1,
            depth: 1,
            border: 0,
            format,
            ty,
            data: TexData::Bytes(Arc::from(bytes)),
        }),
        param(TexParam::MinFilter(Filter::Nearest)),
        param(TexParam::MagFilter(Filter::Nearest)),
        param(TexParam::WrapS(Wrap::ClampToEdge)),
        param(TexParam::WrapT(Wrap::ClampToEdge)),
    ]
}

/// REPLACE per base format, fragment colour Cf = (51, 102, 153, 204)/255:
/// L → (L, L, L, Af); I → (I, I, I, I); A → (Cf, A); LA → (L, L, L, A); RGB → (C, Af);
/// RGBA → (C, A). Tolerance ±1 (the unorm8 round trip of the colour).
#[test]
fn legacy_formats_replace_by_base_format() {
    use PixelFormat as P;
    let cases: [(TexFormat, PixelFormat, Vec<u8>, [u8; 4]); 6] = [
        (
            TexFormat::Luminance8,
            P::Luminance,
            vec![200],
            [200, 200, 200, 204],
        ),
        (
            TexFormat::Intensity8,
            P::Luminance,
            vec![200],
            [200, 200, 200, 200],
        ),
        (TexFormat::Alpha8, P::Alpha, vec![200], [51, 102, 153, 200]),
        (
            TexFormat::Luminance8Alpha8,
            P::LuminanceAlpha,
            vec![200, 100],
            [200, 200, 200, 100],
        ),
        (TexFormat::Rgb8, P::Rgb, vec![10, 20, 30], [10, 20, 30, 204]),
        (
            TexFormat::Rgba8,
            P::Rgba,
            vec![10, 20, 30, 40],
            [10, 20, 30, 40],
        ),
    ];
    for backend in support::HEADLESS {
        let ctx = context(backend, Profile::Compatibility);
        let t = target(&ctx, cases.len() as u32, 1, DepthBits::D24, false);
        let mut pipe = NativePipeline::new(&ctx).expect("native");
        let mut cmds = ortho(cases.len() as f32);
        cmds.extend([
            Command::Enable(Capability::Texture2D),
            Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Replace)),
            Command::Color(Vec4::new(51.0, 102.0, 153.0, 204.0) / 255.0),
        ]);
        for (i, (internal, format, bytes, _)) in cases.iter().enumerate() {
            cmds.extend(texture(
                i as u32 + 1,
                1,
                *internal,
                *format,
                PixelType::UnsignedByte,
                bytes.clone(),
            ));
            cmds.push(column(i as f32));
        }
        pipe.execute(&ctx, &cmds).expect("execute");
        assert_eq!(pipe.take_gl_error(), None);
        let img = t.read_color(&ctx).expect("colour");
        for (i, (internal, _, _, want)) in cases.iter().enumerate() {
            let got = img.get_pixel(i as u32, 0).0;
            let ok = got.iter().zip(want).all(|(g, w)| g.abs_diff(*w) <= 1);
            assert!(ok, "{backend} {internal:?}: {got:?}, want {want:?} ± 1");
        }
        assert_eq!(pipe.counters().texture_uploads, cases.len() as u64);
        pipe.release(&ctx);
        assert_no_gl_error(&ctx);
    }
}

/// ARB_shadow on DEPTH_COMPONENT16/24/32F: texels 0.25 and 0.75, r = 0.5, LEQUAL →
/// fail (left) and pass (right); GREATER the reverse. DEPTH_TEXTURE_MODE is INTENSITY, so
/// the texel is (c, c, c, c) and REPLACE writes c to all four channels — Mesa 22.3.6 does
/// honour the mode here (an earlier note said it returned (c, c, c, 1); that does not
/// reproduce, see tests/fidelity_depth_texture.rs). The fail value 0.4 (ARB_shadow_ambient)
/// is kept by the model and ignored natively: a failed compare reads 0.
#[test]
fn depth_compare_on_every_depth_format() {
    let depths: Vec<u8> = [0.25f32, 0.75]
        .iter()
        .flat_map(|z| z.to_ne_bytes())
        .collect();
    let formats = [
        TexFormat::DepthComponent16,
        TexFormat::DepthComponent24,
        TexFormat::DepthComponent32F,
    ];
    for backend in support::HEADLESS {
        let ctx = context(backend, Profile::Compatibility);
        let t = target(&ctx, 4, 1, DepthBits::D24, false);
        let mut pipe = NativePipeline::new(&ctx).expect("native");
        for format in formats {
            for (func, left, right) in [
                (CompareFunc::Lequal, 0u8, 255u8),
                (CompareFunc::Greater, 255, 0),
            ] {
                let mut cmds = ortho(4.0);
                cmds.extend(texture(
                    1,
                    2,
                    format,
                    PixelFormat::DepthComponent,
                    PixelType::Float,
                    depths.clone(),
                ));
                cmds.extend([
                    param(TexParam::CompareMode(CompareMode::CompareRToTexture)),
                    param(TexParam::CompareFunc(func)),
                    param(TexParam::DepthTextureMode(DepthTextureMode::Intensity)),
                    param(TexParam::CompareFailValue(0.4)),
                    Command::Enable(Capability::Texture2D),
                    Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Replace)),
                    Command::TexCoord {
                        unit: 0,
                        coord: Vec4::new(0.25, 0.5, 0.5, 1.0),
                    },
                    column(0.0),
                    column(1.0),
                    Command::TexCoord {
                        unit: 0,
                        coord: Vec4::new(0.75, 0.5, 0.5, 1.0),
                    },
                    column(2.0),
                    column(3.0),
                ]);
                pipe.execute(&ctx, &cmds).expect("execute");
                assert_eq!(pipe.take_gl_error(), None);
                let tex = pipe
                    .state()
                    .texture(TextureTarget::Texture2D, 1)
                    .expect("texture 1");
                assert_eq!(tex.params.compare_fail_value, 0.4, "the model keeps it");
                let img = t.read_color(&ctx).expect("colour");
                for (x, want) in [(0, left), (3, right)] {
                    let got = img.get_pixel(x, 0).0;
                    assert_eq!(
                        got, [want; 4],
                        "{backend} {format:?} {func:?} column {x}: {got:?}"
                    );
                }
            }
        }
        pipe.release(&ctx);
        assert_no_gl_error(&ctx);
    }
}
