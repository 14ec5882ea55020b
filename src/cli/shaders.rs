//! `fixedfunc shaders [FILE | --scene SCENE]`: the distinct programs a script's draws (or
//! one frame of a scene's technique) need, each with its key and generated GLSL. No GL context is needed: the state model derives the keys.
//! A technique's own programs (`UseProgram`) follow; for `occluder-planes`, those of its
//! program forms: Coleman's historical files and the generic program generated for the
//! scene's planes (or why a form does not fit the scene).

use std::path::Path;
use std::sync::Arc;

use fixedfunc::ff::{Command, FixedState, ShaderProgram};
use fixedfunc::pipeline::emulate::key::ShaderKey;
use fixedfunc::pipeline::emulate::shadergen;
use fixedfunc::render::RenderError;
use fixedfunc::scene::{Limits, OccluderProgram, Scene};
use fixedfunc::techniques::{self, TechniqueError};
use fixedfunc::vocab::{Named, TechniqueId};

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

/// A program a plan brings (`UseProgram`), or why a form of the technique has none here.
type OwnProgram = (String, Result<Arc<ShaderProgram>, TechniqueError>);

/// The setup and one frame (maps included) of a scene's technique, as Commands, and the
/// programs of its own it shows (`technique_programs`).
fn scene_frame(
    scene: Option<&Path>,
    technique: Option<&str>,
    limits: Limits,
) -> Result<(String, Vec<Command>, Vec<OwnProgram>), CliError> {
    let scene_value = super::scene_arg::load(scene, limits)?;
    let id = match technique {
        Some(name) => techniques::parse_name(name).map_err(RenderError::from)?,
        None => scene_value.shadow.technique,
    };
    let t = techniques::technique(id);
    let prepared = techniques::Prepared::new(&scene_value);
    let plan = (t.plan)(&scene_value, &prepared).map_err(RenderError::from)?;
    let label = format!("{} ({id})", super::scene_arg::name(scene));
    let programs = technique_programs(&scene_value, &prepared, id, &plan);
    Ok((label, frame_commands(&plan), programs))
}

/// The distinct programs of a plan's frame (not its mask look), in order of first use.
fn plan_programs(plan: &techniques::Plan) -> Vec<Arc<ShaderProgram>> {
    let mut out: Vec<Arc<ShaderProgram>> = Vec::new();
    for c in plan.frame_commands() {
        if let Command::UseProgram(Some(p)) = c {
            if !out.contains(p) {
                out.push(p.clone());
            }
        }
    }
    out
}

/// The plan's own programs; for `occluder-planes` those of every `[shadow] program` form
/// (the historical files and the generated one), or why a form does not fit the scene.
fn technique_programs(
    scene: &Scene,
    prepared: &techniques::Prepared,
    id: TechniqueId,
    plan: &techniques::Plan,
) -> Vec<OwnProgram> {
    if id != TechniqueId::OccluderPlanes {
        let label = |p: &Arc<ShaderProgram>| p.name.clone();
        return plan_programs(plan)
            .into_iter()
            .map(|p| (label(&p), Ok(p)))
            .collect();
    }
    let mut out = Vec::new();
    for form in [OccluderProgram::Coleman, OccluderProgram::Generic] {
        let mut s = scene.clone();
        s.shadow.occluder_program = form;
        let label = format!("program = \"{}\"", form.name());
        match (techniques::technique(id).plan)(&s, prepared) {
            Ok(plan) => out.extend(
                plan_programs(&plan)
                    .into_iter()
                    .map(|p| (format!("{label}: {}", p.name), Ok(p))),
            ),
            Err(e) => out.push((label, Err(e))),
        }
    }
    out
}

/// A plan's own program as `shaders` prints it: its name, samplers, then its GLSL.
fn own_program_text((label, program): &OwnProgram) -> String {
    match program {
        Err(e) => format!("=== {label} ===\nnot for this scene: {e}"),
        Ok(p) => {
            let samplers: Vec<String> = p
                .samplers
                .iter()
                .map(|s| format!("{} ← unit {}", s.name, s.unit))
                .collect();
            format!(
                "=== {label} ===\n--- samplers ---\n{}\n--- vertex shader ---\n{}\n\
                 --- fragment shader ---\n{}",
                samplers.join(", "),
                p.vertex,
                p.fragment
            )
        }
    }
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
    let (label, commands, own) = match file {
        Some(file) => (
            file.display().to_string(),
            script_io::load(file)?,
            Vec::new(),
        ),
        None => scene_frame(scene, technique, limits)?,
    };
    let keys = distinct_keys(&commands);
    outln!("{label}: {} distinct program(s)", keys.len())?;
    for (i, key) in keys.iter().enumerate() {
        outln!("\n{}", program_text(i, key))?;
    }
    if !own.is_empty() {
        outln!("\nthe technique's own programs:")?;
    }
    for program in &own {
        outln!("\n{}", own_program_text(program))?;
    }
    Ok(())
}
