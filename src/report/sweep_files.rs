//! The files of a bias sweep: `heatmap-PIPELINE-DEPTH.svg`/`.png` per measured surface,
//! `sweep.csv` (one line per cell), `sweep.json` (the grid, the best cell of each surface,
//! skipped surfaces with their reason, timings); and the text `sweep-bias` prints.

use std::path::Path;

use serde::Serialize;

use crate::render::pipeline_name;
use crate::stats::Summary;
use crate::study::{edges, Cell, SurfaceResult, Sweep};
use crate::vocab::TechniqueId;

use super::csv::line;
use super::heatmap::{self, depth_arg, depth_label};
use super::{ensure_dir, write_png, write_text, ReportError, Written};

/// Stem of a surface's heatmap files.
pub fn heatmap_stem(
    pipeline: crate::vocab::PipelineKind,
    depth: crate::vocab::DepthBits,
) -> String {
    format!("heatmap-{}-{}", pipeline_name(pipeline), depth_arg(depth))
}

/// Writes the sweep's files into `dir` (created when missing).
pub fn write_sweep(s: &Sweep, dir: &Path) -> Result<Written, ReportError> {
    ensure_dir(dir)?;
    let mut written = Written::default();
    for surface in &s.surfaces {
        let stem = heatmap_stem(surface.pipeline, surface.depth);
        let svg = dir.join(format!("{stem}.svg"));
        if let Some(png) = heatmap::heatmap(s, surface, &svg)? {
            written.push(svg);
            write_png(dir, &format!("{stem}.png"), &png, &mut written)?;
        }
    }
    write_text(dir, "sweep.csv", &sweep_csv(s), &mut written)?;
    write_text(dir, "sweep.json", &sweep_json(s)?, &mut written)?;
    Ok(written)
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
    error_percent: f64,
    false_shadow: u64,
    missed_shadow: u64,
    coverage: u64,
    geometry_pixels: u64,
    outside_band_error_percent: f64,
    ms: f64,
}

impl JsonCell {
    fn of(c: &Cell) -> JsonCell {
        let a = &c.metrics.all;
        JsonCell {
            factor: c.factor,
            units: c.units,
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
struct JsonSurface {
    pipeline: &'static str,
    depth_bits: &'static str,
    skipped: Option<String>,
    setup_ms: Option<f64>,
    cell_ms: Option<Summary>,
    best: Option<JsonCell>,
    cells: Vec<JsonCell>,
}

#[derive(Serialize)]
struct JsonSweep {
    technique: TechniqueId,
    factors: Vec<f32>,
    units: Vec<f32>,
    truth_ms: f64,
    total_ms: f64,
    surfaces: Vec<JsonSurface>,
}

fn sweep_json(s: &Sweep) -> Result<String, ReportError> {
    let surfaces = s
        .surfaces
        .iter()
        .map(|surface| {
            let (pipeline, depth_bits) =
                (pipeline_name(surface.pipeline), depth_arg(surface.depth));
            match &surface.result {
                SurfaceResult::Measured {
                    cells,
                    best,
                    setup_ms,
                } => JsonSurface {
                    pipeline,
                    depth_bits,
                    skipped: None,
                    setup_ms: Some(*setup_ms),
                    cell_ms: cell_times(cells),
                    best: cells.get(*best).map(JsonCell::of),
                    cells: cells.iter().map(JsonCell::of).collect(),
                },
                SurfaceResult::Skipped { reason } => JsonSurface {
                    pipeline,
                    depth_bits,
                    skipped: Some(reason.clone()),
                    setup_ms: None,
                    cell_ms: None,
                    best: None,
                    cells: Vec::new(),
                },
            }
        })
        .collect();
    let json = JsonSweep {
        technique: s.technique,
        factors: s.factors.clone(),
        units: s.units.clone(),
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

/// What `sweep-bias` prints: per surface its best cell (or why it was skipped) and the
/// cost of a cell, then the time of the truth and of the whole sweep.
pub fn sweep_summary(s: &Sweep) -> String {
    let mut out = format!(
        "{}: {} factors × {} units per depth format\n",
        s.technique,
        s.factors.len(),
        s.units.len()
    );
    for surface in &s.surfaces {
        let head = format!(
            "{:<12} {:<7}",
            depth_label(surface.depth),
            pipeline_name(surface.pipeline)
        );
        match &surface.result {
            SurfaceResult::Measured {
                cells,
                best,
                setup_ms,
            } => {
                let b = &cells[*best];
                let a = &b.metrics.all;
                let t = cell_times(cells);
                out.push_str(&format!(
                    "{head} best offset ({}, {}), units = {}: error {:.2}% (false shadow {}, missed shadow {}) · cell {:.1} ms median, setup {:.0} ms\n",
                    b.factor,
                    b.units,
                    surface.depth.offset_units_in_steps(b.units),
                    a.wrong_percent,
                    a.false_shadow,
                    a.missed_shadow,
                    t.map_or(0.0, |t| t.median),
                    setup_ms
                ));
                let sides = edges(*best, s.factors.len(), s.units.len());
                if !sides.is_empty() {
                    let names: Vec<String> = sides.iter().map(|e| e.to_string()).collect();
                    out.push_str(&format!(
                        "{head} warning: the best cell lies on the grid's edge ({}): a better \
                         offset may lie beyond it; widen --factor/--units past that side\n",
                        names.join(", ")
                    ));
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
