//! The CPU ground truth: ray-cast shadow masks and soft-shadow visibility (never touches GL).
//!
//! **BVH.** obvhs (compressed 8-wide BVH built by PLOC with reinsertion, SIMD node tests).
//! Chosen over the `bvh` crate because it speaks glam instead of nalgebra, like the rest
//! of the crate, has an early-out "any hit" query (`ray_traverse_miss`) — what a shadow
//! ray needs — instead of returning a `Vec` of candidate shapes per ray, and is built for
//! ray-tracing throughput. Primary rays use its closest-hit query; shadow rays a packet
//! traversal of its nodes written in `accel` (obvhs has none), which decides each ray as
//! `ray_traverse_miss` does.
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
//! **Area lights.** N samples per pixel (`[truth] samples`, `truth --samples`; default
//! [`TruthSettings::DEFAULT_SAMPLES`]) in two independent stratified grids A and B of
//! s × s cells each over the rectangle, s = ⌈√(N/2)⌉ (so N is rounded up to 2 s²: 2, 8, 18,
//! 32, 50, 72, 98, 128, …). Each sample is jittered inside its cell by a hash of (seed,
//! grid, pixel, sample) — deterministic, and unrelated between grids and seeds. A sample
//! is seen when n · L > 0 and nothing occludes it; with a and b the samples each grid
//! sees, visibility = (a + b) / 2s². The hard mask is the centre's, as for a point light.
//! Point lights' visibility is 1 or 0 with the mask.
//!
//! **Suns.** A directional light with `angular_diameter` α > 0 is a disc of directions, the
//! cone of half-angle α/2 around w = −direction. It is sampled as an area light is, with
//! the same two s × s grids and the same jitter, each jittered point (s, t) of the unit
//! square carried onto the cone by `scene::SunDisc::direction` (Shirley–Chiu's concentric
//! map onto the disc, then the cap uniformly in solid angle: 1 − cos θ = r² (1 − cos α/2)),
//! so the strata stay strata. A sample is seen when n · ω > 0 (the part of the sun above
//! the receiver's plane, as for an area light's points) and no caster lies along ω; the
//! visibility is again (a + b) / 2s², with the same standard error. The hard mask is w's
//! ray, the same as a hard directional light's. Its cost, measured at 512² and 242
//! samples: `assets/sunlight.toml`, 41.5 M shadow rays in 1.5–1.7 s on 2 cores, against
//! 1.0–1.1 s for the same count under `assets/soft.toml`'s area light; a sun of 10⁻⁴°
//! over the same scene takes as long, so the spread of the directions costs nothing — the
//! map itself is ≈ 13 ns a sample (sin_cos, one root).
//!
//! **The truth's own error.** A and B are independent unbiased estimates of the same
//! visibility V, so E[((A − B)/2)²] = (Var A + Var B)/4 = Var((A + B)/2): the per-pixel
//! (A − B)²/4 is an unbiased estimate of the squared error of the visibility given, and
//! the root of its mean over the geometry pixels is [`AreaEstimate::standard_error`] —
//! the truth's RMSE against the exact visibility, measured by the truth itself. (The
//! binomial variance V(1 − V)/N would only bound it from above: stratification makes the
//! error several times smaller than that, most of all where the penumbra is wide.) The
//! price is two grids of s² instead of one of 2s²: for a sharp edge across the light the
//! stratified error falls as N^(−3/4), so the halves cost 2^(1/4) ≈ 1.19 in RMSE at the
//! same N.
//!
//! **The default, measured.** [`TruthSettings::DEFAULT_SAMPLES`] = 242 (2 × 11²) keeps
//! the RMSE under 0.005 with a 20% margin (200 is the first count under it) on both
//! area-light scenes of the tests, at 256², against an independent reference of 2048 samples (2 × 32², seed 1; its
//! own standard error 0.00085 and 0.00033): `half-plane` (the `area_light_penumbra` scene,
//! a 2 × 2 light 8 above the ground and a half-plane occluder at 4, whose exact visibility
//! clamp((x + 1)/2, 0, 1) is known; a quarter of its pixels in penumbra, the hard case) and
//! `default-area` (the default scene lit by a 2 × 2 area light where its spot light was;
//! 5% in penumbra). RMSE over geometry pixels, then over the reference's penumbra:
//!
//! | samples | half-plane vs reference | vs exact | its standard error | default-area | its standard error |
//! |--------:|------------------------:|---------:|-------------------:|-------------:|-------------------:|
//! |      18 | 0.0279 (0.0557)         |   0.0279 |             0.0278 | 0.0112 (0.0496) |          0.0113 |
//! |     128 | 0.0064 (0.0128)         |   0.0063 |             0.0064 | 0.0026 (0.0116) |          0.0026 |
//! |     200 | 0.0046 (0.0092)         |   0.0045 |             0.0046 | 0.0019 (0.0084) |          0.0019 |
//! | **242** | **0.0040** (0.0080)     |   0.0039 |             0.0039 | 0.0016 (0.0070) |          0.0016 |
//! |     288 | 0.0036 (0.0071)         |   0.0035 |             0.0035 | 0.0014 (0.0064) |          0.0014 |
//!
//! The error falls as N^(−3/4), the printed standard error matches the measured RMSE
//! within 3%, and the mean error is 0 (`the_standard_error_is_the_error_against_the_exact_visibility`).
//! Repeat with `cargo test --release --lib truth::tests::default_samples_converge --
//! --ignored --nocapture` (it prints every count from 8 to 338 and checks the default).
//!
//! **Speed.** Shadow rays are traced in packets of 32 (`accel`): one pixel's samples of an
//! area light share an origin, neighbouring pixels' rays share a point light, and either
//! bundle walks the BVH together, a pretest dropping for the whole packet the children no
//! ray enters. Point and directional lights give the same masks, bit for bit, as tracing
//! each ray alone through obvhs did. Each pixel's primary hit is kept as its point and a
//! triangle index (16 bytes), no ray allocates, and rows are spread over threads by
//! rayon, each with its own packet and traversal stack (`shade`).
//!
//! **Determinism.** Every pixel is a pure function of the scene and its coordinates; rayon
//! only spreads rows over threads, so results do not depend on the thread count.

