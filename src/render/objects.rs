//! The per-object lines `fixedfunc render` prints under its figures line for a scene of
//! several objects: on each object, how much of its self-shadow (attached, and cast by its
//! own geometry), of the shadow other objects cast on it, and of its lit surface the
//! technique got wrong (`metrics::per_object`, causes from `truth::shadow_causes`).
//!
//! `  aircraft: self-shadow wrong 3.11% (42 of 1350 px; facing away 2 of 900, own
//! occluder 40 of 450) · from others wrong 0.00% (0 of 0 px) · lit wrong 0.40% (12 of
//! 3000 px)` — one line per object that shows in the image, in scene order. An object
//! without a name is called by its index and shape.
//!
//! The split is made in two steps so that a study judging many masks against one truth
//! traces the causes once: [`object_causes`] (one extra shadow ray per shadowed pixel that
//! faces the light) and [`object_split`] (one pass over the pixels). A scene of one object
//! has no split: its one line would only repeat the figures line.

use crate::metrics::{per_object, Mask, ObjectErrors, ShadowCauses};
use crate::scene::{Scene, Shape};
use crate::truth::{self, TruthError};

use super::RenderError;

/// Why each pixel of `truth`, the truth mask of `scene` for its light `light`, is lit or
/// shadowed, by object; `None` for a scene of one object (no split).
pub fn object_causes(
    scene: &Scene,
    light: usize,
    truth: &Mask,
) -> Result<Option<ShadowCauses>, TruthError> {
    if scene.objects.len() < 2 {
        return Ok(None);
    }
    truth::shadow_causes(scene, light, truth).map(Some)
}

/// Each object's share of `mask`'s errors against the truth `causes` were made from
/// (`metrics::per_object`); empty without causes.
pub fn object_split(
    mask: &Mask,
    causes: Option<&ShadowCauses>,
) -> Result<Vec<ObjectErrors>, RenderError> {
    Ok(match causes {
        Some(causes) => per_object(mask, causes)?,
        None => Vec::new(),
    })
}

/// The per-object split of `mask`'s errors, one line each (see the module note).
pub fn object_lines(
    scene: &Scene,
    mask: &Mask,
    causes: &ShadowCauses,
) -> Result<Vec<String>, RenderError> {
    Ok(per_object(mask, causes)?
        .iter()
        .map(|e| object_line(scene, e))
        .collect())
}

/// What a line calls object `index`: its name, else `object I (shape)`.
pub fn object_name(scene: &Scene, index: usize) -> String {
    match scene.objects.get(index) {
        Some(o) => match &o.name {
            Some(name) => name.clone(),
            None => format!("object {index} ({})", shape_word(&o.shape)),
        },
        None => format!("object {index}"),
    }
}

/// One object's line.
pub fn object_line(scene: &Scene, e: &ObjectErrors) -> String {
    let own = e.self_shadow();
    format!(
        "  {}: self-shadow wrong {:.2}% ({} of {} px; facing away {} of {}, own occluder {} of {}) \
         · from others wrong {:.2}% ({} of {} px) · lit wrong {:.2}% ({} of {} px)",
        object_name(scene, e.object),
        own.percent(),
        own.wrong,
        own.pixels,
        e.faces_away.wrong,
        e.faces_away.pixels,
        e.own_occluder.wrong,
        e.own_occluder.pixels,
        e.other_occluder.percent(),
        e.other_occluder.wrong,
        e.other_occluder.pixels,
        e.lit.percent(),
        e.lit.wrong,
        e.lit.pixels,
    )
}

/// The scene file's word for a shape.
fn shape_word(shape: &Shape) -> &'static str {
    match shape {
        Shape::Plane { .. } => "plane",
        Shape::Box { .. } => "box",
        Shape::Sphere { .. } => "sphere",
        Shape::Torus { .. } => "torus",
        Shape::Teapot { .. } => "teapot",
        Shape::Aircraft { .. } => "aircraft",
        Shape::Obj { .. } => "mesh",
    }
}
