//! `render` end to end on real contexts: the `none` technique on the default scene, on both
//! pipelines and both headless backends.
//!
//! Tolerances: images agree within 3/255 per channel (piglit's 3/2^bits) on all but 1% of
//! the pixels (edge pixels where the two paths rasterise or light a sample differently);
//! the mask's coverage differs from the truth's only on pixels next to a coverage edge, and
//! on at most 1% of the pixels.

mod support;

use fixedfunc::gpu::Backend;
use fixedfunc::metrics::{Mask, BACKGROUND};
use fixedfunc::render::{render, ImageSize, RenderOptions, RenderOutcome};
use fixedfunc::scene::Scene;
use fixedfunc::vocab::{PipelineKind, TechniqueId};
use support::{assert_images_match, Tolerance, HEADLESS};

const SIZE: ImageSize = ImageSize {
    width: 160,
    height: 120,
};
const FRAMES: u32 = 3;
const KINDS: [PipelineKind; 2] = [PipelineKind::Native, PipelineKind::Emulate];

fn run(backend: Backend, pipeline: PipelineKind) -> RenderOutcome {
    let options = RenderOptions {
        backend,
        pipeline,
        technique: Some(TechniqueId::None),
        size: Some(SIZE),
        frames: FRAMES,
        ..RenderOptions::default()
    };
    render(&Scene::default_scene(), &options)
        .unwrap_or_else(|e| panic!("{backend} {pipeline:?}: {e}"))
}

#[test]
fn none_on_the_default_scene_matches_across_pipelines_and_backends() {
    let oracle = run(Backend::Egl, PipelineKind::Native);
    let tolerance = Tolerance {
        per_channel: 3,
        max_bad_pixels: (SIZE.width * SIZE.height / 100) as usize,
    };
    for backend in HEADLESS {
        for kind in KINDS {
            let got = run(backend, kind);
            assert_images_match(
                &format!("none-default-{backend}-{kind:?}"),
                &got.image,
                &oracle.image,
                tolerance,
            );
        }
    }
}

/// The stored reference (`tests/reference/none-default-160x120.png`, made once by the
/// native path on EGL) guards against both paths drifting together. Tolerance as above.
/// Set FIXEDFUNC_BLESS=1 to rewrite it after an intended change of the default scene.
#[test]
fn none_on_the_default_scene_matches_the_reference_image() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/reference/none-default-160x120.png"
    );
    if std::env::var_os("FIXEDFUNC_BLESS").is_some() {
        run(Backend::Egl, PipelineKind::Native)
            .image
            .save(path)
            .expect("write reference");
    }
    let reference = image::open(path).expect("reference image").to_rgba8();
    let tolerance = Tolerance {
        per_channel: 3,
        max_bad_pixels: (SIZE.width * SIZE.height / 100) as usize,
    };
    for backend in HEADLESS {
        for kind in KINDS {
            let got = run(backend, kind);
            assert_images_match(
                &format!("none-reference-{backend}-{kind:?}"),
                &got.image,
                &reference,
                tolerance,
            );
        }
    }
}

#[test]
fn none_runs_one_pass_and_compiles_few_programs() {
    let objects = Scene::default_scene().objects.len() as u64;
    for backend in HEADLESS {
        for kind in KINDS {
            let got = run(backend, kind);
            assert_eq!(got.passes, 1, "{backend} {kind:?}");
            assert_eq!(got.counters.draws, FRAMES as u64 * objects);
            assert_eq!(got.counters.texture_uploads, 0);
            match kind {
                // All objects share one key (lit, one spot light, no texture): one program,
                // two at most if the clear or the readback needs its own.
                PipelineKind::Emulate => assert!(
                    (1..=2).contains(&got.counters.programs_compiled),
                    "{backend}: {:?}",
                    got.counters
                ),
                PipelineKind::Native => assert_eq!(got.counters.programs_compiled, 0),
            }
            assert_eq!(got.timings.frames_ms.len(), FRAMES as usize);
        }
    }
}

/// Pixels whose geometry/background class differs from a 4-neighbour's.
fn coverage_edges(mask: &Mask) -> Vec<bool> {
    let (w, h) = (mask.width as i64, mask.height as i64);
    let bg = |x: i64, y: i64| mask.data[(y * w + x) as usize] == BACKGROUND;
    let mut edge = vec![false; mask.data.len()];
    for y in 0..h {
        for x in 0..w {
            edge[(y * w + x) as usize] = [(1, 0), (-1, 0), (0, 1), (0, -1)]
                .iter()
                .map(|(dx, dy)| (x + dx, y + dy))
                .filter(|&(nx, ny)| (0..w).contains(&nx) && (0..h).contains(&ny))
                .any(|(nx, ny)| bg(nx, ny) != bg(x, y));
        }
    }
    edge
}

#[test]
fn none_mask_is_the_truth_coverage_up_to_edge_pixels() {
    for backend in HEADLESS {
        for kind in KINDS {
            let got = run(backend, kind);
            let truth = &got.truth.mask;
            assert_eq!((got.mask.width, got.mask.height), (SIZE.width, SIZE.height));
            assert!(got.mask.data.iter().all(|&v| v == 255 || v == BACKGROUND));
            let edges = coverage_edges(truth);
            let mut differ = 0;
            for (i, (&m, &t)) in got.mask.data.iter().zip(&truth.data).enumerate() {
                if (m == BACKGROUND) != (t == BACKGROUND) {
                    differ += 1;
                    assert!(
                        edges[i],
                        "{backend} {kind:?}: coverage differs off an edge at {i}"
                    );
                }
            }
            assert!(
                differ <= (SIZE.width * SIZE.height / 100) as usize,
                "{backend} {kind:?}: {differ} pixels"
            );
            // `none` lights everything: it can miss shadows but never invent them.
            assert_eq!(got.metrics.all.false_shadow, 0);
        }
    }
}
