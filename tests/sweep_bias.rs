//! `fixedfunc sweep-bias` end to end on real EGL contexts at small sizes: a cell equals a
//! `render` with its offset (the first cell, made by a fresh session, and a later one,
//! made after `Session::restage`), the best cell is no worse than any other, formats a
//! technique cannot use are skipped with the reason, and bad ranges and techniques that read
//! no polygon offset are refused clearly.

use std::path::Path;
use std::process::{Command, Output};

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

/// The light's map edge: no larger than the image, so that the framebuffer is the image's
/// size. (A framebuffer larger than the image exposes a viewport mismatch in
/// `Session::finish`, which resets the viewport behind the pipeline's state cache; the
/// sweep's `Session::mask` path does not, so the two would disagree for that reason alone.)
const MAP: &str = "64";

fn sweep_json(dir: &Path) -> serde_json::Value {
    let s = std::fs::read_to_string(dir.join("sweep.json")).expect("sweep.json");
    serde_json::from_str(&s).expect("valid JSON")
}

/// (false shadow, missed shadow) of `render` with these shadow settings.
fn render_counts(dir: &Path, technique: &str, offset: &str, depth: &str) -> (u64, u64) {
    let img = dir.join(format!("r-{offset}-{depth}.png"));
    let mask = dir.join(format!("r-{offset}-{depth}-mask.png"));
    let run = fixedfunc(&[
        "render",
        "--technique",
        technique,
        "--size",
        "96x96",
        "--map-size",
        MAP,
        "--frames",
        "1",
        "--offset",
        offset,
        "--depth-bits",
        depth,
        "--out",
        arg(&img),
        "--mask",
        arg(&mask),
    ]);
    assert!(run.status.success(), "{}", text(&run.stderr));
    let out = text(&run.stdout);
    let num = |key: &str| -> u64 {
        let i = out.find(key).unwrap_or_else(|| panic!("{key} in {out}")) + key.len();
        out[i..]
            .split(|c: char| !c.is_ascii_digit())
            .next()
            .and_then(|s| s.parse().ok())
            .expect("a count")
    };
    (num("false shadow "), num("missed shadow "))
}

fn counts(cell: &serde_json::Value) -> (u64, u64) {
    (
        cell["false_shadow"].as_u64().expect("false"),
        cell["missed_shadow"].as_u64().expect("missed"),
    )
}

#[test]
fn a_single_cell_sweep_equals_render_with_those_parameters() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("sweep");
    let run = fixedfunc(&[
        "sweep-bias",
        "--technique",
        "depth-compare",
        "--factor",
        "1.5",
        "--units",
        "3..3:1",
        "--depth-bits",
        "24",
        "--size",
        "96x96",
        "--map-size",
        MAP,
        "--out",
        arg(&out),
    ]);
    assert!(run.status.success(), "{}", text(&run.stderr));
    let s = sweep_json(&out);
    let surface = &s["surfaces"][0];
    assert_eq!(surface["cells"].as_array().map(Vec::len), Some(1));
    let cell = &surface["cells"][0];
    assert_eq!(
        (cell["factor"].as_f64(), cell["units"].as_f64()),
        (Some(1.5), Some(3.0))
    );
    assert_eq!(
        counts(cell),
        render_counts(dir.path(), "depth-compare", "1.5,3", "24")
    );
    assert!(
        text(&run.stdout).contains("best offset (1.5, 3)"),
        "{}",
        text(&run.stdout)
    );
}

#[test]
fn a_restaged_cell_equals_render_and_unusable_formats_are_skipped() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("sweep");
    // multidigit16 needs stencil, which a 16-bit depth buffer lacks.
    let run = fixedfunc(&[
        "sweep-bias",
        "--technique",
        "multidigit16-combine",
        "--factor",
        "0..2:2",
        "--units",
        "4",
        "--depth-bits",
        "16,24",
        "--size",
        "96x96",
        "--map-size",
        MAP,
        "--out",
        arg(&out),
    ]);
    assert!(run.status.success(), "{}", text(&run.stderr));
    let s = sweep_json(&out);
    let surfaces = s["surfaces"].as_array().expect("surfaces");
    assert_eq!(surfaces.len(), 2);
    assert_eq!(surfaces[0]["depth_bits"], "16");
    assert!(
        surfaces[0]["skipped"]
            .as_str()
            .unwrap_or("")
            .contains("stencil"),
        "{}",
        surfaces[0]
    );
    assert!(
        text(&run.stdout).contains("skipped"),
        "{}",
        text(&run.stdout)
    );
    assert!(!out.join("heatmap-emulate-16.png").exists());
    let cells = surfaces[1]["cells"].as_array().expect("cells");
    assert_eq!(cells.len(), 2);
    // Cell 2 was made by restaging the session of cell 1.
    let zero = render_counts(dir.path(), "multidigit16-combine", "0,4", "24");
    let two = render_counts(dir.path(), "multidigit16-combine", "2,4", "24");
    assert_eq!(counts(&cells[0]), zero);
    assert_eq!(counts(&cells[1]), two);
    assert_ne!(
        zero, two,
        "the offset changes the mask, so the equality means something"
    );
}

