//! What `render` and `truth` share: the optional scene argument, `--size`, image output
//! (checked before the work, written so that a failure is reported).

use std::path::Path;

use fixedfunc::render::ImageSize;
use fixedfunc::report;
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
