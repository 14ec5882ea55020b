//! Pixel storage (GL 1.5 §3.6.1 and §4.3.2, Table 6.20): how the rows of pixel data lie in
//! the program's memory. It is client state: it belongs to the front end, which reads
//! glTexImage's, glTexSubImage's, glDrawPixels', glBitmap's and glPolygonStipple's data with
//! the unpack parameters (a C pointer, or a script's compound literal alike) and writes
//! glReadPixels', glGetTexImage's and glGetPolygonStipple's with the pack parameters; the
//! Commands hold tightly packed rows in the machine's byte order, bitmaps most significant
//! bit first (`pixel_layout` does the address arithmetic).
//!
//! Every parameter of Table 6.20 is kept, for both directions: ALIGNMENT, ROW_LENGTH,
//! SKIP_ROWS, SKIP_PIXELS, SWAP_BYTES, LSB_FIRST, and GL 1.2's IMAGE_HEIGHT and SKIP_IMAGES,
//! which only the 3D calls read (glTexImage3D, glTexSubImage3D, glGetTexImage of a 3D
//! level).

use super::args::Args;

/// SWAP_BYTES: whether each multi-byte element is stored in the other byte order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ByteOrder {
    /// GL default: FALSE.
    Native,
    Swapped,
}

/// LSB_FIRST: which bit of a bitmap byte is its leftmost pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BitOrder {
    /// GL default: FALSE, the most significant bit leftmost.
    MsbFirst,
    LsbFirst,
}

/// One direction's parameters (unpack: the data a call reads; pack: the data it writes).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Packing {
    /// 1, 2, 4 or 8: each row starts at a multiple of it. GL default: 4.
    pub alignment: usize,
    /// Pixels from one row's start to the next; 0: the image's width. GL default: 0.
    pub row_length: usize,
    /// Rows skipped before the first. GL default: 0.
    pub skip_rows: usize,
    /// Pixels (bits, for a bitmap) skipped at each row's start. GL default: 0.
    pub skip_pixels: usize,
    /// Rows of one image of a 3D texture; 0: the height. GL default: 0.
    pub image_height: usize,
    /// Images of a 3D texture skipped before the first. GL default: 0.
    pub skip_images: usize,
    /// GL default: FALSE.
    pub swap_bytes: ByteOrder,
    /// GL default: FALSE.
    pub lsb_first: BitOrder,
}

impl Packing {
    pub const DEFAULT: Self = Self {
        alignment: 4,
        row_length: 0,
        skip_rows: 0,
        skip_pixels: 0,
        image_height: 0,
        skip_images: 0,
        swap_bytes: ByteOrder::Native,
        lsb_first: BitOrder::MsbFirst,
    };

    /// Tightly packed rows with this alignment: what a Command's data is, printed.
    pub fn aligned(alignment: usize) -> Self {
        Self {
            alignment,
            ..Self::DEFAULT
        }
    }
}

impl Default for Packing {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// Both directions. GL default: every parameter at its default.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PixelStore {
    pub pack: Packing,
    pub unpack: Packing,
}

/// The parameter names glPixelStore takes (GL 1.5 Table 3.1), pack then unpack.
pub const PNAMES: &[&str] = &[
    "GL_PACK_SWAP_BYTES",
    "GL_PACK_LSB_FIRST",
    "GL_PACK_ROW_LENGTH",
    "GL_PACK_SKIP_ROWS",
    "GL_PACK_SKIP_PIXELS",
    "GL_PACK_ALIGNMENT",
    "GL_PACK_IMAGE_HEIGHT",
    "GL_PACK_SKIP_IMAGES",
    "GL_UNPACK_SWAP_BYTES",
    "GL_UNPACK_LSB_FIRST",
    "GL_UNPACK_ROW_LENGTH",
    "GL_UNPACK_SKIP_ROWS",
    "GL_UNPACK_SKIP_PIXELS",
    "GL_UNPACK_ALIGNMENT",
    "GL_UNPACK_IMAGE_HEIGHT",
    "GL_UNPACK_SKIP_IMAGES",
];