#[test]
fn the_best_cell_is_no_worse_than_any_other_and_files_are_written() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("sweep");
    let run = fixedfunc(&[
        "sweep-bias",
        "--technique",
        "depth-compare",
        "--factor",
        "-1..2:4",
        "--units",
        "0..8:3",
        "--depth-bits",
        "16,32f",
        "--size",
        "64x64",
        "--out",
        arg(&out),
    ]);
    assert!(run.status.success(), "{}", text(&run.stderr));
    let s = sweep_json(&out);
    assert_eq!(s["factors"].as_array().map(Vec::len), Some(4));
    for surface in s["surfaces"].as_array().expect("surfaces") {
        let cells = surface["cells"].as_array().expect("cells");
        assert_eq!(cells.len(), 12);
        let wrong = |c: &serde_json::Value| {
            let (f, m) = counts(c);
            f + m + c["coverage"].as_u64().expect("coverage")
        };
        let best = wrong(&surface["best"]);
        for c in cells {
            assert!(best <= wrong(c), "best {best} > {} at {c}", wrong(c));
        }
        let spread: std::collections::HashSet<u64> = cells.iter().map(wrong).collect();
        assert!(spread.len() > 1, "the grid's cells differ: {spread:?}");
    }
    for name in [
        "heatmap-emulate-16.svg",
        "heatmap-emulate-16.png",
        "heatmap-emulate-32f.svg",
        "heatmap-emulate-32f.png",
    ] {
        assert!(out.join(name).is_file(), "{name}");
    }
    let csv = std::fs::read_to_string(out.join("sweep.csv")).expect("csv");
    assert_eq!(csv.lines().count(), 1 + 2 * 12);
    assert_eq!(csv.lines().filter(|l| l.ends_with(",true")).count(), 2);
}

#[test]
fn bad_ranges_are_refused_with_the_reason() {
    let cases = [
        ("4..1", "greater than"),
        ("0..4:0", "at least 1"),
        ("NaN..1", "not a finite number"),
        ("0..inf", "not a finite number"),
        ("1,4", "A..B[:steps]"),
        ("0..4:x", "A..B[:steps]"),
        ("0..4:1", "one step"),
    ];
    for (range, message) in cases {
        let run = fixedfunc(&[
            "sweep-bias",
            "--technique",
            "depth-compare",
            "--factor",
            range,
            "--units",
            "0",
        ]);
        assert!(!run.status.success(), "{range} accepted");
        let err = text(&run.stderr);
        assert!(
            err.contains(message) && err.contains("--factor"),
            "{range}: {err}"
        );
    }
    let run = fixedfunc(&[
        "sweep-bias",
        "--technique",
        "depth-compare",
        "--factor",
        "1",
    ]);
    assert!(!run.status.success());
    assert!(text(&run.stderr).contains("--units"));
}

#[test]
fn a_best_cell_on_the_grids_edge_is_warned_of_and_units_are_shown_in_depth_steps() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("sweep");
    // Two units values: whichever is best lies on a side of the grid.
    let run = fixedfunc(&[
        "sweep-bias",
        "--technique",
        "depth-compare",
        "--factor",
        "0",
        "--units",
        "0..4:2",
        "--depth-bits",
        "24",
        "--size",
        "96x96",
        "--map-size",
        MAP,
        "--out",
        arg(&out),
    ]);
    let stdout = text(&run.stdout);
    assert!(run.status.success(), "{}", text(&run.stderr));
    let low = stdout.contains("best offset (0, 0), units = 0 LSB of 24-bit depth")
        && stdout.contains("warning: the best cell lies on the grid's edge (the lowest units)");
    let high = stdout.contains("best offset (0, 4), units = 8 LSB of 24-bit depth")
        && stdout.contains("warning: the best cell lies on the grid's edge (the highest units)");
    assert!(low != high, "{stdout}");
    // The factor is fixed (one value): no warning names it.
    assert!(!stdout.contains("factor)"), "{stdout}");
}

