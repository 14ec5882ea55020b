//! The storage Mesa 22.3.6 llvmpipe gives a texture level, by the internal format the
//! program named (measured through OSMesa: `glGetTexLevelParameter`'s sizes and the texel
//! (0x9b, 0x57, 0xd3, 0x6a) read back). GL 1.1's reduced formats keep their bits, so an
//! RGBA4 texel reads (0x99, 0x55, 0xcc, 0x66) — each component rounded to 4 bits, then
//! expanded by 255/15 — and RGB5_A1 drops that alpha to 0; the 10-bit formats keep 10 bits
//! and the 12- and 16-bit ones 16. Every other sized format of a base (ALPHA4,
//! LUMINANCE6_ALPHA2, INTENSITY4 …) is its base's 8-bit format (`TexFormat`), as Mesa
//! stores it too — except LUMINANCE4_ALPHA4, which Mesa keeps at 4 bits: core GL has no
//! two-component 4-bit format, so the emulated path stores luminance and alpha in the red
//! and green of an RGBA4 level, which the LUMINANCE_ALPHA swizzle (L, L, L, A) reads.
//!
//! Both paths store the level so: the native path names the requested format to Mesa, the
//! emulated path asks core GL for the format of the same bits ([`core_format`]), which
//! llvmpipe rounds into as its compatibility context does.

use super::glenum::registry as r;

/// The bits of each component a level is stored with (0: the base format lacks it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StoredBits {
    pub red: i32,
    pub green: i32,
    pub blue: i32,
    pub alpha: i32,
    pub luminance: i32,
    pub intensity: i32,
}

const fn rgba(red: i32, green: i32, blue: i32, alpha: i32) -> StoredBits {
    StoredBits {
        red,
        green,
        blue,
        alpha,
        luminance: 0,
        intensity: 0,
    }
}

const fn legacy(alpha: i32, luminance: i32, intensity: i32) -> StoredBits {
    StoredBits {
        red: 0,
        green: 0,
        blue: 0,
        alpha,
        luminance,
        intensity,
    }
}

/// The bits of a requested internal format not stored in its base's 8-bit format; `None`
/// for every other (the 8-bit formats, the unsized and numbered ones, depth).
pub fn stored_bits(requested: u32) -> Option<StoredBits> {
    Some(match requested {
        r::R3_G3_B2 => rgba(3, 3, 2, 0),
        r::RGB4 => rgba(4, 4, 4, 0),
        r::RGB5 => rgba(5, 5, 5, 0),
        r::RGB10 => rgba(10, 10, 10, 0),
        r::RGB12 | r::RGB16 => rgba(16, 16, 16, 0),
        r::RGBA2 | r::RGBA4 => rgba(4, 4, 4, 4),
        r::RGB5_A1 => rgba(5, 5, 5, 1),
        r::RGB10_A2 => rgba(10, 10, 10, 2),
        r::LUMINANCE4_ALPHA4 => legacy(4, 4, 0),
        r::RGBA12 | r::RGBA16 => rgba(16, 16, 16, 16),
        r::ALPHA12 | r::ALPHA16 => legacy(16, 0, 0),
        r::LUMINANCE12 | r::LUMINANCE16 => legacy(0, 16, 0),
        r::LUMINANCE12_ALPHA4 | r::LUMINANCE12_ALPHA12 | r::LUMINANCE16_ALPHA16 => {
            legacy(16, 16, 0)
        }
        r::INTENSITY12 | r::INTENSITY16 => legacy(0, 0, 16),
        _ => return None,
    })
}

/// The core internal format of the same bits, for the emulated path (the swizzle of the
/// base format still applies: one 16-bit channel for ALPHA, LUMINANCE and INTENSITY, two for
/// LUMINANCE_ALPHA); `None` where the base's 8-bit core format serves.
pub fn core_format(requested: u32) -> Option<u32> {
    stored_bits(requested)?;
    Some(match requested {
        r::RGBA2 => r::RGBA4,
        r::ALPHA12
        | r::ALPHA16
        | r::LUMINANCE12
        | r::LUMINANCE16
        | r::INTENSITY12
        | r::INTENSITY16 => r::R16,
        r::LUMINANCE12_ALPHA4 | r::LUMINANCE12_ALPHA12 | r::LUMINANCE16_ALPHA16 => r::RG16,
        r::LUMINANCE4_ALPHA4 => r::RGBA4,
        other => other,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reduced_formats_keep_their_bits_and_others_are_eight() {
        assert_eq!(stored_bits(r::RGBA4), Some(rgba(4, 4, 4, 4)));
        assert_eq!(stored_bits(r::RGB5_A1).map(|b| b.alpha), Some(1));
        for eight in [r::RGBA8, r::RGB, 3, r::ALPHA4, r::INTENSITY4] {
            assert_eq!(stored_bits(eight), None);
            assert_eq!(core_format(eight), None);
        }
        assert_eq!(core_format(r::RGBA2), Some(r::RGBA4));
        assert_eq!(core_format(r::LUMINANCE16), Some(r::R16));
        assert_eq!(core_format(r::R3_G3_B2), Some(r::R3_G3_B2));
    }
}
