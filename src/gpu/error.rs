//! The gpu layer's one error type. Every variant carries what a user needs to act: the
//! library that did not load and the Debian package that provides it, the EGL call and its
//! error code, the limit a request exceeded.

use super::Backend;
use crate::vocab::DepthBits;

/// Everything that can go wrong while creating a context, a target, or reading pixels back.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    /// A system library could not be loaded at run time.
    #[error(
        "cannot load {library} for the {backend} backend: {reason}\n  install it with: apt-get install {debian_packages}{hint}"
    )]
    LibraryMissing {
        backend: Backend,
        library: String,
        reason: String,
        /// Space-separated Debian package names.
        debian_packages: &'static str,
        /// Extra advice, starting with a newline when present.
        hint: &'static str,
    },
    /// A backend name that is not one of ours.
    #[error("unknown backend `{name}`; valid backends: {}", valid.join(", "))]
    UnknownBackend {
        name: String,
        valid: Vec<&'static str>,
    },
    /// The backend was compiled out (the `window` feature).
    #[error("the {backend} backend is not compiled in: build with `--features {feature}`")]
    NotCompiled {
        backend: Backend,
        feature: &'static str,
    },
    /// A window buffer (framebuffer 0 with an accumulation buffer) asked of a backend whose
    /// framebuffer 0 is no buffer of ours: EGL surfaceless has no window at all.
    #[error("the {backend} backend has no window buffer with an accumulation buffer; use --backend osmesa (Mesa gives framebuffer objects no accumulation buffer)")]
    NoWindowBuffer { backend: Backend },
    /// EGL has neither the surfaceless nor the device platform.
    #[error("EGL offers no headless platform (neither EGL_MESA_platform_surfaceless nor EGL_EXT_platform_device); client extensions: {extensions}\n  install Mesa's EGL: apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri")]
    NoHeadlessPlatform { extensions: String },
    /// An EGL call failed.
    #[error("{call} failed on the EGL {platform} platform: {code}")]
    Egl {
        call: &'static str,
        platform: &'static str,
        code: String,
    },
    /// An OSMesa call failed.
    #[error("{call} failed: {detail}")]
    OsMesa { call: &'static str, detail: String },
    /// The window backend failed (no display, no visual, winit or glutin errors).
    #[error("window backend: {detail}")]
    Window { detail: String },
    /// A render target size outside what the context allows.
    #[error("render target {width}x{height} is impossible: each side must be between 1 and {limit} (GL_MAX_RENDERBUFFER_SIZE of this context)")]
    TargetSize { width: u32, height: u32, limit: u32 },
    /// The framebuffer was not complete after attaching the requested buffers.
    #[error("framebuffer with depth {depth:?} (stencil: {stencil}) is incomplete: status 0x{status:04X}")]
    IncompleteFramebuffer {
        depth: DepthBits,
        stencil: bool,
        status: u32,
    },
    /// A GL object could not be created.
    #[error("GL object creation failed: {0}")]
    Object(String),
    /// A readback rectangle outside the target.
    #[error("readback of {width}x{height} at ({x},{y}) lies outside the {target_width}x{target_height} target")]
    ReadOutside {
        x: u32,
        y: u32,
        width: u32,
        height: u32,
        target_width: u32,
        target_height: u32,
    },
    /// The target has no stencil buffer, but a stencil readback was asked for.
    #[error("this target has no stencil buffer: create it with stencil to read stencil back")]
    NoStencil,
    /// A GL error was raised by a gpu-layer call.
    #[error("GL error 0x{code:04X} ({name}) after {call}")]
    Gl {
        call: &'static str,
        code: u32,
        name: &'static str,
    },
    /// Writing an image failed.
    #[error("cannot write {path}: {reason}")]
    Save { path: String, reason: String },
}
