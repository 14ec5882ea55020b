//! `FixedState`: the GL 1.x fixed-function state, every field at its GL initial value.
//!
//! Change it only through [`FixedState::apply`] (in `apply.rs`), which follows GL's error
//! semantics; read it freely. Values whose enable is separate in GL are [`Toggle`]s, so
//! disabling keeps the parameters and `toggle.get()` gives the `Option` a shader key wants.

use std::collections::BTreeMap;

use glam::{Mat4, Vec3, Vec4};

use super::attrib::AttribFrame;
use super::combiners::RegisterCombiners;
use super::command::EvalEnables;
use super::error::GlError;
use super::fog::Fog;
use super::fragment::{
    AlphaTest, Blend, ClearValues, ColorMask, DepthRange, DepthTest, Face, FrontFace, Hints,
    LogicOp, OffsetEnables, PolygonMode, ScissorBox, ShadeModel, StencilTest, Toggle, Viewport,
};
use super::framebuffer::Framebuffers;
use super::light::{ColorMaterial, Light, LightModel, Materials, MAX_LIGHTS};
use super::matrix::{
    MatrixMode, MatrixStack, MODELVIEW_STACK_DEPTH, PROJECTION_STACK_DEPTH, TEXTURE_STACK_DEPTH,
};
use super::pixels::{PixelTransfer, PixelZoom};
use super::point::{PointParams, PointSprite};
use super::raster::RasterPos;
use super::sample_coverage::SampleCoverage;
use super::stipple::{LineStipple, PolygonStipple};
use super::texenv::TexEnv;
use super::texgen::{TexCoord, TexGen};
use super::texture::{TexFormat, TextureObject, TextureTarget};
use crate::vocab::PolygonOffset;

/// GL_MAX_TEXTURE_UNITS modelled: texgen, env, matrices and coordinates for 8 units (the
/// pipelines need at least 4 image units).
pub const MAX_TEXTURE_UNITS: usize = 8;

/// GL_MAX_CLIP_PLANES modelled: Mesa's 8 (measured on llvmpipe's compatibility context,
/// `tests/fidelity_clip_planes.rs`; GL 1.5 asks for at least 6).
pub const MAX_CLIP_PLANES: usize = 8;

/// The antialiasing enables (GL 1.5 §3.3, §3.4.2, §3.5.4). GL default: all FALSE.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Smoothing {
    pub point: bool,
    pub line: bool,
    pub polygon: bool,
}

/// The current vertex values (glColor, glNormal, glMultiTexCoord).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurrentValues {
    /// GL default: (1, 1, 1, 1).
    pub color: Vec4,
    /// GL default: (0, 0, 1).
    pub normal: Vec3,
    /// GL default: (0, 0, 0, 1) on every unit.
    pub texcoords: [Vec4; MAX_TEXTURE_UNITS],
    /// glEdgeFlag: whether an edge starting at a vertex is a boundary edge of its
    /// polygon (GL 1.5 §2.6.2). GL default: TRUE.
    pub edge_flag: bool,
    /// glSecondaryColor (GL 1.4 §2.7), unclamped as given; alpha is 1 unless a size-4
    /// SECONDARY_COLOR_ARRAY element set it (glArrayElement, as Mesa keeps it). GL
    /// default: (0, 0, 0, 1).
    pub secondary_color: Vec4,
    /// glFogCoord (GL 1.4 §2.7), as given. GL default: 0.
    pub fog_coord: f32,
    /// glIndex: the current colour index, as given (`color_index`). GL default: 1.
    pub index: f32,
}

impl CurrentValues {
    pub const DEFAULT: Self = Self {
        color: Vec4::ONE,
        normal: Vec3::Z,
        texcoords: [Vec4::W; MAX_TEXTURE_UNITS],
        edge_flag: true,
        secondary_color: Vec4::W,
        fog_coord: 0.0,
        index: 1.0,
    };
}

/// Front and back polygon modes. GL default: FILL, FILL.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct PolygonModes {
    pub front: PolygonMode,
    pub back: PolygonMode,
}

