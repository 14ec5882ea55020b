//! The current raster position (GL 1.5 §2.13): glRasterPos transforms a point as a vertex
//! is transformed — modelview, projection, clipping against the view volume and the
//! enabled user clip planes, perspective division, viewport and depth range — and keeps
//! the window coordinates with the colour, texture coordinates and eye distance the vertex
//! would have had. glWindowPos (GL 1.4) sets the window coordinates directly.
//!
//! What Mesa 22.3 does where GL leaves room, followed here and checked against the native
//! path (`tests/fidelity_raster_pos.rs`):
//! - An invalid position keeps the other raster values as they were (GL leaves them
//!   undefined); only VALID becomes FALSE.
//! - The fourth window coordinate is the clip w; the distance is the Euclidean eye-space
//!   distance √(x_e² + y_e² + z_e²) under FOG_COORD_SRC = FRAGMENT_DEPTH, and the current
//!   fog coordinate as given (a negative one stays negative) under FOG_COORD, for
//!   glRasterPos and glWindowPos alike (measured, `tests/c/secondary.c`).
//! - glRasterPos's unlit colour is the current colour as given (unclamped); glWindowPos
//!   clamps it to [0, 1], and sets the distance to 0 (under FRAGMENT_DEPTH) and w to 1.
//! - SPHERE_MAP reflects the eye position in the *object* normal unless Mesa computes in
//!   eye space (lighting on, or a texturing unit generating in eye space).

use glam::{Vec3, Vec4};

use super::error::{GlError, GlResult};
use super::pixels::{check_rect, Bitmap};
use super::state::{FixedState, MAX_TEXTURE_UNITS};
use super::texgen::{sphere_map, TexCoord, TexGenMode};

/// CURRENT_RASTER_* (GL 1.5 Table 6.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RasterPos {
    /// (x_w, y_w, z_w, w_c). GL default: (0, 0, 0, 1).
    pub window: Vec4,
    /// GL default: TRUE.
    pub valid: bool,
    /// GL default: (1, 1, 1, 1).
    pub color: Vec4,
    /// Per unit. GL default: (0, 0, 0, 1).
    pub texcoords: [Vec4; MAX_TEXTURE_UNITS],
    /// GL default: 0.
    pub distance: f32,
}

impl RasterPos {
    pub const DEFAULT: Self = Self {
        window: Vec4::W,
        valid: true,
        color: Vec4::ONE,
        texcoords: [Vec4::W; MAX_TEXTURE_UNITS],
        distance: 0.0,
    };
}

impl Default for RasterPos {
    fn default() -> Self {
        Self::DEFAULT
    }
}

impl FixedState {
    /// glRasterPos4f(object) (§2.13).
    pub(crate) fn set_raster_pos(&mut self, object: Vec4) {
        let eye = self.modelview_matrix() * object;
        let clip = self.projection_matrix() * eye;
        // Clipping (§2.12): −w ≤ x, y, z ≤ w; a user plane keeps p′·v_e ≥ 0. As Mesa tests
        // it (measured through OSMesa): rejected only where a comparison fails outright
        // (x > w, x < −w, p′·v_e < 0), so a NaN or an infinity that makes one passes, and the
        // position is valid with NaN window coordinates, which draw nothing.
        let outside = [clip.x, clip.y, clip.z]
            .iter()
            .any(|c| *c > clip.w || *c < -clip.w);
        let rejected = self
            .clip_planes
            .iter()
            .filter(|p| p.enabled)
            .any(|p| p.value.dot(eye) < 0.0);
        if outside || rejected {
            self.raster.valid = false;
            return;
        }
        // Normalised device coordinates x/w; Mesa divides by 1 where w = 0 (the point
        // (0, 0, 0, 0) passes the test above and lands at the viewport's centre).
        let w = if clip.w == 0.0 { 1.0 } else { clip.w };
        let ndc = clip.truncate() / w;
        let v = self.viewport;
        let (n, f) = (self.depth_range.near, self.depth_range.far);
        // x_w = (p_x/2)·x_d + o_x with p_x = width, o_x = x + width/2 (§2.11.1); likewise y;
        // z_w = ((f − n)/2)·z_d + (n + f)/2.
        let window = Vec4::new(
            v.width as f32 / 2.0 * ndc.x + (v.x as f32 + v.width as f32 / 2.0),
            v.height as f32 / 2.0 * ndc.y + (v.y as f32 + v.height as f32 / 2.0),
            (f - n) / 2.0 * ndc.z + (n + f) / 2.0,
            clip.w,
        );
        let normal = self.eye_normal();
        let color = if self.lighting {
            super::raster_light::lit_color(self, eye, normal)
        } else {
            self.current.color
        };
        // Mesa's sphere map reads the eye normal only when it computes in eye space: with
        // lighting, or a texturing unit generating in eye space; otherwise the object
        // normal (measured: `tests/query_native.rs`, a sphere map on a unit without a
        // texture).
        let texgen_normal = if self.lighting || self.texturing_needs_eye_space() {
            normal
        } else {
            self.current.normal
        };
        let texcoords =
            std::array::from_fn(|u| self.raster_texcoord(u, object, eye, texgen_normal));
        self.raster = RasterPos {
            window,
            valid: true,
            color,
            texcoords,
            distance: self.raster_distance(eye.truncate().length()),
        };
    }

