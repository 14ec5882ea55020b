//! Coleman's CPU-limit test (`bench --only coleman`, `render::submission`) on real GL
//! contexts: the F-35 fleet drawn with its objects submitted in immediate mode, as display
//! lists and from buffers gives the same picture and mask — tolerance: none, not one
//! channel of one pixel differs (the same triangles in the same order reach the same
//! rasteriser; only the door differs) — and the doors really differ in what they cost:
//! immediate mode uploads every object's geometry at every draw, a display list and a
//! buffer once.

use fixedfunc::bench::coleman::{fleet, measure_submissions, SUBMISSIONS, SUBMITTED};
use fixedfunc::render::{ImageSize, RemakeMaps, RenderOptions, RenderOutcome, Session};
use fixedfunc::truth::{self, TruthOptions};
use fixedfunc::vocab::{Named, PipelineKind, Submission};

const AIRCRAFT: usize = 10;
const FRAMES: u64 = 3;

/// `FRAMES` frames of the fleet through `submission`, judged against `truth`.
fn render(
    entrant: fixedfunc::bench::coleman::Entrant,
    submission: Submission,
    truth: Option<&truth::Truth>,
) -> (RenderOutcome, fixedfunc::scene::Scene) {
    let mut scene = fleet(AIRCRAFT, 1.0).expect("the fleet");
    scene.shadow.occluder_program = entrant.program.unwrap_or_default();
    let options = RenderOptions {
        pipeline: PipelineKind::Emulate,
        technique: Some(entrant.technique),
        size: Some(ImageSize {
            width: 256,
            height: 256,
        }),
        remake_maps: RemakeMaps::Always,
        submission,
        ..RenderOptions::default()
    };
    let mut session = Session::new(&scene, &options)
        .unwrap_or_else(|e| panic!("{} {submission}: {e}", entrant.label()));
    for _ in 0..FRAMES {
        session
            .frame()
            .unwrap_or_else(|e| panic!("{} {submission}: {e}", entrant.label()));
    }
    let rendered = session.scene().clone();
    let outcome = session
        .finish(truth)
        .unwrap_or_else(|e| panic!("{} {submission}: {e}", entrant.label()));
    (outcome, rendered)
}

#[test]
fn the_three_doors_draw_the_same_and_only_immediate_mode_uploads_every_draw() {
    for entrant in SUBMITTED {
        let label = entrant.label();
        let (buffers, scene) = render(entrant, Submission::Buffers, None);
        let truth = truth::truth(&scene, &TruthOptions::default()).expect("the truth");
        let objects = scene.objects.len() as u64;
        let (immediate, _) = render(entrant, Submission::Immediate, Some(&truth));
        let (lists, _) = render(entrant, Submission::DisplayList, Some(&truth));
        for (door, other) in [("immediate", &immediate), ("display-list", &lists)] {
            let differing = buffers
                .image
                .pixels()
                .zip(other.image.pixels())
                .filter(|(a, b)| a != b)
                .count();
            assert_eq!(differing, 0, "{label} {door}: pixels unlike buffers'");
            assert!(
                buffers.mask == other.mask,
                "{label} {door}: the mask differs"
            );
            // One draw command per object draw, whatever the door.
            assert_eq!(
                other.counters.draws, buffers.counters.draws,
                "{label} {door}"
            );
        }
        let (b, i, l) = (
            buffers.counters.geometry_uploads,
            immediate.counters.geometry_uploads,
            lists.counters.geometry_uploads,
        );
        // A list's geometry replaces the prepared one, one for one, uploaded once.
        assert_eq!(l, b, "{label}: lists uploaded {l}, buffers {b}");
        // Every object is drawn at least once a frame; immediate mode uploads each draw.
        assert!(
            i >= b + FRAMES * objects,
            "{label}: immediate mode uploaded {i}, buffers {b}, {objects} objects × {FRAMES} frames"
        );
        // The front left no GL error (`finish` would have failed) and the shadows agree
        // with the truth as much as buffers' do: the same mask.
        assert_eq!(immediate.metrics.all, buffers.metrics.all, "{label}");
    }
}

#[test]
fn the_cpu_limit_test_gives_a_row_per_entrant_and_door() {
    let mut rounds = 0;
    let (rows, skipped) = measure_submissions(1, &[1], || rounds += 1).expect("the test runs");
    assert!(skipped.is_empty(), "{skipped:#?}");
    assert_eq!(rounds, 2, "a cold and a steady frame");
    assert_eq!(rows.len(), SUBMITTED.len() * SUBMISSIONS.len(), "{rows:#?}");
    for e in SUBMITTED {
        for s in SUBMISSIONS {
            let row = rows
                .iter()
                .find(|r| r.technique == e.technique && r.submission == s)
                .unwrap_or_else(|| panic!("no row for {} {s}", e.label()));
            assert!(row.cold_ms > 0.0 && row.frame.min > 0.0, "{row:?}");
            assert_eq!((row.instances, row.scale), (1, 1.0));
        }
    }
    let json = serde_json::to_value(&rows[0]).expect("a row serialises");
    assert_eq!(json["submission"], SUBMISSIONS[0].name());
}
