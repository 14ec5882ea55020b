//! Tables for `FixedState::apply`: initial values, error semantics, set-time transforms.

use glam::{Mat4, Vec3, Vec4};

use super::*;

fn run(cmds: &[Command]) -> FixedState {
    let mut s = FixedState::new();
    for c in cmds {
        s.apply(c).unwrap_or_else(|e| panic!("{c:?}: {e}"));
    }
    s
}

#[test]
fn initial_values() {
    let s = FixedState::new();
    assert_eq!(s.matrix_mode, MatrixMode::Modelview);
    assert_eq!(s.modelview_matrix(), Mat4::IDENTITY);
    assert_eq!(s.modelview.max_depth(), 32);
    assert_eq!(s.projection.max_depth(), 32);
    assert_eq!(s.texture_matrices[7].max_depth(), 10);
    assert_eq!(s.current.color, Vec4::ONE);
    assert_eq!(s.current.normal, Vec3::Z);
    assert_eq!(s.current.texcoords[3], Vec4::W);
    assert!(!s.lighting && s.lights.iter().all(|l| !l.enabled));
    assert_eq!(s.light_model.ambient, Vec4::new(0.2, 0.2, 0.2, 1.0));
    assert_eq!(s.materials.front.diffuse, Vec4::new(0.8, 0.8, 0.8, 1.0));
    assert_eq!(s.shade_model, ShadeModel::Smooth);
    assert_eq!(s.active_texture, 0);
    assert!(s.units.iter().all(|u| u.enabled_target().is_none()));
    assert_eq!(s.units[0].env.mode, TexEnvMode::Modulate);
    assert_eq!(s.units[0].texgen[0].value.mode, TexGenMode::EyeLinear);
    assert_eq!(s.units[0].texgen[1].value.object_plane, Vec4::Y);
    assert_eq!(s.units[0].texgen[3].value.eye_plane, Vec4::ZERO);
    assert_eq!(s.alpha_test.get(), None);
    assert_eq!(s.alpha_test.value, AlphaTest::DEFAULT);
    assert_eq!(s.depth_test.value, DepthTest::LESS_WRITE);
    assert_eq!(s.stencil_test.value, StencilTest::DEFAULT);
    assert_eq!(s.blend.value, Blend::ONE_ZERO);
    assert_eq!(s.cull_face.value, Face::Back);
    assert_eq!(s.front_face, FrontFace::Ccw);
    assert_eq!(s.clear.depth, 1.0);
    assert_eq!(s.depth_range, DepthRange::DEFAULT);
    assert_eq!(s.register_combiners.get(), None);
    assert_eq!(s.register_combiners.value.num_general, 1);
    assert_eq!(s.fog.get(), None);
    assert_eq!(s.fog.value, Fog::DEFAULT);
    assert_eq!(s.fog.value.mode, FogMode::Exp);
    assert_eq!(s.scissor.get(), None);
    assert_eq!(s.scissor.value, None);
    assert_eq!(s.scissor_box(), None);
    assert_eq!(s.blend.value.equation, BlendEquation::FuncAdd);
    assert_eq!(s.blend_color, Vec4::ZERO);
    assert_eq!(s.logic_op.get(), None);
    assert_eq!(s.logic_op.value, LogicOp::Copy);
    assert!(!s.index_logic_op);
    assert!(s.dither);
    assert_eq!(s.hints, Hints::DEFAULT);
    assert!(s
        .clip_planes
        .iter()
        .all(|p| !p.enabled && p.value == Vec4::ZERO));
    assert_eq!(s.error(), None);
}

