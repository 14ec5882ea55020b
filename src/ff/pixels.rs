//! Pixel rectangles (GL 1.5 §3.6, §3.7, §4.3.3): glPixelTransfer and glPixelZoom state,
//! the glBitmap, glDrawPixels and glCopyPixels commands, and the conversion of an image to
//! the fragments' colour, depth or stencil values both pipelines draw.
//!
//! The conversion is the spec's sequence (§3.6.4), done once here on the CPU so the emulated
//! path draws exactly these values:
//! 1. unpack: each component of type UNSIGNED_BYTE/SHORT/INT becomes c/(2ⁿ − 1) (Table
//!    2.9), a FLOAT as it is; STENCIL_INDEX values stay integers;
//! 2. conversion to RGBA: L → (L, L, L, 1), LA → (L, L, L, A), A → (0, 0, 0, A),
//!    RGB → (R, G, B, 1), R → (R, 0, 0, 1), G → (0, G, 0, 1), B → (0, 0, B, 1) (Table 3.8:
//!    missing colour components are 0, alpha 1);
//! 3. arithmetic: c·c_SCALE + c_BIAS on all four components (the filled-in ones too), depth
//!    d·DEPTH_SCALE + DEPTH_BIAS; stencil shifted by INDEX_SHIFT (left for > 0, right for
//!    < 0) plus INDEX_OFFSET by GL — which Mesa skips, and so does the layer;
//! 4. final conversion: colours and depth clamped to [0, 1] (§3.6.5); stencil masked to
//!    the stencil bits, 2⁸ − 1.
//!
//! COLOR_INDEX images take their colours from the I_TO maps with no transfer at all
//! (`index_pixels`).
//!
//! 5. with MAP_COLOR, each colour component through its map (R_TO_R … A_TO_A,
//!    `pixel_map`). MAP_STENCIL is state: Mesa 22.3 draws stencil images without the index
//!    arithmetic, and the layer follows it there (see `convert`).

use std::sync::Arc;

use glam::Vec4;

use super::error::{GlError, GlResult};
use super::pixel_map::PixelMaps;
use super::pixel_types;
use super::texture::{PixelFormat, PixelType};

/// The most pixels one glDrawPixels, glBitmap or glCopyPixels may cover: 2²⁴ (4096², or a
/// 16384 × 1024 strip). The converted image holds 16 bytes a pixel, so the budget bounds it
/// at 256 MiB before anything is read or allocated; more is refused with INVALID_VALUE.
pub const MAX_RECT_PIXELS: u64 = 1 << 24;

/// Stencil bits of every target the layer draws into (D24S8, D32F with S8).
pub const STENCIL_BITS: u32 = 8;

/// Refuses a rectangle with a negative side (INVALID_VALUE, §3.6.4) or beyond the budget.
pub fn check_rect(call: &'static str, width: i32, height: i32) -> GlResult {
    if width < 0 || height < 0 {
        return Err(GlError::invalid_value(match call {
            "Bitmap" => "Bitmap width and height must be ≥ 0",
            "CopyPixels" => "CopyPixels width and height must be ≥ 0",
            _ => "DrawPixels width and height must be ≥ 0",
        }));
    }
    if width as u64 * height as u64 > MAX_RECT_PIXELS {
        return Err(GlError::invalid_value(
            "pixel rectangle beyond 2^24 pixels (fixedfunc's budget)",
        ));
    }
    Ok(())
}

/// glPixelTransfer state (GL 1.5 Table 6.16).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PixelTransfer {
    /// RED/GREEN/BLUE/ALPHA_SCALE. GL default: 1.
    pub scale: Vec4,
    /// RED/GREEN/BLUE/ALPHA_BIAS. GL default: 0.
    pub bias: Vec4,
    /// GL default: 1.
    pub depth_scale: f32,
    /// GL default: 0.
    pub depth_bias: f32,
    /// GL default: 0.
    pub index_shift: i32,
    /// GL default: 0.
    pub index_offset: i32,
    /// MAP_COLOR. GL default: FALSE.
    pub map_color: bool,
    /// MAP_STENCIL. GL default: FALSE. State only.
    pub map_stencil: bool,
}

