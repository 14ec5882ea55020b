//! `fixedfunc replay FILE`: runs a script of GL 1.x calls on either pipeline and writes the
//! image it leaves in the colour buffer.

use fixedfunc::vocab::{DepthBits, PipelineKind};
use std::path::Path;

use fixedfunc::gpu::{
    Backend, ContextRequest, GpuContext, RenderTarget, TargetSpec, VirtualDisplay, WindowBuffer,
};
use fixedfunc::pipeline;

use super::error::CliError;
use super::script_io;
use fixedfunc::render::ImageSize;

pub fn run(
    file: &Path,
    kind: PipelineKind,
    backend: Backend,
    size: ImageSize,
    out: &Path,
    accum: bool,
) -> Result<(), CliError> {
    let commands = script_io::load_lines(file)?;
    super::scene_arg::check_png_outputs(&[("--out", out)])?;
    let _display = if backend == Backend::Window {
        VirtualDisplay::start_if_needed()?
    } else {
        None
    };
    // The native path's accumulation buffer is OSMesa's window buffer (framebuffer 0):
    // Mesa gives framebuffer objects none.
    let window = accum && kind == PipelineKind::Native;
    if window && backend != Backend::OsMesa {
        return Err(pipeline::PipelineError::NoAccumBuffer { backend }.into());
    }
    let mut request = ContextRequest::new(backend, fixedfunc::pipeline::profile(kind));
    if window {
        request = request.with_window(WindowBuffer {
            width: size.width,
            height: size.height,
        });
    }
    let ctx = GpuContext::new(&request)?;
    let target = match window {
        true => None,
        false => Some(RenderTarget::new(
            &ctx,
            TargetSpec::new(size.width, size.height, DepthBits::D24).with_stencil(),
        )?),
    };
    let mut p: Box<dyn pipeline::Pipeline> = match (accum, kind) {
        (false, _) => pipeline::create(kind, &ctx)?,
        (true, PipelineKind::Emulate) => {
            let mut e = pipeline::emulate::EmulatedPipeline::new(&ctx)?;
            e.set_accum_buffer(Some((size.width as usize, size.height as usize)));
            Box::new(e)
        }
        (true, PipelineKind::Native) => {
            Box::new(pipeline::native::NativePipeline::with_window_accum(&ctx)?)
        }
    };
    // One command at a time, so a GL error names the script line that raised it (GL keeps
    // only the first error until glGetError; a script has no glGetError, so each is read
    // and reported as it happens).
    let mut errors = 0usize;
    for (line, cmd) in &commands {
        p.execute(&ctx, std::slice::from_ref(cmd))?;
        if let Some(e) = p.take_gl_error() {
            errors += 1;
            eprintln!("{}:{line}: {}: {e}", file.display(), cmd.entry().name());
        }
    }
    let image = match &target {
        Some(t) => t.read_color(&ctx)?,
        None => ctx.read_window_color(size.width, size.height)?,
    };
    super::scene_arg::save(&image, out)?;
    let c = p.counters();
    outln!(
        "replay {}: {} commands, {} draws, {} programs compiled, {} state calls sent / {} skipped → {}",
        file.display(),
        c.commands,
        c.draws,
        c.programs_compiled,
        c.state_calls_sent,
        c.state_calls_skipped,
        out.display()
    )?;
    if errors > 0 {
        eprintln!("{errors} GL error(s) recorded (each named above with its line)");
    }
    p.release(&ctx);
    Ok(())
}
