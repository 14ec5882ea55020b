//! Reading a GL script file into Commands, with the file named in every error.

use std::path::Path;

use fixedfunc::ff::{script, Command};

use super::error::CliError;

pub fn load(path: &Path) -> Result<Vec<Command>, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| CliError::Read {
        path: path.display().to_string(),
        reason: e.to_string(),
    })?;
    script::parse(&text).map_err(|source| CliError::Script {
        path: path.display().to_string(),
        source,
    })
}
