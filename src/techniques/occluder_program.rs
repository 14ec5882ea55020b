//! `occluder-planes` with shader programs (`[shadow] program`): Coleman's own shaders
//! (`shaders/coleman/`, run unchanged) and one program generated here for any planes. Both
//! run only on the emulated pipeline (`Command::UseProgram`); the native one refuses them.
//!
//! ```text
//! setup   per plane k: glBindTexture(2D, 80 + k); LINEAR; CLAMP_TO_BORDER (white);
//!                      glTexImage2D(LUMINANCE8, the occluder)
//! generic dim:  the fixed-function form's (shadowing light off)
//!         lit:  glDepthFunc(EQUAL); glBlendFunc(ONE, ONE); units k ← 80 + k;
//!               glUseProgram(occluder-planes/generic); the light and the planes in eye space
//!               as uniforms; draw the receivers; glUseProgram(0); the others lit
//! coleman eye:  the receivers through coleman/occluder (units 0 white, 1 ← 80, 2 ← 81),
//!               the others fixed-function, one pass
//!         mask: the same pass, then `flipped` (below) added with DepthFunc(EQUAL)
//! ```
//!
//! **The generic program** is generated from a [`GenericKey`] alone (plane count, light form,
//! output) — the predicates; the planes and the light are uniforms. It works per fragment in
//! eye space: p the fragment's eye position (interpolated from ff_modelview · vertex), L the
//! ray's direction (a directional light's direction towards it, or S − p for a point light at
//! S: the ray from the point goes towards the light's position), and per plane
//! s_I = n·(o − p) / (n·L) (equation 6), q = p + s_I·L,
//! (s, t) = (right·(q − o) / width, up·(q − o) / height) (equation 8, the appendix's sign) —
//! the math of `occluder_planes::plane_matrix`, evaluated per fragment instead of folded into
//! texgen rows. A plane is moved to eye space by M = V · M_caster: o by M, and n, up, right
//! as covectors by M₃⁻ᵀ (n_obj · x_obj = (M₃⁻ᵀ n_obj) · M₃ x_obj), so s_I, s and t are
//! exactly the object-space ones under any affine model matrix. The plane counts only
//! between the point and the light (s_I > 0, §4.1); for a point light a plane beyond the
//! light (s_I > 1) still counts, as in the fixed-function form; |n·L| < 10⁻⁶·|n|·|L| casts
//! nothing. Outside [0, 1]² the occluder's white border is read (CLAMP_TO_BORDER). Its frame
//! is the fixed-function form's: the dim pass, then the lit pass adding the shadowing
//! light's diffuse term (per vertex, GL 1.5 §2.14.1; no specular, spot cone or attenuation,
//! like the thesis's shader) × Π factors — or, in the mask look,
//! grey Π factors over the dim pass's black — with ff_modelview_projection, so the depths
//! equal the dim pass's and DepthFunc(EQUAL) holds.
//!
//! **The historical program** hard-codes the F-35's planes in its model space, so it fits
//! only that scene (an `f35` aircraft with the thesis's three planes, the only caster with
//! planes) under a directional light: its vertex shader reads light 0's position as a
//! direction (w ignored). Its uniforms are glstate's: P · V · M_f35, V · M_f35, its inverse
//! and inverse transpose, the light in eye space, the light's and the material's colours.
//! Every receiver is drawn in the F-35's model space (its vertices moved there once, by
//! M_f35⁻¹ · M_receiver), because the planes' equations take IN.position as model space.
//! The fragment shader has two occluder samplers: shadowTEX (unit 1) for the z = 0 plane,
//! shadowTEX2 (unit 2) for both fins, as in the appendix (the fins are mirror images, so
//! their silhouettes in their own (right, up) frames are one picture); colorTEX (unit 0) is
//! a white 1×1 texture. Its picture is diffuse · shadow + ambient in one pass (no specular).
//!
//! **Its mask look** keeps the shader too. With the light's diffuse 10³⁰ the vertex colour,
//! clamp(cos · 10³⁰), is 1 wherever the vertex faces the light; drawn a second time with the
//! normal matrix negated and added (glBlendFunc(ONE, ONE), DepthFunc(EQUAL): the same
//! program and uniforms give the same depths), each vertex is 1 in exactly one of the two
//! draws (cos ≠ 0), so the interpolated colours sum to 1 and the pixel is 1 · shadowPercent:
//! the fixed-function form's mask (white × Π factors, whatever the facing).

use std::sync::Arc;

use glam::{Mat3, Mat4, Vec3, Vec4};

use crate::ff::{
    self, Capability, Command, Geometry, SamplerBinding, ShaderProgram, TextureTarget, UniformValue,
};
use crate::mesh::occluder::{OccluderTexture, PASSES};
use crate::mesh::AircraftLayout;
use crate::scene::{Scene, Shape};
use crate::shaders::F35_PLANES;