#[test]
fn error_semantics_table() {
    use GlErrorKind::*;
    let combine_out = CombinerOutput {
        ab: Register::Spare1,
        scale: CombinerScale::ByFour,
        bias: CombinerBias::ByNegativeOneHalf,
        ..CombinerOutput::DEFAULT
    };
    let cases: Vec<(Command, GlErrorKind)> = vec![
        (Command::PopMatrix, StackUnderflow),
        (
            Command::TexEnv(TexEnvParam::CombineAlpha(CombineFunc::Dot3Rgb)),
            InvalidEnum,
        ),
        (Command::TexEnv(TexEnvParam::AlphaScale(3.0)), InvalidValue),
        (
            Command::CombinerParameter(CombinerParam::NumGeneralCombiners(0)),
            InvalidValue,
        ),
        (
            Command::CombinerParameter(CombinerParam::NumGeneralCombiners(9)),
            InvalidValue,
        ),
        (
            Command::CombinerOutput {
                stage: 0,
                portion: Portion::Rgb,
                output: combine_out,
            },
            InvalidOperation,
        ),
        (Command::Enable(Capability::Light(8)), InvalidEnum),
        (Command::ActiveTexture(8), InvalidEnum),
        (
            Command::Light {
                light: 0,
                param: LightParam::SpotCutoff(100.0),
            },
            InvalidValue,
        ),
        (
            Command::Viewport(Viewport {
                x: 0,
                y: 0,
                width: -1,
                height: 4,
            }),
            InvalidValue,
        ),
        (
            Command::TexGen {
                coord: TexCoord::Q,
                param: TexGenParam::Mode(TexGenMode::SphereMap),
            },
            InvalidEnum,
        ),
        (
            Command::Frustum(ViewVolume {
                left: -1.0,
                right: 1.0,
                bottom: -1.0,
                top: 1.0,
                near: 0.0,
                far: 1.0,
            }),
            InvalidValue,
        ),
        (Command::LineWidth(0.0), InvalidValue),
        (Command::Fog(FogParam::Density(-0.5)), InvalidValue),
        (
            Command::ClipPlane {
                plane: MAX_CLIP_PLANES as u8,
                equation: Vec4::X,
            },
            InvalidEnum,
        ),
        (
            Command::Enable(Capability::ClipPlane(MAX_CLIP_PLANES as u8)),
            InvalidEnum,
        ),
        (
            Command::Scissor(ScissorBox {
                x: 0,
                y: 0,
                width: -1,
                height: 4,
            }),
            InvalidValue,
        ),
    ];
    for (cmd, kind) in cases {
        // A non-default state, so "unchanged" is meaningful.
        let mut s = run(&[
            Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Replace)),
            Command::Translate(Vec3::new(1.0, 2.0, 3.0)),
        ]);
        let before = s.clone();
        let err = s.apply(&cmd).unwrap_err();
        assert_eq!(err.kind, kind, "{cmd:?}");
        assert_eq!(
            s.take_error(),
            Some(err),
            "sticky error recorded for {cmd:?}"
        );
        assert_eq!(s, before, "state unchanged by {cmd:?}");
    }
}

#[test]
fn invalid_enum_keeps_the_previous_texenv() {
    let mut s = run(&[
        Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Combine)),
        Command::TexEnv(TexEnvParam::CombineAlpha(CombineFunc::AddSigned)),
    ]);
    assert!(s
        .apply(&Command::TexEnv(TexEnvParam::CombineAlpha(
            CombineFunc::Dot3Rgba
        )))
        .is_err());
    assert_eq!(s.units[0].env.mode, TexEnvMode::Combine);
    assert_eq!(s.units[0].env.alpha.func, CombineFunc::AddSigned);
}

#[test]
fn first_error_sticks_until_read() {
    let mut s = FixedState::new();
    let first = s.apply(&Command::PopMatrix).unwrap_err();
    let _ = s.apply(&Command::ActiveTexture(42));
    assert_eq!(s.take_error(), Some(first));
    assert_eq!(s.take_error(), None);
}

#[test]
fn stack_overflow_per_stack() {
    // Mesa's depths: projection 32 (31 pushes fit), texture 10 per unit.
    let mut cmds = vec![Command::MatrixMode(MatrixMode::Projection)];
    cmds.extend(std::iter::repeat_n(
        Command::PushMatrix,
        crate::ff::matrix::PROJECTION_STACK_DEPTH - 1,
    ));
    let mut s = run(&cmds);
    assert_eq!(s.take_error(), None);
    assert_eq!(
        s.apply(&Command::PushMatrix).unwrap_err().kind,
        GlErrorKind::StackOverflow
    );
    // The texture stack is per unit: unit 1's is still empty.
    let mut s = run(&[
        Command::MatrixMode(MatrixMode::Texture),
        Command::PushMatrix,
        Command::Scale(Vec3::splat(2.0)),
        Command::ActiveTexture(1),
    ]);
    assert_eq!(
        s.apply(&Command::PopMatrix).unwrap_err().kind,
        GlErrorKind::StackUnderflow
    );
    assert_eq!(s.texture_matrix(0), Mat4::from_scale(Vec3::splat(2.0)));
    assert_eq!(s.texture_matrix(1), Mat4::IDENTITY);
}

