//! The Utah teapot, tessellated from Martin Newell's 32 bicubic Bézier patches (1975,
//! public domain), written here in a compact form instead of the usual 306-point table:
//!
//! - 28 patches are surfaces of revolution about Newell's z axis: rim, upper and lower body,
//!   two lid pieces and the bottom, each a 4-point profile (r, k, z) swept through four
//!   quadrants. A profile point becomes the quadrant's control row (r, 0), (r, −k), (k, −r),
//!   (0, −r), rotated by −90° per quadrant (+90° for the bottom, whose patches run the other
//!   way round). k is Newell's off-axis handle, 0.56 r for all but the lid knob (0.45 for
//!   r = 0.8).
//! - The handle (2 patches) and spout (2 patches) are stored for y ≤ 0 only; the y ≥ 0 half
//!   is the mirror image y → −y with the columns reversed (which keeps the winding).
//!
//! Each patch is evaluated on an (n + 1)² grid: P(u, v) = Σᵢ Σⱼ Bᵢ(u) Bⱼ(v) Pᵢⱼ with the cubic
//! Bernstein weights B = ((1−t)³, 3t(1−t)², 3t²(1−t), t³). Shared patch edges have the same
//! control points in the same order, so they evaluate bit-identically and are welded; the
//! triangles that collapse at the lid and bottom poles are dropped, and normals are averaged
//! from the faces. Newell's data is z-up; the result is turned to y-up by (x, y, z) →
//! (x, z, −y), base on y = 0, height 3.15 × `size`.

use super::Mesh;
use glam::{Mat4, Vec3};

type Patch = [[Vec3; 4]; 4];

/// Profiles of the surfaces of revolution: (r, k, z) from the patch's first row to its last.
const RIM: [[f32; 3]; 4] = [
    [1.4, 0.784, 2.4],
    [1.3375, 0.749, 2.53125],
    [1.4375, 0.805, 2.53125],
    [1.5, 0.84, 2.4],
];
const UPPER_BODY: [[f32; 3]; 4] = [
    [1.5, 0.84, 2.4],
    [1.75, 0.98, 1.875],
    [2.0, 1.12, 1.35],
    [2.0, 1.12, 0.9],
];
const LOWER_BODY: [[f32; 3]; 4] = [
    [2.0, 1.12, 0.9],
    [2.0, 1.12, 0.45],
    [1.5, 0.84, 0.225],
    [1.5, 0.84, 0.15],
];
const LID_KNOB: [[f32; 3]; 4] = [
    [0.0, 0.0, 3.15],
    [0.8, 0.45, 3.15],
    [0.0, 0.0, 2.85],
    [0.2, 0.112, 2.7],
];
const LID: [[f32; 3]; 4] = [
    [0.2, 0.112, 2.7],
    [0.4, 0.224, 2.55],
    [1.3, 0.728, 2.55],
    [1.3, 0.728, 2.4],
];
const BOTTOM: [[f32; 3]; 4] = [
    [0.0, 0.0, 0.0],
    [1.425, 0.798, 0.0],
    [1.5, 0.84, 0.075],
    [1.5, 0.84, 0.15],
];

/// The y ≤ 0 halves of the handle and spout patches, rows of (x, y, z).
const HALF_PATCHES: [[[[f32; 3]; 4]; 4]; 4] = [
    // upper handle
    [
        [
            [-1.6, 0.0, 2.025],
            [-1.6, -0.3, 2.025],
            [-1.5, -0.3, 2.25],
            [-1.5, 0.0, 2.25],
        ],
        [
            [-2.3, 0.0, 2.025],
            [-2.3, -0.3, 2.025],
            [-2.5, -0.3, 2.25],
            [-2.5, 0.0, 2.25],
        ],
        [
            [-2.7, 0.0, 2.025],
            [-2.7, -0.3, 2.025],
            [-3.0, -0.3, 2.25],
            [-3.0, 0.0, 2.25],
        ],
        [
            [-2.7, 0.0, 1.8],
            [-2.7, -0.3, 1.8],
            [-3.0, -0.3, 1.8],
            [-3.0, 0.0, 1.8],
        ],
    ],
    // lower handle
    [
        [
            [-2.7, 0.0, 1.8],
            [-2.7, -0.3, 1.8],
            [-3.0, -0.3, 1.8],
            [-3.0, 0.0, 1.8],
        ],
        [
            [-2.7, 0.0, 1.575],
            [-2.7, -0.3, 1.575],
            [-3.0, -0.3, 1.35],
            [-3.0, 0.0, 1.35],
        ],
        [
            [-2.5, 0.0, 1.125],
            [-2.5, -0.3, 1.125],
            [-2.65, -0.3, 0.9375],
            [-2.65, 0.0, 0.9375],
        ],
        [
            [-2.0, 0.0, 0.9],
            [-2.0, -0.3, 0.9],
            [-1.9, -0.3, 0.6],
            [-1.9, 0.0, 0.6],
        ],
    ],
    // spout body
    [
        [
            [1.7, 0.0, 1.425],
            [1.7, -0.66, 1.425],
            [1.7, -0.66, 0.6],
            [1.7, 0.0, 0.6],
        ],
        [
            [2.6, 0.0, 1.425],
            [2.6, -0.66, 1.425],
            [3.1, -0.66, 0.825],
            [3.1, 0.0, 0.825],
        ],
        [
            [2.3, 0.0, 2.1],
            [2.3, -0.25, 2.1],
            [2.4, -0.25, 2.025],
            [2.4, 0.0, 2.025],
        ],
        [
            [2.7, 0.0, 2.4],
            [2.7, -0.25, 2.4],
            [3.3, -0.25, 2.4],
            [3.3, 0.0, 2.4],
        ],
    ],
    // spout tip
    [
        [
            [2.7, 0.0, 2.4],
            [2.7, -0.25, 2.4],
            [3.3, -0.25, 2.4],
            [3.3, 0.0, 2.4],
        ],
        [
            [2.8, 0.0, 2.475],
            [2.8, -0.25, 2.475],
            [3.525, -0.25, 2.49375],
            [3.525, 0.0, 2.49375],
        ],
        [
            [2.9, 0.0, 2.475],
            [2.9, -0.15, 2.475],
            [3.45, -0.15, 2.5125],
            [3.45, 0.0, 2.5125],
        ],
        [
            [2.8, 0.0, 2.4],
            [2.8, -0.15, 2.4],
            [3.2, -0.15, 2.4],
            [3.2, 0.0, 2.4],
        ],
    ],
];

