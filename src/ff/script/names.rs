//! GL token names of our enums: the only place the script layer spells `GL_…` enumerants.
//!
//! Each table lists one name per value; a value may appear again under an alias (accepted
//! when parsing, never printed: the first entry is the printed one). Indexed families
//! (GL_LIGHTi, GL_TEXTUREi, GL_COMBINERi_NV) are handled by [`Family`], with `GL_LIGHT0 + n`
//! for indices beyond the named tokens, as C allows.

use crate::ff::*;

/// An enum with GL token names.
pub trait GlName: Copy + PartialEq + 'static {
    const TABLE: &'static [(&'static str, Self)];

    /// The printed name, if the value has one.
    fn gl_name(self) -> Option<&'static str> {
        Self::TABLE
            .iter()
            .find(|(_, v)| *v == self)
            .map(|(n, _)| *n)
    }

    fn from_gl_name(name: &str) -> Option<Self> {
        Self::TABLE
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, v)| *v)
    }

    fn names() -> Vec<&'static str> {
        Self::TABLE.iter().map(|(n, _)| *n).collect()
    }
}

macro_rules! gl_names {
    ($ty:ty { $($name:literal => $val:expr),* $(,)? }) => {
        impl GlName for $ty {
            const TABLE: &'static [(&'static str, Self)] = &[$(($name, $val)),*];
        }
    };
}

gl_names!(MatrixMode {
    "GL_MODELVIEW" => MatrixMode::Modelview,
    "GL_PROJECTION" => MatrixMode::Projection,
    "GL_TEXTURE" => MatrixMode::Texture,
});

gl_names!(Capability {
    "GL_LIGHTING" => Capability::Lighting,
    "GL_COLOR_MATERIAL" => Capability::ColorMaterial,
    "GL_NORMALIZE" => Capability::Normalize,
    "GL_RESCALE_NORMAL" => Capability::RescaleNormal,
    "GL_TEXTURE_1D" => Capability::Texture1D,
    "GL_TEXTURE_2D" => Capability::Texture2D,
    "GL_TEXTURE_GEN_S" => Capability::TextureGen(TexCoord::S),
    "GL_TEXTURE_GEN_T" => Capability::TextureGen(TexCoord::T),
    "GL_TEXTURE_GEN_R" => Capability::TextureGen(TexCoord::R),
    "GL_TEXTURE_GEN_Q" => Capability::TextureGen(TexCoord::Q),
    "GL_ALPHA_TEST" => Capability::AlphaTest,
    "GL_DEPTH_TEST" => Capability::DepthTest,
    "GL_STENCIL_TEST" => Capability::StencilTest,
    "GL_BLEND" => Capability::Blend,
    "GL_CULL_FACE" => Capability::CullFace,
    "GL_POLYGON_OFFSET_FILL" => Capability::PolygonOffsetFill,
    "GL_POLYGON_OFFSET_LINE" => Capability::PolygonOffsetLine,
    "GL_POLYGON_OFFSET_POINT" => Capability::PolygonOffsetPoint,
    "GL_REGISTER_COMBINERS_NV" => Capability::RegisterCombiners,
});

gl_names!(CompareFunc {
    "GL_NEVER" => CompareFunc::Never,
    "GL_LESS" => CompareFunc::Less,
    "GL_EQUAL" => CompareFunc::Equal,
    "GL_LEQUAL" => CompareFunc::Lequal,
    "GL_GREATER" => CompareFunc::Greater,
    "GL_NOTEQUAL" => CompareFunc::Notequal,
    "GL_GEQUAL" => CompareFunc::Gequal,
    "GL_ALWAYS" => CompareFunc::Always,
});

gl_names!(StencilOp {
    "GL_KEEP" => StencilOp::Keep,
    "GL_ZERO" => StencilOp::Zero,
    "GL_REPLACE" => StencilOp::Replace,
    "GL_INCR" => StencilOp::Incr,
    "GL_DECR" => StencilOp::Decr,
    "GL_INVERT" => StencilOp::Invert,
    "GL_INCR_WRAP" => StencilOp::IncrWrap,
    "GL_DECR_WRAP" => StencilOp::DecrWrap,
});

