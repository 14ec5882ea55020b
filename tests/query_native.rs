//! The model's query answers against the real driver: each scene runs on the native
//! pipeline (compatibility context, EGL and OSMesa), then every pname of `ff::query` is read
//! from Mesa with glGetBooleanv/Integerv/Floatv/Doublev and glIsEnabled, and every light,
//! material, texenv, texgen, texparameter and texlevelparameter pname with each of its
//! getters, on every texture unit; the model's answer, converted by `QueryValue`, must match.
//!
//! Tolerance: booleans, integers and enums exactly; floats and doubles within
//! |a − b| ≤ 1e-6 · max(|a|, |b|, 1) (relative above 1, absolute below; the driver computes
//! matrices and eye-space planes in its own order of operations).
//!
//! Left out of the comparison, each for a reason:
//! - the NV_register_combiners pnames and capability: Mesa does not expose the extension;
//! - TEXTURE_COMPARE_FAIL_VALUE_ARB: Mesa does not expose ARB_shadow_ambient.
//!
//! Scenes keep to what both sides store alike: depth values exactly representable in f32
//! (Mesa keeps glDepthRange and glClearDepth as doubles, and glGetIntegerv scales the
//! double), sized internal formats (Mesa returns an unsized one as given), texture names
//! bound in increasing order from 1 (the native path's glGenTextures names are 1, 2, 3…).

mod support;

use std::sync::Arc;

use fixedfunc::ff::glenum::registry as r;
use fixedfunc::ff::query::{self, NV_PNAMES};
use fixedfunc::ff::{
    AttribGroup, AttribMask, BlendFactor, Capability, ClearMask, ColorControl, ColorMask,
    ColorMaterialMode, CombineArg, CombineFunc, CombineOperand, CombineSource, Command,
    CompareFunc, CompareMode, CubeFace, DepthTextureMode, Face, Filter, FixedState, FrontFace,
    Geometry, GlErrorKind, LightModelParam, LightParam, MaterialParam, MatrixMode, PixelFormat,
    PixelType, PolygonMode, Primitive, QueryValue, ShadeModel, StencilOp, TexCoord, TexEnvMode,
    TexEnvParam, TexFormat, TexGenMode, TexGenParam, TexImage, TexParam, TextureTarget, ViewVolume,
    Viewport, Wrap, MAX_TEXTURE_UNITS,
};
use fixedfunc::gpu::{Backend, GpuContext, Profile, RenderTarget};
use fixedfunc::pipeline::native::{bindings as gl, NativeGl, NativePipeline};
use fixedfunc::pipeline::Pipeline;
use fixedfunc::vocab::DepthBits;
use glam::{Mat4, Vec3, Vec4};
use support::{context, target, HEADLESS};

const W: u32 = 32;
const H: u32 = 32;

fn setup(backend: Backend) -> (GpuContext, RenderTarget, NativePipeline) {
    let ctx = context(backend, Profile::Compatibility);
    let t = target(&ctx, W, H, DepthBits::D24, true);
    let pipe = NativePipeline::new(&ctx).expect("native pipeline");
    (ctx, t, pipe)
}

/// Floats agree within 1e-6 · max(|a|, |b|, 1); NaN agrees with NaN.
fn close(a: f64, b: f64) -> bool {
    a == b || (a.is_nan() && b.is_nan()) || (a - b).abs() <= 1e-6 * a.abs().max(b.abs()).max(1.0)
}

/// What the driver wrote through each getter of one query (`None`: the getter does not
/// exist for it).
#[derive(Default)]
struct Read {
    b: Option<Vec<u8>>,
    i: Option<Vec<i32>>,
    f: Option<Vec<f32>>,
    d: Option<Vec<f64>>,
}

/// Compares one answer read every available way; mismatches are collected, not panicked
/// on, so a run reports all of them.
fn compare(label: &str, model: &[QueryValue], read: &Read, out: &mut Vec<String>) {
    let n = model.len();
    if let Some(b) = &read.b {
        let want: Vec<u8> = model.iter().map(|v| u8::from(v.as_bool())).collect();
        if b[..n] != want[..] {
            out.push(format!(
                "{label} boolean: driver {:?}, model {want:?}",
                &b[..n]
            ));
        }
    }
    if let Some(i) = &read.i {
        let want: Vec<i32> = model.iter().map(|v| v.as_int()).collect();
        if i[..n] != want[..] {
            out.push(format!(
                "{label} integer: driver {:?}, model {want:?}",
                &i[..n]
            ));
        }
    }
    if let Some(f) = &read.f {
        let want: Vec<f32> = model.iter().map(|v| v.as_float()).collect();
        if !f[..n]
            .iter()
            .zip(&want)
            .all(|(a, b)| close(f64::from(*a), f64::from(*b)))
        {
            out.push(format!(
                "{label} float: driver {:?}, model {want:?}",
                &f[..n]
            ));
        }
    }
    if let Some(d) = &read.d {
        let want: Vec<f64> = model.iter().map(|v| v.as_double()).collect();
        if !d[..n].iter().zip(&want).all(|(a, b)| close(*a, *b)) {
            out.push(format!(
                "{label} double: driver {:?}, model {want:?}",
                &d[..n]
            ));
        }
    }
}

/// Every query of the model against the driver, for the active unit of `s`.
struct Oracle<'a> {
    g: &'a gl::Gl,
    out: Vec<String>,
}