impl PixelTransfer {
    pub const DEFAULT: Self = Self {
        scale: Vec4::ONE,
        bias: Vec4::ZERO,
        depth_scale: 1.0,
        depth_bias: 0.0,
        index_shift: 0,
        index_offset: 0,
        map_color: false,
        map_stencil: false,
    };

    pub fn set(&mut self, p: PixelTransferParam) {
        use PixelTransferParam as P;
        match p {
            P::Scale(i, v) => self.scale[usize::from(i.min(3))] = v,
            P::Bias(i, v) => self.bias[usize::from(i.min(3))] = v,
            P::DepthScale(v) => self.depth_scale = v,
            P::DepthBias(v) => self.depth_bias = v,
            P::IndexShift(v) => self.index_shift = v,
            P::IndexOffset(v) => self.index_offset = v,
            P::MapColor(b) => self.map_color = b,
            P::MapStencil(b) => self.map_stencil = b,
        }
    }

    /// Steps 2–4 on one unpacked colour already converted to RGBA.
    pub fn color(&self, c: Vec4) -> Vec4 {
        (c * self.scale + self.bias).clamp(Vec4::ZERO, Vec4::ONE)
    }

    /// d·DEPTH_SCALE + DEPTH_BIAS clamped to [0, 1].
    pub fn depth(&self, d: f32) -> f32 {
        let v = d * self.depth_scale + self.depth_bias;
        // A NaN depth is drawn as 0 (measured on Mesa 22.3: glDrawPixels of a NaN
        // GL_FLOAT depth writes 0).
        if v.is_nan() {
            0.0
        } else {
            v.clamp(0.0, 1.0)
        }
    }

    /// The index arithmetic of §3.6.4 on a stencil value, masked to the stencil bits:
    /// v << shift (shift > 0) or v >> −shift, plus the offset, mod 2⁸. Shifts of 32 or
    /// more give 0 (the value has no bits left), as wrapping arithmetic on i64 does.
    pub fn stencil(&self, v: i64) -> u8 {
        let s = self.index_shift;
        let shifted = if s >= 0 {
            if s >= 63 {
                0
            } else {
                v.wrapping_shl(s as u32)
            }
        } else if -s >= 63 {
            if v < 0 {
                -1
            } else {
                0
            }
        } else {
            v >> (-s) as u32
        };
        (shifted.wrapping_add(i64::from(self.index_offset)) & ((1 << STENCIL_BITS) - 1)) as u8
    }

    /// The index arithmetic of §3.6.4 on a colour index of a texture image, as Mesa does it
    /// on 32 bits: i << s (s > 0) or i >> −s (a count of 32 or more taken mod 32, as x86
    /// shifts), plus the offset, wrapping (`index_pixels`).
    pub fn colour_index(&self, i: u32) -> u32 {
        let s = self.index_shift;
        let i = if s >= 0 {
            i.wrapping_shl(s as u32)
        } else {
            i.wrapping_shr(s.unsigned_abs())
        };
        i.wrapping_add(self.index_offset as u32)
    }

    /// Whether a stencil value read goes through unchanged: no shift, no offset, no
    /// MAP_STENCIL.
    pub fn stencil_identity(&self) -> bool {
        self.index_shift == 0 && self.index_offset == 0 && !self.map_stencil
    }

    /// A stencil value as glReadPixels gives it (GL 1.5 §4.3.2): the index arithmetic
    /// ([`PixelTransfer::stencil`]), then S_TO_S under MAP_STENCIL, each result kept to
    /// 8 bits as Mesa's `_mesa_apply_stencil_transfer_ops` keeps it in a byte (a map
    /// entry beyond 255 keeps its low byte).
    pub fn stencil_read(&self, s: u8, maps: &PixelMaps) -> u8 {
        let v = self.stencil(i64::from(s));
        if self.map_stencil {
            maps.stencil(i64::from(v)) as i64 as u8
        } else {
            v
        }
    }
}

