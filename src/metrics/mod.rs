//! The `metrics` layer (see DESIGN in the README).
