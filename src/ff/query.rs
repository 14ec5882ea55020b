//! State queries: glGet*, glIsEnabled and the per-object getters, answered from the model.
//!
//! Every answer is a list of [`QueryValue`]s, each tagged with the kind of value the state
//! holds, so one answer serves glGetBooleanv, glGetIntegerv, glGetFloatv and glGetDoublev
//! through the conversions of GL 1.5 §6.1.2 ([`QueryValue::as_bool`], [`QueryValue::as_int`],
//! [`QueryValue::as_float`], [`QueryValue::as_double`]). The conversions are Mesa's
//! (`src/mesa/main/get.c`, 22.x), which the native oracle test checks against llvmpipe:
//!
//! - boolean → 0/1 (1.0/0.0); integer or enum → boolean: ≠ 0; integer → float: exact for the
//!   values the model holds (enums are < 2²⁴);
//! - float → boolean: ≠ 0 (C truth, so NaN → TRUE);
//! - float → integer, ordinary values ([`QueryValue::Float`]): rounded to nearest, halves away
//!   from zero (Mesa `lroundf`, stored into a GLint: NaN and |x| ≥ 2⁶³ give 0, larger than
//!   2³¹ wraps modulo 2³²);
//! - float → integer, colours, normals, depth range, depth clear value, alpha reference and
//!   matrices ([`QueryValue::Normalized`]): the "most positive representable integer" rule,
//!   Mesa's `FLOAT_TO_INT(x) = (GLint)(2147483647.0 · x)`, truncating: 1 → 2³¹ − 1,
//!   −1 → −(2³¹ − 1) (the spec's Table 4.5 gives −2³¹), 0.5 → 1073741823; a result outside
//!   GLint (|x| > 1) or NaN gives −2³¹, the x86-64 conversion of an out-of-range double.
//!   Matrices through glGetIntegerv are a Mesa deviation: the spec rounds them;
//! - the `…iv` getters of lights, texgen planes (glGetLightiv POSITION, glGetTexGeniv
//!   EYE_PLANE…) truncate (`(GLint) f` in Mesa's `light.c`, `texgen.c`; the spec rounds):
//!   [`QueryValue::Truncated`].
//!
//! Other Mesa behaviour the answers follow (each pinned in `tests/query_native.rs`):
//! TRANSPOSE_TEXTURE_MATRIX is unit 0's whatever the active unit; the stencil masks are
//! unsigned and start as 0xFF; an unspecified texture level reports internal format RGBA.
//! Where the model stores less than Mesa the answers differ, by design: DEPTH_RANGE is f32
//! here and doubles in Mesa (glGetIntegerv scales the double, so values not exact in f32
//! can differ in the last bits; DEPTH_CLEAR_VALUE is a double here too, as it decides the
//! cleared depth's last bit); TEXTURE_INTERNAL_FORMAT is the
//! sized format the model keeps (Mesa returns an unsized name as given).
//!
//! Not answered yet (INVALID_ENUM), because the model does not hold the state: fog,
//! scissor, clip planes, logic op, blend equation and colour, hints, pixel store and
//! transfer, the raster position, client state (CLIENT_ACTIVE_TEXTURE, arrays), framebuffer
//! bits, implementation limits other than those listed, TEXTURE_PRIORITY,
//! TEXTURE_RESIDENT.
//!
//! Adding a pname: one line in the [`PNAMES`] table (or in the marked block at its end) —
//! the GL token without `GL_`, and a function from `&FixedState` to its values built with
//! the helpers below (`floats`, `normalized`, `enm`, `int`, `boolean`, `matrix`). The
//! registry constant, the printed name and the oracle test's list all come from that line.
//! A capability goes in `glenum`'s `Capability` table instead: glGet and glIsEnabled answer
//! every capability from [`FixedState::is_enabled`].

use glam::{Mat4, Vec4};

use super::attrib::MAX_ATTRIB_STACK_DEPTH;
use super::combiners::MAX_GENERAL_COMBINERS;
use super::command::Capability;
use super::compressed::CompressedFormat;
use super::error::GlErrorKind;
use super::fragment::STENCIL_BITS;
use super::framebuffer;
use super::glenum::{gl, registry as r, GlEnum};
use super::light::MAX_LIGHTS;
use super::matrix::MatrixStack;
use super::pixel_map::{PixelMapName, MAX_PIXEL_MAP_TABLE};
use super::state::{FixedState, MAX_TEXTURE_UNITS};
use super::texenv::{CombineSource, TexEnv};
use super::texgen::TexCoord;
use super::texture::{
    TexFormat, TexLevel, TextureTarget, MAX_3D_TEXTURE_SIZE, MAX_CUBE_MAP_TEXTURE_SIZE,
    MAX_TEXTURE_SIZE,
};

/// GL_TEXTURE_COMPARE_FAIL_VALUE_ARB (ARB_shadow_ambient, outside the registry subset
/// `build.rs` reads).
pub const TEXTURE_COMPARE_FAIL_VALUE_ARB: u32 = 0x80BF;

/// One value of a query answer, as the state holds it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum QueryValue {
    Bool(bool),
    Int(i32),
    /// An unsigned value (Mesa's TYPE_UINT: the stencil masks): as an integer, clamped to
    /// 2³¹ − 1, so all 32 ones read 2147483647, not −1.
    UInt(u32),
    /// A GLenum; as an integer, its value.
    Enum(u32),
    /// A float that becomes an integer by rounding (§6.1.2).
    Float(f32),
    /// A colour, normal, depth or matrix value that becomes an integer by Mesa's
    /// `FLOAT_TO_INT` (see the module note).
    Normalized(f32),
    /// A float that Mesa's `…iv` getter casts to GLint, truncating.
    Truncated(f32),
    /// A float that Mesa's `…iv` getter rounds and clamps to GLint (a texture's MIN_LOD,
    /// MAX_LOD and LOD_BIAS): [`saturated_round`].
    Saturated(f32),
    /// A value GL keeps as a double (DEPTH_CLEAR_VALUE, Mesa's TYPE_DOUBLEN): as an
    /// integer by `FLOAT_TO_INT` of the double, as a float rounded once.
    NormalizedDouble(f64),
}

/// A query's values in the order GL writes them.
pub type Queried = Vec<QueryValue>;

impl QueryValue {
    /// glGetBooleanv's conversion.
    pub fn as_bool(self) -> bool {
        match self {
            QueryValue::Bool(b) => b,
            QueryValue::Int(i) => i != 0,
            QueryValue::UInt(u) | QueryValue::Enum(u) => u != 0,
            // C truth: NaN is TRUE.
            QueryValue::Float(f)
            | QueryValue::Normalized(f)
            | QueryValue::Truncated(f)
            | QueryValue::Saturated(f) => f != 0.0,
            QueryValue::NormalizedDouble(d) => d != 0.0,
        }
    }

    /// glGetIntegerv's conversion.
    pub fn as_int(self) -> i32 {
        match self {
            QueryValue::Bool(b) => i32::from(b),
            QueryValue::Int(i) => i,
            QueryValue::UInt(u) => u.min(i32::MAX as u32) as i32,
            QueryValue::Enum(e) => e as i32,
            QueryValue::Float(f) => round_to_int(f64::from(f)),
            QueryValue::Normalized(f) => normalized_to_int(f64::from(f)),
            QueryValue::NormalizedDouble(d) => normalized_to_int(d),
            QueryValue::Truncated(f) => c_int(f64::from(f)),
            QueryValue::Saturated(f) => saturated_round(f),
        }
    }

    /// glGetFloatv's conversion.
    pub fn as_float(self) -> f32 {
        match self {
            QueryValue::Bool(b) => f32::from(u8::from(b)),
            QueryValue::Int(i) => i as f32,
            QueryValue::UInt(u) | QueryValue::Enum(u) => u as f32,
            QueryValue::Float(f)
            | QueryValue::Normalized(f)
            | QueryValue::Truncated(f)
            | QueryValue::Saturated(f) => f,
            QueryValue::NormalizedDouble(d) => d as f32,
        }
    }

