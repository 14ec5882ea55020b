//! Primary rays through GL's sample points.
//!
//! GL rasterises a triangle into pixel (i, j_gl) when it covers the pixel centre, window
//! coordinates (i + ½, j_gl + ½) with j_gl counted from the bottom. Image rows are stored
//! top row first, so image row y is j_gl = H − 1 − y and the sample is at window
//! (i + ½, H − y − ½). Its normalised device coordinates are x = 2 wx / W − 1,
//! y = 2 wy / H − 1; the ray runs from the unprojected point at z_ndc = −1 (near plane) to
//! the one at z_ndc = +1 (far plane) through (P·V)⁻¹, P and V being gluPerspective/glOrtho
//! and gluLookAt. Depth clipping is then exactly t ∈ [0, 1] along that segment, and the
//! nearest t is the nearest window depth (depth is monotonic along the ray), as GL's LESS
//! test picks.

use crate::scene::Scene;
use glam::{Mat4, Vec3};

/// The camera's ray generator for the scene's image size.
pub(super) struct PrimaryRays {
    inverse: Mat4,
    width: f32,
    height: f32,
}

impl PrimaryRays {
    pub fn new(scene: &Scene) -> PrimaryRays {
        let (w, h) = (scene.image.width as f32, scene.image.height as f32);
        let clip = scene.camera.projection_matrix(w / h) * scene.camera.view();
        PrimaryRays {
            inverse: clip.inverse(),
            width: w,
            height: h,
        }
    }

    /// The segment (origin on the near plane, far − near) through pixel (x, y), y from the top.
    pub fn ray(&self, x: u32, y: u32) -> (Vec3, Vec3) {
        let wx = x as f32 + 0.5;
        let wy = self.height - y as f32 - 0.5;
        let nx = 2.0 * wx / self.width - 1.0;
        let ny = 2.0 * wy / self.height - 1.0;
        let near = self.inverse.project_point3(Vec3::new(nx, ny, -1.0));
        let far = self.inverse.project_point3(Vec3::new(nx, ny, 1.0));
        (near, far - near)
    }
}
