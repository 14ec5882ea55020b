//! Where a pixel rectangle's groups lie in the program's memory (GL 1.5 §3.6.4, "Unpacking",
//! and §4.3.2, which packs by the same rules), and the two copies between that memory and
//! the tight rows the Commands hold.
//!
//! For an image of `width × height` groups of `n` elements of `s` bytes each, with
//! `l` = ROW_LENGTH if > 0 else `width` and `a` = ALIGNMENT:
//! - a row is `k = a·⌈s·n·l / a⌉` bytes when `s < a`, `s·n·l` otherwise — the same number,
//!   as `a` and `s` are powers of two: `s·n·l` rounded up to `a`;
//! - the first group read is `SKIP_PIXELS·n` elements into the row `SKIP_ROWS` rows in;
//! - with SWAP_BYTES each element of 2 or 4 bytes is read with its bytes reversed
//!   (GL 1.5 Table 3.7); a packed type (GL 1.2) is one element of its whole size.
//!
//! A bitmap (glBitmap, glPolygonStipple, glGetPolygonStipple) is one bit a pixel: a row is
//! `a·⌈l / 8a⌉` bytes, SKIP_PIXELS counts bits, and LSB_FIRST says that bit 0 of a byte is
//! its leftmost pixel. The tight form is most significant bit first, rows of ⌈width/8⌉.
//!
//! A COLOR_INDEX image (`ShapeKind::IndexRun`, `IndexBits`) is read as Mesa 22.3 reads
//! it: from its first group (or bit, SKIP_PIXELS counting bits), each image's
//! `width·height` groups (bits) one run, whatever ALIGNMENT and ROW_LENGTH say of rows;
//! the tight form is that run (for bits, most significant bit first, ⌈w·h/8⌉ bytes).
//!
//! The `depth` images of a 3D call (GL 1.2 §3.8.1) follow one another `k·h_i` bytes apart,
//! `h_i` = IMAGE_HEIGHT if > 0 else `height`, the first SKIP_IMAGES images skipped (Mesa's
//! `_mesa_image_address`); a 2D call leaves both parameters out. The tight form is the
//! images one after the other, the first (r = 0) first.

use super::args::{LsbFirst, PixelShape, ShapeKind};
use super::pixel_store::{BitOrder, ByteOrder, Packing};

/// Where the rows are, in bytes from the pointer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// The first byte of the first row read (for a bitmap, the byte holding its first bit).
    pub first: usize,
    /// From one row's start to the next.
    pub stride: usize,
    /// Bytes of one row in the tight form.
    pub tight_row: usize,
    /// Bytes one row touches from its first byte.
    pub span: usize,
    /// Rows of one image.
    pub rows: usize,
    /// Images (1 for a 2D rectangle).
    pub images: usize,
    /// From one image's first row to the next's.
    pub image_stride: usize,
    /// Bytes from the pointer to the end of the last row: what the memory must hold.
    pub extent: usize,
}

impl Layout {
    /// Bytes of the tight form: every row of every image.
    pub fn tight_len(&self) -> usize {
        self.tight_row * self.rows * self.images
    }

    /// Where row `y` of image `z` starts, from the pointer.
    fn row_start(&self, z: usize, y: usize) -> usize {
        self.first + z * self.image_stride + y * self.stride
    }
}

/// The layout of `shape` under `p`.
pub fn layout(shape: PixelShape, p: &Packing) -> Layout {
    let (w, h) = (shape.width.max(0) as usize, shape.height.max(0) as usize);
    let l = if p.row_length > 0 { p.row_length } else { w };
    let a = p.alignment.max(1);
    let (first, stride, tight_row, span) = match shape.kind {
        ShapeKind::IndexRun => {
            let group = shape.group_bytes();
            let stride = (l * group).div_ceil(a) * a;
            let run = w * h * group;
            (
                p.skip_rows * stride + p.skip_pixels * group,
                stride,
                run,
                run,
            )
        }
        ShapeKind::IndexBits(_) => {
            let stride = l.div_ceil(8 * a) * a;
            let span = (p.skip_pixels % 8 + w * h).div_ceil(8);
            (
                p.skip_rows * stride + p.skip_pixels / 8,
                stride,
                (w * h).div_ceil(8),
                span,
            )
        }
        ShapeKind::Groups => {
            let group = shape.group_bytes();
            let stride = (l * group).div_ceil(a) * a;
            let row = w * group;
            (
                p.skip_rows * stride + p.skip_pixels * group,
                stride,
                row,
                row,
            )
        }
        ShapeKind::Bitmap => {
            let stride = l.div_ceil(8 * a) * a;
            let span = (p.skip_pixels % 8 + w).div_ceil(8);
            (
                p.skip_rows * stride + p.skip_pixels / 8,
                stride,
                w.div_ceil(8),
                span,
            )
        }
    };
    // GL 1.2 §3.8.1: a 3D call's images, IMAGE_HEIGHT rows apart (the height when 0),
    // after SKIP_IMAGES of them. Saturating: a layout beyond the address space needs more
    // than any memory holds, so the front ends refuse it as too short.
    let (images, image_stride, first) = match shape.depth {
        None => (1, h.saturating_mul(stride), first),
        Some(d) => {
            let image_rows = if p.image_height > 0 {
                p.image_height
            } else {
                h
            };
            let image_stride = image_rows.saturating_mul(stride);
            let skipped = p.skip_images.saturating_mul(image_stride);
            (
                d.max(0) as usize,
                image_stride,
                first.saturating_add(skipped),
            )
        }
    };
    // A run is one row of each image.
    let rows = match shape.kind {
        ShapeKind::IndexRun | ShapeKind::IndexBits(_) => 1,
        ShapeKind::Groups | ShapeKind::Bitmap => h,
    };
    let extent = if w == 0 || h == 0 || images == 0 {
        0
    } else {
        first
            .saturating_add((images - 1).saturating_mul(image_stride))
            .saturating_add((rows - 1).saturating_mul(stride))
            .saturating_add(span)
    };
    Layout {
        first,
        stride,
        tight_row,
        span,
        rows: if w == 0 || h == 0 { 0 } else { rows },
        images,
        image_stride,
        extent,
    }
}

