//! The C library: the OSMesa API and the GL 1.x entry points, exported with C linkage from
//! the `cdylib` this crate builds (soname `libOSMesa.so.8`, see `fixedfunc osmesa-dir`), so
//! that an unmodified program written for Mesa's OSMesa runs on the layer.
//!
//! - [`osmesa`]: OSMesaCreateContext… OSMesaGetProcAddress. Each OSMesa context is an EGL
//!   surfaceless core 3.3 context running the emulated pipeline ([`context`]); one context
//!   is current per thread.
//! - [`exports`]: one C function per row of the entry-point table (`ff::api`), expanded
//!   from the table itself. Each converts its arguments ([`cargs`]) with the converters the
//!   script reader uses (`ff::calls`, `ff::immediate`) and executes the Commands on the
//!   current context's pipeline. What only a C program can receive is answered here:
//!   glGetError's flag, glGetString's strings, glGenTextures' names, the image at
//!   glFinish; queries and pixel storage are the shared front end's (`ff::front_state`).
//! - [`trace`]: with `FIXEDFUNC_TRACE=calls.c`, every executed call as the script
//!   dialect, replayable with `fixedfunc replay`.
//! - No Rust panic crosses the boundary: one is caught, printed on stderr, and recorded as
//!   GL_INVALID_OPERATION.

#[cfg(test)]
mod buffer_tests;
pub mod cargs;
pub mod context;
pub mod exports;
pub mod framebuffers;
pub mod osmesa;
pub mod strings;
pub mod trace;

use std::cell::Cell;
use std::panic::{catch_unwind, AssertUnwindSafe};

use crate::ff::api::Entry;
use crate::ff::GlErrorKind;

use self::cargs::CArg;
use self::context::{Context, Ret};

/// Why a context could not be made.
#[derive(Debug, thiserror::Error)]
pub enum AbiError {
    #[error(transparent)]
    Gpu(#[from] crate::gpu::GpuError),
    #[error(transparent)]
    Pipeline(#[from] crate::pipeline::PipelineError),
}

thread_local! {
    /// The context OSMesaMakeCurrent made current on this thread.
    static CURRENT: Cell<*mut Context> = const { Cell::new(std::ptr::null_mut()) };
    /// The context whose EGL context is current on this thread (creating a context makes
    /// its EGL context current; the GL calls then restore the OSMesa one).
    static GL_CURRENT: Cell<*mut Context> = const { Cell::new(std::ptr::null_mut()) };
}

pub(crate) fn current() -> *mut Context {
    CURRENT.with(Cell::get)
}

pub(crate) fn set_current(ctx: *mut Context) {
    CURRENT.with(|c| c.set(ctx));
}

/// Makes `ctx`'s EGL context current on this thread unless it already is.
pub(crate) fn ensure_gl_current(ctx: *mut Context) -> bool {
    if GL_CURRENT.with(Cell::get) == ctx {
        return true;
    }
    // SAFETY: `ctx` is a live context (OSMesaDestroyContext clears both thread-locals).
    let ok = unsafe { (*ctx).make_gl_current() };
    if ok {
        GL_CURRENT.with(|c| c.set(ctx));
    }
    ok
}

pub(crate) fn forget_gl_current(ctx: *mut Context) {
    GL_CURRENT.with(|c| {
        if c.get() == ctx {
            c.set(std::ptr::null_mut())
        }
    });
}

pub(crate) fn note_gl_current(ctx: *mut Context) {
    GL_CURRENT.with(|c| c.set(ctx));
}

/// One GL call from C on the current context; nothing without one (GL's calls have no
/// effect without a current context).
pub(crate) fn dispatch(entry: Entry, args: &[CArg]) -> Ret {
    let ctx = current();
    if ctx.is_null() || !ensure_gl_current(ctx) {
        return Ret::None;
    }
    // SAFETY: the current context is live and used by this thread only.
    let outcome = catch_unwind(AssertUnwindSafe(|| unsafe { (*ctx).call(entry, args) }));
    match outcome {
        Ok(r) => r,
        Err(panic) => {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            eprintln!(
                "fixedfunc: internal error in {entry}: {what}; recorded GL_INVALID_OPERATION"
            );
            // SAFETY: as above.
            let _ = catch_unwind(AssertUnwindSafe(|| unsafe {
                (*ctx).record_error(GlErrorKind::InvalidOperation)
            }));
            Ret::None
        }
    }
}