/// One texture unit's state (apart from its matrix stack).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TextureUnit {
    /// TEXTURE_1D enable. GL default: FALSE.
    pub texture_1d: bool,
    /// TEXTURE_2D enable. GL default: FALSE.
    pub texture_2d: bool,
    /// TEXTURE_3D enable (GL 1.2). GL default: FALSE.
    pub texture_3d: bool,
    /// TEXTURE_CUBE_MAP enable (GL 1.3). GL default: FALSE.
    pub texture_cube_map: bool,
    /// Names bound to TEXTURE_1D, TEXTURE_2D and TEXTURE_3D. GL default: 0 (the default
    /// textures).
    pub bound_1d: u32,
    pub bound_2d: u32,
    pub bound_3d: u32,
    /// The name bound to TEXTURE_CUBE_MAP (GL 1.3). GL default: 0.
    pub bound_cube_map: u32,
    /// GL default: [`TexEnv::DEFAULT`].
    pub env: TexEnv,
    /// S, T, R, Q. GL default: disabled, EYE_LINEAR, planes per [`TexGen::default_for`].
    pub texgen: [Toggle<TexGen>; 4],
}

impl TextureUnit {
    pub fn new() -> Self {
        Self {
            texture_1d: false,
            texture_2d: false,
            texture_3d: false,
            texture_cube_map: false,
            bound_1d: 0,
            bound_2d: 0,
            bound_3d: 0,
            bound_cube_map: 0,
            env: TexEnv::DEFAULT,
            texgen: TexCoord::ALL.map(|c| Toggle::off(TexGen::default_for(c))),
        }
    }

    /// The target that texturing uses: the cube map wins over 3D, 3D over 2D, 2D over 1D
    /// (GL 1.5 §3.8.15); `None` = unit off.
    pub fn enabled_target(&self) -> Option<TextureTarget> {
        self.enabled_targets().next()
    }

    /// The enabled targets, highest priority first (cube map, 3D, 2D, 1D).
    pub fn enabled_targets(&self) -> impl Iterator<Item = TextureTarget> + '_ {
        [
            (self.texture_cube_map, TextureTarget::CubeMap),
            (self.texture_3d, TextureTarget::Texture3D),
            (self.texture_2d, TextureTarget::Texture2D),
            (self.texture_1d, TextureTarget::Texture1D),
        ]
        .into_iter()
        .filter_map(|(on, target)| on.then_some(target))
    }

    /// The name bound to `target` (a cube face's: the cube map's).
    pub fn bound(&self, target: TextureTarget) -> u32 {
        match target {
            TextureTarget::Texture1D => self.bound_1d,
            TextureTarget::Texture2D => self.bound_2d,
            TextureTarget::Texture3D => self.bound_3d,
            TextureTarget::CubeMap | TextureTarget::CubeFace(_) => self.bound_cube_map,
        }
    }

    pub fn texgen(&self, coord: TexCoord) -> Option<TexGen> {
        self.texgen[coord.index()].get()
    }
}

impl Default for TextureUnit {
    fn default() -> Self {
        Self::new()
    }
}

/// The whole fixed-function state.
#[derive(Debug, Clone, PartialEq)]
pub struct FixedState {
    /// The sticky error flag (glGetError). GL default: NO_ERROR.
    pub(crate) error: Option<GlError>,

    /// GL default: MODELVIEW.
    pub matrix_mode: MatrixMode,
    /// Depth 32; GL default: one identity matrix.
    pub modelview: MatrixStack,
    /// Depth 2; GL default: one identity matrix.
    pub projection: MatrixStack,
    /// Depth 2 per unit; GL default: one identity matrix each.
    pub texture_matrices: [MatrixStack; MAX_TEXTURE_UNITS],
    /// GL default: the window; here (0, 0, 0, 0) until set.
    pub viewport: Viewport,
    /// GL default: [0, 1].
    pub depth_range: DepthRange,

    pub current: CurrentValues,