use super::occluder_planes::{
    clip_commands, sectioned_dim_pass, unclip_commands, LightAt, ReceiverDraw, ScenePlane,
};
use super::parts::{does_not_receive, eye_start, lighting, objects, reset, LightSet, Look};
use super::setup::GLOBAL_AMBIENT;
use super::{Pass, Prepared};

/// The 2D texture name of plane k's occluder: `OCCLUDER_2D_BASE + k` (80 to 94 for
/// `scene::MAX_SCENE_PLANES`, below occlusion-textures' 96).
pub const OCCLUDER_2D_BASE: u32 = 80;
/// The white 1×1 texture Coleman's colorTEX reads (and an unused slot of the generic
/// program), above the fixed-function form's 3D names (64 to 78).
pub const WHITE_TEXTURE: u32 = OCCLUDER_2D_BASE - 1;

/// Below this |n·L| / (|n|·|L|) a plane is taken as parallel to the ray (the fixed-function
/// form's threshold).
const PARALLEL: f32 = 1e-6;

/// The light's diffuse colour in Coleman's mask look: clamp(cos · DIFFUSE) is 1 for any
/// cos above 10⁻³⁰ (module note).
const MASK_DIFFUSE: f32 = 1e30;

/// How the ray towards the light is formed: a predicate of the program.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RayForm {
    /// L = the direction towards the light (a uniform).
    Directional,
    /// L = S − p, S the light's position (a uniform).
    Point,
}

/// What the generic program writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Output {
    /// The shadowing light's diffuse term × Π factors (added over the dim pass).
    Lit,
    /// Π factors as grey (the mask look, over the dim pass's black).
    Mask,
}

/// Everything that shapes the generic program's code; numbers are uniforms.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct GenericKey {
    /// 1 to `ff::MAX_TEXTURE_UNITS`: plane k reads unit k.
    pub planes: u8,
    /// The user clip planes the draws enable (a sectioned receiver's cuts): the vertex
    /// stage writes gl_ClipDistance[0..clips] from `ff_clip_plane{i}`, since a program is
    /// clipped only where it writes them (GL 3.0 §2.17).
    pub clips: u8,
    pub ray: RayForm,
    pub output: Output,
}

impl GenericKey {
    pub fn of(planes: usize, clips: usize, light: LightAt, look: Look) -> GenericKey {
        GenericKey {
            planes: planes.min(ff::MAX_TEXTURE_UNITS) as u8,
            clips: clips.min(ff::MAX_CLIP_PLANES) as u8,
            ray: match light {
                LightAt::Direction(_) => RayForm::Directional,
                LightAt::Point(_) => RayForm::Point,
            },
            output: match look {
                Look::Shaded => Output::Lit,
                Look::Mask => Output::Mask,
            },
        }
    }
}

/// One uniform of plane k.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlaneField {
    Origin,
    Normal,
    Up,
    Right,
    /// (width, height).
    Size,
}

impl PlaneField {
    const ALL: [PlaneField; 5] = [
        PlaneField::Origin,
        PlaneField::Normal,
        PlaneField::Up,
        PlaneField::Right,
        PlaneField::Size,
    ];

    fn glsl_type(self) -> &'static str {
        match self {
            PlaneField::Size => "vec2",
            _ => "vec3",
        }
    }

    fn suffix(self) -> &'static str {
        match self {
            PlaneField::Origin => "origin",
            PlaneField::Normal => "normal",
            PlaneField::Up => "up",
            PlaneField::Right => "right",
            PlaneField::Size => "size",
        }
    }
}

/// The GLSL name of plane k's `field`: the generator declares it, the plan sets it.
pub fn plane_uniform(k: usize, field: PlaneField) -> String {
    format!("plane{k}_{}", field.suffix())
}

/// The sampler of plane k's occluder (unit k).
pub fn occluder_sampler(k: usize) -> String {
    format!("occluder{k}")
}

/// The uniform holding the light: towards it (directional) or its position, eye space.
pub const LIGHT_UNIFORM: &str = "u_light";

/// The generic program of `key`.
pub fn generate(key: &GenericKey) -> ShaderProgram {
    ShaderProgram {
        name: "occluder-planes/generic".into(),
        vertex: emit_vertex(key),
        fragment: emit_fragment(key),
        samplers: (0..usize::from(key.planes))
            .map(|k| SamplerBinding {
                name: occluder_sampler(k),
                unit: k as u8,
            })
            .collect(),
    }
}

fn header(key: &GenericKey) -> String {
    format!(
        "#version 330 core\n// occluder-planes, generic: {} plane(s), {:?} light, {:?} output \
         (generated by techniques::occluder_program)\n",
        key.planes, key.ray, key.output
    )
}

