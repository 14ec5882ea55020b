//! The analytic shapes: plane, box, sphere, torus, and the lathe the aircraft's fuselage uses.
//!
//! Tessellation counts below their minimum (1 for a plane, 3 slices / 2 stacks for a sphere,
//! 3 rings and sides for a torus) are raised to it, so no input panics; the scene layer
//! rejects such counts before they get here.
//!
//! Triangle counts: plane n → 2n²; box → 12; sphere (slices s, stacks k) → 2s(k − 1)
//! (fans at the poles); torus (rings r, sides s) → 2rs; lathe (m profile points, s
//! segments, poles at both ends) → 2s(m − 2).

use super::Mesh;
use glam::Vec3;
use std::f32::consts::{PI, TAU};

/// A square of edge `size` in the y = 0 plane, centred on the origin, facing +y, cut into
/// `tessellation` × `tessellation` cells (fine cells keep per-vertex lighting and the
/// eye-space depths of a large ground well behaved).
pub fn plane(size: f32, tessellation: u32) -> Mesh {
    let n = tessellation.max(1);
    let row = n + 1;
    let mut mesh = Mesh::default();
    for j in 0..=n {
        for i in 0..=n {
            let x = size * (i as f32 / n as f32 - 0.5);
            let z = size * (j as f32 / n as f32 - 0.5);
            mesh.positions.push(Vec3::new(x, 0.0, z));
            mesh.normals.push(Vec3::Y);
        }
    }
    for j in 0..n {
        for i in 0..n {
            let a = j * row + i;
            let (b, c, d) = (a + row, a + 1, a + row + 1);
            // (b − a) × (c − a) = ẑ × x̂ = +ŷ
            mesh.triangles.push([a, b, c]);
            mesh.triangles.push([c, b, d]);
        }
    }
    mesh
}

/// An axis-aligned box of edge lengths `size`, centred on the origin, with flat normals
/// (four vertices per face). Corners are computed as ±half, so faces meeting at an edge
/// share bit-identical positions.
pub fn cuboid(size: Vec3) -> Mesh {
    let half = size * 0.5;
    let mut mesh = Mesh::default();
    // For each face normal axis a, (u, v) with ê_u × ê_v = ê_a.
    for (axis, u, v) in [(0usize, 1usize, 2usize), (1, 2, 0), (2, 0, 1)] {
        for sign in [1.0f32, -1.0] {
            let (u, v) = if sign > 0.0 { (u, v) } else { (v, u) };
            let base = mesh.positions.len() as u32;
            for (su, sv) in [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                let mut s = [0.0f32; 3];
                s[axis] = sign;
                s[u] = su;
                s[v] = sv;
                mesh.positions.push(Vec3::from_array(s) * half);
                let mut n = [0.0f32; 3];
                n[axis] = sign;
                mesh.normals.push(Vec3::from_array(n));
            }
            mesh.triangles.push([base, base + 1, base + 2]);
            mesh.triangles.push([base, base + 2, base + 3]);
        }
    }
    mesh
}

/// A sphere of `radius` about the origin, poles on ±y: p(φ, θ) = r (sin φ sin θ, cos φ,
/// sin φ cos θ), φ = π i / stacks, θ = 2π j / slices. The seam reuses the first column's
/// vertices, so the surface is closed.
pub fn sphere(radius: f32, slices: u32, stacks: u32) -> Mesh {
    let slices = slices.max(3);
    let stacks = stacks.max(2);
    let mut mesh = Mesh::default();
    let push = |mesh: &mut Mesh, n: Vec3| {
        mesh.positions.push(n * radius);
        mesh.normals.push(n);
    };
    push(&mut mesh, Vec3::Y);
    for i in 1..stacks {
        let phi = PI * i as f32 / stacks as f32;
        for j in 0..slices {
            let theta = TAU * j as f32 / slices as f32;
            let n = Vec3::new(phi.sin() * theta.sin(), phi.cos(), phi.sin() * theta.cos());
            push(&mut mesh, n);
        }
    }
    push(&mut mesh, -Vec3::Y);
    let south = mesh.positions.len() as u32 - 1;
    let ring = |i: u32, j: u32| 1 + (i - 1) * slices + j % slices;
    for j in 0..slices {
        // (b − a) × (c − a) = ∂φ × ∂θ points outwards.
        mesh.triangles.push([0, ring(1, j), ring(1, j + 1)]);
        for i in 1..stacks - 1 {
            let (a, b, c, d) = (
                ring(i, j),
                ring(i + 1, j),
                ring(i, j + 1),
                ring(i + 1, j + 1),
            );
            mesh.triangles.push([a, b, c]);
            mesh.triangles.push([c, b, d]);
        }
        mesh.triangles
            .push([ring(stacks - 1, j), south, ring(stacks - 1, j + 1)]);
    }
    mesh
}