impl Oracle<'_> {
    fn error(&mut self, label: &str) {
        // SAFETY: plain GL call.
        let e = unsafe { self.g.GetError() };
        if e != gl::NO_ERROR {
            self.out.push(format!("{label}: driver raised 0x{e:04X}"));
        }
    }

    fn check(&mut self, label: String, model: &[QueryValue], read: Read) {
        self.error(&label);
        compare(&label, model, &read, &mut self.out);
    }

    fn get(&mut self, s: &FixedState, pname: u32) {
        let label = format!(
            "{} (0x{pname:04X})",
            query::pname_name(pname).unwrap_or("?")
        );
        let model = s.get(pname).expect("a table pname answers");
        let g = self.g;
        // SAFETY: every buffer holds 16 values, the most any pname writes.
        let read = unsafe {
            let mut b = vec![0u8; 16];
            let mut i = vec![0i32; 16];
            let mut f = vec![0f32; 16];
            let mut d = vec![0f64; 16];
            g.GetBooleanv(pname, b.as_mut_ptr());
            g.GetIntegerv(pname, i.as_mut_ptr());
            g.GetFloatv(pname, f.as_mut_ptr());
            g.GetDoublev(pname, d.as_mut_ptr());
            Read {
                b: Some(b),
                i: Some(i),
                f: Some(f),
                d: Some(d),
            }
        };
        self.check(label, &model, read);
    }

    fn is_enabled(&mut self, s: &FixedState, cap: u32) {
        let model = s.is_enabled(cap).expect("a capability answers");
        // SAFETY: plain GL call.
        let driver = unsafe { self.g.IsEnabled(cap) } != 0;
        self.error("IsEnabled");
        if driver != model {
            self.out.push(format!(
                "glIsEnabled({}): driver {driver}, model {model}",
                query::pname_name(cap).unwrap_or("?")
            ));
        }
    }

    /// The glGet table and glIsEnabled for the active unit.
    fn state(&mut self, s: &FixedState) {
        // The native path's window is a framebuffer object of the test's render target:
        // the framebuffer bindings and colour buffers of a real window are checked
        // against Mesa's OSMesa by tests/c/fbo.c instead.
        let skip = [
            r::REGISTER_COMBINERS_NV,
            query::TEXTURE_COMPARE_FAIL_VALUE_ARB,
            r::DRAW_FRAMEBUFFER_BINDING,
            r::READ_FRAMEBUFFER_BINDING,
            r::RENDERBUFFER_BINDING,
            r::DRAW_BUFFER,
            r::READ_BUFFER,
            // The layer lists the three S3TC formats it decodes of Mesa's twelve (README,
            // "Compressed textures"); tests/c/compressed.c checks they are Mesa's.
            r::NUM_COMPRESSED_TEXTURE_FORMATS,
            r::COMPRESSED_TEXTURE_FORMATS,
        ];
        for p in query::pnames() {
            if NV_PNAMES.contains(&p) || skip.contains(&p) {
                continue;
            }
            self.get(s, p);
        }
        for cap in query::capabilities() {
            if cap != r::REGISTER_COMBINERS_NV {
                self.is_enabled(s, cap);
            }
        }
    }

    fn lights(&mut self, s: &FixedState) {
        let pnames = [
            r::AMBIENT,
            r::DIFFUSE,
            r::SPECULAR,
            r::POSITION,
            r::SPOT_DIRECTION,
            r::SPOT_EXPONENT,
            r::SPOT_CUTOFF,
            r::CONSTANT_ATTENUATION,
            r::LINEAR_ATTENUATION,
            r::QUADRATIC_ATTENUATION,
        ];
        for l in 0..8 {
            for p in pnames {
                let model = s.get_light(r::LIGHT0 + l, p).unwrap();
                let (mut f, mut i) = (vec![0f32; 16], vec![0i32; 16]);
                // SAFETY: 16-value buffers.
                unsafe {
                    self.g.GetLightfv(r::LIGHT0 + l, p, f.as_mut_ptr());
                    self.g.GetLightiv(r::LIGHT0 + l, p, i.as_mut_ptr());
                }
                let read = Read {
                    f: Some(f),
                    i: Some(i),
                    ..Read::default()
                };
                self.check(format!("glGetLight(LIGHT{l}, 0x{p:04X})"), &model, read);
            }
        }
        let pnames = [
            r::AMBIENT,
            r::DIFFUSE,
            r::SPECULAR,
            r::EMISSION,
            r::SHININESS,
        ];
        for face in [r::FRONT, r::BACK] {
            for p in pnames {
                let model = s.get_material(face, p).unwrap();
                let (mut f, mut i) = (vec![0f32; 16], vec![0i32; 16]);
                // SAFETY: 16-value buffers.
                unsafe {
                    self.g.GetMaterialfv(face, p, f.as_mut_ptr());
                    self.g.GetMaterialiv(face, p, i.as_mut_ptr());
                }
                let read = Read {
                    f: Some(f),
                    i: Some(i),
                    ..Read::default()
                };
                self.check(
                    format!("glGetMaterial(0x{face:04X}, 0x{p:04X})"),
                    &model,
                    read,
                );
            }
        }
    }

    /// Texenv, texgen and the bound textures' parameters of the active unit.
    fn unit(&mut self, s: &FixedState) {
        let u = s.active_unit();
        let env = [
            r::TEXTURE_ENV_MODE,
            r::TEXTURE_ENV_COLOR,
            r::COMBINE_RGB,
            r::COMBINE_ALPHA,
            r::SOURCE0_RGB,
            r::SOURCE1_RGB,
            r::SOURCE2_RGB,
            r::SOURCE0_ALPHA,
            r::SOURCE1_ALPHA,
            r::SOURCE2_ALPHA,
            r::OPERAND0_RGB,
            r::OPERAND1_RGB,
            r::OPERAND2_RGB,
            r::OPERAND0_ALPHA,
            r::OPERAND1_ALPHA,
            r::OPERAND2_ALPHA,
            r::RGB_SCALE,
            r::ALPHA_SCALE,
        ];
        for p in env {
            let model = s.get_tex_env(r::TEXTURE_ENV, p).unwrap();
            let (mut f, mut i) = (vec![0f32; 16], vec![0i32; 16]);
            // SAFETY: 16-value buffers.
            unsafe {
                self.g.GetTexEnvfv(r::TEXTURE_ENV, p, f.as_mut_ptr());
                self.g.GetTexEnviv(r::TEXTURE_ENV, p, i.as_mut_ptr());
            }
            let read = Read {
                f: Some(f),
                i: Some(i),
                ..Read::default()
            };
            self.check(format!("unit {u} glGetTexEnv(0x{p:04X})"), &model, read);
        }
        for coord in [r::S, r::T, r::R, r::Q] {
            for p in [r::TEXTURE_GEN_MODE, r::OBJECT_PLANE, r::EYE_PLANE] {
                let model = s.get_tex_gen(coord, p).unwrap();
                let (mut f, mut i, mut d) = (vec![0f32; 16], vec![0i32; 16], vec![0f64; 16]);
                // SAFETY: 16-value buffers.
                unsafe {
                    self.g.GetTexGenfv(coord, p, f.as_mut_ptr());
                    self.g.GetTexGeniv(coord, p, i.as_mut_ptr());
                    self.g.GetTexGendv(coord, p, d.as_mut_ptr());
                }
                let read = Read {
                    f: Some(f),
                    i: Some(i),
                    d: Some(d),
                    ..Read::default()
                };
                let label = format!("unit {u} glGetTexGen(0x{coord:04X}, 0x{p:04X})");
                self.check(label, &model, read);
            }
        }
        for target in [r::TEXTURE_1D, r::TEXTURE_2D] {
            self.texture(s, u, target, &[target]);
        }
        // A cube map's parameters are the cube's, its levels the faces'.
        let faces: Vec<u32> = (0..6).map(|f| r::TEXTURE_CUBE_MAP_POSITIVE_X + f).collect();
        self.texture(s, u, r::TEXTURE_CUBE_MAP, &faces);
    }

    /// The parameters of `target`'s texture and the levels of its image targets.
    fn texture(&mut self, s: &FixedState, u: usize, target: u32, images: &[u32]) {
        let params = [
            r::TEXTURE_MIN_FILTER,
            r::TEXTURE_MAG_FILTER,
            r::TEXTURE_WRAP_S,
            r::TEXTURE_WRAP_T,
            r::TEXTURE_BORDER_COLOR,
            r::TEXTURE_COMPARE_MODE,
            r::TEXTURE_COMPARE_FUNC,
            r::DEPTH_TEXTURE_MODE,
            r::GENERATE_MIPMAP,
            r::TEXTURE_BASE_LEVEL,
            r::TEXTURE_MAX_LEVEL,
            r::TEXTURE_MIN_LOD,
            r::TEXTURE_MAX_LOD,
        ];
        for p in params {
            let model = s.get_tex_parameter(target, p).unwrap();
            let (mut f, mut i) = (vec![0f32; 16], vec![0i32; 16]);
            // SAFETY: 16-value buffers.
            unsafe {
                self.g.GetTexParameterfv(target, p, f.as_mut_ptr());
                self.g.GetTexParameteriv(target, p, i.as_mut_ptr());
            }
            let read = Read {
                f: Some(f),
                i: Some(i),
                ..Read::default()
            };
            let label = format!("unit {u} glGetTexParameter(0x{target:04X}, 0x{p:04X})");
            self.check(label, &model, read);
        }
        let level_params = [
            r::TEXTURE_WIDTH,
            r::TEXTURE_HEIGHT,
            r::TEXTURE_BORDER,
            r::TEXTURE_INTERNAL_FORMAT,
            r::TEXTURE_RED_SIZE,
            r::TEXTURE_GREEN_SIZE,
            r::TEXTURE_BLUE_SIZE,
            r::TEXTURE_ALPHA_SIZE,
            r::TEXTURE_LUMINANCE_SIZE,
            r::TEXTURE_INTENSITY_SIZE,
            r::TEXTURE_DEPTH_SIZE,
            r::TEXTURE_COMPRESSED,
        ];
        for (&target, level) in images.iter().flat_map(|t| (0..3).map(move |l| (t, l))) {
            for p in level_params {
                let model = s.get_tex_level_parameter(target, level, p).unwrap();
                let (mut f, mut i) = (vec![0f32; 16], vec![0i32; 16]);
                // SAFETY: 16-value buffers.
                unsafe {
                    self.g
                        .GetTexLevelParameterfv(target, level, p, f.as_mut_ptr());
                    self.g
                        .GetTexLevelParameteriv(target, level, p, i.as_mut_ptr());
                }
                let read = Read {
                    f: Some(f),
                    i: Some(i),
                    ..Read::default()
                };
                let label =
                    format!("unit {u} glGetTexLevelParameter(0x{target:04X}, {level}, 0x{p:04X})");
                self.check(label, &model, read);
            }
        }
    }
}

