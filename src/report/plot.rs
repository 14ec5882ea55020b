//! `accuracy_vs_time`: error % of geometry pixels (y) against ms per frame (x), one point per
//! measured technique × pipeline (emulate filled circles, native hollow squares), each
//! labelled, and the Pareto front drawn as the staircase through its points: the frontier
//! below and left of which no measured row lies. Time starts at 0 so that distances
//! read as ratios on the time axis; the error axis is logarithmic. Drawn once for SVG and once for PNG by the same function.

use crate::vocab::PipelineKind;
use std::path::Path;

use image::RgbImage;
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::render::pipeline_name;

use super::{font, ReportError, ResultRow};

/// Plot size in pixels.
pub const SIZE: (u32, u32) = (960, 600);

struct Point {
    label: String,
    ms: f64,
    error: f64,
    pipeline: PipelineKind,
    pareto: bool,
}

fn points(rows: &[ResultRow]) -> Vec<Point> {
    rows.iter()
        .filter_map(|r| {
            r.measured.as_ref().map(|m| Point {
                label: r.technique.to_string(),
                ms: m.typical_ms,
                error: m.error_percent,
                pipeline: r.pipeline,
                pareto: r.pareto,
            })
        })
        .collect()
}

/// Writes the plot as SVG to `svg` and returns the PNG picture.
pub fn accuracy_vs_time(rows: &[ResultRow], svg: &Path) -> Result<RgbImage, ReportError> {
    font::ensure()?;
    let pts = points(rows);
    let err = super::plot_error(svg);
    let mut text = String::new();
    draw(
        SVGBackend::with_string(&mut text, SIZE).into_drawing_area(),
        &pts,
    )
    .map_err(|e| err(&e))?;
    super::files::write_file(svg, text.as_bytes())?;
    let mut png = RgbImage::new(SIZE.0, SIZE.1);
    draw(
        BitMapBackend::with_buffer(&mut png, SIZE).into_drawing_area(),
        &pts,
    )
    .map_err(|e| err(&e))?;
    Ok(png)
}

const EMULATE: RGBColor = RGBColor(0, 90, 200);
const NATIVE: RGBColor = RGBColor(200, 80, 0);
const FRONT: RGBColor = RGBColor(0, 150, 70);

fn colour(kind: PipelineKind) -> RGBColor {
    match kind {
        PipelineKind::Emulate => EMULATE,
        PipelineKind::Native => NATIVE,
    }
}

/// Emulate labels above their point, native ones below, so a technique's two points
/// (often at nearly the same error) keep readable labels.
fn label_dy(kind: PipelineKind) -> i32 {
    match kind {
        PipelineKind::Emulate => -18,
        PipelineKind::Native => 4,
    }
}

fn draw<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, pts: &[Point]) -> Result<(), String> {
    let e = |x: &dyn std::fmt::Display| x.to_string();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let max_ms = pts.iter().map(|p| p.ms).fold(0.0, f64::max).max(0.1) * 1.25;
    // Errors span orders of magnitude (a self-shadowing 8-bit map near 90%, a good map
    // under 1%): the error axis is logarithmic, and an error of 0 sits on its floor.
    let floor = pts
        .iter()
        .map(|p| p.error)
        .filter(|&e| e > 0.0)
        .fold(1.0, f64::min)
        .max(0.01)
        / 2.0;
    let max_err = pts.iter().map(|p| p.error).fold(1.0, f64::max) * 2.0;
    let y = |err: f64| err.max(floor);
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Shadow error against time per frame",
            (font::FAMILY, 24).into_font(),
        )
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..max_ms, (floor..max_err).log_scale())
        .map_err(|x| e(&x))?;
    chart
        .configure_mesh()
        .x_desc("ms per frame (median of the steady frames)")
        .y_desc("error, % of geometry pixels (log scale)")
        .y_label_formatter(&|v: &f64| {
            if *v >= 1.0 {
                format!("{v:.0}")
            } else {
                format!("{v}")
            }
        })
        .label_style((font::FAMILY, 14))
        .axis_desc_style((font::FAMILY, 16))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(|x| e(&x))?;

    let mut front: Vec<&Point> = pts.iter().filter(|p| p.pareto).collect();
    front.sort_by(|a, b| a.ms.total_cmp(&b.ms));
    if !front.is_empty() {
        // Staircase: from each front point right to the next one's time, then down.
        let mut stairs = Vec::new();
        for (i, p) in front.iter().enumerate() {
            stairs.push((p.ms, y(p.error)));
            if let Some(next) = front.get(i + 1) {
                stairs.push((next.ms, y(p.error)));
            }
        }
        if let Some(last) = front.last() {
            stairs.push((max_ms, y(last.error)));
        }
        chart
            .draw_series(LineSeries::new(stairs, FRONT.stroke_width(3)))
            .map_err(|x| e(&x))?
            .label("Pareto front")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], FRONT.stroke_width(3)));
    }
    for kind in [PipelineKind::Emulate, PipelineKind::Native] {
        let c = colour(kind);
        let series: Vec<&Point> = pts.iter().filter(|p| p.pipeline == kind).collect();
        if series.is_empty() {
            continue;
        }
        let name = format!("{} pipeline", pipeline_name(kind));
        let at = |p: &&Point| (p.ms, y(p.error));
        match kind {
            PipelineKind::Emulate => {
                chart
                    .draw_series(series.iter().map(|p| Circle::new(at(p), 6, c.filled())))
                    .map_err(|x| e(&x))?
                    .label(name)
                    .legend(move |(x, y)| Circle::new((x + 10, y), 6, c.filled()));
            }
            PipelineKind::Native => {
                let square = [(-6, -6), (6, 6)];
                chart
                    .draw_series(series.iter().map(|p| {
                        EmptyElement::at(at(p)) + Rectangle::new(square, c.stroke_width(2))
                    }))
                    .map_err(|x| e(&x))?
                    .label(name)
                    .legend(move |(x, y)| {
                        EmptyElement::at((x + 10, y)) + Rectangle::new(square, c.stroke_width(2))
                    });
            }
        }
        chart
            .draw_series(series.iter().map(|p| {
                EmptyElement::at((p.ms, y(p.error)))
                    + Text::new(
                        p.label.clone(),
                        (9, label_dy(kind)),
                        (font::FAMILY, 15).into_font().color(&c),
                    )
            }))
            .map_err(|x| e(&x))?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .label_font((font::FAMILY, 14))
        .background_style(WHITE.mix(0.9))
        .border_style(RGBColor(200, 200, 200))
        .draw()
        .map_err(|x| e(&x))?;
    root.present().map_err(|x| e(&x))?;
    Ok(())
}
