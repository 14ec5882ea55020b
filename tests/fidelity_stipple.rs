//! Polygon stipple (GL 1.5 §3.5.2) against Mesa's native path: every polygon primitive
//! (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN, QUADS, QUAD_STRIP, POLYGON) filled under an
//! asymmetric 32×32 pattern, in a viewport offset from the window's origin on a target
//! that is no multiple of 32 wide or high, then again with the front faces in LINE mode
//! and the back faces in POINT mode (neither stippled), lines and points drawn with the
//! stipple enabled (never stippled), and a pattern changed inside
//! glPushAttrib(GL_POLYGON_STIPPLE_BIT) and restored by the pop. Exact pixels between the
//! paths; the filled cells are probed against the pattern itself (the window-relative
//! rule x_w mod 32, y_w mod 32).

mod fidelity;
mod support;

use fidelity::{compare, Frame};
use fixedfunc::ff::PolygonStipple;
use support::Tolerance;

const W: u32 = 150;
const H: u32 = 90;

/// An asymmetric mask: no row or column repeats with a period below 32.
fn mask() -> Vec<u8> {
    (0..128u32)
        .map(|i| ((i * 37 + 11) ^ ((i >> 2) * 5)) as u8)
        .collect()
}

fn bytes(mask: &[u8]) -> String {
    let v: Vec<String> = mask.iter().map(|b| b.to_string()).collect();
    format!("(GLubyte[]){{{}}}", v.join(", "))
}

/// One 20×20 cell at (x, y) of the ortho space drawn as `primitive`.
fn cell(primitive: &str, x: f32, y: f32) -> String {
    let (x1, y1) = (x + 20.0, y + 20.0);
    let (mx, my) = (x + 10.0, y + 10.0);
    let v = |x: f32, y: f32| format!("glVertex2f({x}, {y});");
    let vs: Vec<String> = match primitive {
        "GL_TRIANGLES" => vec![v(x, y), v(x1, y), v(x1, y1), v(x, y), v(x1, y1), v(x, y1)],
        "GL_TRIANGLE_STRIP" | "GL_QUAD_STRIP" => vec![v(x, y), v(x1, y), v(x, y1), v(x1, y1)],
        "GL_TRIANGLE_FAN" => vec![v(mx, my), v(x, y), v(x1, y), v(x1, y1), v(x, y1), v(x, y)],
        _ => vec![v(x, y), v(x1, y), v(x1, y1), v(x, y1)],
    };
    format!("glBegin({primitive});\n{}\nglEnd();\n", vs.join(" "))
}

const PRIMITIVES: [&str; 6] = [
    "GL_TRIANGLES",
    "GL_TRIANGLE_STRIP",
    "GL_TRIANGLE_FAN",
    "GL_QUADS",
    "GL_QUAD_STRIP",
    "GL_POLYGON",
];

/// The viewport's lower-left corner in the window.
const VIEWPORT: (u32, u32) = (7, 5);

fn script() -> String {
    let mut s = String::new();
    s += "glClearColor(0, 0, 0, 1);\nglClear(GL_COLOR_BUFFER_BIT);\n";
    s += &format!("glViewport({}, {}, 140, 84);\n", VIEWPORT.0, VIEWPORT.1);
    s += "glMatrixMode(GL_PROJECTION);\nglLoadIdentity();\nglOrtho(0, 140, 0, 84, -1, 1);\n";
    s += "glMatrixMode(GL_MODELVIEW);\nglLoadIdentity();\n";
    s += &format!("glPolygonStipple({});\n", bytes(&mask()));
    s += "glEnable(GL_POLYGON_STIPPLE);\n";
    // Row 0: every primitive filled.
    s += "glColor3f(1, 1, 0);\n";
    for (i, p) in PRIMITIVES.iter().enumerate() {
        s += &cell(p, 2.0 + 23.0 * i as f32, 2.0);
    }
    // Row 1: front faces as lines, back faces (clockwise) as points; both unstippled.
    s += "glPolygonMode(GL_FRONT, GL_LINE);\nglPolygonMode(GL_BACK, GL_POINT);\n";
    s += "glColor3f(0, 1, 1);\nglPointSize(3);\n";
    for (i, p) in PRIMITIVES.iter().enumerate() {
        s += "glFrontFace(GL_CCW);\n";
        s += &cell(p, 2.5 + 23.0 * i as f32, 25.5);
    }
    s += "glFrontFace(GL_CW);\n";
    s += &cell("GL_QUADS", 2.5, 48.5);
    s += "glFrontFace(GL_CCW);\nglPolygonMode(GL_FRONT_AND_BACK, GL_FILL);\n";
    // Lines and points are not polygons: never polygon-stippled.
    s += "glColor3f(1, 0, 1);\nglBegin(GL_LINES);\nglVertex2f(30.5, 50.5); glVertex2f(70.5, 66.5);\nglEnd();\n";
    s += "glBegin(GL_POINTS);\nglVertex2f(80.5, 60.5);\nglEnd();\n";
    // A pattern pushed, replaced and popped: the cell is drawn with the first mask.
    s += "glPushAttrib(GL_POLYGON_STIPPLE_BIT);\n";
    s += &format!("glPolygonStipple({});\n", bytes(&[0x0F; 128]));
    s += "glPopAttrib();\nglColor3f(1, 1, 1);\n";
    s += &cell("GL_QUADS", 95.0, 50.0);
    // POLYGON_STIPPLE is in ENABLE_BIT: disabled inside, enabled again after the pop.
    s += "glPushAttrib(GL_ENABLE_BIT);\nglDisable(GL_POLYGON_STIPPLE);\nglPopAttrib();\n";
    s += "glColor3f(1, 0.5, 0);\n";
    s += &cell("GL_TRIANGLES", 118.0, 50.0);
    s
}

