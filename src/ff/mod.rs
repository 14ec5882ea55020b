//! The `ff` layer (see DESIGN in the README).
