//! The address arithmetic of §3.6.4 on small images, each boundary named.

use super::*;
use crate::ff::texture::{PixelFormat, PixelType};

fn rgb_ub(w: i32, h: i32) -> PixelShape {
    PixelShape::groups(w, h, PixelFormat::Rgb, PixelType::UnsignedByte)
}

#[test]
fn row_length_and_skips_move_the_first_group_and_the_stride() {
    let p = Packing {
        row_length: 5,
        skip_rows: 2,
        skip_pixels: 1,
        ..Packing::DEFAULT
    };
    // l = 5 RGB bytes: 15 rounded up to 4 = 16; first = 2·16 + 1·3.
    let lay = layout(rgb_ub(2, 2), &p);
    assert_eq!((lay.stride, lay.first, lay.tight_row), (16, 35, 6));
    assert_eq!(lay.extent, 35 + 16 + 6);
    let src: Vec<u8> = (0..=255).collect();
    let out = unpack(&src, rgb_ub(2, 2), &p).unwrap();
    assert_eq!(out, [35, 36, 37, 38, 39, 40, 51, 52, 53, 54, 55, 56]);
    assert_eq!(unpack(&src[..lay.extent - 1], rgb_ub(2, 2), &p), None);
}

#[test]
fn elements_wider_than_the_alignment_are_not_padded() {
    let p = Packing::aligned(2);
    let f = PixelShape::groups(3, 2, PixelFormat::Luminance, PixelType::Float);
    assert_eq!(layout(f, &p).stride, 12);
    let ub = PixelShape::groups(3, 2, PixelFormat::Luminance, PixelType::UnsignedByte);
    assert_eq!(layout(ub, &Packing::aligned(8)).stride, 8);
}

#[test]
fn swap_bytes_reverses_each_element_not_the_group() {
    let p = Packing {
        swap_bytes: ByteOrder::Swapped,
        ..Packing::aligned(1)
    };
    let us = PixelShape::groups(1, 1, PixelFormat::LuminanceAlpha, PixelType::UnsignedShort);
    assert_eq!(unpack(&[1, 2, 3, 4], us, &p).unwrap(), [2, 1, 4, 3]);
    let ui = PixelShape::groups(1, 1, PixelFormat::Luminance, PixelType::UnsignedInt);
    assert_eq!(unpack(&[1, 2, 3, 4], ui, &p).unwrap(), [4, 3, 2, 1]);
    let ub = PixelShape::groups(2, 1, PixelFormat::Luminance, PixelType::UnsignedByte);
    assert_eq!(unpack(&[1, 2], ub, &p).unwrap(), [1, 2]);
}

#[test]
fn lsb_first_bitmaps_and_bit_skips() {
    let lsb = Packing {
        lsb_first: BitOrder::LsbFirst,
        ..Packing::aligned(1)
    };
    let b = PixelShape::bitmap(8, 1);
    // LSB first: bit 0 is the leftmost pixel; the tight form puts it in bit 7.
    assert_eq!(unpack(&[0x01], b, &lsb).unwrap(), [0x80]);
    assert_eq!(unpack(&[0x80], b, &lsb).unwrap(), [0x01]);
    let skip = Packing {
        skip_pixels: 3,
        ..Packing::aligned(1)
    };
    // Skipping 3 bits: pixels 0..8 are bits 3..11 of the row, MSB first.
    let lay = layout(b, &skip);
    assert_eq!((lay.first, lay.span), (0, 2));
    assert_eq!(
        unpack(&[0b0001_0000, 0b1110_0000], b, &skip).unwrap(),
        [0x87]
    );
    let skip9 = Packing {
        skip_pixels: 9,
        ..Packing::aligned(1)
    };
    assert_eq!(layout(b, &skip9).first, 1);
    // Rows of a bitmap: a·⌈l / 8a⌉ bytes, l = 17 bits, a = 4: 4 bytes.
    let long = Packing {
        row_length: 17,
        ..Packing::DEFAULT
    };
    assert_eq!(layout(PixelShape::bitmap(3, 2), &long).stride, 4);
}

