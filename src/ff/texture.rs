//! Texture objects, formats and parameters (GL 1.5 §3.8, ARB_depth_texture, ARB_shadow,
//! ARB_shadow_ambient), with GL 1.2's 3D textures (EXT_texture3D; their calls are
//! `texture_volume`'s) and GL 1.3's cube maps (ARB_texture_cube_map).
//!
//! A cube map is one object (bound, enabled and given parameters as TEXTURE_CUBE_MAP)
//! with six sets of levels, one per face; the faces are the image targets of
//! glTexImage2D and the other 2D image calls (`TextureTarget::CubeFace`), never bound.
//!
//! A level has a width, a height and a depth; a 1D level has height 1, a 1D or 2D level
//! depth 1, so one completeness rule serves every target: each mip level is
//! max(1, ⌊previous / 2⌋) in every dimension down to 1×1×1.
//!
//! The table maps a texture name (u32, as GL) to its target, parameters and mip levels.
//! Name 0 is the default texture of each target. Pixel data is kept as the bytes of the
//! upload (with their format and type) so a pipeline or a CPU model can read them; after a
//! CopyTexImage2D, or a TexSubImage2D in another format/type, only the GPU copy is
//! authoritative and `data` is `None`.

use std::sync::Arc;

use glam::Vec4;

use super::error::{GlError, GlResult};
use super::fragment::CompareFunc;
pub use super::pixel_types::PackedType;

/// GL_MAX_TEXTURE_SIZE assumed by validation (every GL 3.3 context has at least 1024; llvmpipe
/// has 16384). Non-power-of-two sizes are accepted (a core context supports them).
pub const MAX_TEXTURE_SIZE: i32 = 16384;
/// Highest mip level accepted: log2(MAX_TEXTURE_SIZE).
pub const MAX_TEXTURE_LEVEL: i32 = 14;
/// GL_MAX_CUBE_MAP_TEXTURE_SIZE: Mesa 22.3.6 llvmpipe answers 16384 (measured natively),
/// the 2D limit, so a face's size checks are the 2D image's.
pub const MAX_CUBE_MAP_TEXTURE_SIZE: i32 = MAX_TEXTURE_SIZE;
/// GL_MAX_3D_TEXTURE_SIZE: Mesa 22.3 llvmpipe answers 2048 (measured natively); every GL
/// 3.3 context has at least 256, and llvmpipe's core context has 2048 too.
pub const MAX_3D_TEXTURE_SIZE: i32 = 2048;
/// Highest 3D mip level accepted: log2(MAX_3D_TEXTURE_SIZE) (Mesa: level 12 is
/// INVALID_VALUE, 11 accepted).
pub const MAX_3D_TEXTURE_LEVEL: i32 = 11;

/// Texture targets of the fixed-function pipeline.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TextureTarget {
    Texture1D,
    Texture2D,
    /// GL 1.2: images of width × height × depth texels, sampled at (s, t, r).
    Texture3D,
    /// GL 1.3 (ARB_texture_cube_map): six square faces sampled by the direction (s, t, r);
    /// what glBindTexture, glEnable and glTexParameter name. Not an image target.
    CubeMap,
    /// One face of the bound cube map: an image target of glTexImage2D, glTexSubImage2D,
    /// glCopyTexImage2D, glCopyTexSubImage2D, glGetTexImage and glGetTexLevelParameter;
    /// not bindable.
    CubeFace(CubeFace),
}

/// The faces of a cube map, in the order of their GL names (face i is
/// TEXTURE_CUBE_MAP_POSITIVE_X plus i): the face a direction selects is its major axis
/// and that axis' sign (GL 1.5 Table 3.21).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CubeFace {
    PositiveX,
    NegativeX,
    PositiveY,
    NegativeY,
    PositiveZ,
    NegativeZ,
}

impl CubeFace {
    pub const ALL: [CubeFace; 6] = [
        CubeFace::PositiveX,
        CubeFace::NegativeX,
        CubeFace::PositiveY,
        CubeFace::NegativeY,
        CubeFace::PositiveZ,
        CubeFace::NegativeZ,
    ];

    /// 0 for +X … 5 for −Z: the offset of the face's GL name from
    /// TEXTURE_CUBE_MAP_POSITIVE_X.
    pub fn index(self) -> usize {
        self as usize
    }
}

impl TextureTarget {
    /// Every bindable target, in the order texturing ranks them from the lowest (GL 1.5
    /// §3.8.15: the cube map wins over 3D, 3D over 2D, 2D over 1D).
    pub const ALL: [TextureTarget; 4] = [
        TextureTarget::Texture1D,
        TextureTarget::Texture2D,
        TextureTarget::Texture3D,
        TextureTarget::CubeMap,
    ];

    /// The target an object of this image target is bound to: a cube face's is
    /// TEXTURE_CUBE_MAP, every other target its own.
    pub fn binding(self) -> TextureTarget {
        match self {
            TextureTarget::CubeFace(_) => TextureTarget::CubeMap,
            t => t,
        }
    }

    /// The cube face this image target names, if it names one.
    pub fn face(self) -> Option<CubeFace> {
        match self {
            TextureTarget::CubeFace(f) => Some(f),
            _ => None,
        }
    }

    /// The highest mip level an image of this target may have: log2 of the target's
    /// largest size (MAX_TEXTURE_SIZE, MAX_3D_TEXTURE_SIZE).
    pub fn max_level(self) -> i32 {
        match self {
            TextureTarget::Texture1D
            | TextureTarget::Texture2D
            | TextureTarget::CubeMap
            | TextureTarget::CubeFace(_) => MAX_TEXTURE_LEVEL,
            TextureTarget::Texture3D => MAX_3D_TEXTURE_LEVEL,
        }
    }
}

/// Sized internal formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TexFormat {
    Rgba8,
    Rgb8,
    Luminance8,
    Intensity8,
    Alpha8,
    Luminance8Alpha8,
    DepthComponent16,
    DepthComponent24,
    DepthComponent32F,
    /// RGBA in 32-bit floats, unclamped (ARB_texture_float's RGBA32F). Only the
    /// techniques' own programs make it (the summed-area tables of `occlusion-textures`);
    /// the script dialect and the C library do not take it.
    Rgba32F,
}

/// The base internal format, which decides how texenv treats a texel (GL 1.5 Table 3.23).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BaseFormat {
    Alpha,
    Luminance,
    LuminanceAlpha,
    Intensity,
    Rgb,
    Rgba,
    Depth,
}

