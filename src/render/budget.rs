//! What a run will need in memory, estimated from the scene before any context is made,
//! and refused over the scene's [`Limits::memory_bytes`].
//!
//! A run is the truth plus `sessions` renders held open at once (`render`: 1; `compare`:
//! every technique × pipeline; `sweep-bias`: one per depth format and pipeline; `truth`:
//! 0). Its bytes, with W×H the image and F×G = max(W, map) × max(H, map) the shared
//! framebuffer (image and light map side by side, see `techniques::map`):
//!
//! - the scene: triangles × `BYTES_PER_TRIANGLE` (meshes, draw-ready geometry, the truth's
//!   BVH), once;
//! - per session: [`SESSION_BYTES`] for the context, [`OBJECT_BYTES`] per object (its
//!   buffers and commands), triangles × `GPU_BYTES_PER_TRIANGLE` (llvmpipe's vertex and
//!   index buffers), F·G · (4 colour + depth bytes) for the framebuffer, F·G · 4 for the
//!   colour readback, W·H · 6 for the image and the mask, map² · 8 for the map's readbacks;
//! - the truth: W·H · [`TRUTH_BYTES_PER_PIXEL`] (each pixel's primary hit, its shade, the
//!   mask and the visibility);
//! - for `compare --passes`, each row's pass pictures held until the report is written:
//!   W·H · [`CAPTURE_BYTES_PER_PIXEL`] per row ([`Footprint::with_pass_captures`]).
//!
//! Measured (peak resident memory, `/usr/bin/time -f %M`, llvmpipe on EGL): `compare
//! --size 2048x2048` of the default scene peaks at 1.44 GiB, estimated 1.6 GiB; `render`
//! of 2000 spheres (1.92 million triangles) at 0.80 GiB, estimated 0.84 GiB; `truth` of a
//! 2-million-triangle plane at 0.57 GiB, estimated 0.56 GiB. `compare --size 8192x8192`
//! used to climb to 6.9 GiB before llvmpipe gave up with an incomplete framebuffer; its
//! estimate is 22.0 GiB and it is refused with the figures before the first context.

use crate::scene::{
    grouped, human_bytes, Limits, Scene, BYTES_PER_TRIANGLE, GPU_BYTES_PER_TRIANGLE,
};
use crate::vocab::DepthBits;

/// Bytes per pixel of the truth: the primary hit (`Option<Hit>`: point, normal, a vertex
/// and a flag, 40), the shade (value, visibility, rays: 12), the mask (1), the visibility
/// (4), rounded up.
pub const TRUTH_BYTES_PER_PIXEL: u64 = 60;

/// Bytes per image pixel of one row's pass pictures (`render::pass_images`): at most 8
/// passes (projective's silhouettes and copies, the eye passes), each holding colour (4),
/// depth (4), stencil (1), the alpha before the test (4, two reads kept as one) and the
/// map minus the ramp (4).
pub const CAPTURE_BYTES_PER_PIXEL: u64 = 8 * (4 + 4 + 1 + 4 + 4);

/// A GL context held open: 16 MiB (measured: 13.5 MB per session added to a comparison of
/// the default scene at 64×64).
pub const SESSION_BYTES: u64 = 16 << 20;

/// An object in a session: 96 KiB (its vertex and index buffers' allocation granules and
/// its commands; measured 84 KB per object over the per-triangle share, 2000 spheres).
pub const OBJECT_BYTES: u64 = 96 << 10;

/// A run's estimated needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Footprint {
    /// Triangles of the scene's meshes (as loaded).
    pub triangles: u64,
    /// Renders held open at once.
    pub sessions: u64,
    /// The meshes and the truth's BVH, once.
    pub scene_bytes: u64,
    /// One session: its copy of the geometry, framebuffer and readbacks.
    pub session_bytes: u64,
    /// The truth's per-pixel buffers.
    pub truth_bytes: u64,
    /// Pass pictures held for the report (`compare --passes`), all rows together.
    pub capture_bytes: u64,
}

