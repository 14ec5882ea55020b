//! The one place that names the concrete pipelines: everything else in `render` speaks to
//! the [`Pipeline`] trait, so adding or swapping a path touches this function only.

use crate::gpu::GpuContext;
use crate::pipeline::{Pipeline, PipelineKind};

use super::RenderError;

/// A pipeline of `kind` on `ctx` (which must have `kind.profile()` and be current).
///
/// No implementation of either path is built in yet: this returns
/// [`RenderError::PipelineMissing`] until the emulated and native paths land, when the body
/// becomes their two constructors.
pub fn make_pipeline(
    kind: PipelineKind,
    ctx: &GpuContext,
) -> Result<Box<dyn Pipeline>, RenderError> {
    let _ = ctx;
    Err(RenderError::PipelineMissing(kind))
}
