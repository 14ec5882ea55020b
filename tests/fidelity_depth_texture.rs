//! Depth-texture fidelity: piglit texturing/depth-tex-compare (r from 2.0 to 0.0, clamped to
//! [0, 1] before the compare, H11) and texturing/texdepth (cells 0, 0.25, 0.5, 1.0 against
//! r = 0.6/0.2/0.5/0.8 in LUMINANCE, INTENSITY and ALPHA modes, the w = 3.3 homogeneous run,
//! and the ARB_shadow_ambient fail value 0.4 — asserted on emulate only, Mesa has no
//! ARB_shadow_ambient), and texdepth's second texture made by CopyTexImage2D from the
//! depth buffer. Results are shown with REPLACE and checked per pixel.
//!
//! DEPTH_TEXTURE_MODE: the paths are compared exactly everywhere; no deviation of Mesa's
//! native path from ARB_depth_texture was measured (Mesa 22.3.6, see
//! `depth_texture_mode_is_honoured_by_both_paths`, which would name one).

mod fidelity;
mod support;

use fidelity::{compare, ortho, run_one, script_file, Frame};
use fixedfunc::vocab::{PipelineKind, Precision};
use support::Tolerance;

/// A compare function: (r, d) → passes.
type Compare = fn(f64, f64) -> bool;

const FUNCS: [(&str, Compare); 8] = [
    ("GL_NEVER", |_, _| false),
    ("GL_LESS", |r, d| r < d),
    ("GL_LEQUAL", |r, d| r <= d),
    ("GL_EQUAL", |r, d| r == d),
    ("GL_GREATER", |r, d| r > d),
    ("GL_NOTEQUAL", |r, d| r != d),
    ("GL_GEQUAL", |r, d| r >= d),
    ("GL_ALWAYS", |_, _| true),
];

/// depth-tex-compare (script `depth_tex_compare.c`): a 2×2 checker of 0.5 / 1.0, REPEAT;
/// one 16×16 quad per function with s, t from 0 to 2 and r from 2.0 to 0.0 across x.
/// Expected per pixel: compare(min(r, 1), d) → 255 or 0, exact; pixels with |r − d| < 0.05
/// (unclamped ties) are left out. Between paths: exact.
#[test]
fn depth_compare_clamps_r_before_comparing() {
    let src = script_file("depth_tex_compare");
    for p in compare(
        "depth-tex-compare",
        &src,
        Frame::new(128, 16),
        Tolerance::EXACT,
    ) {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            for (i, (func, cmp)) in FUNCS.iter().enumerate() {
                for px in 0..16u32 {
                    for py in 0..16u32 {
                        let s = 2.0 * (f64::from(px) + 0.5) / 16.0;
                        let t = 2.0 * (f64::from(py) + 0.5) / 16.0;
                        let r = 2.0 - s;
                        let cell = ((2.0 * s) as usize + (2.0 * t) as usize) % 2;
                        let d = [0.5, 1.0][cell];
                        let rc = r.min(1.0);
                        if (rc - d).abs() < 0.05 && r <= 1.0 {
                            continue;
                        }
                        let e = if cmp(rc, d) { 255 } else { 0 };
                        let got = out.image.get_pixel(i as u32 * 16 + px, 15 - py).0;
                        assert_eq!(
                            got[0], e,
                            "{} {path} {func} at ({px},{py}): r {r:.3}, d {d}",
                            p.backend
                        );
                    }
                }
            }
        }
    }
}

const TEXDEPTH_R: [f64; 4] = [0.6, 0.2, 0.5, 0.8];
/// Texture 0 of texdepth (scripts `texdepth*.c`); one row of 4 pixels per mode × function
/// × r samples these texels.
const TEXDEPTH_D: [f64; 4] = [0.0, 0.25, 0.5, 1.0];
const MODES: [&str; 3] = ["GL_LUMINANCE", "GL_INTENSITY", "GL_ALPHA"];
/// texdepth skips EQUAL and NOTEQUAL ("bound to be unreliable due to precision problems").
const TEXDEPTH_FUNCS: [usize; 6] = [0, 1, 2, 6, 4, 7];

