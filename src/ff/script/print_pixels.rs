//! The raster-position and pixel-rectangle commands as script calls (`print`'s inverse is
//! `parse`, through `ff::calls_pixels`): glRasterPos4f, glWindowPos3f, glBitmap with its
//! rows as a GLubyte array, glDrawPixels with its data as `print` writes any pixel array
//! (tightly packed, bottom row first), glCopyPixels, glPixelTransfer{f,i}, glPixelZoom.

use super::print::{f, fs, image_bytes, n, padded, pixels};
use crate::ff::api::Entry;
use crate::ff::{Command, CopyKind, PixelTransferParam, PixelType};

/// One command of this area as a call without the ';' (empty for other commands), its
/// image rows padded to GL_UNPACK_ALIGNMENT `alignment`, as the reader unpacks them.
pub(super) fn call(c: &Command, alignment: usize) -> String {
    match c {
        Command::RasterPos(p) => format!("{}({})", Entry::RasterPos4f, fs(&p.to_array())),
        Command::WindowPos(p) => format!("{}({})", Entry::WindowPos3f, fs(&p.to_array())),
        Command::Bitmap(b) => format!(
            "{}({}, {}, {}, {}, {})",
            Entry::Bitmap,
            b.width,
            b.height,
            fs(&[b.origin.0, b.origin.1]),
            fs(&[b.advance.0, b.advance.1]),
            b.bits.as_ref().map_or("NULL".into(), |bits| pixels(
                PixelType::UnsignedByte,
                &padded(bits, crate::ff::Bitmap::row_bytes(b.width), alignment)
            ))
        ),
        Command::DrawPixels(d) => format!(
            "{}({}, {}, {}, {}, {})",
            Entry::DrawPixels,
            d.width,
            d.height,
            n(d.format),
            n(d.ty),
            pixels(
                d.ty,
                &image_bytes(&d.data, d.format, d.ty, (d.width, d.height), alignment)
            )
        ),
        Command::CopyPixels(c) => format!(
            "{}({}, {}, {}, {}, {})",
            Entry::CopyPixels,
            c.x,
            c.y,
            c.width,
            c.height,
            match c.kind {
                CopyKind::Color => "GL_COLOR",
                CopyKind::Depth => "GL_DEPTH",
                CopyKind::Stencil => "GL_STENCIL",
            }
        ),
        Command::PixelTransfer(p) => transfer(*p),
        Command::PixelZoom { x, y } => format!("{}({})", Entry::PixelZoom, fs(&[*x, *y])),
        // The mask's rows of 4 bytes, as glBitmap's of width 32.
        Command::PolygonStipple(s) => format!(
            "{}({})",
            Entry::PolygonStipple,
            pixels(
                PixelType::UnsignedByte,
                &padded(&s.to_bytes(), 4, alignment)
            )
        ),
        _ => String::new(),
    }
}

fn transfer(p: PixelTransferParam) -> String {
    use PixelTransferParam as P;
    const COMPONENT: [&str; 4] = ["RED", "GREEN", "BLUE", "ALPHA"];
    let float = |name: String, v: f32| format!("{}(GL_{name}, {})", Entry::PixelTransferf, f(v));
    let int = |name: &str, v: i32| format!("{}(GL_{name}, {v})", Entry::PixelTransferi);
    match p {
        P::Scale(i, v) => float(format!("{}_SCALE", COMPONENT[usize::from(i.min(3))]), v),
        P::Bias(i, v) => float(format!("{}_BIAS", COMPONENT[usize::from(i.min(3))]), v),
        P::DepthScale(v) => float("DEPTH_SCALE".into(), v),
        P::DepthBias(v) => float("DEPTH_BIAS".into(), v),
        P::IndexShift(v) => int("INDEX_SHIFT", v),
        P::IndexOffset(v) => int("INDEX_OFFSET", v),
        P::MapColor(b) => int("MAP_COLOR", i32::from(b)),
        P::MapStencil(b) => int("MAP_STENCIL", i32::from(b)),
    }
}