impl Footprint {
    /// The needs of the truth of `scene` and `sessions` renders of it held open at once.
    pub fn of(scene: &Scene, sessions: usize) -> Footprint {
        let triangles: u64 = scene
            .objects
            .iter()
            .map(|o| o.mesh.triangle_count() as u64)
            .sum();
        let (w, h) = (u64::from(scene.image.width), u64::from(scene.image.height));
        let map = u64::from(scene.shadow.map_size);
        let (fw, fh) = (w.max(map), h.max(map));
        let depth_bytes = match scene.shadow.depth {
            DepthBits::D16 => 2,
            // D24 always has 8 stencil bits; D32F may have them.
            DepthBits::D24 => 4,
            DepthBits::D32F => 8,
        };
        let framebuffer = fw * fh * (4 + depth_bytes + 4);
        let objects = scene.objects.len() as u64;
        let session_bytes = SESSION_BYTES
            + objects.saturating_mul(OBJECT_BYTES)
            + triangles.saturating_mul(GPU_BYTES_PER_TRIANGLE)
            + framebuffer
            + w * h * 6
            + map * map * 8;
        Footprint {
            triangles,
            sessions: sessions as u64,
            scene_bytes: triangles.saturating_mul(BYTES_PER_TRIANGLE),
            session_bytes,
            truth_bytes: w * h * TRUTH_BYTES_PER_PIXEL,
            capture_bytes: 0,
        }
    }

    /// With `rows` rows' pass pictures of `scene`'s image held until the report is written.
    pub fn with_pass_captures(mut self, scene: &Scene, rows: usize) -> Footprint {
        let pixels = u64::from(scene.image.width) * u64::from(scene.image.height);
        self.capture_bytes = (rows as u64)
            .saturating_mul(pixels)
            .saturating_mul(CAPTURE_BYTES_PER_PIXEL);
        self
    }

    /// Everything together.
    pub fn total_bytes(&self) -> u64 {
        self.scene_bytes
            .saturating_add(self.sessions.saturating_mul(self.session_bytes))
            .saturating_add(self.truth_bytes)
            .saturating_add(self.capture_bytes)
    }

    /// `Err` naming the figures when the triangles are over `limits.max_triangles` (a
    /// scene built in code, not loaded, meets the budget here first) or the total is over
    /// `limits.memory_bytes`.
    pub fn check(&self, limits: &Limits) -> Result<(), OverBudget> {
        if self.triangles > limits.max_triangles {
            Err(OverBudget::Triangles {
                triangles: self.triangles,
                max_triangles: limits.max_triangles,
            })
        } else if self.total_bytes() > limits.memory_bytes {
            Err(OverBudget::Memory {
                footprint: *self,
                memory_bytes: limits.memory_bytes,
            })
        } else {
            Ok(())
        }
    }
}

/// A run refused before it started: what it would need and the budget.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum OverBudget {
    #[error(
        "the scene has {} triangles; the budget is {} triangles; raise it with --max-triangles N",
        grouped(*.triangles),
        grouped(*.max_triangles)
    )]
    Triangles { triangles: u64, max_triangles: u64 },
    #[error(
        "the run would need ≈ {} ({} for {} triangles, {} × {} per render held open \
         (geometry, framebuffer, readbacks), {} for the truth's pixels, {} for pass \
         pictures); the memory budget is {}; raise it with --memory-budget GIB, or ask for a \
         smaller --size or fewer techniques",
        human_bytes(.footprint.total_bytes()),
        human_bytes(.footprint.scene_bytes),
        grouped(.footprint.triangles),
        .footprint.sessions,
        human_bytes(.footprint.session_bytes),
        human_bytes(.footprint.truth_bytes),
        human_bytes(.footprint.capture_bytes),
        human_bytes(*.memory_bytes)
    )]
    Memory {
        footprint: Footprint,
        memory_bytes: u64,
    },
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_scene_fits_and_a_huge_comparison_does_not() {
        let scene = Scene::default_scene();
        let one = Footprint::of(&scene, 1);
        assert!(one.total_bytes() < 64 << 20, "{one:?}");
        assert!(one.check(&scene.limits).is_ok());
        let mut big = scene.clone();
        big.image.width = 8192;
        big.image.height = 8192;
        let compare = Footprint::of(&big, 14);
        let err = compare.check(&big.limits).expect_err("over budget");
        let text = err.to_string();
        assert!(
            text.contains("8.0 GiB") && text.contains("--memory-budget"),
            "{text}"
        );
        let raised = Limits {
            memory_bytes: 64 << 30,
            ..big.limits
        };
        assert!(compare.check(&raised).is_ok());
        // Pass pictures count when asked for: 14 rows of 512² pictures.
        let pictured = Footprint::of(&scene, 14).with_pass_captures(&scene, 14);
        let pixels = u64::from(scene.image.width * scene.image.height);
        assert_eq!(
            pictured.capture_bytes,
            14 * pixels * CAPTURE_BYTES_PER_PIXEL
        );
        assert_eq!(
            pictured.total_bytes(),
            Footprint::of(&scene, 14).total_bytes() + pictured.capture_bytes
        );
    }
}
