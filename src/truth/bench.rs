//! Ray-caster throughput, for `fixedfunc bench` and `benches/truth.rs`.
//!
//! Figures: BVH build time, primary rays/s, and shadow rays/s — the shadow phase alone
//! (every primary hit facing the light casts one ray per light sample), which is the
//! figure the target (40 M/s on the default scene, 2 cores) is about. `fixedfunc bench
//! --only truth` on this machine's 2 cores, four interleaved runs of each build: default
//! scene 17.8–20.7 M/s when each shadow ray went through obvhs alone, 43.8–47.8 M/s (one
//! disturbed run 23.0) with the packets of `accel`; the ~1M-triangle scene 9.2–11.5 and
//! 7.8–13.3 M/s, unchanged (its rays part ways below the top of the tree and finish
//! alone). An area light's samples share their pixel's origin: 58–77 M/s at 242 per pixel
//! (`area_light_scene`), where 16 per pixel ran at 19–22 M/s before.

use super::{truth, TruthError, TruthOptions};
use crate::scene::{Camera, Light, LightKind, Object, Scene, Shape};
use glam::Vec3;
use serde::Serialize;

/// Measured throughput of one truth run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Throughput {
    pub width: u32,
    pub height: u32,
    pub triangles: usize,
    pub build_ms: f64,
    pub primary_rays: u64,
    pub primary_rays_per_s: f64,
    pub shadow_rays: u64,
    pub shadow_rays_per_s: f64,
    pub total_ms: f64,
}

/// Runs the truth on `scene` `runs` times (at least once) and reports the median run (by
/// total time; the upper middle for an even count).
pub fn throughput(
    scene: &Scene,
    options: &TruthOptions,
    runs: u32,
) -> Result<Throughput, TruthError> {
    let mut all: Vec<Throughput> = Vec::new();
    for _ in 0..runs.max(1) {
        let t = truth(scene, options)?;
        let per_s = |n: u64, d: std::time::Duration| n as f64 / d.as_secs_f64().max(1e-9);
        let run = Throughput {
            width: t.mask.width,
            height: t.mask.height,
            triangles: t.triangles,
            build_ms: t.timings.build.as_secs_f64() * 1e3,
            primary_rays: t.primary_rays,
            primary_rays_per_s: per_s(t.primary_rays, t.timings.primary),
            shadow_rays: t.shadow_rays,
            shadow_rays_per_s: per_s(t.shadow_rays, t.timings.shadow),
            total_ms: t.timings.total().as_secs_f64() * 1e3,
        };
        all.push(run);
    }
    all.sort_by(|a, b| a.total_ms.total_cmp(&b.total_ms));
    let middle = all.len() / 2;
    all.into_iter().nth(middle).ok_or(TruthError::NoSuchLight {
        index: options.light,
        count: scene.lights.len(),
    })
}

/// The default scene with its sphere tessellated to about a million triangles
/// (1000 slices × 500 stacks → 998 000, plus the ground and the torus).
pub fn million_triangle_scene() -> Scene {
    let mut scene = Scene::default_scene();
    for object in &mut scene.objects {
        if let Shape::Sphere { radius, .. } = object.shape {
            let shape = Shape::Sphere {
                radius,
                slices: 1000,
                stacks: 500,
            };
            *object = Object {
                mesh: std::sync::Arc::new(shape.procedural_mesh().unwrap_or_default()),
                shape,
                ..object.clone()
            };
        }
    }
    scene
}

/// The default scene with its spot light replaced by a 2 × 2 area light at the same place,
/// facing the origin: 242 shadow rays per lit pixel by default instead of one.
pub fn area_light_scene() -> Scene {
    let mut scene = Scene::default_scene();
    let centre = Vec3::new(6.0, 10.0, 6.0);
    let n = -centre.normalize();
    let u = Vec3::Y.cross(n).normalize();
    let v = n.cross(u);
    scene.lights = vec![Light {
        kind: LightKind::Area {
            corner: centre - (u + v),
            edge_u: 2.0 * u,
            edge_v: 2.0 * v,
        },
        // The spot light's own view, from the same place.
        view: Camera {
            eye: centre,
            ..scene.lights[0].view
        },
        colour: Vec3::ONE,
        intensity: 1.0,
    }];
    scene
}
