//! Script tables: parse errors with lines and alternatives, immediate-mode folding, round
//! trips (hand-picked and property-based), and C validity of printed scripts.

use std::sync::Arc;

use glam::{Mat4, Vec3, Vec4};
use proptest::prelude::*;

use super::names::GlEnum;
use super::*;
use crate::ff::*;
use crate::vocab::DepthRule;

fn err(src: &str) -> ScriptError {
    parse(src).unwrap_err()
}

/// A vertex outside glBegin/glEnd is no error, on Mesa as here (GL leaves its effect
/// undefined; Mesa ignores it): the script parses, and the vertex draws nothing.
#[test]
fn a_vertex_outside_a_pair_is_ignored() {
    assert_eq!(parse("glVertex3f(0, 0, 0);").unwrap(), vec![]);
    let cmds =
        parse("glVertex2f(1, 1);\nglBegin(GL_POINTS);\nglVertex2f(0, 0);\nglEnd();").unwrap();
    let draws: Vec<_> = cmds
        .iter()
        .filter(|c| matches!(c, Command::Draw(_)))
        .collect();
    assert_eq!(draws.len(), 1);
    let Command::Draw(g) = draws[0] else {
        unreachable!()
    };
    assert_eq!(g.positions, vec![Vec4::new(0.0, 0.0, 0.0, 1.0)]);
}

#[test]
fn parses_a_texgen_script() {
    let src = "// piglit general/texgen, quad 2\n\
               glMatrixMode(GL_MODELVIEW);\n\
               glTexGenfv(GL_S, GL_EYE_PLANE, (GLfloat[]){1, 0, 0, -0.25f});\n\
               /* then move */ glTranslatef(0.5, -0.5, 0);\n\
               glEnable(GL_TEXTURE_GEN_S);\n";
    let cmds = parse(src).unwrap();
    assert_eq!(
        cmds,
        vec![
            Command::MatrixMode(MatrixMode::Modelview),
            Command::TexGen {
                coord: TexCoord::S,
                param: TexGenParam::EyePlane(Vec4::new(1.0, 0.0, 0.0, -0.25)),
            },
            Command::Translate(Vec3::new(0.5, -0.5, 0.0)),
            Command::Enable(Capability::TextureGen(TexCoord::S)),
        ]
    );
}

#[test]
fn error_table() {
    // Unknown call: line 2, closest first.
    match err("glLoadIdentity();\nglTexEnvv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);") {
        ScriptError::UnknownCall {
            line,
            name,
            expected,
        } => {
            assert_eq!((line, name.as_str()), (2, "glTexEnvv"));
            assert!(expected[..3].contains(&"glTexEnvi"), "{expected:?}");
        }
        e => panic!("{e}"),
    }
    // An enum valid in GL but not for this argument: the six texenv modes are listed.
    match err("\n\nglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DOT3_RGB);") {
        ScriptError::UnknownEnum {
            line,
            call,
            arg,
            name,
            expected,
        } => {
            assert_eq!(
                (line, call, arg, name.as_str()),
                (3, "glTexEnvi", 3, "GL_DOT3_RGB")
            );
            let mut want = TexEnvMode::names();
            want.sort();
            let mut got = expected.clone();
            got.sort();
            assert_eq!(got, want);
        }
        e => panic!("{e}"),
    }
    let table: Vec<(&str, usize, &str)> = vec![
        ("glEnable(GL_FOO);", 1, "UnknownEnum"),
        ("glEnable(GL_LIGHT9);", 1, "UnknownEnum"),
        ("glDepthFunc(GL_LESS)", 1, "Syntax"),
        ("glRotatef(1, 2, 3);", 1, "ArgCount"),
        ("glAlphaFunc(GL_GREATER, GL_ONE);", 1, "BadArgument"),
        ("\nglTexGenfv(GL_S, GL_EYE_PLANE, (GLfloat[]){1, 0, 0});", 2, "ArrayLength"),
        ("glBegin(GL_QUADS);\nglEnable(GL_BLEND);", 2, "Immediate"),
        ("glEnd();", 1, "Immediate"),
        ("glBegin(GL_TRIANGLES);\nglVertex3f(0,0,0);", 1, "Immediate"),
        ("glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, buffer);", 1, "BadArgument"),
        ("glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){256, 0, 0, 0});", 1, "BadArgument"),
        ("glClear(GL_COLOR_BUFFER_BIT | GL_POINT_BIT);", 1, "UnknownEnum"),
        ("\n\n\n  @", 4, "UnexpectedChar"),
        ("/* a\n b", 1, "UnterminatedComment"),
        ("glClear(0);\nglRenderMode(GL_SELECT);", 2, "NotImplemented"),
    ];
    for (src, want_line, want_kind) in table {
        let e = err(src);
        let (line, kind) = match &e {
            ScriptError::UnexpectedChar { line, .. } => (*line, "UnexpectedChar"),
            ScriptError::UnterminatedComment { line } => (*line, "UnterminatedComment"),
            ScriptError::Preprocessor { line, .. } => (*line, "Preprocessor"),
            ScriptError::Syntax { line, .. } => (*line, "Syntax"),
            ScriptError::UnknownCall { line, .. } => (*line, "UnknownCall"),
            ScriptError::UnknownEnum { line, .. } => (*line, "UnknownEnum"),
            ScriptError::ArgCount { line, .. } => (*line, "ArgCount"),
            ScriptError::BadArgument { line, .. } => (*line, "BadArgument"),
            ScriptError::ArrayLength { line, .. } => (*line, "ArrayLength"),
            ScriptError::Immediate { line, .. } => (*line, "Immediate"),
            ScriptError::NotImplemented { line, .. } => (*line, "NotImplemented"),
        };
        assert_eq!((line, kind), (want_line, want_kind), "{src:?}: {e}");
        assert!(
            e.to_string().starts_with(&format!("line {want_line}:")),
            "{e}"
        );
    }
}

#[test]
fn immediate_mode_folds_into_one_draw() {
    let src = "glColor4f(1, 0, 0, 1);\n\
               glBegin(GL_QUADS);\n\
               glVertex3f(0, 0, 0);\n\
               glColor3f(0, 1, 0);\n\
               glMultiTexCoord2f(GL_TEXTURE1, 0.5, 1);\n\
               glVertex2f(1, 0);\n\
               glVertex4f(1, 1, 0, 2);\n\
               glNormal3f(0, 1, 0);\n\
               glEnd();\n";
    let cmds = parse(src).unwrap();
    // The colour before, the draw, then what the pair left current (a draw changes none).
    assert_eq!(cmds.len(), 5, "{cmds:?}");
    let Command::Draw(g) = &cmds[1] else {
        panic!("{cmds:?}")
    };
    assert_eq!(g.primitive, Primitive::Quads);
    assert_eq!(g.positions[2], Vec4::new(1.0, 1.0, 0.0, 2.0));
    let red = Vec4::new(1.0, 0.0, 0.0, 1.0);
    let green = Vec4::new(0.0, 1.0, 0.0, 1.0);
    assert_eq!(g.colors.as_deref(), Some(&[red, green, green][..]));
    assert_eq!(g.texcoords[1].as_deref().map(|t| t[0]), Some(Vec4::W));
    assert_eq!(
        g.texcoords[1].as_deref().map(|t| t[1]),
        Some(Vec4::new(0.5, 1.0, 0.0, 1.0))
    );
    assert!(g.normals.is_none(), "the normal came after the last vertex");
    // ... so it is kept as the current normal after the draw.
    assert_eq!(cmds[2], Command::Color(green));
    assert_eq!(cmds[3], Command::Normal(Vec3::Y));
}

