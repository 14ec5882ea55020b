//! Standard output that reports its failures. `println!` panics when stdout cannot be
//! written (a full disk, a closed descriptor, `> /dev/full`); the commands print through
//! [`out!`] and [`outln!`] instead, which return the failure as [`CliError::Stdout`]: one
//! line on stderr and a non-zero exit. (A reader that closed the pipe is another case:
//! SIGPIPE ends the process quietly, as it ends any Unix tool; see `signals`.)

use std::io::Write;

use super::error::CliError;

/// Writes formatted text to stdout, and flushes it when `flush` (at the end of a line).
pub fn write(args: std::fmt::Arguments<'_>, newline: bool) -> Result<(), CliError> {
    let mut stdout = std::io::stdout().lock();
    stdout
        .write_fmt(args)
        .and_then(|()| {
            if newline {
                stdout.write_all(b"\n")?;
                stdout.flush()
            } else {
                Ok(())
            }
        })
        .map_err(CliError::Stdout)
}

/// Flushes what is left in stdout's buffer, reporting a failure.
pub fn flush() -> Result<(), CliError> {
    std::io::stdout().flush().map_err(CliError::Stdout)
}