gl_names!(BlendFactor {
    "GL_ZERO" => BlendFactor::Zero,
    "GL_ONE" => BlendFactor::One,
    "GL_SRC_COLOR" => BlendFactor::SrcColor,
    "GL_ONE_MINUS_SRC_COLOR" => BlendFactor::OneMinusSrcColor,
    "GL_DST_COLOR" => BlendFactor::DstColor,
    "GL_ONE_MINUS_DST_COLOR" => BlendFactor::OneMinusDstColor,
    "GL_SRC_ALPHA" => BlendFactor::SrcAlpha,
    "GL_ONE_MINUS_SRC_ALPHA" => BlendFactor::OneMinusSrcAlpha,
    "GL_DST_ALPHA" => BlendFactor::DstAlpha,
    "GL_ONE_MINUS_DST_ALPHA" => BlendFactor::OneMinusDstAlpha,
    "GL_SRC_ALPHA_SATURATE" => BlendFactor::SrcAlphaSaturate,
});

gl_names!(Face {
    "GL_FRONT" => Face::Front,
    "GL_BACK" => Face::Back,
    "GL_FRONT_AND_BACK" => Face::FrontAndBack,
});

gl_names!(FrontFace { "GL_CW" => FrontFace::Cw, "GL_CCW" => FrontFace::Ccw });

gl_names!(PolygonMode {
    "GL_POINT" => PolygonMode::Point,
    "GL_LINE" => PolygonMode::Line,
    "GL_FILL" => PolygonMode::Fill,
});

gl_names!(ShadeModel { "GL_FLAT" => ShadeModel::Flat, "GL_SMOOTH" => ShadeModel::Smooth });

gl_names!(Primitive {
    "GL_POINTS" => Primitive::Points,
    "GL_LINES" => Primitive::Lines,
    "GL_LINE_STRIP" => Primitive::LineStrip,
    "GL_LINE_LOOP" => Primitive::LineLoop,
    "GL_TRIANGLES" => Primitive::Triangles,
    "GL_TRIANGLE_STRIP" => Primitive::TriangleStrip,
    "GL_TRIANGLE_FAN" => Primitive::TriangleFan,
    "GL_QUADS" => Primitive::Quads,
    "GL_QUAD_STRIP" => Primitive::QuadStrip,
    "GL_POLYGON" => Primitive::Polygon,
});

gl_names!(ColorMaterialMode {
    "GL_AMBIENT" => ColorMaterialMode::Ambient,
    "GL_DIFFUSE" => ColorMaterialMode::Diffuse,
    "GL_SPECULAR" => ColorMaterialMode::Specular,
    "GL_EMISSION" => ColorMaterialMode::Emission,
    "GL_AMBIENT_AND_DIFFUSE" => ColorMaterialMode::AmbientAndDiffuse,
});

gl_names!(ColorControl {
    "GL_SINGLE_COLOR" => ColorControl::SingleColor,
    "GL_SEPARATE_SPECULAR_COLOR" => ColorControl::SeparateSpecularColor,
});

gl_names!(TextureTarget {
    "GL_TEXTURE_1D" => TextureTarget::Texture1D,
    "GL_TEXTURE_2D" => TextureTarget::Texture2D,
});

// Unsized names of the era are accepted as aliases of the sized formats they give.
gl_names!(TexFormat {
    "GL_RGBA8" => TexFormat::Rgba8,
    "GL_RGB8" => TexFormat::Rgb8,
    "GL_LUMINANCE8" => TexFormat::Luminance8,
    "GL_INTENSITY8" => TexFormat::Intensity8,
    "GL_ALPHA8" => TexFormat::Alpha8,
    "GL_LUMINANCE8_ALPHA8" => TexFormat::Luminance8Alpha8,
    "GL_DEPTH_COMPONENT16" => TexFormat::DepthComponent16,
    "GL_DEPTH_COMPONENT24" => TexFormat::DepthComponent24,
    "GL_DEPTH_COMPONENT32F" => TexFormat::DepthComponent32F,
    "GL_RGBA" => TexFormat::Rgba8,
    "GL_RGB" => TexFormat::Rgb8,
    "GL_LUMINANCE" => TexFormat::Luminance8,
    "GL_INTENSITY" => TexFormat::Intensity8,
    "GL_ALPHA" => TexFormat::Alpha8,
    "GL_LUMINANCE_ALPHA" => TexFormat::Luminance8Alpha8,
    "GL_DEPTH_COMPONENT" => TexFormat::DepthComponent24,
});

