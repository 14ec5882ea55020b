//! The native pipeline on real compatibility contexts (EGL and OSMesa): Commands become
//! Mesa's own fixed-function rendering, with the numbers of the GL formulas and of piglit.
//! Colour tolerances are in 8-bit steps per channel and stated at each probe.

mod support;

use fixedfunc::vocab::DepthBits;
use std::sync::Arc;

use fixedfunc::ff::matrix::{MODELVIEW_STACK_DEPTH, PROJECTION_STACK_DEPTH, TEXTURE_STACK_DEPTH};
use fixedfunc::ff::{
    Capability, ClearMask, CombineArg, CombineFunc, CombineOperand, CombineSource, CompareFunc,
    Face, Filter, Geometry, GlErrorKind, MaterialParam, PixelFormat, PixelType, Primitive,
    ReadPixels, StencilOp, TexCoord, TexEnvMode, TexEnvParam, TexFormat, TexGenMode, TexGenParam,
    TexImage, TexParam, TextureTarget, ViewVolume, Wrap,
};
use fixedfunc::ff::{Command, LightParam, MatrixMode, TexData, Viewport};
use fixedfunc::gpu::{Backend, GpuContext, Profile, RenderTarget};
use fixedfunc::pipeline::native::{bindings as gl, NativeGl, NativePipeline};
use fixedfunc::pipeline::{Pipeline, PipelineError};
use glam::{Mat4, Vec3, Vec4};
use support::{assert_no_gl_error, context, probe, target};

/// A context, a bound target of `w × h` (D24, optional stencil) and a native pipeline.
fn setup(
    backend: Backend,
    w: u32,
    h: u32,
    stencil: bool,
) -> (GpuContext, RenderTarget, NativePipeline) {
    let ctx = context(backend, Profile::Compatibility);
    let t = target(&ctx, w, h, DepthBits::D24, stencil);
    let pipe = NativePipeline::new(&ctx).expect("native pipeline on a compatibility context");
    (ctx, t, pipe)
}

/// Projection = glOrtho(l, r, b, t, −1, 1); modelview = identity.
fn ortho(l: f32, r: f32, b: f32, t: f32) -> Vec<Command> {
    vec![
        Command::MatrixMode(MatrixMode::Projection),
        Command::LoadIdentity,
        Command::Ortho(ViewVolume {
            left: l,
            right: r,
            bottom: b,
            top: t,
            near: -1.0,
            far: 1.0,
        }),
        Command::MatrixMode(MatrixMode::Modelview),
        Command::LoadIdentity,
    ]
}

/// An axis-aligned quad at depth z (object coordinates).
fn quad(x0: f32, y0: f32, x1: f32, y1: f32, z: f32) -> Command {
    Command::Draw(Arc::new(Geometry::new(
        Primitive::Quads,
        vec![
            Vec4::new(x0, y0, z, 1.0),
            Vec4::new(x1, y0, z, 1.0),
            Vec4::new(x1, y1, z, 1.0),
            Vec4::new(x0, y1, z, 1.0),
        ],
    )))
}

fn clear_all() -> Vec<Command> {
    vec![
        Command::ClearColor(Vec4::new(0.0, 0.0, 0.0, 1.0)),
        Command::Clear(ClearMask::ALL),
    ]
}

/// A 2D RGBA8 texture named `name` on the active unit, NEAREST, CLAMP_TO_EDGE.
fn rgba_texture(name: u32, w: i32, h: i32, texels: Vec<u8>) -> Vec<Command> {
    vec![
        Command::BindTexture {
            target: TextureTarget::Texture2D,
            name,
        },
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::Rgba8,
            width: w,
            height: h,
            depth: 1,
            border: 0,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            data: TexData::Bytes(Arc::from(texels)),
        }),
        tex_param(TexParam::MinFilter(Filter::Nearest)),
        tex_param(TexParam::MagFilter(Filter::Nearest)),
        tex_param(TexParam::WrapS(Wrap::ClampToEdge)),
        tex_param(TexParam::WrapT(Wrap::ClampToEdge)),
        Command::Enable(Capability::Texture2D),
    ]
}

fn tex_param(param: TexParam) -> Command {
    Command::TexParameter {
        target: TextureTarget::Texture2D,
        param,
    }
}

