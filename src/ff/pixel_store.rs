//! Pixel storage (GL 1.5 §3.6.1 and §4.3.2, Table 6.20): how the rows of pixel data lie in
//! the program's memory. It is client state: it belongs to the front end, which reads
//! glTexImage's and glTexSubImage's data with the unpack alignment (a C pointer, or a
//! script's compound literal alike) and writes glReadPixels' and glGetTexImage's with the
//! pack alignment; the Commands hold tightly packed rows. Only the alignments are kept:
//! rows start at a multiple of them.

use super::args::Args;

/// GL_PACK_ALIGNMENT and GL_UNPACK_ALIGNMENT, in bytes: 1, 2, 4 or 8. GL default: 4 each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelStore {
    pub pack_alignment: usize,
    pub unpack_alignment: usize,
}

impl Default for PixelStore {
    fn default() -> Self {
        PixelStore {
            pack_alignment: 4,
            unpack_alignment: 4,
        }
    }
}

impl PixelStore {
    /// The bytes from one row's start to the next: `row` rounded up to `alignment`.
    pub fn stride(row: usize, alignment: usize) -> usize {
        row.div_ceil(alignment.max(1)) * alignment.max(1)
    }

    /// glPixelStore{i,f}(pname, param): GL_PACK_ALIGNMENT or GL_UNPACK_ALIGNMENT (another
    /// name: INVALID_ENUM) to 1, 2, 4 or 8 (another value: INVALID_VALUE, GL 1.5 §4.3.1);
    /// glPixelStoref's value is rounded to the nearest integer. A bad call changes nothing.
    pub fn call<A: Args>(&mut self, c: &A) -> Result<(), A::Error> {
        c.count(2)?;
        let pname = c.pname(0, &["GL_PACK_ALIGNMENT", "GL_UNPACK_ALIGNMENT"])?;
        let v = c.f64(1)?.round();
        if ![1.0, 2.0, 4.0, 8.0].contains(&v) {
            return Err(c.bad(1, "an alignment of 1, 2, 4 or 8"));
        }
        match pname {
            "GL_PACK_ALIGNMENT" => self.pack_alignment = v as usize,
            _ => self.unpack_alignment = v as usize,
        }
        Ok(())
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
}
