//! What `render` and `truth` share: the optional scene argument, `--size`, image output
//! (checked before the work, written so that a failure is reported).

use std::path::Path;

use fixedfunc::render::ImageSize;
use fixedfunc::report;
use fixedfunc::scene::{Limits, Scene};

use super::error::CliError;

/// `--size WxH`, parsed by the render layer's rules (clap shows its message).
pub fn parse_size(text: &str) -> Result<ImageSize, String> {
    text.parse::<ImageSize>().map_err(|e| e.to_string())
}

/// `--max-triangles` and `--memory-budget`, accepted by every command (see the README's
/// Limits).
#[derive(clap::Args, Debug, Clone, Copy, Default)]
pub struct LimitArgs {
    /// Refuse a scene with more triangles than N (default 20,000,000), counted from the
    /// shapes' parameters before any mesh is built.
    #[arg(long, global = true, value_name = "N")]
    pub max_triangles: Option<u64>,
    /// Refuse a run estimated to need more than GIB gibibytes (default 8: a third of a
    /// 24 GiB machine), before any mesh or context is made.
    #[arg(long, global = true, value_name = "GIB", value_parser = parse_gib)]
    pub memory_budget: Option<u64>,
}

impl LimitArgs {
    /// The defaults with the flags given applied.
    pub fn limits(&self) -> Limits {
        let defaults = Limits::default();
        Limits {
            max_triangles: self.max_triangles.unwrap_or(defaults.max_triangles),
            memory_bytes: self.memory_budget.unwrap_or(defaults.memory_bytes),
        }
    }
}

/// `--memory-budget GIB`: a positive number of GiB (fractions allowed), as bytes.
fn parse_gib(text: &str) -> Result<u64, String> {
    match text.trim().parse::<f64>() {
        Ok(g) if g.is_finite() && g > 0.0 && g < 1e9 => Ok((g * f64::from(1u32 << 30)) as u64),
        _ => Err(format!(
            "expected a positive number of GiB (e.g. 16 or 0.5), not `{text}`"
        )),
    }
}

/// The scene file, or the built-in default scene, under `limits`; loading warnings go to
/// stderr.
pub fn load(path: Option<&Path>, limits: Limits) -> Result<Scene, CliError> {
    let Some(path) = path else {
        let mut scene = Scene::default_scene();
        scene.limits = limits;
        return Ok(scene);
    };
    let scene = Scene::load_with(path, limits)?;
    for warning in &scene.warnings {
        eprintln!("warning: {warning}");
    }
    Ok(scene)
}

/// The scene's name in messages.
pub fn name(path: Option<&Path>) -> String {
    path.map_or("the default scene".to_string(), |p| p.display().to_string())
}

/// Saves an image as PNG: encoded in memory, written to a temporary name, synced and
/// renamed (`report::save_png`); a failure is an error, never a file reported as written.
pub fn save<P, C>(image: &image::ImageBuffer<P, C>, path: &Path) -> Result<(), CliError>
where
    P: image::PixelWithColorType,
    [P::Subpixel]: image::EncodableLayout,
    C: std::ops::Deref<Target = [P::Subpixel]>,
{
    Ok(report::save_png(image, path)?)
}

/// `dir/name.png` + `label` → `dir/name-label.png` (a file written beside another).
pub fn beside(path: &Path, label: &str) -> std::path::PathBuf {
    let stem = path
        .file_stem()
        .map_or("image".into(), |s| s.to_string_lossy());
    let ext = path
        .extension()
        .map_or("png".into(), |e| e.to_string_lossy());
    path.with_file_name(format!("{stem}-{label}.{ext}"))
}

/// Refuses, before any work, PNG outputs that cannot be written (see
/// `report::check_output`), that are not named `.png`, or two options that name one file.
/// `outputs` pairs each option (`--out`) with its path.
pub fn check_png_outputs(outputs: &[(&'static str, &Path)]) -> Result<(), CliError> {
    for (i, &(flag, path)) in outputs.iter().enumerate() {
        report::check_png_name(path)?;
        report::check_output(path)?;
        if let Some(&(first, _)) = outputs[..i]
            .iter()
            .find(|(_, earlier)| report::same_file(earlier, path))
        {
            return Err(CliError::SameFile {
                first,
                second: flag.to_string(),
                path: path.to_path_buf(),
            });
        }
    }
    Ok(())
}
