//! `fixedfunc view`: the scene in a window, rendered through the same [`Session`] as
//! `render`, with keys to change the technique and its bias and the error against the
//! truth on a status bar.
//!
//! One responsibility per file:
//! - [`keys`]: the key table (the help is generated from it);
//! - [`settings`]: what is rendered and shown, what each action changes and at what cost,
//!   and the `render` command that reproduces a view;
//! - [`script`]: key scripts, for deterministic runs and tests;
//! - [`compose`]: the picture shown — the view on top, a status bar below;
//! - [`threads`]: the window thread and the truth worker;
//! - [`viewer`]: the loop.
//!
//! The scene is rendered headless (EGL by default) and the picture is shown in a window of
//! its own (glutin + winit on X11), read back from the window's buffer after each frame:
//! what a screenshot holds is what the window showed.
//!
//! [`Session`]: crate::render::Session

pub mod compose;
pub mod keys;
pub mod script;
pub mod settings;
mod threads;
mod viewer;

pub use keys::{help_lines, Action, Binding, BINDINGS};
pub use script::{KeyScript, ScriptError};
pub use settings::{Change, Show, ViewSettings};
pub use viewer::{run, ViewEnd, ViewOptions};

use crate::gpu::GpuError;
use crate::render::RenderError;
use crate::report::ReportError;
use crate::truth::TruthError;

/// What stops the viewer.
#[derive(Debug, thiserror::Error)]
pub enum ViewError {
    #[error(transparent)]
    Gpu(#[from] GpuError),
    #[error(transparent)]
    Render(#[from] RenderError),
    #[error(transparent)]
    Report(#[from] ReportError),
    #[error(transparent)]
    Truth(#[from] TruthError),
    #[error("the truth worker stopped before the frame's truth arrived")]
    TruthWorkerGone,
    #[error("no frame was rendered")]
    NoFrame,
}
