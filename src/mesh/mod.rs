//! The `mesh` layer (see DESIGN in the README).
