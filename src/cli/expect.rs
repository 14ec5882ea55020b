//! `--expect REF.png [--tolerance STEPS,SHARE]` (`render`, `replay`): the image the command
//! wrote is compared with a reference (`metrics::image_diff`). Within the tolerance the
//! command says so and succeeds; beyond it, or at another size, it writes the difference
//! picture beside the image (`NAME-diff.png`) and exits 1 — the exit code of a check that
//! failed, apart from 2 for trouble (see `cli::exit_code`).

use std::path::{Path, PathBuf};

use fixedfunc::metrics::image_diff::{self, Tolerance, Verdict};
use image::RgbaImage;

use super::error::CliError;
use super::scene_arg;

#[derive(clap::Args, Clone, Debug)]
pub struct ExpectArgs {
    /// Compare the image with this PNG: beyond --tolerance, write a difference picture
    /// beside the image (NAME-diff.png: equal pixels dimmed, within the steps yellow,
    /// beyond them red) and exit 1.
    #[arg(long, value_name = "PNG")]
    pub expect: Option<PathBuf>,
    /// How far the image may differ from --expect: STEPS,PERCENT% — at most PERCENT% of
    /// the pixels differ by more than STEPS/255 in a channel (or STEPS,FRACTION).
    #[arg(long, value_name = "STEPS,SHARE", default_value = "3,1%", value_parser = parse_tolerance)]
    pub tolerance: Tolerance,
}

fn parse_tolerance(s: &str) -> Result<Tolerance, String> {
    s.parse()
}

impl ExpectArgs {
    /// The difference picture's path for the image at `out`, when a reference is given.
    pub fn picture_path(&self, out: &Path) -> Option<PathBuf> {
        self.expect.as_ref().map(|_| scene_arg::beside(out, "diff"))
    }

    /// Compares `image` (written to `out`) with the reference, if one was given.
    pub fn check(&self, image: &RgbaImage, out: &Path) -> Result<(), CliError> {
        let Some(reference_path) = &self.expect else {
            return Ok(());
        };
        let reference = image::open(reference_path)
            .map_err(|e| CliError::Read {
                path: reference_path.display().to_string(),
                reason: e.to_string(),
            })?
            .to_rgba8();
        // Images of another size do not compare: that is a difference too.
        let verdict =
            Verdict::of(image, &reference, self.tolerance).map_err(|e| CliError::Expectation {
                reference: reference_path.clone(),
                detail: e.to_string(),
                picture: None,
            })?;
        if verdict.passes() {
            outln!(
                "expect {}: within {}: {verdict}",
                reference_path.display(),
                self.tolerance
            )?;
            return Ok(());
        }
        let path = scene_arg::beside(out, "diff");
        let picture = image_diff::picture(image, &reference, self.tolerance.per_channel);
        scene_arg::save(&picture, &path)?;
        Err(CliError::Expectation {
            reference: reference_path.clone(),
            detail: verdict.to_string(),
            picture: Some(path),
        })
    }
}
