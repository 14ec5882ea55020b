//! The key's claim, case by case: state that does not change the generated code does not
//! change the key, and state that does, does.
//!
//! Each case builds a base state from GL commands (through `FixedState::apply`, so every
//! command is checked for GL errors), takes its key, applies a change, takes the key again,
//! and asserts two things:
//! 1. the key changed exactly when the case says the code should;
//! 2. the generated programs (`shadergen::generate`) are equal exactly when the keys are —
//!    a key that splits identical code (a needless program) or merges different code (a
//!    wrong program) fails here, whatever the case's author believed.
//!
//! Run against the key as it was, eight cases failed. In seven, state the code does not read
//! still split the key: NORMALIZE / RESCALE_NORMAL with no normal in use; COLOR_MATERIAL on
//! the back face without two-sided lighting (with the front face, and alone); an argument
//! the combine function ignores; COMBINE_ALPHA under DOT3_RGBA; the env and the
//! DEPTH_TEXTURE_MODE of a unit under register combiners. In one, SEPARATE_SPECULAR_COLOR,
//! state that changes the picture changed neither the key nor the code: it is generated now,
//! and replayed against Mesa in `tests/scripts/fidelity/separate_specular.c`.
//!
//! Fog: its enable and FOG_MODE shape the code; density, start, end and colour are
//! uniforms, and fog parameters set while fog is off change nothing.

use crate::vocab::Precision;
use std::sync::Arc;

use glam::{Mat4, Vec3, Vec4};

use super::ShaderKey;
use crate::ff::{
    Capability, ClearMask, ColorControl, ColorMask, ColorMaterialMode, CombineArg, CombineFunc,
    CombineOperand, CombineSource, CombinerParam, Command, CompareFunc, CompareMode,
    DepthTextureMode, Face, Filter, FixedState, FrontFace, LightModelParam, LightParam,
    MaterialParam, MatrixMode, PixelFormat, PixelType, PolygonMode, ShadeModel, StencilOp,
    TexCoord, TexData, TexEnvMode, TexEnvParam, TexFormat, TexGenMode, TexGenParam, TexImage,
    TexParam, TexSubImage, TextureTarget, ViewVolume, Viewport, Wrap,
};
use crate::ff::{FogMode, FogParam, HintMode, HintTarget};
use crate::pipeline::emulate::shadergen;

/// What a case's change should do to the code (and so to the key).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Code {
    Same,
    Changes,
}

struct Case {
    name: &'static str,
    base: Vec<Command>,
    change: Vec<Command>,
    code: Code,
}

fn same(name: &'static str, base: Vec<Command>, change: Vec<Command>) -> Case {
    Case {
        name,
        base,
        change,
        code: Code::Same,
    }
}

fn changes(name: &'static str, base: Vec<Command>, change: Vec<Command>) -> Case {
    Case {
        name,
        base,
        change,
        code: Code::Changes,
    }
}

fn state_of(commands: &[Command], name: &str) -> FixedState {
    let mut state = FixedState::new();
    for c in commands {
        state
            .apply(c)
            .unwrap_or_else(|e| panic!("{name}: {c:?} is a GL error: {e:?}"));
    }
    state
}

/// The key in `Precision::Float`.
fn key(state: &FixedState) -> ShaderKey {
    ShaderKey::from_state(state, Precision::Float)
}

// --- Base states -------------------------------------------------------------------------

fn image(target: TextureTarget, format: TexFormat, pixels: PixelFormat, size: i32) -> Command {
    let ty = if pixels == PixelFormat::DepthComponent {
        PixelType::Float
    } else {
        PixelType::UnsignedByte
    };
    Command::TexImage(TexImage {
        requested: None,
        target,
        level: 0,
        internal_format: format,
        width: size,
        height: if target == TextureTarget::Texture1D {
            1
        } else {
            size
        },
        depth: 1,
        border: 0,
        format: pixels,
        ty,
        data: TexData::Null,
    })
}

/// Texture `name` bound to TEXTURE_2D of the active unit with a 2×2 level 0 and MIN_FILTER
/// NEAREST (so it is complete without mipmaps), enabled.
fn texture(name: u32, format: TexFormat, pixels: PixelFormat) -> Vec<Command> {
    vec![
        Command::BindTexture {
            target: TextureTarget::Texture2D,
            name,
        },
        image(TextureTarget::Texture2D, format, pixels, 2),
        tex_param(TexParam::MinFilter(Filter::Nearest)),
        Command::Enable(Capability::Texture2D),
    ]
}

