//! `fixedfunc truth`: the CPU ground truth of a scene (no GL), its mask and optionally its
//! soft-shadow visibility as PNGs, with the time it took; for a soft light (area or sun), also how it
//! was sampled and its own standard error.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use fixedfunc::render::{self, ImageSize, RenderError};
use fixedfunc::scene::{grouped, Limits, TruthSettings};
use fixedfunc::truth::{self, TruthOptions};
use indicatif::{ProgressBar, ProgressStyle};

use super::error::CliError;
use super::scene_arg;

/// Arguments of `truth`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Scene file (TOML); the built-in default scene when omitted.
    pub scene: Option<PathBuf>,
    /// Where the mask goes (PNG: 255 lit, 0 shadowed, 128 background).
    #[arg(long, default_value = "truth.png")]
    pub mask: PathBuf,
    /// Also write the visibility fraction (grey + alpha PNG; alpha 0 on background).
    #[arg(long)]
    pub visibility: Option<PathBuf>,
    /// Image size WxH (default: the scene's).
    #[arg(long, value_name = "WxH", value_parser = scene_arg::parse_size)]
    pub size: Option<ImageSize>,
    /// Which of the scene's lights casts the shadows (0-based).
    #[arg(long, default_value_t = 0)]
    pub light: usize,
    /// Shadow rays per pixel for a soft light (area or sun), 1 to 8192, rounded up to two
    /// s × s stratified grids (2s²) (default: the scene's `[truth] samples`, else 242).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=i64::from(TruthSettings::MAX_SAMPLES)))]
    pub samples: Option<u32>,
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
        area_samples: args.samples,
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
    if let Some(area) = &truth.area {
        let sun = scene.lights.get(args.light).and_then(|l| l.sun());
        outln!(
            "{}: {} samples per pixel (two independent {s}×{s} stratified grids), \
             standard error {:.4} (RMS over {} geometry pixels of |A − B| / 2, A and B the \
             grids' visibilities)",
            sun.map_or("area light".to_string(), |s| format!(
                "sun of {:.2}°",
                s.angular_diameter.to_degrees()
            )),
            area.samples(),
            area.standard_error,
            grouped(area.geometry_pixels),
            s = area.side,
        )?;
    }
    Ok(())
}
