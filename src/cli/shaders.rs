//! `fixedfunc shaders [FILE | --scene SCENE]`: the distinct programs a script's draws (or
//! one frame of a scene's technique) need, each with its key and generated GLSL. No GL context is needed: the state model derives the keys.

use std::path::Path;

use fixedfunc::ff::{Command, FixedState};
use fixedfunc::pipeline::emulate::key::ShaderKey;
use fixedfunc::pipeline::emulate::shadergen;
use fixedfunc::render::RenderError;
use fixedfunc::scene::Limits;
use fixedfunc::techniques;

use super::error::CliError;
use super::script_io;

/// The keys of the draws in order of first use.
pub fn distinct_keys(commands: &[Command]) -> Vec<ShaderKey> {
    let mut state = FixedState::new();
    let mut keys: Vec<ShaderKey> = Vec::new();
    for cmd in commands {
        if state.apply(cmd).is_ok() && matches!(cmd, Command::Draw(_)) {
            let key = ShaderKey::from_state(&state, fixedfunc::vocab::Precision::Float);
            if !keys.contains(&key) {
                keys.push(key);
            }
        }
    }
    keys
}

/// The setup and one frame (maps included) of a scene's technique, as Commands.
fn scene_frame(
    scene: Option<&Path>,
    technique: Option<&str>,
    limits: Limits,
) -> Result<(String, Vec<Command>), CliError> {
    let scene_value = super::scene_arg::load(scene, limits)?;
    let id = match technique {
        Some(name) => techniques::parse_name(name).map_err(RenderError::from)?,
        None => scene_value.shadow.technique,
    };
    let t = techniques::technique(id);
    let prepared = techniques::Prepared::new(&scene_value);
    let plan = (t.plan)(&scene_value, &prepared).map_err(RenderError::from)?;
    let label = format!("{} ({id})", super::scene_arg::name(scene));
    Ok((label, frame_commands(&plan)))
}

/// A plan's setup and one frame that makes its maps, as Commands (what `shaders` and
/// `explain` show of a scene's technique).
pub fn frame_commands(plan: &techniques::Plan) -> Vec<Command> {
    plan.setup
        .iter()
        .chain(plan.frame_commands())
        .cloned()
        .collect()
}

/// Program `index` as `shaders` prints it: its key, then its generated GLSL.
pub fn program_text(index: usize, key: &ShaderKey) -> String {
    let program = shadergen::generate(key);
    format!(
        "=== program {index} ===\n--- key ---\n{key:#?}\n--- vertex shader ---\n{}\n\
         --- fragment shader ---\n{}",
        program.vertex, program.fragment
    )
}

pub fn run(
    file: Option<&Path>,
    scene: Option<&Path>,
    technique: Option<&str>,
    limits: Limits,
) -> Result<(), CliError> {
    let (label, commands) = match file {
        Some(file) => (file.display().to_string(), script_io::load(file)?),
        None => scene_frame(scene, technique, limits)?,
    };
    let keys = distinct_keys(&commands);
    outln!("{label}: {} distinct program(s)", keys.len())?;
    for (i, key) in keys.iter().enumerate() {
        outln!("\n{}", program_text(i, key))?;
    }
    Ok(())
}