    /// CURRENT_RASTER_DISTANCE: `depth` (what FRAGMENT_DEPTH gives), or the current fog
    /// coordinate under FOG_COORD_SRC = FOG_COORD.
    fn raster_distance(&self, depth: f32) -> f32 {
        match self.fog.value.coord_source {
            super::fog::FogCoordSource::FragmentDepth => depth,
            super::fog::FogCoordSource::FogCoord => self.current.fog_coord,
        }
    }

    /// glWindowPos3f (GL 1.4 §2.13): x and y as given, z_w = n + z·(f − n) with z clamped
    /// to [0, 1]; the colour and coordinates are the current ones; always valid.
    pub(crate) fn set_window_pos(&mut self, p: Vec3) {
        let (n, f) = (self.depth_range.near, self.depth_range.far);
        let z = n + p.z.clamp(0.0, 1.0) * (f - n);
        self.raster = RasterPos {
            window: Vec4::new(p.x, p.y, z, 1.0),
            valid: true,
            color: self.current.color.clamp(Vec4::ZERO, Vec4::ONE),
            texcoords: self.current.texcoords,
            distance: self.raster_distance(0.0),
        };
    }

    /// glBitmap's effect on the model (§3.7): with a valid raster position, x_r += x_move and
    /// y_r += y_move; with an invalid one nothing. Negative sizes are INVALID_VALUE.
    pub(crate) fn bitmap(&mut self, b: &Bitmap) -> GlResult {
        check_rect("Bitmap", b.width, b.height)?;
        if let Some(bits) = &b.bits {
            if bits.len() != Bitmap::row_bytes(b.width) * b.height as usize {
                return Err(GlError::invalid_value(
                    "bitmap length differs from height·⌈width/8⌉",
                ));
            }
        }
        if self.raster.valid {
            self.raster.window.x += b.advance.0;
            self.raster.window.y += b.advance.1;
        }
        Ok(())
    }

    /// Whether a unit with a complete enabled texture generates a coordinate in eye space
    /// (EYE_LINEAR or SPHERE_MAP).
    fn texturing_needs_eye_space(&self) -> bool {
        (0..MAX_TEXTURE_UNITS).any(|u| {
            self.enabled_texture(u).is_some()
                && TexCoord::ALL.iter().any(|c| {
                    self.units[u]
                        .texgen(*c)
                        .is_some_and(|g| g.mode != TexGenMode::ObjectLinear)
                })
        })
    }

    /// The current normal in eye coordinates, n_e = n·M⁻¹ (§2.11.3), normalised or rescaled
    /// as NORMALIZE and RESCALE_NORMAL say.
    fn eye_normal(&self) -> Vec3 {
        let inv = super::matrix::inverse_or_identity(self.modelview_matrix());
        let m = glam::Mat3::from_mat4(inv).transpose();
        let n = m * self.current.normal;
        if self.normalize {
            n.normalize_or_zero()
        } else if self.rescale_normal {
            // f = 1/√(m31² + m32² + m33²) of M⁻¹ (eqn 2.6).
            let row = Vec3::new(inv.x_axis.z, inv.y_axis.z, inv.z_axis.z);
            let len = row.length();
            if len > 0.0 {
                n / len
            } else {
                n
            }
        } else {
            n
        }
    }