impl Default for PixelTransfer {
    fn default() -> Self {
        Self::DEFAULT
    }
}

impl super::state::FixedState {
    /// PIXEL_MODE_BIT's state as the commands that set it (`attrib::group_commands`).
    pub(crate) fn pixel_mode_commands(&self, out: &mut Vec<super::command::Command>) {
        use PixelTransferParam as P;
        let t = self.pixel_transfer;
        for i in 0..4u8 {
            out.push(super::command::Command::PixelTransfer(P::Scale(
                i,
                t.scale[usize::from(i)],
            )));
            out.push(super::command::Command::PixelTransfer(P::Bias(
                i,
                t.bias[usize::from(i)],
            )));
        }
        for p in [
            P::DepthScale(t.depth_scale),
            P::DepthBias(t.depth_bias),
            P::IndexShift(t.index_shift),
            P::IndexOffset(t.index_offset),
            P::MapColor(t.map_color),
            P::MapStencil(t.map_stencil),
        ] {
            out.push(super::command::Command::PixelTransfer(p));
        }
        out.push(super::command::Command::PixelZoom {
            x: self.pixel_zoom.x,
            y: self.pixel_zoom.y,
        });
    }
}

/// One glPixelTransfer parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PixelTransferParam {
    /// RED_SCALE (0) … ALPHA_SCALE (3).
    Scale(u8, f32),
    /// RED_BIAS (0) … ALPHA_BIAS (3).
    Bias(u8, f32),
    DepthScale(f32),
    DepthBias(f32),
    /// INDEX_SHIFT, rounded to an integer.
    IndexShift(i32),
    IndexOffset(i32),
    MapColor(bool),
    MapStencil(bool),
}

/// glPixelZoom (§3.6.4). GL default: (1, 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PixelZoom {
    pub x: f32,
    pub y: f32,
}

impl PixelZoom {
    pub const DEFAULT: Self = Self { x: 1.0, y: 1.0 };
}

/// glBitmap (§3.7). `bits` holds `height` rows of ⌈width/8⌉ bytes, bottom row first, the
/// most significant bit of each byte the leftmost pixel, as the front end unpacked them
/// (UNPACK_LSB_FIRST, the skips and the row length applied: `pixel_layout`); `None` for NULL (nothing is drawn, the position
/// still moves).
#[derive(Debug, Clone, PartialEq)]
pub struct Bitmap {
    pub width: i32,
    pub height: i32,
    pub origin: (f32, f32),
    pub advance: (f32, f32),
    pub bits: Option<Arc<[u8]>>,
}

impl Bitmap {
    /// Bytes of one row.
    pub fn row_bytes(width: i32) -> usize {
        (width.max(0) as usize).div_ceil(8)
    }

    /// Whether bit (x, y) is set (x from the left, y from the bottom row).
    pub fn bit(&self, x: usize, y: usize) -> bool {
        let row = Bitmap::row_bytes(self.width);
        self.bits
            .as_ref()
            .and_then(|b| b.get(y * row + x / 8))
            .is_some_and(|byte| byte & (0x80 >> (x % 8)) != 0)
    }

    /// The window x and y of the bitmap's lower-left pixel: (⌊x_r − x_o⌋, ⌊y_r − y_o⌋)
    /// (§3.7).
    pub fn corner(&self, raster: Vec4) -> (i32, i32) {
        (
            (raster.x - self.origin.0).floor() as i32,
            (raster.y - self.origin.1).floor() as i32,
        )
    }
}

/// glDrawPixels (§3.6.4): tightly packed rows, bottom row first, in the machine's byte
/// order (the front end applied the unpack parameters).
#[derive(Debug, Clone, PartialEq)]
pub struct DrawPixels {
    pub width: i32,
    pub height: i32,
    pub format: PixelFormat,
    pub ty: PixelType,
    pub data: Arc<[u8]>,
}