/// Runs `scene` and compares every query on every unit; the mismatches, labelled.
fn mismatches(backend: Backend, scene: &[Command]) -> Vec<String> {
    let (ctx, _t, mut pipe) = setup(backend);
    let mut cmds = vec![Command::Viewport(Viewport {
        x: 0,
        y: 0,
        width: W as i32,
        height: H as i32,
    })];
    cmds.extend_from_slice(scene);
    pipe.execute(&ctx, &cmds).expect("scene runs");
    assert_eq!(pipe.take_gl_error(), None, "the scene is valid");
    let native = NativeGl::load(&ctx).expect("compatibility context");
    let mut oracle = Oracle {
        g: native.raw(),
        out: Vec::new(),
    };
    oracle.error("before the queries");
    oracle.lights(pipe.state());
    let active = pipe.state().active_unit() as u8;
    for u in 0..MAX_TEXTURE_UNITS as u8 {
        pipe.execute(&ctx, &[Command::ActiveTexture(u)]).unwrap();
        oracle.state(pipe.state());
        oracle.unit(pipe.state());
    }
    pipe.execute(&ctx, &[Command::ActiveTexture(active)])
        .unwrap();
    oracle.state(pipe.state());
    oracle.out
}

fn assert_agree(name: &str, scene: &[Command]) {
    for backend in HEADLESS {
        let m = mismatches(backend, scene);
        assert!(
            m.is_empty(),
            "{name} on {backend}: {} mismatches\n{}",
            m.len(),
            m.join("\n")
        );
    }
}

#[test]
fn defaults_agree() {
    assert_agree("defaults", &[]);
}

fn lighting_scene() -> Vec<Command> {
    vec![
        Command::MatrixMode(MatrixMode::Modelview),
        Command::Translate(Vec3::new(1.0, -2.0, 0.5)),
        Command::Rotate {
            angle_deg: 30.0,
            axis: Vec3::new(0.0, 1.0, 0.0),
        },
        Command::Enable(Capability::Lighting),
        Command::Enable(Capability::Light(0)),
        Command::Enable(Capability::Light(2)),
        Command::Light {
            light: 0,
            param: LightParam::Position(Vec4::new(2.5, 3.7, -1.2, 1.0)),
        },
        Command::Light {
            light: 0,
            param: LightParam::Ambient(Vec4::new(0.1, 0.25, 0.5, 1.0)),
        },
        Command::Light {
            light: 2,
            param: LightParam::Diffuse(Vec4::new(0.3, -0.6, 0.9, 0.75)),
        },
        Command::Light {
            light: 2,
            param: LightParam::Specular(Vec4::new(0.2, 0.4, 0.8, 1.0)),
        },
        Command::Light {
            light: 2,
            param: LightParam::SpotDirection(Vec3::new(0.0, -1.0, -1.0)),
        },
        Command::Light {
            light: 2,
            param: LightParam::SpotCutoff(45.5),
        },
        Command::Light {
            light: 2,
            param: LightParam::SpotExponent(12.7),
        },
        Command::Light {
            light: 2,
            param: LightParam::LinearAttenuation(0.5),
        },
        Command::Light {
            light: 2,
            param: LightParam::QuadraticAttenuation(2.5),
        },
        Command::LightModel(LightModelParam::Ambient(Vec4::new(0.05, 0.1, 0.15, 0.2))),
        Command::LightModel(LightModelParam::LocalViewer(true)),
        Command::LightModel(LightModelParam::TwoSide(true)),
        Command::LightModel(LightModelParam::ColorControl(
            ColorControl::SeparateSpecularColor,
        )),
        Command::Material {
            face: Face::Front,
            param: MaterialParam::Specular(Vec4::new(0.9, 0.8, 0.7, 1.0)),
        },
        Command::Material {
            face: Face::Back,
            param: MaterialParam::Emission(Vec4::new(0.1, 0.0, 0.3, 1.0)),
        },
        Command::Material {
            face: Face::FrontAndBack,
            param: MaterialParam::Shininess(37.5),
        },
        Command::ColorMaterial {
            face: Face::Back,
            mode: ColorMaterialMode::Diffuse,
        },
        Command::Enable(Capability::ColorMaterial),
        Command::Color(Vec4::new(0.25, 0.5, 0.75, 0.5)),
        Command::Normal(Vec3::new(0.6, 0.0, -0.8)),
        Command::ShadeModel(ShadeModel::Flat),
        Command::Enable(Capability::Normalize),
        Command::Enable(Capability::RescaleNormal),
    ]
}

#[test]
fn lighting_agrees() {
    assert_agree("lighting", &lighting_scene());
}

