//! The vertex stage: transform (GL 1.5 §2.10), lighting (§2.14.1), texture coordinate
//! generation (§2.11.4) and the texture matrix.
//!
//! Under flat shading the colour is lit from the *shade* attributes — the position, normal and
//! colour of the provoking vertex of the primitive the vertex belongs to (`assembly`) — and
//! passed `flat`; texture coordinates still come from the vertex's own values. For the types
//! core GL draws, the shade attributes are the vertex's own and core GL's provoking vertex
//! picks the corner; for split polygons every corner carries its polygon's provoking vertex,
//! so the whole polygon has one colour whichever way it was split.

use crate::ff::{ColorMaterialMode, FogCoordSource, TexCoord, TexGenMode};
use crate::pipeline::emulate::glsl::GlslWriter;
use crate::pipeline::emulate::key::{
    ColorMaterialKey, CoordSource, FragmentKey, LightKey, LightingKey, PointKey, PointShape,
    PositionSource, VertexKey, VertexUnitKey,
};
use crate::pipeline::emulate::pixel_fan::PixelFan;
use crate::pipeline::emulate::uniforms::{ColorTerm, LightValue, MaterialValue, UniformSource};

use super::{
    material_location, ATTRIB_COLOR, ATTRIB_EDGE, ATTRIB_FOG_COORD, ATTRIB_NORMAL, ATTRIB_POSITION,
    ATTRIB_SECONDARY, ATTRIB_SHADE_NORMAL, ATTRIB_SHADE_POSITION, ATTRIB_TEXCOORD0, ATTRIB_WINDOW,
    WINDOW_SPAN,
};

pub fn generate(key: &VertexKey, fragment: &FragmentKey) -> GlslWriter {
    let mut w = GlslWriter::new();
    w.declare(&format!(
        "layout(location = {ATTRIB_POSITION}) in vec4 a_position;"
    ));
    w.declare(&format!(
        "layout(location = {ATTRIB_COLOR}) in vec4 a_color;"
    ));
    let flat = if fragment.flat { "flat " } else { "" };
    w.declare(&format!("{flat}out vec4 v_color;"));
    match key.positions {
        // One expression for every program, so DepthFunc(EQUAL) passes see identical
        // depths: P·M applied at once, as Mesa's fixed-function program does.
        PositionSource::Transformed => {
            let mvp = w.uniform(UniformSource::ModelviewProjection);
            w.line(format!("gl_Position = {mvp} * a_position;"))
        }
        // Window coordinates back through the viewport (−S, −S, 2S, 2S) and depth range
        // [0, 1]: x_c = x_w / S, z_c = 2·z_w − 1, w_c = 1.
        PositionSource::Window => {
            w.declare(&format!(
                "layout(location = {ATTRIB_WINDOW}) in vec4 a_window;"
            ));
            w.line(format!(
                "gl_Position = vec4(a_window.xy / {WINDOW_SPAN}.0, a_window.z * 2.0 - 1.0, 1.0);"
            ));
        }
    }
    let mut eye = EyeTerms::default();
    if let Some(points) = key.point_size {
        emit_point_size(&mut w, &mut eye, points);
    }
    for &i in &key.clip_planes {
        // User clip plane i (GL 1.5 §2.12): kept where p′·x_eye ≥ 0, p′ the eye plane.
        let e = eye.position(&mut w);
        let p = w.uniform(UniformSource::ClipPlane(i));
        w.line(format!("gl_ClipDistance[{i}] = dot({p}, {e});"));
    }
    // Under flat shading the colour attribute holds the provoking vertex's colour (`draw`).
    let color = "a_color";
    match &key.lighting {
        Some(lighting) => {
            let inputs = if fragment.flat {
                shade_inputs(&mut w, key)
            } else {
                Inputs {
                    eye: eye.position(&mut w),
                    normal: eye.normal(&mut w, key),
                    color,
                }
            };
            emit_lighting(&mut w, lighting, &inputs, flat);
        }
        None => {
            w.declare(SATURATE);
            w.line(format!("v_color = saturate({color});"));
            if fragment.color_sum {
                emit_secondary_attribute(&mut w, flat);
            }
        }
    }
    for unit in &key.units {
        emit_texcoords(&mut w, &mut eye, key, unit);
    }
    if fragment.fog.is_some() {
        w.declare("out float v_fog;");
        match key.fog_source {
            // FOG_COORD_SRC = FRAGMENT_DEPTH as Mesa computes it: z = |z_eye| per vertex
            // (ffvertex_prog.c, FDM_EYE_PLANE_ABS), interpolated; f per fragment.
            FogCoordSource::FragmentDepth => {
                let e = eye.position(&mut w);
                w.line(format!("v_fog = abs({e}.z);"));
            }
            // FOG_COORD: the magnitude of the vertex's fog coordinate, taken per vertex
            // (Mesa: coordinates −10 and 10 fog the whole span as 10), interpolated.
            FogCoordSource::FogCoord => {
                w.declare(&format!(
                    "layout(location = {ATTRIB_FOG_COORD}) in float a_fog_coord;"
                ));
                w.line("v_fog = abs(a_fog_coord);");
            }
        }
    }
    if fragment.edges.is_some() {
        emit_edge(&mut w);
    }
    if let Some(fan) = key.pixel_fan {
        emit_pixel_fan(&mut w, fan);
    }
    w
}

