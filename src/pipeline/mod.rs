//! Executes fixed-function Commands on a GL context, by one of two interchangeable paths:
//! `native` (real legacy GL calls on a compatibility context, the oracle) and `emulate`
//! (generated GLSL keyed by state, on a core 3.3 context).
//!
//! Both paths fold every Command into their own `ff::FixedState` (so GL's error semantics
//! are the model's, on either path), render into whatever framebuffer the caller bound (a
//! `gpu::RenderTarget`), keep the bytes of each `ReadPixels` in its slot, and count what
//! they did (`Counters`): the figures `render` and `bench` report.

pub mod core;
pub mod emulate;
pub mod error;
pub mod framebuffers;
pub mod native;
pub mod queries;

use std::borrow::Cow;
use std::collections::HashMap;

use serde::Serialize;

use crate::ff::{Command, FixedState, GlError, PixelFormat, PixelType, TexData, TexImage};
use crate::gpu::GpuContext;
use crate::gpu::{depth_to_u16, depth_to_u8};
use crate::vocab::{DepthRule, PipelineKind};

pub use error::{PipelineError, ShaderError, ShaderStage};

/// The context profile a path needs.
pub fn profile(kind: PipelineKind) -> crate::gpu::Profile {
    match kind {
        PipelineKind::Emulate => crate::gpu::Profile::Core33,
        PipelineKind::Native => crate::gpu::Profile::Compatibility,
    }
}

/// Creates the pipeline of `kind` on `ctx` (whose profile must be `profile(kind)`).
pub fn create(kind: PipelineKind, ctx: &GpuContext) -> Result<Box<dyn Pipeline>, PipelineError> {
    create_with(kind, ctx, crate::vocab::Precision::Float)
}

/// [`create`] with the emulated path computing in `precision` (the native path has only
/// the driver's own arithmetic and ignores it).
pub fn create_with(
    kind: PipelineKind,
    ctx: &GpuContext,
    precision: crate::vocab::Precision,
) -> Result<Box<dyn Pipeline>, PipelineError> {
    match kind {
        PipelineKind::Emulate => Ok(Box::new(
            emulate::EmulatedPipeline::new(ctx)?.with_precision(precision),
        )),
        PipelineKind::Native => Ok(Box::new(native::NativePipeline::new(ctx)?)),
    }
}

/// [`create_with`] for a plan that uses the accumulation buffer, `size` pixels of it:
/// the emulated path keeps Mesa's signed 16-bit values beside the context
/// (`emulate::accum`) and draws into the bound target; the native path needs framebuffer
/// 0 of an OSMesa context made with a `gpu::WindowBuffer` (Mesa gives framebuffer objects
/// none), and binds it — on any other context [`PipelineError::NoAccumBuffer`] names the
/// backend to use.
pub fn create_with_accumulation(
    kind: PipelineKind,
    ctx: &GpuContext,
    precision: crate::vocab::Precision,
    size: (u32, u32),
) -> Result<Box<dyn Pipeline>, PipelineError> {
    match kind {
        PipelineKind::Emulate => {
            let mut p = emulate::EmulatedPipeline::new(ctx)?.with_precision(precision);
            p.set_accum_buffer(Some((size.0 as usize, size.1 as usize)));
            Ok(Box::new(p))
        }
        PipelineKind::Native => Ok(Box::new(native::NativePipeline::with_window_accum(ctx)?)),
    }
}

/// The bytes one `ReadPixels` (or glGetTexImage) produced, packed with PACK_ALIGNMENT 1,
/// bottom row first.
#[derive(Clone, Debug, PartialEq)]
pub struct Readback {
    pub width: u32,
    pub height: u32,
    /// `Some(depth)` for a 3D level's glGetTexImage: `depth` images of `height` rows, the
    /// first (r = 0) first, which PACK_IMAGE_HEIGHT and PACK_SKIP_IMAGES lay out in a C
    /// program's memory; `None` for one rectangle.
    pub depth: Option<u32>,
    pub format: PixelFormat,
    pub ty: PixelType,
    pub bytes: Vec<u8>,
}

