//! `accuracy_vs_time`: error % of geometry pixels (y) against ms per frame (x), one point per
//! measured technique × pipeline (emulate filled circles, native hollow squares), each
//! labelled, and the Pareto front drawn as the staircase through its points: the frontier
//! below and left of which no measured row lies. Both axes are logarithmic: equal
//! distances are equal ratios, so techniques a hundred times apart in time (a soft shadow
//! beside a hard one) or in error stay readable. Tick labels carry two significant digits.
//! Drawn once for SVG and once for PNG by the same function.
//!
//! `visibility_vs_time` is the same plot with the visibility RMSE against an area light's
//! truth on the y axis ([`Accuracy::VisibilityRmse`]): soft and hard techniques together,
//! its own Pareto front computed on that error.
//!
//! **Labels never collide** ([`place_labels`]): each label takes the first of a list of
//! places around its point (emulate above, native below first; then the other side, then
//! further out) whose box overlaps no label placed before it, no point's marker and stays
//! inside the plot; when none is free, the place that overlaps least. Boxes are measured
//! with the font the label is drawn in.

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

/// Which error a plot puts on its y axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Accuracy {
    /// Error % of the hard mask (the rows' own Pareto front).
    ErrorPercent,
    /// Visibility RMSE against an area light's truth (rows without one are left out; the
    /// front is computed on it).
    VisibilityRmse,
}

impl Accuracy {
    fn caption(self) -> &'static str {
        match self {
            Accuracy::ErrorPercent => "Shadow error against time per frame",
            Accuracy::VisibilityRmse => "Visibility error against time per frame (soft light)",
        }
    }

    fn y_desc(self) -> &'static str {
        match self {
            Accuracy::ErrorPercent => "error, % of geometry pixels (log scale)",
            Accuracy::VisibilityRmse => "visibility RMSE against the truth (log scale)",
        }
    }

    /// The smallest error the axis shows, and the error axis's least top.
    fn axis_floor_and_top(self) -> (f64, f64) {
        match self {
            Accuracy::ErrorPercent => (0.01, 1.0),
            Accuracy::VisibilityRmse => (0.001, 0.1),
        }
    }
}

fn points(rows: &[ResultRow], accuracy: Accuracy) -> Vec<Point> {
    let error = |m: &super::Measured| match accuracy {
        Accuracy::ErrorPercent => Some(m.error_percent),
        Accuracy::VisibilityRmse => m.visibility_rmse,
    };
    let measured: Vec<(&ResultRow, &super::Measured, f64)> = rows
        .iter()
        .filter_map(|r| {
            let m = r.measured.as_ref()?;
            Some((r, m, error(m)?))
        })
        .collect();
    // The visibility plot's own front: the rows' `pareto` weighs the error %.
    let front: Vec<usize> = match accuracy {
        Accuracy::ErrorPercent => Vec::new(),
        Accuracy::VisibilityRmse => {
            let at: Vec<Option<super::FrontPoint>> = measured
                .iter()
                .map(|(_, m, e)| {
                    Some(super::FrontPoint {
                        error: *e,
                        ..super::FrontPoint::of(m)
                    })
                })
                .collect();
            super::pareto_front(&at)
        }
    };
    measured
        .iter()
        .enumerate()
        .map(|(i, (r, m, error))| Point {
            label: r.technique.to_string(),
            ms: m.typical_ms,
            error: *error,
            pipeline: r.pipeline,
            pareto: match accuracy {
                Accuracy::ErrorPercent => r.pareto,
                Accuracy::VisibilityRmse => front.contains(&i),
            },
        })
        .collect()
}

/// Writes the plot as SVG to `svg` and returns the PNG picture.
pub fn accuracy_vs_time(rows: &[ResultRow], svg: &Path) -> Result<RgbImage, ReportError> {
    plot(rows, svg, Accuracy::ErrorPercent)
}

/// The visibility-RMSE plot of an area-light comparison, as SVG to `svg`; the PNG picture.
pub fn visibility_vs_time(rows: &[ResultRow], svg: &Path) -> Result<RgbImage, ReportError> {
    plot(rows, svg, Accuracy::VisibilityRmse)
}