/// A pixel rectangle's texture coordinates at the fan's corners (`pixel_fan`): s = 0, 1,
/// 1, 0 and t = a, a, b, b in drawing order, exact in every corner, for the rasteriser to
/// interpolate as Mesa's drawpixels quad's.
fn emit_pixel_fan(w: &mut GlslWriter, fan: PixelFan) {
    let (a, b) = fan.corner_t();
    w.declare("out vec2 v_pixel_st;");
    w.line(format!(
        "v_pixel_st = vec2(gl_VertexID == 1 || gl_VertexID == 2 ? 1.0 : 0.0, \
         gl_VertexID < 2 ? {a:?} : {b:?});"
    ));
}

/// The vertex colour clamp of GL 1.x (§2.13.6): every colour leaving the vertex stage is
/// clamped to [0, 1] before rasterisation, so +∞ (and 1e39, +∞ as a GLfloat) becomes 1 and
/// −∞ becomes 0. NaN, which the spec leaves undefined, follows Mesa 22.3.6 llvmpipe's native
/// path (measured, `tests/fidelity_nonfinite.rs`): a NaN the vertex stage computes or reads
/// per vertex becomes 1 — a NaN diffuse material draws full red, and so does a colour
/// array's or a glColor4f(NaN, 0, 1, 1) inside glBegin/glEnd (magenta), primary and
/// secondary, alpha too — as if clamped by a min and a max that drop a NaN operand. A NaN
/// in the *current* colour drawn unlit becomes 0 (glColor4f(NaN, 0, 1, 1) before glBegin
/// draws blue): that one is replaced on the CPU where it is sent (`draw::set_current_values`).
/// GLSL leaves clamp() of NaN undefined; llvmpipe compiles `<` as IEEE 754's ordered
/// compare, false for NaN, so v < 1 ? max(v, 0) : 1 gives 1 for NaN without an isnan — per
/// component a compare, a max and a select, one instruction fewer than clamp and isnan, for
/// every vertex (`tests/fidelity_nonfinite.rs` pins the NaN cases). Clamping after interpolation instead would not do: ∞ interpolated across
/// a triangle is NaN.
const SATURATE: &str =
    "vec4 saturate(vec4 v) { return mix(vec4(1.0), max(v, 0.0), lessThan(v, vec4(1.0))); }";

/// The secondary colour of an unlit vertex (GL 1.4 §2.7): its attribute (under flat
/// shading the provoking vertex's, as for the primary colour), clamped as every colour
/// leaving the vertex stage is. Its alpha is 0, as the lit secondary colour's: the colour
/// sum adds RGB only, and the register combiners' SECONDARY_COLOR alpha is undefined.
fn emit_secondary_attribute(w: &mut GlslWriter, flat: &str) {
    w.declare(&format!(
        "layout(location = {ATTRIB_SECONDARY}) in vec4 a_secondary;"
    ));
    w.declare(&format!("{flat}out vec4 v_secondary;"));
    w.line("v_secondary = vec4(saturate(a_secondary).rgb, 0.0);");
}

