//! glPixelMap's sizes, stored values and lookups at their boundaries.

use super::*;
use glam::Vec4;

#[test]
fn sizes_outside_the_table_or_not_powers_of_two_are_refused() {
    let v = vec![0.5; 3];
    assert!(PixelMap::new(PixelMapName::RToR, &v, MapValues::Float).is_ok());
    assert!(PixelMap::new(PixelMapName::SToS, &v, MapValues::Float).is_err());
    assert!(PixelMap::new(PixelMapName::IToA, &v[..2], MapValues::Float).is_ok());
    assert!(PixelMap::new(PixelMapName::RToR, &[], MapValues::Float).is_err());
    let big = vec![0.0; MAX_PIXEL_MAP_TABLE + 1];
    assert!(PixelMap::new(PixelMapName::GToG, &big, MapValues::Float).is_err());
    assert!(PixelMap::new(PixelMapName::IToI, &big[..256], MapValues::Float).is_ok());
}

#[test]
fn values_are_stored_clamped_normalised_or_rounded() {
    let m = PixelMap::new(PixelMapName::RToR, &[-1.0, 2.0], MapValues::Float).unwrap();
    assert_eq!(&*m.values, &[0.0, 1.0]);
    let m = PixelMap::new(PixelMapName::BToB, &[65535.0, 32768.0], MapValues::UShort).unwrap();
    assert_eq!(m.values[0], 1.0);
    assert_eq!(m.values[1], (32768.0f64 / 65535.0) as f32);
    let m = PixelMap::new(PixelMapName::AToA, &[4294967295.0], MapValues::UInt).unwrap();
    assert_eq!(&*m.values, &[1.0]);
    let m = PixelMap::new(PixelMapName::SToS, &[2.5, 7.0], MapValues::Float).unwrap();
    assert_eq!(&*m.values, &[3.0, 7.0]);
    let m = PixelMap::new(PixelMapName::SToS, &[300.0, 7.0], MapValues::UShort).unwrap();
    assert_eq!(&*m.values, &[300.0, 7.0], "an index map keeps integers");
}

#[test]
fn lookups_take_the_entry_below() {
    let mut maps = PixelMaps::default();
    assert_eq!(
        maps.color(Vec4::ONE),
        Vec4::ZERO,
        "the initial map is one 0"
    );
    let ramp: Vec<f64> = (0..5).map(|i| f64::from(i) / 4.0).rev().collect();
    maps.set(&PixelMap::new(PixelMapName::RToR, &ramp, MapValues::Float).unwrap())
        .unwrap();
    // Texel j = ⌊256·c⌋ (at most 255), entry ⌊5j/256⌋: 0 → entry 0 (1.0), 1 → texel 255,
    // entry 4 (0.0), 0.2 → texel 51, entry 0 (Mesa), 0.625 → texel 160, entry 3,
    // 0.999 → texel 255, entry 4.
    assert_eq!(maps.lookup(PixelMapName::RToR, 0.0), 1.0);
    assert_eq!(maps.lookup(PixelMapName::RToR, 1.0), 0.0);
    assert_eq!(maps.lookup(PixelMapName::RToR, 0.2), 1.0);
    assert_eq!(maps.lookup(PixelMapName::RToR, 0.625), 0.25);
    assert_eq!(
        maps.lookup(PixelMapName::RToR, 0.999),
        0.0,
        "255.7 → texel 255 → entry 4"
    );
    assert_eq!(
        maps.lookup(PixelMapName::RToR, 52.0 / 256.0),
        0.75,
        "texel 52 → entry 1 (5·52 = 260)"
    );
    assert_eq!(
        maps.lookup(PixelMapName::RToR, 51.99 / 256.0),
        1.0,
        "texel 51 → entry 0 (5·51 = 255)"
    );
    let s = PixelMap::new(PixelMapName::SToS, &[5.0, 6.0, 7.0, 8.0], MapValues::Float).unwrap();
    maps.set(&s).unwrap();
    assert_eq!(maps.stencil(6), 7.0, "6 & 3 = 2");
}
