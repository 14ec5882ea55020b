//! Per-fragment fidelity: piglit fbo-alphatest-formats boundaries (RGBA8, emulate in both
//! precisions and native), general/stencil-wrap, general/polygon-offset and gl-1.4
//! polygon-offset (units and slope within piglit's bounds), and the depth readback rules
//! (UNSIGNED_BYTE truncates, UNSIGNED_SHORT rounds, at the boundaries).

mod fidelity;
mod support;

use fidelity::{compare, ortho, parse, probe_gl, run_both, run_one, script_file, Frame};
use fixedfunc::vocab::{PipelineKind, Precision};
use support::Tolerance;

/// A unit quad at pixel (x, y) of an ortho(0, w, 0, h) window, at object depth z.
fn pixel_quad(x: u32, y: u32, z: f32) -> String {
    format!(
        "glBegin(GL_QUADS);\nglVertex3f({x}, {y}, {z}); glVertex3f({}, {y}, {z}); glVertex3f({}, {}, {z}); glVertex3f({x}, {}, {z});\nglEnd();\n",
        x + 1,
        x + 1,
        y + 1,
        y + 1
    )
}

/// fbo-alphatest-formats: (fragment alpha, func, ref, passes).
const ALPHA_CASES: [(f32, &str, f32, bool); 8] = [
    (0.2, "GL_LESS", 0.25, true),
    (0.96, "GL_LEQUAL", 0.92, false),
    (0.6, "GL_GREATER", 0.55, true),
    (0.9, "GL_GREATER", 0.1, true),
    (0.35, "GL_GEQUAL", 0.4, false),
    (0.4, "GL_EQUAL", 0.4, true),
    (0.8, "GL_NOTEQUAL", 0.8, false),
    (0.5, "GL_NEVER", 3.0, false),
];

/// Script `alpha_test_boundaries.c`: each case writes pixel (i, 0) white with its alpha if
/// the test passes, else leaves the clear colour (0, 0, 0, 0). Exact (tol 0 on RGB, 1 on
/// alpha for the stored value) on emulate Float, emulate Fixed8 and native.
#[test]
fn alpha_test_boundaries_of_fbo_alphatest_formats() {
    let commands = parse(&script_file("alpha_test_boundaries"));
    for backend in support::HEADLESS {
        for (kind, precision) in [
            (PipelineKind::Emulate, Precision::Float),
            (PipelineKind::Emulate, Precision::Fixed8),
            (PipelineKind::Native, Precision::Float),
        ] {
            let out = run_one(kind, precision, backend, Frame::new(8, 1), &commands);
            for (i, (a, func, r, pass)) in ALPHA_CASES.iter().enumerate() {
                let px = out.image.get_pixel(i as u32, 0).0;
                let expected = if *pass {
                    [255, 255, 255, fidelity::unorm8(f64::from(*a))]
                } else {
                    [0, 0, 0, 0]
                };
                let ok = px[..3] == expected[..3] && px[3].abs_diff(expected[3]) <= 1;
                assert!(
                    ok,
                    "{backend} {kind:?} {precision:?}: {a} {func} {r}: {px:?}, expected {expected:?}"
                );
            }
        }
    }
}

/// general/stencil-wrap on an 8-bit stencil (max 255), one column per op: INCR 260 times
/// saturates at 255; DECR 5 times from 0 stays 0; INCR_WRAP 260 times leaves 4; DECR_WRAP 5
/// times from 0 leaves 251. A grey quad drawn with StencilFunc(EQUAL, expected) must cover
/// every column (script `stencil_wrap.c`): 0.5 grey (128) everywhere, exact.
#[test]
fn stencil_wrap_saturates_and_wraps() {
    let src = script_file("stencil_wrap");
    for p in compare(
        "stencil-wrap",
        &src,
        Frame::new(4, 1).with_stencil(),
        Tolerance::EXACT,
    ) {
        for out in [&p.emulate, &p.native] {
            for x in 0..4 {
                probe_gl(&out.image, x, 0, [128, 128, 128, 255], 0);
            }
        }
    }
}

/// Window depth w drawn as object z = 1 − 2w under ortho(…, −1, 1) (window z = 0.5 − z/2).
fn depth_script(ws: &[f64], ty: &str) -> String {
    let mut s = format!(
        "glClearDepth(1);\nglClear(GL_DEPTH_BUFFER_BIT);\n{}glEnable(GL_DEPTH_TEST);\nglDepthFunc(GL_ALWAYS);\n",
        ortho(ws.len() as u32, 1)
    );
    for (i, w) in ws.iter().enumerate() {
        s += &pixel_quad(i as u32, 0, (1.0 - 2.0 * w) as f32);
    }
    s + &format!(
        "glReadPixels(0, 0, {}, 1, GL_DEPTH_COMPONENT, {ty}, readback_1);\n",
        ws.len()
    )
}

