//! Texture borders as Mesa's gallium drivers take them: stripped at the call.
//!
//! GL 1.x lets an image carry a border of one texel on each side (GL 1.5 §3.8.1: width
//! 2^n + 2·border), sampled by the CLAMP wrap modes. Mesa's state tracker sets
//! `StripTextureBorder`, so `glTexImage1D/2D/3D` and `glCopyTexImage1D/2D` with border 1
//! keep only the interior: the level is (w − 2) × (h − 2) × (d − 2) with border 0 (a
//! height or depth of 2 kept whole, as Mesa's `strip_texture_border` keeps it), its
//! texels the image's rows 1 … h − 2, columns 1 … w − 2 (of images 1 … d − 2), and
//! TEXTURE_WIDTH/HEIGHT/BORDER answer the stripped level (measured on Mesa 22.3: a 6×6
//! image with border 1 is a 4×4 level whose first texel is the image's (1, 1); 5×6 gives
//! 3×4; glCopyTexImage2D(x, y, 6, 6, 1) copies the 4×4 from (x + 1, y + 1)). The
//! CLAMP modes then blend with the border colour where GL would read the border texels.
//!
//! A proxy keeps its border (Mesa answers 6 × 6, border 1), and a border other than 0 or
//! 1, or one wider than half a side, is left in the command for the model to refuse
//! (INVALID_VALUE), as Mesa refuses it.

use super::command::{CopyTexImage, TexData, TexImage};

/// `t` (of `dims` dimensions: 1, 2 or 3) with its border stripped, where it has a
/// border of 1 on sides of at least 2 texels and its texels are given (bytes or none).
pub fn strip_image(t: TexImage, dims: usize) -> TexImage {
    let sides = [t.width, t.height, t.depth];
    if t.border != 1 || sides.iter().take(dims).any(|&s| s < 2) {
        return t;
    }
    // Mesa strips the width always, a height or depth only from 3 up: a 2-high image
    // keeps both rows (measured: 2×2 with border 1 is a 0×2 level).
    let stripped = |axis: usize| axis < dims && (axis == 0 || sides[axis] >= 3);
    let inner = |axis: usize| sides[axis] - if stripped(axis) { 2 } else { 0 };
    let (w, h, d) = (inner(0), inner(1), inner(2));
    let data = match &t.data {
        TexData::Null => TexData::Null,
        TexData::Bytes(bytes) => {
            let group = t.ty.group_bytes(t.format);
            let (full_w, full_h) = (t.width as usize, t.height as usize);
            // The first kept column, row and image: 1 on the stripped axes.
            let skip = |axis: usize| usize::from(stripped(axis));
            let mut out = Vec::with_capacity(w as usize * h as usize * d as usize * group);
            for z in 0..d as usize {
                for y in 0..h as usize {
                    let row = ((z + skip(2)) * full_h + y + skip(1)) * full_w + skip(0);
                    let start = row * group;
                    let Some(texels) = bytes.get(start..start + w as usize * group) else {
                        // Shorter than its shape: left whole for the model's length check.
                        return t;
                    };
                    out.extend_from_slice(texels);
                }
            }
            TexData::Bytes(out.into())
        }
        // A readback slot's bytes arrive at execution: the border stays, and is refused.
        _ => return t,
    };
    TexImage {
        width: w,
        height: h,
        depth: d,
        border: 0,
        data,
        ..t
    }
}

/// `c` (of `dims` dimensions: 1 or 2) with its border stripped: the copy starts one
/// pixel further right (and up) and is two narrower (and lower).
pub fn strip_copy(c: CopyTexImage, dims: usize) -> CopyTexImage {
    if c.border != 1 || c.width < 2 || (dims == 2 && c.height < 2) {
        return c;
    }
    let two_d = dims == 2;
    CopyTexImage {
        x: c.x + 1,
        y: c.y + i32::from(two_d),
        width: c.width - 2,
        height: c.height - if two_d { 2 } else { 0 },
        border: 0,
        ..c
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::{PixelFormat, PixelType, TexFormat, TextureTarget};

    fn image(w: i32, h: i32, d: i32, border: i32) -> TexImage {
        let bytes: Vec<u8> = (0..w * h * d).map(|i| i as u8).collect();
        TexImage {
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::Luminance8,
            requested: None,
            width: w,
            height: h,
            depth: d,
            border,
            format: PixelFormat::Luminance,
            ty: PixelType::UnsignedByte,
            data: TexData::Bytes(bytes.into()),
        }
    }

    fn bytes(t: &TexImage) -> Vec<u8> {
        match &t.data {
            TexData::Bytes(b) => b.to_vec(),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_bordered_image_keeps_its_interior() {
        // 5 × 4, texel (x, y) = 5y + x: the interior is rows 1–2, columns 1–3.
        let t = strip_image(image(5, 4, 1, 1), 2);
        assert_eq!((t.width, t.height, t.depth, t.border), (3, 2, 1, 0));
        assert_eq!(bytes(&t), vec![6, 7, 8, 11, 12, 13]);
        // 1D: one row, the ends dropped.
        let t = strip_image(image(4, 1, 1, 1), 1);
        assert_eq!((t.width, t.height, t.border), (2, 1, 0));
        assert_eq!(bytes(&t), vec![1, 2]);
        // 3D: 3 × 3 × 3 keeps the centre texel, 13.
        let t = strip_image(image(3, 3, 3, 1), 3);
        assert_eq!((t.width, t.height, t.depth, t.border), (1, 1, 1, 0));
        assert_eq!(bytes(&t), vec![13]);
        // A height of 2 keeps both rows: 4 × 2 → 2 × 2, columns 1–2 of rows 0–1.
        let t = strip_image(image(4, 2, 1, 1), 2);
        assert_eq!((t.width, t.height, t.border), (2, 2, 0));
        assert_eq!(bytes(&t), vec![1, 2, 5, 6]);
    }

    #[test]
    fn borders_the_model_refuses_are_left_for_it() {
        for (w, h, border) in [(1, 4, 1), (4, 1, 1), (6, 6, 2), (6, 6, -1), (6, 6, 0)] {
            let t = strip_image(image(w, h, 1, border), 2);
            assert_eq!((t.width, t.height, t.border), (w, h, border));
        }
        let copy = CopyTexImage {
            face: None,
            level: 0,
            internal_format: TexFormat::Rgba8,
            requested: None,
            x: 3,
            y: 5,
            width: 6,
            height: 6,
            border: 1,
        };
        let s = strip_copy(copy, 2);
        assert_eq!((s.x, s.y, s.width, s.height, s.border), (4, 6, 4, 4, 0));
        let s = strip_copy(CopyTexImage { height: 1, ..copy }, 1);
        assert_eq!((s.x, s.y, s.width, s.height, s.border), (4, 5, 4, 1, 0));
        let s = strip_copy(CopyTexImage { width: 1, ..copy }, 2);
        assert_eq!(s, CopyTexImage { width: 1, ..copy });
    }
}