/// A refined sweep at 64×64 on 24-bit depth: factor 0 and 0.5 at 4 units. Factor 0 is
/// the acne of a map without slope bias, so the best lies on the highest factor, a side
/// past which a better offset may lie.
fn refined_sweep(out: &Path) -> (Output, serde_json::Value) {
    let run = fixedfunc(&[
        "sweep-bias",
        "--technique",
        "depth-compare",
        "--factor",
        "0..0.5:2",
        "--units",
        "4",
        "--depth-bits",
        "24",
        "--size",
        "64x64",
        "--map-size",
        "64",
        "--refine=6",
        "--out",
        arg(out),
    ]);
    assert!(run.status.success(), "{}", text(&run.stderr));
    let json = sweep_json(out);
    (run, json)
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("a number: {v}"))
}

/// A JSON number as fixedfunc prints an f32 (`1`, not JSON's `1.0`).
fn num(v: &serde_json::Value) -> String {
    (f(v) as f32).to_string()
}

#[test]
fn refine_moves_a_grid_whose_best_is_on_an_edge_until_the_best_is_inside_or_says_why_not() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("sweep");
    let (run, s) = refined_sweep(&out);
    let stdout = text(&run.stdout);
    assert_eq!(s["refine"]["max_rounds"], 6);
    let surface = &s["surfaces"][0];
    let rounds = surface["rounds"].as_array().expect("rounds");
    let cells = surface["cells"].as_array().expect("cells");
    assert!(rounds.len() >= 2, "{surface}");
    // Round 1: the best on the highest factor, an open side; the next grid goes past it.
    let first = &rounds[0];
    assert_eq!(
        first["verdict"]["open"],
        serde_json::json!(["highest_factor"])
    );
    assert_eq!(f(&first["best"]["factor"]), 0.5, "{first}");
    let second_top = rounds[1]["factors"]
        .as_array()
        .and_then(|v| v.last())
        .map(f)
        .expect("round 2's factors");
    assert!(second_top > 0.5, "round 2 did not move: {}", rounds[1]);
    assert!(stdout.contains("round 2 moves past that side"), "{stdout}");
    // Every round is printed, and each round's cells carry its number.
    for r in rounds {
        let n = r["round"].as_u64().expect("round");
        assert!(stdout.contains(&format!("round {n}: factor ")), "{stdout}");
        let (first, count) = (
            r["first"].as_u64().expect("first") as usize,
            r["count"].as_u64().expect("count") as usize,
        );
        assert_eq!(
            count,
            r["factors"].as_array().map_or(0, Vec::len)
                * r["units_values"].as_array().map_or(0, Vec::len)
        );
        for c in &cells[first..first + count] {
            assert_eq!(c["round"].as_u64(), Some(n), "{c}");
        }
    }
    let last = rounds.last().expect("a round");
    if last["settled"] == true {
        // Settled: the best so far lies on no open side, with the factor step at the floor.
        assert_eq!(last["verdict"]["open"], serde_json::json!([]), "{last}");
        let factors = last["factors"].as_array().expect("factors");
        assert!(f(&factors[1]) - f(&factors[0]) <= 0.125 + 1e-6, "{last}");
        assert!(!stdout.contains("round limit"), "{stdout}");
    } else {
        assert_eq!(rounds.len(), 6, "stopped early without settling: {last}");
        assert!(stdout.contains("the round limit (6) stopped"), "{stdout}");
    }
    // The best printed is the best over all rounds, and its round is named.
    let wrong = |c: &serde_json::Value| {
        let (a, b) = counts(c);
        a + b + c["coverage"].as_u64().expect("coverage")
    };
    let best = &surface["best"];
    assert!(cells.iter().all(|c| wrong(best) <= wrong(c)));
    let line = format!(
        "best offset ({}, 4) from round {}, units = 8 LSB of 24-bit depth",
        num(&best["factor"]),
        best["round"]
    );
    assert!(stdout.contains(&line), "{line} in {stdout}");
    assert_eq!(best["units_in_depth_steps"], "8 LSB of 24-bit depth");
}

