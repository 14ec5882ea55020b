//! `fixedfunc view` in a real window (a private Xvfb when no display is set): key scripts
//! change the technique, offset, depth bits, light and pipeline; what the window showed
//! equals what `render` gives for the command line the viewer prints; an idle viewer sleeps.

mod support;

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use support::{assert_images_match, Tolerance};

fn fixedfunc(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run fixedfunc")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

fn work_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("view")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a work folder");
    dir
}

/// `error 1.23% (false shadow 3, missed shadow 4)` out of a line of figures.
fn error_figures(out: &str) -> String {
    let start = out.find("error ").expect("an error figure");
    let end = start + out[start..].find(')').expect("its closing parenthesis") + 1;
    out[start..end].to_string()
}

#[test]
fn a_key_script_changes_the_view_and_the_window_shows_what_render_gives() {
    let dir = work_dir("script");
    std::fs::write(
        dir.join("keys.txt"),
        "# depth-compare, then: units up, 32F depth, dual8, the light turned, linear filter\n\
         2 key u\n3 key d\n4 key t\n5 key right\n6 drag 10 -4\n7 key l\n8 key p\n",
    )
    .unwrap();
    let args = [
        "view",
        "--technique",
        "depth-compare",
        "--size",
        "128x96",
        "--script",
        "keys.txt",
        "--frames",
        "8",
        "--out",
        "shot.png",
    ];
    let view = fixedfunc(&args, &dir);
    let said = text(&view.stdout);
    assert!(view.status.success(), "{said}\n{}", text(&view.stderr));
    let command = said
        .lines()
        .find(|l| l.starts_with("fixedfunc render"))
        .expect("`p` prints the render command");
    for part in [
        "--technique dual8",
        "--offset 1,4.5",
        "--depth-bits 32f",
        "--filter linear",
        "--turn light:10,2",
        "--size 128x96",
    ] {
        assert!(command.contains(part), "{part} missing from: {command}");
    }
    let words: Vec<&str> = command.split_whitespace().skip(1).collect();
    let mut render_args = words.clone();
    render_args.extend(["--frames", "1", "--out", "render.png", "--mask", "mask.png"]);
    let render = fixedfunc(&render_args, &dir);
    let rendered = text(&render.stdout);
    assert!(
        render.status.success(),
        "{rendered}\n{}",
        text(&render.stderr)
    );
    // The overlay's error is render's.
    let status = said
        .lines()
        .find(|l| l.starts_with("error "))
        .expect("the status bar's error line");
    assert_eq!(error_figures(status), error_figures(&rendered));
    // The window's top rows are the image render writes (the status bar is below them).
    let shown = image::open(dir.join("shot.png")).unwrap().to_rgba8();
    let image = image::open(dir.join("render.png")).unwrap().to_rgba8();
    assert!(
        shown.height() > image.height(),
        "a status bar under the image"
    );
    let top = image::imageops::crop_imm(&shown, 0, 0, image.width(), image.height()).to_image();
    let pixels = (image.width() * image.height()) as usize;
    assert_images_match(
        "view-script",
        &top,
        &image,
        Tolerance {
            per_channel: 3,
            max_bad_pixels: pixels / 100,
        },
    );
}

#[test]
fn switching_the_pipeline_renders_natively_and_keeps_the_settings() {
    let dir = work_dir("pipeline");
    std::fs::write(dir.join("keys.txt"), "2 key n\n2 key o\n3 key p\n").unwrap();
    let view = fixedfunc(
        &[
            "view",
            "--technique",
            "depth-compare",
            "--size",
            "96x96",
            "--script",
            "keys.txt",
            "--frames",
            "3",
            "--out",
            "shot.png",
        ],
        &dir,
    );
    let said = text(&view.stdout);
    assert!(view.status.success(), "{said}\n{}", text(&view.stderr));
    let command = said
        .lines()
        .find(|l| l.starts_with("fixedfunc render"))
        .expect("the render command");
    assert!(command.contains("--pipeline native"), "{command}");
    assert!(command.contains("--offset none"), "{command}");
    let first = said
        .lines()
        .find(|l| l.starts_with("depth-compare · native"))
        .expect("the status bar names the technique and pipeline");
    assert!(first.contains("offset none (command line)"), "{first}");
    let mut render_args: Vec<&str> = command.split_whitespace().skip(1).collect();
    render_args.extend(["--frames", "1", "--out", "render.png", "--mask", "mask.png"]);
    let render = fixedfunc(&render_args, &dir);
    let rendered = text(&render.stdout);
    assert!(render.status.success(), "{rendered}");
    let status = said.lines().find(|l| l.starts_with("error ")).unwrap();
    assert_eq!(error_figures(status), error_figures(&rendered));
    // No offset on a 24-bit map: the acne the key asked for.
    let percent: f64 = error_figures(status)[6..]
        .split('%')
        .next()
        .and_then(|p| p.parse().ok())
        .expect("a percentage");
    assert!(percent > 5.0, "{status}");
}