/// The expected texdepth image: REPLACE of a depth texture in `mode` with result L
/// (1 on pass, `fail` otherwise): LUMINANCE (L, L, L, 1); INTENSITY (L, L, L, L);
/// ALPHA (1, 1, 1, L) (white fragment colour).
fn texdepth_check(name: &str, img: &image::RgbaImage, fail: f64) {
    texdepth_check_texels(name, img, fail, TEXDEPTH_D)
}

fn texdepth_check_texels(name: &str, img: &image::RgbaImage, fail: f64, texels: [f64; 4]) {
    let mut row = 0u32;
    for mode in MODES {
        for f in TEXDEPTH_FUNCS {
            for r in TEXDEPTH_R {
                for (x, d) in texels.iter().enumerate() {
                    let l = if FUNCS[f].1(r, *d) { 1.0 } else { fail };
                    let l8 = fidelity::unorm8(l);
                    let e = match mode {
                        "GL_LUMINANCE" => [l8, l8, l8, 255],
                        "GL_INTENSITY" => [l8; 4],
                        _ => [255, 255, 255, l8],
                    };
                    let got = img.get_pixel(x as u32, 71 - row).0;
                    let ok = got.iter().zip(e).all(|(&g, e)| g.abs_diff(e) <= 1);
                    assert!(
                        ok,
                        "{name} {mode} {} r {r} d {d}: {got:?}, expected {e:?} ± 1",
                        FUNCS[f].0
                    );
                }
                row += 1;
            }
        }
    }
}

/// texdepth, plain (w = 1) and homogeneous (w = 3.3, so s, t and r are divided by q):
/// every cell against the compare result, tol 1/255; paths exact against each other.
#[test]
fn texdepth_functions_modes_and_homogeneous_run() {
    for (w, script) in [(1.0, "texdepth"), (3.3, "texdepth_homogeneous")] {
        let name = format!("texdepth-w{w}");
        for p in compare(
            &name,
            &script_file(script),
            Frame::new(4, 72),
            Tolerance::EXACT,
        ) {
            texdepth_check(
                &format!("{name} {} emulate", p.backend),
                &p.emulate.image,
                0.0,
            );
            texdepth_check(
                &format!("{name} {} native", p.backend),
                &p.native.image,
                0.0,
            );
        }
    }
}

/// texdepth's texture 1, made by CopyTexImage2D(DEPTH_COMPONENT) from the depth buffer
/// (0.25 cleared, 0.75 drawn with DepthFunc ALWAYS): every mode × function × r against the
/// texels 0.25, 0.25, 0.75, 0.75, tol 1/255 per channel; paths exact against each other.
#[test]
fn texdepth_copied_depth_texture() {
    for p in compare(
        "texdepth-copied",
        &script_file("texdepth_copied"),
        Frame::new(4, 72),
        Tolerance::EXACT,
    ) {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            let name = format!("texdepth-copied {} {path}", p.backend);
            texdepth_check_texels(&name, &out.image, 0.0, [0.25, 0.25, 0.75, 0.75]);
        }
    }
}

/// texdepth's ambient run: COMPARE_FAIL_VALUE_ARB 0.4, so a failed compare gives 0.4 (102)
/// instead of 0. Emulate only, against the ARB_shadow_ambient spec value (Mesa's native
/// path has no ARB_shadow_ambient); tol 1/255. The only test of the suite without an
/// oracle: the number is the spec's.
#[test]
fn texdepth_fail_value_on_emulate() {
    let commands = fidelity::parse(&script_file("texdepth_ambient"));
    for backend in support::HEADLESS {
        let frame = Frame::new(4, 72);
        let out = run_one(
            PipelineKind::Emulate,
            Precision::Float,
            backend,
            frame,
            &commands,
        );
        // Only the LUMINANCE block carries the fail value (it is set on that texture).
        texdepth_check_luminance_fail(&format!("ambient {backend}"), &out.image);
    }
}

/// The LUMINANCE rows (the bottom 24) of the ambient run: pass 255, fail 102.
fn texdepth_check_luminance_fail(name: &str, img: &image::RgbaImage) {
    let mut row = 0u32;
    for f in TEXDEPTH_FUNCS {
        for r in TEXDEPTH_R {
            for (x, d) in TEXDEPTH_D.iter().enumerate() {
                let l8 = if FUNCS[f].1(r, *d) { 255 } else { 102 };
                let got = img.get_pixel(x as u32, 71 - row).0;
                let e = [l8, l8, l8, 255];
                let ok = got.iter().zip(e).all(|(&g, e)| g.abs_diff(e) <= 1);
                assert!(
                    ok,
                    "{name} {} r {r} d {d}: {got:?}, expected {e:?} ± 1",
                    FUNCS[f].0
                );
            }
            row += 1;
        }
    }
}