fn run(ctx: &GpuContext, pipe: &mut NativePipeline, cmds: &[Command]) {
    pipe.execute(ctx, cmds).expect("execute");
    assert_eq!(pipe.take_gl_error(), None, "the model raised an error");
    assert_no_gl_error(ctx);
}

fn unorm8(v: f64) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// One directional light on a quad facing the viewer, by the GL 1.5 §2.14.1 formula:
/// c = e + a_m·a_global + a_m·a_l + (n·L)·d_m·d_l + (n·h)^s·s_m·s_l, h = L + (0,0,1)
/// normalised (non-local viewer); alpha = the diffuse material's alpha.
#[test]
fn directional_light_on_a_quad_follows_the_lighting_formula() {
    let l = Vec3::new(0.0, 0.6, 0.8);
    let diffuse = Vec4::new(0.5, 0.25, 1.0, 1.0);
    let specular = Vec4::new(0.1, 0.3, 0.1, 1.0);
    let shininess = 10.0f32;
    let n_dot_l = f64::from(l.z); // n = (0, 0, 1)
    let h = (l + Vec3::Z).normalize();
    let n_dot_h = f64::from(h.z).powf(f64::from(shininess));
    let expected: [u8; 4] = std::array::from_fn(|i| {
        if i == 3 {
            return 255;
        }
        // Global ambient 0.2 × material ambient 0.2; light 0 ambient is 0.
        let c = 0.2 * 0.2 + n_dot_l * f64::from(diffuse[i]) + n_dot_h * f64::from(specular[i]);
        unorm8(c)
    });
    for backend in support::HEADLESS {
        let (ctx, t, mut pipe) = setup(backend, 8, 8, false);
        let mut cmds = clear_all();
        cmds.extend(ortho(-1.0, 1.0, -1.0, 1.0));
        cmds.extend([
            Command::Enable(Capability::Lighting),
            Command::Enable(Capability::Light(0)),
            Command::Light {
                light: 0,
                param: LightParam::Position(l.extend(0.0)),
            },
            Command::Material {
                face: Face::FrontAndBack,
                param: MaterialParam::Diffuse(diffuse),
            },
            Command::Material {
                face: Face::Front,
                param: MaterialParam::Specular(specular),
            },
            Command::Material {
                face: Face::Front,
                param: MaterialParam::Shininess(shininess),
            },
            Command::Normal(Vec3::Z),
            quad(-1.0, -1.0, 1.0, 1.0, 0.0),
        ]);
        run(&ctx, &mut pipe, &cmds);
        let img = t.read_color(&ctx).expect("colour");
        // ±1: Mesa evaluates the formula in fp32 per vertex, then converts to unorm8.
        for (x, y) in [(1, 1), (4, 4), (6, 2)] {
            probe(&img, x, y, expected, 1);
        }
    }
}

/// The checkerboard of piglit_checkerboard_texture(256², squares of 128): texel (row i,
/// column j) is the second colour where i/128 + j/128 is odd.
fn checker() -> Vec<u8> {
    const GREEN: [u8; 4] = [0, 255, 0, 255];
    const BLUE: [u8; 4] = [0, 0, 255, 255];
    (0..256)
        .flat_map(|i| (0..256).map(move |j| (i, j)))
        .flat_map(|(i, j)| {
            if (i / 128 + j / 128) % 2 == 1 {
                BLUE
            } else {
                GREEN
            }
        })
        .collect()
}