/// A torus about the y axis: p(θ, φ) = ((R + r cos φ) sin θ, r sin φ, (R + r cos φ) cos θ)
/// with `rings` steps of θ around the axis and `sides` steps of φ around the tube.
pub fn torus(major: f32, minor: f32, rings: u32, sides: u32) -> Mesh {
    let rings = rings.max(3);
    let sides = sides.max(3);
    let mut mesh = Mesh::default();
    for i in 0..rings {
        let theta = TAU * i as f32 / rings as f32;
        for k in 0..sides {
            let phi = TAU * k as f32 / sides as f32;
            let n = Vec3::new(phi.cos() * theta.sin(), phi.sin(), phi.cos() * theta.cos());
            let centre = Vec3::new(theta.sin(), 0.0, theta.cos()) * major;
            mesh.positions.push(centre + n * minor);
            mesh.normals.push(n);
        }
    }
    let index = |i: u32, k: u32| (i % rings) * sides + k % sides;
    for i in 0..rings {
        for k in 0..sides {
            // (b − a) × (c − a) = ∂θ × ∂φ points away from the tube's centre line.
            let (a, b, c, d) = (
                index(i, k),
                index(i + 1, k),
                index(i, k + 1),
                index(i + 1, k + 1),
            );
            mesh.triangles.push([a, b, c]);
            mesh.triangles.push([c, b, d]);
        }
    }
    mesh
}

/// A closed surface of revolution about the x axis through the profile points (x, r),
/// listed from +x to −x; the first and last must have r = 0 (they become poles).
/// p(i, θ) = (x_i, r_i cos θ, r_i sin θ). Normals are computed from the faces.
pub(super) fn lathe(profile: &[(f32, f32)], segments: u32) -> Mesh {
    let segments = segments.max(3);
    let mut mesh = Mesh::default();
    let Some((&first, rest)) = profile.split_first() else {
        return mesh;
    };
    let Some((&last, inner)) = rest.split_last() else {
        return mesh;
    };
    mesh.positions.push(Vec3::new(first.0, 0.0, 0.0));
    for &(x, r) in inner {
        for j in 0..segments {
            let theta = TAU * j as f32 / segments as f32;
            mesh.positions
                .push(Vec3::new(x, r * theta.cos(), r * theta.sin()));
        }
    }
    mesh.positions.push(Vec3::new(last.0, 0.0, 0.0));
    let rings = inner.len() as u32;
    if rings == 0 {
        return Mesh::default();
    }
    let tail = mesh.positions.len() as u32 - 1;
    let ring = |i: u32, j: u32| 1 + i * segments + j % segments;
    for j in 0..segments {
        // Profile direction × ∂θ points outwards (the profile runs towards −x).
        mesh.triangles.push([0, ring(0, j), ring(0, j + 1)]);
        for i in 0..rings - 1 {
            let (a, b, c, d) = (
                ring(i, j),
                ring(i + 1, j),
                ring(i, j + 1),
                ring(i + 1, j + 1),
            );
            mesh.triangles.push([a, b, c]);
            mesh.triangles.push([c, b, d]);
        }
        mesh.triangles
            .push([ring(rings - 1, j), tail, ring(rings - 1, j + 1)]);
    }
    mesh.compute_normals();
    mesh
}