/// The edge attribute of split polygons, passed on without perspective so a component
/// that is 0 at both ends of an edge stays exactly 0 along it (`polygon`).
fn emit_edge(w: &mut GlslWriter) {
    w.declare(&format!("layout(location = {ATTRIB_EDGE}) in vec4 a_edge;"));
    w.declare("noperspective out vec4 v_edge;");
    w.line("v_edge = a_edge;");
}

/// What lighting reads: the eye-space position and normal, and the colour attribute that
/// COLOR_MATERIAL tracks.
struct Inputs {
    eye: &'static str,
    normal: &'static str,
    color: &'static str,
}

/// The provoking vertex's eye-space position and normal, from the shade attributes.
fn shade_inputs(w: &mut GlslWriter, key: &VertexKey) -> Inputs {
    w.declare(&format!(
        "layout(location = {ATTRIB_SHADE_POSITION}) in vec4 a_shade_position;"
    ));
    w.declare(&format!(
        "layout(location = {ATTRIB_SHADE_NORMAL}) in vec3 a_shade_normal;"
    ));
    let mv = w.uniform(UniformSource::Modelview);
    w.line(format!("vec4 shade_eye = {mv} * a_shade_position;"));
    emit_normal(w, key, "shade_normal", "a_shade_normal");
    Inputs {
        eye: "shade_eye",
        normal: "shade_normal",
        color: "a_color",
    }
}

/// `out` = (M⁻¹)ᵀ·`attribute`, then NORMALIZE (n/|n|) or RESCALE_NORMAL (f·n) (§2.11.3).
fn emit_normal(w: &mut GlslWriter, key: &VertexKey, out: &str, attribute: &str) {
    let nm = w.uniform(UniformSource::NormalMatrix);
    w.line(format!("vec3 {out} = {nm} * {attribute};"));
    if key.normalize {
        w.line(format!("{out} = normalize({out});"));
    } else if key.rescale_normal {
        let f = w.uniform(UniformSource::RescaleFactor);
        w.line(format!("{out} *= {f};"));
    }
}

/// The size of a points pass: written to gl_PointSize only when attenuated (per vertex; core
/// GL reads it with PROGRAM_POINT_SIZE on); a pass of one size has it from glPointSize,
/// computed once on the CPU ([`uniform_point_size`]), and keeps only what the fragment
/// stage and the position need here.
/// The derived size is `ff::point`'s: glPointSize's value, attenuated by
/// 1/√(a + d·(b + d·c)) with d = |z_eye| (Mesa's order of operations) when the parameters
/// attenuate, then clamped to [POINT_SIZE_MIN, POINT_SIZE_MAX] (max, then min).
///
/// An aliased point's side is that size rounded as llvmpipe's point setup rounds it
/// (GL 1.5 §3.3: aliased sizes are rounded): in 1/256 pixel steps, s₈ = roundEven(256·size),
/// side = max(1, ⌊(s₈ + 127)/256⌋), so halves round down (1.5 → 1, 2.5 → 2). llvmpipe's
/// legacy points cover the pixels whose centres c lie at X − side/2 < c ≤ X + side/2, X the
/// window position in 1/256 steps; the core context rasterises a point sprite, whose rule
/// is the other way round (lo ≤ c < hi). So the sprite is drawn two pixels wider than the
/// side and the fragment stage keeps the legacy rule's pixels (`PointCut::Legacy`). A
/// point whose centre lies on the right or top plane (x = w) is inside the view volume
/// (GL 1.5 §2.12) and keeps its pixels beyond it.
///
/// A round point is the square of Mesa's aapoint stage, side 2r: r = 1 up to size 2 and
/// size/2 above for glPointSize's size, size/2 for an attenuated (per-vertex) one; r goes
/// to the fragment stage as `v_point_r`.
fn emit_point_size(w: &mut GlslWriter, eye: &mut EyeTerms, points: PointKey) {
    let size = w.uniform(UniformSource::PointSize);
    let limits = w.uniform(UniformSource::PointLimits);
    w.line(format!("float point_size = {size};"));
    if points.attenuated {
        let e = eye.position(w);
        let a = w.uniform(UniformSource::PointAttenuation);
        w.line(format!("float point_d = abs({e}.z);"));
        w.line(format!(
            "point_size = point_size * inversesqrt(point_d * (point_d * {a}.z + {a}.y) + {a}.x);"
        ));
    }
    w.line(format!(
        "point_size = min(max(point_size, {limits}.x), {limits}.y);"
    ));
    match points.shape {
        PointShape::Square => {
            let window = w.uniform(UniformSource::PointWindow);
            w.declare("noperspective out vec3 v_point;");
            w.line(
                "float point_side = max(1.0, floor((roundEven(point_size * 256.0) + 127.0) / 256.0));",
            );
            if points.attenuated {
                w.line("gl_PointSize = point_side + 2.0;");
            }
            // The window position as the draw module computes it: x/w, then the viewport.
            w.line(format!(
                "v_point = vec3(gl_Position.xy * (1.0 / gl_Position.w) * {window}.xy + {window}.zw, point_side);"
            ));
        }
        PointShape::Round => {
            w.declare("flat out float v_point_r;");
            if points.attenuated {
                w.line("v_point_r = 0.5 * point_size;");
            } else {
                w.line("v_point_r = point_size <= 2.0 ? 1.0 : 0.5 * point_size;");
            }
            if points.attenuated {
                w.line("gl_PointSize = 2.0 * v_point_r;");
            }
        }
        // Centred where the vertex is, of the size as computed.
        PointShape::Sprite => {
            if points.attenuated {
                w.line("gl_PointSize = point_size;");
            }
        }
    }
}

