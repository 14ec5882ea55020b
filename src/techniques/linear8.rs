//! `linear8`: Heidrich's linear-depth variant of the dual-texture map ("Improving depth map
//! precision: use linear depth precision", Kilgard's slides). The 8 bits are spread evenly
//! over the light's range instead of crowding near its near plane.
//!
//! ```text
//! maps   light:    colour on, cleared to white; depth test on; unit 0: the 256-texel ramp
//!                  with eye-linear S = the light's linear distance plane (+ bias), REPLACE;
//!                  draw the casters — the nearest caster's distance ends in colour alpha
//!        readback: glReadPixels(0, 0, map, map, ALPHA, UNSIGNED_BYTE, buf)
//!        upload:   glTexImage2D(TEXTURE_2D, 0, INTENSITY8, map, map, 0, LUMINANCE, UNSIGNED_BYTE, buf)
//! frame  dim, lit: as `dual8`, with unit 1's S = the same linear distance plane (q = 1)
//! ```
//! The map is colour, not depth: it is read back as ALPHA bytes whatever the scene's
//! depth `readback` rule says (the ramp already made the bytes).
//!
//! The distance plane gives s = (d − near)/(far − near) with d the eye-planar distance from
//! the light (`ShadowLight::linear_distance_plane`); the ramp stores ⌊256·s⌋, exactly, in the
//! alpha channel (i/255 is exact in RGBA8), so the map holds M = ⌊256·(s + b)⌋ and the
//! fragment F = ⌊256·s⌋: lit iff M > F, as in `dual8`.
//!
//! **Bias.** Polygon offset moves depth values, not the colour this map is made of, so it
//! cannot bias a linear map (the era's programs shifted the plane instead). `linear8`
//! reads the scene's polygon offset *units* as ramp steps: b = units/256 is added to the
//! map's distance plane; the factor has no meaning here and is ignored. Without an offset
//! M = F everywhere a surface sees the light, and the ADD_SIGNED tie shadows it.

use glam::Vec4;

use crate::ff::{
    Capability, Command, PixelFormat, PixelType, TexCoord, TexData, TexEnvMode, TexEnvParam,
    TextureTarget,
};
use crate::scene::Scene;
use crate::vocab::TechniqueId;

use super::dual8::{dual_texture_pass, setup, upload_pass};
use super::map::{read_map, MapSettings, MAP_SLOT, RAMP_TEXTURE};
use super::parts::{
    dim_pass, eye_linear, map_pass_start, objects, texturing_off, Look, Paint, ShadowLight,
};
use super::{
    check_light_count, colour_mask, MapImagePlan, MapImageSource, Pass, Plan, Prepared, Technique,
    TechniqueError,
};

pub const ID: TechniqueId = TechniqueId::Linear8;

pub const TECHNIQUE: Technique = Technique {
    summary: "Heidrich's linear depth: the light's distance through a ramp into alpha, 8 bits",
    plan,
};

/// b = units/256: the scene's polygon offset units as ramp steps (see the module note).
pub fn bias(scene: &Scene) -> f32 {
    scene.shadow.offset().map_or(0.0, |o| o.units / 256.0)
}

pub fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, TechniqueError> {
    check_light_count(scene)?;
    let light = ShadowLight::of(scene, ID)?;
    let map = MapSettings::of(scene);
    let distance = light.linear_distance_plane();
    let ramp_planes = [(TexCoord::S, distance)];
    let eye = |look| {
        vec![
            dim_pass(scene, prepared, look, false),
            dual_texture_pass(scene, prepared, &light, look, &ramp_planes),
        ]
    };
    let biased = distance + Vec4::new(0.0, 0.0, 0.0, bias(scene));
    Ok(Plan {
        setup: setup(&map),
        maps: vec![
            distance_pass(scene, prepared, &light, map.size, biased),
            Pass {
                name: "readback",
                commands: vec![read_map(
                    map.size,
                    PixelFormat::Alpha,
                    PixelType::UnsignedByte,
                )],
            },
            upload_pass(map.size, TexData::Readback(MAP_SLOT)),
        ],
        passes: eye(Look::Shaded),
        mask: colour_mask(scene, eye(Look::Mask)),
        framebuffer: map.framebuffer(scene, false),
        map_image: Some(MapImagePlan {
            commands: Vec::new(),
            source: MapImageSource::Bytes {
                slot: MAP_SLOT,
                size: map.size,
                from_float: None,
            },
        }),
        notes: Vec::new(),
    })
}

/// The light pass writing the ramp's value of `plane` into colour (alpha = ⌊256·s⌋/255).
fn distance_pass(
    scene: &Scene,
    prepared: &Prepared,
    light: &ShadowLight,
    size: u32,
    plane: Vec4,
) -> Pass {
    let mut c = map_pass_start(size, true);
    c.extend(light.view_commands());
    c.extend([
        Command::ActiveTexture(0),
        Command::BindTexture {
            target: TextureTarget::Texture1D,
            name: RAMP_TEXTURE,
        },
        Command::Enable(Capability::Texture1D),
        Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Replace)),
    ]);
    // Set while the modelview holds the light's view: the plane is in world coordinates.
    c.extend(eye_linear(&[(TexCoord::S, plane)]));
    c.extend(objects(
        scene,
        prepared,
        |o| o.casts,
        Paint::Flat(Vec4::ONE),
    ));
    c.extend(texturing_off());
    Pass {
        name: "light",
        commands: c,
    }
}
