use super::*;

fn packed(p: PackedType) -> PixelType {
    PixelType::Packed(p)
}

#[test]
fn fields_follow_tables_3_11_to_3_13() {
    use PackedType as P;
    // The first component in the highest bits, or (REV) in the lowest.
    assert_eq!(P::UnsignedByte332.fields(), [(5, 3), (2, 3), (0, 2)]);
    assert_eq!(P::UnsignedByte233Rev.fields(), [(0, 3), (3, 3), (6, 2)]);
    assert_eq!(P::UnsignedShort565.fields(), [(11, 5), (5, 6), (0, 5)]);
    assert_eq!(P::UnsignedShort565Rev.fields(), [(0, 5), (5, 6), (11, 5)]);
    assert_eq!(
        P::UnsignedShort1555Rev.fields(),
        [(0, 5), (5, 5), (10, 5), (15, 1)]
    );
    assert_eq!(
        P::UnsignedInt2101010Rev.fields(),
        [(0, 10), (10, 10), (20, 10), (30, 2)]
    );
    assert_eq!(
        P::UnsignedInt1010102.fields(),
        [(22, 10), (12, 10), (2, 10), (0, 2)]
    );
}

#[test]
fn packed_types_take_only_formats_of_their_component_count() {
    use PixelFormat as F;
    let three = packed(PackedType::UnsignedShort565);
    let four = packed(PackedType::UnsignedInt8888Rev);
    assert_eq!(refused(F::Rgb, three), None);
    // Mesa refuses BGR with the 3-component types (measured).
    assert_eq!(refused(F::Bgr, three), Some(GlErrorKind::InvalidOperation));
    assert_eq!(refused(F::Rgba, three), Some(GlErrorKind::InvalidOperation));
    assert_eq!(refused(F::Bgra, four), None);
    assert_eq!(refused(F::Rgb, four), Some(GlErrorKind::InvalidOperation));
    assert_eq!(
        refused(F::Luminance, four),
        Some(GlErrorKind::InvalidOperation)
    );
    assert_eq!(
        refused(F::DepthComponent, three),
        Some(GlErrorKind::InvalidOperation)
    );
    assert_eq!(refused(F::Bgra, PixelType::Byte), None);
}

#[test]
fn fields_widen_to_eight_bits_as_mesa_unpacks_them() {
    // Measured on Mesa (tests/c/pixel_types.c): 5 bits repeat, 3 → 24 and 28 → 231, where
    // round(c·255/31) gives 25 and 230; 6 bits 11 → 44; 3 bits 1 → 36; 2 bits ·85.
    assert_eq!(field_to_unorm8(3, 5), 24);
    assert_eq!(field_to_unorm8(28, 5), 231);
    assert_eq!(field_to_unorm8(31, 5), 255);
    assert_eq!(field_to_unorm8(11, 6), 44);
    assert_eq!(field_to_unorm8(63, 6), 255);
    assert_eq!(field_to_unorm8(1, 3), 36);
    assert_eq!(field_to_unorm8(7, 3), 255);
    assert_eq!(field_to_unorm8(2, 2), 170);
    assert_eq!(field_to_unorm8(1, 1), 255);
    assert_eq!(field_to_unorm8(15, 4), 255);
    // 10 bits round: 195 → 49 (48.6), where a shift gives 48.
    assert_eq!(field_to_unorm8(195, 10), 49);
    assert_eq!(field_to_unorm8(1023, 10), 255);
    assert_eq!(field_to_unorm8(1, 10), 0);
    // Every field of every width stays within [0, 255] and is monotonic.
    for bits in [1, 2, 3, 4, 5, 6, 8, 10] {
        let mut last = 0;
        for v in 0..(1 << bits) {
            let u = field_to_unorm8(v, bits);
            assert!(u >= last, "{bits} bits: {v} → {u} after {last}");
            last = u;
        }
        assert_eq!(last, 255, "{bits} bits reach 255");
    }
}

