//! The native path's only table from `ff` enums to GL constants. Every match is exhaustive
//! with no wildcard, so a new `ff` variant fails to compile here until it is given its GL
//! name. Constants newer than the GL 2.1 bindings (DEPTH_COMPONENT32F, GL 3.0 /
//! ARB_depth_buffer_float) are spelled out with their registry value.

use crate::ff::{
    BlendFactor, Capability, ColorControl, ColorMaterialMode, CombineFunc, CombineOperand,
    CombineSource, CompareFunc, CompareMode, DepthTextureMode, Face, Filter, FrontFace, MatrixMode,
    PixelFormat, PixelType, PolygonMode, Primitive, ShadeModel, StencilOp, TexCoord, TexEnvMode,
    TexFormat, TexGenMode, TextureTarget, Wrap,
};

use super::bindings as gl;
use super::bindings::types::GLenum;

/// GL_DEPTH_COMPONENT32F (GL 3.0, ARB_depth_buffer_float): not in the GL 2.1 registry.
pub const DEPTH_COMPONENT32F: GLenum = 0x8CAC;

/// A `GLint` view of an enum, for the `…i` entry points (every GL enum fits in 31 bits).
pub fn int(e: GLenum) -> i32 {
    e as i32
}

pub fn texture_unit(unit: u8) -> GLenum {
    gl::TEXTURE0 + GLenum::from(unit)
}

pub fn matrix_mode(m: MatrixMode) -> GLenum {
    match m {
        MatrixMode::Modelview => gl::MODELVIEW,
        MatrixMode::Projection => gl::PROJECTION,
        MatrixMode::Texture => gl::TEXTURE,
    }
}

/// The glEnable name of a capability; `None` for REGISTER_COMBINERS_NV, which Mesa lacks
/// (the model records it; a draw with it enabled is refused).
pub fn capability(c: Capability) -> Option<GLenum> {
    Some(match c {
        Capability::Lighting => gl::LIGHTING,
        Capability::Light(i) => gl::LIGHT0 + GLenum::from(i),
        Capability::ColorMaterial => gl::COLOR_MATERIAL,
        Capability::Normalize => gl::NORMALIZE,
        Capability::RescaleNormal => gl::RESCALE_NORMAL,
        Capability::Texture1D => gl::TEXTURE_1D,
        Capability::Texture2D => gl::TEXTURE_2D,
        Capability::TextureGen(TexCoord::S) => gl::TEXTURE_GEN_S,
        Capability::TextureGen(TexCoord::T) => gl::TEXTURE_GEN_T,
        Capability::TextureGen(TexCoord::R) => gl::TEXTURE_GEN_R,
        Capability::TextureGen(TexCoord::Q) => gl::TEXTURE_GEN_Q,
        Capability::AlphaTest => gl::ALPHA_TEST,
        Capability::DepthTest => gl::DEPTH_TEST,
        Capability::StencilTest => gl::STENCIL_TEST,
        Capability::Blend => gl::BLEND,
        Capability::CullFace => gl::CULL_FACE,
        Capability::PolygonOffsetFill => gl::POLYGON_OFFSET_FILL,
        Capability::PolygonOffsetLine => gl::POLYGON_OFFSET_LINE,
        Capability::PolygonOffsetPoint => gl::POLYGON_OFFSET_POINT,
        Capability::RegisterCombiners => return None,
    })
}

pub fn face(f: Face) -> GLenum {
    match f {
        Face::Front => gl::FRONT,
        Face::Back => gl::BACK,
        Face::FrontAndBack => gl::FRONT_AND_BACK,
    }
}

pub fn front_face(f: FrontFace) -> GLenum {
    match f {
        FrontFace::Cw => gl::CW,
        FrontFace::Ccw => gl::CCW,
    }
}

pub fn polygon_mode(m: PolygonMode) -> GLenum {
    match m {
        PolygonMode::Point => gl::POINT,
        PolygonMode::Line => gl::LINE,
        PolygonMode::Fill => gl::FILL,
    }
}

pub fn shade_model(m: ShadeModel) -> GLenum {
    match m {
        ShadeModel::Flat => gl::FLAT,
        ShadeModel::Smooth => gl::SMOOTH,
    }
}

pub fn compare_func(f: CompareFunc) -> GLenum {
    match f {
        CompareFunc::Never => gl::NEVER,
        CompareFunc::Less => gl::LESS,
        CompareFunc::Equal => gl::EQUAL,
        CompareFunc::Lequal => gl::LEQUAL,
        CompareFunc::Greater => gl::GREATER,
        CompareFunc::Notequal => gl::NOTEQUAL,
        CompareFunc::Gequal => gl::GEQUAL,
        CompareFunc::Always => gl::ALWAYS,
    }
}

