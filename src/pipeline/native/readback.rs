//! glReadPixels into a readback slot: colour, DEPTH_COMPONENT (UNSIGNED_BYTE, UNSIGNED_SHORT,
//! UNSIGNED_INT, FLOAT) or STENCIL_INDEX from the current read framebuffer, PACK_ALIGNMENT 1,
//! bottom row first (GL's own order). Depth conversions are the driver's: on Mesa 22.3
//! llvmpipe UNSIGNED_BYTE truncates (⌊255·z⌋) and UNSIGNED_SHORT rounds (≈ ⌊65535·z + ½⌋),
//! the rules `gpu::readback` names `Truncate` and `Round`.

use std::ffi::c_void;

use crate::ff::{texture::image_size, ReadPixels};
use crate::pipeline::Readback;

use super::bindings as gl;
use super::conv;

/// Reads the rectangle of `r` (sizes already checked ≥ 0 by the model).
pub fn read_pixels(g: &gl::Gl, r: &ReadPixels) -> Readback {
    let mut bytes = vec![0u8; image_size(r.format, r.ty, r.width, r.height)];
    // SAFETY: `bytes` holds width·height·components·size bytes and PACK_ALIGNMENT is 1, so
    // GL writes exactly that many; no PIXEL_PACK_BUFFER is bound (the pipeline unbinds it).
    unsafe {
        g.PixelStorei(gl::PACK_ALIGNMENT, 1);
        g.ReadPixels(
            r.x,
            r.y,
            r.width,
            r.height,
            conv::value(r.format),
            conv::value(r.ty),
            bytes.as_mut_ptr().cast::<c_void>(),
        );
    }
    Readback {
        width: r.width.max(0) as u32,
        height: r.height.max(0) as u32,
        depth: None,
        format: r.format,
        ty: r.ty,
        bytes,
    }
}