mod accel;
pub mod bench;
mod camera;
mod objects;
mod shade;
#[cfg(test)]
mod tests;

use crate::metrics::Mask;
use crate::scene::{LightKind, Scene, TruthSettings};
pub use objects::shadow_causes;

use accel::Accel;
use camera::PrimaryRays;
use glam::Vec3;
use image::GrayAlphaImage;
use rayon::prelude::*;
use shade::{Emitter, Hit, Shader, Tally};
use std::time::{Duration, Instant};

/// Relative shadow-ray offset: ε = `OFFSET` · scene radius.
pub const OFFSET: f32 = 1e-4;

/// What to compute. Default: light 0, the scene's samples, seed 0.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct TruthOptions {
    /// Which of the scene's lights casts the shadows judged.
    pub light: usize,
    /// Samples per pixel for an area light, 1 to [`TruthSettings::MAX_SAMPLES`] (rounded
    /// up to 2 s²); `None`: the scene's `[truth] samples`.
    pub area_samples: Option<u32>,
    /// Which jitter the area-light samples take: 0 for the truth; any other value gives an
    /// estimate independent of it (a reference for the truth's own error).
    pub seed: u32,
}

/// Failures of the truth layer.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TruthError {
    /// `--light I` past the scene's lights. Light 0 of a scene without lights is not this
    /// error: that truth is "nothing casts", every visible surface lit (what `none` draws).
    #[error("light {index} asked for, but {}", lights_phrase(*.count))]
    NoSuchLight { index: usize, count: usize },
    /// An area-light sample count outside 1 to `max`.
    #[error("{samples} samples per pixel asked for; the truth takes 1 to {max}")]
    Samples { samples: u32, max: u32 },
    /// A mask given to [`shadow_causes`] that is not of the scene's image size.
    #[error("the truth mask is {}×{}, the scene's image {}×{}", .mask.0, .mask.1, .image.0, .image.1)]
    MaskSize { mask: (u32, u32), image: (u32, u32) },
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

/// How an area light's (or a sun's) visibility was sampled, and how close it is to the
/// exact one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AreaEstimate {
    /// Each of the two stratified grids is `side` × `side`.
    pub side: u32,
    /// Root mean square over the geometry pixels of |A − B| / 2, A and B the visibility
    /// of the two independent grids: the estimated RMSE of the visibility (module note).
    pub standard_error: f64,
    /// Pixels that see geometry (the mean's count).
    pub geometry_pixels: u64,
}

