//! Texgen fidelity: piglit general/texgen (eye-plane transform timing, H9), gl-1.0/texgen
//! (object/eye-linear and sphere-map quadrants), projective texturing through a Q plane with
//! an identity texture matrix (H10, gl4es' bug) and q ≈ 0 / q < 0 at vertices. Every case
//! runs on the emulated and the native path on EGL and OSMesa.

mod fidelity;
mod support;

use fidelity::{compare, probe_rgb, script_file, Frame};
use image::RgbaImage;
use support::Tolerance;

/// The general/texgen texture: texel (x, y) = (0.25x, 0.25y, 0), stored as bytes.
const LEVEL: [u8; 4] = [0, 64, 128, 191];

/// general/texgen: each of the three quads covers [0, 0.75]² of a 16×16 window; cell (x, y)
/// (4×4 pixels) must show texel (x+1, y+1), wherever the plane was set relative to the
/// modelview. Tolerance: both paths sample the same texel (NEAREST), so exact (0) between
/// paths and 1 LSB against piglit's values.
#[test]
fn eye_planes_are_transformed_when_set_not_when_drawn() {
    for quad in 1..=3 {
        let name = format!("texgen_eye_plane_{quad}");
        let pairs = compare(
            &name,
            &script_file(&name),
            Frame::new(16, 16),
            Tolerance::EXACT,
        );
        for p in &pairs {
            for out in [&p.emulate, &p.native] {
                for cy in 0..3u32 {
                    for cx in 0..3u32 {
                        let e = [LEVEL[cx as usize + 1], LEVEL[cy as usize + 1], 0];
                        probe_rgb(&out.image, cx * 4 + 2, cy * 4 + 2, e, 1);
                    }
                }
                // Outside the quad: the clear colour.
                probe_rgb(&out.image, 14, 14, [0, 0, 0], 0);
            }
        }
    }
}

const GREEN: [u8; 3] = [0, 255, 0];
const BLUE: [u8; 3] = [0, 0, 255];

/// Six probe points inside the sphere's upper-left quadrant of the 50×50 window (bottom-left
/// origin), 5 to 8 units from the centre: away from the silhouette, the axes and the
/// sphere-map singularity at the pole facing the viewer, where coarse facets interpolate
/// across quadrants.
const UPPER_LEFT: [(u32, u32); 6] = [(10, 38), (14, 36), (12, 33), (16, 40), (8, 34), (18, 36)];

/// gl-1.0/texgen: the upper-left quadrant of the sphere reads green (OBJECT_LINEAR) or blue
/// (EYE_LINEAR, SPHERE_MAP), exactly. Image tolerance between paths: exact colours, with up
/// to 1% of pixels (25 of 2500) allowed to differ where NEAREST sampling sits on a checker
/// edge and the two paths interpolate the coordinate by a different last bit.
#[test]
fn object_eye_and_sphere_map_quadrants_match_glean() {
    for (name, colour) in [
        ("texgen_object_linear", GREEN),
        ("texgen_eye_linear", BLUE),
        ("texgen_sphere_map", BLUE),
    ] {
        let tol = Tolerance {
            per_channel: 0,
            max_bad_pixels: 25,
        };
        for p in compare(name, &script_file(name), Frame::new(50, 50), tol) {
            for out in [&p.emulate, &p.native] {
                for (x, y) in UPPER_LEFT {
                    probe_rgb(&out.image, x, y, colour, 0);
                }
            }
        }
    }
}

/// The 4×4 general/texgen texture, unit 0, NEAREST, CLAMP_TO_EDGE, REPLACE.
fn ramp_texture() -> String {
    let texels: Vec<String> = (0..16)
        .map(|i| format!("{},{},0", LEVEL[i % 4], LEVEL[i / 4]))
        .collect();
    format!(
        "glBindTexture(GL_TEXTURE_2D, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, (GLubyte[]){{{}}});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
glEnable(GL_TEXTURE_2D);
",
        texels.join(",")
    )
}

