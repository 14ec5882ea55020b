//! Non-finite values (±∞, NaN, and 1e39, which becomes +∞ as a GLfloat) at each entry point
//! that takes a float, on both paths: one named case per entry point, each drawing small
//! quads into an 8×2 frame, the paths compared exactly — colour buffer and depth buffer —
//! on both headless backends. The reference is Mesa's native fixed-function path (Mesa
//! 22.3.6 llvmpipe); each case states what it measured, and the emulated path follows the
//! rule written next to its code.
//!
//! Every case matches: where the spec leaves the result undefined (NaN through a clamp, a
//! NaN texture coordinate, a NaN depth) the emulated path follows what Mesa was measured to
//! do, by a rule written next to its code. A case that could not match would be written as
//! a pinned deviation (an assertion that the paths still differ, so a change is noticed);
//! none was needed.

mod fidelity;
mod support;

use fidelity::{ortho, run_both, Frame, Pair};

const W: u32 = 8;
const H: u32 = 2;

struct Case {
    name: &'static str,
    /// The GL calls after the common start (clear to opaque black, depth 1; ortho 8×2).
    script: fn() -> String,
    /// What Mesa's native path was measured to draw at pixel (0, 0) (bottom left), when
    /// the case pins it; the paths are compared with each other in any case.
    pixel: Option<[u8; 4]>,
}

/// A quad over the whole frame at object z = `z`, texture coordinates 0..1.
fn quad(z: f32) -> String {
    format!(
        "glBegin(GL_QUADS);
glTexCoord2f(0, 0); glVertex3f(0, 0, {z});
glTexCoord2f(1, 0); glVertex3f({W}, 0, {z});
glTexCoord2f(1, 1); glVertex3f({W}, {H}, {z});
glTexCoord2f(0, 1); glVertex3f(0, {H}, {z});
glEnd();
"
    )
}

/// A unit quad at pixel column x, row y.
fn pixel_quad(x: u32, y: u32) -> String {
    format!(
        "glBegin(GL_QUADS);\nglVertex2f({x}, {y}); glVertex2f({}, {y}); glVertex2f({}, {}); glVertex2f({x}, {});\nglEnd();\n",
        x + 1,
        x + 1,
        y + 1,
        y + 1
    )
}

const LIT: &str = "glEnable(GL_LIGHTING);
glEnable(GL_LIGHT0);
glNormal3f(0, 0, 1);
";

/// A 2×1 RGBA texture, red then green, NEAREST, REPEAT, REPLACE, enabled.
const TEXTURE: &str = "glBindTexture(GL_TEXTURE_2D, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){255, 0, 0, 255, 0, 255, 0, 255});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
glEnable(GL_TEXTURE_2D);
";

const FUNCS: [&str; 8] = [
    "GL_NEVER",
    "GL_LESS",
    "GL_EQUAL",
    "GL_LEQUAL",
    "GL_GREATER",
    "GL_NOTEQUAL",
    "GL_GEQUAL",
    "GL_ALWAYS",
];

/// The alpha test with reference `reference`: column i uses FUNCS[i]; row 0 draws white
/// with alpha 0.25, row 1 with alpha 1. A passing fragment is white, a failing one leaves
/// the black clear.
fn alpha_test(reference: &str) -> String {
    let mut s = String::from("glEnable(GL_ALPHA_TEST);\n");
    for (i, f) in FUNCS.iter().enumerate() {
        s += &format!("glAlphaFunc({f}, {reference});\n");
        for (y, a) in [(0, "0.25"), (1, "1")] {
            s += &format!("glColor4f(1, 1, 1, {a});\n");
            s += &pixel_quad(i as u32, y);
        }
    }
    s
}