fn texenv_scene() -> Vec<Command> {
    let mut cmds = vec![
        Command::MatrixMode(MatrixMode::Modelview),
        Command::Translate(Vec3::new(0.0, 0.0, -3.0)),
    ];
    for u in 0..3u8 {
        let f = f32::from(u);
        cmds.extend([
            Command::ActiveTexture(u),
            Command::TexCoord {
                unit: u,
                coord: Vec4::new(0.5 + f, -1.5, 2.25, 1.0),
            },
            Command::TexGen {
                coord: TexCoord::S,
                param: TexGenParam::Mode(if u == 1 {
                    TexGenMode::SphereMap
                } else {
                    TexGenMode::ObjectLinear
                }),
            },
            Command::TexGen {
                coord: TexCoord::T,
                param: TexGenParam::EyePlane(Vec4::new(0.0, 1.0 + f, 0.5, 2.0)),
            },
            Command::TexGen {
                coord: TexCoord::R,
                param: TexGenParam::ObjectPlane(Vec4::new(1.5, -2.5, 0.0, 3.0)),
            },
            Command::Enable(Capability::TextureGen(TexCoord::S)),
            Command::Enable(Capability::TextureGen(TexCoord::T)),
            Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Combine)),
            Command::TexEnv(TexEnvParam::CombineRgb(CombineFunc::Interpolate)),
            Command::TexEnv(TexEnvParam::CombineAlpha(CombineFunc::AddSigned)),
            Command::TexEnv(TexEnvParam::SourceRgb(
                CombineArg::Arg1,
                CombineSource::TextureUnit(2 - u),
            )),
            Command::TexEnv(TexEnvParam::SourceAlpha(
                CombineArg::Arg2,
                CombineSource::PrimaryColor,
            )),
            Command::TexEnv(TexEnvParam::OperandRgb(
                CombineArg::Arg0,
                CombineOperand::OneMinusSrcAlpha,
            )),
            Command::TexEnv(TexEnvParam::OperandAlpha(
                CombineArg::Arg1,
                CombineOperand::OneMinusSrcAlpha,
            )),
            Command::TexEnv(TexEnvParam::RgbScale(2.0)),
            Command::TexEnv(TexEnvParam::AlphaScale(4.0)),
            Command::TexEnv(TexEnvParam::Color(Vec4::new(0.1, 0.2 * f, 0.3, 0.4))),
        ]);
    }
    cmds.push(Command::ActiveTexture(1));
    cmds
}

#[test]
fn texgen_and_texenv_agree() {
    assert_agree("texgen and texenv", &texenv_scene());
}

fn matrices_scene() -> Vec<Command> {
    vec![
        Command::MatrixMode(MatrixMode::Projection),
        Command::Frustum(ViewVolume {
            left: -1.0,
            right: 1.0,
            bottom: -0.75,
            top: 0.75,
            near: 1.0,
            far: 10.0,
        }),
        Command::PushMatrix,
        Command::Scale(Vec3::new(0.5, 0.25, 1.0)),
        Command::MatrixMode(MatrixMode::Modelview),
        Command::PushMatrix,
        Command::Translate(Vec3::new(0.25, 0.5, -0.75)),
        Command::PushMatrix,
        // A rotation by 90° about z, exactly (glRotatef's own rounding is not the subject).
        Command::MultMatrix(Mat4::from_cols_array(&[
            0.0, 1.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        ])),
        Command::PushMatrix,
        Command::ActiveTexture(1),
        Command::MatrixMode(MatrixMode::Texture),
        Command::Scale(Vec3::new(0.5, 0.5, 1.0)),
        Command::PushMatrix,
        Command::Translate(Vec3::new(0.125, 0.0, 0.0)),
        Command::ActiveTexture(0),
        Command::DepthRange {
            near: 0.25,
            far: 0.75,
        },
    ]
}

#[test]
fn matrices_and_stacks_agree() {
    assert_agree("matrices", &matrices_scene());
}

fn fragment_scene() -> Vec<Command> {
    vec![
        Command::Enable(Capability::AlphaTest),
        Command::AlphaFunc {
            func: CompareFunc::Gequal,
            reference: 0.375,
        },
        Command::Enable(Capability::DepthTest),
        Command::DepthFunc(CompareFunc::Lequal),
        Command::DepthMask(false),
        Command::Enable(Capability::StencilTest),
        Command::StencilFunc {
            func: CompareFunc::Notequal,
            reference: 300,
            mask: 0x3C,
        },
        Command::StencilOp {
            fail: StencilOp::Incr,
            depth_fail: StencilOp::DecrWrap,
            depth_pass: StencilOp::Invert,
        },
        Command::StencilMask(0xF0),
        Command::Enable(Capability::Blend),
        Command::BlendFunc {
            src: BlendFactor::SrcAlphaSaturate,
            dst: BlendFactor::OneMinusDstColor,
        },
        Command::ColorMask(ColorMask {
            r: true,
            g: false,
            b: true,
            a: false,
        }),
        Command::ClearColor(Vec4::new(0.25, 0.5, 0.125, 1.0)),
        Command::ClearDepth(0.25),
        Command::ClearStencil(77),
        Command::Enable(Capability::PolygonOffsetFill),
        Command::Enable(Capability::PolygonOffsetPoint),
        Command::PolygonOffset {
            factor: 1.5,
            units: -2.5,
        },
        Command::PolygonMode {
            face: Face::Front,
            mode: PolygonMode::Line,
        },
        Command::PolygonMode {
            face: Face::Back,
            mode: PolygonMode::Point,
        },
        Command::Enable(Capability::CullFace),
        Command::CullFace(Face::FrontAndBack),
        Command::FrontFace(FrontFace::Cw),
        Command::LineWidth(2.5),
        Command::PointSize(3.5),
        Command::Clear(ClearMask::ALL),
    ]
}

#[test]
fn fragment_state_agrees() {
    assert_agree("fragment", &fragment_scene());
}

fn image(target: TextureTarget, level: i32, format: TexFormat, w: i32, h: i32) -> Command {
    let (pf, ty) = if format.is_depth() {
        (PixelFormat::DepthComponent, PixelType::Float)
    } else {
        (PixelFormat::Rgba, PixelType::UnsignedByte)
    };
    let bytes = (w * h) as usize * pf.components() * ty.size();
    Command::TexImage(TexImage {
        requested: None,
        target,
        level,
        internal_format: format,
        width: w,
        height: h,
        depth: 1,
        border: 0,
        format: pf,
        ty,
        data: vec![0x40; bytes].into(),
    })
}

