//! The files of a bias sweep: per measured surface and round a heatmap
//! (`heatmap-PIPELINE-DEPTH.svg`/`.png` for the grid as given,
//! `heatmap-PIPELINE-DEPTH-roundN.*` for later rounds), each cell's image, mask and error
//! image (written as the sweep goes, by `sweep_page::SweepPictures`), the truth mask,
//! `sweep.csv` (one line per cell of every round, with its round), `sweep.json` (the
//! rounds, the grid, the best cell of each surface, skipped surfaces with their reason,
//! timings), and last the page `index.html`; and the text `sweep-bias` prints. Units are
//! given also in the depth steps of each surface's format
//! (`DepthBits::offset_units_in_steps`, the one source of that conversion).

use std::path::Path;

use serde::Serialize;

use crate::render::pipeline_name;
use crate::stats::Summary;
use crate::study::{Cell, Edge, Round, Surface, SurfaceResult, Sweep, Verdict};
use crate::vocab::{DepthBits, TechniqueId};

use super::csv::line;
use super::file_names::TRUTH_MASK;
use super::heatmap::{self, depth_arg, depth_label};
use super::sweep_page::{self, heatmap_stem, SweepPictures, CSV, INDEX, JSON};
use super::{write_png, write_text, ReportError, Written};

/// Writes the sweep's files into `dir` after the cells' `pictures`: the heatmaps, the
/// truth mask, the CSV and JSON, and last the page. `scene` names the scene on the page.
pub fn write_sweep(
    s: &Sweep,
    scene: &str,
    dir: &Path,
    pictures: SweepPictures,
) -> Result<Written, ReportError> {
    let mut written = pictures.finish()?;
    for surface in &s.surfaces {
        let SurfaceResult::Measured { rounds, .. } = &surface.result else {
            continue;
        };
        for round in rounds {
            let (view, view_surface) = round_view(s, surface, round);
            let stem = heatmap_stem(surface.pipeline, surface.depth, round.number);
            let svg = dir.join(format!("{stem}.svg"));
            if let Some(png) = heatmap::heatmap(&view, &view_surface, &svg)? {
                written.push(svg);
                write_png(dir, &format!("{stem}.png"), &png, &mut written)?;
            }
        }
    }
    write_png(dir, TRUTH_MASK, &s.truth.mask.to_image(), &mut written)?;
    write_text(dir, CSV, &sweep_csv(s), &mut written)?;
    write_text(dir, JSON, &sweep_json(s)?, &mut written)?;
    let page = sweep_page::page(s, scene, &written, dir);
    write_text(dir, INDEX, &page, &mut written)?;
    Ok(written)
}

/// One round of a surface as a sweep of its own (its grid, its cells, its best), the
/// shape a heatmap draws.
fn round_view(s: &Sweep, surface: &Surface, round: &Round) -> (Sweep, Surface) {
    let (cells, setup_ms) = match &surface.result {
        SurfaceResult::Measured {
            cells, setup_ms, ..
        } => (cells[round.cells.clone()].to_vec(), *setup_ms),
        SurfaceResult::Skipped { .. } => (Vec::new(), 0.0),
    };
    let start = round.cells.start;
    let own = Round {
        cells: 0..cells.len(),
        best: round.best - start,
        verdict: None,
        ..round.clone()
    };
    let view = Sweep {
        technique: s.technique,
        factors: round.factor.values(),
        units: round.units.values(),
        surfaces: Vec::new(),
        truth: s.truth.clone(),
        truth_ms: s.truth_ms,
        total_ms: s.total_ms,
        refine: None,
    };
    let surface = Surface {
        depth: surface.depth,
        pipeline: surface.pipeline,
        result: SurfaceResult::Measured {
            best: own.best,
            rounds: vec![own],
            cells,
            setup_ms,
        },
    };
    (view, surface)
}

fn percent(n: u64, of: u64) -> f64 {
    if of == 0 {
        0.0
    } else {
        100.0 * n as f64 / of as f64
    }
}

