//! `--pipeline emulate|native|both` for the commands that study several renders, and the
//! technique names they accept (the registry's, in its order).

use fixedfunc::techniques::REGISTRY;
use fixedfunc::vocab::PipelineKind;

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

/// Every registered technique's name, for clap's possible values.
pub fn technique_names() -> clap::builder::PossibleValuesParser {
    clap::builder::PossibleValuesParser::new(REGISTRY.iter().map(|t| t.name))
}
