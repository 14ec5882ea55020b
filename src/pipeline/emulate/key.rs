//! `ShaderKey::from_state`: everything in the fixed-function state that changes the *shape*
//! of the generated code, and nothing else. Values (matrices, planes, colours, the alpha
//! reference, the env colour) are uniforms; disabled units, lights and tests are absent
//! from the key, so toggling them off can never cause a recompile of an unrelated program.
//! State that is set but not read — the arguments a combine function ignores, the env of a
//! unit under register combiners, NORMALIZE without lighting or sphere mapping, a back-face
//! COLOR_MATERIAL without two-sided lighting — enters the key as one fixed value, so the
//! rule holds both ways: equal code ⇔ equal key (`key_tests` checks it case by case).

use super::pixel_fan::PixelFan;
use super::polygon::EdgeRule;
use crate::ff::{
    AlphaTest, BaseFormat, ColorControl, ColorMaterialMode, Combine, CombineFunc, CombineOperand,
    CombineScale, CombineSource, CombinerInput, CompareFunc, CompareMode, DepthTextureMode, Face,
    Filter, FixedState, FogCoordSource, FogMode, GeneralStage, ShadeModel, TexCoord, TexEnvMode,
    TexFormat, TexGenMode, TexParams, TextureTarget, Wrap, MAX_CLIP_PLANES, MAX_LIGHTS,
    MAX_TEXTURE_UNITS,
};
use crate::vocab::Precision;

/// Where a vertex colour comes from when lighting is on (COLOR_MATERIAL).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ColorMaterialKey {
    pub front: bool,
    pub back: bool,
    pub mode: ColorMaterialMode,
}

/// One enabled light: only what changes the code.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LightKey {
    pub index: u8,
    /// w = 0 in eye space: no attenuation, L = position.xyz.
    pub directional: bool,
    /// SPOT_CUTOFF ≠ 180.
    pub spot: bool,
}

/// The lighting part of the vertex key.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct LightingKey {
    pub lights: Vec<LightKey>,
    pub local_viewer: bool,
    pub two_side: bool,
    pub color_material: Option<ColorMaterialKey>,
    /// LIGHT_MODEL_COLOR_CONTROL = SEPARATE_SPECULAR_COLOR: the specular terms go to the
    /// secondary colour instead of the primary (GL 1.2 §2.13.1).
    pub separate_specular: bool,
    /// The material values the draw's vertices carry (glMaterial inside glBegin/glEnd), as
    /// a mask of `MaterialSlot::bit`s: read from attributes instead of uniforms.
    pub vertex_materials: u16,
}

/// How one texture coordinate is produced.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CoordSource {
    /// The vertex's (or current) texture coordinate.
    Attribute,
    Generated(TexGenMode),
}

/// One enabled unit's vertex stage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct VertexUnitKey {
    pub unit: u8,
    pub coords: [CoordSource; 4],
    /// The unit's texture matrix is not the identity: the coordinates go through it. An
    /// identity matrix is left out, as Mesa's program leaves it out — also so that a NaN
    /// in one coordinate does not spread to the others through 0·NaN.
    pub matrix: bool,
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct VertexKey {
    /// Where gl_Position comes from: the transform, or window coordinates the CPU computed
    /// (the dashes of stippled lines, `line_stipple`). Set per pass, like the edge rule.
    pub positions: PositionSource,
    pub lighting: Option<LightingKey>,
    /// The enabled user clip planes, ascending: each writes gl_ClipDistance[i] (the plane
    /// itself is a uniform).
    pub clip_planes: Vec<u8>,
    pub normalize: bool,
    pub rescale_normal: bool,
    pub units: Vec<VertexUnitKey>,
    /// The program places points (and writes gl_PointSize when attenuated): a pass that
    /// rasterises points, square or round (POINT_SMOOTH). Set per pass; `None` from the state alone and for a pass that draws
    /// no points, since a vertex output less is work saved for every vertex.
    pub point_size: Option<PointKey>,
    /// The fog distance of each vertex: |z_eye|, or |fog coordinate| (GL 1.4's
    /// FOG_COORD_SRC). FRAGMENT_DEPTH whenever fog is off, so the unused source splits no
    /// programs.
    pub fog_source: FogCoordSource,
    /// A glDrawPixels or glCopyPixels fan (`pixel_fan`): the program gives the fragment
    /// the corners' texture coordinates, whose t this says. Set per draw, `None` from the
    /// state alone.
    pub pixel_fan: Option<PixelFan>,
}