impl TexFormat {
    pub fn base(self) -> BaseFormat {
        match self {
            TexFormat::Rgba8 | TexFormat::Rgba32F => BaseFormat::Rgba,
            TexFormat::Rgb8 => BaseFormat::Rgb,
            TexFormat::Luminance8 => BaseFormat::Luminance,
            TexFormat::Intensity8 => BaseFormat::Intensity,
            TexFormat::Alpha8 => BaseFormat::Alpha,
            TexFormat::Luminance8Alpha8 => BaseFormat::LuminanceAlpha,
            TexFormat::DepthComponent16
            | TexFormat::DepthComponent24
            | TexFormat::DepthComponent32F => BaseFormat::Depth,
        }
    }

    pub fn is_depth(self) -> bool {
        self.base() == BaseFormat::Depth
    }
}

/// The external format of pixel data (TexImage, TexSubImage, ReadPixels).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PixelFormat {
    Rgba,
    Rgb,
    Luminance,
    LuminanceAlpha,
    Alpha,
    DepthComponent,
    StencilIndex,
    /// RED, GREEN, BLUE: one colour component (GL 1.5 Table 3.6), the others 0 and alpha 1
    /// when converted to RGBA. Read by glDrawPixels and glReadPixels; not texture data here.
    Red,
    Green,
    Blue,
    /// GL 1.2's BGR and BGRA (§3.6.4, Table 3.5): RGB and RGBA with red and blue in each
    /// other's place. Client data in them is taken apart into RGB and RGBA where it enters
    /// the layer (`pixel_types`); glReadPixels and glGetTexImage give them.
    Bgr,
    Bgra,
    /// EXT_abgr's ABGR_EXT: RGBA with its components in reverse order (alpha first), taken
    /// apart and given back as BGRA is.
    Abgr,
    /// COLOR_INDEX (GL 1.5 §3.6.4): one index a group, which an RGBA context turns into
    /// a colour through the I_TO_R/G/B/A maps (`index_pixels`). glDrawPixels and the
    /// texture images take it; the layer keeps it in the client's type (GL_BITMAP as
    /// UNSIGNED_BYTE indices 0 and 1).
    ColorIndex,
}

impl PixelFormat {
    /// Components per pixel.
    pub fn components(self) -> usize {
        match self {
            PixelFormat::Rgba | PixelFormat::Bgra | PixelFormat::Abgr => 4,
            PixelFormat::Rgb | PixelFormat::Bgr => 3,
            PixelFormat::LuminanceAlpha => 2,
            PixelFormat::Luminance
            | PixelFormat::Alpha
            | PixelFormat::DepthComponent
            | PixelFormat::StencilIndex
            | PixelFormat::ColorIndex
            | PixelFormat::Red
            | PixelFormat::Green
            | PixelFormat::Blue => 1,
        }
    }
}

/// The external component type of pixel data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PixelType {
    UnsignedByte,
    UnsignedShort,
    UnsignedInt,
    Float,
    /// GL 1.0's signed component types (GL 1.5 Table 3.5). Client data in them is
    /// converted to FLOAT where it enters the layer (`pixel_types`).
    Byte,
    Short,
    Int,
    /// GL 1.2's packed types: one element holds a whole group (Table 3.8).
    Packed(PackedType),
}

impl PixelType {
    /// Bytes per element: a component, or a whole group of a packed type.
    pub fn size(self) -> usize {
        match self {
            PixelType::UnsignedByte | PixelType::Byte => 1,
            PixelType::UnsignedShort | PixelType::Short => 2,
            PixelType::UnsignedInt | PixelType::Int | PixelType::Float => 4,
            PixelType::Packed(p) => p.bytes(),
        }
    }

    /// Bytes of one group of `format`: one element per component, or one packed element.
    pub fn group_bytes(self, format: PixelFormat) -> usize {
        match self {
            PixelType::Packed(p) => p.bytes(),
            _ => format.components() * self.size(),
        }
    }
}

/// Bytes of a tightly packed `width × height` image (UNPACK/PACK_ALIGNMENT 1 assumed; the
/// pipelines set it).
pub fn image_size(format: PixelFormat, ty: PixelType, width: i32, height: i32) -> usize {
    let w = width.max(0) as usize;
    let h = height.max(0) as usize;
    w * h * ty.group_bytes(format)
}

/// Bytes of a tightly packed `width × height × depth` image: `depth` images of
/// `height` rows, the first image first.
pub fn volume_size(
    format: PixelFormat,
    ty: PixelType,
    width: i32,
    height: i32,
    depth: i32,
) -> usize {
    image_size(format, ty, width, height) * depth.max(0) as usize
}

/// Minification and magnification filters. Mag accepts NEAREST and LINEAR only.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Filter {
    Nearest,
    Linear,
    NearestMipmapNearest,
    LinearMipmapNearest,
    NearestMipmapLinear,
    LinearMipmapLinear,
}

impl Filter {
    pub fn uses_mipmaps(self) -> bool {
        !matches!(self, Filter::Nearest | Filter::Linear)
    }

    /// Whether texels within a level are blended (LINEAR, LINEAR_MIPMAP_*) rather than
    /// the nearest taken (NEAREST, NEAREST_MIPMAP_*).
    pub fn blends_within_level(self) -> bool {
        matches!(
            self,
            Filter::Linear | Filter::LinearMipmapNearest | Filter::LinearMipmapLinear
        )
    }
}

/// Wrap modes. CLAMP clamps the coordinate to [0, 1] before filtering, so LINEAR blends the
/// edge texel half and half with the border colour there and NEAREST takes the edge texel;
/// CLAMP_TO_EDGE never samples the border; CLAMP_TO_BORDER samples only the border outside
/// [0, 1].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Wrap {
    Repeat,
    Clamp,
    ClampToEdge,
    ClampToBorder,
    /// GL 1.4 (ARB_texture_mirrored_repeat): the image repeated, every other copy mirrored.
    MirroredRepeat,
}

/// TEXTURE_COMPARE_MODE (ARB_shadow).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CompareMode {
    None,
    /// Compare r (clamped to [0, 1] after the divide by q) with the depth texel.
    CompareRToTexture,
}

/// DEPTH_TEXTURE_MODE (ARB_depth_texture): how a depth (or compare) result L becomes a texel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DepthTextureMode {
    /// (L, L, L, 1)
    Luminance,
    /// (L, L, L, L)
    Intensity,
    /// (0, 0, 0, L)
    Alpha,
}

