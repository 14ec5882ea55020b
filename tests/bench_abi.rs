//! `bench --only abi`: the benchmark's C program (`benches/c/abi_bench.c`) compiled as the
//! group compiles it and run on Mesa's OSMesa and on the layer's C library. No timing is
//! asserted: what is checked is that both libraries draw each mode's workload alike (the
//! same vertex and draw counts, images within 3/255 on 99% of pixels, a shadow in the
//! shadow frame), that the group's JSON has a row per mode, and that a bad mode, a missing
//! library folder, compiler or header give their stated errors.

#[path = "c/harness.rs"]
mod harness;
mod support;

use std::path::{Path, PathBuf};
use std::process::Command;

use fixedfunc::bench::abi::{AbiError, AbiMode, Heap, Libraries, Library, Program};
use fixedfunc::vocab::Named;
use image::{Rgba, RgbaImage};
use support::{assert_images_match, Tolerance};

/// Per frame: 16 spheres of 48 × 24 cells, two triangles each; the shadow frame adds a
/// 32 × 32 ground and draws everything twice (light pass, eye pass).
const SPHERES_VERTICES: u64 = 16 * 6 * 48 * 24;
const SHADOW_VERTICES: u64 = 2 * (SPHERES_VERTICES + 6 * 32 * 32);

fn work_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("bench_abi")
        .join(name);
    std::fs::create_dir_all(&dir).expect("the test folder can be made");
    dir
}

/// A binary PPM (P6, maxval 255) as an opaque RGBA image.
fn read_ppm(path: &Path) -> RgbaImage {
    let data = std::fs::read(path).expect("the program wrote its image");
    let header = b"P6\n256 256\n255\n";
    assert!(
        data.starts_with(header),
        "{} is not a 256x256 PPM",
        path.display()
    );
    let pixels = &data[header.len()..];
    assert_eq!(pixels.len(), 256 * 256 * 3);
    RgbaImage::from_fn(256, 256, |x, y| {
        let i = ((y * 256 + x) * 3) as usize;
        Rgba([pixels[i], pixels[i + 1], pixels[i + 2], 255])
    })
}

#[test]
fn both_libraries_draw_every_mode_alike() {
    let program = Program::compile().expect("the program compiles");
    let libraries = Libraries {
        fixedfunc_dir: harness::fixedfunc_dir(),
    };
    let dir = work_dir("modes");
    for mode in AbiMode::all() {
        let [mesa, ours] = [Library::Mesa, Library::Fixedfunc].map(|library| {
            let ppm = dir.join(format!("{mode}-{library}.ppm"));
            let out = program
                .run(&libraries, library, mode, Heap::Glibc, 2, Some(&ppm))
                .unwrap_or_else(|e| panic!("{mode} on {library}: {e}"));
            (out, read_ppm(&ppm))
        });
        let expected = match mode {
            AbiMode::Shadow => SHADOW_VERTICES,
            _ => SPHERES_VERTICES,
        };
        assert_eq!(mesa.0.vertices, expected, "{mode}: vertices per frame");
        assert_eq!(ours.0.vertices, expected, "{mode}: vertices per frame");
        assert_eq!(mesa.0.draws, ours.0.draws, "{mode}: draws per frame");
        assert_eq!(mesa.0.frame_ms.len(), 2);
        assert_eq!(ours.0.frame_ms.len(), 2);
        assert_ne!(mesa.0.vendor, "fixedfunc");
        assert_eq!(ours.0.vendor, "fixedfunc");
        if mode == AbiMode::Shadow {
            // More than 2% of the image in shadow, on both.
            assert!(
                mesa.0.dark > 1300 && ours.0.dark > 1300,
                "{mode}: no shadow"
            );
        }
        assert_images_match(
            &format!("bench-abi-{mode}"),
            &ours.1,
            &mesa.1,
            Tolerance {
                per_channel: 3,
                max_bad_pixels: 256 * 256 / 100,
            },
        );
    }
}

#[test]
fn an_unknown_mode_or_frame_count_is_refused_with_the_usage() {
    let program = Program::compile().expect("the program compiles");
    for args in [&["spheres", "3"][..], &["arrays", "0"], &["arrays"]] {
        let out = Command::new(program.path())
            .args(args)
            .output()
            .expect("the program runs");
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            stderr.contains("MODE is immediate, arrays, lists, buffers or shadow"),
            "{args:?}: {stderr}"
        );
    }
}

