//! `fixedfunc compare` end to end on real EGL contexts (llvmpipe), at 96×96 with few frames:
//! its rows carry exactly `render`'s figures, its page refers only to files it wrote, and a
//! combination a pipeline cannot run is skipped and reported instead of failing the run.

use fixedfunc::vocab::{PipelineKind, PolygonOffset, TechniqueId};
use std::collections::HashMap;
use std::path::Path;
use std::process::{Command, Output};

use fixedfunc::render::{render, ImageSize, RenderOptions};
use fixedfunc::scene::{OffsetSetting, Scene};
use fixedfunc::study::{self, CompareSpec};

fn fixedfunc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .args(args)
        .output()
        .expect("run fixedfunc")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

fn arg(p: &Path) -> &str {
    p.to_str().expect("temporary paths are UTF-8")
}

fn json(path: &Path) -> serde_json::Value {
    let s = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&s).expect("valid JSON")
}

fn row<'a>(
    report: &'a serde_json::Value,
    technique: &str,
    pipeline: &str,
) -> &'a serde_json::Value {
    report["rows"]
        .as_array()
        .expect("rows")
        .iter()
        .find(|r| r["technique"] == technique && r["pipeline"] == pipeline)
        .unwrap_or_else(|| panic!("no row {technique} {pipeline}"))
}

/// (error % as printed, false shadow, missed shadow) from `render`'s figures line.
fn render_line(stdout: &str) -> (String, u64, u64) {
    let line = stdout
        .lines()
        .find(|l| l.contains(" · error "))
        .expect("figures line");
    let after = |key: &str| -> &str {
        let i = line.find(key).unwrap_or_else(|| panic!("{key} in {line}")) + key.len();
        &line[i..]
    };
    let pct = after("error ").split('%').next().unwrap_or("").to_string();
    let num = |key: &str| -> u64 {
        after(key)
            .split(|c: char| !c.is_ascii_digit())
            .next()
            .and_then(|s| s.parse().ok())
            .unwrap_or_else(|| panic!("{key} in {line}"))
    };
    (pct, num("false shadow "), num("missed shadow "))
}

/// CSV rows as header → field maps (fields here hold no quotes or commas).
/// One CSV line's fields as RFC 4180 quotes them (a quoted field may hold commas and
/// doubled quotes; the report's fields hold no line breaks).
fn csv_fields(line: &str) -> Vec<String> {
    let mut fields = vec![String::new()];
    let (mut quoted, mut chars) = (false, line.chars().peekable());
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                chars.next();
                fields.last_mut().expect("a field").push('"');
            }
            ('"', _) => quoted = !quoted,
            (',', false) => fields.push(String::new()),
            (c, _) => fields.last_mut().expect("a field").push(c),
        }
    }
    fields
}

fn csv_rows(path: &Path) -> Vec<HashMap<String, String>> {
    let s = std::fs::read_to_string(path).expect("results.csv");
    let mut lines = s.lines();
    let header = csv_fields(lines.next().expect("header"));
    lines
        .map(|l| {
            let fields = csv_fields(l);
            assert_eq!(fields.len(), header.len(), "{l}");
            header.iter().cloned().zip(fields).collect()
        })
        .collect()
}

#[test]
fn a_compare_row_has_exactly_the_figures_of_a_render_of_the_same_technique() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("report");
    let common = [
        "--size",
        "96x96",
        "--map-size",
        "64",
        "--frames",
        "2",
        "--offset",
        "1,4",
    ];
    let mut args = vec![
        "compare",
        "--techniques",
        "none,depth-compare",
        "--pipeline",
        "emulate",
        "--out",
        arg(&out),
    ];
    args.extend(common);
    let run = fixedfunc(&args);
    assert!(run.status.success(), "{}", text(&run.stderr));

    let img = dir.path().join("render.png");
    let mask = dir.path().join("render-mask.png");
    let mut args = vec![
        "render",
        "--technique",
        "depth-compare",
        "--pipeline",
        "emulate",
        "--out",
        arg(&img),
        "--mask",
        arg(&mask),
    ];
    args.extend(common);
    let single = fixedfunc(&args);
    assert!(single.status.success(), "{}", text(&single.stderr));
    let (pct, false_shadow, missed_shadow) = render_line(&text(&single.stdout));

    let report = json(&out.join("results.json"));
    let m = &row(&report, "depth-compare", "emulate")["measured"];
    assert_eq!(
        format!("{:.2}", m["error_percent"].as_f64().expect("error %")),
        pct
    );
    assert_eq!(m["false_shadow"].as_u64(), Some(false_shadow));
    assert_eq!(m["missed_shadow"].as_u64(), Some(missed_shadow));
    assert!(
        false_shadow + missed_shadow > 0,
        "a 96×96 shadow map render has some error; the comparison must not be vacuous"
    );
    // The masks agree pixel for pixel, and the CSV carries the JSON's numbers.
    let a = image::open(&mask).expect("render mask").to_luma8();
    let b = image::open(out.join("depth-compare-emulate-mask.png"))
        .expect("compare mask")
        .to_luma8();
    assert_eq!(a, b, "compare's mask differs from render's");
    let csv = csv_rows(&out.join("results.csv"));
    let line = csv
        .iter()
        .find(|r| r["technique"] == "depth-compare" && r["pipeline"] == "emulate")
        .expect("CSV row");
    assert_eq!(line["false_shadow"], false_shadow.to_string());
    assert_eq!(line["missed_shadow"], missed_shadow.to_string());
    assert_eq!(
        line["error_percent"].parse::<f64>().ok(),
        m["error_percent"].as_f64()
    );
    // What produced the numbers: the version, the command line, the GL strings.
    let produced = &report["produced_by"];
    assert_eq!(
        produced["fixedfunc_version"].as_str(),
        Some(env!("CARGO_PKG_VERSION"))
    );
    let command = produced["command_line"].as_str().expect("command line");
    assert!(
        command.contains("compare --techniques none,depth-compare"),
        "{command}"
    );
    let contexts = report["contexts"].as_array().expect("contexts");
    assert!(
        !contexts.is_empty()
            && contexts.iter().all(|c| c["renderer"]
                .as_str()
                .is_some_and(|r| r.contains("llvmpipe"))),
        "{contexts:?}"
    );
    assert!(line["gl_renderer"].contains("llvmpipe"), "{line:?}");
    assert_eq!(line["command_line"], command);
    let page = std::fs::read_to_string(out.join("report.html")).expect("page");
    assert!(page.contains("produced by") && page.contains("llvmpipe"));
    // The offset the command line gave, and where it came from, in every form.
    assert_eq!(line["polygon_offset"], "1,4");
    assert_eq!(line["offset_source"], "command line");
    assert_eq!(m["offset_source"], "command-line");
    assert!(
        text(&single.stdout).contains("offset 1,4 (command line)"),
        "{}",
        text(&single.stdout)
    );
}