/// One glTexParameter with its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TexParam {
    MinFilter(Filter),
    /// NEAREST or LINEAR, else INVALID_ENUM.
    MagFilter(Filter),
    WrapS(Wrap),
    WrapT(Wrap),
    /// TEXTURE_WRAP_R (GL 1.2): kept for every target, read by 3D textures only.
    WrapR(Wrap),
    BorderColor(Vec4),
    CompareMode(CompareMode),
    CompareFunc(CompareFunc),
    DepthTextureMode(DepthTextureMode),
    /// TEXTURE_COMPARE_FAIL_VALUE_ARB, clamped to [0, 1].
    CompareFailValue(f32),
    /// GENERATE_MIPMAP (GL 1.4).
    GenerateMipmap(bool),
    /// TEXTURE_BASE_LEVEL (GL 1.2): negative is INVALID_VALUE.
    BaseLevel(i32),
    /// TEXTURE_MAX_LEVEL (GL 1.2): negative is INVALID_VALUE.
    MaxLevel(i32),
    /// TEXTURE_MIN_LOD (GL 1.2): any value, NaN kept (Mesa stores it as given).
    MinLod(f32),
    /// TEXTURE_MAX_LOD (GL 1.2).
    MaxLod(f32),
    /// TEXTURE_LOD_BIAS (GL 1.4, Table 6.16): any value, kept as given.
    LodBias(f32),
    /// TEXTURE_PRIORITY (GL 1.1), clamped to [0, 1]; glPrioritizeTextures sets it too.
    Priority(f32),
    /// TEXTURE_MAX_ANISOTROPY_EXT (EXT_texture_filter_anisotropic): below 1 is
    /// INVALID_VALUE; above MAX_TEXTURE_MAX_ANISOTROPY_EXT it is that maximum.
    MaxAnisotropy(f32),
}

/// MAX_TEXTURE_MAX_ANISOTROPY_EXT: Mesa 22.3.6 llvmpipe's (measured, `tests/c/anisotropy.c`).
pub const MAX_TEXTURE_MAX_ANISOTROPY: f32 = 16.0;

/// A level parameter (BASE_LEVEL, MAX_LEVEL) from glTexParameterf's float as Mesa converts
/// it (measured): rounded to nearest, halves away from zero (1.7 → 2, −0.4 → 0), saturated
/// to the GLint range (3e9 → 2147483647); NaN becomes the most negative GLint, which the
/// parameter then refuses as INVALID_VALUE.
pub fn level_from_float(v: f64) -> i32 {
    if v.is_nan() {
        i32::MIN
    } else {
        v.round().clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i32
    }
}

/// The parameters of one texture object.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TexParams {
    /// GL default: NEAREST_MIPMAP_LINEAR.
    pub min_filter: Filter,
    /// GL default: LINEAR.
    pub mag_filter: Filter,
    /// GL default: REPEAT.
    pub wrap_s: Wrap,
    /// GL default: REPEAT.
    pub wrap_t: Wrap,
    /// GL default: REPEAT.
    pub wrap_r: Wrap,
    /// Clamped to [0, 1]. GL default: (0, 0, 0, 0).
    pub border_color: Vec4,
    /// GL default: NONE.
    pub compare_mode: CompareMode,
    /// GL default: LEQUAL.
    pub compare_func: CompareFunc,
    /// GL default: LUMINANCE.
    pub depth_texture_mode: DepthTextureMode,
    /// The result of a failed compare (ARB_shadow_ambient). GL default: 0.
    pub compare_fail_value: f32,
    /// GL default: FALSE.
    pub generate_mipmap: bool,
    /// GL default: 0.
    pub base_level: i32,
    /// GL default: 1000.
    pub max_level: i32,
    /// GL default: −1000.
    pub min_lod: f32,
    /// GL default: 1000.
    pub max_lod: f32,
    /// The object's level-of-detail bias, added to the unit's (TEXTURE_FILTER_CONTROL's)
    /// and the sum clamped to ±MAX_TEXTURE_LOD_BIAS (GL 1.4 §3.8.8). GL default: 0.
    pub lod_bias: f32,
    /// A residence hint (GL 1.1 §3.8.12), in [0, 1]. GL default: 1.
    pub priority: f32,
    /// The most samples an anisotropic footprint takes (EXT_texture_filter_anisotropic),
    /// in [1, MAX_TEXTURE_MAX_ANISOTROPY]. GL default: 1 (isotropic).
    pub max_anisotropy: f32,
}

impl TexParams {
    pub const DEFAULT: Self = Self {
        min_filter: Filter::NearestMipmapLinear,
        mag_filter: Filter::Linear,
        wrap_s: Wrap::Repeat,
        wrap_t: Wrap::Repeat,
        wrap_r: Wrap::Repeat,
        border_color: Vec4::ZERO,
        compare_mode: CompareMode::None,
        compare_func: CompareFunc::Lequal,
        depth_texture_mode: DepthTextureMode::Luminance,
        compare_fail_value: 0.0,
        generate_mipmap: false,
        base_level: 0,
        max_level: 1000,
        min_lod: -1000.0,
        max_lod: 1000.0,
        lod_bias: 0.0,
        priority: 1.0,
        max_anisotropy: 1.0,
    };

    /// glTexParameter: validates, then sets.
    pub fn set(&mut self, param: TexParam) -> GlResult {
        match param {
            TexParam::MinFilter(f) => self.min_filter = f,
            TexParam::MagFilter(f) => {
                if f.uses_mipmaps() {
                    return Err(GlError::invalid_enum(
                        "MAG_FILTER must be NEAREST or LINEAR",
                    ));
                }
                self.mag_filter = f;
            }
            TexParam::WrapS(w) => self.wrap_s = w,
            TexParam::WrapT(w) => self.wrap_t = w,
            TexParam::WrapR(w) => self.wrap_r = w,
            TexParam::BorderColor(c) => self.border_color = c.clamp(Vec4::ZERO, Vec4::ONE),
            TexParam::CompareMode(m) => self.compare_mode = m,
            TexParam::CompareFunc(f) => self.compare_func = f,
            TexParam::DepthTextureMode(m) => self.depth_texture_mode = m,
            TexParam::CompareFailValue(v) => self.compare_fail_value = v.clamp(0.0, 1.0),
            TexParam::GenerateMipmap(b) => self.generate_mipmap = b,
            TexParam::BaseLevel(l) | TexParam::MaxLevel(l) if l < 0 => {
                return Err(GlError::invalid_value(
                    "TEXTURE_BASE_LEVEL and TEXTURE_MAX_LEVEL must not be negative",
                ));
            }
            TexParam::BaseLevel(l) => self.base_level = l,
            TexParam::MaxLevel(l) => self.max_level = l,
            TexParam::MinLod(v) => self.min_lod = v,
            TexParam::MaxLod(v) => self.max_lod = v,
            TexParam::LodBias(v) => self.lod_bias = v,
            // NaN stays NaN, as Mesa's CLAMP macro leaves it.
            // Clamped to [0, 1]; a NaN priority becomes 0, as Mesa 22.3 reads it back
            // (measured, `tests/c/float_params.c`).
            TexParam::Priority(v) if v.is_nan() => self.priority = 0.0,
            TexParam::Priority(v) => self.priority = v.clamp(0.0, 1.0),
            // Mesa's rule: `v < 1.0` is INVALID_VALUE (a NaN passes it), then
            // MIN2(v, maximum), which is the maximum for a NaN (measured).
            TexParam::MaxAnisotropy(v) if v < 1.0 => {
                return Err(GlError::invalid_value(
                    "TEXTURE_MAX_ANISOTROPY_EXT must be at least 1",
                ));
            }
            TexParam::MaxAnisotropy(v) => {
                self.max_anisotropy = if v < MAX_TEXTURE_MAX_ANISOTROPY {
                    v
                } else {
                    MAX_TEXTURE_MAX_ANISOTROPY
                }
            }
        }
        Ok(())
    }
}

