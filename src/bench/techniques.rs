//! `bench --only techniques`: every shadow technique on the default scene (512² image, 512²
//! map, its well-chosen bias), on the emulated and the native path, frames interleaved
//! round-robin across all of them (`render::rounds`) so machine noise hits each alike; a
//! session whose frame fails (no path for a feature) leaves the rounds and, for the rows
//! that remake their maps, is listed with its reason. Maps are re-made every frame
//! (`RemakeMaps::Always`) so that each frame's split is comparable; with `pass_times`
//! every pass ends in glFinish, so the split adds a little synchronisation to the frame
//! time it explains.
//!
//! Per row: the frame (cold, and steady median/min/max over the repeats), split into the
//! light pass, readback + upload (every other map pass) and the eye passes, the frame time
//! against `none` on the same path (the cost of the shadow as a ratio) and emulated against
//! native; and, from a second session of the same technique whose maps are made once
//! (`RemakeMaps::WhenMoved`, the static scene), its steady frame — which should cost about
//! the eye passes alone.

use crate::vocab::{Named, PipelineKind, TechniqueId};
use serde::Serialize;

use crate::render::rounds::{self, Lane, Rules, Verdict};
use crate::render::{ImageSize, PassTime, RemakeMaps, RenderError, RenderOptions, Session};
use crate::scene::{OffsetSetting, Scene};
use crate::stats::Summary;

/// One technique on one path.
#[derive(Debug, Clone, Serialize)]
pub struct TechniqueRow {
    pub technique: TechniqueId,
    pub pipeline: PipelineKind,
    pub cold_ms: f64,
    pub frame: Summary,
    /// The light pass (`light`), per frame.
    pub light: Option<Summary>,
    /// Every other map pass (readback, upload, copy), per frame.
    pub readback_upload: Option<Summary>,
    /// The eye passes, per frame.
    pub eye: Summary,
    /// Steady frame median / `none`'s on the same path.
    pub vs_none: Option<f64>,
    /// Emulated steady frame median / native's (on the emulated row).
    pub emulate_vs_native: Option<f64>,
    /// The steady frame of a static scene (maps made once, on frame 1): the eye passes'
    /// cost plus nothing.
    pub static_frame: Option<Summary>,
    pub passes: usize,
    pub programs: u64,
}

/// A technique or path that could not run (e.g. register combiners on the native path).
#[derive(Debug, Clone, Serialize)]
pub struct Skipped {
    pub technique: TechniqueId,
    pub pipeline: PipelineKind,
    pub reason: String,
}

/// What the group keeps beside each session in the rounds.
type Tag = (TechniqueId, PipelineKind, RemakeMaps);

/// The group's rules for the rounds: a failed session leaves them (listed with its reason
/// when it is a row's own), and each round ticks the progress.
struct BenchRules<'a, F> {
    skipped: &'a mut Vec<Skipped>,
    tick: F,
}

impl<F: FnMut()> Rules<Tag> for BenchRules<'_, F> {
    fn failed(&mut self, &(technique, pipeline, remake): &Tag, error: &RenderError) -> Verdict {
        if remake == RemakeMaps::Always {
            self.skipped.push(Skipped {
                technique,
                pipeline,
                reason: error.to_string(),
            });
        }
        Verdict::Retire
    }

    fn round_done(&mut self, _round: u32) {
        (self.tick)();
    }
}