const CASES: &[Case] = &[
    // glColor: GL 1.x clamps the vertex colour to [0, 1] before rasterisation (§2.13.6
    // "Colors and Coloring"). Measured native, the current colour: +∞ → 1, −∞ → 0, NaN → 0,
    // 1e39 → 1.
    Case {
        name: "color_positive_infinity",
        script: || format!("glColor4f(INFINITY, 0, 0, 1);\n{}", quad(0.0)),
        pixel: Some([255, 0, 0, 255]),
    },
    Case {
        name: "color_negative_infinity",
        script: || format!("glColor4f(-INFINITY, 1, 0, 1);\n{}", quad(0.0)),
        pixel: Some([0, 255, 0, 255]),
    },
    Case {
        name: "color_nan",
        script: || format!("glColor4f(NAN, 0, 1, 1);\n{}", quad(0.0)),
        pixel: Some([0, 0, 255, 255]),
    },
    Case {
        name: "color_1e39",
        script: || format!("glColor4f(1e39, 0, 0, 1);\n{}", quad(0.0)),
        pixel: Some([255, 0, 0, 255]),
    },
    Case {
        name: "color_alpha_nan",
        script: || format!("glColor4f(1, 1, 1, NAN);\n{}", quad(0.0)),
        pixel: Some([255, 255, 255, 0]),
    },
    // One vertex +∞, the others finite: clamped at the vertex, then interpolated.
    Case {
        name: "color_per_vertex_infinity",
        script: || {
            format!(
                "glBegin(GL_QUADS);
glColor4f(INFINITY, 0, 0, 1); glVertex2f(0, 0);
glColor4f(0, 0, 0, 1); glVertex2f({W}, 0);
glColor4f(0, 0, 0, 1); glVertex2f({W}, {H});
glColor4f(0, 0, 0, 1); glVertex2f(0, {H});
glEnd();
"
            )
        },
        pixel: None,
    },
    // A NaN given per vertex (glColor inside glBegin/glEnd) is a vertex attribute, and the
    // vertex clamp sends it to 1, alpha too; the current colour's NaN (`color_nan`) to 0.
    // Measured native: magenta, opaque; the emulated path drew opaque-less blue.
    Case {
        name: "color_per_vertex_nan",
        script: || {
            format!(
                "glBegin(GL_QUADS);
glColor4f(NAN, 0, 1, NAN); glVertex2f(0, 0);
glColor4f(NAN, 0, 1, NAN); glVertex2f({W}, 0);
glColor4f(NAN, 0, 1, NAN); glVertex2f({W}, {H});
glColor4f(NAN, 0, 1, NAN); glVertex2f(0, {H});
glEnd();
"
            )
        },
        pixel: Some([255, 0, 255, 255]),
    },
    // The secondary colour follows the same rule: per vertex NaN → 1, current NaN → 0.
    Case {
        name: "secondary_color_per_vertex_nan",
        script: || {
            format!(
                "glEnable(GL_COLOR_SUM);
glColor4f(0, 0, 0, 1);
glBegin(GL_QUADS);
glSecondaryColor3f(NAN, 0, 0.5); glVertex2f(0, 0);
glSecondaryColor3f(NAN, 0, 0.5); glVertex2f({W}, 0);
glSecondaryColor3f(NAN, 0, 0.5); glVertex2f({W}, {H});
glSecondaryColor3f(NAN, 0, 0.5); glVertex2f(0, {H});
glEnd();
"
            )
        },
        pixel: Some([255, 0, 128, 255]),
    },
    Case {
        name: "secondary_color_nan",
        script: || {
            format!(
                "glEnable(GL_COLOR_SUM);\nglColor4f(0, 0, 0, 1);\nglSecondaryColor3f(NAN, 0, 0.5);\n{}",
                quad(0.0)
            )
        },
        pixel: Some([0, 0, 128, 255]),
    },
    // COLOR_MATERIAL tracks the unclamped current colour; lighting then clamps its sum. The
    // red sum is ∞ + ∞·0 (the light's ambient is 0) = NaN, and a lit NaN clamps to 1.
    // Measured native: red; the starting emulated path drew black.
    Case {
        name: "color_material_infinity",
        script: || {
            format!(
                "{LIT}glEnable(GL_COLOR_MATERIAL);\nglColor4f(INFINITY, 0, 0, 1);\n{}",
                quad(0.0)
            )
        },
        pixel: Some([255, 0, 0, 255]),
    },
    // glAlphaFunc: GL clamps ref to [0, 1]: +∞ is 1, −∞ is 0. Measured native: a NaN
    // reference compares as 1 in all eight functions (GREATER passes nothing, LESS and
    // NOTEQUAL pass alpha 0.25, EQUAL passes alpha 1); the starting emulated path compared
    // it as 0 (GREATER passed everything). Pixel (0, 0) is NEVER's: black.
    Case {
        name: "alpha_func_ref_nan",
        script: || alpha_test("NAN"),
        pixel: None,
    },
    Case {
        name: "alpha_func_ref_positive_infinity",
        script: || alpha_test("INFINITY"),
        pixel: None,
    },
    Case {
        name: "alpha_func_ref_negative_infinity",
        script: || alpha_test("-INFINITY"),
        pixel: None,
    },
    // glLight. A NaN position (directional, or w NaN) makes n·L NaN: measured native, the
    // light adds only its ambient term (0 by default), so the quad shows the scene ambient
    // 0.2 × material ambient 0.2 = 0.04 (10/255); the starting emulated path drew black.
    Case {
        name: "light_position_nan",
        script: || {
            format!(
                "{LIT}glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){{NAN, 0, 1, 0}});\n{}",
                quad(0.0)
            )
        },
        pixel: Some([10, 10, 10, 255]),
    },
    Case {
        name: "light_position_w_nan",
        script: || {
            format!(
                "{LIT}glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){{0, 0, 1, NAN}});\n{}",
                quad(0.0)
            )
        },
        pixel: Some([10, 10, 10, 255]),
    },
    // An infinite diffuse light: the red sum is +∞, clamped to 1.
    Case {
        name: "light_diffuse_infinity",
        script: || {
            format!(
                "{LIT}glLightfv(GL_LIGHT0, GL_DIFFUSE, (GLfloat[]){{INFINITY, 0, 0, 1}});\n{}",
                quad(0.0)
            )
        },
        pixel: Some([255, 10, 10, 255]),
    },
    // glMaterial. A NaN diffuse red makes the lit red sum NaN: measured native, 1 (full red);
    // the starting emulated path drew 0.
    Case {
        name: "material_diffuse_nan",
        script: || {
            format!(
                "{LIT}glMaterialfv(GL_FRONT, GL_DIFFUSE, (GLfloat[]){{NAN, 1, 0, 1}});\n{}",
                quad(0.0)
            )
        },
        pixel: Some([255, 255, 10, 255]),
    },
    // −∞ emission red: the red sum is −∞, clamped to 0; green and blue lit as usual.
    Case {
        name: "material_emission_negative_infinity",
        script: || {
            format!(
                "{LIT}glMaterialfv(GL_FRONT, GL_EMISSION, (GLfloat[]){{-INFINITY, 0, 0, 1}});\n{}",
                quad(0.0)
            )
        },
        pixel: Some([0, 214, 214, 255]),
    },
    // glTexGen. A NaN or infinite plane makes s NaN (∞·0 in the dot product, or the eye
    // plane's ∞ times the inverse modelview's zeros): measured native, the REPEAT lookup
    // reads texel 0 (red). The emulated path makes a NaN coordinate 0
    // (`shadergen::fragment::projected`) and agrees.
    Case {
        name: "texgen_object_plane_nan",
        script: || {
            format!(
                "{TEXTURE}glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);\nglTexGenfv(GL_S, GL_OBJECT_PLANE, (GLfloat[]){{NAN, 0, 0, 0}});\nglEnable(GL_TEXTURE_GEN_S);\n{}",
                quad(0.0)
            )
        },
        pixel: Some([255, 0, 0, 255]),
    },
    Case {
        name: "texgen_eye_plane_infinity",
        script: || {
            format!(
                "{TEXTURE}glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);\nglTexGenfv(GL_S, GL_EYE_PLANE, (GLfloat[]){{INFINITY, 0, 0, 0}});\nglEnable(GL_TEXTURE_GEN_S);\n{}",
                quad(0.0)
            )
        },
        pixel: Some([255, 0, 0, 255]),
    },
    // The same NaN coordinate under CLAMP_TO_EDGE, and a NaN given by glTexCoord itself:
    // measured native, texel 0 (red) in both.
    Case {
        name: "texgen_object_plane_nan_clamp_to_edge",
        script: || {
            format!(
                "{TEXTURE}glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);\nglTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);\nglTexGenfv(GL_S, GL_OBJECT_PLANE, (GLfloat[]){{NAN, 0, 0, 0}});\nglEnable(GL_TEXTURE_GEN_S);\n{}",
                quad(0.0)
            )
        },
        pixel: Some([255, 0, 0, 255]),
    },
    Case {
        name: "tex_coord_nan",
        script: || {
            format!(
                "{TEXTURE}glBegin(GL_QUADS);\nglTexCoord2f(NAN, 0); glVertex2f(0, 0);\nglTexCoord2f(NAN, 0); glVertex2f({W}, 0);\nglTexCoord2f(NAN, 1); glVertex2f({W}, {H});\nglTexCoord2f(NAN, 1); glVertex2f(0, {H});\nglEnd();\n"
            )
        },
        pixel: Some([255, 0, 0, 255]),
    },
    // Matrices: a NaN or infinite modelview makes every clip position NaN or ∞; measured
    // native, nothing is drawn (both paths rasterise with the same Mesa, so they agree).
    Case {
        name: "translate_nan",
        script: || {
            format!(
                "glColor4f(1, 1, 1, 1);\nglTranslatef(NAN, 0, 0);\n{}",
                quad(0.0)
            )
        },
        pixel: Some([0, 0, 0, 255]),
    },
    Case {
        name: "scale_infinity",
        script: || {
            format!(
                "glColor4f(1, 1, 1, 1);\nglScalef(INFINITY, 1, 1);\n{}",
                quad(0.0)
            )
        },
        pixel: Some([0, 0, 0, 255]),
    },
    // glClearColor: clamped to [0, 1] (GL 1.5 §4.2.3); NaN → 0 (the model's clamp, and Mesa
    // measured alike): (1, 0, 0, 1).
    Case {
        name: "clear_color_nonfinite",
        script: || {
            "glClearColor(INFINITY, -INFINITY, NAN, 1e39);\nglClear(GL_COLOR_BUFFER_BIT);\n".into()
        },
        pixel: Some([255, 0, 0, 255]),
    },
    // glClearDepth: clamped to [0, 1]; NaN → 0 in the model. A quad at window z 0.5 with
    // LESS then fails against a depth cleared to 0.
    Case {
        name: "clear_depth_nan",
        script: || {
            format!(
                "glClearDepth(NAN);\nglClear(GL_DEPTH_BUFFER_BIT);\nglEnable(GL_DEPTH_TEST);\nglColor4f(1, 1, 1, 1);\n{}",
                quad(0.0)
            )
        },
        pixel: None,
    },
    // glPolygonOffset: a quad at window z 0.5 drawn with LESS against the cleared 1. The
    // offset is the rasteriser's (the same Mesa code on both paths). Measured: units NaN and
    // factor +∞ (∞ × the zero slope of a flat quad = NaN) give a NaN depth that fails LESS:
    // nothing drawn; units −∞ gives depth 0: drawn.
    Case {
        name: "polygon_offset_units_nan",
        script: || {
            format!(
                "glEnable(GL_DEPTH_TEST);\nglEnable(GL_POLYGON_OFFSET_FILL);\nglPolygonOffset(0, NAN);\nglColor4f(1, 1, 1, 1);\n{}",
                quad(0.0)
            )
        },
        pixel: Some([0, 0, 0, 255]),
    },
    Case {
        name: "polygon_offset_factor_infinity",
        script: || {
            format!(
                "glEnable(GL_DEPTH_TEST);\nglEnable(GL_POLYGON_OFFSET_FILL);\nglPolygonOffset(INFINITY, 0);\nglColor4f(1, 1, 1, 1);\n{}",
                quad(0.0)
            )
        },
        pixel: Some([0, 0, 0, 255]),
    },
    Case {
        name: "polygon_offset_units_negative_infinity",
        script: || {
            format!(
                "glEnable(GL_DEPTH_TEST);\nglEnable(GL_POLYGON_OFFSET_FILL);\nglPolygonOffset(0, -INFINITY);\nglColor4f(1, 1, 1, 1);\n{}",
                quad(0.0)
            )
        },
        pixel: Some([255, 255, 255, 255]),
    },
    // glDepthRange: clamped to [0, 1]; NaN → 0 (`ff::apply::unit_clamp`). Measured native:
    // (NaN, 1) puts z = 0 at 0.5, as (0, 1) does; (−∞, +∞) is (0, 1).
    Case {
        name: "depth_range_nan",
        script: || {
            format!(
                "glEnable(GL_DEPTH_TEST);\nglDepthFunc(GL_ALWAYS);\nglDepthRange(NAN, 1);\nglColor4f(1, 1, 1, 1);\n{}",
                quad(0.0)
            )
        },
        pixel: Some([255, 255, 255, 255]),
    },
    Case {
        name: "depth_range_infinities",
        script: || {
            format!(
                "glEnable(GL_DEPTH_TEST);\nglDepthFunc(GL_ALWAYS);\nglDepthRange(-INFINITY, INFINITY);\nglColor4f(1, 1, 1, 1);\n{}",
                quad(0.5)
            )
        },
        pixel: Some([255, 255, 255, 255]),
    },
    // glTexEnv TEXTURE_ENV_COLOR: clamped to [0, 1], NaN → 0 (the model's clamp; measured
    // native alike). BLEND of a LUMINANCE 128/255 texture over 0.25 grey: RGB =
    // mix(0.25, (0, 1, 0), 0.5) = (32, 160, 32); LUMINANCE leaves alpha 1.
    Case {
        name: "tex_env_color_nonfinite",
        script: || {
            format!(
                "glBindTexture(GL_TEXTURE_2D, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8, 1, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, (GLubyte[]){{128}});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, (GLfloat[]){{NAN, INFINITY, -INFINITY, 1e39}});
glEnable(GL_TEXTURE_2D);
glColor4f(0.25, 0.25, 0.25, 1);
{}",
                quad(0.0)
            )
        },
        pixel: Some([32, 160, 32, 255]),
    },
];

