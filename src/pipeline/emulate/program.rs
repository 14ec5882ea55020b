//! Compiling a generated program and uploading its uniforms. The location list is built
//! from the same `UniformSource` list the generator declared.
//!
//! A uniform keeps its value in the program object (GL 4.6 §7.6), and only this module
//! sets a generated program's uniforms, so a bind uploads only the values that differ,
//! bit for bit, from the ones the program last received: a frame of many objects that
//! differ only in their modelview matrix sends the matrices, not the lights and
//! materials again. (Each glUniform costs the driver a call and a check even when the
//! value is the same.)

use std::cell::RefCell;

use glow::HasContext;

use super::key::ShaderKey;
use super::shadergen::{self, GeneratedProgram};
use super::uniforms::{self, UniformSource, UniformValue};
use crate::ff::FixedState;
use crate::pipeline::{ShaderError, ShaderStage};

pub struct Program {
    pub program: glow::Program,
    uniforms: Vec<(UniformSource, Option<glow::UniformLocation>)>,
    /// The value each of `uniforms` last received (None: never uploaded).
    sent: RefCell<Vec<Option<UniformValue>>>,
}

/// Compiles one stage; a failure carries `label` (the program's key or name), the GLSL and
/// the driver's log.
fn compile_stage(
    gl: &glow::Context,
    kind: u32,
    stage: ShaderStage,
    source: &str,
    label: &str,
) -> Result<glow::Shader, ShaderError> {
    let err = |log: String| ShaderError {
        stage,
        key: label.to_string(),
        glsl: source.to_string(),
        log,
    };
    // SAFETY: plain GL calls on the current context.
    unsafe {
        let shader = gl.create_shader(kind).map_err(err)?;
        gl.shader_source(shader, source);
        gl.compile_shader(shader);
        if !gl.get_shader_compile_status(shader) {
            let log = gl.get_shader_info_log(shader);
            gl.delete_shader(shader);
            return Err(err(log));
        }
        Ok(shader)
    }
}

/// Compiles both stages and links them; a failure carries `label` (the program's key or
/// name), the GLSL and the driver's log, and leaves no shader or program behind.
pub(super) fn compile_and_link(
    gl: &glow::Context,
    vertex: &str,
    fragment: &str,
    label: &str,
) -> Result<glow::Program, ShaderError> {
    let vs = compile_stage(gl, glow::VERTEX_SHADER, ShaderStage::Vertex, vertex, label)?;
    // SAFETY: plain GL calls on the current context, on the shaders just made.
    unsafe {
        let fs = compile_stage(
            gl,
            glow::FRAGMENT_SHADER,
            ShaderStage::Fragment,
            fragment,
            label,
        )
        .inspect_err(|_| gl.delete_shader(vs))?;
        let link_err = |log: String| ShaderError {
            stage: ShaderStage::Link,
            key: label.to_string(),
            glsl: format!("{vertex}\n// ---- fragment ----\n{fragment}"),
            log,
        };
        let program = gl.create_program().map_err(link_err)?;
        gl.attach_shader(program, vs);
        gl.attach_shader(program, fs);
        gl.link_program(program);
        gl.delete_shader(vs);
        gl.delete_shader(fs);
        if !gl.get_program_link_status(program) {
            let log = gl.get_program_info_log(program);
            gl.delete_program(program);
            return Err(link_err(log));
        }
        Ok(program)
    }
}

impl Program {
    /// Generates, compiles and links the program of `key`.
    pub fn build(gl: &glow::Context, key: &ShaderKey) -> Result<Program, ShaderError> {
        let GeneratedProgram {
            vertex,
            fragment,
            uniforms,
        } = shadergen::generate(key);
        let program = compile_and_link(gl, &vertex, &fragment, &format!("{key:?}"))?;
        // SAFETY: uniform queries on the program just linked, on the current context.
        unsafe {
            let uniforms: Vec<_> = uniforms
                .into_iter()
                .map(|u| (u, gl.get_uniform_location(program, &u.name())))
                .collect();
            let sent = RefCell::new(vec![None; uniforms.len()]);
            Ok(Program {
                program,
                uniforms,
                sent,
            })
        }
    }

    /// Uses the program and uploads the uniforms it declared whose values in `state`
    /// differ from the ones it holds.
    pub fn bind(&self, gl: &glow::Context, state: &FixedState) {
        self.use_and_upload(gl, state, |_| true);
    }

    /// Uses the program and uploads only its uniforms that read the modelview or
    /// projection matrix, where they changed: for a draw after which nothing else the
    /// program reads has changed (`repeat`).
    pub fn bind_transform(&self, gl: &glow::Context, state: &FixedState) {
        self.use_and_upload(gl, state, UniformSource::reads_transform);
    }

    /// Uses the program and uploads each uniform `which` selects whose value in `state`
    /// differs, bit for bit, from the one the program holds.
    fn use_and_upload(
        &self,
        gl: &glow::Context,
        state: &FixedState,
        which: impl Fn(UniformSource) -> bool,
    ) {
        let mut sent = self.sent.borrow_mut();
        // SAFETY: plain GL calls on the current context.
        unsafe { gl.use_program(Some(self.program)) };
        for ((source, location), held) in self.uniforms.iter().zip(sent.iter_mut()) {
            let Some(loc) = location.as_ref().filter(|_| which(*source)) else {
                continue; // not selected, or declared but optimised away by the compiler
            };
            let value = uniforms::value(*source, state);
            if held.is_some_and(|h| h.same_bits(&value)) {
                continue;
            }
            *held = Some(value);
            value.upload(gl, loc);
        }
    }

    pub fn delete(&self, gl: &glow::Context) {
        unsafe { gl.delete_program(self.program) };
    }
}
