//! Every GL-like operation, listed once, as data.
//!
//! Techniques emit `Command`s; the emulated and native pipelines execute them;
//! [`FixedState::apply`](super::FixedState::apply) folds them into the state model;
//! [`script`](super::script) reads and prints them as the GL 1.x calls of the era. Values
//! are typed: an enum the GL entry point would reject with INVALID_ENUM cannot be written
//! here unless the rejection depends on the state or on another argument (e.g. DOT3 for
//! COMBINE_ALPHA, light 9, TEXTURE12); the script parser rejects the rest with the valid
//! alternatives.

use std::sync::Arc;

use glam::{Mat4, Vec3, Vec4};

use crate::vocab::DepthRule;

use super::api::Entry;
use super::error::GlErrorKind;

use super::accum::AccumOp;
use super::attrib::AttribMask;
use super::blit::Blit;
use super::combiners::{
    CombinerInput, CombinerOutput, CombinerParam, FinalVariable, Portion, Variable,
};
use super::fog::FogParam;
use super::fragment::{
    BlendEquation, BlendFactor, ClearMask, ColorMask, CompareFunc, Face, FrontFace, HintMode,
    HintTarget, LogicOp, PolygonMode, ScissorBox, ShadeModel, StencilOp, Viewport,
};
use super::framebuffer::{AttachmentPoint, ColorBuffer, FramebufferTarget, RenderbufferFormat};
use super::geometry::Geometry;
use super::light::{ColorMaterialMode, LightModelParam, LightParam, MaterialParam};
use super::matrix::{MatrixMode, ViewVolume};
use super::pixels::{Bitmap, CopyPixels, DrawPixels, PixelTransferParam};
use super::point::PointParam;
use super::stipple::{LineStipple, PolygonStipple};
use super::texenv::TexEnvParam;
use super::texgen::{TexCoord, TexGenParam};
use super::texture::{CubeFace, PixelFormat, PixelType, TexFormat, TexParam, TextureTarget};

/// glEnable / glDisable capabilities.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Capability {
    Lighting,
    /// LIGHTi; INVALID_ENUM for i ≥ MAX_LIGHTS.
    Light(u8),
    ColorMaterial,
    Normalize,
    RescaleNormal,
    /// Of the active texture unit.
    Texture1D,
    /// Of the active texture unit.
    Texture2D,
    /// Of the active texture unit (GL 1.2).
    Texture3D,
    /// TEXTURE_CUBE_MAP of the active texture unit (GL 1.3); a face's name is
    /// INVALID_ENUM.
    TextureCubeMap,
    /// TEXTURE_GEN_S/T/R/Q of the active texture unit.
    TextureGen(TexCoord),
    AlphaTest,
    DepthTest,
    StencilTest,
    Blend,
    CullFace,
    PolygonOffsetFill,
    PolygonOffsetLine,
    PolygonOffsetPoint,
    /// REGISTER_COMBINERS_NV.
    RegisterCombiners,
    /// FOG (GL 1.5 §3.10).
    Fog,
    /// SCISSOR_TEST (§4.1.2).
    ScissorTest,
    /// CLIP_PLANEi (§2.12); INVALID_ENUM for i ≥ MAX_CLIP_PLANES.
    ClipPlane(u8),
    /// COLOR_LOGIC_OP (§4.1.10).
    ColorLogicOp,
    /// DITHER (§4.1.9); enabled initially. State only.
    Dither,
    /// INDEX_LOGIC_OP (= GL 1.0's LOGIC_OP): colour-index mode only; recorded, no effect
    /// in RGBA.
    IndexLogicOp,
    /// POLYGON_STIPPLE (§3.5.2).
    PolygonStipple,
    /// LINE_STIPPLE (§3.4.2).
    LineStipple,
    /// POINT_SMOOTH (§3.3): antialiased points.
    PointSmooth,
    /// POINT_SPRITE (ARB_point_sprite): points drawn as textured squares (`point`).
    PointSprite,
    /// LINE_SMOOTH (§3.4.2): antialiased lines.
    LineSmooth,
    /// POLYGON_SMOOTH (§3.5.4): antialiased polygons.
    PolygonSmooth,
    /// COLOR_SUM (GL 1.4 §3.9): adds the secondary colour after texturing when lighting
    /// is off.
    ColorSum,
    /// MULTISAMPLE (GL 1.3 §3.2.1): no effect on the single-sample buffers the layer has;
    /// state only, and exact.
    Multisample,
    /// SAMPLE_COVERAGE, SAMPLE_ALPHA_TO_COVERAGE, SAMPLE_ALPHA_TO_ONE (GL 1.3 §3.2.1):
    /// state only, likewise (`sample_coverage`).
    SampleCoverage,
    SampleAlphaToCoverage,
    SampleAlphaToOne,
    /// SAMPLE_COVERAGE_INVERT as a capability: Mesa 22.3 takes it in glEnable, glDisable and
    /// glIsEnabled as the flag glSampleCoverage sets (measured; GL 1.3 makes it a value
    /// only); ENABLE_BIT does not save it there, MULTISAMPLE_BIT does with the value.
    SampleCoverageInvert,
    /// AUTO_NORMAL (§5.1): state only, evaluators being left out.
    AutoNormal,
    /// MAP1_* and MAP2_* (§5.1): state only, likewise.
    Map(EvalMap),
}

