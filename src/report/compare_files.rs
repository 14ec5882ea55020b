//! The files of a comparison, written into one folder: per measured row its image, mask
//! and error image, and its pass images (`SLUG-pass-NN-PASS-KIND.png` and
//! `SLUG-pass-legend.txt`, `pass_pictures`); the truth mask; `results.csv`, `objects.csv`
//! (the error by object, `objects`) and `results.json`; `accuracy_vs_time.svg`/`.png`;
//! `contact_sheet.png`; and last `report.html`, built from the list of what was written.
//! The CSVs, the JSON and the page each say what produced them (`provenance`). A
//! `report.html` already in the folder is removed before the first new file is written: a
//! run stopped half-way leaves new pictures and no page, never an old page that links new
//! pictures under its old names.

use std::path::Path;

use serde::Serialize;

use crate::scene::{LightKind, Scene};
use crate::study::{Comparison, RowCost, RowResult};

use super::csv::{line, opt};
use super::file_names::{
    RowFiles, CSV, HTML, JSON, OBJECTS_CSV, PLOT_PNG, PLOT_SVG, SHEET, TRUTH_MASK,
    VISIBILITY_PLOT_PNG, VISIBILITY_PLOT_SVG,
};
use super::pictures::{self, SheetLine};
use super::provenance::{self, ContextStrings, Provenance};
use super::{
    ensure_dir, html, objects, pass_pictures, plot, write_png, write_text, ReportError, ResultRow,
    Written,
};

/// Writes every file of the comparison into `dir` (created when missing). `scene_name`
/// names the scene on the page.
pub fn write_comparison(
    c: &Comparison,
    scene_name: &str,
    dir: &Path,
) -> Result<Written, ReportError> {
    ensure_dir(dir)?;
    super::files::remove_if_present(&dir.join(HTML))?;
    let rows = ResultRow::all(&c.rows, &c.scene);
    let produced = Provenance::of_this_process();
    let contexts = provenance::contexts(&rows);
    let mut written = Written::default();
    let truth_rgb = pictures::mask_rgb(&c.truth.mask);
    write_png(dir, TRUTH_MASK, &c.truth.mask.to_image(), &mut written)?;

    let mut pictures_of = Vec::new();
    let mut strips = Vec::new();
    for (row, result) in c.rows.iter().zip(&rows) {
        let Some(outcome) = row.outcome() else {
            continue;
        };
        let files = RowFiles::of(&row.slug());
        let image = pictures::rgb(&outcome.image);
        let mask = pictures::mask_rgb(&outcome.mask);
        let error = pictures::error_image(&outcome.mask, &c.truth.mask);
        write_png(dir, &files.image, &image, &mut written)?;
        write_png(dir, &files.mask, &outcome.mask.to_image(), &mut written)?;
        write_png(dir, &files.error, &error, &mut written)?;
        pictures_of.push((pictures::row_label(result), [image, mask, error]));
        if let Some(passes) = row.pass_images() {
            let prefix = format!("{}-pass-", row.slug());
            let (pictures, files) = pass_pictures::write_pass_images(passes, dir, &prefix)?;
            written.files.extend(files.files);
            strips.push(html::PassStrip {
                slug: row.slug(),
                passes: pass_pictures::strip(&pictures),
                legend: pass_pictures::legend_name(&prefix),
            });
        }
    }

    write_text(dir, CSV, &results_csv(c, &rows, &produced), &mut written)?;
    let objects = objects::objects_csv(&rows, &produced);
    write_text(dir, OBJECTS_CSV, &objects, &mut written)?;
    write_text(
        dir,
        JSON,
        &results_json(c, &rows, scene_name, &produced, &contexts)?,
        &mut written,
    )?;

    let svg = dir.join(PLOT_SVG);
    let png = plot::accuracy_vs_time(&rows, &svg)?;
    written.push(svg);
    write_png(dir, PLOT_PNG, &png, &mut written)?;
    // An area light: every row's visibility RMSE on one plot, soft and hard alike.
    if rows.iter().any(|r| {
        r.measured
            .as_ref()
            .is_some_and(|m| m.visibility_rmse.is_some())
    }) {
        let svg = dir.join(VISIBILITY_PLOT_SVG);
        let png = plot::visibility_vs_time(&rows, &svg)?;
        written.push(svg);
        write_png(dir, VISIBILITY_PLOT_PNG, &png, &mut written)?;
    }

    let mut lines = vec![SheetLine {
        label: "ground truth (ray-cast): shadow mask, and the colours of the error images"
            .to_string(),
        tiles: [None, Some(&truth_rgb), None],
    }];
    lines.extend(pictures_of.iter().map(|(label, [a, b, e])| SheetLine {
        label: label.clone(),
        tiles: [Some(a), Some(b), Some(e)],
    }));
    let size = (c.truth.mask.width, c.truth.mask.height);
    let title = format!(
        "{scene_name} · {}×{} · columns: image, shadow mask, error against the truth",
        size.0, size.1
    );
    let sheet = pictures::contact_sheet(&title, size, &lines, &dir.join(SHEET))?;
    write_png(dir, SHEET, &sheet, &mut written)?;

    let mut facts = scene_facts(&c.scene);
    facts.extend(provenance::facts(&produced, &contexts));
    let page = html::page(c, &rows, scene_name, &facts, &written, &strips);
    write_text(dir, HTML, &page, &mut written)?;
    Ok(written)
}