/// Pixel bytes as uploaded, with their external format and type.
#[derive(Debug, Clone, PartialEq)]
pub struct PixelData {
    pub format: PixelFormat,
    pub ty: PixelType,
    pub bytes: Arc<[u8]>,
}

/// One mip level.
#[derive(Debug, Clone, PartialEq)]
pub struct TexLevel {
    pub internal_format: TexFormat,
    pub width: i32,
    /// 1 for 1D textures.
    pub height: i32,
    /// 1 for 1D and 2D textures.
    pub depth: i32,
    /// TEXTURE_BORDER: 0, but in a proxy's level (a real image with a border is refused
    /// here); `width`, `height` (not 1D's) and `depth` (3D's) include it, as GL's do.
    pub border: i32,
    /// The CPU copy of the texels, when known (see the module note).
    pub data: Option<PixelData>,
    /// A compressed level's blocks as given (`compressed`); `data` holds them decoded.
    pub compressed: Option<super::compressed::CompressedImage>,
    /// The internal format as the program named it, when it did (`TexImage::requested`).
    pub requested: Option<u32>,
}

impl TexLevel {
    /// The internal format as GL answers TEXTURE_INTERNAL_FORMAT and Mesa compares levels
    /// (`gl_texture_image::InternalFormat`): the token or component count the program
    /// named (GL_RGBA, GL_RGBA8 and 4 are three formats), a compressed level's format, or
    /// the sized name of a level the layer made.
    pub fn named_format(&self) -> u32 {
        match &self.compressed {
            Some(c) => super::glenum::gl(c.format),
            None => self
                .requested
                .unwrap_or_else(|| super::glenum::gl(self.internal_format)),
        }
    }
}

/// Why a texture is incomplete (GL 1.5 §3.8.10): the first rule it breaks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Incomplete {
    /// The base level (TEXTURE_BASE_LEVEL, 0 by default) was never specified.
    NoBaseLevel,
    /// The base level has a zero width, height or depth.
    EmptyBaseLevel,
    /// TEXTURE_BASE_LEVEL is above TEXTURE_MAX_LEVEL.
    BaseAboveMax,
    /// A mipmap filter, and this level of the chain is not specified.
    MissingLevel(i32),
    /// A mipmap filter, and this level is not half the previous one (rounded down, min 1).
    WrongSize {
        level: i32,
        /// (width, height, depth).
        expected: (i32, i32, i32),
        found: (i32, i32, i32),
    },
    /// A mipmap filter, and this level's internal format is not the base level's.
    FormatDiffers(i32),
    /// A cube map whose faces' base levels differ in size or internal format (GL 1.5
    /// §3.8.10's cube completeness); a face without a base level is `NoBaseLevel`.
    FacesDiffer(CubeFace),
}

/// A texture object: what glBindTexture names.
#[derive(Debug, Clone, PartialEq)]
pub struct TextureObject {
    pub target: TextureTarget,
    pub params: TexParams,
    /// Index = mip level; `None` = level not specified. A cube map's face +X.
    pub levels: Vec<Option<TexLevel>>,
    /// A cube map's other faces' levels, −X, +Y, −Y, +Z, −Z (empty for other targets).
    pub other_faces: [Vec<Option<TexLevel>>; 5],
}

impl TextureObject {
    pub fn new(target: TextureTarget) -> Self {
        Self {
            target,
            params: TexParams::DEFAULT,
            levels: Vec::new(),
            other_faces: Default::default(),
        }
    }

    /// The levels of an image target: a cube face's own, the object's for any other.
    pub fn images(&self, target: TextureTarget) -> &[Option<TexLevel>] {
        match target.face().map(CubeFace::index) {
            Some(i @ 1..) => &self.other_faces[i - 1],
            _ => &self.levels,
        }
    }

    fn images_mut(&mut self, target: TextureTarget) -> &mut Vec<Option<TexLevel>> {
        match target.face().map(CubeFace::index) {
            Some(i @ 1..) => &mut self.other_faces[i - 1],
            _ => &mut self.levels,
        }
    }

    /// A level of an image target (a cube face, or the object's own target).
    pub fn level_in(&self, target: TextureTarget, level: i32) -> Option<&TexLevel> {
        usize::try_from(level)
            .ok()
            .and_then(|l| self.images(target).get(l))
            .and_then(Option::as_ref)
    }

    pub(crate) fn level_in_mut(
        &mut self,
        target: TextureTarget,
        level: i32,
    ) -> Option<&mut TexLevel> {
        usize::try_from(level)
            .ok()
            .and_then(|l| self.images_mut(target).get_mut(l))
            .and_then(Option::as_mut)
    }

    pub(crate) fn set_level_in(&mut self, target: TextureTarget, level: i32, image: TexLevel) {
        let Ok(l) = usize::try_from(level) else {
            return;
        };
        let levels = self.images_mut(target);
        if levels.len() <= l {
            levels.resize(l + 1, None);
        }
        levels[l] = Some(image);
    }

    /// The image targets holding this object's levels: its six faces for a cube map,
    /// its own target otherwise.
    pub fn image_targets(&self) -> Vec<TextureTarget> {
        match self.target {
            TextureTarget::CubeMap | TextureTarget::CubeFace(_) => {
                CubeFace::ALL.map(TextureTarget::CubeFace).to_vec()
            }
            t => vec![t],
        }
    }

    pub fn level(&self, level: i32) -> Option<&TexLevel> {
        usize::try_from(level)
            .ok()
            .and_then(|l| self.levels.get(l))
            .and_then(Option::as_ref)
    }

    /// The base level (TEXTURE_BASE_LEVEL), if specified.
    pub fn base(&self) -> Option<&TexLevel> {
        self.level(self.params.base_level)
    }

    /// The base level's internal format, if specified.
    pub fn format(&self) -> Option<TexFormat> {
        self.base().map(|l| l.internal_format)
    }

    /// The last level a mipmap filter reads, q = min(base + p, MAX_LEVEL) (GL 1.5
    /// §3.8.8), p the log2 of the base level's largest dimension; the base level without
    /// one.
    pub fn last_level(&self) -> i32 {
        self.last_level_in(self.target)
    }

