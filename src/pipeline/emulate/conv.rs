//! The emulated path's GL values: the model's enums through `ff::glenum`'s one table, except
//! where a core 3.3 context lacks the legacy value and the path substitutes its own —
//! CLAMP, the legacy texture formats (R8/RG8 storage plus the swizzle that makes the
//! sampled texel GL 1.x's) and the legacy client pixel formats. Those substitutions, and
//! only those, are written out here, with exhaustive matches.

use crate::ff::{PixelFormat, TexFormat, Wrap};

pub use crate::ff::glenum::gl as value;

/// CLAMP (GL 1.x: clamp s to [0, 1], so LINEAR mixes in the border colour and NEAREST takes
/// the edge texel) has no core equivalent: it is sampled with CLAMP_TO_BORDER from
/// coordinates the program has clamped (`key::ClampKey`), which gives both.
pub fn wrap(w: Wrap) -> u32 {
    match w {
        Wrap::Repeat => glow::REPEAT,
        Wrap::Clamp => glow::CLAMP_TO_BORDER,
        Wrap::ClampToEdge => glow::CLAMP_TO_EDGE,
        Wrap::ClampToBorder => glow::CLAMP_TO_BORDER,
        Wrap::MirroredRepeat => glow::MIRRORED_REPEAT,
    }
}

/// The core internal format a level is stored in: the one of the bits Mesa stores the
/// requested format at (`ff::texture_storage`), else the base's 8-bit core format.
pub fn stored_format(f: TexFormat, requested: Option<u32>) -> u32 {
    requested
        .and_then(crate::ff::texture_storage::core_format)
        .unwrap_or_else(|| tex_format(f).0)
}

/// Core storage and the swizzle (R, G, B, A sources) giving GL 1.x's texel per base format:
/// LUMINANCE (L,L,L,1), INTENSITY (I,I,I,I), ALPHA (0,0,0,A), LUMINANCE_ALPHA (L,L,L,A).
pub fn tex_format(f: TexFormat) -> (u32, [u32; 4]) {
    const RGBA: [u32; 4] = [glow::RED, glow::GREEN, glow::BLUE, glow::ALPHA];
    match f {
        TexFormat::Rgba8 => (glow::RGBA8, RGBA),
        TexFormat::Rgb8 => (glow::RGB8, [glow::RED, glow::GREEN, glow::BLUE, glow::ONE]),
        TexFormat::Luminance8 => (glow::R8, [glow::RED, glow::RED, glow::RED, glow::ONE]),
        TexFormat::Intensity8 => (glow::R8, [glow::RED; 4]),
        TexFormat::Alpha8 => (glow::R8, [glow::ZERO, glow::ZERO, glow::ZERO, glow::RED]),
        TexFormat::Luminance8Alpha8 => (glow::RG8, [glow::RED, glow::RED, glow::RED, glow::GREEN]),
        TexFormat::DepthComponent16 => (glow::DEPTH_COMPONENT16, RGBA),
        TexFormat::DepthComponent24 => (glow::DEPTH_COMPONENT24, RGBA),
        TexFormat::DepthComponent32F => (glow::DEPTH_COMPONENT32F, RGBA),
        TexFormat::Rgba32F => (glow::RGBA32F, RGBA),
    }
}

/// Client pixel formats as core ones: the one-channel legacy formats upload as RED (and
/// LUMINANCE_ALPHA as RG), which is what the R8/RG8 storage above expects.
pub fn pixel_format(f: PixelFormat) -> u32 {
    match f {
        PixelFormat::Rgba => glow::RGBA,
        PixelFormat::Rgb => glow::RGB,
        PixelFormat::Bgra => glow::BGRA,
        PixelFormat::Bgr => glow::BGR,
        PixelFormat::Luminance | PixelFormat::Alpha => glow::RED,
        PixelFormat::LuminanceAlpha => glow::RG,
        PixelFormat::DepthComponent => glow::DEPTH_COMPONENT,
        PixelFormat::StencilIndex => glow::STENCIL_INDEX,
        PixelFormat::Red => glow::RED,
        PixelFormat::Green => glow::GREEN,
        PixelFormat::Blue => glow::BLUE,
        // Never uploaded as it is: a COLOR_INDEX image is stored through `texel_store`.
        PixelFormat::ColorIndex => glow::RED,
        // Never uploaded or read as it is: ABGR data is taken apart into RGBA where it
        // enters the layer and put together from RGBA reads (`pixel_types`).
        PixelFormat::Abgr => glow::RGBA,
    }
}