#[test]
fn the_csv_gives_each_cells_round_and_its_units_in_depth_steps() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("sweep");
    let (_, s) = refined_sweep(&out);
    let csv = std::fs::read_to_string(out.join("sweep.csv")).expect("csv");
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().expect("a header").split(',').collect();
    let col = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("no {name} column in {header:?}"))
    };
    let (round, steps) = (col("round"), col("units_in_depth_steps"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let cells = s["surfaces"][0]["cells"].as_array().expect("cells");
    assert_eq!(rows.len(), cells.len());
    for (row, cell) in rows.iter().zip(cells) {
        assert_eq!(row.len(), header.len(), "{row:?}");
        assert_eq!(row[round], cell["round"].to_string());
        assert_eq!(row[steps], "8 LSB of 24-bit depth");
    }
    let rounds = s["surfaces"][0]["rounds"].as_array().map_or(0, Vec::len);
    let seen: std::collections::BTreeSet<&str> = rows.iter().map(|r| r[round]).collect();
    let want: std::collections::BTreeSet<String> = (1..=rounds).map(|n| n.to_string()).collect();
    assert_eq!(
        seen.into_iter()
            .map(String::from)
            .collect::<std::collections::BTreeSet<_>>(),
        want
    );
}

/// The `href` and `src` targets of a page.
fn links(html: &str) -> Vec<String> {
    let mut out = Vec::new();
    for key in ["href=\"", "src=\""] {
        let mut rest = html;
        while let Some(i) = rest.find(key) {
            rest = &rest[i + key.len()..];
            let end = rest.find('"').expect("a closing quote");
            out.push(rest[..end].to_string());
            rest = &rest[end..];
        }
    }
    out
}

#[test]
fn the_page_links_every_cell_to_its_image_mask_and_error_image_and_every_link_resolves() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("sweep");
    std::fs::create_dir_all(&out).expect("folder");
    // A page of an earlier run is not left behind.
    std::fs::write(out.join("index.html"), "old page").expect("old page");
    let (_, s) = refined_sweep(&out);
    let html = std::fs::read_to_string(out.join("index.html")).expect("index.html");
    assert!(
        html.starts_with("<!doctype html>"),
        "{}",
        &html[..40.min(html.len())]
    );
    let targets = links(&html);
    let mut files = 0;
    for t in &targets {
        if t.starts_with('#') {
            continue;
        }
        assert!(
            !t.contains("://") && !t.starts_with('/'),
            "not relative: {t}"
        );
        assert!(out.join(t).is_file(), "{t} is linked but missing");
        files += 1;
    }
    // Every cell of every round: its image, mask and error image, each linked.
    let surface = &s["surfaces"][0];
    let cells = surface["cells"].as_array().expect("cells");
    for c in cells {
        let stem = format!(
            "cells/emulate-24/round{}/f{}_u{}",
            c["round"],
            num(&c["factor"]),
            num(&c["units"])
        );
        for name in [
            format!("{stem}.png"),
            format!("{stem}-mask.png"),
            format!("{stem}-error.png"),
        ] {
            assert!(targets.contains(&name), "{name} not linked");
        }
    }
    assert!(
        files >= 3 * cells.len(),
        "{files} links for {} cells",
        cells.len()
    );
    // The error image colours false shadow orange and missed shadow blue, as compare's.
    let first = &cells[0];
    let error = image::open(out.join(format!(
        "cells/emulate-24/round1/f{}_u{}-error.png",
        num(&first["factor"]),
        num(&first["units"])
    )))
    .expect("an error image")
    .to_rgb8();
    let orange = error.pixels().filter(|p| p.0 == [240, 120, 0]).count() as u64;
    assert_eq!(orange, counts(first).0, "false shadow pixels");
    // The best cell is highlighted and its units shown in depth steps.
    assert_eq!(html.matches("class=\"best\"").count(), 1, "one best cell");
    assert!(html.contains("8 LSB of 24-bit depth"));
    // Each round's heatmap is on the page.
    for r in surface["rounds"].as_array().expect("rounds") {
        let n = r["round"].as_u64().expect("round");
        let name = if n == 1 {
            "heatmap-emulate-24.png".to_string()
        } else {
            format!("heatmap-emulate-24-round{n}.png")
        };
        assert!(targets.contains(&name), "{name}");
    }
}

#[test]
fn a_technique_that_reads_no_polygon_offset_is_refused_before_the_folder_is_touched() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("sweep");
    for technique in ["occluder-planes", "projective"] {
        let run = fixedfunc(&[
            "sweep-bias",
            "--technique",
            technique,
            "--factor",
            "0..2:3",
            "--units",
            "0..4:3",
            "--size",
            "64x64",
            "--out",
            arg(&out),
        ]);
        assert!(!run.status.success(), "{technique} swept");
        let err = text(&run.stderr);
        assert!(
            err.contains(&format!("`{technique}` reads no polygon offset"))
                && err.contains("depth-compare"),
            "{technique}: {err}"
        );
        assert!(!out.exists(), "{technique}: the folder was made");
    }
}
