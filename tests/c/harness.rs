//! How the tests build and run C programs on the OSMesa API: compiled with `cc` as C99 with
//! every warning an error against Mesa's `GL/osmesa.h` (Debian's libosmesa6-dev), linked
//! with `-lOSMesa -lm`, and run on Mesa's `libOSMesa.so.8` or, with
//! `LD_LIBRARY_PATH=$(fixedfunc osmesa-dir)`, on the layer's; their images are binary PPMs.
//! The rules are `tests/c_programs.rs`'s, kept here to be shared by every test that runs a C
//! program (`#[path = "c/harness.rs"] mod harness;`).
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use image::{Rgba, RgbaImage};

/// Which library a program runs on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Library {
    Mesa,
    Fixedfunc,
}

/// Compiles `source` into `exe` as C99 with every warning an error, against Mesa's headers
/// and `-lOSMesa -lm`.
pub fn compile(source: &Path, exe: &Path) {
    let out = Command::new("cc")
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-O1", "-o"])
        .arg(exe)
        .arg(source)
        .args(["-lOSMesa", "-lm"])
        .output()
        .expect("cc runs");
    assert!(
        out.status.success(),
        "cc {} failed (needs gcc and libosmesa6-dev):\n{}",
        source.display(),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The folder `fixedfunc osmesa-dir` prints, holding the layer as `libOSMesa.so.8`.
pub fn fixedfunc_dir() -> PathBuf {
    let out = Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .arg("osmesa-dir")
        .output()
        .expect("fixedfunc runs");
    assert!(
        out.status.success(),
        "fixedfunc osmesa-dir failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let dir = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
    assert!(
        dir.join("libOSMesa.so.8").exists(),
        "{} lacks libOSMesa.so.8",
        dir.display()
    );
    dir
}

/// Runs `exe` with `args` on `library`, whatever its exit status.
pub fn output(exe: &Path, library: Library, args: &[&str]) -> Output {
    let mut cmd = Command::new(exe);
    cmd.args(args);
    match library {
        Library::Fixedfunc => {
            cmd.env("LD_LIBRARY_PATH", fixedfunc_dir());
        }
        Library::Mesa => {
            cmd.env_remove("LD_LIBRARY_PATH");
        }
    }
    cmd.output().expect("the program runs")
}

/// Runs `exe` with `args` on `library`; it must succeed.
pub fn run(exe: &Path, library: Library, args: &[&str]) -> Output {
    let out = output(exe, library, args);
    assert!(
        out.status.success(),
        "{} on {library:?} failed ({}):\n{}",
        exe.display(),
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// A binary PPM (P6, maxval 255) as an opaque RGBA image.
pub fn read_ppm(path: &Path) -> RgbaImage {
    let data = std::fs::read(path).expect("the program wrote its image");
    let mut fields = Vec::new();
    let mut pos = 0;
    while fields.len() < 4 {
        while data[pos].is_ascii_whitespace() {
            pos += 1;
        }
        let start = pos;
        while !data[pos].is_ascii_whitespace() {
            pos += 1;
        }
        fields.push(String::from_utf8_lossy(&data[start..pos]).into_owned());
    }
    assert_eq!(fields[0], "P6");
    let (w, h): (u32, u32) = (fields[1].parse().unwrap(), fields[2].parse().unwrap());
    let pixels = &data[pos + 1..];
    RgbaImage::from_fn(w, h, |x, y| {
        let i = ((y * w + x) * 3) as usize;
        Rgba([pixels[i], pixels[i + 1], pixels[i + 2], 255])
    })
}
