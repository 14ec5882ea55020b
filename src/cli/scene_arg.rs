//! What `render` and `truth` share: the optional scene argument, `--size`, image output.

use std::path::{Path, PathBuf};

use fixedfunc::render::ImageSize;
use fixedfunc::scene::Scene;

use super::error::CliError;

/// `--size WxH`, parsed by the render layer's rules (clap shows its message).
pub fn parse_size(text: &str) -> Result<ImageSize, String> {
    text.parse::<ImageSize>().map_err(|e| e.to_string())
}

/// The scene file, or the built-in default scene; loading warnings go to stderr.
pub fn load(path: Option<&Path>) -> Result<Scene, CliError> {
    let Some(path) = path else {
        return Ok(Scene::default_scene());
    };
    let scene = Scene::load(path)?;
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
