//! The CLI's error type: what a command reports before exiting with failure.

use fixedfunc::ff::script::ScriptError;
use fixedfunc::gpu::{Backend, GpuError};
use fixedfunc::pipeline::PipelineError;
use std::path::PathBuf;

use fixedfunc::render::RenderError;
use fixedfunc::scene::SceneError;
use fixedfunc::truth::TruthError;

#[derive(Debug, thiserror::Error)]
pub enum CliError {
    #[error(transparent)]
    Gpu(#[from] GpuError),
    #[error(transparent)]
    Pipeline(#[from] PipelineError),
    #[error("the {backend} backend does not work here:\n{reasons}")]
    BackendUnavailable { backend: Backend, reasons: String },
    #[error(transparent)]
    Bench(#[from] fixedfunc::bench::pipeline::BenchError),
    #[error(transparent)]
    Coleman(#[from] fixedfunc::bench::coleman::ColemanError),
    #[error("cannot write JSON: {0}")]
    Json(#[from] serde_json::Error),
    #[error("{path}: {source}")]
    Script { path: String, source: ScriptError },
    #[error("cannot read {path}: {reason}")]
    Read { path: String, reason: String },
    /// Scene errors name the file, line and column, and the valid alternatives.
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error(transparent)]
    Render(#[from] RenderError),
    #[error(transparent)]
    Truth(#[from] TruthError),
    #[error(transparent)]
    Metrics(#[from] fixedfunc::metrics::MetricsError),
    #[error(transparent)]
    Study(#[from] fixedfunc::study::StudyError),
    #[error(transparent)]
    Report(#[from] fixedfunc::report::ReportError),
    #[error(transparent)]
    View(#[from] fixedfunc::view::ViewError),
    #[error("{path}: {source}")]
    KeyScript {
        path: String,
        source: fixedfunc::view::ScriptError,
    },
    #[error("{0}")]
    Usage(String),
    #[error("osmesa-dir: {0}")]
    Osmesa(String),
    #[error("cannot write to standard output: {0}")]
    Stdout(#[source] std::io::Error),
    /// `--expect`: the image differs from the reference beyond the tolerance.
    #[error(
        "the image differs from {}: {detail}{}",
        .reference.display(),
        .picture.as_ref().map_or(String::new(), |p| format!(" (difference picture: {})", p.display()))
    )]
    Expectation {
        reference: PathBuf,
        detail: String,
        picture: Option<PathBuf>,
    },
    /// `replay --strict`: the script raised a GL error.
    #[error(
        "{file}:{line}: {entry}: {error} (on the {kind} path; --strict stops at the first GL \
         error)"
    )]
    StrictGlError {
        file: String,
        kind: &'static str,
        line: usize,
        entry: &'static str,
        error: String,
    },
    #[error("{first} and {second} both name {path}: one file would overwrite the other")]
    SameFile {
        first: &'static str,
        second: String,
        path: PathBuf,
    },
}

impl CliError {
    /// The process's exit code for this error: 1 when the command ran and a check it was
    /// asked for failed (`--expect`, `replay --strict`), 2 for trouble — the command could
    /// not do what was asked (clap also exits 2 on a bad command line).
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Expectation { .. } | CliError::StrictGlError { .. } => 1,
            _ => 2,
        }
    }
}