fn textures_scene() -> Vec<Command> {
    let t2 = TextureTarget::Texture2D;
    let t1 = TextureTarget::Texture1D;
    let mut cmds = Vec::new();
    // Names 1..=7 bound in order (one per format), images at levels 0 and 1.
    let formats = [
        TexFormat::Rgba8,
        TexFormat::Rgb8,
        TexFormat::Luminance8,
        TexFormat::Intensity8,
        TexFormat::Alpha8,
        TexFormat::Luminance8Alpha8,
        TexFormat::DepthComponent24,
    ];
    for (i, f) in formats.iter().enumerate() {
        let unit = (i % MAX_TEXTURE_UNITS) as u8;
        cmds.extend([
            Command::ActiveTexture(unit),
            Command::BindTexture {
                target: t2,
                name: i as u32 + 1,
            },
            image(t2, 0, *f, 8, 4),
            image(t2, 1, *f, 4, 2),
        ]);
    }
    cmds.extend([
        Command::ActiveTexture(7),
        Command::BindTexture {
            target: t2,
            name: 8,
        },
        image(t2, 0, TexFormat::DepthComponent16, 4, 4),
        Command::TexParameter {
            target: t2,
            param: TexParam::CompareMode(CompareMode::CompareRToTexture),
        },
        Command::TexParameter {
            target: t2,
            param: TexParam::CompareFunc(CompareFunc::Greater),
        },
        Command::TexParameter {
            target: t2,
            param: TexParam::DepthTextureMode(DepthTextureMode::Alpha),
        },
        Command::ActiveTexture(6),
        Command::BindTexture {
            target: t2,
            name: 9,
        },
        image(t2, 0, TexFormat::DepthComponent32F, 2, 2),
        Command::ActiveTexture(1),
        Command::BindTexture {
            target: t1,
            name: 10,
        },
        image(t1, 0, TexFormat::Rgba8, 16, 1),
        Command::TexParameter {
            target: t1,
            param: TexParam::WrapS(Wrap::Clamp),
        },
        Command::TexParameter {
            target: t1,
            param: TexParam::MinFilter(Filter::LinearMipmapNearest),
        },
        // GL 1.2's level range and LOD clamps, answered as set.
        Command::TexParameter {
            target: t1,
            param: TexParam::BaseLevel(1),
        },
        Command::TexParameter {
            target: t1,
            param: TexParam::MaxLevel(3),
        },
        Command::TexParameter {
            target: t1,
            param: TexParam::MinLod(-2.5),
        },
        Command::TexParameter {
            target: t1,
            param: TexParam::MaxLod(2.6),
        },
        // GL 1.3's cube map on unit 2: six RGBA faces, −Z also at level 1, wrapped and
        // enabled over the unit's 2D texture.
        Command::ActiveTexture(2),
        Command::BindTexture {
            target: TextureTarget::CubeMap,
            name: 11,
        },
    ]);
    for f in CubeFace::ALL {
        cmds.push(image(TextureTarget::CubeFace(f), 0, TexFormat::Rgba8, 4, 4));
    }
    cmds.extend([
        image(
            TextureTarget::CubeFace(CubeFace::NegativeZ),
            1,
            TexFormat::Luminance8,
            2,
            2,
        ),
        Command::TexParameter {
            target: TextureTarget::CubeMap,
            param: TexParam::WrapT(Wrap::ClampToEdge),
        },
        Command::TexParameter {
            target: TextureTarget::CubeMap,
            param: TexParam::MinFilter(Filter::Linear),
        },
        Command::Enable(Capability::TextureCubeMap),
        Command::Enable(Capability::Texture2D),
        Command::ActiveTexture(0),
        Command::TexParameter {
            target: t2,
            param: TexParam::BorderColor(Vec4::new(0.5, 0.25, 1.0, 0.75)),
        },
        Command::TexParameter {
            target: t2,
            param: TexParam::WrapT(Wrap::ClampToBorder),
        },
        Command::TexParameter {
            target: t2,
            param: TexParam::MagFilter(Filter::Nearest),
        },
        Command::TexParameter {
            target: t2,
            param: TexParam::GenerateMipmap(true),
        },
        Command::Enable(Capability::Texture2D),
        Command::ActiveTexture(1),
        Command::Enable(Capability::Texture1D),
    ]);
    cmds
}

#[test]
fn textures_agree() {
    assert_agree("textures", &textures_scene());
}

#[test]
fn pushed_attributes_agree() {
    let mut cmds = lighting_scene();
    cmds.extend([
        Command::PushAttrib(AttribMask::ALL),
        Command::PushAttrib(AttribMask::of(&[
            AttribGroup::Lighting,
            AttribGroup::Current,
        ])),
        Command::Disable(Capability::Lighting),
        Command::Color(Vec4::new(1.0, 0.0, 0.0, 1.0)),
        Command::PushAttrib(AttribMask(0)),
    ]);
    cmds.extend(fragment_scene());
    cmds.extend(texenv_scene());
    cmds.extend(textures_scene());
    assert_agree("pushed", &cmds);
    // Popped back one level at a time, agreeing at each.
    for pops in 1..=3 {
        let mut c = cmds.clone();
        c.extend(std::iter::repeat_n(Command::PopAttrib, pops));
        assert_agree(&format!("{pops} pops"), &c);
    }
}

/// A draw from arrays leaves the current values as they were, in the model and (restored
/// by the native path) in the driver.
#[test]
fn current_values_after_a_draw_agree() {
    let mut g = Geometry::new(
        Primitive::Triangles,
        vec![Vec4::W, Vec4::X + Vec4::W, Vec4::Y + Vec4::W],
    );
    g.colors = Some(vec![Vec4::new(0.125, 0.25, 0.5, 1.0); 3]);
    g.normals = Some(vec![Vec3::new(0.0, 0.6, 0.8); 3]);
    assert_agree("draw", &[Command::Draw(Arc::new(g))]);
}

/// A raw compatibility context and its legacy entry points (no pipeline, no model).
fn raw(backend: Backend) -> (GpuContext, RenderTarget, NativeGl) {
    let ctx = context(backend, Profile::Compatibility);
    let t = target(&ctx, W, H, DepthBits::D24, true);
    let g = NativeGl::load(&ctx).expect("compatibility context");
    (ctx, t, g)
}

fn line_width(g: &gl::Gl) -> f32 {
    let mut w = 0f32;
    // SAFETY: LINE_WIDTH writes one float.
    unsafe { g.GetFloatv(gl::LINE_WIDTH, &mut w) };
    w
}

/// Mesa deviation (22.3): glPopAttrib restores only the groups changed since the push, and a
/// pop resets that record to the one saved at its push, so a change made while an inner
/// entry was on the stack is not undone by the outer pop (GL 1.5 §6.1.14 restores every
/// group of the mask). The native pipeline sends the popped groups again from the model,
/// so it follows the spec.
#[test]
fn mesa_nested_pop_attrib_skips_groups_changed_inside() {
    for backend in HEADLESS {
        let (ctx, _t, native) = raw(backend);
        let g = native.raw();
        // SAFETY: plain GL calls.
        unsafe {
            g.PushAttrib(gl::LINE_BIT);
            g.LineWidth(3.0);
            g.PopAttrib();
        }
        assert_eq!(line_width(g), 1.0, "{backend}: one level restores");
        // SAFETY: plain GL calls.
        unsafe {
            g.PushAttrib(gl::LINE_BIT);
            g.PushAttrib(0);
            g.LineWidth(3.0);
            g.PopAttrib();
            g.PopAttrib();
        }
        assert_eq!(line_width(g), 3.0, "{backend}: the outer pop skips LINE");
        drop(ctx);

        let (ctx, _t, mut pipe) = setup(backend);
        let cmds = [
            Command::PushAttrib(AttribMask::of(&[AttribGroup::Line])),
            Command::PushAttrib(AttribMask(0)),
            Command::LineWidth(3.0),
            Command::PopAttrib,
            Command::PopAttrib,
        ];
        pipe.execute(&ctx, &cmds).unwrap();
        let native = NativeGl::load(&ctx).unwrap();
        assert_eq!(line_width(native.raw()), 1.0, "{backend}: the native path");
        assert_eq!(pipe.state().line_width, 1.0);
    }
}

