//! Where every uniform's value comes from. The generator declares a uniform by naming its
//! `UniformSource`; the GLSL writer records the list; upload walks that same list and asks
//! `value` for each — so the code and the uploads cannot disagree. A source names its GLSL
//! type here too; the writer (`glsl`) uses this module, never the reverse.

use glam::{Mat3, Mat4, Vec4};

use crate::ff::{FixedState, Material, TexCoord};

/// The GLSL type of a uniform.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum UniformType {
    Float,
    Vec4,
    Mat3,
    Mat4,
    Int,
    /// 32 words (a stipple pattern's rows).
    Rows,
}

impl UniformType {
    pub fn glsl(self) -> &'static str {
        match self {
            UniformType::Float => "float",
            UniformType::Vec4 => "vec4",
            UniformType::Mat3 => "mat3",
            UniformType::Mat4 => "mat4",
            UniformType::Int => "int",
            UniformType::Rows => "uint[32]",
        }
    }
}

/// A light parameter, in eye space where GL stores it so.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LightValue {
    Ambient,
    Diffuse,
    Specular,
    Position,
    /// The eye-space spot direction normalised as Mesa normalises it
    /// ([`normalized_as_mesa`]).
    SpotDirection,
    /// (spot exponent, cos(cutoff) as Mesa keeps it (`Light::cos_cutoff`), 0, 0).
    Spot,
    /// (constant, linear, quadratic, 0).
    Attenuation,
    /// A directional light's unit direction VP = P̂ (GL 1.5 §2.14.1), computed once per
    /// draw as Mesa computes it on the CPU (`normalized_as_mesa`).
    Direction,
    /// A directional light's half vector for an infinite viewer, ĥ = normalize(P̂ + (0, 0, 1)),
    /// also computed once per draw as Mesa does.
    HalfVector,
}

/// v / |v| as Mesa's lighting normalises on the CPU: a zero vector stays zero (its length
/// is tested before the division); a NaN one stays NaN.
pub fn normalized_as_mesa(v: glam::Vec3) -> glam::Vec3 {
    let len = v.length();
    if len != 0.0 {
        v * (1.0 / len)
    } else {
        v
    }
}

/// A material parameter of one face.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MaterialValue {
    Ambient,
    Diffuse,
    Specular,
    Emission,
    Shininess,
}

/// The three colours a light and a material each have, whose products light a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ColorTerm {
    Ambient,
    Diffuse,
    Specular,
}

impl ColorTerm {
    pub fn material(self) -> MaterialValue {
        match self {
            ColorTerm::Ambient => MaterialValue::Ambient,
            ColorTerm::Diffuse => MaterialValue::Diffuse,
            ColorTerm::Specular => MaterialValue::Specular,
        }
    }

