//! `fixedfunc truth` needs no GL: it writes the ground-truth mask, reports its time, and
//! rejects bad scenes and sizes with clear messages.

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

#[test]
fn truth_writes_a_mask_of_the_requested_size_with_only_mask_values() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mask = dir.path().join("truth.png");
    let vis = dir.path().join("vis.png");
    let out = fixedfunc(&[
        "truth",
        "--mask",
        arg(&mask),
        "--visibility",
        arg(&vis),
        "--size",
        "96x64",
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("96x64") && stdout.contains(" s "),
        "{stdout}"
    );

    let img = image::open(&mask).expect("a PNG").to_luma8();
    assert_eq!(img.dimensions(), (96, 64));
    let mut seen = [false; 3];
    for p in img.pixels() {
        match p.0[0] {
            0 => seen[0] = true,
            128 => seen[1] = true,
            255 => seen[2] = true,
            v => panic!("mask value {v} is not 0, 128 or 255"),
        }
    }
    assert_eq!(
        seen, [true; 3],
        "the default scene has shadow, sky and light"
    );
    let vis = image::open(&vis).expect("a PNG");
    assert_eq!((vis.width(), vis.height()), (96, 64));
}

#[test]
fn truth_uses_the_scene_size_without_size() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scene = dir.path().join("small.toml");
    let default =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/default.toml"))
            .expect("assets/default.toml");
    let small = default
        .replace("width = 512", "width = 40")
        .replace("height = 512", "height = 30");
    std::fs::write(&scene, small).expect("write scene");
    let mask = dir.path().join("t.png");
    let out = fixedfunc(&["truth", arg(&scene), "--mask", arg(&mask)]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let img = image::open(&mask).expect("a PNG");
    assert_eq!((img.width(), img.height()), (40, 30));
}

#[test]
fn a_bad_scene_names_its_line_and_the_alternatives() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scene = dir.path().join("bad.toml");
    // Line 4 names a shape that does not exist.
    std::fs::write(
        &scene,
        "[camera]\neye = [0, 2, 5]\n[[object]]\nshape = \"cylinder\"\n",
    )
    .expect("write scene");
    let out = fixedfunc(&[
        "truth",
        arg(&scene),
        "--mask",
        arg(&dir.path().join("m.png")),
    ]);
    assert!(!out.status.success());
    let stderr = text(&out.stderr);
    assert!(stderr.contains("bad.toml:4:"), "{stderr}");
    assert!(
        stderr.contains("sphere") && stderr.contains("torus"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn a_missing_scene_file_is_a_clear_error() {
    let out = fixedfunc(&["truth", "no/such/scene.toml", "--mask", "unused.png"]);
    assert!(!out.status.success());
    let stderr = text(&out.stderr);
    assert!(stderr.contains("no/such/scene.toml"), "{stderr}");
}

#[test]
fn bad_sizes_are_refused_with_the_reason() {
    for (size, reason) in [
        ("0x64", "at least 1"),
        ("64x0", "at least 1"),
        ("abc", "WIDTHxHEIGHT"),
        ("64", "WIDTHxHEIGHT"),
        ("-5x5", "WIDTHxHEIGHT"),
        ("100000x10", "at most 8192"),
    ] {
        for command in ["truth", "render"] {
            let flag = format!("--size={size}");
            let out = fixedfunc(&[command, &flag]);
            assert!(!out.status.success(), "{command} --size {size}");
            let stderr = text(&out.stderr);
            assert!(stderr.contains(reason), "{command} --size {size}: {stderr}");
        }
    }
}

#[test]
fn render_refuses_an_unknown_technique_with_the_known_ones() {
    let out = fixedfunc(&["render", "--technique", "shadow-volumes"]);
    assert!(!out.status.success());
    let stderr = text(&out.stderr);
    assert!(stderr.contains("none"), "{stderr}");
}

/// The default scene with its spot light replaced by a 2 × 2 area light at the same place,
/// at 48×36, with `extra` appended (e.g. a `[truth]` table).
fn area_scene(dir: &Path, extra: &str) -> std::path::PathBuf {
    let default =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/default.toml"))
            .expect("assets/default.toml");
    let (before, rest) = default.split_once("[[light]]").expect("a light");
    let (_, objects) = rest.split_once("[[object]]").expect("objects");
    let text = format!(
        "{before}[[light]]\ntype = \"area\"\ncentre = [6, 10, 6]\nsize = [2, 2]\n\
         at = [0, 0, 0]\n\n[[object]]{objects}\n{extra}"
    )
    .replace("width = 512", "width = 48")
    .replace("height = 512", "height = 36");
    let path = dir.join("area.toml");
    std::fs::write(&path, text).expect("write scene");
    path
}

/// The samples line of `truth`'s output for an area light.
fn samples_line(stdout: &str) -> &str {
    stdout
        .lines()
        .find(|l| l.starts_with("area light: "))
        .unwrap_or_else(|| panic!("no area-light line in {stdout}"))
}

#[test]
fn an_area_light_truth_prints_its_samples_and_standard_error() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mask = dir.path().join("m.png");
    let scene = area_scene(dir.path(), "");
    let out = fixedfunc(&["truth", arg(&scene), "--mask", arg(&mask)]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    let line = samples_line(&stdout);
    assert!(
        line.contains("242 samples per pixel") && line.contains("11×11"),
        "the default: {line}"
    );
    let error: f64 = line
        .split("standard error ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no figure in {line}"));
    assert!(error > 0.0 && error < 0.005, "{line}");

    // A point light prints no such line.
    let out = fixedfunc(&["truth", "--size", "48x36", "--mask", arg(&mask)]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(!text(&out.stdout).contains("area light"));
}

#[test]
fn samples_come_from_the_command_line_else_the_scene() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mask = dir.path().join("m.png");
    let scene = area_scene(dir.path(), "[truth]\nsamples = 32\n");
    let run = |extra: &[&str]| {
        let mut args = vec!["truth", arg(&scene), "--mask", arg(&mask)];
        args.extend_from_slice(extra);
        let out = fixedfunc(&args);
        assert!(out.status.success(), "{}", text(&out.stderr));
        samples_line(&text(&out.stdout)).to_string()
    };
    assert!(run(&[]).contains("32 samples per pixel (two independent 4×4"));
    assert!(run(&["--samples", "8"]).contains("8 samples per pixel (two independent 2×2"));
    assert!(
        run(&["--samples", "9"]).contains("18 samples per pixel"),
        "rounded up to 2s²"
    );
}

#[test]
fn impossible_sample_counts_are_refused_with_the_range() {
    for n in ["0", "8193"] {
        let out = fixedfunc(&["truth", "--samples", n, "--mask", "unused.png"]);
        assert!(!out.status.success(), "--samples {n}");
        let stderr = text(&out.stderr);
        assert!(stderr.contains("1..=8192"), "--samples {n}: {stderr}");
    }
    let dir = tempfile::tempdir().expect("temp dir");
    let scene = area_scene(dir.path(), "[truth]\nsamples = 0\n");
    let out = fixedfunc(&[
        "truth",
        arg(&scene),
        "--mask",
        arg(&dir.path().join("m.png")),
    ]);
    assert!(!out.status.success());
    let stderr = text(&out.stderr);
    let line = std::fs::read_to_string(&scene)
        .expect("scene")
        .lines()
        .position(|l| l == "samples = 0")
        .expect("the line")
        + 1;
    assert!(
        stderr.contains(&format!("area.toml:{line}:"))
            && stderr.contains("truth.samples")
            && stderr.contains("[1, 8192]"),
        "{stderr}"
    );
}
