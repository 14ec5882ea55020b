//! The command line: argument parsing (clap) and the user-facing output of each command.
//! Errors from the layers below arrive here and become a message and an exit code; nothing
//! below this module exits the process.

/// `print!` that returns a failed write as an error (see `output`).
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::cli::output::write(format_args!($($arg)*), false)
    };
}

/// `println!` that returns a failed write as an error (see `output`).
macro_rules! outln {
    () => {
        $crate::cli::output::write(format_args!(""), true)
    };
    ($($arg:tt)*) => {
        $crate::cli::output::write(format_args!($($arg)*), true)
    };
}

mod bench;
mod compare;
mod error;
mod expect;
mod explain;
mod info;
mod named;
mod osmesa_dir;
mod output;
mod pipelines;
mod progress;
mod render;
mod replay;
mod scene_arg;
mod script_io;
mod shaders;
mod shadow_args;
pub mod signals;
mod sweep_bias;
mod truth;
mod view;

use fixedfunc::vocab::{PipelineKind, TechniqueId};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use fixedfunc::bench::BenchGroup;
use fixedfunc::gpu::Backend;
use fixedfunc::render::{ImageSize, RemakeMaps};

/// An emulator of the OpenGL 1.x fixed-function pipeline for the classic shadow techniques.
#[derive(Parser)]
#[command(
    name = "fixedfunc",
    version,
    about,
    after_help = "Exit status: 0 when the command did what was asked and every check passed; \
                  1 when a check it was asked for failed (--expect: the image differs beyond \
                  the tolerance; replay --strict: the script raised a GL error); 2 for \
                  trouble (a bad command line, an unreadable or malformed input, a missing \
                  system library, a GL failure, a write that failed)."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    #[command(flatten)]
    limits: scene_arg::LimitArgs,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene, write its image and shadow mask, print one line of figures: technique,
    /// pipeline, backend, error against the ground truth, ms per frame, passes, programs.
    Render {
        /// Scene file (TOML); the built-in default scene when omitted.
        scene: Option<PathBuf>,
        /// Technique (default: the scene's `[shadow] technique`).
        #[arg(long, value_parser = pipelines::technique_parser())]
        technique: Option<TechniqueId>,
        /// Which path executes the fixed-function commands.
        #[arg(long, value_parser = named::named::<PipelineKind>(), default_value = "emulate")]
        pipeline: PipelineKind,
        #[arg(long, value_parser = named::named::<Backend>(), default_value = "egl")]
        backend: Backend,
        /// Image size WxH (default: the scene's).
        #[arg(long, value_name = "WxH", value_parser = scene_arg::parse_size)]
        size: Option<ImageSize>,
        /// Where the colour image goes (PNG).
        #[arg(long, default_value = "render.png")]
        out: PathBuf,
        /// Where the shadow mask goes (PNG: 255 lit, 0 shadowed, 128 background).
        #[arg(long, default_value = "render-mask.png")]
        mask: PathBuf,
        /// Frames rendered and timed; the figure is the median of frames 2…N.
        #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=100_000))]
        frames: u32,
        #[command(flatten)]
        shadow: shadow_args::ShadowArgs,
        /// When shadow maps are made again after the first frame.
        #[arg(long, value_parser = named::named::<RemakeMaps>(), default_value = "when-moved")]
        remake_maps: RemakeMaps,
        /// Also write the light's map (PNG; for multidigit16 the two digits, as
        /// NAME-big-digit.png and NAME-little-digit.png).
        #[arg(long, value_name = "FILE")]
        depth_map: Option<PathBuf>,
        /// Move something each frame: camera:DEG or light:DEG turns the camera's or the
        /// light's eye about the vertical through what it looks at. Maps are made again
        /// only when the light moved (unless --remake-maps always).
        #[arg(long, value_name = "WHAT:DEGREES")]
        orbit: Option<fixedfunc::render::Orbit>,
        /// Place the light or the camera before frame 1: light:AZ[,EL] or camera:AZ[,EL]
        /// turns its eye by EL degrees of elevation (kept within ±85°) then AZ degrees
        /// about the vertical through what it looks at (repeatable; `view`'s `p` prints
        /// these).
        #[arg(long = "turn", value_name = "WHAT:AZ[,EL]", allow_hyphen_values = true)]
        turns: Vec<fixedfunc::render::Turn>,
        #[command(flatten)]
        expect: expect::ExpectArgs,
        #[command(flatten)]
        passes: render::PassesArgs,
    },
    /// Every technique on both pipelines against one ground truth, frames interleaved: a
    /// table, and a report folder (report.html, results.csv/json, accuracy_vs_time.svg/png,
    /// contact_sheet.png).
    Compare(compare::Args),
    /// A polygon-offset grid (factor × units) for one technique per depth format: error
    /// split into false shadow (acne) and missed shadow (peter-panning), heatmaps, CSV, best
    /// cell.
    SweepBias(sweep_bias::Args),
    /// The CPU ground truth of a scene (no GL): shadow mask and soft-shadow visibility.
    Truth(truth::Args),
    /// Which backends work here: GL strings, limits, depth/stencil bits, shadow extensions.
    Info {
        /// Only this backend (default: all three).
        #[arg(long, value_parser = named::named::<Backend>())]
        backend: Option<Backend>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Run a script of GL 1.x calls (valid C99) and write the image it draws.
    Replay(replay::Args),
    /// The scene in a window: keys change the technique, its polygon offset, depth bits,
    /// map size, filter, precision, pipeline and what is shown; the mouse turns the light
    /// (shift: the camera); the status bar gives the error against the truth. Starts a
    /// private Xvfb when no display is set.
    #[command(after_help = view::keys_help())]
    View(view::Args),
    /// Print a technique's frame as the era wrote it: a C99 program on the OSMesa API
    /// (`--format c`), the replay script (`script`), or a page of each pass's purpose, state
    /// and GLSL with the figures that decide success (`markdown`).
    Explain(explain::Args),
    /// Print each distinct program a script needs: its key and its generated GLSL.
    Shaders {
        /// A GL script; without it, one frame of `--scene` (the default scene) with its
        /// technique.
        file: Option<PathBuf>,
        /// A scene file whose technique's frame is shown (when no script is given).
        #[arg(long, conflicts_with = "file")]
        scene: Option<PathBuf>,
        /// The technique to show for the scene (default: the scene's own).
        #[arg(long)]
        technique: Option<String>,
    },
    /// Print a folder holding the C library as libOSMesa.so.8, for
    /// `LD_LIBRARY_PATH=$(fixedfunc osmesa-dir) ./program`: an unmodified OSMesa program
    /// then renders through the layer (the emulated pipeline on EGL).
    OsmesaDir,
    /// Repeated timings, reported as medians.
    Bench {
        /// Only this group (default: all).
        #[arg(long, value_parser = named::named::<BenchGroup>())]
        only: Option<BenchGroup>,
        /// Repetitions per measurement, 1 to 1000 (see `bench::MAX_REPEATS`).
        #[arg(long, default_value_t = 10, value_parser = bench::parse_repeats)]
        repeats: usize,
        /// Print JSON instead of a table.
        #[arg(long)]
        json: bool,
    },
}