/// H4/H5: UNSIGNED_BYTE is ⌊255z⌋ (0.25 → 63, 0.5 → 127, 127.9/255 → 127, 128.1/255 → 128);
/// UNSIGNED_SHORT is round(65535z) (0.25 → 16384, 0.5 → 32768, 1000.4/65535 → 1000,
/// 1000.6/65535 → 1001). Exact on both paths (the readback reads the same D24 buffer).
#[test]
fn depth_readback_ubyte_truncates_ushort_rounds() {
    let ub = [0.25, 0.5, 127.9 / 255.0, 128.1 / 255.0];
    for p in run_both(&depth_script(&ub, "GL_UNSIGNED_BYTE"), Frame::new(4, 1)) {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            assert_eq!(
                out.readbacks[&1].bytes,
                vec![63, 127, 127, 128],
                "{} {path} UNSIGNED_BYTE",
                p.backend
            );
        }
    }
    let us = [0.25, 0.5, 1000.4 / 65535.0, 1000.6 / 65535.0];
    for p in run_both(&depth_script(&us, "GL_UNSIGNED_SHORT"), Frame::new(4, 1)) {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            let v: Vec<u16> = out.readbacks[&1]
                .bytes
                .chunks_exact(2)
                .map(|b| u16::from_le_bytes([b[0], b[1]]))
                .collect();
            assert_eq!(
                v,
                vec![16384, 32768, 1000, 1001],
                "{} {path} UNSIGNED_SHORT",
                p.backend
            );
        }
    }
}

/// general/polygon-offset (FILL/FILL): a red quad with offset (0, 0), then a blue quad at
/// the same z with units −1 (blue must win under LESS) or +1 (red stays). Exact colours.
#[test]
fn polygon_offset_units_decide_coplanar_quads() {
    for (units, expected) in [(-1.0, [0, 0, 255, 255]), (1.0, [255, 0, 0, 255])] {
        let src = format!(
            "glClearColor(0, 0, 0, 1);\nglClearDepth(1);\nglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);\n{}glEnable(GL_DEPTH_TEST);\nglDepthFunc(GL_LESS);\nglEnable(GL_POLYGON_OFFSET_FILL);\nglPolygonOffset(0, 0);\nglColor4f(1, 0, 0, 1);\nglBegin(GL_QUADS);\nglVertex3f(0, 0, 0.3f); glVertex3f(8, 0, 0.3f); glVertex3f(8, 8, 0.3f); glVertex3f(0, 8, 0.3f);\nglEnd();\nglPolygonOffset(0, {units});\nglColor4f(0, 0, 1, 1);\nglBegin(GL_QUADS);\nglVertex3f(0, 0, 0.3f); glVertex3f(8, 0, 0.3f); glVertex3f(8, 8, 0.3f); glVertex3f(0, 8, 0.3f);\nglEnd();\n",
            ortho(8, 8)
        );
        for p in compare(
            &format!("offset-units-{units}"),
            &src,
            Frame::new(8, 8),
            Tolerance::EXACT,
        ) {
            for out in [&p.emulate, &p.native] {
                probe_gl(&out.image, 1, 1, expected, 0);
                probe_gl(&out.image, 6, 6, expected, 0);
            }
        }
    }
}

/// One quad filling a 32×32 window under ortho(±1, ±1, −10, 10), rotated `angle`° about
/// `axis`, drawn with PolygonOffset(factor, units); returns the depth buffer per path.
fn offset_depths(
    dz: f32,
    angle: f32,
    axis: [f32; 3],
    factor: f32,
    units: f32,
) -> Vec<(Vec<f32>, Vec<f32>)> {
    let src = format!(
        "glClearDepth(1);\nglClear(GL_DEPTH_BUFFER_BIT);\nglMatrixMode(GL_PROJECTION);\nglLoadIdentity();\nglOrtho(-1, 1, -1, 1, -10, 10);\nglMatrixMode(GL_MODELVIEW);\nglLoadIdentity();\nglTranslatef(0, 0, {dz}f);\nglRotatef({angle}f, {}f, {}f, {}f);\nglEnable(GL_DEPTH_TEST);\nglDepthFunc(GL_ALWAYS);\nglEnable(GL_POLYGON_OFFSET_FILL);\nglPolygonOffset({factor}f, {units}f);\nglBegin(GL_QUADS);\nglVertex3f(-0.8f, -0.8f, 0); glVertex3f(0.8f, -0.8f, 0); glVertex3f(0.8f, 0.8f, 0); glVertex3f(-0.8f, 0.8f, 0);\nglEnd();\n",
        axis[0], axis[1], axis[2]
    );
    run_both(&src, Frame::new(32, 32))
        .into_iter()
        .map(|p| (p.emulate.depth, p.native.depth))
        .collect()
}

