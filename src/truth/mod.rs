//! The `truth` layer (see DESIGN in the README).