/// piglit gl-1.0/texgen, EYE_LINEAR run: ortho ±10 on 50×50, S plane (0, 0.05, 0, 1), T plane
/// (0.05, 0, 0, 1) set with an identity modelview, REPLACE, NEAREST, REPEAT; upper-left
/// quadrant blue, upper-right green (checked at piglit's six points per quadrant). A quad of
/// ±9.9 stands in for the sphere: eye-linear texgen does not depend on the normal.
#[test]
fn texgen_eye_linear_quadrants_match_piglit() {
    for backend in support::HEADLESS {
        let (ctx, t, mut pipe) = setup(backend, 50, 50, false);
        let mut cmds = clear_all();
        cmds.extend(ortho(-10.0, 10.0, -10.0, 10.0));
        cmds.extend(rgba_texture(7, 256, 256, checker()));
        cmds.extend([
            tex_param(TexParam::WrapS(Wrap::Repeat)),
            tex_param(TexParam::WrapT(Wrap::Repeat)),
            Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Replace)),
        ]);
        for (coord, plane) in [
            (TexCoord::S, Vec4::new(0.0, 0.05, 0.0, 1.0)),
            (TexCoord::T, Vec4::new(0.05, 0.0, 0.0, 1.0)),
        ] {
            cmds.extend([
                Command::TexGen {
                    coord,
                    param: TexGenParam::Mode(TexGenMode::EyeLinear),
                },
                Command::TexGen {
                    coord,
                    param: TexGenParam::EyePlane(plane),
                },
                Command::Enable(Capability::TextureGen(coord)),
            ]);
        }
        cmds.push(quad(-9.9, -9.9, 9.9, 9.9, 0.0));
        run(&ctx, &mut pipe, &cmds);
        let img = t.read_color(&ctx).expect("colour");
        let blue = [0, 0, 255, 255];
        let green = [0, 255, 0, 255];
        let samples = [(13, 13), (4, 22), (22, 4), (20, 20), (20, 10), (10, 20)];
        // (x, y) bottom-up as piglit probes; the image is top row first.
        let at = |x: u32, y: u32, want: [u8; 4]| probe(&img, x, 49 - y, want, 0);
        for (x, y) in samples {
            at(x, y, green); // lower left
            at(50 - x, y, blue); // lower right
            at(50 - x, 50 - y, green); // upper right
            at(x, 50 - y, blue); // upper left
        }
    }
}

/// An eye plane passed as given, under a non-identity modelview, ends in GL equal to the
/// model's (GL multiplies by the inverse modelview itself, GL 1.5 §2.11.4).
#[test]
fn eye_planes_in_gl_equal_the_model() {
    for backend in support::HEADLESS {
        let (ctx, _t, mut pipe) = setup(backend, 4, 4, false);
        let plane = Vec4::new(1.0, 0.0, 0.0, -0.25);
        let cmds = [
            Command::MatrixMode(MatrixMode::Modelview),
            Command::LoadIdentity,
            Command::Translate(Vec3::new(0.5, -0.5, 0.0)),
            Command::Scale(Vec3::new(2.0, 1.0, 1.0)),
            Command::Rotate {
                angle_deg: 30.0,
                axis: Vec3::new(0.0, 1.0, 1.0),
            },
            Command::ActiveTexture(2),
            Command::TexGen {
                coord: TexCoord::R,
                param: TexGenParam::EyePlane(plane),
            },
        ];
        run(&ctx, &mut pipe, &cmds);
        let model = pipe.state().units[2].texgen[TexCoord::R.index()]
            .value
            .eye_plane;
        let native = NativeGl::load(&ctx).expect("compatibility");
        let mut got = [0.0f32; 4];
        unsafe {
            native.raw().ActiveTexture(gl::TEXTURE2);
            native
                .raw()
                .GetTexGenfv(gl::R, gl::EYE_PLANE, got.as_mut_ptr());
        }
        for i in 0..4 {
            assert!(
                (got[i] - model[i]).abs() < 1e-5,
                "{backend}: GL eye plane {got:?}, model {model}"
            );
        }
        assert_no_gl_error(&ctx);
    }
}