/// A points pass's rasterisation: its shape, and whether sizes are attenuated by
/// distance (`ff::point`; the program then reads the eye position).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PointKey {
    pub shape: PointShape,
    pub attenuated: bool,
}

impl PointKey {
    /// The points of `state`: sprites under POINT_SPRITE (which POINT_SMOOTH does not
    /// round, as Mesa's rasterizer state has it), else round under POINT_SMOOTH; attenuated when
    /// POINT_DISTANCE_ATTENUATION is not (1, 0, 0).
    pub fn of(state: &FixedState) -> PointKey {
        PointKey {
            shape: match (state.point_sprite.enabled, state.smooth.point) {
                (true, _) => PointShape::Sprite,
                (false, true) => PointShape::Round,
                (false, false) => PointShape::Square,
            },
            attenuated: state.point_params.attenuated(),
        }
    }
}

/// A sprite pass's coordinate replacement: the units that take (s, t, 0, 1) from the
/// fragment's place in the point's square, and the edge where t is 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SpriteKey {
    /// Bit u: unit u replaces its coordinates.
    pub units: u8,
    pub origin: SpriteOrigin,
}

/// POINT_SPRITE_COORD_ORIGIN. The core context keeps its own at UPPER_LEFT, where
/// gl_PointCoord's t is 0 at the top (Mesa's state tracker turns both alike for the
/// buffer's orientation): LOWER_LEFT reads 1 − t.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SpriteOrigin {
    UpperLeft,
    LowerLeft,
}

impl SpriteKey {
    /// The sprites of a draw under `state`, if any unit replaces.
    pub fn of(state: &FixedState) -> Option<SpriteKey> {
        let sprite = state.point_sprite;
        if !sprite.enabled || sprite.coord_replace == 0 {
            return None;
        }
        Some(SpriteKey {
            units: sprite.coord_replace,
            origin: match state.point_params.sprite_coord_origin {
                crate::ff::point::LOWER_LEFT => SpriteOrigin::LowerLeft,
                _ => SpriteOrigin::UpperLeft,
            },
        })
    }

    /// Whether unit `u` replaces its coordinates.
    pub fn replaces(&self, u: u8) -> bool {
        self.units & (1 << u) != 0
    }
}

/// The fragments a points pass keeps of the square the core context rasterises.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PointCut {
    /// An aliased point (`PointShape::Square`): the pixels of llvmpipe's rule for legacy
    /// points, whose centres c lie at X − side/2 < c ≤ X + side/2 in x and in y, X the
    /// point's window position in 1/256-pixel steps; the others of the sprite (two pixels
    /// wider than the side) are discarded.
    Legacy,
    /// POINT_SMOOTH (`PointShape::Round`): fragments outside the point's circle are
    /// discarded and its alpha scaled as Mesa's aapoint stage scales it.
    Round,
}

impl PointCut {
    /// The cut of points of `shape`: none for sprites, which the core context draws as
    /// Mesa does.
    pub fn of(shape: PointShape) -> Option<PointCut> {
        match shape {
            PointShape::Square => Some(PointCut::Legacy),
            PointShape::Round => Some(PointCut::Round),
            PointShape::Sprite => None,
        }
    }
}