/// One evaluator map an enable names: MAPn_<attribute>.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct EvalMap {
    pub dims: MapDims,
    pub attribute: MapAttribute,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MapDims {
    One,
    Two,
}

/// What a map evaluates, in the order of GL 1.5 Table 5.1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MapAttribute {
    Vertex3,
    Vertex4,
    Index,
    Color4,
    Normal,
    TextureCoord1,
    TextureCoord2,
    TextureCoord3,
    TextureCoord4,
}

impl MapAttribute {
    /// Every attribute, in declaration order (its bit position).
    pub const ALL: [MapAttribute; 9] = [
        MapAttribute::Vertex3,
        MapAttribute::Vertex4,
        MapAttribute::Index,
        MapAttribute::Color4,
        MapAttribute::Normal,
        MapAttribute::TextureCoord1,
        MapAttribute::TextureCoord2,
        MapAttribute::TextureCoord3,
        MapAttribute::TextureCoord4,
    ];
}

impl EvalMap {
    /// Every map, MAP1_* then MAP2_*.
    pub fn all() -> impl Iterator<Item = EvalMap> {
        [MapDims::One, MapDims::Two].into_iter().flat_map(|dims| {
            MapAttribute::ALL
                .into_iter()
                .map(move |attribute| EvalMap { dims, attribute })
        })
    }

    /// Its bit in [`EvalEnables::maps`].
    pub fn bit(self) -> u32 {
        let dims = match self.dims {
            MapDims::One => 0,
            MapDims::Two => 9,
        };
        1 << (dims + self.attribute as u32)
    }
}

/// The evaluator enables (Table 6.28): AUTO_NORMAL and one bit per map. GL default: all
/// off. Kept and answered; nothing is evaluated (`glMap*`, `glEvalCoord*` are left out).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct EvalEnables {
    pub auto_normal: bool,
    pub maps: u32,
}

/// glTexImage1D / glTexImage2D / glTexImage3D.
#[derive(Debug, Clone, PartialEq)]
pub struct TexImage {
    pub target: TextureTarget,
    pub level: i32,
    pub internal_format: TexFormat,
    /// The internal format as the program named it (GL_RGBA, 3, GL_RGB5), which
    /// TEXTURE_INTERNAL_FORMAT answers as Mesa does; `None`: the sized format's name.
    pub requested: Option<u32>,
    pub width: i32,
    /// 1 for TEXTURE_1D (glTexImage1D has no height).
    pub height: i32,
    /// 1 for TEXTURE_1D and TEXTURE_2D; for TEXTURE_3D the data holds `depth` images of
    /// `height` rows, the first image (r = 0) first.
    pub depth: i32,
    pub border: i32,
    pub format: PixelFormat,
    pub ty: PixelType,
    pub data: TexData,
}

