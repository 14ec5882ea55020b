//! The OSMesa API of Mesa's `GL/osmesa.h`, with Mesa's semantics: a context is made with a
//! colour format and depth/stencil bits, made current with the caller's buffer, and the
//! image is in that buffer after glFinish or glFlush. Several contexts may exist; one is
//! current per thread.
//!
//! Refusals follow Mesa (a null context, a null buffer, a size outside 1…OSMESA_MAX_WIDTH,
//! a type other than GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or GL_FLOAT: OSMesaMakeCurrent
//! returns GL_FALSE), and each prints
//! why on stderr, since a C program only sees the GL_FALSE.
#![allow(clippy::missing_safety_doc, non_snake_case)]

use std::collections::HashMap;
use std::ffi::{c_char, c_void, CStr};

use super::context::{ClientBuffer, ColorFormat, ColorType, Context, MAX_SIZE};
use crate::ff::api::ctypes::*;

const OSMESA_ROW_LENGTH: GLint = 0x10;
const OSMESA_Y_UP: GLint = 0x11;
const OSMESA_WIDTH: GLint = 0x20;
const OSMESA_HEIGHT: GLint = 0x21;
const OSMESA_FORMAT: GLint = 0x22;
const OSMESA_TYPE: GLint = 0x23;
const OSMESA_MAX_WIDTH: GLint = 0x24;
const OSMESA_MAX_HEIGHT: GLint = 0x25;
const OSMESA_DEPTH_BITS: i32 = 0x30;
const OSMESA_STENCIL_BITS: i32 = 0x31;
const OSMESA_ACCUM_BITS: i32 = 0x32;
const OSMESA_PROFILE: i32 = 0x33;
const OSMESA_CORE_PROFILE: i32 = 0x34;
const OSMESA_COMPAT_PROFILE: i32 = 0x35;
const OSMESA_CONTEXT_MAJOR_VERSION: i32 = 0x36;
const OSMESA_CONTEXT_MINOR_VERSION: i32 = 0x37;

/// The opaque handle C programs hold.
pub type OSMesaContext = *mut Context;

fn refuse(why: &str) -> OSMesaContext {
    eprintln!("fixedfunc: {why}");
    std::ptr::null_mut()
}