/// The vertex stage: the eye position for the fragment, the clip position from
/// ff_modelview_projection (the dim pass's depths), and for `Lit` GL's diffuse term per
/// vertex: max(n·l, 0) · d_material · d_light (GL 1.5 §2.14.1, l the unit vector to the light).
fn emit_vertex(key: &GenericKey) -> String {
    let mut s = header(key);
    s.push_str("layout(location = 0) in vec4 a_position;\n");
    s.push_str("uniform mat4 ff_modelview;\nuniform mat4 ff_modelview_projection;\n");
    s.push_str("out vec3 v_eye;\n");
    for i in 0..key.clips {
        s.push_str(&format!("uniform vec4 ff_clip_plane{i};\n"));
    }
    let lit = key.output == Output::Lit;
    if lit {
        s.push_str(
            "layout(location = 1) in vec3 a_normal;\nuniform mat3 ff_normal_matrix;\n\
             uniform vec4 ff_light0_diffuse;\nuniform vec4 ff_front_diffuse;\n",
        );
        s.push_str(&format!(
            "uniform vec3 {LIGHT_UNIFORM};\nout vec4 v_colour;\n"
        ));
    }
    s.push_str(
        "void main()\n{\n    vec4 eye = ff_modelview * a_position;\n    v_eye = eye.xyz / eye.w;\n\
         \x20   gl_Position = ff_modelview_projection * a_position;\n",
    );
    for i in 0..key.clips {
        // User clip plane i (GL 1.5 §2.12): kept where p′·x_eye ≥ 0, p′ the eye plane.
        s.push_str(&format!(
            "    gl_ClipDistance[{i}] = dot(ff_clip_plane{i}, eye);\n"
        ));
    }
    if lit {
        s.push_str(&format!(
            "    vec3 n = normalize(ff_normal_matrix * a_normal);\n\
             \x20   vec3 l = normalize({});\n\
             \x20   v_colour = vec4(max(dot(n, l), 0.0) * ff_front_diffuse.rgb * ff_light0_diffuse.rgb,\n\
             \x20                   ff_front_diffuse.a);\n",
            ray(key.ray, "v_eye")
        ));
    }
    s.push_str("}\n");
    s
}

/// The ray's direction from eye point `p`, as GLSL.
fn ray(form: RayForm, p: &str) -> String {
    match form {
        RayForm::Directional => LIGHT_UNIFORM.to_string(),
        RayForm::Point => format!("{LIGHT_UNIFORM} - {p}"),
    }
}

/// The fragment stage: the planes' uniforms and samplers, the factor function, the product.
fn emit_fragment(key: &GenericKey) -> String {
    let mut s = header(key);
    s.push_str("in vec3 v_eye;\n");
    if key.output == Output::Lit {
        s.push_str("in vec4 v_colour;\n");
    }
    s.push_str(&format!(
        "uniform vec3 {LIGHT_UNIFORM};\nlayout(location = 0) out vec4 frag_color;\n"
    ));
    for k in 0..usize::from(key.planes) {
        s.push_str(&emit_plane_uniforms(k));
    }
    s.push_str(&emit_factor_function());
    s.push_str(&format!(
        "void main()\n{{\n    vec3 L = {};\n    float shadow = 1.0;\n",
        ray(key.ray, "v_eye")
    ));
    for k in 0..usize::from(key.planes) {
        s.push_str(&emit_plane_factor(k));
    }
    s.push_str(match key.output {
        Output::Lit => "    frag_color = vec4(v_colour.rgb * shadow, v_colour.a);\n}\n",
        Output::Mask => "    frag_color = vec4(vec3(shadow), 1.0);\n}\n",
    });
    s
}

/// Plane k's five uniforms and its sampler.
fn emit_plane_uniforms(k: usize) -> String {
    let mut s: String = PlaneField::ALL
        .iter()
        .map(|&f| format!("uniform {} {};\n", f.glsl_type(), plane_uniform(k, f)))
        .collect();
    s.push_str(&format!("uniform sampler2D {};\n", occluder_sampler(k)));
    s
}