/// Mesa deviation: GL_TRANSPOSE_TEXTURE_MATRIX is unit 0's texture matrix whatever the
/// active unit, while GL_TEXTURE_MATRIX is the active unit's. The model answers alike.
#[test]
fn mesa_transpose_texture_matrix_is_unit_zero() {
    for backend in HEADLESS {
        let (_ctx, _t, native) = raw(backend);
        let g = native.raw();
        let (mut m, mut t) = ([0f32; 16], [0f32; 16]);
        // SAFETY: plain GL calls; the matrices write 16 floats.
        unsafe {
            g.ActiveTexture(gl::TEXTURE1);
            g.MatrixMode(gl::TEXTURE);
            g.Scalef(0.5, 0.25, 1.0);
            g.GetFloatv(gl::TEXTURE_MATRIX, m.as_mut_ptr());
            g.GetFloatv(gl::TRANSPOSE_TEXTURE_MATRIX, t.as_mut_ptr());
        }
        assert_eq!(m[0], 0.5, "{backend}: TEXTURE_MATRIX is unit 1's");
        assert_eq!(t, Mat4::IDENTITY.to_cols_array(), "{backend}: unit 0's");
        let mut s = FixedState::new();
        for c in [
            Command::ActiveTexture(1),
            Command::MatrixMode(MatrixMode::Texture),
            Command::Scale(Vec3::new(0.5, 0.25, 1.0)),
        ] {
            s.apply(&c).unwrap();
        }
        let model: Vec<f32> = s
            .get(r::TRANSPOSE_TEXTURE_MATRIX)
            .unwrap()
            .iter()
            .map(|v| v.as_float())
            .collect();
        assert_eq!(model, t.to_vec());
    }
}

/// Mesa's initial stencil masks are 0xFF (all ones of an 8-bit stencil buffer), reported
/// as 255; a mask set to all 32 ones reads back as 2³¹ − 1 through glGetIntegerv (Mesa
/// clamps its unsigned values), not −1. The model's defaults and conversion are Mesa's.
#[test]
fn stencil_masks_start_as_eight_ones() {
    for backend in HEADLESS {
        let (_ctx, _t, native) = raw(backend);
        let g = native.raw();
        let (mut v, mut w) = (0i32, 0i32);
        // SAFETY: one integer each.
        unsafe {
            g.GetIntegerv(gl::STENCIL_VALUE_MASK, &mut v);
            g.GetIntegerv(gl::STENCIL_WRITEMASK, &mut w);
        }
        assert_eq!((v, w), (255, 255), "{backend}");
        // SAFETY: plain GL calls.
        unsafe {
            g.StencilMask(u32::MAX);
            g.GetIntegerv(gl::STENCIL_WRITEMASK, &mut w);
        }
        assert_eq!(w, i32::MAX, "{backend}");
        let mut s = FixedState::new();
        s.apply(&Command::StencilMask(u32::MAX)).unwrap();
        assert_eq!(s.get(r::STENCIL_WRITEMASK).unwrap()[0].as_int(), i32::MAX);
        assert_eq!(
            FixedState::new().get(r::STENCIL_VALUE_MASK).unwrap()[0].as_int(),
            255
        );
    }
}

/// Mesa's integer conversions where the spec says otherwise (GL 1.5 §6.1.2), matched by
/// `QueryValue`: glGetLightiv truncates a position (spec: rounds), glGetIntegerv scales a
/// matrix element like a colour (spec: rounds), and −1.0 as a colour is −(2³¹ − 1) (Table
/// 4.5: −2³¹).
#[test]
fn mesa_integer_getters_truncate_and_scale() {
    for backend in HEADLESS {
        let (_ctx, _t, native) = raw(backend);
        let g = native.raw();
        let (mut pos, mut m, mut c) = ([0i32; 4], [0i32; 16], [0i32; 4]);
        // SAFETY: plain GL calls; each buffer holds what its pname writes.
        unsafe {
            g.Lightfv(gl::LIGHT1, gl::POSITION, [1.7f32, -2.7, 3.0, 1.0].as_ptr());
            g.GetLightiv(gl::LIGHT1, gl::POSITION, pos.as_mut_ptr());
            g.Scalef(0.5, 2.0, 1.0);
            g.GetIntegerv(gl::MODELVIEW_MATRIX, m.as_mut_ptr());
            g.Color4f(-1.0, 0.5, 1.0, 0.0);
            g.GetIntegerv(gl::CURRENT_COLOR, c.as_mut_ptr());
        }
        assert_eq!(pos, [1, -2, 3, 1], "{backend}");
        assert_eq!(&m[..2], &[1_073_741_823, 0], "{backend}");
        assert_eq!(
            m[5],
            i32::MIN,
            "{backend}: 2.0 is outside GLint once scaled"
        );
        assert_eq!(
            c,
            [-2_147_483_647, 1_073_741_823, 2_147_483_647, 0],
            "{backend}"
        );

        let mut s = FixedState::new();
        for cmd in [
            Command::Light {
                light: 1,
                param: LightParam::Position(Vec4::new(1.7, -2.7, 3.0, 1.0)),
            },
            Command::Scale(Vec3::new(0.5, 2.0, 1.0)),
            Command::Color(Vec4::new(-1.0, 0.5, 1.0, 0.0)),
        ] {
            s.apply(&cmd).unwrap();
        }
        let ints = |v: Vec<QueryValue>| -> Vec<i32> { v.iter().map(|x| x.as_int()).collect() };
        assert_eq!(ints(s.get_light(r::LIGHT0 + 1, r::POSITION).unwrap()), pos);
        assert_eq!(ints(s.get(r::MODELVIEW_MATRIX).unwrap()), m);
        assert_eq!(ints(s.get(r::CURRENT_COLOR).unwrap()), c);
    }
}

/// The GL error code of a model error.
fn code(e: GlErrorKind) -> u32 {
    e.code()
}

