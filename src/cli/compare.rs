//! `fixedfunc compare`: every technique × pipeline on one scene, frames interleaved, one
//! truth; prints the table (and, for a scene of several objects, the error by object) and
//! writes the report folder (HTML page, CSVs, JSON, plot, contact sheet).

use std::path::PathBuf;

use fixedfunc::gpu::Backend;
use fixedfunc::render::ImageSize;
use fixedfunc::report;
use fixedfunc::scene::Limits;
use fixedfunc::study::{self, CompareSpec};
use fixedfunc::vocab::{Named, TechniqueId};

use super::error::CliError;
use super::pipelines::{technique_parser, PipelineChoice};
use super::progress::{Estimate, StudyBar};
use super::scene_arg;
use super::shadow_args::ShadowArgs;

/// Arguments of `compare`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Scene file (TOML); the built-in default scene when omitted.
    pub scene: Option<PathBuf>,
    /// Techniques to compare, comma-separated (default: every technique).
    #[arg(long, value_delimiter = ',', value_parser = technique_parser())]
    pub techniques: Vec<TechniqueId>,
    /// The folder the report is written to (created when missing).
    #[arg(long, default_value = "compare-report")]
    pub out: PathBuf,
    /// Frames per technique and pipeline; times are the median of frames 2…N.
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=10_000))]
    pub frames: u32,
    /// Which pipelines run (a combination a pipeline cannot execute is skipped and said so).
    #[arg(long, value_enum, default_value_t = PipelineChoice::Both)]
    pub pipeline: PipelineChoice,
    #[arg(long, value_parser = super::named::named::<Backend>(), default_value = "egl")]
    pub backend: Backend,
    /// Image size WxH (default: the scene's).
    #[arg(long, value_name = "WxH", value_parser = scene_arg::parse_size)]
    pub size: Option<ImageSize>,
    /// Picture every pass of each measured row (its colour, depth, stencil, alpha and map
    /// buffers, as `render --passes`) and give each card a strip of them: a session more
    /// per row, and the pictures held until the report is written.
    #[arg(long)]
    pub passes: bool,
    #[command(flatten)]
    pub shadow: ShadowArgs,
}

pub fn run(args: Args, limits: Limits) -> Result<(), CliError> {
    let mut scene = scene_arg::load(args.scene.as_deref(), limits)?;
    args.shadow.apply(&mut scene);
    // The folder must take files before the study runs, not after.
    report::check_output_dir(&args.out)?;
    let techniques = if args.techniques.is_empty() {
        TechniqueId::all()
    } else {
        let mut chosen = Vec::new();
        for id in args.techniques {
            if !chosen.contains(&id) {
                chosen.push(id);
            }
        }
        chosen
    };
    let spec = CompareSpec {
        techniques,
        pipelines: args.pipeline.kinds(),
        backend: args.backend,
        frames: args.frames,
        size: args.size,
        passes: if args.passes {
            study::PassStrips::With
        } else {
            study::PassStrips::Without
        },
    };
    let mut bar = StudyBar::new("compare", Estimate::Never);
    let comparison = study::compare(&scene, &spec, |p| bar.update(p));
    bar.finish();
    let comparison = comparison?;
    let name = scene_arg::name(args.scene.as_deref());
    let written = report::write_comparison(&comparison, &name, &args.out)?;
    let rows = report::ResultRow::all(&comparison.rows, &comparison.scene);
    out!("{}", report::comparison_table(&rows))?;
    out!("{}", report::objects_table(&rows))?;
    out!("{}", report::phase_lines(&comparison))?;
    outln!(
        "report {} ({} files)",
        args.out.join("report.html").display(),
        written.files.len()
    )?;
    Ok(())
}