/// piglit tests/general/texgen.c: the eye plane is transformed by the modelview current when
/// it is set. Each quad's S must equal the same function of the cell position.
#[test]
fn eye_plane_transform_timing_piglit_general_texgen() {
    let s_plane = |p: Vec4| Command::TexGen {
        coord: TexCoord::S,
        param: TexGenParam::EyePlane(p),
    };
    let s_of = |state: &FixedState, x: f32| {
        let object = Vec4::new(x, 0.0, 0.0, 1.0);
        let eye = state.modelview_matrix() * object;
        state.units[0].texgen[0].value.linear(object, eye).unwrap()
    };
    // Quad 1: plane (1,0,0,0.25) with the identity: s = x + 0.25.
    let q1 = run(&[s_plane(Vec4::new(1.0, 0.0, 0.0, 0.25))]);
    // Quad 2: plane (1,0,0,−0.25) set before Translate(0.5,−0.5,0)·Scale(2,1,1):
    // the plane stays, the vertex moves: s = (2x + 0.5) − 0.25.
    let q2 = run(&[
        s_plane(Vec4::new(1.0, 0.0, 0.0, -0.25)),
        Command::Translate(Vec3::new(0.5, -0.5, 0.0)),
        Command::Scale(Vec3::new(2.0, 1.0, 1.0)),
    ]);
    // Quad 3: plane (−1,0,0,1.25) set after Translate(1,0.5,0)·Scale(−1,1,1): multiplied by
    // MV⁻¹, so the object-space result is unchanged: s = −x + 1.25.
    let q3 = run(&[
        Command::Translate(Vec3::new(1.0, 0.5, 0.0)),
        Command::Scale(Vec3::new(-1.0, 1.0, 1.0)),
        s_plane(Vec4::new(-1.0, 0.0, 0.0, 1.25)),
    ]);
    for x in [0.0, 0.125, 0.25, 0.5] {
        assert!((s_of(&q1, x) - (x + 0.25)).abs() < 1e-6);
        assert!((s_of(&q2, x) - (2.0 * x + 0.25)).abs() < 1e-6);
        assert!((s_of(&q3, x) - (1.25 - x)).abs() < 1e-6);
    }
    // Changing the modelview afterwards does not move a stored plane.
    let mut later = q1.clone();
    later.apply(&Command::Translate(Vec3::X)).unwrap();
    assert_eq!(
        later.units[0].texgen[0].value.eye_plane,
        q1.units[0].texgen[0].value.eye_plane
    );
}

#[test]
fn light_position_uses_the_modelview_at_set_time() {
    let s = run(&[
        Command::Translate(Vec3::new(0.0, 0.0, -5.0)),
        Command::Light {
            light: 2,
            param: LightParam::Position(Vec4::new(0.0, 1.0, 0.0, 1.0)),
        },
        Command::LoadIdentity,
    ]);
    assert_eq!(s.lights[2].value.position, Vec4::new(0.0, 1.0, -5.0, 1.0));
}

#[test]
fn color_material_tracks_the_current_colour() {
    let red = Vec4::new(1.0, 0.0, 0.0, 1.0);
    let s = run(&[
        Command::ColorMaterial {
            face: Face::Front,
            mode: ColorMaterialMode::Diffuse,
        },
        Command::Enable(Capability::ColorMaterial),
        Command::Color(red),
    ]);
    assert_eq!(s.materials.front.diffuse, red);
    assert_eq!(s.materials.back.diffuse, Material::DEFAULT.diffuse);
}

