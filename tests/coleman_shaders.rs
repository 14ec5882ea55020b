//! Coleman's occluder-texture shaders (`shaders/coleman/`) on a real core 3.3 context (EGL,
//! llvmpipe): both stages compile and link, and a receiver quad drawn through the program
//! with synthetic 8×8 occluder textures matches a CPU model of the appendix's math pixel
//! for pixel.
//!
//! The CPU model takes the plane geometry from `fixedfunc::shaders::ShadowPlane::shadow_coord`
//! (equations 6 and 8) and mirrors the rest of the shaders: saturate, a NEAREST look-up under the wrap
//! mode in force, the sign test, the product of the three factors, the lit colour with the
//! unnormalised eye-space light and the COLOR0 clamp, plus the ambient term. Tolerance:
//! 2/255 per channel and no pixel beyond it, after leaving out the pixels whose result
//! hangs on rounding (a look-up within 1/1000 of a texel of a texel edge, or s_I within
//! 1e-3 of 0); the test fails if those exceed 5% of the image.

mod support;

use fixedfunc::ff::{matrix, matrix_ops, ViewVolume};
use fixedfunc::gpu::{Backend, GpuContext, Profile};
use fixedfunc::shaders::{self, Stage, F35_PLANES};
use fixedfunc::vocab::DepthBits;
use glam::{Mat3, Mat4, Vec3, Vec4};
use glow::HasContext;
use image::{Rgba, RgbaImage};
use support::{assert_images_match, assert_no_gl_error, context, probe, target, Tolerance};

const W: u32 = 128;
const H: u32 = 64;
/// Occluder textures are N × N.
const N: usize = 8;
/// Skip a pixel whose look-up lies this close to a texel edge, in texels.
const EDGE_MARGIN: f32 = 1e-3;
/// Skip a pixel whose s_I lies this close to 0.
const SIGN_MARGIN: f32 = 1e-3;

/// The receiver: a quad in the model-space plane y = RECEIVER_Y, facing −y (the camera).
const RECEIVER_Y: f32 = -1.5;
const RECEIVER_NORMAL: Vec3 = Vec3::NEG_Y;
const RECEIVER_COLOR: Vec4 = Vec4::new(1.0, 0.9, 0.8, 0.75);
/// The model-space direction toward the light, deliberately not of unit length: GL keeps a
/// directional light's position as given, and the appendix's diffuse term uses it as is.
const LIGHT_MODEL: Vec3 = Vec3::new(1.0, -0.5, 0.6);
/// Red above 1: the COLOR0 clamp decides the lit red channel.
const LIGHT_DIFFUSE: Vec4 = Vec4::new(3.0, 1.0, 0.6, 1.0);
const LIGHT_AMBIENT: Vec4 = Vec4::new(0.2, 0.2, 0.2, 1.0);
const MATERIAL_DIFFUSE: Vec4 = Vec4::new(0.9, 0.8, 0.7, 1.0);
const MATERIAL_AMBIENT: Vec4 = Vec4::new(1.0, 0.8, 0.6, 1.0);
/// colorTEX, one texel.
const BASE_TEXEL: [u8; 4] = [128, 255, 204, 255];

/// The camera, as glRotatef/glTranslatef would set it: the receiver seen from 10 m along
/// −y, rolled 15° and shifted, so that neither the rotation nor the translation of the
/// modelview is trivial.
fn modelview() -> Mat4 {
    let turn = |deg, axis| matrix_ops::rotation(deg, axis).expect("a rotation");
    matrix_ops::translate(
        turn(15.0, Vec3::Z) * turn(-90.0, Vec3::X),
        Vec3::new(-0.3, 10.0, -0.2),
    )
}

/// glOrtho(−6, 6, −3, 3, 1, 20).
fn projection() -> Mat4 {
    let volume = ViewVolume {
        left: -6.0,
        right: 6.0,
        bottom: -3.0,
        top: 3.0,
        near: 1.0,
        far: 20.0,
    };
    matrix::ortho(volume).expect("a valid volume")
}