/// ABGR reverses the group both ways, in the model's RGBA and back.
#[test]
fn abgr_reverses_each_group() {
    let data: Arc<[u8]> = vec![1, 2, 3, 4, 5, 6, 7, 8].into();
    let model = to_model(PixelFormat::Abgr, PixelType::UnsignedByte, data);
    assert_eq!(&model[..], &[4, 3, 2, 1, 8, 7, 6, 5]);
    let back = from_model(
        &model,
        PixelFormat::Abgr,
        PixelType::UnsignedByte,
        ReadFrom::Unorm8,
        Packer::ReadPixels,
    );
    assert_eq!(&back[..], &[1, 2, 3, 4, 5, 6, 7, 8]);
    assert_eq!(
        refused(PixelFormat::Abgr, packed(PackedType::UnsignedInt8888)),
        None
    );
    assert_eq!(
        refused(PixelFormat::Abgr, packed(PackedType::UnsignedShort565)),
        Some(GlErrorKind::InvalidOperation)
    );
}

#[test]
fn bgra_moves_components_and_keeps_their_bytes() {
    let data: Arc<[u8]> = vec![1, 2, 3, 4, 5, 6, 7, 8].into();
    let model = to_model(PixelFormat::Bgra, PixelType::UnsignedByte, data);
    assert_eq!(&model[..], &[3, 2, 1, 4, 7, 6, 5, 8]);
    assert_eq!(
        model_form(PixelFormat::Bgr, PixelType::UnsignedShort),
        (PixelFormat::Rgb, PixelType::UnsignedShort)
    );
    let back = from_model(
        &model,
        PixelFormat::Bgra,
        PixelType::UnsignedByte,
        ReadFrom::Unorm8,
        Packer::ReadPixels,
    );
    assert_eq!(&back[..], &[1, 2, 3, 4, 5, 6, 7, 8]);
}