fn sweep_csv(s: &Sweep) -> String {
    let mut out = line(&[
        "technique",
        "pipeline",
        "depth_bits",
        "factor",
        "units",
        "error_percent",
        "false_shadow",
        "missed_shadow",
        "false_shadow_percent",
        "missed_shadow_percent",
        "coverage",
        "geometry_pixels",
        "outside_band_error_percent",
        "cell_ms",
        "round",
        "units_in_depth_steps",
        "best",
    ]);
    for surface in &s.surfaces {
        let SurfaceResult::Measured { cells, best, .. } = &surface.result else {
            continue;
        };
        for (i, c) in cells.iter().enumerate() {
            let a = &c.metrics.all;
            out.push_str(&line(&[
                s.technique.to_string(),
                pipeline_name(surface.pipeline).to_string(),
                depth_arg(surface.depth).to_string(),
                c.factor.to_string(),
                c.units.to_string(),
                a.wrong_percent.to_string(),
                a.false_shadow.to_string(),
                a.missed_shadow.to_string(),
                percent(a.false_shadow, a.pixels).to_string(),
                percent(a.missed_shadow, a.pixels).to_string(),
                a.coverage.to_string(),
                a.pixels.to_string(),
                c.metrics.outside_band.wrong_percent.to_string(),
                c.ms.to_string(),
                c.round.to_string(),
                surface.depth.offset_units_in_steps(c.units),
                (i == *best).to_string(),
            ]));
        }
    }
    out
}

#[derive(Serialize)]
struct JsonCell {
    factor: f32,
    units: f32,
    /// The units as the depth distance they make in the surface's format.
    units_in_depth_steps: String,
    /// The round the cell was measured in (1: the grid as given).
    round: u32,
    error_percent: f64,
    false_shadow: u64,
    missed_shadow: u64,
    coverage: u64,
    geometry_pixels: u64,
    outside_band_error_percent: f64,
    ms: f64,
}

impl JsonCell {
    fn of(c: &Cell, depth: DepthBits) -> JsonCell {
        let a = &c.metrics.all;
        JsonCell {
            factor: c.factor,
            units: c.units,
            units_in_depth_steps: depth.offset_units_in_steps(c.units),
            round: c.round,
            error_percent: a.wrong_percent,
            false_shadow: a.false_shadow,
            missed_shadow: a.missed_shadow,
            coverage: a.coverage,
            geometry_pixels: a.pixels,
            outside_band_error_percent: c.metrics.outside_band.wrong_percent,
            ms: c.ms,
        }
    }
}

#[derive(Serialize)]
struct JsonRound<'a> {
    round: u32,
    /// `A..B:steps`, as `--factor` takes it.
    factor: String,
    units: String,
    factors: Vec<f32>,
    units_values: Vec<f32>,
    /// The round's cells: `cells[first .. first + count]` of the surface.
    first: usize,
    count: usize,
    /// The round's own best cell.
    best: JsonCell,
    /// The sides of the round's grid its own best lies on.
    edges: Vec<Edge>,
    /// With `--refine`: where the best cell so far (`verdict.best`, an index into the
    /// surface's `cells`) lies on this grid.
    verdict: Option<&'a Verdict>,
    settled: Option<bool>,
}

#[derive(Serialize)]
struct JsonSurface<'a> {
    pipeline: &'static str,
    depth_bits: &'static str,
    skipped: Option<String>,
    setup_ms: Option<f64>,
    cell_ms: Option<Summary>,
    /// The best cell over all rounds.
    best: Option<JsonCell>,
    rounds: Vec<JsonRound<'a>>,
    /// Warnings as `sweep-bias` prints them: a best on the edge, a round limit.
    warnings: Vec<String>,
    cells: Vec<JsonCell>,
}

#[derive(Serialize)]
struct JsonRefine {
    max_rounds: u32,
    factor_floor: f64,
    units_floor: f64,
}

#[derive(Serialize)]
struct JsonSweep<'a> {
    technique: TechniqueId,
    /// The grid as given (round 1).
    factors: Vec<f32>,
    units: Vec<f32>,
    refine: Option<JsonRefine>,
    truth_ms: f64,
    total_ms: f64,
    surfaces: Vec<JsonSurface<'a>>,
}

fn json_round<'a>(depth: DepthBits, cells: &[Cell], r: &'a Round) -> JsonRound<'a> {
    JsonRound {
        round: r.number,
        factor: r.factor.to_string(),
        units: r.units.to_string(),
        factors: r.factor.values(),
        units_values: r.units.values(),
        first: r.cells.start,
        count: r.cells.len(),
        best: JsonCell::of(&cells[r.best], depth),
        edges: r.edges(),
        verdict: r.verdict.as_ref(),
        settled: r.verdict.as_ref().map(Verdict::settled),
    }
}

