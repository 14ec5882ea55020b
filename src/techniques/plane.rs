//! Flat receivers and the shadow matrix, shared by `planar` and `projective` (pure maths,
//! no Commands).
//!
//! **The shadow matrix** (Blinn's "me and my (fake) shadow"; Kilgard's dinoshade):
//! for a plane p = (a, b, c, d) and a light l = (x, y, z, w) — w = 1 at a point, w = 0 for a
//! directional light, l = (−direction, 0) —
//!
//! ```text
//! M = (p·l)·I − l·pᵀ
//! M·x = (p·l)·x − (p·x)·l
//! ```
//! p·(M·x) = (p·l)(p·x) − (p·x)(p·l) = 0, so M·x lies on the plane; and M·x is a
//! combination of x and l, so it lies on the line through them: the projection of x from
//! the light. Its w is W(x) = (p·l)·x_w − l_w·(p·x): for a point light and x_w = 1,
//! W = d_L − d(x), the height of the light above x measured along the plane's normal.
//!
//! **Which parts of a caster cast** (false-shadow rejection). With p scaled to a unit
//! normal and oriented so that d_L = p·l > 0, a point x darkens the plane iff it lies on a
//! segment from a plane point to the light, i.e. iff 0 < d(x) < d_L (point light) or
//! 0 < d(x) (directional). Points with d(x) > d_L are beyond the light (W < 0 would mirror
//! them onto the plane), points with d(x) < 0 are below the plane: both cast nothing. The
//! era did this with glClipPlane or with the projector's pseudo-depth; `planar` does it on
//! the CPU, clipping every caster triangle to the slab δ ≤ d(x) ≤ d_L − δ before drawing.
//! δ = 10⁻⁴·R (R the scene's bounding radius) is the truth's own offset rule: geometry
//! lying in the receiver's plane (the receiver itself) casts nothing.
//!
//! **Facing.** The truth sees the side of a surface that faces the eye and calls it
//! shadowed when the light is not strictly in front of that side (n·L ≤ 0). So a flat
//! receiver's plane is oriented towards the eye, and it can be lit only when p·l > 0 in
//! that orientation: a light in the plane (p·l = 0), a directional light parallel to it,
//! or a light behind it leaves the whole receiver unlit — a defined result, never a
//! division by p·l.

use glam::{Mat4, Vec3, Vec4};

use crate::mesh::Mesh;
use crate::scene::{Light, LightKind};

/// Relative offset δ = `OFFSET` · R of the casting slab (the truth's rule).
pub const OFFSET: f32 = 1e-4;

/// Relative flatness tolerance: every vertex within `FLATNESS` · (the mesh's bounding
/// diagonal) of the plane of its largest triangle.
pub const FLATNESS: f32 = 1e-5;

/// l: the light as a homogeneous point — (position, 1) for point, spot and area lights (an
/// area light's centre, as the truth's hard mask), (−direction, 0) for a directional one.
pub fn light_vector(light: &Light) -> Vec4 {
    match (light.kind, light.position()) {
        (LightKind::Directional { direction, .. }, _) => {
            (-direction.normalize_or_zero()).extend(0.0)
        }
        (_, Some(p)) => p.extend(1.0),
        (_, None) => light.view.eye.extend(1.0),
    }
}

/// M = (p·l)·I − l·pᵀ (see the module note). Finite whenever p and l are.
pub fn shadow_matrix(plane: Vec4, light: Vec4) -> Mat4 {
    let dot = plane.dot(light);
    // Column j of l·pᵀ is l·p_j.
    let outer = Mat4::from_cols(
        light * plane.x,
        light * plane.y,
        light * plane.z,
        light * plane.w,
    );
    Mat4::from_diagonal(Vec4::splat(dot)) - outer
}

/// d(x) = p·(x, 1): the signed distance of x from a plane with a unit normal.
pub fn distance(plane: Vec4, x: Vec3) -> f32 {
    plane.dot(x.extend(1.0))
}