#[test]
fn bad_key_scripts_and_options_are_refused_with_their_reason() {
    let dir = work_dir("refused");
    std::fs::write(dir.join("keys.txt"), "1 key t\n2 press u\n").unwrap();
    let bad = fixedfunc(&["view", "--script", "keys.txt", "--frames", "2"], &dir);
    assert_eq!(bad.status.code(), Some(2));
    let e = text(&bad.stderr);
    assert!(e.contains("keys.txt: line 2: unknown event `press`"), "{e}");
    assert!(e.contains("FRAME drag DX DY"), "{e}");
    let window = fixedfunc(&["view", "--backend", "window", "--frames", "1"], &dir);
    assert_eq!(window.status.code(), Some(2));
    assert!(text(&window.stderr).contains("egl or osmesa"));
    let no_frames = fixedfunc(&["view", "--script", "keys.txt"], &dir);
    assert_eq!(no_frames.status.code(), Some(2), "--script needs --frames");
}

/// CPU seconds (user + system) the process has used, from /proc/PID/stat.
fn cpu_seconds(pid: u32) -> Option<f64> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // Fields after the command name's closing parenthesis: state is field 3, utime 14.
    let rest = &stat[stat.rfind(')')? + 2..];
    let fields: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = fields.get(11)?.parse::<f64>().ok()? + fields.get(12)?.parse::<f64>().ok()?;
    // SAFETY: sysconf has no preconditions.
    let hz = unsafe { libc::sysconf(libc::_SC_CLK_TCK) } as f64;
    Some(ticks / hz)
}

#[test]
fn an_idle_viewer_sleeps_and_a_signal_stops_it_and_its_x_server() {
    let dir = work_dir("idle");
    let mut child = Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .args(["view", "--size", "96x96"])
        .current_dir(&dir)
        .env_remove("DISPLAY")
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start the viewer");
    let pid = child.id();
    // Settled: the first frame and its truth are done when the CPU time stops growing.
    let start = Instant::now();
    let mut last = cpu_seconds(pid).unwrap_or(0.0);
    loop {
        std::thread::sleep(Duration::from_millis(500));
        let now = cpu_seconds(pid).expect("the viewer runs");
        if now - last < 0.01 || start.elapsed() > Duration::from_secs(60) {
            break;
        }
        last = now;
    }
    let before = cpu_seconds(pid).expect("the viewer runs");
    let idle = Duration::from_secs(3);
    std::thread::sleep(idle);
    let used = cpu_seconds(pid).expect("the viewer runs") - before;
    // SAFETY: kill with a valid signal on our own child.
    unsafe { libc::kill(pid as i32, libc::SIGTERM) };
    let status = child.wait().expect("the viewer ends");
    let share = used / idle.as_secs_f64();
    assert!(
        share < 0.05,
        "idle, the viewer used {:.1}% of a core",
        share * 100.0
    );
    assert_eq!(
        std::os::unix::process::ExitStatusExt::signal(&status),
        Some(libc::SIGTERM)
    );
    let mut stderr = String::new();
    use std::io::Read;
    let _ = child
        .stderr
        .take()
        .map(|mut e| e.read_to_string(&mut stderr));
    let display = stderr
        .split("private Xvfb (")
        .nth(1)
        .and_then(|r| r.split(')').next())
        .expect("the viewer says it started a private Xvfb");
    let number = display.trim_start_matches(':');
    assert!(
        !Path::new(&format!("/tmp/.X11-unix/X{number}")).exists(),
        "the private X server {display} was stopped with the viewer"
    );
}
