//! The names of a comparison's files, the one list both sides use: `compare_files` writes
//! under these names and `html` links to them, so the page and the folder cannot disagree.
//! A leaf of `report` (it imports nothing): `compare_files` uses `html` and this list,
//! `html` uses this list only, so no import runs back.

/// File names of a row's pictures.
pub(super) struct RowFiles {
    pub image: String,
    pub mask: String,
    pub error: String,
}

impl RowFiles {
    pub fn of(slug: &str) -> RowFiles {
        RowFiles {
            image: format!("{slug}.png"),
            mask: format!("{slug}-mask.png"),
            error: format!("{slug}-error.png"),
        }
    }
}

pub(super) const TRUTH_MASK: &str = "truth-mask.png";
pub(super) const PLOT_SVG: &str = "accuracy_vs_time.svg";
pub(super) const PLOT_PNG: &str = "accuracy_vs_time.png";
/// Area lights only: visibility RMSE against time, every technique.
pub(super) const VISIBILITY_PLOT_SVG: &str = "visibility_vs_time.svg";
pub(super) const VISIBILITY_PLOT_PNG: &str = "visibility_vs_time.png";
pub(super) const SHEET: &str = "contact_sheet.png";
pub(super) const CSV: &str = "results.csv";
pub(super) const JSON: &str = "results.json";
/// One line per row × object: each object's share of the row's error.
pub(super) const OBJECTS_CSV: &str = "objects.csv";
pub(super) const HTML: &str = "report.html";