/// gl-1.4 polygon-offset, units: the ideal MRD of a D24 buffer is one step, 1/(2²⁴ − 1);
/// PolygonOffset(0, ±1) must move the depth by [0.99, 2.0] × MRD, on both paths. The quad
/// is translated to z_eye = 0.2 (window z 0.49), away from the exact-half case of H7.
#[test]
fn polygon_offset_units_within_piglit_mrd_bounds() {
    let mrd = 1.0 / f64::from((1u32 << 24) - 1);
    let base = offset_depths(0.2, 0.0, [1.0, 0.0, 0.0], 0.0, 0.0);
    for units in [-1.0f32, 1.0] {
        let moved = offset_depths(0.2, 0.0, [1.0, 0.0, 0.0], 0.0, units);
        for ((b_e, b_n), (m_e, m_n)) in base.iter().zip(&moved) {
            for (path, b, m) in [("emulate", b_e, m_e), ("native", b_n, m_n)] {
                let i = 16 * 32 + 16;
                let d = (f64::from(m[i]) - f64::from(b[i])) * f64::from(units);
                println!(
                    "{path} units {units}: base {} shift {:.3} LSB",
                    b[i],
                    d / mrd
                );
                assert!(
                    d >= 0.99 * mrd && d <= 2.0 * mrd,
                    "{path} units {units}: shift {d:e} not in [0.99, 2.0] × MRD {mrd:e}"
                );
            }
        }
    }
}

/// gl-1.4 polygon-offset, slope: the quad rotated 30/45/60/80° about (1,0,0), (0,1,0),
/// (1,1,0) and (2,1,0); dz/dx and dz/dy from neighbouring depths at the centre.
/// PolygonOffset(−1, 0) must shift by [0.9·max(|dzdx|,|dzdy|), 1.1·√(dzdx²+dzdy²) + MRD]
/// and (−2, 0) by twice that range, on both paths.
#[test]
fn polygon_offset_slope_within_piglit_bounds() {
    let mrd = 1.0 / f64::from((1u32 << 24) - 1);
    for axis in [
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 0.0],
        [2.0, 1.0, 0.0],
    ] {
        for angle in [30.0f32, 45.0, 60.0, 80.0] {
            let base = offset_depths(0.0, angle, axis, 0.0, 0.0);
            for factor in [-1.0f32, -2.0] {
                let moved = offset_depths(0.0, angle, axis, factor, 0.0);
                for ((b_e, b_n), (m_e, m_n)) in base.iter().zip(&moved) {
                    for (path, b, m) in [("emulate", b_e, m_e), ("native", b_n, m_n)] {
                        let at = |x: usize, y: usize| f64::from(b[y * 32 + x]);
                        let dzdx = (at(17, 16) - at(15, 16)) / 2.0;
                        let dzdy = (at(16, 17) - at(16, 15)) / 2.0;
                        let k = -f64::from(factor);
                        let lo = k * 0.9 * dzdx.abs().max(dzdy.abs());
                        let hi = k * (1.1 * dzdx.hypot(dzdy) + mrd);
                        let d = at(16, 16) - f64::from(m[16 * 32 + 16]);
                        assert!(
                            d >= lo && d <= hi,
                            "{path} {angle}° about {axis:?}, factor {factor}: shift {d:e} not in [{lo:e}, {hi:e}]"
                        );
                    }
                }
            }
        }
    }
}

/// H7 in D24 steps at the centre pixel: at window z 0.5 exactly (z_eye 0) units −1/+1/+4
/// shift by −2/+1/+7, at window z 0.49 by −2/+2/+8 (llvmpipe's numbers
/// as measured for H7). Exact, and emulate must equal native step for step.
#[test]
fn polygon_offset_steps_match_mesa_exactly() {
    let step = |z: f32| (f64::from(z) * f64::from((1u32 << 24) - 1)).round() as i64;
    for (dz, shifts) in [(0.0f32, [-2i64, 1, 7]), (0.2, [-2, 2, 8])] {
        let base = offset_depths(dz, 0.0, [1.0, 0.0, 0.0], 0.0, 0.0);
        for (units, want) in [-1.0f32, 1.0, 4.0].into_iter().zip(shifts) {
            let moved = offset_depths(dz, 0.0, [1.0, 0.0, 0.0], 0.0, units);
            for ((b_e, b_n), (m_e, m_n)) in base.iter().zip(&moved) {
                let i = 16 * 32 + 16;
                let e = step(m_e[i]) - step(b_e[i]);
                let n = step(m_n[i]) - step(b_n[i]);
                assert_eq!(
                    (e, n),
                    (want, want),
                    "z_eye {dz}, units {units}: (emulate, native)"
                );
            }
        }
    }
}
