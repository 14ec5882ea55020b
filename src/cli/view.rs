//! `fixedfunc view`: the scene in a window with the viewer's keys (`fixedfunc::view`).
//! Starts a private Xvfb when no display is set, and says so; with `--frames N` the run is
//! deterministic (a key script's events at their frames, each frame judged) and ends by
//! writing what the window showed (`--out`) and printing the last status bar.

use std::path::PathBuf;

use fixedfunc::gpu::{Backend, VirtualDisplay};
use fixedfunc::render::ImageSize;
use fixedfunc::scene::Limits;
use fixedfunc::view::{self, KeyScript, ViewOptions, ViewSettings};
use fixedfunc::vocab::{PipelineKind, TechniqueId};

use super::error::CliError;
use super::pipelines::technique_parser;
use super::scene_arg;
use super::shadow_args::ShadowArgs;

/// Arguments of `view`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Scene file (TOML); the built-in default scene when omitted.
    pub scene: Option<PathBuf>,
    /// Technique to start with (default: the scene's).
    #[arg(long, value_parser = technique_parser())]
    pub technique: Option<TechniqueId>,
    /// Pipeline to start with (`n` switches).
    #[arg(long, value_parser = super::named::named::<PipelineKind>(), default_value = "emulate")]
    pub pipeline: PipelineKind,
    /// Where frames are rendered before the window shows them: egl or osmesa (the window
    /// itself is always a glutin window on X11).
    #[arg(long, value_parser = super::named::named::<Backend>(), default_value = "egl")]
    pub backend: Backend,
    /// Image size WxH (default: the scene's).
    #[arg(long, value_name = "WxH", value_parser = scene_arg::parse_size)]
    pub size: Option<ImageSize>,
    #[command(flatten)]
    pub shadow: ShadowArgs,
    /// Key and mouse events with the frame they arrive before (lines `FRAME key KEY
    /// [shift]` or `FRAME drag DX DY [shift]`); needs --frames.
    #[arg(long, value_name = "KEYS", requires = "frames")]
    pub script: Option<PathBuf>,
    /// Render exactly N frames (each waits for its truth), then stop.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub frames: Option<u32>,
    /// With --frames: write what the window showed last (PNG).
    #[arg(long, value_name = "FILE", requires = "frames")]
    pub out: Option<PathBuf>,
    /// Where `s` writes view-N.png.
    #[arg(long, value_name = "DIR", default_value = ".")]
    pub save_dir: PathBuf,
}

/// The keys, for `view --help`.
pub fn keys_help() -> String {
    let mut text = String::from("Keys:\n");
    for line in view::help_lines() {
        text += &line;
        text.push('\n');
    }
    text
}

pub fn run(args: Args, limits: Limits) -> Result<(), CliError> {
    if !cfg!(feature = "window") {
        return Err(fixedfunc::gpu::GpuError::NotCompiled {
            backend: Backend::Window,
            feature: "window",
        }
        .into());
    }
    if args.backend == Backend::Window {
        return Err(CliError::Usage(
            "view --backend names where frames are rendered (egl or osmesa); the view is \
             always shown in a window"
                .into(),
        ));
    }
    let mut scene = scene_arg::load(args.scene.as_deref(), limits)?;
    args.shadow.apply(&mut scene);
    if let Some(t) = args.technique {
        scene.shadow.technique = t;
    }
    if let Some(out) = &args.out {
        scene_arg::check_png_outputs(&[("--out", out.as_path())])?;
    }
    let script = match &args.script {
        Some(path) => {
            let text = std::fs::read_to_string(path).map_err(|e| CliError::Read {
                path: path.display().to_string(),
                reason: e.to_string(),
            })?;
            Some(
                KeyScript::parse(&text).map_err(|source| CliError::KeyScript {
                    path: path.display().to_string(),
                    source,
                })?,
            )
        }
        None => None,
    };
    let display = VirtualDisplay::start_if_needed()?;
    if let Some(d) = &display {
        eprintln!(
            "no display set: the window opens on a private Xvfb ({}), where no one sees it; \
             use --frames N --out FILE to keep what it shows",
            d.display()
        );
    }
    let options = ViewOptions {
        backend: args.backend,
        size: args.size,
        scene_path: args.scene.as_ref().map(|p| p.display().to_string()),
        script,
        frames: args.frames,
        save_dir: args.save_dir.clone(),
        truth: Default::default(),
        band: 1,
    };
    let settings = ViewSettings::of(&scene, args.pipeline);
    let mut said: Result<(), CliError> = Ok(());
    let end = view::run(&scene, settings, &options, &mut |line| {
        if said.is_ok() {
            said = outln!("{line}");
        }
    })?;
    said?;
    if let (Some(out), Some(shown)) = (&args.out, &end.shown) {
        scene_arg::save(shown, out)?;
        outln!("window {} ({} frames)", out.display(), end.frames)?;
    }
    if args.frames.is_some() {
        for line in &end.status {
            outln!("{line}")?;
        }
    }
    Ok(())
}
