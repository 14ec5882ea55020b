//! `dual8`: Heidrich's dual-texture shadow map as Kilgard's GDC 2000 slides set it up, on
//! 8-bit consumer hardware (TNT, GeForce 256).
//!
//! ```text
//! maps   light:    glPolygonOffset(factor, units); depth only; draw the casters
//!        readback: glReadPixels(0, 0, map, map, DEPTH_COMPONENT, UNSIGNED_BYTE, buf)
//!        upload:   glTexImage2D(TEXTURE_2D, 0, INTENSITY8, map, map, 0, LUMINANCE, UNSIGNED_BYTE, buf)
//! frame  dim:      the shadowing light off; draw everything
//!        lit:      glDepthFunc(EQUAL); every light on
//!                  unit 0: the map; eye-linear S, T, Q = rows 0, 1, 3 of B·P·V
//!                          COMBINE rgb REPLACE(PRIMARY_COLOR), alpha REPLACE(TEXTURE)
//!                  unit 1: the 256-texel ramp; eye-linear S = row 2 (R), Q = row 3
//!                          COMBINE rgb REPLACE(PREVIOUS), alpha ADD_SIGNED(PREVIOUS, 1 − TEXTURE)
//!                  glAlphaFunc(GREATER, 0.5); draw receivers (others without textures)
//! ```
//! **The comparison, as numbers** (notes H4, H6): the map holds M = ⌊255·z⌋ (Mesa's
//! UNSIGNED_BYTE readback truncates; the scene's `readback` rule can impose truncation or
//! rounding on any driver, `map::DepthTransfer`), the ramp gives the fragment F = ⌊256·r/q⌋ clamped to
//! 255; alpha = M/255 + (1 − F/255) − ½, and GREATER ½ passes iff M > F — equality is
//! shadowed (the ADD_SIGNED tie, H1), and a 1-LSB difference is at the mercy of rounding
//! (H12 and `ff::precision`). Since F − M ∈ {0, 1} for the same z, a surface shadows itself
//! unless the light pass's polygon offset lifts its stored depth by two 8-bit steps: the
//! slide's "usually (1.0, 4.0) works well" was said of this 24-bit-to-8-bit setup and is not
//! enough — the artifact this technique exists to show.

use glam::Vec4;

use crate::ff::{
    Capability, CombineArg, CombineFunc, CombineOperand, CombineSource, Command, CompareFunc,
    PixelFormat, PixelType, TexCoord, TexData, TexEnvMode, TexEnvParam, TexFormat, TextureTarget,
    Wrap,
};
use crate::scene::Scene;
use crate::vocab::TechniqueId;

use super::map::{
    bind_map, map_parameters, ramp, upload_map, DepthTransfer, MapSettings, MAP_SLOT, RAMP_TEXTURE,
};
use super::parts::{
    dim_pass, does_not_receive, eye_linear, light_pass, lighting, objects, receives, reset,
    LightSet, Look, ShadowLight,
};
use super::{
    check_light_count, colour_mask, MapImagePlan, MapImageSource, Pass, Plan, Prepared, Technique,
    TechniqueError,
};

pub const ID: TechniqueId = TechniqueId::Dual8;

pub const TECHNIQUE: Technique = Technique {
    summary: "Heidrich/Kilgard dual texture: 8-bit depth map, 1D ramp, ADD_SIGNED, alpha test",
    plan,
};

pub fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, TechniqueError> {
    check_light_count(scene)?;
    let light = ShadowLight::of(scene, ID)?;
    let map = MapSettings::of(scene);
    let ramp_planes = [(TexCoord::S, light.plane(2)), (TexCoord::Q, light.plane(3))];
    let eye = |look| {
        vec![
            dim_pass(scene, prepared, look, false),
            dual_texture_pass(scene, prepared, &light, look, &ramp_planes),
        ]
    };
    let transfer = DepthTransfer {
        ty: PixelType::UnsignedByte,
        rule: map.readback,
    };
    Ok(Plan {
        setup: setup(&map),
        maps: vec![
            light_pass(scene, prepared, &light, map.size, map.offset, false),
            Pass {
                name: "readback",
                commands: vec![transfer.read(map.size)],
            },
            upload_pass(map.size, transfer.data()),
        ],
        passes: eye(Look::Shaded),
        mask: colour_mask(scene, eye(Look::Mask)),
        framebuffer: map.framebuffer(scene, false),
        map_image: Some(MapImagePlan {
            commands: Vec::new(),
            source: MapImageSource::Bytes {
                slot: MAP_SLOT,
                size: map.size,
                from_float: transfer.conversion(),
            },
        }),
        notes: Vec::new(),
    })
}

