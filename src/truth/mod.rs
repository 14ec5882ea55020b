//! The CPU ground truth: ray-cast shadow masks and soft-shadow visibility (never touches GL).
//!
//! **BVH.** obvhs (compressed 8-wide BVH built by PLOC with reinsertion, SIMD node tests).
//! Chosen over the `bvh` crate because it speaks glam instead of nalgebra, has an
//! early-out "any hit" query (`ray_traverse_miss`) — what a shadow ray needs — instead of
//! returning a `Vec` of candidate shapes per ray, and is built for ray-tracing throughput.
//! It speaks glam, like the rest of the crate.
//!
//! **Rays.** One primary ray per pixel through GL's sample point (see `camera`), then for
//! the hit point p with geometric normal n (flipped to face the viewer — we see the side we
//! see, as with two-sided lighting):
//! - if n · L ≤ 0 the surface faces away from the light: shadowed (0). For a light at a
//!   point q, n · L is taken as n · (q − v₀), v₀ a vertex of the hit triangle — the same
//!   number as n · (q − p) for p in the triangle's plane, without p's rounding, so a light
//!   exactly in a receiver's plane gives 0 everywhere instead of scattered ±10⁻⁷;
//! - else a shadow ray from p + ε n towards the light decides lit (255) or shadowed (0);
//!   only objects with `casts` occlude, only objects with `receives` are shadowed (the
//!   others are 255 when they face the light);
//! - no hit: background (128).
//!
//! L is the light position − p (point and spot lights, and the centre of an area light for
//! the hard mask), or −direction for a directional light. The spot cone is not applied:
//! the mask says whether the light is visible, not how bright it is.
//!
//! **Offset rule.** ε = 10⁻⁴ · R, R the radius of the scene's bounding sphere (half the
//! diagonal of the world bounds), so the rule does not depend on the scene's units. The
//! geometric (not interpolated) normal is used, so the terminator falls where the
//! tessellated surface's n · L = 0 and no facet shadows itself.
//!
//! **Area lights.** N samples per pixel in an s × s stratified grid (s = ⌈√N⌉) over the
//! rectangle, each jittered inside its cell by a hash of (pixel, sample) — deterministic —
//! give visibility = (unoccluded samples with n · L > 0) / s². Point lights' visibility is
//! 1 or 0 with the mask.
//!
//! **Determinism.** Every pixel is a pure function of the scene and its coordinates; rayon
//! only spreads rows over threads, so results do not depend on the thread count.

mod accel;
pub mod bench;
mod camera;
#[cfg(test)]
mod tests;

use crate::metrics::{Mask, BACKGROUND, LIT, SHADOWED};
use crate::scene::{LightKind, Scene};
use accel::Accel;
use camera::PrimaryRays;
use glam::Vec3;
use image::GrayAlphaImage;
use rayon::prelude::*;
use std::time::{Duration, Instant};

/// Relative shadow-ray offset: ε = `OFFSET` · scene radius.
pub const OFFSET: f32 = 1e-4;

/// What to compute.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TruthOptions {
    /// Which of the scene's lights casts the shadows judged.
    pub light: usize,
    /// Samples per pixel for area lights (rounded up to a square).
    pub area_samples: u32,
}

impl Default for TruthOptions {
    fn default() -> Self {
        TruthOptions {
            light: 0,
            area_samples: 16,
        }
    }
}

/// Failures of the truth layer.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TruthError {
    /// `--light I` past the scene's lights. Light 0 of a scene without lights is not this
    /// error: that truth is "nothing casts", every visible surface lit (what `none` draws).
    #[error("light {index} asked for, but {}", lights_phrase(*.count))]
    NoSuchLight { index: usize, count: usize },
}

/// "the scene has no lights" / "the scene has 1 light (index 0)" / "… 3 lights (indices
/// 0 to 2)".
fn lights_phrase(count: usize) -> String {
    match count {
        0 => "the scene has no lights".to_string(),
        1 => "the scene has 1 light (index 0)".to_string(),
        n => format!("the scene has {n} lights (indices 0 to {})", n - 1),
    }
}

/// Time spent, by phase.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Timings {
    pub build: Duration,
    pub primary: Duration,
    pub shadow: Duration,
}

impl Timings {
    pub fn total(&self) -> Duration {
        self.build + self.primary + self.shadow
    }
}