/// The client memory a glTexImage call reads: tightly packed rows, bottom row first.
#[derive(Debug, Clone, PartialEq)]
pub enum TexData {
    /// NULL: storage only, texels undefined.
    Null,
    /// Bytes given with the command.
    Bytes(Arc<[u8]>),
    /// The bytes an earlier `ReadPixels` left in this readback slot — the era's
    /// glReadPixels(…, buf); glTexImage2D(…, buf) round trip through client memory. The
    /// pipeline that executes the command substitutes the slot's bytes before anything
    /// else sees it (a missing slot stops execution); the state model alone, which has no
    /// readbacks, records the level with unknown texels.
    Readback(u32),
    /// The depth values an earlier glReadPixels(…, DEPTH_COMPONENT, FLOAT, buf) left in
    /// `slot`, converted on the CPU — client code between the two calls — to one `ty`
    /// (UNSIGNED_BYTE or UNSIGNED_SHORT) per value by `rule`. What a program does when it
    /// will not leave the float-to-integer rule to the driver. A script writes it as
    /// `fixedfunc_depth_<ubyte|ushort>_<truncate|round>(readback_<slot>)`.
    ConvertedDepth {
        slot: u32,
        ty: PixelType,
        rule: DepthRule,
    },
}

impl TexData {
    /// The bytes, when the command carries them.
    pub fn bytes(&self) -> Option<&Arc<[u8]>> {
        match self {
            TexData::Bytes(b) => Some(b),
            TexData::Null | TexData::Readback(_) | TexData::ConvertedDepth { .. } => None,
        }
    }
}

impl From<Vec<u8>> for TexData {
    fn from(bytes: Vec<u8>) -> Self {
        TexData::Bytes(Arc::from(bytes))
    }
}

/// glTexSubImage1D/2D/3D (the target is the Command's: TexSubImage1D, TexSubImage2D,
/// TexSubImage3D); for 3D the data holds `depth` images of `height` rows.
#[derive(Debug, Clone, PartialEq)]
pub struct TexSubImage {
    /// glTexSubImage2D of a cube face (TEXTURE_CUBE_MAP_POSITIVE_X …); `None`: the
    /// call's own target.
    pub face: Option<CubeFace>,
    pub level: i32,
    pub x: i32,
    pub y: i32,
    /// 0 but for glTexSubImage3D.
    pub z: i32,
    pub width: i32,
    pub height: i32,
    /// 1 but for glTexSubImage3D.
    pub depth: i32,
    pub format: PixelFormat,
    pub ty: PixelType,
    /// The region's pixels; `None` for a NULL pointer, which GL does not refuse: the call
    /// is checked and changes no texel (Mesa: no error, nothing stored).
    pub data: Option<Arc<[u8]>>,
}

impl TexSubImage {
    /// The image target of a glTexSubImage2D: TEXTURE_2D or its cube face.
    pub fn target_2d(&self) -> TextureTarget {
        self.face
            .map_or(TextureTarget::Texture2D, TextureTarget::CubeFace)
    }
}

impl CopyTexImage {
    /// The image target of a glCopyTexImage2D: TEXTURE_2D or its cube face.
    pub fn target_2d(&self) -> TextureTarget {
        self.face
            .map_or(TextureTarget::Texture2D, TextureTarget::CubeFace)
    }
}

/// glCopyTexImage2D (target TEXTURE_2D or a cube face) from the current read buffer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct CopyTexImage {
    /// glCopyTexImage2D of a cube face; `None`: the call's own target.
    pub face: Option<CubeFace>,
    pub level: i32,
    pub internal_format: TexFormat,
    /// The internal format as the program named it (GL_RGB, 3, GL_RGB5), which
    /// TEXTURE_INTERNAL_FORMAT answers as Mesa does; `None`: the sized format's name.
    pub requested: Option<u32>,
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
    pub border: i32,
}

/// glReadPixels into a numbered readback slot (the pipeline keeps the bytes under `slot`;
/// a script names it `readback_<slot>`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ReadPixels {
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
    /// A colour format, DEPTH_COMPONENT or STENCIL_INDEX.
    pub format: PixelFormat,
    pub ty: PixelType,
    pub slot: u32,
}