gl_names!(PixelFormat {
    "GL_RGBA" => PixelFormat::Rgba,
    "GL_RGB" => PixelFormat::Rgb,
    "GL_LUMINANCE" => PixelFormat::Luminance,
    "GL_LUMINANCE_ALPHA" => PixelFormat::LuminanceAlpha,
    "GL_ALPHA" => PixelFormat::Alpha,
    "GL_DEPTH_COMPONENT" => PixelFormat::DepthComponent,
    "GL_STENCIL_INDEX" => PixelFormat::StencilIndex,
});

gl_names!(PixelType {
    "GL_UNSIGNED_BYTE" => PixelType::UnsignedByte,
    "GL_UNSIGNED_SHORT" => PixelType::UnsignedShort,
    "GL_UNSIGNED_INT" => PixelType::UnsignedInt,
    "GL_FLOAT" => PixelType::Float,
});

gl_names!(Filter {
    "GL_NEAREST" => Filter::Nearest,
    "GL_LINEAR" => Filter::Linear,
    "GL_NEAREST_MIPMAP_NEAREST" => Filter::NearestMipmapNearest,
    "GL_LINEAR_MIPMAP_NEAREST" => Filter::LinearMipmapNearest,
    "GL_NEAREST_MIPMAP_LINEAR" => Filter::NearestMipmapLinear,
    "GL_LINEAR_MIPMAP_LINEAR" => Filter::LinearMipmapLinear,
});

gl_names!(Wrap {
    "GL_REPEAT" => Wrap::Repeat,
    "GL_CLAMP" => Wrap::Clamp,
    "GL_CLAMP_TO_EDGE" => Wrap::ClampToEdge,
    "GL_CLAMP_TO_BORDER" => Wrap::ClampToBorder,
});

gl_names!(CompareMode {
    "GL_NONE" => CompareMode::None,
    "GL_COMPARE_R_TO_TEXTURE" => CompareMode::CompareRToTexture,
    "GL_COMPARE_R_TO_TEXTURE_ARB" => CompareMode::CompareRToTexture,
});

gl_names!(DepthTextureMode {
    "GL_LUMINANCE" => DepthTextureMode::Luminance,
    "GL_INTENSITY" => DepthTextureMode::Intensity,
    "GL_ALPHA" => DepthTextureMode::Alpha,
});

gl_names!(TexCoord {
    "GL_S" => TexCoord::S,
    "GL_T" => TexCoord::T,
    "GL_R" => TexCoord::R,
    "GL_Q" => TexCoord::Q,
});

gl_names!(TexGenMode {
    "GL_OBJECT_LINEAR" => TexGenMode::ObjectLinear,
    "GL_EYE_LINEAR" => TexGenMode::EyeLinear,
    "GL_SPHERE_MAP" => TexGenMode::SphereMap,
});

gl_names!(TexEnvMode {
    "GL_MODULATE" => TexEnvMode::Modulate,
    "GL_REPLACE" => TexEnvMode::Replace,
    "GL_DECAL" => TexEnvMode::Decal,
    "GL_BLEND" => TexEnvMode::Blend,
    "GL_ADD" => TexEnvMode::Add,
    "GL_COMBINE" => TexEnvMode::Combine,
});

gl_names!(CombineFunc {
    "GL_REPLACE" => CombineFunc::Replace,
    "GL_MODULATE" => CombineFunc::Modulate,
    "GL_ADD" => CombineFunc::Add,
    "GL_ADD_SIGNED" => CombineFunc::AddSigned,
    "GL_INTERPOLATE" => CombineFunc::Interpolate,
    "GL_SUBTRACT" => CombineFunc::Subtract,
    "GL_DOT3_RGB" => CombineFunc::Dot3Rgb,
    "GL_DOT3_RGBA" => CombineFunc::Dot3Rgba,
});

