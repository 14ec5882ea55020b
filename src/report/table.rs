//! The comparison as text for the terminal: one aligned line per row, skipped rows with
//! their reason, and where the study's time went.

use crate::render::pipeline_name;
use crate::study::{Comparison, RowResult};

use super::ResultRow;

const HEADER: [&str; 13] = [
    "technique",
    "pipeline",
    "offset",
    "error %",
    "false",
    "missed",
    "outside band %",
    "visibility RMSE",
    "ms/frame median [min–max]",
    "cold ms",
    "passes",
    "programs",
    "maps",
];

/// `a [b–c]`, or `a (cold only)`.
pub(super) fn ms_cell(r: &super::Measured) -> String {
    match (r.ms_median, r.ms_min, r.ms_max) {
        (Some(m), Some(lo), Some(hi)) => format!("{m:.2} [{lo:.2}–{hi:.2}]"),
        _ => format!("{:.2} (cold only)", r.cold_ms),
    }
}

/// The table `compare` prints; `*` marks the Pareto front.
pub fn comparison_table(rows: &[ResultRow]) -> String {
    let mut lines: Vec<Vec<String>> = vec![HEADER.iter().map(|s| s.to_string()).collect()];
    let mut skipped = Vec::new();
    for r in rows {
        let name = format!("{}{}", r.technique, if r.pareto { " *" } else { "" });
        match (&r.measured, &r.skipped) {
            (Some(m), _) => lines.push(vec![
                name,
                pipeline_name(r.pipeline).to_string(),
                m.offset_cell(),
                format!("{:.2}", m.error_percent),
                m.false_shadow.to_string(),
                m.missed_shadow.to_string(),
                format!("{:.2}", m.outside_band_error_percent),
                m.visibility_rmse
                    .map_or("—".to_string(), |r| format!("{r:.3}")),
                ms_cell(m),
                format!("{:.2}", m.cold_ms),
                m.passes.to_string(),
                m.programs_compiled.to_string(),
                m.maps_made.to_string(),
            ]),
            (None, reason) => skipped.push(format!(
                "skipped {} on {}: {}",
                r.technique,
                pipeline_name(r.pipeline),
                reason.as_deref().unwrap_or("not run")
            )),
        }
    }
    // Names (and the offset) left, numbers right.
    let mut out = aligned(&lines, 3, HeaderRule::Dashes);
    out.push_str(
        "* on the Pareto front: no other row is faster beyond doubt (all its frames quicker) \
         and as accurate, or as fast within the frames' spread and more accurate\n",
    );
    for s in skipped {
        out.push_str(&s);
        out.push('\n');
    }
    out
}

/// Where the study's wall time went: the truth, then each row's setup + frames + finish.
pub fn phase_lines(c: &Comparison) -> String {
    let mut out = format!(
        "time: {:.2} s in all; ground truth {:.0} ms\n",
        c.total_ms / 1e3,
        c.truth_ms
    );
    for row in &c.rows {
        if let RowResult::Measured { cost, .. } = &row.result {
            out.push_str(&format!(
                "  {:<22} {:<8} {:>8.0} ms = setup {:.0} + {} frames {:.0} + mask and scoring {:.0}\n",
                row.technique,
                pipeline_name(row.pipeline),
                cost.total_ms(),
                cost.setup_ms,
                c.frames,
                cost.frames_ms,
                cost.finish_ms
            ));
        }
    }
    out
}

/// Whether a rule of dashes follows the first line of an [`aligned`] table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum HeaderRule {
    Dashes,
    None,
}

/// `lines` as columns two spaces apart, each as wide as its widest cell: the first `left`
/// columns left-aligned (names), the others right-aligned (figures); a line each.
pub(super) fn aligned(lines: &[Vec<String>], left: usize, rule: HeaderRule) -> String {
    let columns = lines.first().map_or(0, Vec::len);
    let widths: Vec<usize> = (0..columns)
        .map(|c| {
            lines
                .iter()
                .map(|l| l.get(c).map_or(0, |t| t.chars().count()))
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    for (i, l) in lines.iter().enumerate() {
        let cells: Vec<String> = l
            .iter()
            .zip(&widths)
            .enumerate()
            .map(|(c, (text, &w))| {
                let pad = " ".repeat(w.saturating_sub(text.chars().count()));
                if c < left {
                    format!("{text}{pad}")
                } else {
                    format!("{pad}{text}")
                }
            })
            .collect();
        out.push_str(cells.join("  ").trim_end());
        out.push('\n');
        if i == 0 && rule == HeaderRule::Dashes {
            let width = widths.iter().sum::<usize>() + 2 * widths.len().saturating_sub(1);
            out.push_str(&"-".repeat(width));
            out.push('\n');
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::Backend;
    use crate::vocab::TechniqueId;

    #[test]
    fn skipped_rows_say_why_and_columns_align() {
        let measured = super::super::Measured {
            error_percent: 1.5,
            false_shadow: 10,
            missed_shadow: 2,
            coverage: 0,
            geometry_pixels: 800,
            band: 1,
            outside_band_error_percent: 0.25,
            outside_band_false_shadow: 2,
            outside_band_missed_shadow: 0,
            visibility_rmse: Some(0.0345),
            visibility_max_abs: Some(0.5),
            penumbra_rmse: None,
            ms_median: Some(2.0),
            ms_min: Some(1.5),
            ms_max: Some(3.0),
            steady_frames: 4,
            cold_ms: 40.0,
            typical_ms: 2.0,
            passes: 3,
            programs_compiled: 4,
            maps_made: 1,
            notes: Vec::new(),
            offset: Some("1,4".to_string()),
            offset_source: Some(crate::vocab::OffsetSource::Scene),
            gl_renderer: "llvmpipe".to_string(),
            gl_version: "3.3".to_string(),
            objects: Vec::new(),
        };
        let row = |t: TechniqueId, m: Option<super::super::Measured>| ResultRow {
            technique: t,
            summary: "",
            pipeline: crate::vocab::PipelineKind::Native,
            backend: Backend::Egl,
            pareto: m.is_some(),
            skipped: m
                .is_none()
                .then(|| "register combiners are not supported".to_string()),
            measured: m,
        };
        let text = comparison_table(&[
            row(TechniqueId::Dual8, Some(measured)),
            row(TechniqueId::Multidigit16, None),
        ]);
        assert!(text.contains("dual8 *"), "{text}");
        assert!(text.contains("1,4 (scene)"), "{text}");
        assert!(text.contains("2.00 [1.50–3.00]"), "{text}");
        assert!(
            text.contains("visibility RMSE") && text.contains("0.035"),
            "{text}"
        );
        assert!(
            text.contains("skipped multidigit16 on native: register combiners are not supported"),
            "{text}"
        );
        let lines: Vec<&str> = text.lines().collect();
        let col = |l: &str| l.find("native").or_else(|| l.find("pipeline"));
        assert_eq!(col(lines[0]), col(lines[2]), "{text}");
    }
}