fn sweep_json(s: &Sweep) -> Result<String, ReportError> {
    let surfaces = s
        .surfaces
        .iter()
        .map(|surface| {
            let (pipeline, depth_bits) =
                (pipeline_name(surface.pipeline), depth_arg(surface.depth));
            let depth = surface.depth;
            match &surface.result {
                SurfaceResult::Measured {
                    cells,
                    rounds,
                    best,
                    setup_ms,
                } => JsonSurface {
                    pipeline,
                    depth_bits,
                    skipped: None,
                    setup_ms: Some(*setup_ms),
                    cell_ms: cell_times(cells),
                    best: cells.get(*best).map(|c| JsonCell::of(c, depth)),
                    rounds: rounds.iter().map(|r| json_round(depth, cells, r)).collect(),
                    warnings: sweep_page::warnings(s.refine, rounds),
                    cells: cells.iter().map(|c| JsonCell::of(c, depth)).collect(),
                },
                SurfaceResult::Skipped { reason } => JsonSurface {
                    pipeline,
                    depth_bits,
                    skipped: Some(reason.clone()),
                    setup_ms: None,
                    cell_ms: None,
                    best: None,
                    rounds: Vec::new(),
                    warnings: Vec::new(),
                    cells: Vec::new(),
                },
            }
        })
        .collect();
    let json = JsonSweep {
        technique: s.technique,
        factors: s.factors.clone(),
        units: s.units.clone(),
        refine: s.refine.map(|r| JsonRefine {
            max_rounds: r.max_rounds,
            factor_floor: crate::study::FACTOR_FLOOR,
            units_floor: crate::study::UNITS_FLOOR,
        }),
        truth_ms: s.truth_ms,
        total_ms: s.total_ms,
        surfaces,
    };
    Ok(serde_json::to_string_pretty(&json)? + "\n")
}

/// Median, min and max of the cells' times. The first cell also makes the session's
/// programs, so it is left out when there are others.
fn cell_times(cells: &[Cell]) -> Option<Summary> {
    let ms: Vec<f64> = cells.iter().map(|c| c.ms).collect();
    Summary::of(if ms.len() > 1 { &ms[1..] } else { &ms })
}

/// What `sweep-bias` prints: per surface (with `--refine`, each round's best cell and
/// what it said first) its best cell, its units in the format's depth steps, the cost of
/// a cell and any warning (or why it was skipped); then the time of the truth and of the
/// whole sweep.
pub fn sweep_summary(s: &Sweep) -> String {
    let mut out = format!(
        "{}: {} factors × {} units per depth format\n",
        s.technique,
        s.factors.len(),
        s.units.len()
    );
    if let Some(r) = s.refine {
        out.push_str(&sweep_page::refine_rule(r));
        out.push('\n');
    }
    for surface in &s.surfaces {
        let head = format!(
            "{:<12} {:<7}",
            depth_label(surface.depth),
            pipeline_name(surface.pipeline)
        );
        match &surface.result {
            SurfaceResult::Measured {
                cells,
                rounds,
                best,
                setup_ms,
            } => {
                if s.refine.is_some() {
                    for (i, round) in rounds.iter().enumerate() {
                        let last = i + 1 == rounds.len();
                        let line = sweep_page::round_line(surface.depth, cells, round, last);
                        out.push_str(&format!("{head} {line}\n"));
                    }
                }
                let b = &cells[*best];
                let a = &b.metrics.all;
                let t = cell_times(cells);
                let from = if s.refine.is_some() {
                    format!(" from round {}", b.round)
                } else {
                    String::new()
                };
                out.push_str(&format!(
                    "{head} best offset ({}, {}){from}, units = {}: error {:.2}% (false shadow {}, missed shadow {}) · cell {:.1} ms median, setup {:.0} ms\n",
                    b.factor,
                    b.units,
                    surface.depth.offset_units_in_steps(b.units),
                    a.wrong_percent,
                    a.false_shadow,
                    a.missed_shadow,
                    t.map_or(0.0, |t| t.median),
                    setup_ms
                ));
                for w in sweep_page::warnings(s.refine, rounds) {
                    out.push_str(&format!("{head} {w}\n"));
                }
            }
            SurfaceResult::Skipped { reason } => {
                out.push_str(&format!("{head} skipped: {reason}\n"));
            }
        }
    }
    out.push_str(&format!(
        "time: {:.2} s in all; ground truth {:.0} ms (once)\n",
        s.total_ms / 1e3,
        s.truth_ms
    ));
    out
}