/// `cmd` with a `TexData::Readback` replaced by the bytes of its slot (what the era's
/// program passed to glTexImage2D was the buffer glReadPixels had filled). Every other
/// command is returned as it is, without a copy.
pub(crate) fn resolve_readback<'c>(
    cmd: &'c Command,
    readbacks: &HashMap<u32, Readback>,
) -> Result<Cow<'c, Command>, PipelineError> {
    match cmd {
        Command::TexImage(
            t @ TexImage {
                data: TexData::Readback(slot),
                ..
            },
        ) => {
            let r = readbacks
                .get(slot)
                .ok_or(PipelineError::MissingReadback { slot: *slot })?;
            Ok(Cow::Owned(Command::TexImage(TexImage {
                data: TexData::Bytes(r.bytes.as_slice().into()),
                ..t.clone()
            })))
        }
        Command::TexImage(
            t @ TexImage {
                data: TexData::ConvertedDepth { slot, ty, rule },
                ..
            },
        ) => {
            let r = readbacks
                .get(slot)
                .ok_or(PipelineError::MissingReadback { slot: *slot })?;
            let bytes =
                convert_depth(r, *ty, *rule).ok_or(PipelineError::NotFloatDepth { slot: *slot })?;
            Ok(Cow::Owned(Command::TexImage(TexImage {
                data: TexData::Bytes(bytes.into()),
                ..t.clone()
            })))
        }
        _ => Ok(Cow::Borrowed(cmd)),
    }
}

/// FLOAT depth bytes → one `ty` per value by `rule` (`gpu::readback`'s conversions, which
/// state and test the boundaries); `None` when the readback is not FLOAT depth or `ty` is
/// neither UNSIGNED_BYTE nor UNSIGNED_SHORT.
pub fn convert_depth(r: &Readback, ty: PixelType, rule: DepthRule) -> Option<Vec<u8>> {
    if (r.format, r.ty) != (PixelFormat::DepthComponent, PixelType::Float) {
        return None;
    }
    let depths = r
        .bytes
        .chunks_exact(4)
        .map(|b| f32::from_ne_bytes([b[0], b[1], b[2], b[3]]));
    match ty {
        PixelType::UnsignedByte => Some(depths.map(|z| depth_to_u8(z, rule)).collect()),
        PixelType::UnsignedShort => Some(
            depths
                .flat_map(|z| depth_to_u16(z, rule).to_ne_bytes())
                .collect(),
        ),
        _ => None,
    }
}

/// What a path did, for reports and for tests that assert "only what the scene asks for".
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Counters {
    /// Commands executed.
    pub commands: u64,
    /// Draw commands executed.
    pub draws: u64,
    /// Programs generated and compiled (emulate only; 0 on native).
    pub programs_compiled: u64,
    /// GL state calls sent to the driver by the state-sync layer.
    pub state_calls_sent: u64,
    /// GL state calls skipped because the driver already had that state.
    pub state_calls_skipped: u64,
    /// Texture images uploaded or copied (TexImage, TexSubImage, CopyTexImage).
    pub texture_uploads: u64,
    /// Draw geometries uploaded into GL buffers (emulate only; 0 on native).
    pub geometry_uploads: u64,
    /// Draws that repeated the draw before them under new matrices, its program and pass
    /// kept (emulate only; `emulate::repeat`).
    pub repeated_draws: u64,
}

/// One way of executing Commands. The context must be current and stay the same for the
/// life of the pipeline, and its GL state belongs to the pipeline: the emulated path keeps
/// a copy of what it last sent and skips calls GL already has, so a caller that changes GL
/// state behind it (`RenderTarget::bind` resets the viewport) must do so before creating
/// the pipeline.
pub trait Pipeline {
    fn kind(&self) -> PipelineKind;

    /// Executes the commands in order. A command the GL state model rejects records the
    /// error (see [`Pipeline::take_gl_error`]) and is otherwise skipped, as GL does; GPU or
    /// shader failures stop execution with `Err`.
    fn execute(&mut self, ctx: &GpuContext, commands: &[Command]) -> Result<(), PipelineError>;

    /// The bytes the last `ReadPixels` into `slot` produced.
    fn readback(&self, slot: u32) -> Option<&Readback>;

    /// The model state after the commands so far.
    fn state(&self) -> &FixedState;

    /// Reads and clears the first GL error recorded since the last call (glGetError).
    fn take_gl_error(&mut self) -> Option<GlError>;

    fn counters(&self) -> Counters;

    /// What glGetQueryObject* reads of query `id` (`queries`): its sample count, waiting
    /// for it, or whether it is ready; `None` for a query this path never began.
    fn query_result(&mut self, ctx: &GpuContext, id: u32, what: queries::QueryFetch)
        -> Option<u64>;

    /// Deletes every GL object the pipeline made (textures, buffers, programs).
    fn release(&mut self, ctx: &GpuContext);
}
