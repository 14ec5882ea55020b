//! A plan's own shader programs (`ff::program`) on the emulated path, against what the
//! program computes on the CPU: the built-in matrices from the fixed-function state, a
//! sampler on its unit, a uniform value; the return to the generated programs; and the
//! refusals (a uniform without a program, the native pipeline).

mod support;

use std::sync::Arc;

use fixedfunc::ff::{
    Capability, ClearMask, Command, Filter, Geometry, MatrixMode, PixelFormat, PixelType,
    Primitive, SamplerBinding, ShaderProgram, TexData, TexFormat, TexImage, TexParam,
    TextureTarget, UniformValue,
};
use fixedfunc::gpu::Profile;
use fixedfunc::pipeline::emulate::EmulatedPipeline;
use fixedfunc::pipeline::native::NativePipeline;
use fixedfunc::pipeline::{Pipeline, PipelineError};
use fixedfunc::vocab::DepthBits;
use glam::{Vec2, Vec3, Vec4};
use support::{assert_no_gl_error, context, probe, target};

const VERTEX: &str = "#version 330 core
layout(location = 0) in vec4 position;
layout(location = 3) in vec4 texcoord;
uniform mat4 ff_modelview_projection;
out vec2 uv;
void main() {
    uv = texcoord.st;
    gl_Position = ff_modelview_projection * position;
}
";

const FRAGMENT: &str = "#version 330 core
uniform sampler2D occlusion;
uniform vec4 tint;
in vec2 uv;
out vec4 colour;
void main() {
    colour = texture(occlusion, uv) * tint;
}
";

fn program() -> Arc<ShaderProgram> {
    Arc::new(ShaderProgram {
        name: "test/tinted".into(),
        vertex: VERTEX.into(),
        fragment: FRAGMENT.into(),
        samplers: vec![SamplerBinding {
            name: "occlusion".into(),
            unit: 2,
        }],
    })
}

/// The unit square [0, 1]² at z = 0 with texture coordinates equal to x and y.
fn square() -> Arc<Geometry> {
    let corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
    let positions: Vec<Vec4> = corners
        .iter()
        .map(|&(x, y)| Vec4::new(x, y, 0.0, 1.0))
        .collect();
    let mut g = Geometry::new(Primitive::Quads, positions.clone());
    g.texcoords[0] = Some(positions);
    Arc::new(g)
}

/// 2×2 RGBA texels, bottom row first: (255,0,0), (0,255,0) / (0,0,255), (255,255,255).
const TEXELS: [u8; 16] = [
    255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255,
];

/// Texture 7 on unit 2 (not enabled: a program samples what is bound), NEAREST; the
/// projection glOrtho(0, 1, 0, 1, −1, 1); the modelview scales x by ½, so the square
/// covers the left half of the target.
fn setup() -> Vec<Command> {
    let param = |param| Command::TexParameter {
        target: TextureTarget::Texture2D,
        param,
    };
    vec![
        Command::ClearColor(Vec4::new(0.0, 0.0, 0.0, 1.0)),
        Command::Clear(ClearMask {
            color: true,
            depth: true,
            stencil: false,
            accum: false,
        }),
        Command::ActiveTexture(2),
        Command::BindTexture {
            target: TextureTarget::Texture2D,
            name: 7,
        },
        Command::TexImage(TexImage {
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::Rgba8,
            requested: None,
            width: 2,
            height: 2,
            depth: 1,
            border: 0,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            data: TexData::Bytes(Arc::from(TEXELS.to_vec())),
        }),
        param(TexParam::MinFilter(Filter::Nearest)),
        param(TexParam::MagFilter(Filter::Nearest)),
        Command::ActiveTexture(0),
        Command::MatrixMode(MatrixMode::Projection),
        Command::LoadIdentity,
        Command::Ortho(fixedfunc::ff::ViewVolume {
            left: 0.0,
            right: 1.0,
            bottom: 0.0,
            top: 1.0,
            near: -1.0,
            far: 1.0,
        }),
        Command::MatrixMode(MatrixMode::Modelview),
        Command::LoadIdentity,
        Command::Scale(Vec3::new(0.5, 1.0, 1.0)),
    ]
}

