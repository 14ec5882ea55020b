//! Texture coordinate generation (GL 1.5 §2.11.4).
//!
//! Eye planes are stored already multiplied by the inverse modelview current when
//! glTexGen(EYE_PLANE) was called: later modelview changes do not move them (piglit
//! general/texgen). Object planes are stored as given. All four coordinates S, T, R, Q are
//! generated when enabled, whatever the texture matrix (gl4es drops R and Q).

use glam::{Mat4, Vec3, Vec4};

use super::error::{GlError, GlResult};
use super::matrix::plane_to_eye;

/// S, T, R, Q.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TexCoord {
    S,
    T,
    R,
    Q,
}

impl TexCoord {
    pub const ALL: [TexCoord; 4] = [TexCoord::S, TexCoord::T, TexCoord::R, TexCoord::Q];

    pub fn index(self) -> usize {
        match self {
            TexCoord::S => 0,
            TexCoord::T => 1,
            TexCoord::R => 2,
            TexCoord::Q => 3,
        }
    }
}

/// TEXTURE_GEN_MODE.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TexGenMode {
    /// g = p·v_object.
    ObjectLinear,
    /// g = p_eye·v_eye.
    EyeLinear,
    /// S and T only: the reflection vector mapped into a sphere map.
    SphereMap,
    /// S, T and R (GL 1.3 §2.10.4, ARB_texture_cube_map): the eye-space reflection
    /// vector r = u − 2n(n·u), u the unit vector from the eye to the vertex, n the eye
    /// normal; Q refuses it (INVALID_ENUM, Mesa measured).
    ReflectionMap,
    /// S, T and R (GL 1.3 §2.10.4): the eye-space normal n; not for Q.
    NormalMap,
}

/// One glTexGen parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TexGenParam {
    Mode(TexGenMode),
    ObjectPlane(Vec4),
    /// In object coordinates as given; stored in eye coordinates.
    EyePlane(Vec4),
}

/// One coordinate's generation state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TexGen {
    /// GL default: EYE_LINEAR.
    pub mode: TexGenMode,
    /// GL default: S (1,0,0,0), T (0,1,0,0), R and Q (0,0,0,0).
    pub object_plane: Vec4,
    /// In eye coordinates. GL default: as the object plane.
    pub eye_plane: Vec4,
}

impl TexGen {
    pub fn default_for(coord: TexCoord) -> Self {
        let plane = match coord {
            TexCoord::S => Vec4::X,
            TexCoord::T => Vec4::Y,
            TexCoord::R | TexCoord::Q => Vec4::ZERO,
        };
        Self {
            mode: TexGenMode::EyeLinear,
            object_plane: plane,
            eye_plane: plane,
        }
    }

    /// glTexGen for `coord`; SPHERE_MAP on R or Q, REFLECTION_MAP and NORMAL_MAP on Q are
    /// INVALID_ENUM (Mesa 22.3.6 measured).
    pub fn set(&mut self, coord: TexCoord, param: TexGenParam, modelview: Mat4) -> GlResult {
        match param {
            TexGenParam::Mode(TexGenMode::ReflectionMap | TexGenMode::NormalMap)
                if coord == TexCoord::Q =>
            {
                return Err(GlError::invalid_enum(
                    "REFLECTION_MAP and NORMAL_MAP are only valid for S, T and R",
                ));
            }
            TexGenParam::Mode(TexGenMode::SphereMap)
                if matches!(coord, TexCoord::R | TexCoord::Q) =>
            {
                return Err(GlError::invalid_enum(
                    "SPHERE_MAP is only valid for S and T",
                ));
            }
            TexGenParam::Mode(m) => self.mode = m,
            TexGenParam::ObjectPlane(p) => self.object_plane = p,
            TexGenParam::EyePlane(p) => self.eye_plane = plane_to_eye(p, modelview),
        }
        Ok(())
    }

    /// The generated coordinate for a linear mode: the dot product of the plane with the
    /// vertex in the matching space (GL 1.5 eqn 2.3/2.4). Sphere maps return `None` (they need
    /// the normal and are computed by the pipeline).
    pub fn linear(&self, object: Vec4, eye: Vec4) -> Option<f32> {
        match self.mode {
            TexGenMode::ObjectLinear => Some(self.object_plane.dot(object)),
            TexGenMode::EyeLinear => Some(self.eye_plane.dot(eye)),
            TexGenMode::SphereMap | TexGenMode::ReflectionMap | TexGenMode::NormalMap => None,
        }
    }
}

/// REFLECTION_MAP (GL 1.3 §2.10.4): r = u − 2n(n·u), u the unit eye position, n the eye
/// normal (as the pipeline has it: normalized when NORMALIZE or lighting asks).
pub fn reflection_map(eye_position: Vec3, eye_normal: Vec3) -> Vec3 {
    let u = eye_position.normalize_or_zero();
    u - 2.0 * eye_normal * eye_normal.dot(u)
}

/// SPHERE_MAP (GL 1.5 §2.11.4): u = unit eye position, n = eye normal, r = u − 2n(n·u),
/// m = 2·√(r_x² + r_y² + (r_z + 1)²), s = r_x/m + ½, t = r_y/m + ½.
pub fn sphere_map(eye_position: Vec3, eye_normal: Vec3) -> (f32, f32) {
    let u = eye_position.normalize_or_zero();
    let r = u - 2.0 * eye_normal * eye_normal.dot(u);
    let m = 2.0 * (r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0)).sqrt();
    if m == 0.0 {
        return (0.5, 0.5);
    }
    (r.x / m + 0.5, r.y / m + 0.5)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sphere_map_on_r_is_invalid_enum() {
        let mut g = TexGen::default_for(TexCoord::R);
        let before = g;
        assert!(g
            .set(
                TexCoord::R,
                TexGenParam::Mode(TexGenMode::SphereMap),
                Mat4::IDENTITY
            )
            .is_err());
        assert_eq!(g, before);
    }

    #[test]
    fn cube_map_modes_on_q_are_invalid_enum_and_on_r_valid() {
        for mode in [TexGenMode::ReflectionMap, TexGenMode::NormalMap] {
            let mut q = TexGen::default_for(TexCoord::Q);
            assert!(q
                .set(TexCoord::Q, TexGenParam::Mode(mode), Mat4::IDENTITY)
                .is_err());
            assert_eq!(q.mode, TexGenMode::EyeLinear);
            let mut r = TexGen::default_for(TexCoord::R);
            r.set(TexCoord::R, TexGenParam::Mode(mode), Mat4::IDENTITY)
                .unwrap();
            assert_eq!(r.mode, mode);
        }
        // Looking down −z at a surface facing the viewer: r points back at the eye.
        assert!(reflection_map(Vec3::new(0.0, 0.0, -3.0), Vec3::Z).abs_diff_eq(Vec3::Z, 1e-6));
    }

    #[test]
    fn sphere_map_centre() {
        // Looking straight down −z at a surface facing the viewer: the centre of the map.
        let (s, t) = sphere_map(Vec3::NEG_Z, Vec3::Z);
        assert!((s - 0.5).abs() < 1e-6 && (t - 0.5).abs() < 1e-6);
    }
}