/// What glCopyPixels copies (§4.3.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CopyKind {
    Color,
    Depth,
    Stencil,
}

/// glCopyPixels from the read buffer at (x, y) to the raster position.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct CopyPixels {
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
    pub kind: CopyKind,
}

/// The values a pixel rectangle's fragments carry, bottom row first.
#[derive(Debug, Clone, PartialEq)]
pub enum Converted {
    /// Colour images: RGBA after transfer, clamped.
    Color(Vec<Vec4>),
    /// DEPTH_COMPONENT: window z after transfer, clamped.
    Depth(Vec<f32>),
    /// STENCIL_INDEX: after shift and offset, masked.
    Stencil(Vec<u8>),
}

/// Step 1: the components of `data` as numbers — unsigned c/(2ⁿ − 1) (Table 2.9: 255 → 1,
/// 65535 → 1, 2³² − 1 → 1, exact in f64 then rounded to f32), floats as they are; for
/// STENCIL_INDEX the integers themselves (a float truncated towards zero).
fn components(data: &[u8], ty: PixelType, normalize: bool) -> Vec<f64> {
    if let PixelType::Packed(p) = ty {
        return pixel_types::packed_components(data, p);
    }
    let size = ty.size();
    data.chunks_exact(size)
        .map(|b| {
            let (v, max) = match ty {
                PixelType::UnsignedByte => (f64::from(b[0]), 255.0),
                PixelType::UnsignedShort => (f64::from(u16::from_ne_bytes([b[0], b[1]])), 65535.0),
                PixelType::UnsignedInt => (
                    f64::from(u32::from_ne_bytes([b[0], b[1], b[2], b[3]])),
                    4294967295.0,
                ),
                PixelType::Float => {
                    let f = f64::from(f32::from_ne_bytes([b[0], b[1], b[2], b[3]]));
                    return if normalize { f } else { f.trunc() };
                }
                // Signed types: c / (2ⁿ⁻¹ − 1) (`pixel_types`' rule), a stencil index as it is.
                PixelType::Byte | PixelType::Short | PixelType::Int => {
                    return pixel_types::element(b, ty, !normalize);
                }
                PixelType::Packed(_) => (0.0, 1.0),
            };
            if normalize {
                v / max
            } else {
                v
            }
        })
        .collect()
}

impl DrawPixels {
    /// Checks the command against GL's rules: sizes (§3.6.4), and the data length.
    pub fn check(&self) -> GlResult {
        check_rect("DrawPixels", self.width, self.height)?;
        let n = self.width as usize * self.height as usize;
        if self.data.len() != n * self.ty.group_bytes(self.format) {
            return Err(GlError::invalid_value(
                "pixel data length differs from width·height·components·size",
            ));
        }
        Ok(())
    }

