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
//! The camera and the lights come from [`super::setup`], which the shadow techniques share
//! (through [`super::parts`]).
//!
//! Without lights nothing about lighting is enabled and each object is drawn in its flat
//! colour (glColor). NORMALIZE is enabled only when some transform scales (a rotation and a
//! translation keep normals unit length). No texture unit is touched.
//!
//! **Mask.** The technique casts no shadows, so its mask is its coverage: the frame's depth
//! buffer read back as FLOAT after the last frame (no extra pass), 255 where z < 1, 128 where
//! the clear value 1 survived (see [`super::MaskSource::DepthCoverage`]).

use crate::ff::{Command, PixelFormat, PixelType, ReadPixels};
use crate::scene::Scene;
use crate::vocab::DepthBits;

use super::parts::Paint;
use super::setup::lighting;
use super::{
    check_light_count, FramebufferNeeds, MaskPlan, MaskSource, Pass, Plan, Prepared, Technique,
    TechniqueError, MASK_SLOT,
};

pub const TECHNIQUE: Technique = Technique {
    summary: "the lit scene alone, one pass, no shadows",
    plan,
};

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