fn plot(rows: &[ResultRow], svg: &Path, accuracy: Accuracy) -> Result<RgbImage, ReportError> {
    font::ensure()?;
    let pts = points(rows, accuracy);
    let err = super::plot_error(svg);
    let mut text = String::new();
    draw(
        SVGBackend::with_string(&mut text, SIZE).into_drawing_area(),
        &pts,
        accuracy,
    )
    .map_err(|e| err(&e))?;
    super::files::write_file(svg, text.as_bytes())?;
    let mut png = RgbImage::new(SIZE.0, SIZE.1);
    draw(
        BitMapBackend::with_buffer(&mut png, SIZE).into_drawing_area(),
        &pts,
        accuracy,
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

/// How many label heights a label may move away from its point before it gives up on a
/// free place.
const STEPS_OUT: i32 = 12;

/// The legend's size in pixels at most (width, height), kept clear of labels.
const LEGEND: (i32, i32) = (200, 90);

/// A box in pixels: left, top, right, bottom.
type PixelBox = (i32, i32, i32, i32);

fn overlap(a: PixelBox, b: PixelBox) -> i64 {
    let w = (a.2.min(b.2) - a.0.max(b.0)).max(0);
    let h = (a.3.min(b.3) - a.1.max(b.1)).max(0);
    i64::from(w) * i64::from(h)
}

/// Where each label goes, as its top-left offset from its point: `at` the points in
/// pixels, `size` each label's (width, height), `above` whether it prefers above its point
/// (emulate) or below (native), `area` the plot's box, `keep_clear` boxes no label may
/// cover (the legend). Greedy, in order: the first free place among the candidates, else
/// the least overlapping one.
fn place_labels(
    at: &[(i32, i32)],
    size: &[(i32, i32)],
    above: &[bool],
    area: PixelBox,
    keep_clear: &[PixelBox],
) -> Vec<(i32, i32)> {
    const MARKER: i32 = 7;
    let markers: Vec<PixelBox> = at
        .iter()
        .map(|&(x, y)| (x - MARKER, y - MARKER, x + MARKER, y + MARKER))
        .collect();
    let mut placed: Vec<PixelBox> = Vec::new();
    let mut offsets = Vec::new();
    for (i, (&(x, y), &(w, h))) in at.iter().zip(size).enumerate() {
        let (up, down) = (-h - 4, 4);
        let first = if above[i] { up } else { down };
        let mut candidates = Vec::new();
        for step in 0..STEPS_OUT {
            let far = step * (h + 2);
            let ups = up - far;
            let downs = down + far;
            let (a, b) = if above[i] { (ups, downs) } else { (downs, ups) };
            candidates.extend([(9, a), (9, b), (-9 - w, a), (-9 - w, b)]);
        }
        let cost = |&(dx, dy): &(i32, i32)| {
            let b = (x + dx, y + dy, x + dx + w, y + dy + h);
            let outside = i64::from(b.0 < area.0 || b.1 < area.1 || b.2 > area.2 || b.3 > area.3)
                * i64::from(w * h);
            placed
                .iter()
                .chain(&markers)
                .chain(keep_clear)
                .map(|&o| overlap(b, o))
                .sum::<i64>()
                + outside
        };
        let best = candidates
            .iter()
            .copied()
            .find(|c| cost(c) == 0)
            .or_else(|| candidates.iter().copied().min_by_key(cost))
            .unwrap_or((9, first));
        placed.push((x + best.0, y + best.1, x + best.0 + w, y + best.1 + h));
        offsets.push(best);
    }
    offsets
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    pts: &[Point],
    accuracy: Accuracy,
) -> Result<(), String> {
    let e = |x: &dyn std::fmt::Display| x.to_string();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let max_ms = pts.iter().map(|p| p.ms).fold(0.0, f64::max).max(0.1) * 1.5;
    let min_ms = pts
        .iter()
        .map(|p| p.ms)
        .filter(|&ms| ms > 0.0)
        .fold(max_ms, f64::min)
        / 1.5;
    // Errors span orders of magnitude (a self-shadowing 8-bit map near 90%, a good map
    // under 1%): the error axis is logarithmic, and an error of 0 sits on its floor.
    let (least, top) = accuracy.axis_floor_and_top();
    let floor = pts
        .iter()
        .map(|p| p.error)
        .filter(|&e| e > 0.0)
        .fold(top, f64::min)
        .max(least)
        / 2.0;
    let max_err = pts.iter().map(|p| p.error).fold(top, f64::max) * 2.0;
    let y = |err: f64| err.max(floor);
    let mut chart = ChartBuilder::on(&root)
        .caption(accuracy.caption(), (font::FAMILY, 24).into_font())
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(64)
        .build_cartesian_2d((min_ms..max_ms).log_scale(), (floor..max_err).log_scale())
        .map_err(|x| e(&x))?;
    chart
        .configure_mesh()
        .x_desc("ms per frame (median of the steady frames, log scale)")
        .y_desc(accuracy.y_desc())
        .x_label_formatter(&|v: &f64| tick_label(*v))
        .y_label_formatter(&|v: &f64| tick_label(*v))
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
            stairs.push((p.ms.max(min_ms), y(p.error)));
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
        let at = |p: &&Point| (p.ms.max(min_ms), y(p.error));
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
    }
    // Labels last, placed around their points so that none collides.
    let label_font = (font::FAMILY, 15).into_font();
    let label_style: TextStyle = label_font.clone().into();
    let at: Vec<(i32, i32)> = pts
        .iter()
        .map(|p| chart.backend_coord(&(p.ms.max(min_ms), y(p.error))))
        .collect();
    let mut sizes = Vec::new();
    for p in pts {
        let (w, h) = root
            .estimate_text_size(&p.label, &label_style)
            .map_err(|x| e(&x))?;
        sizes.push((w as i32, h as i32));
    }
    let above: Vec<bool> = pts
        .iter()
        .map(|p| p.pipeline == PipelineKind::Emulate)
        .collect();
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let area = (xs.start, ys.start, xs.end, ys.end);
    // The legend's box in the upper right (three entries of the label font and a margin).
    let legend = (xs.end - LEGEND.0, ys.start, xs.end, ys.start + LEGEND.1);
    let offsets = place_labels(&at, &sizes, &above, area, &[legend]);
    for (((p, &(x, y0)), &(dx, dy)), &(w, h)) in pts.iter().zip(&at).zip(&offsets).zip(&sizes) {
        // A label moved away from its point is tied to it by a thin line to its near edge.
        if dy < -h - 8 || dy > 8 {
            let end_y = if dy < 0 { y0 + dy + h } else { y0 + dy };
            let end_x = if dx < 0 { x + dx + w } else { x + dx };
            root.draw(&PathElement::new(
                vec![(x, y0), (end_x, end_y)],
                colour(p.pipeline).mix(0.5).stroke_width(1),
            ))
            .map_err(|x| e(&x))?;
        }
        root.draw(&Text::new(
            p.label.clone(),
            (x + dx, y0 + dy),
            label_font.clone().color(&colour(p.pipeline)),
        ))
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

/// A tick value with two significant digits and no trailing zeros: 0.30000000000000004
/// → "0.3", 0.05 → "0.05", 250 → "250", 1500 → "1500".
fn tick_label(v: f64) -> String {
    if !v.is_finite() || v <= 0.0 {
        return format!("{v}");
    }
    let decimals = (1 - v.log10().floor() as i32).max(0) as usize;
    let text = format!("{v:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_labels_have_two_significant_digits() {
        for (v, label) in [
            (0.30000000000000004, "0.3"),
            (0.05, "0.05"),
            (0.043, "0.043"),
            (0.0004, "0.0004"),
            (1.0, "1"),
            (2.5, "2.5"),
            (250.0, "250"),
            (1500.0, "1500"),
        ] {
            assert_eq!(tick_label(v), label, "{v}");
        }
    }

    #[test]
    fn labels_of_crowded_points_do_not_collide_or_leave_the_plot() {
        // Eight techniques × two pipelines at nearly the same place, as a compare on a
        // scene where every map technique lands near 1% makes them.
        let mut at = Vec::new();
        let mut above = Vec::new();
        for i in 0..16 {
            at.push((300 + (i % 4) * 6, 300 + (i / 4) * 5));
            above.push(i % 2 == 0);
        }
        let size = vec![(80, 15); at.len()];
        let area = (60, 40, 900, 540);
        let legend = (700, 40, 900, 130);
        let offsets = place_labels(&at, &size, &above, area, &[legend]);
        let boxes: Vec<PixelBox> = at
            .iter()
            .zip(&offsets)
            .map(|(&(x, y), &(dx, dy))| (x + dx, y + dy, x + dx + 80, y + dy + 15))
            .collect();
        for (i, a) in boxes.iter().enumerate() {
            assert!(a.0 >= area.0 && a.1 >= area.1 && a.2 <= area.2 && a.3 <= area.3);
            assert_eq!(overlap(*a, legend), 0);
            for b in &boxes[i + 1..] {
                assert_eq!(overlap(*a, *b), 0, "{a:?} and {b:?} collide");
            }
        }
        // A lone point keeps its preferred place: emulate above-right, native below-right.
        assert_eq!(
            place_labels(&[(400, 300)], &[(80, 15)], &[true], area, &[]),
            vec![(9, -19)]
        );
        assert_eq!(
            place_labels(&[(400, 300)], &[(80, 15)], &[false], area, &[]),
            vec![(9, 4)]
        );
    }
}