/// How a pass's points are rasterised.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PointShape {
    /// Aliased: a square of glPointSize's side.
    Square,
    /// POINT_SMOOTH, as Mesa's draw module draws it (its aapoint stage): a square of
    /// side 2r, r = 1 for sizes up to 2 and size/2 above, whose fragments outside the
    /// circle of radius r are discarded and whose alpha takes the stage's factor
    /// (`shadergen::fragment`, "point coverage").
    Round,
    /// POINT_SPRITE: a square of the size itself, unrounded, rasterised as a quad by the
    /// rules of polygons (llvmpipe's `point_quad_rasterization`, which Mesa sets for
    /// sprites), where aliased points are drawn by its rule for legacy points.
    Sprite,
}

/// The source of a vertex's clip coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum PositionSource {
    /// projection · modelview · position (GL 1.5 §2.10).
    #[default]
    Transformed,
    /// The window coordinates of the window attribute, mapped back through the fixed
    /// viewport of `shadergen::WINDOW_SPAN` so that llvmpipe's viewport transform gives
    /// them back bit for bit (a power-of-two scale and no translation).
    Window,
}

/// How the texel of a unit is formed from the texture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TexelKey {
    /// A colour texture of this base format (texel already swizzled to GL's (L,L,L,1) etc.).
    Color(BaseFormat),
    /// A depth texture without compare: the depth value as L, I or A.
    Depth(DepthTextureMode),
    /// A depth texture with COMPARE_R_TO_TEXTURE: the compare result (with the fail value)
    /// as L, I or A.
    Compare(DepthTextureMode),
}

impl TexelKey {
    /// The texel as register combiners read it: a depth texture's DEPTH_TEXTURE_MODE is
    /// ignored there (depth arrives as (0,0,0,D), a compare result as (c,c,c,c)), so it
    /// is fixed to one value.
    fn under_combiners(self) -> TexelKey {
        match self {
            TexelKey::Color(b) => TexelKey::Color(b),
            TexelKey::Depth(_) => TexelKey::Depth(DepthTextureMode::Intensity),
            TexelKey::Compare(_) => TexelKey::Compare(DepthTextureMode::Intensity),
        }
    }

    /// The base format the texture environment sees (ARB_depth_texture: depth acts as
    /// LUMINANCE, INTENSITY or ALPHA by DEPTH_TEXTURE_MODE).
    pub fn env_base(self) -> BaseFormat {
        match self {
            TexelKey::Color(b) => b,
            TexelKey::Depth(m) | TexelKey::Compare(m) => match m {
                DepthTextureMode::Luminance => BaseFormat::Luminance,
                DepthTextureMode::Intensity => BaseFormat::Intensity,
                DepthTextureMode::Alpha => BaseFormat::Alpha,
            },
        }
    }
}

/// The texture environment of a unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EnvKey {
    Modulate,
    Replace,
    Decal,
    Blend,
    Add,
    Combine { rgb: Combine, alpha: Combine },
}

/// One enabled unit's fragment stage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FragmentUnitKey {
    pub unit: u8,
    pub target: TextureTarget,
    pub texel: TexelKey,
    pub env: EnvKey,
    /// GL 1.x's CLAMP on some of the texture's axes; `None` without it.
    pub clamp: Option<ClampKey>,
}

/// CLAMP (GL 1.5 §3.8.7), which core GL lacks: the coordinate is clamped to [0, 1] before
/// the filter, so LINEAR blends the edge texel half and half with the border colour at
/// s = 1 and NEAREST takes the edge texel (i = 2ⁿ − 1 at s = 1). The program clamps the
/// axes and samples with CLAMP_TO_BORDER (`conv::wrap`), the level of detail from the
/// unclamped coordinates; which rule applies depends on the filter the fragment uses
/// (measured on Mesa 22.3.6 llvmpipe: a texture with MIN_FILTER NEAREST and MAG_FILTER
/// LINEAR takes the edge texel where minified and blends with the border where magnified).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ClampKey {
    /// s, t, r: which axes wrap with CLAMP (only those the target has).
    pub axes: [bool; 3],
    /// Whether the MIN_FILTER blends within a level.
    pub minified: InLevel,
    /// Whether the MAG_FILTER does.
    pub magnified: InLevel,
}