/// H10: s = x, t = y, q = 0.5x + 0.25y + 0.75 in eye space; the fragment samples (s/q, t/q).
/// `via_planes`: the rows are the EYE planes and the texture matrix is the identity (the case
/// gl4es gets wrong by leaving q = 1); otherwise the planes are the identity and the rows are
/// loaded as the texture matrix.
fn projective(via_planes: bool) -> String {
    let gen = "glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
glEnable(GL_TEXTURE_GEN_S);
glEnable(GL_TEXTURE_GEN_T);
glEnable(GL_TEXTURE_GEN_R);
glEnable(GL_TEXTURE_GEN_Q);
";
    let planes = if via_planes {
        "glTexGenfv(GL_S, GL_EYE_PLANE, (GLfloat[]){1, 0, 0, 0});
glTexGenfv(GL_T, GL_EYE_PLANE, (GLfloat[]){0, 1, 0, 0});
glTexGenfv(GL_R, GL_EYE_PLANE, (GLfloat[]){0, 0, 1, 0});
glTexGenfv(GL_Q, GL_EYE_PLANE, (GLfloat[]){0.5f, 0.25f, 0, 0.75f});
"
    } else {
        // Column-major: row 3 of the matrix is (0.5, 0.25, 0, 0.75).
        "glTexGenfv(GL_S, GL_EYE_PLANE, (GLfloat[]){1, 0, 0, 0});
glTexGenfv(GL_T, GL_EYE_PLANE, (GLfloat[]){0, 1, 0, 0});
glTexGenfv(GL_R, GL_EYE_PLANE, (GLfloat[]){0, 0, 1, 0});
glTexGenfv(GL_Q, GL_EYE_PLANE, (GLfloat[]){0, 0, 0, 1});
glMatrixMode(GL_TEXTURE);
glLoadMatrixf((GLfloat[]){1, 0, 0, 0.5f, 0, 1, 0, 0.25f, 0, 0, 1, 0, 0, 0, 0, 0.75f});
glMatrixMode(GL_MODELVIEW);
"
    };
    format!(
        "glClearColor(0, 0, 0, 1);
glClear(GL_COLOR_BUFFER_BIT);
{}{}{gen}{planes}glBegin(GL_QUADS);
glVertex2f(0, 0); glVertex2f(1, 0); glVertex2f(1, 1); glVertex2f(0, 1);
glEnd();
",
        fidelity::ortho(1, 1),
        ramp_texture()
    )
}

/// The image the GL formula gives for [`projective`] on a 16×16 window.
fn projective_expected() -> RgbaImage {
    RgbaImage::from_fn(16, 16, |px, row| {
        let x = (f64::from(px) + 0.5) / 16.0;
        let y = (f64::from(15 - row) + 0.5) / 16.0;
        let q = 0.5 * x + 0.25 * y + 0.75;
        let cell = |c: f64| ((4.0 * c / q).floor() as usize).min(3);
        image::Rgba([LEVEL[cell(x)], LEVEL[cell(y)], 0, 255])
    })
}

/// H10: the Q plane with an identity texture matrix divides exactly like the same rows in
/// the texture matrix. Tolerance: between the two formulations and between paths, exact
/// colours with at most 4 of 256 pixels off (a pixel whose s/q falls within float rounding
/// of a texel edge); against the formula the same.
#[test]
fn q_plane_with_identity_texture_matrix_projects_like_the_texture_matrix() {
    let tol = Tolerance {
        per_channel: 0,
        max_bad_pixels: 4,
    };
    let expected = projective_expected();
    let planes = compare("h10-planes", &projective(true), Frame::new(16, 16), tol);
    let matrix = compare("h10-matrix", &projective(false), Frame::new(16, 16), tol);
    for (a, b) in planes.iter().zip(&matrix) {
        let tag = a.backend;
        support::assert_images_match(
            &format!("h10-planes-vs-matrix-{tag}"),
            &a.emulate.image,
            &b.emulate.image,
            tol,
        );
        support::assert_images_match(
            &format!("h10-formula-{tag}"),
            &a.emulate.image,
            &expected,
            tol,
        );
        support::assert_images_match(
            &format!("h10-formula-native-{tag}"),
            &a.native.image,
            &expected,
            tol,
        );
    }
}

/// Named hard case: q = 0 at one vertex and q < 0 at another (texcoords given directly).
/// Rule: s/q is whatever the division gives, the sampler clamps (CLAMP_TO_EDGE), so every
/// covered pixel is one of the four texel colours of a 2×2 texture and no undefined value
/// (NaN turned into a random byte) reaches the framebuffer; depth stays finite. Asserted
/// on both paths; the paths are compared with a loose tolerance (10% of pixels may pick a
/// different texel near the q = 0 line, where the quotient is unbounded).
#[test]
fn q_zero_and_negative_at_vertices_give_only_texel_colours() {
    let src = format!(
        "glClearColor(0, 0, 0, 1);
glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
{}glBindTexture(GL_TEXTURE_2D, 1);
glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, (GLubyte[]){{255,0,0, 0,255,0, 0,0,255, 255,255,255}});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
glEnable(GL_TEXTURE_2D);
glBegin(GL_QUADS);
glTexCoord4f(0.2f, 0.2f, 0, 0); glVertex2f(0, 0);
glTexCoord4f(0.8f, 0.2f, 0, 1); glVertex2f(1, 0);
glTexCoord4f(0.8f, 0.8f, 0, -1); glVertex2f(1, 1);
glTexCoord4f(0.2f, 0.8f, 0, 0.000001f); glVertex2f(0, 1);
glEnd();
",
        fidelity::ortho(1, 1)
    );
    let tol = Tolerance {
        per_channel: 0,
        max_bad_pixels: 26,
    };
    let allowed = [
        [255, 0, 0, 255],
        [0, 255, 0, 255],
        [0, 0, 255, 255],
        [255, 255, 255, 255],
    ];
    for p in compare("q-zero-negative", &src, Frame::new(16, 16), tol) {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            for (x, y, px) in out.image.enumerate_pixels() {
                assert!(
                    allowed.contains(&px.0),
                    "{} {path}: pixel ({x},{y}) = {:?} is no texel colour",
                    p.backend,
                    px.0
                );
            }
            assert!(out.depth.iter().all(|z| z.is_finite()), "{path}: depth");
        }
    }
}