/// The size core GL rasterises a points pass at when it is the same for every vertex (no
/// distance attenuation): the `gl_PointSize` [`emit_point_size`] computes, from glPointSize's
/// `size` and POINT_SIZE_MIN/MAX `limits`, in the same steps. The sync gives it to
/// glPointSize with PROGRAM_POINT_SIZE off, as Mesa's rasteriser state carries a size that
/// is not per vertex: llvmpipe then clips a point by its centre only and draws it whole
/// beyond a viewport smaller than the buffer, where a per-vertex size makes its draw module
/// cut the point at the viewport's edge.
pub fn uniform_point_size(size: f32, limits: (f32, f32), shape: PointShape) -> f32 {
    let size = size.max(limits.0).min(limits.1);
    match shape {
        PointShape::Square => {
            (((size * 256.0).round_ties_even() + 127.0) / 256.0)
                .floor()
                .max(1.0)
                + 2.0
        }
        PointShape::Round => 2.0 * if size <= 2.0 { 1.0 } else { 0.5 * size },
        PointShape::Sprite => size,
    }
}

/// Eye-space position and normal, emitted on first use only.
#[derive(Default)]
struct EyeTerms {
    position: bool,
    normal: bool,
}

impl EyeTerms {
    fn position(&mut self, w: &mut GlslWriter) -> &'static str {
        if !self.position {
            let mv = w.uniform(UniformSource::Modelview);
            w.line(format!("vec4 eye = {mv} * a_position;"));
            self.position = true;
        }
        "eye"
    }

    /// The vertex's own eye-space normal (`emit_normal`).
    fn normal(&mut self, w: &mut GlslWriter, key: &VertexKey) -> &'static str {
        if !self.normal {
            w.declare(&format!(
                "layout(location = {ATTRIB_NORMAL}) in vec3 a_normal;"
            ));
            emit_normal(w, key, "normal", "a_normal");
            self.normal = true;
        }
        "normal"
    }
}

fn emit_lighting(w: &mut GlslWriter, lighting: &LightingKey, inputs: &Inputs, flat: &str) {
    let (e, n) = (inputs.eye, inputs.normal);
    w.line(format!(
        "vec3 view_dir = {};",
        if lighting.local_viewer {
            format!("normalize(-{e}.xyz)")
        } else {
            "vec3(0.0, 0.0, 1.0)".to_string()
        }
    ));
    if lighting.separate_specular {
        w.declare(&format!("{flat}out vec4 v_secondary;"));
    }
    emit_face(w, lighting, inputs, 0, n, ["v_color", "v_secondary"]);
    if lighting.two_side {
        w.declare(&format!("{flat}out vec4 v_back_color;"));
        if lighting.separate_specular {
            w.declare(&format!("{flat}out vec4 v_back_secondary;"));
        }
        w.line(format!("vec3 back_normal = -{n};"));
        emit_face(
            w,
            lighting,
            inputs,
            1,
            "back_normal",
            ["v_back_color", "v_back_secondary"],
        );
    }
}