/// How a filter reads within one level.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum InLevel {
    Nearest,
    Linear,
}

impl InLevel {
    fn of(f: Filter) -> InLevel {
        if f.blends_within_level() {
            InLevel::Linear
        } else {
            InLevel::Nearest
        }
    }
}

/// The CLAMP axes of a texture sampled through `target`, if any. A cube map has none:
/// its (s, t, r) is a direction, and the face coordinates GL wraps are the sampler's to
/// compute, always in [0, 1], where CLAMP_TO_BORDER (CLAMP on the emulated path,
/// `conv::wrap`) samples as CLAMP does.
fn clamp_key(target: TextureTarget, p: &TexParams) -> Option<ClampKey> {
    let dims = match target {
        TextureTarget::Texture1D => 1,
        TextureTarget::Texture2D => 2,
        TextureTarget::Texture3D => 3,
        TextureTarget::CubeMap | TextureTarget::CubeFace(_) => return None,
    };
    let wraps = [p.wrap_s, p.wrap_t, p.wrap_r];
    let axes: [bool; 3] = std::array::from_fn(|i| i < dims && wraps[i] == Wrap::Clamp);
    axes.contains(&true).then(|| ClampKey {
        axes,
        minified: InLevel::of(p.min_filter),
        magnified: InLevel::of(p.mag_filter),
    })
}

/// NV_register_combiners: the stages that run and the final combiner (the constant
/// colours are uniforms).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct CombinersKey {
    pub stages: Vec<GeneralStage>,
    pub final_inputs: [CombinerInput; 7],
    pub color_sum_clamp: bool,
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct FragmentKey {
    pub units: Vec<FragmentUnitKey>,
    /// The arithmetic of the stages and the alpha test.
    pub precision: Precision,
    /// Register combiners replace the texture environments when enabled.
    pub combiners: Option<CombinersKey>,
    /// Two-sided lighting: the fragment picks the back colour on back faces.
    pub two_side: bool,
    /// Colour sum (GL 1.2 §3.9): the secondary colour (the separate specular of lighting)
    /// is added to the RGB after texturing; under register combiners it is their
    /// SECONDARY_COLOR register instead.
    pub color_sum: bool,
    pub flat: bool,
    /// FOG's mode; `None` when fog is off (no fog code, no fog varying). The vertex stage
    /// writes |z_eye|, the fragment stage blends after texturing and the colour sum — or,
    /// under register combiners, fills their FOG register instead (the final combiner
    /// applies fog there, NV_register_combiners).
    pub fog: Option<FogMode>,
    /// `None` when the alpha test is off or ALWAYS (no code at all).
    pub alpha_test: Option<CompareFunc>,
    /// Which fragments of a split quad or polygon survive in LINE or POINT mode
    /// (`polygon`); set per draw pass, `None` from the state alone.
    pub edges: Option<EdgeRule>,
    /// POLYGON_STIPPLE on a pass that fills polygons (§3.5.2): fragments at unset bits of
    /// the pattern (a uniform) are discarded; set per draw pass, `false` from the state
    /// alone.
    pub polygon_stipple: bool,
    /// What a pass that rasterises points does to their fragments (`PointCut`); set per
    /// pass, `None` from the state alone and for sprites.
    pub point_cut: Option<PointCut>,
    /// POINT_SPRITE with a unit whose COORD_REPLACE is TRUE (`ff::point::PointSprite`):
    /// those units read the fragment's place in the point's square (gl_PointCoord), on
    /// every pass of the geometry as Mesa's program reads it; set per pass, `None` from the
    /// state alone.
    pub sprite: Option<SpriteKey>,
    /// A pixel rectangle's draw (glBitmap, glDrawPixels, glCopyPixels: `pixels`): what the
    /// image gives the fragment; set per draw, `None` from the state alone.
    pub pixels: Option<PixelSource>,
}

