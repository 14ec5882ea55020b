//! GL 1.3's cube maps (ARB_texture_cube_map) on both paths: six faces of one colour each
//! sampled by explicit (s, t, r) around each axis (the face a direction selects, GL 1.5
//! Table 3.21), faces of 4×4 ramps under LINEAR with CLAMP_TO_EDGE and CLAMP, texgen
//! REFLECTION_MAP on a tilted quad and on a lit sphere, NORMAL_MAP on a lit sphere, a
//! negative q (which turns the direction round: Mesa divides (s, t, r) by q), cube
//! completeness (a missing face, faces of different sizes, a mipmap filter without the
//! levels: the untextured colour), generated mipmaps minified, and a face read back by
//! glGetTexImage. The emulated path (a samplerCube at (s, t, r)/q, texgen in the vertex
//! program) must draw the native path's image (Mesa's own cube mapping) exactly and read
//! back the same bytes.

mod fidelity;
mod support;

use fidelity::{probe_gl, run_both, Frame};

const PANEL: u32 = 24;
const COLUMNS: u32 = 7;
const ROWS: u32 = 2;

/// The faces' colours, +X, −X, +Y, −Y, +Z, −Z.
const COLOURS: [[u8; 3]; 6] = [
    [255, 0, 0],
    [0, 255, 0],
    [0, 0, 255],
    [255, 255, 0],
    [0, 255, 255],
    [255, 0, 255],
];

/// The face targets, in the order of `COLOURS`.
const FACES: [&str; 6] = [
    "GL_TEXTURE_CUBE_MAP_POSITIVE_X",
    "GL_TEXTURE_CUBE_MAP_NEGATIVE_X",
    "GL_TEXTURE_CUBE_MAP_POSITIVE_Y",
    "GL_TEXTURE_CUBE_MAP_NEGATIVE_Y",
    "GL_TEXTURE_CUBE_MAP_POSITIVE_Z",
    "GL_TEXTURE_CUBE_MAP_NEGATIVE_Z",
];

/// The untextured colour of the incomplete panels.
const PLAIN: [u8; 4] = [204, 153, 51, 255];

fn bytes(texels: impl Iterator<Item = [u8; 4]>) -> String {
    let b: Vec<String> = texels.flat_map(|t| t.map(|v| v.to_string())).collect();
    format!("(GLubyte[]){{{}}}", b.join(", "))
}

/// A face of `size`² texels: its colour halved plus a ramp in x and y.
fn ramp(face: usize, size: u32) -> String {
    bytes((0..size * size).map(|i| {
        let (x, y) = (i % size, i / size);
        let c = COLOURS[face].map(|v| (u32::from(v) / 2 + (x * 80 + y * 40) / size).min(255) as u8);
        [c[0], c[1], c[2], 255]
    }))
}

fn solid(face: usize, size: u32) -> String {
    let [r, g, b] = COLOURS[face];
    bytes((0..size * size).map(|_| [r, g, b, 255]))
}

/// Faces 0..faces of cube `name`, each given by `texels(face)` at `size`², NEAREST.
fn cube(name: u32, size: u32, faces: usize, texels: impl Fn(usize, u32) -> String) -> String {
    let mut s = format!("glBindTexture(GL_TEXTURE_CUBE_MAP, {name});\n");
    for (f, target) in FACES.iter().enumerate().take(faces) {
        s.push_str(&format!(
            "glTexImage2D({target}, 0, GL_RGBA8, {size}, {size}, 0, GL_RGBA, GL_UNSIGNED_BYTE, {});\n",
            texels(f, size)
        ));
    }
    s.push_str(&filters("GL_NEAREST", "GL_NEAREST"));
    s
}

fn filters(min: &str, mag: &str) -> String {
    format!(
        "glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, {min});\n\
         glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, {mag});\n"
    )
}

/// Panel (col, row) as the viewport, with projection `projection` and identity modelview.
fn panel(col: u32, row: u32, projection: &str) -> String {
    format!(
        "glViewport({}, {}, {PANEL}, {PANEL});\n\
         glMatrixMode(GL_PROJECTION);\nglLoadIdentity();\n{projection}\
         glMatrixMode(GL_MODELVIEW);\nglLoadIdentity();\n",
        col * PANEL,
        row * PANEL
    )
}

/// A quad over the viewport sampled at the directions `axis` ± `spread`·u ± `spread`·v,
/// (u, v) the two other axes, with q as given.
fn directions(axis: [f32; 3], spread: f32, q: f32) -> String {
    let k = axis.iter().position(|v| *v != 0.0).unwrap_or(0);
    let (u, v) = ((k + 1) % 3, (k + 2) % 3);
    let mut s = "glBegin(GL_QUADS);\n".to_string();
    for (x, y) in [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        let mut d = axis;
        d[u] += x * spread;
        d[v] += y * spread;
        s.push_str(&format!(
            "glTexCoord4f({}, {}, {}, {q}); glVertex2f({x}, {y});\n",
            d[0], d[1], d[2]
        ));
    }
    s.push_str("glEnd();\n");
    s
}