/// COMBINE argument order (hard case H13) and ADD_SIGNED with RGB_SCALE 2, against the
/// model's own combine formulas (`CombineFunc::eval`, clamped after scaling).
#[test]
fn combine_interpolate_order_and_add_signed() {
    use CombineArg::{Arg0, Arg1, Arg2};
    // Left half: INTERPOLATE(Arg0 = texture, Arg1 = primary, Arg2 = constant 0.25)
    // = Arg0·Arg2 + Arg1·(1 − Arg2): texel (1, 1, 0, 1), colour (0, 0, 1, 0) →
    // (0.25, 0.25, 0.75, 0.25). Regal's mix(Arg0, Arg1, Arg2) would give (0.75, 0.75, 0.25, 0.75).
    let interp = CombineFunc::Interpolate;
    let tex_i = [1.0f32, 1.0, 0.0, 1.0];
    let col_i = [0.0f32, 0.0, 1.0, 0.0];
    let want_i: [u8; 4] =
        std::array::from_fn(|c| unorm8(f64::from(interp.eval([tex_i[c], col_i[c], 0.25]))));
    assert_eq!(want_i, [64, 64, 191, 64]);
    // Right half: ADD_SIGNED(texture, primary) × 2 for RGB, × 1 for alpha:
    // texel (0.6, 0.2, 1.0, 0.8), colour (0.3, 0.1, 0.25, 0.5) → (0.8, 0 clamped, 1 clamped, 0.8).
    let tex_a = [153u8, 51, 255, 204];
    let col_a = [0.3f32, 0.1, 0.25, 0.5];
    let want_a: [u8; 4] = std::array::from_fn(|c| {
        let scale = if c == 3 { 1.0 } else { 2.0 };
        let v = CombineFunc::AddSigned.eval([f32::from(tex_a[c]) / 255.0, col_a[c], 0.0]);
        unorm8(f64::from(v * scale))
    });
    assert_eq!(want_a, [204, 0, 255, 204]);

    let env = Command::TexEnv;
    for backend in support::HEADLESS {
        let (ctx, t, mut pipe) = setup(backend, 8, 4, false);
        let mut cmds = clear_all();
        cmds.extend(ortho(0.0, 8.0, 0.0, 4.0));
        cmds.extend(rgba_texture(1, 1, 1, vec![255, 255, 0, 255]));
        cmds.extend(rgba_texture(2, 1, 1, tex_a.to_vec()));
        cmds.extend([
            Command::BindTexture {
                target: TextureTarget::Texture2D,
                name: 1,
            },
            env(TexEnvParam::Mode(TexEnvMode::Combine)),
            env(TexEnvParam::Color(Vec4::splat(0.25))),
        ]);
        cmds.extend([
            env(TexEnvParam::CombineRgb(interp)),
            env(TexEnvParam::CombineAlpha(interp)),
            env(TexEnvParam::SourceRgb(Arg0, CombineSource::Texture)),
            env(TexEnvParam::SourceRgb(Arg1, CombineSource::PrimaryColor)),
            env(TexEnvParam::SourceRgb(Arg2, CombineSource::Constant)),
            env(TexEnvParam::OperandRgb(Arg2, CombineOperand::SrcColor)),
            env(TexEnvParam::SourceAlpha(Arg0, CombineSource::Texture)),
            env(TexEnvParam::SourceAlpha(Arg1, CombineSource::PrimaryColor)),
            env(TexEnvParam::SourceAlpha(Arg2, CombineSource::Constant)),
            Command::Color(Vec4::from(col_i)),
            quad(0.0, 0.0, 4.0, 4.0, 0.0),
            Command::BindTexture {
                target: TextureTarget::Texture2D,
                name: 2,
            },
            env(TexEnvParam::CombineRgb(CombineFunc::AddSigned)),
            env(TexEnvParam::CombineAlpha(CombineFunc::AddSigned)),
            env(TexEnvParam::RgbScale(2.0)),
            Command::Color(Vec4::from(col_a)),
            quad(4.0, 0.0, 8.0, 4.0, 0.0),
        ]);
        run(&ctx, &mut pipe, &cmds);
        let img = t.read_color(&ctx).expect("colour");
        // ±1: one 8-bit step for the unorm8 conversions of texel, colour and result.
        probe(&img, 1, 1, want_i, 1);
        probe(&img, 6, 2, want_a, 1);
    }
}

/// piglit fbo-alphatest-formats boundaries (tolerance 3/2^8 in piglit; here exact pass/fail).
#[test]
fn alpha_test_boundaries_match_piglit() {
    use CompareFunc::*;
    let cases = [
        (0.2, Less, 0.25, true),
        (0.96, Lequal, 0.92, false),
        (0.6, Greater, 0.55, true),
        (0.9, Greater, 0.1, true),
        (0.35, Gequal, 0.4, false),
        (0.4, Equal, 0.4, true),
        (0.8, Notequal, 0.8, false),
        (1.0, Never, 3.0, false),
    ];
    for backend in support::HEADLESS {
        let (ctx, t, mut pipe) = setup(backend, cases.len() as u32, 1, false);
        let mut cmds = clear_all();
        cmds.extend(ortho(0.0, cases.len() as f32, 0.0, 1.0));
        cmds.push(Command::Enable(Capability::AlphaTest));
        for (i, &(alpha, func, reference, _)) in cases.iter().enumerate() {
            let x = i as f32;
            cmds.extend([
                Command::AlphaFunc { func, reference },
                Command::Color(Vec4::new(1.0, 1.0, 1.0, alpha)),
                quad(x, 0.0, x + 1.0, 1.0, 0.0),
            ]);
        }
        run(&ctx, &mut pipe, &cmds);
        let img = t.read_color(&ctx).expect("colour");
        for (i, &(alpha, func, reference, pass)) in cases.iter().enumerate() {
            let got = img.get_pixel(i as u32, 0).0;
            assert_eq!(
                got[0] == 255,
                pass,
                "{backend}: alpha {alpha} {func:?} {reference} gave {got:?}"
            );
        }
    }
}