    /// LIGHTING. GL default: FALSE.
    pub lighting: bool,
    /// LIGHT0..7. GL default: disabled, [`Light::default_for`].
    pub lights: [Toggle<Light>; MAX_LIGHTS],
    pub light_model: LightModel,
    pub materials: Materials,
    /// COLOR_MATERIAL. GL default: disabled, FRONT_AND_BACK, AMBIENT_AND_DIFFUSE.
    pub color_material: Toggle<ColorMaterial>,
    /// GL default: SMOOTH.
    pub shade_model: ShadeModel,
    /// NORMALIZE. GL default: FALSE.
    pub normalize: bool,
    /// RESCALE_NORMAL. GL default: FALSE.
    pub rescale_normal: bool,

    /// ACTIVE_TEXTURE as an index. GL default: 0 (TEXTURE0).
    pub active_texture: usize,
    pub units: [TextureUnit; MAX_TEXTURE_UNITS],
    /// Texture objects by name (≠ 0), created by their first glBindTexture.
    pub textures: BTreeMap<u32, TextureObject>,
    /// Framebuffer objects, renderbuffers, their bindings and the colour buffers drawn
    /// and read. GL default: the window bound, FRONT.
    pub framebuffers: Framebuffers,
    /// Query objects and the active occlusion query. GL default: none, none active.
    pub queries: super::queries::Queries,
    /// The default (name 0) textures of TEXTURE_1D, TEXTURE_2D and TEXTURE_3D.
    pub default_1d: TextureObject,
    pub default_2d: TextureObject,
    pub default_3d: TextureObject,
    /// The default TEXTURE_CUBE_MAP (GL 1.3).
    pub default_cube_map: TextureObject,
    /// PROXY_TEXTURE_1D's, _2D's, _CUBE_MAP's and _3D's levels (GL 1.5 §3.8.11): what
    /// glTexImage on the proxy target found acceptable, every field 0 where it did not; no
    /// unit samples them. GL default: no level specified.
    pub proxy_1d: TextureObject,
    pub proxy_2d: TextureObject,
    pub proxy_cube_map: TextureObject,
    pub proxy_3d: TextureObject,

    /// REGISTER_COMBINERS_NV. GL default: disabled, [`RegisterCombiners::DEFAULT`].
    pub register_combiners: Toggle<RegisterCombiners>,

    /// ALPHA_TEST. GL default: disabled, ALWAYS, 0.
    pub alpha_test: Toggle<AlphaTest>,
    /// DEPTH_TEST. GL default: disabled, LESS, mask TRUE.
    pub depth_test: Toggle<DepthTest>,
    /// STENCIL_TEST. GL default: disabled, [`StencilTest::DEFAULT`].
    pub stencil_test: Toggle<StencilTest>,
    /// BLEND. GL default: disabled, ONE, ZERO (RGB and alpha), FUNC_ADD.
    pub blend: Toggle<Blend>,
    /// glBlendColor's constant colour c, clamped to [0, 1] when set. GL default: (0,0,0,0).
    pub blend_color: Vec4,
    /// GL default: all TRUE.
    pub color_mask: ColorMask,
    /// GL default: factor 0, units 0.
    pub polygon_offset: PolygonOffset,
    /// POLYGON_OFFSET_FILL/LINE/POINT. GL default: all FALSE.
    pub offset_enables: OffsetEnables,
    /// GL default: FILL, FILL.
    pub polygon_mode: PolygonModes,
    /// CULL_FACE with glCullFace. GL default: disabled, BACK.
    pub cull_face: Toggle<Face>,
    /// GL default: CCW.
    pub front_face: FrontFace,
    /// POLYGON_STIPPLE with glPolygonStipple's mask (`stipple`). GL default: disabled,
    /// every bit 1.
    pub polygon_stipple: Toggle<PolygonStipple>,
    /// GL default: 1.
    pub line_width: f32,
    /// LINE_STIPPLE with glLineStipple's factor and pattern (`stipple`). GL default:
    /// disabled, factor 1, pattern 0xFFFF.
    pub line_stipple: Toggle<LineStipple>,
    /// GL default: 1.
    pub point_size: f32,
    /// glPointParameter's sizes, threshold and attenuation (`point`).
    pub point_params: PointParams,
    /// POINT_SPRITE and the units' COORD_REPLACE (`point`).
    pub point_sprite: PointSprite,
    /// POINT_SMOOTH, LINE_SMOOTH, POLYGON_SMOOTH. GL default: all FALSE.
    pub smooth: Smoothing,
    /// COLOR_SUM. GL default: FALSE (no effect without a secondary colour: Capability).
    pub color_sum: bool,
    /// MULTISAMPLE. GL default: TRUE (no effect on single-sample buffers).
    pub multisample: bool,
    /// glSampleCoverage and the sample enables (`sample_coverage`): state only.
    pub sample_coverage: SampleCoverage,
    /// glClearIndex, as Mesa stores it (`color_index`). GL default: 0.
    pub clear_index: u32,
    /// glIndexMask. GL default: all ones.
    pub index_mask: u32,
    /// GL default: colour (0,0,0,0), depth 1, stencil 0.
    pub clear: ClearValues,