/// What a pixel rectangle's image gives its fragments (GL 1.5 §3.6.4, §3.7): read at the
/// fan's interpolated coordinates (`pixel_fan`), a bitmap with texelFetch at the
/// fragment's pixel of the rectangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelSource {
    /// A colour image: the fragment colour is the image's (in place of the primary colour).
    Color,
    /// DEPTH_COMPONENT: the fragment depth is the image's; the colour the raster colour.
    Depth,
    /// glBitmap: fragments at unset bits are discarded; the colour the raster colour.
    Bitmap,
    /// One bit plane of a STENCIL_INDEX image: fragments whose value lacks the pass's bit
    /// are discarded (the pass writes that bit through the stencil write mask).
    StencilBit,
}

/// The whole key: the generator sees nothing else.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ShaderKey {
    pub vertex: VertexKey,
    pub fragment: FragmentKey,
}

impl ShaderKey {
    pub fn from_state(state: &FixedState, precision: Precision) -> ShaderKey {
        let units = enabled_units(state);
        let lighting = lighting_key(state);
        let two_side = lighting.as_ref().is_some_and(|l| l.two_side);
        // A secondary colour is read when lighting makes one (SEPARATE_SPECULAR_COLOR; a
        // single-colour model's is 0) or, unlit, for COLOR_SUM and the register
        // combiners' SECONDARY_COLOR (GL 1.4 §2.7: the vertex's secondary colour).
        let color_sum = match &lighting {
            Some(l) => l.separate_specular,
            None => state.color_sum || state.register_combiners.enabled,
        };
        let vertex_units: Vec<VertexUnitKey> = units
            .iter()
            .map(|&(unit, ..)| VertexUnitKey {
                unit: unit as u8,
                coords: TexCoord::ALL.map(|c| match state.units[unit].texgen(c) {
                    Some(g) if !(g.mode == TexGenMode::SphereMap && c.index() >= 2) => {
                        CoordSource::Generated(g.mode)
                    }
                    _ => CoordSource::Attribute,
                }),
                matrix: state.texture_matrices[unit].top() != glam::Mat4::IDENTITY,
            })
            .collect();
        // The eye-space normal exists only for lighting, SPHERE_MAP, REFLECTION_MAP and
        // NORMAL_MAP; without them NORMALIZE and RESCALE_NORMAL change no code, so they
        // are not in the key.
        let normal_used = lighting.is_some()
            || vertex_units.iter().any(|u| {
                [
                    TexGenMode::SphereMap,
                    TexGenMode::ReflectionMap,
                    TexGenMode::NormalMap,
                ]
                .iter()
                .any(|m| u.coords.contains(&CoordSource::Generated(*m)))
            });
        let clip_planes = (0..MAX_CLIP_PLANES)
            .filter(|&i| state.clip_planes[i].enabled)
            .map(|i| i as u8)
            .collect();
        let vertex = VertexKey {
            positions: PositionSource::Transformed,
            clip_planes,
            normalize: normal_used && state.normalize,
            rescale_normal: normal_used && state.rescale_normal && !state.normalize,
            units: vertex_units,
            lighting,
            point_size: None,
            fog_source: match state.fog.get() {
                Some(f) => f.coord_source,
                None => FogCoordSource::FragmentDepth,
            },
            pixel_fan: None,
        };
        let combiners = state.register_combiners.get().map(|rc| CombinersKey {
            stages: rc.active_stages().to_vec(),
            final_inputs: rc.final_inputs,
            color_sum_clamp: rc.color_sum_clamp,
        });
        let fragment = FragmentKey {
            units: units
                .iter()
                .map(|&(unit, target, texel, clamp)| match combiners {
                    // Register combiners replace the environments and read a depth texel
                    // in one fixed layout (`shadergen::fragment::emit_texel`): neither the
                    // env nor DEPTH_TEXTURE_MODE changes the code.
                    Some(_) => FragmentUnitKey {
                        unit: unit as u8,
                        target,
                        texel: texel.under_combiners(),
                        env: EnvKey::Modulate,
                        clamp,
                    },
                    None => FragmentUnitKey {
                        unit: unit as u8,
                        target,
                        texel,
                        env: env_key(state, unit),
                        clamp,
                    },
                })
                .collect(),
            precision,
            combiners,
            two_side,
            color_sum,
            flat: state.shade_model == ShadeModel::Flat,
            fog: state.fog.get().map(|f| f.mode),
            alpha_test: state
                .alpha_test
                .get()
                .map(|AlphaTest { func, .. }| func)
                .filter(|f| *f != CompareFunc::Always),
            edges: None,
            polygon_stipple: false,
            point_cut: None,
            sprite: None,
            pixels: None,
        };
        ShaderKey { vertex, fragment }
    }
}