#[test]
fn client_arrays_draw_from_compound_literals() {
    let src = "glVertexPointer(2, GL_SHORT, 0, (GLshort[]){0, 0, 4, 0, 4, 4, 0, 4});\n\
               glColorPointer(4, GL_UNSIGNED_BYTE, 0, (GLubyte[]){255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255});\n\
               glEnableClientState(GL_VERTEX_ARRAY);\n\
               glEnableClientState(GL_COLOR_ARRAY);\n\
               glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, (GLubyte[]){0, 1, 2, 0, 2, 3});\n\
               glDisableClientState(GL_COLOR_ARRAY);\n\
               glDrawArrays(GL_LINE_LOOP, 1, 3);\n\
               glDisableClientState(GL_VERTEX_ARRAY);\n\
               glDrawArrays(GL_POINTS, 0, 4);\n";
    let cmds = parse(src).unwrap();
    assert_eq!(
        cmds.len(),
        2,
        "a draw without the vertex array draws nothing: {cmds:?}"
    );
    let Command::Draw(g) = &cmds[0] else {
        panic!("{cmds:?}")
    };
    assert_eq!(g.positions[2], Vec4::new(4.0, 4.0, 0.0, 1.0));
    assert_eq!(g.indices.as_deref(), Some(&[0, 1, 2, 0, 2, 3][..]));
    assert_eq!(
        g.colors.as_ref().map(|c| c[1]),
        Some(Vec4::new(0.0, 1.0, 0.0, 1.0))
    );
    let Command::Draw(g) = &cmds[1] else {
        panic!("{cmds:?}")
    };
    assert_eq!((g.primitive, g.positions.len()), (Primitive::LineLoop, 3));
    assert_eq!(g.positions[0], Vec4::new(4.0, 0.0, 0.0, 1.0));
    assert!(g.colors.is_none());
    // Bad sizes, types and counts are the errors GL gives, with the line.
    let err = parse("glVertexPointer(5, GL_FLOAT, 0, NULL);").unwrap_err();
    assert!(
        matches!(err, ScriptError::BadArgument { line: 1, .. }),
        "{err}"
    );
    let err = parse("glVertexPointer(3, GL_UNSIGNED_BYTE, 0, NULL);").unwrap_err();
    assert!(matches!(err, ScriptError::UnknownEnum { .. }), "{err}");
}

#[test]
fn display_lists_expand_where_they_are_called() {
    let src = "glGenLists(3);\n\
               glNewList(1, GL_COMPILE);\n\
               glColor3f(1, 0, 0);\n\
               glBegin(GL_POINTS); glVertex2f(0, 0); glEnd();\n\
               glEndList();\n\
               glNewList(2, GL_COMPILE_AND_EXECUTE);\n\
               glTranslatef(1, 0, 0); glCallList(1);\n\
               glEndList();\n\
               glListBase(1);\n\
               glCallLists(2, GL_UNSIGNED_BYTE, (GLubyte[]){0, 1});\n";
    let cmds = parse(src).unwrap();
    let draws = cmds
        .iter()
        .filter(|c| matches!(c, Command::Draw(_)))
        .count();
    let moves = cmds
        .iter()
        .filter(|c| matches!(c, Command::Translate(_)))
        .count();
    // List 2 ran once as it was compiled, then lists 1 and 2 through the base.
    assert_eq!((draws, moves), (3, 2), "{cmds:?}");
    let err = parse("glNewList(0, GL_COMPILE);").unwrap_err();
    assert!(
        matches!(err, ScriptError::BadArgument { line: 1, .. }),
        "{err}"
    );
    let err = parse("glEndList();").unwrap_err();
    assert!(
        matches!(err, ScriptError::Immediate { line: 1, .. }),
        "{err}"
    );
}