fn case(name: &str) -> &'static Case {
    CASES
        .iter()
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("no case {name}"))
}

fn source(c: &Case) -> String {
    format!(
        "glClearColor(0, 0, 0, 1);\nglClearDepth(1);\nglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);\n{}{}",
        ortho(W, H),
        (c.script)()
    )
}

fn run_case(name: &str) {
    let c = case(name);
    for p in run_both(&source(c), Frame::new(W, H)) {
        check(c, &p);
    }
}

/// The colour and depth buffers of the paths equal, bit for bit; the native pixel (0, 0)
/// as measured, when the case pins it.
fn check(c: &Case, p: &Pair) {
    let (e, n) = (&p.emulate, &p.native);
    support::assert_images_match(
        &format!("nonfinite-{}-{}", c.name, p.backend),
        &e.image,
        &n.image,
        support::Tolerance::EXACT,
    );
    let bits = |d: &[f32]| d.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    assert_eq!(
        bits(&e.depth),
        bits(&n.depth),
        "{} {}: depth buffers differ: emulate {:?}, native {:?}",
        c.name,
        p.backend,
        e.depth,
        n.depth
    );
    if let Some(rgba) = c.pixel {
        fidelity::probe_gl(&n.image, 0, 0, rgba, 0);
    }
}

