//! The model's enums as GL enumerants: one table per enum giving each value its token
//! name and its GLenum value. The values come from the Khronos registry (`build.rs` writes
//! every enumerant as a constant; an entry names the constant, and its string is made from
//! the same identifier), so neither a name nor a number is typed twice. The script reader
//! and printer use the names; both pipelines use the values (the emulated path's core
//! substitutions — legacy formats as R8/RG8 storage, CLAMP as CLAMP_TO_BORDER — are the
//! documented exceptions in `pipeline::emulate::conv`).
//!
//! A value may appear again under an alias (accepted when parsing, never printed or sent:
//! the first entry is the canonical one). Indexed families (GL_LIGHTi, GL_TEXTUREi,
//! GL_COMBINERi_NV, GL_CLIP_PLANEi) are not tables: `LIGHT0 + i`.

use super::compressed::CompressedFormat;
use super::framebuffer::{AttachmentPoint, ColorBuffer, FramebufferTarget, RenderbufferFormat};
use super::pixel_map::PixelMapName;
use super::pixel_types::PackedType;
use super::texture::CubeFace;
use super::*;

/// Every enumerant of the registry, as `pub const NAME: u32`.
#[allow(dead_code, non_upper_case_globals, clippy::unreadable_literal)]
pub mod registry {
    include!(concat!(env!("OUT_DIR"), "/gl_enums.rs"));
}

/// An enum of the model with GL token names and values.
pub trait GlEnum: Copy + PartialEq + 'static {
    /// (token name, value, model value); the first entry of a model value is canonical.
    const TABLE: &'static [(&'static str, u32, Self)];

    /// The printed name, if the value has one.
    fn gl_name(self) -> Option<&'static str> {
        Self::TABLE
            .iter()
            .find(|(_, _, v)| *v == self)
            .map(|(n, _, _)| *n)
    }

    /// The GLenum value (of the canonical entry).
    fn gl_value(self) -> Option<u32> {
        Self::TABLE
            .iter()
            .find(|(_, _, v)| *v == self)
            .map(|(_, e, _)| *e)
    }

    fn from_gl_name(name: &str) -> Option<Self> {
        Self::TABLE
            .iter()
            .find(|(n, _, _)| *n == name)
            .map(|(_, _, v)| *v)
    }

    fn from_gl_value(value: u32) -> Option<Self> {
        Self::TABLE
            .iter()
            .find(|(_, e, _)| *e == value)
            .map(|(_, _, v)| *v)
    }

    fn names() -> Vec<&'static str> {
        Self::TABLE.iter().map(|(n, _, _)| *n).collect()
    }
}

/// The GLenum of a model value that every table lists (a test checks each table covers its
/// enum; a value without an entry is a bug, reported as 0 = GL_NONE / GL_ZERO / GL_FALSE).
pub fn gl<T: GlEnum>(v: T) -> u32 {
    v.gl_value().unwrap_or(0)
}

/// The command the registry names `name` an alias of (glBlendEquationEXT →
/// glBlendEquation: the same call under an extension's name).
pub fn registry_alias(name: &str) -> Option<&'static str> {
    if let Ok(at) = registry::COMMAND_ALIASES.binary_search_by(|(alias, _)| (*alias).cmp(name)) {
        return Some(registry::COMMAND_ALIASES[at].1);
    }
    TEXTURE_OBJECT_EXT
        .iter()
        .find(|(alias, _)| *alias == name)
        .map(|(_, command)| *command)
}

/// EXT_texture_object's names the registry does not make aliases (their GLX protocol
/// differs from GL 1.1's), though they are the same calls in GL: Mesa's
/// OSMesaGetProcAddress answers them with GL 1.1's functions.
const TEXTURE_OBJECT_EXT: [(&str, &str); 4] = [
    ("glAreTexturesResidentEXT", "glAreTexturesResident"),
    ("glDeleteTexturesEXT", "glDeleteTextures"),
    ("glGenTexturesEXT", "glGenTextures"),
    ("glIsTextureEXT", "glIsTexture"),
];

/// The value of a token name (`"GL_AMBIENT"`), from the registry.
pub fn value_of(name: &str) -> Option<u32> {
    registry::BY_NAME
        .binary_search_by(|(n, _)| (*n).cmp(name))
        .ok()
        .map(|i| registry::BY_NAME[i].1)
}

/// The names of token `value` in the registry (aliases: GL_TEXTURE_COMPARE_MODE and
/// GL_TEXTURE_COMPARE_MODE_ARB are one value), by a binary search of the table by value.
pub fn names_of(value: u32) -> impl Iterator<Item = &'static str> {
    entries_of(value).iter().map(|(_, n)| *n)
}

/// The registry's rows of token `value`: the run of equal values in the table sorted by
/// value.
fn entries_of(value: u32) -> &'static [(u32, &'static str)] {
    let table = registry::BY_VALUE;
    let start = table.partition_point(|(v, _)| *v < value);
    let len = table[start..].partition_point(|(v, _)| *v == value);
    &table[start..start + len]
}

