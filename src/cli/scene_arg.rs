//! What `render` and `truth` share: the optional scene argument, `--size`, image output.

use std::path::{Path, PathBuf};

use fixedfunc::render::ImageSize;
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

/// Saves an image as PNG (the format follows the extension).
pub fn save<P, C>(image: &image::ImageBuffer<P, C>, path: &PathBuf) -> Result<(), CliError>
where
    P: image::PixelWithColorType,
    [P::Subpixel]: image::EncodableLayout,
    C: std::ops::Deref<Target = [P::Subpixel]>,
{
    image.save(path).map_err(|source| CliError::WriteImage {
        path: path.clone(),
        source,
    })
}