#[test]
fn library_compare_rows_equal_library_renders() {
    let mut scene = Scene::default_scene();
    scene.shadow.polygon_offset = OffsetSetting::command_line(Some(PolygonOffset {
        factor: 2.0,
        units: 4.0,
    }));
    let size = Some(ImageSize {
        width: 80,
        height: 64,
    });
    let spec = CompareSpec {
        techniques: vec![TechniqueId::Dual8],
        pipelines: vec![PipelineKind::Emulate, PipelineKind::Native],
        backend: fixedfunc::gpu::Backend::Egl,
        frames: 2,
        size,
        passes: fixedfunc::study::PassStrips::Without,
    };
    let c = study::compare(&scene, &spec, |_| {}).expect("compare");
    assert_eq!(c.rows.len(), 2);
    for row in &c.rows {
        let got = row.outcome().expect("dual8 runs on both pipelines");
        let want = render(
            &scene,
            &RenderOptions {
                pipeline: row.pipeline,
                technique: Some(TechniqueId::Dual8),
                size,
                frames: 2,
                ..RenderOptions::default()
            },
        )
        .expect("render");
        assert_eq!(got.metrics, want.metrics, "{:?}", row.pipeline);
        assert_eq!(got.mask, want.mask, "{:?}", row.pipeline);
        let (g, w) = (got.figures(), want.figures());
        assert_eq!(
            (
                g.wrong_percent,
                g.false_shadow,
                g.missed_shadow,
                g.passes,
                g.programs,
                g.maps_made
            ),
            (
                w.wrong_percent,
                w.false_shadow,
                w.missed_shadow,
                w.passes,
                w.programs,
                w.maps_made
            )
        );
    }
}

/// Every `src="…"` and `href="…"` value of the page.
fn references(html: &str) -> Vec<String> {
    let mut refs = Vec::new();
    for key in ["src=\"", "href=\""] {
        let mut rest = html;
        while let Some(i) = rest.find(key) {
            rest = &rest[i + key.len()..];
            let end = rest.find('"').expect("closing quote");
            refs.push(rest[..end].to_string());
            rest = &rest[end..];
        }
    }
    refs
}