/// The first name in `pnames` that token `value` has, if any (in `pnames`' order, as a
/// search of `value_of` over them finds it). The value's names are looked up once, then
/// compared with each candidate.
pub fn pname_of(value: u32, pnames: &[&'static str]) -> Option<&'static str> {
    let names = entries_of(value);
    pnames
        .iter()
        .find(|p| names.iter().any(|(_, n)| n == *p))
        .copied()
}

/// GL_LIGHTi.
pub fn light(i: u8) -> u32 {
    registry::LIGHT0 + u32::from(i)
}

/// GL_TEXTUREi.
pub fn texture_unit(i: u8) -> u32 {
    registry::TEXTURE0 + u32::from(i)
}

/// GL_CLIP_PLANEi.
pub fn clip_plane(i: u8) -> u32 {
    registry::CLIP_PLANE0 + u32::from(i)
}

/// GL_COMBINERi_NV.
pub fn combiner(i: u8) -> u32 {
    registry::COMBINER0_NV + u32::from(i)
}

/// Indexed token families: `GL_LIGHT0`…, `GL_TEXTURE0`…, `GL_COMBINER0_NV`….
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    Light,
    Texture,
    Combiner,
    ClipPlane,
}

impl Family {
    /// (prefix, suffix, number of named tokens).
    fn parts(self) -> (&'static str, &'static str, u32) {
        match self {
            Family::Light => ("GL_LIGHT", "", 8),
            Family::Texture => ("GL_TEXTURE", "", 32),
            Family::Combiner => ("GL_COMBINER", "_NV", 8),
            Family::ClipPlane => ("GL_CLIP_PLANE", "", 6),
        }
    }

    /// `GL_TEXTURE3` (+ offset) → 3 (+ offset). Accepts the `_ARB` spelling of TEXTUREi.
    pub fn parse(self, name: &str, offset: u32) -> Option<u8> {
        let (prefix, suffix, count) = self.parts();
        let rest = name.strip_prefix(prefix)?;
        let digits = match self {
            Family::Texture => rest.strip_suffix("_ARB").unwrap_or(rest),
            _ => rest.strip_suffix(suffix)?,
        };
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        let i: u32 = digits.parse().ok().filter(|i| *i < count)?;
        u8::try_from(i.checked_add(offset)?).ok()
    }

    /// The token for index `i`: `GL_LIGHT2`, or `GL_LIGHT0 + 9` beyond the named ones.
    pub fn print(self, i: u8) -> String {
        let (prefix, suffix, count) = self.parts();
        if u32::from(i) < count {
            format!("{prefix}{i}{suffix}")
        } else {
            format!("{prefix}0{suffix} + {i}")
        }
    }

    /// The index a GLenum value names: `GL_LIGHT0 + 3` → 3. Only the named range counts
    /// (a value beyond it is another token: GL_TEXTURE0 + 110 is GL_SPARE0_NV).
    pub fn from_value(self, value: u32) -> Option<u8> {
        let (_, _, named) = self.parts();
        let (base, count) = match self {
            Family::Light => (registry::LIGHT0, named),
            Family::Texture => (registry::TEXTURE0, named),
            Family::Combiner => (registry::COMBINER0_NV, named),
            // GL_CLIP_PLANE0 + i up to MAX_CLIP_PLANES (8 on Mesa), beyond the six named.
            Family::ClipPlane => (registry::CLIP_PLANE0, super::state::MAX_CLIP_PLANES as u32),
        };
        value
            .checked_sub(base)
            .filter(|i| *i < count)
            .and_then(|i| u8::try_from(i).ok())
    }

    pub fn example(self) -> &'static str {
        match self {
            Family::Light => "GL_LIGHT0..GL_LIGHT7",
            Family::Texture => "GL_TEXTURE0..GL_TEXTURE31",
            Family::Combiner => "GL_COMBINER0_NV..GL_COMBINER7_NV",
            Family::ClipPlane => "GL_CLIP_PLANE0..GL_CLIP_PLANE5",
        }
    }
}

macro_rules! gl_enums {
    ($ty:ty { $($name:ident => $val:expr),* $(,)? }) => {
        impl GlEnum for $ty {
            const TABLE: &'static [(&'static str, u32, Self)] =
                &[$((concat!("GL_", stringify!($name)), registry::$name, $val)),*];
        }
    };
}

gl_enums!(MatrixMode {
    MODELVIEW => MatrixMode::Modelview,
    PROJECTION => MatrixMode::Projection,
    TEXTURE => MatrixMode::Texture,
});

gl_enums!(Capability {
    LIGHTING => Capability::Lighting,
    COLOR_MATERIAL => Capability::ColorMaterial,
    NORMALIZE => Capability::Normalize,
    RESCALE_NORMAL => Capability::RescaleNormal,
    TEXTURE_1D => Capability::Texture1D,
    TEXTURE_2D => Capability::Texture2D,
    TEXTURE_3D => Capability::Texture3D,
    TEXTURE_CUBE_MAP => Capability::TextureCubeMap,
    TEXTURE_GEN_S => Capability::TextureGen(TexCoord::S),
    TEXTURE_GEN_T => Capability::TextureGen(TexCoord::T),
    TEXTURE_GEN_R => Capability::TextureGen(TexCoord::R),
    TEXTURE_GEN_Q => Capability::TextureGen(TexCoord::Q),
    ALPHA_TEST => Capability::AlphaTest,
    DEPTH_TEST => Capability::DepthTest,
    STENCIL_TEST => Capability::StencilTest,
    BLEND => Capability::Blend,
    CULL_FACE => Capability::CullFace,
    POLYGON_OFFSET_FILL => Capability::PolygonOffsetFill,
    POLYGON_OFFSET_LINE => Capability::PolygonOffsetLine,
    POLYGON_OFFSET_POINT => Capability::PolygonOffsetPoint,
    REGISTER_COMBINERS_NV => Capability::RegisterCombiners,
    FOG => Capability::Fog,
    SCISSOR_TEST => Capability::ScissorTest,
    DITHER => Capability::Dither,
    COLOR_LOGIC_OP => Capability::ColorLogicOp,
    INDEX_LOGIC_OP => Capability::IndexLogicOp,
    LOGIC_OP => Capability::IndexLogicOp,
    POLYGON_STIPPLE => Capability::PolygonStipple,
    LINE_STIPPLE => Capability::LineStipple,
    POINT_SMOOTH => Capability::PointSmooth,
    POINT_SPRITE => Capability::PointSprite,
    LINE_SMOOTH => Capability::LineSmooth,
    POLYGON_SMOOTH => Capability::PolygonSmooth,
    COLOR_SUM => Capability::ColorSum,
    MULTISAMPLE => Capability::Multisample,
    SAMPLE_COVERAGE => Capability::SampleCoverage,
    SAMPLE_ALPHA_TO_COVERAGE => Capability::SampleAlphaToCoverage,
    SAMPLE_ALPHA_TO_ONE => Capability::SampleAlphaToOne,
    SAMPLE_COVERAGE_INVERT => Capability::SampleCoverageInvert,
    AUTO_NORMAL => Capability::AutoNormal,
    MAP1_VERTEX_3 => Capability::Map(EvalMap { dims: MapDims::One, attribute: MapAttribute::Vertex3 }),
    MAP1_VERTEX_4 => Capability::Map(EvalMap { dims: MapDims::One, attribute: MapAttribute::Vertex4 }),
    MAP1_INDEX => Capability::Map(EvalMap { dims: MapDims::One, attribute: MapAttribute::Index }),
    MAP1_COLOR_4 => Capability::Map(EvalMap { dims: MapDims::One, attribute: MapAttribute::Color4 }),
    MAP1_NORMAL => Capability::Map(EvalMap { dims: MapDims::One, attribute: MapAttribute::Normal }),
    MAP1_TEXTURE_COORD_1 => Capability::Map(EvalMap { dims: MapDims::One, attribute: MapAttribute::TextureCoord1 }),
    MAP1_TEXTURE_COORD_2 => Capability::Map(EvalMap { dims: MapDims::One, attribute: MapAttribute::TextureCoord2 }),
    MAP1_TEXTURE_COORD_3 => Capability::Map(EvalMap { dims: MapDims::One, attribute: MapAttribute::TextureCoord3 }),
    MAP1_TEXTURE_COORD_4 => Capability::Map(EvalMap { dims: MapDims::One, attribute: MapAttribute::TextureCoord4 }),
    MAP2_VERTEX_3 => Capability::Map(EvalMap { dims: MapDims::Two, attribute: MapAttribute::Vertex3 }),
    MAP2_VERTEX_4 => Capability::Map(EvalMap { dims: MapDims::Two, attribute: MapAttribute::Vertex4 }),
    MAP2_INDEX => Capability::Map(EvalMap { dims: MapDims::Two, attribute: MapAttribute::Index }),
    MAP2_COLOR_4 => Capability::Map(EvalMap { dims: MapDims::Two, attribute: MapAttribute::Color4 }),
    MAP2_NORMAL => Capability::Map(EvalMap { dims: MapDims::Two, attribute: MapAttribute::Normal }),
    MAP2_TEXTURE_COORD_1 => Capability::Map(EvalMap { dims: MapDims::Two, attribute: MapAttribute::TextureCoord1 }),
    MAP2_TEXTURE_COORD_2 => Capability::Map(EvalMap { dims: MapDims::Two, attribute: MapAttribute::TextureCoord2 }),
    MAP2_TEXTURE_COORD_3 => Capability::Map(EvalMap { dims: MapDims::Two, attribute: MapAttribute::TextureCoord3 }),
    MAP2_TEXTURE_COORD_4 => Capability::Map(EvalMap { dims: MapDims::Two, attribute: MapAttribute::TextureCoord4 }),
});