fn texgen(mode: &str) -> String {
    let mut s = String::new();
    for c in ["S", "T", "R"] {
        s.push_str(&format!(
            "glTexGeni(GL_{c}, GL_TEXTURE_GEN_MODE, {mode});\nglEnable(GL_TEXTURE_GEN_{c});\n"
        ));
    }
    s
}

const NO_TEXGEN: &str =
    "glDisable(GL_TEXTURE_GEN_S);\nglDisable(GL_TEXTURE_GEN_T);\nglDisable(GL_TEXTURE_GEN_R);\n";

/// A sphere of radius 1 of 12 × 8 quad strips, each vertex's normal its position.
fn sphere() -> String {
    let mut s = String::new();
    let pi = std::f32::consts::PI;
    for j in 0..8 {
        s.push_str("glBegin(GL_QUAD_STRIP);\n");
        for i in 0..=12 {
            let b = 2.0 * pi * i as f32 / 12.0;
            for jj in [j + 1, j] {
                let a = pi * jj as f32 / 8.0 - pi / 2.0;
                let n = [a.cos() * b.cos(), a.sin(), a.cos() * b.sin()];
                s.push_str(&format!(
                    "glNormal3f({:.6}f, {:.6}f, {:.6}f); glVertex3f({:.6}f, {:.6}f, {:.6}f);\n",
                    n[0], n[1], n[2], n[0], n[1], n[2]
                ));
            }
        }
        s.push_str("glEnd();\n");
    }
    s
}

/// A lit sphere in perspective, turned so that several faces show.
fn lit_sphere() -> String {
    format!(
        "glEnable(GL_LIGHTING);\nglEnable(GL_LIGHT0);\n\
         glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){{0.3f, 0.5f, 1, 0}});\n\
         glEnable(GL_DEPTH_TEST);\n\
         glTranslatef(0, 0, -3);\nglRotatef(30, 1, 1, 0);\n{}\
         glDisable(GL_DEPTH_TEST);\nglDisable(GL_LIGHTING);\n",
        sphere()
    )
}

const FRUSTUM: &str = "glFrustum(-0.6, 0.6, -0.6, 0.6, 1, 10);\n";
const ORTHO: &str = "glOrtho(-1, 1, -1, 1, -1, 1);\n";

const AXES: [[f32; 3]; 6] = [
    [1.0, 0.0, 0.0],
    [-1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, -1.0, 0.0],
    [0.0, 0.0, 1.0],
    [0.0, 0.0, -1.0],
];

fn script() -> String {
    let mut s = String::from("glPixelStorei(GL_UNPACK_ALIGNMENT, 1);\n");
    s.push_str(
        "glClearColor(0.1f, 0.2f, 0.3f, 1);\nglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);\n",
    );
    s.push_str("glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);\n");
    // Cube 1: one colour a face. Row 0, panels 0–5: each face by directions around its axis.
    s.push_str(&cube(1, 1, 6, solid));
    s.push_str("glEnable(GL_TEXTURE_CUBE_MAP);\n");
    for (f, axis) in AXES.iter().enumerate() {
        s.push_str(&panel(f as u32, 0, ORTHO));
        s.push_str(&directions(*axis, 0.8, 1.0));
    }
    // Panel 6: q = −1 turns +X's directions to −X's.
    s.push_str(&panel(6, 0, ORTHO));
    s.push_str(&directions(AXES[0], 0.8, -1.0));
    // Cube 2: ramps, LINEAR, CLAMP_TO_EDGE. Row 1, panel 0: the +Z face across its edges
    // (directions beyond 45° reach the neighbouring faces).
    s.push_str(&cube(2, 4, 6, ramp));
    s.push_str(&filters("GL_LINEAR", "GL_LINEAR"));
    s.push_str(
        "glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);\n\
         glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);\n",
    );
    s.push_str(&panel(0, 1, ORTHO));
    s.push_str(&directions(AXES[4], 1.3, 1.0));
    // Panel 1: REFLECTION_MAP on a quad tilted in perspective, lit, MODULATE.
    s.push_str("glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);\n");
    s.push_str(&panel(1, 1, FRUSTUM));
    s.push_str(&texgen("GL_REFLECTION_MAP"));
    s.push_str(
        "glTranslatef(0, 0, -2);\nglRotatef(50, 1, 0.3f, 0);\nglNormal3f(0, 0, 1);\n\
         glBegin(GL_QUADS);\nglVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(1, 1); glVertex2f(-1, 1);\nglEnd();\n",
    );
    // Panels 2 and 3: REFLECTION_MAP and NORMAL_MAP on a lit sphere.
    s.push_str(&panel(2, 1, FRUSTUM));
    s.push_str(&lit_sphere());
    s.push_str(&panel(3, 1, FRUSTUM));
    s.push_str(&texgen("GL_NORMAL_MAP"));
    s.push_str(&lit_sphere());
    s.push_str(NO_TEXGEN);
    s.push_str("glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);\n");
    // Panel 4: the ramps under CLAMP (GL 1.x's clamp to [0, 1] of the face coordinates).
    s.push_str(
        "glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP);\n\
         glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP);\n",
    );
    s.push_str(&panel(4, 1, ORTHO));
    s.push_str(&directions(AXES[2], 1.0, 1.0));
    // Panel 5: incomplete cubes draw the untextured colour: cube 3 lacks −Z, cube 4's +X
    // is 2×2 beside 1×1 faces, cube 5 has one level under a mipmap filter. Each covers a
    // third of the panel.
    s.push_str("glColor4ub(204, 153, 51, 255);\n");
    s.push_str(&cube(3, 1, 5, solid));
    s.push_str(&panel(5, 1, ORTHO));
    s.push_str(&strip(-1.0, AXES[0]));
    s.push_str(&cube(4, 1, 6, solid));
    s.push_str("glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);\n");
    s.push_str(&strip(-1.0 / 3.0, AXES[0]));
    s.push_str(&cube(5, 2, 6, solid));
    s.push_str(&filters("GL_NEAREST_MIPMAP_NEAREST", "GL_NEAREST"));
    s.push_str(&strip(1.0 / 3.0, AXES[0]));
    s.push_str("glColor4ub(255, 255, 255, 255);\n");
    // Panel 6: cube 6's 8×8 ramps with GENERATE_MIPMAP, minified 4× under
    // NEAREST_MIPMAP_NEAREST.
    s.push_str("glBindTexture(GL_TEXTURE_CUBE_MAP, 6);\nglTexParameteri(GL_TEXTURE_CUBE_MAP, GL_GENERATE_MIPMAP, GL_TRUE);\n");
    for (f, target) in FACES.iter().enumerate() {
        s.push_str(&format!(
            "glTexImage2D({target}, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, {});\n",
            ramp(f, 8)
        ));
    }
    s.push_str(&filters("GL_NEAREST_MIPMAP_NEAREST", "GL_NEAREST"));
    s.push_str(&panel(6, 1, ORTHO));
    s.push_str("glScalef(0.25f, 0.25f, 1);\n");
    s.push_str(&directions(AXES[5], 0.9, 1.0));
    // Read back: cube 2's −Y face and cube 6's generated level 1 of +Y.
    s.push_str("glBindTexture(GL_TEXTURE_CUBE_MAP, 2);\n");
    s.push_str("glGetTexImage(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback_0);\n");
    s.push_str("glBindTexture(GL_TEXTURE_CUBE_MAP, 6);\n");
    s.push_str("glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 1, GL_RGBA, GL_UNSIGNED_BYTE, readback_1);\n");
    s
}

