//! The accumulation buffer (`ff::accum`, `pipeline::emulate::accum`) against Mesa's own
//! glAccum on the native path. Mesa gives framebuffer objects no accumulation buffer, so
//! the native side draws into OSMesa's window buffer (`gpu::WindowBuffer`: 16 accumulation
//! bits per channel) and the emulated side into a target with the layer's CPU buffer of
//! Mesa's signed 16-bit values. `tests/scripts/accum/ops.c` runs every operation — ACCUM,
//! LOAD, ADD, MULT, RETURN — with values out of range, negative weights and clamped clear
//! values, one per column; the images must be equal, alpha included. On EGL the native
//! path has no window with an accumulation buffer and says which backend to use.

mod support;

use std::path::Path;

use fixedfunc::ff::script;
use fixedfunc::gpu::{Backend, ContextRequest, GpuContext, Profile, WindowBuffer};
use fixedfunc::pipeline::emulate::EmulatedPipeline;
use fixedfunc::pipeline::native::NativePipeline;
use fixedfunc::pipeline::{Pipeline, PipelineError};
use fixedfunc::vocab::DepthBits;
use image::RgbaImage;
use support::Tolerance;

const W: u32 = 64;
const H: u32 = 32;

fn commands() -> Vec<fixedfunc::ff::Command> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/scripts/accum/ops.c");
    let text = std::fs::read_to_string(&path).expect("tests/scripts/accum/ops.c");
    script::parse(&text).unwrap_or_else(|e| panic!("{e}"))
}

fn run(p: &mut dyn Pipeline, ctx: &GpuContext, what: &str) {
    p.execute(ctx, &commands())
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    assert_eq!(p.take_gl_error(), None, "{what}: model GL error");
}

/// The emulated path on `backend`: a target and the CPU accumulation buffer.
fn emulated(backend: Backend) -> RgbaImage {
    let ctx = support::context(backend, Profile::Core33);
    let t = support::target(&ctx, W, H, DepthBits::D24, true);
    let mut p = EmulatedPipeline::new(&ctx).expect("emulated pipeline");
    p.set_accum_buffer(Some((W as usize, H as usize)));
    run(&mut p, &ctx, "emulate");
    let image = t.read_color(&ctx).expect("colour readback");
    support::assert_no_gl_error(&ctx);
    p.release(&ctx);
    t.delete(&ctx);
    image
}

/// Mesa's glAccum: the native path in OSMesa's window buffer.
fn native_osmesa() -> RgbaImage {
    let request =
        ContextRequest::new(Backend::OsMesa, Profile::Compatibility).with_window(WindowBuffer {
            width: W,
            height: H,
        });
    let ctx = GpuContext::new(&request).expect("an OSMesa window buffer with accumulation");
    let mut p = NativePipeline::with_window_accum(&ctx).expect("the window's accumulation");
    run(&mut p, &ctx, "native");
    let image = ctx.read_window_color(W, H).expect("window readback");
    support::assert_no_gl_error(&ctx);
    p.release(&ctx);
    image
}

#[test]
fn every_accum_op_matches_mesas_native_glaccum() {
    let native = native_osmesa();
    // Mesa's numbers, one pixel per column (row 16 from the top): the clamped clear value
    // returned (0.5, −0.25 → 0, 1.5 → 1, −2 → 0), ADD past the range wrapping, RETURN
    // through the colour mask.
    for (column, expected) in [
        (0u32, [127, 0, 255, 0]),
        (3, [0, 0, 0, 68]),
        (5, [177, 124, 128, 153]),
        (7, [0, 124, 223, 105]),
    ] {
        support::probe(&native, 8 * column + 4, 16, expected, 0);
    }
    let exact = Tolerance {
        per_channel: 0,
        max_bad_pixels: 0,
    };
    for backend in support::HEADLESS {
        support::assert_images_match(
            &format!("accum-ops-{backend}"),
            &emulated(backend),
            &native,
            exact,
        );
    }
}

#[test]
fn the_native_path_on_egl_names_the_backend_with_an_accumulation_buffer() {
    let ctx = support::context(Backend::Egl, Profile::Compatibility);
    let err = match NativePipeline::with_window_accum(&ctx) {
        Ok(_) => panic!("EGL surfaceless gave the native path an accumulation buffer"),
        Err(e) => e,
    };
    assert!(
        matches!(
            err,
            PipelineError::NoAccumBuffer {
                backend: Backend::Egl
            }
        ),
        "{err}"
    );
    assert!(err.to_string().contains("--backend osmesa"), "{err}");
    // Nor can an EGL context be asked for a window buffer.
    let request =
        ContextRequest::new(Backend::Egl, Profile::Compatibility).with_window(WindowBuffer {
            width: W,
            height: H,
        });
    let refused = GpuContext::new(&request).err().map(|e| e.to_string());
    assert!(
        refused
            .as_deref()
            .is_some_and(|e| e.contains("--backend osmesa")),
        "{refused:?}"
    );
}