/// Bad arguments raise the same error in the model and in Mesa: FRONT_AND_BACK for a
/// material, a light beyond MAX_LIGHTS, a level outside [0, 14], a pname or target the
/// getter does not take, an unknown glGet pname or capability.
#[test]
fn argument_errors_agree() {
    let s = FixedState::new();
    type Call = Box<dyn Fn(&gl::Gl)>;
    let mut buf = [0f32; 16];
    let p = buf.as_mut_ptr();
    let mut ibuf = [0i32; 16];
    let ip = ibuf.as_mut_ptr();
    // SAFETY (every closure): 16-value buffers that outlive the calls.
    let cases: Vec<(&str, Result<(), GlErrorKind>, Call)> = vec![
        (
            "material FRONT_AND_BACK",
            s.get_material(r::FRONT_AND_BACK, r::AMBIENT).map(drop),
            Box::new(move |g| unsafe { g.GetMaterialfv(gl::FRONT_AND_BACK, gl::AMBIENT, p) }),
        ),
        (
            "material POSITION",
            s.get_material(r::FRONT, r::POSITION).map(drop),
            Box::new(move |g| unsafe { g.GetMaterialfv(gl::FRONT, gl::POSITION, p) }),
        ),
        (
            "LIGHT8",
            s.get_light(r::LIGHT0 + 8, r::AMBIENT).map(drop),
            Box::new(move |g| unsafe { g.GetLightfv(gl::LIGHT0 + 8, gl::AMBIENT, p) }),
        ),
        (
            "light SHININESS",
            s.get_light(r::LIGHT0, r::SHININESS).map(drop),
            Box::new(move |g| unsafe { g.GetLightfv(gl::LIGHT0, gl::SHININESS, p) }),
        ),
        (
            "level -1",
            s.get_tex_level_parameter(r::TEXTURE_2D, -1, r::TEXTURE_WIDTH)
                .map(drop),
            Box::new(move |g| unsafe {
                g.GetTexLevelParameteriv(gl::TEXTURE_2D, -1, gl::TEXTURE_WIDTH, ip)
            }),
        ),
        (
            "level 15",
            s.get_tex_level_parameter(r::TEXTURE_2D, 15, r::TEXTURE_WIDTH)
                .map(drop),
            Box::new(move |g| unsafe {
                g.GetTexLevelParameteriv(gl::TEXTURE_2D, 15, gl::TEXTURE_WIDTH, ip)
            }),
        ),
        (
            "texenv target",
            s.get_tex_env(r::TEXTURE_2D, r::TEXTURE_ENV_MODE).map(drop),
            Box::new(move |g| unsafe { g.GetTexEnviv(gl::TEXTURE_2D, gl::TEXTURE_ENV_MODE, ip) }),
        ),
        (
            "texgen pname",
            s.get_tex_gen(r::S, r::AMBIENT).map(drop),
            Box::new(move |g| unsafe { g.GetTexGeniv(gl::S, gl::AMBIENT, ip) }),
        ),
        (
            "texparameter pname",
            s.get_tex_parameter(r::TEXTURE_2D, r::AMBIENT).map(drop),
            Box::new(move |g| unsafe { g.GetTexParameteriv(gl::TEXTURE_2D, gl::AMBIENT, ip) }),
        ),
        (
            "glGet pname",
            s.get(0xFFFF).map(drop),
            Box::new(move |g| unsafe { g.GetIntegerv(0xFFFF, ip) }),
        ),
        (
            "IsEnabled LIGHT8",
            s.is_enabled(r::LIGHT0 + 8).map(drop),
            Box::new(|g| {
                // SAFETY: plain GL call.
                unsafe { g.IsEnabled(gl::LIGHT0 + 8) };
            }),
        ),
    ];
    for backend in HEADLESS {
        let (_ctx, _t, native) = raw(backend);
        let g = native.raw();
        for (name, model, call) in &cases {
            call(g);
            // SAFETY: plain GL call.
            let driver = unsafe { g.GetError() };
            let want = model.map_or_else(code, |()| gl::NO_ERROR);
            assert_eq!(driver, want, "{backend} {name}: driver 0x{driver:04X}");
        }
    }
}

// The raster position (GL 1.5 §2.13) and the pixel-transfer state, against Mesa's answers
// after the same commands: CURRENT_RASTER_POSITION, _VALID, _COLOR (lit on the CPU by
// `ff::raster_light`), _TEXTURE_COORDS (texgen and texture matrix) and _DISTANCE on every
// unit, within the file's float tolerance.

/// A perspective view with the lighting scene's lights, a point in view lit by them.
fn lit_raster_scene() -> Vec<Command> {
    let mut s = vec![
        Command::MatrixMode(MatrixMode::Projection),
        Command::Frustum(ViewVolume {
            left: -1.0,
            right: 1.0,
            bottom: -1.0,
            top: 1.0,
            near: 1.0,
            far: 20.0,
        }),
    ];
    s.extend(lighting_scene());
    // The scene's two-sided, separate-specular model: the raster colour is the front
    // primary colour (Mesa keeps the secondary apart).
    s.push(Command::RasterPos(Vec4::new(-1.0, 2.5, -4.0, 1.0)));
    s
}

#[test]
fn lit_raster_position_agrees() {
    assert_agree("lit raster position", &lit_raster_scene());
}

#[test]
fn lit_raster_position_single_colour_agrees() {
    let mut s = lit_raster_scene();
    s.pop();
    s.push(Command::LightModel(LightModelParam::ColorControl(
        ColorControl::SingleColor,
    )));
    s.push(Command::LightModel(LightModelParam::LocalViewer(false)));
    s.push(Command::Disable(Capability::ColorMaterial));
    s.push(Command::RasterPos(Vec4::new(0.5, 1.5, -5.0, 1.0)));
    assert_agree("lit raster position, single colour", &s);
}

#[test]
fn raster_texcoords_with_texgen_and_matrices_agree() {
    let mut s = vec![
        Command::MatrixMode(MatrixMode::Projection),
        Command::Ortho(ViewVolume {
            left: -2.0,
            right: 2.0,
            bottom: -2.0,
            top: 2.0,
            near: -3.0,
            far: 3.0,
        }),
        Command::MatrixMode(MatrixMode::Modelview),
        Command::Rotate {
            angle_deg: 20.0,
            axis: Vec3::new(1.0, 1.0, 0.0),
        },
        Command::DepthRange {
            near: 0.25,
            far: 0.75,
        },
        Command::Color(Vec4::new(0.2, 0.4, 0.6, 0.8)),
        Command::Normal(Vec3::new(0.0, 0.6, 0.8)),
        Command::TexCoord {
            unit: 0,
            coord: Vec4::new(0.1, 0.2, 0.3, 0.5),
        },
        Command::TexCoord {
            unit: 2,
            coord: Vec4::new(0.7, 0.6, 0.5, 1.0),
        },
        Command::ActiveTexture(0),
        Command::TexGen {
            coord: TexCoord::S,
            param: TexGenParam::Mode(TexGenMode::ObjectLinear),
        },
        Command::TexGen {
            coord: TexCoord::S,
            param: TexGenParam::ObjectPlane(Vec4::new(1.0, 2.0, 0.0, 0.5)),
        },
        Command::TexGen {
            coord: TexCoord::T,
            param: TexGenParam::EyePlane(Vec4::new(0.0, 1.0, 1.0, 0.0)),
        },
        Command::Enable(Capability::TextureGen(TexCoord::S)),
        Command::Enable(Capability::TextureGen(TexCoord::T)),
        Command::ActiveTexture(2),
        Command::TexGen {
            coord: TexCoord::S,
            param: TexGenParam::Mode(TexGenMode::SphereMap),
        },
        Command::TexGen {
            coord: TexCoord::T,
            param: TexGenParam::Mode(TexGenMode::SphereMap),
        },
        Command::Enable(Capability::TextureGen(TexCoord::S)),
        Command::Enable(Capability::TextureGen(TexCoord::T)),
        Command::MatrixMode(MatrixMode::Texture),
        Command::Translate(Vec3::new(0.5, -0.25, 0.0)),
        Command::Scale(Vec3::new(2.0, 1.0, 1.0)),
        Command::MatrixMode(MatrixMode::Modelview),
        Command::RasterPos(Vec4::new(0.5, -0.75, 0.25, 1.0)),
    ];
    assert_agree("raster texcoords", &s);
    // Moved by a NULL bitmap (the idiom), then invalid: VALID is FALSE and Mesa keeps the
    // other values.
    s.push(Command::Bitmap(fixedfunc::ff::Bitmap {
        width: 0,
        height: 0,
        origin: (0.0, 0.0),
        advance: (3.5, -2.25),
        bits: None,
    }));
    assert_agree("moved by glBitmap", &s);
    s.push(Command::RasterPos(Vec4::new(9.0, 0.0, 0.0, 1.0)));
    assert_agree("invalid raster position", &s);
}

