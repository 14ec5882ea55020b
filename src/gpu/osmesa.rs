//! OSMesa, loaded at run time from `libOSMesa.so.8` (Debian: `libosmesa6`). OSMesa was
//! removed from Mesa 25.1; on newer systems use the EGL backend.
//!
//! `OSMesaCreateContextAttribs` gives a core 3.3 or a compatibility context. OSMesa needs a
//! client buffer to make a context current; ours is 1×1 and never drawn to — every frame goes
//! to a framebuffer object, exactly as on EGL, so both backends read back the same pixels.
//!
//! The one exception is the native path's accumulation buffer: Mesa gives framebuffer
//! objects none, so the oracle of glAccum draws into OSMesa's own buffer. A
//! [`WindowBuffer`] request makes the client buffer window-sized, with 24 depth, 8 stencil
//! and 16 accumulation bits per channel (`OSMESA_ACCUM_BITS`), and framebuffer 0 is then a
//! window GL draws to.

use std::ffi::{c_char, c_int, c_uint, c_void, CString};

use libloading::Library;

use super::{Backend, GpuError, Profile};

const DEFAULT_LIBRARY: &str = "libOSMesa.so.8";

// osmesa.h
const OSMESA_FORMAT: c_int = 0x22;
const OSMESA_RGBA: c_int = 0x1908;
const OSMESA_DEPTH_BITS: c_int = 0x30;
const OSMESA_STENCIL_BITS: c_int = 0x31;
const OSMESA_ACCUM_BITS: c_int = 0x32;
const OSMESA_PROFILE: c_int = 0x33;
const OSMESA_CORE_PROFILE: c_int = 0x34;
const OSMESA_COMPAT_PROFILE: c_int = 0x35;
const OSMESA_CONTEXT_MAJOR_VERSION: c_int = 0x36;
const OSMESA_CONTEXT_MINOR_VERSION: c_int = 0x37;
const GL_UNSIGNED_BYTE: c_uint = 0x1401;

/// A window-sized client buffer that framebuffer 0 draws to, with an accumulation buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WindowBuffer {
    pub width: u32,
    pub height: u32,
}

/// Accumulation bits per channel of a [`WindowBuffer`] (Mesa's OSMesa: signed 16-bit).
const WINDOW_ACCUM_BITS: c_int = 16;

type RawContext = *mut c_void;
type CreateContextAttribs = unsafe extern "C" fn(*const c_int, RawContext) -> RawContext;
type MakeCurrent = unsafe extern "C" fn(RawContext, *mut c_void, c_uint, c_int, c_int) -> u8;
type DestroyContext = unsafe extern "C" fn(RawContext);
type GetProcAddress = unsafe extern "C" fn(*const c_char) -> *const c_void;

pub struct OsMesaContext {
    context: RawContext,
    make_current: MakeCurrent,
    destroy: DestroyContext,
    get_proc: GetProcAddress,
    /// The client buffer OSMesa requires: 1×1 and never rendered to, or the window's.
    buffer: Vec<u8>,
    width: c_int,
    height: c_int,
    // Last: the function pointers above point into it.
    _library: Library,
}

fn symbol<T: Copy>(library: &Library, name: &'static str) -> Result<T, GpuError> {
    // SAFETY: each call site names the symbol's C signature as `T`.
    unsafe { library.get::<T>(name.as_bytes()) }
        .map(|s| *s)
        .map_err(|e| GpuError::OsMesa {
            call: name,
            detail: format!("symbol missing from libOSMesa: {e}"),
        })
}