    /// glGetDoublev's conversion.
    pub fn as_double(self) -> f64 {
        match self {
            QueryValue::Bool(b) => f64::from(u8::from(b)),
            QueryValue::Int(i) => f64::from(i),
            QueryValue::UInt(u) | QueryValue::Enum(u) => f64::from(u),
            QueryValue::Float(f)
            | QueryValue::Normalized(f)
            | QueryValue::Truncated(f)
            | QueryValue::Saturated(f) => f64::from(f),
            QueryValue::NormalizedDouble(d) => d,
        }
    }
}

/// Mesa's float → GLint for ordinary values, and glPixelStoref's value: `lroundf`
/// (nearest, halves away from zero) into a `long`, stored into a GLint (the low 32 bits:
/// 5e9 gives 705032704). `lroundf` of NaN or of a value beyond `long` is `LONG_MIN` on
/// x86-64 glibc, whose low 32 bits are 0.
pub fn round_to_int(f: f64) -> i32 {
    c_long(f.round()) as i32
}

/// C's conversion of an integral double to `long` on x86-64 (`cvttsd2si`): `LONG_MIN` for
/// NaN and values beyond ±2⁶³ (whose low 32 bits are 0).
pub fn c_long(t: f64) -> i64 {
    // 2⁶³: the first value outside `long`.
    const LONG_RANGE: f64 = 9_223_372_036_854_775_808.0;
    if t.is_nan() || !(-LONG_RANGE..LONG_RANGE).contains(&t) {
        i64::MIN
    } else {
        t as i64
    }
}

/// A texture's LOD parameter as Mesa's glGetTexParameteriv answers it: rounded to nearest
/// (halves away from zero) and clamped to GLint, the value "so large in magnitude that it
/// cannot be represented" giving the nearest representable one; a NaN reads −2³¹
/// (measured: 2.5 → 3, 1e10 → 2147483647, −1e10 and NaN → −2147483648).
pub fn saturated_round(f: f32) -> i32 {
    let r = f64::from(f).round();
    if r.is_nan() || r <= f64::from(i32::MIN) {
        i32::MIN
    } else if r >= f64::from(i32::MAX) {
        i32::MAX
    } else {
        r as i32
    }
}

/// Mesa's `FLOAT_TO_INT(x) = (GLint)(2147483647.0 · x)`: linear, [−1, 1] → [−(2³¹ − 1),
/// 2³¹ − 1], truncating.
pub fn normalized_to_int(x: f64) -> i32 {
    c_int(2_147_483_647.0 * x)
}

/// C's `(GLint) x` as x86-64 computes it (`cvttsd2si`): truncation toward zero; NaN and
/// values outside GLint give −2³¹ (the "integer indefinite").
pub fn c_int(x: f64) -> i32 {
    let t = x.trunc();
    if t.is_nan() || t < f64::from(i32::MIN) || t > f64::from(i32::MAX) {
        i32::MIN
    } else {
        t as i32
    }
}

fn floats(v: &[f32]) -> Queried {
    v.iter().map(|f| QueryValue::Float(*f)).collect()
}

fn normalized(v: &[f32]) -> Queried {
    v.iter().map(|f| QueryValue::Normalized(*f)).collect()
}

fn truncated(v: &[f32]) -> Queried {
    v.iter().map(|f| QueryValue::Truncated(*f)).collect()
}

fn enm<T: GlEnum>(v: T) -> Queried {
    vec![QueryValue::Enum(gl(v))]
}

fn int(i: i32) -> Queried {
    vec![QueryValue::Int(i)]
}

fn count(n: usize) -> Queried {
    int(i32::try_from(n).unwrap_or(i32::MAX))
}

fn boolean(b: bool) -> Queried {
    vec![QueryValue::Bool(b)]
}

/// A matrix in column-major order, as glGet writes it (Mesa's TYPE_MATRIX: FLOAT_TO_INT for
/// glGetIntegerv).
fn matrix(m: Mat4) -> Queried {
    normalized(&m.to_cols_array())
}

fn depth(s: &MatrixStack) -> Queried {
    count(s.depth())
}

/// The GLenum of a combine source (TEXTUREn is the family TEXTURE0 + n).
fn source(s: CombineSource) -> u32 {
    match s {
        CombineSource::TextureUnit(n) => r::TEXTURE0 + u32::from(n),
        other => gl(other),
    }
}

/// One glGet pname: its token, its value and how the model answers it.
pub struct Pname {
    /// `GL_…`.
    pub name: &'static str,
    pub value: u32,
    get: fn(&FixedState) -> Queried,
}

macro_rules! pnames {
    ($($name:ident => $get:expr,)*) => {
        /// Every glGet pname the model answers besides the capabilities (see the module note
        /// for how to add one).
        pub const PNAMES: &[Pname] = &[$(Pname {
            name: concat!("GL_", stringify!($name)),
            value: r::$name,
            get: $get,
        }),*];
    };
}