#[test]
fn pack_is_unpack_inverted_and_leaves_the_gaps() {
    for p in [
        Packing {
            row_length: 4,
            skip_rows: 1,
            skip_pixels: 1,
            swap_bytes: ByteOrder::Swapped,
            ..Packing::DEFAULT
        },
        Packing {
            skip_pixels: 5,
            lsb_first: BitOrder::LsbFirst,
            ..Packing::aligned(2)
        },
    ] {
        for shape in [
            PixelShape::groups(2, 2, PixelFormat::Rgb, PixelType::UnsignedShort),
            PixelShape::bitmap(11, 3),
        ] {
            let lay = layout(shape, &p);
            let tight: Vec<u8> = (0..lay.tight_row * lay.rows)
                .map(|i| (i * 37 + 11) as u8)
                .collect();
            let mut dst = vec![0xAAu8; lay.extent];
            assert!(pack(&tight, &mut dst, shape, &p));
            let back = unpack(&dst, shape, &p).unwrap();
            // Only the bits of real pixels survive a round trip.
            let keep = |v: &[u8]| -> Vec<u8> {
                match shape.kind {
                    ShapeKind::Groups | ShapeKind::IndexRun => v.to_vec(),
                    ShapeKind::Bitmap | ShapeKind::IndexBits(_) => v
                        .chunks(lay.tight_row)
                        .flat_map(|r| {
                            let mut r = r.to_vec();
                            if let Some(l) = r.last_mut() {
                                *l &= 0xFFu8 << ((8 - shape.width as usize % 8) % 8);
                            }
                            r
                        })
                        .collect(),
                }
            };
            assert_eq!(keep(&back), keep(&tight), "{p:?} {shape:?}");
            if shape.kind == ShapeKind::Groups {
                assert_eq!(dst[0], 0xAA, "a skipped row is left alone");
            }
        }
    }
}

/// GL 1.2 §3.8.1 as Mesa 22.3 reads and writes it (measured, `tests/c/tex3d.c`): a 2×2×2
/// LUMINANCE volume with IMAGE_HEIGHT 3, SKIP_IMAGES 1 and SKIP_ROWS 1 starts 1·6 + 1·2
/// bytes in, its images 6 bytes apart; a 2D rectangle ignores both image parameters.
#[test]
fn images_of_a_volume_lie_image_height_rows_apart() {
    let p = Packing {
        image_height: 3,
        skip_images: 1,
        skip_rows: 1,
        ..Packing::aligned(1)
    };
    let l = PixelShape::volume(2, 2, 2, PixelFormat::Luminance, PixelType::UnsignedByte);
    let lay = layout(l, &p);
    assert_eq!((lay.first, lay.image_stride, lay.images), (8, 6, 2));
    assert_eq!(lay.extent, 8 + 6 + 2 + 2);
    let src: Vec<u8> = (0..=255).collect();
    assert_eq!(unpack(&src, l, &p).unwrap(), [8, 9, 10, 11, 14, 15, 16, 17]);
    let flat = PixelShape::groups(2, 2, PixelFormat::Luminance, PixelType::UnsignedByte);
    assert_eq!(unpack(&src, flat, &p).unwrap(), [2, 3, 4, 5]);
    // Packed: bytes between the images are left alone.
    let pack_p = Packing {
        image_height: 3,
        skip_images: 1,
        ..Packing::aligned(1)
    };
    let mut dst = vec![0xEE; 20];
    assert!(pack(&[8, 9, 10, 11, 14, 15, 16, 17], &mut dst, l, &pack_p));
    let e = 0xEE;
    assert_eq!(
        dst,
        [e, e, e, e, e, e, 8, 9, 10, 11, e, e, 14, 15, 16, 17, e, e, e, e]
    );
    // An empty volume reads nothing.
    let empty = PixelShape::volume(2, 2, 0, PixelFormat::Luminance, PixelType::UnsignedByte);
    assert_eq!(layout(empty, &p).extent, 0);
}

#[test]
fn a_colour_index_image_is_one_run_whatever_the_alignment() {
    use crate::ff::args::LsbFirst;
    let p = Packing::aligned(4);
    let run = PixelShape {
        kind: ShapeKind::IndexRun,
        ..PixelShape::groups(3, 2, PixelFormat::ColorIndex, PixelType::UnsignedByte)
    };
    let src = [1, 2, 3, 99, 0, 1, 2, 99];
    assert_eq!(unpack(&src, run, &p), Some(vec![1, 2, 3, 99, 0, 1]));
    // Bits: 5 × 2 of them in one run; DrawPixels reads the most significant bit first.
    let bits = PixelShape {
        kind: ShapeKind::IndexBits(LsbFirst::Ignored),
        ..PixelShape::groups(5, 2, PixelFormat::ColorIndex, PixelType::UnsignedByte)
    };
    let lsb = Packing {
        lsb_first: BitOrder::LsbFirst,
        ..Packing::aligned(1)
    };
    assert_eq!(unpack(&[0xc4, 0x5b], bits, &lsb), Some(vec![0xc4, 0x40]));
}
