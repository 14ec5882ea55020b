//! Polygon and line stipple (GL 1.5 §3.5.2, §3.4.2) as state. The polygon stipple is a
//! 32×32 bitmap unpacked as glBitmap's (rows of 4 bytes, bottom row first, the most
//! significant bit of a byte leftmost: UNPACK_LSB_FIRST = FALSE); a filled polygon's
//! fragment at window (x_w, y_w) is kept iff bit (x_w mod 32, y_w mod 32) is 1. The
//! pipelines read [`PolygonStipple::rows`], one word per row with the leftmost pixel in
//! the most significant bit.

/// The polygon stipple pattern. GL default: every bit 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PolygonStipple {
    /// Row y (from the bottom) as a word: bit 31 − x is pixel x.
    pub rows: [u32; 32],
}

impl PolygonStipple {
    /// All ones (GL 1.5 Table 6.13).
    pub const DEFAULT: PolygonStipple = PolygonStipple {
        rows: [u32::MAX; 32],
    };

    /// Bytes of the unpacked 32×32 mask: 32 rows of 4.
    pub const BYTES: usize = 128;

    /// From the unpacked mask (`BYTES` bytes, bottom row first); `None` for another length.
    pub fn from_bytes(bytes: &[u8]) -> Option<PolygonStipple> {
        if bytes.len() != Self::BYTES {
            return None;
        }
        let mut rows = [0u32; 32];
        for (row, chunk) in rows.iter_mut().zip(bytes.chunks_exact(4)) {
            *row = u32::from_be_bytes([chunk[0], chunk[1], chunk[2], chunk[3]]);
        }
        Some(PolygonStipple { rows })
    }

    /// The mask as glGetPolygonStipple packs it (PACK_LSB_FIRST = FALSE, tightly).
    pub fn to_bytes(&self) -> Vec<u8> {
        self.rows.iter().flat_map(|r| r.to_be_bytes()).collect()
    }

    /// Whether the fragment at window (x, y) passes: bit (x mod 32, y mod 32).
    pub fn passes(&self, x: i32, y: i32) -> bool {
        let (x, y) = (x.rem_euclid(32) as u32, y.rem_euclid(32) as usize);
        self.rows[y] >> (31 - x) & 1 == 1
    }
}

/// glLineStipple (§3.4.2): a fragment of a line is drawn iff bit ⌊s/factor⌋ mod 16 of
/// `pattern` is 1, s counting window pixels along the line. GL default: factor 1, pattern
/// 0xFFFF.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LineStipple {
    /// LINE_STIPPLE_REPEAT, in [1, 256].
    pub factor: u16,
    /// LINE_STIPPLE_PATTERN.
    pub pattern: u16,
}

impl LineStipple {
    /// Factor 1, every bit set (GL 1.5 Table 6.11).
    pub const DEFAULT: LineStipple = LineStipple {
        factor: 1,
        pattern: 0xFFFF,
    };

    /// The stipple of glLineStipple(factor, pattern): the factor clamped to [1, 256].
    pub fn new(factor: i32, pattern: u16) -> LineStipple {
        LineStipple {
            factor: factor.clamp(1, 256) as u16,
            pattern,
        }
    }

    /// Whether the fragment at stipple counter `s` is drawn.
    pub fn passes(&self, s: u32) -> bool {
        self.pattern >> (s / u32::from(self.factor) % 16) & 1 == 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_byte_msb_is_the_lower_left_pixel() {
        let mut bytes = vec![0u8; PolygonStipple::BYTES];
        bytes[0] = 0x80; // row 0, pixel 0
        bytes[4 * 31 + 3] = 0x01; // row 31, pixel 31
        let s = PolygonStipple::from_bytes(&bytes).unwrap();
        assert!(s.passes(0, 0) && s.passes(32, -32) && s.passes(31, 31));
        assert!(!s.passes(1, 0) && !s.passes(0, 1) && !s.passes(30, 31));
        assert_eq!(s.to_bytes(), bytes);
        assert!(PolygonStipple::from_bytes(&bytes[1..]).is_none());
        assert!(PolygonStipple::DEFAULT.passes(17, 5));
    }

    #[test]
    fn line_stipple_clamps_its_factor_and_repeats_each_bit() {
        assert_eq!(LineStipple::new(0, 1).factor, 1);
        assert_eq!(LineStipple::new(-5, 1).factor, 1);
        assert_eq!(LineStipple::new(1000, 1).factor, 256);
        let s = LineStipple::new(3, 0b101);
        let drawn: Vec<bool> = (0..10).map(|i| s.passes(i)).collect();
        assert_eq!(
            drawn,
            [true, true, true, false, false, false, true, true, true, false]
        );
        // Bit 15 is followed by bit 0 again.
        assert!(LineStipple::new(1, 0x8001).passes(15) && LineStipple::new(1, 0x8001).passes(16));
    }
}
