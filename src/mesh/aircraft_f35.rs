//! The aircraft in the model space of Coleman's F-35 (thesis 003, §5 and Appendix A), so
//! that the thesis's hard-coded shadow planes fit it: metres, z up, nose towards +y, span
//! along x.
//!
//! - fuselage: a lathe about the y axis, its round section flattened to an ellipse
//!   (half-width 1.6 r, half-height 0.55 r), centred on z = 0;
//! - wings and horizontal stabilisers: convex planforms in the x–y plane extruded to slabs
//!   centred on z = 0, so the z = 0 plane cuts the fuselage, the wings and the stabilisers
//!   in half, as the thesis's modified model was cut (§5), and all of them lie within the
//!   15 m square from (−7.5, −5.315, 0);
//! - two canted vertical fins, slabs centred on the two fin planes of the appendix
//!   (`shaders::F35_PLANES`): each outline is given in its plane's (right, up) frame,
//!   within the 4.1218186 m square of its occluder texture, its root buried in the
//!   fuselage (up = 0.9 m, z ≈ 0.12, where the fuselage is 1.57 m wide).
//!
//! The plane frames are repeated here as numbers rather than imported, because the mesh
//! layer sits below the shader files; a test checks that each fin lies in its plane.

use super::aircraft::slab;
use super::{shapes::lathe, Mesh};
use glam::{Mat4, Vec3};

/// Fuselage profile (y, r) from nose to tail; the section is r · (1.6, 0.55) in (x, z).
const FUSELAGE: [(f32, f32); 9] = [
    (9.5, 0.0),
    (8.6, 0.3),
    (7.0, 0.62),
    (5.0, 0.85),
    (2.0, 1.0),
    (-1.5, 1.0),
    (-3.5, 0.92),
    (-4.7, 0.8),
    (-4.7, 0.0),
];
/// The section's scale along x and z.
const SECTION: Vec3 = Vec3::new(1.6, 1.0, 0.55);

/// Right wing planform (x, y), root inside the fuselage.
const WING: [[f32; 2]; 4] = [[1.2, 2.5], [5.3, -1.0], [5.3, -2.0], [1.2, -2.2]];
/// Half the wing's thickness.
const WING_HALF: f32 = 0.06;
/// Right horizontal stabiliser planform (x, y).
const STABILISER: [[f32; 2]; 4] = [[1.2, -3.0], [3.3, -4.2], [3.3, -4.6], [1.2, -4.6]];
const STABILISER_HALF: f32 = 0.04;

/// Fin outline in its plane's frame (a along `right`, b along `up`, metres from the
/// plane's origin): root buried in the fuselage, swept tip.
const FIN: [[f32; 2]; 4] = [[1.3, 0.9], [2.9, 3.2], [3.95, 3.2], [3.9, 0.9]];
/// Half the fin's thickness (along the plane's normal).
pub const FIN_HALF: f32 = 0.03;

/// A fin plane's frame: origin, right, up and normal (Appendix A).
#[derive(Clone, Copy, Debug)]
pub(super) struct FinFrame {
    pub origin: Vec3,
    pub right: Vec3,
    pub up: Vec3,
    pub normal: Vec3,
}

/// The right (x > 0) and left fin planes of `coleman/occluder.vert`.
#[allow(clippy::excessive_precision)]
pub(super) const FIN_FRAMES: [FinFrame; 2] = [
    FinFrame {
        origin: Vec3::new(0.899235, -0.676381, -0.706742),
        right: Vec3::NEG_Y,
        up: Vec3::new(0.3975177, 0.0, 0.91759448),
        normal: Vec3::new(-0.917594, 0.0, 0.397518),
    },
    FinFrame {
        origin: Vec3::new(-0.899235, -0.676381, -0.706742),
        right: Vec3::NEG_Y,
        up: Vec3::new(-0.3975177, 0.0, 0.91759448),
        normal: Vec3::new(0.917594, 0.0, 0.397518),
    },
];

/// The F-35-like aircraft, 14.2 m from nose to tail, 10.6 m span.
pub fn aircraft_f35() -> Mesh {
    // The lathe turns about x; rotating +90° about z takes x to y (and y to −x).
    let place = Mat4::from_scale(SECTION) * Mat4::from_rotation_z(std::f32::consts::FRAC_PI_2);
    let mut mesh = lathe(&FUSELAGE, 24).transformed(&place);
    for side in [1.0f32, -1.0] {
        let mirror = |p: &[f32; 2]| [p[0] * side, p[1]];
        let wing: Vec<[f32; 2]> = WING.iter().map(mirror).collect();
        mesh.append(&slab(&wing, WING_HALF, Vec3::new));
        let stab: Vec<[f32; 2]> = STABILISER.iter().map(mirror).collect();
        mesh.append(&slab(&stab, STABILISER_HALF, Vec3::new));
    }
    for f in FIN_FRAMES {
        mesh.append(&slab(&FIN, FIN_HALF, |a, b, c| {
            f.origin + f.right * a + f.up * b + f.normal * c
        }));
    }
    mesh
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_model_is_closed_and_inside_the_z0_plane_square() {
        let mesh = aircraft_f35();
        assert!(mesh.is_closed());
        let (lo, hi) = mesh.bounds().unwrap();
        // The 15 m square from (−7.5, −5.315) on z = 0.
        assert!(
            lo.x > -7.5 && hi.x < 7.5 && lo.y > -5.315 && hi.y < 9.685,
            "{lo} {hi}"
        );
        // Cut in half by z = 0 below the fins: the fuselage's extremes are symmetric.
        assert!((lo.z + 0.55).abs() < 1e-5, "{lo}");
        assert!(hi.z > 2.0, "the fins rise above: {hi}");
    }

    #[test]
    fn each_fin_lies_in_its_plane_within_its_texture_square() {
        let mesh = aircraft_f35();
        let fin_vertices = 2 * FIN.len();
        // The fins are appended last: right fin, then left fin.
        let start = mesh.positions.len() - 2 * 3 * fin_vertices;
        for (k, f) in FIN_FRAMES.iter().enumerate() {
            let range = start + k * 3 * fin_vertices..start + (k + 1) * 3 * fin_vertices;
            for p in &mesh.positions[range] {
                let d = *p - f.origin;
                assert!((f.normal.dot(d).abs() - FIN_HALF).abs() < 1e-4, "{k}: {p}");
                for v in [f.right.dot(d), f.up.dot(d)] {
                    assert!((0.0..4.1218186).contains(&v), "{k}: {p}");
                }
            }
        }
        // The fins cant outwards: the right fin's tip is farther out than its root.
        assert!(FIN_FRAMES[0].up.x > 0.0 && FIN_FRAMES[1].up.x < 0.0);
    }
}
