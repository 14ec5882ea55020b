//! `fixedfunc sweep-bias` end to end on real EGL contexts at small sizes: a cell equals a
//! `render` with its offset (the first cell, made by a fresh session, and a later one,
//! made after `Session::restage`), the best cell is no worse than any other, formats a
//! technique cannot use are skipped with the reason, and bad ranges are refused clearly.

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
