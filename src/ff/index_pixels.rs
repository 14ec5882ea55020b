//! Colour-index images in an RGBA context (GL 1.5 §3.6.4, §3.6.5 "Color Index Lookup"):
//! glDrawPixels, glTexImage* and glTexSubImage* of COLOR_INDEX data, as Mesa 22.3 draws
//! and stores them (measured, `tests/c/index_pixels.c`).
//!
//! The data is read as one run an image (`pixel_layout`) and kept in the client's type,
//! GL_BITMAP as UNSIGNED_BYTE indices 0 and 1; the indices become colours where the
//! command executes, under the transfer state of that moment (a display list's image too).
//!
//! Each element is an index as Mesa's `extract_uint_indexes` makes it: an unsigned value
//! as it is, a signed one's two's-complement bits (−1 is 2³² − 1), a float truncated
//! towards zero as C converts it to a 32-bit unsigned on x86-64, through a 64-bit integer
//! (−1.0 is 2³² − 1; NaN and values beyond ±2⁶³ are 0). Index i takes entry
//! i & (size − 1) of each of I_TO_R, I_TO_G, I_TO_B and I_TO_A, kept as 8 bits,
//! roundEven(255·v): Mesa makes the image RGBA UNSIGNED_BYTE first.
//! - Texture images: the index is first shifted by INDEX_SHIFT (left for > 0, right for
//!   < 0, on 32 bits) and offset by INDEX_OFFSET (wrapping); after the lookup neither
//!   scale and bias nor MAP_COLOR apply (Mesa's texture store).
//! - glDrawPixels: no transfer at all — neither INDEX_SHIFT and INDEX_OFFSET (Mesa draws
//!   with the image transfer off, as it does stencil images) nor scale, bias and MAP_COLOR
//!   (unlike an RGBA image); the colour passes through the storage Mesa picks for the
//!   client's type: BYTE an RGBA8_SNORM texture (u → ⌊(127u + 127)/255⌋ / 127), SHORT and
//!   INT an RGBA16_SNORM one (u → (128u + ⌊u/2⌋) / 32767), the others u/255 exactly.

use glam::Vec4;

use super::args::{Args, LsbFirst, PixelShape, ShapeKind};
use super::glenum::registry;
use super::pixel_map::{PixelMapName, PixelMaps};
use super::pixels::PixelTransfer;
use super::query::c_long;
use super::texture::{PixelFormat, PixelType};

/// The image of a pixel call whose format and type are arguments `format_at` and
/// `format_at + 1`: `width × height` groups (`depth` images of them for a 3D call); for
/// COLOR_INDEX a run (`ShapeKind::IndexRun`), or with GL_BITMAP a run of bits read with
/// `lsb_first`.
pub fn image_shape<A: Args>(
    c: &A,
    (width, height, depth): (i32, i32, Option<i32>),
    format_at: usize,
    lsb_first: LsbFirst,
) -> Result<PixelShape, A::Error> {
    let format: PixelFormat = c.enm(format_at)?;
    let bits = format == PixelFormat::ColorIndex && c.token(format_at + 1)? == registry::BITMAP;
    let ty = if bits {
        PixelType::UnsignedByte
    } else {
        c.enm(format_at + 1)?
    };
    let mut shape = match depth {
        Some(d) => PixelShape::volume(width, height, d, format, ty),
        None => PixelShape::groups(width, height, format, ty),
    };
    if format == PixelFormat::ColorIndex {
        shape.kind = if bits {
            ShapeKind::IndexBits(lsb_first)
        } else {
            ShapeKind::IndexRun
        };
    }
    Ok(shape)
}

/// The bits of an `IndexBits` shape's tight runs (each image's ⌈w·h/8⌉ bytes, most
/// significant bit first) as one UNSIGNED_BYTE index a pixel, 0 or 1.
pub fn bits_as_indices(runs: &[u8], shape: PixelShape) -> Vec<u8> {
    let n = shape.width.max(0) as usize * shape.height.max(0) as usize;
    let images = shape.depth.map_or(1, |d| d.max(0) as usize);
    let run = n.div_ceil(8);
    (0..images)
        .flat_map(|z| (0..n).map(move |k| (z * run + k / 8, k % 8)))
        .map(|(byte, bit)| runs.get(byte).map_or(0, |b| (b >> (7 - bit)) & 1))
        .collect()
}

/// The indices of tight COLOR_INDEX data in `ty` (see the module note).
pub fn indices(data: &[u8], ty: PixelType) -> Vec<u32> {
    let size = ty.size();
    data.chunks_exact(size)
        .map(|e| match ty {
            PixelType::UnsignedByte => u32::from(e[0]),
            PixelType::Byte => e[0] as i8 as u32,
            PixelType::UnsignedShort => u32::from(u16::from_ne_bytes([e[0], e[1]])),
            PixelType::Short => i16::from_ne_bytes([e[0], e[1]]) as u32,
            PixelType::UnsignedInt | PixelType::Int => u32::from_ne_bytes([e[0], e[1], e[2], e[3]]),
            PixelType::Float => {
                let f = f32::from_ne_bytes([e[0], e[1], e[2], e[3]]);
                c_long(f64::from(f).trunc()) as u32
            }
            // Refused before (`pixel_types::refused`): no packed index type.
            PixelType::Packed(_) => 0,
        })
        .collect()
}

