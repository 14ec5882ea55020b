//! The fidelity harness: one GL script, run through the emulated path (core 3.3) and the
//! native path (Mesa's own fixed-function code on a compatibility context) on each headless
//! backend, returning both framebuffers and both sets of readback slots so a test can
//! compare the paths against each other and against piglit's numbers.
#![allow(dead_code)]

use fixedfunc::vocab::{DepthBits, PipelineKind, Precision};
use std::collections::BTreeMap;
use std::path::PathBuf;

use fixedfunc::ff::{script, Command};
use fixedfunc::gpu::Backend;
use fixedfunc::pipeline::emulate::EmulatedPipeline;
use fixedfunc::pipeline::{self, Pipeline, Readback};
use image::RgbaImage;

use crate::support::{self, Tolerance};

/// The size and buffers of the target a case renders into.
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    pub stencil: bool,
}

impl Frame {
    pub const fn new(width: u32, height: u32) -> Frame {
        Frame {
            width,
            height,
            stencil: false,
        }
    }

    pub const fn with_stencil(mut self) -> Frame {
        self.stencil = true;
        self
    }
}

/// What one path produced: the colour buffer (top row first), the readback slots and the
/// window depth values (bottom row first, as GL reads them).
pub struct Output {
    pub image: RgbaImage,
    pub readbacks: BTreeMap<u32, Readback>,
    pub depth: Vec<f32>,
    /// What the pipeline counted.
    pub counters: fixedfunc::pipeline::Counters,
}

/// Both paths on one backend.
pub struct Pair {
    pub backend: Backend,
    pub emulate: Output,
    pub native: Output,
}

/// Reads `tests/scripts/fidelity/NAME.c`.
pub fn script_file(name: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/scripts/fidelity")
        .join(format!("{name}.c"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Parses a script; a parse error fails the test with its line and column.
pub fn parse(source: &str) -> Vec<Command> {
    script::parse(source).unwrap_or_else(|e| panic!("{e}"))
}

/// Runs `commands` through one path on `backend`; the model must record no GL error and
/// the driver none either.
pub fn run_one(
    kind: PipelineKind,
    precision: Precision,
    backend: Backend,
    frame: Frame,
    commands: &[Command],
) -> Output {
    let ctx = support::context(backend, fixedfunc::pipeline::profile(kind));
    let t = support::target(
        &ctx,
        frame.width,
        frame.height,
        DepthBits::D24,
        frame.stencil,
    );
    let mut p: Box<dyn Pipeline> = match kind {
        PipelineKind::Emulate => Box::new(
            EmulatedPipeline::new(&ctx)
                .expect("emulated pipeline")
                .with_precision(precision),
        ),
        PipelineKind::Native => pipeline::create(kind, &ctx).expect("native pipeline"),
    };
    p.execute(&ctx, commands)
        .unwrap_or_else(|e| panic!("{backend} {kind:?}: {e}"));
    assert_eq!(
        p.take_gl_error(),
        None,
        "{backend} {kind:?}: model GL error"
    );
    let mut readbacks = BTreeMap::new();
    for slot in 0..64 {
        if let Some(r) = p.readback(slot) {
            readbacks.insert(slot, r.clone());
        }
    }
    let image = t.read_color(&ctx).expect("colour readback");
    let depth = t.read_depth_f32(&ctx).expect("depth readback");
    support::assert_no_gl_error(&ctx);
    let counters = p.counters();
    p.release(&ctx);
    t.delete(&ctx);
    Output {
        image,
        readbacks,
        depth,
        counters,
    }
}

/// Runs the script on both paths (emulate in `Precision::Float`) on every headless backend.
pub fn run_both(source: &str, frame: Frame) -> Vec<Pair> {
    let commands = parse(source);
    support::HEADLESS
        .into_iter()
        .map(|backend| Pair {
            backend,
            emulate: run_one(
                PipelineKind::Emulate,
                Precision::Float,
                backend,
                frame,
                &commands,
            ),
            native: run_one(
                PipelineKind::Native,
                Precision::Float,
                backend,
                frame,
                &commands,
            ),
        })
        .collect()
}

/// Runs both paths and asserts the images agree within `tol`; returns the pairs for probes.
pub fn compare(name: &str, source: &str, frame: Frame, tol: Tolerance) -> Vec<Pair> {
    let pairs = run_both(source, frame);
    for p in &pairs {
        support::assert_images_match(
            &format!("{name}-{}", p.backend),
            &p.emulate.image,
            &p.native.image,
            tol,
        );
    }
    pairs
}

/// Probes the pixel at (x, y) counted from the bottom-left, as GL and piglit do.
pub fn probe_gl(img: &RgbaImage, x: u32, y: u32, expected: [u8; 4], tol: u8) {
    support::probe(img, x, img.height() - 1 - y, expected, tol);
}

/// Probes only the RGB channels (bottom-left origin).
pub fn probe_rgb(img: &RgbaImage, x: u32, y: u32, expected: [u8; 3], tol: u8) {
    let p = img.get_pixel(x, img.height() - 1 - y).0;
    let ok = (0..3).all(|i| p[i].abs_diff(expected[i]) <= tol);
    assert!(
        ok,
        "pixel ({x},{y}) from bottom is {p:?}, expected rgb {expected:?} ± {tol}"
    );
}

/// A value in [0, 1] as an unorm8 byte.
pub fn unorm8(v: f64) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// Projection glOrtho(0, w, 0, h, −1, 1) and identity modelview, so that a unit quad at
/// (x, y) covers exactly pixel (x, y).
pub fn ortho(w: u32, h: u32) -> String {
    format!(
        "glMatrixMode(GL_PROJECTION);\nglLoadIdentity();\nglOrtho(0, {w}, 0, {h}, -1, 1);\nglMatrixMode(GL_MODELVIEW);\nglLoadIdentity();\n"
    )
}
