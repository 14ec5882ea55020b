//! The command line: argument parsing (clap) and the user-facing output of each command.
//! Errors from the layers below arrive here and become a message and an exit code; nothing
//! below this module exits the process.

mod bench;
mod error;
mod info;
mod replay;
mod script_io;
mod shaders;
mod size;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

use fixedfunc::bench::BenchGroup;
use std::path::PathBuf;

use fixedfunc::gpu::Backend;
use fixedfunc::pipeline::PipelineKind;

/// An emulator of the OpenGL 1.x fixed-function pipeline for the classic shadow techniques.
#[derive(Parser)]
#[command(name = "fixedfunc", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Which backends work here: GL strings, limits, depth/stencil bits, shadow extensions.
    Info {
        /// Only this backend (default: all three).
        #[arg(long, value_enum)]
        backend: Option<Backend>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Run a script of GL 1.x calls (valid C99) and write the image it draws.
    Replay {
        /// The script.
        file: PathBuf,
        #[arg(long, value_enum, default_value = "emulate")]
        pipeline: PipelineKind,
        #[arg(long, value_enum, default_value = "egl")]
        backend: Backend,
        /// Target size, WIDTHxHEIGHT.
        #[arg(long, default_value = "256x256")]
        size: size::Size,
        /// The PNG to write.
        #[arg(long, default_value = "replay.png")]
        out: PathBuf,
    },
    /// Print each distinct program a script needs: its key and its generated GLSL.
    Shaders {
        /// The script.
        file: PathBuf,
    },
    /// Repeated timings, reported as medians.
    Bench {
        /// Only this group (default: all).
        #[arg(long, value_enum)]
        only: Option<BenchGroup>,
        /// Repetitions per measurement.
        #[arg(long, default_value_t = 10)]
        repeats: usize,
        /// Print JSON instead of a table.
        #[arg(long)]
        json: bool,
    },
}

pub fn run() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Info { backend, json } => info::run(backend, json),
        Command::Replay {
            file,
            pipeline,
            backend,
            size,
            out,
        } => replay::run(&file, pipeline, backend, size, &out),
        Command::Shaders { file } => shaders::run(&file),
        Command::Bench {
            only,
            repeats,
            json,
        } => bench::run(only, repeats, json),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("fixedfunc: {error}");
            ExitCode::FAILURE
        }
    }
}