/// tint (1, ½, 1, 1): each quadrant of the left half is its texel with green halved,
/// round(255 · ½) = 128; the right half keeps the clear colour. Then UseProgram(None) and a
/// fixed-function draw of the right half in glColor: the generated programs are back.
#[test]
fn a_program_draws_its_texels_times_its_uniform_where_the_state_puts_the_square() {
    for backend in support::HEADLESS {
        let ctx = context(backend, Profile::Core33);
        let t = target(&ctx, 16, 16, DepthBits::D24, false);
        let mut p = EmulatedPipeline::new(&ctx).expect("pipeline");
        let mut commands = setup();
        commands.extend([
            Command::UseProgram(Some(program())),
            Command::Uniform {
                name: "tint".into(),
                value: UniformValue::Vec4(Vec4::new(1.0, 0.5, 1.0, 1.0)),
            },
            Command::Draw(square()),
            Command::UseProgram(None),
            Command::LoadIdentity,
            Command::Translate(Vec3::new(0.5, 0.0, 0.0)),
            Command::Scale(Vec3::new(0.5, 0.5, 1.0)),
            Command::Color(Vec4::new(0.0, 1.0, 1.0, 1.0)),
            Command::Draw(square()),
        ]);
        p.execute(&ctx, &commands).expect("execute");
        assert_eq!(p.take_gl_error(), None, "{backend}");
        let img = t.read_color(&ctx).expect("colour");
        // Top row first: the top-left quadrant is the texel row 1, column 0.
        probe(&img, 1, 1, [0, 0, 255, 255], 0);
        probe(&img, 6, 1, [255, 128, 255, 255], 0);
        probe(&img, 1, 14, [255, 0, 0, 255], 0);
        probe(&img, 6, 14, [0, 128, 0, 255], 0);
        // Right half: the fixed-function square below, the clear colour above.
        probe(&img, 12, 14, [0, 255, 255, 255], 0);
        probe(&img, 12, 1, [0, 0, 0, 255], 0);
        // One generated program (the fixed-function draw) and the plan's program.
        assert_eq!(p.counters().programs_compiled, 2);
        assert_no_gl_error(&ctx);
        p.release(&ctx);
    }
}

/// A built-in the program declares follows the state at each draw: the same program drawn
/// twice under two modelviews lands twice.
#[test]
fn built_in_matrices_are_sent_at_each_draw() {
    let ctx = context(support::HEADLESS[0], Profile::Core33);
    let t = target(&ctx, 16, 16, DepthBits::D24, false);
    let mut p = EmulatedPipeline::new(&ctx).expect("pipeline");
    let mut commands = setup();
    commands.extend([
        Command::UseProgram(Some(program())),
        Command::Uniform {
            name: "tint".into(),
            value: UniformValue::Vec4(Vec4::ONE),
        },
        Command::LoadIdentity,
        Command::Scale(Vec3::new(0.25, 0.25, 1.0)),
        Command::Draw(square()),
        Command::Translate(Vec3::new(3.0, 3.0, 0.0)),
        Command::Draw(square()),
        Command::UseProgram(None),
    ]);
    p.execute(&ctx, &commands).expect("execute");
    let img = t.read_color(&ctx).expect("colour");
    // The lower-left 4×4 and the upper-right 4×4 (rows 0–3 from the top).
    probe(&img, 0, 15, [255, 0, 0, 255], 0);
    probe(&img, 15, 0, [255, 255, 255, 255], 0);
    probe(&img, 8, 8, [0, 0, 0, 255], 0);
    assert_no_gl_error(&ctx);
    p.release(&ctx);
}

#[test]
fn a_uniform_without_a_program_and_a_bad_program_are_errors_not_panics() {
    let ctx = context(support::HEADLESS[0], Profile::Core33);
    let _t = target(&ctx, 4, 4, DepthBits::D24, false);
    let mut p = EmulatedPipeline::new(&ctx).expect("pipeline");
    let err = p
        .execute(
            &ctx,
            &[Command::Uniform {
                name: "tint".into(),
                value: UniformValue::Vec2(Vec2::ONE),
            }],
        )
        .unwrap_err();
    assert!(
        matches!(err, PipelineError::UniformWithoutProgram { ref name } if name == "tint"),
        "{err}"
    );
    let bad = Arc::new(ShaderProgram {
        name: "test/bad".into(),
        vertex: VERTEX.into(),
        fragment: "#version 330 core\nvoid main() { undeclared = 1.0; }\n".into(),
        samplers: Vec::new(),
    });
    let err = p
        .execute(&ctx, &[Command::UseProgram(Some(bad))])
        .unwrap_err();
    let text = err.to_string();
    assert!(
        text.contains("Fragment") && text.contains("test/bad") && text.contains("undeclared"),
        "{text}"
    );
    p.release(&ctx);
}

#[test]
fn the_native_pipeline_refuses_programs_by_name() {
    let ctx = context(support::HEADLESS[0], Profile::Compatibility);
    let _t = target(&ctx, 4, 4, DepthBits::D24, false);
    let mut p = NativePipeline::new(&ctx).expect("native pipeline");
    let err = p
        .execute(
            &ctx,
            &[
                Command::Enable(Capability::DepthTest),
                Command::UseProgram(Some(program())),
            ],
        )
        .unwrap_err();
    assert!(matches!(err, PipelineError::ShaderPrograms), "{err}");
    assert!(
        err.to_string().contains(
            "shader programs run on the emulate pipeline; Mesa's fixed function has none"
        ),
        "{err}"
    );
    p.release(&ctx);
}