    /// [`TextureObject::last_level`] from one image target's base level (a cube face's).
    pub fn last_level_in(&self, target: TextureTarget) -> i32 {
        let b = self.params.base_level;
        let Some(base) = self.level_in(target, b) else {
            return b;
        };
        let mut size = (base.width, base.height, base.depth);
        let mut p = 0;
        while let Some(next) = half(size) {
            p += 1;
            size = next;
        }
        b.saturating_add(p).min(self.params.max_level.max(b))
    }

    /// Texture completeness (GL 1.5 §3.8.10), from b = TEXTURE_BASE_LEVEL to
    /// q = [`TextureObject::last_level`]:
    /// - the base level b is specified with a non-zero width and height (Mesa:
    ///   "texture width or height = 0"); a default object never given an image is
    ///   incomplete;
    /// - b ≤ TEXTURE_MAX_LEVEL. Mesa 22.3.6 (measured) treats b > MAX_LEVEL as incomplete
    ///   under a mipmap filter only, and under NEAREST or LINEAR samples a mixture of
    ///   levels that no rule gives; the model calls it incomplete under any filter, as
    ///   GL 3.0 §3.9.10 says;
    /// - with a non-mipmap MIN_FILTER (NEAREST, LINEAR) that is all;
    /// - with a mipmap MIN_FILTER, levels b + 1..=q are specified too, each level
    ///   max(1, ⌊previous / 2⌋) in each dimension (so a full chain ends 1×1; a 1D texture
    ///   halves its width only, its height stays 1; a 3D texture halves its depth too),
    ///   all in the base level's internal format and border. Levels outside b..=q are
    ///   ignored.
    ///
    /// Borders: the model accepts border 0 only (`check_image_size`), so they always agree.
    /// A cube map is complete when each face is, and the faces' base levels agree in size
    /// and internal format (cube completeness); q is computed from face +X's base level,
    /// which the others equal when complete.
    ///
    /// An incomplete texture disables its unit: the fragment gets the colour the unit
    /// receives, as if texturing were off for it (§3.8.15) — Mesa's native path does so,
    /// and the emulated path drops the unit from the `ShaderKey`.
    pub fn completeness(&self) -> Result<TexFormat, Incomplete> {
        if self.target != TextureTarget::CubeMap {
            return self.images_completeness(self.target);
        }
        // Cube completeness (GL 1.5 §3.8.10): the six base levels alike in size and
        // internal format (square, as every face image is), and each face complete as a
        // 2D texture under the filter.
        let first = self.images_completeness(TextureTarget::CubeFace(CubeFace::PositiveX))?;
        let size = |t| {
            self.level_in(t, self.params.base_level)
                .map(|l| (l.width, l.height, l.internal_format))
        };
        let base = size(TextureTarget::CubeFace(CubeFace::PositiveX));
        for face in &CubeFace::ALL[1..] {
            let target = TextureTarget::CubeFace(*face);
            self.images_completeness(target)?;
            if size(target) != base {
                return Err(Incomplete::FacesDiffer(*face));
            }
        }
        Ok(first)
    }

    /// Whether a cube map's six base levels are all specified, alike in size and
    /// internal format (the first half of cube completeness).
    pub fn faces_alike(&self) -> bool {
        let base = |f| {
            self.level_in(TextureTarget::CubeFace(f), self.params.base_level)
                .map(|l| (l.width, l.height, l.internal_format))
        };
        let first = base(CubeFace::PositiveX);
        first.is_some() && CubeFace::ALL.iter().all(|f| base(*f) == first)
    }

    /// [`TextureObject::completeness`] of one image target's levels (one face of a cube
    /// map).
    fn images_completeness(&self, target: TextureTarget) -> Result<TexFormat, Incomplete> {
        let base = self
            .level_in(target, self.params.base_level)
            .ok_or(Incomplete::NoBaseLevel)?;
        if base.width <= 0 || base.height <= 0 || base.depth <= 0 {
            return Err(Incomplete::EmptyBaseLevel);
        }
        // Under a filter without mipmaps Mesa's completeness check lets this pass, but
        // what it then samples depends on the texture's history in its state tracker (the
        // base level when the texture was drawn complete before, zero texels when not:
        // measured, README), so no rule follows it; GL 4.6 §8.17 calls it incomplete.
        if self.params.base_level > self.params.max_level {
            return Err(Incomplete::BaseAboveMax);
        }
        if !self.params.min_filter.uses_mipmaps() {
            return Ok(base.internal_format);
        }
        let mut size = (base.width, base.height, base.depth);
        let last = self.last_level_in(target);
        let mut level = self.params.base_level;
        while level < last {
            let Some(next) = half(size) else { break };
            level += 1;
            size = next;
            let l = self
                .level_in(target, level)
                .ok_or(Incomplete::MissingLevel(level))?;
            if (l.width, l.height, l.depth) != size {
                return Err(Incomplete::WrongSize {
                    level,
                    expected: size,
                    found: (l.width, l.height, l.depth),
                });
            }
            // Mesa compares the formats as named: RGBA and RGBA8, or RGBA and 4, differ
            // though they are stored alike (`TexLevel::named_format`).
            if l.internal_format != base.internal_format || l.named_format() != base.named_format()
            {
                return Err(Incomplete::FormatDiffers(level));
            }
        }
        Ok(base.internal_format)
    }

    /// Whether the texture is complete (see [`TextureObject::completeness`]).
    pub fn is_complete(&self) -> bool {
        self.completeness().is_ok()
    }

    /// GENERATE_MIPMAP (GL 1.4 §3.8.8): after the base level (TEXTURE_BASE_LEVEL) changes
    /// (TexImage, CopyTexImage, TexSubImage) while the parameter is TRUE, the levels above
    /// it are replaced by images derived from it ([`TextureObject::generate_levels`]); a
    /// change to another level derives nothing (Mesa, measured). The texels are the GL's to
    /// compute (a box filter is typical), so the model records the levels with unknown
    /// texels.
    pub(crate) fn level_changed(&mut self, level: i32) {
        let target = self.target;
        self.level_changed_in(target, level);
    }

    /// [`TextureObject::level_changed`] for one image target: a cube face's change
    /// derives that face's levels.
    pub(crate) fn level_changed_in(&mut self, target: TextureTarget, level: i32) {
        if self.params.generate_mipmap && level == self.params.base_level {
            self.generate_levels_in(target);
        }
    }

    /// Levels b + 1..=q derived from the base level b (glGenerateMipmap, GENERATE_MIPMAP):
    /// halved sizes down to 1×1 or MAX_LEVEL, the base internal format, texels unknown to
    /// the model.
    pub(crate) fn generate_levels(&mut self) {
        for target in self.image_targets() {
            self.generate_levels_in(target);
        }
    }

