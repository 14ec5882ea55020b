//! A bias sweep as one HTML page, `index.html` in the sweep's folder: the best cell of
//! each depth format (its units also in the format's own depth steps), the truth and the
//! error colours, then a section per depth format and pipeline with, round by round, what
//! the round's best said (edges, refinement), its heatmap, and the grid of its cells —
//! each cell a thumbnail of its error image with links to its image, mask and error image,
//! the best cell outlined.
//!
//! **Names.** This file also holds the names of a sweep's files, the one list both sides
//! use: `sweep_files` and [`SweepPictures`] write under them and the page links to them.
//! A cell's pictures go in a folder per surface and round,
//! `cells/PIPELINE-DEPTH/roundN/f{factor}_u{units}.png` with `-mask.png` and
//! `-error.png` beside it (`file_names::RowFiles`, as a comparison's rows are named).
//!
//! **Complete or absent**, as a comparison's page: [`SweepPictures::begin`] removes the
//! folder's old page before the first picture is written, the page is written last, and
//! it links only files this run wrote ([`Written`]); every file goes through
//! `report::files` (temporary name, sync, rename). Inline CSS, no scripts, relative links:
//! the folder opens from disk.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use crate::render::pipeline_name;
use crate::study::{Axis, Cell, Edge, Refine, Round, Shot, Surface, SurfaceResult, Sweep, Verdict};
use crate::vocab::{DepthBits, PipelineKind};

use super::file_names::{RowFiles, TRUTH_MASK};
use super::heatmap::{depth_arg, depth_label};
use super::html::escape;
use super::pictures;
use super::{ensure_dir, write_png, ReportError, Written};

/// The page.
pub(super) const INDEX: &str = "index.html";
/// One line per cell of every round.
pub(super) const CSV: &str = "sweep.csv";
/// The rounds, cells, best cells and skipped surfaces.
pub(super) const JSON: &str = "sweep.json";

/// `emulate-24`: a surface in file and folder names, and the page's anchor.
fn surface_slug(pipeline: PipelineKind, depth: DepthBits) -> String {
    format!("{}-{}", pipeline_name(pipeline), depth_arg(depth))
}

/// Stem of a round's heatmap files: `heatmap-emulate-24` for the grid as given (round 1),
/// `heatmap-emulate-24-round2` for later rounds.
pub(super) fn heatmap_stem(pipeline: PipelineKind, depth: DepthBits, round: u32) -> String {
    let stem = format!("heatmap-{}", surface_slug(pipeline, depth));
    if round <= 1 {
        stem
    } else {
        format!("{stem}-round{round}")
    }
}

/// A cell's pictures, relative to the sweep's folder (with `/`, as links and as paths).
pub(super) fn cell_files(pipeline: PipelineKind, depth: DepthBits, cell: &Cell) -> RowFiles {
    RowFiles::of(&format!(
        "cells/{}/round{}/f{}_u{}",
        surface_slug(pipeline, depth),
        cell.round,
        cell.factor,
        cell.units
    ))
}

/// Whether `written` holds the file `name` (relative to `dir`).
fn has(written: &Written, dir: &Path, name: &str) -> bool {
    let path = dir.join(name);
    written.files.contains(&path)
}

/// Writes each cell's image, mask and error image as the sweep measures it (the study
/// does not keep them). The first failure is kept, later cells are not written, and
/// [`SweepPictures::finish`] returns it.
pub struct SweepPictures {
    dir: PathBuf,
    written: Written,
    failed: Option<ReportError>,
}

impl SweepPictures {
    /// Creates `dir` when missing and removes the page of an earlier run, so that no page
    /// ever links pictures of another run.
    pub fn begin(dir: &Path) -> Result<SweepPictures, ReportError> {
        ensure_dir(dir)?;
        super::files::remove_if_present(&dir.join(INDEX))?;
        Ok(SweepPictures {
            dir: dir.to_path_buf(),
            written: Written::default(),
            failed: None,
        })
    }

    /// Writes one cell's pictures.
    pub fn add(&mut self, shot: Shot<'_>) {
        if self.failed.is_none() {
            if let Err(e) = self.write(&shot) {
                self.failed = Some(e);
            }
        }
    }

