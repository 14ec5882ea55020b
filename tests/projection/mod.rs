//! Shared by the projection-shadow tests: scenes from TOML text, renders on real contexts,
//! and scoring a mask against the truth on one receiver's pixels.
#![allow(dead_code)]

use fixedfunc::vocab::PipelineKind;
use std::path::Path;

use fixedfunc::metrics::{edge_band, Class, Mask};
use fixedfunc::render::{apply_overrides, render, ImageSize, RenderOptions, RenderOutcome};
use fixedfunc::scene::Scene;
use fixedfunc::techniques::parse_name;
use fixedfunc::truth::{truth, TruthOptions};

pub const KINDS: [PipelineKind; 2] = [PipelineKind::Emulate, PipelineKind::Native];

/// A scene from TOML text; a bad scene fails the test with its error.
pub fn scene(text: &str) -> Scene {
    Scene::parse(text, Path::new("test.toml")).unwrap_or_else(|e| panic!("{e}"))
}

/// One frame of `technique` on the EGL backend at `size`.
pub fn run(
    scene: &Scene,
    technique: &str,
    pipeline: PipelineKind,
    size: ImageSize,
) -> RenderOutcome {
    let options = RenderOptions {
        pipeline,
        technique: Some(parse_name(technique).expect("a technique")),
        size: Some(size),
        frames: 2,
        ..RenderOptions::default()
    };
    render(scene, &options).unwrap_or_else(|e| panic!("{technique} {pipeline:?}: {e}"))
}

/// The pixels where object `index` is the visible surface: geometry in the truth of the
/// scene, background in the truth of the scene without that object's rivals… computed as
/// "geometry with it, background without everything else" — exact when the other objects
/// stand in front of it (the eye and they are on the same side of a floor).
pub fn pixels_of(scene: &Scene, index: usize, size: ImageSize) -> Vec<bool> {
    let full = apply_overrides(scene, Some(size), None);
    let mut others = full.clone();
    others.objects.remove(index);
    let options = TruthOptions::default();
    let with = truth(&full, &options).expect("truth").mask;
    let without = truth(&others, &options).expect("truth").mask;
    with.data
        .iter()
        .zip(&without.data)
        .map(|(&a, &b)| Class::of(a) != Class::Background && Class::of(b) == Class::Background)
        .collect()
}

/// Disagreements of `mask` with `truth` over `pixels`: (pixels, wrong, wrong outside the
/// k-pixel band around the truth's shadow edges).
#[derive(Debug, Clone, Copy)]
pub struct Score {
    pub pixels: usize,
    pub shadowed_in_truth: usize,
    pub wrong: usize,
    pub wrong_outside_band: usize,
}

pub fn score(mask: &Mask, truth: &Mask, pixels: &[bool], band: u32) -> Score {
    let near_edge = edge_band(truth, band);
    let mut s = Score {
        pixels: 0,
        shadowed_in_truth: 0,
        wrong: 0,
        wrong_outside_band: 0,
    };
    for i in (0..pixels.len()).filter(|&i| pixels[i]) {
        s.pixels += 1;
        let t = Class::of(truth.data[i]);
        if t == Class::Shadowed {
            s.shadowed_in_truth += 1;
        }
        if Class::of(mask.data[i]) != t {
            s.wrong += 1;
            if !near_edge[i] {
                s.wrong_outside_band += 1;
            }
        }
    }
    s
}

/// Pixels a mask shadows.
pub fn shadowed(mask: &Mask) -> usize {
    mask.data
        .iter()
        .filter(|&&v| Class::of(v) == Class::Shadowed)
        .count()
}

/// Pixels whose class differs between two masks.
pub fn mask_difference(a: &Mask, b: &Mask) -> usize {
    a.data
        .iter()
        .zip(&b.data)
        .filter(|(x, y)| Class::of(**x) != Class::of(**y))
        .count()
}

/// A floor (16 × 16 at y = 0, receives only) under a point light, with `objects` appended
/// (TOML `[[object]]` tables) and `shadow` lines in `[shadow]`.
pub fn floor_scene(light: &str, objects: &str, shadow: &str) -> Scene {
    scene(&format!(
        r#"
[camera]
eye = [0, 12, 18]
at = [0, 0, 0]
up = [0, 1, 0]
fovy = 45
near = 2
far = 60

[image]
width = 128
height = 128
background = [0.25, 0.25, 0.375]

{light}

[[object]]
name = "floor"
shape = "plane"
size = 16
tessellation = 4
casts = false
colour = [0.8, 0.8, 0.8]

{objects}

[shadow]
{shadow}
"#
    ))
}

/// A point light at `position` looking at the origin.
pub fn point_light(position: [f32; 3]) -> String {
    format!(
        "[[light]]\ntype = \"point\"\nposition = [{}, {}, {}]\nat = [0, 0, 0]\nfovy = 120\nnear = 0.5\nfar = 60\n",
        position[0], position[1], position[2]
    )
}
