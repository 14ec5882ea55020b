//! Compressed textures (GL 1.3, ARB_texture_compression) in the S3TC formats of
//! EXT_texture_compression_s3tc: DXT1 (RGB and RGBA), DXT3 and DXT5.
//!
//! A compressed image is kept twice in a level: its blocks as given (what
//! glGetCompressedTexImage returns and TEXTURE_COMPRESSED_IMAGE_SIZE counts) and its texels
//! decoded into the level's 8-bit storage (RGB8 for RGB_DXT1, RGBA8 for the others), which
//! is what both paths sample. The decoding is Mesa's, bit for bit (measured with OSMesa on
//! 256 random blocks per format, `tests/c/compressed.c`):
//! - the 5:6:5 endpoints widen by repeating their bits: (v << 3) | (v >> 2), (v << 2) | (v >> 4);
//! - LERP(a, b, x) = a + ⌊(b − a)·x / 256⌋, rounding towards −∞;
//! - four-colour blocks: colour 2 = LERP(c0, c1, 85), colour 3 = LERP(c0, c1, 170)
//!   ((255,0,0) and (0,0,255) give (170,0,84) and (85,0,169));
//! - DXT1 when c0 ≤ c1 (as 16-bit values): colour 2 = (c0 + c1 + 1) >> 1, colour 3 black,
//!   transparent in RGBA_DXT1; DXT3 and DXT5 colour blocks are always four-colour;
//! - DXT3 alpha: the 4-bit value · 17, texel 0 in the low nibble;
//! - DXT5 alpha, a0 > a1: codes 2–7 = LERP(a0, a1, 36, 72, 109, 145, 182, 218); a0 ≤ a1:
//!   codes 2–5 = LERP(a0, a1, 51, 102, 153, 204), code 6 = 0, code 7 = 255.
//!
//! Blocks are 4×4 texels, rows of blocks from the image's first row (GL's bottom) up; a
//! size that is not a multiple of 4 takes one block per started 4×4.

use std::sync::Arc;

/// The compressed internal formats the layer decodes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CompressedFormat {
    RgbDxt1,
    RgbaDxt1,
    RgbaDxt3,
    RgbaDxt5,
}

impl CompressedFormat {
    /// COMPRESSED_TEXTURE_FORMATS: the formats of Mesa's list the layer decodes, in Mesa's
    /// order (RGBA_DXT1 is taken but not listed, as on Mesa).
    pub const LISTED: [CompressedFormat; 3] = [
        CompressedFormat::RgbDxt1,
        CompressedFormat::RgbaDxt3,
        CompressedFormat::RgbaDxt5,
    ];

    /// Bytes of one 4×4 block.
    pub fn block_bytes(self) -> usize {
        match self {
            CompressedFormat::RgbDxt1 | CompressedFormat::RgbaDxt1 => 8,
            CompressedFormat::RgbaDxt3 | CompressedFormat::RgbaDxt5 => 16,
        }
    }

    /// Bytes of a `width × height` image: one block per started 4×4.
    pub fn image_size(self, width: i32, height: i32) -> u64 {
        let blocks = |n: i32| (n.max(0) as u64).div_ceil(4);
        blocks(width) * blocks(height) * self.block_bytes() as u64
    }

    /// Whether the format has alpha (TEXTURE_ALPHA_SIZE 4 on Mesa; RGB_DXT1 0).
    pub fn has_alpha(self) -> bool {
        self != CompressedFormat::RgbDxt1
    }
}

/// A compressed level's blocks, as given.
#[derive(Debug, Clone, PartialEq)]
pub struct CompressedImage {
    pub format: CompressedFormat,
    pub bytes: Arc<[u8]>,
}

/// glCompressedTexImage2D of TEXTURE_2D (or, `proxy`, PROXY_TEXTURE_2D: checked, nothing
/// kept), its checks of arguments alone made (`calls_compressed::check_image`).
#[derive(Debug, Clone, PartialEq)]
pub struct CompressedTexImage {
    pub proxy: bool,
    pub level: i32,
    pub format: CompressedFormat,
    pub width: i32,
    pub height: i32,
    /// The blocks; `None` for NULL (zero blocks, as Mesa stores them).
    pub data: Option<Arc<[u8]>>,
}

impl CompressedTexImage {
    /// The blocks, NULL's as zeros.
    pub fn blocks(&self) -> Arc<[u8]> {
        self.data.clone().unwrap_or_else(|| {
            vec![0u8; self.format.image_size(self.width, self.height) as usize].into()
        })
    }
}

/// glCompressedTexSubImage2D of TEXTURE_2D: whole blocks at (x, y).
#[derive(Debug, Clone, PartialEq)]
pub struct CompressedTexSubImage {
    pub level: i32,
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
    pub format: CompressedFormat,
    /// The blocks; `None` for NULL (nothing changes).
    pub data: Option<Arc<[u8]>>,
}

impl CompressedTexSubImage {
    /// The region's texels decoded, as the glTexSubImage2D of RGBA bytes that writes them
    /// into the level's storage (`None` for NULL blocks, which change nothing).
    pub fn texels(&self) -> Option<super::command::TexSubImage> {
        let blocks = self.data.as_ref()?;
        Some(super::command::TexSubImage {
            face: None,
            level: self.level,
            x: self.x,
            y: self.y,
            z: 0,
            width: self.width,
            height: self.height,
            depth: 1,
            format: super::texture::PixelFormat::Rgba,
            ty: super::texture::PixelType::UnsignedByte,
            data: Some(decode(self.format, self.width, self.height, blocks).into()),
        })
    }
}