/// Unit 0 textures with an RGB8 image under MODULATE.
fn textured() -> Vec<Command> {
    texture(1, TexFormat::Rgb8, PixelFormat::Rgb)
}

fn texgen(coord: TexCoord, mode: TexGenMode) -> [Command; 2] {
    [
        Command::TexGen {
            coord,
            param: TexGenParam::Mode(mode),
        },
        Command::Enable(Capability::TextureGen(coord)),
    ]
}

/// `textured` with S and T generated EYE_LINEAR (R and Q off).
fn eye_linear() -> Vec<Command> {
    let mut c = textured();
    c.extend(texgen(TexCoord::S, TexGenMode::EyeLinear));
    c.extend(texgen(TexCoord::T, TexGenMode::EyeLinear));
    c
}

/// `textured` with S and T generated SPHERE_MAP.
fn sphere_mapped() -> Vec<Command> {
    let mut c = textured();
    c.extend(texgen(TexCoord::S, TexGenMode::SphereMap));
    c.extend(texgen(TexCoord::T, TexGenMode::SphereMap));
    c
}

fn env(param: TexEnvParam) -> Command {
    Command::TexEnv(param)
}

/// `textured` under COMBINE (GL's default combine: MODULATE(TEXTURE, PREVIOUS)).
fn combine() -> Vec<Command> {
    let mut c = textured();
    c.push(env(TexEnvParam::Mode(TexEnvMode::Combine)));
    c
}

/// `combine` with COMBINE_RGB = `func`.
fn combine_rgb(func: CombineFunc) -> Vec<Command> {
    let mut c = combine();
    c.push(env(TexEnvParam::CombineRgb(func)));
    c
}

/// A DEPTH_COMPONENT24 texture on unit 0, compared (COMPARE_R_TO_TEXTURE) or not.
fn depth_texture(compared: bool) -> Vec<Command> {
    let mut c = texture(1, TexFormat::DepthComponent24, PixelFormat::DepthComponent);
    if compared {
        c.push(tex_param(TexParam::CompareMode(
            CompareMode::CompareRToTexture,
        )));
    }
    c
}

fn tex_param(param: TexParam) -> Command {
    Command::TexParameter {
        target: TextureTarget::Texture2D,
        param,
    }
}

fn with_combiners(mut base: Vec<Command>) -> Vec<Command> {
    base.push(Command::Enable(Capability::RegisterCombiners));
    base
}

/// LIGHTING with LIGHT0 made positional (GL's default LIGHT0 is directional, (0, 0, 1, 0)),
/// no spot.
fn lit() -> Vec<Command> {
    vec![
        Command::Enable(Capability::Lighting),
        Command::Light {
            light: 0,
            param: LightParam::Position(Vec4::new(0.0, 0.0, 5.0, 1.0)),
        },
        Command::Enable(Capability::Light(0)),
    ]
}

fn light(index: u8, param: LightParam) -> Command {
    Command::Light {
        light: index,
        param,
    }
}

/// `lit` with LIGHT0 a spot of cutoff 30°.
fn spot() -> Vec<Command> {
    let mut c = lit();
    c.push(light(0, LightParam::SpotCutoff(30.0)));
    c
}

/// `lit` with COLOR_MATERIAL on `face`, tracking AMBIENT_AND_DIFFUSE.
fn colour_material(face: Face) -> Vec<Command> {
    let mut c = lit();
    c.push(Command::ColorMaterial {
        face,
        mode: ColorMaterialMode::AmbientAndDiffuse,
    });
    c.push(Command::Enable(Capability::ColorMaterial));
    c
}

fn plus(mut base: Vec<Command>, more: impl IntoIterator<Item = Command>) -> Vec<Command> {
    base.extend(more);
    base
}

fn alpha(func: CompareFunc, reference: f32) -> Command {
    Command::AlphaFunc { func, reference }
}

// --- The table ---------------------------------------------------------------------------

