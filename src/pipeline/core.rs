//! The front end both paths share. A Command reaches GL in the same four steps on either
//! path: it is counted; a `TexData::Readback` is replaced by the bytes of its slot; it is
//! folded into the model (`FixedState::apply`), and a command the model rejects — an invalid
//! enum or value, a stack overflow — records the GL error and sends nothing (GL 1.5 §2.5);
//! an accepted command is then *issued* by the path: real legacy calls (`native`) or the
//! state sync and draws of generated programs (`emulate`). Only that last step differs, so
//! it is the only thing a path implements ([`Issue`]).

use std::collections::HashMap;

use super::{Counters, Pipeline, PipelineError, Readback};
use crate::ff::{Command, FixedState, GlError};
use crate::gpu::GpuContext;
use crate::vocab::PipelineKind;

/// What every path keeps: the model state, the bytes of each ReadPixels by slot, and the
/// counts both paths report the same way.
#[derive(Default)]
pub struct Core {
    pub state: FixedState,
    pub readbacks: HashMap<u32, Readback>,
    pub counters: Counters,
    /// The occlusion queries, on the path's GL.
    pub queries: super::queries::GlQueries,
}

impl Core {
    /// A core whose model starts with the window-sized state GL gives a new context: the
    /// viewport and the scissor box cover the target bound now (GL 1.5 §2.11.1, §4.1.2:
    /// both start as the window; the model knows the window only through GL).
    pub fn for_bound_target(ctx: &GpuContext) -> Core {
        let mut core = Core::default();
        let mut v = [0i32; 4];
        // SAFETY: VIEWPORT writes 4 integers.
        unsafe { glow::HasContext::get_parameter_i32_slice(ctx.gl(), glow::VIEWPORT, &mut v) };
        let _ = core.state.apply(&Command::Viewport(crate::ff::Viewport {
            x: v[0],
            y: v[1],
            width: v[2],
            height: v[3],
        }));
        core.state.framebuffers.window_bits = super::framebuffers::bound_bits(ctx.gl());
        let _ = core.state.apply(&Command::Scissor(crate::ff::ScissorBox {
            x: v[0],
            y: v[1],
            width: v[2],
            height: v[3],
        }));
        core
    }
}

/// One path's half of execution.
pub trait Issue {
    /// Which path this is.
    const KIND: PipelineKind;

    /// Before a list of commands runs (the native path unbinds what would redirect legacy
    /// calls).
    fn begin(&mut self, _ctx: &GpuContext) {}

    /// The GL work of `cmd`, which the model in `core.state` has just accepted.
    fn issue(
        &mut self,
        ctx: &GpuContext,
        core: &mut Core,
        cmd: &Command,
    ) -> Result<(), PipelineError>;

    /// The core's counters with what only this path counts added.
    fn counters(&self, core: &Counters) -> Counters {
        *core
    }

    /// Deletes every GL object the path made.
    fn release(&mut self, ctx: &GpuContext);
}

/// A [`Pipeline`] made of the shared front end and one path's [`Issue`].
pub struct PathPipeline<P: Issue> {
    pub(crate) core: Core,
    pub(crate) path: P,
}

impl<P: Issue> PathPipeline<P> {
    pub(crate) fn from_parts(core: Core, path: P) -> Self {
        PathPipeline { core, path }
    }

    /// Takes the bytes of readback slot `slot` out (the C library's caller slot is filled
    /// anew by each glReadPixels or glGetTexImage that stores something).
    pub fn take_readback(&mut self, slot: u32) -> Option<Readback> {
        self.core.readbacks.remove(&slot)
    }

    /// glBitmap: drawn at the raster position the call finds, then the position advances
    /// (GL 1.5 §3.7). The model applies the call (errors, the advance, which is all it
    /// changes); the path then draws it with the position from before, so the bitmap lands
    /// where the call found it whatever the advance (a fractional or NaN one included).
    fn bitmap(&mut self, ctx: &GpuContext, cmd: &Command) -> Result<(), PipelineError> {
        let found = self.core.state.raster.window;
        if self.core.state.apply(cmd).is_err() {
            return Ok(());
        }
        let advanced = std::mem::replace(&mut self.core.state.raster.window, found);
        let drawn = self.path.issue(ctx, &mut self.core, cmd);
        self.core.state.raster.window = advanced;
        drawn
    }
}

impl<P: Issue> Pipeline for PathPipeline<P> {
    fn kind(&self) -> PipelineKind {
        P::KIND
    }

    fn execute(&mut self, ctx: &GpuContext, commands: &[Command]) -> Result<(), PipelineError> {
        self.path.begin(ctx);
        for cmd in commands {
            self.core.counters.commands += 1;
            let cmd = super::resolve_readback(cmd, &self.core.readbacks)?;
            if let Command::Bitmap(_) = cmd.as_ref() {
                self.bitmap(ctx, &cmd)?;
                continue;
            }
            if self.core.state.apply(&cmd).is_err() {
                continue;
            }
            if let Command::Query(q) = cmd.as_ref() {
                self.core.queries.issue(ctx, q)?;
                continue;
            }
            self.path.issue(ctx, &mut self.core, &cmd)?;
        }
        Ok(())
    }

    fn readback(&self, slot: u32) -> Option<&Readback> {
        self.core.readbacks.get(&slot)
    }

    fn state(&self) -> &FixedState {
        &self.core.state
    }

    fn take_gl_error(&mut self) -> Option<GlError> {
        self.core.state.take_error()
    }

    fn counters(&self) -> Counters {
        self.path.counters(&self.core.counters)
    }

    fn query_result(
        &mut self,
        ctx: &GpuContext,
        id: u32,
        what: super::queries::QueryFetch,
    ) -> Option<u64> {
        self.core.queries.fetch(ctx, id, what)
    }

    fn release(&mut self, ctx: &GpuContext) {
        self.core.queries.release(ctx);
        self.path.release(ctx);
    }
}
