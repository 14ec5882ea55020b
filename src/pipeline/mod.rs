//! Executes fixed-function Commands on a GL context, by one of two interchangeable paths:
//! `native` (real legacy GL calls on a compatibility context, the oracle) and, on a core 3.3
//! context, the emulated path (generated GLSL keyed by state).

pub mod native;
