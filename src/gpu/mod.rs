//! The only layer that creates GL contexts.
//!
//! Three backends, one `GpuContext`:
//! - `Backend::Egl` (the default): Mesa's `EGL_MESA_platform_surfaceless`, loaded at run time
//!   through khronos-egl; when that platform is missing, the `EGL_EXT_platform_device`
//!   platform. No window system: rendering goes to framebuffer objects, or into a pbuffer
//!   surface the C library binds (`GpuContext::bind_window_surface`).
//! - `Backend::OsMesa`: `libOSMesa.so.8` through libloading (`OSMesaCreateContextAttribs`).
//!   The context gets a 1×1 client buffer it never draws to; rendering goes to FBOs, so the
//!   same frame reads back identically on both headless backends. The exception: a
//!   [`WindowBuffer`] request, a window-sized buffer with an accumulation buffer that the
//!   native path's glAccum draws into (Mesa gives FBOs none).
//! - `Backend::Window`: glutin + winit on X11, a real window that can present a rendered
//!   target (a framebuffer blit) and save what it shows.
//!
//! Each backend gives either profile: `Profile::Core33` for the emulated pipeline,
//! `Profile::Compatibility` for Mesa's native fixed-function path (the oracle).
//! A library that does not load is a `GpuError::LibraryMissing` naming the Debian package.

mod conv;
mod egl;
mod error;
mod info;
mod osmesa;
mod raster_threads;
mod readback;
mod target;
mod trivial;
#[cfg(feature = "window")]
mod window;
mod window_input;
mod xvfb;

use std::fmt;
use std::str::FromStr;

use glow::HasContext;

use crate::vocab::Named;

pub use egl::{EglPlatform, PbufferSpec};
pub use error::GpuError;
pub use info::{ContextInfo, DepthReport, ExtensionReport, Limits, SHADOW_EXTENSIONS};
pub use osmesa::WindowBuffer;
pub use raster_threads::{RasterPlacement, ThreadsBefore};
pub use readback::{depth_to_u16, depth_to_u32, depth_to_u8};
pub use target::{ColorStorage, DepthStencilBuffers, RenderTarget, TargetSpec};
pub use trivial::FlatProgram;
pub use window_input::{Input, KeyName, Waker};
pub use xvfb::{await_ending_signal, ending, mark_ending, stop_private_displays, VirtualDisplay};

/// Which library provides the context.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Backend {
    /// EGL, surfaceless platform (device platform as a fallback). The default.
    Egl,
    /// OSMesa (`libOSMesa.so.8`; removed from Mesa 25.1).
    OsMesa,
    /// A glutin window on X11 (needs a display, e.g. Xvfb).
    Window,
}

impl Backend {
    pub const ALL: [Backend; 3] = [Backend::Egl, Backend::OsMesa, Backend::Window];

    pub fn name(self) -> &'static str {
        Named::name(self)
    }
}

impl Named for Backend {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("egl", Backend::Egl),
        ("osmesa", Backend::OsMesa),
        ("window", Backend::Window),
    ];

    fn help(self) -> &'static str {
        match self {
            Backend::Egl => "EGL, surfaceless platform (device platform as a fallback)",
            Backend::OsMesa => "OSMesa (libOSMesa.so.8; removed from Mesa 25.1)",
            Backend::Window => "a glutin window on X11 (needs a display, e.g. Xvfb)",
        }
    }
}

impl fmt::Display for Backend {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Backend {
    type Err = GpuError;
    fn from_str(s: &str) -> Result<Self, GpuError> {
        Backend::all()
            .into_iter()
            .find(|b| b.name().eq_ignore_ascii_case(s))
            .ok_or_else(|| GpuError::UnknownBackend {
                name: s.to_string(),
                valid: Backend::ALL.iter().map(|b| b.name()).collect(),
            })
    }
}

/// Which GL profile a context exposes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Profile {
    /// OpenGL 3.3 core: no fixed function; the emulated pipeline runs here.
    Core33,
    /// The highest compatibility profile the driver offers: Mesa's fixed-function path.
    Compatibility,
}

impl Profile {
    pub const ALL: [Profile; 2] = [Profile::Core33, Profile::Compatibility];

    pub fn name(self) -> &'static str {
        match self {
            Profile::Core33 => "core 3.3",
            Profile::Compatibility => "compatibility",
        }
    }
}