    fn write(&mut self, shot: &Shot<'_>) -> Result<(), ReportError> {
        let files = cell_files(shot.pipeline, shot.depth, shot.cell);
        if let Some(folder) = self.dir.join(&files.image).parent() {
            ensure_dir(folder)?;
        }
        let (dir, w) = (&self.dir, &mut self.written);
        write_png(dir, &files.image, &pictures::rgb(shot.image), w)?;
        write_png(dir, &files.mask, &shot.mask.to_image(), w)?;
        let error = pictures::error_image(shot.mask, shot.truth);
        write_png(dir, &files.error, &error, w)
    }

    /// The pictures written, or the first failure.
    pub(super) fn finish(self) -> Result<Written, ReportError> {
        match self.failed {
            Some(e) => Err(e),
            None => Ok(self.written),
        }
    }
}

/// `(1, 4)`.
fn offset(c: &Cell) -> String {
    format!("({}, {})", c.factor, c.units)
}

/// `error 0.86% (false shadow 195, missed shadow 824)`.
fn error_brief(c: &Cell) -> String {
    let a = &c.metrics.all;
    format!(
        "error {:.2}% (false shadow {}, missed shadow {})",
        a.wrong_percent, a.false_shadow, a.missed_shadow
    )
}

fn list<T: ToString>(items: &[T]) -> String {
    items
        .iter()
        .map(|i| i.to_string())
        .collect::<Vec<_>>()
        .join(", ")
}

/// A spacing as a person reads it (f32's shortest form).
fn spacing(h: f64) -> String {
    (h as f32).to_string()
}

/// What a round's verdict says, and what the next round does with it (`last`: there is
/// none). Plain text; the page escapes it.
pub(super) fn verdict_text(cells: &[Cell], round: &Round, v: &Verdict, last: bool) -> String {
    let b = &cells[v.best];
    let mut out = if v.best == round.best {
        "it".to_string()
    } else {
        format!("the best so far, {} from round {},", offset(b), b.round)
    };
    let lowest: Vec<String> = v
        .at_lowest
        .iter()
        .map(|e| {
            let at = match e {
                Edge::LowestFactor | Edge::HighestFactor => b.factor,
                Edge::LowestUnits | Edge::HighestUnits => b.units,
            };
            format!("{e} at {at}, the lowest tried")
        })
        .collect();
    let place = match (v.open.is_empty(), lowest.is_empty()) {
        (true, true) => "lies inside".to_string(),
        (true, false) => format!("lies on {}", lowest.join(" and ")),
        (false, true) => format!("lies on {}", list(&v.open)),
        (false, false) => format!("lies on {} and on {}", list(&v.open), lowest.join(" and ")),
    };
    let mut facts = vec![place];
    for &a in &v.coarse {
        facts.push(format!(
            "{a} steps of {} are above the floor {}",
            spacing(axis_spacing(round, a)),
            spacing(a.floor())
        ));
    }
    let _ = write!(out, " {}", facts.join("; "));
    if v.settled() {
        out.push_str("; every step is at or under its floor: settled");
    } else if last {
        out.push_str(": the round limit ends the refinement here");
    } else {
        let mut next = Vec::new();
        if !v.open.is_empty() {
            next.push("moves past that side".to_string());
        }
        if !v.coarse.is_empty() {
            next.push(format!("halves the {} steps", list(&v.coarse)));
        }
        let _ = write!(out, ": round {} {}", round.number + 1, next.join(" and "));
    }
    out
}

/// A round's spacing on one axis.
fn axis_spacing(round: &Round, axis: Axis) -> f64 {
    match axis {
        Axis::Factor => round.factor.spacing(),
        Axis::Units => round.units.spacing(),
    }
}

