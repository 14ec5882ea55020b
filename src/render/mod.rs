//! Rendering a scene with one technique on one pipeline and backend, and judging it: the
//! library half of `fixedfunc render` (no printing, no files, no exit codes).
//!
//! One responsibility per file:
//! - [`options`](RenderOptions): what a render is asked to do beyond the scene;
//! - [`motion`](Orbit): what moves from frame to frame (`--orbit`);
//! - [`session`](Session): one render held open — context, framebuffer, pipeline, plan —
//!   with frames on demand, so that a caller can hold several renders open and interleave
//!   their frames;
//! - [`rounds`]: that interleaving (frame k of every session before frame k + 1 of any),
//!   written once for the studies and the benchmarks;
//! - [`outcome`](RenderOutcome), [`figures`](Figures): what a render produced and its
//!   one-line summary; [`light_map`](LightMap): the light's map read back (its pictures
//!   are `report`'s); [`pass_images`]: what each pass of a frame leaves in the buffers.
//!
//! [`render`] is one session from start to end: `frames` frames, then the mask, the image,
//! the counters, the truth ray-cast on the CPU and the mask compared with it
//! (`metrics::compare` with an edge band of `band` pixels).
//!
//! **A truth that cannot judge is an error, not a score.** Before scoring, the geometry the
//! truth saw is checked against the render's: the pixels each marks as background (no
//! geometry) must agree but for at most [`COVERAGE_TOLERANCE`] of the pixels (samples on a
//! silhouette, which GL's rasteriser and the ray cast may tip either way). A truth whose
//! camera went wrong (an empty mask while the render shows the scene) used to score every
//! technique 0.00% and put it on the Pareto front; now it stops the run with both counts
//! ([`RenderError::CoverageMismatch`]).
//!
//! **Budgets.** [`Session::new`] refuses a run whose [`Footprint`] is over the scene's
//! memory budget, and an image larger than [`MAX_IMAGE_SIZE`], before it makes a context.
//!
//! A command the GL model rejects is a bug in the technique, not a driver problem: the
//! frame stops with [`RenderError::Gl`] naming the pass.

mod budget;
mod figures;
mod light_map;
mod motion;
mod objects;
mod options;
mod outcome;
pub mod pass_images;
pub mod rounds;
mod session;
mod size;
mod submission;

pub use budget::{
    Footprint, OverBudget, CAPTURE_BYTES_PER_PIXEL, OBJECT_BYTES, SESSION_BYTES,
    TRUTH_BYTES_PER_PIXEL,
};
pub use figures::{error_text, Figures};
pub use light_map::{LightMap, MapTexels};
pub use motion::{Orbit, OrbitTarget, Turn, MAX_ELEVATION};
pub use objects::{object_causes, object_line, object_lines, object_name, object_split};
pub use options::{apply_overrides, RemakeMaps, RenderOptions};
pub use outcome::{FrameTimings, PassTime, RenderOutcome, VisibilityOutcome, VisibilitySource};
pub use pass_images::{AlphaBeforeTest, Corner, PassImage, PassImages};
pub use session::Session;
pub use size::{ImageSize, SizeProblem, MAX_IMAGE_SIZE};

