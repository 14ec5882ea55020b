//! Shader programs in a plan: the one extension of the fixed-function model beyond GL 1.x.
//!
//! A technique that needs real shaders (Eisemann & Décoret's occlusion textures) emits
//! `Command::UseProgram(Some(program))`, sets its own uniforms with `Command::Uniform`, and
//! draws as usual; `Command::UseProgram(None)` returns to the fixed-function pipeline, as
//! glUseProgram(0) does (GL 2.0 §2.15). While a program is in use the emulate pipeline draws
//! with it instead of the program it generates from the state, through the same geometry
//! upload, and fills the [`BuiltIn`] uniforms the program declares from the fixed-function
//! state at each draw — Cg's `glstate`, the way the era's shaders read the legacy matrices.
//! Everything else (framebuffers, textures, depth, blend, viewport, raster state) keeps its
//! fixed-function meaning and is sent as for any draw. Mesa's native fixed function has no
//! programs: the native pipeline refuses both commands.
//!
//! **Attributes** arrive at the generated programs' locations: position 0, normal 1,
//! colour 2, texture coordinate 0 at 3 (`pipeline::emulate::shadergen::ATTRIB_*`); a
//! program declares them with `layout(location = …)`.
//!
//! **Samplers** are bound to texture units by the program ([`SamplerBinding`]); a draw
//! binds on each such unit the TEXTURE_2D object the unit has bound in the state, enabled
//! or not (a program samples what is bound, GL 2.0 §2.15.4).
//!
//! **Uniform values** belong to the program in use: `Command::Uniform` with no program in
//! use is refused by the pipeline (GL's INVALID_OPERATION), and a value set stays with the
//! program object until set again (GL 2.0 §2.15.3).

use glam::{Mat4, Vec2, Vec3, Vec4};

/// A program of a vertex and a fragment shader, GLSL 3.30 core (`#version 330 core`
/// first), and the texture unit each of its samplers reads.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct ShaderProgram {
    /// What it is, for errors and `explain`: e.g. `eisemann/slices`.
    pub name: String,
    pub vertex: String,
    pub fragment: String,
    pub samplers: Vec<SamplerBinding>,
}

/// glUniform1i(location of `name`, unit): the sampler reads texture unit `unit`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct SamplerBinding {
    pub name: String,
    pub unit: u8,
}

/// The value of glUniform{1f, 2f, 3f, 4f, 1i, 1fv, Matrix4fv} for one uniform.
#[derive(Debug, Clone, PartialEq)]
pub enum UniformValue {
    Float(f32),
    Vec2(Vec2),
    Vec3(Vec3),
    Vec4(Vec4),
    Int(i32),
    /// A `float[n]` array from its first element.
    Floats(Vec<f32>),
    Mat4(Mat4),
}

/// The uniforms a program may declare to read the fixed-function state at each draw, by
/// their GLSL names. A program declares only those it needs; the others are not sent.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BuiltIn {
    /// `uniform mat4 ff_modelview;` the top of MODELVIEW.
    Modelview,
    /// `uniform mat4 ff_projection;` the top of PROJECTION.
    Projection,
    /// `uniform mat4 ff_modelview_projection;` P · M multiplied on the CPU, as the generated
    /// programs take it, so that a program's depths equal a fixed-function pass's (a later
    /// DepthFunc(EQUAL) pass over either matches).
    ModelviewProjection,
    /// `uniform mat3 ff_normal_matrix;` the inverse transpose of the modelview's upper 3×3
    /// (GL 1.5 §2.11.3).
    NormalMatrix,
    /// `uniform mat4 ff_texture_matrix0;` … the top of unit i's TEXTURE stack.
    TextureMatrix(u8),
    /// `uniform vec4 ff_light0_position;` LIGHT0's position in eye coordinates, as glLight
    /// stored it (multiplied by the modelview current then, §2.14.1).
    Light0Position,
    /// `uniform vec4 ff_light0_diffuse;` LIGHT0's diffuse colour.
    Light0Diffuse,
    /// `uniform vec4 ff_front_diffuse;` the front material's diffuse colour (glMaterial).
    FrontDiffuse,
    /// `uniform vec4 ff_clip_plane0;` … user clip plane i in eye coordinates, as glClipPlane
    /// stored it (§2.12). A program is clipped by an enabled plane i only where it writes
    /// `gl_ClipDistance[i]` (GL 3.0 §2.17): `dot(ff_clip_plane{i}, eye)` is the fixed-function
    /// rule.
    ClipPlane(u8),
}

impl BuiltIn {
    /// Every built-in, in the order a program's locations are looked up.
    pub fn all() -> Vec<BuiltIn> {
        let mut all = vec![
            BuiltIn::Modelview,
            BuiltIn::Projection,
            BuiltIn::ModelviewProjection,
            BuiltIn::NormalMatrix,
        ];
        all.extend((0..super::MAX_TEXTURE_UNITS as u8).map(BuiltIn::TextureMatrix));
        all.extend([
            BuiltIn::Light0Position,
            BuiltIn::Light0Diffuse,
            BuiltIn::FrontDiffuse,
        ]);
        all.extend((0..super::MAX_CLIP_PLANES as u8).map(BuiltIn::ClipPlane));
        all
    }

    /// Its GLSL name.
    pub fn name(self) -> String {
        match self {
            BuiltIn::Modelview => "ff_modelview".into(),
            BuiltIn::Projection => "ff_projection".into(),
            BuiltIn::ModelviewProjection => "ff_modelview_projection".into(),
            BuiltIn::NormalMatrix => "ff_normal_matrix".into(),
            BuiltIn::TextureMatrix(u) => format!("ff_texture_matrix{u}"),
            BuiltIn::Light0Position => "ff_light0_position".into(),
            BuiltIn::Light0Diffuse => "ff_light0_diffuse".into(),
            BuiltIn::FrontDiffuse => "ff_front_diffuse".into(),
            BuiltIn::ClipPlane(i) => format!("ff_clip_plane{i}"),
        }
    }
}

/// Where the pipeline puts `#define`s a technique adds to a shader: right after the
/// `#version` line, which GLSL requires first.
pub fn with_defines(source: &str, defines: &[(&str, String)]) -> String {
    let (version, rest) = match source.split_once('\n') {
        Some((first, rest)) if first.trim_start().starts_with("#version") => (first, rest),
        _ => ("", source),
    };
    let mut out = String::with_capacity(source.len() + 32 * defines.len());
    if !version.is_empty() {
        out.push_str(version);
        out.push('\n');
    }
    for (name, value) in defines {
        out.push_str(&format!("#define {name} {value}\n"));
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn built_in_names_are_distinct_and_prefixed() {
        let names: Vec<String> = BuiltIn::all().into_iter().map(BuiltIn::name).collect();
        let mut unique = names.clone();
        unique.sort();
        unique.dedup();
        assert_eq!(unique.len(), names.len());
        assert!(names.iter().all(|n| n.starts_with("ff_")));
    }

    #[test]
    fn defines_follow_the_version_line() {
        let s = with_defines(
            "#version 330 core\nvoid main() {}\n",
            &[("SLICES", "16".into())],
        );
        assert_eq!(s, "#version 330 core\n#define SLICES 16\nvoid main() {}\n");
    }
}