#[test]
fn texture_table() {
    let img = TexImage {
        requested: None,
        target: TextureTarget::Texture2D,
        level: 0,
        internal_format: TexFormat::Rgba8,
        width: 2,
        height: 2,
        depth: 1,
        border: 0,
        format: PixelFormat::Rgba,
        ty: PixelType::UnsignedByte,
        data: (0u8..16).collect::<Vec<_>>().into(),
    };
    let mut s = run(&[
        Command::BindTexture {
            target: TextureTarget::Texture2D,
            name: 7,
        },
        Command::TexImage(img.clone()),
        Command::TexParameter {
            target: TextureTarget::Texture2D,
            param: TexParam::CompareMode(CompareMode::CompareRToTexture),
        },
        Command::TexSubImage2D(TexSubImage {
            face: None,
            level: 0,
            x: 1,
            y: 1,
            z: 0,
            width: 1,
            height: 1,
            depth: 1,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            data: Some(vec![9u8; 4].into()),
        }),
        Command::Enable(Capability::Texture2D),
    ]);
    // The default MIN_FILTER wants mipmaps: incomplete, so the unit samples nothing.
    assert!(s.enabled_texture(0).is_none());
    let t = s
        .texture(
            TextureTarget::Texture2D,
            s.units[0].bound(TextureTarget::Texture2D),
        )
        .unwrap();
    assert_eq!(t.params.compare_mode, CompareMode::CompareRToTexture);
    let data = t.level(0).unwrap().data.as_ref().unwrap();
    assert_eq!(&data.bytes[12..16], &[9, 9, 9, 9]);
    assert_eq!(&data.bytes[..4], &[0, 1, 2, 3]);
    // Binding name 7 to the other target is INVALID_OPERATION.
    let e = s
        .apply(&Command::BindTexture {
            target: TextureTarget::Texture1D,
            name: 7,
        })
        .unwrap_err();
    assert_eq!(e.kind, GlErrorKind::InvalidOperation);
    // Wrong data length, depth/colour mismatch.
    let short = TexImage {
        data: vec![0u8; 3].into(),
        ..img.clone()
    };
    assert_eq!(
        s.apply(&Command::TexImage(short)).unwrap_err().kind,
        GlErrorKind::InvalidValue
    );
    let depth = TexImage {
        internal_format: TexFormat::DepthComponent24,
        ..img
    };
    assert_eq!(
        s.apply(&Command::TexImage(depth)).unwrap_err().kind,
        GlErrorKind::InvalidOperation
    );
}

#[test]
fn draw_leaves_the_current_values_alone() {
    let mut g = Geometry::new(Primitive::Triangles, vec![Vec4::W; 3]);
    g.colors = Some(vec![Vec4::ONE, Vec4::ONE, Vec4::new(0.0, 1.0, 0.0, 1.0)]);
    let grey = Vec4::new(0.5, 0.5, 0.5, 1.0);
    let s = run(&[Command::Color(grey), Command::Draw(g.clone().into())]);
    assert_eq!(
        s.current.color, grey,
        "as Mesa after glDrawArrays (tests/c/state.c)"
    );
    g.normals = Some(vec![Vec3::X]);
    let mut s = FixedState::new();
    assert_eq!(
        s.apply(&Command::Draw(g.into())).unwrap_err().kind,
        GlErrorKind::InvalidValue
    );
}

/// A clip plane is stored in eye space with the modelview of glClipPlane (§2.12):
/// p′ = p·M⁻¹, so under glTranslatef(½, 0, 0) the plane −x ≥ 0 becomes −x_e + ½ ≥ 0.
#[test]
fn clip_planes_are_transformed_when_specified() {
    let s = run(&[
        Command::Translate(Vec3::new(0.5, 0.0, 0.0)),
        Command::ClipPlane {
            plane: 7,
            equation: Vec4::new(-1.0, 0.0, 0.0, 0.0),
        },
        Command::LoadIdentity,
        Command::Enable(Capability::ClipPlane(7)),
    ]);
    assert!(s.clip_planes[7].enabled);
    assert_eq!(s.clip_planes[7].value, Vec4::new(-1.0, 0.0, 0.0, 0.5));
}

/// glBlendFunc sets the RGB and alpha factors alike; glBlendColor clamps to [0, 1].
#[test]
fn blend_func_sets_both_factor_pairs_and_blend_color_clamps() {
    let s = run(&[
        Command::BlendFuncSeparate {
            src_rgb: BlendFactor::ConstantAlpha,
            dst_rgb: BlendFactor::One,
            src_alpha: BlendFactor::SrcAlphaSaturate,
            dst_alpha: BlendFactor::OneMinusConstantColor,
        },
        Command::BlendFunc {
            src: BlendFactor::SrcAlpha,
            dst: BlendFactor::OneMinusSrcAlpha,
        },
        Command::BlendEquation(BlendEquation::Max),
        Command::BlendColor(Vec4::new(-1.0, 0.5, 2.0, f32::INFINITY)),
    ]);
    let b = s.blend.value;
    assert_eq!(
        (b.src_rgb, b.dst_rgb, b.src_alpha, b.dst_alpha, b.equation),
        (
            BlendFactor::SrcAlpha,
            BlendFactor::OneMinusSrcAlpha,
            BlendFactor::SrcAlpha,
            BlendFactor::OneMinusSrcAlpha,
            BlendEquation::Max
        )
    );
    assert_eq!(s.blend_color, Vec4::new(0.0, 0.5, 1.0, 1.0));
}