/// Where one face's material values come from in the program: the current colour for
/// the values COLOR_MATERIAL tracks, an attribute for those a glMaterial inside
/// glBegin/glEnd set per vertex, the material state's uniforms for the rest.
#[derive(Clone, Copy)]
struct FaceMaterial<'a> {
    cm: Option<ColorMaterialKey>,
    per_vertex: u16,
    color: &'a str,
    face: u8,
}

impl<'a> FaceMaterial<'a> {
    fn of(lighting: &LightingKey, color: &'a str, face: u8) -> Self {
        FaceMaterial {
            cm: lighting.color_material,
            per_vertex: lighting.vertex_materials,
            color,
            face,
        }
    }

    /// The value: varying where it varies, the state's uniform otherwise.
    fn value(&self, w: &mut GlslWriter, value: MaterialValue) -> String {
        self.varying(w, value)
            .unwrap_or_else(|| w.uniform(UniformSource::Material(self.face, value)))
    }

    /// m·l of light `light`'s and the face's colours of `term` (rgb): the CPU's product
    /// (`UniformSource::LightProduct`) where the material value is the state's, the
    /// program's where it varies per vertex.
    fn light_product(&self, w: &mut GlslWriter, light: u8, term: ColorTerm) -> String {
        match self.varying(w, term.material()) {
            Some(m) => {
                let l = w.uniform(UniformSource::Light(light, term.light()));
                format!("({m}.rgb * {l}.rgb)")
            }
            None => {
                let p = w.uniform(UniformSource::LightProduct(light, self.face, term));
                format!("{p}.rgb")
            }
        }
    }

    /// The value where it varies per vertex; `None` for the material state's.
    fn varying(&self, w: &mut GlslWriter, value: MaterialValue) -> Option<String> {
        let (cm, face) = (self.cm, self.face);
        let tracks = cm.is_some_and(|c| {
            (if face == 0 { c.front } else { c.back })
                && matches!(
                    (c.mode, value),
                    (ColorMaterialMode::Ambient, MaterialValue::Ambient)
                        | (ColorMaterialMode::Diffuse, MaterialValue::Diffuse)
                        | (ColorMaterialMode::Specular, MaterialValue::Specular)
                        | (ColorMaterialMode::Emission, MaterialValue::Emission)
                        | (ColorMaterialMode::AmbientAndDiffuse, MaterialValue::Ambient)
                        | (ColorMaterialMode::AmbientAndDiffuse, MaterialValue::Diffuse)
                )
        });
        if tracks {
            Some(self.color.to_string())
        } else {
            vertex_material(w, self.per_vertex, face, value)
        }
    }
}

/// The attribute of a material value a glMaterial inside glBegin/glEnd set per vertex
/// (bit `MaterialSlot::bit` of `per_vertex`), declared at its location; `None` when the
/// value is the material state's. Shininess arrays hold (s, 0, 0, 1): `.x`.
fn vertex_material(
    w: &mut GlslWriter,
    per_vertex: u16,
    face: u8,
    value: MaterialValue,
) -> Option<String> {
    let face = u32::from(face);
    let index = match value {
        MaterialValue::Ambient => 4 * face,
        MaterialValue::Diffuse => 4 * face + 1,
        MaterialValue::Specular => 4 * face + 2,
        MaterialValue::Emission => 4 * face + 3,
        MaterialValue::Shininess => 8 + face,
    };
    if per_vertex & (1 << index) == 0 {
        return None;
    }
    w.declare(&format!(
        "layout(location = {}) in vec4 a_material{index};",
        material_location(per_vertex, index as usize)
    ));
    Some(match value {
        MaterialValue::Shininess => format!("a_material{index}.x"),
        _ => format!("a_material{index}"),
    })
}