/// The plane of a world-space mesh when all of it is flat: (n, −n·o) with n the unit
/// normal of its largest triangle (winding kept) and o that triangle's centroid; `None`
/// for a mesh without area or with a vertex off that plane by more than the tolerance.
pub fn flat_plane(mesh: &Mesh) -> Option<Vec4> {
    let (lo, hi) = mesh.bounds()?;
    let tolerance = FLATNESS * (hi - lo).length();
    let (mut best, mut best_area2) = (None, 0.0f32);
    for t in 0..mesh.triangle_count() {
        let [a, b, c] = mesh.corners(t);
        let cross = (b - a).cross(c - a);
        let area2 = cross.length_squared();
        if area2.is_finite() && area2 > best_area2 {
            best_area2 = area2;
            best = Some((cross / area2.sqrt(), (a + b + c) / 3.0));
        }
    }
    let (n, o) = best?;
    let plane = n.extend(-n.dot(o));
    let used = mesh.triangles.iter().flatten();
    used.into_iter()
        .all(|&i| distance(plane, mesh.positions[i as usize]).abs() <= tolerance)
        .then_some(plane)
}

/// Total area of a mesh's triangles.
pub fn area(mesh: &Mesh) -> f32 {
    (0..mesh.triangle_count())
        .map(|t| {
            let [a, b, c] = mesh.corners(t);
            0.5 * (b - a).cross(c - a).length()
        })
        .sum()
}

/// R: half the diagonal of the world bounds of every object (1 for an empty scene) — the
/// truth's own measure, so that δ = `truth::OFFSET`·R means the same here.
pub use crate::truth::scene_radius;

/// How a flat receiver stands towards the eye and the light.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Facing {
    /// The eye and the light are strictly on the same side; `plane` is oriented towards
    /// them (p·eye > 0, p·l > 0).
    Lit { plane: Vec4 },
    /// The light is in the plane, parallel to it, or behind it as seen from the eye: the
    /// visible side is unlit everywhere.
    Unlit,
    /// The eye is in the plane: the receiver covers no pixel.
    EdgeOnToEye,
}

/// Orients `plane` towards `eye` and classifies it against the homogeneous light `l`.
pub fn facing(plane: Vec4, eye: Vec3, light: Vec4) -> Facing {
    let side = distance(plane, eye);
    if side == 0.0 {
        return Facing::EdgeOnToEye;
    }
    let plane = if side > 0.0 { plane } else { -plane };
    if plane.dot(light) > 0.0 {
        Facing::Lit { plane }
    } else {
        Facing::Unlit
    }
}

/// The slab of distances from the plane whose points cast onto it (see the module note).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slab {
    pub low: f32,
    /// `None` for a directional light (no far side).
    pub high: Option<f32>,
}

impl Slab {
    /// δ ≤ d ≤ d_L − δ for a point light, δ ≤ d for a directional one (`plane` oriented so
    /// that p·l > 0).
    pub fn new(plane: Vec4, light: Vec4, delta: f32) -> Slab {
        let high = (light.w != 0.0).then(|| plane.dot(light) / light.w - delta);
        Slab { low: delta, high }
    }
}

/// The parts of `mesh`'s triangles inside the slab, as a triangle list (three world
/// positions per triangle, windings kept): each triangle is clipped against d ≥ low and
/// d ≤ high (Sutherland–Hodgman; both boundaries are planes parallel to the receiver, so
/// the clip is linear in d along every edge) and the convex rest fanned from its first
/// vertex.
pub fn clip_to_slab(mesh: &Mesh, plane: Vec4, slab: Slab) -> Vec<Vec3> {
    let mut out = Vec::new();
    for t in 0..mesh.triangle_count() {
        let mut poly: Vec<Vec3> = mesh.corners(t).to_vec();
        poly = clip_polygon(&poly, |x| distance(plane, x) - slab.low);
        if let Some(high) = slab.high {
            poly = clip_polygon(&poly, |x| high - distance(plane, x));
        }
        for i in 1..poly.len().saturating_sub(1) {
            out.extend([poly[0], poly[i], poly[i + 1]]);
        }
    }
    out
}

