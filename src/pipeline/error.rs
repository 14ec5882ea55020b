//! The pipeline layer's errors. A shader error carries the evidence: the stage, the key that
//! produced the program (as text), the generated source and the driver's log.

use crate::gpu::GpuError;

/// Which shader stage failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShaderStage {
    Vertex,
    Fragment,
    /// The link step of the program.
    Link,
}

/// A generated program that the driver refused.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{stage:?} shader failed for key {key}:\n{log}\n--- generated GLSL ---\n{glsl}")]
pub struct ShaderError {
    pub stage: ShaderStage,
    pub key: String,
    /// The generated GLSL (thiserror reserves the name `source`).
    pub glsl: String,
    pub log: String,
}

/// Everything that can stop a Command list from executing.
#[derive(Debug, thiserror::Error)]
pub enum PipelineError {
    #[error(transparent)]
    Shader(#[from] ShaderError),
    #[error(transparent)]
    Gpu(#[from] GpuError),
    /// The native path needs a compatibility context, the emulated one a core context.
    #[error("the {path} pipeline needs a {needs} context, got {got}")]
    WrongProfile {
        path: &'static str,
        needs: &'static str,
        got: &'static str,
    },
    /// A feature the path cannot execute faithfully (e.g. NV_register_combiners on the
    /// native path: Mesa no longer has it). Refused rather than drawn some other way.
    #[error("{what} is not supported by the {path} pipeline")]
    Unsupported {
        what: &'static str,
        path: &'static str,
    },
    /// The native path's glAccum needs a window with an accumulation buffer (Mesa gives
    /// framebuffer objects none): only OSMesa's own buffer has one.
    #[error("the native pipeline has no accumulation buffer on the {backend} backend: its framebuffers are objects, which Mesa gives none; run it with --backend osmesa, whose window buffer has one")]
    NoAccumBuffer { backend: crate::gpu::Backend },
    /// glTexImage named a readback buffer no ReadPixels has filled.
    #[error("glTexImage reads readback_{slot}, which no glReadPixels has filled")]
    MissingReadback { slot: u32 },
    /// A converted depth readback names a slot that does not hold FLOAT depth (or asks
    /// for a type other than UNSIGNED_BYTE / UNSIGNED_SHORT).
    #[error("readback_{slot} is not FLOAT depth, or the conversion is not to UNSIGNED_BYTE or UNSIGNED_SHORT")]
    NotFloatDepth { slot: u32 },
    /// A plan's shader program (`ff::program`) on the native path.
    #[error("shader programs run on the emulate pipeline; Mesa's fixed function has none (use --pipeline emulate)")]
    ShaderPrograms,
    /// glUniform with no program in use (GL's INVALID_OPERATION), refused.
    #[error("glUniform of `{name}` with no shader program in use")]
    UniformWithoutProgram { name: String },
    /// A GL object could not be created.
    #[error("GL object creation failed: {0}")]
    Object(String),
}
