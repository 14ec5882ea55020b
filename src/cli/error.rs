//! The CLI's error type: what a command reports before exiting with failure.

use fixedfunc::ff::script::ScriptError;
use fixedfunc::gpu::{Backend, GpuError};
use fixedfunc::pipeline::PipelineError;

#[derive(Debug, thiserror::Error)]
pub enum CliError {
    #[error(transparent)]
    Gpu(#[from] GpuError),
    #[error(transparent)]
    Pipeline(#[from] PipelineError),
    #[error("the {backend} backend does not work here:\n{reasons}")]
    BackendUnavailable { backend: Backend, reasons: String },
    #[error("cannot write JSON: {0}")]
    Json(#[from] serde_json::Error),
    #[error("{path}: {source}")]
    Script { path: String, source: ScriptError },
    #[error("cannot read {path}: {reason}")]
    Read { path: String, reason: String },
    #[error("cannot write {path}: {reason}")]
    Write { path: String, reason: String },
    #[error("--size {given}: expected WIDTHxHEIGHT with both sides from 1 to 16384, e.g. 512x512")]
    Size { given: String },
}