fn sample_commands() -> Vec<Command> {
    let mut g = Geometry::new(
        Primitive::TriangleFan,
        vec![
            Vec4::new(0.0, 0.0, 0.0, 1.0),
            Vec4::new(1.0, 0.0, -0.5, 1.0),
            Vec4::new(1.0, 1.0, 0.0, 0.5),
        ],
    );
    g.colors = Some(vec![
        Vec4::ONE,
        Vec4::X + Vec4::W,
        Vec4::new(0.1, 0.2, 0.3, 0.4),
    ]);
    g.normals = Some(vec![Vec3::Z; 3]);
    g.texcoords[0] = Some(vec![Vec4::W, Vec4::X, Vec4::Y]);
    g.texcoords[3] = Some(vec![Vec4::ZERO; 3]);
    g.secondary_colors = Some(vec![Vec4::W, Vec4::new(0.5, 0.25, 0.0, 0.5), Vec4::ONE]);
    g.fog_coords = Some(vec![0.0, -2.5, 1e3]);
    let input = CombinerInput {
        register: Register::Texture(1),
        mapping: Mapping::ExpandNormal,
        usage: ComponentUsage::Rgb,
    };
    vec![
        Command::MatrixMode(MatrixMode::Texture),
        Command::LoadMatrix(Mat4::from_cols_array(&std::array::from_fn(|i| {
            i as f32 * 0.1
        }))),
        Command::MultMatrix(Mat4::IDENTITY),
        Command::PushMatrix,
        Command::PopMatrix,
        Command::LoadIdentity,
        Command::Rotate {
            angle_deg: 30.0,
            axis: Vec3::new(1.0, 1.0, 0.0),
        },
        Command::Scale(Vec3::new(-1.0, 1e-7, 3e20)),
        Command::Frustum(ViewVolume {
            left: -1.0,
            right: 1.0,
            bottom: -0.75,
            top: 0.75,
            near: 4.0,
            far: 24.0,
        }),
        Command::Ortho(ViewVolume {
            left: 0.0,
            right: 1.0,
            bottom: 0.0,
            top: 1.0,
            near: -1.0,
            far: f32::INFINITY,
        }),
        Command::Viewport(Viewport {
            x: 0,
            y: 0,
            width: 256,
            height: 256,
        }),
        Command::DepthRange {
            near: 0.0,
            far: 1.0,
        },
        Command::Enable(Capability::Light(3)),
        Command::Disable(Capability::Light(12)),
        Command::Enable(Capability::RegisterCombiners),
        Command::Color(Vec4::new(0.0, 0.25, 0.5, 0.75)),
        Command::Normal(Vec3::NEG_Z),
        Command::SecondaryColor(Vec4::new(0.5, -1.0, 2.0, 1.0)),
        Command::FogCoord(-3.25),
        Command::Fog(FogParam::CoordSource(FogCoordSource::FogCoord)),
        Command::Index(-2.5),
        Command::ClearIndex(7.0),
        Command::IndexMask(0xF0F0_F0F0),
        Command::SampleCoverage {
            value: 0.25,
            invert: true,
        },
        Command::Enable(Capability::SampleAlphaToCoverage),
        Command::TexCoord {
            unit: 2,
            coord: Vec4::new(0.5, 0.5, 0.0, 1.0),
        },
        Command::Light {
            light: 0,
            param: LightParam::Position(Vec4::new(1.0, 2.0, 3.0, 0.0)),
        },
        Command::Light {
            light: 1,
            param: LightParam::SpotDirection(Vec3::NEG_Y),
        },
        Command::Light {
            light: 7,
            param: LightParam::SpotCutoff(40.0),
        },
        Command::Light {
            light: 2,
            param: LightParam::QuadraticAttenuation(0.01),
        },
        Command::LightModel(LightModelParam::Ambient(Vec4::splat(0.1))),
        Command::LightModel(LightModelParam::TwoSide(true)),
        Command::LightModel(LightModelParam::ColorControl(
            ColorControl::SeparateSpecularColor,
        )),
        Command::Material {
            face: Face::FrontAndBack,
            param: MaterialParam::AmbientAndDiffuse(Vec4::ONE),
        },
        Command::Material {
            face: Face::Front,
            param: MaterialParam::Shininess(64.0),
        },
        Command::ColorMaterial {
            face: Face::Back,
            mode: ColorMaterialMode::Emission,
        },
        Command::ShadeModel(ShadeModel::Flat),
        Command::ActiveTexture(1),
        Command::BindTexture {
            target: TextureTarget::Texture1D,
            name: 42,
        },
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture1D,
            level: 0,
            internal_format: TexFormat::Intensity8,
            width: 4,
            height: 1,
            depth: 1,
            border: 0,
            format: PixelFormat::Luminance,
            ty: PixelType::UnsignedByte,
            data: TexData::Bytes(Arc::from(vec![0u8, 85, 170, 255])),
        }),
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::DepthComponent24,
            width: 2,
            height: 1,
            depth: 1,
            border: 0,
            format: PixelFormat::DepthComponent,
            ty: PixelType::Float,
            data: TexData::Bytes(Arc::from(
                [0.25f32.to_le_bytes(), 1.0f32.to_le_bytes()].concat(),
            )),
        }),
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture2D,
            level: 1,
            internal_format: TexFormat::Luminance8Alpha8,
            width: 256,
            height: 256,
            depth: 1,
            border: 0,
            format: PixelFormat::LuminanceAlpha,
            ty: PixelType::UnsignedByte,
            data: TexData::Null,
        }),
        Command::TexSubImage2D(TexSubImage {
            face: None,
            level: 0,
            x: 1,
            y: 0,
            z: 0,
            width: 1,
            height: 1,
            depth: 1,
            format: PixelFormat::DepthComponent,
            ty: PixelType::UnsignedShort,
            data: Some(Arc::from(65535u16.to_le_bytes().to_vec())),
        }),
        // GL 1.2's 3D textures: rows of 9 bytes padded to 4 across two images.
        Command::BindTexture {
            target: TextureTarget::Texture3D,
            name: 9,
        },
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture3D,
            level: 0,
            internal_format: TexFormat::Rgb8,
            width: 3,
            height: 2,
            depth: 2,
            border: 0,
            format: PixelFormat::Rgb,
            ty: PixelType::UnsignedByte,
            data: TexData::Bytes((0u8..36).collect::<Vec<_>>().into()),
        }),
        Command::ProxyTexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture3D,
            level: 2,
            internal_format: TexFormat::Alpha8,
            width: 4096,
            height: 1,
            depth: 1,
            border: 0,
            format: PixelFormat::Alpha,
            ty: PixelType::UnsignedByte,
            data: TexData::Null,
        }),
        Command::TexSubImage3D(TexSubImage {
            face: None,
            level: 0,
            x: 1,
            y: 0,
            z: 1,
            width: 2,
            height: 1,
            depth: 1,
            format: PixelFormat::Rgb,
            ty: PixelType::UnsignedByte,
            data: Some(Arc::from(vec![7u8; 6])),
        }),
        Command::CopyTexSubImage(crate::ff::texture_calls::CopyTexSubImage {
            target: TextureTarget::Texture3D,
            level: 0,
            xoffset: 0,
            yoffset: 1,
            zoffset: 1,
            x: 2,
            y: 3,
            width: 2,
            height: 1,
        }),
        Command::TexParameter {
            target: TextureTarget::Texture3D,
            param: TexParam::WrapR(Wrap::ClampToEdge),
        },
        Command::Enable(Capability::Texture3D),
        Command::FramebufferTexture {
            target: crate::ff::framebuffer::FramebufferTarget::Draw,
            attachment: crate::ff::framebuffer::AttachmentPoint::Color(1),
            texture: Some((TextureTarget::Texture3D, 9)),
            level: 1,
            layer: 2,
        },
        Command::GetTexImage(crate::ff::texture_calls::GetTexImage {
            target: TextureTarget::Texture3D,
            level: 0,
            format: PixelFormat::Rgba,
            ty: PixelType::Float,
            slot: 3,
        }),
        // GL 1.3's cube maps: the cube bound, enabled and given parameters; its faces the
        // image targets; texgen REFLECTION_MAP and NORMAL_MAP.
        Command::BindTexture {
            target: TextureTarget::CubeMap,
            name: 11,
        },
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::CubeFace(crate::ff::CubeFace::NegativeY),
            level: 1,
            internal_format: TexFormat::Rgba8,
            width: 1,
            height: 1,
            depth: 1,
            border: 0,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            data: TexData::Bytes(vec![1u8, 2, 3, 4].into()),
        }),
        Command::TexSubImage2D(TexSubImage {
            face: Some(crate::ff::CubeFace::PositiveZ),
            level: 0,
            x: 0,
            y: 0,
            z: 0,
            width: 1,
            height: 1,
            depth: 1,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            data: Some(Arc::from(vec![9u8; 4])),
        }),
        Command::CopyTexImage2D(CopyTexImage {
            face: Some(crate::ff::CubeFace::NegativeX),
            requested: None,
            level: 0,
            internal_format: TexFormat::Rgb8,
            x: 1,
            y: 2,
            width: 4,
            height: 4,
            border: 0,
        }),
        Command::CopyTexSubImage(crate::ff::texture_calls::CopyTexSubImage {
            target: TextureTarget::CubeFace(crate::ff::CubeFace::PositiveY),
            level: 0,
            xoffset: 1,
            yoffset: 1,
            zoffset: 0,
            x: 0,
            y: 0,
            width: 2,
            height: 2,
        }),
        Command::GetTexImage(crate::ff::texture_calls::GetTexImage {
            target: TextureTarget::CubeFace(crate::ff::CubeFace::PositiveX),
            level: 0,
            format: PixelFormat::Rgb,
            ty: PixelType::UnsignedByte,
            slot: 4,
        }),
        Command::TexParameter {
            target: TextureTarget::CubeMap,
            param: TexParam::WrapS(Wrap::ClampToEdge),
        },
        Command::Enable(Capability::TextureCubeMap),
        Command::TexGen {
            coord: TexCoord::R,
            param: TexGenParam::Mode(crate::ff::TexGenMode::ReflectionMap),
        },
        Command::TexGen {
            coord: TexCoord::S,
            param: TexGenParam::Mode(crate::ff::TexGenMode::NormalMap),
        },
        Command::CopyTexImage2D(CopyTexImage {
            face: None,
            requested: None,
            level: 0,
            internal_format: TexFormat::DepthComponent16,
            x: 0,
            y: 0,
            width: 64,
            height: 64,
            border: 0,
        }),
        Command::TexParameter {
            target: TextureTarget::Texture2D,
            param: TexParam::MinFilter(Filter::LinearMipmapNearest),
        },
        Command::TexParameter {
            target: TextureTarget::Texture2D,
            param: TexParam::WrapT(Wrap::ClampToBorder),
        },
        Command::TexParameter {
            target: TextureTarget::Texture2D,
            param: TexParam::BorderColor(Vec4::ONE),
        },
        Command::TexParameter {
            target: TextureTarget::Texture2D,
            param: TexParam::CompareMode(CompareMode::CompareRToTexture),
        },
        Command::TexParameter {
            target: TextureTarget::Texture2D,
            param: TexParam::CompareFunc(CompareFunc::Gequal),
        },
        Command::TexParameter {
            target: TextureTarget::Texture2D,
            param: TexParam::DepthTextureMode(DepthTextureMode::Intensity),
        },
        Command::TexParameter {
            target: TextureTarget::Texture2D,
            param: TexParam::CompareFailValue(0.3),
        },
        Command::TexParameter {
            target: TextureTarget::Texture2D,
            param: TexParam::GenerateMipmap(true),
        },
        Command::TexGen {
            coord: TexCoord::Q,
            param: TexGenParam::Mode(TexGenMode::ObjectLinear),
        },
        Command::TexGen {
            coord: TexCoord::R,
            param: TexGenParam::ObjectPlane(Vec4::new(0.0, 0.05, 0.0, 1.5)),
        },
        Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Combine)),
        Command::TexEnv(TexEnvParam::Color(Vec4::new(0.25, 0.5, 0.75, 1.0))),
        Command::TexEnv(TexEnvParam::CombineRgb(CombineFunc::Dot3Rgba)),
        Command::TexEnv(TexEnvParam::CombineAlpha(CombineFunc::AddSigned)),
        Command::TexEnv(TexEnvParam::SourceRgb(
            CombineArg::Arg2,
            CombineSource::TextureUnit(3),
        )),
        Command::TexEnv(TexEnvParam::SourceAlpha(
            CombineArg::Arg1,
            CombineSource::Previous,
        )),
        Command::TexEnv(TexEnvParam::OperandRgb(
            CombineArg::Arg0,
            CombineOperand::OneMinusSrcColor,
        )),
        Command::TexEnv(TexEnvParam::OperandAlpha(
            CombineArg::Arg1,
            CombineOperand::OneMinusSrcAlpha,
        )),
        Command::TexEnv(TexEnvParam::RgbScale(4.0)),
        Command::TexEnv(TexEnvParam::AlphaScale(2.0)),
        Command::CombinerParameter(CombinerParam::NumGeneralCombiners(2)),
        Command::CombinerParameter(CombinerParam::ColorSumClamp(true)),
        Command::CombinerParameter(CombinerParam::ConstantColor1(Vec4::splat(0.5))),
        Command::CombinerInput {
            stage: 1,
            portion: Portion::Rgb,
            variable: Variable::D,
            input,
        },
        Command::CombinerOutput {
            stage: 0,
            portion: Portion::Alpha,
            output: CombinerOutput {
                ab: Register::Discard,
                cd: Register::Texture(0),
                sum: Register::Spare0,
                scale: CombinerScale::ByTwo,
                bias: CombinerBias::ByNegativeOneHalf,
                ab_product: Product::Componentwise,
                cd_product: Product::Dot,
                sum_or_mux: SumOrMux::Mux,
            },
        },
        Command::FinalCombinerInput {
            variable: FinalVariable::G,
            input: CombinerInput {
                register: Register::Spare0,
                mapping: Mapping::UnsignedInvert,
                usage: ComponentUsage::Alpha,
            },
        },
        Command::AlphaFunc {
            func: CompareFunc::Greater,
            reference: 0.5,
        },
        Command::DepthFunc(CompareFunc::Equal),
        Command::DepthMask(false),
        Command::StencilFunc {
            func: CompareFunc::Notequal,
            reference: -1,
            mask: 0xFF,
        },
        Command::StencilOp {
            fail: StencilOp::IncrWrap,
            depth_fail: StencilOp::Invert,
            depth_pass: StencilOp::Replace,
        },
        Command::StencilMask(u32::MAX),
        Command::BlendFunc {
            src: BlendFactor::SrcAlphaSaturate,
            dst: BlendFactor::OneMinusSrcAlpha,
        },
        Command::ColorMask(ColorMask {
            r: true,
            g: false,
            b: true,
            a: false,
        }),
        Command::PolygonOffset {
            factor: -2.0,
            units: -9.0,
        },
        Command::PolygonMode {
            face: Face::Back,
            mode: PolygonMode::Line,
        },
        Command::CullFace(Face::Front),
        Command::FrontFace(FrontFace::Cw),
        Command::LineWidth(12.0),
        Command::PointSize(0.5),
        Command::Enable(Capability::Fog),
        Command::Enable(Capability::ScissorTest),
        Command::Enable(Capability::ColorLogicOp),
        Command::Disable(Capability::IndexLogicOp),
        Command::LogicOp(LogicOp::OrReverse),
        Command::Disable(Capability::Dither),
        Command::Hint {
            target: HintTarget::Fog,
            mode: HintMode::Nicest,
        },
        Command::BlendColor(Vec4::new(0.25, 0.5, 0.75, 1.0)),
        Command::BlendEquation(BlendEquation::FuncReverseSubtract),
        Command::BlendFuncSeparate {
            src_rgb: BlendFactor::ConstantColor,
            dst_rgb: BlendFactor::OneMinusConstantAlpha,
            src_alpha: BlendFactor::SrcAlphaSaturate,
            dst_alpha: BlendFactor::Zero,
        },
        Command::Enable(Capability::ClipPlane(7)),
        Command::Disable(Capability::ClipPlane(2)),
        Command::ClipPlane {
            plane: 6,
            equation: Vec4::new(0.5, -1.0, 0.0, 0.25),
        },
        Command::Scissor(ScissorBox {
            x: -2,
            y: 3,
            width: 10,
            height: 0,
        }),
        Command::Fog(FogParam::Mode(FogMode::Exp2)),
        Command::Fog(FogParam::Density(0.25)),
        Command::Fog(FogParam::Start(-1.5)),
        Command::Fog(FogParam::End(40.0)),
        Command::Fog(FogParam::Index(2.0)),
        Command::Fog(FogParam::Color(Vec4::new(0.1, 0.2, 0.3, 1.0))),
        Command::Clear(ClearMask::ALL),
        Command::Clear(ClearMask::default()),
        Command::BlitFramebuffer(crate::ff::blit::Blit {
            src: crate::ff::blit::BlitRect {
                x0: 0,
                y0: 0,
                x1: 32,
                y1: -4,
            },
            dst: crate::ff::blit::BlitRect {
                x0: 64,
                y0: 0,
                x1: 0,
                y1: 64,
            },
            mask: crate::ff::blit::BlitMask::from_bits(0x4100),
            filter: crate::ff::blit::FilterArg::Known(crate::ff::blit::BlitFilter::Linear),
        }),
        // A mask bit and a filter outside the sets travel as numbers (ff::blit).
        Command::BlitFramebuffer(crate::ff::blit::Blit {
            src: crate::ff::blit::BlitRect {
                x0: 0,
                y0: 0,
                x1: 1,
                y1: 1,
            },
            dst: crate::ff::blit::BlitRect {
                x0: 0,
                y0: 0,
                x1: 1,
                y1: 1,
            },
            mask: crate::ff::blit::BlitMask::from_bits(0x4201),
            filter: crate::ff::blit::FilterArg::Other(0x0DE1),
        }),
        Command::ClearColor(Vec4::new(0.5, 0.5, 0.5, 0.0)),
        Command::ClearDepth(1.0),
        Command::ClearStencil(128),
        Command::ReadPixels(ReadPixels {
            x: 0,
            y: 0,
            width: 4,
            height: 4,
            format: PixelFormat::DepthComponent,
            ty: PixelType::UnsignedInt,
            slot: 3,
        }),
        // The bytes glReadPixels left in readback_3 become a texture (the two-phase idiom
        // of the 8- and 16-bit shadow maps).
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::Luminance8Alpha8,
            width: 4,
            height: 4,
            depth: 1,
            border: 0,
            format: PixelFormat::LuminanceAlpha,
            ty: PixelType::UnsignedByte,
            data: TexData::Readback(3),
        }),
        // The program's own conversion of FLOAT depth in readback_3 (see TexData).
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::Luminance8Alpha8,
            width: 2,
            height: 2,
            depth: 1,
            border: 0,
            format: PixelFormat::LuminanceAlpha,
            ty: PixelType::UnsignedByte,
            data: TexData::ConvertedDepth {
                slot: 3,
                ty: PixelType::UnsignedShort,
                rule: DepthRule::Round,
            },
        }),
        Command::Draw(Arc::new(g)),
        Command::Draw(Arc::new(Geometry::new(Primitive::Points, vec![]))),
        Command::PushAttrib(AttribMask::ALL),
        Command::PushAttrib(AttribMask::of(&[
            AttribGroup::Lighting,
            AttribGroup::Texture,
        ])),
        Command::PushAttrib(AttribMask(0)),
        Command::PushAttrib(AttribMask(0x4000_0001)),
        Command::PopAttrib,
    ]
}