pub fn stencil_op(op: StencilOp) -> GLenum {
    match op {
        StencilOp::Keep => gl::KEEP,
        StencilOp::Zero => gl::ZERO,
        StencilOp::Replace => gl::REPLACE,
        StencilOp::Incr => gl::INCR,
        StencilOp::Decr => gl::DECR,
        StencilOp::Invert => gl::INVERT,
        StencilOp::IncrWrap => gl::INCR_WRAP,
        StencilOp::DecrWrap => gl::DECR_WRAP,
    }
}

pub fn blend_factor(f: BlendFactor) -> GLenum {
    match f {
        BlendFactor::Zero => gl::ZERO,
        BlendFactor::One => gl::ONE,
        BlendFactor::SrcColor => gl::SRC_COLOR,
        BlendFactor::OneMinusSrcColor => gl::ONE_MINUS_SRC_COLOR,
        BlendFactor::DstColor => gl::DST_COLOR,
        BlendFactor::OneMinusDstColor => gl::ONE_MINUS_DST_COLOR,
        BlendFactor::SrcAlpha => gl::SRC_ALPHA,
        BlendFactor::OneMinusSrcAlpha => gl::ONE_MINUS_SRC_ALPHA,
        BlendFactor::DstAlpha => gl::DST_ALPHA,
        BlendFactor::OneMinusDstAlpha => gl::ONE_MINUS_DST_ALPHA,
        BlendFactor::SrcAlphaSaturate => gl::SRC_ALPHA_SATURATE,
    }
}

pub fn primitive(p: Primitive) -> GLenum {
    match p {
        Primitive::Points => gl::POINTS,
        Primitive::Lines => gl::LINES,
        Primitive::LineStrip => gl::LINE_STRIP,
        Primitive::LineLoop => gl::LINE_LOOP,
        Primitive::Triangles => gl::TRIANGLES,
        Primitive::TriangleStrip => gl::TRIANGLE_STRIP,
        Primitive::TriangleFan => gl::TRIANGLE_FAN,
        Primitive::Quads => gl::QUADS,
        Primitive::QuadStrip => gl::QUAD_STRIP,
        Primitive::Polygon => gl::POLYGON,
    }
}

pub fn color_control(c: ColorControl) -> GLenum {
    match c {
        ColorControl::SingleColor => gl::SINGLE_COLOR,
        ColorControl::SeparateSpecularColor => gl::SEPARATE_SPECULAR_COLOR,
    }
}

pub fn color_material_mode(m: ColorMaterialMode) -> GLenum {
    match m {
        ColorMaterialMode::Ambient => gl::AMBIENT,
        ColorMaterialMode::Diffuse => gl::DIFFUSE,
        ColorMaterialMode::Specular => gl::SPECULAR,
        ColorMaterialMode::Emission => gl::EMISSION,
        ColorMaterialMode::AmbientAndDiffuse => gl::AMBIENT_AND_DIFFUSE,
    }
}

pub fn tex_coord(c: TexCoord) -> GLenum {
    match c {
        TexCoord::S => gl::S,
        TexCoord::T => gl::T,
        TexCoord::R => gl::R,
        TexCoord::Q => gl::Q,
    }
}

pub fn texgen_mode(m: TexGenMode) -> GLenum {
    match m {
        TexGenMode::ObjectLinear => gl::OBJECT_LINEAR,
        TexGenMode::EyeLinear => gl::EYE_LINEAR,
        TexGenMode::SphereMap => gl::SPHERE_MAP,
    }
}

pub fn texenv_mode(m: TexEnvMode) -> GLenum {
    match m {
        TexEnvMode::Modulate => gl::MODULATE,
        TexEnvMode::Replace => gl::REPLACE,
        TexEnvMode::Decal => gl::DECAL,
        TexEnvMode::Blend => gl::BLEND,
        TexEnvMode::Add => gl::ADD,
        TexEnvMode::Combine => gl::COMBINE,
    }
}

pub fn combine_func(f: CombineFunc) -> GLenum {
    match f {
        CombineFunc::Replace => gl::REPLACE,
        CombineFunc::Modulate => gl::MODULATE,
        CombineFunc::Add => gl::ADD,
        CombineFunc::AddSigned => gl::ADD_SIGNED,
        CombineFunc::Interpolate => gl::INTERPOLATE,
        CombineFunc::Subtract => gl::SUBTRACT,
        CombineFunc::Dot3Rgb => gl::DOT3_RGB,
        CombineFunc::Dot3Rgba => gl::DOT3_RGBA,
    }
}

/// A combine source; TEXTUREn is the crossbar (ARB_texture_env_crossbar, GL 1.4).
pub fn combine_source(s: CombineSource) -> GLenum {
    match s {
        CombineSource::Texture => gl::TEXTURE,
        CombineSource::TextureUnit(n) => texture_unit(n),
        CombineSource::Constant => gl::CONSTANT,
        CombineSource::PrimaryColor => gl::PRIMARY_COLOR,
        CombineSource::Previous => gl::PREVIOUS,
    }
}