/// c = e_m + a_m·a_cs + Σ att·spot·(a_m·a_l + max(n·L,0)·d_m·d_l + f·max(n·h,0)^s·s_m·s_l),
/// alpha = d_m.a, clamped to [0, 1] (GL 1.5 §2.14.1). With SEPARATE_SPECULAR_COLOR the
/// specular sum Σ att·spot·f·max(n·h,0)^s·s_m·s_l is the secondary colour instead, its
/// alpha 0, clamped alike (GL 1.2 §2.13.1). `out` names the primary and secondary outputs.
fn emit_face(
    w: &mut GlslWriter,
    lighting: &LightingKey,
    inputs: &Inputs,
    face: u8,
    n: &str,
    out: [&str; 2],
) {
    let m = FaceMaterial::of(lighting, inputs.color, face);
    let diffuse = m.value(w, MaterialValue::Diffuse);
    let c = format!("c{face}");
    // e_m + a_m·a_cs: the CPU's sum (`UniformSource::SceneColor`) unless a term varies.
    let varies = m.varying(w, MaterialValue::Emission).is_some()
        || m.varying(w, MaterialValue::Ambient).is_some();
    let scene_color = if varies {
        let emission = m.value(w, MaterialValue::Emission);
        let ambient = m.value(w, MaterialValue::Ambient);
        let scene = w.uniform(UniformSource::LightModelAmbient);
        format!("{emission}.rgb + {ambient}.rgb * {scene}.rgb")
    } else {
        format!("{}.rgb", w.uniform(UniformSource::SceneColor(face)))
    };
    w.line(format!("vec3 {c} = {scene_color};"));
    let secondary = format!("s{face}");
    if lighting.separate_specular {
        w.line(format!("vec3 {secondary} = vec3(0.0);"));
    }
    for light in &lighting.lights {
        emit_light(w, lighting, inputs, *light, face, n, [&c, &secondary]);
    }
    w.declare(SATURATE);
    w.line(format!("{} = saturate(vec4({c}, {diffuse}.a));", out[0]));
    if lighting.separate_specular {
        w.line(format!(
            "{} = vec4(saturate(vec4({secondary}, 0.0)).rgb, 0.0);",
            out[1]
        ));
    }
}