/// The ground truth of one scene and light.
#[derive(Debug, Clone, PartialEq)]
pub struct Truth {
    /// 255 lit, 0 shadowed, 128 background; top row first.
    pub mask: Mask,
    /// Fraction of the light visible per pixel, in [0, 1]; 0 on background.
    pub visibility: Vec<f32>,
    pub timings: Timings,
    pub triangles: usize,
    pub primary_rays: u64,
    pub shadow_rays: u64,
}

impl Truth {
    /// Visibility as grey (round(255 v)) with alpha 0 on background, alpha 255 elsewhere.
    pub fn visibility_image(&self) -> GrayAlphaImage {
        let data = self
            .visibility
            .iter()
            .zip(&self.mask.data)
            .flat_map(|(v, m)| {
                let alpha = if *m == BACKGROUND { 0 } else { 255 };
                [(v.clamp(0.0, 1.0) * 255.0).round() as u8, alpha]
            })
            .collect();
        GrayAlphaImage::from_raw(self.mask.width, self.mask.height, data)
            .unwrap_or_else(|| GrayAlphaImage::new(self.mask.width, self.mask.height))
    }
}

/// Where the light is, as seen from a point.
#[derive(Debug, Clone, Copy)]
enum Emitter {
    None,
    Point(Vec3),
    Directional(Vec3),
    Area { corner: Vec3, u: Vec3, v: Vec3 },
}

/// The primary hit of a pixel: point, viewer-facing unit normal, receives.
#[derive(Debug, Clone, Copy)]
struct Hit {
    p: Vec3,
    n: Vec3,
    /// A vertex of the hit triangle: n · (light − corner) decides facing exactly where
    /// n · (light − p) would carry p's rounding (a light in the receiver's plane).
    corner: Vec3,
    receives: bool,
}

/// Where a shadow ray goes: to a point (tmax = 1 along light − p) or along a direction.
#[derive(Debug, Clone, Copy)]
enum Toward {
    Point(Vec3),
    Direction(Vec3),
}

/// Computes the truth mask and visibility of `scene` for `options.light`.
pub fn truth(scene: &Scene, options: &TruthOptions) -> Result<Truth, TruthError> {
    let emitter = match scene.lights.get(options.light) {
        None if scene.lights.is_empty() && options.light == 0 => Emitter::None,
        None => {
            return Err(TruthError::NoSuchLight {
                index: options.light,
                count: scene.lights.len(),
            })
        }
        Some(light) => match (light.kind, light.position()) {
            (LightKind::Directional { direction }, _) => {
                Emitter::Directional(-direction.normalize())
            }
            (
                LightKind::Area {
                    corner,
                    edge_u,
                    edge_v,
                },
                _,
            ) => Emitter::Area {
                corner,
                u: edge_u,
                v: edge_v,
            },
            (_, Some(p)) => Emitter::Point(p),
            (_, None) => Emitter::None,
        },
    };
    let start = Instant::now();
    let all = Accel::build(scene, |_| true);
    // When every object casts, the shadow rays use the primary BVH: one build, not two.
    let every_object_casts = scene.objects.iter().all(|o| o.casts);
    let casters_only = if every_object_casts {
        None
    } else {
        Accel::build(scene, |o| o.casts)
    };
    let casters = if every_object_casts {
        all.as_ref()
    } else {
        casters_only.as_ref()
    };
    let build = start.elapsed();
    let (w, h) = (scene.image.width, scene.image.height);
    let epsilon = OFFSET * scene_radius(scene);

    let start = Instant::now();
    let rays = PrimaryRays::new(scene);
    let mut hits: Vec<Option<Hit>> = vec![None; w as usize * h as usize];
    if let Some(all) = &all {
        hits.par_chunks_mut(w.max(1) as usize)
            .enumerate()
            .for_each(|(y, row)| {
                for (x, hit) in row.iter_mut().enumerate() {
                    let (o, d, t_max) = rays.ray(x as u32, y as u32);
                    *hit = all.closest(o, d, 0.0, t_max).map(|(t, id)| {
                        let n = all.normals[id];
                        Hit {
                            p: o + t * d,
                            n: if n.dot(d) > 0.0 { -n } else { n },
                            corner: all.corner(id),
                            receives: all.receives[id],
                        }
                    });
                }
            });
    }
    let primary = start.elapsed();

    let start = Instant::now();
    let side = (options.area_samples.max(1) as f32).sqrt().ceil() as u32;
    let shaded: Vec<(u8, f32, u32)> = hits
        .par_iter()
        .enumerate()
        .map(|(i, hit)| match hit {
            None => (BACKGROUND, 0.0, 0),
            Some(hit) => shade(hit, emitter, casters, epsilon, side, i as u32),
        })
        .collect();
    let shadow = start.elapsed();

    Ok(Truth {
        mask: Mask {
            width: w,
            height: h,
            data: shaded.iter().map(|s| s.0).collect(),
        },
        visibility: shaded.iter().map(|s| s.1).collect(),
        timings: Timings {
            build,
            primary,
            shadow,
        },
        triangles: all.as_ref().map_or(0, Accel::triangle_count),
        primary_rays: u64::from(w) * u64::from(h),
        shadow_rays: shaded.iter().map(|s| u64::from(s.2)).sum(),
    })
}