pnames! {
    // Transformation (GL 1.5 Table 6.6).
    MATRIX_MODE => |s| enm(s.matrix_mode),
    MODELVIEW_MATRIX => |s| matrix(s.modelview.top()),
    PROJECTION_MATRIX => |s| matrix(s.projection.top()),
    TEXTURE_MATRIX => |s| matrix(s.texture_matrix(s.active_unit())),
    TRANSPOSE_MODELVIEW_MATRIX => |s| matrix(s.modelview.top().transpose()),
    TRANSPOSE_PROJECTION_MATRIX => |s| matrix(s.projection.top().transpose()),
    // Mesa deviation (pinned in `tests/query_native.rs`): unit 0's matrix whatever the
    // active unit (its table entry points at the first stack), where TEXTURE_MATRIX follows
    // the active unit.
    TRANSPOSE_TEXTURE_MATRIX => |s| matrix(s.texture_matrix(0).transpose()),
    MODELVIEW_STACK_DEPTH => |s| depth(&s.modelview),
    PROJECTION_STACK_DEPTH => |s| depth(&s.projection),
    TEXTURE_STACK_DEPTH => |s| depth(&s.texture_matrices[s.active_unit()]),
    MAX_MODELVIEW_STACK_DEPTH => |s| count(s.modelview.max_depth()),
    MAX_PROJECTION_STACK_DEPTH => |s| count(s.projection.max_depth()),
    MAX_TEXTURE_STACK_DEPTH => |s| count(s.texture_matrices[0].max_depth()),
    VIEWPORT => |s| {
        let v = s.viewport;
        [v.x, v.y, v.width, v.height].into_iter().map(QueryValue::Int).collect()
    },
    DEPTH_RANGE => |s| normalized(&[s.depth_range.near, s.depth_range.far]),

    // Current values (Table 6.5): the texture coordinates of the active unit.
    CURRENT_COLOR => |s| normalized(&s.current.color.to_array()),
    CURRENT_NORMAL => |s| normalized(&s.current.normal.to_array()),
    EDGE_FLAG => |s| boolean(s.current.edge_flag),
    CURRENT_SECONDARY_COLOR => |s| normalized(&s.current.secondary_color.to_array()),
    CURRENT_FOG_COORD => |s| floats(&[s.current.fog_coord]),
    CURRENT_INDEX => |s| floats(&[s.current.index]),
    INDEX_CLEAR_VALUE => |s| int(s.clear_index as i32),
    INDEX_WRITEMASK => |s| int(s.index_mask as i32),
    SAMPLE_COVERAGE_VALUE => |s| floats(&[s.sample_coverage.value]),
    // SAMPLE_COVERAGE_INVERT is answered as a capability (`Capability::SampleCoverageInvert`).
    CURRENT_TEXTURE_COORDS => |s| floats(&s.current.texcoords[s.active_unit()].to_array()),

    // The raster position (Table 6.5, `raster`): the active unit's texture coordinates.
    CURRENT_RASTER_POSITION => |s| floats(&s.raster.window.to_array()),
    CURRENT_RASTER_POSITION_VALID => |s| boolean(s.raster.valid),
    CURRENT_RASTER_COLOR => |s| normalized(&s.raster.color.to_array()),
    CURRENT_RASTER_TEXTURE_COORDS => |s| floats(&s.raster.texcoords[s.active_unit()].to_array()),
    CURRENT_RASTER_DISTANCE => |s| floats(&[s.raster.distance]),
    // The raster position's colour index: 1 in an RGBA context, which never sets it (Mesa's
    // initial RasterIndex, measured).
    CURRENT_RASTER_INDEX => |_| floats(&[1.0]),

    // Pixel transfer and zoom (Table 6.16, `pixels`).
    ZOOM_X => |s| floats(&[s.pixel_zoom.x]),
    ZOOM_Y => |s| floats(&[s.pixel_zoom.y]),
    RED_SCALE => |s| floats(&[s.pixel_transfer.scale.x]),
    GREEN_SCALE => |s| floats(&[s.pixel_transfer.scale.y]),
    BLUE_SCALE => |s| floats(&[s.pixel_transfer.scale.z]),
    ALPHA_SCALE => |s| floats(&[s.pixel_transfer.scale.w]),
    RED_BIAS => |s| floats(&[s.pixel_transfer.bias.x]),
    GREEN_BIAS => |s| floats(&[s.pixel_transfer.bias.y]),
    BLUE_BIAS => |s| floats(&[s.pixel_transfer.bias.z]),
    ALPHA_BIAS => |s| floats(&[s.pixel_transfer.bias.w]),
    DEPTH_SCALE => |s| floats(&[s.pixel_transfer.depth_scale]),
    DEPTH_BIAS => |s| floats(&[s.pixel_transfer.depth_bias]),
    INDEX_SHIFT => |s| int(s.pixel_transfer.index_shift),
    INDEX_OFFSET => |s| int(s.pixel_transfer.index_offset),
    MAP_COLOR => |s| boolean(s.pixel_transfer.map_color),
    MAP_STENCIL => |s| boolean(s.pixel_transfer.map_stencil),
    // The pixel maps' sizes (Table 6.17, `pixel_map`).
    PIXEL_MAP_I_TO_I_SIZE => |s| count(s.pixel_maps.get(PixelMapName::IToI).len()),
    PIXEL_MAP_S_TO_S_SIZE => |s| count(s.pixel_maps.get(PixelMapName::SToS).len()),
    PIXEL_MAP_I_TO_R_SIZE => |s| count(s.pixel_maps.get(PixelMapName::IToR).len()),
    PIXEL_MAP_I_TO_G_SIZE => |s| count(s.pixel_maps.get(PixelMapName::IToG).len()),
    PIXEL_MAP_I_TO_B_SIZE => |s| count(s.pixel_maps.get(PixelMapName::IToB).len()),
    PIXEL_MAP_I_TO_A_SIZE => |s| count(s.pixel_maps.get(PixelMapName::IToA).len()),
    PIXEL_MAP_R_TO_R_SIZE => |s| count(s.pixel_maps.get(PixelMapName::RToR).len()),
    PIXEL_MAP_G_TO_G_SIZE => |s| count(s.pixel_maps.get(PixelMapName::GToG).len()),
    PIXEL_MAP_B_TO_B_SIZE => |s| count(s.pixel_maps.get(PixelMapName::BToB).len()),
    PIXEL_MAP_A_TO_A_SIZE => |s| count(s.pixel_maps.get(PixelMapName::AToA).len()),
    MAX_PIXEL_MAP_TABLE => |_| count(MAX_PIXEL_MAP_TABLE),

    // Lighting (Tables 6.9, 6.10).
    LIGHT_MODEL_AMBIENT => |s| normalized(&s.light_model.ambient.to_array()),
    LIGHT_MODEL_LOCAL_VIEWER => |s| boolean(s.light_model.local_viewer),
    LIGHT_MODEL_TWO_SIDE => |s| boolean(s.light_model.two_side),
    LIGHT_MODEL_COLOR_CONTROL => |s| enm(s.light_model.color_control),
    SHADE_MODEL => |s| enm(s.shade_model),
    COLOR_MATERIAL_FACE => |s| enm(s.color_material.value.face),
    COLOR_MATERIAL_PARAMETER => |s| enm(s.color_material.value.mode),

    // Texturing (Tables 6.15–6.20): the active unit's bindings.
    ACTIVE_TEXTURE => |s| vec![QueryValue::Enum(r::TEXTURE0 + s.active_unit() as u32)],
    TEXTURE_BINDING_1D => |s| name(s.units[s.active_unit()].bound_1d),
    TEXTURE_BINDING_2D => |s| name(s.units[s.active_unit()].bound_2d),
    TEXTURE_BINDING_3D => |s| name(s.units[s.active_unit()].bound_3d),
    TEXTURE_BINDING_CUBE_MAP => |s| name(s.units[s.active_unit()].bound_cube_map),

    // Per-fragment operations (Table 6.21) and framebuffer control (Table 6.22).
    ALPHA_TEST_FUNC => |s| enm(s.alpha_test.value.func),
    ALPHA_TEST_REF => |s| normalized(&[s.alpha_test.value.answered_reference()]),
    DEPTH_FUNC => |s| enm(s.depth_test.value.func),
    DEPTH_WRITEMASK => |s| boolean(s.depth_test.value.write),
    STENCIL_FUNC => |s| enm(s.stencil_test.value.func),
    STENCIL_VALUE_MASK => |s| vec![QueryValue::UInt(s.stencil_test.value.value_mask)],
    // Clamped to [0, 2ˢ − 1] when queried (§4.1.5), s = STENCIL_BITS; stored as given. Mesa
    // clamps with the draw buffer's bits, so without a stencil buffer it answers 0.
    STENCIL_REF => |s| int(s.stencil_test.value.reference.clamp(0, (1 << STENCIL_BITS) - 1)),
    STENCIL_FAIL => |s| enm(s.stencil_test.value.fail),
    STENCIL_PASS_DEPTH_FAIL => |s| enm(s.stencil_test.value.depth_fail),
    STENCIL_PASS_DEPTH_PASS => |s| enm(s.stencil_test.value.depth_pass),
    STENCIL_WRITEMASK => |s| vec![QueryValue::UInt(s.stencil_test.value.write_mask)],
    BLEND_SRC => |s| enm(s.blend.value.src_rgb),
    BLEND_DST => |s| enm(s.blend.value.dst_rgb),
    COLOR_WRITEMASK => |s| {
        let m = s.color_mask;
        [m.r, m.g, m.b, m.a].into_iter().map(QueryValue::Bool).collect()
    },
    COLOR_CLEAR_VALUE => |s| normalized(&s.clear.color.clamp(Vec4::ZERO, Vec4::ONE).to_array()),
    DEPTH_CLEAR_VALUE => |s| vec![QueryValue::NormalizedDouble(s.clear.depth)],
    STENCIL_CLEAR_VALUE => |s| int(s.clear.stencil),

    // Rasterisation (Tables 6.11–6.14).
    POLYGON_OFFSET_FACTOR => |s| floats(&[s.polygon_offset.factor]),
    POLYGON_OFFSET_UNITS => |s| floats(&[s.polygon_offset.units]),
    POLYGON_MODE => |s| {
        [s.polygon_mode.front, s.polygon_mode.back]
            .into_iter()
            .map(|m| QueryValue::Enum(gl(m)))
            .collect()
    },
    CULL_FACE_MODE => |s| enm(s.cull_face.value),
    FRONT_FACE => |s| enm(s.front_face),
    LINE_WIDTH => |s| floats(&[s.line_width]),
    LINE_STIPPLE_PATTERN => |s| int(i32::from(s.line_stipple.value.pattern)),
    LINE_STIPPLE_REPEAT => |s| int(i32::from(s.line_stipple.value.factor)),
    POINT_SIZE => |s| floats(&[s.point_size]),
    POINT_SIZE_MIN => |s| floats(&[s.point_params.size_min]),
    POINT_SIZE_MAX => |s| floats(&[s.point_params.size_max]),
    POINT_FADE_THRESHOLD_SIZE => |s| floats(&[s.point_params.fade_threshold]),
    POINT_DISTANCE_ATTENUATION => |s| floats(&s.point_params.attenuation),
    POINT_SPRITE_COORD_ORIGIN => |s| vec![QueryValue::Enum(s.point_params.sprite_coord_origin)],

    // Framebuffer objects (GL 3.0 Table 6.23, 6.34) and the colour buffers (Table 6.21).
    DRAW_FRAMEBUFFER_BINDING => |s| int(s.framebuffers.draw as i32),
    READ_FRAMEBUFFER_BINDING => |s| int(s.framebuffers.read as i32),
    RENDERBUFFER_BINDING => |s| int(s.framebuffers.renderbuffer as i32),
    MAX_COLOR_ATTACHMENTS => |_| int(i32::from(framebuffer::MAX_COLOR_ATTACHMENTS)),
    MAX_RENDERBUFFER_SIZE => |_| int(framebuffer::MAX_RENDERBUFFER_SIZE),
    RED_BITS => |s| int(i32::from(s.draw_bits(s.framebuffers.window_bits).red)),
    GREEN_BITS => |s| int(i32::from(s.draw_bits(s.framebuffers.window_bits).green)),
    BLUE_BITS => |s| int(i32::from(s.draw_bits(s.framebuffers.window_bits).blue)),
    ALPHA_BITS => |s| int(i32::from(s.draw_bits(s.framebuffers.window_bits).alpha)),
    DEPTH_BITS => |s| int(i32::from(s.draw_bits(s.framebuffers.window_bits).depth)),
    STENCIL_BITS => |s| int(i32::from(s.draw_bits(s.framebuffers.window_bits).stencil)),
    ACCUM_RED_BITS => |s| int(i32::from(s.accum_bits())),
    ACCUM_GREEN_BITS => |s| int(i32::from(s.accum_bits())),
    ACCUM_BLUE_BITS => |s| int(i32::from(s.accum_bits())),
    ACCUM_ALPHA_BITS => |s| int(i32::from(s.accum_bits())),
    // Read as integers like COLOR_CLEAR_VALUE (Mesa measured: 0.3 → 644245119).
    ACCUM_CLEAR_VALUE => |s| normalized(&s.clear.accum.to_array()),
    DRAW_BUFFER => |s| enm(s.framebuffers.color_buffer(framebuffer::FramebufferTarget::Draw)),
    READ_BUFFER => |s| enm(s.framebuffers.color_buffer(framebuffer::FramebufferTarget::Read)),

    // Display lists (Table 6.36); LIST_BASE is a GLuint read as it is.
    LIST_BASE => |s| int(s.list_base as i32),

    // Attribute stack (Table 6.39).
    ATTRIB_STACK_DEPTH => |s| count(s.attrib_depth()),
    MAX_ATTRIB_STACK_DEPTH => |_| count(MAX_ATTRIB_STACK_DEPTH),

    // Implementation limits (Table 6.32): the model's, which are llvmpipe's.
    MAX_LIGHTS => |_| count(MAX_LIGHTS),
    MAX_TEXTURE_UNITS => |_| count(MAX_TEXTURE_UNITS),
    MAX_TEXTURE_SIZE => |_| int(MAX_TEXTURE_SIZE),
    MAX_TEXTURE_LOD_BIAS => |_| floats(&[super::texenv::MAX_TEXTURE_LOD_BIAS]),
    MAX_TEXTURE_MAX_ANISOTROPY_EXT => |_| floats(&[super::texture::MAX_TEXTURE_MAX_ANISOTROPY]),
    MAX_3D_TEXTURE_SIZE => |_| int(MAX_3D_TEXTURE_SIZE),
    MAX_CUBE_MAP_TEXTURE_SIZE => |_| int(MAX_CUBE_MAP_TEXTURE_SIZE),

    // NV_register_combiners (not in Mesa: the oracle test leaves these out).
    NUM_GENERAL_COMBINERS_NV => |s| count(s.register_combiners.value.num_general),
    COLOR_SUM_CLAMP_NV => |s| boolean(s.register_combiners.value.color_sum_clamp),
    CONSTANT_COLOR0_NV => |s| normalized(&s.register_combiners.value.constant_color[0].to_array()),
    CONSTANT_COLOR1_NV => |s| normalized(&s.register_combiners.value.constant_color[1].to_array()),
    MAX_GENERAL_COMBINERS_NV => |_| count(MAX_GENERAL_COMBINERS),

    // Blending of GL 1.4, logic op, dither (Table 6.21).
    BLEND_SRC_RGB => |s| enm(s.blend.value.src_rgb),
    BLEND_DST_RGB => |s| enm(s.blend.value.dst_rgb),
    BLEND_SRC_ALPHA => |s| enm(s.blend.value.src_alpha),
    BLEND_DST_ALPHA => |s| enm(s.blend.value.dst_alpha),
    BLEND_EQUATION => |s| enm(s.blend.value.equation),
    BLEND_EQUATION_ALPHA => |s| enm(s.blend.value.equation),
    BLEND_COLOR => |s| normalized(&s.blend_color.to_array()),
    LOGIC_OP_MODE => |s| enm(s.logic_op.value),

    // Fog (Table 6.10).
    FOG_MODE => |s| enm(s.fog.value.mode),
    FOG_DENSITY => |s| floats(&[s.fog.value.density]),
    FOG_START => |s| floats(&[s.fog.value.start]),
    FOG_END => |s| floats(&[s.fog.value.end]),
    FOG_COLOR => |s| normalized(&s.fog.value.color.to_array()),
    FOG_INDEX => |s| floats(&[s.fog.value.index]),
    FOG_COORD_SRC => |s| enm(s.fog.value.coord_source),

    // Scissor (Table 6.16): the box as set; before any glScissor, the whole target, which
    // the front end that knows the window sets at its first make-current.
    SCISSOR_BOX => |s| {
        let b = s.scissor.value.unwrap_or_default();
        [b.x, b.y, b.width, b.height].into_iter().map(QueryValue::Int).collect()
    },
    MAX_CLIP_PLANES => |_| count(super::state::MAX_CLIP_PLANES),

    // Hints (Table 6.27).
    PERSPECTIVE_CORRECTION_HINT => |s| enm(s.hints.perspective_correction),
    POINT_SMOOTH_HINT => |s| enm(s.hints.point_smooth),
    LINE_SMOOTH_HINT => |s| enm(s.hints.line_smooth),
    POLYGON_SMOOTH_HINT => |s| enm(s.hints.polygon_smooth),
    FOG_HINT => |s| enm(s.hints.fog),
    TEXTURE_COMPRESSION_HINT => |s| enm(s.hints.texture_compression),
    GENERATE_MIPMAP_HINT => |s| enm(s.hints.generate_mipmap),
    // Selection, feedback and evaluators are left out: the render mode is always RENDER,
    // and the state their calls would set keeps its initial values (Tables 6.25 and 6.31),
    // which is what Mesa answers until such a call.
    RENDER_MODE => |_| vec![QueryValue::Enum(r::RENDER)],
    NAME_STACK_DEPTH => |_| int(0),
    SELECTION_BUFFER_SIZE => |_| int(0),
    FEEDBACK_BUFFER_SIZE => |_| int(0),
    FEEDBACK_BUFFER_TYPE => |_| vec![QueryValue::Enum(GL_2D)],
    MAP1_GRID_DOMAIN => |_| floats(&[0.0, 1.0]),
    MAP1_GRID_SEGMENTS => |_| int(1),
    MAP2_GRID_DOMAIN => |_| floats(&[0.0, 1.0, 0.0, 1.0]),
    MAP2_GRID_SEGMENTS => |_| vec![QueryValue::Int(1), QueryValue::Int(1)],
    // The S3TC formats the layer decodes, of Mesa's twelve (`ff::compressed`).
    NUM_COMPRESSED_TEXTURE_FORMATS => |_| count(CompressedFormat::LISTED.len()),
    COMPRESSED_TEXTURE_FORMATS => |_| CompressedFormat::LISTED
        .iter()
        .map(|f| QueryValue::Enum(gl(*f)))
        .collect(),

    // Point and line limits (Table 6.32): llvmpipe's, which rasterises both paths' points
    // and lines (sizes and widths 1…255 in steps of 0.1, aliased and smooth alike).
    ALIASED_POINT_SIZE_RANGE => |_| floats(&[1.0, 255.0]),
    ALIASED_LINE_WIDTH_RANGE => |_| floats(&[1.0, 255.0]),
    SMOOTH_POINT_SIZE_RANGE => |_| floats(&[1.0, 255.0]),
    SMOOTH_POINT_SIZE_GRANULARITY => |_| floats(&[0.1]),
    SMOOTH_LINE_WIDTH_RANGE => |_| floats(&[1.0, 255.0]),
    SMOOTH_LINE_WIDTH_GRANULARITY => |_| floats(&[0.1]),
    // Other limits and the visual (Tables 6.32, 6.34), as Mesa's llvmpipe answers them: a
    // single-buffered RGBA visual without multisampling, auxiliary or stereo buffers.
    MAX_VIEWPORT_DIMS => |_| {
        let side = super::apply::MAX_VIEWPORT_SIDE;
        vec![QueryValue::Int(side), QueryValue::Int(side)]
    },
    SUBPIXEL_BITS => |_| int(8),
    MAX_ELEMENTS_VERTICES => |_| int(3000),
    MAX_ELEMENTS_INDICES => |_| int(3000),
    MAX_NAME_STACK_DEPTH => |_| int(64),
    MAX_EVAL_ORDER => |_| int(30),
    SAMPLE_BUFFERS => |_| int(0),
    SAMPLES => |_| int(0),
    AUX_BUFFERS => |_| int(0),
    RGBA_MODE => |_| boolean(true),
    INDEX_MODE => |_| boolean(false),
    INDEX_BITS => |_| int(0),
    DOUBLEBUFFER => |_| boolean(false),
    STEREO => |_| boolean(false),

    // ── New pnames go here: `TOKEN => |s| helper(s.field),` as above. ──
}

