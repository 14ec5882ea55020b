//! The `fixedfunc` command line.

mod cli;

fn main() -> std::process::ExitCode {
    // Output piped into `head` and closed early ends the process quietly, as Unix tools do,
    // instead of a panic on a failed print; SIGINT, SIGTERM and SIGHUP end it as usual. All
    // four first stop the private Xvfb, if one runs (see `cli::signals`).
    cli::signals::install();
    cli::run()
}