/// Index `i` through I_TO_R, I_TO_G, I_TO_B and I_TO_A, each entry i & (size − 1) kept as
/// roundEven(255·v) (Mesa's CLAMPED_FLOAT_TO_UBYTE).
pub fn rgba8(i: u32, maps: &PixelMaps) -> [u8; 4] {
    [
        PixelMapName::IToR,
        PixelMapName::IToG,
        PixelMapName::IToB,
        PixelMapName::IToA,
    ]
    .map(|m| (maps.entry_masked(m, u64::from(i)).clamp(0.0, 1.0) * 255.0).round_ties_even() as u8)
}

/// A texture image's colours, 8 bits a component, RGBA: each index shifted and offset,
/// then looked up.
pub fn stored_colours(
    data: &[u8],
    ty: PixelType,
    t: &PixelTransfer,
    maps: &PixelMaps,
) -> Vec<Vec4> {
    indices(data, ty)
        .into_iter()
        .map(|i| {
            let c = rgba8(t.colour_index(i), maps);
            Vec4::from_array(c.map(|u| f32::from(u) / 255.0))
        })
        .collect()
}

/// glDrawPixels' colours: each index looked up, through the storage of the client's type
/// (module note).
pub fn drawn_colours(data: &[u8], ty: PixelType, maps: &PixelMaps) -> Vec<Vec4> {
    indices(data, ty)
        .into_iter()
        .map(|i| Vec4::from_array(rgba8(i, maps).map(|u| drawn_component(u, ty))))
        .collect()
}

/// An 8-bit component as the drawing texture of `ty` holds it: RGBA8_SNORM for BYTE and
/// RGBA16_SNORM for SHORT and INT (Mesa's `_mesa_unorm_to_snorm`), else exact.
fn drawn_component(u: u8, ty: PixelType) -> f32 {
    let u = u32::from(u);
    match ty {
        PixelType::Byte => ((127 * u + 127) / 255) as f32 / 127.0,
        PixelType::Short | PixelType::Int => (128 * u + u / 2) as f32 / 32767.0,
        PixelType::UnsignedByte
        | PixelType::UnsignedShort
        | PixelType::UnsignedInt
        | PixelType::Float
        | PixelType::Packed(_) => u as f32 / 255.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::pixel_map::{MapValues, PixelMap};

    fn maps() -> PixelMaps {
        let mut m = PixelMaps::default();
        for (name, v) in [
            (PixelMapName::IToR, vec![0.0, 0.2, 0.5, 1.0]),
            (PixelMapName::IToG, vec![1.0, 0.5, 0.25, 0.9]),
            (PixelMapName::IToB, vec![0.1, 0.9]),
            (PixelMapName::IToA, vec![1.0]),
        ] {
            let map = PixelMap::new(name, &v, MapValues::Float).expect("a power of two");
            m.set(&map).expect("stored");
        }
        m
    }

    #[test]
    fn indices_are_masked_to_each_map_and_rounded_to_8_bits() {
        let m = maps();
        assert_eq!(rgba8(0, &m), [0, 255, 26, 255]);
        assert_eq!(rgba8(1, &m), [51, 128, 230, 255]);
        assert_eq!(rgba8(6, &m), [128, 64, 26, 255]);
        assert_eq!(rgba8(u32::MAX, &m), [255, 230, 230, 255]);
    }

    #[test]
    fn elements_become_indices_as_c_converts_them() {
        assert_eq!(indices(&[0xff], PixelType::Byte), vec![u32::MAX]);
        let floats: Vec<u8> = [1.7f32, -1.0, -2.5, 1e10, f32::NAN]
            .iter()
            .flat_map(|f| f.to_ne_bytes())
            .collect();
        assert_eq!(
            indices(&floats, PixelType::Float),
            vec![1, u32::MAX, u32::MAX - 1, 1_410_065_408, 0]
        );
    }

    #[test]
    fn shift_and_offset_wrap_on_32_bits() {
        let mut t = PixelTransfer::DEFAULT;
        t.index_shift = 1;
        t.index_offset = 1;
        assert_eq!(t.colour_index(255), 511);
        t.index_shift = -1;
        t.index_offset = -1;
        assert_eq!(t.colour_index(0), u32::MAX);
        assert_eq!(t.colour_index(255), 126);
    }

    #[test]
    fn bits_read_most_significant_first_image_by_image() {
        let shape = PixelShape {
            kind: ShapeKind::IndexBits(LsbFirst::Honoured),
            ..PixelShape::volume(5, 1, 2, PixelFormat::ColorIndex, PixelType::UnsignedByte)
        };
        assert_eq!(
            bits_as_indices(&[0b1010_0000, 0b0100_1000], shape),
            vec![1, 0, 1, 0, 0, 0, 1, 0, 0, 1]
        );
    }

    #[test]
    fn a_signed_byte_image_draws_through_snorm_storage() {
        assert_eq!(
            (drawn_component(230, PixelType::Byte) * 255.0).round(),
            231.0
        );
        assert_eq!(
            (drawn_component(230, PixelType::Short) * 255.0).round(),
            230.0
        );
        assert_eq!(drawn_component(128, PixelType::UnsignedByte), 128.0 / 255.0);
    }
}