/// Values (uniforms), disabled state, and state the code does not read.
fn same_code() -> Vec<Case> {
    let none = Vec::new;
    vec![
        same(
            "TEXTURE_WRAP_R of the enabled volume (a texture parameter)",
            plus(textured(), volume()),
            vec![Command::TexParameter {
                target: TextureTarget::Texture3D,
                param: TexParam::WrapR(Wrap::ClampToEdge),
            }],
        ),
        same(
            "eye plane values",
            eye_linear(),
            vec![Command::TexGen {
                coord: TexCoord::S,
                param: TexGenParam::EyePlane(Vec4::new(0.3, 0.1, 0.0, 2.0)),
            }],
        ),
        same(
            "object plane values",
            eye_linear(),
            vec![Command::TexGen {
                coord: TexCoord::T,
                param: TexGenParam::ObjectPlane(Vec4::new(0.0, 0.0, 1.0, 0.5)),
            }],
        ),
        same(
            "texgen mode of a coordinate that is not generated",
            eye_linear(),
            vec![
                Command::TexGen {
                    coord: TexCoord::R,
                    param: TexGenParam::Mode(TexGenMode::ObjectLinear),
                },
                Command::TexGen {
                    coord: TexCoord::Q,
                    param: TexGenParam::Mode(TexGenMode::ObjectLinear),
                },
            ],
        ),
        same(
            "modelview, projection and texture matrices",
            plus(eye_linear(), lit()),
            vec![
                Command::LoadMatrix(Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0))),
                Command::MatrixMode(MatrixMode::Projection),
                Command::Frustum(ViewVolume {
                    left: -1.0,
                    right: 1.0,
                    bottom: -1.0,
                    top: 1.0,
                    near: 1.0,
                    far: 10.0,
                }),
                Command::MatrixMode(MatrixMode::Modelview),
            ],
        ),
        same(
            "one texture matrix for another, neither the identity",
            plus(
                eye_linear(),
                vec![
                    Command::MatrixMode(MatrixMode::Texture),
                    Command::Scale(Vec3::splat(0.5)),
                ],
            ),
            vec![Command::Translate(Vec3::new(0.25, 0.0, 0.0))],
        ),
        same(
            "a positional light's position, colours and attenuation",
            lit(),
            vec![
                light(0, LightParam::Position(Vec4::new(1.0, 2.0, 3.0, 1.0))),
                light(0, LightParam::Diffuse(Vec4::new(0.5, 0.4, 0.3, 1.0))),
                light(0, LightParam::Specular(Vec4::ONE)),
                light(0, LightParam::Ambient(Vec4::splat(0.1))),
                light(0, LightParam::LinearAttenuation(0.5)),
                light(0, LightParam::QuadraticAttenuation(0.1)),
                light(0, LightParam::SpotDirection(Vec3::X)),
                light(0, LightParam::SpotExponent(10.0)),
            ],
        ),
        same(
            "a directional light's direction",
            plus(
                lit(),
                [light(
                    0,
                    LightParam::Position(Vec4::new(0.0, 1.0, 0.0, 0.0)),
                )],
            ),
            vec![light(
                0,
                LightParam::Position(Vec4::new(1.0, 1.0, 0.0, 0.0)),
            )],
        ),
        same(
            "a spot's cutoff and exponent",
            spot(),
            vec![
                light(0, LightParam::SpotCutoff(45.0)),
                light(0, LightParam::SpotExponent(64.0)),
            ],
        ),
        same(
            "material values and the scene ambient",
            lit(),
            vec![
                Command::Material {
                    face: Face::FrontAndBack,
                    param: MaterialParam::AmbientAndDiffuse(Vec4::new(0.2, 0.6, 0.2, 1.0)),
                },
                Command::Material {
                    face: Face::Front,
                    param: MaterialParam::Shininess(40.0),
                },
                Command::LightModel(LightModelParam::Ambient(Vec4::splat(0.4))),
            ],
        ),
        same(
            "current colour, normal and texture coordinates",
            plus(textured(), lit()),
            vec![
                Command::Color(Vec4::new(1.0, 0.0, 0.0, 1.0)),
                Command::Normal(Vec3::X),
                Command::TexCoord {
                    unit: 0,
                    coord: Vec4::new(0.5, 0.5, 0.0, 1.0),
                },
            ],
        ),
        same(
            "a disabled light's settings",
            lit(),
            vec![
                light(1, LightParam::Position(Vec4::new(0.0, 1.0, 0.0, 0.0))),
                light(1, LightParam::SpotCutoff(20.0)),
            ],
        ),
        same(
            "lights, two-sided lighting and colour material while lighting is off",
            none(),
            vec![
                Command::Enable(Capability::Light(0)),
                Command::Enable(Capability::Light(3)),
                Command::LightModel(LightModelParam::TwoSide(true)),
                Command::LightModel(LightModelParam::LocalViewer(true)),
                Command::Enable(Capability::ColorMaterial),
            ],
        ),
        same(
            "SEPARATE_SPECULAR_COLOR while lighting is off",
            textured(),
            vec![Command::LightModel(LightModelParam::ColorControl(
                ColorControl::SeparateSpecularColor,
            ))],
        ),
        same(
            "NORMALIZE and RESCALE_NORMAL with no lighting and no sphere map",
            eye_linear(),
            vec![
                Command::Enable(Capability::Normalize),
                Command::Enable(Capability::RescaleNormal),
            ],
        ),
        same(
            "RESCALE_NORMAL under NORMALIZE",
            plus(lit(), [Command::Enable(Capability::Normalize)]),
            vec![Command::Enable(Capability::RescaleNormal)],
        ),
        same(
            "back-face COLOR_MATERIAL without two-sided lighting",
            colour_material(Face::Front),
            vec![Command::ColorMaterial {
                face: Face::FrontAndBack,
                mode: ColorMaterialMode::AmbientAndDiffuse,
            }],
        ),
        same(
            "COLOR_MATERIAL on the back face alone without two-sided lighting",
            lit(),
            vec![
                Command::ColorMaterial {
                    face: Face::Back,
                    mode: ColorMaterialMode::Diffuse,
                },
                Command::Enable(Capability::ColorMaterial),
            ],
        ),
        same(
            "alpha reference value",
            vec![
                Command::Enable(Capability::AlphaTest),
                alpha(CompareFunc::Greater, 0.5),
            ],
            vec![alpha(CompareFunc::Greater, 0.25)],
        ),
        same(
            "alpha function while the test is off",
            none(),
            vec![alpha(CompareFunc::Less, 0.5)],
        ),
        same(
            "alpha test on with ALWAYS",
            none(),
            vec![Command::Enable(Capability::AlphaTest)],
        ),
        same(
            "env colour under BLEND",
            plus(textured(), [env(TexEnvParam::Mode(TexEnvMode::Blend))]),
            vec![env(TexEnvParam::Color(Vec4::new(0.2, 0.4, 0.6, 0.8)))],
        ),
        same(
            "combine settings while the mode is not COMBINE",
            textured(),
            vec![
                env(TexEnvParam::CombineRgb(CombineFunc::AddSigned)),
                env(TexEnvParam::SourceRgb(
                    CombineArg::Arg0,
                    CombineSource::PrimaryColor,
                )),
                env(TexEnvParam::RgbScale(4.0)),
            ],
        ),
        same(
            "an argument the combine function does not read",
            combine_rgb(CombineFunc::Replace),
            vec![
                env(TexEnvParam::SourceRgb(
                    CombineArg::Arg1,
                    CombineSource::Constant,
                )),
                env(TexEnvParam::OperandRgb(
                    CombineArg::Arg2,
                    CombineOperand::OneMinusSrcColor,
                )),
            ],
        ),
        same(
            "COMBINE_ALPHA under DOT3_RGBA",
            combine_rgb(CombineFunc::Dot3Rgba),
            vec![
                env(TexEnvParam::CombineAlpha(CombineFunc::AddSigned)),
                env(TexEnvParam::SourceAlpha(
                    CombineArg::Arg0,
                    CombineSource::Constant,
                )),
            ],
        ),
        same(
            "a disabled unit's env, texgen and texture",
            textured(),
            vec![
                Command::ActiveTexture(1),
                env(TexEnvParam::Mode(TexEnvMode::Add)),
                Command::TexGen {
                    coord: TexCoord::S,
                    param: TexGenParam::Mode(TexGenMode::SphereMap),
                },
                Command::Enable(Capability::TextureGen(TexCoord::S)),
                Command::BindTexture {
                    target: TextureTarget::Texture2D,
                    name: 2,
                },
                image(
                    TextureTarget::Texture2D,
                    TexFormat::Rgba8,
                    PixelFormat::Rgba,
                    4,
                ),
                Command::ActiveTexture(0),
            ],
        ),
        same(
            "a unit enabled without an image (incomplete: the unit is off)",
            none(),
            vec![
                Command::ActiveTexture(2),
                Command::Enable(Capability::Texture2D),
            ],
        ),
        same(
            "a unit with level 0 alone under the default mipmap filter (incomplete: off)",
            none(),
            vec![
                Command::ActiveTexture(3),
                Command::BindTexture {
                    target: TextureTarget::Texture2D,
                    name: 9,
                },
                image(
                    TextureTarget::Texture2D,
                    TexFormat::Rgba8,
                    PixelFormat::Rgba,
                    4,
                ),
                Command::Enable(Capability::Texture2D),
            ],
        ),
        same(
            "texture filters, wraps, border and image size",
            textured(),
            vec![
                tex_param(TexParam::MinFilter(Filter::Linear)),
                tex_param(TexParam::MagFilter(Filter::Nearest)),
                tex_param(TexParam::WrapS(Wrap::ClampToEdge)),
                tex_param(TexParam::BorderColor(Vec4::ONE)),
                image(
                    TextureTarget::Texture2D,
                    TexFormat::Rgb8,
                    PixelFormat::Rgb,
                    8,
                ),
                Command::TexSubImage2D(TexSubImage {
                    face: None,
                    level: 0,
                    x: 0,
                    y: 0,
                    z: 0,
                    width: 1,
                    height: 1,
                    depth: 1,
                    format: PixelFormat::Rgb,
                    ty: PixelType::UnsignedByte,
                    data: Some(Arc::from(vec![1u8, 2, 3])),
                }),
            ],
        ),
        same(
            "compare function and fail value of a compared depth texture",
            depth_texture(true),
            vec![
                tex_param(TexParam::CompareFunc(CompareFunc::Gequal)),
                tex_param(TexParam::CompareFailValue(0.5)),
            ],
        ),
        same(
            "compare mode and DEPTH_TEXTURE_MODE of a colour texture",
            textured(),
            vec![
                tex_param(TexParam::CompareMode(CompareMode::CompareRToTexture)),
                tex_param(TexParam::DepthTextureMode(DepthTextureMode::Alpha)),
            ],
        ),
        same(
            "the env of a unit under register combiners",
            with_combiners(textured()),
            vec![
                env(TexEnvParam::Mode(TexEnvMode::Combine)),
                env(TexEnvParam::CombineRgb(CombineFunc::AddSigned)),
            ],
        ),
        same(
            "DEPTH_TEXTURE_MODE under register combiners",
            with_combiners(depth_texture(true)),
            vec![tex_param(TexParam::DepthTextureMode(
                DepthTextureMode::Alpha,
            ))],
        ),
        same(
            "register combiner constant colours",
            with_combiners(textured()),
            vec![
                Command::CombinerParameter(CombinerParam::ConstantColor0(Vec4::splat(0.5))),
                Command::CombinerParameter(CombinerParam::ConstantColor1(Vec4::ONE)),
            ],
        ),
        same(
            "raster and per-fragment state outside the program",
            plus(textured(), lit()),
            vec![
                Command::PolygonOffset {
                    factor: 1.0,
                    units: 4.0,
                },
                Command::Enable(Capability::PolygonOffsetFill),
                Command::Viewport(Viewport {
                    x: 0,
                    y: 0,
                    width: 64,
                    height: 32,
                }),
                Command::DepthRange {
                    near: 0.1,
                    far: 0.9,
                },
                Command::ClearColor(Vec4::new(0.1, 0.2, 0.3, 1.0)),
                Command::ClearDepth(0.5),
                Command::Clear(ClearMask {
                    color: true,
                    depth: true,
                    stencil: false,
                    accum: false,
                }),
                Command::Enable(Capability::DepthTest),
                Command::DepthFunc(CompareFunc::Equal),
                Command::DepthMask(false),
                Command::Enable(Capability::StencilTest),
                Command::StencilFunc {
                    func: CompareFunc::Equal,
                    reference: 1,
                    mask: 0xff,
                },
                Command::StencilOp {
                    fail: StencilOp::Keep,
                    depth_fail: StencilOp::Keep,
                    depth_pass: StencilOp::Incr,
                },
                Command::Enable(Capability::Blend),
                Command::ColorMask(ColorMask {
                    r: true,
                    g: false,
                    b: true,
                    a: false,
                }),
                Command::Enable(Capability::CullFace),
                Command::CullFace(Face::Front),
                Command::FrontFace(FrontFace::Cw),
                Command::PolygonMode {
                    face: Face::FrontAndBack,
                    mode: PolygonMode::Line,
                },
                Command::LineWidth(3.0),
                Command::PointSize(4.0),
            ],
        ),
        same(
            "fog values are uniforms",
            vec![Command::Enable(Capability::Fog)],
            vec![
                Command::Fog(FogParam::Density(0.3)),
                Command::Fog(FogParam::Start(2.0)),
                Command::Fog(FogParam::End(9.0)),
                Command::Fog(FogParam::Color(Vec4::ONE)),
                Command::Fog(FogParam::Index(1.0)),
            ],
        ),
        same(
            "a clip plane's equation is a uniform",
            vec![Command::Enable(Capability::ClipPlane(2))],
            vec![Command::ClipPlane {
                plane: 2,
                equation: Vec4::new(1.0, 2.0, 3.0, 4.0),
            }],
        ),
        same(
            "DITHER and the hints are state only",
            vec![Command::Enable(Capability::Fog)],
            vec![
                Command::Disable(Capability::Dither),
                Command::Hint {
                    target: HintTarget::Fog,
                    mode: HintMode::Nicest,
                },
                Command::Hint {
                    target: HintTarget::PerspectiveCorrection,
                    mode: HintMode::Fastest,
                },
            ],
        ),
        same(
            "the fog mode while fog is off",
            textured(),
            vec![Command::Fog(FogParam::Mode(FogMode::Linear))],
        ),
    ]
}