/// The map's parameters on unit 0 and the ramp on unit 1 (made once).
pub fn setup(map: &MapSettings) -> Vec<Command> {
    let mut commands = vec![Command::ActiveTexture(0), bind_map()];
    commands.extend(map_parameters(map.gl_filter()));
    commands.push(Command::ActiveTexture(1));
    commands.extend(ramp(RAMP_TEXTURE, Wrap::ClampToEdge));
    commands.push(Command::ActiveTexture(0));
    commands
}

/// glTexImage2D of the read-back bytes into the INTENSITY8 map.
pub fn upload_pass(size: u32, data: TexData) -> Pass {
    Pass {
        name: "upload",
        commands: vec![
            Command::ActiveTexture(0),
            bind_map(),
            upload_map(size, TexFormat::Intensity8, PixelFormat::Luminance, data),
        ],
    }
}

/// The slide's second pass: the map on unit 0 (projective S, T, Q), the ramp on unit 1 at
/// the coordinates `ramp_planes` generate, alpha = T0 + (1 − T1) − ½, GREATER ½.
pub fn dual_texture_pass(
    scene: &Scene,
    prepared: &Prepared,
    light: &ShadowLight,
    look: Look,
    ramp_planes: &[(TexCoord, Vec4)],
) -> Pass {
    let env = TexEnvParam::Mode(TexEnvMode::Combine);
    let mut c = vec![Command::DepthFunc(CompareFunc::Equal)];
    c.extend(lighting(scene, look, LightSet::All));
    // Unit 0: the map.
    c.extend([
        Command::ActiveTexture(0),
        bind_map(),
        Command::Enable(Capability::Texture2D),
        Command::TexEnv(env),
        Command::TexEnv(TexEnvParam::CombineRgb(CombineFunc::Replace)),
        Command::TexEnv(TexEnvParam::SourceRgb(
            CombineArg::Arg0,
            CombineSource::PrimaryColor,
        )),
        Command::TexEnv(TexEnvParam::OperandRgb(
            CombineArg::Arg0,
            CombineOperand::SrcColor,
        )),
        Command::TexEnv(TexEnvParam::CombineAlpha(CombineFunc::Replace)),
        Command::TexEnv(TexEnvParam::SourceAlpha(
            CombineArg::Arg0,
            CombineSource::Texture,
        )),
        Command::TexEnv(TexEnvParam::OperandAlpha(
            CombineArg::Arg0,
            CombineOperand::SrcAlpha,
        )),
    ]);
    c.extend(eye_linear(&[
        (TexCoord::S, light.plane(0)),
        (TexCoord::T, light.plane(1)),
        (TexCoord::Q, light.plane(3)),
    ]));
    // Unit 1: the ramp.
    c.extend([
        Command::ActiveTexture(1),
        Command::BindTexture {
            target: TextureTarget::Texture1D,
            name: RAMP_TEXTURE,
        },
        Command::Enable(Capability::Texture1D),
        Command::TexEnv(env),
        Command::TexEnv(TexEnvParam::CombineRgb(CombineFunc::Replace)),
        Command::TexEnv(TexEnvParam::SourceRgb(
            CombineArg::Arg0,
            CombineSource::Previous,
        )),
        Command::TexEnv(TexEnvParam::OperandRgb(
            CombineArg::Arg0,
            CombineOperand::SrcColor,
        )),
        Command::TexEnv(TexEnvParam::CombineAlpha(CombineFunc::AddSigned)),
        Command::TexEnv(TexEnvParam::SourceAlpha(
            CombineArg::Arg0,
            CombineSource::Previous,
        )),
        Command::TexEnv(TexEnvParam::OperandAlpha(
            CombineArg::Arg0,
            CombineOperand::SrcAlpha,
        )),
        Command::TexEnv(TexEnvParam::SourceAlpha(
            CombineArg::Arg1,
            CombineSource::Texture,
        )),
        Command::TexEnv(TexEnvParam::OperandAlpha(
            CombineArg::Arg1,
            CombineOperand::OneMinusSrcAlpha,
        )),
    ]);
    c.extend(eye_linear(ramp_planes));
    c.extend([
        Command::Enable(Capability::AlphaTest),
        Command::AlphaFunc {
            func: CompareFunc::Greater,
            reference: 0.5,
        },
    ]);
    let paint = look.paint(true);
    c.extend(objects(scene, prepared, receives, paint));
    // Non-receivers: no textures, alpha 1 passes the test.
    for unit in [1, 0] {
        c.push(Command::ActiveTexture(unit));
        c.push(Command::Disable(Capability::Texture1D));
        c.push(Command::Disable(Capability::Texture2D));
    }
    c.extend(objects(scene, prepared, does_not_receive, paint));
    c.extend(reset(&[0, 1]));
    Pass {
        name: "lit",
        commands: c,
    }
}
