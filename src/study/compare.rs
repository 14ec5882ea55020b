//! Every chosen technique × pipeline on one scene, frames interleaved, one truth.
//!
//! Order of work: the truth (CPU, timed), every session's setup (context, framebuffer,
//! programs of the setup commands), `frames` rounds of one frame per live session, then
//! each session's `finish` with the shared truth. A session that turns out not to apply
//! (see [`super::not_applicable`]) at setup or at a frame is dropped and its row says why.

use crate::vocab::PipelineKind;
use std::time::Instant;

use crate::gpu::Backend;
use crate::render::{self, pipeline_name, ImageSize, RenderOptions, RenderOutcome, Session};
use crate::scene::Scene;
use crate::techniques::Technique;
use crate::truth::{self, Truth};

use super::{ms_since, not_applicable, Progress, StudyError};

/// What to compare.
#[derive(Debug, Clone)]
pub struct CompareSpec {
    pub techniques: Vec<&'static Technique>,
    pub pipelines: Vec<PipelineKind>,
    pub backend: Backend,
    /// Frames per session (frame 1 cold, 2…N steady), at least 1.
    pub frames: u32,
    /// Replaces the scene's image size.
    pub size: Option<ImageSize>,
}

/// Wall time a row cost the study, by phase (ms).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct RowCost {
    /// `Session::new`: context, framebuffer, pipeline, setup commands.
    pub setup_ms: f64,
    /// The sum of its frames.
    pub frames_ms: f64,
    /// Mask passes, readback, scoring.
    pub finish_ms: f64,
}

impl RowCost {
    pub fn total_ms(&self) -> f64 {
        self.setup_ms + self.frames_ms + self.finish_ms
    }
}

/// What became of one technique × pipeline.
#[derive(Debug, Clone)]
pub enum RowResult {
    Measured {
        outcome: Box<RenderOutcome>,
        cost: RowCost,
    },
    /// Does not apply here (the reason is the refusing layer's message).
    Skipped { reason: String },
}

/// One technique on one pipeline.
#[derive(Debug, Clone)]
pub struct Row {
    pub technique: &'static Technique,
    pub pipeline: PipelineKind,
    pub backend: Backend,
    pub result: RowResult,
}

impl Row {
    /// The outcome, when measured.
    pub fn outcome(&self) -> Option<&RenderOutcome> {
        match &self.result {
            RowResult::Measured { outcome, .. } => Some(outcome),
            RowResult::Skipped { .. } => None,
        }
    }

    /// `technique-pipeline`, the stem of the row's files.
    pub fn slug(&self) -> String {
        format!("{}-{}", self.technique.name, pipeline_name(self.pipeline))
    }
}

/// A finished comparison.
#[derive(Debug, Clone)]
pub struct Comparison {
    /// The scene as rendered (size override applied).
    pub scene: Scene,
    pub truth: Truth,
    /// Wall time of the truth (ms).
    pub truth_ms: f64,
    /// Rows in the order technique-major, pipeline-minor.
    pub rows: Vec<Row>,
    pub frames: u32,
    /// Wall time of the whole study (ms).
    pub total_ms: f64,
}

enum Slot {
    Open(Box<Session>, RowCost),
    Done(RowResult),
}

/// Runs the comparison; `progress` is called after each step.
pub fn compare(
    scene: &Scene,
    spec: &CompareSpec,
    mut progress: impl FnMut(Progress),
) -> Result<Comparison, StudyError> {
    if spec.techniques.is_empty() || spec.pipelines.is_empty() {
        return Err(StudyError::Empty);
    }
    let start = Instant::now();
    let frames = spec.frames.max(1);
    let combos: Vec<(&'static Technique, PipelineKind)> = spec
        .techniques
        .iter()
        .flat_map(|t| spec.pipelines.iter().map(move |p| (*t, *p)))
        .collect();
    let n = combos.len() as u64;
    let total = 1 + n * (2 + u64::from(frames));
    let mut done = 0;
    let mut step = |what: String| {
        done += 1;
        progress(Progress { done, total, what });
    };

    let base = RenderOptions {
        backend: spec.backend,
        size: spec.size,
        frames,
        ..RenderOptions::default()
    };
    let scene = render::apply_overrides(scene, spec.size, None);
    let truth_start = Instant::now();
    let truth = truth::truth(&scene, &base.truth)?;
    let truth_ms = ms_since(truth_start);
    step("ground truth".to_string());

    let fail = |t: &Technique, p: PipelineKind, source| StudyError::Render {
        technique: t.name.to_string(),
        pipeline: pipeline_name(p),
        source: Box::new(source),
    };
    let mut slots = Vec::with_capacity(combos.len());
    for &(technique, pipeline) in &combos {
        let options = RenderOptions {
            pipeline,
            technique: Some(technique.name.to_string()),
            ..base.clone()
        };
        let t0 = Instant::now();
        let slot = match Session::new(&scene, &options) {
            Ok(s) => Slot::Open(
                Box::new(s),
                RowCost {
                    setup_ms: ms_since(t0),
                    ..RowCost::default()
                },
            ),
            Err(e) => match not_applicable(&e) {
                Some(reason) => Slot::Done(RowResult::Skipped { reason }),
                None => return Err(fail(technique, pipeline, e)),
            },
        };
        slots.push(slot);
        step(format!(
            "set up {} ({})",
            technique.name,
            pipeline_name(pipeline)
        ));
    }

    for f in 1..=frames {
        for (slot, &(technique, pipeline)) in slots.iter_mut().zip(&combos) {
            if let Slot::Open(session, cost) = slot {
                match session.frame() {
                    Ok(ms) => cost.frames_ms += ms,
                    Err(e) => match not_applicable(&e) {
                        Some(reason) => *slot = Slot::Done(RowResult::Skipped { reason }),
                        None => return Err(fail(technique, pipeline, e)),
                    },
                }
            }
            step(format!(
                "frame {f}/{frames} of {} ({})",
                technique.name,
                pipeline_name(pipeline)
            ));
        }
    }

    let mut rows = Vec::with_capacity(slots.len());
    for (slot, &(technique, pipeline)) in slots.into_iter().zip(&combos) {
        let result = match slot {
            Slot::Done(result) => result,
            Slot::Open(session, mut cost) => {
                let t0 = Instant::now();
                match session.finish(Some(&truth)) {
                    Ok(outcome) => {
                        cost.finish_ms = ms_since(t0);
                        RowResult::Measured {
                            outcome: Box::new(outcome),
                            cost,
                        }
                    }
                    Err(e) => match not_applicable(&e) {
                        Some(reason) => RowResult::Skipped { reason },
                        None => return Err(fail(technique, pipeline, e)),
                    },
                }
            }
        };
        rows.push(Row {
            technique,
            pipeline,
            backend: spec.backend,
            result,
        });
        step(format!(
            "judged {} ({})",
            technique.name,
            pipeline_name(pipeline)
        ));
    }

    Ok(Comparison {
        scene,
        truth,
        truth_ms,
        rows,
        frames,
        total_ms: ms_since(start),
    })
}