/// One light's term added to the face's sums `sums` = [primary, secondary] (the secondary
/// only with SEPARATE_SPECULAR_COLOR).
fn emit_light(
    w: &mut GlslWriter,
    lighting: &LightingKey,
    inputs: &Inputs,
    l: LightKey,
    face: u8,
    n: &str,
    sums: [&str; 2],
) {
    let [c, secondary] = sums;
    let (e, color) = (inputs.eye, inputs.color);
    let i = l.index;
    let u = |w: &mut GlslWriter, v| w.uniform(UniformSource::Light(i, v));
    let m = FaceMaterial::of(lighting, color, face);
    let ambient = m.light_product(w, i, ColorTerm::Ambient);
    let diffuse = m.light_product(w, i, ColorTerm::Diffuse);
    let specular_product = m.light_product(w, i, ColorTerm::Specular);
    let shin = vertex_material(w, lighting.vertex_materials, face, MaterialValue::Shininess)
        .unwrap_or_else(|| w.uniform(UniformSource::Material(face, MaterialValue::Shininess)));
    let v = format!("l{i}_{face}");
    w.line(format!(
        "// light {i}, {} face",
        ["front", "back"][face as usize]
    ));
    if l.directional {
        let dir = u(w, LightValue::Direction);
        w.line(format!("vec3 {v}_dir = {dir}.xyz;"));
        w.line(format!("float {v}_att = 1.0;"));
    } else {
        let pos = u(w, LightValue::Position);
        let k = u(w, LightValue::Attenuation);
        w.line(format!(
            "vec3 {v}_d = {pos}.xyz / {pos}.w - {e}.xyz / {e}.w;"
        ));
        w.line(format!("float {v}_dist = length({v}_d);"));
        w.line(format!("vec3 {v}_dir = {v}_d / max({v}_dist, 1e-30);"));
        // Attenuation (1, 0, 0) is exactly 1, whatever the distance — even a NaN one (a NaN
        // light position): Mesa's key leaves the term out for (1, 0, 0) (measured: a light
        // at (0, 0, 1, NaN) adds nothing but its ambient term).
        w.line(format!(
            "float {v}_att = ({k}.xyz == vec3(1.0, 0.0, 0.0)) ? 1.0 : 1.0 / ({k}.x + {k}.y * {v}_dist + {k}.z * {v}_dist * {v}_dist);"
        ));
    }
    if l.spot {
        // spot = (−L·ŝ)^e when −L·ŝ > cos(cutoff), else 0; x^0 = 1 (GLSL's pow(0,0) is
        // undefined). GL 1.5 §2.14.1 lights −L·ŝ ≥ cos(cutoff); Mesa's program tests
        // cos(cutoff) < −L·ŝ (SLT) with the cosine raised to 0 and ŝ normalised on the CPU
        // (`LightValue::Spot`, `LightValue::SpotDirection`), so a zero spot direction, which
        // stays zero, lights nothing but the ambient term (measured on Mesa); followed. Mesa
        // multiplies the test's 0 or 1 by |−L·ŝ|^e, so a NaN exponent makes the factor NaN
        // outside the cone too (measured: the light then saturates every vertex); followed.
        let dir = u(w, LightValue::SpotDirection);
        let spot = u(w, LightValue::Spot);
        w.line(format!("float {v}_sd = dot(-{v}_dir, {dir}.xyz);"));
        w.line(format!(
            "float {v}_spot = ({spot}.x == 0.0) ? 1.0 : pow(abs({v}_sd), {spot}.x);"
        ));
        w.line(format!(
            "{v}_att *= (({v}_sd > {spot}.y) ? 1.0 : 0.0) * {v}_spot;"
        ));
    }
    // n·L of NaN (a NaN light position or direction) counts as facing away: no diffuse or
    // specular term, the ambient one stays — Mesa's LIT takes max(n·L, 0) with a max that
    // drops the NaN (measured: the light at (NaN, 0, 1, 0) leaves the ambient colour).
    // `lit` is n·L > 0, false for NaN; it selects both the diffuse factor and the specular
    // term (§2.14.1 adds the specular term only where n·L > 0).
    w.line(format!("float {v}_ndl = dot({n}, {v}_dir);"));
    w.line(format!("bool {v}_lit = {v}_ndl > 0.0;"));
    w.line(format!(
        "vec3 {v}_c = {ambient} + ({v}_lit ? {v}_ndl : 0.0) * {diffuse};"
    ));
    // The specular term joins the primary sum, or its own for SEPARATE_SPECULAR_COLOR.
    let specular = if lighting.separate_specular {
        w.line(format!("vec3 {v}_s = vec3(0.0);"));
        format!("{v}_s")
    } else {
        format!("{v}_c")
    };
    // The half vector: constant for a directional light and an infinite viewer (computed
    // on the CPU, as Mesa does), per vertex otherwise.
    let half = if l.directional && !lighting.local_viewer {
        format!("{}.xyz", u(w, LightValue::HalfVector))
    } else {
        format!("normalize({v}_dir + view_dir)")
    };
    // Only where n·L > 0 (§2.14.1); a select rather than a branch, as Mesa's program
    // has it: every lane of llvmpipe's SIMD batch computes both sides either way.
    w.line(format!("float {v}_ndh = max(dot({n}, {half}), 0.0);"));
    w.line(format!(
        "float {v}_sp = ({shin} == 0.0) ? 1.0 : pow({v}_ndh, {shin});"
    ));
    w.line(format!(
        "{specular} += {v}_lit ? {v}_sp * {specular_product} : vec3(0.0);"
    ));
    w.line(format!("{c} += {v}_att * {v}_c;"));
    if lighting.separate_specular {
        w.line(format!("{secondary} += {v}_att * {specular};"));
    }
}

