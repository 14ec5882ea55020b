//! The private Xvfb is stopped on every exit path and leaves nothing behind: its lock file
//! `/tmp/.XN-lock`, its socket `/tmp/.X11-unix/XN` and its process are gone after the
//! guard drops and after the CLI is ended by SIGINT, SIGTERM, SIGHUP or SIGPIPE; and when
//! it cannot start, what it said is shown.

use std::io::Read;
use std::os::unix::process::ExitStatusExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use fixedfunc::gpu::VirtualDisplay;

fn lock_file(display: &str) -> PathBuf {
    PathBuf::from(format!("/tmp/.X{}-lock", display.trim_start_matches(':')))
}

fn socket(display: &str) -> PathBuf {
    PathBuf::from(format!(
        "/tmp/.X11-unix/X{}",
        display.trim_start_matches(':')
    ))
}

/// The pid in a display's lock file, if there is one.
fn lock_owner(display: &str) -> Option<u32> {
    std::fs::read_to_string(lock_file(display))
        .ok()?
        .trim()
        .parse()
        .ok()
}

/// Whether process `pid` exists (a zombie, not yet reaped, counts).
fn alive(pid: u32) -> bool {
    Path::new(&format!("/proc/{pid}")).exists()
}

/// The Xvfb processes whose parent is `parent`, with their display (`:N`).
fn xvfb_children(parent: u32) -> Vec<(u32, String)> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir("/proc").expect("/proc").flatten() {
        let Some(pid) = entry
            .file_name()
            .to_str()
            .and_then(|s| s.parse::<u32>().ok())
        else {
            continue;
        };
        let status = std::fs::read_to_string(entry.path().join("status")).unwrap_or_default();
        let field = |name: &str| {
            status
                .lines()
                .find_map(|l| l.strip_prefix(name))
                .map(|v| v.trim().to_string())
        };
        if field("Name:").as_deref() != Some("Xvfb")
            || field("PPid:").and_then(|p| p.parse().ok()) != Some(parent)
        {
            continue;
        }
        let cmdline = std::fs::read(entry.path().join("cmdline")).unwrap_or_default();
        if let Some(display) = cmdline
            .split(|&b| b == 0)
            .map(|a| String::from_utf8_lossy(a).into_owned())
            .find(|a| a.starts_with(':'))
        {
            found.push((pid, display));
        }
    }
    found
}

/// Waits (up to 30 s) for `cli` to have a running Xvfb child with its socket up.
fn wait_for_xvfb(cli: &mut Child) -> (u32, String) {
    let start = Instant::now();
    loop {
        // The one that owns its display (a server that lost the number to another
        // process's ends at once, and the CLI tries the next number).
        let children = xvfb_children(cli.id());
        if let Some((pid, display)) = children
            .into_iter()
            .find(|(pid, display)| lock_owner(display) == Some(*pid) && socket(display).exists())
        {
            return (pid, display);
        }
        if let Ok(Some(status)) = cli.try_wait() {
            let mut said = String::new();
            if let Some(mut stderr) = cli.stderr.take() {
                let _ = stderr.read_to_string(&mut said);
            }
            panic!("the CLI ended ({status}) before its Xvfb was seen: {said}");
        }
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "no Xvfb child within 30 s"
        );
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// Asserts the server is gone with everything it made; kills a survivor so that a failed
/// test leaks nothing either. Other tests (and other programs) start servers at the same
/// time, and one may take the freed number at once: a lock file that names another pid is
/// theirs, and so is the socket then.
fn assert_gone(pid: u32, display: &str, after: &str) {
    let survived = alive(pid);
    let state = std::fs::read_to_string(format!("/proc/{pid}/status"))
        .unwrap_or_default()
        .lines()
        .filter(|l| l.starts_with("State:") || l.starts_with("PPid:"))
        .collect::<Vec<_>>()
        .join(", ");
    let owner = lock_owner(display);
    let ours = owner == Some(pid);
    let lock_left = ours || (lock_file(display).exists() && owner.is_none());
    let socket_left = socket(display).exists() && (owner.is_none() || ours);
    if survived {
        // SAFETY: a signal to a test's own leftover process.
        unsafe {
            libc::kill(pid as i32, libc::SIGTERM);
        }
    }
    assert!(
        !survived,
        "Xvfb {display} (pid {pid}, {state}) outlived {after}"
    );
    assert!(
        !lock_left,
        "{} left behind after {after}",
        lock_file(display).display()
    );
    assert!(
        !socket_left,
        "{} left behind after {after}",
        socket(display).display()
    );
}

#[test]
fn a_dropped_display_leaves_no_lock_file_socket_or_process() {
    let before = std::env::var_os("DISPLAY");
    let display = VirtualDisplay::start().expect("Xvfb starts");
    let (pid, name) = (display.pid(), display.display().to_string());
    assert!(alive(pid));
    assert!(lock_file(&name).exists() && socket(&name).exists());
    assert_eq!(
        std::env::var("DISPLAY").ok().as_deref(),
        Some(name.as_str())
    );
    drop(display);
    assert_gone(pid, &name, "the guard's drop");
    assert_eq!(
        std::env::var_os("DISPLAY"),
        before,
        "DISPLAY is put back as it was"
    );
}

/// The CLI with no display, so that it starts its own Xvfb.
fn cli(args: &[&str]) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_fixedfunc"));
    command.args(args).env_remove("DISPLAY");
    command
}