    /// [`TextureObject::generate_levels`] of one image target (one cube face).
    fn generate_levels_in(&mut self, target: TextureTarget) {
        let Some(base) = self.level_in(target, self.params.base_level) else {
            return;
        };
        let format = base.internal_format;
        let requested = base.requested;
        let mut size = (base.width, base.height, base.depth);
        if size.0 <= 0 || size.1 <= 0 || size.2 <= 0 {
            return;
        }
        let last = self.last_level_in(target);
        let mut level = self.params.base_level;
        while level < last {
            let Some(next) = half(size) else { break };
            level += 1;
            size = next;
            self.set_level_in(
                target,
                level,
                TexLevel {
                    internal_format: format,
                    width: size.0,
                    height: size.1,
                    depth: size.2,
                    border: 0,
                    data: None,
                    compressed: None,
                    requested,
                },
            );
        }
    }

    pub(crate) fn set_level(&mut self, level: i32, image: TexLevel) {
        let Ok(l) = usize::try_from(level) else {
            return;
        };
        if self.levels.len() <= l {
            self.levels.resize(l + 1, None);
        }
        self.levels[l] = Some(image);
    }

    pub(crate) fn level_mut(&mut self, level: i32) -> Option<&mut TexLevel> {
        usize::try_from(level)
            .ok()
            .and_then(|l| self.levels.get_mut(l))
            .and_then(Option::as_mut)
    }
}

/// The next mip level's size, max(1, ⌊n / 2⌋) in each dimension (§3.8.8), or `None`
/// after the 1×1×1 level.
fn half((w, h, d): (i32, i32, i32)) -> Option<(i32, i32, i32)> {
    (w > 1 || h > 1 || d > 1).then(|| ((w / 2).max(1), (h / 2).max(1), (d / 2).max(1)))
}

/// glTexImage3D's size checks (GL 1.5 §3.8.1, as Mesa orders them): the arguments
/// ([`check_volume_arguments`]), then each of width, height and depth in
/// [0, MAX_3D_TEXTURE_SIZE >> level] (Mesa's `_mesa_legal_texture_dimensions`: level 1
/// holds at most 1024) — all INVALID_VALUE.
pub fn check_volume_size(level: i32, size: [i32; 3], border: i32) -> GlResult {
    check_volume_arguments(level, size, border)?;
    if !volume_fits(level, size) {
        return Err(GlError::invalid_value(
            "width, height and depth must be in [0, MAX_3D_TEXTURE_SIZE >> level]",
        ));
    }
    Ok(())
}

/// glTexImage3D's argument checks: level in [0, log2(MAX_3D_TEXTURE_SIZE)], no size below
/// 0, border 0 (see [`check_image_size`]; a proxy's are [`check_proxy_arguments`]).
pub fn check_volume_arguments(level: i32, size: [i32; 3], border: i32) -> GlResult {
    if !(0..=MAX_3D_TEXTURE_LEVEL).contains(&level) {
        return Err(GlError::invalid_value(
            "level must be in [0, log2(MAX_3D_TEXTURE_SIZE)]",
        ));
    }
    if size.iter().any(|v| *v < 0) {
        return Err(GlError::invalid_value(
            "width, height and depth must be 0 or more",
        ));
    }
    if border != 0 {
        return Err(GlError::invalid_value(
            "border must be 0, or 1 on sides of at least 2 texels (stripped at the call, as Mesa strips it)",
        ));
    }
    Ok(())
}

/// Whether every side of a level-`level` volume is at most MAX_3D_TEXTURE_SIZE >> level
/// (the level already checked to be in range).
pub fn volume_fits(level: i32, size: [i32; 3]) -> bool {
    let max = MAX_3D_TEXTURE_SIZE >> level.clamp(0, MAX_3D_TEXTURE_LEVEL);
    size.iter().all(|v| (0..=max).contains(v))
}

/// The checks a proxy image (PROXY_TEXTURE_1D, _2D, _CUBE_MAP, _3D) raises errors for
/// too (Mesa, measured: `tests/c/proxy_tex.c`), all INVALID_VALUE: level in
/// [0, `max_level`], no size below 0, border 0 or 1 (GL 1.5 §3.8.1: a proxy may have the
/// border a real image here may not, see [`check_image_size`]).
pub fn check_proxy_arguments(level: i32, max_level: i32, size: [i32; 3], border: i32) -> GlResult {
    if !(0..=max_level).contains(&level) {
        return Err(GlError::invalid_value(
            "level must be in [0, log2(MAX_TEXTURE_SIZE)]",
        ));
    }
    if size.iter().any(|v| *v < 0) {
        return Err(GlError::invalid_value("sizes must be 0 or more"));
    }
    if !(0..=1).contains(&border) {
        return Err(GlError::invalid_value("border must be 0 or 1"));
    }
    Ok(())
}

/// Whether each side of a level-`level` proxy image (its border included) is in
/// [2·border, 2·border + (`max` >> level)] (Mesa's `_mesa_legal_texture_dimensions`; the
/// level already checked to be in range).
pub fn proxy_fits(level: i32, max: i32, sides: &[i32], border: i32) -> bool {
    let max = max >> level.clamp(0, 30);
    sides
        .iter()
        .all(|v| (2 * border..=2 * border + max).contains(v))
}

/// The checks TexImage and CopyTexImage share (GL 1.5 §3.8.1, ARB_depth_texture):
/// level in [0, MAX_TEXTURE_LEVEL], sizes in [0, MAX_TEXTURE_SIZE >> level] (Mesa's
/// `_mesa_legal_texture_dimensions`: level 3 holds at most 2048), border 0 (borders are
/// not supported by a core context: INVALID_VALUE).
pub fn check_image_size(level: i32, width: i32, height: i32, border: i32) -> GlResult {
    if !(0..=MAX_TEXTURE_LEVEL).contains(&level) {
        return Err(GlError::invalid_value(
            "level must be in [0, log2(MAX_TEXTURE_SIZE)]",
        ));
    }
    let max = MAX_TEXTURE_SIZE >> level;
    if !(0..=max).contains(&width) || !(0..=max).contains(&height) {
        return Err(GlError::invalid_value(
            "width and height must be in [0, MAX_TEXTURE_SIZE >> level]",
        ));
    }
    if border != 0 {
        return Err(GlError::invalid_value(
            "border must be 0, or 1 on sides of at least 2 texels (stripped at the call, as Mesa strips it)",
        ));
    }
    Ok(())
}

/// A depth internal format needs DEPTH_COMPONENT pixels and the other way round
/// (ARB_depth_texture: INVALID_OPERATION); STENCIL_INDEX data suits no texture format
/// here (INVALID_OPERATION: Mesa 22.3 measured, glTexImage2D and glTexImage3D alike).
pub fn check_format_pair(internal: TexFormat, format: PixelFormat) -> GlResult {
    if format == PixelFormat::StencilIndex {
        return Err(GlError::invalid_operation(
            "STENCIL_INDEX data suits no texture internal format",
        ));
    }
    if internal.is_depth() != (format == PixelFormat::DepthComponent) {
        return Err(GlError::invalid_operation(
            "depth internal formats need DEPTH_COMPONENT pixel data and vice versa",
        ));
    }
    Ok(())
}

