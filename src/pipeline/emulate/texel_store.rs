//! Client images and framebuffer copies as a texture's storage holds them, when the core
//! upload of the bytes as they are would hold something else.
//!
//! GL 1.5 §3.8.1: a texture image's groups become RGBA (Table 3.8: L → (L, L, L, 1),
//! A → (0, 0, 0, A), RGB → (R, G, B, 1)…), go through the pixel transfer (scale and bias,
//! then MAP_COLOR's maps — by the nearest entry, as Mesa's texture store takes them,
//! `ff::pixel_map`), are clamped to [0, 1], and the internal base format keeps its
//! components (Table 3.15: L and I from R, A from A). The core storage of the legacy
//! formats is R8/RG8 (`conv::tex_format`), so a core upload of ALPHA data into RGBA8, of
//! RGBA into ALPHA8 or LUMINANCE_ALPHA8, or of LUMINANCE into LUMINANCE_ALPHA8 would put
//! the wrong components in the channels; those, and every colour image under a transfer
//! that is not the identity, are converted here: each component kept is stored as
//! roundEven(255·c) (Mesa's `_mesa_float_to_unorm`). Depth images go as they are: Mesa
//! 22.3 applies neither DEPTH_SCALE nor DEPTH_BIAS to them (measured, tests/c/transfer.c).
//! COLOR_INDEX images always go through here: their colours are the I_TO maps' entries
//! (`ff::index_pixels`), kept as the base format keeps RGBA.

use glam::Vec4;

use crate::ff::index_pixels;
use crate::ff::pixel_map::PixelMaps;
use crate::ff::pixels::rgba_groups;
use crate::ff::texture::{BaseFormat, PixelFormat, PixelType, TexFormat};
use crate::ff::PixelTransfer;

/// The client format, type and bytes per texel of a format's storage.
pub fn storage(f: TexFormat) -> (u32, u32, usize) {
    match f.base() {
        BaseFormat::Rgba => (glow::RGBA, glow::UNSIGNED_BYTE, 4),
        BaseFormat::Rgb => (glow::RGB, glow::UNSIGNED_BYTE, 3),
        BaseFormat::LuminanceAlpha => (glow::RG, glow::UNSIGNED_BYTE, 2),
        BaseFormat::Luminance | BaseFormat::Intensity | BaseFormat::Alpha => {
            (glow::RED, glow::UNSIGNED_BYTE, 1)
        }
        BaseFormat::Depth => (glow::DEPTH_COMPONENT, glow::FLOAT, 4),
    }
}

/// The RGBA components (0 R, 1 G, 2 B, 3 A) a base format keeps, in its storage's order.
pub fn kept(base: BaseFormat) -> &'static [usize] {
    match base {
        BaseFormat::Rgba => &[0, 1, 2, 3],
        BaseFormat::Rgb => &[0, 1, 2],
        BaseFormat::LuminanceAlpha => &[0, 3],
        BaseFormat::Luminance | BaseFormat::Intensity => &[0],
        BaseFormat::Alpha | BaseFormat::Depth => &[3],
    }
}

/// Whether the core upload of `format` data into `internal`'s storage keeps what GL
/// keeps (the channels the storage reads from the client's are the right ones).
fn core_upload_keeps(format: PixelFormat, internal: TexFormat) -> bool {
    use PixelFormat as P;
    match internal.base() {
        BaseFormat::Rgba | BaseFormat::Rgb => matches!(format, P::Rgba | P::Rgb),
        // R8 takes the first channel: R of RGB(A), L of LUMINANCE(_ALPHA).
        BaseFormat::Luminance | BaseFormat::Intensity => {
            matches!(format, P::Rgba | P::Rgb | P::Luminance | P::LuminanceAlpha)
        }
        BaseFormat::Alpha => format == P::Alpha,
        BaseFormat::LuminanceAlpha => format == P::LuminanceAlpha,
        BaseFormat::Depth => true,
    }
}

/// The bytes of a client image as `internal`'s storage holds them (one unsigned byte per
/// kept component), or `None` when the bytes can be uploaded as they are.
pub fn stored_image(
    data: &[u8],
    format: PixelFormat,
    ty: PixelType,
    internal: TexFormat,
    transfer: &PixelTransfer,
    maps: &PixelMaps,
) -> Option<Vec<u8>> {
    let colour = !matches!(
        format,
        PixelFormat::DepthComponent | PixelFormat::StencilIndex
    );
    if !colour
        || internal.is_depth()
        || (transfer.colour_identity() && core_upload_keeps(format, internal))
    {
        return None;
    }
    if format == PixelFormat::ColorIndex {
        // Indices shifted, offset and looked up; no colour transfer after (`index_pixels`).
        let colours = index_pixels::stored_colours(data, ty, transfer, maps);
        return Some(store(&colours, internal, &PixelTransfer::DEFAULT, maps));
    }
    let groups = rgba_groups(data, format, ty);
    Some(store(&groups, internal, transfer, maps))
}

/// RGBA colours (a framebuffer read as floats, or decoded client groups) through the
/// transfer, clamped, and kept as `internal`'s storage holds them.
pub fn store(
    colours: &[Vec4],
    internal: TexFormat,
    transfer: &PixelTransfer,
    maps: &PixelMaps,
) -> Vec<u8> {
    let keep = kept(internal.base());
    let mut out = Vec::with_capacity(colours.len() * keep.len());
    for c in colours {
        let c = transfer
            .colour_nearest(*c, maps)
            .clamp(Vec4::ZERO, Vec4::ONE);
        let c = c.to_array();
        out.extend(keep.iter().map(|&k| (c[k] * 255.0).round_ties_even() as u8));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mismatched_formats_are_stored_as_gl_keeps_them() {
        let t = PixelTransfer::DEFAULT;
        let maps = PixelMaps::default();
        let ub = PixelType::UnsignedByte;
        // ALPHA data into RGBA: (0, 0, 0, A).
        let s = stored_image(&[100], PixelFormat::Alpha, ub, TexFormat::Rgba8, &t, &maps);
        assert_eq!(s, Some(vec![0, 0, 0, 100]));
        // LUMINANCE_ALPHA into ALPHA keeps A; RGB into LUMINANCE_ALPHA keeps (R, 1).
        let la = [100, 200];
        let s = stored_image(
            &la,
            PixelFormat::LuminanceAlpha,
            ub,
            TexFormat::Alpha8,
            &t,
            &maps,
        );
        assert_eq!(s, Some(vec![200]));
        let s = stored_image(
            &[10, 20, 30],
            PixelFormat::Rgb,
            ub,
            TexFormat::Luminance8Alpha8,
            &t,
            &maps,
        );
        assert_eq!(s, Some(vec![10, 255]));
        // Matching formats go as they are.
        let s = stored_image(
            &la,
            PixelFormat::LuminanceAlpha,
            ub,
            TexFormat::Luminance8,
            &t,
            &maps,
        );
        assert_eq!(s, None);
    }

    #[test]
    fn the_transfer_scales_biases_and_clamps_before_the_store() {
        let mut t = PixelTransfer::DEFAULT;
        t.scale.x = 0.5;
        t.bias.y = 0.1;
        let maps = PixelMaps::default();
        let s = stored_image(
            &[200, 200, 200, 255],
            PixelFormat::Rgba,
            PixelType::UnsignedByte,
            TexFormat::Rgba8,
            &t,
            &maps,
        );
        // 200·0.5 = 100; 200/255 + 0.1 → 225.5 → 226 (round half to even keeps 226).
        assert_eq!(s, Some(vec![100, 226, 200, 255]));
    }
}