/// Prints what each path draws for every case (pixels bottom row first, depth at (0, 0)):
/// the measurement behind the cases' comments.
/// `cargo test --test fidelity_nonfinite -- --ignored --nocapture measure`
#[test]
#[ignore]
fn measure() {
    for c in CASES {
        for p in run_both(&source(c), Frame::new(W, H)) {
            for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
                let rows: Vec<Vec<[u8; 4]>> = (0..H)
                    .rev()
                    .map(|y| (0..W).map(|x| out.image.get_pixel(x, y).0).collect())
                    .collect();
                println!(
                    "{} {} {path}: {:?} depth {:?}",
                    c.name, p.backend, rows, out.depth[0]
                );
            }
        }
    }
}

macro_rules! named_cases {
    ($($name:ident),* $(,)?) => {
        $(
            #[test]
            fn $name() {
                run_case(stringify!($name));
            }
        )*

        /// Every case of the table has its named test.
        #[test]
        fn every_case_is_named() {
            let named = [$(stringify!($name)),*];
            for c in CASES {
                assert!(named.contains(&c.name), "case {} has no named test", c.name);
            }
        }
    };
}

named_cases!(
    color_positive_infinity,
    color_negative_infinity,
    color_nan,
    color_1e39,
    color_alpha_nan,
    color_per_vertex_infinity,
    color_per_vertex_nan,
    secondary_color_per_vertex_nan,
    secondary_color_nan,
    color_material_infinity,
    alpha_func_ref_nan,
    alpha_func_ref_positive_infinity,
    alpha_func_ref_negative_infinity,
    light_position_nan,
    light_position_w_nan,
    light_diffuse_infinity,
    material_diffuse_nan,
    material_emission_negative_infinity,
    texgen_object_plane_nan,
    texgen_eye_plane_infinity,
    texgen_object_plane_nan_clamp_to_edge,
    tex_coord_nan,
    translate_nan,
    scale_infinity,
    clear_color_nonfinite,
    clear_depth_nan,
    polygon_offset_units_nan,
    polygon_offset_factor_infinity,
    polygon_offset_units_negative_infinity,
    depth_range_nan,
    depth_range_infinities,
    tex_env_color_nonfinite,
);