    /// Unit `u`'s raster texture coordinate: the current one with the enabled texgen
    /// coordinates generated (§2.11.4), then the texture matrix applied.
    fn raster_texcoord(&self, u: usize, object: Vec4, eye: Vec4, normal: Vec3) -> Vec4 {
        let unit = &self.units[u];
        let mut t = self.current.texcoords[u];
        let sphere = sphere_map(eye.truncate() / eye.w, normal.normalize_or_zero());
        for c in TexCoord::ALL {
            let Some(g) = unit.texgen(c) else { continue };
            let v = match (g.mode, c) {
                (TexGenMode::SphereMap, TexCoord::S) => sphere.0,
                (TexGenMode::SphereMap, TexCoord::T) => sphere.1,
                (TexGenMode::SphereMap, _) => continue,
                _ => g.linear(object, eye).unwrap_or(0.0),
            };
            t[c.index()] = v;
        }
        self.texture_matrix(u) * t
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::{Capability, Command, ViewVolume, Viewport};

    fn state() -> FixedState {
        let mut s = FixedState::new();
        s.apply(&Command::Viewport(Viewport {
            x: 0,
            y: 0,
            width: 100,
            height: 50,
        }))
        .unwrap();
        s
    }

    #[test]
    fn the_origin_lands_at_the_viewport_centre() {
        let mut s = state();
        s.set_raster_pos(Vec4::new(0.0, 0.0, 0.0, 1.0));
        assert!(s.raster.valid);
        assert_eq!(s.raster.window, Vec4::new(50.0, 25.0, 0.5, 1.0));
        // The view volume's edge is inside (−w ≤ x ≤ w); a hair beyond is not.
        s.set_raster_pos(Vec4::new(1.0, -1.0, 1.0, 1.0));
        assert!(s.raster.valid);
        assert_eq!(s.raster.window.truncate(), Vec3::new(100.0, 0.0, 1.0));
        s.set_raster_pos(Vec4::new(1.0001, 0.0, 0.0, 1.0));
        assert!(!s.raster.valid);
        // An invalid position keeps the last window coordinates (Mesa).
        assert_eq!(s.raster.window.x, 100.0);
    }

    #[test]
    fn user_clip_planes_invalidate_and_distance_is_euclidean() {
        let mut s = state();
        s.apply(&Command::MatrixMode(crate::ff::MatrixMode::Projection))
            .unwrap();
        s.apply(&Command::Frustum(ViewVolume {
            left: -1.0,
            right: 1.0,
            bottom: -1.0,
            top: 1.0,
            near: 1.0,
            far: 10.0,
        }))
        .unwrap();
        s.apply(&Command::MatrixMode(crate::ff::MatrixMode::Modelview))
            .unwrap();
        s.set_raster_pos(Vec4::new(0.0, 0.0, -5.0, 1.0));
        assert_eq!(s.raster.distance, 5.0);
        assert_eq!(s.raster.window.w, 5.0);
        s.apply(&Command::ClipPlane {
            plane: 0,
            equation: Vec4::new(-1.0, 0.0, 0.0, 0.0),
        })
        .unwrap();
        s.apply(&Command::Enable(Capability::ClipPlane(0))).unwrap();
        s.set_raster_pos(Vec4::new(0.5, 0.0, -5.0, 1.0));
        assert!(!s.raster.valid);
        s.set_raster_pos(Vec4::new(-0.5, 0.0, -5.0, 1.0));
        assert!(s.raster.valid);
        assert_eq!(s.raster.distance, 0.5f32.hypot(5.0));
    }

    #[test]
    fn window_pos_clamps_z_and_the_colour() {
        let mut s = state();
        s.apply(&Command::DepthRange {
            near: 0.25,
            far: 0.75,
        })
        .unwrap();
        s.apply(&Command::Color(Vec4::new(2.0, -1.0, 0.5, 1.0)))
            .unwrap();
        s.set_window_pos(Vec3::new(3.5, -7.0, 2.0));
        assert_eq!(s.raster.window, Vec4::new(3.5, -7.0, 0.75, 1.0));
        assert_eq!(s.raster.color, Vec4::new(1.0, 0.0, 0.5, 1.0));
        s.set_raster_pos(Vec4::new(0.0, 0.0, 0.0, 1.0));
        assert_eq!(s.raster.color, Vec4::new(2.0, -1.0, 0.5, 1.0));
    }
}