// Without TEXTUREi (a `Family`).
gl_names!(CombineSource {
    "GL_TEXTURE" => CombineSource::Texture,
    "GL_CONSTANT" => CombineSource::Constant,
    "GL_PRIMARY_COLOR" => CombineSource::PrimaryColor,
    "GL_PREVIOUS" => CombineSource::Previous,
});

gl_names!(CombineOperand {
    "GL_SRC_COLOR" => CombineOperand::SrcColor,
    "GL_ONE_MINUS_SRC_COLOR" => CombineOperand::OneMinusSrcColor,
    "GL_SRC_ALPHA" => CombineOperand::SrcAlpha,
    "GL_ONE_MINUS_SRC_ALPHA" => CombineOperand::OneMinusSrcAlpha,
});

// Without TEXTUREi_ARB (a `Family`).
gl_names!(Register {
    "GL_ZERO" => Register::Zero,
    "GL_CONSTANT_COLOR0_NV" => Register::ConstantColor0,
    "GL_CONSTANT_COLOR1_NV" => Register::ConstantColor1,
    "GL_FOG" => Register::Fog,
    "GL_PRIMARY_COLOR_NV" => Register::PrimaryColor,
    "GL_SECONDARY_COLOR_NV" => Register::SecondaryColor,
    "GL_SPARE0_NV" => Register::Spare0,
    "GL_SPARE1_NV" => Register::Spare1,
    "GL_DISCARD_NV" => Register::Discard,
    "GL_E_TIMES_F_NV" => Register::ETimesF,
    "GL_SPARE0_PLUS_SECONDARY_COLOR_NV" => Register::Spare0PlusSecondaryColor,
});

gl_names!(Portion { "GL_RGB" => Portion::Rgb, "GL_ALPHA" => Portion::Alpha });

gl_names!(ComponentUsage {
    "GL_RGB" => ComponentUsage::Rgb,
    "GL_ALPHA" => ComponentUsage::Alpha,
    "GL_BLUE" => ComponentUsage::Blue,
});

gl_names!(Variable {
    "GL_VARIABLE_A_NV" => Variable::A,
    "GL_VARIABLE_B_NV" => Variable::B,
    "GL_VARIABLE_C_NV" => Variable::C,
    "GL_VARIABLE_D_NV" => Variable::D,
});

gl_names!(FinalVariable {
    "GL_VARIABLE_A_NV" => FinalVariable::A,
    "GL_VARIABLE_B_NV" => FinalVariable::B,
    "GL_VARIABLE_C_NV" => FinalVariable::C,
    "GL_VARIABLE_D_NV" => FinalVariable::D,
    "GL_VARIABLE_E_NV" => FinalVariable::E,
    "GL_VARIABLE_F_NV" => FinalVariable::F,
    "GL_VARIABLE_G_NV" => FinalVariable::G,
});

gl_names!(Mapping {
    "GL_UNSIGNED_IDENTITY_NV" => Mapping::UnsignedIdentity,
    "GL_UNSIGNED_INVERT_NV" => Mapping::UnsignedInvert,
    "GL_EXPAND_NORMAL_NV" => Mapping::ExpandNormal,
    "GL_EXPAND_NEGATE_NV" => Mapping::ExpandNegate,
    "GL_HALF_BIAS_NORMAL_NV" => Mapping::HalfBiasNormal,
    "GL_HALF_BIAS_NEGATE_NV" => Mapping::HalfBiasNegate,
    "GL_SIGNED_IDENTITY_NV" => Mapping::SignedIdentity,
    "GL_SIGNED_NEGATE_NV" => Mapping::SignedNegate,
});

gl_names!(CombinerScale {
    "GL_NONE" => CombinerScale::None,
    "GL_SCALE_BY_TWO_NV" => CombinerScale::ByTwo,
    "GL_SCALE_BY_FOUR_NV" => CombinerScale::ByFour,
    "GL_SCALE_BY_ONE_HALF_NV" => CombinerScale::ByOneHalf,
});