/// What to create. `library` overrides the shared library the backend loads (the default is
/// `libEGL.so.1` or `libOSMesa.so.8`); it exists so that a missing library can be tested.
/// `egl_platform` forces one EGL platform instead of "surfaceless, else device".
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ContextRequest {
    pub backend: Backend,
    pub profile: Profile,
    pub library: Option<String>,
    pub egl_platform: Option<EglPlatform>,
    /// OSMesa only: framebuffer 0 is a window-sized buffer with an accumulation buffer
    /// (`osmesa::WindowBuffer`), for the native path's glAccum.
    pub window: Option<WindowBuffer>,
}

impl ContextRequest {
    pub fn new(backend: Backend, profile: Profile) -> Self {
        ContextRequest {
            backend,
            profile,
            library: None,
            egl_platform: None,
            window: None,
        }
    }

    /// OSMesa with a window-sized client buffer and an accumulation buffer as
    /// framebuffer 0 (the other backends refuse it: their framebuffer 0 is no window).
    pub fn with_window(mut self, window: WindowBuffer) -> Self {
        self.window = Some(window);
        self
    }

    pub fn with_egl_platform(mut self, platform: EglPlatform) -> Self {
        self.egl_platform = Some(platform);
        self
    }

    pub fn with_library(mut self, library: impl Into<String>) -> Self {
        self.library = Some(library.into());
        self
    }
}

/// The backend-specific half of a context: what must stay alive, and how to make it current.
enum Handle {
    Egl(Box<egl::EglContext>),
    OsMesa(osmesa::OsMesaContext),
    #[cfg(feature = "window")]
    Window(Box<window::WindowContext>),
}

/// A live GL context with its function table. Dropping it destroys the context.
pub struct GpuContext {
    // Field order matters: `gl` holds function pointers into the library `handle` owns.
    gl: glow::Context,
    handle: Handle,
    backend: Backend,
    profile: Profile,
    /// How the context was obtained, e.g. "EGL_MESA_platform_surfaceless".
    path: String,
}

impl GpuContext {
    /// Creates a context as requested and makes it current on this thread.
    pub fn new(request: &ContextRequest) -> Result<GpuContext, GpuError> {
        let lib = request.library.as_deref();
        if let (Some(_), Backend::Egl | Backend::Window) = (request.window, request.backend) {
            return Err(GpuError::NoWindowBuffer {
                backend: request.backend,
            });
        }
        let (gl, handle, path) = match request.backend {
            Backend::Egl => {
                let (ctx, gl) =
                    egl::EglContext::create(request.profile, lib, request.egl_platform)?;
                let path = match (request.egl_platform, ctx.platform()) {
                    (None, egl::EglPlatform::Device) => {
                        "EGL_EXT_platform_device (no surfaceless platform)".to_string()
                    }
                    (_, platform) => platform.to_string(),
                };
                (gl, Handle::Egl(Box::new(ctx)), path)
            }
            Backend::OsMesa => {
                let (ctx, gl) =
                    osmesa::OsMesaContext::create(request.profile, lib, request.window)?;
                (
                    gl,
                    Handle::OsMesa(ctx),
                    "OSMesaCreateContextAttribs".to_string(),
                )
            }
            #[cfg(feature = "window")]
            Backend::Window => {
                let (ctx, gl) = window::WindowContext::create(request.profile)?;
                let path = ctx.describe();
                (gl, Handle::Window(Box::new(ctx)), path)
            }
            #[cfg(not(feature = "window"))]
            Backend::Window => {
                return Err(GpuError::NotCompiled {
                    backend: Backend::Window,
                    feature: "window",
                })
            }
        };
        Ok(GpuContext {
            gl,
            handle,
            backend: request.backend,
            profile: request.profile,
            path,
        })
    }

    /// The GL function table. Call [`GpuContext::make_current`] first when several contexts
    /// live on one thread.
    pub fn gl(&self) -> &glow::Context {
        &self.gl
    }

    pub fn backend(&self) -> Backend {
        self.backend
    }

    pub fn profile(&self) -> Profile {
        self.profile
    }

    /// How the context was obtained (the EGL platform, OSMesa, or the window system).
    pub fn path(&self) -> &str {
        &self.path
    }

    /// The address of a GL entry point of this context (null when the driver has none), for
    /// bindings other than glow's (the native pipeline's generated ones).
    pub fn proc_address(&self, name: &str) -> *const std::ffi::c_void {
        match &self.handle {
            Handle::Egl(c) => c.proc_address(name),
            Handle::OsMesa(c) => c.proc_address(name),
            #[cfg(feature = "window")]
            Handle::Window(c) => c.proc_address(name),
        }
    }

