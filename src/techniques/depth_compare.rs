//! `depth-compare`: SGIX_shadow / ARB_shadow — the depth buffer copied into a depth texture
//! whose lookup *is* the comparison (Kilgard, "Dedicated hardware shadow mapping support").
//!
//! ```text
//! maps   light:  glViewport(map); glColorMask(F,F,F,F); glClear(DEPTH); light's frustum and
//!                gluLookAt; glPolygonOffset(factor, units); draw the casters
//!        copy:   glBindTexture(2D, map); glCopyTexImage2D(DEPTH_COMPONENT16|24|32F, 0, 0, map, map)
//! frame  dim:    clear; eye camera; the shadowing light off; draw everything
//!        lit:    glDepthFunc(EQUAL); glDepthMask(F); glBlendFunc(ONE, ONE); only the shadowing
//!                light, no global ambient; unit 0: the map, COMPARE_R_TO_TEXTURE, LEQUAL,
//!                eye-linear S, T, R, Q = rows of B·P_light·V_light, MODULATE; draw receivers
//! ```
//! The texel is the compare result c (DEPTH_TEXTURE_MODE LUMINANCE: (c, c, c, 1)): 1 where
//! r/q ≤ the stored depth (lit), 0 where something nearer the light was stored. MODULATE
//! scales the shadowing light's contribution by c and the additive blend puts it on top of
//! the dim pass, so lit pixels equal `none`'s image and shadowed ones keep the ambient.
//! With the LINEAR filter the four nearest compares are blended bilinearly — the era's
//! hardware percentage-closer filtering — and c takes values between 0 and 1.
//!
//! r/q is clamped to [0, 1] before the compare (ARB_shadow), so surfaces beyond the light's
//! far plane compare as 1 and stay lit only where the stored depth is 1.

use crate::ff::{
    Command, CompareFunc, CompareMode, DepthTextureMode, PixelFormat, PixelType, TexParam,
    TextureTarget,
};
use crate::scene::Scene;
use crate::vocab::TechniqueId;

use super::map::{bind_map, map_parameters, MapSettings, MAP_IMAGE_SLOT};
use super::parts::{light_pass, Look, ShadowLight};
use super::{
    check_light_count, colour_mask, MapImagePlan, MapImageSource, Pass, Plan, Prepared, Technique,
    TechniqueError,
};

pub const ID: TechniqueId = TechniqueId::DepthCompare;

pub const TECHNIQUE: Technique = Technique {
    summary: "ARB_shadow: the depth buffer copied into a depth texture that compares r/q",
    plan,
};

pub fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, TechniqueError> {
    check_light_count(scene)?;
    let light = ShadowLight::of(scene, ID)?;
    let map = MapSettings::of(scene);
    let param = |param| Command::TexParameter {
        target: TextureTarget::Texture2D,
        param,
    };
    let mut setup = vec![Command::ActiveTexture(0), bind_map()];
    setup.extend(map_parameters(map.gl_filter()));
    setup.extend([
        param(TexParam::CompareMode(CompareMode::CompareRToTexture)),
        param(TexParam::CompareFunc(CompareFunc::Lequal)),
        param(TexParam::DepthTextureMode(DepthTextureMode::Luminance)),
    ]);
    Ok(Plan {
        setup,
        maps: vec![
            light_pass(scene, prepared, &light, map.size, map.offset, false),
            map.copy_depth_pass(),
        ],
        passes: eye_passes(scene, prepared, &light, Look::Shaded),
        mask: colour_mask(scene, eye_passes(scene, prepared, &light, Look::Mask)),
        framebuffer: map.framebuffer(scene, false),
        map_image: Some(MapImagePlan {
            commands: vec![super::map::read_corner(
                map.size,
                PixelFormat::DepthComponent,
                PixelType::Float,
                MAP_IMAGE_SLOT,
            )],
            source: MapImageSource::DepthFloat {
                slot: MAP_IMAGE_SLOT,
                size: map.size,
            },
        }),
        notes: Vec::new(),
    })
}

fn eye_passes(scene: &Scene, prepared: &Prepared, light: &ShadowLight, look: Look) -> Vec<Pass> {
    super::parts::dim_then_added_light(scene, prepared, [0, 1, 2, 3].map(|i| light.plane(i)), look)
}