/// `occluder_factor`: the factor one plane puts on the light at eye point p (module note).
fn emit_factor_function() -> String {
    format!(
        "// s_I = n·(o − p) / (n·L) (equation 6); q = p + s_I·L; (s, t) = (right·(q − o) / width,\n\
         // up·(q − o) / height) (equation 8). Between the point and the light iff s_I > 0 (§4.1);\n\
         // parallel to the ray (|n·L| < {PARALLEL:e}·|n||L|) it casts nothing; outside [0, 1]² the\n\
         // white border reads 1.\n\
         float occluder_factor(sampler2D occluder, vec3 p, vec3 L, vec3 o, vec3 n, vec3 up,\n\
         \x20                     vec3 right, vec2 size)\n\
         {{\n\
         \x20   float nl = dot(n, L);\n\
         \x20   if (abs(nl) < {PARALLEL:e} * length(n) * length(L)) return 1.0;\n\
         \x20   float s_i = dot(n, o - p) / nl;\n\
         \x20   if (!(s_i > 0.0)) return 1.0;\n\
         \x20   vec3 d = p + s_i * L - o;\n\
         \x20   return texture(occluder, vec2(dot(right, d) / size.x, dot(up, d) / size.y)).r;\n\
         }}\n"
    )
}

/// `shadow *= occluder_factor(…)` for plane k.
fn emit_plane_factor(k: usize) -> String {
    let u = |f| plane_uniform(k, f);
    format!(
        "    shadow *= occluder_factor({}, v_eye, L, {}, {}, {}, {}, {});\n",
        occluder_sampler(k),
        u(PlaneField::Origin),
        u(PlaneField::Normal),
        u(PlaneField::Up),
        u(PlaneField::Right),
        u(PlaneField::Size)
    )
}

fn uniform(name: &str, value: UniformValue) -> Command {
    Command::Uniform {
        name: Arc::from(name),
        value,
    }
}

/// The 2D texture of an occluder: LUMINANCE8, LINEAR, CLAMP_TO_BORDER with a white border
/// (outside the plane's rectangle nothing occludes).
pub fn texture_2d_commands(name: u32, texture: &OccluderTexture) -> Vec<Command> {
    super::occluder_planes::luminance_texture(
        TextureTarget::Texture2D,
        name,
        texture,
        1,
        texture.texels.clone(),
    )
}

/// The setup of the program forms: plane k's occluder as 2D texture 80 + k, and the white
/// texture for Coleman's colorTEX.
pub fn setup(planes: &[ScenePlane]) -> Vec<Command> {
    let mut commands = Vec::new();
    for (k, p) in planes.iter().enumerate() {
        commands.extend(texture_2d_commands(
            OCCLUDER_2D_BASE + k as u32,
            &p.plane.texture,
        ));
    }
    let white = OccluderTexture {
        width: 1,
        height: 1,
        texels: vec![PASSES],
    };
    commands.extend(texture_2d_commands(WHITE_TEXTURE, &white));
    commands
}

/// glActiveTexture(unit); glBindTexture(2D, name) for each pair, unit 0 left active.
fn bind_2d(pairs: &[(u8, u32)]) -> Vec<Command> {
    let mut commands = Vec::new();
    for &(unit, name) in pairs {
        commands.extend([
            Command::ActiveTexture(unit),
            Command::BindTexture {
                target: TextureTarget::Texture2D,
                name,
            },
        ]);
    }
    commands.push(Command::ActiveTexture(0));
    commands
}

/// The camera's projection as glFrustum/glOrtho builds it after glLoadIdentity (the same
/// f32 product the fixed-function state holds).
fn projection(scene: &Scene) -> Mat4 {
    let aspect = scene.image.width as f32 / scene.image.height.max(1) as f32;
    let volume = match super::setup::view_volume(scene.camera.projection, aspect) {
        Command::Frustum(v) => ff::matrix::frustum(v),
        Command::Ortho(v) => ff::matrix::ortho(v),
        // view_volume returns Frustum or Ortho only.
        _ => Ok(Mat4::IDENTITY),
    };
    // A scene's volume is validated (near < far, fovy in range): the matrix exists.
    Mat4::IDENTITY * volume.unwrap_or(Mat4::IDENTITY)
}

/// The light in eye space: towards it (directional, w = 0) or its position (w = 1).
fn eye_light(scene: &Scene, light: LightAt) -> Vec4 {
    let view = scene.camera.view();
    match light {
        LightAt::Direction(d) => view * d.normalize_or_zero().extend(0.0),
        LightAt::Point(p) => view * p.extend(1.0),
    }
}

/// Plane `p` in eye space as the generic program's uniforms (module note: o by M, the
/// axes as covectors by M₃⁻ᵀ, M = V · M_caster).
pub fn plane_uniforms(scene: &Scene, k: usize, p: &ScenePlane) -> Vec<Command> {
    let m = scene.camera.view() * scene.objects[p.caster].transform.matrix();
    let covector = Mat3::from_mat4(m).inverse().transpose();
    let f = &p.plane.frame;
    let value = |field| match field {
        PlaneField::Origin => UniformValue::Vec3(m.transform_point3(f.origin)),
        PlaneField::Normal => UniformValue::Vec3(covector * f.normal),
        PlaneField::Up => UniformValue::Vec3(covector * f.up),
        PlaneField::Right => UniformValue::Vec3(covector * f.right),
        PlaneField::Size => UniformValue::Vec2(glam::Vec2::new(f.width, f.height)),
    };
    PlaneField::ALL
        .iter()
        .map(|&field| uniform(&plane_uniform(k, field), value(field)))
        .collect()
}

