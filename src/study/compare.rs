//! Every chosen technique × pipeline on one scene, frames interleaved, one truth.
//!
//! Order of work: the truth and, for a scene of several objects, its shadow causes by
//! object (CPU, timed together; each row's error by object is split from them), every
//! session's setup (context, framebuffer, programs of the setup commands), `frames` rounds
//! of one frame per live session, then each session's `finish` with the shared truth, and
//! for each measured row its pass images (`render::pass_images::capture`: the last frame
//! once more in a session of its own, opened after the measured one is released, so that
//! no measured figure counts the capture). The rounds are `render::rounds`; their rule
//! here: a session that turns out not to apply (see [`super::not_applicable`]) at setup or
//! at a frame leaves them and its row says why, any other failure ends the study.

use crate::vocab::{PipelineKind, TechniqueId};
use std::time::Instant;

use crate::gpu::Backend;
use crate::render::rounds::{self, Lane, Rules, Verdict};
use crate::render::{
    self, pass_images, pipeline_name, ImageSize, PassImages, RenderError, RenderOptions,
    RenderOutcome, Session,
};
use crate::scene::Scene;
use crate::truth::{self, Truth};

use super::{ms_since, not_applicable, Progress, StudyError};

/// What to compare.
#[derive(Debug, Clone)]
pub struct CompareSpec {
    pub techniques: Vec<TechniqueId>,
    pub pipelines: Vec<PipelineKind>,
    pub backend: Backend,
    /// Frames per session (frame 1 cold, 2…N steady), at least 1.
    pub frames: u32,
    /// Replaces the scene's image size.
    pub size: Option<ImageSize>,
    /// Whether each measured row's passes are pictured for the report's pass strip.
    pub passes: PassStrips,
}

/// Whether a comparison pictures every pass of each measured row (`compare --passes`): a
/// session more per row, and the pictures held until the report is written (counted in
/// the run's footprint).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum PassStrips {
    #[default]
    Without,
    With,
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
    /// The pass images' own session (`pass_images::capture`); not part of
    /// [`total_ms`](Self::total_ms), which is the measured session's.
    pub passes_ms: f64,
}

impl RowCost {
    /// The measured session's phases: setup, frames, finish.
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
        /// What each pass of the last frame left (the report's pass strip), when asked.
        passes: Option<Box<PassImages>>,
    },
    /// Does not apply here (the reason is the refusing layer's message).
    Skipped { reason: String },
}

/// One technique on one pipeline.
#[derive(Debug, Clone)]
pub struct Row {
    pub technique: TechniqueId,
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

    /// The pass images, when measured.
    pub fn pass_images(&self) -> Option<&PassImages> {
        match &self.result {
            RowResult::Measured { passes, .. } => passes.as_deref(),
            RowResult::Skipped { .. } => None,
        }
    }

    /// `technique-pipeline`, the stem of the row's files.
    pub fn slug(&self) -> String {
        format!("{}-{}", self.technique, pipeline_name(self.pipeline))
    }
}

/// A finished comparison.
#[derive(Debug, Clone)]
pub struct Comparison {
    /// The scene as rendered (size override applied).
    pub scene: Scene,
    pub truth: Truth,
    /// Wall time of the truth and of its shadow causes by object (ms).
    pub truth_ms: f64,
    /// Rows in the order technique-major, pipeline-minor.
    pub rows: Vec<Row>,
    pub frames: u32,
    /// Wall time of the whole study (ms).
    pub total_ms: f64,
}

/// What the study keeps beside each session in the rounds.
struct Entry {
    technique: TechniqueId,
    pipeline: PipelineKind,
    cost: RowCost,
}

/// The study's rules for the rounds: a combination that does not apply leaves them, any
/// other failure stops them; every turn is a progress step and adds to the row's cost.
struct CompareRules<F> {
    frames: u32,
    step: F,
}

impl<F: FnMut(String)> Rules<Entry> for CompareRules<F> {
    fn failed(&mut self, _: &Entry, error: &RenderError) -> Verdict {
        match not_applicable(error) {
            Some(_) => Verdict::Retire,
            None => Verdict::Stop,
        }
    }

    fn turn(&mut self, round: u32, entry: &mut Entry, ms: Option<f64>) {
        entry.cost.frames_ms += ms.unwrap_or(0.0);
        (self.step)(format!(
            "frame {round}/{} of {} ({})",
            self.frames,
            entry.technique,
            pipeline_name(entry.pipeline)
        ));
    }
}