/// GL_2D, the initial FEEDBACK_BUFFER_TYPE (the registry's name starts with a digit, so
/// the generated table has no constant for it).
const GL_2D: u32 = 0x0600;

/// A texture name as glGetIntegerv reports it.
fn name(n: u32) -> Queried {
    int(n as i32)
}

/// The pnames of NV_register_combiners, which Mesa does not expose.
pub const NV_PNAMES: [u32; 5] = [
    r::NUM_GENERAL_COMBINERS_NV,
    r::COLOR_SUM_CLAMP_NV,
    r::CONSTANT_COLOR0_NV,
    r::CONSTANT_COLOR1_NV,
    r::MAX_GENERAL_COMBINERS_NV,
];

/// The capability a glEnable/glIsEnabled enum names (LIGHTi for i < MAX_LIGHTS).
pub fn capability(cap: u32) -> Option<Capability> {
    let light = cap.wrapping_sub(r::LIGHT0);
    if (light as usize) < MAX_LIGHTS {
        return Some(Capability::Light(light as u8));
    }
    if let Some(i) = super::glenum::Family::ClipPlane.from_value(cap) {
        return Some(Capability::ClipPlane(i));
    }
    Capability::from_gl_value(cap)
}

/// Every capability enum the model answers (for glIsEnabled and as glGet pnames).
pub fn capabilities() -> Vec<u32> {
    let mut caps: Vec<u32> = Capability::TABLE.iter().map(|(_, v, _)| *v).collect();
    caps.extend((0..MAX_LIGHTS as u32).map(|i| r::LIGHT0 + i));
    caps.extend((0..super::state::MAX_CLIP_PLANES as u32).map(|i| r::CLIP_PLANE0 + i));
    // An alias (GL_LOGIC_OP for GL_INDEX_LOGIC_OP) is one capability.
    let mut seen = std::collections::HashSet::new();
    caps.retain(|c| seen.insert(*c));
    caps
}

