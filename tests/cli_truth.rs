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