const CSV_HEADER: [&str; 35] = [
    "technique",
    "pipeline",
    "backend",
    "polygon_offset",
    "offset_source",
    "status",
    "skipped_because",
    "error_percent",
    "false_shadow",
    "missed_shadow",
    "coverage",
    "geometry_pixels",
    "band",
    "outside_band_error_percent",
    "outside_band_false_shadow",
    "outside_band_missed_shadow",
    "visibility_rmse",
    "visibility_max_abs",
    "penumbra_rmse",
    "ms_median",
    "ms_min",
    "ms_max",
    "steady_frames",
    "cold_ms",
    "passes",
    "programs_compiled",
    "maps_made",
    "pareto",
    "setup_ms",
    "frames_total_ms",
    "finish_ms",
    "gl_renderer",
    "gl_version",
    "fixedfunc_version",
    "command_line",
];

fn cost(result: &RowResult) -> Option<RowCost> {
    match result {
        RowResult::Measured { cost, .. } => Some(*cost),
        RowResult::Skipped { .. } => None,
    }
}

/// One line per row; numbers at full precision, empty fields where a row has none.
fn results_csv(c: &Comparison, rows: &[ResultRow], produced: &Provenance) -> String {
    let mut out = line(&CSV_HEADER);
    for (r, row) in rows.iter().zip(&c.rows) {
        let m = r.measured.as_ref();
        let k = cost(&row.result);
        out.push_str(&line(&[
            r.technique.to_string(),
            crate::render::pipeline_name(r.pipeline).to_string(),
            r.backend.name().to_string(),
            m.and_then(|m| m.offset.clone()).unwrap_or_default(),
            opt(m.and_then(|m| m.offset_source)),
            if m.is_some() { "measured" } else { "skipped" }.to_string(),
            r.skipped.clone().unwrap_or_default(),
            opt(m.map(|m| m.error_percent)),
            opt(m.map(|m| m.false_shadow)),
            opt(m.map(|m| m.missed_shadow)),
            opt(m.map(|m| m.coverage)),
            opt(m.map(|m| m.geometry_pixels)),
            opt(m.map(|m| m.band)),
            opt(m.map(|m| m.outside_band_error_percent)),
            opt(m.map(|m| m.outside_band_false_shadow)),
            opt(m.map(|m| m.outside_band_missed_shadow)),
            opt(m.and_then(|m| m.visibility_rmse)),
            opt(m.and_then(|m| m.visibility_max_abs)),
            opt(m.and_then(|m| m.penumbra_rmse)),
            opt(m.and_then(|m| m.ms_median)),
            opt(m.and_then(|m| m.ms_min)),
            opt(m.and_then(|m| m.ms_max)),
            opt(m.map(|m| m.steady_frames)),
            opt(m.map(|m| m.cold_ms)),
            opt(m.map(|m| m.passes)),
            opt(m.map(|m| m.programs_compiled)),
            opt(m.map(|m| m.maps_made)),
            r.pareto.to_string(),
            opt(k.map(|k| k.setup_ms)),
            opt(k.map(|k| k.frames_ms)),
            opt(k.map(|k| k.finish_ms)),
            m.map(|m| m.gl_renderer.clone()).unwrap_or_default(),
            m.map(|m| m.gl_version.clone()).unwrap_or_default(),
            produced.fixedfunc_version.to_string(),
            produced.command_line.clone(),
        ]));
    }
    out
}