    /// glPushAttrib entries (`attrib`). GL default: empty.
    pub(crate) attrib_stack: Vec<AttribFrame>,
    /// FOG. GL default: disabled, EXP, density 1, start 0, end 1, colour (0,0,0,0); the
    /// distance is |z_eye| (FOG_COORDINATE_SOURCE = FRAGMENT_DEPTH, as Mesa computes it).
    pub fog: Toggle<Fog>,
    /// SCISSOR_TEST with glScissor's box. GL default: disabled, (0, 0, window width, window
    /// height). The model does not know the window: `None` = never set = the whole target,
    /// so an enabled test without a box restricts nothing.
    pub scissor: Toggle<Option<ScissorBox>>,
    /// CLIP_PLANEi with glClipPlane's plane in eye coordinates (§2.12): stored already
    /// multiplied by the inverse of the modelview current when it was specified,
    /// p′ = p·M⁻¹; a vertex is kept where p′·(x_e, y_e, z_e, w_e)ᵀ ≥ 0. GL default: all
    /// disabled, (0, 0, 0, 0).
    pub clip_planes: [Toggle<Vec4>; MAX_CLIP_PLANES],
    /// COLOR_LOGIC_OP with glLogicOp. GL default: disabled, COPY. While enabled, blending
    /// is not applied (§4.1.10).
    pub logic_op: Toggle<LogicOp>,
    /// INDEX_LOGIC_OP. GL default: FALSE; no effect on an RGBA framebuffer.
    pub index_logic_op: bool,
    /// DITHER (§4.1.9). GL default: TRUE. State only: an 8-bit target has nothing to
    /// dither on llvmpipe, and the emulated path leaves core GL's own DITHER as it is.
    pub dither: bool,
    /// AUTO_NORMAL and the MAPn_* enables; state only.
    pub eval: EvalEnables,
    /// glHint. GL default: DONT_CARE for every target; state only.
    pub hints: Hints,
    /// LIST_BASE (glListBase), LIST_BIT state: the front end adds it to glCallLists'
    /// names. GL default: 0.
    pub list_base: u32,
    /// CURRENT_RASTER_* (`raster`). GL default: [`RasterPos::DEFAULT`].
    pub raster: RasterPos,
    /// glPixelTransfer (`pixels`). GL default: [`PixelTransfer::DEFAULT`].
    pub pixel_transfer: PixelTransfer,
    /// glPixelMap (`pixel_map`). GL default: each map one entry of 0.
    pub pixel_maps: super::pixel_map::PixelMaps,
    /// glPixelZoom. GL default: (1, 1).
    pub pixel_zoom: PixelZoom,
    /// The last geometry a draw found valid (a memo, not GL state).
    pub(crate) validated_draw: super::geometry::ValidatedDraw,
}

impl Default for FixedState {
    fn default() -> Self {
        Self::new()
    }
}

