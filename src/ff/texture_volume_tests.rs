//! The depth dimension of texture levels: completeness and generated chains of volumes
//! (GL 1.5 §3.8.8/§3.8.10 with GL 1.2's depth), and glTexImage3D's size checks as Mesa
//! 22.3 llvmpipe gives them (measured natively: MAX_3D_TEXTURE_SIZE 2048, level 11 accepted,
//! level 12 and a width of 3000 INVALID_VALUE).

use super::*;
use crate::ff::GlErrorKind;

fn volume(format: TexFormat, (width, height, depth): (i32, i32, i32)) -> Option<TexLevel> {
    Some(TexLevel {
        internal_format: format,
        width,
        height,
        depth,
        data: None,
    })
}

/// A mipmapped 8×4×2 chain is 8×4×2, 4×2×1, 2×1×1, 1×1×1; the depth halves like the
/// other dimensions and stops at 1.
#[test]
fn volume_chains_halve_every_dimension() {
    let mut t = TextureObject::new(TextureTarget::Texture2D);
    t.params.min_filter = Filter::LinearMipmapLinear;
    t.params.generate_mipmap = true;
    t.set_level(0, volume(TexFormat::Rgba8, (8, 4, 2)).unwrap());
    t.base_level_changed();
    let sizes: Vec<_> = t
        .levels
        .iter()
        .flatten()
        .map(|l| (l.width, l.height, l.depth))
        .collect();
    assert_eq!(sizes, [(8, 4, 2), (4, 2, 1), (2, 1, 1), (1, 1, 1)]);
    assert_eq!(t.completeness(), Ok(TexFormat::Rgba8));
    // A depth that does not halve breaks the chain.
    t.levels[1] = volume(TexFormat::Rgba8, (4, 2, 2));
    assert_eq!(
        t.completeness(),
        Err(Incomplete::WrongSize {
            level: 1,
            expected: (4, 2, 1),
            found: (4, 2, 2),
        })
    );
}

/// A 1×1×4 base needs levels down to 1×1×1: the depth alone sets p.
#[test]
fn depth_alone_sets_the_chain_length() {
    let mut t = TextureObject::new(TextureTarget::Texture2D);
    t.params.min_filter = Filter::NearestMipmapNearest;
    t.levels = vec![
        volume(TexFormat::Rgb8, (1, 1, 4)),
        volume(TexFormat::Rgb8, (1, 1, 2)),
    ];
    assert_eq!(t.completeness(), Err(Incomplete::MissingLevel(2)));
    t.levels.push(volume(TexFormat::Rgb8, (1, 1, 1)));
    assert!(t.is_complete());
    t.levels[0] = volume(TexFormat::Rgb8, (1, 1, 0));
    assert_eq!(t.completeness(), Err(Incomplete::EmptyBaseLevel));
}

#[test]
fn volume_sizes_follow_mesa() {
    let kind = |level, size, border| check_volume_size(level, size, border).map_err(|e| e.kind);
    assert_eq!(kind(0, [4, 4, 4], 0), Ok(()));
    assert_eq!(kind(11, [1, 1, 1], 0), Ok(()));
    assert_eq!(kind(0, [2048, 1, 1], 0), Ok(()));
    assert_eq!(kind(12, [1, 1, 1], 0), Err(GlErrorKind::InvalidValue));
    assert_eq!(kind(-1, [1, 1, 1], 0), Err(GlErrorKind::InvalidValue));
    assert_eq!(kind(0, [3000, 1, 1], 0), Err(GlErrorKind::InvalidValue));
    assert_eq!(kind(0, [4, -1, 4], 0), Err(GlErrorKind::InvalidValue));
    assert_eq!(kind(0, [4, 4, 4], 2), Err(GlErrorKind::InvalidValue));
    assert_eq!(
        volume_size(PixelFormat::Rgba, PixelType::UnsignedByte, 5, 3, 7),
        5 * 3 * 7 * 4
    );
}
