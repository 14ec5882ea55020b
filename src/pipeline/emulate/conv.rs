//! The emulated path's ff enums → core-profile GL constants, exhaustive matches. Legacy
//! formats map to the R8/RG8 storage plus the swizzle that makes the sampled texel GL 1.x's.

use crate::ff::{
    BlendFactor, CompareFunc, Face, Filter, FrontFace, PixelFormat, PixelType, PolygonMode,
    StencilOp, TexFormat, Wrap,
};

pub fn compare_func(f: CompareFunc) -> u32 {
    match f {
        CompareFunc::Never => glow::NEVER,
        CompareFunc::Less => glow::LESS,
        CompareFunc::Equal => glow::EQUAL,
        CompareFunc::Lequal => glow::LEQUAL,
        CompareFunc::Greater => glow::GREATER,
        CompareFunc::Notequal => glow::NOTEQUAL,
        CompareFunc::Gequal => glow::GEQUAL,
        CompareFunc::Always => glow::ALWAYS,
    }
}

pub fn stencil_op(op: StencilOp) -> u32 {
    match op {
        StencilOp::Keep => glow::KEEP,
        StencilOp::Zero => glow::ZERO,
        StencilOp::Replace => glow::REPLACE,
        StencilOp::Incr => glow::INCR,
        StencilOp::Decr => glow::DECR,
        StencilOp::Invert => glow::INVERT,
        StencilOp::IncrWrap => glow::INCR_WRAP,
        StencilOp::DecrWrap => glow::DECR_WRAP,
    }
}

pub fn blend_factor(f: BlendFactor) -> u32 {
    match f {
        BlendFactor::Zero => glow::ZERO,
        BlendFactor::One => glow::ONE,
        BlendFactor::SrcColor => glow::SRC_COLOR,
        BlendFactor::OneMinusSrcColor => glow::ONE_MINUS_SRC_COLOR,
        BlendFactor::DstColor => glow::DST_COLOR,
        BlendFactor::OneMinusDstColor => glow::ONE_MINUS_DST_COLOR,
        BlendFactor::SrcAlpha => glow::SRC_ALPHA,
        BlendFactor::OneMinusSrcAlpha => glow::ONE_MINUS_SRC_ALPHA,
        BlendFactor::DstAlpha => glow::DST_ALPHA,
        BlendFactor::OneMinusDstAlpha => glow::ONE_MINUS_DST_ALPHA,
        BlendFactor::SrcAlphaSaturate => glow::SRC_ALPHA_SATURATE,
    }
}

pub fn face(f: Face) -> u32 {
    match f {
        Face::Front => glow::FRONT,
        Face::Back => glow::BACK,
        Face::FrontAndBack => glow::FRONT_AND_BACK,
    }
}

pub fn front_face(f: FrontFace) -> u32 {
    match f {
        FrontFace::Ccw => glow::CCW,
        FrontFace::Cw => glow::CW,
    }
}

pub fn polygon_mode(m: PolygonMode) -> u32 {
    match m {
        PolygonMode::Point => glow::POINT,
        PolygonMode::Line => glow::LINE,
        PolygonMode::Fill => glow::FILL,
    }
}

pub fn filter(f: Filter) -> u32 {
    match f {
        Filter::Nearest => glow::NEAREST,
        Filter::Linear => glow::LINEAR,
        Filter::NearestMipmapNearest => glow::NEAREST_MIPMAP_NEAREST,
        Filter::LinearMipmapNearest => glow::LINEAR_MIPMAP_NEAREST,
        Filter::NearestMipmapLinear => glow::NEAREST_MIPMAP_LINEAR,
        Filter::LinearMipmapLinear => glow::LINEAR_MIPMAP_LINEAR,
    }
}

/// CLAMP (GL 1.x: clamp s to [0,1], so LINEAR mixes in the border colour) has no core
/// equivalent; CLAMP_TO_BORDER reproduces it exactly for LINEAR and is CLAMP_TO_EDGE-like
/// for NEAREST, which is what CLAMP does there too.
pub fn wrap(w: Wrap) -> u32 {
    match w {
        Wrap::Repeat => glow::REPEAT,
        Wrap::Clamp => glow::CLAMP_TO_BORDER,
        Wrap::ClampToEdge => glow::CLAMP_TO_EDGE,
        Wrap::ClampToBorder => glow::CLAMP_TO_BORDER,
    }
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
    }
}

/// Client pixel formats as core ones: the one-channel legacy formats upload as RED (and
/// LUMINANCE_ALPHA as RG), which is what the R8/RG8 storage above expects.
pub fn pixel_format(f: PixelFormat) -> u32 {
    match f {
        PixelFormat::Rgba => glow::RGBA,
        PixelFormat::Rgb => glow::RGB,
        PixelFormat::Luminance | PixelFormat::Alpha => glow::RED,
        PixelFormat::LuminanceAlpha => glow::RG,
        PixelFormat::DepthComponent => glow::DEPTH_COMPONENT,
        PixelFormat::StencilIndex => glow::STENCIL_INDEX,
    }
}

pub fn pixel_type(t: PixelType) -> u32 {
    match t {
        PixelType::UnsignedByte => glow::UNSIGNED_BYTE,
        PixelType::UnsignedShort => glow::UNSIGNED_SHORT,
        PixelType::UnsignedInt => glow::UNSIGNED_INT,
        PixelType::Float => glow::FLOAT,
    }
}
