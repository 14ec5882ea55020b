//! A procedural fighter-like aircraft (nose towards +x, up +y, span along z), built from
//! closed parts so every part's edges are each shared by two triangles:
//!
//! - fuselage: a lathe about the x axis through a pointed nose and a blunt tail;
//! - swept wings and horizontal stabilisers: convex planforms in the x–z plane extruded
//!   to a thin slab;
//! - two vertical tail fins, slabs in the x–y plane, canted outwards by ±`FIN_CANT` about
//!   the x axis (the F-18/F-22 layout).
//!
//! Slabs are convex, so each face is oriented outwards by the rule n · (face centre − slab
//! centre) > 0 instead of by hand. The whole model is 4 units long before `length` scales it.

use super::{shapes::lathe, Mesh};
use glam::{Mat4, Vec2, Vec3};

/// Outward cant of the vertical fins from the vertical, in degrees.
const FIN_CANT: f32 = 25.0;

/// Fuselage profile (x, radius) from nose to tail.
const FUSELAGE: [(f32, f32); 9] = [
    (2.0, 0.0),
    (1.7, 0.12),
    (1.2, 0.24),
    (0.6, 0.3),
    (-0.4, 0.32),
    (-1.3, 0.3),
    (-1.9, 0.22),
    (-2.0, 0.18),
    (-2.0, 0.0),
];

/// Right wing planform (x, z), root inside the fuselage.
const WING: [[f32; 2]; 4] = [[0.7, 0.2], [-0.9, 2.0], [-1.3, 2.0], [-0.9, 0.2]];
/// Right horizontal stabiliser planform (x, z).
const STABILISER: [[f32; 2]; 4] = [[-1.35, 0.2], [-1.85, 0.95], [-2.1, 0.95], [-2.05, 0.2]];
/// Vertical fin outline (x, y) before canting, root at y = 0.
const FIN: [[f32; 2]; 4] = [[-1.1, 0.0], [-1.75, 0.85], [-2.0, 0.85], [-2.0, 0.0]];

/// A convex polygon (points in its own (a, b) plane) extruded by ±`half` along the third
/// axis; `to_xyz` maps (a, b, c) to model space. Flat normals, outward by construction.
pub(super) fn slab(
    outline: &[[f32; 2]],
    half: f32,
    to_xyz: impl Fn(f32, f32, f32) -> Vec3,
) -> Mesh {
    let top: Vec<Vec3> = outline.iter().map(|p| to_xyz(p[0], p[1], half)).collect();
    let bottom: Vec<Vec3> = outline.iter().map(|p| to_xyz(p[0], p[1], -half)).collect();
    let centre = top.iter().chain(&bottom).copied().sum::<Vec3>() / (2 * outline.len()) as f32;
    let mut faces: Vec<Vec<Vec3>> = vec![top.clone(), bottom.clone()];
    for k in 0..outline.len() {
        let l = (k + 1) % outline.len();
        faces.push(vec![top[k], top[l], bottom[l], bottom[k]]);
    }
    let mut mesh = Mesh::default();
    for mut face in faces {
        let face_centre = face.iter().copied().sum::<Vec3>() / face.len() as f32;
        let normal = (face[1] - face[0]).cross(face[2] - face[0]);
        if normal.dot(face_centre - centre) < 0.0 {
            face.reverse();
        }
        let normal = (face[1] - face[0])
            .cross(face[2] - face[0])
            .normalize_or_zero();
        let base = mesh.positions.len() as u32;
        for p in &face {
            mesh.positions.push(*p);
            mesh.normals.push(normal);
        }
        for k in 1..face.len() as u32 - 1 {
            mesh.triangles.push([base, base + k, base + k + 1]);
        }
    }
    mesh
}

/// The aircraft, `length` units from nose to tail.
pub fn aircraft(length: f32) -> Mesh {
    let mut mesh = lathe(&FUSELAGE, 24);
    for side in [1.0f32, -1.0] {
        let mirror = |p: Vec2| Vec2::new(p.x, p.y * side);
        let wing: Vec<[f32; 2]> = WING.iter().map(|p| mirror(Vec2::from(*p)).into()).collect();
        mesh.append(&slab(&wing, 0.04, |x, z, y| Vec3::new(x, y - 0.05, z)));
        let stab: Vec<[f32; 2]> = STABILISER
            .iter()
            .map(|p| mirror(Vec2::from(*p)).into())
            .collect();
        mesh.append(&slab(&stab, 0.025, |x, z, y| Vec3::new(x, y, z)));
        let fin = slab(&FIN, 0.025, Vec3::new);
        let place = Mat4::from_translation(Vec3::new(0.0, 0.2, 0.22 * side))
            * Mat4::from_rotation_x(side * FIN_CANT.to_radians());
        mesh.append(&fin.transformed(&place));
    }
    mesh.transformed(&Mat4::from_scale(Vec3::splat(length / 4.0)))
}
