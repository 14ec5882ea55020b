//! The CLI's error type: what a command reports before exiting with failure.

use fixedfunc::gpu::{Backend, GpuError};

#[derive(Debug, thiserror::Error)]
pub enum CliError {
    #[error(transparent)]
    Gpu(#[from] GpuError),
    #[error("the {backend} backend does not work here:\n{reasons}")]
    BackendUnavailable { backend: Backend, reasons: String },
    #[error("cannot write JSON: {0}")]
    Json(#[from] serde_json::Error),
}
