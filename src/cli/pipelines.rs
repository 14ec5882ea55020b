//! `--pipeline emulate|native|both` for the commands that study several renders, and the
//! parser of `--technique`/`--techniques` (every technique's name, in `TechniqueId`'s
//! order, parsed into the id).

use clap::builder::TypedValueParser;
use fixedfunc::vocab::{Named, PipelineKind, TechniqueId};

/// Which pipelines a study runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum PipelineChoice {
    Emulate,
    Native,
    Both,
}

impl PipelineChoice {
    pub fn kinds(self) -> Vec<PipelineKind> {
        match self {
            PipelineChoice::Emulate => vec![PipelineKind::Emulate],
            PipelineChoice::Native => vec![PipelineKind::Native],
            PipelineChoice::Both => vec![PipelineKind::Emulate, PipelineKind::Native],
        }
    }
}

/// A technique's name into its id; clap lists the names as possible values.
pub fn technique_parser() -> impl TypedValueParser<Value = TechniqueId> {
    clap::builder::PossibleValuesParser::new(TechniqueId::names()).try_map(|name| {
        TechniqueId::from_name(&name).ok_or_else(|| format!("unknown technique {name}"))
    })
}