#[test]
fn attribute_masks_read_and_print_as_bits() {
    same(
        "glPushAttrib(GL_ENABLE_BIT | GL_DEPTH_BUFFER_BIT);",
        "glPushAttrib(GL_DEPTH_BUFFER_BIT|GL_ENABLE_BIT);",
    );
    assert_eq!(
        parse("glPushAttrib(GL_ALL_ATTRIB_BITS); glPopAttrib();").unwrap(),
        vec![Command::PushAttrib(AttribMask::ALL), Command::PopAttrib]
    );
    assert_eq!(
        print(&[Command::PushAttrib(AttribMask::of(&[
            AttribGroup::Current,
            AttribGroup::Fog
        ]))]),
        "glPushAttrib(GL_CURRENT_BIT | GL_FOG_BIT);\n"
    );
    same(
        "glPushAttrib(0x2001);",
        "glPushAttrib(GL_CURRENT_BIT | GL_ENABLE_BIT);",
    );
    let e = parse("glPushAttrib(GL_CURRENT_BIT | GL_FOGG_BIT);").unwrap_err();
    assert!(e.to_string().contains("GL_FOG_BIT"), "{e}");
}

#[test]
fn round_trip_of_every_command() {
    let cmds = sample_commands();
    let text = print(&cmds);
    let back = parse(&text).unwrap_or_else(|e| panic!("{e}\n{text}"));
    for (a, b) in cmds.iter().zip(&back) {
        assert_eq!(a, b, "\n{text}");
    }
    assert_eq!(back.len(), cmds.len());
}