/// Runs the group: `repeats` steady frames after the cold one, per row.
pub fn measure(
    repeats: usize,
    tick: impl FnMut(),
) -> Result<(Vec<TechniqueRow>, Vec<Skipped>), RenderError> {
    let mut lanes = Vec::new();
    let mut skipped = Vec::new();
    for technique in TechniqueId::all() {
        for pipeline in [PipelineKind::Emulate, PipelineKind::Native] {
            for remake in [RemakeMaps::Always, RemakeMaps::WhenMoved] {
                let mut scene = Scene::default_scene();
                scene.shadow.map_size = 512;
                scene.shadow.polygon_offset = OffsetSetting::TechniqueDefault;
                let options = RenderOptions {
                    pipeline,
                    technique: Some(technique),
                    size: Some(ImageSize {
                        width: 512,
                        height: 512,
                    }),
                    remake_maps: remake,
                    pass_times: remake == RemakeMaps::Always,
                    ..RenderOptions::default()
                };
                match Session::new(&scene, &options) {
                    Ok(s) => lanes.push(Lane {
                        tag: (technique, pipeline, remake),
                        session: Ok(s),
                    }),
                    Err(e) if remake == RemakeMaps::Always => skipped.push(Skipped {
                        technique,
                        pipeline,
                        reason: e.to_string(),
                    }),
                    Err(_) => {}
                }
            }
        }
    }
    let rounds = u32::try_from(repeats.max(1))
        .unwrap_or(u32::MAX)
        .saturating_add(1);
    let mut rules = BenchRules {
        skipped: &mut skipped,
        tick,
    };
    rounds::run(&mut lanes, rounds, &mut rules).map_err(|stop| stop.error)?;
    let truth = crate::truth::truth(&Scene::default_scene(), &Default::default())?;
    let mut rows: Vec<TechniqueRow> = Vec::new();
    let mut statics = Vec::new();
    for lane in lanes {
        let ((technique, pipeline, remake), Ok(session)) = (lane.tag, lane.session) else {
            continue;
        };
        let outcome = session.finish(Some(&truth))?;
        if remake == RemakeMaps::WhenMoved {
            statics.push((technique, pipeline, outcome.timings.steady));
            continue;
        }
        let steady = |ms: &[f64]| Summary::of(ms.get(1..).unwrap_or(&[]));
        let sum_by = |pick: &dyn Fn(&PassTime) -> bool| -> Option<Summary> {
            let chosen: Vec<_> = outcome.pass_times.iter().filter(|p| pick(p)).collect();
            if chosen.is_empty() {
                return None;
            }
            let frames = chosen[0].ms.len();
            let per_frame: Vec<f64> = (0..frames)
                .map(|f| {
                    chosen
                        .iter()
                        .map(|p| p.ms.get(f).copied().unwrap_or(0.0))
                        .sum()
                })
                .collect();
            steady(&per_frame)
        };
        let Some(frame) = outcome.timings.steady else {
            continue;
        };
        rows.push(TechniqueRow {
            technique,
            pipeline,
            cold_ms: outcome.timings.cold_ms,
            frame,
            light: sum_by(&|p| p.map && p.name == "light"),
            readback_upload: sum_by(&|p| p.map && p.name != "light"),
            eye: sum_by(&|p| !p.map).unwrap_or(frame),
            vs_none: None,
            emulate_vs_native: None,
            static_frame: None,
            passes: outcome.passes,
            programs: outcome.counters.programs_compiled,
        });
    }
    let none: Vec<(PipelineKind, f64)> = rows
        .iter()
        .filter(|r| r.technique == TechniqueId::None)
        .map(|r| (r.pipeline, r.frame.median))
        .collect();
    let medians: Vec<(TechniqueId, PipelineKind, f64)> = rows
        .iter()
        .map(|r| (r.technique, r.pipeline, r.frame.median))
        .collect();
    for r in &mut rows {
        r.vs_none = none
            .iter()
            .find(|(p, _)| *p == r.pipeline)
            .map(|(_, n)| r.frame.median / n);
        if r.pipeline == PipelineKind::Emulate {
            r.emulate_vs_native = medians
                .iter()
                .find(|(t, p, _)| *t == r.technique && *p == PipelineKind::Native)
                .map(|(_, _, n)| r.frame.median / n);
        }
        r.static_frame = statics
            .iter()
            .find(|(t, p, _)| *t == r.technique && *p == r.pipeline)
            .and_then(|(_, _, s)| *s);
    }
    Ok((rows, skipped))
}