    /// The fragments' values (steps 1–4 of the module note; with MAP_COLOR each clamped
    /// component then goes through its map, §3.6.5).
    pub fn convert(&self, t: &PixelTransfer, maps: &PixelMaps) -> Converted {
        let stencil = self.format == PixelFormat::StencilIndex;
        let v = match self.format {
            // Indices are read by `index_pixels`.
            PixelFormat::ColorIndex => Vec::new(),
            _ => components(&self.data, self.ty, !stencil),
        };
        match self.format {
            // Mesa 22.3 draws stencil images without INDEX_SHIFT and INDEX_OFFSET (measured:
            // `tests/fidelity_pixels.rs`, mesa_ignores_index_shift_and_offset_for_stencil);
            // followed, masked to the stencil bits. GL 1.5 §3.6.4 would apply
            // `PixelTransfer::stencil`.
            PixelFormat::StencilIndex => Converted::Stencil(
                v.iter()
                    .map(|s| (*s as i64 & ((1 << STENCIL_BITS) - 1)) as u8)
                    .collect(),
            ),
            // UNSIGNED_BYTE depths as Mesa's UBYTE_TO_FLOAT makes them, b · (1/255) in
            // single precision (measured: 97 draws 0x616162 in 24 bits, where the correctly
            // rounded 97/255 draws 0x616161).
            PixelFormat::DepthComponent if self.ty == PixelType::UnsignedByte => Converted::Depth(
                self.data
                    .iter()
                    .map(|b| t.depth(f32::from(*b) * (1.0 / 255.0)))
                    .collect(),
            ),
            PixelFormat::DepthComponent => {
                Converted::Depth(v.iter().map(|d| t.depth(*d as f32)).collect())
            }
            // Indices through the I_TO maps, and no transfer at all (`index_pixels`).
            PixelFormat::ColorIndex => Converted::Color(super::index_pixels::drawn_colours(
                &self.data, self.ty, maps,
            )),
            f => {
                let k = f.components();
                Converted::Color(
                    v.chunks_exact(k)
                        .map(|c| {
                            let c: Vec<f32> = c.iter().map(|x| *x as f32).collect();
                            let c = t.color(to_rgba(f, &c));
                            if t.map_color {
                                maps.color(c)
                            } else {
                                c
                            }
                        })
                        .collect(),
                )
            }
        }
    }
}

/// The colour groups of a client image of a colour `format` as RGBA (steps 1 and 2 of the
/// module note: unsigned types normalised, Table 3.8's filling), before any transfer.
pub fn rgba_groups(data: &[u8], format: PixelFormat, ty: PixelType) -> Vec<Vec4> {
    let k = format.components();
    components(data, ty, true)
        .chunks_exact(k)
        .map(|c| {
            let c: Vec<f32> = c.iter().map(|x| *x as f32).collect();
            to_rgba(format, &c)
        })
        .collect()
}

impl PixelTransfer {
    /// Whether the colour transfer changes nothing: unit scales, zero biases, no
    /// MAP_COLOR.
    pub fn colour_identity(&self) -> bool {
        self.scale == Vec4::ONE && self.bias == Vec4::ZERO && !self.map_color
    }

    /// A colour through the transfer as glReadPixels and the texture images take it:
    /// c·scale + bias, then MAP_COLOR's maps by the nearest entry (`pixel_map`); not
    /// clamped (the caller clamps where its destination does).
    pub fn colour_nearest(&self, c: Vec4, maps: &PixelMaps) -> Vec4 {
        let c = c * self.scale + self.bias;
        if self.map_color {
            maps.color_nearest(c)
        } else {
            c
        }
    }
}

