//! `fixedfunc shaders FILE`: the distinct programs a script's draws need, each with its key
//! and generated GLSL. No GL context is needed: the state model derives the keys.

use std::path::Path;

use fixedfunc::ff::{Command, FixedState};
use fixedfunc::pipeline::emulate::key::ShaderKey;
use fixedfunc::pipeline::emulate::shadergen;

use super::error::CliError;
use super::script_io;

/// The keys of the draws in order of first use.
pub fn distinct_keys(commands: &[Command]) -> Vec<ShaderKey> {
    let mut state = FixedState::new();
    let mut keys: Vec<ShaderKey> = Vec::new();
    for cmd in commands {
        if state.apply(cmd).is_ok() && matches!(cmd, Command::Draw(_)) {
            let key = ShaderKey::from_state(&state, fixedfunc::ff::Precision::Float);
            if !keys.contains(&key) {
                keys.push(key);
            }
        }
    }
    keys
}

pub fn run(file: &Path) -> Result<(), CliError> {
    let commands = script_io::load(file)?;
    let keys = distinct_keys(&commands);
    println!("{}: {} distinct program(s)", file.display(), keys.len());
    for (i, key) in keys.iter().enumerate() {
        let program = shadergen::generate(key);
        println!("\n=== program {i} ===\n--- key ---\n{key:#?}");
        println!("--- vertex shader ---\n{}", program.vertex);
        println!("--- fragment shader ---\n{}", program.fragment);
    }
    Ok(())
}
