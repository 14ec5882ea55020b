//! The command line: argument parsing (clap) and the user-facing output of each command.
//! Errors from the layers below arrive here and become a message and an exit code; nothing
//! below this module exits the process.

mod bench;
mod error;
mod info;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

use fixedfunc::bench::BenchGroup;
use fixedfunc::gpu::Backend;

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
