//! Reading a GL script file into Commands, with the file named in every error.

use std::path::Path;

use fixedfunc::ff::{script, Command};

use super::error::CliError;

pub fn load(path: &Path) -> Result<Vec<Command>, CliError> {
    Ok(load_lines(path)?.into_iter().map(|(_, c)| c).collect())
}

/// The commands with the script line of each.
pub fn load_lines(path: &Path) -> Result<Vec<(usize, Command)>, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| CliError::Read {
        path: path.display().to_string(),
        reason: e.to_string(),
    })?;
    script::parse_lines(&text).map_err(|source| CliError::Script {
        path: path.display().to_string(),
        source,
    })
}