#[test]
fn the_page_refers_only_to_files_it_wrote_and_skips_what_a_pipeline_cannot_run() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("nested").join("report");
    let run = fixedfunc(&[
        "compare",
        "--techniques",
        "none,multidigit16",
        "--pipeline",
        "both",
        "--size",
        "96x96",
        "--frames",
        "2",
        "--out",
        arg(&out),
    ]);
    assert!(run.status.success(), "{}", text(&run.stderr));
    let stdout = text(&run.stdout);
    assert!(
        stdout.contains("skipped multidigit16 on native") && stdout.contains("not supported"),
        "{stdout}"
    );

    let html = std::fs::read_to_string(out.join("report.html")).expect("report.html");
    let refs = references(&html);
    assert!(refs.len() >= 10, "pictures and links: {refs:?}");
    for r in &refs {
        assert!(
            !r.contains('/') && !r.contains(':') && !r.contains('\\'),
            "`{r}` is not a file in the report folder"
        );
        assert!(
            out.join(r).is_file(),
            "the page names {r}, which is missing"
        );
    }
    for needed in [
        "accuracy_vs_time.svg",
        "truth-mask.png",
        "none-emulate.png",
        "none-native-mask.png",
        "multidigit16-emulate-error.png",
        "results.csv",
        "results.json",
        "contact_sheet.png",
    ] {
        assert!(refs.iter().any(|r| r == needed), "the page omits {needed}");
    }
    // Every picture opens full size: it is the target of a link to itself.
    for picture in html.split("<img src=\"").skip(1) {
        let name = picture.split('"').next().unwrap_or_default();
        assert!(
            html.contains(&format!("<a href=\"{name}\"><img src=\"{name}\"")),
            "{name} is shown without a link to itself"
        );
    }
    assert!(!html.contains("<script"), "no scripts");
    assert!(
        !html.contains("multidigit16-native"),
        "no pictures of a skipped run"
    );
    assert!(html.contains("skipped") && html.contains("NV_register_combiners"));

    let report = json(&out.join("results.json"));
    let skipped = &row(&report, "multidigit16", "native");
    assert!(skipped["measured"].is_null());
    assert!(skipped["skipped"]
        .as_str()
        .unwrap_or("")
        .contains("not supported"));
    assert!(row(&report, "multidigit16", "emulate")["measured"]["passes"].as_u64() > Some(1));
    assert!(report["rows"]
        .as_array()
        .is_some_and(|r| r.iter().any(|r| r["pareto"] == true)));

    let svg = std::fs::read_to_string(out.join("accuracy_vs_time.svg")).expect("svg");
    assert!(
        svg.contains("<svg") && svg.contains("Pareto front"),
        "{}",
        &svg[..200.min(svg.len())]
    );
    let plot = image::open(out.join("accuracy_vs_time.png")).expect("plot png");
    assert_eq!((plot.width(), plot.height()), (960, 600));
    // Header line, truth line, three measured runs: each a line of 96-pixel tiles.
    let sheet = image::open(out.join("contact_sheet.png"))
        .expect("sheet")
        .to_rgb8();
    assert!(sheet.height() >= 4 * 96, "{:?}", sheet.dimensions());
    let distinct: std::collections::HashSet<[u8; 3]> = sheet.pixels().map(|p| p.0).collect();
    assert!(distinct.len() > 20, "the sheet holds pictures and text");
}

#[test]
fn bad_compare_arguments_are_refused_with_the_valid_choices() {
    let run = fixedfunc(&["compare", "--techniques", "none,shadow-volumes"]);
    assert!(!run.status.success());
    let err = text(&run.stderr);
    assert!(
        err.contains("shadow-volumes") && err.contains("depth-compare"),
        "{err}"
    );
    let run = fixedfunc(&["compare", "--frames", "0"]);
    assert!(!run.status.success());
    assert!(
        text(&run.stderr).contains("--frames"),
        "{}",
        text(&run.stderr)
    );
}

/// Each card carries its pass strip (thumbnails linked to the full-size pictures, each a
/// file the run wrote) and one sentence computed from its counts; dual8's names its map's
/// 8-bit step in scene units.
#[test]
fn each_card_has_a_pass_strip_and_says_why_it_is_right_or_wrong() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("report");
    let run = fixedfunc(&[
        "compare",
        "--techniques",
        "depth-compare,dual8",
        "--pipeline",
        "both",
        "--size",
        "64x64",
        "--frames",
        "2",
        "--passes",
        "--out",
        arg(&out),
    ]);
    assert!(run.status.success(), "{}", text(&run.stderr));
    let html = std::fs::read_to_string(out.join("report.html")).expect("report.html");
    for slug in [
        "dual8-emulate",
        "dual8-native",
        "depth-compare-emulate",
        "depth-compare-native",
    ] {
        let thumbnail = format!("{slug}-pass-01-light-depth.png");
        assert!(
            html.contains(&format!("<a href=\"{thumbnail}\"><img src=\"{thumbnail}\"")),
            "{slug}: no linked thumbnail of the light pass"
        );
        assert!(out.join(&thumbnail).is_file(), "{thumbnail}");
        let legend = format!("{slug}-pass-legend.txt");
        assert!(
            html.contains(&legend) && out.join(&legend).is_file(),
            "{legend}"
        );
    }
    assert!(out
        .join("dual8-native-pass-05-lit-map-minus-ramp.png")
        .is_file());
    assert!(html.contains("href=\"dual8-emulate-pass-05-lit-alpha.png\""));
    let sentences: Vec<&str> = html
        .split("<p class=\"why\">")
        .skip(1)
        .map(|s| s.split("</p>").next().unwrap_or_default())
        .collect();
    assert_eq!(sentences.len(), 4, "one sentence per measured card");
    for s in &sentences {
        assert!(
            (s.starts_with("Right") || s.starts_with("Wrong by")) && s.ends_with('.'),
            "{s}"
        );
    }
    assert_eq!(
        sentences
            .iter()
            .filter(|s| s.contains("scene units at the receivers"))
            .count(),
        2,
        "dual8's two cards give its map's step: {sentences:?}"
    );
}