pub fn run() -> ExitCode {
    let cli = Cli::parse();
    let limits = cli.limits.limits();
    let result = match cli.command {
        Command::Info { backend, json } => info::run(backend, json),
        Command::OsmesaDir => osmesa_dir::run(),
        Command::Compare(args) => compare::run(args, limits),
        Command::SweepBias(args) => sweep_bias::run(args, limits),
        Command::Replay(args) => replay::run(args),
        Command::Explain(args) => explain::run(args, limits),
        Command::View(args) => view::run(args, limits),
        Command::Shaders {
            file,
            scene,
            technique,
        } => shaders::run(
            file.as_deref(),
            scene.as_deref(),
            technique.as_deref(),
            limits,
        ),
        Command::Bench {
            only,
            repeats,
            json,
        } => bench::run(only, repeats, json),
        Command::Render {
            scene,
            technique,
            pipeline,
            backend,
            size,
            out,
            mask,
            frames,
            shadow,
            remake_maps,
            depth_map,
            orbit,
            turns,
            expect,
            passes,
        } => render::run_with_passes(
            render::Args {
                scene,
                technique,
                pipeline,
                backend,
                size,
                out,
                mask,
                frames,
                shadow,
                remake_maps,
                depth_map,
                orbit,
                turns,
                expect,
            },
            passes,
            limits,
        ),
        Command::Truth(args) => truth::run(args, limits),
    };
    match result.and_then(|()| output::flush()) {
        Ok(()) => ExitCode::SUCCESS,
        // A signal is ending the process and stopped the X server under the work: the
        // failure is that, and the re-raised signal ends the process with its own status
        // (`signals`), not this error's.
        Err(_) if fixedfunc::gpu::ending() => fixedfunc::gpu::await_ending_signal(),
        Err(error) => {
            // Nowhere is left to report a failure to write this.
            let _ = writeln!(std::io::stderr(), "fixedfunc: {error}");
            ExitCode::from(error.exit_code())
        }
    }
}