/// A third of the viewport from x = `x0`, sampled around `axis`.
fn strip(x0: f32, axis: [f32; 3]) -> String {
    let x1 = x0 + 2.0 / 3.0;
    format!(
        "glBegin(GL_QUADS);\n\
         glTexCoord3f({a}, {b}, {c}); glVertex2f({x0}, -1);\n\
         glTexCoord3f({a}, {b}, {c}); glVertex2f({x1}, -1);\n\
         glTexCoord3f({a}, {b}, {c}); glVertex2f({x1}, 1);\n\
         glTexCoord3f({a}, {b}, {c}); glVertex2f({x0}, 1);\n\
         glEnd();\n",
        a = axis[0],
        b = axis[1],
        c = axis[2]
    )
}

#[test]
fn cube_maps_sample_generate_and_complete_as_on_the_native_path() {
    let src = script();
    for p in run_both(&src, Frame::new(COLUMNS * PANEL, ROWS * PANEL)) {
        support::assert_images_match(
            &format!("cube-map-{}", p.backend),
            &p.emulate.image,
            &p.native.image,
            support::Tolerance::EXACT,
        );
        let centre = PANEL / 2;
        // Each face by its axis, and q = −1 giving −X.
        for (f, [r, g, b]) in COLOURS.iter().enumerate() {
            probe_gl(
                &p.native.image,
                f as u32 * PANEL + centre,
                centre,
                [*r, *g, *b, 255],
                0,
            );
        }
        let [r, g, b] = COLOURS[1];
        probe_gl(
            &p.native.image,
            6 * PANEL + centre,
            centre,
            [r, g, b, 255],
            0,
        );
        // The three incomplete cubes draw the colour.
        for x in [4, 12, 20] {
            probe_gl(&p.native.image, 5 * PANEL + x, PANEL + centre, PLAIN, 0);
        }
        // The lit spheres are textured: their centres are neither the background nor
        // grey.
        for col in [2, 3] {
            let img = &p.native.image;
            let px = img
                .get_pixel(col * PANEL + centre, img.height() - 1 - (PANEL + centre))
                .0;
            assert!(
                px[..3] != [26, 51, 77] && !(px[0] == px[1] && px[1] == px[2]),
                "{}: sphere {col} is {px:?}",
                p.backend
            );
        }
        assert_eq!(p.native.readbacks.len(), 2, "{}", p.backend);
        for (slot, native) in &p.native.readbacks {
            let emulated = &p.emulate.readbacks[slot];
            assert_eq!(
                (emulated.width, emulated.height, &emulated.bytes),
                (native.width, native.height, &native.bytes),
                "{}: readback_{slot}",
                p.backend
            );
        }
        assert_eq!(p.native.readbacks[&1].width, 4);
    }
}
