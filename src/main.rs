//! The `fixedfunc` command line.

mod cli;

fn main() -> std::process::ExitCode {
    // Output piped into `head` and closed early ends the process quietly, as Unix tools do,
    // instead of a panic on a failed print.
    // SAFETY: restoring the default disposition of SIGPIPE at start-up, before any thread.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    cli::run()
}