impl FixedState {
    /// The GL initial state.
    pub fn new() -> Self {
        Self {
            error: None,
            matrix_mode: MatrixMode::Modelview,
            modelview: MatrixStack::new(MODELVIEW_STACK_DEPTH),
            projection: MatrixStack::new(PROJECTION_STACK_DEPTH),
            texture_matrices: std::array::from_fn(|_| MatrixStack::new(TEXTURE_STACK_DEPTH)),
            viewport: Viewport::default(),
            depth_range: DepthRange::DEFAULT,
            current: CurrentValues::DEFAULT,
            lighting: false,
            lights: std::array::from_fn(|i| Toggle::off(Light::default_for(i))),
            light_model: LightModel::DEFAULT,
            materials: Materials::DEFAULT,
            color_material: Toggle::off(ColorMaterial::DEFAULT),
            shade_model: ShadeModel::Smooth,
            normalize: false,
            rescale_normal: false,
            active_texture: 0,
            units: [TextureUnit::new(); MAX_TEXTURE_UNITS],
            textures: BTreeMap::new(),
            framebuffers: Framebuffers::default(),
            queries: Default::default(),
            default_1d: TextureObject::new(TextureTarget::Texture1D),
            default_2d: TextureObject::new(TextureTarget::Texture2D),
            default_3d: TextureObject::new(TextureTarget::Texture3D),
            default_cube_map: TextureObject::new(TextureTarget::CubeMap),
            proxy_1d: TextureObject::new(TextureTarget::Texture1D),
            proxy_2d: TextureObject::new(TextureTarget::Texture2D),
            proxy_cube_map: TextureObject::new(TextureTarget::CubeMap),
            proxy_3d: TextureObject::new(TextureTarget::Texture3D),
            register_combiners: Toggle::off(RegisterCombiners::DEFAULT),
            alpha_test: Toggle::off(AlphaTest::DEFAULT),
            depth_test: Toggle::off(DepthTest::LESS_WRITE),
            stencil_test: Toggle::off(StencilTest::DEFAULT),
            blend: Toggle::off(Blend::ONE_ZERO),
            blend_color: Vec4::ZERO,
            color_mask: ColorMask::ALL,
            polygon_offset: PolygonOffset {
                factor: 0.0,
                units: 0.0,
            },
            offset_enables: OffsetEnables::default(),
            polygon_mode: PolygonModes {
                front: PolygonMode::Fill,
                back: PolygonMode::Fill,
            },
            cull_face: Toggle::off(Face::Back),
            front_face: FrontFace::Ccw,
            polygon_stipple: Toggle::off(PolygonStipple::DEFAULT),
            line_width: 1.0,
            line_stipple: Toggle::off(LineStipple::DEFAULT),
            point_size: 1.0,
            point_params: PointParams::DEFAULT,
            point_sprite: PointSprite::default(),
            clear: ClearValues::DEFAULT,
            attrib_stack: Vec::new(),
            fog: Toggle::off(Fog::DEFAULT),
            scissor: Toggle::off(None),
            clip_planes: [Toggle::off(Vec4::ZERO); MAX_CLIP_PLANES],
            logic_op: Toggle::off(LogicOp::Copy),
            index_logic_op: false,
            dither: true,
            eval: EvalEnables::default(),
            smooth: Smoothing::default(),
            color_sum: false,
            multisample: true,
            sample_coverage: SampleCoverage::DEFAULT,
            clear_index: 0,
            index_mask: u32::MAX,
            hints: Hints::DEFAULT,
            list_base: 0,
            raster: RasterPos::DEFAULT,
            pixel_transfer: PixelTransfer::DEFAULT,
            pixel_maps: Default::default(),
            pixel_zoom: PixelZoom::DEFAULT,
            validated_draw: Default::default(),
        }
    }

    /// glGetError without clearing: the first error since the last read.
    pub fn error(&self) -> Option<GlError> {
        self.error
    }

    /// glGetError: returns and clears the pending error.
    pub fn take_error(&mut self) -> Option<GlError> {
        self.error.take()
    }

    /// The active texture unit's index, always < MAX_TEXTURE_UNITS.
    pub fn active_unit(&self) -> usize {
        self.active_texture.min(MAX_TEXTURE_UNITS - 1)
    }

