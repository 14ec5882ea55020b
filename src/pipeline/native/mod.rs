//! The native path: the same Commands as real legacy GL calls on a compatibility context —
//! Mesa's own fixed-function implementation, the oracle the emulated path is checked against.

pub mod bindings;

use crate::gpu::{GpuContext, Profile};

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