/// Units that texture: an enabled target with a complete texture (GL 1.5 §3.8.10, the
/// rules in `TextureObject::completeness`), the highest such (`FixedState::
/// sampled_texture`, Mesa's fallback past an incomplete higher target). Without one the
/// unit is off (§3.8.15): it leaves the key, so the program is the one with the unit off —
/// what Mesa's native path does (measured: level 0 alone under the default
/// NEAREST_MIPMAP_LINEAR draws the untextured colour, `tests/fidelity_completeness.rs`).
fn enabled_units(state: &FixedState) -> Vec<(usize, TextureTarget, TexelKey, Option<ClampKey>)> {
    (0..MAX_TEXTURE_UNITS)
        .filter_map(|unit| {
            let (target, texture, format) = state.sampled_texture(unit)?;
            // ARB_shadow compares r with a 1D or 2D depth texel; a depth cube map is read
            // for its depth (a compare there is outside GL 1.x and not modelled).
            let compare = match target {
                TextureTarget::CubeMap => CompareMode::None,
                _ => texture.params.compare_mode,
            };
            let texel = texel_key(format, compare, texture.params.depth_texture_mode);
            Some((unit, target, texel, clamp_key(target, &texture.params)))
        })
        .collect()
}

fn texel_key(format: TexFormat, compare: CompareMode, mode: DepthTextureMode) -> TexelKey {
    match (format.base(), compare) {
        (BaseFormat::Depth, CompareMode::CompareRToTexture) => TexelKey::Compare(mode),
        (BaseFormat::Depth, CompareMode::None) => TexelKey::Depth(mode),
        (base, _) => TexelKey::Color(base),
    }
}

fn env_key(state: &FixedState, unit: usize) -> EnvKey {
    let env = &state.units[unit].env;
    match env.mode {
        TexEnvMode::Modulate => EnvKey::Modulate,
        TexEnvMode::Replace => EnvKey::Replace,
        TexEnvMode::Decal => EnvKey::Decal,
        TexEnvMode::Blend => EnvKey::Blend,
        TexEnvMode::Add => EnvKey::Add,
        TexEnvMode::Combine => {
            let rgb = used_arguments(env.rgb, CombineOperand::SrcColor);
            // DOT3_RGBA writes the dot product to alpha too: COMBINE_ALPHA and its
            // sources are ignored, ALPHA_SCALE is not (GL 1.5 §3.8.13: the alpha is the
            // dot product scaled by ALPHA_SCALE; Mesa alike).
            let alpha = if env.rgb.func == CombineFunc::Dot3Rgba {
                Combine {
                    scale: env.alpha.scale,
                    ..IGNORED_ALPHA
                }
            } else {
                used_arguments(env.alpha, CombineOperand::SrcAlpha)
            };
            EnvKey::Combine { rgb, alpha }
        }
    }
}