/// The generic form's eye passes: the fixed-function form's dim pass, then the lit pass
/// through the generated program (module note).
pub fn generic_passes(
    scene: &Scene,
    prepared: &Prepared,
    planes: &[ScenePlane],
    draws: &[ReceiverDraw],
    light: LightAt,
    look: Look,
) -> Vec<Pass> {
    let used = draws.iter().map(|d| d.planes.len()).max().unwrap_or(0);
    let clips = draws.iter().map(|d| d.clips.len()).max().unwrap_or(0);
    let key = GenericKey::of(used.max(1), clips, light, look);
    let mut lit = vec![
        Command::DepthFunc(ff::CompareFunc::Equal),
        Command::DepthMask(false),
        Command::Enable(Capability::Blend),
        Command::BlendFunc {
            src: ff::BlendFactor::One,
            dst: ff::BlendFactor::One,
        },
    ];
    lit.extend(lighting(scene, look, LightSet::ShadowingOnly));
    lit.push(Command::UseProgram(Some(Arc::new(generate(&key)))));
    lit.push(uniform(
        LIGHT_UNIFORM,
        UniformValue::Vec3(eye_light(scene, light).truncate()),
    ));
    let paint = look.paint(true);
    let slots = usize::from(key.planes);
    for draw in draws {
        // Slot u reads plane draw.planes[u]; a slot the draw does not use reads the white
        // texture (factor 1) with any plane's uniforms.
        let units: Vec<(u8, u32)> = (0..slots)
            .map(|u| {
                let name = draw
                    .planes
                    .get(u)
                    .map_or(WHITE_TEXTURE, |&k| OCCLUDER_2D_BASE + k as u32);
                (u as u8, name)
            })
            .collect();
        lit.extend(bind_2d(&units));
        for u in 0..slots {
            let k = draw
                .planes
                .get(u)
                .or(draw.planes.first())
                .copied()
                .unwrap_or(0);
            if let Some(p) = planes.get(k) {
                lit.extend(plane_uniforms(scene, u, p));
            }
        }
        let object = &scene.objects[draw.receiver];
        lit.extend(clip_commands(object.transform.matrix(), &draw.clips));
        lit.extend(objects(scene, prepared, |o| std::ptr::eq(o, object), paint));
        lit.extend(unclip_commands(&draw.clips));
    }
    lit.push(Command::UseProgram(None));
    lit.extend(objects(scene, prepared, does_not_receive, paint));
    let used: Vec<u8> = (0..slots as u8).collect();
    lit.extend(reset(&used));
    vec![
        sectioned_dim_pass(scene, prepared, look, draws),
        Pass {
            name: "lit",
            commands: lit,
        },
    ]
}

/// Why Coleman's shaders do not fit a scene.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ColemanMisfit {
    #[error("the shadow planes belong to {count} casters, and the shaders hold one aircraft's")]
    ManyCasters { count: usize },
    #[error(
        "the object with shadow planes ({object}) is not `shape = \"aircraft\", layout = \"f35\"`"
    )]
    NotTheF35 { object: String },
    #[error("the F-35's planes are not the thesis's three (declared `[[object.plane]]` tables replace them)")]
    OtherPlanes,
    #[error("the aircraft is cut into `[[object.section]]`s, and the shaders draw it whole")]
    Sectioned,
    #[error("the shadowing light is a {found} light, and the vertex shader reads light 0's position as a direction (w ignored)")]
    NotDirectional { found: &'static str },
}

/// The scene as Coleman's shaders see it: the F-35's object index and the direction
/// towards the light (world space).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ColemanFit {
    pub aircraft: usize,
    pub towards: Vec3,
}