/// 5:6:5 as 8-bit RGB, the bits repeated.
fn rgb565(c: u16) -> [i32; 3] {
    let r = i32::from(c >> 11);
    let g = i32::from((c >> 5) & 63);
    let b = i32::from(c & 31);
    [
        (r << 3) | (r >> 2),
        (g << 2) | (g >> 4),
        (b << 3) | (b >> 2),
    ]
}

/// a + ⌊(b − a)·x / 256⌋ (an arithmetic shift rounds towards −∞).
fn lerp(a: i32, b: i32, x: i32) -> i32 {
    a + (((b - a) * x) >> 8)
}

/// The 16 texels of a colour block (8 bytes), RGBA, texel (x, y) at 4y + x.
fn colour_block(b: &[u8], format: CompressedFormat) -> [[u8; 4]; 16] {
    let c0 = u16::from_le_bytes([b[0], b[1]]);
    let c1 = u16::from_le_bytes([b[2], b[3]]);
    let bits = u32::from_le_bytes([b[4], b[5], b[6], b[7]]);
    let (e0, e1) = (rgb565(c0), rgb565(c1));
    let dxt1 = matches!(
        format,
        CompressedFormat::RgbDxt1 | CompressedFormat::RgbaDxt1
    );
    let four = c0 > c1 || !dxt1;
    let opaque = |c: [i32; 3]| [c[0] as u8, c[1] as u8, c[2] as u8, 255];
    let palette: [[u8; 4]; 4] = if four {
        [
            opaque(e0),
            opaque(e1),
            opaque(std::array::from_fn(|i| lerp(e0[i], e1[i], 85))),
            opaque(std::array::from_fn(|i| lerp(e0[i], e1[i], 170))),
        ]
    } else {
        let black_alpha = if format == CompressedFormat::RgbaDxt1 {
            0
        } else {
            255
        };
        [
            opaque(e0),
            opaque(e1),
            opaque(std::array::from_fn(|i| (e0[i] + e1[i] + 1) >> 1)),
            [0, 0, 0, black_alpha],
        ]
    };
    std::array::from_fn(|t| palette[((bits >> (2 * t)) & 3) as usize])
}

/// The 16 alphas of a DXT5 alpha block (8 bytes).
fn dxt5_alpha(b: &[u8]) -> [u8; 16] {
    let (a0, a1) = (i32::from(b[0]), i32::from(b[1]));
    let mut bits = 0u64;
    for (i, v) in b[2..8].iter().enumerate() {
        bits |= u64::from(*v) << (8 * i);
    }
    let code = |c: u64| -> i32 {
        match c {
            0 => a0,
            1 => a1,
            c if a0 > a1 => lerp(a0, a1, [36, 72, 109, 145, 182, 218][c as usize - 2]),
            c @ 2..=5 => lerp(a0, a1, [51, 102, 153, 204][c as usize - 2]),
            6 => 0,
            _ => 255,
        }
    };
    std::array::from_fn(|t| code((bits >> (3 * t)) & 7) as u8)
}

/// A `width × height` image of `format` (`data` holds [`CompressedFormat::image_size`]
/// bytes) as tight RGBA8 rows, in the image's row order.
pub fn decode(format: CompressedFormat, width: i32, height: i32, data: &[u8]) -> Vec<u8> {
    let (w, h) = (width.max(0) as usize, height.max(0) as usize);
    let blocks_across = w.div_ceil(4);
    let mut out = vec![0u8; w * h * 4];
    for (i, block) in data.chunks_exact(format.block_bytes()).enumerate() {
        let (bx, by) = (i % blocks_across.max(1) * 4, i / blocks_across.max(1) * 4);
        if by >= h {
            break;
        }
        let (colour, alpha): (&[u8], Option<[u8; 16]>) = match format {
            CompressedFormat::RgbDxt1 | CompressedFormat::RgbaDxt1 => (block, None),
            CompressedFormat::RgbaDxt3 => {
                let a = std::array::from_fn(|t| ((block[t / 2] >> (4 * (t % 2))) & 15) * 17);
                (&block[8..], Some(a))
            }
            CompressedFormat::RgbaDxt5 => (&block[8..], Some(dxt5_alpha(block))),
        };
        let texels = colour_block(colour, format);
        for (t, texel) in texels.iter().enumerate() {
            let (x, y) = (bx + t % 4, by + t / 4);
            if x >= w || y >= h {
                continue;
            }
            let o = (y * w + x) * 4;
            out[o..o + 4].copy_from_slice(texel);
            if let Some(a) = alpha {
                out[o + 3] = a[t];
            }
        }
    }
    out
}

/// The blocks of a `width × height` sub-image written into a level's blocks at texel
/// (x, y), both multiples of 4 (the caller checks).
pub fn splice(
    level: &mut [u8],
    level_width: i32,
    format: CompressedFormat,
    at: (i32, i32),
    size: (i32, i32),
    blocks: &[u8],
) {
    let bb = format.block_bytes();
    let across = (level_width.max(0) as usize).div_ceil(4);
    let (bx, by) = (at.0.max(0) as usize / 4, at.1.max(0) as usize / 4);
    let (sw, sh) = (
        (size.0.max(0) as usize).div_ceil(4),
        (size.1.max(0) as usize).div_ceil(4),
    );
    for row in 0..sh {
        let src = row * sw * bb;
        let dst = ((by + row) * across + bx) * bb;
        if let (Some(from), Some(to)) = (
            blocks.get(src..src + sw * bb),
            level.get_mut(dst..dst + sw * bb),
        ) {
            to.copy_from_slice(from);
        }
    }
}

#[cfg(test)]
#[path = "compressed_tests.rs"]
mod tests;
