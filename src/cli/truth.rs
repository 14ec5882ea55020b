//! `fixedfunc truth`: the CPU ground truth of a scene (no GL), its mask and optionally its
//! soft-shadow visibility as PNGs, with the time it took.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use fixedfunc::render::{self, ImageSize, RenderError};
use fixedfunc::scene::Limits;
use fixedfunc::truth::{self, TruthOptions};
use indicatif::{ProgressBar, ProgressStyle};

use super::error::CliError;
use super::scene_arg;

pub struct Args {
    pub scene: Option<PathBuf>,
    pub mask: PathBuf,
    pub visibility: Option<PathBuf>,
    pub size: Option<ImageSize>,
    pub light: usize,
}

pub fn run(args: Args, limits: Limits) -> Result<(), CliError> {
    let scene = scene_arg::load(args.scene.as_deref(), limits)?;
    let mut outputs = vec![("--mask", args.mask.as_path())];
    if let Some(path) = &args.visibility {
        outputs.push(("--visibility", path.as_path()));
    }
    scene_arg::check_png_outputs(&outputs)?;
    let scene = render::apply_overrides(&scene, args.size, None);
    render::Footprint::of(&scene, 0)
        .check(&scene.limits)
        .map_err(RenderError::from)?;
    let options = TruthOptions {
        light: args.light,
        ..TruthOptions::default()
    };
    let spinner = ProgressBar::new_spinner()
        .with_style(ProgressStyle::default_spinner())
        .with_message(format!(
            "ray-casting the ground truth of {}",
            scene_arg::name(args.scene.as_deref())
        ));
    spinner.enable_steady_tick(Duration::from_millis(100));
    let start = Instant::now();
    let result = truth::truth(&scene, &options);
    let wall = start.elapsed();
    spinner.finish_and_clear();
    let truth = result?;
    scene_arg::save(&truth.mask.to_image(), &args.mask)?;
    if let Some(path) = &args.visibility {
        scene_arg::save(&truth.visibility_image(), path)?;
    }
    let t = &truth.timings;
    let s = |d: Duration| format!("{:.3}", d.as_secs_f64());
    outln!(
        "truth: {}x{}, {} triangles, {} primary + {} shadow rays in {} s \
         (BVH {} s, primary {} s, shadow {} s) → {}{}",
        truth.mask.width,
        truth.mask.height,
        truth.triangles,
        truth.primary_rays,
        truth.shadow_rays,
        s(wall),
        s(t.build),
        s(t.primary),
        s(t.shadow),
        args.mask.display(),
        args.visibility
            .as_ref()
            .map_or(String::new(), |p| format!(", visibility → {}", p.display())),
    )?;
    Ok(())
}
