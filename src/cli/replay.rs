//! `fixedfunc replay FILE`: runs a script of GL 1.x calls on either pipeline, or on both,
//! and writes the image it leaves in the colour buffer.
//!
//! Each GL error is reported with the script line that raised it (GL keeps only the first
//! error until glGetError; a script has no glGetError, so each is read as it happens);
//! `--strict` stops at the first, writes nothing and exits 1. `--pipeline both` runs the
//! script once per path, each on its own context, writes both images and the difference
//! picture of the emulated image against the native one, and prints the largest difference
//! and its pixel. `--expect` compares each image written with a reference (`expect`).

use fixedfunc::vocab::{DepthBits, Named, PipelineKind};
use std::path::{Path, PathBuf};

use fixedfunc::ff::Command;
use fixedfunc::gpu::{
    Backend, ContextRequest, GpuContext, PbufferSpec, RenderTarget, TargetSpec, VirtualDisplay,
    WindowBuffer,
};
use fixedfunc::metrics::image_diff::{self, Verdict};
use fixedfunc::pipeline;
use image::RgbaImage;

use super::error::CliError;
use super::expect::ExpectArgs;
use super::pipelines::PipelineChoice;
use super::scene_arg;
use super::script_io;
use fixedfunc::render::ImageSize;

/// Arguments of `replay`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The script.
    file: PathBuf,
    /// Which path runs it; `both` runs it on each (each on its own context), writes the
    /// native image as NAME-native.png and the difference picture of the two as
    /// NAME-paths.png, and prints the largest difference and its pixel.
    #[arg(long, value_enum, default_value = "emulate")]
    pipeline: PipelineChoice,
    #[arg(long, value_parser = super::named::named::<Backend>(), default_value = "egl")]
    backend: Backend,
    /// Target size, WIDTHxHEIGHT.
    #[arg(long, value_name = "WxH", default_value = "256x256", value_parser = scene_arg::parse_size)]
    size: ImageSize,
    /// The PNG to write.
    #[arg(long, default_value = "replay.png")]
    out: PathBuf,
    /// Give the window an accumulation buffer (the native path: with --backend
    /// osmesa only, drawing into OSMesa's own buffer, since Mesa gives framebuffer
    /// objects none).
    #[arg(long)]
    accum: bool,
    /// Stop at the first GL error the script raises, naming its line, write no image
    /// and exit 1 (without it each error is reported and the run goes on).
    #[arg(long)]
    strict: bool,
    #[command(flatten)]
    expect: ExpectArgs,
}

/// What one path's run left.
struct Replayed {
    image: RgbaImage,
    counters: pipeline::Counters,
    errors: usize,
}