/// The COMBINE_ALPHA of the key when DOT3_RGBA makes it unused (but for its scale).
const IGNORED_ALPHA: Combine = Combine {
    func: CombineFunc::Replace,
    sources: [CombineSource::Previous; 3],
    operands: [CombineOperand::SrcAlpha; 3],
    scale: CombineScale::One,
};

/// A combine with the arguments its function does not read set to (PREVIOUS, `operand`),
/// as Mesa keeps only `_NumArgs` arguments in its key: REPLACE reads a0; MODULATE, ADD,
/// ADD_SIGNED, SUBTRACT and DOT3 read a0, a1; INTERPOLATE reads all three. An unread
/// CONSTANT would otherwise declare the env colour for nothing, and a technique that
/// leaves SOURCE2 at its default would get a second program for the same code.
fn used_arguments(mut combine: Combine, operand: CombineOperand) -> Combine {
    let used = match combine.func {
        CombineFunc::Replace => 1,
        CombineFunc::Interpolate => 3,
        CombineFunc::Modulate
        | CombineFunc::Add
        | CombineFunc::AddSigned
        | CombineFunc::Subtract
        | CombineFunc::Dot3Rgb
        | CombineFunc::Dot3Rgba => 2,
    };
    for i in used..3 {
        combine.sources[i] = CombineSource::Previous;
        combine.operands[i] = operand;
    }
    combine
}

fn lighting_key(state: &FixedState) -> Option<LightingKey> {
    if !state.lighting {
        return None;
    }
    let lights = (0..MAX_LIGHTS)
        .filter_map(|i| {
            let l = state.lights[i].get()?;
            Some(LightKey {
                index: i as u8,
                directional: l.position.w == 0.0,
                spot: l.spot_cutoff != 180.0,
            })
        })
        .collect();
    // Back-face colours exist only with two-sided lighting: without it COLOR_MATERIAL on
    // the back face tracks nothing, and BACK alone is no COLOR_MATERIAL at all.
    let two_side = state.light_model.two_side;
    let color_material = state
        .color_material
        .get()
        .map(|cm| ColorMaterialKey {
            front: matches!(cm.face, Face::Front | Face::FrontAndBack),
            back: two_side && matches!(cm.face, Face::Back | Face::FrontAndBack),
            mode: cm.mode,
        })
        .filter(|cm| cm.front || cm.back);
    Some(LightingKey {
        lights,
        local_viewer: state.light_model.local_viewer,
        two_side,
        color_material,
        separate_specular: state.light_model.color_control == ColorControl::SeparateSpecularColor,
        vertex_materials: 0,
    })
}

impl ShaderKey {
    /// Lighting that reads the material values `g`'s vertices carry (all of them: their
    /// attribute locations follow from the whole mask, `shadergen::material_location`).
    /// Those take the last texture units' coordinate locations: a draw that reads one of
    /// those units is refused.
    pub fn with_vertex_materials(
        &mut self,
        g: &crate::ff::Geometry,
    ) -> Result<(), crate::pipeline::PipelineError> {
        let Some(lighting) = &mut self.vertex.lighting else {
            return Ok(());
        };
        lighting.vertex_materials = g.materials.as_ref().map_or(0, |m| m.mask());
        let units = crate::ff::MAX_TEXTURE_UNITS;
        let first = units.saturating_sub(lighting.vertex_materials.count_ones() as usize);
        let clash = (first..units).any(|u| {
            g.texcoords[u].is_some() || self.vertex.units.iter().any(|k| usize::from(k.unit) == u)
        });
        if clash {
            return Err(crate::pipeline::PipelineError::Unsupported {
                what: "glMaterial inside glBegin/glEnd with texture units 8 − (material values set) to 7 in use",
                path: "emulate",
            });
        }
        Ok(())
    }
}

#[cfg(test)]
#[path = "key_tests.rs"]
mod key_tests;
