//! Contexts and render targets.
