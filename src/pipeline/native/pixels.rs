//! The raster position and pixel rectangles as Mesa's own calls: glRasterPos4f,
//! glWindowPos3f, glBitmap, glDrawPixels, glCopyPixels, glPixelTransferf, glPixelZoom. The
//! model's bitmaps and images are tightly packed, so they are sent with UNPACK_ALIGNMENT 1
//! (the native path keeps it at 1, as its texture uploads do).

use crate::ff::Command;

use super::bindings as gl;
use super::conv;

/// Issues one command of this area; `false` for commands of other areas.
pub(super) fn issue(g: &gl::Gl, cmd: &Command) -> bool {
    // SAFETY (all unsafe blocks): plain GL calls on the current context; the pointers are
    // the command's own bytes, which hold what the call reads (width·height groups packed
    // at alignment 1; ⌈width/8⌉ bytes per bitmap row), checked by the model.
    match cmd {
        Command::RasterPos(p) => unsafe { g.RasterPos4f(p.x, p.y, p.z, p.w) },
        Command::WindowPos(p) => unsafe { g.WindowPos3f(p.x, p.y, p.z) },
        Command::Bitmap(b) => unsafe {
            g.PixelStorei(gl::UNPACK_ALIGNMENT, 1);
            let bits = b.bits.as_ref().map_or(std::ptr::null(), |b| b.as_ptr());
            g.Bitmap(
                b.width,
                b.height,
                b.origin.0,
                b.origin.1,
                b.advance.0,
                b.advance.1,
                bits,
            );
        },
        Command::DrawPixels(d) => unsafe {
            g.PixelStorei(gl::UNPACK_ALIGNMENT, 1);
            g.DrawPixels(
                d.width,
                d.height,
                conv::value(d.format),
                conv::value(d.ty),
                d.data.as_ptr().cast(),
            );
        },
        Command::CopyPixels(c) => unsafe {
            g.CopyPixels(c.x, c.y, c.width, c.height, conv::copy_kind(c.kind))
        },
        Command::PixelTransfer(p) => {
            let (pname, v) = conv::pixel_transfer(*p);
            unsafe { g.PixelTransferf(pname, v) }
        }
        Command::PixelZoom { x, y } => unsafe { g.PixelZoom(*x, *y) },
        // The stored values (clamped or rounded as Mesa stores them) as floats.
        Command::PixelMap(m) => unsafe {
            g.PixelMapfv(
                conv::pixel_map(m.map),
                m.values.len() as i32,
                m.values.as_ptr(),
            )
        },
        _ => return false,
    }
    true
}
