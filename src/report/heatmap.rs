//! Bias heatmaps: one figure per depth format and pipeline, three panels over the same
//! polygon-offset grid (factor across, units up): all error, false shadow (acne: too
//! little offset) and missed shadow (peter-panning: too much), each as % of the truth's
//! geometry pixels. A panel's colour runs from white (0) to its colour at the panel's
//! largest value, by √(v / max) so that the small errors near the best cell still differ;
//! grids of at most 12 × 12 also print each value. The best cell is outlined in every
//! panel.

use crate::vocab::DepthBits;
use std::path::Path;

use image::RgbImage;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::render::pipeline_name;
use crate::study::{Cell, Surface, SurfaceResult, Sweep};

use super::{font, ReportError, ERROR_COLOURS};

/// Figure size in pixels.
pub const SIZE: (u32, u32) = (1500, 560);
const TEXT_LIMIT: usize = 12;

/// `16-bit`, `24-bit`, `32-bit float`.
pub fn depth_label(d: DepthBits) -> &'static str {
    match d {
        DepthBits::D16 => "16-bit",
        DepthBits::D24 => "24-bit",
        DepthBits::D32F => "32-bit float",
    }
}

/// `16`, `24`, `32f`: the `--depth-bits` spelling, used in file names.
pub fn depth_arg(d: DepthBits) -> &'static str {
    match d {
        DepthBits::D16 => "16",
        DepthBits::D24 => "24",
        DepthBits::D32F => "32f",
    }
}

/// What a panel shows.
#[derive(Clone, Copy)]
enum Panel {
    All,
    Acne,
    PeterPanning,
}

impl Panel {
    const ALL: [Panel; 3] = [Panel::All, Panel::Acne, Panel::PeterPanning];

    fn title(self) -> &'static str {
        match self {
            Panel::All => "all error %",
            Panel::Acne => "false shadow % (acne)",
            Panel::PeterPanning => "missed shadow % (peter-panning)",
        }
    }

    fn value(self, c: &Cell) -> f64 {
        let all = &c.metrics.all;
        let pct = |n: u64| {
            if all.pixels == 0 {
                0.0
            } else {
                100.0 * n as f64 / all.pixels as f64
            }
        };
        match self {
            Panel::All => all.wrong_percent,
            Panel::Acne => pct(all.false_shadow),
            Panel::PeterPanning => pct(all.missed_shadow),
        }
    }

    fn colour(self) -> [u8; 3] {
        match self {
            Panel::All => [90, 40, 120],
            Panel::Acne => ERROR_COLOURS.false_shadow,
            Panel::PeterPanning => ERROR_COLOURS.missed_shadow,
        }
    }
}

/// White → `to` by √t.
fn ramp(to: [u8; 3], t: f64) -> RGBColor {
    let s = t.clamp(0.0, 1.0).sqrt();
    let c = |k: usize| (255.0 + (f64::from(to[k]) - 255.0) * s).round() as u8;
    RGBColor(c(0), c(1), c(2))
}

/// The figure's title line.
pub fn title(sweep: &Sweep, surface: &Surface) -> String {
    let head = format!(
        "{} · {} depth · {} pipeline",
        sweep.technique,
        depth_label(surface.depth),
        pipeline_name(surface.pipeline)
    );
    match &surface.result {
        SurfaceResult::Measured { cells, best, .. } => {
            let b = &cells[*best];
            format!(
                "{head} — best: factor {}, units {} → error {:.2}% (false {}, missed {})",
                b.factor,
                b.units,
                b.metrics.all.wrong_percent,
                b.metrics.all.false_shadow,
                b.metrics.all.missed_shadow
            )
        }
        SurfaceResult::Skipped { reason } => format!("{head} — skipped: {reason}"),
    }
}

/// Writes the surface's heatmap as SVG to `svg` and returns the PNG picture; `None` for a
/// skipped surface.
pub fn heatmap(
    sweep: &Sweep,
    surface: &Surface,
    svg: &Path,
) -> Result<Option<RgbImage>, ReportError> {
    let SurfaceResult::Measured { cells, best, .. } = &surface.result else {
        return Ok(None);
    };
    font::ensure()?;
    let grid = Grid {
        factors: &sweep.factors,
        units: &sweep.units,
        cells,
        best: *best,
        title: title(sweep, surface),
    };
    let err = super::plot_error(svg);
    let mut text = String::new();
    draw(
        SVGBackend::with_string(&mut text, SIZE).into_drawing_area(),
        &grid,
    )
    .map_err(|e| err(&e))?;
    super::files::write_file(svg, text.as_bytes())?;
    let mut png = RgbImage::new(SIZE.0, SIZE.1);
    draw(
        BitMapBackend::with_buffer(&mut png, SIZE).into_drawing_area(),
        &grid,
    )
    .map_err(|e| err(&e))?;
    Ok(Some(png))
}