/// Whether the historical shaders fit: one caster with planes, the `f35` aircraft with the
/// thesis's three planes, a directional light.
pub fn coleman_fit(
    scene: &Scene,
    planes: &[ScenePlane],
    light: LightAt,
) -> Result<ColemanFit, ColemanMisfit> {
    // `planes` is in scene order, a caster's planes together: dedup leaves each caster once.
    let mut casters: Vec<usize> = planes.iter().map(|p| p.caster).collect();
    casters.dedup();
    let aircraft = match casters[..] {
        [one] => one,
        _ => {
            return Err(ColemanMisfit::ManyCasters {
                count: casters.len(),
            })
        }
    };
    let object = &scene.objects[aircraft];
    if !matches!(
        object.shape,
        Shape::Aircraft {
            layout: AircraftLayout::F35
        }
    ) {
        let name = object.name.clone();
        return Err(ColemanMisfit::NotTheF35 {
            object: name.unwrap_or_else(|| format!("object {aircraft}")),
        });
    }
    if !thesis_planes(planes) {
        return Err(ColemanMisfit::OtherPlanes);
    }
    let sectioned =
        |p: &&crate::scene::ObjectPlanes| p.object == aircraft && !p.sections.is_empty();
    if scene.shadow.planes.iter().any(|p| sectioned(&p)) {
        return Err(ColemanMisfit::Sectioned);
    }
    match light {
        LightAt::Direction(towards) => Ok(ColemanFit { aircraft, towards }),
        LightAt::Point(_) => Err(ColemanMisfit::NotDirectional {
            found: scene
                .lights
                .first()
                .map_or("point", |l| light_kind_name(l.kind)),
        }),
    }
}

fn light_kind_name(kind: crate::scene::LightKind) -> &'static str {
    use crate::scene::LightKind;
    match kind {
        LightKind::Point => "point",
        LightKind::Spot { .. } => "spot",
        LightKind::Area { .. } => "area",
        LightKind::Directional { .. } => "directional",
    }
}

/// Whether `planes` are F35_PLANES, in order (to 10⁻⁵: the scene normalises the axes).
fn thesis_planes(planes: &[ScenePlane]) -> bool {
    let close = |a: Vec3, b: Vec3| (a - b).abs().max_element() < 1e-5;
    planes.len() == F35_PLANES.len()
        && planes.iter().zip(&F35_PLANES).all(|(p, t)| {
            let f = &p.plane.frame;
            close(f.origin, t.origin)
                && close(f.normal, t.normal)
                && close(f.up, t.up)
                && close(f.right, t.right)
                && (f.width - t.width).abs() < 1e-5
                && (f.height - t.height).abs() < 1e-5
        })
}

/// `coleman/occluder`: the two historical files unchanged, the samplers on units 0-2.
pub fn coleman_program() -> ShaderProgram {
    let source = |name| crate::shaders::find(name).map_or("", |s| s.source);
    let sampler = |name: &str, unit| SamplerBinding {
        name: name.into(),
        unit,
    };
    ShaderProgram {
        name: "coleman/occluder".into(),
        vertex: source("coleman/occluder.vert").into(),
        fragment: source("coleman/occluder.frag").into(),
        samplers: vec![
            sampler("colorTEX", 0),
            sampler(F35_PLANES[0].occluder, 1),
            sampler(F35_PLANES[1].occluder, 2),
        ],
    }
}

/// Every receiver's geometry in the aircraft's model space: its own for the aircraft, the
/// others moved by A = M_aircraft⁻¹ · M_receiver (p' = A p, n' = normalize(A₃⁻ᵀ n)).
pub fn receivers_in_aircraft_space(
    scene: &Scene,
    prepared: &Prepared,
    aircraft: usize,
) -> Vec<(usize, Arc<Geometry>)> {
    let inverse = scene.objects[aircraft].transform.matrix().inverse();
    scene
        .objects
        .iter()
        .zip(&prepared.objects)
        .enumerate()
        .filter(|(_, (o, _))| o.receives)
        .map(|(i, (o, g))| {
            if i == aircraft {
                return (i, g.clone());
            }
            let a = inverse * o.transform.matrix();
            let normal_matrix = Mat3::from_mat4(a).inverse().transpose();
            let mut moved = (**g).clone();
            moved.positions = g.positions.iter().map(|&p| a * p).collect();
            moved.normals = g.normals.as_ref().map(|ns| {
                ns.iter()
                    .map(|&n| (normal_matrix * n).normalize_or_zero())
                    .collect()
            });
            (i, Arc::new(moved))
        })
        .collect()
}

/// glstate's matrices for the aircraft's model space, the normal matrix times `sign`.
fn coleman_matrices(scene: &Scene, aircraft: usize, sign: f32) -> Vec<Command> {
    let modelview = scene.camera.view() * scene.objects[aircraft].transform.matrix();
    let inverse = modelview.inverse();
    vec![
        uniform(
            "u_modelview_projection",
            UniformValue::Mat4(projection(scene) * modelview),
        ),
        uniform("u_modelview", UniformValue::Mat4(modelview)),
        uniform("u_modelview_inverse", UniformValue::Mat4(inverse)),
        uniform(
            "u_modelview_inverse_transpose",
            UniformValue::Mat4(inverse.transpose() * sign),
        ),
    ]
}

