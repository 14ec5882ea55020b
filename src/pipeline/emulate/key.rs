//! `ShaderKey::from_state`: everything in the fixed-function state that changes the *shape*
//! of the generated code, and nothing else. Values (matrices, planes, colours, the alpha
//! reference, the env colour) are uniforms; disabled units, lights and tests are absent
//! from the key, so toggling them off can never cause a recompile of an unrelated program.

use super::polygon::EdgeRule;
use crate::ff::{
    AlphaTest, BaseFormat, ColorMaterialMode, Combine, CombinerInput, CompareFunc, CompareMode,
    DepthTextureMode, Face, FixedState, GeneralStage, ShadeModel, TexCoord, TexEnvMode, TexFormat,
    TexGenMode, TextureTarget, MAX_LIGHTS, MAX_TEXTURE_UNITS,
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
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct VertexKey {
    pub lighting: Option<LightingKey>,
    pub normalize: bool,
    pub rescale_normal: bool,
    pub units: Vec<VertexUnitKey>,
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
    pub flat: bool,
    /// `None` when the alpha test is off or ALWAYS (no code at all).
    pub alpha_test: Option<CompareFunc>,
    /// Which fragments of a split quad or polygon survive in LINE or POINT mode
    /// (`polygon`); set per draw pass, `None` from the state alone.
    pub edges: Option<EdgeRule>,
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
        let vertex = VertexKey {
            normalize: state.normalize,
            rescale_normal: state.rescale_normal && !state.normalize,
            units: units
                .iter()
                .map(|&(unit, _, _)| VertexUnitKey {
                    unit: unit as u8,
                    coords: TexCoord::ALL.map(|c| match state.units[unit].texgen(c) {
                        Some(g) if !(g.mode == TexGenMode::SphereMap && c.index() >= 2) => {
                            CoordSource::Generated(g.mode)
                        }
                        _ => CoordSource::Attribute,
                    }),
                })
                .collect(),
            lighting,
        };
        let fragment = FragmentKey {
            units: units
                .iter()
                .map(|&(unit, target, texel)| FragmentUnitKey {
                    unit: unit as u8,
                    target,
                    texel,
                    env: env_key(state, unit),
                })
                .collect(),
            precision,
            combiners: state.register_combiners.get().map(|rc| CombinersKey {
                stages: rc.active_stages().to_vec(),
                final_inputs: rc.final_inputs,
                color_sum_clamp: rc.color_sum_clamp,
            }),
            two_side,
            flat: state.shade_model == ShadeModel::Flat,
            alpha_test: state
                .alpha_test
                .get()
                .map(|AlphaTest { func, .. }| func)
                .filter(|f| *f != CompareFunc::Always),
            edges: None,
        };
        ShaderKey { vertex, fragment }
    }
}

/// Units that texture: enabled, with a complete level-0 image (GL 1.5 §3.8.10: an incomplete
/// texture disables the unit).
fn enabled_units(state: &FixedState) -> Vec<(usize, TextureTarget, TexelKey)> {
    (0..MAX_TEXTURE_UNITS)
        .filter_map(|unit| {
            let target = state.units[unit].enabled_target()?;
            let texture = state.enabled_texture(unit)?;
            let format = texture.level(0).map(|l| l.internal_format)?;
            let texel = texel_key(
                format,
                texture.params.compare_mode,
                texture.params.depth_texture_mode,
            );
            Some((unit, target, texel))
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
        TexEnvMode::Combine => EnvKey::Combine {
            rgb: env.rgb,
            alpha: env.alpha,
        },
    }
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
    let color_material = state.color_material.get().map(|cm| ColorMaterialKey {
        front: matches!(cm.face, Face::Front | Face::FrontAndBack),
        back: matches!(cm.face, Face::Back | Face::FrontAndBack),
        mode: cm.mode,
    });
    Some(LightingKey {
        lights,
        local_viewer: state.light_model.local_viewer,
        two_side: state.light_model.two_side,
        color_material,
    })
}