#[test]
fn raster_position_clipping_and_window_pos_agree() {
    let planes = vec![
        Command::ClipPlane {
            plane: 1,
            equation: Vec4::new(1.0, 0.0, 0.0, -0.25),
        },
        Command::Enable(Capability::ClipPlane(1)),
    ];
    let mut clipped = planes.clone();
    clipped.push(Command::RasterPos(Vec4::new(0.0, 0.0, 0.0, 1.0)));
    assert_agree("clipped by a user plane", &clipped);
    let mut kept = planes;
    kept.push(Command::RasterPos(Vec4::new(0.5, 0.5, 0.0, 2.0)));
    assert_agree("kept by a user plane, w = 2", &kept);
    let window = vec![
        Command::DepthRange {
            near: 0.5,
            far: 0.25,
        },
        Command::Color(Vec4::new(1.5, -0.5, 0.25, 1.0)),
        Command::RasterPos(Vec4::new(5.0, 5.0, 0.0, 1.0)),
        Command::WindowPos(Vec3::new(-3.5, 40.25, 0.75)),
    ];
    assert_agree("window position", &window);
}

/// Non-finite and zero-w positions as Mesa takes them: a NaN or an infinity passes the
/// clip test (only a failing comparison rejects) and leaves a valid position whose window
/// coordinates are NaN; w = 0 with x = y = z = 0 lands at the viewport's centre. Both
/// before and after a user clip plane.
#[test]
fn non_finite_raster_positions_agree() {
    for (name, p) in [
        ("NaN x", Vec4::new(f32::NAN, 0.0, 0.0, 1.0)),
        ("NaN w", Vec4::new(0.0, 0.0, 0.0, f32::NAN)),
        ("+inf x", Vec4::new(f32::INFINITY, 0.0, 0.0, 1.0)),
        ("w = 0", Vec4::new(0.0, 0.0, 0.0, 0.0)),
    ] {
        let scene = vec![Command::RasterPos(p)];
        assert_agree(&format!("raster position {name}"), &scene);
        let clipped = vec![
            Command::ClipPlane {
                plane: 0,
                equation: Vec4::new(1.0, 0.0, 0.0, 0.0),
            },
            Command::Enable(Capability::ClipPlane(0)),
            Command::RasterPos(p),
        ];
        assert_agree(&format!("raster position {name}, user plane"), &clipped);
    }
}

#[test]
fn pixel_transfer_zoom_and_their_attribute_groups_agree() {
    use fixedfunc::ff::PixelTransferParam as P;
    let mut s = vec![
        Command::PushAttrib(AttribMask::of(&[
            AttribGroup::PixelMode,
            AttribGroup::Current,
        ])),
        Command::PixelZoom { x: -1.5, y: 2.0 },
        Command::PixelTransfer(P::Scale(1, 0.5)),
        Command::PixelTransfer(P::Bias(3, -0.25)),
        Command::PixelTransfer(P::DepthScale(2.0)),
        Command::PixelTransfer(P::DepthBias(0.125)),
        Command::PixelTransfer(P::IndexShift(-3)),
        Command::PixelTransfer(P::IndexOffset(7)),
        Command::PixelTransfer(P::MapColor(true)),
        Command::RasterPos(Vec4::new(0.25, 0.5, 0.0, 1.0)),
    ];
    assert_agree("pixel transfer", &s);
    s.push(Command::PopAttrib);
    assert_agree("pixel transfer popped", &s);
}

/// The smoothing, COLOR_SUM and MULTISAMPLE enables: Mesa's defaults, and each restored by
/// its own attribute group and by ENABLE_BIT, in the model as in Mesa — except COLOR_SUM,
/// which Mesa 22.3 restores with neither FOG_BIT nor ENABLE_BIT (GL 2.1 Table 6.11 says
/// "fog/enable"): pinned here, followed by the model.
#[test]
fn smoothing_and_sum_enables_follow_their_attribute_groups() {
    let caps = [
        (
            gl::POINT_SMOOTH,
            Capability::PointSmooth,
            AttribGroup::Point,
        ),
        (gl::LINE_SMOOTH, Capability::LineSmooth, AttribGroup::Line),
        (
            gl::POLYGON_SMOOTH,
            Capability::PolygonSmooth,
            AttribGroup::Polygon,
        ),
        (gl::COLOR_SUM, Capability::ColorSum, AttribGroup::Fog),
        (
            gl::MULTISAMPLE,
            Capability::Multisample,
            AttribGroup::Multisample,
        ),
    ];
    for backend in HEADLESS {
        let (_ctx, _t, native) = raw(backend);
        let g = native.raw();
        for (name, cap, group) in caps {
            for mask in [
                AttribMask::of(&[group]),
                AttribMask::of(&[AttribGroup::Enable]),
            ] {
                let mut s = FixedState::new();
                // SAFETY: plain GL calls.
                let mesa = unsafe {
                    let initial = g.IsEnabled(name) != 0;
                    g.PushAttrib(mask.0);
                    if initial {
                        g.Disable(name)
                    } else {
                        g.Enable(name)
                    }
                    let flipped = g.IsEnabled(name) != 0;
                    g.PopAttrib();
                    let after = g.IsEnabled(name) != 0;
                    // Back to the default for the next case, whatever the pop left.
                    if initial {
                        g.Enable(name)
                    } else {
                        g.Disable(name)
                    }
                    (initial, flipped, after, g.GetError())
                };
                let initial = s.is_enabled(name).unwrap();
                let flip = if initial {
                    Command::Disable(cap)
                } else {
                    Command::Enable(cap)
                };
                s.apply(&Command::PushAttrib(mask)).unwrap();
                s.apply(&flip).unwrap();
                let flipped = s.is_enabled(name).unwrap();
                s.apply(&Command::PopAttrib).unwrap();
                let model = (initial, flipped, s.is_enabled(name).unwrap(), 0);
                assert_eq!(model, mesa, "{backend}: {cap:?} under {mask:?}");
                assert_ne!(model.0, model.1, "{backend}: {cap:?} flips");
                let restored = model.2 == model.0;
                let mesa_keeps = cap == Capability::ColorSum;
                assert_eq!(restored, !mesa_keeps, "{backend}: {cap:?} under {mask:?}");
            }
        }
    }
}