gl_enums!(LogicOp {
    CLEAR => LogicOp::Clear,
    AND => LogicOp::And,
    AND_REVERSE => LogicOp::AndReverse,
    COPY => LogicOp::Copy,
    AND_INVERTED => LogicOp::AndInverted,
    NOOP => LogicOp::Noop,
    XOR => LogicOp::Xor,
    OR => LogicOp::Or,
    NOR => LogicOp::Nor,
    EQUIV => LogicOp::Equiv,
    INVERT => LogicOp::Invert,
    OR_REVERSE => LogicOp::OrReverse,
    COPY_INVERTED => LogicOp::CopyInverted,
    OR_INVERTED => LogicOp::OrInverted,
    NAND => LogicOp::Nand,
    SET => LogicOp::Set,
});

gl_enums!(HintTarget {
    PERSPECTIVE_CORRECTION_HINT => HintTarget::PerspectiveCorrection,
    POINT_SMOOTH_HINT => HintTarget::PointSmooth,
    LINE_SMOOTH_HINT => HintTarget::LineSmooth,
    POLYGON_SMOOTH_HINT => HintTarget::PolygonSmooth,
    FOG_HINT => HintTarget::Fog,
    TEXTURE_COMPRESSION_HINT => HintTarget::TextureCompression,
    GENERATE_MIPMAP_HINT => HintTarget::GenerateMipmap,
});

gl_enums!(HintMode {
    FASTEST => HintMode::Fastest,
    NICEST => HintMode::Nicest,
    DONT_CARE => HintMode::DontCare,
});

gl_enums!(FogMode {
    LINEAR => FogMode::Linear,
    EXP => FogMode::Exp,
    EXP2 => FogMode::Exp2,
});

gl_enums!(FogCoordSource {
    FRAGMENT_DEPTH => FogCoordSource::FragmentDepth,
    FOG_COORD => FogCoordSource::FogCoord,
    FOG_COORDINATE => FogCoordSource::FogCoord,
});

gl_enums!(CompareFunc {
    NEVER => CompareFunc::Never,
    LESS => CompareFunc::Less,
    EQUAL => CompareFunc::Equal,
    LEQUAL => CompareFunc::Lequal,
    GREATER => CompareFunc::Greater,
    NOTEQUAL => CompareFunc::Notequal,
    GEQUAL => CompareFunc::Gequal,
    ALWAYS => CompareFunc::Always,
});

gl_enums!(StencilOp {
    KEEP => StencilOp::Keep,
    ZERO => StencilOp::Zero,
    REPLACE => StencilOp::Replace,
    INCR => StencilOp::Incr,
    DECR => StencilOp::Decr,
    INVERT => StencilOp::Invert,
    INCR_WRAP => StencilOp::IncrWrap,
    DECR_WRAP => StencilOp::DecrWrap,
});

gl_enums!(BlendFactor {
    ZERO => BlendFactor::Zero,
    ONE => BlendFactor::One,
    SRC_COLOR => BlendFactor::SrcColor,
    ONE_MINUS_SRC_COLOR => BlendFactor::OneMinusSrcColor,
    DST_COLOR => BlendFactor::DstColor,
    ONE_MINUS_DST_COLOR => BlendFactor::OneMinusDstColor,
    SRC_ALPHA => BlendFactor::SrcAlpha,
    ONE_MINUS_SRC_ALPHA => BlendFactor::OneMinusSrcAlpha,
    DST_ALPHA => BlendFactor::DstAlpha,
    ONE_MINUS_DST_ALPHA => BlendFactor::OneMinusDstAlpha,
    SRC_ALPHA_SATURATE => BlendFactor::SrcAlphaSaturate,
    CONSTANT_COLOR => BlendFactor::ConstantColor,
    ONE_MINUS_CONSTANT_COLOR => BlendFactor::OneMinusConstantColor,
    CONSTANT_ALPHA => BlendFactor::ConstantAlpha,
    ONE_MINUS_CONSTANT_ALPHA => BlendFactor::OneMinusConstantAlpha,
});

gl_enums!(BlendEquation {
    FUNC_ADD => BlendEquation::FuncAdd,
    FUNC_SUBTRACT => BlendEquation::FuncSubtract,
    FUNC_REVERSE_SUBTRACT => BlendEquation::FuncReverseSubtract,
    MIN => BlendEquation::Min,
    MAX => BlendEquation::Max,
});

gl_enums!(Face {
    FRONT => Face::Front,
    BACK => Face::Back,
    FRONT_AND_BACK => Face::FrontAndBack,
});

gl_enums!(FrontFace { CW => FrontFace::Cw, CCW => FrontFace::Ccw });

gl_enums!(PolygonMode {
    POINT => PolygonMode::Point,
    LINE => PolygonMode::Line,
    FILL => PolygonMode::Fill,
});

gl_enums!(ShadeModel { FLAT => ShadeModel::Flat, SMOOTH => ShadeModel::Smooth });