/// glAlphaFunc(func, NaN) compares as the reference 1 on both paths, in all eight functions
/// (the `alpha_func_ref_nan` case draws column i with FUNCS[i], alpha 0.25 in row 0 and 1
/// in row 1): pass ⇔ func(alpha, 1), white; fail, black. Exact.
#[test]
fn alpha_func_nan_reference_compares_as_one() {
    let c = case("alpha_func_ref_nan");
    let passes = |func: &str, a: f32| match func {
        "GL_NEVER" => false,
        "GL_LESS" => a < 1.0,
        "GL_EQUAL" => a == 1.0,
        "GL_LEQUAL" => a <= 1.0,
        "GL_GREATER" => a > 1.0,
        "GL_NOTEQUAL" => a != 1.0,
        "GL_GEQUAL" => a >= 1.0,
        _ => true,
    };
    for p in run_both(&source(c), Frame::new(W, H)) {
        check(c, &p);
        for out in [&p.emulate, &p.native] {
            for (i, func) in FUNCS.iter().enumerate() {
                for (y, a, a8) in [(0, 0.25, 64), (1, 1.0, 255)] {
                    let e = if passes(func, a) {
                        [255, 255, 255, a8]
                    } else {
                        [0, 0, 0, 255]
                    };
                    fidelity::probe_gl(&out.image, i as u32, y, e, 0);
                }
            }
        }
    }
}
