//! The native path: the same Commands as real legacy GL calls on a compatibility context —
//! Mesa's own fixed-function implementation, the oracle the emulated path is checked against.
//!
//! Every Command is folded into the pipeline's own `FixedState` first. A command the model
//! rejects (an invalid enum or value, a stack overflow) sends nothing to GL: GL would have
//! ignored it too (GL 1.5 §2.5), and the model's error is what `take_gl_error` returns. An
//! accepted command becomes its GL calls (`execute.rs`); if GL then raises an error the
//! model did not, the two disagree and execution stops with `PipelineError::Gpu` naming the
//! call. Known deviations, each documented where it is handled:
//! - ARB_shadow_ambient's fail value is recorded in the model and not sent (Mesa lacks the
//!   extension): a failed compare reads 0 here;
//! - NV_register_combiners has no native path: a draw with it enabled is `Unsupported`;
//! - Mesa's texture-matrix pop bug is worked around by re-loading the matrix after a pop.

pub mod bindings;
mod conv;
mod draw;
mod execute;
mod lighting;
mod readback;
mod texenv;
mod textures;

use std::collections::HashMap;

use glow::HasContext;

use crate::ff::{Command, FixedState, GlError};
use crate::gpu::{GpuContext, Profile};

use super::{Counters, Pipeline, PipelineError, PipelineKind, Readback};

/// The legacy entry points of one compatibility context.
pub struct NativeGl {
    gl: bindings::Gl,
}

impl NativeGl {
    /// Loads the entry points of `ctx`; `None` for a core-profile context, which has no
    /// fixed function to call.
    pub fn load(ctx: &GpuContext) -> Option<NativeGl> {
        if ctx.profile() != Profile::Compatibility {
            return None;
        }
        let gl = bindings::Gl::load_with(|name| ctx.proc_address(name));
        Some(NativeGl { gl })
    }

    /// The raw generated bindings.
    pub fn raw(&self) -> &bindings::Gl {
        &self.gl
    }
}

/// Commands executed by Mesa's fixed-function pipeline.
pub struct NativePipeline {
    gl: NativeGl,
    state: FixedState,
    textures: textures::Textures,
    readbacks: HashMap<u32, Readback>,
    counters: Counters,
}

impl NativePipeline {
    /// A pipeline on `ctx`, which must be a current compatibility context.
    pub fn new(ctx: &GpuContext) -> Result<NativePipeline, PipelineError> {
        let gl = NativeGl::load(ctx).ok_or(PipelineError::WrongProfile {
            path: "native",
            needs: Profile::Compatibility.name(),
            got: ctx.profile().name(),
        })?;
        Ok(NativePipeline {
            gl,
            state: FixedState::new(),
            textures: textures::Textures::default(),
            readbacks: HashMap::new(),
            counters: Counters::default(),
        })
    }

    /// How many GL texture objects the pipeline holds.
    pub fn texture_objects(&self) -> usize {
        self.textures.len()
    }

    /// Unbinds what would redirect the legacy calls: a program (the fixed function runs only
    /// with program 0), a vertex array object and buffers (client arrays and pixel pointers
    /// must be client memory). Errors raised before this call are not ours: drained.
    fn prepare(ctx: &GpuContext) {
        let gl = ctx.gl();
        // SAFETY: plain GL calls on the current context.
        unsafe {
            while gl.get_error() != glow::NO_ERROR {}
            gl.use_program(None);
            gl.bind_vertex_array(None);
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
            gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, None);
            gl.bind_buffer(glow::PIXEL_PACK_BUFFER, None);
            gl.bind_buffer(glow::PIXEL_UNPACK_BUFFER, None);
        }
    }
}

impl Pipeline for NativePipeline {
    fn kind(&self) -> PipelineKind {
        PipelineKind::Native
    }

    fn execute(&mut self, ctx: &GpuContext, commands: &[Command]) -> Result<(), PipelineError> {
        Self::prepare(ctx);
        for cmd in commands {
            self.counters.commands += 1;
            let cmd = super::resolve_readback(cmd, &self.readbacks)?;
            // A rejected command has no effect on GL (GL 1.5 §2.5): nothing is sent.
            if self.state.apply(&cmd).is_err() {
                continue;
            }
            self.issue(&cmd)?;
            ctx.check_error(execute::gl_call(&cmd))?;
        }
        Ok(())
    }

    fn readback(&self, slot: u32) -> Option<&Readback> {
        self.readbacks.get(&slot)
    }

    fn state(&self) -> &FixedState {
        &self.state
    }

    fn take_gl_error(&mut self) -> Option<GlError> {
        self.state.take_error()
    }

    fn counters(&self) -> Counters {
        self.counters
    }

    fn release(&mut self, _ctx: &GpuContext) {
        self.textures.delete_all(self.gl.raw());
    }
}
