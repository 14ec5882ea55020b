//! The scene's camera and lights as GL 1.x Commands — the set-up every eye pass shares (the
//! `none` technique's whole pass, and through [`super::parts`] every shadow technique's),
//! and the view volume of the shadowing light. A leaf of `techniques`: it uses nothing
//! but `ff` and `scene`, so `none` and `parts` both build on it and neither on the other.
//!
//! Lights are specified with the modelview equal to the camera's view, so GL stores their
//! positions and spot directions in eye space (§2.14.1) exactly where the scene puts them
//! in the world. Each light's diffuse and specular are colour × intensity, ambient stays
//! GL's black; the global ambient is a small 0.1 grey so faces turned away are not black.
//! A point or spot light is positional (w = 1); a directional light is (−direction, 0),
//! GL's "towards the light"; an area light has no GL 1.x equivalent and is lit as a point
//! at its centre (the truth softens it, the image does not).

use glam::{Vec3, Vec4};

use crate::ff::{Capability, Command, LightModelParam, LightParam, MatrixMode, ViewVolume};
use crate::scene::{Camera, Light, LightKind, Projection};

/// GL_LIGHT_MODEL_AMBIENT (RGB) while lighting is on.
pub const GLOBAL_AMBIENT: f32 = 0.1;

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
        LightKind::Directional { direction, .. } => Vec4::from((-direction.normalize(), 0.0)),
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
