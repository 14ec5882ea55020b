//! Writes that fail are reported, never counted as written: PNG, CSV, JSON and SVG files
//! sent to a full device (`/dev/full`, directly or through a symbolic link), stdout sent
//! there, outputs that cannot be written (refused before any rendering), two options
//! naming one file, an extension that is not `.png`, and a comparison stopped half-way into
//! a folder that held an older report.

use std::fs;
use std::os::unix::fs::PermissionsExt;
use std::os::unix::process::CommandExt;
use std::path::Path;
use std::process::{Command, Output, Stdio};

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

/// A failed run that reported its failure: exit code 2, trouble (not a panic's 101), one message
/// naming `needle` on stderr, no panic.
fn assert_reported(run: &Output, needle: &str) -> String {
    let stderr = text(&run.stderr);
    assert_eq!(
        run.status.code(),
        Some(2),
        "expected a reported failure; stdout: {} stderr: {stderr}",
        text(&run.stdout)
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(stderr.contains(needle), "`{needle}` in: {stderr}");
    stderr
}

/// A render small and short enough for tests, writing `out` and `mask`.
fn render_args<'a>(out: &'a str, mask: &'a str) -> Vec<&'a str> {
    vec![
        "render",
        "--size",
        "32x32",
        "--map-size",
        "32",
        "--frames",
        "1",
        "--out",
        out,
        "--mask",
        mask,
    ]
}

#[test]
fn a_png_written_to_a_full_device_is_an_error_not_written() {
    let dir = tempfile::tempdir().expect("temp dir");
    let image = dir.path().join("image.png");
    let run = fixedfunc(&render_args(arg(&image), "/dev/full"));
    let stderr = assert_reported(&run, "/dev/full");
    assert!(stderr.contains("No space left"), "{stderr}");
    assert!(
        !text(&run.stdout).contains("mask /dev/full"),
        "the mask is not reported as written: {}",
        text(&run.stdout)
    );

    let run = fixedfunc(&["truth", "--size", "32x32", "--mask", "/dev/full"]);
    assert_reported(&run, "/dev/full");
    assert!(run.stdout.is_empty(), "{}", text(&run.stdout));
}

/// A one-cell sweep into `dir`.
fn sweep_into(dir: &Path) -> Output {
    fixedfunc(&[
        "sweep-bias",
        "--technique",
        "depth-compare",
        "--factor",
        "1",
        "--units",
        "4",
        "--depth-bits",
        "24",
        "--size",
        "32x32",
        "--map-size",
        "32",
        "--out",
        arg(dir),
    ])
}

#[test]
fn report_files_written_to_a_full_device_are_errors() {
    for name in [
        "sweep.csv",
        "sweep.json",
        "heatmap-emulate-24.svg",
        "heatmap-emulate-24.png",
    ] {
        let dir = tempfile::tempdir().expect("temp dir");
        std::os::unix::fs::symlink("/dev/full", dir.path().join(name)).expect("symlink");
        let run = sweep_into(dir.path());
        let stderr = assert_reported(&run, "No space left");
        assert!(stderr.contains(name), "{name} named in: {stderr}");
        assert!(
            !text(&run.stdout).contains("wrote"),
            "{name}: {}",
            text(&run.stdout)
        );
    }
    // The same sweep into a plain folder succeeds and leaves no temporary file.
    let dir = tempfile::tempdir().expect("temp dir");
    let run = sweep_into(dir.path());
    assert!(run.status.success(), "{}", text(&run.stderr));
    for entry in fs::read_dir(dir.path()).expect("list") {
        let name = entry.expect("entry").file_name();
        let name = name.to_string_lossy();
        assert!(!name.starts_with('.'), "temporary file left: {name}");
    }
}

#[test]
fn stdout_that_cannot_be_written_is_an_error_not_a_panic() {
    for json in [false, true] {
        let full = fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .expect("/dev/full");
        let mut command = Command::new(env!("CARGO_BIN_EXE_fixedfunc"));
        command.args(["info", "--backend", "egl"]);
        if json {
            command.arg("--json");
        }
        let run = command
            .stdout(Stdio::from(full))
            .stderr(Stdio::piped())
            .output()
            .expect("run fixedfunc info");
        assert_reported(&run, "cannot write to standard output");
    }
}

#[test]
fn out_and_mask_naming_one_file_are_refused() {
    let dir = tempfile::tempdir().expect("temp dir");
    fs::create_dir(dir.path().join("sub")).expect("mkdir");
    let out = dir.path().join("same.png");
    let mask = dir.path().join("sub").join("..").join("same.png");
    let run = fixedfunc(&render_args(arg(&out), arg(&mask)));
    assert_reported(&run, "--out and --mask both name");
    assert!(!out.exists(), "nothing is rendered or written");

    let vis = dir.path().join("t.png");
    let run = fixedfunc(&[
        "truth",
        "--size",
        "32x32",
        "--mask",
        arg(&vis),
        "--visibility",
        arg(&vis),
    ]);
    assert_reported(&run, "--mask and --visibility both name");
    assert!(!vis.exists());
}

/// Asserts `run` refused `mask` before rendering: it names it, and the image (checked
/// and written first otherwise) was never written.
fn assert_refused_before_rendering(run: &Output, needle: &str, image: &Path) {
    assert_reported(run, needle);
    assert!(run.stdout.is_empty(), "{}", text(&run.stdout));
    assert!(!image.exists(), "no work was done, so no image was written");
}

#[test]
fn outputs_that_cannot_be_written_are_refused_before_rendering() {
    let dir = tempfile::tempdir().expect("temp dir");
    let image = dir.path().join("image.png");

    // A folder.
    let folder = dir.path().join("folder");
    fs::create_dir(&folder).expect("mkdir");
    let run = fixedfunc(&render_args(arg(&image), arg(&folder)));
    assert_refused_before_rendering(&run, "it is a folder", &image);

    // A parent folder that cannot be made (a file is in the way).
    fs::write(dir.path().join("file"), "").expect("write");
    let blocked = dir.path().join("file").join("sub").join("mask.png");
    let run = fixedfunc(&render_args(arg(&image), arg(&blocked)));
    assert_refused_before_rendering(&run, "cannot create the output folder", &image);

    // An extension that is not PNG, which once left a 0-byte file behind.
    let jpg = dir.path().join("mask.jpg");
    let run = fixedfunc(&render_args(arg(&image), arg(&jpg)));
    assert_refused_before_rendering(&run, "only PNG images are written", &image);
    assert!(!jpg.exists(), "no 0-byte file");
    let run = fixedfunc(&render_args(arg(&jpg), arg(&image)));
    assert_refused_before_rendering(&run, "only PNG images are written", &jpg);
    assert!(!image.exists());

    // A read-only folder. Root ignores permission bits, so as root the run is made as
    // `nobody` (uid 65534), for whom they hold.
    let shared = dir.path().join("shared");
    fs::create_dir(&shared).expect("mkdir");
    fs::set_permissions(dir.path(), fs::Permissions::from_mode(0o755)).expect("chmod");
    fs::set_permissions(&shared, fs::Permissions::from_mode(0o777)).expect("chmod");
    let read_only = dir.path().join("read-only");
    fs::create_dir(&read_only).expect("mkdir");
    fs::set_permissions(&read_only, fs::Permissions::from_mode(0o555)).expect("chmod");
    let image = shared.join("image.png");
    let mask = read_only.join("mask.png");
    let mut command = Command::new(env!("CARGO_BIN_EXE_fixedfunc"));
    command.args(render_args(arg(&image), arg(&mask)));
    // SAFETY: geteuid has no preconditions.
    if unsafe { libc::geteuid() } == 0 {
        command.uid(65534).gid(65534);
    }
    let run = command.output().expect("run fixedfunc");
    assert_refused_before_rendering(&run, "Permission denied", &image);
    assert!(!mask.exists());
}

/// A comparison of one technique into `dir`.
fn compare_into(dir: &Path) -> Output {
    fixedfunc(&[
        "compare",
        "--techniques",
        "depth-compare",
        "--pipeline",
        "emulate",
        "--size",
        "32x32",
        "--map-size",
        "32",
        "--frames",
        "2",
        "--out",
        arg(dir),
    ])
}

#[test]
fn a_compare_stopped_half_way_leaves_no_old_page_linking_new_pictures() {
    let dir = tempfile::tempdir().expect("temp dir");
    let run = compare_into(dir.path());
    assert!(run.status.success(), "{}", text(&run.stderr));
    let page = dir.path().join("report.html");
    assert!(page.exists());

    // The second run fails after it wrote the pictures (results.csv is on a full device).
    let csv = dir.path().join("results.csv");
    fs::remove_file(&csv).expect("rm");
    std::os::unix::fs::symlink("/dev/full", &csv).expect("symlink");
    let run = compare_into(dir.path());
    assert_reported(&run, "results.csv");
    assert!(
        !page.exists(),
        "the old page would link the new pictures under its old names"
    );
    // No half-written file under a real name, and no temporary one either.
    for entry in fs::read_dir(dir.path()).expect("list") {
        let name = entry.expect("entry").file_name();
        let name = name.to_string_lossy();
        assert!(!name.starts_with('.'), "temporary file left: {name}");
    }
}
