//! Studies: many renders of one scene, measured in one run and judged against one truth.
//! The library half of `fixedfunc compare` and `fixedfunc sweep-bias` (no printing, no
//! files; `report` turns a study into tables, plots and pages).
//!
//! - [`compare`]: every chosen technique × pipeline held open as a `render::Session` at
//!   once; their frames are interleaved round-robin by `render::rounds` (frame 1 of each,
//!   then frame 2 of each, …) so that machine noise — another build, a frequency step —
//!   hits all of them alike instead of whichever ran during it. The truth is ray-cast once and handed to
//!   every `Session::finish`, so each row's figures are exactly `render`'s.
//! - [`sweep`]: one session per depth format and pipeline (the depth format belongs to
//!   the framebuffer); each cell of the polygon-offset grid is `Session::restage` with the
//!   cell's offset, one frame (the maps are stale, so the map pass runs again with the new
//!   offset; the eye passes run because the comparison happens there), the mask passes,
//!   and `metrics::compare` against the truth computed once. Contexts, framebuffers and
//!   compiled programs are made once per session, not once per cell.
//!
//! **Not applicable is not a failure.** A combination the pipeline refuses
//! (`PipelineError::Unsupported`: register combiners on the native path) or the technique
//! refuses for these settings (`TechniqueError::NeedsStencil` with a 16-bit depth buffer,
//! `NoLight`, `NoAreaLight` for `accumulate` under a point light, a scene without the
//! shadow planes, flat receiver or F-35 a technique or program form needs; the native path's
//! missing accumulation buffer outside OSMesa, `PipelineError::NoAccumBuffer`, and its
//! window's fixed 24-bit depth, `RenderError::WindowDepth`) becomes a skipped entry
//! carrying the reason, and the study goes on. Any other error is a real failure and ends
//! the study.

pub mod compare;
pub mod range;
pub mod sweep;

pub use compare::{compare, CompareSpec, Comparison, PassStrips, Row, RowCost, RowResult};
pub use range::{RangeProblem, SweepRange};
pub use sweep::{
    best, edges, refine_round, sweep, sweep_with_pictures, Axis, Cell, Edge, Refine, Round, Shot,
    Surface, SurfaceResult, Sweep, SweepSpec, Verdict, FACTOR_FLOOR, MAX_ROUNDS, UNITS_FLOOR,
};

use crate::pipeline::PipelineError;
use crate::render::RenderError;
use crate::techniques::TechniqueError;
use crate::truth::TruthError;
use crate::vocab::TechniqueId;

/// Failures of a study.
#[derive(Debug, thiserror::Error)]
pub enum StudyError {
    #[error("`{technique}` on the {pipeline} pipeline: {source}")]
    Render {
        technique: TechniqueId,
        pipeline: &'static str,
        #[source]
        source: Box<RenderError>,
    },
    #[error(transparent)]
    Truth(#[from] TruthError),
    #[error(transparent)]
    OverBudget(#[from] crate::render::OverBudget),
    #[error(transparent)]
    Technique(#[from] TechniqueError),
    #[error("nothing to study: no technique or no pipeline was chosen")]
    Empty,
    /// A bias sweep of a technique whose passes read no polygon offset: every cell would
    /// render the same mask.
    #[error(
        "`{technique}` reads no polygon offset (it makes no depth map of the light to \
         offset), so every cell of the sweep would score the same mask; the techniques \
         that read one: {}",
        offset_techniques()
    )]
    NoOffset { technique: TechniqueId },
}

/// The techniques whose passes read the polygon offset, by name, comma-separated.
fn offset_techniques() -> String {
    use crate::vocab::Named;
    let names: Vec<&str> = TechniqueId::all()
        .into_iter()
        .filter(|t| t.uses_offset())
        .map(|t| t.name())
        .collect();
    names.join(", ")
}

/// Progress of a study, for progress bars and progress lines.
#[derive(Debug, Clone, PartialEq)]
pub struct Progress {
    /// Units of work done so far.
    pub done: u64,
    /// Units of work in the whole study.
    pub total: u64,
    /// What a unit is, plural: `cells` (a sweep), `steps` (a comparison).
    pub unit: &'static str,
    /// What was just finished.
    pub what: String,
}

/// The reason to skip a combination that does not apply, or `None` for a real failure.
pub fn not_applicable(error: &RenderError) -> Option<String> {
    match error {
        RenderError::Pipeline(
            e @ (PipelineError::Unsupported { .. }
            | PipelineError::NoAccumBuffer { .. }
            | PipelineError::ShaderPrograms),
        ) => Some(e.to_string()),
        RenderError::Technique(
            e @ (TechniqueError::NeedsStencil { .. }
            | TechniqueError::NoLight { .. }
            | TechniqueError::NoAreaLight { .. }
            | TechniqueError::NoShadowPlanes { .. }
            | TechniqueError::NoProjectionPlane { .. }
            | TechniqueError::TooManyFlatReceivers { .. }
            | TechniqueError::ColemanDoesNotFit { .. }),
        ) => Some(e.to_string()),
        e @ RenderError::WindowDepth { .. } => Some(e.to_string()),
        _ => None,
    }
}

/// Milliseconds since `start`.
fn ms_since(start: std::time::Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vocab::TechniqueId;

    /// A technique that cannot draw this scene is skipped with its reason; a broken scene
    /// (more lights than GL has) stays a failure.
    #[test]
    fn scene_misfits_are_skipped_and_other_errors_fail() {
        let misfit = RenderError::Technique(TechniqueError::NoProjectionPlane {
            technique: TechniqueId::Projective,
        });
        let reason = not_applicable(&misfit).unwrap_or_default();
        assert!(reason.contains("pseudo-depth"), "{reason}");
        let broken = RenderError::Technique(TechniqueError::TooManyLights { count: 9, max: 8 });
        assert_eq!(not_applicable(&broken), None);
    }
}