/// The study's error for a combination that failed for real.
fn failure(technique: TechniqueId, pipeline: PipelineKind, source: RenderError) -> StudyError {
    StudyError::Render {
        technique,
        pipeline: pipeline_name(pipeline),
        source: Box::new(source),
    }
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
    let combos: Vec<(TechniqueId, PipelineKind)> = spec
        .techniques
        .iter()
        .flat_map(|t| spec.pipelines.iter().map(move |p| (*t, *p)))
        .collect();
    let n = combos.len() as u64;
    let total = 1 + n * (3 + u64::from(frames));
    let mut done = 0;
    let mut step = |what: String| {
        done += 1;
        progress(Progress {
            done,
            total,
            unit: "steps",
            what,
        });
    };

    let base = RenderOptions {
        backend: spec.backend,
        size: spec.size,
        frames,
        ..RenderOptions::default()
    };
    let scene = render::apply_overrides(scene, spec.size, None);
    // Every session is held open at once: refuse what will not fit before the first.
    let mut footprint = render::Footprint::of(&scene, combos.len());
    if spec.passes == PassStrips::With {
        footprint = footprint.with_pass_captures(&scene, combos.len());
    }
    footprint.check(&scene.limits)?;
    let truth_start = Instant::now();
    let truth = truth::truth(&scene, &base.truth)?;
    // Why each truth pixel is lit or shadowed, by object: traced once, every row's
    // per-object split is made from it.
    let causes = render::object_causes(&scene, base.truth.light, &truth.mask)?;
    let truth_ms = ms_since(truth_start);
    step("ground truth".to_string());

    let mut lanes = Vec::with_capacity(combos.len());
    for &(technique, pipeline) in &combos {
        let options = RenderOptions {
            pipeline,
            technique: Some(technique),
            ..base.clone()
        };
        let t0 = Instant::now();
        let session = match Session::new(&scene, &options) {
            Err(e) if not_applicable(&e).is_none() => return Err(failure(technique, pipeline, e)),
            result => result,
        };
        let setup_ms = ms_since(t0);
        lanes.push(Lane {
            tag: Entry {
                technique,
                pipeline,
                cost: RowCost {
                    setup_ms,
                    ..RowCost::default()
                },
            },
            session,
        });
        step(format!("set up {technique} ({})", pipeline_name(pipeline)));
    }

    let mut rules = CompareRules {
        frames,
        step: &mut step,
    };
    if let Err(stop) = rounds::run(&mut lanes, frames, &mut rules) {
        let entry = &lanes[stop.lane].tag;
        return Err(failure(entry.technique, entry.pipeline, stop.error));
    }

    let mut rows = Vec::with_capacity(lanes.len());
    for lane in lanes {
        let Entry {
            technique,
            pipeline,
            mut cost,
        } = lane.tag;
        let options = RenderOptions {
            pipeline,
            technique: Some(technique),
            ..base.clone()
        };
        let finished = lane.session.and_then(|session| {
            let t0 = Instant::now();
            let outcome = session.finish_with_causes(&truth, causes.as_ref());
            cost.finish_ms = ms_since(t0);
            outcome
        });
        let result = match finished {
            Ok(outcome) => {
                step(format!("judged {technique} ({})", pipeline_name(pipeline)));
                let passes = match spec.passes {
                    PassStrips::With => {
                        let t0 = Instant::now();
                        match pass_images::capture(&scene, &options) {
                            Ok(passes) => {
                                cost.passes_ms = ms_since(t0);
                                Some(Box::new(passes))
                            }
                            // The native path's accumulation runs in OSMesa's window, whose
                            // buffers the pictures cannot read: the row keeps no strip.
                            Err(RenderError::WindowPassImages) => None,
                            Err(e) => return Err(failure(technique, pipeline, e)),
                        }
                    }
                    PassStrips::Without => None,
                };
                RowResult::Measured {
                    outcome: Box::new(outcome),
                    cost,
                    passes,
                }
            }
            Err(e) => match not_applicable(&e) {
                Some(reason) => {
                    step(format!("judged {technique} ({})", pipeline_name(pipeline)));
                    RowResult::Skipped { reason }
                }
                None => return Err(failure(technique, pipeline, e)),
            },
        };
        let what = match &result {
            RowResult::Measured {
                passes: Some(_), ..
            } => "pictured the passes of",
            RowResult::Measured { passes: None, .. } => "finished",
            RowResult::Skipped { .. } => "no passes to picture for",
        };
        rows.push(Row {
            technique,
            pipeline,
            backend: spec.backend,
            result,
        });
        step(format!("{what} {technique} ({})", pipeline_name(pipeline)));
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