/// DEPTH_TEXTURE_MODE on Mesa's native path, pinned. ARB_depth_texture: a depth (or compare)
/// result c becomes (c, c, c, 1) in LUMINANCE, (c, c, c, c) in INTENSITY and (0, 0, 0, c) in
/// ALPHA, which REPLACE with a white fragment shows as (c, c, c, 1), (c, c, c, c) and
/// (1, 1, 1, c). The design notes recorded that Mesa 22.3 llvmpipe returned (c, c, c, 1)
/// whatever the mode for fixed-function depth compares; measured here on Mesa 22.3.6 (EGL
/// and OSMesa), for DEPTH_COMPONENT16/24/32F, with and without a compare, and whether the
/// mode is set before or after the image, it follows the spec. Both paths are asserted
/// against the spec, so the deviation coming (back) would fail this test by name. Texels
/// 0.25 and 0.75, r = 0.5, LEQUAL; without compare c is the depth itself; tol 1/255.
#[test]
fn depth_texture_mode_is_honoured_by_both_paths() {
    let formats = [
        "GL_DEPTH_COMPONENT16",
        "GL_DEPTH_COMPONENT24",
        "GL_DEPTH_COMPONENT32F",
    ];
    let compares = ["GL_COMPARE_R_TO_TEXTURE", "GL_NONE"];
    let mut src = format!(
        "glClearColor(0, 0, 0, 1);\nglClear(GL_COLOR_BUFFER_BIT);\n{}",
        ortho(2, 18)
    );
    let mut expected = Vec::new();
    let mut row = 0;
    for format in formats {
        for compare in compares {
            for (m, mode) in MODES.iter().enumerate() {
                // Mode before the image on odd rows, after it on even rows.
                let mode_param =
                    format!("glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, {mode});\n");
                let (before, after) = if m % 2 == 1 {
                    (mode_param.as_str(), "")
                } else {
                    ("", mode_param.as_str())
                };
                src += &format!(
                    "glBindTexture(GL_TEXTURE_2D, {tex});
{before}glTexImage2D(GL_TEXTURE_2D, 0, {format}, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, (GLfloat[]){{0.25f, 0.75f}});
{after}glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, {compare});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
glEnable(GL_TEXTURE_2D);
glColor4f(1, 1, 1, 1);
glBegin(GL_QUADS);
glTexCoord3f(0, 0.5f, 0.5f); glVertex2f(0, {row});
glTexCoord3f(1, 0.5f, 0.5f); glVertex2f(2, {row});
glTexCoord3f(1, 0.5f, 0.5f); glVertex2f(2, {next});
glTexCoord3f(0, 0.5f, 0.5f); glVertex2f(0, {next});
glEnd();
",
                    tex = row + 1,
                    next = row + 1
                );
                for (x, d) in [0.25, 0.75].into_iter().enumerate() {
                    let c = match compare {
                        "GL_NONE" => fidelity::unorm8(d),
                        _ => fidelity::unorm8(if 0.5 <= d { 1.0 } else { 0.0 }),
                    };
                    let texel = match *mode {
                        "GL_LUMINANCE" => [c, c, c, 255],
                        "GL_INTENSITY" => [c; 4],
                        _ => [255, 255, 255, c],
                    };
                    expected.push((x as u32, row, format, compare, *mode, texel));
                }
                row += 1;
            }
        }
    }
    for p in compare(
        "depth-texture-mode",
        &src,
        Frame::new(2, 18),
        Tolerance::EXACT,
    ) {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            for &(x, row, format, cmp, mode, texel) in &expected {
                let got = out.image.get_pixel(x, 17 - row).0;
                let ok = got.iter().zip(texel).all(|(&g, e)| g.abs_diff(e) <= 1);
                assert!(
                    ok,
                    "{} {path} {format} {cmp} {mode} texel {x}: {got:?}, spec {texel:?} ± 1",
                    p.backend
                );
            }
        }
    }
}