/// Every glGet pname the model answers: the table and the capabilities.
pub fn pnames() -> Vec<u32> {
    let mut all: Vec<u32> = PNAMES.iter().map(|p| p.value).collect();
    all.extend(capabilities());
    all
}

/// The token of a pname the model answers (`GL_…`), for messages.
pub fn pname_name(pname: u32) -> Option<&'static str> {
    if let Some(p) = PNAMES.iter().find(|p| p.value == pname) {
        return Some(p.name);
    }
    match capability(pname)? {
        Capability::Light(_) => Some("GL_LIGHTi"),
        c => c.gl_name(),
    }
}

impl FixedState {
    /// glGet{Boolean,Integer,Float,Double}v(pname): the values, to be converted with
    /// [`QueryValue`]'s `as_*`; INVALID_ENUM for a pname the model does not answer.
    pub fn get(&self, pname: u32) -> Result<Queried, GlErrorKind> {
        if let Some(p) = PNAMES.iter().find(|p| p.value == pname) {
            return Ok((p.get)(self));
        }
        self.is_enabled(pname).map(boolean)
    }

    /// glGetBooleanv(pname), converted (GL_TRUE = true).
    pub fn get_booleanv(&self, pname: u32) -> Result<Vec<bool>, GlErrorKind> {
        Ok(self.get(pname)?.iter().map(|v| v.as_bool()).collect())
    }

    /// glGetIntegerv(pname), converted.
    pub fn get_integerv(&self, pname: u32) -> Result<Vec<i32>, GlErrorKind> {
        Ok(self.get(pname)?.iter().map(|v| v.as_int()).collect())
    }

    /// glGetFloatv(pname), converted.
    pub fn get_floatv(&self, pname: u32) -> Result<Vec<f32>, GlErrorKind> {
        Ok(self.get(pname)?.iter().map(|v| v.as_float()).collect())
    }

    /// glGetDoublev(pname), converted.
    pub fn get_doublev(&self, pname: u32) -> Result<Vec<f64>, GlErrorKind> {
        Ok(self.get(pname)?.iter().map(|v| v.as_double()).collect())
    }

