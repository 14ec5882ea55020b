//! Rendering a scene with one technique on one pipeline and backend, and judging it: the
//! library half of `fixedfunc render` (no printing, no files, no exit codes).
//!
//! [`render`] does, in order:
//! 1. applies the options' overrides (image size, technique) to a copy of the scene;
//! 2. prepares the geometry once (`techniques::Prepared`) and builds the technique's plan
//!    once;
//! 3. creates a context of the pipeline's profile on the backend (a private Xvfb for the
//!    window backend when no display is set), a target of the image size (RGBA8, D24 + 8
//!    stencil) and the pipeline (`pipeline::create`, the only code naming a concrete path);
//! 4. runs the plan's passes `frames` times; each frame is timed from its first command to
//!    glFinish returning, so the driver's work is inside the figure. Frame 1 is *cold*
//!    (programs compiled, buffers uploaded); frames 2…N are *steady*;
//! 5. executes the mask plan, decodes the mask, reads the colour image, takes the counters;
//! 6. ray-casts the truth (CPU) and compares the mask with it (`metrics::compare` with an
//!    edge band of `band` pixels).
//!
//! A command the GL model rejects is a bug in the technique, not a driver problem: the
//! frame stops with [`RenderError::Gl`] naming the pass.

mod figures;
mod size;

pub use figures::Figures;
pub use size::{ImageSize, SizeProblem, MAX_IMAGE_SIZE};

use std::time::Instant;

use image::RgbaImage;

use crate::bench::Summary;
use crate::ff::GlError;
use crate::gpu::{
    Backend, ContextRequest, DepthBits, GpuContext, GpuError, RenderTarget, TargetSpec,
    VirtualDisplay,
};
use crate::metrics::{self, Mask, Metrics, MetricsError};
use crate::pipeline::{Counters, Pipeline, PipelineError, PipelineKind};
use crate::scene::Scene;
use crate::techniques::{self, Plan, Prepared, TechniqueError};
use crate::truth::{self, Truth, TruthError, TruthOptions};

/// Failures of the render layer.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    #[error(transparent)]
    Technique(#[from] TechniqueError),
    #[error(transparent)]
    Gpu(#[from] GpuError),
    #[error(transparent)]
    Pipeline(#[from] PipelineError),
    #[error("pass `{pass}` of frame {frame}: the GL model rejected a command: {error}")]
    Gl {
        pass: &'static str,
        frame: u32,
        error: GlError,
    },
    #[error(transparent)]
    Truth(#[from] TruthError),
    #[error(transparent)]
    Metrics(#[from] MetricsError),
    #[error("image size `{text}`: {problem}")]
    Size { text: String, problem: SizeProblem },
}

/// The name the CLI uses for a pipeline path.
pub fn pipeline_name(kind: PipelineKind) -> &'static str {
    match kind {
        PipelineKind::Emulate => "emulate",
        PipelineKind::Native => "native",
    }
}

/// What to render and how.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    pub backend: Backend,
    pub pipeline: PipelineKind,
    /// Replaces the scene's `[shadow] technique`.
    pub technique: Option<String>,
    /// Replaces the scene's `[image]` width and height.
    pub size: Option<ImageSize>,
    /// Frames rendered and timed (at least 1).
    pub frames: u32,
    /// Which light the truth judges, and area-light samples.
    pub truth: TruthOptions,
    /// Half-width k of the edge band the metrics exclude in `outside_band`.
    pub band: u32,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            backend: Backend::Egl,
            pipeline: PipelineKind::Emulate,
            technique: None,
            size: None,
            frames: 1,
            truth: TruthOptions::default(),
            band: 1,
        }
    }
}

/// Where a render is, for progress displays.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Progress {
    /// `done` of `total` frames rendered.
    Frame { done: u32, total: u32 },
    /// The ground truth is being ray-cast.
    Truth,
}

/// Per-frame wall times in milliseconds.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameTimings {
    /// Every frame, in order.
    pub frames_ms: Vec<f64>,
    /// The first frame (programs compiled, geometry uploaded).
    pub cold_ms: f64,
    /// Frames 2…N; `None` with one frame.
    pub steady: Option<Summary>,
}

impl FrameTimings {
    /// The first frame's time and the later frames' times.
    pub fn new(cold_ms: f64, steady_ms: Vec<f64>) -> FrameTimings {
        let steady = Summary::of(&steady_ms);
        let mut frames_ms = vec![cold_ms];
        frames_ms.extend(steady_ms);
        FrameTimings {
            frames_ms,
            cold_ms,
            steady,
        }
    }

    /// The figure a report shows: the steady median, or the cold frame when it is alone.
    pub fn typical_ms(&self) -> f64 {
        self.steady.map_or(self.cold_ms, |s| s.median)
    }
}

