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
pub mod vertex_calls;

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

/// This thread's contexts: the one OSMesaMakeCurrent made current, and the one whose EGL
/// context is current (creating a context makes its EGL context current; the GL calls
/// then restore the OSMesa one). One thread-local, read once per call.
struct ThreadContexts {
    osmesa: Cell<*mut Context>,
    gl: Cell<*mut Context>,
}

thread_local! {
    static CURRENT: ThreadContexts = const {
        ThreadContexts {
            osmesa: Cell::new(std::ptr::null_mut()),
            gl: Cell::new(std::ptr::null_mut()),
        }
    };
}

pub(crate) fn current() -> *mut Context {
    CURRENT.with(|c| c.osmesa.get())
}

pub(crate) fn set_current(ctx: *mut Context) {
    CURRENT.with(|c| c.osmesa.set(ctx));
}

/// Makes `ctx`'s EGL context current on this thread unless it already is.
pub(crate) fn ensure_gl_current(ctx: *mut Context) -> bool {
    if CURRENT.with(|c| c.gl.get()) == ctx {
        return true;
    }
    make_gl_current(ctx)
}

fn make_gl_current(ctx: *mut Context) -> bool {
    // SAFETY: `ctx` is a live context (OSMesaDestroyContext clears both thread-locals).
    let ok = unsafe { (*ctx).make_gl_current() };
    if ok {
        note_gl_current(ctx);
    }
    ok
}

pub(crate) fn forget_gl_current(ctx: *mut Context) {
    CURRENT.with(|c| {
        if c.gl.get() == ctx {
            c.gl.set(std::ptr::null_mut())
        }
    });
}

pub(crate) fn note_gl_current(ctx: *mut Context) {
    CURRENT.with(|c| c.gl.set(ctx));
}

/// One GL call from C on the current context; nothing without one (GL's calls have no
/// effect without a current context).
pub(crate) fn dispatch(entry: Entry, args: &[CArg]) -> Ret {
    let (ctx, gl) = CURRENT.with(|c| (c.osmesa.get(), c.gl.get()));
    if ctx.is_null() || (gl != ctx && !make_gl_current(ctx)) {
        return Ret::None;
    }
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: the current context is live and used by this thread only.
        let ctx = unsafe { &mut *ctx };
        if ctx.attribute_in_pair(entry, args) {
            Ret::Enum(0)
        } else {
            ctx.call(entry, args)
        }
    }));
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