gl_enums!(Primitive {
    POINTS => Primitive::Points,
    LINES => Primitive::Lines,
    LINE_LOOP => Primitive::LineLoop,
    LINE_STRIP => Primitive::LineStrip,
    TRIANGLES => Primitive::Triangles,
    TRIANGLE_STRIP => Primitive::TriangleStrip,
    TRIANGLE_FAN => Primitive::TriangleFan,
    QUADS => Primitive::Quads,
    QUAD_STRIP => Primitive::QuadStrip,
    POLYGON => Primitive::Polygon,
});

gl_enums!(ColorMaterialMode {
    AMBIENT => ColorMaterialMode::Ambient,
    DIFFUSE => ColorMaterialMode::Diffuse,
    SPECULAR => ColorMaterialMode::Specular,
    EMISSION => ColorMaterialMode::Emission,
    AMBIENT_AND_DIFFUSE => ColorMaterialMode::AmbientAndDiffuse,
});

gl_enums!(ColorControl {
    SINGLE_COLOR => ColorControl::SingleColor,
    SEPARATE_SPECULAR_COLOR => ColorControl::SeparateSpecularColor,
});

gl_enums!(TextureTarget {
    TEXTURE_1D => TextureTarget::Texture1D,
    TEXTURE_2D => TextureTarget::Texture2D,
    TEXTURE_3D => TextureTarget::Texture3D,
    TEXTURE_CUBE_MAP => TextureTarget::CubeMap,
    TEXTURE_CUBE_MAP_POSITIVE_X => TextureTarget::CubeFace(CubeFace::PositiveX),
    TEXTURE_CUBE_MAP_NEGATIVE_X => TextureTarget::CubeFace(CubeFace::NegativeX),
    TEXTURE_CUBE_MAP_POSITIVE_Y => TextureTarget::CubeFace(CubeFace::PositiveY),
    TEXTURE_CUBE_MAP_NEGATIVE_Y => TextureTarget::CubeFace(CubeFace::NegativeY),
    TEXTURE_CUBE_MAP_POSITIVE_Z => TextureTarget::CubeFace(CubeFace::PositiveZ),
    TEXTURE_CUBE_MAP_NEGATIVE_Z => TextureTarget::CubeFace(CubeFace::NegativeZ),
});

// Unsized names of the era are accepted as aliases of the sized formats they give.
gl_enums!(TexFormat {
    RGBA8 => TexFormat::Rgba8,
    RGB8 => TexFormat::Rgb8,
    LUMINANCE8 => TexFormat::Luminance8,
    INTENSITY8 => TexFormat::Intensity8,
    ALPHA8 => TexFormat::Alpha8,
    LUMINANCE8_ALPHA8 => TexFormat::Luminance8Alpha8,
    DEPTH_COMPONENT16 => TexFormat::DepthComponent16,
    DEPTH_COMPONENT24 => TexFormat::DepthComponent24,
    DEPTH_COMPONENT32F => TexFormat::DepthComponent32F,
    RGBA => TexFormat::Rgba8,
    RGB => TexFormat::Rgb8,
    LUMINANCE => TexFormat::Luminance8,
    INTENSITY => TexFormat::Intensity8,
    ALPHA => TexFormat::Alpha8,
    LUMINANCE_ALPHA => TexFormat::Luminance8Alpha8,
    DEPTH_COMPONENT => TexFormat::DepthComponent24,
    // GL 1.1's other sized formats (Table 3.16): the model's format is their base's 8-bit
    // one; the bits they are stored at are `texture_storage`'s (from the requested name).
    ALPHA4 => TexFormat::Alpha8,
    ALPHA12 => TexFormat::Alpha8,
    ALPHA16 => TexFormat::Alpha8,
    LUMINANCE4 => TexFormat::Luminance8,
    LUMINANCE12 => TexFormat::Luminance8,
    LUMINANCE16 => TexFormat::Luminance8,
    LUMINANCE4_ALPHA4 => TexFormat::Luminance8Alpha8,
    LUMINANCE6_ALPHA2 => TexFormat::Luminance8Alpha8,
    LUMINANCE12_ALPHA4 => TexFormat::Luminance8Alpha8,
    LUMINANCE12_ALPHA12 => TexFormat::Luminance8Alpha8,
    LUMINANCE16_ALPHA16 => TexFormat::Luminance8Alpha8,
    INTENSITY4 => TexFormat::Intensity8,
    INTENSITY12 => TexFormat::Intensity8,
    INTENSITY16 => TexFormat::Intensity8,
    R3_G3_B2 => TexFormat::Rgb8,
    RGB4 => TexFormat::Rgb8,
    RGB5 => TexFormat::Rgb8,
    RGB10 => TexFormat::Rgb8,
    RGB12 => TexFormat::Rgb8,
    RGB16 => TexFormat::Rgb8,
    RGBA2 => TexFormat::Rgba8,
    RGBA4 => TexFormat::Rgba8,
    RGB5_A1 => TexFormat::Rgba8,
    RGB10_A2 => TexFormat::Rgba8,
    RGBA12 => TexFormat::Rgba8,
    RGBA16 => TexFormat::Rgba8,
    DEPTH_COMPONENT32 => TexFormat::DepthComponent24,
    // GL 1.3's generic compressed formats (Table 3.17), kept uncompressed: GL lets an
    // implementation store them so; Mesa compresses the luminance and colour ones.
    COMPRESSED_ALPHA => TexFormat::Alpha8,
    COMPRESSED_LUMINANCE => TexFormat::Luminance8,
    COMPRESSED_LUMINANCE_ALPHA => TexFormat::Luminance8Alpha8,
    COMPRESSED_INTENSITY => TexFormat::Intensity8,
    COMPRESSED_RGB => TexFormat::Rgb8,
    COMPRESSED_RGBA => TexFormat::Rgba8,
});

gl_enums!(PixelFormat {
    RGBA => PixelFormat::Rgba,
    RGB => PixelFormat::Rgb,
    LUMINANCE => PixelFormat::Luminance,
    LUMINANCE_ALPHA => PixelFormat::LuminanceAlpha,
    ALPHA => PixelFormat::Alpha,
    DEPTH_COMPONENT => PixelFormat::DepthComponent,
    STENCIL_INDEX => PixelFormat::StencilIndex,
    RED => PixelFormat::Red,
    GREEN => PixelFormat::Green,
    BLUE => PixelFormat::Blue,
    BGR => PixelFormat::Bgr,
    BGRA => PixelFormat::Bgra,
    ABGR_EXT => PixelFormat::Abgr,
    COLOR_INDEX => PixelFormat::ColorIndex,
});