/// glstate's light: position in eye space; diffuse and ambient for `look` (module note).
fn coleman_light(scene: &Scene, fit: &ColemanFit, look: Look) -> Vec<Command> {
    let position = eye_light(scene, LightAt::Direction(fit.towards));
    let (diffuse, ambient) = match (look, scene.lights.first()) {
        (Look::Shaded, Some(l)) => (
            (l.colour * l.intensity).extend(1.0),
            Vec3::splat(GLOBAL_AMBIENT).extend(1.0),
        ),
        _ => (Vec4::splat(MASK_DIFFUSE), Vec4::ZERO),
    };
    vec![
        uniform("u_light_position", UniformValue::Vec4(position)),
        uniform("u_light_diffuse", UniformValue::Vec4(diffuse)),
        uniform("u_light_ambient", UniformValue::Vec4(ambient)),
    ]
}

/// One draw per receiver with its material (the mask look: white).
fn coleman_draws(scene: &Scene, receivers: &[(usize, Arc<Geometry>)], look: Look) -> Vec<Command> {
    let mut commands = Vec::new();
    for (i, geometry) in receivers {
        let colour = match look {
            Look::Shaded => scene.objects[*i].material.colour.extend(1.0),
            Look::Mask => Vec4::ONE,
        };
        commands.extend([
            uniform("u_material_ambient", UniformValue::Vec4(colour)),
            uniform("u_material_diffuse", UniformValue::Vec4(colour)),
            Command::Draw(geometry.clone()),
        ]);
    }
    commands
}

/// The program's part of a pass: bind, use, glstate, draw, back to fixed function.
fn coleman_program_commands(
    scene: &Scene,
    fit: &ColemanFit,
    receivers: &[(usize, Arc<Geometry>)],
    look: Look,
    sign: f32,
) -> Vec<Command> {
    let mut commands = bind_2d(&[
        (0, WHITE_TEXTURE),
        (1, OCCLUDER_2D_BASE),
        (2, OCCLUDER_2D_BASE + 1),
    ]);
    // COLOR0 of the appendix's appin: glColor, white.
    commands.push(Command::Color(Vec4::ONE));
    commands.push(Command::UseProgram(Some(Arc::new(coleman_program()))));
    commands.extend(coleman_matrices(scene, fit.aircraft, sign));
    commands.extend(coleman_light(scene, fit, look));
    commands.extend(coleman_draws(scene, receivers, look));
    commands.push(Command::UseProgram(None));
    commands
}