/// Occluder "A" (the z = 0 plane, shadowTEX): column 3 black, columns 2 and 5 half grey.
fn occluder_a() -> Vec<u8> {
    (0..N * N)
        .map(|i| match i % N {
            3 => 0,
            2 | 5 => 128,
            _ => 255,
        })
        .collect()
}

/// Occluder "B" (both fins, shadowTEX2; row 0 is t = 0): in columns 2-7 a fin, half grey
/// in rows 1-2, black in rows 3-5, half grey in row 6 (columns 3-7); row 7 white; row 0
/// black across (the root extended into the body, as the thesis's §5 advises).
fn occluder_b() -> Vec<u8> {
    (0..N * N)
        .map(|i| match (i % N, i / N) {
            (_, 0) => 0,
            (c, r) if r <= 2 && c >= 2 => 128,
            (c, r) if r <= 5 && c >= 2 => 0,
            (c, 6) if c >= 3 => 128,
            _ => 255,
        })
        .collect()
}

/// The texture wrap mode the occluders are sampled with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Wrap {
    /// GL's default, which the thesis kept (Appendix B, lines 742-744).
    Repeat,
    ClampToEdge,
}

impl Wrap {
    fn gl(self) -> i32 {
        match self {
            Wrap::Repeat => glow::REPEAT as i32,
            Wrap::ClampToEdge => glow::CLAMP_TO_EDGE as i32,
        }
    }

    /// The texel index NEAREST selects for coordinate `c`: wrap(⌊c·N⌋) (GL 3.3 §3.8.11),
    /// REPEAT taking it modulo N, CLAMP_TO_EDGE clamping it to [0, N − 1].
    fn texel(self, c: f32) -> usize {
        let i = (c * N as f32).floor() as i64;
        match self {
            Wrap::Repeat => i.rem_euclid(N as i64) as usize,
            Wrap::ClampToEdge => i.clamp(0, N as i64 - 1) as usize,
        }
    }
}

fn sample(texels: &[u8], wrap: Wrap, s: f32, t: f32) -> f32 {
    f32::from(texels[wrap.texel(t) * N + wrap.texel(s)]) / 255.0
}

/// What the model predicts at one pixel.
#[derive(Clone, Copy, Debug)]
struct Prediction {
    rgba: [u8; 4],
    /// Rounding could flip a look-up or a sign test: the pixel is not compared.
    ambiguous: bool,
    /// Each plane's shadowPercent, in the order of F35_PLANES.
    factor: [f32; 3],
    /// Each plane's look-up after saturate, whether or not the sign test uses it.
    looked_up: [f32; 3],
    /// Each plane's look-up without saturate (the raw coordinate under the wrap mode).
    unsaturated: [f32; 3],
    /// Each plane lies between the point and the light.
    between: [bool; 3],
    /// Each plane's coordinate lies outside [0, 1]².
    outside: [bool; 3],
}

fn near_texel_edge(c: f32) -> bool {
    let u = c * N as f32;
    (-EDGE_MARGIN..=N as f32 + EDGE_MARGIN).contains(&u) && (u - u.round()).abs() < EDGE_MARGIN
}