gl_enums!(CompressedFormat {
    COMPRESSED_RGB_S3TC_DXT1_EXT => CompressedFormat::RgbDxt1,
    COMPRESSED_RGBA_S3TC_DXT1_EXT => CompressedFormat::RgbaDxt1,
    COMPRESSED_RGBA_S3TC_DXT3_EXT => CompressedFormat::RgbaDxt3,
    COMPRESSED_RGBA_S3TC_DXT5_EXT => CompressedFormat::RgbaDxt5,
});

gl_enums!(PixelType {
    UNSIGNED_BYTE => PixelType::UnsignedByte,
    UNSIGNED_SHORT => PixelType::UnsignedShort,
    UNSIGNED_INT => PixelType::UnsignedInt,
    FLOAT => PixelType::Float,
    BYTE => PixelType::Byte,
    SHORT => PixelType::Short,
    INT => PixelType::Int,
    UNSIGNED_BYTE_3_3_2 => PixelType::Packed(PackedType::UnsignedByte332),
    UNSIGNED_BYTE_2_3_3_REV => PixelType::Packed(PackedType::UnsignedByte233Rev),
    UNSIGNED_SHORT_5_6_5 => PixelType::Packed(PackedType::UnsignedShort565),
    UNSIGNED_SHORT_5_6_5_REV => PixelType::Packed(PackedType::UnsignedShort565Rev),
    UNSIGNED_SHORT_4_4_4_4 => PixelType::Packed(PackedType::UnsignedShort4444),
    UNSIGNED_SHORT_4_4_4_4_REV => PixelType::Packed(PackedType::UnsignedShort4444Rev),
    UNSIGNED_SHORT_5_5_5_1 => PixelType::Packed(PackedType::UnsignedShort5551),
    UNSIGNED_SHORT_1_5_5_5_REV => PixelType::Packed(PackedType::UnsignedShort1555Rev),
    UNSIGNED_INT_8_8_8_8 => PixelType::Packed(PackedType::UnsignedInt8888),
    UNSIGNED_INT_8_8_8_8_REV => PixelType::Packed(PackedType::UnsignedInt8888Rev),
    UNSIGNED_INT_10_10_10_2 => PixelType::Packed(PackedType::UnsignedInt1010102),
    UNSIGNED_INT_2_10_10_10_REV => PixelType::Packed(PackedType::UnsignedInt2101010Rev),
});

gl_enums!(Filter {
    NEAREST => Filter::Nearest,
    LINEAR => Filter::Linear,
    NEAREST_MIPMAP_NEAREST => Filter::NearestMipmapNearest,
    LINEAR_MIPMAP_NEAREST => Filter::LinearMipmapNearest,
    NEAREST_MIPMAP_LINEAR => Filter::NearestMipmapLinear,
    LINEAR_MIPMAP_LINEAR => Filter::LinearMipmapLinear,
});

gl_enums!(Wrap {
    REPEAT => Wrap::Repeat,
    CLAMP => Wrap::Clamp,
    CLAMP_TO_EDGE => Wrap::ClampToEdge,
    CLAMP_TO_BORDER => Wrap::ClampToBorder,
    MIRRORED_REPEAT => Wrap::MirroredRepeat,
});

gl_enums!(CompareMode {
    NONE => CompareMode::None,
    COMPARE_R_TO_TEXTURE => CompareMode::CompareRToTexture,
    COMPARE_R_TO_TEXTURE_ARB => CompareMode::CompareRToTexture,
});

gl_enums!(DepthTextureMode {
    LUMINANCE => DepthTextureMode::Luminance,
    INTENSITY => DepthTextureMode::Intensity,
    ALPHA => DepthTextureMode::Alpha,
});

gl_enums!(TexCoord {
    S => TexCoord::S,
    T => TexCoord::T,
    R => TexCoord::R,
    Q => TexCoord::Q,
});

gl_enums!(TexGenMode {
    OBJECT_LINEAR => TexGenMode::ObjectLinear,
    EYE_LINEAR => TexGenMode::EyeLinear,
    SPHERE_MAP => TexGenMode::SphereMap,
    REFLECTION_MAP => TexGenMode::ReflectionMap,
    NORMAL_MAP => TexGenMode::NormalMap,
});

gl_enums!(TexEnvMode {
    MODULATE => TexEnvMode::Modulate,
    REPLACE => TexEnvMode::Replace,
    DECAL => TexEnvMode::Decal,
    BLEND => TexEnvMode::Blend,
    ADD => TexEnvMode::Add,
    COMBINE => TexEnvMode::Combine,
});

gl_enums!(CombineFunc {
    REPLACE => CombineFunc::Replace,
    MODULATE => CombineFunc::Modulate,
    ADD => CombineFunc::Add,
    ADD_SIGNED => CombineFunc::AddSigned,
    INTERPOLATE => CombineFunc::Interpolate,
    SUBTRACT => CombineFunc::Subtract,
    DOT3_RGB => CombineFunc::Dot3Rgb,
    DOT3_RGBA => CombineFunc::Dot3Rgba,
});

// Without TEXTUREi (a `Family`).
gl_enums!(CombineSource {
    TEXTURE => CombineSource::Texture,
    CONSTANT => CombineSource::Constant,
    PRIMARY_COLOR => CombineSource::PrimaryColor,
    PREVIOUS => CombineSource::Previous,
});

gl_enums!(CombineOperand {
    SRC_COLOR => CombineOperand::SrcColor,
    ONE_MINUS_SRC_COLOR => CombineOperand::OneMinusSrcColor,
    SRC_ALPHA => CombineOperand::SrcAlpha,
    ONE_MINUS_SRC_ALPHA => CombineOperand::OneMinusSrcAlpha,
});

// Without TEXTUREi_ARB (a `Family`).
gl_enums!(Register {
    ZERO => Register::Zero,
    CONSTANT_COLOR0_NV => Register::ConstantColor0,
    CONSTANT_COLOR1_NV => Register::ConstantColor1,
    FOG => Register::Fog,
    PRIMARY_COLOR_NV => Register::PrimaryColor,
    SECONDARY_COLOR_NV => Register::SecondaryColor,
    SPARE0_NV => Register::Spare0,
    SPARE1_NV => Register::Spare1,
    DISCARD_NV => Register::Discard,
    E_TIMES_F_NV => Register::ETimesF,
    SPARE0_PLUS_SECONDARY_COLOR_NV => Register::Spare0PlusSecondaryColor,
});

gl_enums!(Portion { RGB => Portion::Rgb, ALPHA => Portion::Alpha });

gl_enums!(ComponentUsage {
    RGB => ComponentUsage::Rgb,
    ALPHA => ComponentUsage::Alpha,
    BLUE => ComponentUsage::Blue,
});

gl_enums!(Variable {
    VARIABLE_A_NV => Variable::A,
    VARIABLE_B_NV => Variable::B,
    VARIABLE_C_NV => Variable::C,
    VARIABLE_D_NV => Variable::D,
});

