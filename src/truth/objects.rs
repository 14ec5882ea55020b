//! Why each shadowed pixel of the truth is shadowed, by object (`metrics::per_object`'s
//! input): the object the pixel shows, and whether its shadow is attached (the surface
//! faces away from the light), cast by the object's own geometry, or cast by others only.
//!
//! Made from a finished truth mask, so it can never disagree with it: the primary rays are
//! traced again exactly as `truth` traces them (same ray, same BVH, same hit point and
//! flipped normal), and only the mask's shadowed pixels that face the light get one more
//! shadow ray — against a BVH of the pixel's own object alone, from the same origin
//! p + ε n towards the same point (the light, or an area light's centre; the direction,
//! or a sun's centre). A hit there
//! means the object shadows itself, whatever else also blocks the light; no hit means
//! only other objects do. An object that does not cast cannot shadow itself that way.

use super::accel::{Accel, Packet};
use super::camera::PrimaryRays;
use super::shade::Emitter;
use super::{emitter, scene_radius, TruthError, OFFSET};
use crate::metrics::{Cause, Mask, ShadowCauses, BACKGROUND, LIT};
use crate::scene::Scene;
use glam::Vec3;
use rayon::prelude::*;

/// The cause of every pixel's light or shadow in `mask`, the truth mask of `scene` for its
/// light `light`.
pub fn shadow_causes(scene: &Scene, light: usize, mask: &Mask) -> Result<ShadowCauses, TruthError> {
    let (w, h) = (scene.image.width, scene.image.height);
    if (mask.width, mask.height) != (w, h) {
        return Err(TruthError::MaskSize {
            mask: (mask.width, mask.height),
            image: (w, h),
        });
    }
    let toward = match emitter(scene, light)? {
        Emitter::None => None,
        Emitter::Point(q) => Some(Toward::Point(q)),
        Emitter::Directional(d) => Some(Toward::Direction(d)),
        Emitter::Area { corner, u, v } => Some(Toward::Point(corner + 0.5 * (u + v))),
        Emitter::Sun(sun) => Some(Toward::Direction(sun.towards)),
    };
    let n = w as usize * h as usize;
    let mut causes = ShadowCauses {
        width: w,
        height: h,
        object: vec![u32::MAX; n],
        cause: vec![Cause::Background; n],
    };
    let Some(all) = Accel::build(scene, |_| true) else {
        return Ok(causes);
    };
    let own: Vec<Option<Accel>> = (0..scene.objects.len())
        .map(|k| {
            let o = &scene.objects[k];
            (o.casts && o.receives)
                .then(|| Accel::build_where(scene, |i, _| i == k))
                .flatten()
        })
        .collect();
    let epsilon = OFFSET * scene_radius(scene);
    let rays = PrimaryRays::new(scene);
    let width = w.max(1) as usize;
    causes
        .object
        .par_chunks_mut(width)
        .zip(causes.cause.par_chunks_mut(width))
        .zip(mask.data.par_chunks(width))
        .enumerate()
        .for_each(|(y, ((objects, row), values))| {
            let mut stack = Vec::new();
            for (x, (object, cause)) in objects.iter_mut().zip(row.iter_mut()).enumerate() {
                let (o, d, t_max) = rays.ray(x as u32, y as u32);
                let Some((t, id)) = all.closest(o, d, 0.0, t_max) else {
                    continue;
                };
                *object = all.objects[id];
                *cause = match (values[x], toward) {
                    (BACKGROUND, _) => Cause::Background,
                    (LIT, _) => Cause::Lit,
                    (_, None) => Cause::Lit,
                    (_, Some(toward)) => {
                        let n = if all.normals[id].dot(d) > 0.0 {
                            -all.normals[id]
                        } else {
                            all.normals[id]
                        };
                        let p = o + t * d;
                        let (facing, to_light, tmax) = toward.from(p, n, all.corner(id));
                        if facing <= 0.0 {
                            Cause::FacesAway
                        } else {
                            match &own[*object as usize] {
                                Some(accel) => {
                                    let to_light = if tmax.is_finite() {
                                        to_light - epsilon * n
                                    } else {
                                        to_light
                                    };
                                    let mut packet = Packet::default();
                                    packet.push(p + epsilon * n, to_light, tmax);
                                    if accel.occluded(&packet, &mut stack) & 1 != 0 {
                                        Cause::OwnOccluder
                                    } else {
                                        Cause::OtherOccluder
                                    }
                                }
                                None => Cause::OtherOccluder,
                            }
                        }
                    }
                };
            }
        });
    Ok(causes)
}

/// The light seen from a surface: a point, or a direction towards it.
#[derive(Debug, Clone, Copy)]
enum Toward {
    Point(Vec3),
    Direction(Vec3),
}

impl Toward {
    /// (n · L as `truth` decides facing — from the triangle's vertex `corner` for a point —
    /// the ray's direction towards the light from p, its length limit).
    fn from(self, p: Vec3, n: Vec3, corner: Vec3) -> (f32, Vec3, f32) {
        match self {
            Toward::Point(q) => (n.dot(q - corner), q - p, 1.0),
            Toward::Direction(d) => (n.dot(d), d, f32::INFINITY),
        }
    }
}