/// Everything a render produced.
#[derive(Debug, Clone)]
pub struct RenderOutcome {
    pub technique: &'static str,
    pub pipeline: PipelineKind,
    pub backend: Backend,
    /// How the context was obtained (e.g. the EGL platform).
    pub context_path: String,
    /// The colour image of the last frame, top row first.
    pub image: RgbaImage,
    /// The technique's shadow mask.
    pub mask: Mask,
    pub truth: Truth,
    pub metrics: Metrics,
    pub timings: FrameTimings,
    /// Passes per frame.
    pub passes: usize,
    /// The pipeline's counters after every frame and the mask readback.
    pub counters: Counters,
}

impl RenderOutcome {
    /// The one-line summary.
    pub fn figures(&self) -> Figures {
        Figures {
            technique: self.technique,
            pipeline: self.pipeline,
            backend: self.backend,
            wrong_percent: self.metrics.all.wrong_percent,
            false_shadow: self.metrics.all.false_shadow,
            missed_shadow: self.metrics.all.missed_shadow,
            timings: self.timings.clone(),
            passes: self.passes,
            programs: self.counters.programs_compiled,
        }
    }
}

/// `scene` with the options' size and technique applied.
pub fn apply_overrides(scene: &Scene, size: Option<ImageSize>, technique: Option<&str>) -> Scene {
    let mut scene = scene.clone();
    if let Some(size) = size {
        scene.image.width = size.width;
        scene.image.height = size.height;
    }
    if let Some(name) = technique {
        scene.shadow.technique = name.to_string();
    }
    scene
}

/// Renders `scene` as `options` say and judges the mask against the truth.
pub fn render(scene: &Scene, options: &RenderOptions) -> Result<RenderOutcome, RenderError> {
    render_with_progress(scene, options, |_| {})
}

/// [`render`], calling `progress` after each frame and before the truth.
pub fn render_with_progress(
    scene: &Scene,
    options: &RenderOptions,
    mut progress: impl FnMut(Progress),
) -> Result<RenderOutcome, RenderError> {
    let scene = apply_overrides(scene, options.size, options.technique.as_deref());
    let technique = techniques::lookup(&scene.shadow.technique)?;
    let prepared = Prepared::new(&scene);
    let plan = (technique.plan)(&scene, &prepared)?;

    let _display = match options.backend {
        Backend::Window => VirtualDisplay::start_if_needed()?,
        Backend::Egl | Backend::OsMesa => None,
    };
    let ctx = GpuContext::new(&ContextRequest::new(
        options.backend,
        options.pipeline.profile(),
    ))?;
    let (width, height) = (scene.image.width, scene.image.height);
    let target = RenderTarget::new(
        &ctx,
        TargetSpec::new(width, height, DepthBits::D24).with_stencil(),
    )?;
    let mut pipeline = crate::pipeline::create(options.pipeline, &ctx)?;
    let gpu = run_gpu(
        &ctx,
        &target,
        pipeline.as_mut(),
        &plan,
        options,
        &mut progress,
    );
    pipeline.release(&ctx);
    target.delete(&ctx);
    let (image, mask, timings, counters) = gpu?;

    progress(Progress::Truth);
    let truth = truth::truth(&scene, &options.truth)?;
    let metrics = metrics::compare(&mask, &truth.mask, options.band)?;
    Ok(RenderOutcome {
        technique: technique.name,
        pipeline: options.pipeline,
        backend: options.backend,
        context_path: ctx.path().to_string(),
        image,
        mask,
        truth,
        metrics,
        timings,
        passes: plan.passes.len(),
        counters,
    })
}

type GpuResults = (RgbaImage, Mask, FrameTimings, Counters);

/// The frames, the mask and the colour readback.
fn run_gpu(
    ctx: &GpuContext,
    target: &RenderTarget,
    pipeline: &mut dyn Pipeline,
    plan: &Plan,
    options: &RenderOptions,
    progress: &mut impl FnMut(Progress),
) -> Result<GpuResults, RenderError> {
    let total = options.frames.max(1);
    target.bind(ctx);
    let mut frame = |n: u32| -> Result<f64, RenderError> {
        let start = Instant::now();
        for pass in &plan.passes {
            pipeline.execute(ctx, &pass.commands)?;
            if let Some(error) = pipeline.take_gl_error() {
                return Err(RenderError::Gl {
                    pass: pass.name,
                    frame: n,
                    error,
                });
            }
        }
        ctx.finish();
        let ms = start.elapsed().as_secs_f64() * 1e3;
        progress(Progress::Frame { done: n, total });
        Ok(ms)
    };
    let cold_ms = frame(1)?;
    let steady_ms = (2..=total).map(&mut frame).collect::<Result<Vec<_>, _>>()?;
    let timings = FrameTimings::new(cold_ms, steady_ms);

    pipeline.execute(ctx, &plan.mask.commands)?;
    if let Some(error) = pipeline.take_gl_error() {
        return Err(RenderError::Gl {
            pass: "mask",
            frame: total,
            error,
        });
    }
    let mask = plan.mask.decode(|slot| pipeline.readback(slot))?;
    let image = target.read_color(ctx)?;
    Ok((image, mask, timings, pipeline.counters()))
}