/// `round 2: factor 0.5..1.5:3 × units 1..3:3 — best (1, 2), units = 4 LSB of 24-bit
/// depth: error …`, and the verdict when refining.
pub(super) fn round_line(depth: DepthBits, cells: &[Cell], round: &Round, last: bool) -> String {
    let b = &cells[round.best];
    let mut line = format!(
        "round {}: factor {} × units {} — best {}, units = {}: {}",
        round.number,
        round.factor,
        round.units,
        offset(b),
        depth.offset_units_in_steps(b.units),
        error_brief(b)
    );
    if let Some(v) = &round.verdict {
        line.push_str("; ");
        line.push_str(&verdict_text(cells, round, v, last));
    }
    line
}

/// What stopped a refinement short of settling, as warning lines (none when it settled
/// or was not asked for).
pub(super) fn limit_lines(refine: Option<Refine>, round: &Round) -> Vec<String> {
    let (Some(refine), Some(v)) = (refine, &round.verdict) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    if !v.open.is_empty() {
        out.push(format!(
            "warning: the round limit ({}) stopped the refinement with the best cell still on \
             the grid's edge ({}): a better offset may lie beyond it; raise --refine=ROUNDS or \
             start the grid there",
            refine.max_rounds,
            list(&v.open)
        ));
    }
    for &a in &v.coarse {
        let h = axis_spacing(round, a);
        out.push(format!(
            "note: the round limit ({}) stopped the refinement with the {a} steps ({}) still \
             above the floor {}",
            refine.max_rounds,
            spacing(h),
            spacing(a.floor())
        ));
    }
    out
}

/// The warnings of a measured surface: with `--refine` what the round limit left
/// unsettled; without it a best cell on a side of the grid (the best offset may lie
/// beyond it).
pub(super) fn warnings(refine: Option<Refine>, rounds: &[Round]) -> Vec<String> {
    let Some(last) = rounds.last() else {
        return Vec::new();
    };
    if refine.is_some() {
        return limit_lines(refine, last);
    }
    let sides = last.edges();
    if sides.is_empty() {
        return Vec::new();
    }
    let names: Vec<String> = sides.iter().map(|e| e.to_string()).collect();
    vec![format!(
        "warning: the best cell lies on the grid's edge ({}): a better offset may lie beyond \
         it; widen --factor/--units past that side, or run with --refine",
        names.join(", ")
    )]
}

/// How `--refine` works, in a sentence (for the page and the terminal).
pub(super) fn refine_rule(refine: Refine) -> String {
    format!(
        "Refined: up to {} rounds per depth format, each grid centred on the best cell so \
         far — the same steps while it lies on a side past which a better offset may lie, \
         half the steps while it lies inside (or at 0, the lowest tried) — until it lies \
         inside with steps of at most {} (factor) and {} (units)",
        refine.max_rounds,
        spacing(crate::study::FACTOR_FLOOR),
        spacing(crate::study::UNITS_FLOOR)
    )
}