impl AreaEstimate {
    /// Samples per pixel: 2 s².
    pub fn samples(&self) -> u32 {
        2 * self.side * self.side
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
    /// For an area light or a sun: the sampling and its standard error; `None` otherwise
    /// (its presence is what makes a scene judged by visibility).
    pub area: Option<AreaEstimate>,
}

impl Truth {
    /// Visibility as grey (round(255 v)) with alpha 0 on background, alpha 255 elsewhere.
    pub fn visibility_image(&self) -> GrayAlphaImage {
        let data = self
            .visibility
            .iter()
            .zip(&self.mask.data)
            .flat_map(|(v, m)| {
                let alpha = if *m == crate::metrics::BACKGROUND {
                    0
                } else {
                    255
                };
                [(v.clamp(0.0, 1.0) * 255.0).round() as u8, alpha]
            })
            .collect();
        GrayAlphaImage::from_raw(self.mask.width, self.mask.height, data)
            .unwrap_or_else(|| GrayAlphaImage::new(self.mask.width, self.mask.height))
    }
}

/// The side s of the two s × s grids for `samples` per pixel: ⌈√(samples / 2)⌉.
pub fn grid_side(samples: u32) -> u32 {
    let mut side = 1;
    while 2 * side * side < samples {
        side += 1;
    }
    side
}

/// Computes the truth mask and visibility of `scene` for `options.light`.
pub fn truth(scene: &Scene, options: &TruthOptions) -> Result<Truth, TruthError> {
    let samples = options.area_samples.unwrap_or(scene.truth.samples);
    if !(1..=TruthSettings::MAX_SAMPLES).contains(&samples) {
        return Err(TruthError::Samples {
            samples,
            max: TruthSettings::MAX_SAMPLES,
        });
    }
    let emitter = emitter(scene, options.light)?;
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
    let width = w.max(1) as usize;

    let start = Instant::now();
    let rays = PrimaryRays::new(scene);
    let mut hits = vec![Hit::NONE; w as usize * h as usize];
    if let Some(all) = &all {
        hits.par_chunks_mut(width).enumerate().for_each(|(y, row)| {
            for (x, hit) in row.iter_mut().enumerate() {
                let (o, d, t_max) = rays.ray(x as u32, y as u32);
                if let Some((t, id)) = all.closest(o, d, 0.0, t_max) {
                    *hit = Hit::new(o + t * d, id, all.normals[id].dot(d) > 0.0);
                }
            }
        });
    }
    let primary = start.elapsed();

    let side = grid_side(samples);
    let mut mask = vec![0u8; hits.len()];
    let mut visibility = vec![0.0f32; hits.len()];
    let start = Instant::now();
    let tally = match &all {
        None => {
            mask.fill(crate::metrics::BACKGROUND);
            Tally::default()
        }
        Some(all) => {
            let shader = Shader {
                all,
                casters,
                emitter,
                epsilon: OFFSET * scene_radius(scene),
                side,
                seed: options.seed,
            };
            let rows: Vec<Tally> = mask
                .par_chunks_mut(width)
                .zip(visibility.par_chunks_mut(width))
                .zip(hits.par_chunks(width))
                .enumerate()
                .map_init(shade::Scratch::default, |scratch, (y, ((m, v), hits))| {
                    shader.row(y as u32 * w, hits, m, v, scratch)
                })
                .collect();
            rows.iter().fold(Tally::default(), |a, b| a.add(b))
        }
    };
    let shadow = start.elapsed();

    let soft = matches!(emitter, Emitter::Area { .. } | Emitter::Sun(_));
    let area = soft.then(|| AreaEstimate {
        side,
        standard_error: tally.standard_error(side),
        geometry_pixels: tally.geometry_pixels,
    });
    Ok(Truth {
        mask: Mask {
            width: w,
            height: h,
            data: mask,
        },
        visibility,
        timings: Timings {
            build,
            primary,
            shadow,
        },
        triangles: all.as_ref().map_or(0, Accel::triangle_count),
        primary_rays: u64::from(w) * u64::from(h),
        shadow_rays: tally.rays,
        area,
    })
}

/// The light `light` of the scene as the shader sees it (an area light or a sun whole; its
/// centre is the hard mask's point or direction).
fn emitter(scene: &Scene, light: usize) -> Result<Emitter, TruthError> {
    Ok(match scene.lights.get(light) {
        None if scene.lights.is_empty() && light == 0 => Emitter::None,
        None => {
            return Err(TruthError::NoSuchLight {
                index: light,
                count: scene.lights.len(),
            })
        }
        Some(light) => match (light.kind, light.position()) {
            (LightKind::Directional { direction, .. }, _) => match light.sun() {
                Some(sun) => Emitter::Sun(sun),
                None => Emitter::Directional(-direction.normalize()),
            },
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