#[derive(Serialize)]
struct JsonRow<'a> {
    #[serde(flatten)]
    row: &'a ResultRow,
    cost: Option<RowCost>,
}

#[derive(Serialize)]
struct JsonReport<'a> {
    produced_by: &'a Provenance,
    contexts: &'a [ContextStrings],
    scene: &'a str,
    facts: Vec<(String, String)>,
    width: u32,
    height: u32,
    frames: u32,
    truth_ms: f64,
    total_ms: f64,
    rows: Vec<JsonRow<'a>>,
}

fn results_json(
    c: &Comparison,
    rows: &[ResultRow],
    scene: &str,
    produced: &Provenance,
    contexts: &[ContextStrings],
) -> Result<String, ReportError> {
    let report = JsonReport {
        produced_by: produced,
        contexts,
        scene,
        facts: scene_facts(&c.scene),
        width: c.scene.image.width,
        height: c.scene.image.height,
        frames: c.frames,
        truth_ms: c.truth_ms,
        total_ms: c.total_ms,
        rows: rows
            .iter()
            .zip(&c.rows)
            .map(|(row, r)| JsonRow {
                row,
                cost: cost(&r.result),
            })
            .collect(),
    };
    Ok(serde_json::to_string_pretty(&report)? + "\n")
}

/// What the page says about the scene, as (what, value) lines.
pub(super) fn scene_facts(scene: &Scene) -> Vec<(String, String)> {
    let v = |p: glam::Vec3| format!("({}, {}, {})", p.x, p.y, p.z);
    let mut facts = vec![
        (
            "image".to_string(),
            format!("{}×{} pixels", scene.image.width, scene.image.height),
        ),
        (
            "camera".to_string(),
            format!(
                "eye {} looking at {}",
                v(scene.camera.eye),
                v(scene.camera.at)
            ),
        ),
    ];
    for (i, light) in scene.lights.iter().enumerate() {
        let kind = match light.kind {
            LightKind::Point => "point light".to_string(),
            LightKind::Spot { cutoff, .. } => format!("spot light, cutoff {cutoff}°"),
            LightKind::Directional {
                direction,
                angular_diameter,
            } => {
                if angular_diameter > 0.0 {
                    format!(
                        "sun along {}, {:.2}° across (hard mask from its centre; visibility from \
                     the whole disc)",
                        v(direction),
                        angular_diameter.to_degrees()
                    )
                } else {
                    format!("directional light along {}", v(direction))
                }
            }
            LightKind::Area { .. } => {
                "area light (hard mask from its centre; visibility from the whole rectangle)"
                    .to_string()
            }
        };
        facts.push((
            format!("light {i}"),
            format!(
                "{kind} at {} aimed at {}",
                v(light.view.eye),
                v(light.view.at)
            ),
        ));
    }
    for (i, o) in scene.objects.iter().enumerate() {
        let name = o.name.clone().unwrap_or_else(|| format!("object {i}"));
        let shape = format!("{:?}", o.shape);
        let shape = shape
            .split([' ', '{', '('])
            .next()
            .unwrap_or("")
            .to_lowercase();
        facts.push((
            name,
            format!(
                "{shape}, {} triangles at {}{}{}",
                o.mesh.triangle_count(),
                v(o.transform.translate),
                if o.casts { "" } else { ", casts no shadow" },
                if o.receives { "" } else { ", receives none" }
            ),
        ));
    }
    let s = &scene.shadow;
    facts.push((
        "shadow map".to_string(),
        format!(
            "{}² texels, {} depth, {}, {:?} precision, {:?} filter",
            s.map_size,
            super::heatmap::depth_label(s.depth),
            super::offset_brief(s),
            s.precision,
            s.filter
        ),
    ));
    facts
}