#[test]
fn a_folder_without_the_library_is_an_error_not_a_run_on_mesa() {
    let program = Program::compile().expect("the program compiles");
    let empty = work_dir("empty");
    let libraries = Libraries {
        fixedfunc_dir: empty.clone(),
    };
    let error = program
        .run(
            &libraries,
            Library::Fixedfunc,
            AbiMode::Arrays,
            Heap::Glibc,
            1,
            None,
        )
        .expect_err("no library in the folder");
    assert!(matches!(error, AbiError::LibraryMissing { .. }), "{error}");
    let text = error.to_string();
    assert!(
        text.contains(&empty.join("libOSMesa.so.8").display().to_string())
            && text.contains("cargo build"),
        "{text}"
    );
}

fn bench_abi(cc: Option<&str>, json: bool) -> std::process::Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_fixedfunc"));
    cmd.args(["bench", "--only", "abi", "--repeats", "1"]);
    if json {
        cmd.arg("--json");
    }
    if let Some(cc) = cc {
        cmd.env("CC", cc);
    }
    cmd.output().expect("fixedfunc runs")
}

#[test]
fn the_group_reports_a_row_per_mode_heap_and_span() {
    let out = bench_abi(None, true);
    assert!(
        out.status.success(),
        "bench --only abi failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let rows: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let rows = rows.as_array().expect("an array of rows");
    let cases: Vec<(&str, &str, &str)> = rows
        .iter()
        .filter_map(|r| {
            Some((
                r["mode"].as_str()?,
                r["heap"].as_str()?,
                r["span"].as_str()?,
            ))
        })
        .collect();
    // Early runs under both heaps; settled runs under the untrimmed heap.
    let expected: Vec<(&str, &str, &str)> = AbiMode::names()
        .iter()
        .flat_map(|&m| {
            [
                (m, "glibc", "early"),
                (m, "untrimmed", "early"),
                (m, "untrimmed", "settled"),
            ]
        })
        .collect();
    assert_eq!(cases, expected);
    for r in rows {
        let mode = r["mode"].as_str().unwrap_or("?");
        let expected = if mode == "shadow" {
            SHADOW_VERTICES
        } else {
            SPHERES_VERTICES
        };
        assert_eq!(r["vertices_per_frame"].as_u64(), Some(expected), "{mode}");
        let ratio = r["ratio"].as_f64().expect("a ratio");
        assert!(ratio.is_finite() && ratio > 0.0, "{mode}: ratio {ratio}");
        // One repeat: the one pair's ratio is the ratio of the two medians.
        let paired = &r["paired"];
        assert_eq!(paired["samples"].as_u64(), Some(1), "{mode}");
        let p = paired["median"].as_f64().expect("a paired ratio");
        assert!(
            (p - ratio).abs() < 1e-9,
            "{mode}: paired {p}, ratio {ratio}"
        );
        let verdict = r["verdict"].as_str().expect("a verdict");
        let target = r["target"].as_f64();
        match target {
            Some(t) => assert_eq!(verdict, if ratio <= t { "met" } else { "missed" }),
            None => assert_eq!(verdict, "none"),
        }
        assert_eq!(r["fixedfunc"]["vendor"], "fixedfunc");
        assert_ne!(r["mesa"]["vendor"], "fixedfunc");
        for library in ["mesa", "fixedfunc"] {
            let frame = &r[library]["frame_ms"];
            assert_eq!(frame["samples"].as_u64(), Some(1), "{mode} {library}");
            assert!(frame["median"].as_f64().is_some_and(|m| m > 0.0));
        }
    }
}

#[test]
fn a_missing_compiler_or_header_names_the_packages() {
    for (cc, names) in [
        (
            "/nonexistent/cc",
            "cannot run the C compiler `/nonexistent/cc`",
        ),
        // No system headers under that root: GL/osmesa.h is the first include missing.
        ("cc --sysroot=/nonexistent", "osmesa.h"),
    ] {
        let out = bench_abi(Some(cc), false);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{cc}: the bench ran");
        assert!(
            stderr.contains(names) && stderr.contains("gcc") && stderr.contains("libosmesa6-dev"),
            "{cc}: {stderr}"
        );
    }
}
