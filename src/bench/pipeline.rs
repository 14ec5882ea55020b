//! The same Command sequence — one frame of the default scene's `none` plan — through the
//! emulated and the native pipeline in one run, interleaved frame by frame so that machine
//! noise hits both alike. Reported per path: frame time (execute + glFinish), submit time
//! per draw (the CPU side: `execute` before glFinish, divided by the draws), programs
//! compiled in all and after the first frame, state calls sent and skipped.

use crate::vocab::{DepthBits, PipelineKind};
use std::time::Instant;

use serde::Serialize;

use crate::ff::Command;
use crate::gpu::{Backend, ContextRequest, GpuContext, RenderTarget, TargetSpec};
use crate::pipeline::{self, Counters, Pipeline, PipelineError};
use crate::scene::Scene;
use crate::stats::Summary;
use crate::techniques::{self, Prepared};

/// One path's figures.
#[derive(Clone, Debug, Serialize)]
pub struct PipelineTiming {
    pub pipeline: PipelineKind,
    pub backend: Backend,
    pub frame_ms: Summary,
    pub submit_us_per_draw: Summary,
    pub programs_compiled: u64,
    pub programs_after_first_frame: u64,
    pub counters: Counters,
}

/// Why the benchmark could not run.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    #[error(transparent)]
    Pipeline(#[from] PipelineError),
    #[error(transparent)]
    Gpu(#[from] crate::gpu::GpuError),
    #[error(transparent)]
    Technique(#[from] techniques::TechniqueError),
    #[error("no samples")]
    NoSamples,
    #[error("bench abi: {0}")]
    Abi(#[from] super::abi::AbiError),
}

struct Path {
    kind: PipelineKind,
    ctx: GpuContext,
    _target: RenderTarget,
    pipeline: Box<dyn Pipeline>,
    frame_ms: Vec<f64>,
    submit_us: Vec<f64>,
    after_first: u64,
}

/// Runs `frames` interleaved frames on each path; `progress` is called after each frame.
pub fn measure(
    backend: Backend,
    frames: usize,
    mut progress: impl FnMut(),
) -> Result<Vec<PipelineTiming>, BenchError> {
    let scene = Scene::default_scene();
    let prepared = Prepared::new(&scene);
    let plan = techniques::none::plan(&scene, &prepared)?;
    let commands: Vec<Command> = plan.frame_commands().cloned().collect();
    let draws = commands
        .iter()
        .filter(|c| matches!(c, Command::Draw(_)))
        .count()
        .max(1) as f64;
    let mut paths = Vec::new();
    for kind in [PipelineKind::Emulate, PipelineKind::Native] {
        let ctx = GpuContext::new(&ContextRequest::new(
            backend,
            crate::pipeline::profile(kind),
        ))?;
        let spec = TargetSpec::new(scene.image.width, scene.image.height, DepthBits::D24);
        let target = RenderTarget::new(&ctx, spec.with_stencil())?;
        let pipeline = pipeline::create(kind, &ctx)?;
        paths.push(Path {
            kind,
            ctx,
            _target: target,
            pipeline,
            frame_ms: Vec::new(),
            submit_us: Vec::new(),
            after_first: 0,
        });
    }
    for frame in 0..frames.max(2) {
        for p in &mut paths {
            p.ctx.make_current()?;
            let t0 = Instant::now();
            p.pipeline.execute(&p.ctx, &commands)?;
            let t1 = Instant::now();
            p.ctx.finish();
            let t2 = Instant::now();
            p.frame_ms.push((t2 - t0).as_secs_f64() * 1e3);
            p.submit_us.push((t1 - t0).as_secs_f64() * 1e6 / draws);
            if frame == 0 {
                p.after_first = p.pipeline.counters().programs_compiled;
            }
            progress();
        }
    }
    paths
        .into_iter()
        .map(|mut p| {
            let counters = p.pipeline.counters();
            p.pipeline.release(&p.ctx);
            Ok(PipelineTiming {
                pipeline: p.kind,
                backend,
                // The first frame compiles and uploads: it is left out of the medians.
                frame_ms: Summary::of(&p.frame_ms[1..]).ok_or(BenchError::NoSamples)?,
                submit_us_per_draw: Summary::of(&p.submit_us[1..]).ok_or(BenchError::NoSamples)?,
                programs_compiled: counters.programs_compiled,
                programs_after_first_frame: counters.programs_compiled - p.after_first,
                counters,
            })
        })
        .collect()
}