/// piglit general/stencil-wrap: INCR max+5 times saturates at max, DECR from 0 stays 0,
/// INCR_WRAP max+5 times leaves 4, DECR_WRAP 5 times from 0 leaves max − 4; the stencil is
/// read back through a ReadPixels slot and agrees with the model's `StencilOp::apply`.
#[test]
fn stencil_wrap_matches_piglit() {
    let max = 255u32;
    let runs = [
        (StencilOp::Incr, max + 5, 255u8),
        (StencilOp::Decr, 5, 0),
        (StencilOp::IncrWrap, max + 5, 4),
        (StencilOp::DecrWrap, 5, 251),
    ];
    for backend in support::HEADLESS {
        let (ctx, _t, mut pipe) = setup(backend, 4, 1, true);
        let mut cmds = vec![Command::ClearStencil(0)];
        cmds.extend(clear_all());
        cmds.extend(ortho(0.0, 4.0, 0.0, 1.0));
        cmds.extend([
            Command::Enable(Capability::StencilTest),
            Command::StencilFunc {
                func: CompareFunc::Always,
                reference: 0,
                mask: !0,
            },
        ]);
        for (i, &(op, times, _)) in runs.iter().enumerate() {
            let x = i as f32;
            cmds.push(Command::StencilOp {
                fail: StencilOp::Keep,
                depth_fail: StencilOp::Keep,
                depth_pass: op,
            });
            let q = quad(x, 0.0, x + 1.0, 1.0, 0.0);
            cmds.extend(std::iter::repeat_n(q, times as usize));
        }
        cmds.push(Command::ReadPixels(ReadPixels {
            x: 0,
            y: 0,
            width: 4,
            height: 1,
            format: PixelFormat::StencilIndex,
            ty: PixelType::UnsignedByte,
            slot: 3,
        }));
        run(&ctx, &mut pipe, &cmds);
        let read = pipe.readback(3).expect("slot 3");
        for (i, &(op, times, want)) in runs.iter().enumerate() {
            let model = (0..times).fold(0, |v, _| op.apply(v, 0, max));
            assert_eq!(model, u32::from(want), "model {op:?}");
            assert_eq!(read.bytes[i], want, "{backend}: {op:?} × {times}");
        }
        assert_eq!(pipe.counters().draws, u64::from(2 * (max + 5) + 10));
    }
}

