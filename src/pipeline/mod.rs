//! Executes fixed-function Commands on a GL context, by one of two interchangeable paths:
//! `native` (real legacy GL calls on a compatibility context, the oracle) and `emulate`
//! (generated GLSL keyed by state, on a core 3.3 context).

pub mod emulate;
pub mod error;
pub mod native;

pub use error::{PipelineError, ShaderError, ShaderStage};
