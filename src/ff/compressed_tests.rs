use super::*;

/// One DXT1 block: endpoints and 2-bit indices (texel t at bits 2t).
fn dxt1(c0: u16, c1: u16, indices: u32) -> Vec<u8> {
    let mut b = c0.to_le_bytes().to_vec();
    b.extend(c1.to_le_bytes());
    b.extend(indices.to_le_bytes());
    b
}

/// Texels 0 to 3 of a block image take codes 0 to 3.
const CODES_0123: u32 = 0b11_10_01_00;

#[test]
fn four_colour_blocks_interpolate_as_mesa() {
    // Measured on Mesa: red over blue gives (170, 0, 84) and (85, 0, 169), not 85 and 170.
    let t = decode(
        CompressedFormat::RgbDxt1,
        4,
        4,
        &dxt1(0xf800, 0x001f, CODES_0123),
    );
    assert_eq!(
        &t[0..16],
        &[255, 0, 0, 255, 0, 0, 255, 255, 170, 0, 84, 255, 85, 0, 169, 255]
    );
}

#[test]
fn three_colour_blocks_average_and_keep_black_or_transparent() {
    // c0 ≤ c1: colour 2 is the rounded mean, colour 3 black (transparent in RGBA_DXT1).
    let block = dxt1(0x001f, 0xf800, CODES_0123);
    let rgb = decode(CompressedFormat::RgbDxt1, 4, 4, &block);
    assert_eq!(&rgb[8..16], &[128, 0, 128, 255, 0, 0, 0, 255]);
    let rgba = decode(CompressedFormat::RgbaDxt1, 4, 4, &block);
    assert_eq!(&rgba[12..16], &[0, 0, 0, 0]);
    // Equal endpoints are three-colour too.
    let eq = decode(CompressedFormat::RgbaDxt1, 4, 4, &dxt1(5, 5, 3));
    assert_eq!(&eq[0..4], &[0, 0, 0, 0]);
}

#[test]
fn dxt3_and_dxt5_colour_blocks_are_always_four_colour() {
    let mut block = vec![0xff; 8];
    block.extend(dxt1(0x001f, 0xf800, CODES_0123));
    let t = decode(CompressedFormat::RgbaDxt3, 4, 4, &block);
    // Colour 3 = LERP(blue, red, 170): (169, 0, 85).
    assert_eq!(&t[12..16], &[169, 0, 85, 255]);
}

#[test]
fn dxt5_alpha_codes_follow_mesas_weights() {
    // a0 = 200 > a1 = 10: 200, 10, 173, 146, 119, 92, 64, 38 (measured).
    let mut block = vec![200u8, 10];
    let mut bits = 0u64;
    for t in 0..8u64 {
        bits |= t << (3 * t);
    }
    block.extend(&bits.to_le_bytes()[..6]);
    block.extend(dxt1(0, 0, 0));
    let t = decode(CompressedFormat::RgbaDxt5, 4, 4, &block);
    let alphas: Vec<u8> = (0..8).map(|i| t[4 * i + 3]).collect();
    assert_eq!(alphas, [200, 10, 173, 146, 119, 92, 64, 38]);
    // a0 ≤ a1: four weights, then 0 and 255.
    block[0] = 10;
    block[1] = 200;
    let t = decode(CompressedFormat::RgbaDxt5, 4, 4, &block);
    let alphas: Vec<u8> = (0..8).map(|i| t[4 * i + 3]).collect();
    assert_eq!(&alphas[6..], &[0, 255]);
    assert_eq!(alphas[2], (10 + ((190 * 51) >> 8)) as u8);
}

#[test]
fn sizes_count_started_blocks_and_odd_images_drop_the_rest() {
    assert_eq!(CompressedFormat::RgbDxt1.image_size(5, 5), 32);
    assert_eq!(CompressedFormat::RgbaDxt5.image_size(1, 1), 16);
    assert_eq!(CompressedFormat::RgbDxt1.image_size(0, 8), 0);
    let blocks = [dxt1(0xffff, 0, 0), dxt1(0, 0xffff, 0)].concat();
    let t = decode(CompressedFormat::RgbDxt1, 5, 2, &blocks);
    assert_eq!(t.len(), 5 * 2 * 4);
    // Texel 4 of row 0 is the second block's first: c0 = 0 ≤ c1, code 0: black.
    assert_eq!(&t[16..20], &[0, 0, 0, 255]);
    assert_eq!(&t[0..4], &[255, 255, 255, 255]);
}

#[test]
fn a_sub_image_replaces_whole_blocks() {
    let mut level = vec![0u8; 8 * 4];
    splice(
        &mut level,
        8,
        CompressedFormat::RgbDxt1,
        (4, 4),
        (4, 4),
        &[7; 8],
    );
    assert_eq!(&level[24..32], &[7; 8]);
    assert!(level[..24].iter().all(|b| *b == 0));
}