/// Depth read into slots with every type: UNSIGNED_BYTE truncates (⌊255z⌋, exactly),
/// UNSIGNED_SHORT rounds (⌊65535z + ½⌋, ±1 and ≥ 98 % exact, Mesa's rare ties),
/// UNSIGNED_INT agrees with FLOAT within 1e−6; on a ramp where truncation and rounding
/// differ for many bytes, so the rules are told apart.
#[test]
fn depth_readback_slots_follow_the_named_rules() {
    let w = 256;
    for backend in support::HEADLESS {
        let (ctx, _t, mut pipe) = setup(backend, w, 1, false);
        let mut cmds = clear_all();
        cmds.extend(ortho(0.0, w as f32, 0.0, 1.0));
        cmds.extend([
            Command::Enable(Capability::DepthTest),
            Command::DepthFunc(CompareFunc::Always),
            // Window z runs from 0 (object z = 1) on the left to 1 (z = −1) on the right.
            Command::Draw(Arc::new(Geometry::new(
                Primitive::Quads,
                vec![
                    Vec4::new(0.0, 0.0, 1.0, 1.0),
                    Vec4::new(w as f32, 0.0, -1.0, 1.0),
                    Vec4::new(w as f32, 1.0, -1.0, 1.0),
                    Vec4::new(0.0, 1.0, 1.0, 1.0),
                ],
            ))),
        ]);
        let types = [
            PixelType::UnsignedByte,
            PixelType::UnsignedShort,
            PixelType::UnsignedInt,
            PixelType::Float,
        ];
        for (slot, ty) in types.into_iter().enumerate() {
            cmds.push(Command::ReadPixels(ReadPixels {
                x: 0,
                y: 0,
                width: w as i32,
                height: 1,
                format: PixelFormat::DepthComponent,
                ty,
                slot: slot as u32,
            }));
        }
        run(&ctx, &mut pipe, &cmds);
        let slot = |s: u32| pipe.readback(s).expect("slot").bytes.clone();
        let floats: Vec<f32> = slot(3)
            .chunks_exact(4)
            .map(|b| f32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
            .collect();
        assert_eq!(floats.len(), w as usize);
        let bytes = slot(0);
        let mut differs = 0;
        for (i, (&b, &z)) in bytes.iter().zip(&floats).enumerate() {
            let z = f64::from(z);
            assert_eq!(b, (255.0 * z).floor() as u8, "{backend}: byte {i}, z {z}");
            if b != (255.0 * z + 0.5).floor() as u8 {
                differs += 1;
            }
        }
        assert!(differs > 64, "{backend}: the ramp must separate the rules");
        let shorts: Vec<u16> = slot(1)
            .chunks_exact(2)
            .map(|b| u16::from_ne_bytes([b[0], b[1]]))
            .collect();
        let mut exact = 0;
        for (&s, &z) in shorts.iter().zip(&floats) {
            let want = (65535.0 * f64::from(z) + 0.5).floor() as u16;
            assert!(s.abs_diff(want) <= 1, "{backend}: short {s}, want {want}");
            exact += usize::from(s == want);
        }
        assert!(exact * 100 >= 98 * shorts.len(), "{backend}: {exact} exact");
        let ints = slot(2);
        for (b, &z) in ints.chunks_exact(4).zip(&floats) {
            let i = u32::from_ne_bytes([b[0], b[1], b[2], b[3]]);
            let from_int = f64::from(i) / f64::from(u32::MAX);
            assert!(
                (from_int - f64::from(z)).abs() < 1e-6,
                "{backend}: int {i} z {z}"
            );
        }
    }
}

/// The commands of the texture-matrix case: texel 0 red, texel 1 green (NEAREST); the
/// current texture coordinate s = 0.25 samples red; the texture matrix translates s by 0.5
/// (green), is pushed, replaced by the identity, and popped before the draw.
fn texture_matrix_pop_case() -> Vec<Command> {
    let mut cmds = clear_all();
    cmds.extend(ortho(0.0, 1.0, 0.0, 1.0));
    cmds.extend(rgba_texture(5, 2, 1, vec![255, 0, 0, 255, 0, 255, 0, 255]));
    cmds.extend([
        Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Replace)),
        Command::TexCoord {
            unit: 0,
            coord: Vec4::new(0.25, 0.5, 0.0, 1.0),
        },
        // A draw first, so the texture state is validated before the push/pop.
        quad(0.0, 0.0, 1.0, 1.0, 0.0),
        Command::MatrixMode(MatrixMode::Texture),
        Command::LoadIdentity,
        Command::Translate(Vec3::new(0.5, 0.0, 0.0)),
        Command::PushMatrix,
        Command::LoadIdentity,
        quad(0.0, 0.0, 1.0, 1.0, 0.0),
        Command::PopMatrix,
        Command::MatrixMode(MatrixMode::Modelview),
        quad(0.0, 0.0, 1.0, 1.0, 0.0),
    ]);
    cmds
}