/// Copies a `w × h` block of `src` (rows of `w` pixels) into `dst` (rows of `dst_width`
/// pixels) at (x, y); `pixel` bytes per pixel. Bounds are checked by the caller.
pub(crate) fn blit(dst: &mut [u8], dst_width: usize, src: &[u8], rect: [usize; 4], pixel: usize) {
    let [x, y, w, h] = rect;
    for row in 0..h {
        let s = row * w * pixel;
        let d = ((y + row) * dst_width + x) * pixel;
        if let (Some(from), Some(to)) = (src.get(s..s + w * pixel), dst.get_mut(d..d + w * pixel)) {
            to.copy_from_slice(from);
        }
    }
}

#[cfg(test)]
#[path = "texture_volume_tests.rs"]
mod volume_tests;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults() {
        let p = TexParams::DEFAULT;
        assert_eq!(p.min_filter, Filter::NearestMipmapLinear);
        assert_eq!(p.mag_filter, Filter::Linear);
        assert_eq!(p.compare_func, CompareFunc::Lequal);
        assert_eq!(p.depth_texture_mode, DepthTextureMode::Luminance);
    }

    #[test]
    fn mag_filter_rejects_mipmaps_and_keeps_the_state() {
        let mut p = TexParams::DEFAULT;
        let e = p
            .set(TexParam::MagFilter(Filter::LinearMipmapLinear))
            .unwrap_err();
        assert_eq!(e.kind, crate::ff::GlErrorKind::InvalidEnum);
        assert_eq!(p, TexParams::DEFAULT);
    }

    #[test]
    fn fail_value_and_border_are_clamped() {
        let mut p = TexParams::DEFAULT;
        p.set(TexParam::CompareFailValue(1.5)).unwrap();
        p.set(TexParam::BorderColor(Vec4::splat(-1.0))).unwrap();
        assert_eq!(p.compare_fail_value, 1.0);
        assert_eq!(p.border_color, Vec4::ZERO);
    }

    #[test]
    fn depth_format_pairs() {
        assert!(
            check_format_pair(TexFormat::DepthComponent24, PixelFormat::DepthComponent).is_ok()
        );
        assert!(check_format_pair(TexFormat::DepthComponent24, PixelFormat::Rgba).is_err());
        assert!(check_format_pair(TexFormat::Intensity8, PixelFormat::DepthComponent).is_err());
        assert!(
            check_format_pair(TexFormat::Luminance8Alpha8, PixelFormat::LuminanceAlpha).is_ok()
        );
    }

    fn level(format: TexFormat, width: i32, height: i32) -> Option<TexLevel> {
        Some(TexLevel {
            internal_format: format,
            width,
            height,
            depth: 1,
            border: 0,
            data: None,
            compressed: None,
            requested: None,
        })
    }

    fn object(filter: Filter, levels: Vec<Option<TexLevel>>) -> TextureObject {
        let mut t = TextureObject::new(TextureTarget::Texture2D);
        t.params.min_filter = filter;
        t.levels = levels;
        t
    }

    /// GL 1.5 §3.8.10, case by case: (name, MIN_FILTER, levels, verdict).
    #[test]
    fn level_parameters_round_saturate_and_refuse_negatives() {
        assert_eq!(level_from_float(1.7), 2);
        assert_eq!(level_from_float(1.4), 1);
        assert_eq!(level_from_float(-0.4), 0);
        assert_eq!(level_from_float(2.5), 3);
        assert_eq!(level_from_float(3e9), i32::MAX);
        assert_eq!(level_from_float(f64::NAN), i32::MIN);
        let mut p = TexParams::DEFAULT;
        assert!(p.set(TexParam::BaseLevel(-1)).is_err());
        assert!(p
            .set(TexParam::MaxLevel(level_from_float(f64::NAN)))
            .is_err());
        assert_eq!((p.base_level, p.max_level), (0, 1000));
        p.set(TexParam::MaxLod(f32::NAN)).unwrap();
        assert!(p.max_lod.is_nan());
    }

    #[test]
    fn the_level_range_bounds_the_chain() {
        use Filter::*;
        let mut t = TextureObject::new(TextureTarget::Texture2D);
        t.set_level(0, level(TexFormat::Rgba8, 8, 8).unwrap());
        assert_eq!(t.last_level(), 3);
        assert_eq!(t.completeness(), Err(Incomplete::MissingLevel(1)));
        t.params.max_level = 0;
        assert_eq!(t.last_level(), 0);
        assert!(t.is_complete());
        t.params.max_level = 1000;
        t.params.base_level = 1;
        assert_eq!(t.completeness(), Err(Incomplete::NoBaseLevel));
        t.set_level(1, level(TexFormat::Rgba8, 4, 4).unwrap());
        t.params.min_filter = Nearest;
        assert!(t.is_complete());
        t.params.min_filter = NearestMipmapNearest;
        assert_eq!(t.completeness(), Err(Incomplete::MissingLevel(2)));
        t.params.generate_mipmap = true;
        t.level_changed(0);
        assert_eq!(t.completeness(), Err(Incomplete::MissingLevel(2)));
        t.level_changed(1);
        assert_eq!(t.last_level(), 3);
        assert!(t.is_complete());
        t.params.max_level = 0;
        assert_eq!(t.completeness(), Err(Incomplete::BaseAboveMax));
    }

    #[test]
    fn completeness_rules() {
        use Filter::*;
        use TexFormat::{Luminance8, Rgba8};
        let chain = |w: i32, h: i32| {
            let mut v = vec![level(Rgba8, w, h)];
            let (mut w, mut h) = (w, h);
            while w > 1 || h > 1 {
                w = (w / 2).max(1);
                h = (h / 2).max(1);
                v.push(level(Rgba8, w, h));
            }
            v
        };
        let mut wrong_size = chain(8, 8);
        wrong_size[2] = level(Rgba8, 3, 2);
        let mut missing = chain(8, 8);
        missing[1] = None;
        let mut other_format = chain(8, 8);
        other_format[3] = level(Luminance8, 1, 1);
        let mut truncated = chain(8, 8);
        truncated.pop();
        let mut extra = chain(4, 4);
        extra.extend([None, level(Luminance8, 5, 5)]);
        type Case = (&'static str, Filter, Vec<Option<TexLevel>>, Verdict);
        type Verdict = Result<TexFormat, Incomplete>;
        let cases: Vec<Case> = vec![
            ("no image", Nearest, vec![], Err(Incomplete::NoBaseLevel)),
            (
                "no image, mipmaps",
                NearestMipmapLinear,
                vec![],
                Err(Incomplete::NoBaseLevel),
            ),
            (
                "zero width",
                Linear,
                vec![level(Rgba8, 0, 4)],
                Err(Incomplete::EmptyBaseLevel),
            ),
            (
                "level 0, default filter",
                NearestMipmapLinear,
                vec![level(Rgba8, 8, 8)],
                Err(Incomplete::MissingLevel(1)),
            ),
            (
                "level 0, LINEAR",
                Linear,
                vec![level(Rgba8, 8, 8)],
                Ok(Rgba8),
            ),
            (
                "level 0, NEAREST, holes after",
                Nearest,
                vec![level(Rgba8, 8, 8), None, level(Luminance8, 9, 9)],
                Ok(Rgba8),
            ),
            (
                "1×1 alone is a full chain",
                LinearMipmapLinear,
                vec![level(Rgba8, 1, 1)],
                Ok(Rgba8),
            ),
            (
                "full chain 8×8",
                NearestMipmapLinear,
                chain(8, 8),
                Ok(Rgba8),
            ),
            (
                "full chain 8×2 (height stops at 1)",
                LinearMipmapNearest,
                chain(8, 2),
                Ok(Rgba8),
            ),
            (
                "full chain 5×3 (rounded down)",
                NearestMipmapNearest,
                chain(5, 3),
                Ok(Rgba8),
            ),
            (
                "wrong size",
                NearestMipmapLinear,
                wrong_size,
                Err(Incomplete::WrongSize {
                    level: 2,
                    expected: (2, 2, 1),
                    found: (3, 2, 1),
                }),
            ),
            (
                "missing level",
                NearestMipmapLinear,
                missing,
                Err(Incomplete::MissingLevel(1)),
            ),
            (
                "format differs",
                NearestMipmapLinear,
                other_format,
                Err(Incomplete::FormatDiffers(3)),
            ),
            (
                "stops before 1×1",
                NearestMipmapLinear,
                truncated,
                Err(Incomplete::MissingLevel(3)),
            ),
            (
                "levels after p are ignored",
                NearestMipmapLinear,
                extra,
                Ok(Rgba8),
            ),
        ];
        for (name, filter, levels, verdict) in cases {
            assert_eq!(object(filter, levels).completeness(), verdict, "{name}");
        }
    }

    /// A 1D texture halves its width only: 8×1, 4×1, 2×1, 1×1.
    #[test]
    fn one_d_chain() {
        let mut t = TextureObject::new(TextureTarget::Texture1D);
        t.levels = [8, 4, 2, 1].map(|w| level(TexFormat::Rgb8, w, 1)).to_vec();
        assert!(t.is_complete());
        t.levels[2] = level(TexFormat::Rgb8, 2, 2);
        assert!(!t.is_complete());
    }

    /// GENERATE_MIPMAP: a base level set while it is TRUE brings the whole chain.
    #[test]
    fn generated_mipmaps_complete_the_chain() {
        let mut t = object(Filter::LinearMipmapLinear, vec![]);
        t.set_level(0, level(TexFormat::Rgba8, 6, 3).unwrap());
        t.level_changed(0);
        assert_eq!(t.completeness(), Err(Incomplete::MissingLevel(1)));
        t.params.generate_mipmap = true;
        t.level_changed(0);
        assert_eq!(t.completeness(), Ok(TexFormat::Rgba8));
        let sizes: Vec<_> = t
            .levels
            .iter()
            .flatten()
            .map(|l| (l.width, l.height))
            .collect();
        assert_eq!(sizes, [(6, 3), (3, 1), (1, 1)]);
    }

    /// Cube completeness (GL 1.5 §3.8.10): six faces, alike in size and format, each
    /// mipmap-complete under a mipmap filter; GENERATE_MIPMAP derives a face's own levels.
    #[test]
    fn cube_completeness_needs_six_alike_faces() {
        let face = |f| TextureTarget::CubeFace(f);
        let mut t = TextureObject::new(TextureTarget::CubeMap);
        t.params.min_filter = Filter::Nearest;
        for f in &CubeFace::ALL[..5] {
            t.set_level_in(face(*f), 0, level(TexFormat::Rgba8, 4, 4).unwrap());
        }
        assert_eq!(t.completeness(), Err(Incomplete::NoBaseLevel));
        assert!(!t.faces_alike());
        t.set_level_in(
            face(CubeFace::NegativeZ),
            0,
            level(TexFormat::Rgba8, 2, 2).unwrap(),
        );
        assert_eq!(
            t.completeness(),
            Err(Incomplete::FacesDiffer(CubeFace::NegativeZ))
        );
        t.set_level_in(
            face(CubeFace::NegativeZ),
            0,
            level(TexFormat::Luminance8, 4, 4).unwrap(),
        );
        assert_eq!(
            t.completeness(),
            Err(Incomplete::FacesDiffer(CubeFace::NegativeZ))
        );
        t.set_level_in(
            face(CubeFace::NegativeZ),
            0,
            level(TexFormat::Rgba8, 4, 4).unwrap(),
        );
        assert_eq!(t.completeness(), Ok(TexFormat::Rgba8));
        assert_eq!(t.level_in(face(CubeFace::PositiveX), 0), t.level(0));
        t.params.min_filter = Filter::LinearMipmapNearest;
        assert_eq!(t.completeness(), Err(Incomplete::MissingLevel(1)));
        t.params.generate_mipmap = true;
        t.level_changed_in(face(CubeFace::PositiveY), 0);
        assert_eq!(
            t.level_in(face(CubeFace::PositiveY), 2).map(|l| l.width),
            Some(1)
        );
        assert_eq!(t.completeness(), Err(Incomplete::MissingLevel(1)));
        t.generate_levels();
        assert_eq!(t.completeness(), Ok(TexFormat::Rgba8));
    }

    #[test]
    fn face_targets_bind_as_their_cube_and_rank_first() {
        assert_eq!(
            TextureTarget::CubeFace(CubeFace::NegativeY).binding(),
            TextureTarget::CubeMap
        );
        assert_eq!(TextureTarget::Texture3D.binding(), TextureTarget::Texture3D);
        assert_eq!(TextureTarget::ALL.last(), Some(&TextureTarget::CubeMap));
        assert_eq!(TextureTarget::CubeMap.max_level(), MAX_TEXTURE_LEVEL);
    }

    #[test]
    fn blit_patches_rows() {
        let mut dst = vec![0u8; 4 * 3];
        blit(&mut dst, 4, &[1, 2, 3, 4], [1, 1, 2, 2], 1);
        assert_eq!(dst, [0, 0, 0, 0, 0, 1, 2, 0, 0, 3, 4, 0]);
    }
}