impl OsMesaContext {
    pub fn create(
        profile: Profile,
        library: Option<&str>,
        window: Option<WindowBuffer>,
    ) -> Result<(OsMesaContext, glow::Context), GpuError> {
        let name = library.unwrap_or(DEFAULT_LIBRARY);
        // SAFETY: loading libOSMesa runs Mesa's initialisers, which have no preconditions.
        let library = unsafe { Library::new(name) }.map_err(|e| GpuError::LibraryMissing {
            backend: Backend::OsMesa,
            library: name.to_string(),
            reason: e.to_string(),
            debian_packages: "libosmesa6",
            hint: "\n  note: OSMesa was removed from Mesa 25.1; on newer systems use --backend egl",
        })?;
        let create: CreateContextAttribs = symbol(&library, "OSMesaCreateContextAttribs")?;
        let make_current: MakeCurrent = symbol(&library, "OSMesaMakeCurrent")?;
        let destroy: DestroyContext = symbol(&library, "OSMesaDestroyContext")?;
        let get_proc: GetProcAddress = symbol(&library, "OSMesaGetProcAddress")?;

        let (profile_value, major, minor) = match profile {
            Profile::Core33 => (OSMESA_CORE_PROFILE, 3, 3),
            // Mesa grants the highest compatibility version it has for 1.0.
            Profile::Compatibility => (OSMESA_COMPAT_PROFILE, 1, 0),
        };
        let (depth, stencil, accum, width, height) = match window {
            None => (0, 0, 0, 1, 1),
            Some(w) => {
                let side = |v: u32| c_int::try_from(v).ok().filter(|v| (1..=16384).contains(v));
                let (Some(width), Some(height)) = (side(w.width), side(w.height)) else {
                    return Err(GpuError::OsMesa {
                        call: "OSMesaMakeCurrent",
                        detail: format!("a {}x{} buffer (1 to 16384 a side)", w.width, w.height),
                    });
                };
                (24, 8, WINDOW_ACCUM_BITS, width, height)
            }
        };
        let attribs = [
            OSMESA_FORMAT,
            OSMESA_RGBA,
            OSMESA_DEPTH_BITS,
            depth,
            OSMESA_STENCIL_BITS,
            stencil,
            OSMESA_ACCUM_BITS,
            accum,
            OSMESA_PROFILE,
            profile_value,
            OSMESA_CONTEXT_MAJOR_VERSION,
            major,
            OSMESA_CONTEXT_MINOR_VERSION,
            minor,
            0,
        ];
        // SAFETY: a zero-terminated attribute list and no share context.
        let context = unsafe { create(attribs.as_ptr(), std::ptr::null_mut()) };
        if context.is_null() {
            return Err(GpuError::OsMesa {
                call: "OSMesaCreateContextAttribs",
                detail: format!("no {} context", profile.name()),
            });
        }
        let ctx = OsMesaContext {
            context,
            make_current,
            destroy,
            get_proc,
            buffer: vec![0; 4 * width as usize * height as usize],
            width,
            height,
            _library: library,
        };
        ctx.make_current()?;
        // SAFETY: the context is current; OSMesaGetProcAddress returns its entry points.
        let gl = unsafe { glow::Context::from_loader_function(|name| ctx.proc_address(name)) };
        Ok((ctx, gl))
    }

    pub fn proc_address(&self, name: &str) -> *const c_void {
        match CString::new(name) {
            // SAFETY: a NUL-terminated name; OSMesaGetProcAddress only reads it.
            Ok(c) => unsafe { (self.get_proc)(c.as_ptr()) },
            Err(_) => std::ptr::null(),
        }
    }

    pub fn make_current(&self) -> Result<(), GpuError> {
        // SAFETY: the buffer is width × height RGBA8 and lives as long as the context.
        let ok = unsafe {
            (self.make_current)(
                self.context,
                self.buffer.as_ptr() as *mut c_void,
                GL_UNSIGNED_BYTE,
                self.width,
                self.height,
            )
        };
        if ok == 0 {
            return Err(GpuError::OsMesa {
                call: "OSMesaMakeCurrent",
                detail: "the context could not be made current".into(),
            });
        }
        Ok(())
    }
}

impl Drop for OsMesaContext {
    fn drop(&mut self) {
        // SAFETY: the context was created by this library and is destroyed once.
        unsafe { (self.destroy)(self.context) };
    }
}
