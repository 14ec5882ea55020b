//! `none`: the lit scene alone, in one pass, with no shadows — the baseline every shadow
//! technique is timed against, and the eye pass they build on.
//!
//! The pass, as a program of the era would write it:
//! ```text
//! glViewport(0, 0, w, h); glClearColor(bg, 1); glClear(COLOR | DEPTH); glEnable(DEPTH_TEST)
//! glMatrixMode(PROJECTION); glLoadIdentity(); glFrustum(…)   // gluPerspective, or glOrtho
//! glMatrixMode(MODELVIEW); glLoadMatrixf(view)                // gluLookAt
//! [lights]   glEnable(LIGHTING); glLightModel(AMBIENT, 0.1); per light i: glLight(…); glEnable(LIGHTi)
//! per object: glPushMatrix(); glMultMatrixf(M); glMaterial(…) or glColor(…); draw; glPopMatrix()
//! ```
//! Lights are specified with the modelview equal to the camera's view, so GL stores their
//! positions and spot directions in eye space (§2.14.1) exactly where the scene puts them
//! in the world. Each light's diffuse and specular are colour × intensity, ambient stays
//! GL's black; the global ambient is a small 0.1 grey so faces turned away are not black.
//! A point or spot light is positional (w = 1); a directional light is (−direction, 0),
//! GL's "towards the light"; an area light has no GL 1.x equivalent and is lit as a point
//! at its centre (the truth softens it, the image does not).
//!
//! Without lights nothing about lighting is enabled and each object is drawn in its flat
//! colour (glColor). NORMALIZE is enabled only when some transform scales (a rotation and a
//! translation keep normals unit length). No texture unit is touched.
//!
//! **Mask.** The technique casts no shadows, so its mask is its coverage: the frame's depth
//! buffer read back as FLOAT after the last frame (no extra pass), 255 where z < 1, 128 where
//! the clear value 1 survived (see [`super::MaskSource::DepthCoverage`]).

use crate::vocab::DepthBits;
use glam::{Vec3, Vec4};

use crate::ff::{
    Capability, Command, LightModelParam, LightParam, MatrixMode, PixelFormat, PixelType,
    ReadPixels, ViewVolume,
};
use crate::scene::{Camera, Light, LightKind, Projection, Scene};

use super::parts::Paint;
use super::{
    check_light_count, FramebufferNeeds, MaskPlan, MaskSource, Pass, Plan, Prepared, Technique,
    TechniqueError, MASK_SLOT,
};

pub const TECHNIQUE: Technique = Technique {
    summary: "the lit scene alone, one pass, no shadows",
    plan,
};

/// GL_LIGHT_MODEL_AMBIENT (RGB) while lighting is on.
pub const GLOBAL_AMBIENT: f32 = 0.1;

/// The one-pass plan and its depth-coverage mask.
pub fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, TechniqueError> {
    check_light_count(scene)?;
    let (width, height) = (scene.image.width, scene.image.height);
    let mut commands = super::parts::eye_start(scene, super::parts::Look::Shaded, false);
    commands.extend(lighting(&scene.lights));
    commands.extend(objects(scene, prepared));
    Ok(Plan::single(
        vec![Pass {
            name: "eye",
            commands,
        }],
        depth_coverage_mask(width, height),
        FramebufferNeeds {
            width,
            height,
            depth: DepthBits::D24,
            stencil: false,
        },
    ))
}

/// glFrustum (as gluPerspective(fovy, aspect, near, far) writes it) or glOrtho of a
/// projection.
pub fn view_volume(projection: Projection, aspect: f32) -> Command {
    match projection {
        // gluPerspective: top = near · tan(fovy / 2), right = top · aspect.
        Projection::Perspective { fovy, near, far } => {
            let top = near * (fovy.to_radians() / 2.0).tan();
            Command::Frustum(ViewVolume {
                left: -top * aspect,
                right: top * aspect,
                bottom: -top,
                top,
                near,
                far,
            })
        }
        Projection::Orthographic {
            left,
            right,
            bottom,
            top,
            near,
            far,
        } => Command::Ortho(ViewVolume {
            left,
            right,
            bottom,
            top,
            near,
            far,
        }),
    }
}

/// Projection (glFrustum as gluPerspective writes it, or glOrtho) and the view as the
/// modelview, left current.
pub fn camera(camera: &Camera, width: u32, height: u32) -> Vec<Command> {
    let aspect = width as f32 / height.max(1) as f32;
    let volume = view_volume(camera.projection, aspect);
    vec![
        Command::MatrixMode(MatrixMode::Projection),
        Command::LoadIdentity,
        volume,
        Command::MatrixMode(MatrixMode::Modelview),
        Command::LoadMatrix(camera.view()),
    ]
}

/// LIGHTING and the scene's lights, set while the modelview is the view. Nothing when the
/// scene has no lights.
pub fn lighting(lights: &[Light]) -> Vec<Command> {
    if lights.is_empty() {
        return Vec::new();
    }
    let mut commands = vec![
        Command::Enable(Capability::Lighting),
        Command::LightModel(LightModelParam::Ambient(
            Vec3::splat(GLOBAL_AMBIENT).extend(1.0),
        )),
    ];
    for (i, light) in lights.iter().enumerate() {
        commands.extend(light_commands(i as u8, light));
    }
    commands
}

/// glLight calls for one light, then glEnable(LIGHTi).
pub fn light_commands(index: u8, light: &Light) -> Vec<Command> {
    let colour = (light.colour * light.intensity).extend(1.0);
    let set = |param| Command::Light {
        light: index,
        param,
    };
    let position = match light.kind {
        // GL's directional position points towards the light: −(direction of travel).
        LightKind::Directional { direction } => Vec4::from((-direction.normalize(), 0.0)),
        _ => light
            .position()
            .map_or(Vec4::new(0.0, 0.0, 1.0, 0.0), |p| p.extend(1.0)),
    };
    let mut commands = vec![
        set(LightParam::Diffuse(colour)),
        set(LightParam::Specular(colour)),
        set(LightParam::Position(position)),
    ];
    if let LightKind::Spot { cutoff, exponent } = light.kind {
        let direction = (light.view.at - light.view.eye).normalize();
        commands.extend([
            set(LightParam::SpotDirection(direction)),
            set(LightParam::SpotCutoff(cutoff)),
            set(LightParam::SpotExponent(exponent)),
        ]);
    }
    commands.push(Command::Enable(Capability::Light(index)));
    commands
}

/// Each object under its model matrix, with its material (lit) or colour (unlit).
pub fn objects(scene: &Scene, prepared: &Prepared) -> Vec<Command> {
    let paint = if scene.lights.is_empty() {
        Paint::OwnColour
    } else {
        Paint::Material
    };
    super::parts::objects(scene, prepared, |_| true, paint)
}

/// Reads the frame's depth as FLOAT into [`MASK_SLOT`]; geometry where z < 1.
pub fn depth_coverage_mask(width: u32, height: u32) -> MaskPlan {
    MaskPlan {
        commands: vec![Command::ReadPixels(ReadPixels {
            x: 0,
            y: 0,
            width: width as i32,
            height: height as i32,
            format: PixelFormat::DepthComponent,
            ty: PixelType::Float,
            slot: MASK_SLOT,
        })],
        source: MaskSource::DepthCoverage {
            slot: MASK_SLOT,
            width,
            height,
        },
    }
}