fn unorm8(x: f32) -> u8 {
    (x.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// The appendix's math at model-space point `p` on the receiver.
fn predict(p: Vec3, wrap: Wrap) -> Prediction {
    let mv = modelview();
    let light_eye = mv * LIGHT_MODEL.extend(0.0); // glLightfv(GL_POSITION) stores MV · p
    let light_model = (mv.inverse() * light_eye).truncate().normalize();
    let occluders = [occluder_a(), occluder_b(), occluder_b()];
    let mut prediction = Prediction {
        rgba: [0; 4],
        ambiguous: false,
        factor: [1.0; 3],
        looked_up: [1.0; 3],
        unsaturated: [1.0; 3],
        between: [false; 3],
        outside: [false; 3],
    };
    for (k, plane) in F35_PLANES.iter().enumerate() {
        let c = plane.shadow_coord(p, light_model);
        let (s, t) = (c.st.x, c.st.y);
        let looked_up = sample(&occluders[k], wrap, s.clamp(0.0, 1.0), t.clamp(0.0, 1.0));
        prediction.looked_up[k] = looked_up;
        prediction.unsaturated[k] = sample(&occluders[k], wrap, s, t);
        prediction.between[k] = c.plane_between();
        prediction.outside[k] = !(0.0..=1.0).contains(&s) || !(0.0..=1.0).contains(&t);
        prediction.factor[k] = if c.plane_between() { looked_up } else { 1.0 };
        prediction.ambiguous |= c.s_i.abs() < SIGN_MARGIN
            || (c.plane_between() && (near_texel_edge(s) || near_texel_edge(t)));
    }
    prediction.rgba = shade(prediction.factor.iter().product());
    prediction
}

/// The receiver's colour for a product of shadow factors (its normal, colour and base
/// texel are the same everywhere).
fn shade(shadow: f32) -> [u8; 4] {
    let mv = modelview();
    let light_eye = mv * LIGHT_MODEL.extend(0.0);
    // Vertex shader: eye-space diffuse with the unnormalised light, COLOR0 clamp, ambient.
    let n_eye = (Mat3::from_mat4(mv.inverse().transpose()) * RECEIVER_NORMAL).normalize();
    let cos_ang = n_eye.dot(light_eye.truncate()).max(0.0);
    let diffuse = cos_ang * MATERIAL_DIFFUSE.truncate() * LIGHT_DIFFUSE.truncate();
    let color0 = (RECEIVER_COLOR.truncate() * diffuse)
        .extend(RECEIVER_COLOR.w)
        .clamp(Vec4::ZERO, Vec4::ONE);
    let ambient = LIGHT_AMBIENT * MATERIAL_AMBIENT;
    // Fragment shader.
    let tex = Vec4::from_array(BASE_TEXEL.map(|b| f32::from(b) / 255.0));
    let diffuse_color = color0 * tex;
    let out = diffuse_color.truncate() * shadow + tex.truncate() * ambient.truncate();
    out.extend(diffuse_color.w).to_array().map(unorm8)
}

/// The model-space point on the receiver seen at the centre of pixel (x, y), top row first.
fn receiver_point(x: u32, y: u32) -> Vec3 {
    let mvp = projection() * modelview();
    let depth = mvp.project_point3(Vec3::new(0.0, RECEIVER_Y, 0.0)).z;
    let ndc = Vec3::new(
        2.0 * (x as f32 + 0.5) / W as f32 - 1.0,
        2.0 * ((H - 1 - y) as f32 + 0.5) / H as f32 - 1.0,
        depth,
    );
    mvp.inverse().project_point3(ndc)
}

/// Compiles one stage; panics with the info log on failure.
fn compile(gl: &glow::Context, stage: Stage, name: &str, source: &str) -> glow::Shader {
    let kind = match stage {
        Stage::Vertex => glow::VERTEX_SHADER,
        Stage::Fragment => glow::FRAGMENT_SHADER,
    };
    unsafe {
        let shader = gl.create_shader(kind).expect("create shader");
        gl.shader_source(shader, source);
        gl.compile_shader(shader);
        let log = gl.get_shader_info_log(shader);
        assert!(
            gl.get_shader_compile_status(shader),
            "{name} does not compile:\n{log}"
        );
        shader
    }
}

/// Coleman's two stages, compiled and linked; panics with the info log on failure.
fn build_program(ctx: &GpuContext) -> glow::Program {
    let gl = ctx.gl();
    let stages = ["coleman/occluder.vert", "coleman/occluder.frag"]
        .map(|name| shaders::find(name).unwrap_or_else(|| panic!("{name} is embedded")));
    unsafe {
        let program = gl.create_program().expect("create program");
        for s in stages {
            let shader = compile(gl, s.stage, s.name, s.source);
            gl.attach_shader(program, shader);
            gl.delete_shader(shader);
        }
        gl.link_program(program);
        let log = gl.get_program_info_log(program);
        assert!(
            gl.get_program_link_status(program),
            "coleman/occluder does not link:\n{log}"
        );
        program
    }
}

#[test]
fn both_stages_compile_and_link_on_a_core_33_context() {
    let ctx = context(Backend::Egl, Profile::Core33);
    let gl = ctx.gl();
    let program = build_program(&ctx);
    unsafe {
        // The attributes sit where the header says: appin's order.
        for (i, name) in ["a_position", "a_normal", "a_color0", "a_texcoord0"]
            .iter()
            .enumerate()
        {
            assert_eq!(
                gl.get_attrib_location(program, name),
                Some(i as u32),
                "{name}"
            );
        }
        // Every uniform the algorithm reads is active; u_modelview, unused in the Cg too,
        // is not.
        let active: Vec<String> = (0..gl.get_active_uniforms(program))
            .filter_map(|i| gl.get_active_uniform(program, i))
            .map(|u| u.name)
            .collect();
        let mut expected = vec![
            "colorTEX",
            "shadowTEX",
            "shadowTEX2",
            "u_light_ambient",
            "u_light_diffuse",
            "u_light_position",
            "u_material_ambient",
            "u_material_diffuse",
            "u_modelview_inverse",
            "u_modelview_inverse_transpose",
            "u_modelview_projection",
        ];
        let mut active_sorted: Vec<&str> = active.iter().map(String::as_str).collect();
        active_sorted.sort_unstable();
        expected.sort_unstable();
        assert_eq!(active_sorted, expected);
        gl.delete_program(program);
    }
    assert_no_gl_error(&ctx);
}

/// A square texture of `size`² texels on `unit`, NEAREST, wrapped with `wrap`.
fn upload_texture(
    gl: &glow::Context,
    unit: u32,
    format: (u32, u32),
    size: i32,
    texels: &[u8],
    wrap: Wrap,
) -> glow::Texture {
    unsafe {
        let texture = gl.create_texture().expect("create texture");
        gl.active_texture(glow::TEXTURE0 + unit);
        gl.bind_texture(glow::TEXTURE_2D, Some(texture));
        gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(
            glow::TEXTURE_2D,
            0,
            format.0 as i32,
            size,
            size,
            0,
            format.1,
            glow::UNSIGNED_BYTE,
            glow::PixelUnpackData::Slice(Some(texels)),
        );
        for (parameter, value) in [
            (glow::TEXTURE_MIN_FILTER, glow::NEAREST as i32),
            (glow::TEXTURE_MAG_FILTER, glow::NEAREST as i32),
            (glow::TEXTURE_WRAP_S, wrap.gl()),
            (glow::TEXTURE_WRAP_T, wrap.gl()),
        ] {
            gl.tex_parameter_i32(glow::TEXTURE_2D, parameter, value);
        }
        texture
    }
}

/// Draws the receiver quad through Coleman's program, the occluders sampled with `wrap`.
fn render(ctx: &GpuContext, wrap: Wrap) -> RgbaImage {
    let gl = ctx.gl();
    let t = target(ctx, W, H, DepthBits::D24, false);
    let program = build_program(ctx);
    let mv = modelview();
    // Large enough to cover the rolled view; every vertex carries appin's four members.
    let corners = [(-8.0, -7.5), (8.5, -7.5), (8.5, 7.5), (-8.0, 7.5)];
    let vertex = |(x, z): (f32, f32)| -> Vec<f32> {
        let mut v = vec![x, RECEIVER_Y, z];
        v.extend(RECEIVER_NORMAL.to_array());
        v.extend(RECEIVER_COLOR.to_array());
        v.extend([0.5, 0.5, 0.0, 1.0]);
        v
    };
    let floats: Vec<f32> = [0, 1, 2, 0, 2, 3]
        .iter()
        .flat_map(|&i| vertex(corners[i]))
        .collect();
    let bytes: Vec<u8> = floats.iter().flat_map(|f| f.to_ne_bytes()).collect();
    unsafe {
        gl.clear_color(1.0, 0.0, 1.0, 1.0);
        gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
        let textures = [
            upload_texture(gl, 0, (glow::RGBA8, glow::RGBA), 1, &BASE_TEXEL, wrap),
            upload_texture(gl, 1, (glow::R8, glow::RED), N as i32, &occluder_a(), wrap),
            upload_texture(gl, 2, (glow::R8, glow::RED), N as i32, &occluder_b(), wrap),
        ];
        gl.use_program(Some(program));
        for (name, unit) in [("colorTEX", 0), ("shadowTEX", 1), ("shadowTEX2", 2)] {
            gl.uniform_1_i32(gl.get_uniform_location(program, name).as_ref(), unit);
        }
        // GL's column-major arrays, transpose = false: `mul(M, v)` is `M * v`.
        let inverse = mv.inverse();
        for (name, m) in [
            ("u_modelview_projection", projection() * mv),
            ("u_modelview", mv),
            ("u_modelview_inverse", inverse),
            ("u_modelview_inverse_transpose", inverse.transpose()),
        ] {
            let location = gl.get_uniform_location(program, name);
            gl.uniform_matrix_4_f32_slice(location.as_ref(), false, &m.to_cols_array());
        }
        for (name, v) in [
            ("u_light_position", mv * LIGHT_MODEL.extend(0.0)),
            ("u_light_diffuse", LIGHT_DIFFUSE),
            ("u_light_ambient", LIGHT_AMBIENT),
            ("u_material_ambient", MATERIAL_AMBIENT),
            ("u_material_diffuse", MATERIAL_DIFFUSE),
        ] {
            let location = gl.get_uniform_location(program, name);
            gl.uniform_4_f32_slice(location.as_ref(), &v.to_array());
        }
        let vao = gl.create_vertex_array().expect("vertex array");
        let vbo = gl.create_buffer().expect("buffer");
        gl.bind_vertex_array(Some(vao));
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
        gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &bytes, glow::STATIC_DRAW);
        let stride = 14 * 4;
        for (location, size, offset) in [(0, 3, 0), (1, 3, 12), (2, 4, 24), (3, 4, 40)] {
            gl.enable_vertex_attrib_array(location);
            gl.vertex_attrib_pointer_f32(location, size, glow::FLOAT, false, stride, offset);
        }
        gl.draw_arrays(glow::TRIANGLES, 0, 6);
        gl.delete_vertex_array(vao);
        gl.delete_buffer(vbo);
        gl.delete_program(program);
        for texture in textures {
            gl.delete_texture(texture);
        }
    }
    assert_no_gl_error(ctx);
    let image = t.read_color(ctx).expect("read colour");
    t.delete(ctx);
    image
}

/// What a pixel exercises; a pixel may be of several kinds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// No plane darkens it.
    Lit,
    /// One plane alone darkens it (index into F35_PLANES).
    Alone(usize),
    /// Two planes darken it only partly: their factors multiply (½ · ½ = ¼).
    Multiplied,
    /// This plane, behind the point, looks up a dark texel that the sign test ignores; lit.
    SignTestIgnores(usize),
    /// This plane's coordinate lies outside [0, 1]² and saturate changes its look-up.
    SaturateDecides(usize),
}