/// The Mesa texture-matrix bug (DESIGN "Measured facts") and its workaround: the pipeline
/// draws with the popped (translated) matrix, green. Replaying the same GL calls without the
/// re-load draws red on Mesa 22.3: if that ever turns green, Mesa is fixed and the
/// workaround can go.
#[test]
fn texture_matrix_survives_a_pop() {
    for backend in support::HEADLESS {
        let (ctx, t, mut pipe) = setup(backend, 4, 4, false);
        let cmds = texture_matrix_pop_case();
        run(&ctx, &mut pipe, &cmds);
        assert_eq!(
            pipe.state().texture_matrix(0),
            Mat4::from_translation(Vec3::new(0.5, 0.0, 0.0))
        );
        let img = t.read_color(&ctx).expect("colour");
        probe(&img, 2, 2, [0, 255, 0, 255], 0);
        assert_eq!(pipe.counters().texture_uploads, 1);
        assert_eq!(pipe.counters().draws, 3);
        assert_eq!(pipe.counters().commands, cmds.len() as u64);
        assert_eq!(pipe.counters().programs_compiled, 0);
        // release deletes the GL texture objects.
        assert_eq!(pipe.texture_objects(), 1);
        pipe.release(&ctx);
        assert_eq!(pipe.texture_objects(), 0);
        assert_no_gl_error(&ctx);
    }
}

/// The bug itself, in raw GL: without the re-load Mesa samples with the identity (red).
#[test]
fn mesa_draws_with_the_identity_after_a_texture_pop() {
    for backend in support::HEADLESS {
        let ctx = context(backend, Profile::Compatibility);
        let t = target(&ctx, 4, 4, DepthBits::D24, false);
        let native = NativeGl::load(&ctx).expect("compatibility");
        let g = native.raw();
        let texels: [u8; 8] = [255, 0, 0, 255, 0, 255, 0, 255];
        let mut tex = 0;
        let draw = || unsafe {
            g.Begin(gl::QUADS);
            g.Vertex2f(0.0, 0.0);
            g.Vertex2f(1.0, 0.0);
            g.Vertex2f(1.0, 1.0);
            g.Vertex2f(0.0, 1.0);
            g.End();
        };
        unsafe {
            g.MatrixMode(gl::PROJECTION);
            g.LoadIdentity();
            g.Ortho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
            g.MatrixMode(gl::MODELVIEW);
            g.LoadIdentity();
            g.GenTextures(1, &mut tex);
            g.BindTexture(gl::TEXTURE_2D, tex);
            g.PixelStorei(gl::UNPACK_ALIGNMENT, 1);
            g.TexImage2D(
                gl::TEXTURE_2D,
                0,
                gl::RGBA8 as i32,
                2,
                1,
                0,
                gl::RGBA,
                gl::UNSIGNED_BYTE,
                texels.as_ptr().cast(),
            );
            g.TexParameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
            g.TexParameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
            g.TexEnvi(gl::TEXTURE_ENV, gl::TEXTURE_ENV_MODE, gl::REPLACE as i32);
            g.Enable(gl::TEXTURE_2D);
            g.MultiTexCoord4f(gl::TEXTURE0, 0.25, 0.5, 0.0, 1.0);
            draw();
            g.MatrixMode(gl::TEXTURE);
            g.LoadIdentity();
            g.Translatef(0.5, 0.0, 0.0);
            g.PushMatrix();
            g.LoadIdentity();
            draw();
            g.PopMatrix();
            g.MatrixMode(gl::MODELVIEW);
            draw();
        }
        let img = t.read_color(&ctx).expect("colour");
        probe(&img, 2, 2, [255, 0, 0, 255], 0);
        assert_no_gl_error(&ctx);
    }
}

/// Register combiners have no native path: a draw with them enabled is refused, clearly.
#[test]
fn register_combiners_are_unsupported_natively() {
    for backend in support::HEADLESS {
        let (ctx, _t, mut pipe) = setup(backend, 4, 4, false);
        // Enabling them alone is only model state (Mesa would raise INVALID_ENUM).
        let enable = [Command::Enable(Capability::RegisterCombiners)];
        run(&ctx, &mut pipe, &enable);
        assert!(pipe.state().register_combiners.enabled);
        let err = pipe
            .execute(&ctx, &[quad(-1.0, -1.0, 1.0, 1.0, 0.0)])
            .expect_err("a draw with register combiners must fail");
        assert!(
            matches!(err, PipelineError::Unsupported { path: "native", .. }),
            "{backend}: {err}"
        );
        assert!(err.to_string().contains("register_combiners"), "{err}");
        assert_eq!(pipe.counters().draws, 0);
        // Disabled again, the same draw runs.
        let cmds = [
            Command::Disable(Capability::RegisterCombiners),
            quad(-1.0, -1.0, 1.0, 1.0, 0.0),
        ];
        run(&ctx, &mut pipe, &cmds);
        assert_eq!(pipe.counters().draws, 1);
    }
}

