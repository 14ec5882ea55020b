//! Long work says what it is doing, also off a terminal: `sweep-bias` with stderr piped
//! prints an estimate of the whole and plain progress lines; counts that would do nothing
//! or run without bound are refused with a clear error.

use std::process::{Command, Output};

fn fixedfunc(args: &[&str], env: &[(&str, &str)]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .args(args)
        .envs(env.iter().copied())
        .output()
        .expect("run fixedfunc")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn sweep_bias_off_a_terminal_prints_an_estimate_and_progress_lines() {
    let dir = tempfile::tempdir().expect("temp dir");
    let run = fixedfunc(
        &[
            "sweep-bias",
            "--technique",
            "depth-compare",
            "--factor",
            "0..2:3",
            "--units",
            "0..4:3",
            "--depth-bits",
            "24",
            "--size",
            "32x32",
            "--map-size",
            "32",
            "--out",
            dir.path().to_str().expect("UTF-8"),
        ],
        // A line at every report, so that a short sweep shows them.
        &[("FIXEDFUNC_PROGRESS_INTERVAL_MS", "0")],
    );
    let stderr = text(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    let estimate = stderr
        .lines()
        .find(|l| l.starts_with("sweep-bias: 9 cells × ~"))
        .unwrap_or_else(|| panic!("an estimate of 9 cells in: {stderr}"));
    assert!(estimate.contains(" ms ≈ "), "{estimate}");
    let progress: Vec<&str> = stderr
        .lines()
        .filter(|l| l.starts_with("sweep-bias: ") && l.contains("/9 cells, "))
        .collect();
    assert!(
        progress.len() >= 2,
        "progress lines (one per cell at interval 0) in: {stderr}"
    );
    assert!(
        progress.iter().all(|l| l.contains(" elapsed")),
        "{progress:?}"
    );
    assert!(
        progress.iter().any(|l| l.ends_with(" left")),
        "a time left once a cell is done: {progress:?}"
    );
    // Nothing of it on stdout, which carries the results.
    assert!(
        !text(&run.stdout).contains("cells, "),
        "{}",
        text(&run.stdout)
    );
}

#[test]
fn bench_refuses_zero_repeats_and_more_than_its_bound() {
    let run = fixedfunc(&["bench", "--only", "truth", "--repeats", "0"], &[]);
    let stderr = text(&run.stderr);
    assert_eq!(
        run.status.code(),
        Some(2),
        "refused by the parser: {stderr}"
    );
    assert!(stderr.contains("0 repeats measure nothing"), "{stderr}");

    let run = fixedfunc(&["bench", "--only", "truth", "--repeats", "1001"], &[]);
    let stderr = text(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("at most 1000 repeats"), "{stderr}");
}

#[test]
fn zero_frames_and_zero_steps_are_refused() {
    for args in [
        &["render", "--frames", "0"][..],
        &["compare", "--frames", "0"],
        &[
            "sweep-bias",
            "--technique",
            "dual8",
            "--factor",
            "0..1:0",
            "--units",
            "1",
        ],
    ] {
        let run = fixedfunc(args, &[]);
        let stderr = text(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains("invalid value '0"), "{args:?}: {stderr}");
    }
}

/// `bench` off a terminal: counted groups print progress lines with the time left, and
/// the truth group names each part as it starts.
#[test]
fn bench_off_a_terminal_prints_progress_lines() {
    let env = [("FIXEDFUNC_PROGRESS_INTERVAL_MS", "0")];
    let run = fixedfunc(&["bench", "--only", "pipeline", "--repeats", "3"], &env);
    let err = text(&run.stderr);
    assert!(run.status.success(), "{err}");
    let lines: Vec<&str> = err
        .lines()
        .filter(|l| l.starts_with("bench pipeline: ") && l.contains(" frames, "))
        .collect();
    assert!(lines.len() >= 2, "{err}");
    assert!(lines.iter().any(|l| l.contains("left")), "{err}");
    let run = fixedfunc(&["bench", "--only", "truth", "--repeats", "1"], &env);
    let err = text(&run.stderr);
    assert!(run.status.success(), "{err}");
    assert!(
        err.contains("bench truth: ray casting the default scene (1 runs)"),
        "{err}"
    );
}
