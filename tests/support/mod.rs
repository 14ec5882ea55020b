//! Shared test support: real contexts per backend, GL error checks, pixel probes with a
//! tolerance, and image comparison that leaves `-actual.png` / `-diff.png` on failure.
#![allow(dead_code)]

use fixedfunc::vocab::DepthBits;
use std::path::PathBuf;

use fixedfunc::gpu::{Backend, ContextRequest, GpuContext, Profile, RenderTarget, TargetSpec};
use glow::HasContext;
use image::{Rgba, RgbaImage};

/// The headless backends every GPU test runs on.
pub const HEADLESS: [Backend; 2] = [Backend::Egl, Backend::OsMesa];

/// A real context; a test that cannot get one fails with the backend's own error.
pub fn context(backend: Backend, profile: Profile) -> GpuContext {
    match GpuContext::new(&ContextRequest::new(backend, profile)) {
        Ok(ctx) => ctx,
        Err(e) => panic!("{backend} {} context: {e}", profile.name()),
    }
}

/// A target, bound, with the viewport covering it.
pub fn target(ctx: &GpuContext, w: u32, h: u32, depth: DepthBits, stencil: bool) -> RenderTarget {
    let spec = TargetSpec {
        stencil,
        ..TargetSpec::new(w, h, depth)
    };
    RenderTarget::new(ctx, spec).unwrap_or_else(|e| panic!("target {spec:?}: {e}"))
}

/// Fails the test if GL recorded an error.
pub fn assert_no_gl_error(ctx: &GpuContext) {
    let code = unsafe { ctx.gl().get_error() };
    assert_eq!(code, glow::NO_ERROR, "GL error 0x{code:04X}");
}

/// Asserts that the pixel at (x, y), top row first, is `expected` within `tol` per channel.
pub fn probe(img: &RgbaImage, x: u32, y: u32, expected: [u8; 4], tol: u8) {
    let got = img.get_pixel(x, y).0;
    let ok = got.iter().zip(expected).all(|(&g, e)| g.abs_diff(e) <= tol);
    assert!(
        ok,
        "pixel ({x},{y}) is {got:?}, expected {expected:?} ± {tol}"
    );
}

/// How far two images may differ.
#[derive(Clone, Copy, Debug)]
pub struct Tolerance {
    /// Largest allowed difference of one channel.
    pub per_channel: u8,
    /// How many pixels may exceed `per_channel`.
    pub max_bad_pixels: usize,
}

impl Tolerance {
    pub const EXACT: Tolerance = Tolerance {
        per_channel: 0,
        max_bad_pixels: 0,
    };
}

/// Where failing image tests leave their evidence.
pub fn output_dir() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("images");
    let _ = std::fs::create_dir_all(&dir);
    dir
}

/// Compares two images; on failure writes `NAME-expected.png`, `NAME-actual.png` and
/// `NAME-diff.png` (red where a pixel is out of tolerance) and panics with the count.
pub fn assert_images_match(name: &str, actual: &RgbaImage, expected: &RgbaImage, tol: Tolerance) {
    assert_eq!(
        actual.dimensions(),
        expected.dimensions(),
        "{name}: image sizes differ"
    );
    let mut diff = RgbaImage::new(actual.width(), actual.height());
    let mut bad = 0;
    let mut worst = 0u8;
    for (x, y, a) in actual.enumerate_pixels() {
        let e = expected.get_pixel(x, y);
        let d =
            a.0.iter()
                .zip(e.0)
                .map(|(&p, q)| p.abs_diff(q))
                .max()
                .unwrap_or(0);
        worst = worst.max(d);
        if d > tol.per_channel {
            bad += 1;
            diff.put_pixel(x, y, Rgba([255, 0, 0, 255]));
        } else {
            diff.put_pixel(x, y, Rgba([d * 16, d * 16, d * 16, 255]));
        }
    }
    if bad > tol.max_bad_pixels {
        let dir = output_dir();
        let _ = actual.save(dir.join(format!("{name}-actual.png")));
        let _ = expected.save(dir.join(format!("{name}-expected.png")));
        let _ = diff.save(dir.join(format!("{name}-diff.png")));
        panic!(
            "{name}: {bad} pixels differ by more than {} (allowed {}; worst {worst}); see {}",
            tol.per_channel,
            tol.max_bad_pixels,
            dir.display()
        );
    }
}