/// The part of a convex polygon where `inside(x) ≥ 0` (`inside` affine in x).
fn clip_polygon(poly: &[Vec3], inside: impl Fn(Vec3) -> f32) -> Vec<Vec3> {
    let mut out = Vec::with_capacity(poly.len() + 1);
    for (i, &a) in poly.iter().enumerate() {
        let b = poly[(i + 1) % poly.len()];
        let (fa, fb) = (inside(a), inside(b));
        if fa >= 0.0 {
            out.push(a);
        }
        // The edge crosses the boundary: the point where f = 0, t = fa / (fa − fb) ∈ (0, 1).
        if (fa >= 0.0) != (fb >= 0.0) {
            out.push(a + (b - a) * (fa / (fa - fb)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh;

    const FLOOR: Vec4 = Vec4::new(0.0, 1.0, 0.0, 0.0);

    fn projected(m: Mat4, x: Vec3) -> Vec3 {
        let h = m * x.extend(1.0);
        h.truncate() / h.w
    }

    #[test]
    fn a_point_projects_onto_the_plane_along_the_light_ray() {
        let plane = Vec4::new(0.3, 0.8, -0.2, 0.7).normalize();
        let light = Vec4::new(2.0, 9.0, -1.0, 1.0);
        let m = shadow_matrix(plane, light);
        for x in [
            Vec3::new(0.5, 2.0, 0.25),
            Vec3::new(-3.0, 1.0, 4.0),
            Vec3::new(1.0, 5.0, -2.0),
        ] {
            let s = projected(m, x);
            assert!(distance(plane, s).abs() < 1e-5, "{s} is off the plane");
            // s, x and the light are collinear.
            let l = light.truncate();
            let off_line = (x - l).cross(s - l).length() / (x - l).length();
            assert!(off_line < 1e-4, "{s} is {off_line} off the ray through {x}");
        }
    }

    #[test]
    fn dinoshade_floor_numbers() {
        // Floor y = 0, light (12 cos 0, 20, 12 sin 0, 1) = (12, 20, 0, 1): a point at height
        // 10 above (2, 0, 3) lands at 2 + (2 − 12)·10 / (20 − 10) = −8 along x.
        let m = shadow_matrix(FLOOR, Vec4::new(12.0, 20.0, 0.0, 1.0));
        let s = projected(m, Vec3::new(2.0, 10.0, 3.0));
        assert!((s - Vec3::new(-8.0, 0.0, 6.0)).length() < 1e-5, "{s}");
        // Points on the plane stay where they are.
        let on = Vec3::new(-5.0, 0.0, 7.0);
        assert!((projected(m, on) - on).length() < 1e-5);
    }

    #[test]
    fn a_directional_light_projects_along_its_direction() {
        let dir = Vec3::new(1.0, -2.0, 0.5).normalize();
        let m = shadow_matrix(FLOOR, (-dir).extend(0.0));
        let x = Vec3::new(0.0, 4.0, 0.0);
        // x + t·dir reaches y = 0 at t = 4 / 2·|dir|… i.e. x − (x_y / dir_y)·dir.
        let expected = x - dir * (x.y / dir.y);
        assert!((projected(m, x) - expected).length() < 1e-5);
        // W is constant: p·l, the cosine between the floor's normal and −dir.
        assert!(((m * x.extend(1.0)).w - FLOOR.dot((-dir).extend(0.0))).abs() < 1e-6);
    }

    #[test]
    fn degenerate_lights_give_finite_matrices_and_no_lit_side() {
        // Light in the plane: p·l = 0, M = −l·pᵀ (rank 1) — finite, and the plane is unlit.
        let in_plane = Vec4::new(3.0, 0.0, 1.0, 1.0);
        let parallel = Vec4::new(-1.0, 0.0, 0.0, 0.0);
        for l in [in_plane, parallel] {
            let m = shadow_matrix(FLOOR, l);
            assert!(m.is_finite(), "{m}");
            assert_eq!(facing(FLOOR, Vec3::new(0.0, 5.0, 5.0), l), Facing::Unlit);
        }
        // The eye below the floor sees the underside: a light above leaves it unlit.
        let above = Vec4::new(0.0, 8.0, 0.0, 1.0);
        assert_eq!(
            facing(FLOOR, Vec3::new(0.0, -1.0, 3.0), above),
            Facing::Unlit
        );
        assert_eq!(
            facing(-FLOOR, Vec3::new(0.0, 2.0, 3.0), above),
            Facing::Lit { plane: FLOOR }
        );
        assert_eq!(
            facing(FLOOR, Vec3::new(0.0, 0.0, 3.0), above),
            Facing::EdgeOnToEye
        );
    }

    #[test]
    fn clipping_keeps_the_slab_between_plane_and_light() {
        // A vertical triangle from y = −1 to y = 9 under a light at height 6.
        let tri = Mesh {
            positions: vec![
                Vec3::new(0.0, -1.0, 0.0),
                Vec3::new(2.0, -1.0, 0.0),
                Vec3::new(1.0, 9.0, 0.0),
            ],
            normals: Vec::new(),
            triangles: vec![[0, 1, 2]],
        };
        let light = Vec4::new(0.0, 6.0, 5.0, 1.0);
        let slab = Slab::new(FLOOR, light, 0.01);
        assert_eq!(
            slab,
            Slab {
                low: 0.01,
                high: Some(5.99)
            }
        );
        let kept = clip_to_slab(&tri, FLOOR, slab);
        assert!(!kept.is_empty() && kept.len() % 3 == 0);
        for p in &kept {
            assert!(
                p.is_finite() && (0.01 - 1e-5..=5.99 + 1e-5).contains(&p.y),
                "{p}"
            );
        }
        // The kept area is the band 0.01 ≤ y ≤ 5.99 of the triangle: width 2·(9 − y)/10.
        let band = |y: f32| 2.0 * (9.0 - y) / 10.0;
        let expected = 0.5 * (band(0.01) + band(5.99)) * 5.98;
        let got: f32 = kept
            .chunks(3)
            .map(|t| 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).length())
            .sum();
        assert!(
            (got - expected).abs() < 1e-3,
            "area {got}, expected {expected}"
        );
        // A directional light keeps everything above the plane.
        let up = clip_to_slab(
            &tri,
            FLOOR,
            Slab::new(FLOOR, Vec4::new(0.0, 1.0, 0.0, 0.0), 0.01),
        );
        assert!(up.iter().all(|p| p.y >= 0.01 - 1e-5) && up.iter().any(|p| p.y == 9.0));
    }

    #[test]
    fn flat_meshes_are_detected_and_curved_ones_are_not() {
        let floor = mesh::plane(16.0, 8);
        let plane = flat_plane(&floor).expect("a plane is flat");
        assert!((plane.truncate().abs() - Vec3::Y).length() < 1e-6 && plane.w.abs() < 1e-6);
        let wall = floor.transformed(
            &(Mat4::from_translation(Vec3::new(0.0, 4.0, -8.0))
                * Mat4::from_rotation_x(90f32.to_radians())),
        );
        let p = flat_plane(&wall).expect("a turned plane is flat");
        assert!(distance(p, Vec3::new(3.0, 1.0, -8.0)).abs() < 1e-4, "{p}");
        assert_eq!(flat_plane(&mesh::sphere(1.0, 16, 8)), None);
        assert_eq!(flat_plane(&mesh::cuboid(Vec3::ONE)), None);
        assert_eq!(flat_plane(&Mesh::default()), None);
    }
}