pub fn run(args: Args) -> Result<(), CliError> {
    let commands = script_io::load_lines(&args.file)?;
    let kinds = args.pipeline.kinds();
    // Where each path's image goes: --out, or with both paths the native one beside it.
    let outs: Vec<(PipelineKind, PathBuf)> = kinds
        .iter()
        .map(|&k| match (k, kinds.len()) {
            (PipelineKind::Native, 2) => (k, scene_arg::beside(&args.out, "native")),
            _ => (k, args.out.clone()),
        })
        .collect();
    let paths_picture = (kinds.len() == 2).then(|| scene_arg::beside(&args.out, "paths"));
    let mut outputs: Vec<(&'static str, &Path)> = vec![("--out", args.out.as_path())];
    if let [_, (_, native)] = outs.as_slice() {
        outputs.push(("the native image", native.as_path()));
    }
    if let Some(p) = &paths_picture {
        outputs.push(("the paths' difference picture", p.as_path()));
    }
    let pictures: Vec<PathBuf> = outs
        .iter()
        .filter_map(|(_, o)| args.expect.picture_path(o))
        .collect();
    outputs.extend(
        pictures
            .iter()
            .map(|p| ("an --expect difference picture", p.as_path())),
    );
    scene_arg::check_png_outputs(&outputs)?;
    let _display = if args.backend == Backend::Window {
        VirtualDisplay::start_if_needed()?
    } else {
        None
    };
    let mut images = Vec::new();
    for (kind, out) in &outs {
        let r = replay_on(&args, *kind, &commands)?;
        scene_arg::save(&r.image, out)?;
        let c = r.counters;
        outln!(
            "replay {} ({}): {} commands, {} draws, {} programs compiled, {} state calls sent / {} skipped → {}",
            args.file.display(),
            kind.name(),
            c.commands,
            c.draws,
            c.programs_compiled,
            c.state_calls_sent,
            c.state_calls_skipped,
            out.display()
        )?;
        if r.errors > 0 {
            eprintln!(
                "{} GL error(s) recorded on {} (each named above with its line)",
                r.errors,
                kind.name()
            );
        }
        images.push(r.image);
    }
    if let ([emulated, native], Some(picture)) = (images.as_slice(), &paths_picture) {
        let verdict = Verdict::of(emulated, native, args.expect.tolerance)?;
        scene_arg::save(
            &image_diff::picture(emulated, native, args.expect.tolerance.per_channel),
            picture,
        )?;
        outln!("emulate against native: {verdict} → {}", picture.display())?;
    }
    let mut failure = None;
    for ((_, out), image) in outs.iter().zip(&images) {
        if let Err(e) = args.expect.check(image, out) {
            eprintln!("fixedfunc: {e}");
            failure.get_or_insert(e);
        }
    }
    failure.map_or(Ok(()), Err)
}

/// The script on one path, on a context of its own.
fn replay_on(
    args: &Args,
    kind: PipelineKind,
    commands: &[(usize, Command)],
) -> Result<Replayed, CliError> {
    let (backend, size) = (args.backend, args.size);
    // The native path's accumulation buffer is OSMesa's window buffer (framebuffer 0):
    // Mesa gives framebuffer objects none.
    let window = args.accum && kind == PipelineKind::Native;
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
        false => Some(script_target(&ctx, size)?),
    };
    let mut p: Box<dyn pipeline::Pipeline> = match (args.accum, kind) {
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
    let result = execute(args, kind, &ctx, p.as_mut(), commands).and_then(|errors| {
        let image = match &target {
            Some(t) => t.read_color(&ctx)?,
            None => ctx.read_window_color(size.width, size.height)?,
        };
        Ok(Replayed {
            image,
            counters: p.counters(),
            errors,
        })
    });
    p.release(&ctx);
    result
}

/// The buffer a script draws into: as a traced C program's (`abi`), a window-system
/// buffer of 24 depth and 8 stencil bits where the backend gives one (an EGL pbuffer), else
/// a framebuffer object of the same buffers. Mesa stores a window-system buffer top row
/// first and an object bottom row first, and what depends on that direction — the pixel a
/// line's end on a pixel centre lights, the footprint of an anisotropic sample — is then
/// as the traced program drew it.
fn script_target(ctx: &GpuContext, size: ImageSize) -> Result<RenderTarget, CliError> {
    let spec = TargetSpec::new(size.width, size.height, DepthBits::D24).with_stencil();
    let surface = PbufferSpec {
        width: size.width,
        height: size.height,
        alpha_bits: 8,
        depth_bits: 24,
        stencil_bits: 8,
    };
    Ok(match ctx.bind_window_surface(surface)? {
        true => RenderTarget::surface(ctx, spec)?,
        false => RenderTarget::new(ctx, spec)?,
    })
}

/// Runs the commands one at a time, so that a GL error names its line; the count of GL
/// errors, or under `--strict` the first as an error.
fn execute(
    args: &Args,
    kind: PipelineKind,
    ctx: &GpuContext,
    p: &mut dyn pipeline::Pipeline,
    commands: &[(usize, Command)],
) -> Result<usize, CliError> {
    let file = args.file.display();
    let mut errors = 0usize;
    for (line, cmd) in commands {
        p.execute(ctx, std::slice::from_ref(cmd))?;
        let Some(e) = p.take_gl_error() else { continue };
        if args.strict {
            return Err(CliError::StrictGlError {
                file: file.to_string(),
                kind: kind.name(),
                line: *line,
                entry: cmd.entry().name(),
                error: e.to_string(),
            });
        }
        errors += 1;
        eprintln!("{file}:{line}: {}: {e}", cmd.entry().name());
    }
    Ok(errors)
}