    /// glIsEnabled(cap); INVALID_ENUM for a capability the model does not have. Texture
    /// and texgen enables are the active unit's.
    pub fn is_enabled(&self, cap: u32) -> Result<bool, GlErrorKind> {
        let cap = capability(cap).ok_or(GlErrorKind::InvalidEnum)?;
        let unit = &self.units[self.active_unit()];
        Ok(match cap {
            Capability::Lighting => self.lighting,
            Capability::Light(i) => self.lights.get(usize::from(i)).is_some_and(|l| l.enabled),
            Capability::ColorMaterial => self.color_material.enabled,
            Capability::Normalize => self.normalize,
            Capability::RescaleNormal => self.rescale_normal,
            Capability::Texture1D => unit.texture_1d,
            Capability::Texture2D => unit.texture_2d,
            Capability::Texture3D => unit.texture_3d,
            Capability::TextureCubeMap => unit.texture_cube_map,
            Capability::TextureGen(c) => unit.texgen[c.index()].enabled,
            Capability::AlphaTest => self.alpha_test.enabled,
            Capability::DepthTest => self.depth_test.enabled,
            Capability::StencilTest => self.stencil_test.enabled,
            Capability::Blend => self.blend.enabled,
            Capability::CullFace => self.cull_face.enabled,
            Capability::PolygonOffsetFill => self.offset_enables.fill,
            Capability::PolygonOffsetLine => self.offset_enables.line,
            Capability::PolygonOffsetPoint => self.offset_enables.point,
            Capability::RegisterCombiners => self.register_combiners.enabled,
            Capability::Fog => self.fog.enabled,
            Capability::ScissorTest => self.scissor.enabled,
            Capability::ClipPlane(i) => self
                .clip_planes
                .get(usize::from(i))
                .is_some_and(|p| p.enabled),
            Capability::ColorLogicOp => self.logic_op.enabled,
            Capability::IndexLogicOp => self.index_logic_op,
            Capability::Dither => self.dither,
            Capability::PointSmooth => self.smooth.point,
            Capability::PointSprite => self.point_sprite.enabled,
            Capability::LineSmooth => self.smooth.line,
            Capability::PolygonSmooth => self.smooth.polygon,
            Capability::ColorSum => self.color_sum,
            Capability::Multisample => self.multisample,
            Capability::SampleCoverage => self.sample_coverage.coverage,
            Capability::SampleAlphaToCoverage => self.sample_coverage.alpha_to_coverage,
            Capability::SampleAlphaToOne => self.sample_coverage.alpha_to_one,
            Capability::SampleCoverageInvert => self.sample_coverage.invert,
            Capability::AutoNormal => self.eval.auto_normal,
            Capability::Map(m) => self.eval.maps & m.bit() != 0,
            Capability::PolygonStipple => self.polygon_stipple.enabled,
            Capability::LineStipple => self.line_stipple.enabled,
        })
    }

    /// glGetLight{f,i}v(light, pname): colours are normalised values, the rest truncate
    /// under glGetLightiv (Mesa). Position and spot direction are in eye coordinates, as
    /// stored (GL 1.5 §6.1.3). INVALID_ENUM for a light ≥ MAX_LIGHTS or another pname.
    pub fn get_light(&self, light: u32, pname: u32) -> Result<Queried, GlErrorKind> {
        let i = light.wrapping_sub(r::LIGHT0) as usize;
        let l = self.lights.get(i).ok_or(GlErrorKind::InvalidEnum)?.value;
        Ok(match pname {
            r::AMBIENT => normalized(&l.ambient.to_array()),
            r::DIFFUSE => normalized(&l.diffuse.to_array()),
            r::SPECULAR => normalized(&l.specular.to_array()),
            r::POSITION => truncated(&l.position.to_array()),
            r::SPOT_DIRECTION => truncated(&l.spot_direction.to_array()),
            r::SPOT_EXPONENT => truncated(&[l.spot_exponent]),
            r::SPOT_CUTOFF => truncated(&[l.spot_cutoff]),
            r::CONSTANT_ATTENUATION => truncated(&[l.constant_attenuation]),
            r::LINEAR_ATTENUATION => truncated(&[l.linear_attenuation]),
            r::QUADRATIC_ATTENUATION => truncated(&[l.quadratic_attenuation]),
            _ => return Err(GlErrorKind::InvalidEnum),
        })
    }

    /// glGetMaterial{f,i}v(face, pname): face FRONT or BACK (FRONT_AND_BACK is
    /// INVALID_ENUM, §6.1.3); colours normalised, SHININESS and COLOR_INDEXES rounded.
    pub fn get_material(&self, face: u32, pname: u32) -> Result<Queried, GlErrorKind> {
        let m = match face {
            r::FRONT => self.materials.front,
            r::BACK => self.materials.back,
            _ => return Err(GlErrorKind::InvalidEnum),
        };
        Ok(match pname {
            r::AMBIENT => normalized(&m.ambient.to_array()),
            r::DIFFUSE => normalized(&m.diffuse.to_array()),
            r::SPECULAR => normalized(&m.specular.to_array()),
            r::EMISSION => normalized(&m.emission.to_array()),
            r::SHININESS => floats(&[m.shininess]),
            r::COLOR_INDEXES => floats(&m.color_indexes.to_array()),
            _ => return Err(GlErrorKind::InvalidEnum),
        })
    }

    /// glGetTexEnv{f,i}v(TEXTURE_ENV, pname) of the active unit, and of its
    /// TEXTURE_FILTER_CONTROL's LOD bias and POINT_SPRITE's COORD_REPLACE. Other targets and
    /// pnames: INVALID_ENUM.
    pub fn get_tex_env(&self, target: u32, pname: u32) -> Result<Queried, GlErrorKind> {
        let e: &TexEnv = &self.units[self.active_unit()].env;
        match (target, pname) {
            // Mesa's glGetTexEnviv casts the bias to GLint (measured: 2.5 reads 2).
            (r::TEXTURE_FILTER_CONTROL, r::TEXTURE_LOD_BIAS) => {
                return Ok(vec![QueryValue::Truncated(e.lod_bias)])
            }
            (r::POINT_SPRITE, r::COORD_REPLACE) => {
                return Ok(boolean(self.point_sprite.replaces(self.active_unit())))
            }
            (r::TEXTURE_ENV, _) => {}
            _ => return Err(GlErrorKind::InvalidEnum),
        }
        let src = |v: CombineSource| vec![QueryValue::Enum(source(v))];
        Ok(match pname {
            r::TEXTURE_ENV_MODE => enm(e.mode),
            r::TEXTURE_ENV_COLOR => normalized(&e.color.to_array()),
            r::COMBINE_RGB => enm(e.rgb.func),
            r::COMBINE_ALPHA => enm(e.alpha.func),
            r::SOURCE0_RGB => src(e.rgb.sources[0]),
            r::SOURCE1_RGB => src(e.rgb.sources[1]),
            r::SOURCE2_RGB => src(e.rgb.sources[2]),
            r::SOURCE0_ALPHA => src(e.alpha.sources[0]),
            r::SOURCE1_ALPHA => src(e.alpha.sources[1]),
            r::SOURCE2_ALPHA => src(e.alpha.sources[2]),
            r::OPERAND0_RGB => enm(e.rgb.operands[0]),
            r::OPERAND1_RGB => enm(e.rgb.operands[1]),
            r::OPERAND2_RGB => enm(e.rgb.operands[2]),
            r::OPERAND0_ALPHA => enm(e.alpha.operands[0]),
            r::OPERAND1_ALPHA => enm(e.alpha.operands[1]),
            r::OPERAND2_ALPHA => enm(e.alpha.operands[2]),
            r::RGB_SCALE => floats(&[e.rgb.scale.factor()]),
            r::ALPHA_SCALE => floats(&[e.alpha.scale.factor()]),
            _ => return Err(GlErrorKind::InvalidEnum),
        })
    }

    /// glGetTexGen{d,f,i}v(coord, pname) of the active unit. The eye plane is the stored,
    /// eye-space one (§6.1.3); planes truncate under glGetTexGeniv (Mesa).
    pub fn get_tex_gen(&self, coord: u32, pname: u32) -> Result<Queried, GlErrorKind> {
        let c = TexCoord::from_gl_value(coord).ok_or(GlErrorKind::InvalidEnum)?;
        let g = self.units[self.active_unit()].texgen[c.index()].value;
        Ok(match pname {
            r::TEXTURE_GEN_MODE => enm(g.mode),
            r::OBJECT_PLANE => truncated(&g.object_plane.to_array()),
            r::EYE_PLANE => truncated(&g.eye_plane.to_array()),
            _ => return Err(GlErrorKind::InvalidEnum),
        })
    }