gl_enums!(FinalVariable {
    VARIABLE_A_NV => FinalVariable::A,
    VARIABLE_B_NV => FinalVariable::B,
    VARIABLE_C_NV => FinalVariable::C,
    VARIABLE_D_NV => FinalVariable::D,
    VARIABLE_E_NV => FinalVariable::E,
    VARIABLE_F_NV => FinalVariable::F,
    VARIABLE_G_NV => FinalVariable::G,
});

gl_enums!(Mapping {
    UNSIGNED_IDENTITY_NV => Mapping::UnsignedIdentity,
    UNSIGNED_INVERT_NV => Mapping::UnsignedInvert,
    EXPAND_NORMAL_NV => Mapping::ExpandNormal,
    EXPAND_NEGATE_NV => Mapping::ExpandNegate,
    HALF_BIAS_NORMAL_NV => Mapping::HalfBiasNormal,
    HALF_BIAS_NEGATE_NV => Mapping::HalfBiasNegate,
    SIGNED_IDENTITY_NV => Mapping::SignedIdentity,
    SIGNED_NEGATE_NV => Mapping::SignedNegate,
});

gl_enums!(CombinerScale {
    NONE => CombinerScale::None,
    SCALE_BY_TWO_NV => CombinerScale::ByTwo,
    SCALE_BY_FOUR_NV => CombinerScale::ByFour,
    SCALE_BY_ONE_HALF_NV => CombinerScale::ByOneHalf,
});

gl_enums!(CombinerBias {
    NONE => CombinerBias::None,
    BIAS_BY_NEGATIVE_ONE_HALF_NV => CombinerBias::ByNegativeOneHalf,
});

gl_enums!(Product { FALSE => Product::Componentwise, TRUE => Product::Dot });

gl_enums!(SumOrMux { FALSE => SumOrMux::Sum, TRUE => SumOrMux::Mux });

gl_enums!(bool { FALSE => false, TRUE => true });

gl_enums!(super::accum::AccumOp {
    ACCUM => super::accum::AccumOp::Accum,
    LOAD => super::accum::AccumOp::Load,
    RETURN => super::accum::AccumOp::Return,
    MULT => super::accum::AccumOp::Mult,
    ADD => super::accum::AccumOp::Add,
});

gl_enums!(AttribGroup {
    CURRENT_BIT => AttribGroup::Current,
    POINT_BIT => AttribGroup::Point,
    LINE_BIT => AttribGroup::Line,
    POLYGON_BIT => AttribGroup::Polygon,
    POLYGON_STIPPLE_BIT => AttribGroup::PolygonStipple,
    PIXEL_MODE_BIT => AttribGroup::PixelMode,
    LIGHTING_BIT => AttribGroup::Lighting,
    FOG_BIT => AttribGroup::Fog,
    DEPTH_BUFFER_BIT => AttribGroup::DepthBuffer,
    ACCUM_BUFFER_BIT => AttribGroup::AccumBuffer,
    STENCIL_BUFFER_BIT => AttribGroup::StencilBuffer,
    VIEWPORT_BIT => AttribGroup::Viewport,
    TRANSFORM_BIT => AttribGroup::Transform,
    ENABLE_BIT => AttribGroup::Enable,
    COLOR_BUFFER_BIT => AttribGroup::ColorBuffer,
    HINT_BIT => AttribGroup::Hint,
    EVAL_BIT => AttribGroup::Eval,
    LIST_BIT => AttribGroup::List,
    TEXTURE_BIT => AttribGroup::Texture,
    SCISSOR_BIT => AttribGroup::Scissor,
    MULTISAMPLE_BIT => AttribGroup::Multisample,
});

// Framebuffer objects (ff::framebuffer). FRAMEBUFFER_EXT and the other EXT tokens have
// the same values and are read as these.
gl_enums!(super::blit::BlitFilter {
    NEAREST => super::blit::BlitFilter::Nearest,
    LINEAR => super::blit::BlitFilter::Linear,
    SCALED_RESOLVE_FASTEST_EXT => super::blit::BlitFilter::ScaledResolveFastest,
    SCALED_RESOLVE_NICEST_EXT => super::blit::BlitFilter::ScaledResolveNicest,
});

gl_enums!(FramebufferTarget {
    FRAMEBUFFER => FramebufferTarget::Both,
    DRAW_FRAMEBUFFER => FramebufferTarget::Draw,
    READ_FRAMEBUFFER => FramebufferTarget::Read,
    FRAMEBUFFER_EXT => FramebufferTarget::Both,
    DRAW_FRAMEBUFFER_EXT => FramebufferTarget::Draw,
    READ_FRAMEBUFFER_EXT => FramebufferTarget::Read,
});

gl_enums!(AttachmentPoint {
    COLOR_ATTACHMENT0 => AttachmentPoint::Color(0),
    COLOR_ATTACHMENT1 => AttachmentPoint::Color(1),
    COLOR_ATTACHMENT2 => AttachmentPoint::Color(2),
    COLOR_ATTACHMENT3 => AttachmentPoint::Color(3),
    COLOR_ATTACHMENT4 => AttachmentPoint::Color(4),
    COLOR_ATTACHMENT5 => AttachmentPoint::Color(5),
    COLOR_ATTACHMENT6 => AttachmentPoint::Color(6),
    COLOR_ATTACHMENT7 => AttachmentPoint::Color(7),
    COLOR_ATTACHMENT8 => AttachmentPoint::Color(8),
    COLOR_ATTACHMENT9 => AttachmentPoint::Color(9),
    COLOR_ATTACHMENT10 => AttachmentPoint::Color(10),
    COLOR_ATTACHMENT11 => AttachmentPoint::Color(11),
    COLOR_ATTACHMENT12 => AttachmentPoint::Color(12),
    COLOR_ATTACHMENT13 => AttachmentPoint::Color(13),
    COLOR_ATTACHMENT14 => AttachmentPoint::Color(14),
    COLOR_ATTACHMENT15 => AttachmentPoint::Color(15),
    DEPTH_ATTACHMENT => AttachmentPoint::Depth,
    STENCIL_ATTACHMENT => AttachmentPoint::Stencil,
    DEPTH_STENCIL_ATTACHMENT => AttachmentPoint::DepthStencil,
    COLOR_ATTACHMENT0_EXT => AttachmentPoint::Color(0),
    COLOR_ATTACHMENT1_EXT => AttachmentPoint::Color(1),
    COLOR_ATTACHMENT2_EXT => AttachmentPoint::Color(2),
    COLOR_ATTACHMENT3_EXT => AttachmentPoint::Color(3),
    COLOR_ATTACHMENT4_EXT => AttachmentPoint::Color(4),
    COLOR_ATTACHMENT5_EXT => AttachmentPoint::Color(5),
    COLOR_ATTACHMENT6_EXT => AttachmentPoint::Color(6),
    COLOR_ATTACHMENT7_EXT => AttachmentPoint::Color(7),
    COLOR_ATTACHMENT8_EXT => AttachmentPoint::Color(8),
    COLOR_ATTACHMENT9_EXT => AttachmentPoint::Color(9),
    COLOR_ATTACHMENT10_EXT => AttachmentPoint::Color(10),
    COLOR_ATTACHMENT11_EXT => AttachmentPoint::Color(11),
    COLOR_ATTACHMENT12_EXT => AttachmentPoint::Color(12),
    COLOR_ATTACHMENT13_EXT => AttachmentPoint::Color(13),
    COLOR_ATTACHMENT14_EXT => AttachmentPoint::Color(14),
    COLOR_ATTACHMENT15_EXT => AttachmentPoint::Color(15),
    DEPTH_ATTACHMENT_EXT => AttachmentPoint::Depth,
    STENCIL_ATTACHMENT_EXT => AttachmentPoint::Stencil,
});