impl PixelStore {
    /// The bytes from one row's start to the next: `row` rounded up to `alignment`.
    pub fn stride(row: usize, alignment: usize) -> usize {
        row.div_ceil(alignment.max(1)) * alignment.max(1)
    }

    /// glPixelStore{i,f}(pname, param), as Mesa's `_mesa_PixelStorei` (glPixelStoref
    /// passes its value converted by `query::round_to_int`, `(GLint) lroundf`; measured,
    /// `tests/c/float_params.c`: 5e9 sets a ROW_LENGTH of 705032704, 1e20 and NaN set 0,
    /// none with an error; 3e9 wraps negative and is refused): a name
    /// outside Table 3.1 is INVALID_ENUM; a negative ROW_LENGTH, SKIP_* or IMAGE_HEIGHT,
    /// or an alignment other than 1, 2, 4 or 8, INVALID_VALUE (GL 1.5 §4.3.1); SWAP_BYTES
    /// and LSB_FIRST are TRUE for any value ≠ 0. A bad call changes nothing.
    pub fn call<A: Args>(&mut self, c: &A) -> Result<(), A::Error> {
        c.count(2)?;
        let pname = c.pname(0, PNAMES)?;
        let v = super::query::round_to_int(c.f64(1)?);
        let (side, name) = match pname.strip_prefix("GL_PACK_") {
            Some(n) => (&mut self.pack, n),
            None => (&mut self.unpack, &pname["GL_UNPACK_".len()..]),
        };
        let count = || usize::try_from(v).map_err(|_| c.bad(1, "a count ≥ 0"));
        match name {
            "SWAP_BYTES" => {
                side.swap_bytes = if v != 0 {
                    ByteOrder::Swapped
                } else {
                    ByteOrder::Native
                }
            }
            "LSB_FIRST" => {
                side.lsb_first = if v != 0 {
                    BitOrder::LsbFirst
                } else {
                    BitOrder::MsbFirst
                }
            }
            "ALIGNMENT" => {
                side.alignment = match v {
                    1 | 2 | 4 | 8 => v as usize,
                    _ => return Err(c.bad(1, "an alignment of 1, 2, 4 or 8")),
                };
            }
            "ROW_LENGTH" => side.row_length = count()?,
            "SKIP_ROWS" => side.skip_rows = count()?,
            "SKIP_PIXELS" => side.skip_pixels = count()?,
            "IMAGE_HEIGHT" => side.image_height = count()?,
            _ => side.skip_images = count()?,
        }
        Ok(())
    }

    /// The value glGet answers for one of [`PNAMES`] (by name), or `None`.
    pub fn get(&self, pname: &str) -> Option<i64> {
        let (side, name) = match pname.strip_prefix("GL_PACK_") {
            Some(n) => (&self.pack, n),
            None => (&self.unpack, pname.strip_prefix("GL_UNPACK_")?),
        };
        Some(match name {
            "SWAP_BYTES" => i64::from(side.swap_bytes == ByteOrder::Swapped),
            "LSB_FIRST" => i64::from(side.lsb_first == BitOrder::LsbFirst),
            "ALIGNMENT" => side.alignment as i64,
            "ROW_LENGTH" => side.row_length as i64,
            "SKIP_ROWS" => side.skip_rows as i64,
            "SKIP_PIXELS" => side.skip_pixels as i64,
            "IMAGE_HEIGHT" => side.image_height as i64,
            "SKIP_IMAGES" => side.skip_images as i64,
            _ => return None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strides_round_rows_up_to_the_alignment() {
        assert_eq!(PixelStore::stride(9, 4), 12);
        assert_eq!(PixelStore::stride(9, 1), 9);
        assert_eq!(PixelStore::stride(8, 8), 8);
        assert_eq!(PixelStore::stride(0, 4), 0);
    }

    #[test]
    fn every_pname_answers_its_default() {
        let s = PixelStore::default();
        for p in PNAMES {
            let want = if p.ends_with("ALIGNMENT") { 4 } else { 0 };
            assert_eq!(s.get(p), Some(want), "{p}");
        }
        assert_eq!(s.get("GL_RED_SCALE"), None);
    }
}