    /// glGetTexParameter{f,i}v(target, pname): the texture bound to `target` on the active
    /// unit.
    pub fn get_tex_parameter(&self, target: u32, pname: u32) -> Result<Queried, GlErrorKind> {
        let t = TextureTarget::from_gl_value(target)
            .filter(|t| t.face().is_none())
            .ok_or(GlErrorKind::InvalidEnum)?;
        let name = self.units[self.active_unit()].bound(t);
        let p = self
            .texture(t, name)
            .ok_or(GlErrorKind::InvalidOperation)?
            .params;
        Ok(match pname {
            r::TEXTURE_MIN_FILTER => enm(p.min_filter),
            r::TEXTURE_MAG_FILTER => enm(p.mag_filter),
            r::TEXTURE_WRAP_S => enm(p.wrap_s),
            r::TEXTURE_WRAP_T => enm(p.wrap_t),
            r::TEXTURE_WRAP_R => enm(p.wrap_r),
            r::TEXTURE_BORDER_COLOR => normalized(&p.border_color.to_array()),
            r::TEXTURE_COMPARE_MODE => enm(p.compare_mode),
            r::TEXTURE_COMPARE_FUNC => enm(p.compare_func),
            r::DEPTH_TEXTURE_MODE => enm(p.depth_texture_mode),
            r::GENERATE_MIPMAP => boolean(p.generate_mipmap),
            TEXTURE_COMPARE_FAIL_VALUE_ARB => floats(&[p.compare_fail_value]),
            r::TEXTURE_BASE_LEVEL => int(p.base_level),
            r::TEXTURE_MAX_LEVEL => int(p.max_level),
            r::TEXTURE_MIN_LOD => vec![QueryValue::Saturated(p.min_lod)],
            r::TEXTURE_MAX_LOD => vec![QueryValue::Saturated(p.max_lod)],
            r::TEXTURE_LOD_BIAS => vec![QueryValue::Saturated(p.lod_bias)],
            r::TEXTURE_MAX_ANISOTROPY_EXT => vec![QueryValue::Saturated(p.max_anisotropy)],
            // As an integer, the colour-style conversion (Mesa: 1 → INT_MAX).
            r::TEXTURE_PRIORITY => normalized(&[p.priority]),
            // Every texture is resident.
            r::TEXTURE_RESIDENT => boolean(true),
            _ => return Err(GlErrorKind::InvalidEnum),
        })
    }

    /// glGetTexLevelParameter{f,i}v(target, level, pname) of the texture bound to `target`
    /// on the active unit, or of a proxy target's levels (`texture_volume`). A level
    /// outside [0, log2 MAX_TEXTURE_SIZE] (3D: MAX_3D_TEXTURE_SIZE) is INVALID_VALUE; an
    /// unspecified level answers 0 for everything but the internal format, which is RGBA
    /// (Mesa, after GL 4.0; GL 1.5 says 1). The internal format is the one the program named,
    /// as Mesa answers it (3, GL_RGBA, GL_RGB5: `TexLevel::requested`), a compressed
    /// level's format, or the sized name of a level the layer made (mipmaps take their
    /// base's). Component sizes are those of Mesa's llvmpipe formats, 0 for components the
    /// base format lacks.
    pub fn get_tex_level_parameter(
        &self,
        target: u32,
        level: i32,
        pname: u32,
    ) -> Result<Queried, GlErrorKind> {
        // A cube map's levels are its faces' (TEXTURE_CUBE_MAP itself: INVALID_ENUM, Mesa).
        let proxy = match target {
            r::PROXY_TEXTURE_1D => Some(&self.proxy_1d),
            r::PROXY_TEXTURE_2D => Some(&self.proxy_2d),
            r::PROXY_TEXTURE_CUBE_MAP => Some(&self.proxy_cube_map),
            r::PROXY_TEXTURE_3D => Some(&self.proxy_3d),
            _ => None,
        };
        let (object, image) = if let Some(p) = proxy {
            (p, p.target)
        } else {
            let t = TextureTarget::from_gl_value(target)
                .filter(|t| *t != TextureTarget::CubeMap)
                .ok_or(GlErrorKind::InvalidEnum)?;
            let name = self.units[self.active_unit()].bound(t);
            let object = self.texture(t, name).ok_or(GlErrorKind::InvalidOperation)?;
            (object, t)
        };
        if !(0..=object.target.max_level()).contains(&level) {
            return Err(GlErrorKind::InvalidValue);
        }
        let l = object.level_in(image, level);
        let format = l.map(|l| l.internal_format);
        let compressed = l.and_then(|l| l.compressed.as_ref());
        // A compressed level's sizes are Mesa's for S3TC: 4 bits a colour component, alpha
        // 4 bits but in RGB_DXT1.
        let size = |component: Component| match compressed {
            Some(c) => int(match component {
                Component::Red | Component::Green | Component::Blue => 4,
                Component::Alpha if c.format.has_alpha() => 4,
                _ => 0,
            }),
            None => int(
                match l
                    .and_then(|l| l.requested)
                    .and_then(super::texture_storage::stored_bits)
                {
                    Some(b) => match component {
                        Component::Red => b.red,
                        Component::Green => b.green,
                        Component::Blue => b.blue,
                        Component::Alpha => b.alpha,
                        Component::Luminance => b.luminance,
                        Component::Intensity => b.intensity,
                        Component::Depth => 0,
                    },
                    None => format.map_or(0, |f| bits(f, component)),
                },
            ),
        };
        Ok(match pname {
            r::TEXTURE_WIDTH => int(l.map_or(0, |l| l.width)),
            r::TEXTURE_HEIGHT => int(l.map_or(0, |l| l.height)),
            r::TEXTURE_DEPTH => int(l.map_or(0, |l| l.depth)),
            r::TEXTURE_BORDER => int(l.map_or(0, |l| l.border)),
            r::TEXTURE_INTERNAL_FORMAT => {
                vec![QueryValue::Enum(l.map_or(r::RGBA, TexLevel::named_format))]
            }
            r::TEXTURE_RED_SIZE => size(Component::Red),
            r::TEXTURE_GREEN_SIZE => size(Component::Green),
            r::TEXTURE_BLUE_SIZE => size(Component::Blue),
            r::TEXTURE_ALPHA_SIZE => size(Component::Alpha),
            r::TEXTURE_LUMINANCE_SIZE => size(Component::Luminance),
            r::TEXTURE_INTENSITY_SIZE => size(Component::Intensity),
            r::TEXTURE_DEPTH_SIZE => size(Component::Depth),
            r::TEXTURE_COMPRESSED => boolean(compressed.is_some()),
            // INVALID_OPERATION for a level that is not compressed (Mesa, measured).
            r::TEXTURE_COMPRESSED_IMAGE_SIZE => match compressed {
                Some(c) => count(c.bytes.len()),
                None => return Err(GlErrorKind::InvalidOperation),
            },
            _ => return Err(GlErrorKind::InvalidEnum),
        })
    }
}

/// The components glGetTexLevelParameter reports sizes of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Component {
    Red,
    Green,
    Blue,
    Alpha,
    Luminance,
    Intensity,
    Depth,
}

