//! Shadow masks: one byte per pixel, top row first — 255 lit, 0 shadowed, 128 background.

use image::GrayImage;

/// Mask value of a lit geometry pixel.
pub const LIT: u8 = 255;
/// Mask value of a shadowed geometry pixel (including surfaces facing away from the light).
pub const SHADOWED: u8 = 0;
/// Mask value where no geometry was hit.
pub const BACKGROUND: u8 = 128;

/// How a mask value reads: exactly 128 is background; above is lit, below is shadowed (so a
/// filtered technique's intermediate values count as the side they lean to).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Class {
    Lit,
    Shadowed,
    Background,
}

impl Class {
    pub fn of(v: u8) -> Class {
        match v {
            BACKGROUND => Class::Background,
            v if v > BACKGROUND => Class::Lit,
            _ => Class::Shadowed,
        }
    }
}

/// A shadow mask, row-major, top row first.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mask {
    pub width: u32,
    pub height: u32,
    pub data: Vec<u8>,
}

impl Mask {
    /// A mask filled with `value`.
    pub fn filled(width: u32, height: u32, value: u8) -> Mask {
        Mask {
            width,
            height,
            data: vec![value; width as usize * height as usize],
        }
    }

    /// The class of pixel (x, y), y counted from the top.
    pub fn class(&self, x: u32, y: u32) -> Class {
        Class::of(self.data[(y * self.width + x) as usize])
    }

    /// As an 8-bit grey image (for PNG output).
    pub fn to_image(&self) -> GrayImage {
        GrayImage::from_raw(self.width, self.height, self.data.clone())
            .unwrap_or_else(|| GrayImage::new(self.width, self.height))
    }

    /// From an 8-bit grey image (e.g. a technique's mask read back from a PNG).
    pub fn from_image(image: &GrayImage) -> Mask {
        Mask {
            width: image.width(),
            height: image.height(),
            data: image.as_raw().clone(),
        }
    }
}
