//! `fixedfunc render`: renders a scene, writes the image and the shadow mask, prints the
//! figures line. For a soft light (an area light or a sun) the line carries the visibility RMSE, a second line the
//! visibility's other figures (maximum error, penumbra RMSE), and a soft technique's
//! visibility image (grey = fraction of the light seen, alpha 0 on background) is written
//! beside the mask as `MASK-visibility.png`. Progress bars for multiple frames and for the ground truth (stderr; hidden
//! when stderr is not a terminal).
//!
//! `--passes DIR` also writes what every pass of the last frame left in the buffers
//! (`render::pass_images`, pictured by `report::write_pass_images`): captured in a session
//! of its own after the render, so the figures line is the render's alone.

use fixedfunc::vocab::{PipelineKind, TechniqueId};
use std::path::PathBuf;
use std::time::Duration;

use fixedfunc::gpu::Backend;
use fixedfunc::render::{self, ImageSize, Progress, RemakeMaps, RenderOptions};
use fixedfunc::report;
use fixedfunc::scene::Limits;
use indicatif::{ProgressBar, ProgressStyle};

use super::error::CliError;
use super::expect::ExpectArgs;
use super::shadow_args::ShadowArgs;

use super::scene_arg;

pub struct Args {
    pub scene: Option<PathBuf>,
    pub technique: Option<TechniqueId>,
    pub pipeline: PipelineKind,
    pub backend: Backend,
    pub size: Option<ImageSize>,
    pub out: PathBuf,
    pub mask: PathBuf,
    pub frames: u32,
    pub shadow: ShadowArgs,
    pub remake_maps: RemakeMaps,
    pub depth_map: Option<PathBuf>,
    pub orbit: Option<fixedfunc::render::Orbit>,
    pub turns: Vec<fixedfunc::render::Turn>,
    pub expect: ExpectArgs,
}

/// `--passes DIR`, kept apart from [`Args`] so that the command's parser can flatten it.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct PassesArgs {
    /// Also write, for every pass of the last frame (the light's map passes included), its
    /// colour, depth (normalised) and stencil buffers, the light's map where a pass leaves
    /// it in a texture, and for alpha-tested passes the alpha before the test and (8-bit
    /// maps) the map minus the ramp in 8-bit steps, as DIR/NN-PASS-KIND.png, with
    /// DIR/legend.txt. Captured in a render of its own: the figures are unchanged.
    #[arg(long, value_name = "DIR")]
    pub passes: Option<PathBuf>,
}

/// `render`, with `--passes` when given.
pub fn run_with_passes(args: Args, passes: PassesArgs, limits: Limits) -> Result<(), CliError> {
    let mut scene = scene_arg::load(args.scene.as_deref(), limits)?;
    args.shadow.apply(&mut scene);
    if let Some(dir) = &passes.passes {
        // The folder must take files before the render, not after.
        report::check_output_dir(dir)?;
    }
    for turn in &args.turns {
        scene = turn.apply(&scene);
    }
    let mut outputs = vec![
        ("--out", args.out.as_path()),
        ("--mask", args.mask.as_path()),
    ];
    if let Some(path) = &args.depth_map {
        outputs.push(("--depth-map", path.as_path()));
    }
    let visibility_path = scene_arg::beside(&args.mask, "visibility");
    outputs.push((
        "the visibility image beside --mask",
        visibility_path.as_path(),
    ));
    let picture = args.expect.picture_path(&args.out);
    if let Some(path) = &picture {
        outputs.push(("the --expect difference picture", path.as_path()));
    }
    scene_arg::check_png_outputs(&outputs)?;
    let options = RenderOptions {
        backend: args.backend,
        pipeline: args.pipeline,
        technique: args.technique,
        size: args.size,
        frames: args.frames,
        remake_maps: args.remake_maps,
        depth_map: args.depth_map.is_some(),
        orbit: args.orbit,
        ..RenderOptions::default()
    };
    let bar = ProgressBar::hidden();
    let outcome = render::render_with_progress(&scene, &options, |p| match p {
        Progress::Frame { done, total } if total > 1 => {
            if done == 1 {
                bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
                bar.set_length(u64::from(total));
                bar.set_style(
                    ProgressStyle::with_template("frames [{bar:30}] {pos}/{len}")
                        .unwrap_or_else(|_| ProgressStyle::default_bar()),
                );
            }
            bar.set_position(u64::from(done));
        }
        Progress::Frame { .. } => {}
        Progress::Truth => {
            bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            bar.set_style(ProgressStyle::default_spinner());
            bar.set_message(format!(
                "ray-casting the ground truth of {}",
                scene_arg::name(args.scene.as_deref())
            ));
            bar.enable_steady_tick(Duration::from_millis(100));
        }
    });
    bar.finish_and_clear();
    let outcome = outcome?;
    scene_arg::save(&outcome.image, &args.out)?;
    scene_arg::save(&outcome.mask.to_image(), &args.mask)?;
    if let Some(path) = &args.depth_map {
        let pictures = outcome
            .light_map
            .as_ref()
            .map(report::light_map_pictures)
            .unwrap_or_default();
        for (label, picture) in &pictures {
            let file = if pictures.len() == 1 {
                path.clone()
            } else {
                scene_arg::beside(path, label)
            };
            scene_arg::save(picture, &file)?;
            outln!("light's map ({label}) {}", file.display())?;
        }
        if pictures.is_empty() {
            outln!(
                "`{}` makes no light's map: --depth-map ignored",
                outcome.technique
            )?;
        }
    }
    if let Some(dir) = &passes.passes {
        write_passes(&scene, &options, dir)?;
    }
    let soft = outcome
        .visibility
        .as_ref()
        .filter(|v| v.source == render::VisibilitySource::Soft);
    if let Some(v) = soft {
        scene_arg::save(&v.image.to_image(), &visibility_path)?;
    }
    outln!("{}", outcome.figures())?;
    if let Some(v) = &outcome.visibility {
        let e = &v.errors;
        let penumbra = e
            .penumbra_rmse
            .map_or("no penumbra in the truth".to_string(), |r| {
                format!("penumbra RMSE {r:.3} over {} pixels", e.penumbra_pixels)
            });
        let from = match v.source {
            render::VisibilitySource::Soft => "the technique's soft visibility",
            render::VisibilitySource::HardMask => "the hard mask as 0 or 1",
        };
        outln!(
            "visibility ({from}): RMSE {:.3}, max |error| {:.3}, {penumbra}{}",
            e.rmse,
            e.max_abs,
            soft.map_or(String::new(), |_| format!(
                " · image {}",
                visibility_path.display()
            ))
        )?;
    }
    for e in &outcome.objects {
        outln!("{}", render::object_line(&scene, e))?;
    }
    for note in &outcome.notes {
        outln!("note: {note}")?;
    }
    outln!(
        "image {} · mask {} · {}x{} via {}",
        args.out.display(),
        args.mask.display(),
        outcome.image.width(),
        outcome.image.height(),
        outcome.context_path
    )?;
    args.expect.check(&outcome.image, &args.out)
}

/// Captures the last frame's passes and writes their pictures into `dir`.
fn write_passes(
    scene: &fixedfunc::scene::Scene,
    options: &RenderOptions,
    dir: &std::path::Path,
) -> Result<(), CliError> {
    let images = render::pass_images::capture(scene, options)?;
    let (_, written) = report::write_pass_images(&images, dir, "")?;
    outln!(
        "pass images {} ({} passes, {} files, legend {})",
        dir.display(),
        images.passes.len(),
        written.files.len(),
        report::legend_name("")
    )?;
    Ok(())
}