/// The sweep page's own rules (after `html::BASE_STYLE`).
const STYLE: &str = "
h2{margin-top:32px}h3{font-size:16px;margin:22px 0 6px}
table.bests{width:100%}
.two{display:grid;grid-template-columns:1fr 2fr;gap:24px;align-items:start}
.two img,.heat img{width:100%;border:1px solid #dde0e8;background:#fff}
.note{font-size:14px;color:#8a4b00;margin:4px 0}
.grid{margin:8px 0 0}.grid td{text-align:center;vertical-align:top;padding:4px;border:1px solid #e6e8ee}
.grid th{font-weight:600;text-align:center}.grid th.u{text-align:right}
.grid img{width:88px;image-rendering:pixelated;display:block;margin:0 auto}
.grid .pct{font-size:12.5px;margin:2px 0}.grid .links{font-size:11.5px}
.grid td.rbest{box-shadow:inset 0 0 0 2px #7fbf9a}.grid td.best{box-shadow:inset 0 0 0 3px #1f9d57;background:#eefaf2}
.tag{display:inline-block;font-size:11px;padding:1px 6px;border-radius:8px;background:#1f9d57;color:#fff;margin-left:6px;vertical-align:1px}
";

/// A picture linked to the file itself (a click opens it full size), when written.
fn img(name: &str, alt: &str, written: &Written, dir: &Path) -> String {
    if has(written, dir, name) {
        format!(
            "<a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\" loading=\"lazy\"></a>",
            escape(name),
            escape(alt)
        )
    } else {
        String::new()
    }
}

/// A link to `name` reading `text`, when written; the bare text otherwise.
fn link(name: &str, text: &str, written: &Written, dir: &Path) -> String {
    if has(written, dir, name) {
        format!("<a href=\"{}\">{}</a>", escape(name), escape(text))
    } else {
        escape(text)
    }
}

/// `24-bit depth · emulate pipeline`.
fn surface_title(surface: &Surface) -> String {
    format!(
        "{} depth · {} pipeline",
        depth_label(surface.depth),
        pipeline_name(surface.pipeline)
    )
}

/// The page. `written` lists the files of the folder `dir` it links to.
pub(super) fn page(s: &Sweep, scene: &str, written: &Written, dir: &Path) -> String {
    let mut h = String::new();
    let _ = write!(
        h,
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <meta name=\"viewport\" content=\"width=device-width\">\
         <title>fixedfunc sweep-bias — {} — {}</title><style>{}{STYLE}</style></head><body>\n",
        escape(&s.technique.to_string()),
        escape(scene),
        super::html::BASE_STYLE
    );
    headline(&mut h, s, scene, dir, written);
    truth_and_legend(&mut h, written, dir);
    for surface in &s.surfaces {
        section(&mut h, s, surface, written, dir);
    }
    footer(&mut h, s, written, dir);
    h.push_str("</body></html>\n");
    h
}

fn headline(h: &mut String, s: &Sweep, scene: &str, dir: &Path, written: &Written) {
    let range = |v: &[f32]| match (v.first(), v.last()) {
        (Some(a), Some(b)) if v.len() > 1 => format!("{} values from {a} to {b}", v.len()),
        (Some(a), _) => format!("fixed at {a}"),
        _ => "none".to_string(),
    };
    let _ = writeln!(
        h,
        "<header><h1>Polygon offset for {}: a bias sweep</h1>\
         <p class=\"lead\">{} — factor {}, units {}; every cell re-makes the light's maps \
         with its offset and is scored against one ray-cast ground truth: error is the share \
         of geometry pixels whose shadow differs from it. {}.</p></header>",
        escape(&s.technique.to_string()),
        escape(scene),
        escape(&range(&s.factors)),
        escape(&range(&s.units)),
        escape(&match s.refine {
            Some(r) => refine_rule(r),
            None => "One round: the grid as given".to_string(),
        })
    );
    h.push_str(
        "<h2>Best offset per depth format</h2><table class=\"bests\"><tr>\
         <th class=\"name\">depth</th><th class=\"name\">pipeline</th><th>factor</th>\
         <th>units</th><th class=\"name\">units in depth steps</th><th>round</th>\
         <th>error %</th><th>false shadow</th><th>missed shadow</th><th class=\"name\">pictures</th>\
         <th class=\"name\">advice</th></tr>\n",
    );
    for surface in &s.surfaces {
        let name = format!(
            "<td class=\"name\"><a href=\"#{}\">{}</a></td><td class=\"name\">{}</td>",
            surface_slug(surface.pipeline, surface.depth),
            depth_label(surface.depth),
            pipeline_name(surface.pipeline)
        );
        match &surface.result {
            SurfaceResult::Measured {
                cells,
                rounds,
                best,
                ..
            } => {
                let b = &cells[*best];
                let a = &b.metrics.all;
                let _ = writeln!(
                    h,
                    "<tr>{name}<td>{}</td><td>{}</td><td class=\"name\">{}</td><td>{}</td>\
                     <td>{:.2}</td><td>{}</td><td>{}</td><td class=\"name\">{}</td><td class=\"name\">{}</td></tr>",
                    b.factor,
                    b.units,
                    escape(&surface.depth.offset_units_in_steps(b.units)),
                    b.round,
                    a.wrong_percent,
                    a.false_shadow,
                    a.missed_shadow,
                    cell_links(surface, b, written, dir),
                    escape(&advice(s.refine, rounds))
                );
            }
            SurfaceResult::Skipped { reason } => {
                let _ = writeln!(
                    h,
                    "<tr class=\"skip\">{name}<td class=\"name\" colspan=\"9\">skipped: {}</td></tr>",
                    escape(reason)
                );
            }
        }
    }
    h.push_str(
        "</table><p class=\"muted\">One unit of glPolygonOffset is two LSBs of a 16- or \
         24-bit depth buffer on llvmpipe and 2⁻²⁴ of a float one at depths in [0.5, 1). \
         False shadow: lit in the truth, shadowed by the technique (acne: too little offset). \
         Missed shadow: shadowed in the truth, lit by the technique (peter-panning: too much).</p>\n",
    );
}

/// The short advice of a surface's table row: settled, or what to widen.
fn advice(refine: Option<Refine>, rounds: &[Round]) -> String {
    let Some(last) = rounds.last() else {
        return String::new();
    };
    match (refine, &last.verdict) {
        (Some(_), Some(v)) if v.settled() => match rounds.len() {
            1 => "settled in the grid as given".to_string(),
            n => format!("settled after {n} rounds"),
        },
        (Some(_), Some(v)) if !v.open.is_empty() => format!(
            "round limit reached with the best on {}: widen past it",
            list(&v.open)
        ),
        (Some(_), Some(v)) => format!(
            "round limit reached with the {} steps above the floor",
            list(&v.coarse)
        ),
        // One round: its own best is the best.
        _ => match last.edges() {
            sides if sides.is_empty() => "inside the grid".to_string(),
            sides => format!("on {}: widen past it, or --refine", list(&sides)),
        },
    }
}

/// `image · mask · error` links of a cell.
fn cell_links(surface: &Surface, c: &Cell, written: &Written, dir: &Path) -> String {
    let f = cell_files(surface.pipeline, surface.depth, c);
    format!(
        "{} · {} · {}",
        link(&f.image, "image", written, dir),
        link(&f.mask, "mask", written, dir),
        link(&f.error, "error", written, dir)
    )
}

fn truth_and_legend(h: &mut String, written: &Written, dir: &Path) {
    let _ = writeln!(
        h,
        "<section class=\"two\"><div><h2>Ground truth</h2>{}\
         <p class=\"muted\">White lit, black shadowed (surfaces facing away from the light \
         included), grey background.</p></div><div><h2>Error colours</h2>\
         {}<p class=\"muted\">Each cell of a grid below shows its error image; \
         a click opens it full size, and the links under it open the cell's rendered image \
         and shadow mask. The best cell of all rounds is outlined in dark green and tagged, \
         each round's own best in light green.</p></div></section>",
        img(TRUTH_MASK, "ground-truth shadow mask", written, dir),
        super::html::error_legend(),
    );
}

fn section(h: &mut String, s: &Sweep, surface: &Surface, written: &Written, dir: &Path) {
    let _ = write!(
        h,
        "<section id=\"{}\"><h2>{}</h2>",
        surface_slug(surface.pipeline, surface.depth),
        escape(&surface_title(surface))
    );
    let (cells, rounds, best) = match &surface.result {
        SurfaceResult::Measured {
            cells,
            rounds,
            best,
            ..
        } => (cells, rounds, *best),
        SurfaceResult::Skipped { reason } => {
            let _ = writeln!(
                h,
                "<p class=\"note\">skipped: {}</p></section>",
                escape(reason)
            );
            return;
        }
    };
    let b = &cells[best];
    let _ = write!(
        h,
        "<p class=\"lead\">Best offset <b>{}</b>, units = {}, from round {}: {} — {}</p>",
        offset(b),
        escape(&surface.depth.offset_units_in_steps(b.units)),
        b.round,
        escape(&error_brief(b)),
        cell_links(surface, b, written, dir)
    );
    for w in warnings(s.refine, rounds) {
        let _ = write!(h, "<p class=\"note\">{}</p>", escape(&w));
    }
    for (i, round) in rounds.iter().enumerate() {
        let last = i + 1 == rounds.len();
        let stem = heatmap_stem(surface.pipeline, surface.depth, round.number);
        let (png, svg) = (format!("{stem}.png"), format!("{stem}.svg"));
        let _ = write!(
            h,
            "<h3>Round {}: factor {} × units {}</h3><p class=\"muted\">{}</p>\
             <div class=\"heat\">{}</div><p class=\"muted\">Heatmap: {} · {}</p>",
            round.number,
            escape(&round.factor.to_string()),
            escape(&round.units.to_string()),
            escape(&round_line(surface.depth, cells, round, last)),
            img(
                &png,
                &format!("heatmap of round {}", round.number),
                written,
                dir
            ),
            link(&png, &png, written, dir),
            link(&svg, &svg, written, dir)
        );
        grid(h, surface, cells, round, best, written, dir);
    }
    h.push_str("</section>\n");
}

/// The round's cells as a table: factor across, units up (as the heatmap).
fn grid(
    h: &mut String,
    surface: &Surface,
    cells: &[Cell],
    round: &Round,
    best: usize,
    written: &Written,
    dir: &Path,
) {
    let nf = round.factor.steps.max(1) as usize;
    let factors = round.factor.values();
    let units = round.units.values();
    h.push_str("<table class=\"grid\"><tr><th class=\"u\">units ╲ factor</th>");
    for f in &factors {
        let _ = write!(h, "<th>{f}</th>");
    }
    h.push_str("</tr>\n");
    for (u, value) in units.iter().enumerate().rev() {
        let _ = write!(
            h,
            "<tr><th class=\"u\">{value}<br><span class=\"muted\">{}</span></th>",
            escape(&surface.depth.offset_units_in_steps(*value))
        );
        for f in 0..nf {
            let i = round.cells.start + u * nf + f;
            let Some(c) = cells.get(i) else {
                h.push_str("<td></td>");
                continue;
            };
            let files = cell_files(surface.pipeline, surface.depth, c);
            let class = if i == best {
                " class=\"best\""
            } else if i == round.best {
                " class=\"rbest\""
            } else {
                ""
            };
            let _ = write!(
                h,
                "<td{class}>{}<div class=\"pct\">{:.2}%{}</div><div class=\"links\">{}</div></td>",
                img(
                    &files.error,
                    &format!("error image of offset {}", offset(c)),
                    written,
                    dir
                ),
                c.metrics.all.wrong_percent,
                if i == best {
                    "<span class=\"tag\">best</span>"
                } else {
                    ""
                },
                cell_links(surface, c, written, dir)
            );
        }
        h.push_str("</tr>\n");
    }
    h.push_str("</table>\n");
}

fn footer(h: &mut String, s: &Sweep, written: &Written, dir: &Path) {
    let mut links = Vec::new();
    for name in [CSV, JSON] {
        if has(written, dir, name) {
            links.push(link(name, name, written, dir));
        }
    }
    let _ = writeln!(
        h,
        "<h2>Files and time</h2><p class=\"muted\">Also in this folder: {} (a line per cell \
         of every round, with its round), and each round's heatmap as SVG. The sweep took \
         {:.1} s: ground truth {:.0} ms (once).</p>",
        links.join(", "),
        s.total_ms / 1e3,
        s.truth_ms
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_of_heatmaps_and_cell_pictures() {
        let (p, d) = (PipelineKind::Emulate, DepthBits::D24);
        assert_eq!(heatmap_stem(p, d, 1), "heatmap-emulate-24");
        assert_eq!(heatmap_stem(p, d, 3), "heatmap-emulate-24-round3");
        let cell = Cell {
            factor: 0.5,
            units: -1.0,
            round: 2,
            metrics: crate::metrics::Metrics {
                all: Default::default(),
                outside_band: Default::default(),
                band: 1,
                extra_coverage: 0,
                visibility_rmse: None,
            },
            ms: 0.0,
        };
        let f = cell_files(p, DepthBits::D32F, &cell);
        assert_eq!(f.image, "cells/emulate-32f/round2/f0.5_u-1.png");
        assert_eq!(f.mask, "cells/emulate-32f/round2/f0.5_u-1-mask.png");
        assert_eq!(f.error, "cells/emulate-32f/round2/f0.5_u-1-error.png");
    }
}