/// Each coordinate from its source, then the texture matrix: tc = T·(s, t, r, q) (no
/// product when T is the identity, `VertexUnitKey::matrix`).
fn emit_texcoords(w: &mut GlslWriter, eye: &mut EyeTerms, key: &VertexKey, unit: &VertexUnitKey) {
    let u = unit.unit;
    let attribute = format!("a_texcoord{u}");
    w.declare(&format!(
        "layout(location = {}) in vec4 {attribute};",
        ATTRIB_TEXCOORD0 + u32::from(u)
    ));
    w.declare(&format!("out vec4 v_tc{u};"));
    let sphere = unit
        .coords
        .contains(&CoordSource::Generated(TexGenMode::SphereMap));
    if sphere {
        // r = u − 2n(n·u), m = 2√(rx² + ry² + (rz+1)²), (s,t) = r.xy/m + ½ (§2.11.4).
        let e = eye.position(w);
        let n = eye.normal(w, key);
        w.line(format!("vec3 sm_u{u} = normalize({e}.xyz);"));
        w.line(format!("vec3 sm_r{u} = reflect(sm_u{u}, {n});"));
        w.line(format!(
            "float sm_m{u} = 2.0 * sqrt(sm_r{u}.x * sm_r{u}.x + sm_r{u}.y * sm_r{u}.y + (sm_r{u}.z + 1.0) * (sm_r{u}.z + 1.0));"
        ));
    }
    let generated = |m| unit.coords.contains(&CoordSource::Generated(m));
    if generated(TexGenMode::ReflectionMap) {
        // r = u − 2n(n·u), u the unit eye position (GL 1.3 §2.10.4).
        let e = eye.position(w);
        let n = eye.normal(w, key);
        w.line(format!("vec3 rm_r{u} = reflect(normalize({e}.xyz), {n});"));
    }
    let normal_map = if generated(TexGenMode::NormalMap) {
        Some(eye.normal(w, key))
    } else {
        None
    };
    let mut parts = Vec::new();
    for coord in TexCoord::ALL {
        let i = coord.index();
        let comp = ["x", "y", "z", "w"][i];
        parts.push(match unit.coords[i] {
            CoordSource::Attribute => format!("{attribute}.{comp}"),
            CoordSource::Generated(TexGenMode::ObjectLinear) => {
                let p = w.uniform(UniformSource::ObjectPlane(u, coord));
                format!("dot({p}, a_position)")
            }
            CoordSource::Generated(TexGenMode::EyeLinear) => {
                let e = eye.position(w);
                let p = w.uniform(UniformSource::EyePlane(u, coord));
                format!("dot({p}, {e})")
            }
            CoordSource::Generated(TexGenMode::SphereMap) => {
                format!("(sm_r{u}.{comp} / sm_m{u} + 0.5)")
            }
            CoordSource::Generated(TexGenMode::ReflectionMap) => format!("rm_r{u}.{comp}"),
            // S, T and R only (Q refuses the mode), so `comp` is x, y or z.
            CoordSource::Generated(TexGenMode::NormalMap) => {
                format!("{}.{comp}", normal_map.unwrap_or("vec3(0.0)"))
            }
        });
    }
    let coords = format!("vec4({})", parts.join(", "));
    match unit.matrix {
        true => {
            let m = w.uniform(UniformSource::TextureMatrix(u));
            w.line(format!("v_tc{u} = {m} * {coords};"));
        }
        false => w.line(format!("v_tc{u} = {coords};")),
    }
}

#[cfg(test)]
mod tests {
    use crate::ff::{Capability, Command, FixedState, ShadeModel};
    use crate::pipeline::emulate::key::ShaderKey;
    use crate::vocab::Precision;

    fn vertex_source(commands: &[Command]) -> String {
        let mut state = FixedState::new();
        for c in commands {
            assert!(state.apply(c).is_ok(), "{c:?}");
        }
        super::super::generate(&ShaderKey::from_state(&state, Precision::Float)).vertex
    }

    #[test]
    fn flat_shading_lights_the_provoking_vertex() {
        let lit = [
            Command::Enable(Capability::Lighting),
            Command::Enable(Capability::Light(0)),
        ];
        let smooth = vertex_source(&lit);
        assert!(smooth.contains("in vec3 a_normal;"));
        assert!(!smooth.contains("a_shade"));
        let flat = vertex_source(&[
            lit[0].clone(),
            lit[1].clone(),
            Command::ShadeModel(ShadeModel::Flat),
        ]);
        assert!(flat.contains("flat out vec4 v_color;"));
        assert!(flat.contains("vec3 shade_normal = "));
        assert!(flat.contains("vec4 shade_eye = "));
        assert!(
            !flat.contains("in vec3 a_normal;"),
            "nothing else reads the vertex's own normal"
        );
        let unlit = vertex_source(&[Command::ShadeModel(ShadeModel::Flat)]);
        assert!(unlit.contains("v_color = saturate(a_color);"));
    }
}