/// Predicates: what the code is made of.
/// Unit 0's 2D texture and, enabled over it, a 2×2×1 RGB8 volume with MIN_FILTER NEAREST.
fn volume() -> Vec<Command> {
    vec![
        Command::BindTexture {
            target: TextureTarget::Texture3D,
            name: 3,
        },
        image(
            TextureTarget::Texture3D,
            TexFormat::Rgb8,
            PixelFormat::Rgb,
            2,
        ),
        Command::TexParameter {
            target: TextureTarget::Texture3D,
            param: TexParam::MinFilter(Filter::Nearest),
        },
        Command::Enable(Capability::Texture3D),
    ]
}

fn changed_code() -> Vec<Case> {
    let none = Vec::new;
    vec![
        changes("enabling a unit with an image", none(), textured()),
        changes(
            "a texture matrix other than the identity (the identity is left out)",
            textured(),
            vec![
                Command::MatrixMode(MatrixMode::Texture),
                Command::Scale(Vec3::splat(0.5)),
            ],
        ),
        changes(
            "ALPHA_SCALE under DOT3_RGBA (it scales the dot product in alpha)",
            combine_rgb(CombineFunc::Dot3Rgba),
            vec![env(TexEnvParam::AlphaScale(2.0))],
        ),
        changes(
            "a 1D texture instead of the 2D one",
            textured(),
            vec![
                Command::Disable(Capability::Texture2D),
                Command::BindTexture {
                    target: TextureTarget::Texture1D,
                    name: 2,
                },
                image(
                    TextureTarget::Texture1D,
                    TexFormat::Rgb8,
                    PixelFormat::Rgb,
                    2,
                ),
                Command::TexParameter {
                    target: TextureTarget::Texture1D,
                    param: TexParam::MinFilter(Filter::Nearest),
                },
                Command::Enable(Capability::Texture1D),
            ],
        ),
        changes(
            "a 3D texture enabled over the 2D one (sampler3D at (s, t, r)/q)",
            textured(),
            volume(),
        ),
        changes(
            "the base format of the unit's image",
            textured(),
            vec![image(
                TextureTarget::Texture2D,
                TexFormat::Luminance8,
                PixelFormat::Luminance,
                2,
            )],
        ),
        changes(
            "enabling texgen on a coordinate",
            textured(),
            texgen(TexCoord::S, TexGenMode::ObjectLinear).to_vec(),
        ),
        changes(
            "the texgen mode of a generated coordinate",
            eye_linear(),
            vec![Command::TexGen {
                coord: TexCoord::S,
                param: TexGenParam::Mode(TexGenMode::ObjectLinear),
            }],
        ),
        changes(
            "SPHERE_MAP on a generated coordinate",
            eye_linear(),
            vec![Command::TexGen {
                coord: TexCoord::T,
                param: TexGenParam::Mode(TexGenMode::SphereMap),
            }],
        ),
        changes(
            "the env mode",
            textured(),
            vec![env(TexEnvParam::Mode(TexEnvMode::Replace))],
        ),
        changes(
            "the combine function",
            combine(),
            vec![env(TexEnvParam::CombineRgb(CombineFunc::AddSigned))],
        ),
        changes(
            "a combine source the function reads",
            combine(),
            vec![env(TexEnvParam::SourceRgb(
                CombineArg::Arg1,
                CombineSource::PrimaryColor,
            ))],
        ),
        changes(
            "a combine operand the function reads",
            combine(),
            vec![env(TexEnvParam::OperandAlpha(
                CombineArg::Arg0,
                CombineOperand::OneMinusSrcAlpha,
            ))],
        ),
        changes(
            "the combine scale",
            combine(),
            vec![env(TexEnvParam::RgbScale(2.0))],
        ),
        changes(
            "the third argument of INTERPOLATE",
            combine_rgb(CombineFunc::Interpolate),
            vec![env(TexEnvParam::SourceRgb(
                CombineArg::Arg2,
                CombineSource::PrimaryColor,
            ))],
        ),
        changes(
            "the alpha function",
            vec![
                Command::Enable(Capability::AlphaTest),
                alpha(CompareFunc::Greater, 0.5),
            ],
            vec![alpha(CompareFunc::Less, 0.5)],
        ),
        changes(
            "enabling the alpha test",
            vec![alpha(CompareFunc::Greater, 0.5)],
            vec![Command::Enable(Capability::AlphaTest)],
        ),
        changes(
            "enabling lighting",
            none(),
            vec![Command::Enable(Capability::Lighting)],
        ),
        changes(
            "enabling a light",
            lit(),
            vec![Command::Enable(Capability::Light(1))],
        ),
        changes(
            "a positional light becoming directional",
            lit(),
            vec![light(
                0,
                LightParam::Position(Vec4::new(0.0, 1.0, 0.0, 0.0)),
            )],
        ),
        changes(
            "a light becoming a spot",
            lit(),
            vec![light(0, LightParam::SpotCutoff(45.0))],
        ),
        changes(
            "two-sided lighting",
            lit(),
            vec![Command::LightModel(LightModelParam::TwoSide(true))],
        ),
        changes(
            "a local viewer",
            lit(),
            vec![Command::LightModel(LightModelParam::LocalViewer(true))],
        ),
        changes(
            "enabling COLOR_MATERIAL",
            lit(),
            vec![Command::Enable(Capability::ColorMaterial)],
        ),
        changes(
            "the COLOR_MATERIAL mode",
            colour_material(Face::Front),
            vec![Command::ColorMaterial {
                face: Face::Front,
                mode: ColorMaterialMode::Specular,
            }],
        ),
        changes(
            "back-face COLOR_MATERIAL with two-sided lighting",
            plus(
                colour_material(Face::Front),
                [Command::LightModel(LightModelParam::TwoSide(true))],
            ),
            vec![Command::ColorMaterial {
                face: Face::FrontAndBack,
                mode: ColorMaterialMode::AmbientAndDiffuse,
            }],
        ),
        changes(
            "NORMALIZE with lighting",
            lit(),
            vec![Command::Enable(Capability::Normalize)],
        ),
        changes(
            "RESCALE_NORMAL with lighting",
            lit(),
            vec![Command::Enable(Capability::RescaleNormal)],
        ),
        changes(
            "NORMALIZE with SPHERE_MAP",
            sphere_mapped(),
            vec![Command::Enable(Capability::Normalize)],
        ),
        changes(
            "SEPARATE_SPECULAR_COLOR",
            plus(textured(), lit()),
            vec![Command::LightModel(LightModelParam::ColorControl(
                ColorControl::SeparateSpecularColor,
            ))],
        ),
        changes(
            "SEPARATE_SPECULAR_COLOR under register combiners (their SECONDARY_COLOR)",
            with_combiners(plus(textured(), lit())),
            vec![Command::LightModel(LightModelParam::ColorControl(
                ColorControl::SeparateSpecularColor,
            ))],
        ),
        changes(
            "flat shading",
            none(),
            vec![Command::ShadeModel(ShadeModel::Flat)],
        ),
        changes(
            "compare mode on a depth texture",
            depth_texture(false),
            vec![tex_param(TexParam::CompareMode(
                CompareMode::CompareRToTexture,
            ))],
        ),
        changes(
            "DEPTH_TEXTURE_MODE of a depth texture",
            depth_texture(true),
            vec![tex_param(TexParam::DepthTextureMode(
                DepthTextureMode::Alpha,
            ))],
        ),
        changes(
            "enabling register combiners",
            textured(),
            vec![Command::Enable(Capability::RegisterCombiners)],
        ),
        changes(
            "enabling a clip plane",
            textured(),
            vec![Command::Enable(Capability::ClipPlane(5))],
        ),
        changes(
            "another clip plane",
            vec![Command::Enable(Capability::ClipPlane(0))],
            vec![
                Command::Disable(Capability::ClipPlane(0)),
                Command::Enable(Capability::ClipPlane(1)),
            ],
        ),
        changes(
            "enabling fog",
            textured(),
            vec![Command::Enable(Capability::Fog)],
        ),
        changes(
            "the fog mode",
            vec![Command::Enable(Capability::Fog)],
            vec![Command::Fog(FogParam::Mode(FogMode::Exp2))],
        ),
        changes(
            "fog under register combiners fills their FOG register",
            with_combiners(textured()),
            vec![Command::Enable(Capability::Fog)],
        ),
        changes(
            "the number of general combiners",
            with_combiners(textured()),
            vec![Command::CombinerParameter(
                CombinerParam::NumGeneralCombiners(2),
            )],
        ),
    ]
}

