//! How long a context takes to create, and to produce its first read-back frame (a 256×256
//! D24 target, a clear, one triangle from a freshly compiled program, a colour readback).

use crate::vocab::DepthBits;
use std::time::Instant;

use serde::Serialize;

use crate::gpu::{
    Backend, ContextRequest, FlatProgram, GpuContext, GpuError, Profile, RenderTarget, TargetSpec,
};
use crate::stats::Summary;

/// One backend × profile row.
#[derive(Clone, Debug, Serialize)]
pub struct ContextTiming {
    pub backend: Backend,
    pub profile: Profile,
    /// Milliseconds to create the context and make it current.
    pub create_ms: Summary,
    /// Milliseconds from a current context to the first frame read back.
    pub first_frame_ms: Summary,
}

/// Times `repeats` creations and first frames; `progress` is called after each repeat.
pub fn measure(
    backend: Backend,
    profile: Profile,
    repeats: usize,
    mut progress: impl FnMut(),
) -> Result<ContextTiming, GpuError> {
    let mut create = Vec::with_capacity(repeats);
    let mut first = Vec::with_capacity(repeats);
    for _ in 0..repeats.max(1) {
        let t0 = Instant::now();
        let ctx = GpuContext::new(&ContextRequest::new(backend, profile))?;
        let t1 = Instant::now();
        first_frame(&ctx)?;
        let t2 = Instant::now();
        create.push((t1 - t0).as_secs_f64() * 1e3);
        first.push((t2 - t1).as_secs_f64() * 1e3);
        drop(ctx);
        progress();
    }
    let summary = |v: &[f64]| Summary::of(v).ok_or(GpuError::Object("no timing samples".into()));
    Ok(ContextTiming {
        backend,
        profile,
        create_ms: summary(&create)?,
        first_frame_ms: summary(&first)?,
    })
}

fn first_frame(ctx: &GpuContext) -> Result<(), GpuError> {
    use glow::HasContext;
    let target = RenderTarget::new(ctx, TargetSpec::new(256, 256, DepthBits::D24))?;
    let flat = FlatProgram::new(ctx)?;
    unsafe {
        ctx.gl().clear_color(0.0, 0.0, 0.0, 1.0);
        ctx.gl()
            .clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
    }
    flat.draw(
        ctx,
        &[[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [0.0, 1.0, 0.0]],
        [1.0, 1.0, 1.0, 1.0],
    );
    let image = target.read_color(ctx)?;
    // The frame must really have been drawn: the centre is inside the triangle.
    if image.get_pixel(128, 128).0 != [255, 255, 255, 255] {
        return Err(GpuError::Object(
            "first frame has no triangle at its centre".into(),
        ));
    }
    flat.delete(ctx);
    target.delete(ctx);
    Ok(())
}
