//! The `scene` layer (see DESIGN in the README).