#[test]
fn signed_types_normalise_by_the_largest_positive_value() {
    // c / 127, at least −1: −128 and −127 are both −1; 64 → 0.5039.
    let data: Arc<[u8]> = vec![0x80, 0x81, 0xff, 0, 1, 64, 127, 0].into();
    let model = to_model(PixelFormat::Rgba, PixelType::Byte, data);
    let f: Vec<f32> = model
        .chunks_exact(4)
        .map(|b| f32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    assert_eq!(f[0], -1.0);
    assert_eq!(f[1], -1.0);
    assert_eq!(f[2], (-1.0f64 / 127.0) as f32);
    assert_eq!(f[3], 0.0);
    assert_eq!(f[5], (64.0f64 / 127.0) as f32);
    assert_eq!(f[6], 1.0);
    assert_eq!(snorm_to_float(i64::from(i32::MIN), 32), -1.0);
}

#[test]
fn a_signed_stencil_index_keeps_its_bits() {
    let data: Arc<[u8]> = vec![0xff, 5].into();
    let model = to_model(PixelFormat::StencilIndex, PixelType::Byte, data);
    assert_eq!(
        model_form(PixelFormat::StencilIndex, PixelType::Byte),
        (PixelFormat::StencilIndex, PixelType::UnsignedInt)
    );
    assert_eq!(&model[..4], &u32::MAX.to_ne_bytes());
    assert_eq!(&model[4..], &5u32.to_ne_bytes());
}

#[test]
fn reads_from_eight_bits_follow_mesas_integer_rules() {
    let read = |u: u8, ty: PixelType| -> Vec<u8> {
        let f = f32::from(u) / 255.0;
        let rgba: Vec<u8> = [f, f, f, f].iter().flat_map(|v| v.to_ne_bytes()).collect();
        from_model(
            &rgba,
            PixelFormat::Rgba,
            ty,
            ReadFrom::Unorm8,
            Packer::ReadPixels,
        )
    };
    // Measured: 128 as INT is 0x40404040 (the bits repeated), not round(128/255 · (2³¹−1)).
    assert_eq!(
        &read(128, PixelType::Int)[..4],
        &0x4040_4040i32.to_ne_bytes()
    );
    assert_eq!(&read(255, PixelType::Int)[..4], &i32::MAX.to_ne_bytes());
    assert_eq!(&read(128, PixelType::Short)[..2], &16448i16.to_ne_bytes());
    assert_eq!(read(128, PixelType::Byte)[0], 64);
    assert_eq!(read(3, PixelType::Byte)[0], 1);
    assert_eq!(read(0, PixelType::Byte)[0], 0);
    // 8 → 5 bits rounds (no exact ties), 8 → 10 bits repeats: 43 → 172, not round(172.5).
    let word = |b: Vec<u8>| u32::from_ne_bytes([b[0], b[1], b[2], b[3]]);
    let w = word(read(43, packed(PackedType::UnsignedInt1010102)));
    assert_eq!(w >> 22, 172);
    let w = read(128, packed(PackedType::UnsignedShort565));
    assert_eq!(u16::from_ne_bytes([w[0], w[1]]) >> 11, 16);
}

#[test]
fn reads_from_floats_round_and_clamp() {
    let floats = |v: [f32; 4]| -> Vec<u8> { v.iter().flat_map(|x| x.to_ne_bytes()).collect() };
    let b = from_model(
        &floats([-2.0, 0.5, f32::NAN, 1.5]),
        PixelFormat::Rgba,
        PixelType::Byte,
        ReadFrom::Float,
        Packer::ReadPixels,
    );
    assert_eq!(b, [0x81, 64, 0, 127]);
    let p = from_model(
        &floats([1.0, 0.5, 0.0, 1.0]),
        PixelFormat::Rgba,
        packed(PackedType::UnsignedShort4444),
        ReadFrom::Float,
        Packer::ReadPixels,
    );
    assert_eq!(u16::from_ne_bytes([p[0], p[1]]), 0xf80f);
}

#[test]
fn packed_groups_become_bytes_in_the_formats_order() {
    // 5_6_5 0xf81f: red 31, green 0, blue 31; as BGRA 1_5_5_5_REV 0x801f: blue 31 … alpha 1.
    let v: Arc<[u8]> = 0xf81fu16.to_ne_bytes().to_vec().into();
    let m = to_model(
        PixelFormat::Rgb,
        packed(PackedType::UnsignedShort565),
        v.clone(),
    );
    assert_eq!(&m[..], &[255, 0, 255]);
    let v: Arc<[u8]> = 0x801fu16.to_ne_bytes().to_vec().into();
    let m = to_model(
        PixelFormat::Bgra,
        packed(PackedType::UnsignedShort1555Rev),
        v,
    );
    assert_eq!(&m[..], &[0, 0, 255, 255]);
}

/// Mesa's integer widening and narrowing of unsigned normalised values
/// (`_mesa_unorm_to_unorm`): the bits repeated going up, rounded going down.
#[test]
fn unorm_conversions_follow_mesas_integer_rules() {
    assert_eq!(unorm_to(4369, 16, 31), 143_165_576); // (u << 15) | (u >> 1)
    assert_eq!(unorm_to(4369, 16, 32), 286_331_153); // u · 65537
    assert_eq!(unorm_to(255, 8, 31), i32::MAX as u32);
    assert_eq!(unorm_to(177, 8, 10), 4 * 177 + (177 >> 6));
    assert_eq!(unorm_to(65535, 16, 8), 255);
    assert_eq!(unorm_to(32768, 16, 8), 128);
    assert_eq!(unorm_to(3, 8, 5), 0); // (3·31 + 127) / 255
}

/// A float read as INT: the f32 product with 2³¹, so 1.0 wraps to INT_MIN.
#[test]
fn a_float_one_reads_as_int_min() {
    assert_eq!(Stored::Float(1.0).snorm(32), i64::from(i32::MIN));
    assert_eq!(Stored::Float(0.533_333_36).snorm(32), 1_145_324_672);
    assert_eq!(Stored::Float(-1.0).snorm(32), i64::from(i32::MIN));
    assert_eq!(Stored::Float(2.0).snorm(32), i64::from(i32::MAX));
}