#[test]
fn polygon_stipple_matches_mesa_for_every_polygon_primitive() {
    let pairs = compare(
        "polygon-stipple",
        &script(),
        Frame::new(W, H),
        Tolerance::EXACT,
    );
    let pattern = PolygonStipple::from_bytes(&mask()).unwrap();
    for p in pairs {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            // Inside each filled cell (2 pixels in from its edges) a pixel is lit iff its
            // window position's bit is set.
            let mut cells: Vec<(u32, u32, [u8; 3])> =
                (0..6).map(|i| (2 + 23 * i, 2, [255, 255, 0])).collect();
            cells.push((95, 50, [255, 255, 255]));
            cells.push((118, 50, [255, 128, 0]));
            for (cx, cy, colour) in cells {
                let (mut set, mut unset) = (0, 0);
                for y in cy + 2..cy + 18 {
                    for x in cx + 2..cx + 18 {
                        let (wx, wy) = (x + VIEWPORT.0, y + VIEWPORT.1);
                        let got = out.image.get_pixel(wx, H - 1 - wy).0;
                        let lit = pattern.passes(wx as i32, wy as i32);
                        let expected = if lit { colour } else { [0, 0, 0] };
                        assert_eq!(
                            got[..3],
                            expected,
                            "{} {path}: cell ({cx}, {cy}) window pixel ({wx}, {wy})",
                            p.backend
                        );
                        if lit {
                            set += 1;
                        } else {
                            unset += 1;
                        }
                    }
                }
                assert!(set > 20 && unset > 20, "the pattern shows in the cell");
            }
            // The outline of a LINE-mode polygon is drawn whole: the bottom edge of the
            // quad of row 1 at y = 25.5 covers window row 25 + 5 from x 3 to 22.
            for x in 3..22 {
                let got = out.image.get_pixel(23 * 3 + x + VIEWPORT.0, H - 1 - 30).0;
                assert_eq!(
                    got[..3],
                    [0, 255, 255],
                    "{} {path}: line at x {x}",
                    p.backend
                );
            }
        }
    }
}

/// Mesa's line stipple, measured on the native path (GL 1.5 §3.4.2): an x-major line from
/// pixel centre x = 0.5 draws pixel x iff bit ⌊x/factor⌋ mod 16 of the pattern is set; the
/// counter restarts at each segment of GL_LINES and runs on along a GL_LINE_STRIP.
#[test]
fn mesa_line_stipple_counts_window_pixels_along_the_line() {
    use fidelity::run_one;
    use fixedfunc::ff::LineStipple;
    use fixedfunc::vocab::{PipelineKind, Precision};
    let s = LineStipple::new(2, 0x0F3D);
    let script = format!(
        "{}glClearColor(0, 0, 0, 1);\nglClear(GL_COLOR_BUFFER_BIT);\nglLineStipple(2, 0x0F3D);\nglEnable(GL_LINE_STIPPLE);\nglColor3f(1, 1, 1);\n\
         glBegin(GL_LINES);\nglVertex2f(0, 2.5); glVertex2f(80, 2.5);\nglVertex2f(0, 6.5); glVertex2f(40, 6.5);\nglVertex2f(40, 6.5); glVertex2f(80, 6.5);\nglEnd();\n\
         glBegin(GL_LINE_STRIP);\nglVertex2f(0, 10.5); glVertex2f(40, 10.5); glVertex2f(80, 10.5);\nglEnd();\n",
        fidelity::ortho(80, 16)
    );
    let commands = fidelity::parse(&script);
    for backend in support::HEADLESS {
        let out = run_one(
            PipelineKind::Native,
            Precision::Float,
            backend,
            Frame::new(80, 16),
            &commands,
        );
        let lit = |x: u32, y: u32| out.image.get_pixel(x, 15 - y).0[0] == 255;
        for x in 0..80 {
            assert_eq!(lit(x, 2), s.passes(x), "{backend}: one segment, x {x}");
            assert_eq!(
                lit(x, 6),
                s.passes(x % 40),
                "{backend}: two segments, x {x}"
            );
            assert_eq!(lit(x, 10), s.passes(x), "{backend}: a strip, x {x}");
        }
    }
}