/// Runs one case in one precision; returns a line describing a failure.
fn check(case: &Case, precision: Precision) -> Option<String> {
    let before = state_of(&case.base, case.name);
    let mut after = before.clone();
    for c in &case.change {
        after
            .apply(c)
            .unwrap_or_else(|e| panic!("{}: {c:?} is a GL error: {e:?}", case.name));
    }
    let (k0, k1) = (
        ShaderKey::from_state(&before, precision),
        ShaderKey::from_state(&after, precision),
    );
    let key_changed = k0 != k1;
    let code_changed = shadergen::generate(&k0) != shadergen::generate(&k1);
    let expected = case.code == Code::Changes;
    let name = format!("{} ({precision:?})", case.name);
    if key_changed != expected {
        return Some(format!(
            "{name}: the key {} but should {}\n  before {k0:?}\n  after  {k1:?}",
            if key_changed { "changed" } else { "stayed" },
            if expected { "change" } else { "stay" },
        ));
    }
    if key_changed != code_changed {
        return Some(format!(
            "{name}: the key {} but the code {}",
            if key_changed { "changed" } else { "stayed" },
            if code_changed { "changed" } else { "stayed" },
        ));
    }
    None
}

#[test]
fn equal_code_has_an_equal_key_and_different_code_a_different_key() {
    let cases: Vec<Case> = same_code().into_iter().chain(changed_code()).collect();
    // Both precisions: Fixed8 generates other code for the same key shape.
    let failures: Vec<String> = [Precision::Float, Precision::Fixed8]
        .into_iter()
        .flat_map(|p| cases.iter().filter_map(move |c| check(c, p)))
        .collect();
    assert!(
        failures.is_empty(),
        "{} of {} cases fail:\n{}",
        failures.len(),
        2 * cases.len(),
        failures.join("\n")
    );
}

