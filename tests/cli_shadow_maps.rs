//! `fixedfunc render` with the shadow-map options: the figures line counts maps made, the
//! light's map is written as pictures (two digits for multidigit16), and impossible
//! parameters get clear errors.

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
fn multidigit16_writes_both_digits_and_counts_its_map() {
    let dir = tempfile::tempdir().expect("temp dir");
    let map = dir.path().join("map.png");
    let (out_png, mask_png) = (dir.path().join("r.png"), dir.path().join("m.png"));
    let out = fixedfunc(&[
        "render",
        "--technique",
        "multidigit16",
        "--size",
        "96x72",
        "--map-size",
        "64",
        "--offset",
        "1,256",
        "--frames",
        "3",
        "--depth-map",
        arg(&map),
        "--out",
        arg(&out_png),
        "--mask",
        arg(&mask_png),
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert!(stdout.contains("· 1 map made"), "{stdout}");
    assert!(stdout.contains("6 passes"), "{stdout}");
    let big = image::open(dir.path().join("map-big-digit.png")).expect("big digit");
    let little = image::open(dir.path().join("map-little-digit.png")).expect("little digit");
    assert_eq!((big.width(), big.height()), (64, 64));
    // The big digit barely changes over the receivers; the little digit is where the
    // information is: many more distinct values.
    let distinct = |img: &image::DynamicImage| {
        let mut v: Vec<[u8; 4]> = img.to_rgba8().pixels().map(|p| p.0).collect();
        v.sort_unstable();
        v.dedup();
        v.len()
    };
    assert!(
        distinct(&little) > 2 * distinct(&big),
        "little {} vs big {} distinct values",
        distinct(&little),
        distinct(&big)
    );
    // The big digit is grey, the little digit pseudo-coloured.
    assert!(big
        .to_rgba8()
        .pixels()
        .all(|p| p[0] == p[1] && p[1] == p[2]));
    assert!(little
        .to_rgba8()
        .pixels()
        .any(|p| p[0] != p[1] || p[1] != p[2]));
}

#[test]
fn remaking_maps_every_frame_is_counted() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (out_png, mask_png) = (dir.path().join("r.png"), dir.path().join("m.png"));
    let out = fixedfunc(&[
        "render",
        "--technique",
        "dual8",
        "--size",
        "64x64",
        "--frames",
        "3",
        "--remake-maps",
        "always",
        "--out",
        arg(&out_png),
        "--mask",
        arg(&mask_png),
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).contains("· 3 maps made"),
        "{}",
        text(&out.stdout)
    );
}

#[test]
fn impossible_shadow_parameters_are_clear_errors() {
    let cases: [(&[&str], &str); 4] = [
        (&["--offset", "1"], "FACTOR,UNITS"),
        (&["--offset", "1,NaN"], "FACTOR,UNITS"),
        (
            &["--technique", "multidigit16", "--depth-bits", "16"],
            "needs a stencil buffer",
        ),
        (&["--map-size", "0"], "map-size"),
    ];
    for (extra, expected) in cases {
        let mut args = vec!["render", "--size", "32x32", "--out", "/dev/null"];
        args.extend_from_slice(extra);
        let out = fixedfunc(&args);
        assert!(!out.status.success(), "{extra:?} should fail");
        let stderr = text(&out.stderr);
        assert!(stderr.contains(expected), "{extra:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}