/// Radius of the bounding sphere of the world-space scene (half its bounds' diagonal; 1
/// for an empty scene).
pub fn scene_radius(scene: &Scene) -> f32 {
    let bounds = scene.objects.iter().filter_map(|o| o.world_mesh().bounds());
    let (lo, hi) = bounds.fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), (a, b)| {
        (lo.min(a), hi.max(b))
    });
    let r = 0.5 * (hi - lo).length();
    if r.is_finite() && r > 0.0 {
        r
    } else {
        1.0
    }
}

/// Whether `hit` sees the light `toward` a point or along a direction: facing it (n · L
/// from the triangle's plane, exact for a light in that plane), and, on a receiver,
/// nothing in between.
fn sees(hit: &Hit, toward: Toward, casters: Option<&Accel>, epsilon: f32) -> (bool, u32) {
    let (facing, to_light, tmax) = match toward {
        Toward::Point(q) => (hit.n.dot(q - hit.corner), q - hit.p, 1.0),
        Toward::Direction(d) => (hit.n.dot(d), d, f32::INFINITY),
    };
    if facing <= 0.0 {
        return (false, 0);
    }
    match casters {
        Some(c) if hit.receives => {
            let origin = hit.p + epsilon * hit.n;
            let to_light = if tmax.is_finite() {
                to_light - epsilon * hit.n
            } else {
                to_light
            };
            (c.unoccluded(origin, to_light, tmax), 1)
        }
        _ => (true, 0),
    }
}

/// (mask value, visibility, shadow rays cast) of one pixel.
fn shade(
    hit: &Hit,
    emitter: Emitter,
    casters: Option<&Accel>,
    epsilon: f32,
    side: u32,
    pixel: u32,
) -> (u8, f32, u32) {
    let value = |lit: bool| if lit { LIT } else { SHADOWED };
    match emitter {
        Emitter::None => (LIT, 1.0, 0),
        Emitter::Point(p) => {
            let (lit, rays) = sees(hit, Toward::Point(p), casters, epsilon);
            (value(lit), if lit { 1.0 } else { 0.0 }, rays)
        }
        Emitter::Directional(d) => {
            let (lit, rays) = sees(hit, Toward::Direction(d), casters, epsilon);
            (value(lit), if lit { 1.0 } else { 0.0 }, rays)
        }
        Emitter::Area { corner, u, v } => {
            let centre = corner + 0.5 * (u + v);
            let (lit, mut rays) = sees(hit, Toward::Point(centre), casters, epsilon);
            let mut visible = 0;
            for k in 0..side * side {
                let (a, b) = (k % side, k / side);
                let (ja, jb) = jitter(pixel, k);
                let q = corner
                    + u * ((a as f32 + ja) / side as f32)
                    + v * ((b as f32 + jb) / side as f32);
                let (seen, r) = sees(hit, Toward::Point(q), casters, epsilon);
                visible += u32::from(seen);
                rays += r;
            }
            (value(lit), visible as f32 / (side * side) as f32, rays)
        }
    }
}

/// Two numbers in [0, 1) from (pixel, sample) by the PCG output hash: the same every run.
fn jitter(pixel: u32, sample: u32) -> (f32, f32) {
    let hash = |mut x: u32| {
        x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
        let word = ((x >> ((x >> 28) + 4)) ^ x).wrapping_mul(277_803_737);
        (word >> 22) ^ word
    };
    let h1 = hash(
        pixel
            .wrapping_mul(9781)
            .wrapping_add(sample.wrapping_mul(6271))
            .wrapping_add(1),
    );
    let h2 = hash(h1);
    (
        (h1 >> 8) as f32 / (1u32 << 24) as f32,
        (h2 >> 8) as f32 / (1u32 << 24) as f32,
    )
}
