//! Reports: a study (`study::Comparison`, `study::Sweep`) written out as files a person
//! reads — tables (terminal, CSV, JSON), plots (plotters, SVG and PNG), pictures (error
//! images, a labelled contact sheet, the light's map of a render) and one HTML page.
//!
//! **One source of numbers.** Every figure of a compare row comes from
//! `RenderOutcome::figures()` — the function behind `fixedfunc render`'s line — or from the
//! same `metrics::Metrics` it reads, through [`ResultRow::of`]; the terminal table, CSV,
//! JSON, plot and page are all printed from `ResultRow`s, so they cannot disagree.
//!
//! **Files only in the output folder.** The page refers to its pictures by bare file name,
//! each written by this module into the same folder, and uses no network resource (inline
//! CSS, no scripts): it opens from disk in any browser. [`Written`] lists every file, and
//! the page is built from that list's names.
//!
//! **Nothing lost, nothing half-written.** Every file goes through [`files`]: written to a
//! temporary name, synced and renamed when complete; a failed write is an error, never a
//! file reported as written. A comparison's page is written last and the old page is
//! removed first, so a folder never holds a page that links pictures of another run.
//!
//! **Text in bitmaps** needs a font: plotters draws it with ab_glyph from a TrueType file
//! found on the system ([`font`]), so no fontconfig or freetype is linked.

mod compare_files;
mod csv;
mod file_names;
pub mod files;
pub mod font;
mod heatmap;
mod html;
mod light_map;
mod objects;
mod pass_pictures;
mod pictures;
mod plot;
pub mod provenance;
mod rows;
mod sweep_files;
pub mod sweep_page;
mod table;

pub use compare_files::write_comparison;
pub use files::{check_output, check_output_dir, check_png_name, same_file, save_png, write_file};
pub use light_map::{light_map_pictures, pseudo_colour};
pub use objects::{objects_table, ObjectShare, Share};
pub use pass_pictures::{
    legend_name, pass_pictures, stencil_colour, step_colour, write_pass_images, PassPicture,
};
pub use pictures::{error_image, mask_rgb, rgb, ErrorColours, ERROR_COLOURS};
pub use rows::{pareto_front, FrontPoint, Measured, ResultRow};
pub use sweep_files::{sweep_summary, write_sweep};
pub use table::{comparison_table, phase_lines};

use std::path::{Path, PathBuf};

/// Failures of the report layer.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    #[error("cannot create the output folder {path}: {source}")]
    CreateDir {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("cannot write {path}: {source}")]
    Write {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("cannot write {path}: {source}")]
    Image {
        path: PathBuf,
        #[source]
        source: image::ImageError,
    },
    #[error("cannot write {path}: it is a folder")]
    IsFolder { path: PathBuf },
    #[error("cannot write {path}: the file is read-only")]
    ReadOnly { path: PathBuf },
    #[error("{path}: only PNG images are written; give the file a .png name")]
    NotPng { path: PathBuf },
    #[error("cannot draw {path}: {message}")]
    Plot { path: PathBuf, message: String },
    #[error("JSON: {0}")]
    Json(#[from] serde_json::Error),
    #[error("no TrueType font to label plots and pictures; tried {}. Install the Debian package fonts-dejavu-core or set FIXEDFUNC_FONT to a .ttf file", .tried.iter().map(|p| p.display().to_string()).collect::<Vec<_>>().join(", "))]
    NoFont { tried: Vec<PathBuf> },
    #[error("{path} is not a usable TrueType font")]
    BadFont { path: PathBuf },
}

/// The files a report wrote, in the order written (paths inside the output folder).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Written {
    pub files: Vec<PathBuf>,
}

impl Written {
    fn push(&mut self, path: PathBuf) {
        self.files.push(path);
    }

    /// Whether a file of this bare name was written.
    pub fn contains(&self, name: &str) -> bool {
        self.files
            .iter()
            .any(|p| p.file_name().is_some_and(|n| n == name))
    }
}

/// Creates `dir` (and its parents) when missing.
fn ensure_dir(dir: &Path) -> Result<(), ReportError> {
    std::fs::create_dir_all(dir).map_err(|source| ReportError::CreateDir {
        path: dir.to_path_buf(),
        source,
    })
}

/// Writes `text` to `dir/name` ([`files::write_file`]) and records it.
fn write_text(
    dir: &Path,
    name: &str,
    text: &str,
    written: &mut Written,
) -> Result<(), ReportError> {
    let path = dir.join(name);
    files::write_file(&path, text.as_bytes())?;
    written.push(path);
    Ok(())
}

/// Saves a PNG to `dir/name` ([`files::save_png`]) and records it.
fn write_png<P, C>(
    dir: &Path,
    name: &str,
    img: &image::ImageBuffer<P, C>,
    written: &mut Written,
) -> Result<(), ReportError>
where
    P: image::PixelWithColorType,
    [P::Subpixel]: image::EncodableLayout,
    C: std::ops::Deref<Target = [P::Subpixel]>,
{
    let path = dir.join(name);
    files::save_png(img, &path)?;
    written.push(path);
    Ok(())
}

/// A plotters error as a report error about `path`.
fn plot_error(path: &Path) -> impl Fn(&dyn std::fmt::Display) -> ReportError + '_ {
    move |e| ReportError::Plot {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
}

/// The scene's polygon offset in words: `each technique's default polygon offset`, or the
/// one given and by whom (`polygon offset (1, 4) from the command line`).
fn offset_brief(s: &crate::scene::ShadowSettings) -> String {
    use crate::scene::OffsetSetting;
    match s.polygon_offset {
        OffsetSetting::TechniqueDefault => "each technique's default polygon offset".to_string(),
        OffsetSetting::Given { offset: None, by } => format!("no polygon offset (from the {by})"),
        OffsetSetting::Given {
            offset: Some(o),
            by,
        } => format!("polygon offset ({}, {}) from the {by}", o.factor, o.units),
    }
}
