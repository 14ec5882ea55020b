//! A plan's own shader programs on the emulated path (`ff::program`).
//!
//! `UseProgram(Some(p))` compiles `p` the first time it is seen (the cache stores the
//! `Result`, keyed by the program itself, so a bad program fails once) and makes it current;
//! `Uniform` sends a value to the current program at once (a value stays with the program
//! object, GL 2.0 §2.15.3); a draw then uses it instead of the generated program: the
//! built-ins the program declares are filled from the fixed-function state, the units its
//! samplers read get the TEXTURE_2D objects the state has bound there, the raster state is
//! synced as for any draw, and the geometry goes through the same upload (its attribute
//! locations are the generated programs', `shadergen::ATTRIB_*`). `UseProgram(None)`
//! returns to the generated programs.

use std::rc::Rc;
use std::sync::Arc;

use glow::HasContext;

use super::cache::ProgramCache;
use super::program::compile_and_link;
use super::uniforms::{self, LightValue, MaterialValue, UniformSource};
use crate::ff::{BuiltIn, FixedState, ShaderProgram, TextureTarget, UniformValue};
use crate::pipeline::{PipelineError, ShaderError};

/// A linked plan program and the locations of the built-ins it declares.
pub struct UserProgram {
    pub program: glow::Program,
    built_ins: Vec<(BuiltIn, glow::UniformLocation)>,
    /// The texture units its samplers read.
    pub units: Vec<u8>,
}

/// The plan's programs, compiled once each, and the one in use.
#[derive(Default)]
pub struct UserPrograms {
    cache: ProgramCache<ShaderProgram, UserProgram>,
    current: Option<Rc<UserProgram>>,
}

impl UserPrograms {
    /// The program in use, if any.
    pub fn current(&self) -> Option<&Rc<UserProgram>> {
        self.current.as_ref()
    }

    /// How many programs were built.
    pub fn compiles(&self) -> usize {
        self.cache.compiles()
    }

    /// glUseProgram: builds `program` the first time, makes it current (`None`: none).
    pub fn use_program(
        &mut self,
        gl: &glow::Context,
        program: Option<&Arc<ShaderProgram>>,
    ) -> Result<(), PipelineError> {
        self.current = match program {
            Some(p) => Some(self.cache.get_or_build(p, |p| UserProgram::build(gl, p))?),
            None => None,
        };
        Ok(())
    }

    /// glUniform of `name` in the program in use; a name the program lacks (or the
    /// compiler removed) is ignored, as GL ignores location −1.
    pub fn uniform(
        &self,
        gl: &glow::Context,
        name: &str,
        value: &UniformValue,
    ) -> Result<(), PipelineError> {
        let p = self
            .current
            .as_ref()
            .ok_or_else(|| PipelineError::UniformWithoutProgram {
                name: name.to_string(),
            })?;
        unsafe {
            gl.use_program(Some(p.program));
            let Some(loc) = gl.get_uniform_location(p.program, name) else {
                return Ok(());
            };
            let loc = Some(&loc);
            match value {
                UniformValue::Float(v) => gl.uniform_1_f32(loc, *v),
                UniformValue::Vec2(v) => gl.uniform_2_f32(loc, v.x, v.y),
                UniformValue::Vec3(v) => gl.uniform_3_f32(loc, v.x, v.y, v.z),
                UniformValue::Vec4(v) => gl.uniform_4_f32(loc, v.x, v.y, v.z, v.w),
                UniformValue::Int(v) => gl.uniform_1_i32(loc, *v),
                UniformValue::Floats(v) => gl.uniform_1_f32_slice(loc, v),
                UniformValue::Mat4(m) => {
                    gl.uniform_matrix_4_f32_slice(loc, false, &m.to_cols_array())
                }
            }
        }
        Ok(())
    }

    pub fn release(&mut self, gl: &glow::Context) {
        self.current = None;
        for p in self.cache.drain() {
            unsafe { gl.delete_program(p.program) };
        }
    }
}

impl UserProgram {
    /// Compiles and links `p`, binds its samplers to their units and finds its built-ins.
    pub fn build(gl: &glow::Context, p: &ShaderProgram) -> Result<UserProgram, ShaderError> {
        let program = compile_and_link(gl, &p.vertex, &p.fragment, &p.name)?;
        // SAFETY: uniform calls on the program just linked, on the current context.
        unsafe {
            gl.use_program(Some(program));
            for s in &p.samplers {
                if let Some(loc) = gl.get_uniform_location(program, &s.name) {
                    gl.uniform_1_i32(Some(&loc), i32::from(s.unit));
                }
            }
            let built_ins = BuiltIn::all()
                .into_iter()
                .filter_map(|b| Some((b, gl.get_uniform_location(program, &b.name())?)))
                .collect();
            Ok(UserProgram {
                program,
                built_ins,
                units: p.samplers.iter().map(|s| s.unit).collect(),
            })
        }
    }

    /// Uses the program and fills its built-ins from `state`.
    pub fn bind(&self, gl: &glow::Context, state: &FixedState) {
        unsafe {
            gl.use_program(Some(self.program));
            for (b, loc) in &self.built_ins {
                // The same values the generated programs receive (`uniforms::value`).
                let source = match b {
                    BuiltIn::Modelview => UniformSource::Modelview,
                    BuiltIn::ModelviewProjection => UniformSource::ModelviewProjection,
                    BuiltIn::NormalMatrix => UniformSource::NormalMatrix,
                    BuiltIn::TextureMatrix(u) => UniformSource::TextureMatrix(*u),
                    BuiltIn::Light0Position => UniformSource::Light(0, LightValue::Position),
                    BuiltIn::Light0Diffuse => UniformSource::Light(0, LightValue::Diffuse),
                    BuiltIn::FrontDiffuse => UniformSource::Material(0, MaterialValue::Diffuse),
                    BuiltIn::ClipPlane(i) => UniformSource::ClipPlane(*i),
                    BuiltIn::Projection => {
                        uniforms::UniformValue::Mat4(state.projection_matrix()).upload(gl, loc);
                        continue;
                    }
                };
                uniforms::value(source, state).upload(gl, loc);
            }
        }
    }

    /// The (unit, TEXTURE_2D) pairs a draw binds.
    pub fn texture_units(&self) -> Vec<(u8, TextureTarget)> {
        self.units
            .iter()
            .map(|&u| (u, TextureTarget::Texture2D))
            .collect()
    }
}