/// One GL call.
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    // Matrices and viewport.
    MatrixMode(MatrixMode),
    LoadIdentity,
    LoadMatrix(Mat4),
    MultMatrix(Mat4),
    PushMatrix,
    PopMatrix,
    Translate(Vec3),
    Rotate {
        angle_deg: f32,
        axis: Vec3,
    },
    Scale(Vec3),
    Frustum(ViewVolume),
    Ortho(ViewVolume),
    Viewport(Viewport),
    DepthRange {
        near: f32,
        far: f32,
    },

    // Enables and current vertex values.
    Enable(Capability),
    Disable(Capability),
    Color(Vec4),
    Normal(Vec3),
    /// glEdgeFlag(flag).
    EdgeFlag(bool),
    /// glSecondaryColor3f(r, g, b) (GL 1.4 §2.7); the alpha is what the current value
    /// keeps (see `CurrentValues::secondary_color`).
    SecondaryColor(Vec4),
    /// glFogCoordf(coord) (GL 1.4 §2.7).
    FogCoord(f32),
    /// glIndexf(c): the current colour index (`color_index`).
    Index(f32),
    /// glClearIndex(c).
    ClearIndex(f32),
    /// glIndexMask(mask).
    IndexMask(u32),
    /// glSampleCoverage(value, invert).
    SampleCoverage {
        value: f32,
        invert: bool,
    },
    /// glMultiTexCoord4f(TEXTURE0 + unit, s, t, r, q).
    TexCoord {
        unit: u8,
        coord: Vec4,
    },

    // Lighting.
    /// light < MAX_LIGHTS, else INVALID_ENUM.
    Light {
        light: u8,
        param: LightParam,
    },
    LightModel(LightModelParam),
    Material {
        face: Face,
        param: MaterialParam,
    },
    ColorMaterial {
        face: Face,
        mode: ColorMaterialMode,
    },
    ShadeModel(ShadeModel),

    // Textures.
    /// unit < MAX_TEXTURE_UNITS, else INVALID_ENUM.
    ActiveTexture(u8),
    BindTexture {
        target: TextureTarget,
        name: u32,
    },
    TexImage(TexImage),
    /// glDeleteTextures: the objects of these names go; a unit bound to one reverts to
    /// the default texture 0 (GL 1.5 §3.8.12); 0 and unused names are ignored.
    DeleteTextures(Vec<u32>),
    /// glPrioritizeTextures: each named texture object's TEXTURE_PRIORITY, clamped to
    /// [0, 1] (GL 1.5 §3.8.12); 0 and names of no object are ignored (Mesa).
    PrioritizeTextures(Vec<(u32, f32)>),
    TexSubImage2D(TexSubImage),
    CopyTexImage2D(CopyTexImage),
    TexParameter {
        target: TextureTarget,
        param: TexParam,
    },
    TexGen {
        coord: TexCoord,
        param: TexGenParam,
    },
    TexEnv(TexEnvParam),

    // NV_register_combiners.
    CombinerParameter(CombinerParam),
    CombinerInput {
        stage: u8,
        portion: Portion,
        variable: Variable,
        input: CombinerInput,
    },
    CombinerOutput {
        stage: u8,
        portion: Portion,
        output: CombinerOutput,
    },
    FinalCombinerInput {
        variable: FinalVariable,
        input: CombinerInput,
    },

    // Per-fragment operations and rasterisation.
    AlphaFunc {
        func: CompareFunc,
        reference: f32,
    },
    DepthFunc(CompareFunc),
    DepthMask(bool),
    StencilFunc {
        func: CompareFunc,
        reference: i32,
        mask: u32,
    },
    StencilOp {
        fail: StencilOp,
        depth_fail: StencilOp,
        depth_pass: StencilOp,
    },
    StencilMask(u32),
    BlendFunc {
        src: BlendFactor,
        dst: BlendFactor,
    },
    /// glBlendFuncSeparate (GL 1.4): SRC_ALPHA_SATURATE as a destination factor is
    /// INVALID_ENUM.
    BlendFuncSeparate {
        src_rgb: BlendFactor,
        dst_rgb: BlendFactor,
        src_alpha: BlendFactor,
        dst_alpha: BlendFactor,
    },
    BlendEquation(BlendEquation),
    /// glBlendColor, clamped to [0, 1] when set.
    BlendColor(Vec4),
    ColorMask(ColorMask),
    PolygonOffset {
        factor: f32,
        units: f32,
    },
    PolygonMode {
        face: Face,
        mode: PolygonMode,
    },
    CullFace(Face),
    FrontFace(FrontFace),
    /// > 0, else INVALID_VALUE.
    LineWidth(f32),
    /// > 0, else INVALID_VALUE.
    PointSize(f32),
    /// glPointParameter (GL 1.4, `point`).
    PointParameter(PointParam),
    /// glFog: FOG_DENSITY < 0 is INVALID_VALUE.
    Fog(FogParam),
    /// glHint (§5.6): an unknown target or mode is INVALID_ENUM (the script rejects it).
    Hint {
        target: HintTarget,
        mode: HintMode,
    },
    /// glLogicOp: one of the 16 opcodes of Table 4.4.
    LogicOp(LogicOp),
    /// glScissor: a negative width or height is INVALID_VALUE.
    Scissor(ScissorBox),
    /// glClipPlane(CLIP_PLANE0 + plane, equation), the equation in object coordinates;
    /// plane < MAX_CLIP_PLANES, else INVALID_ENUM.
    ClipPlane {
        plane: u8,
        equation: Vec4,
    },

    // Framebuffer.
    Clear(ClearMask),
    ClearColor(Vec4),
    ClearDepth(f64),
    ClearStencil(i32),
    ReadPixels(ReadPixels),
    /// glClearAccum: clamped to [−1, 1] (GL 1.5 §4.2.3).
    ClearAccum(Vec4),
    /// glAccum (GL 1.5 §4.2.4): INVALID_OPERATION without an accumulation buffer (none
    /// with a framebuffer object bound); the rules in `ff::accum`.
    Accum {
        op: AccumOp,
        value: f32,
    },

    /// glBegin … glEnd, or glDrawArrays/glDrawElements.
    Draw(Arc<Geometry>),

    /// A call a display list recorded with arguments GL rejects: running it raises
    /// `error` and does nothing else (GL checks a listed call when the list executes).
    Raise {
        error: GlErrorKind,
        call: Entry,
    },
    // Attribute stack (GL 1.5 §6.1.14).
    /// STACK_OVERFLOW beyond MAX_ATTRIB_STACK_DEPTH entries.
    PushAttrib(AttribMask),
    /// STACK_UNDERFLOW on an empty stack.
    PopAttrib,

    // Framebuffer objects (ff::framebuffer); never compiled into display lists.
    /// glBindFramebuffer: a name never bound makes the object.
    BindFramebuffer {
        target: FramebufferTarget,
        name: u32,
    },
    /// glDeleteFramebuffers: a bound one leaves its binding at 0.
    DeleteFramebuffers(Vec<u32>),
    /// glBindRenderbuffer(GL_RENDERBUFFER, name).
    BindRenderbuffer(u32),
    /// glDeleteRenderbuffers: each is detached from the bound framebuffers.
    DeleteRenderbuffers(Vec<u32>),
    /// glRenderbufferStorage of the bound renderbuffer: none bound is INVALID_OPERATION,
    /// a size below 0 or above MAX_RENDERBUFFER_SIZE INVALID_VALUE.
    RenderbufferStorage {
        format: RenderbufferFormat,
        width: i32,
        height: i32,
    },
    /// glFramebufferTexture1D/2D/3D; `texture` `None` (name 0) detaches.
    FramebufferTexture {
        target: FramebufferTarget,
        attachment: AttachmentPoint,
        texture: Option<(TextureTarget, u32)>,
        level: i32,
        /// glFramebufferTexture3D's zoffset: the image of the 3D level; 0 for 1D and 2D.
        layer: i32,
    },
    /// glFramebufferRenderbuffer; 0 detaches.
    FramebufferRenderbuffer {
        target: FramebufferTarget,
        attachment: AttachmentPoint,
        renderbuffer: u32,
    },
    /// glDrawBuffer of the bound draw framebuffer.
    DrawBuffer(ColorBuffer),
    /// glReadBuffer of the bound read framebuffer.
    ReadBuffer(ColorBuffer),
    /// glListBase(base): the offset glCallLists adds to each name.
    ListBase(u32),
    /// glGenerateMipmap of the active unit's texture: levels 1… from level 0.
    GenerateMipmap(TextureTarget),
    // Texture calls of GL 1.1 beyond the 2D image (ff::texture_calls).
    /// glTexSubImage1D (target TEXTURE_1D): `y` 0, `height` 1.
    TexSubImage1D(TexSubImage),
    /// glCopyTexImage1D (target TEXTURE_1D): a row of `width` pixels from (x, y); `height` 1.
    CopyTexImage1D(CopyTexImage),
    CopyTexSubImage(super::texture_calls::CopyTexSubImage),
    GetTexImage(super::texture_calls::GetTexImage),
    // GL 1.2's 3D textures (ff::texture_volume).
    /// glTexSubImage3D (target TEXTURE_3D).
    TexSubImage3D(TexSubImage),
    /// glTexImage1D/2D/3D of PROXY_TEXTURE_1D, _2D, _CUBE_MAP or _3D: `target` is the
    /// target proxied (TEXTURE_1D, TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_3D).
    ProxyTexImage(TexImage),
    // GL 1.3's compressed textures (ff::compressed).
    /// glCompressedTexImage2D: S3TC blocks, decoded into the level's 8-bit storage.
    CompressedTexImage2D(super::compressed::CompressedTexImage),
    /// glCompressedTexSubImage2D: whole blocks into a compressed level.
    CompressedTexSubImage2D(super::compressed::CompressedTexSubImage),
    // Raster position and pixel rectangles (ff::raster, ff::pixels).
    /// glRasterPos4f: the point in object coordinates (§2.13).
    RasterPos(Vec4),
    /// glWindowPos3f (GL 1.4): window x, y and a depth in [0, 1] mapped by the depth range.
    WindowPos(Vec3),
    /// glBitmap (§3.7): negative sizes are INVALID_VALUE.
    Bitmap(Bitmap),
    /// glDrawPixels (§3.6.4).
    DrawPixels(DrawPixels),
    /// glBlitFramebuffer (GL 3.0 §4.3.3, `ff::blit`): compiled into display lists, as
    /// Mesa does.
    BlitFramebuffer(Blit),
    /// glCopyPixels (§4.3.3).
    CopyPixels(CopyPixels),
    PixelTransfer(PixelTransferParam),
    /// glPixelMap{f,ui,us}v (§3.6.3): the values as stored.
    PixelMap(super::pixel_map::PixelMap),
    /// glPixelZoom(x, y).
    PixelZoom {
        x: f32,
        y: f32,
    },
    // Stipple (ff::stipple).
    /// glPolygonStipple (§3.5.2): the unpacked 32×32 mask.
    /// Boxed: the 128-byte mask would make every Command that large, and each call moves
    /// its Command a few times on the way to the state.
    PolygonStipple(Box<PolygonStipple>),
    /// glLineStipple (§3.4.2): the factor already clamped to [1, 256].
    LineStipple(LineStipple),
    /// glGenQueries, glDeleteQueries, glBeginQuery, glEndQuery (ff::queries).
    Query(super::queries::QueryCommand),
    // Shader programs (ff::program): beyond GL 1.x, for the techniques that bring GLSL.
    /// glUseProgram: draws use `program` instead of the fixed-function pipeline until
    /// `None` (glUseProgram(0)). Emulate pipeline only.
    UseProgram(Option<Arc<super::program::ShaderProgram>>),
    /// glUniform* of the uniform `name` of the program in use.
    Uniform {
        name: Arc<str>,
        value: super::program::UniformValue,
    },
}