use crate::ff::{Command, GlError};
use crate::gpu::{GpuContext, GpuError};
use crate::metrics::{self, Mask, Metrics, MetricsError, VisibilityImage, BACKGROUND};
use crate::pipeline::{Pipeline, PipelineError};
use crate::scene::Scene;
use crate::techniques::TechniqueError;
use crate::truth::{Truth, TruthError};
use crate::vocab::PipelineKind;

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
    #[error("the light's map is {size}² texels; at most {max}² fit a framebuffer")]
    MapTooLarge { size: u32, max: u32 },
    #[error("the image is {width}x{height}; width and height must be at most {max}")]
    ImageTooLarge { width: u32, height: u32, max: u32 },
    #[error(transparent)]
    OverBudget(#[from] OverBudget),
    #[error(
        "the ground truth cannot judge this render: their geometry differs on {differ} of \
         {pixels} pixels (at most {allowed} edge pixels may): the technique's mask has \
         {mask_background} background pixels, the truth's {truth_background}; the truth's \
         camera or scene does not match the render's"
    )]
    CoverageMismatch {
        mask_background: usize,
        truth_background: usize,
        differ: usize,
        allowed: usize,
        pixels: usize,
    },
    #[error("the session's framebuffer was already released")]
    Released,
    #[error("the new shadow settings need another framebuffer (depth bits, stencil or size changed): start a new session")]
    Restage,
    #[error("a session moves only its light and camera: the objects, image size and shadow settings must stay those it was made with")]
    NotAMove,
    #[error("the depth-map readback is missing or malformed (slot {slot})")]
    MapImage { slot: u32 },
    #[error("image size `{text}`: {problem}")]
    Size { text: String, problem: SizeProblem },
    #[error("the native pipeline's accumulation buffer is OSMesa's window buffer, whose depth buffer has 24 bits: a {}-bit map cannot be made there; use depth_bits 24 (or the emulate pipeline)", .depth.bits())]
    WindowDepth { depth: crate::vocab::DepthBits },
    #[error("pass images read the render target's buffers, and the native pipeline accumulates in OSMesa's window buffer instead: picture the passes on the emulate pipeline")]
    WindowPassImages,
}

/// The name the CLI uses for a pipeline path.
pub fn pipeline_name(kind: PipelineKind) -> &'static str {
    match kind {
        PipelineKind::Emulate => "emulate",
        PipelineKind::Native => "native",
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
    let mut session = Session::new(scene, options)?;
    let total = options.frames.max(1);
    for done in 1..=total {
        session.frame()?;
        progress(Progress::Frame { done, total });
    }
    progress(Progress::Truth);
    session.finish(None)
}

/// The share of pixels on which a mask's and the truth's background may differ: 1%
/// (edge samples; `tests/render_pipeline.rs` measures the `none` technique's at well under
/// it on both paths and backends).
pub const COVERAGE_TOLERANCE: f64 = 0.01;

/// Scores `mask` against `truth` (`metrics::compare` with an edge band of `band`) once the
/// two agree on where the geometry is, else [`RenderError::CoverageMismatch`].
pub fn judge(mask: &Mask, truth: &Truth, band: u32) -> Result<Metrics, RenderError> {
    let metrics = metrics::compare(mask, &truth.mask, band)?;
    let background = |m: &Mask| m.data.iter().filter(|&&v| v == BACKGROUND).count();
    let differ = mask
        .data
        .iter()
        .zip(&truth.mask.data)
        .filter(|(m, t)| (**m == BACKGROUND) != (**t == BACKGROUND))
        .count();
    let pixels = mask.data.len();
    let allowed = (pixels as f64 * COVERAGE_TOLERANCE).floor() as usize;
    if differ > allowed {
        return Err(RenderError::CoverageMismatch {
            mask_background: background(mask),
            truth_background: background(&truth.mask),
            differ,
            allowed,
            pixels,
        });
    }
    Ok(metrics)
}

/// For an area-light truth, the technique's visibility — `soft` when its mask plan
/// accumulated one, else its hard mask as 0 or 1 — scored against the truth's
/// (`metrics::visibility_errors`); `None` for any other light.
pub fn judge_visibility(
    mask: &Mask,
    soft: Option<VisibilityImage>,
    truth: &Truth,
) -> Result<Option<VisibilityOutcome>, RenderError> {
    if truth.area.is_none() {
        return Ok(None);
    }
    let (image, source) = match soft {
        Some(v) => (v, VisibilitySource::Soft),
        None => (VisibilityImage::from_mask(mask), VisibilitySource::HardMask),
    };
    let errors = metrics::visibility_errors(&image, &truth.visibility, &truth.mask)?;
    Ok(Some(VisibilityOutcome {
        image,
        source,
        errors,
    }))
}

/// Executes one pass's commands; a command the model rejected is a technique bug.
fn run(
    pipeline: &mut dyn Pipeline,
    ctx: &GpuContext,
    pass: &'static str,
    frame: u32,
    commands: &[Command],
) -> Result<(), RenderError> {
    pipeline.execute(ctx, commands)?;
    match pipeline.take_gl_error() {
        Some(error) => Err(RenderError::Gl { pass, frame, error }),
        None => Ok(()),
    }
}