impl Kind {
    const ALL: [Kind; 11] = [
        Kind::Lit,
        Kind::Alone(0),
        Kind::Alone(1),
        Kind::Alone(2),
        Kind::Multiplied,
        Kind::SignTestIgnores(0),
        Kind::SignTestIgnores(1),
        Kind::SignTestIgnores(2),
        Kind::SaturateDecides(0),
        Kind::SaturateDecides(1),
        Kind::SaturateDecides(2),
    ];

    /// The kinds of a pixel. Each feature counts only where turning it off would change
    /// the pixel: the product against the smallest factor, saturate against the raw
    /// coordinate, the sign test against always using the look-up.
    fn of(p: &Prediction) -> Vec<Kind> {
        let darkening: Vec<usize> = (0..3).filter(|&k| p.factor[k] < 1.0).collect();
        let mut kinds = match darkening[..] {
            [] => vec![Kind::Lit],
            [k] => vec![Kind::Alone(k)],
            _ => Vec::new(),
        };
        let with = |k: usize, f: f32| {
            let mut factor = p.factor;
            factor[k] = f;
            shade(factor.iter().product())
        };
        let min = p.factor.iter().copied().fold(1.0, f32::min);
        if darkening.len() >= 2 && shade(min) != p.rgba {
            kinds.push(Kind::Multiplied);
        }
        for k in 0..3 {
            if !p.between[k] && with(k, p.looked_up[k]) != p.rgba {
                kinds.push(Kind::SignTestIgnores(k));
            }
            if p.between[k] && p.outside[k] && with(k, p.unsaturated[k]) != p.rgba {
                kinds.push(Kind::SaturateDecides(k));
            }
        }
        kinds
    }
}