gl_enums!(ColorBuffer {
    NONE => ColorBuffer::None,
    FRONT => ColorBuffer::Front,
    BACK => ColorBuffer::Back,
    LEFT => ColorBuffer::Left,
    RIGHT => ColorBuffer::Right,
    FRONT_LEFT => ColorBuffer::FrontLeft,
    FRONT_RIGHT => ColorBuffer::FrontRight,
    BACK_LEFT => ColorBuffer::BackLeft,
    BACK_RIGHT => ColorBuffer::BackRight,
    FRONT_AND_BACK => ColorBuffer::FrontAndBack,
    AUX0 => ColorBuffer::Aux(0),
    AUX1 => ColorBuffer::Aux(1),
    AUX2 => ColorBuffer::Aux(2),
    AUX3 => ColorBuffer::Aux(3),
    COLOR_ATTACHMENT0 => ColorBuffer::Attachment(0),
    COLOR_ATTACHMENT1 => ColorBuffer::Attachment(1),
    COLOR_ATTACHMENT2 => ColorBuffer::Attachment(2),
    COLOR_ATTACHMENT3 => ColorBuffer::Attachment(3),
    COLOR_ATTACHMENT4 => ColorBuffer::Attachment(4),
    COLOR_ATTACHMENT5 => ColorBuffer::Attachment(5),
    COLOR_ATTACHMENT6 => ColorBuffer::Attachment(6),
    COLOR_ATTACHMENT7 => ColorBuffer::Attachment(7),
    COLOR_ATTACHMENT8 => ColorBuffer::Attachment(8),
    COLOR_ATTACHMENT9 => ColorBuffer::Attachment(9),
    COLOR_ATTACHMENT10 => ColorBuffer::Attachment(10),
    COLOR_ATTACHMENT11 => ColorBuffer::Attachment(11),
    COLOR_ATTACHMENT12 => ColorBuffer::Attachment(12),
    COLOR_ATTACHMENT13 => ColorBuffer::Attachment(13),
    COLOR_ATTACHMENT14 => ColorBuffer::Attachment(14),
    COLOR_ATTACHMENT15 => ColorBuffer::Attachment(15),
});

gl_enums!(RenderbufferFormat {
    RGBA => RenderbufferFormat::Rgba,
    RGBA8 => RenderbufferFormat::Rgba8,
    RGB => RenderbufferFormat::Rgb,
    RGB8 => RenderbufferFormat::Rgb8,
    RGBA4 => RenderbufferFormat::Rgba4,
    RGB5_A1 => RenderbufferFormat::Rgb5A1,
    RGB565 => RenderbufferFormat::Rgb565,
    RGBA2 => RenderbufferFormat::Rgba2,
    RGB4 => RenderbufferFormat::Rgb4,
    RGB5 => RenderbufferFormat::Rgb5,
    RGB10 => RenderbufferFormat::Rgb10,
    RGB10_A2 => RenderbufferFormat::Rgb10A2,
    RGBA12 => RenderbufferFormat::Rgba12,
    RGBA16 => RenderbufferFormat::Rgba16,
    RGBA16F => RenderbufferFormat::Rgba16F,
    RGBA32F => RenderbufferFormat::Rgba32F,
    RED => RenderbufferFormat::Red,
    R8 => RenderbufferFormat::R8,
    RG8 => RenderbufferFormat::Rg8,
    ALPHA => RenderbufferFormat::Alpha,
    ALPHA8 => RenderbufferFormat::Alpha8,
    LUMINANCE => RenderbufferFormat::Luminance,
    LUMINANCE8 => RenderbufferFormat::Luminance8,
    INTENSITY => RenderbufferFormat::Intensity,
    INTENSITY8 => RenderbufferFormat::Intensity8,
    LUMINANCE_ALPHA => RenderbufferFormat::LuminanceAlpha,
    LUMINANCE8_ALPHA8 => RenderbufferFormat::Luminance8Alpha8,
    DEPTH_COMPONENT => RenderbufferFormat::DepthComponent,
    DEPTH_COMPONENT16 => RenderbufferFormat::DepthComponent16,
    DEPTH_COMPONENT24 => RenderbufferFormat::DepthComponent24,
    DEPTH_COMPONENT32 => RenderbufferFormat::DepthComponent32,
    DEPTH_COMPONENT32F => RenderbufferFormat::DepthComponent32F,
    STENCIL_INDEX => RenderbufferFormat::StencilIndex,
    STENCIL_INDEX1 => RenderbufferFormat::StencilIndex1,
    STENCIL_INDEX4 => RenderbufferFormat::StencilIndex4,
    STENCIL_INDEX8 => RenderbufferFormat::StencilIndex8,
    STENCIL_INDEX16 => RenderbufferFormat::StencilIndex16,
    DEPTH_STENCIL => RenderbufferFormat::DepthStencil,
    DEPTH24_STENCIL8 => RenderbufferFormat::Depth24Stencil8,
    DEPTH32F_STENCIL8 => RenderbufferFormat::Depth32FStencil8,
    STENCIL_INDEX1_EXT => RenderbufferFormat::StencilIndex1,
    STENCIL_INDEX4_EXT => RenderbufferFormat::StencilIndex4,
    STENCIL_INDEX8_EXT => RenderbufferFormat::StencilIndex8,
    STENCIL_INDEX16_EXT => RenderbufferFormat::StencilIndex16,
    DEPTH_STENCIL_EXT => RenderbufferFormat::DepthStencil,
    DEPTH24_STENCIL8_EXT => RenderbufferFormat::Depth24Stencil8,
});