pub fn combine_operand(o: CombineOperand) -> GLenum {
    match o {
        CombineOperand::SrcColor => gl::SRC_COLOR,
        CombineOperand::OneMinusSrcColor => gl::ONE_MINUS_SRC_COLOR,
        CombineOperand::SrcAlpha => gl::SRC_ALPHA,
        CombineOperand::OneMinusSrcAlpha => gl::ONE_MINUS_SRC_ALPHA,
    }
}

/// SRCn_RGB for argument index 0..2.
pub fn source_rgb(arg: usize) -> GLenum {
    gl::SRC0_RGB + arg as GLenum
}

/// SRCn_ALPHA for argument index 0..2.
pub fn source_alpha(arg: usize) -> GLenum {
    gl::SRC0_ALPHA + arg as GLenum
}

/// OPERANDn_RGB for argument index 0..2.
pub fn operand_rgb(arg: usize) -> GLenum {
    gl::OPERAND0_RGB + arg as GLenum
}

/// OPERANDn_ALPHA for argument index 0..2.
pub fn operand_alpha(arg: usize) -> GLenum {
    gl::OPERAND0_ALPHA + arg as GLenum
}

pub fn texture_target(t: TextureTarget) -> GLenum {
    match t {
        TextureTarget::Texture1D => gl::TEXTURE_1D,
        TextureTarget::Texture2D => gl::TEXTURE_2D,
    }
}

/// Sized internal formats; the legacy ones (INTENSITY8, LUMINANCE8, ALPHA8,
/// LUMINANCE8_ALPHA8) exist natively on a compatibility context.
pub fn tex_format(f: TexFormat) -> GLenum {
    match f {
        TexFormat::Rgba8 => gl::RGBA8,
        TexFormat::Rgb8 => gl::RGB8,
        TexFormat::Luminance8 => gl::LUMINANCE8,
        TexFormat::Intensity8 => gl::INTENSITY8,
        TexFormat::Alpha8 => gl::ALPHA8,
        TexFormat::Luminance8Alpha8 => gl::LUMINANCE8_ALPHA8,
        TexFormat::DepthComponent16 => gl::DEPTH_COMPONENT16,
        TexFormat::DepthComponent24 => gl::DEPTH_COMPONENT24,
        TexFormat::DepthComponent32F => DEPTH_COMPONENT32F,
    }
}

pub fn pixel_format(f: PixelFormat) -> GLenum {
    match f {
        PixelFormat::Rgba => gl::RGBA,
        PixelFormat::Rgb => gl::RGB,
        PixelFormat::Luminance => gl::LUMINANCE,
        PixelFormat::LuminanceAlpha => gl::LUMINANCE_ALPHA,
        PixelFormat::Alpha => gl::ALPHA,
        PixelFormat::DepthComponent => gl::DEPTH_COMPONENT,
        PixelFormat::StencilIndex => gl::STENCIL_INDEX,
    }
}

pub fn pixel_type(t: PixelType) -> GLenum {
    match t {
        PixelType::UnsignedByte => gl::UNSIGNED_BYTE,
        PixelType::UnsignedShort => gl::UNSIGNED_SHORT,
        PixelType::UnsignedInt => gl::UNSIGNED_INT,
        PixelType::Float => gl::FLOAT,
    }
}

pub fn filter(f: Filter) -> GLenum {
    match f {
        Filter::Nearest => gl::NEAREST,
        Filter::Linear => gl::LINEAR,
        Filter::NearestMipmapNearest => gl::NEAREST_MIPMAP_NEAREST,
        Filter::LinearMipmapNearest => gl::LINEAR_MIPMAP_NEAREST,
        Filter::NearestMipmapLinear => gl::NEAREST_MIPMAP_LINEAR,
        Filter::LinearMipmapLinear => gl::LINEAR_MIPMAP_LINEAR,
    }
}

pub fn wrap(w: Wrap) -> GLenum {
    match w {
        Wrap::Repeat => gl::REPEAT,
        Wrap::Clamp => gl::CLAMP,
        Wrap::ClampToEdge => gl::CLAMP_TO_EDGE,
        Wrap::ClampToBorder => gl::CLAMP_TO_BORDER,
    }
}

pub fn compare_mode(m: CompareMode) -> GLenum {
    match m {
        CompareMode::None => gl::NONE,
        CompareMode::CompareRToTexture => gl::COMPARE_R_TO_TEXTURE,
    }
}

pub fn depth_texture_mode(m: DepthTextureMode) -> GLenum {
    match m {
        DepthTextureMode::Luminance => gl::LUMINANCE,
        DepthTextureMode::Intensity => gl::INTENSITY,
        DepthTextureMode::Alpha => gl::ALPHA,
    }
}