struct Grid<'a> {
    factors: &'a [f32],
    units: &'a [f32],
    cells: &'a [Cell],
    best: usize,
    title: String,
}

fn draw<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, g: &Grid<'_>) -> Result<(), String> {
    let e = |x: &dyn std::fmt::Display| x.to_string();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let body = root
        .titled(&g.title, (font::FAMILY, 20))
        .map_err(|x| e(&x))?;
    let panels = body.split_evenly((1, 3));
    for (area, panel) in panels.iter().zip(Panel::ALL) {
        draw_panel(area, g, panel)?;
    }
    root.present().map_err(|x| e(&x))?;
    Ok(())
}

fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    g: &Grid<'_>,
    panel: Panel,
) -> Result<(), String> {
    let e = |x: &dyn std::fmt::Display| x.to_string();
    let (nf, nu) = (g.factors.len() as i32, g.units.len() as i32);
    let values: Vec<f64> = g.cells.iter().map(|c| panel.value(c)).collect();
    let max = values.iter().copied().fold(0.0, f64::max);
    let mut chart = ChartBuilder::on(area)
        .caption(
            format!("{} (max {:.2})", panel.title(), max),
            (font::FAMILY, 17),
        )
        .margin(12)
        .x_label_area_size(46)
        .y_label_area_size(56)
        .build_cartesian_2d(-0.5..f64::from(nf) - 0.5, -0.5..f64::from(nu) - 0.5)
        .map_err(|x| e(&x))?;
    // Cell i sits on [i − ½, i + ½]; ticks at whole i are labelled with the i-th value.
    let label = |values: &[f32], v: &f64| {
        let i = v.round();
        if (v - i).abs() > 1e-6 || i < 0.0 {
            return String::new();
        }
        values
            .get(i as usize)
            .map_or(String::new(), |x| format!("{x}"))
    };
    let xl = |v: &f64| label(g.factors, v);
    let yl = |v: &f64| label(g.units, v);
    chart
        .configure_mesh()
        .disable_mesh()
        .x_labels(g.factors.len().min(16))
        .y_labels(g.units.len().min(16))
        .x_label_formatter(&xl)
        .y_label_formatter(&yl)
        .x_desc("polygon offset factor")
        .y_desc("polygon offset units")
        .label_style((font::FAMILY, 13))
        .axis_desc_style((font::FAMILY, 14))
        .draw()
        .map_err(|x| e(&x))?;
    let at = |i: usize| {
        let i = i as i32;
        (f64::from(i % nf.max(1)), f64::from(i / nf.max(1)))
    };
    let square = |(x, y): (f64, f64)| [(x - 0.5, y - 0.5), (x + 0.5, y + 0.5)];
    chart
        .draw_series(values.iter().enumerate().map(|(i, &v)| {
            let t = if max > 0.0 { v / max } else { 0.0 };
            Rectangle::new(square(at(i)), ramp(panel.colour(), t).filled())
        }))
        .map_err(|x| e(&x))?;
    if g.factors.len() <= TEXT_LIMIT && g.units.len() <= TEXT_LIMIT {
        chart
            .draw_series(values.iter().enumerate().map(|(i, &v)| {
                let t = if max > 0.0 { v / max } else { 0.0 };
                let ink = if t.sqrt() > 0.6 { WHITE } else { BLACK };
                Text::new(
                    format!("{v:.1}"),
                    at(i),
                    (font::FAMILY, 12)
                        .into_font()
                        .color(&ink)
                        .pos(Pos::new(HPos::Center, VPos::Center)),
                )
            }))
            .map_err(|x| e(&x))?;
    }
    chart
        .draw_series(std::iter::once(Rectangle::new(
            square(at(g.best)),
            RGBColor(0, 170, 80).stroke_width(4),
        )))
        .map_err(|x| e(&x))?;
    Ok(())
}