/// TEXTURE_*_SIZE of a format: 8 bits per component of the 8-bit formats, the depth
/// formats' bits, 0 for a component the base format does not have.
fn bits(f: TexFormat, c: Component) -> i32 {
    use Component as C;
    match (f, c) {
        (TexFormat::Rgba8, C::Red | C::Green | C::Blue | C::Alpha)
        | (TexFormat::Rgb8, C::Red | C::Green | C::Blue)
        | (TexFormat::Luminance8, C::Luminance)
        | (TexFormat::Intensity8, C::Intensity)
        | (TexFormat::Alpha8, C::Alpha)
        | (TexFormat::Luminance8Alpha8, C::Luminance | C::Alpha) => 8,
        (TexFormat::DepthComponent16, C::Depth) => 16,
        (TexFormat::DepthComponent24, C::Depth) => 24,
        (TexFormat::DepthComponent32F, C::Depth) => 32,
        (TexFormat::Rgba32F, C::Red | C::Green | C::Blue | C::Alpha) => 32,
        _ => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::{Command, Face, LightParam, MaterialParam};
    use glam::Vec4;

    /// GL 1.5 §6.1.2 as Mesa converts, at the boundaries.
    #[test]
    fn floats_become_ints_by_mesa_s_three_rules() {
        // lroundf into a long, its low 32 bits kept (queries and glPixelStoref).
        assert_eq!(round_to_int(2.5), 3);
        assert_eq!(round_to_int(-2.5), -3);
        assert_eq!(round_to_int(-0.4), 0);
        assert_eq!(round_to_int(5e9), 705_032_704);
        assert_eq!(round_to_int(3e9), -1_294_967_296);
        for v in [1e20, -1e20, f64::NAN, f64::INFINITY] {
            assert_eq!(round_to_int(v), 0, "{v}");
        }
        // Rounded and clamped (a texture's LOD parameters).
        assert_eq!(saturated_round(2.5), 3);
        assert_eq!(saturated_round(1e10), i32::MAX);
        assert_eq!(saturated_round(-1e10), i32::MIN);
        assert_eq!(saturated_round(f32::NAN), i32::MIN);
        // C's cast (the environment's LOD bias).
        assert_eq!(c_int(2.5), 2);
        assert_eq!(c_int(1e10), i32::MIN);
    }

    #[test]
    fn conversions_at_their_boundaries() {
        let n = QueryValue::Normalized;
        assert_eq!(n(1.0).as_int(), 2_147_483_647);
        assert_eq!(n(-1.0).as_int(), -2_147_483_647);
        assert_eq!(n(0.0).as_int(), 0);
        assert_eq!(n(0.5).as_int(), 1_073_741_823);
        assert_eq!(
            n(2.0).as_int(),
            i32::MIN,
            "outside [-1, 1]: x86-64's indefinite"
        );
        assert_eq!(n(f32::NAN).as_int(), i32::MIN);
        let f = QueryValue::Float;
        assert_eq!(f(0.5).as_int(), 1, "halves away from zero");
        assert_eq!(f(-0.5).as_int(), -1);
        assert_eq!(f(2.5).as_int(), 3);
        assert_eq!(f(1.4999).as_int(), 1);
        assert_eq!(f(f32::NAN).as_int(), 0, "lroundf's LONG_MIN, low 32 bits");
        assert_eq!(f(f32::INFINITY).as_int(), 0);
        assert_eq!(f(4_294_967_296.0 + 512.0).as_int(), 512, "wraps modulo 2³²");
        let t = QueryValue::Truncated;
        assert_eq!(t(1.9).as_int(), 1);
        assert_eq!(t(-1.9).as_int(), -1);
        assert_eq!(t(f32::NAN).as_int(), i32::MIN);
        // Booleans.
        assert!(f(f32::NAN).as_bool(), "C truth");
        assert!(!f(0.0).as_bool());
        assert!(!f(-0.0).as_bool());
        assert!(n(0.25).as_bool());
        assert!(QueryValue::Int(-1).as_bool());
        assert_eq!(QueryValue::Bool(true).as_int(), 1);
        assert_eq!(QueryValue::Bool(true).as_float(), 1.0);
        assert_eq!(QueryValue::Enum(r::LESS).as_float(), 513.0);
        assert_eq!(QueryValue::Int(-1).as_double(), -1.0);
        assert_eq!(
            QueryValue::UInt(u32::MAX).as_int(),
            i32::MAX,
            "Mesa's TYPE_UINT"
        );
        assert_eq!(QueryValue::UInt(u32::MAX).as_double(), 4_294_967_295.0);
    }

    #[test]
    fn defaults_answer_the_initial_state() {
        let s = FixedState::new();
        let ints = |p| -> Vec<i32> { s.get(p).unwrap().iter().map(|v| v.as_int()).collect() };
        assert_eq!(ints(r::MATRIX_MODE), vec![r::MODELVIEW as i32]);
        assert_eq!(ints(r::CURRENT_COLOR), vec![i32::MAX; 4]);
        assert_eq!(ints(r::MODELVIEW_STACK_DEPTH), vec![1]);
        assert_eq!(ints(r::MAX_ATTRIB_STACK_DEPTH), vec![16]);
        assert_eq!(ints(r::STENCIL_VALUE_MASK), vec![255]);
        assert_eq!(ints(r::POLYGON_MODE), vec![r::FILL as i32; 2]);
        assert_eq!(ints(r::LIGHT0), vec![0]);
        assert_eq!(s.get_integerv(r::MAX_LIGHTS), Ok(vec![8]));
        assert_eq!(s.get_booleanv(r::DEPTH_WRITEMASK), Ok(vec![true]));
        assert_eq!(s.get_floatv(r::LINE_WIDTH), Ok(vec![1.0]));
        assert_eq!(s.get_doublev(r::DEPTH_RANGE), Ok(vec![0.0, 1.0]));
        assert_eq!(s.is_enabled(r::LIGHT0 + 7), Ok(false));
        assert_eq!(s.is_enabled(r::LIGHT0 + 8), Err(GlErrorKind::InvalidEnum));
        assert_eq!(s.get_floatv(r::ACCUM_CLEAR_VALUE), Ok(vec![0.0; 4]));
        assert_eq!(s.get_integerv(r::ACCUM_RED_BITS), Ok(vec![0]));
        assert_eq!(s.get(0xFFFF_FFFF), Err(GlErrorKind::InvalidEnum));
        // Every table entry answers, with a distinct pname.
        let all = pnames();
        for p in &all {
            assert!(
                s.get(*p).is_ok_and(|v| !v.is_empty()),
                "{:?}",
                pname_name(*p)
            );
        }
        let mut sorted = all.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), all.len());
    }

    #[test]
    fn object_getters_check_their_arguments() {
        let mut s = FixedState::new();
        s.apply(&Command::Light {
            light: 1,
            param: LightParam::Position(Vec4::new(1.7, -2.7, 3.0, 1.0)),
        })
        .unwrap();
        let pos = s.get_light(r::LIGHT0 + 1, r::POSITION).unwrap();
        let ints: Vec<i32> = pos.iter().map(|v| v.as_int()).collect();
        assert_eq!(ints, vec![1, -2, 3, 1], "glGetLightiv truncates (Mesa)");
        assert_eq!(
            s.get_light(r::LIGHT0 + 8, r::POSITION),
            Err(GlErrorKind::InvalidEnum)
        );
        assert_eq!(
            s.get_material(r::FRONT_AND_BACK, r::AMBIENT),
            Err(GlErrorKind::InvalidEnum)
        );
        s.apply(&Command::Material {
            face: Face::Back,
            param: MaterialParam::Shininess(10.5),
        })
        .unwrap();
        let sh = s.get_material(r::BACK, r::SHININESS).unwrap();
        assert_eq!(sh[0].as_int(), 11);
        assert_eq!(
            s.get_tex_level_parameter(r::TEXTURE_2D, -1, r::TEXTURE_WIDTH),
            Err(GlErrorKind::InvalidValue)
        );
        let f = s
            .get_tex_level_parameter(r::TEXTURE_2D, 0, r::TEXTURE_INTERNAL_FORMAT)
            .unwrap();
        assert_eq!(f, vec![QueryValue::Enum(r::RGBA)]);
        assert_eq!(
            s.get_tex_env(r::TEXTURE_2D, r::TEXTURE_ENV_MODE),
            Err(GlErrorKind::InvalidEnum)
        );
        assert_eq!(
            s.get_tex_gen(r::S, r::TEXTURE_GEN_MODE).unwrap(),
            vec![QueryValue::Enum(r::EYE_LINEAR)]
        );
    }
}
