//! Budgets: how much a scene may ask of the machine, checked from the scene's parameters
//! before anything large is allocated.
//!
//! A tessellation count is one small number in a file that can ask for billions of
//! triangles (`tessellation = 5000` is 50 million; the process used to abort at 6.5 GiB
//! while building them). So every procedural shape's triangle count is computed from its
//! parameters ([`Shape::triangle_estimate`], the formulas of `mesh::shapes`) and the sum
//! is checked before the first mesh is built; an OBJ file's count is known, and checked,
//! once it is read. The memory a *run* needs besides the meshes (framebuffers, readbacks,
//! the truth's per-pixel buffers, one copy of the geometry per GL context) is estimated by
//! `render::Footprint` against the same [`Limits::memory_bytes`].
//!
//! **The defaults.** The machines this runs on in CI have 24 GiB shared by several builds
//! and test processes; a third, 8 GiB, is the default memory budget, leaving the rest for
//! the operating system, the processes next to us and what an estimate leaves out (driver
//! allocations, allocator slack). The triangle budget, 20 million, is what fits that
//! memory in one `render` with its truth ([`BYTES_PER_TRIANGLE`] +
//! [`GPU_BYTES_PER_TRIANGLE`] each: 6.7 GiB) with room for the framebuffers; it is also
//! where waiting stops being reasonable (2 million triangles take 10 s to ray-cast and 14 s
//! to render once, measured). Both are raised per run with `--max-triangles N` and
//! `--memory-budget GIB` (every command takes them; the library takes a [`Limits`] in
//! `Scene::parse_with` / `load_with`, and the scene carries it to the run).

use super::types::Shape;
use crate::mesh::AircraftLayout;

/// The largest image width or height accepted: 8192. A larger frame's colour target alone
/// is ≥ 256 MiB and its truth ≥ 67 million primary rays; llvmpipe's renderbuffer limit is
/// 16384. Also the largest light map (`[shadow] map_size`): map and image share one
/// framebuffer.
pub const MAX_IMAGE_SIZE: u32 = 8192;

/// Default triangle budget of a scene: 20 million (see the module note).
pub const DEFAULT_MAX_TRIANGLES: u64 = 20_000_000;

/// Default memory budget: 8 GiB, a third of a 24 GiB machine (see the module note).
pub const DEFAULT_MEMORY_BYTES: u64 = 8 << 30;

/// Bytes a triangle costs a run once, whatever renders it holds: the object-space mesh,
/// the truth's world-space copy, its BVH and leaf arrays. Measured: peak resident memory
/// of `fixedfunc truth` on tessellated planes of 0.5 and 2 million triangles grows by
/// 304 B per triangle (2000 spheres: 305 B). `render::Footprint` adds
/// [`GPU_BYTES_PER_TRIANGLE`] per GL context.
pub const BYTES_PER_TRIANGLE: u64 = 300;

/// Bytes a triangle costs inside one GL context (llvmpipe keeps vertex and index buffers
/// in host memory; each session of a comparison has its own copy) and in the draw-ready
/// geometry. Measured as above with `render --technique none`: 47 B per triangle over
/// `truth`'s.
pub const GPU_BYTES_PER_TRIANGLE: u64 = 60;

/// The budgets a scene is loaded and run under.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Triangles of all objects together.
    pub max_triangles: u64,
    /// Bytes a run may need, by `render::Footprint`'s estimate.
    pub memory_bytes: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_triangles: DEFAULT_MAX_TRIANGLES,
            memory_bytes: DEFAULT_MEMORY_BYTES,
        }
    }
}

/// Bytes as a short human figure: "4.1 GiB", "512 MiB", "96 KiB".
pub fn human_bytes(bytes: u64) -> String {
    const UNITS: [(&str, u64); 3] = [("GiB", 1 << 30), ("MiB", 1 << 20), ("KiB", 1 << 10)];
    for (name, size) in UNITS {
        if bytes >= size {
            return format!("{:.1} {name}", bytes as f64 / size as f64);
        }
    }
    format!("{bytes} B")
}

/// A count with thousands separators: 50,000,000.
pub fn grouped(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + digits.len() / 3);
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    out
}