/// The Coleman form's eye passes (module note): one pass; in the mask look a second,
/// `flipped`, added over it.
pub fn coleman_passes(
    scene: &Scene,
    prepared: &Prepared,
    fit: &ColemanFit,
    look: Look,
) -> Vec<Pass> {
    let receivers = receivers_in_aircraft_space(scene, prepared, fit.aircraft);
    let mut eye = eye_start(scene, look, false);
    eye.extend(lighting(scene, look, LightSet::All));
    eye.extend(objects(scene, prepared, does_not_receive, look.paint(true)));
    eye.extend(coleman_program_commands(scene, fit, &receivers, look, 1.0));
    eye.extend(reset(&[0, 1, 2]));
    let mut passes = vec![Pass {
        name: "eye",
        commands: eye,
    }];
    if look == Look::Mask {
        let mut flipped = vec![
            Command::DepthFunc(ff::CompareFunc::Equal),
            Command::DepthMask(false),
            Command::Enable(Capability::Blend),
            Command::BlendFunc {
                src: ff::BlendFactor::One,
                dst: ff::BlendFactor::One,
            },
        ];
        flipped.extend(coleman_program_commands(scene, fit, &receivers, look, -1.0));
        flipped.extend(reset(&[0, 1, 2]));
        passes.push(Pass {
            name: "flipped",
            commands: flipped,
        });
    }
    passes
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::techniques::occluder_planes::{plane_matrix, scene_planes, world_light};
    use std::path::Path;

    fn f35() -> Scene {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/f35.toml");
        Scene::load(&path).unwrap()
    }

    /// The generator's formula, evaluated on the CPU in eye space with the uniforms the
    /// plan sends, gives the fixed-function form's (s, t) and side for the same point.
    #[test]
    fn eye_space_uniforms_give_the_texgen_rows_coordinates() {
        let scene = f35();
        let planes = scene_planes(&scene).unwrap();
        let light = world_light(&scene).unwrap();
        let view = scene.camera.view();
        let l_eye = eye_light(&scene, light).truncate();
        for (k, p) in planes.iter().enumerate() {
            let model = scene.objects[p.caster].transform.matrix();
            let rows = plane_matrix(
                &p.plane.frame,
                super::super::occluder_planes::light_in(light, model),
            );
            let u = plane_uniforms(&scene, k, p);
            let get =
                |f: PlaneField| match &u[PlaneField::ALL.iter().position(|&g| g == f).unwrap()] {
                    Command::Uniform {
                        value: UniformValue::Vec3(v),
                        ..
                    } => *v,
                    Command::Uniform {
                        value: UniformValue::Vec2(v),
                        ..
                    } => v.extend(0.0),
                    other => panic!("{other:?}"),
                };
            let (o, n, up, right, size) = (
                get(PlaneField::Origin),
                get(PlaneField::Normal),
                get(PlaneField::Up),
                get(PlaneField::Right),
                get(PlaneField::Size),
            );
            for x in [
                Vec3::new(0.5, 3.0, -0.4),
                Vec3::new(-1.0, 4.5, 2.0),
                Vec3::new(3.0, 0.0, 1.0),
            ] {
                let p_eye = view.transform_point3(x);
                let s_i = n.dot(o - p_eye) / n.dot(l_eye);
                let d = p_eye + s_i * l_eye - o;
                let st = glam::Vec2::new(right.dot(d) / size.x, up.dot(d) / size.y);
                let h = rows * model.inverse() * x.extend(1.0);
                assert!(
                    (st - glam::Vec2::new(h.x, h.y)).abs().max_element() < 1e-3,
                    "{k} {x}"
                );
                assert_eq!(s_i > 0.0, h.z > 0.5, "{k} {x}");
            }
        }
    }

    /// shadowTEX2 serves both fins (the appendix's choice): their generated silhouettes,
    /// each in its own (right, up) frame, are one picture (measured: all 65 536 texels equal).
    #[test]
    fn the_two_fins_occluders_are_one_picture() {
        let scene = f35();
        let planes = scene_planes(&scene).unwrap();
        let (right, left) = (&planes[1].plane.texture, &planes[2].plane.texture);
        let differ = right
            .texels
            .iter()
            .zip(&left.texels)
            .filter(|(a, b)| a != b)
            .count();
        assert!(right.black_count() > 500);
        assert_eq!(differ, 0, "texels differ");
    }

    /// Every pass of both forms, mask included, ends in fixed function (glUseProgram(0)).
    #[test]
    fn no_pass_leaves_a_program_in_use() {
        use crate::scene::OccluderProgram;
        for form in [OccluderProgram::Coleman, OccluderProgram::Generic] {
            let mut scene = f35();
            scene.shadow.occluder_program = form;
            let plan =
                super::super::occluder_planes::plan(&scene, &Prepared::new(&scene)).expect("plans");
            let mask = Pass {
                name: "mask",
                commands: plan.mask.commands.clone(),
            };
            let mut programs = 0;
            for pass in plan.passes.iter().chain([&mask]) {
                let last = pass
                    .commands
                    .iter()
                    .rev()
                    .find(|c| matches!(c, Command::UseProgram(_)));
                programs += usize::from(last.is_some());
                assert!(
                    last.is_none() || last == Some(&Command::UseProgram(None)),
                    "{form:?} {}",
                    pass.name
                );
            }
            assert!(
                programs >= 2,
                "{form:?}: the picture and the mask use the program"
            );
        }
    }

    #[test]
    fn the_key_shapes_the_code() {
        let key = GenericKey {
            planes: 3,
            clips: 0,
            ray: RayForm::Point,
            output: Output::Mask,
        };
        let p = generate(&key);
        assert!(p.vertex.starts_with("#version 330 core\n"));
        assert!(p.fragment.contains("vec3 L = u_light - v_eye;"));
        assert!(p.fragment.contains("uniform sampler2D occluder2;"));
        assert!(!p.fragment.contains("occluder3"));
        assert!(!p.vertex.contains("a_normal"), "the mask needs no lighting");
        assert_eq!(p.samplers.len(), 3);
        let lit = generate(&GenericKey {
            ray: RayForm::Directional,
            output: Output::Lit,
            ..key
        });
        assert!(lit.fragment.contains("vec3 L = u_light;"));
        assert!(lit.vertex.contains("ff_normal_matrix"));
        assert!(!lit.vertex.contains("gl_ClipDistance"));
        let cut = generate(&GenericKey { clips: 2, ..key });
        assert!(cut
            .vertex
            .contains("gl_ClipDistance[1] = dot(ff_clip_plane1, eye);"));
        assert!(!cut.vertex.contains("gl_ClipDistance[2]"));
    }

    #[test]
    fn coleman_fits_the_f35_only() {
        let scene = f35();
        let planes = scene_planes(&scene).unwrap();
        let light = world_light(&scene).unwrap();
        assert!(coleman_fit(&scene, &planes, light).is_ok());
        assert!(matches!(
            coleman_fit(&scene, &planes, LightAt::Point(Vec3::Y)),
            Err(ColemanMisfit::NotDirectional { .. })
        ));
        assert_eq!(
            coleman_fit(&scene, &planes[..2], light),
            Err(ColemanMisfit::OtherPlanes)
        );
    }
}