    pub fn light(self) -> LightValue {
        match self {
            ColorTerm::Ambient => LightValue::Ambient,
            ColorTerm::Diffuse => LightValue::Diffuse,
            ColorTerm::Specular => LightValue::Specular,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum UniformSource {
    Modelview,
    /// P · M, multiplied on the CPU as Mesa's fixed-function vertex program takes it
    /// (`STATE_MVP_MATRIX`), so clip coordinates round as Mesa's do.
    ModelviewProjection,
    /// Inverse transpose of the modelview's upper 3×3 (GL 1.5 §2.11.3).
    NormalMatrix,
    /// RESCALE_NORMAL's factor: 1 / length of the third row of that inverse.
    RescaleFactor,
    TextureMatrix(u8),
    ObjectPlane(u8, TexCoord),
    EyePlane(u8, TexCoord),
    Light(u8, LightValue),
    /// Face 0 = front, 1 = back.
    Material(u8, MaterialValue),
    LightModelAmbient,
    /// Light i's colour times face f's material colour of the same term, m·l per channel
    /// (alpha 1): multiplied on the CPU once per draw, as Mesa's fixed-function program
    /// takes it (`STATE_LIGHTPROD`), for a material value that is the state's (neither
    /// COLOR_MATERIAL's nor set per vertex). In the program the product costs a multiply
    /// per vertex and channel: llvmpipe does not hoist uniform-only arithmetic out of its
    /// SIMD vertex loop (`bench --only abi` buffers mode: 0.57 M instructions a frame for
    /// one light).
    LightProduct(u8, u8, ColorTerm),
    /// Face f's scene colour e_m + a_m·a_cs (GL 1.5 §2.14.1), summed on the CPU as Mesa's
    /// `STATE_LIGHTMODEL_SCENECOLOR`, when emission and ambient are the state's.
    SceneColor(u8),
    EnvColor(u8),
    /// TEXTURE_COMPARE_FAIL_VALUE of the unit's texture.
    CompareFail(u8),
    AlphaRef,
    /// CONSTANT_COLOR0_NV / CONSTANT_COLOR1_NV.
    CombinerConstant(u8),
    /// The texture image unit the sampler reads (the fixed-function unit index).
    Sampler(u8),
    /// glPointSize: the attenuated size's start, and a round point's radius.
    PointSize,
    /// The viewport transform from normalised device x and y to window coordinates
    /// (GL 1.5 §2.11.1): (width/2, height/2, x + width/2, y + height/2), where an aliased
    /// point is placed (`shadergen::vertex`).
    PointWindow,
    /// (POINT_SIZE_MIN, POINT_SIZE_MAX, 0, 0).
    PointLimits,
    /// POINT_DISTANCE_ATTENUATION's (a, b, c, 0).
    PointAttenuation,
    /// CLIP_PLANEi's plane in eye coordinates.
    ClipPlane(u8),
    /// `Fog::factor_params`: (a, b, d·log₂e, d/√ln 2).
    FogParams,
    /// FOG_COLOR, clamped when set.
    FogColor,
    /// A pixel rectangle's image (`pixels::PIXEL_IMAGE_UNIT`).
    PixelImage,
    /// A pixel rectangle's lower-left window corner and zoom, (x, y, z_x, z_y): the raster
    /// position and zoom of the draw's state (`pixels::rect_state`).
    PixelRect,
    /// The bit a STENCIL_INDEX pass writes: its state's stencil value mask, which the pass's
    /// ALWAYS test does not read (`pixels`).
    PixelStencilBit,
    /// The polygon stipple's rows, bit 31 − x of row y for pixel (x, y) (`ff::stipple`).
    PolygonStipple,
}

impl UniformSource {
    pub fn name(self) -> String {
        let c = |c: TexCoord| ["s", "t", "r", "q"][c.index()];
        match self {
            UniformSource::Modelview => "u_modelview".into(),
            UniformSource::ModelviewProjection => "u_mvp".into(),
            UniformSource::NormalMatrix => "u_normal_matrix".into(),
            UniformSource::RescaleFactor => "u_rescale".into(),
            UniformSource::TextureMatrix(u) => format!("u_texmat{u}"),
            UniformSource::ObjectPlane(u, k) => format!("u_obj_plane{u}_{}", c(k)),
            UniformSource::EyePlane(u, k) => format!("u_eye_plane{u}_{}", c(k)),
            UniformSource::Light(i, v) => format!("u_light{i}_{v:?}").to_lowercase(),
            UniformSource::Material(f, v) => {
                format!("u_{}_{v:?}", ["front", "back"][f as usize & 1]).to_lowercase()
            }
            UniformSource::LightModelAmbient => "u_scene_ambient".into(),
            UniformSource::LightProduct(i, f, t) => format!(
                "u_light{i}_{}_{t:?}_product",
                ["front", "back"][f as usize & 1]
            )
            .to_lowercase(),
            UniformSource::SceneColor(f) => {
                format!("u_{}_scene_color", ["front", "back"][f as usize & 1])
            }
            UniformSource::EnvColor(u) => format!("u_env_color{u}"),
            UniformSource::CompareFail(u) => format!("u_compare_fail{u}"),
            UniformSource::AlphaRef => "u_alpha_ref".into(),
            UniformSource::CombinerConstant(i) => format!("u_combiner_constant{i}"),
            UniformSource::Sampler(u) => format!("u_tex{u}"),
            UniformSource::PointSize => "u_point_size".into(),
            UniformSource::PointWindow => "u_point_window".into(),
            UniformSource::PointLimits => "u_point_limits".into(),
            UniformSource::PointAttenuation => "u_point_attenuation".into(),
            UniformSource::ClipPlane(i) => format!("u_clip_plane{i}"),
            UniformSource::FogParams => "u_fog_params".into(),
            UniformSource::FogColor => "u_fog_color".into(),
            UniformSource::PixelImage => "u_pixel_image".into(),
            UniformSource::PixelRect => "u_pixel_rect".into(),
            UniformSource::PixelStencilBit => "u_pixel_stencil_bit".into(),
            UniformSource::PolygonStipple => "u_polygon_stipple".into(),
        }
    }

    /// Whether the value reads the modelview or projection matrix (and nothing else that
    /// a matrix command changes): the uniforms a repeated draw sends again (`repeat`).
    pub fn reads_transform(self) -> bool {
        matches!(
            self,
            UniformSource::Modelview
                | UniformSource::ModelviewProjection
                | UniformSource::NormalMatrix
                | UniformSource::RescaleFactor
        )
    }

    /// The GLSL type; samplers are typed by the fragment generator (`sampler2D`,
    /// `sampler2DShadow`, …, through `GlslWriter::uniform_typed`).
    pub fn ty(self) -> UniformType {
        match self {
            UniformSource::Modelview
            | UniformSource::ModelviewProjection
            | UniformSource::TextureMatrix(_) => UniformType::Mat4,
            UniformSource::NormalMatrix => UniformType::Mat3,
            UniformSource::RescaleFactor
            | UniformSource::CompareFail(_)
            | UniformSource::AlphaRef
            | UniformSource::PointSize
            | UniformSource::Material(_, MaterialValue::Shininess) => UniformType::Float,
            UniformSource::Sampler(_)
            | UniformSource::PixelImage
            | UniformSource::PixelStencilBit => UniformType::Int,
            UniformSource::PolygonStipple => UniformType::Rows,
            _ => UniformType::Vec4,
        }
    }
}

/// A value ready to upload.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum UniformValue {
    Float(f32),
    Vec4(Vec4),
    Mat3(Mat3),
    Mat4(Mat4),
    Int(i32),
    Rows([u32; 32]),
}

impl UniformValue {
    /// glUniform* of this value at `loc` of the program in use.
    pub fn upload(&self, gl: &glow::Context, loc: &glow::UniformLocation) {
        use glow::HasContext;
        let loc = Some(loc);
        // SAFETY: plain GL calls on the current context; the slices are the values.
        unsafe {
            match *self {
                UniformValue::Float(v) => gl.uniform_1_f32(loc, v),
                UniformValue::Int(v) => gl.uniform_1_i32(loc, v),
                UniformValue::Rows(r) => gl.uniform_1_u32_slice(loc, &r),
                UniformValue::Vec4(v) => gl.uniform_4_f32(loc, v.x, v.y, v.z, v.w),
                UniformValue::Mat3(m) => {
                    gl.uniform_matrix_3_f32_slice(loc, false, &m.to_cols_array())
                }
                UniformValue::Mat4(m) => {
                    gl.uniform_matrix_4_f32_slice(loc, false, &m.to_cols_array())
                }
            }
        }
    }

    /// Whether `other` is the same upload, bit for bit: −0 and +0 differ (a program may
    /// divide by the value), and a NaN is the same as an identical NaN.
    pub fn same_bits(&self, other: &UniformValue) -> bool {
        let bits = |a: &[f32], b: &[f32]| {
            a.iter()
                .map(|x| x.to_bits())
                .eq(b.iter().map(|x| x.to_bits()))
        };
        match (self, other) {
            (UniformValue::Float(a), UniformValue::Float(b)) => a.to_bits() == b.to_bits(),
            (UniformValue::Vec4(a), UniformValue::Vec4(b)) => bits(&a.to_array(), &b.to_array()),
            (UniformValue::Mat3(a), UniformValue::Mat3(b)) => {
                bits(&a.to_cols_array(), &b.to_cols_array())
            }
            (UniformValue::Mat4(a), UniformValue::Mat4(b)) => {
                bits(&a.to_cols_array(), &b.to_cols_array())
            }
            (UniformValue::Int(a), UniformValue::Int(b)) => a == b,
            (UniformValue::Rows(a), UniformValue::Rows(b)) => a == b,
            _ => false,
        }
    }
}

fn material(state: &FixedState, face: u8) -> &Material {
    if face == 0 {
        &state.materials.front
    } else {
        &state.materials.back
    }
}

/// The value of `source` in `state`.
pub fn value(source: UniformSource, state: &FixedState) -> UniformValue {
    use UniformValue::*;
    match source {
        UniformSource::Modelview => Mat4(state.modelview_matrix()),
        UniformSource::ModelviewProjection => {
            Mat4(state.projection_matrix() * state.modelview_matrix())
        }
        UniformSource::NormalMatrix => Mat3(
            glam::Mat3::from_mat4(crate::ff::matrix::inverse_or_identity(
                state.modelview_matrix(),
            ))
            .transpose(),
        ),
        UniformSource::RescaleFactor => {
            // GL 1.5 eqn 2.6: f = 1 / sqrt(m31² + m32² + m33²) of the inverse modelview.
            let inv = crate::ff::matrix::inverse_or_identity(state.modelview_matrix());
            let row = glam::Vec3::new(inv.x_axis.z, inv.y_axis.z, inv.z_axis.z);
            let len = row.length();
            Float(if len > 0.0 { 1.0 / len } else { 1.0 })
        }
        UniformSource::TextureMatrix(u) => Mat4(state.texture_matrix(u as usize)),
        UniformSource::ObjectPlane(u, c) => {
            Vec4(state.units[u as usize].texgen[c.index()].value.object_plane)
        }
        UniformSource::EyePlane(u, c) => {
            Vec4(state.units[u as usize].texgen[c.index()].value.eye_plane)
        }
        UniformSource::Light(i, v) => {
            let l = &state.lights[i as usize].value;
            match v {
                LightValue::Ambient => Vec4(l.ambient),
                LightValue::Diffuse => Vec4(l.diffuse),
                LightValue::Specular => Vec4(l.specular),
                LightValue::Position => Vec4(l.position),
                LightValue::SpotDirection => Vec4(normalized_as_mesa(l.spot_direction).extend(0.0)),
                LightValue::Spot => {
                    Vec4(glam::Vec4::new(l.spot_exponent, l.cos_cutoff(), 0.0, 0.0))
                }
                LightValue::Direction => {
                    Vec4(normalized_as_mesa(l.position.truncate()).extend(0.0))
                }
                LightValue::HalfVector => {
                    let vp = normalized_as_mesa(l.position.truncate());
                    Vec4(normalized_as_mesa(vp + glam::Vec3::Z).extend(0.0))
                }
                LightValue::Attenuation => Vec4(glam::Vec4::new(
                    l.constant_attenuation,
                    l.linear_attenuation,
                    l.quadratic_attenuation,
                    0.0,
                )),
            }
        }
        UniformSource::Material(face, v) => {
            let m = material(state, face);
            match v {
                MaterialValue::Ambient => Vec4(m.ambient),
                MaterialValue::Diffuse => Vec4(m.diffuse),
                MaterialValue::Specular => Vec4(m.specular),
                MaterialValue::Emission => Vec4(m.emission),
                MaterialValue::Shininess => Float(m.lit_exponent()),
            }
        }
        UniformSource::LightModelAmbient => Vec4(state.light_model.ambient),
        UniformSource::LightProduct(i, face, t) => {
            let l = &state.lights[i as usize].value;
            let m = material(state, face);
            let (lc, mc) = match t {
                ColorTerm::Ambient => (l.ambient, m.ambient),
                ColorTerm::Diffuse => (l.diffuse, m.diffuse),
                ColorTerm::Specular => (l.specular, m.specular),
            };
            Vec4((mc.truncate() * lc.truncate()).extend(1.0))
        }
        UniformSource::SceneColor(face) => {
            let m = material(state, face);
            let scene = state.light_model.ambient.truncate();
            Vec4((m.emission.truncate() + m.ambient.truncate() * scene).extend(1.0))
        }
        UniformSource::EnvColor(u) => Vec4(state.units[u as usize].env.color),
        UniformSource::CompareFail(u) => Float(
            state
                .enabled_texture(u as usize)
                .map_or(0.0, |t| t.params.compare_fail_value),
        ),
        UniformSource::AlphaRef => Float(alpha_reference(state.alpha_test.value.reference)),
        UniformSource::CombinerConstant(i) => {
            Vec4(state.register_combiners.value.constant_color[usize::from(i & 1)])
        }
        UniformSource::Sampler(u) => Int(i32::from(u)),
        UniformSource::PointSize => Float(state.point_size),
        UniformSource::PointLimits => Vec4(glam::Vec4::new(
            state.point_params.size_min,
            state.point_params.size_max,
            0.0,
            0.0,
        )),
        UniformSource::PointWindow => {
            let v = state.viewport;
            let (half_w, half_h) = (v.width as f32 / 2.0, v.height as f32 / 2.0);
            Vec4(glam::Vec4::new(
                half_w,
                half_h,
                v.x as f32 + half_w,
                v.y as f32 + half_h,
            ))
        }
        UniformSource::PointAttenuation => {
            let [a, b, c] = state.point_params.attenuation;
            Vec4(glam::Vec4::new(a, b, c, 0.0))
        }
        UniformSource::ClipPlane(i) => Vec4(
            state
                .clip_planes
                .get(usize::from(i))
                .map_or(glam::Vec4::ZERO, |p| p.value),
        ),
        UniformSource::FogParams => Vec4(state.fog.value.factor_params()),
        UniformSource::FogColor => Vec4(state.fog.value.color),
        UniformSource::PixelImage => Int(super::pixels::PIXEL_IMAGE_UNIT as i32),
        UniformSource::PixelRect => Vec4(glam::Vec4::new(
            state.raster.window.x,
            state.raster.window.y,
            state.pixel_zoom.x,
            state.pixel_zoom.y,
        )),
        UniformSource::PixelStencilBit => Int(state.stencil_test.value.value_mask as i32),
        UniformSource::PolygonStipple => Rows(state.polygon_stipple.value.rows),
    }
}

/// glAlphaFunc's reference as the shader compares it. GL clamps it to [0, 1] (the model does
/// when it is set, so ±∞ are 1 and 0 already); a NaN reference survives that clamp and GLSL
/// would leave its conversion undefined. Rule: NaN compares as 1 — what Mesa 22.3.6
/// llvmpipe's native path does (measured with alpha 0.25 and 1 under all eight functions,
/// `tests/fidelity_nonfinite.rs`: GREATER passes nothing, LESS and NOTEQUAL pass 0.25,
/// EQUAL passes 1, exactly as with the reference 1).
fn alpha_reference(reference: f32) -> f32 {
    if reference.is_nan() {
        1.0
    } else {
        reference
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_upload_is_the_same_only_bit_for_bit() {
        let v = |x: f32| UniformValue::Vec4(Vec4::new(x, 1.0, 2.0, 3.0));
        assert!(v(0.5).same_bits(&v(0.5)));
        assert!(!v(0.5).same_bits(&v(0.25)));
        // −0 and +0 compare equal as floats but are different uploads.
        assert!(!v(0.0).same_bits(&v(-0.0)));
        // A NaN is the same upload as the same NaN (`==` would send it at every draw).
        assert!(v(f32::NAN).same_bits(&v(f32::NAN)));
        assert!(!UniformValue::Float(1.0).same_bits(&UniformValue::Int(1)));
        let m = Mat4::from_translation(glam::Vec3::new(1.0, 2.0, 3.0));
        assert!(UniformValue::Mat4(m).same_bits(&UniformValue::Mat4(m)));
        assert!(!UniformValue::Mat4(m).same_bits(&UniformValue::Mat4(Mat4::IDENTITY)));
    }
}
