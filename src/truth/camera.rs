//! Primary rays through GL's sample points, built from the camera's basis in f64.
//!
//! GL rasterises a triangle into pixel (i, j_gl) when it covers the pixel centre, window
//! coordinates (i + ½, j_gl + ½) with j_gl counted from the bottom. Image rows are stored
//! top row first, so image row y is j_gl = H − 1 − y and the sample is at window
//! (i + ½, H − y − ½). Its normalised device coordinates are x = 2 wx / W − 1,
//! y = 2 wy / H − 1.
//!
//! The ray is written in gluLookAt's eye frame — f = (at − eye)/|at − eye|,
//! s = (f × up)/|f × up|, u = s × f, the eye looking down −z_eye = f — and GL's clip volume
//! is exactly near ≤ −z_eye ≤ far. So the ray runs along
//! - gluPerspective: e = (x · t · aspect, y · t, −1) with t = tan(fovy / 2), from the eye
//!   point at distance `near` along it: origin = eye + near · (world of e), and
//!   −z_eye = near + t' along the direction (world of e), t' ∈ [0, far − near];
//! - glOrtho: origin = eye + s · (l + (x + 1)/2 · (r − l)) + u · (b + (y + 1)/2 · (t − b))
//!   + near · f, direction f, t' ∈ [0, far − near].
//!
//! Depth clipping is then t' ∈ [0, far − near], and the nearest t' is the nearest window
//! depth (depth is monotonic along the ray), as GL's LESS test picks.
//!
//! Why not unproject through (P·V)⁻¹: in f32, with far/near ≥ ~10⁵ (near 4, far 10⁶;
//! near 0.01, far 10⁸; near 10⁻⁶, far 50) the inverse's w at z_ndc = ±1 is a difference
//! of nearly equal numbers, the unprojected points are wrong by orders of magnitude (or
//! infinite), every ray missed and the truth came out all background. The basis and the
//! frustum bounds have no such cancellation; f64 keeps the few products exact enough
//! before the result is rounded once to f32 for the BVH.

use crate::scene::{Camera, Projection, Scene};
use glam::{DVec3, Vec3};

/// The camera's ray generator for the scene's image size.
pub(super) struct PrimaryRays {
    eye: DVec3,
    /// gluLookAt's side, up and forward unit vectors (s, u, f).
    side: DVec3,
    up: DVec3,
    forward: DVec3,
    frustum: Frustum,
    width: f64,
    height: f64,
}

/// The projection's bounds in the eye frame.
enum Frustum {
    /// Half-extents of the near plane at unit distance: (tan(fovy/2) · aspect, tan(fovy/2)).
    Perspective {
        half_x: f64,
        half_y: f64,
        near: f64,
        far: f64,
    },
    Orthographic {
        left: f64,
        right: f64,
        bottom: f64,
        top: f64,
        near: f64,
        far: f64,
    },
}

impl PrimaryRays {
    pub fn new(scene: &Scene) -> PrimaryRays {
        let (w, h) = (f64::from(scene.image.width), f64::from(scene.image.height));
        PrimaryRays::for_camera(&scene.camera, w, h)
    }

    fn for_camera(camera: &Camera, width: f64, height: f64) -> PrimaryRays {
        let eye = camera.eye.as_dvec3();
        let forward = (camera.at.as_dvec3() - eye).normalize();
        let side = forward.cross(camera.up.as_dvec3()).normalize();
        let up = side.cross(forward);
        let frustum = match camera.projection {
            Projection::Perspective { fovy, near, far } => {
                let t = (f64::from(fovy).to_radians() / 2.0).tan();
                Frustum::Perspective {
                    half_x: t * width / height,
                    half_y: t,
                    near: f64::from(near),
                    far: f64::from(far),
                }
            }
            Projection::Orthographic {
                left,
                right,
                bottom,
                top,
                near,
                far,
            } => Frustum::Orthographic {
                left: f64::from(left),
                right: f64::from(right),
                bottom: f64::from(bottom),
                top: f64::from(top),
                near: f64::from(near),
                far: f64::from(far),
            },
        };
        PrimaryRays {
            eye,
            side,
            up,
            forward,
            frustum,
            width,
            height,
        }
    }