    /// The box the scissor test restricts fragments and clears to: `None` when the test is
    /// off or the box was never set (the whole target).
    pub fn scissor_box(&self) -> Option<ScissorBox> {
        self.scissor.get().flatten()
    }

    /// The current modelview matrix.
    pub fn modelview_matrix(&self) -> Mat4 {
        self.modelview.top()
    }

    /// The current projection matrix.
    pub fn projection_matrix(&self) -> Mat4 {
        self.projection.top()
    }

    /// The current texture matrix of `unit` (identity for a unit out of range).
    pub fn texture_matrix(&self, unit: usize) -> Mat4 {
        self.texture_matrices
            .get(unit)
            .map_or(Mat4::IDENTITY, MatrixStack::top)
    }

    /// The texture object `name` of `target` (0 = the default texture); a cube face's is
    /// its cube map.
    pub fn texture(&self, target: TextureTarget, name: u32) -> Option<&TextureObject> {
        let target = target.binding();
        match (name, target) {
            (0, TextureTarget::Texture1D) => Some(&self.default_1d),
            (0, TextureTarget::Texture2D) => Some(&self.default_2d),
            (0, TextureTarget::Texture3D) => Some(&self.default_3d),
            (0, TextureTarget::CubeMap) => Some(&self.default_cube_map),
            _ => self.textures.get(&name).filter(|t| t.target == target),
        }
    }

    /// The texture bound to `target` on the active unit.
    pub(crate) fn bound_texture_mut(
        &mut self,
        target: TextureTarget,
    ) -> super::GlResult<&mut TextureObject> {
        let name = self.units[self.active_unit()].bound(target);
        self.texture_mut(target, name)
            .ok_or(super::GlError::invalid_operation(
                "bound name belongs to another target",
            ))
    }

    pub(crate) fn texture_mut(
        &mut self,
        target: TextureTarget,
        name: u32,
    ) -> Option<&mut TextureObject> {
        let target = target.binding();
        match (name, target) {
            (0, TextureTarget::Texture1D) => Some(&mut self.default_1d),
            (0, TextureTarget::Texture2D) => Some(&mut self.default_2d),
            (0, TextureTarget::Texture3D) => Some(&mut self.default_3d),
            (0, TextureTarget::CubeMap) => Some(&mut self.default_cube_map),
            _ => self.textures.get_mut(&name).filter(|t| t.target == target),
        }
    }

    /// The texture a unit samples when drawing: its enabled target's bound object.
    pub fn enabled_texture(&self, unit: usize) -> Option<&TextureObject> {
        self.sampled_texture(unit).map(|(_, t, _)| t)
    }

    /// The target a unit samples and its texture: of the enabled targets, in the order
    /// cube map, 3D, 2D, 1D, the first whose bound texture is complete — Mesa's rule
    /// (`_mesa_update_texture_unit_state`, measured: a stray glEnable(TEXTURE_CUBE_MAP)
    /// over a complete 2D texture leaves the 2D texture drawn). GL 1.5 §3.8.15 takes the
    /// highest enabled target alone and turns the unit off when it is incomplete. None: no
    /// enabled target has a complete texture, the unit is off. With the target and the
    /// texture, the format its completeness gave.
    pub fn sampled_texture(
        &self,
        unit: usize,
    ) -> Option<(TextureTarget, &TextureObject, TexFormat)> {
        let u = self.units.get(unit)?;
        u.enabled_targets().find_map(|target| {
            let texture = self.texture(target, u.bound(target))?;
            let format = texture.completeness().ok()?;
            Some((target, texture, format))
        })
    }

    /// The stack matrix commands act on (the texture stack of the active unit for TEXTURE).
    pub(crate) fn current_stack_mut(&mut self) -> &mut MatrixStack {
        match self.matrix_mode {
            MatrixMode::Modelview => &mut self.modelview,
            MatrixMode::Projection => &mut self.projection,
            MatrixMode::Texture => &mut self.texture_matrices[self.active_unit()],
        }
    }
}