/// The receiver through the real program against the CPU model, under the thesis's REPEAT
/// and under CLAMP_TO_EDGE. Every kind of pixel must occur (at least 10 of each, its first
/// pixel probed by name), except that saturate can decide nothing under CLAMP_TO_EDGE —
/// the thesis's "setting the texture wrap to clamp would work" (line 743). Under REPEAT, a
/// coordinate saturated to 1 reads the texture's first row or column, the far edge's
/// opposite: the scene has pixels where that shadows what CLAMP_TO_EDGE leaves lit.
#[test]
fn the_program_matches_the_cpu_model_under_repeat_and_clamp_to_edge() {
    let ctx = context(Backend::Egl, Profile::Core33);
    for wrap in [Wrap::Repeat, Wrap::ClampToEdge] {
        let actual = render(&ctx, wrap);
        let mut expected = RgbaImage::new(W, H);
        let mut ambiguous = 0;
        let mut found: Vec<(Kind, u32, u32)> = Vec::new();
        for (x, y, pixel) in expected.enumerate_pixels_mut() {
            let p = predict(receiver_point(x, y), wrap);
            if p.ambiguous {
                ambiguous += 1;
                *pixel = *actual.get_pixel(x, y); // not judged
                continue;
            }
            *pixel = Rgba(p.rgba);
            found.extend(Kind::of(&p).into_iter().map(|kind| (kind, x, y)));
        }
        assert!(
            ambiguous * 20 <= (W * H) as usize,
            "{wrap:?}: {ambiguous} pixels are too close to an edge to judge"
        );
        for kind in Kind::ALL {
            let pixels: Vec<(u32, u32)> = found
                .iter()
                .filter(|f| f.0 == kind)
                .map(|f| (f.1, f.2))
                .collect();
            if wrap == Wrap::ClampToEdge && matches!(kind, Kind::SaturateDecides(_)) {
                assert!(pixels.is_empty(), "{wrap:?}: {kind:?} at {pixels:?}");
                continue;
            }
            assert!(pixels.len() >= 10, "{wrap:?}: {kind:?} at {pixels:?}");
            let (x, y) = pixels[0];
            let want = predict(receiver_point(x, y), wrap).rgba;
            probe(&actual, x, y, want, 2);
        }
        let tolerance = Tolerance {
            per_channel: 2,
            max_bad_pixels: 0,
        };
        assert_images_match(&format!("coleman-{wrap:?}"), &actual, &expected, tolerance);
    }
    let repeat_shadows_more = (0..H)
        .flat_map(|y| (0..W).map(move |x| receiver_point(x, y)))
        .filter(|&p| {
            let (r, c) = (predict(p, Wrap::Repeat), predict(p, Wrap::ClampToEdge));
            !r.ambiguous && !c.ambiguous && r.rgba[1] < c.rgba[1]
        })
        .count();
    assert!(repeat_shadows_more >= 10, "{repeat_shadows_more} pixels");
}