#[cfg(test)]
mod tests {
    use super::*;

    /// The registry's command aliases resolve to their commands; calls of other
    /// semantics under an extension's name (glPolygonOffsetEXT's bias) are no aliases.
    #[test]
    fn extension_names_of_core_calls_are_aliases() {
        assert_eq!(
            registry_alias("glBlendEquationEXT"),
            Some("glBlendEquation")
        );
        assert_eq!(
            registry_alias("glActiveTextureARB"),
            Some("glActiveTexture")
        );
        assert_eq!(registry_alias("glBindTextureEXT"), Some("glBindTexture"));
        assert_eq!(registry_alias("glGenTexturesEXT"), Some("glGenTextures"));
        assert_eq!(registry_alias("glPolygonOffsetEXT"), None);
        assert_eq!(registry_alias("glVertexPointerEXT"), None);
        assert_eq!(registry_alias("glBlendEquation"), None);
    }

    /// The GL 1.0 tokens named with a leading digit (glCallLists' GL_2_BYTES …) and the
    /// ARB_shadow_ambient token are in the table, with the registry's values.
    #[test]
    fn digit_named_and_shadow_ambient_tokens_are_known() {
        assert_eq!(value_of("GL_2_BYTES"), Some(0x1407));
        assert_eq!(value_of("GL_3_BYTES"), Some(0x1408));
        assert_eq!(value_of("GL_4_BYTES"), Some(0x1409));
        assert_eq!(value_of("GL_3D_COLOR_TEXTURE"), Some(0x0603));
        assert_eq!(value_of("GL_TEXTURE_COMPARE_FAIL_VALUE_ARB"), Some(0x80BF));
        assert!(names_of(0x1407).any(|n| n == "GL_2_BYTES"));
    }

    /// Every name's value leads back to the name, aliases included, and a pname search
    /// finds the first listed name the token has.
    #[test]
    fn names_of_a_value_are_the_names_with_that_value() {
        for (name, value) in registry::BY_NAME {
            assert!(names_of(*value).any(|n| n == *name), "{name}");
        }
        let compare: Vec<_> = names_of(registry::TEXTURE_COMPARE_MODE).collect();
        assert!(compare.contains(&"GL_TEXTURE_COMPARE_MODE"), "{compare:?}");
        assert!(
            compare.contains(&"GL_TEXTURE_COMPARE_MODE_ARB"),
            "{compare:?}"
        );
        let listed = ["GL_TEXTURE_COMPARE_MODE_ARB", "GL_TEXTURE_COMPARE_MODE"];
        assert_eq!(
            pname_of(registry::TEXTURE_COMPARE_MODE, &listed),
            Some("GL_TEXTURE_COMPARE_MODE_ARB")
        );
        assert_eq!(pname_of(registry::AMBIENT, &listed), None);
        assert_eq!(names_of(0xFFFF_FFF0).count(), 0);
    }

    /// Each value's canonical name and number are the registry's pair.
    #[test]
    fn names_and_values_agree_with_the_registry() {
        assert_eq!(MatrixMode::Modelview.gl_value(), Some(0x1700));
        assert_eq!(MatrixMode::Modelview.gl_name(), Some("GL_MODELVIEW"));
        assert_eq!(TexFormat::DepthComponent32F.gl_value(), Some(0x8CAC));
        assert_eq!(Register::Spare0.gl_value(), Some(0x852E));
        assert_eq!(CompareMode::CompareRToTexture.gl_value(), Some(0x884E));
        assert_eq!(TexFormat::from_gl_value(0x1908), Some(TexFormat::Rgba8)); // GL_RGBA alias
        assert_eq!(light(3), 0x4003);
        assert_eq!(texture_unit(2), 0x84C2);
        assert_eq!(combiner(1), 0x8551);
    }

    /// Every variant of each table's enum has an entry (`gl` never falls back to 0 for a
    /// value the model can hold).
    #[test]
    fn tables_cover_their_enums() {
        fn covers<T: GlEnum + std::fmt::Debug>(values: &[T]) {
            for v in values {
                assert!(v.gl_value().is_some(), "{v:?} has no GL enumerant");
            }
        }
        covers(&[
            MatrixMode::Modelview,
            MatrixMode::Projection,
            MatrixMode::Texture,
        ]);
        covers(&[
            CompareFunc::Never,
            CompareFunc::Less,
            CompareFunc::Equal,
            CompareFunc::Lequal,
            CompareFunc::Greater,
            CompareFunc::Notequal,
            CompareFunc::Gequal,
            CompareFunc::Always,
        ]);
        covers(&[
            Primitive::Points,
            Primitive::Lines,
            Primitive::LineStrip,
            Primitive::LineLoop,
            Primitive::Triangles,
            Primitive::TriangleStrip,
            Primitive::TriangleFan,
            Primitive::Quads,
            Primitive::QuadStrip,
            Primitive::Polygon,
        ]);
        covers(&[
            TexFormat::Rgba8,
            TexFormat::Rgb8,
            TexFormat::Luminance8,
            TexFormat::Intensity8,
            TexFormat::Alpha8,
            TexFormat::Luminance8Alpha8,
            TexFormat::DepthComponent16,
            TexFormat::DepthComponent24,
            TexFormat::DepthComponent32F,
        ]);
        covers(&[
            Wrap::Repeat,
            Wrap::Clamp,
            Wrap::ClampToEdge,
            Wrap::ClampToBorder,
            Wrap::MirroredRepeat,
        ]);
        use super::super::blit::BlitFilter;
        covers(&[
            BlitFilter::Nearest,
            BlitFilter::Linear,
            BlitFilter::ScaledResolveFastest,
            BlitFilter::ScaledResolveNicest,
        ]);
    }
}

gl_enums!(PixelMapName {
    PIXEL_MAP_I_TO_I => PixelMapName::IToI,
    PIXEL_MAP_S_TO_S => PixelMapName::SToS,
    PIXEL_MAP_I_TO_R => PixelMapName::IToR,
    PIXEL_MAP_I_TO_G => PixelMapName::IToG,
    PIXEL_MAP_I_TO_B => PixelMapName::IToB,
    PIXEL_MAP_I_TO_A => PixelMapName::IToA,
    PIXEL_MAP_R_TO_R => PixelMapName::RToR,
    PIXEL_MAP_G_TO_G => PixelMapName::GToG,
    PIXEL_MAP_B_TO_B => PixelMapName::BToB,
    PIXEL_MAP_A_TO_A => PixelMapName::AToA,
});