gl_names!(CombinerBias {
    "GL_NONE" => CombinerBias::None,
    "GL_BIAS_BY_NEGATIVE_ONE_HALF_NV" => CombinerBias::ByNegativeOneHalf,
});

gl_names!(Product { "GL_FALSE" => Product::Componentwise, "GL_TRUE" => Product::Dot });

gl_names!(SumOrMux { "GL_FALSE" => SumOrMux::Sum, "GL_TRUE" => SumOrMux::Mux });

gl_names!(bool { "GL_FALSE" => false, "GL_TRUE" => true });

/// Indexed token families: `GL_LIGHT0`…, `GL_TEXTURE0`…, `GL_COMBINER0_NV`….
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    Light,
    Texture,
    Combiner,
}

impl Family {
    /// (prefix, suffix, number of named tokens).
    fn parts(self) -> (&'static str, &'static str, u32) {
        match self {
            Family::Light => ("GL_LIGHT", "", 8),
            Family::Texture => ("GL_TEXTURE", "", 32),
            Family::Combiner => ("GL_COMBINER", "_NV", 8),
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

    pub fn example(self) -> &'static str {
        match self {
            Family::Light => "GL_LIGHT0..GL_LIGHT7",
            Family::Texture => "GL_TEXTURE0..GL_TEXTURE31",
            Family::Combiner => "GL_COMBINER0_NV..GL_COMBINER7_NV",
        }
    }
}

/// Every call the script reads, for "unknown call" errors.
pub const CALLS: &[&str] = &[
    "glMatrixMode",
    "glLoadIdentity",
    "glLoadMatrixf",
    "glMultMatrixf",
    "glPushMatrix",
    "glPopMatrix",
    "glTranslatef",
    "glRotatef",
    "glScalef",
    "glFrustum",
    "glOrtho",
    "glViewport",
    "glDepthRange",
    "glEnable",
    "glDisable",
    "glColor3f",
    "glColor4f",
    "glNormal3f",
    "glTexCoord1f",
    "glTexCoord2f",
    "glTexCoord3f",
    "glTexCoord4f",
    "glMultiTexCoord1f",
    "glMultiTexCoord2f",
    "glMultiTexCoord3f",
    "glMultiTexCoord4f",
    "glVertex2f",
    "glVertex3f",
    "glVertex4f",
    "glBegin",
    "glEnd",
    "glLightf",
    "glLighti",
    "glLightfv",
    "glLightModelf",
    "glLightModeli",
    "glLightModelfv",
    "glMaterialf",
    "glMaterialfv",
    "glColorMaterial",
    "glShadeModel",
    "glActiveTexture",
    "glBindTexture",
    "glTexImage1D",
    "glTexImage2D",
    "glTexSubImage2D",
    "glCopyTexImage2D",
    "glTexParameteri",
    "glTexParameterf",
    "glTexParameterfv",
    "glTexGeni",
    "glTexGenfv",
    "glTexEnvi",
    "glTexEnvf",
    "glTexEnvfv",
    "glCombinerParameteriNV",
    "glCombinerParameterfvNV",
    "glCombinerInputNV",
    "glCombinerOutputNV",
    "glFinalCombinerInputNV",
    "glAlphaFunc",
    "glDepthFunc",
    "glDepthMask",
    "glStencilFunc",
    "glStencilOp",
    "glStencilMask",
    "glBlendFunc",
    "glColorMask",
    "glPolygonOffset",
    "glPolygonMode",
    "glCullFace",
    "glFrontFace",
    "glLineWidth",
    "glPointSize",
    "glClear",
    "glClearColor",
    "glClearDepth",
    "glClearStencil",
    "glReadPixels",
];

/// Levenshtein distance, to list the closest names first in errors.
pub fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != *cb);
            cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}

/// `names`, closest to `found` first (stable for ties), without duplicates.
pub fn ranked(found: &str, names: &[&'static str]) -> Vec<&'static str> {
    let mut v: Vec<&'static str> = Vec::new();
    for n in names {
        if !v.contains(n) {
            v.push(n);
        }
    }
    v.sort_by_key(|n| distance(found, n));
    v
}