/// Step 2: a colour group as RGBA (Table 3.8).
fn to_rgba(format: PixelFormat, c: &[f32]) -> Vec4 {
    match format {
        PixelFormat::Rgba => Vec4::new(c[0], c[1], c[2], c[3]),
        PixelFormat::Rgb => Vec4::new(c[0], c[1], c[2], 1.0),
        PixelFormat::Bgra => Vec4::new(c[2], c[1], c[0], c[3]),
        PixelFormat::Abgr => Vec4::new(c[3], c[2], c[1], c[0]),
        PixelFormat::Bgr => Vec4::new(c[2], c[1], c[0], 1.0),
        PixelFormat::Luminance => Vec4::new(c[0], c[0], c[0], 1.0),
        PixelFormat::LuminanceAlpha => Vec4::new(c[0], c[0], c[0], c[1]),
        PixelFormat::Alpha => Vec4::new(0.0, 0.0, 0.0, c[0]),
        PixelFormat::Red => Vec4::new(c[0], 0.0, 0.0, 1.0),
        PixelFormat::Green => Vec4::new(0.0, c[0], 0.0, 1.0),
        PixelFormat::Blue => Vec4::new(0.0, 0.0, c[0], 1.0),
        // Not colour formats, or indices: the caller handles them.
        PixelFormat::DepthComponent | PixelFormat::StencilIndex | PixelFormat::ColorIndex => {
            Vec4::ZERO
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn draw(format: PixelFormat, ty: PixelType, data: Vec<u8>, w: i32) -> DrawPixels {
        DrawPixels {
            width: w,
            height: 1,
            format,
            ty,
            data: Arc::from(data),
        }
    }

    #[test]
    fn unsigned_types_map_their_maximum_to_one() {
        let t = PixelTransfer::DEFAULT;
        let ub = draw(
            PixelFormat::Luminance,
            PixelType::UnsignedByte,
            vec![0, 255],
            2,
        );
        assert_eq!(
            ub.convert(&t, &PixelMaps::default()),
            Converted::Color(vec![Vec4::W, Vec4::ONE])
        );
        let us = draw(
            PixelFormat::Alpha,
            PixelType::UnsignedShort,
            [65535u16.to_ne_bytes(), 32768u16.to_ne_bytes()].concat(),
            2,
        );
        let Converted::Color(c) = us.convert(&t, &PixelMaps::default()) else {
            panic!("colour")
        };
        assert_eq!(c[0], Vec4::new(0.0, 0.0, 0.0, 1.0));
        assert_eq!(c[1].w, (32768.0f64 / 65535.0) as f32);
        let ui = draw(
            PixelFormat::DepthComponent,
            PixelType::UnsignedInt,
            u32::MAX.to_ne_bytes().to_vec(),
            1,
        );
        assert_eq!(
            ui.convert(&t, &PixelMaps::default()),
            Converted::Depth(vec![1.0])
        );
    }

    #[test]
    fn scale_and_bias_apply_to_filled_components_and_clamp() {
        let mut t = PixelTransfer::DEFAULT;
        t.set(PixelTransferParam::Scale(3, 0.5));
        t.set(PixelTransferParam::Bias(2, 0.25));
        t.set(PixelTransferParam::Scale(0, 4.0));
        let rgb = draw(
            PixelFormat::Rgb,
            PixelType::Float,
            [0.5f32, 0.0, 0.0]
                .iter()
                .flat_map(|f| f.to_ne_bytes())
                .collect(),
            1,
        );
        // R = 0.5·4 → 1 (clamped), B = 0 + 0.25, A = 1 (filled) · 0.5.
        assert_eq!(
            rgb.convert(&t, &PixelMaps::default()),
            Converted::Color(vec![Vec4::new(1.0, 0.0, 0.25, 0.5)])
        );
    }

    #[test]
    fn stencil_shift_offset_and_mask() {
        let mut t = PixelTransfer::DEFAULT;
        assert_eq!(t.stencil(300), 44, "masked to 8 bits");
        t.set(PixelTransferParam::IndexShift(2));
        t.set(PixelTransferParam::IndexOffset(1));
        assert_eq!(t.stencil(3), 13);
        t.set(PixelTransferParam::IndexShift(-1));
        assert_eq!(t.stencil(7), 4);
        t.set(PixelTransferParam::IndexShift(64));
        assert_eq!(t.stencil(7), 1);
    }

    #[test]
    fn the_budget_is_refused_before_reading() {
        assert!(check_rect("DrawPixels", 4096, 4096).is_ok());
        assert!(check_rect("DrawPixels", 4097, 4096).is_err());
        assert!(check_rect("DrawPixels", 1 << 16, 1 << 15).is_err());
        assert!(check_rect("Bitmap", -1, 1).is_err());
    }

    #[test]
    fn bitmap_bits_read_msb_first() {
        let b = Bitmap {
            width: 10,
            height: 2,
            origin: (0.0, 0.0),
            advance: (0.0, 0.0),
            bits: Some(Arc::from(vec![0x80, 0x40, 0x01, 0x00])),
        };
        assert!(b.bit(0, 0));
        assert!(!b.bit(1, 0));
        assert!(b.bit(9, 0));
        assert!(b.bit(7, 1));
        assert!(!b.bit(8, 1));
        assert_eq!(b.corner(Vec4::new(2.5, 3.0, 0.0, 1.0)), (2, 3));
    }
}
