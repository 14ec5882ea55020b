//! The checks a test run asks of the command line, and their exit codes (0 passed, 1 a
//! check failed, 2 trouble): `render --expect REF --tolerance`, `replay --strict`, and
//! `replay --pipeline both` with its difference picture.

use std::path::{Path, PathBuf};
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

fn work_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_checks")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a work folder");
    dir
}

/// A small render of the default scene with `technique` into `dir/NAME.png`.
fn render(dir: &Path, name: &str, technique: &str, extra: &[&str]) -> (Output, PathBuf) {
    let out = dir.join(format!("{name}.png"));
    let mask = dir.join(format!("{name}-mask.png"));
    let mut args = vec![
        "render",
        "--technique",
        technique,
        "--size",
        "48x48",
        "--map-size",
        "64",
        "--frames",
        "1",
        "--out",
        arg(&out),
        "--mask",
        arg(&mask),
    ];
    args.extend_from_slice(extra);
    (fixedfunc(&args), out)
}

#[test]
fn render_expect_passes_an_equal_image_and_fails_another_with_exit_1_and_a_picture() {
    let dir = work_dir("expect");
    let (first, reference) = render(&dir, "reference", "depth-compare", &[]);
    assert!(first.status.success(), "{}", text(&first.stderr));

    let again = render(
        &dir,
        "again",
        "depth-compare",
        &["--expect", arg(&reference)],
    )
    .0;
    assert_eq!(again.status.code(), Some(0), "{}", text(&again.stderr));
    assert!(text(&again.stdout).contains("largest difference 0/255"));
    assert!(!dir.join("again-diff.png").exists());

    // Planar projection shadows look nothing like a shadow map's.
    let (other, _) = render(&dir, "other", "planar", &["--expect", arg(&reference)]);
    let stderr = text(&other.stderr);
    assert_eq!(other.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("differs from") && stderr.contains("other-diff.png"),
        "{stderr}"
    );
    let picture = image::open(dir.join("other-diff.png"))
        .expect("the difference picture")
        .to_rgba8();
    assert_eq!(picture.dimensions(), (48, 48));
    assert!(
        picture
            .pixels()
            .any(|p| p.0 == [255, 0, 0, 255] || (p[0] > 128 && p[1] == 0)),
        "red where the images differ beyond the steps"
    );

    // Everything may differ at 100%.
    let loose = render(
        &dir,
        "loose",
        "planar",
        &["--expect", arg(&reference), "--tolerance", "0,100%"],
    )
    .0;
    assert_eq!(loose.status.code(), Some(0), "{}", text(&loose.stderr));
}

#[test]
fn trouble_exits_2_a_bad_tolerance_or_a_missing_reference() {
    let dir = work_dir("trouble");
    let missing = dir.join("missing.png");
    let (run, _) = render(&dir, "a", "depth-compare", &["--expect", arg(&missing)]);
    let stderr = text(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("missing.png"), "{stderr}");

    let (run, _) = render(&dir, "b", "depth-compare", &["--tolerance", "3,150%"]);
    let stderr = text(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("0 to 100%"), "{stderr}");
}

const UNDERFLOW: &str = "glClearColor(0.2, 0.3, 0.4, 1);
glClear(GL_COLOR_BUFFER_BIT);
glPopMatrix();
glColor3f(1, 1, 1);
glRectf(-0.5, -0.5, 0.5, 0.5);
";

#[test]
fn replay_strict_stops_at_the_first_gl_error_with_its_line_and_writes_nothing() {
    let dir = work_dir("strict");
    let script = dir.join("underflow.c");
    std::fs::write(&script, UNDERFLOW).expect("the script");
    let out = dir.join("strict.png");
    let run = fixedfunc(&["replay", arg(&script), "--strict", "--out", arg(&out)]);
    let stderr = text(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("underflow.c:3: glPopMatrix"), "{stderr}");
    assert!(!out.exists(), "no image after a strict failure");

    // Without --strict the error is named and the image written.
    let out = dir.join("lenient.png");
    let run = fixedfunc(&["replay", arg(&script), "--out", arg(&out)]);
    let stderr = text(&run.stderr);
    assert_eq!(run.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("underflow.c:3: glPopMatrix"), "{stderr}");
    let image = image::open(&out).expect("the image").to_rgba8();
    assert_eq!(image.get_pixel(128, 128).0, [255, 255, 255, 255]);
}

#[test]
fn replay_on_both_paths_writes_both_images_and_their_difference() {
    let dir = work_dir("both");
    let script = dir.join("rect.c");
    std::fs::write(&script, UNDERFLOW.replace("glPopMatrix();\n", "")).expect("the script");
    let out = dir.join("rect.png");
    let run = fixedfunc(&[
        "replay",
        arg(&script),
        "--pipeline",
        "both",
        "--out",
        arg(&out),
    ]);
    let stdout = text(&run.stdout);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run.stderr));
    assert!(
        stdout.contains("emulate against native: 0 of 65536 pixels")
            && stdout.contains("largest difference 0/255"),
        "{stdout}"
    );
    for name in ["rect.png", "rect-native.png", "rect-paths.png"] {
        let image = image::open(dir.join(name)).expect(name).to_rgba8();
        assert_eq!(image.dimensions(), (256, 256), "{name}");
    }
    let native = image::open(dir.join("rect-native.png"))
        .expect("native")
        .to_rgba8();
    assert_eq!(native.get_pixel(128, 128).0, [255, 255, 255, 255]);
    assert_eq!(native.get_pixel(5, 5).0, [51, 76, 102, 255]);
}
