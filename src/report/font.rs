//! The font plotters draws bitmap text with (ab_glyph): DejaVu Sans from the system, or the
//! file `FIXEDFUNC_FONT` names. Registered once per process under [`FAMILY`]; SVG files
//! only name the family and let the viewer pick its own sans-serif.

use std::path::PathBuf;
use std::sync::OnceLock;

use plotters::style::FontStyle;

use super::ReportError;

/// The family name plots ask for.
pub const FAMILY: &str = "sans-serif";

/// Where Debian (fonts-dejavu-core), Arch and Fedora put DejaVu Sans, then Liberation.
const CANDIDATES: &[&str] = &[
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
];

static REGISTERED: OnceLock<Result<PathBuf, FontProblem>> = OnceLock::new();

#[derive(Debug, Clone)]
enum FontProblem {
    Missing(Vec<PathBuf>),
    Bad(PathBuf),
}

/// Registers the font for bitmap text, once; returns the file used.
pub fn ensure() -> Result<PathBuf, ReportError> {
    REGISTERED
        .get_or_init(register)
        .clone()
        .map_err(|p| match p {
            FontProblem::Missing(tried) => ReportError::NoFont { tried },
            FontProblem::Bad(path) => ReportError::BadFont { path },
        })
}

fn register() -> Result<PathBuf, FontProblem> {
    let mut tried: Vec<PathBuf> = Vec::new();
    if let Some(p) = std::env::var_os("FIXEDFUNC_FONT") {
        tried.push(PathBuf::from(p));
    }
    tried.extend(CANDIDATES.iter().map(PathBuf::from));
    for path in &tried {
        let Ok(bytes) = std::fs::read(path) else {
            continue;
        };
        // plotters keeps a 'static reference: the bytes live for the process, read once.
        let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
        return plotters::style::register_font(FAMILY, FontStyle::Normal, bytes)
            .map(|()| path.clone())
            .map_err(|_| FontProblem::Bad(path.clone()));
    }
    Err(FontProblem::Missing(tried))
}