fn create(format: GLenum, depth: GLint, stencil: GLint, accum: GLint) -> OSMesaContext {
    let Some(format) = ColorFormat::from_osmesa(format) else {
        return refuse(&format!(
            "OSMesaCreateContext: format {format:#x} is not one of OSMESA_RGBA, OSMESA_BGRA, \
             OSMESA_ARGB, OSMESA_RGB, OSMESA_BGR, OSMESA_RGB_565"
        ));
    };
    // Creating the EGL context makes it current on this thread.
    let previous = super::current();
    match std::panic::catch_unwind(|| Context::new(format, depth, stencil, accum)) {
        Ok(Ok(ctx)) => {
            let ptr = Box::into_raw(Box::new(ctx));
            super::note_gl_current(ptr);
            if !previous.is_null() {
                super::ensure_gl_current(previous);
            }
            ptr
        }
        Ok(Err(e)) => refuse(&format!("OSMesaCreateContext: {e}")),
        Err(_) => refuse("OSMesaCreateContext: internal error"),
    }
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaCreateContext(
    format: GLenum,
    _sharelist: OSMesaContext,
) -> OSMesaContext {
    // Mesa's default buffers: 24 depth bits, 8 stencil bits.
    create(format, 24, 8, 0)
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaCreateContextExt(
    format: GLenum,
    depth_bits: GLint,
    stencil_bits: GLint,
    accum_bits: GLint,
    _sharelist: OSMesaContext,
) -> OSMesaContext {
    create(format, depth_bits, stencil_bits, accum_bits)
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaCreateContextAttribs(
    attrib_list: *const i32,
    _sharelist: OSMesaContext,
) -> OSMesaContext {
    // Mesa's defaults: no depth, stencil or accumulation buffer unless asked.
    let (mut format, mut depth, mut stencil, mut accum) = (ColorFormat::RGBA, 0, 0, 0);
    let (mut major, mut minor) = (1, 0);
    let mut k = 0;
    while !attrib_list.is_null() {
        // SAFETY: a zero-terminated list of (name, value) pairs (osmesa.h's contract).
        let name = unsafe { *attrib_list.add(k) };
        if name == 0 {
            break;
        }
        let value = unsafe { *attrib_list.add(k + 1) };
        match name {
            OSMESA_FORMAT => format = value as GLenum,
            OSMESA_DEPTH_BITS => depth = value,
            OSMESA_STENCIL_BITS => stencil = value,
            OSMESA_ACCUM_BITS => accum = value,
            OSMESA_PROFILE => {
                if value == OSMESA_CORE_PROFILE {
                    return refuse(
                        "OSMesaCreateContextAttribs: OSMESA_CORE_PROFILE asked; this library \
                         implements the GL 1.5 fixed-function pipeline (OSMESA_COMPAT_PROFILE)",
                    );
                }
                if value != OSMESA_COMPAT_PROFILE {
                    return refuse("OSMesaCreateContextAttribs: unknown OSMESA_PROFILE value");
                }
            }
            OSMESA_CONTEXT_MAJOR_VERSION => major = value,
            OSMESA_CONTEXT_MINOR_VERSION => minor = value,
            _ => {
                return refuse(&format!(
                    "OSMesaCreateContextAttribs: unknown attribute {name:#x}"
                ))
            }
        }
        k += 2;
    }
    if (major, minor) > (1, 5) {
        return refuse(&format!(
            "OSMesaCreateContextAttribs: version {major}.{minor} asked; this library \
             implements OpenGL 1.5"
        ));
    }
    create(format, depth, stencil, accum)
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaDestroyContext(ctx: OSMesaContext) {
    if ctx.is_null() {
        return;
    }
    let previous = super::current();
    if super::ensure_gl_current(ctx) {
        // SAFETY: a context made by OSMesaCreateContext and not yet destroyed.
        unsafe { (*ctx).release() };
    }
    super::forget_gl_current(ctx);
    if previous == ctx {
        super::set_current(std::ptr::null_mut());
    }
    // SAFETY: as above; the box is dropped once.
    drop(unsafe { Box::from_raw(ctx) });
    if !previous.is_null() && previous != ctx {
        super::ensure_gl_current(previous);
    }
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaMakeCurrent(
    ctx: OSMesaContext,
    buffer: *mut c_void,
    ty: GLenum,
    width: GLsizei,
    height: GLsizei,
) -> GLboolean {
    // OSMesaMakeCurrent(NULL, NULL, …): no context is current any more (Mesa's release,
    // which flushes the old context first); GL calls then do nothing.
    if ctx.is_null() && buffer.is_null() {
        let previous = super::current();
        if !previous.is_null() && super::ensure_gl_current(previous) {
            // SAFETY: a live context.
            unsafe { (*previous).write_back() };
        }
        super::set_current(std::ptr::null_mut());
        return 1;
    }
    if ctx.is_null() || buffer.is_null() {
        return 0;
    }
    if !(1..=MAX_SIZE).contains(&width) || !(1..=MAX_SIZE).contains(&height) {
        eprintln!("fixedfunc: OSMesaMakeCurrent: size {width}×{height} outside 1…{MAX_SIZE}");
        return 0;
    }
    let Some(color_type) = ColorType::from_gl(ty) else {
        eprintln!(
            "fixedfunc: OSMesaMakeCurrent: type {ty:#x}; this library writes GL_UNSIGNED_BYTE, \
             GL_UNSIGNED_SHORT, GL_FLOAT and (OSMESA_RGB_565) GL_UNSIGNED_SHORT_5_6_5 buffers"
        );
        return 0;
    };
    // SAFETY: a live context (OSMesaMakeCurrent's contract).
    let rgb565 = unsafe { (*ctx).format } == ColorFormat::Rgb565;
    if rgb565 != (color_type == ColorType::UnsignedShort565) {
        eprintln!(
            "fixedfunc: OSMesaMakeCurrent: OSMESA_RGB_565 takes GL_UNSIGNED_SHORT_5_6_5 and \
             GL_UNSIGNED_SHORT_5_6_5 only OSMESA_RGB_565 (type {ty:#x})"
        );
        return 0;
    }
    // The image of the context current before goes to its buffer.
    let previous = super::current();
    if !previous.is_null() && previous != ctx && super::ensure_gl_current(previous) {
        // SAFETY: a live context.
        unsafe { (*previous).write_back() };
    }
    if !super::ensure_gl_current(ctx) {
        eprintln!("fixedfunc: OSMesaMakeCurrent: the EGL context could not be made current");
        return 0;
    }
    let buffer = ClientBuffer {
        ptr: buffer,
        ty,
        width,
        height,
    };
    // SAFETY: a live context, used by this thread.
    match unsafe { (*ctx).bind_buffer(buffer) } {
        Ok(()) => {
            super::set_current(ctx);
            1
        }
        Err(e) => {
            eprintln!("fixedfunc: OSMesaMakeCurrent: {e}");
            0
        }
    }
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaGetCurrentContext() -> OSMesaContext {
    super::current()
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaPixelStore(pname: GLint, value: GLint) {
    let ctx = super::current();
    if ctx.is_null() {
        return;
    }
    // SAFETY: the current context is live.
    let ctx = unsafe { &mut *ctx };
    match pname {
        OSMESA_ROW_LENGTH if value >= 0 => ctx.row_length = value,
        OSMESA_ROW_LENGTH => eprintln!("fixedfunc: OSMesaPixelStore: negative OSMESA_ROW_LENGTH"),
        OSMESA_Y_UP => ctx.y_up = value != 0,
        _ => eprintln!("fixedfunc: OSMesaPixelStore: unknown pname {pname:#x}"),
    }
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaGetIntegerv(pname: GLint, value: *mut GLint) {
    if value.is_null() {
        return;
    }
    let ctx = super::current();
    let v = match pname {
        OSMESA_MAX_WIDTH | OSMESA_MAX_HEIGHT => MAX_SIZE,
        _ if ctx.is_null() => return,
        _ => {
            // SAFETY: the current context is live.
            let ctx = unsafe { &*ctx };
            let b = ctx.buffer;
            match pname {
                OSMESA_WIDTH => b.map_or(0, |b| b.width),
                OSMESA_HEIGHT => b.map_or(0, |b| b.height),
                OSMESA_FORMAT => ctx.format.osmesa() as GLint,
                OSMESA_TYPE => b.map_or(0, |b| b.ty as GLint),
                OSMESA_ROW_LENGTH => ctx.row_length,
                OSMESA_Y_UP => GLint::from(ctx.y_up),
                _ => {
                    eprintln!("fixedfunc: OSMesaGetIntegerv: unknown pname {pname:#x}");
                    return;
                }
            }
        }
    };
    // SAFETY: the caller's GLint.
    unsafe { *value = v };
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaGetColorBuffer(
    ctx: OSMesaContext,
    width: *mut GLint,
    height: *mut GLint,
    format: *mut GLint,
    buffer: *mut *mut c_void,
) -> GLboolean {
    if ctx.is_null() || width.is_null() || height.is_null() || format.is_null() || buffer.is_null()
    {
        return 0;
    }
    // SAFETY: a live context and the caller's out-parameters.
    unsafe {
        let c = &*ctx;
        let Some(b) = c.buffer else {
            *width = 0;
            *height = 0;
            *format = 0;
            *buffer = std::ptr::null_mut();
            return 0;
        };
        *width = b.width;
        *height = b.height;
        *format = c.format.osmesa() as GLint;
        *buffer = b.ptr;
    }
    1
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaGetDepthBuffer(
    ctx: OSMesaContext,
    width: *mut GLint,
    height: *mut GLint,
    bytes_per_value: *mut GLint,
    buffer: *mut *mut c_void,
) -> GLboolean {
    if ctx.is_null()
        || width.is_null()
        || height.is_null()
        || bytes_per_value.is_null()
        || buffer.is_null()
    {
        return 0;
    }
    if !super::ensure_gl_current(ctx) {
        return 0;
    }
    // SAFETY: a live context and the caller's out-parameters.
    unsafe {
        let c = &mut *ctx;
        match c.read_depth() {
            Some((w, h, per)) => {
                *width = w;
                *height = h;
                *bytes_per_value = per;
                *buffer = c.depth_copy.as_mut_ptr().cast();
            }
            None => {
                *width = 0;
                *height = 0;
                *bytes_per_value = 0;
                *buffer = std::ptr::null_mut();
                return 0;
            }
        }
    }
    let current = super::current();
    if !current.is_null() {
        super::ensure_gl_current(current);
    }
    1
}

#[no_mangle]
pub unsafe extern "C" fn OSMesaGetProcAddress(name: *const c_char) -> *const c_void {
    if name.is_null() {
        return std::ptr::null();
    }
    // SAFETY: a NUL-terminated string.
    let name = unsafe { CStr::from_ptr(name) };
    name.to_str()
        .map_or(std::ptr::null(), super::exports::proc_address)
}

/// OSMesaColorClamp: clamping of float buffers; the buffers this library writes are
/// GL_UNSIGNED_BYTE, always clamped, so the call changes nothing.
#[no_mangle]
pub unsafe extern "C" fn OSMesaColorClamp(_enable: GLboolean) {}

/// The OSMesa functions by name, for OSMesaGetProcAddress.
pub(crate) fn functions() -> HashMap<&'static str, usize> {
    HashMap::from([
        (
            "OSMesaCreateContext",
            OSMesaCreateContext as *const () as usize,
        ),
        (
            "OSMesaCreateContextExt",
            OSMesaCreateContextExt as *const () as usize,
        ),
        (
            "OSMesaCreateContextAttribs",
            OSMesaCreateContextAttribs as *const () as usize,
        ),
        (
            "OSMesaDestroyContext",
            OSMesaDestroyContext as *const () as usize,
        ),
        ("OSMesaMakeCurrent", OSMesaMakeCurrent as *const () as usize),
        (
            "OSMesaGetCurrentContext",
            OSMesaGetCurrentContext as *const () as usize,
        ),
        ("OSMesaPixelStore", OSMesaPixelStore as *const () as usize),
        ("OSMesaGetIntegerv", OSMesaGetIntegerv as *const () as usize),
        (
            "OSMesaGetColorBuffer",
            OSMesaGetColorBuffer as *const () as usize,
        ),
        (
            "OSMesaGetDepthBuffer",
            OSMesaGetDepthBuffer as *const () as usize,
        ),
        (
            "OSMesaGetProcAddress",
            OSMesaGetProcAddress as *const () as usize,
        ),
        ("OSMesaColorClamp", OSMesaColorClamp as *const () as usize),
    ])
}