/// A command the model rejects sends nothing to GL: GL raises no error of its own, its state
/// is unchanged, and `take_gl_error` reports the model's error once. The texture stack is
/// the sharp case: the push beyond the model's depth (Mesa's, 10) is rejected before GL
/// sees it.
#[test]
fn rejected_commands_leave_gl_untouched() {
    for backend in support::HEADLESS {
        let (ctx, _t, mut pipe) = setup(backend, 4, 4, false);
        let native = NativeGl::load(&ctx).expect("compatibility");
        let g = native.raw();
        let mut cmds = vec![
            Command::Viewport(Viewport {
                x: 0,
                y: 0,
                width: 3,
                height: 3,
            }),
            Command::Viewport(Viewport {
                x: 1,
                y: 1,
                width: -2,
                height: 2,
            }),
            Command::LineWidth(-1.0),
            Command::MatrixMode(MatrixMode::Texture),
        ];
        cmds.extend(std::iter::repeat_n(
            Command::PushMatrix,
            TEXTURE_STACK_DEPTH,
        ));
        cmds.push(Command::MatrixMode(MatrixMode::Modelview));
        pipe.execute(&ctx, &cmds).expect("execute");
        assert_no_gl_error(&ctx);
        let first = pipe.take_gl_error().expect("the model's error");
        assert_eq!(first.kind, GlErrorKind::InvalidValue, "{first}");
        assert_eq!(pipe.take_gl_error(), None, "errors are read once");
        let mut viewport = [0i32; 4];
        let mut depth = 0i32;
        let mut line = 0.0f32;
        unsafe {
            g.GetIntegerv(gl::VIEWPORT, viewport.as_mut_ptr());
            g.MatrixMode(gl::TEXTURE);
            g.GetIntegerv(gl::TEXTURE_STACK_DEPTH, &mut depth);
            g.MatrixMode(gl::MODELVIEW);
            g.GetFloatv(gl::LINE_WIDTH, &mut line);
        }
        assert_eq!(
            viewport,
            [0, 0, 3, 3],
            "{backend}: the accepted viewport only"
        );
        assert_eq!(
            depth, TEXTURE_STACK_DEPTH as i32,
            "{backend}: the rejected push never reached GL"
        );
        assert_eq!(line, 1.0);
        assert_eq!(
            pipe.state().texture_matrices[0].depth(),
            TEXTURE_STACK_DEPTH
        );
        assert_eq!(pipe.counters().commands, cmds.len() as u64);
        assert_no_gl_error(&ctx);
    }
}

/// The native path needs a compatibility context.
#[test]
fn a_core_context_is_the_wrong_profile() {
    let ctx = context(support::HEADLESS[0], Profile::Core33);
    let err = NativePipeline::new(&ctx)
        .err()
        .expect("core context refused");
    assert!(matches!(err, PipelineError::WrongProfile { .. }), "{err}");
}

/// The model's matrix stacks are as deep as Mesa's (GL_MAX_*_STACK_DEPTH), so a program
/// overflows on the emulated path exactly where it overflows natively.
#[test]
fn matrix_stack_depths_are_mesas() {
    for backend in support::HEADLESS {
        let (ctx, _t, _pipe) = setup(backend, 4, 4, false);
        let native = NativeGl::load(&ctx).expect("compatibility");
        let g = native.raw();
        let mut depths = [0i32; 3];
        unsafe {
            g.GetIntegerv(gl::MAX_MODELVIEW_STACK_DEPTH, &mut depths[0]);
            g.GetIntegerv(gl::MAX_PROJECTION_STACK_DEPTH, &mut depths[1]);
            g.GetIntegerv(gl::MAX_TEXTURE_STACK_DEPTH, &mut depths[2]);
        }
        assert_eq!(
            depths.map(|d| d as usize),
            [
                MODELVIEW_STACK_DEPTH,
                PROJECTION_STACK_DEPTH,
                TEXTURE_STACK_DEPTH
            ],
            "{backend}"
        );
        assert_no_gl_error(&ctx);
    }
}