/// Direction of the sweep through the quadrants.
#[derive(Clone, Copy)]
enum Sweep {
    /// Quadrant q is quadrant 0 rotated by −90° q: (x, y) → (y, −x).
    Clockwise,
    /// Quadrant q is (r, 0), (r, k), (k, r), (0, r) rotated by +90° q: (x, y) → (−y, x).
    Anticlockwise,
}

fn revolution(profile: &[[f32; 3]; 4], sweep: Sweep) -> [Patch; 4] {
    let mut patches = [[[Vec3::ZERO; 4]; 4]; 4];
    for (q, patch) in patches.iter_mut().enumerate() {
        for (row, &[r, k, z]) in patch.iter_mut().zip(profile) {
            let base = match sweep {
                Sweep::Clockwise => [(r, 0.0), (r, -k), (k, -r), (0.0, -r)],
                Sweep::Anticlockwise => [(r, 0.0), (r, k), (k, r), (0.0, r)],
            };
            for (cell, (mut x, mut y)) in row.iter_mut().zip(base) {
                for _ in 0..q {
                    (x, y) = match sweep {
                        Sweep::Clockwise => (y, -x),
                        Sweep::Anticlockwise => (-y, x),
                    };
                }
                *cell = Vec3::new(x, y, z);
            }
        }
    }
    patches
}

/// All 32 patches in Newell's z-up frame.
fn patches() -> Vec<Patch> {
    let mut all = Vec::with_capacity(32);
    for profile in [&RIM, &UPPER_BODY, &LOWER_BODY, &LID_KNOB, &LID] {
        all.extend(revolution(profile, Sweep::Clockwise));
    }
    all.extend(revolution(&BOTTOM, Sweep::Anticlockwise));
    for half in &HALF_PATCHES {
        let patch: Patch = half.map(|row| row.map(Vec3::from_array));
        let mirror: Patch = patch.map(|row| {
            let mut m = row.map(|p| Vec3::new(p.x, -p.y, p.z));
            m.reverse();
            m
        });
        all.push(patch);
        all.push(mirror);
    }
    all
}

/// Cubic Bernstein weights at t.
fn bernstein(t: f32) -> [f32; 4] {
    let s = 1.0 - t;
    [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
}

fn evaluate(patch: &Patch, u: f32, v: f32) -> Vec3 {
    let (bu, bv) = (bernstein(u), bernstein(v));
    let mut p = Vec3::ZERO;
    for (row, wu) in patch.iter().zip(bu) {
        for (cell, wv) in row.iter().zip(bv) {
            p += *cell * (wu * wv);
        }
    }
    p
}

/// The teapot with each patch cut into `tessellation`² quads (at most 64·n² triangles,
/// fewer after the pole triangles are dropped).
pub fn teapot(size: f32, tessellation: u32) -> Mesh {
    let n = tessellation.max(1);
    let mut mesh = Mesh::default();
    for patch in patches() {
        let base = mesh.positions.len() as u32;
        for i in 0..=n {
            for j in 0..=n {
                let (u, v) = (i as f32 / n as f32, j as f32 / n as f32);
                mesh.positions.push(evaluate(&patch, u, v));
            }
        }
        let row = n + 1;
        for i in 0..n {
            for j in 0..n {
                let a = base + i * row + j;
                let (b, c, d) = (a + 1, a + row, a + row + 1);
                // (b − a) × (c − a) = ∂v × ∂u, outwards for Newell's patch orientation.
                mesh.triangles.push([a, b, c]);
                mesh.triangles.push([c, b, d]);
            }
        }
    }
    mesh.normals = vec![Vec3::ZERO; mesh.positions.len()];
    mesh.weld();
    mesh.drop_degenerate();
    mesh.compute_normals();
    // z-up → y-up: a −90° turn about x, (x, y, z) → (x, z, −y); then the size.
    let to_y_up =
        Mat4::from_scale(Vec3::splat(size)) * Mat4::from_rotation_x(-std::f32::consts::FRAC_PI_2);
    mesh.transformed(&to_y_up)
}