    /// The ray through pixel (x, y), y from the top: (origin on the near plane, direction,
    /// t_max). Points origin + t · direction with t ∈ [0, t_max] are exactly those GL's
    /// clip volume keeps along the pixel's sample.
    pub fn ray(&self, x: u32, y: u32) -> (Vec3, Vec3, f32) {
        let wx = f64::from(x) + 0.5;
        let wy = self.height - f64::from(y) - 0.5;
        let nx = 2.0 * wx / self.width - 1.0;
        let ny = 2.0 * wy / self.height - 1.0;
        let (origin, direction, length) = match self.frustum {
            Frustum::Perspective {
                half_x,
                half_y,
                near,
                far,
            } => {
                // −z_eye grows by 1 per unit of t along this direction.
                let d = self.side * (nx * half_x) + self.up * (ny * half_y) + self.forward;
                (self.eye + d * near, d, far - near)
            }
            Frustum::Orthographic {
                left,
                right,
                bottom,
                top,
                near,
                far,
            } => {
                let sx = left + 0.5 * (nx + 1.0) * (right - left);
                let sy = bottom + 0.5 * (ny + 1.0) * (top - bottom);
                let o = self.eye + self.side * sx + self.up * sy + self.forward * near;
                (o, self.forward, far - near)
            }
        };
        (origin.as_vec3(), direction.as_vec3(), length as f32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Where GL puts a world point: window (x, y from the top) and depth z_ndc.
    fn project(camera: &Camera, w: f32, h: f32, p: Vec3) -> (f32, f32, f32) {
        let clip = camera.projection_matrix(w / h) * camera.view();
        let c: glam::Vec4 = clip * p.extend(1.0);
        let n = c.truncate() / c.w;
        ((n.x + 1.0) / 2.0 * w, h - (n.y + 1.0) / 2.0 * h, n.z)
    }

    /// For moderate near/far (where the f32 matrices are accurate), each ray's near and
    /// far ends project back onto its pixel's sample, at z_ndc = −1 and +1.
    #[test]
    fn ray_ends_land_on_the_sample_at_the_near_and_far_planes() {
        let cameras = [
            Camera {
                eye: Vec3::new(0.0, 9.0, 20.0),
                at: Vec3::ZERO,
                up: Vec3::Y,
                projection: Projection::Perspective {
                    fovy: 40.0,
                    near: 4.0,
                    far: 50.0,
                },
            },
            Camera {
                eye: Vec3::new(3.0, 5.0, -2.0),
                at: Vec3::new(0.5, 0.0, 1.0),
                up: Vec3::new(0.2, 1.0, 0.0),
                projection: Projection::Orthographic {
                    left: -3.0,
                    right: 5.0,
                    bottom: -2.0,
                    top: 4.0,
                    near: -1.0,
                    far: 30.0,
                },
            },
        ];
        let (w, h) = (64.0f32, 48.0f32);
        for camera in cameras {
            let rays = PrimaryRays::for_camera(&camera, f64::from(w), f64::from(h));
            for (x, y) in [(0, 0), (63, 0), (0, 47), (31, 20), (63, 47)] {
                let (o, d, t_max) = rays.ray(x, y);
                for (p, z) in [(o, -1.0), (o + d * t_max, 1.0)] {
                    let (px, py, pz) = project(&camera, w, h, p);
                    assert!(
                        (px - (x as f32 + 0.5)).abs() < 1e-3
                            && (py - (y as f32 + 0.5)).abs() < 1e-3
                            && (pz - z).abs() < 1e-4,
                        "{camera:?} pixel ({x}, {y}): ({px}, {py}, {pz})"
                    );
                }
            }
        }
    }
}
