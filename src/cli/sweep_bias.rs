//! `fixedfunc sweep-bias`: a polygon-offset grid for one technique per depth format, scored
//! against one truth, repeated around the best cell with `--refine`; prints each format's
//! best cell (and each round's) and writes heatmaps, each cell's pictures, CSV, JSON and
//! the page `index.html`.

use fixedfunc::vocab::{DepthBits, MapFilter, Precision, TechniqueId};
use std::path::PathBuf;

use fixedfunc::gpu::Backend;
use fixedfunc::render::ImageSize;
use fixedfunc::report;
use fixedfunc::report::sweep_page::SweepPictures;
use fixedfunc::scene::Limits;
use fixedfunc::study::{self, Refine, SweepRange, SweepSpec, MAX_ROUNDS};

use super::error::CliError;
use super::pipelines::{technique_parser, PipelineChoice};
use super::progress::{Estimate, StudyBar};
use super::scene_arg;
use super::shadow_args::ShadowArgs;

/// Rounds of a bare `--refine` (`Refine::DEFAULT_ROUNDS`, as clap wants it: text).
const DEFAULT_ROUNDS: &str = "4";

/// `A..B[:steps]` or a single number, with the range layer's message on failure.
fn parse_range(text: &str) -> Result<SweepRange, String> {
    text.parse::<SweepRange>()
        .map_err(|e| format!("`{text}`: {e}"))
}

/// Arguments of `sweep-bias`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Scene file (TOML); the built-in default scene when omitted.
    pub scene: Option<PathBuf>,
    /// The technique whose bias is swept: one that reads the polygon offset (a shadow-map
    /// technique); any other is refused, its cells would all score the same mask.
    #[arg(long, value_parser = technique_parser())]
    pub technique: TechniqueId,
    /// glPolygonOffset factors: A..B[:STEPS] (5 steps when omitted) or one number.
    #[arg(long, value_name = "A..B[:STEPS]", value_parser = parse_range, allow_hyphen_values = true)]
    pub factor: SweepRange,
    /// glPolygonOffset units: A..B[:STEPS] (5 steps when omitted) or one number.
    #[arg(long, value_name = "A..B[:STEPS]", value_parser = parse_range, allow_hyphen_values = true)]
    pub units: SweepRange,
    /// Depth formats of the light pass, comma-separated; one heatmap each.
    #[arg(long, value_parser = super::named::named::<DepthBits>(), value_delimiter = ',', default_values = ["16", "24", "32f"])]
    pub depth_bits: Vec<DepthBits>,
    /// Repeat each depth format's grid around its best cell until the best lies inside
    /// with steps of at most 0.125 (factor) and 0.5 (units), or ROUNDS rounds in all
    /// (the given grid counted; 4 when no number is given): the same steps while the best
    /// lies on a side past which a better offset may lie, half the steps while it lies
    /// inside; never below 0 (or a negative start given).
    #[arg(long, value_name = "ROUNDS", num_args = 0..=1, require_equals = true,
          default_missing_value = DEFAULT_ROUNDS, value_parser = clap::value_parser!(u32).range(2..=MAX_ROUNDS as i64))]
    pub refine: Option<u32>,
    /// The folder the heatmaps, pictures, CSV, JSON and index.html are written to
    /// (created when missing).
    #[arg(long, default_value = "sweep-bias")]
    pub out: PathBuf,
    #[arg(long, value_enum, default_value_t = PipelineChoice::Emulate)]
    pub pipeline: PipelineChoice,
    #[arg(long, value_parser = super::named::named::<Backend>(), default_value = "egl")]
    pub backend: Backend,
    /// Image size WxH (default: the scene's).
    #[arg(long, value_name = "WxH", value_parser = scene_arg::parse_size)]
    pub size: Option<ImageSize>,
    /// Shadow map edge in texels (default: the scene's `map_size`).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=8192))]
    pub map_size: Option<u32>,
    /// Arithmetic of the emulated texture and combiner stages (default: the scene's).
    #[arg(long, value_parser = super::named::named::<Precision>())]
    pub precision: Option<Precision>,
    /// Shadow map filter (default: the scene's `filter`).
    #[arg(long, value_parser = super::named::named::<MapFilter>())]
    pub filter: Option<MapFilter>,
}

pub fn run(args: Args, limits: Limits) -> Result<(), CliError> {
    let mut scene = scene_arg::load(args.scene.as_deref(), limits)?;
    ShadowArgs {
        map_size: args.map_size,
        precision: args.precision,
        filter: args.filter,
        ..ShadowArgs::default()
    }
    .apply(&mut scene);
    let mut depths = Vec::new();
    for d in args.depth_bits {
        if !depths.contains(&d) {
            depths.push(d);
        }
    }
    let spec = SweepSpec {
        technique: args.technique,
        factor: args.factor,
        units: args.units,
        depths,
        pipelines: args.pipeline.kinds(),
        backend: args.backend,
        size: args.size,
        refine: args.refine.map(|max_rounds| Refine { max_rounds }),
    };
    // Refused before the folder is touched; the folder must take files before the study
    // runs, not after.
    spec.check()?;
    report::check_output_dir(&args.out)?;
    // The old page goes before the first picture is written.
    let mut pictures = SweepPictures::begin(&args.out)?;
    let mut bar = StudyBar::new("sweep-bias", Estimate::FromSecondUnit);
    let sweep =
        study::sweep_with_pictures(&scene, &spec, |p| bar.update(p), |shot| pictures.add(shot));
    bar.finish();
    let sweep = sweep?;
    let name = scene_arg::name(args.scene.as_deref());
    let written = report::write_sweep(&sweep, &name, &args.out, pictures)?;
    out!("{}", report::sweep_summary(&sweep))?;
    outln!(
        "wrote {} files to {}; the page: {}",
        written.files.len(),
        args.out.display(),
        args.out.join("index.html").display()
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_bare_refine_takes_the_study_s_default_rounds() {
        assert_eq!(
            super::DEFAULT_ROUNDS.parse::<u32>().ok(),
            Some(fixedfunc::study::Refine::DEFAULT_ROUNDS)
        );
    }
}