#[test]
fn the_precision_mode_is_in_the_key() {
    let state = state_of(&textured(), "textured");
    let (float, fixed) = (
        ShaderKey::from_state(&state, Precision::Float),
        ShaderKey::from_state(&state, Precision::Fixed8),
    );
    assert_ne!(float, fixed);
    assert_ne!(shadergen::generate(&float), shadergen::generate(&fixed));
}

#[test]
fn undoing_a_change_gives_back_the_first_key() {
    // Disabled state leaves no trace: enable, set up and disable again, and the key is the
    // one before (the parameters stay in the state, GL keeps them).
    let base = textured();
    let mut commands = base.clone();
    commands.extend(lit());
    commands.extend(texgen(TexCoord::S, TexGenMode::SphereMap));
    commands.extend([
        Command::Enable(Capability::AlphaTest),
        alpha(CompareFunc::Greater, 0.5),
        Command::Enable(Capability::RegisterCombiners),
        Command::Disable(Capability::RegisterCombiners),
        Command::Disable(Capability::AlphaTest),
        Command::Disable(Capability::TextureGen(TexCoord::S)),
        Command::Disable(Capability::Lighting),
    ]);
    let first = key(&state_of(&base, "base"));
    let again = key(&state_of(&commands, "undone"));
    assert_eq!(first, again);
}