#[test]
fn indexed_geometry_prints_as_draw_elements() {
    let mut g = Geometry::new(
        Primitive::Quads,
        vec![Vec4::W, Vec4::X + Vec4::W, Vec4::ONE, Vec4::Y + Vec4::W],
    );
    g.indices = Some(vec![3, 2, 1, 0]);
    g.colors = Some(vec![Vec4::X, Vec4::Y, Vec4::Z, Vec4::ONE]);
    g.texcoords[2] = Some(vec![Vec4::W; 4]);
    let text = print(&[Command::Draw(Arc::new(g.clone()))]);
    assert!(
        text.contains("glDrawElements(GL_QUADS, 4, GL_UNSIGNED_INT"),
        "{text}"
    );
    // Indexed quads split as Mesa splits indexed quads: the draw stays indexed.
    let back = parse(&text).unwrap();
    assert_eq!(back, vec![Command::Draw(Arc::new(g))], "\n{text}");
}

/// The printed script compiles as C99 against the system's GL headers (the test command
/// installs gcc and libgl-dev).
#[test]
fn printed_script_is_valid_c() {
    let dir = std::env::temp_dir().join(format!("ff-script-c-{}", std::process::id()));
    let header = std::path::Path::new("/usr/include/GL/glext.h");
    assert!(
        header.exists(),
        "GL headers missing: apt-get install libgl-dev"
    );
    std::fs::create_dir_all(&dir).expect("temporary directory");
    let body = print(&sample_commands());
    let src = format!(
        "#define GL_GLEXT_PROTOTYPES 1\n#include <GL/gl.h>\n#include <GL/glext.h>\n#include <math.h>\n#include <stddef.h>\n\
         static GLuint readback_3[16];\n\
         static GLubyte readback_4[16];\n\
         const void *fixedfunc_depth_ubyte_truncate(const void *);\n\
         const void *fixedfunc_depth_ubyte_round(const void *);\n\
         const void *fixedfunc_depth_ushort_truncate(const void *);\n\
         const void *fixedfunc_depth_ushort_round(const void *);\n\
         void script(void) {{\n{body}}}\n"
    );
    let file = dir.join("script.c");
    std::fs::write(&file, src).expect("write script.c");
    let out = std::process::Command::new("gcc")
        .args(["-std=c99", "-fsyntax-only", "-Wall", "-Werror"])
        .arg(&file)
        .output()
        .expect("gcc missing: apt-get install gcc");
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

fn finite() -> impl Strategy<Value = f32> {
    use proptest::num::f32::{NEGATIVE, NORMAL, POSITIVE, SUBNORMAL, ZERO};
    POSITIVE | NEGATIVE | NORMAL | SUBNORMAL | ZERO
}

fn vec4() -> impl Strategy<Value = Vec4> {
    prop::array::uniform4(finite()).prop_map(Vec4::from_array)
}

fn token<T: GlEnum + std::fmt::Debug>() -> impl Strategy<Value = T> {
    prop::sample::select(T::TABLE.iter().map(|(_, _, v)| *v).collect::<Vec<_>>())
}

fn geometry() -> impl Strategy<Value = Geometry> {
    (token::<Primitive>(), 1usize..6).prop_flat_map(|(p, n)| {
        (
            prop::collection::vec(vec4(), n),
            prop::option::of(prop::collection::vec(vec4(), n)),
            prop::option::of(prop::collection::vec(vec4(), n)),
            prop::option::of(prop::collection::vec(vec4(), n)),
        )
            .prop_map(move |(pos, colors, normals, tc)| {
                let mut g = Geometry::new(p, pos);
                g.colors = colors;
                g.normals = normals.map(|v| v.into_iter().map(Vec4::truncate).collect());
                g.texcoords[5] = tc;
                g
            })
    })
}

fn command() -> impl Strategy<Value = Command> {
    prop_oneof![
        vec4().prop_map(Command::Color),
        vec4().prop_map(|v| Command::Translate(v.truncate())),
        (finite(), vec4()).prop_map(|(a, v)| Command::Rotate {
            angle_deg: a,
            axis: v.truncate()
        }),
        prop::array::uniform16(finite())
            .prop_map(|a| Command::LoadMatrix(Mat4::from_cols_array(&a))),
        (token::<TexCoord>(), vec4()).prop_map(|(coord, p)| Command::TexGen {
            coord,
            param: TexGenParam::EyePlane(p)
        }),
        token::<Capability>().prop_map(Command::Enable),
        any::<u8>().prop_map(|i| Command::Disable(Capability::Light(i))),
        (token::<CompareFunc>(), finite())
            .prop_map(|(func, reference)| Command::AlphaFunc { func, reference }),
        (token::<CompareFunc>(), any::<i32>(), any::<u32>()).prop_map(|(func, reference, mask)| {
            Command::StencilFunc {
                func,
                reference,
                mask,
            }
        }),
        (token::<CombineFunc>(), any::<bool>()).prop_map(|(f, rgb)| Command::TexEnv(if rgb {
            TexEnvParam::CombineRgb(f)
        } else {
            TexEnvParam::CombineAlpha(f)
        })),
        (
            any::<u8>(),
            token::<Register>(),
            token::<Mapping>(),
            token::<ComponentUsage>()
        )
            .prop_map(|(stage, register, mapping, usage)| {
                Command::CombinerInput {
                    stage,
                    portion: Portion::Rgb,
                    variable: Variable::B,
                    input: CombinerInput {
                        register,
                        mapping,
                        usage,
                    },
                }
            }),
        (
            any::<u8>(),
            prop::collection::vec(any::<u8>(), 0..12),
            // The front ends give glTexImage only the model's own types (`pixel_types`).
            prop::sample::select(vec![
                PixelType::UnsignedByte,
                PixelType::UnsignedShort,
                PixelType::UnsignedInt,
                PixelType::Float,
            ])
        )
            .prop_map(|(w, bytes, ty)| {
                Command::TexImage(TexImage {
                    requested: None,
                    target: TextureTarget::Texture2D,
                    level: 0,
                    internal_format: TexFormat::Rgba8,
                    width: i32::from(w),
                    height: 1,
                    depth: 1,
                    border: 0,
                    format: PixelFormat::Rgba,
                    ty,
                    data: TexData::Bytes(Arc::from(bytes)),
                })
            }),
        // A volume's rows, padded to the default alignment across its images.
        (1i32..5, 1i32..4, 1i32..4, prop::bool::ANY, any::<u8>()).prop_map(
            |(width, height, depth, rgb, seed)| {
                let format = if rgb {
                    PixelFormat::Rgb
                } else {
                    PixelFormat::Luminance
                };
                let n = (width * height * depth) as usize * format.components();
                let bytes: Vec<u8> = (0..n).map(|i| seed.wrapping_add(i as u8)).collect();
                Command::TexImage(TexImage {
                    requested: None,
                    target: TextureTarget::Texture3D,
                    level: 0,
                    internal_format: TexFormat::Rgb8,
                    width,
                    height,
                    depth,
                    border: 0,
                    format,
                    ty: PixelType::UnsignedByte,
                    data: TexData::Bytes(Arc::from(bytes)),
                })
            }
        ),
        geometry().prop_map(|g| Command::Draw(Arc::new(g))),
    ]
}

proptest! {
    #[test]
    fn parse_inverts_print(cmds in prop::collection::vec(command(), 0..12)) {
        let text = print(&cmds);
        let back = parse(&text);
        prop_assert_eq!(back.as_ref(), Ok(&cmds), "{}", text);
    }

    #[test]
    fn parse_never_panics(src in "[ -~\\n]{0,200}") {
        let _ = parse(&src);
    }

    #[test]
    fn parse_never_panics_on_gl_like_text(
        calls in prop::collection::vec(prop::sample::select(crate::ff::api::Entry::script_names()), 0..6),
        args in prop::collection::vec("(GL_[A-Z0-9_]{1,12}|-?[0-9]{1,3}(\\.[0-9])?|\\(GLfloat\\[\\]\\)\\{[0-9, ]{0,9}\\}|readback_[0-9])", 0..6),
    ) {
        let src: String = calls.iter().map(|c| format!("{c}({});\n", args.join(", "))).collect();
        let _ = parse(&src);
    }
}

/// `written` parses to the same commands as `plain`.
fn same(written: &str, plain: &str) {
    assert_eq!(
        parse(written).unwrap_or_else(|e| panic!("{written:?}: {e}")),
        parse(plain).unwrap(),
        "{written:?}"
    );
}

/// What a C compiler accepts of the dialect, the reader accepts too (each case is the same
/// commands as its plain spelling).
mod c_as_written {
    use super::*;

    #[test]
    fn preprocessor_includes_and_defines() {
        same(
            "#include <GL/gl.h>\n#include <GL/glext.h>\n#define SIZE 0.5f\n#define RED 1, 0, 0\nglColor4f(RED, SIZE);",
            "glColor4f(1, 0, 0, 0.5f);",
        );
        same(
            "#ifndef GL_GLEXT_PROTOTYPES\n#define GL_GLEXT_PROTOTYPES 1\n#endif\nglLoadIdentity();",
            "glLoadIdentity();",
        );
        let e = parse("glLoadIdentity();\n#define SQ(x) ((x)*(x))").unwrap_err();
        assert!(
            matches!(e, ScriptError::Preprocessor { line: 2, .. }),
            "{e}"
        );
    }

    #[test]
    fn null_pointer_spellings() {
        let plain =
            "glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);";
        for null in [
            "0",
            "(void *)0",
            "((void*)0)",
            "(const GLvoid *)NULL",
            "(NULL)",
        ] {
            same(&plain.replace("NULL);", &format!("{null});")), plain);
        }
    }

    #[test]
    fn hex_float_literals() {
        same(
            "glColor4f(0x1p-1f, 0x1.8p1, 0X.8P0, 0x1p0);",
            "glColor4f(0.5f, 3, 0.5f, 1);",
        );
    }

    #[test]
    fn casts_convert_as_c_does() {
        same(
            "glColor4f((GLfloat)1, (float)0.25, (GLclampf)0, (const GLfloat)1);",
            "glColor4f(1, 0.25f, 0, 1);",
        );
        // A cast to an integer type truncates towards zero.
        same("glClearStencil((GLint)2.7);", "glClearStencil(2);");
        same("glClearStencil((int)-2.7);", "glClearStencil(-2);");
        same(
            "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)GL_LINEAR);",
            "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);",
        );
        same(
            "glLightfv(GL_LIGHT0, GL_POSITION, (const GLfloat[]){0, 1, 0, 0});",
            "glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){0, 1, 0, 0});",
        );
    }

    #[test]
    fn redundant_parentheses_and_empty_statements() {
        same(
            ";glColor4f((1.0f), ((0)), (0), 1);;",
            "glColor4f(1, 0, 0, 1);",
        )
    }

    #[test]
    fn a_byte_order_mark() {
        same("\u{FEFF}glLoadIdentity();", "glLoadIdentity();");
    }

    #[test]
    fn tokens_are_named_as_in_c() {
        let e = parse("glDepthFunc(;").unwrap_err().to_string();
        assert!(e.contains("found ';'"), "{e}");
        assert!(!e.contains("Semi"), "{e}");
        let e = parse("glLoadIdentity() glLoadIdentity();")
            .unwrap_err()
            .to_string();
        assert!(e.contains("expected ';', found glLoadIdentity"), "{e}");
    }

    #[test]
    fn commands_keep_their_lines() {
        let cmds = parse_lines(
            "glLoadIdentity();\n\nglBegin(GL_POINTS);\nglVertex2f(0, 0);\nglEnd();\nglPopMatrix();",
        )
        .unwrap();
        let lines: Vec<usize> = cmds.iter().map(|(l, _)| *l).collect();
        assert_eq!(lines, vec![1, 5, 6]);
    }
}

/// Every variant of the vertex-attribute families and the double-precision matrix calls
/// reads as its float spelling with GL's conversion applied.
mod variants {
    use super::*;

    #[test]
    fn integer_colours_are_normalised() {
        // Unsigned c/(2ⁿ − 1); signed (2c + 1)/(2ⁿ − 1) (GL 1.5 Table 2.9).
        let cmds = parse("glColor3ub(255, 0, 51);").unwrap();
        assert_eq!(cmds, vec![Command::Color(Vec4::new(1.0, 0.0, 0.2, 1.0))]);
        let cmds = parse("glColor4bv((GLbyte[]){127, -128, 0, 127});").unwrap();
        assert_eq!(
            cmds,
            vec![Command::Color(Vec4::new(1.0, -1.0, 1.0 / 255.0, 1.0))]
        );
        let cmds = parse("glColor3us(65535, 0, 0);").unwrap();
        assert_eq!(cmds, vec![Command::Color(Vec4::new(1.0, 0.0, 0.0, 1.0))]);
        // C converts 256 to GLubyte as 0 before GL sees it.
        same("glColor3ub(256, 0, 0);", "glColor3f(0, 0, 0);");
        same("glColor3d(0.5, 0.25, 1.0);", "glColor3f(0.5f, 0.25f, 1);");
        same(
            "glColor4fv((GLfloat[]){1, 0, 0, 0.5f});",
            "glColor4f(1, 0, 0, 0.5f);",
        );
    }

    #[test]
    fn vertices_normals_and_texcoords_in_every_type() {
        let plain = "glBegin(GL_TRIANGLES);\nglNormal3f(0, 0, 1);\nglTexCoord2f(1, 2);\nglMultiTexCoord2f(GL_TEXTURE1, 3, 4);\nglVertex3f(1, 2, 0);\nglVertex4f(1, 2, 3, 1);\nglVertex3f(-1, 0.5f, 2);\nglEnd();";
        same(
            "glBegin(GL_TRIANGLES);\nglNormal3d(0, 0, 1);\nglTexCoord2s(1, 2);\nglMultiTexCoord2fARB(GL_TEXTURE1_ARB, 3, 4);\nglVertex2i(1, 2);\nglVertex3dv((GLdouble[]){1, 2, 3});\nglVertex3fv((GLfloat[]){-1, 0.5f, 2});\nglEnd();",
            plain,
        );
        let b = 1.0 / 255.0;
        assert_eq!(
            parse("glNormal3b(0, 0, 127);").unwrap(),
            vec![Command::Normal(Vec3::new(b, b, 1.0))]
        );
    }

    #[test]
    fn double_matrix_calls() {
        same(
            "glTranslated(1, 2, 3);\nglRotated(90, 0, 0, 1);\nglScaled(2, 2, 2);\nglLoadMatrixd((GLdouble[]){1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1});",
            "glTranslatef(1, 2, 3);\nglRotatef(90, 0, 0, 1);\nglScalef(2, 2, 2);\nglLoadMatrixf((GLfloat[]){1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1});",
        );
        same(
            "glActiveTextureARB(GL_TEXTURE1_ARB);\nglTexGenf(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);\nglTexGendv(GL_S, GL_EYE_PLANE, (GLdouble[]){1, 0, 0, 0});",
            "glActiveTexture(GL_TEXTURE1);\nglTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);\nglTexGenfv(GL_S, GL_EYE_PLANE, (GLfloat[]){1, 0, 0, 0});",
        );
    }

    #[test]
    fn rect_is_one_quad() {
        let quad = "glBegin(GL_QUADS);\nglVertex2f(0, 1);\nglVertex2f(2, 1);\nglVertex2f(2, 3);\nglVertex2f(0, 3);\nglEnd();";
        same("glRectf(0, 1, 2, 3);", quad);
        same("glRectiv((GLint[]){0, 1}, (GLint[]){2, 3});", quad);
        let e = parse("glBegin(GL_QUADS);\nglRectf(0, 0, 1, 1);").unwrap_err();
        assert!(matches!(e, ScriptError::Immediate { line: 2, .. }), "{e}");
    }

    #[test]
    fn short_arrays_are_refused() {
        let e = parse("glColor4fv((GLfloat[]){1, 0, 0});").unwrap_err();
        assert!(matches!(e, ScriptError::ArrayLength { .. }), "{e}");
    }
}

#[test]
fn fog_calls_in_every_form() {
    let cmds = parse(
        "glFogf(GL_FOG_MODE, GL_LINEAR); glFogi(GL_FOG_DENSITY, 2); \
         glFogfv(GL_FOG_END, (GLfloat[]){5}); \
         glFogiv(GL_FOG_COLOR, (GLint[]){2147483647, 0, 0, 2147483647});",
    )
    .unwrap();
    assert_eq!(cmds[0], Command::Fog(FogParam::Mode(FogMode::Linear)));
    assert_eq!(cmds[1], Command::Fog(FogParam::Density(2.0)));
    assert_eq!(cmds[2], Command::Fog(FogParam::End(5.0)));
    let Command::Fog(FogParam::Color(c)) = cmds[3] else {
        panic!("{:?}", cmds[3]);
    };
    assert!((c - Vec4::new(1.0, 0.0, 0.0, 1.0)).abs().max_element() < 1e-6);
    assert!(matches!(
        err("glFogi(GL_FOG_MODE, GL_NEAREST);"),
        ScriptError::UnknownEnum { .. }
    ));
}

#[test]
fn draws_from_a_buffer_object_through_offsets() {
    // Buffer 1: a 2-float header to skip, then three xy vertices; buffer 2: indices
    // after one unused GLushort. Both pointers are offsets into the bound buffers.
    let src = "glGenBuffers(2, (GLuint[]){0, 0});\n\
               glBindBuffer(GL_ARRAY_BUFFER, 1);\n\
               glBufferData(GL_ARRAY_BUFFER, 32, (GLfloat[]){9, 9, 0, 0, 1, 0, 0, 1}, \
               GL_STATIC_DRAW);\n\
               glBufferSubData(GL_ARRAY_BUFFER, 16, 4, (GLfloat[]){0.5f});\n\
               glVertexPointer(2, GL_FLOAT, 0, 8);\n\
               glEnableClientState(GL_VERTEX_ARRAY);\n\
               glDrawArrays(GL_TRIANGLES, 0, 3);\n\
               glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 2);\n\
               glBufferData(GL_ELEMENT_ARRAY_BUFFER, 8, (GLushort[]){7, 2, 1, 0}, \
               GL_STATIC_DRAW);\n\
               glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, (const GLvoid *)2);\n\
               glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);\n\
               glUnmapBuffer(GL_ARRAY_BUFFER);\n";
    let cmds = parse(src).unwrap();
    let draws: Vec<_> = cmds
        .iter()
        .filter_map(|c| match c {
            Command::Draw(g) => Some(g.clone()),
            _ => None,
        })
        .collect();
    assert_eq!(draws.len(), 2, "{cmds:?}");
    let xy = |g: &Geometry| -> Vec<(f32, f32)> { g.positions.iter().map(|p| (p.x, p.y)).collect() };
    assert_eq!(xy(&draws[0]), [(0.0, 0.0), (0.5, 0.0), (0.0, 1.0)]);
    assert_eq!(xy(&draws[1]), [(0.0, 0.0), (0.5, 0.0), (0.0, 1.0)]);
    assert_eq!(draws[1].indices, Some(vec![2, 1, 0]));
}

#[test]
fn a_list_keeps_what_a_buffer_held_at_compile_time() {
    // GL 1.5 §5.4: a compiled draw holds the vertex data read when it was compiled; a
    // later glBufferSubData changes what a new draw reads, not the list.
    let src = "glBindBuffer(GL_ARRAY_BUFFER, 5);\n\
               glBufferData(GL_ARRAY_BUFFER, 24, (GLfloat[]){0, 0, 1, 0, 0, 1}, \
               GL_DYNAMIC_DRAW);\n\
               glVertexPointer(2, GL_FLOAT, 0, NULL);\n\
               glEnableClientState(GL_VERTEX_ARRAY);\n\
               glNewList(1, GL_COMPILE);\n\
               glDrawArrays(GL_TRIANGLES, 0, 3);\n\
               glEndList();\n\
               glBufferSubData(GL_ARRAY_BUFFER, 0, 8, (GLfloat[]){-1, -1});\n\
               glCallList(1);\n\
               glDrawArrays(GL_TRIANGLES, 0, 3);\n";
    let firsts: Vec<(f32, f32)> = parse(src)
        .unwrap()
        .iter()
        .filter_map(|c| match c {
            Command::Draw(g) => Some((g.positions[0].x, g.positions[0].y)),
            _ => None,
        })
        .collect();
    assert_eq!(firsts, [(0.0, 0.0), (-1.0, -1.0)]);
}

#[test]
fn buffer_object_misuse_names_the_line_and_the_rule() {
    let e = err("glBindBuffer(GL_ARRAY_BUFFER, 3);\n\
                 glBufferData(GL_ARRAY_BUFFER, 4, NULL, GL_STATIC_DRAW);\n\
                 glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE);\n\
                 glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE);\n")
    .to_string();
    assert!(e.contains("line 4") && e.contains("already mapped"), "{e}");
    let e = err("glBufferData(GL_ELEMENT_ARRAY_BUFFER, 4, NULL, GL_STATIC_DRAW);\n").to_string();
    assert!(
        e.contains("line 1") && e.contains("no buffer object"),
        "{e}"
    );
    let e = err("glBindBuffer(GL_ARRAY_BUFFER, 3);\n\
                 glBufferData(GL_ARRAY_BUFFER, 4, NULL, GL_STATIC_DROW);\n")
    .to_string();
    assert!(e.contains("GL_STATIC_DRAW"), "{e}");
}

#[test]
fn interleaved_arrays_read_a_buffer_from_an_offset() {
    // GL_C3F_V3F from byte 4 of the buffer: the colour at +0, the vertex at +12 of each
    // 24-byte element.
    let src = "glBindBuffer(GL_ARRAY_BUFFER, 1);\n\
               glBufferData(GL_ARRAY_BUFFER, 52, (GLfloat[]){99, 1, 0, 0, 0, 0, 0, \
               0, 1, 0, 1, 0, 0}, GL_STATIC_DRAW);\n\
               glInterleavedArrays(GL_C3F_V3F, 0, (GLvoid *)4);\n\
               glDrawArrays(GL_LINES, 0, 2);\n";
    let cmds = parse(src).unwrap();
    let Some(Command::Draw(g)) = cmds.last() else {
        panic!("a draw: {cmds:?}");
    };
    let xy: Vec<(f32, f32)> = g.positions.iter().map(|p| (p.x, p.y)).collect();
    assert_eq!(xy, [(0.0, 0.0), (1.0, 0.0)]);
    assert_eq!(
        g.colors,
        Some(vec![
            Vec4::new(1.0, 0.0, 0.0, 1.0),
            Vec4::new(0.0, 1.0, 0.0, 1.0)
        ])
    );
}

#[test]
fn multi_draws_read_pointer_arrays_and_become_one_draw_per_list() {
    let head = "glVertexPointer(2, GL_FLOAT, 0, (GLfloat[]){0, 0, 1, 0, 0, 1, 1, 1});\n\
                glEnableClientState(GL_VERTEX_ARRAY);\n";
    let draws = |text: &str| {
        parse(&format!("{head}{text}"))
            .unwrap_or_else(|e| panic!("{text}: {e}"))
            .into_iter()
            .filter(|c| matches!(c, Command::Draw(_)))
            .count()
    };
    assert_eq!(
        draws("glMultiDrawElements(GL_TRIANGLES, (GLsizei[]){3, 3}, GL_UNSIGNED_BYTE, (const void *[]){(GLubyte[]){0, 1, 2}, (GLubyte[]){1, 3, 2}}, 2);"),
        2
    );
    // A later empty list draws nothing of its own (GL 1.5 §2.8); an empty first list
    // stops the whole call, as on Mesa 22.3 (`client::FirstCount`).
    assert_eq!(
        draws("glMultiDrawArrays(GL_TRIANGLES, (GLint[]){0, 1}, (GLsizei[]){3, 0}, 2);"),
        1
    );
    assert_eq!(
        draws("glMultiDrawArrays(GL_TRIANGLES, (GLint[]){0, 1}, (GLsizei[]){0, 3}, 2);"),
        0
    );
    assert_eq!(
        draws("glMultiDrawArrays(GL_TRIANGLES, (GLint[]){0}, (GLsizei[]){3}, 0);"),
        0
    );
    for bad in [
        "glMultiDrawArrays(GL_TRIANGLES, (GLint[]){0}, (GLsizei[]){3}, -1);",
        "glMultiDrawArrays(GL_TRIANGLES, (GLint[]){0}, (GLsizei[]){-3}, 1);",
        "glMultiDrawElements(GL_TRIANGLES, (GLsizei[]){3}, GL_UNSIGNED_BYTE, (const void *[]){(GLubyte[]){0, 1, 2}}, 2);",
        "glMultiDrawElements(GL_TRIANGLES, (GLsizei[]){3}, GL_FLOAT, (const void *[]){(GLubyte[]){0, 1, 2}}, 1);",
    ] {
        assert!(parse(&format!("{head}{bad}")).is_err(), "{bad}");
    }
}

/// A pixel literal shorter than its rows is refused under every unpack layout, the tight
/// one of GL_UNPACK_ALIGNMENT 1 included (found by the script fuzzer: a 3×2 image of four
/// bytes was taken, and printed back as rows the reader then refused).
#[test]
fn a_pixel_literal_shorter_than_its_rows_is_refused() {
    let image = |w: u32, bytes: &str| {
        format!(
            "glPixelStorei(GL_UNPACK_ALIGNMENT, 1);\n\
             glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8, {w}, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, (GLubyte[]){{{bytes}}});\n"
        )
    };
    let err = parse(&image(3, "0, 85, 170, 255")).expect_err("four bytes for six");
    assert!(err.to_string().contains("pixel rows"), "{err}");
    let ok = parse(&image(2, "0, 85, 170, 255")).expect("four bytes for four");
    let printed = print(&ok);
    parse(&printed).unwrap_or_else(|e| panic!("{e}\n{printed}"));
    parse(&image(3, "0, 85, 170, 255, 1, 2")).expect("six bytes for six");
}

/// A script may spell BGRA and the signed and packed types: it reads back as the model's
/// form of the same pixels (`pixel_types`), and prints as that.
#[test]
fn client_pixel_types_read_as_the_models_form() {
    let cmds = parse(
        "glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_BGRA, GL_UNSIGNED_BYTE, \
         (GLubyte[]){1, 2, 3, 4});\n\
         glDrawPixels(1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, (GLushort[]){63519});\n\
         glDrawPixels(1, 1, GL_BGRA, GL_UNSIGNED_SHORT_5_6_5, (GLushort[]){63519});\n",
    )
    .expect("the script parses");
    let Command::TexImage(t) = &cmds[0] else {
        panic!("{cmds:?}")
    };
    assert_eq!(
        (t.format, t.ty),
        (PixelFormat::Rgba, PixelType::UnsignedByte)
    );
    assert_eq!(t.data.bytes().map(|d| d.to_vec()), Some(vec![3, 2, 1, 4]));
    let Command::DrawPixels(d) = &cmds[1] else {
        panic!("{cmds:?}")
    };
    assert_eq!(
        (d.format, d.ty),
        (PixelFormat::Rgb, PixelType::UnsignedByte)
    );
    assert_eq!(&d.data[..], &[255, 0, 255]);
    // A packed type with a format of another component count raises GL's error.
    assert!(matches!(
        cmds[2],
        Command::Raise {
            error: crate::ff::GlErrorKind::InvalidOperation,
            ..
        }
    ));
    // The rewritten calls print and read back as themselves (a raised error prints nothing).
    let rewritten = cmds[..2].to_vec();
    assert_eq!(parse(&print(&rewritten)).as_ref(), Ok(&rewritten));
}