impl Shape {
    /// Triangles the shape's mesh will have, from its parameters alone (no mesh is built);
    /// 0 for an OBJ file, whose count is known once it is read. Exact for every shape but
    /// the teapot, for which it is an upper bound (its 32 patches of 2n² triangles before
    /// the degenerate ones at the poles of the lid and body are dropped: 52 of 64 at n = 1). Saturates at
    /// `u64::MAX`.
    pub fn triangle_estimate(&self) -> u64 {
        let n = |v: u32| u64::from(v);
        let product = |factors: &[u64]| factors.iter().fold(1u64, |acc, &f| acc.saturating_mul(f));
        match *self {
            // plane n → 2n² (counts below a shape's minimum are raised to it, as the mesh
            // functions do).
            Shape::Plane { tessellation, .. } => {
                product(&[2, n(tessellation.max(1)), n(tessellation.max(1))])
            }
            Shape::Box { .. } => 12,
            // 2 · slices · (stacks − 1): fans at the poles, quads between.
            Shape::Sphere { slices, stacks, .. } => {
                product(&[2, n(slices.max(3)), n(stacks.max(2)) - 1])
            }
            Shape::Torus { rings, sides, .. } => product(&[2, n(rings.max(3)), n(sides.max(3))]),
            Shape::Teapot { tessellation, .. } => product(&[
                TEAPOT_PATCHES,
                2,
                n(tessellation.max(1)),
                n(tessellation.max(1)),
            ]),
            Shape::Aircraft {
                layout: AircraftLayout::Fighter { .. },
            } => AIRCRAFT_TRIANGLES,
            Shape::Aircraft {
                layout: AircraftLayout::F35,
            } => F35_TRIANGLES,
            Shape::Obj { .. } => 0,
        }
    }
}

/// Newell's teapot: 32 bicubic patches (`mesh::teapot`).
const TEAPOT_PATCHES: u64 = 32;

/// `mesh::aircraft`'s fixed triangle count (a test keeps it equal to the mesh's).
const AIRCRAFT_TRIANGLES: u64 = 408;
/// `mesh::aircraft_f35`'s fixed triangle count (a test keeps it equal to the mesh's).
const F35_TRIANGLES: u64 = 408;

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn estimates_match_the_meshes() {
        let exact = [
            Shape::Plane {
                size: 1.0,
                tessellation: 7,
            },
            Shape::Box { size: Vec3::ONE },
            Shape::Sphere {
                radius: 1.0,
                slices: 9,
                stacks: 5,
            },
            Shape::Torus {
                major_radius: 1.0,
                minor_radius: 0.2,
                rings: 11,
                sides: 6,
            },
            Shape::Aircraft {
                layout: AircraftLayout::Fighter { length: 4.0 },
            },
            Shape::Aircraft {
                layout: AircraftLayout::F35,
            },
        ];
        for shape in exact {
            let mesh = shape.procedural_mesh().expect("procedural");
            assert_eq!(
                shape.triangle_estimate(),
                mesh.triangle_count() as u64,
                "{shape:?}"
            );
        }
        for tessellation in [1, 4, 9] {
            let teapot = Shape::Teapot {
                size: 1.0,
                tessellation,
            };
            let built = teapot
                .procedural_mesh()
                .expect("procedural")
                .triangle_count() as u64;
            let bound = teapot.triangle_estimate();
            assert!(
                built <= bound && bound - built <= bound / 4,
                "{built} vs {bound}"
            );
        }
        let huge = Shape::Plane {
            size: 1.0,
            tessellation: u32::MAX,
        };
        assert_eq!(huge.triangle_estimate(), u64::MAX, "saturates, never wraps");
    }

    #[test]
    fn figures_read_well() {
        assert_eq!(grouped(50_000_000), "50,000,000");
        assert_eq!(grouped(999), "999");
        assert_eq!(grouped(1000), "1,000");
        assert_eq!(human_bytes(8 << 30), "8.0 GiB");
        assert_eq!(human_bytes(3 << 19), "1.5 MiB");
        assert_eq!(human_bytes(12), "12 B");
    }
}