/// Reverses each `size`-byte element of `row` in place (SWAP_BYTES).
fn swap_elements(row: &mut [u8], size: usize) {
    if size > 1 {
        for e in row.chunks_exact_mut(size) {
            e.reverse();
        }
    }
}

/// Bit `x` of a row starting at bit `skip` of `bytes`, in `order`.
fn bit_at(bytes: &[u8], skip: usize, x: usize, order: BitOrder) -> bool {
    let i = skip + x;
    let mask = match order {
        BitOrder::MsbFirst => 0x80 >> (i % 8),
        BitOrder::LsbFirst => 1 << (i % 8),
    };
    bytes.get(i / 8).is_some_and(|b| b & mask != 0)
}

/// The tight rows of `shape` read from `src` (the program's memory from the pointer), or
/// `None` when `src` is shorter than the layout's extent.
pub fn unpack(src: &[u8], shape: PixelShape, p: &Packing) -> Option<Vec<u8>> {
    let lay = layout(shape, p);
    if src.len() < lay.extent {
        return None;
    }
    let mut out = Vec::with_capacity(lay.tight_len());
    for (z, y) in (0..lay.images).flat_map(|z| (0..lay.rows).map(move |y| (z, y))) {
        let start = lay.row_start(z, y);
        let row = src.get(start..start + lay.span)?;
        match shape.kind {
            ShapeKind::Groups | ShapeKind::IndexRun => {
                let at = out.len();
                out.extend_from_slice(row);
                if p.swap_bytes == ByteOrder::Swapped {
                    swap_elements(&mut out[at..], shape.element_bytes());
                }
            }
            ShapeKind::Bitmap | ShapeKind::IndexBits(_) => {
                let (w, order) = match shape.kind {
                    ShapeKind::IndexBits(rule) => (
                        shape.width.max(0) as usize * shape.height.max(0) as usize,
                        match rule {
                            LsbFirst::Honoured => p.lsb_first,
                            LsbFirst::Ignored => BitOrder::MsbFirst,
                        },
                    ),
                    _ => (shape.width.max(0) as usize, p.lsb_first),
                };
                let mut bytes = vec![0u8; lay.tight_row];
                for x in 0..w {
                    if bit_at(row, p.skip_pixels % 8, x, order) {
                        bytes[x / 8] |= 0x80 >> (x % 8);
                    }
                }
                out.extend_from_slice(&bytes);
            }
        }
    }
    Some(out)
}

/// Writes the tight rows `tight` of `shape` into `dst` (the program's memory from the
/// pointer, at least the layout's extent) under `p`; bytes (bits, for a bitmap) between
/// the rows and groups are left as they were. `false` when `dst` or `tight` is short.
pub fn pack(tight: &[u8], dst: &mut [u8], shape: PixelShape, p: &Packing) -> bool {
    let lay = layout(shape, p);
    if dst.len() < lay.extent || tight.len() < lay.tight_len() {
        return false;
    }
    let rows = (0..lay.images).flat_map(|z| (0..lay.rows).map(move |y| (z, y)));
    for (k, (z, y)) in rows.enumerate() {
        let src = &tight[k * lay.tight_row..(k + 1) * lay.tight_row];
        let start = lay.row_start(z, y);
        let row = &mut dst[start..start + lay.span];
        match shape.kind {
            ShapeKind::Groups | ShapeKind::IndexRun => {
                row.copy_from_slice(src);
                if p.swap_bytes == ByteOrder::Swapped {
                    swap_elements(row, shape.element_bytes());
                }
            }
            ShapeKind::Bitmap | ShapeKind::IndexBits(_) => {
                let skip = p.skip_pixels % 8;
                for x in 0..shape.width.max(0) as usize {
                    let on = src[x / 8] & (0x80 >> (x % 8)) != 0;
                    let i = skip + x;
                    let mask = match p.lsb_first {
                        BitOrder::MsbFirst => 0x80 >> (i % 8),
                        BitOrder::LsbFirst => 1 << (i % 8),
                    };
                    if on {
                        row[i / 8] |= mask;
                    } else {
                        row[i / 8] &= !mask;
                    }
                }
            }
        }
    }
    true
}

#[cfg(test)]
#[path = "pixel_layout_tests.rs"]
mod pixel_layout_tests;