/// Runs a long render on the window backend, sends it `signal` once its Xvfb is up, and
/// asserts the CLI died of that signal (a shell sees 128 + n) and its Xvfb is gone.
fn signal_stops_xvfb(signal: libc::c_int, name: &str) {
    let dir = tempfile::tempdir().expect("temp dir");
    let (out, mask) = (dir.path().join("i.png"), dir.path().join("m.png"));
    // Enough frames to be still rendering when the signal comes.
    let mut run = cli(&[
        "render",
        "--backend",
        "window",
        "--size",
        "32x32",
        "--map-size",
        "32",
        "--frames",
        "100000",
        "--out",
        out.to_str().expect("UTF-8"),
        "--mask",
        mask.to_str().expect("UTF-8"),
    ])
    .stdout(Stdio::null())
    .stderr(Stdio::piped())
    .spawn()
    .expect("run fixedfunc");
    let (pid, display) = wait_for_xvfb(&mut run);
    // SAFETY: a signal to the test's own child.
    unsafe {
        libc::kill(run.id() as i32, signal);
    }
    let status = run.wait().expect("wait");
    assert!(
        status.signal() == Some(signal) || status.code() == Some(128 + signal),
        "{name}: ended by the signal, as without a handler: {status}"
    );
    assert_gone(pid, &display, name);
    assert!(!out.exists(), "{name}: interrupted before writing");
}

#[test]
fn an_interrupted_cli_stops_its_xvfb_before_it_exits() {
    signal_stops_xvfb(libc::SIGINT, "SIGINT to the CLI");
}

#[test]
fn a_cli_ended_by_sigterm_sighup_or_sigpipe_stops_its_xvfb() {
    // SIGPIPE is sent here as a closed pipe would raise it, at a moment the test chooses.
    for (signal, name) in [
        (libc::SIGTERM, "SIGTERM"),
        (libc::SIGHUP, "SIGHUP"),
        (libc::SIGPIPE, "SIGPIPE"),
    ] {
        signal_stops_xvfb(signal, name);
    }
}

#[test]
fn an_xvfb_that_cannot_start_is_shown_with_what_it_said() {
    let dir = tempfile::tempdir().expect("temp dir");
    let fake = dir.path().join("Xvfb");
    std::fs::write(
        &fake,
        "#!/bin/sh\necho 'Fatal server error: no screens found (a test)' >&2\nexit 1\n",
    )
    .expect("write");
    std::fs::set_permissions(&fake, std::os::unix::fs::PermissionsExt::from_mode(0o755))
        .expect("chmod");
    let path = format!(
        "{}:{}",
        dir.path().display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let mut run = cli(&["info", "--backend", "window"])
        .env("PATH", path)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run fixedfunc");
    let mut said = String::new();
    run.stdout
        .take()
        .expect("stdout")
        .read_to_string(&mut said)
        .expect("read");
    run.stderr
        .take()
        .expect("stderr")
        .read_to_string(&mut said)
        .expect("read");
    let status = run.wait().expect("wait");
    assert!(!status.success(), "{said}");
    assert!(
        said.contains("Fatal server error: no screens found (a test)"),
        "{said}"
    );
}
