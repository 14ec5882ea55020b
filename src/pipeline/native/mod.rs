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
//! - Mesa's texture-matrix pop bug is worked around by re-loading the matrix after a pop;
//! - Mesa's nested glPopAttrib bug is worked around by sending the popped groups again.

pub mod bindings;
mod conv;
mod draw;
mod execute;
mod lighting;
mod pixels;
mod readback;
mod texenv;
mod texture_calls;
mod texture_volume;
mod textures;

use glow::HasContext;

use crate::ff::Command;
use crate::gpu::{GpuContext, Profile};
use crate::vocab::PipelineKind;

use super::core::{Core, Issue, PathPipeline};
use super::framebuffers::FramebufferMirror;
use super::PipelineError;

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

/// The native path's half of execution: the legacy entry points and the texture objects
/// made through them.
pub struct Native {
    gl: NativeGl,
    textures: textures::Textures,
    framebuffers: FramebufferMirror,
    /// The masks of the glPushAttrib calls issued and not yet popped.
    attrib_masks: Vec<crate::ff::AttribMask>,
}

/// Commands executed by Mesa's fixed-function pipeline.
pub type NativePipeline = PathPipeline<Native>;

impl NativePipeline {
    /// A pipeline on `ctx`, which must be a current compatibility context.
    pub fn new(ctx: &GpuContext) -> Result<NativePipeline, PipelineError> {
        let gl = NativeGl::load(ctx).ok_or(PipelineError::WrongProfile {
            path: "native",
            needs: Profile::Compatibility.name(),
            got: ctx.profile().name(),
        })?;
        let path = Native {
            gl,
            textures: textures::Textures::default(),
            framebuffers: FramebufferMirror::new(false),
            attrib_masks: Vec::new(),
        };
        // The model's viewport and scissor box start as GL's (the bound target), as on the
        // emulated path: a glPopAttrib(VIEWPORT_BIT) sends the model's viewport back.
        let core = Core::for_bound_target(ctx);
        Ok(PathPipeline::from_parts(core, path))
    }

    /// A pipeline drawing into framebuffer 0 of `ctx` and its accumulation buffer: the
    /// oracle of glAccum, since Mesa gives framebuffer objects no accumulation buffer. Only
    /// an OSMesa context made with a window buffer (`gpu::WindowBuffer`) has one; on any
    /// other, [`PipelineError::NoAccumBuffer`] names the backend to use. Binds
    /// framebuffer 0.
    pub fn with_window_accum(ctx: &GpuContext) -> Result<NativePipeline, PipelineError> {
        let gl = ctx.gl();
        // SAFETY: plain GL calls on the current context.
        unsafe { gl.bind_framebuffer(glow::FRAMEBUFFER, None) };
        let mut pipeline = Self::new(ctx)?;
        // SAFETY: ACCUM_RED_BITS is one integer (compatibility profile, checked above).
        let bits = unsafe { gl.get_parameter_i32(bindings::ACCUM_RED_BITS) };
        let bits = u8::try_from(bits).unwrap_or(0);
        if bits == 0 {
            return Err(PipelineError::NoAccumBuffer {
                backend: ctx.backend(),
            });
        }
        pipeline.core.state.framebuffers.window_accum_bits = bits;
        Ok(pipeline)
    }

    /// How many GL texture objects the pipeline holds.
    pub fn texture_objects(&self) -> usize {
        self.path.textures.len()
    }
}

impl Issue for Native {
    const KIND: PipelineKind = PipelineKind::Native;

    /// Unbinds what would redirect the legacy calls: a program (the fixed function runs only
    /// with program 0), a vertex array object and buffers (client arrays and pixel pointers
    /// must be client memory). Errors raised before this call are not ours: drained.
    fn begin(&mut self, ctx: &GpuContext) {
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

    /// The legacy calls of `cmd`; a GL error the model did not raise means the two disagree,
    /// and stops execution naming the call.
    fn issue(
        &mut self,
        ctx: &GpuContext,
        core: &mut Core,
        cmd: &Command,
    ) -> Result<(), PipelineError> {
        let textures = &self.textures;
        let handled = self
            .framebuffers
            .issue(ctx.gl(), &core.state, cmd, &mut |_, n| textures.id(n))?;
        if !handled {
            if super::framebuffers::uses_framebuffer(cmd) {
                self.framebuffers.sync(ctx.gl(), &core.state)?;
            }
            self.issue_calls(core, cmd)?;
        }
        ctx.check_error(execute::gl_call(cmd))?;
        Ok(())
    }

    fn release(&mut self, ctx: &GpuContext) {
        self.framebuffers.release(ctx.gl());
        self.textures.delete_all(self.gl.raw());
    }
}