    /// Makes this context current on the calling thread.
    pub fn make_current(&self) -> Result<(), GpuError> {
        match &self.handle {
            Handle::Egl(c) => c.make_current(),
            Handle::OsMesa(c) => c.make_current(),
            #[cfg(feature = "window")]
            Handle::Window(c) => c.make_current(),
        }
    }

    /// Makes this context current with a new pbuffer surface of `spec` (EGL only), so that
    /// framebuffer 0 is a window-system framebuffer. Ok(false) when the backend or the
    /// display has no such surface; the context is then as it was.
    pub fn bind_window_surface(&self, spec: PbufferSpec) -> Result<bool, GpuError> {
        match &self.handle {
            Handle::Egl(c) => c.bind_pbuffer(spec),
            _ => Ok(false),
        }
    }

    /// Drops the surface [`bind_window_surface`](Self::bind_window_surface) made; the
    /// context stays current without one.
    pub fn release_window_surface(&self) -> Result<(), GpuError> {
        match &self.handle {
            Handle::Egl(c) => c.release_pbuffer(),
            _ => Ok(()),
        }
    }

    /// glFinish: returns when every command sent so far has completed, so a frame's wall
    /// time includes the driver's work (llvmpipe renders asynchronously).
    pub fn finish(&self) {
        unsafe { self.gl.finish() }
    }

    /// Framebuffer 0's colour (a [`WindowBuffer`]'s) as RGBA8, top row first.
    pub fn read_window_color(&self, width: u32, height: u32) -> Result<image::RgbaImage, GpuError> {
        let mut rows = vec![0u8; 4 * width as usize * height as usize];
        // SAFETY: plain GL calls; `rows` holds width × height RGBA8 pixels, packed.
        unsafe {
            self.gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
            self.gl.read_buffer(glow::FRONT);
            self.gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            self.gl.read_pixels(
                0,
                0,
                width as i32,
                height as i32,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelPackData::Slice(Some(&mut rows)),
            );
        }
        self.check_error("glReadPixels (framebuffer 0)")?;
        let row = 4 * width as usize;
        let flipped: Vec<u8> = rows
            .chunks_exact(row.max(1))
            .rev()
            .flatten()
            .copied()
            .collect();
        image::RgbaImage::from_raw(width, height, flipped).ok_or(GpuError::Object(
            "window readback has the wrong length".into(),
        ))
    }

    /// Reads and clears GL's error flag: `Err` names the call that raised it.
    pub fn check_error(&self, call: &'static str) -> Result<(), GpuError> {
        let code = unsafe { self.gl.get_error() };
        if code == glow::NO_ERROR {
            Ok(())
        } else {
            Err(GpuError::Gl {
                call,
                code,
                name: conv::error_name(code),
            })
        }
    }

    /// Shows a picture made on the CPU (top row first) in the window, sized to it, and
    /// returns what the window shows. Only the window backend has a window.
    pub fn show(&mut self, picture: &image::RgbaImage) -> Result<image::RgbaImage, GpuError> {
        #[cfg(not(feature = "window"))]
        let _ = picture;
        match &mut self.handle {
            #[cfg(feature = "window")]
            Handle::Window(w) => w.show(&self.gl, picture),
            _ => Err(self.no_window()),
        }
    }

    /// Waits for the user's input to the window (see [`Input`]), a [`Waker`], or the
    /// timeout (`None`: none). A headless context has no input and returns at once.
    pub fn wait_input(&mut self, timeout: Option<std::time::Duration>) -> Vec<Input> {
        #[cfg(not(feature = "window"))]
        let _ = timeout;
        match &mut self.handle {
            #[cfg(feature = "window")]
            Handle::Window(w) => w.wait_input(timeout),
            _ => Vec::new(),
        }
    }

    /// What wakes [`wait_input`](Self::wait_input) from another thread.
    pub fn waker(&self) -> Waker {
        match &self.handle {
            #[cfg(feature = "window")]
            Handle::Window(w) => w.waker(),
            _ => Waker {
                #[cfg(feature = "window")]
                proxy: None,
            },
        }
    }

    fn no_window(&self) -> GpuError {
        GpuError::Window {
            detail: format!(
                "the {} backend has no window to present to; use --backend window",
                self.backend
            ),
        }
    }

    /// Presents `target` in the window and returns what the window shows, top row first.
    /// Only the window backend has something to present to.
    pub fn present(&mut self, target: &RenderTarget) -> Result<image::RgbaImage, GpuError> {
        #[cfg(not(feature = "window"))]
        let _ = target;
        match &mut self.handle {
            #[cfg(feature = "window")]
            Handle::Window(w) => w.present(&self.gl, target),
            _ => Err(self.no_window()),
        }
    }
}
