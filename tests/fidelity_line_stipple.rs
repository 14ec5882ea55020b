//! Line stipple (GL 1.5 §3.4.2) on the emulated path against Mesa's native path. The
//! emulated path cuts each line into the dashes Mesa's draw module cuts it into
//! (`pipeline::emulate::line_stipple`) and lets llvmpipe rasterise them as Mesa does, so
//! the tolerance is exact: every pixel equal. The cases: every line primitive, lines from
//! pixel centres, pixel corners and quarter offsets (the diamond-exit ties), x-major,
//! y-major and diagonal lines in both directions, factors 1, 3 and 256, patterns 0xFFFF,
//! 0x0001, 0xAAAA and irregular ones, wide lines, strips crossing each other, smooth and
//! flat colours, an offset viewport, a perspective line crossing the near plane, lines
//! clipped by the viewport and by a user clip plane, and arrays, elements, buffer objects
//! and display lists.

mod fidelity;
mod support;

use fidelity::{compare, Frame};
use support::Tolerance;

const W: u32 = 96;
const H: u32 = 64;

fn header() -> String {
    format!(
        "glClearColor(0, 0, 0, 1);\nglClear(GL_COLOR_BUFFER_BIT);\n{}glEnable(GL_LINE_STIPPLE);\n",
        fidelity::ortho(W, H)
    )
}

/// `glBegin(primitive)` over the vertices, with a colour per vertex when `colours`.
fn lines(primitive: &str, v: &[(f32, f32)], colours: bool) -> String {
    let mut s = format!("glBegin({primitive});\n");
    for (i, (x, y)) in v.iter().enumerate() {
        if colours {
            let k = i as f32 / v.len().max(1) as f32;
            s += &format!("glColor3f({}, {}, 1);", 1.0 - k, k);
        }
        s += &format!("glVertex2f({x}, {y});\n");
    }
    s + "glEnd();\n"
}

/// Both paths draw `body` with equal pixels, and the stipple left both lit and unlit
/// pixels where lines are (a case that draws nothing proves nothing).
fn check(name: &str, body: &str) {
    let pairs = compare(
        name,
        &format!("{}{body}", header()),
        Frame::new(W, H),
        Tolerance::EXACT,
    );
    for p in pairs {
        let lit = p
            .native
            .image
            .pixels()
            .filter(|q| q.0[..3] != [0, 0, 0])
            .count();
        assert!(lit > 20, "{name} {}: only {lit} pixels drawn", p.backend);
    }
}

/// A fan of lines from one point in 16 directions, starting at `offset` within its pixel.
fn star(cx: f32, cy: f32, r: f32) -> Vec<(f32, f32)> {
    let mut v = Vec::new();
    for k in 0..16 {
        let a = k as f32 * std::f32::consts::TAU / 16.0;
        v.push((cx, cy));
        v.push((cx + r * a.cos(), cy + r * a.sin()));
    }
    v
}

#[test]
fn lines_of_every_direction_and_start_offset_match_mesa() {
    for (factor, pattern) in [
        (1, 0xAAAA),
        (1, 0x0001),
        (3, 0x0F3D),
        (1, 0xFFFF),
        (2, 0x00FF),
    ] {
        let mut body = format!("glLineStipple({factor}, {pattern:#06x});\nglColor3f(1, 1, 1);\n");
        for (i, off) in [0.0f32, 0.25, 0.5, 0.75].iter().enumerate() {
            let cx = 12.0 + 24.0 * i as f32 + off;
            body += &lines("GL_LINES", &star(cx, 16.0 + off, 11.0), false);
            body += &lines("GL_LINES", &star(cx, 44.0 + 0.5, 11.0), false);
        }
        check(&format!("line-stipple-star-{factor}-{pattern:x}"), &body);
    }
}

#[test]
fn strips_and_loops_run_the_counter_on_and_lines_restart_it() {
    let zig = [
        (3.0, 3.5),
        (40.25, 20.0),
        (10.5, 30.5),
        (60.0, 5.0),
        (90.75, 58.25),
    ];
    let crossing = [(5.0, 60.0), (90.0, 35.0), (20.5, 8.0), (70.0, 60.5)];
    for (factor, pattern) in [(1, 0x0F3D), (3, 0xAAAA), (256, 0x5555), (1, 0x0001)] {
        let mut body = format!("glLineStipple({factor}, {pattern:#06x});\n");
        for p in ["GL_LINES", "GL_LINE_STRIP", "GL_LINE_LOOP"] {
            body += &lines(p, &zig, true);
            body += &lines(p, &crossing, false);
        }
        check(&format!("line-stipple-strips-{factor}-{pattern:x}"), &body);
    }
    // One long loop of many short segments: the float counter adds up fractional lengths.
    let mut ring = Vec::new();
    for k in 0..40 {
        let a = k as f32 * std::f32::consts::TAU / 40.0;
        ring.push((48.0 + 27.3 * a.cos(), 32.0 + 25.1 * a.sin()));
    }
    check(
        "line-stipple-ring",
        &format!(
            "glLineStipple(2, 0x3F07);\nglColor3f(1, 1, 0);\n{}",
            lines("GL_LINE_LOOP", &ring, false)
        ),
    );
}

#[test]
fn wide_flat_and_smooth_stippled_lines_match_mesa() {
    let v = [(4.0, 4.0), (90.0, 20.5), (50.5, 60.0), (10.25, 40.75)];
    for width in [1, 2, 3, 5] {
        let body = format!(
            "glLineWidth({width});\nglLineStipple(2, 0x1C47);\n{}glShadeModel(GL_FLAT);\n{}",
            lines("GL_LINE_STRIP", &v, true),
            lines(
                "GL_LINES",
                &[(4.0, 60.0), (92.0, 48.0), (70.0, 2.0), (80.0, 62.0)],
                true
            )
        );
        check(&format!("line-stipple-wide-{width}"), &body);
    }
}

/// LINE_SMOOTH: Mesa's stipple stage measures an antialiased segment along the line,
/// √(Δx² + Δy²), not along its major axis (`line_stipple::LineLength`), so a diagonal's
/// pattern repeats every 16/√2 columns; lines of every direction, factors 1 and 3, widths
/// 1 and 2, blended as programs draw them, and a triangle's outline in LINE mode.
#[test]
fn antialiased_stippled_lines_count_along_the_line_as_mesa_does() {
    for (factor, width) in [(1, 1), (3, 1), (1, 2)] {
        let mut body = format!(
            "glEnable(GL_LINE_SMOOTH);\nglEnable(GL_BLEND);\nglBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);\n\
             glLineWidth({width});\nglLineStipple({factor}, 0x0FFF);\n"
        );
        let star = star(48.0, 32.0, 30.0);
        for pair in star.chunks(2) {
            body += &lines("GL_LINES", pair, true);
        }
        body += "glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);\n";
        body += &lines(
            "GL_TRIANGLES",
            &[(6.0, 4.0), (40.0, 12.5), (14.5, 58.0)],
            false,
        );
        check(&format!("line-stipple-smooth-{factor}-{width}"), &body);
    }
}

#[test]
fn offset_viewports_clipping_and_perspective_match_mesa() {
    // A viewport offset from the window and smaller than it: lines leaving it are clipped
    // first, so their counter starts at the viewport's edge.
    let body = format!(
        "glViewport(9, 5, 70, 50);\nglLineStipple(1, 0x33F1);\nglColor3f(0, 1, 0);\n{}",
        lines(
            "GL_LINE_STRIP",
            &[(-30.0, 10.5), (60.0, 30.0), (120.0, 80.0), (40.5, -20.0)],
            false
        )
    );
    check("line-stipple-viewport", &body);
    // A user clip plane x ≤ 50 (eye space) cuts the strip.
    let body = format!(
        "glClipPlane(GL_CLIP_PLANE0, (GLdouble[]){{-1, 0, 0, 50}});\nglEnable(GL_CLIP_PLANE0);\nglLineStipple(1, 0x0F0F);\nglColor3f(1, 0, 1);\n{}",
        lines("GL_LINE_STRIP", &[(2.5, 3.5), (93.0, 30.0), (3.0, 60.5)], false)
    );
    check("line-stipple-clip-plane", &body);
    // Perspective: lines crossing the near plane (one end behind the eye, w < 0).
    let persp = "glMatrixMode(GL_PROJECTION);\nglLoadIdentity();\nglFrustum(-1, 1, -0.7, 0.7, 1, 20);\nglMatrixMode(GL_MODELVIEW);\nglLoadIdentity();\nglLineStipple(1, 0x00FF);\nglColor3f(1, 1, 1);\n";
    let body = format!(
        "{persp}glBegin(GL_LINES);\nglVertex3f(-0.5, -0.3, 2);\nglVertex3f(0.6, 0.4, -6);\nglVertex3f(0.3, -0.5, 0.5);\nglVertex3f(-0.8, 0.2, -3);\nglVertex3f(-2, -1, -4);\nglVertex3f(2, 1, -9);\nglEnd();\nglBegin(GL_LINE_STRIP);\nglVertex3f(0, 0.6, 3);\nglVertex3f(0.1, -0.2, -2.5);\nglVertex3f(1.5, 0.1, -5);\nglEnd();\n"
    );
    check("line-stipple-perspective", &body);
}

#[test]
fn arrays_elements_buffers_and_lists_are_stippled_alike() {
    let arrays = "glVertexPointer(2, GL_FLOAT, 0, (GLfloat[]){3, 3, 90, 10.5, 50.5, 60, 8, 33, 70.25, 40.75});\nglEnableClientState(GL_VERTEX_ARRAY);\n";
    let body = format!(
        "glLineStipple(3, 0x6B5D);\nglColor3f(1, 1, 1);\n{arrays}glDrawArrays(GL_LINE_STRIP, 0, 5);\nglTranslatef(2, -1, 0);\nglDrawElements(GL_LINE_LOOP, 4, GL_UNSIGNED_INT, (GLuint[]){{4, 1, 3, 0}});\nglTranslatef(1, 3, 0);\nglDrawArrays(GL_LINES, 0, 4);\n\
         glNewList(1, GL_COMPILE);\nglBegin(GL_LINE_STRIP);\nglVertex2f(5, 50); glVertex2f(45, 62); glVertex2f(88, 20);\nglEnd();\nglEndList();\nglCallList(1);\nglTranslatef(0, -7, 0);\nglCallList(1);\n\
         glBindBuffer(GL_ARRAY_BUFFER, 1);\nglBufferData(GL_ARRAY_BUFFER, 32, (GLfloat[]){{10, 12, 85, 14, 86, 55, 11, 52}}, GL_STATIC_DRAW);\nglVertexPointer(2, GL_FLOAT, 0, NULL);\nglDrawArrays(GL_LINE_LOOP, 0, 4);\n"
    );
    check("line-stipple-arrays", &body);
}

/// Mesa's counter moves on by whole pixels: ⌈L⌉ per segment of window length L. After
/// segments of 69.25 and 52.5 pixels, the third of the strip starts at bit 123 mod 16, not
/// at ⌊121.75⌋ = 121: the emulated path draws it so (the model's `line_stipple` step 4)
/// and the pixels match Mesa's; with the float counter they would not (measured: 34 and 15
/// pixels differ for a rounded or a ceiled float sum).
#[test]
fn a_strip_counts_whole_pixels_per_segment() {
    let body = format!(
        "glLineStipple(1, 0x0F3D);\nglColor3f(1, 1, 1);\n{}",
        lines(
            "GL_LINE_STRIP",
            &[(20.0, 35.0), (89.25, 8.0), (40.0, 60.5), (10.2, 5.0)],
            false
        )
    );
    check("line-stipple-whole-pixels", &body);
}

/// Renders `body` on the native path only.
fn native(body: &str) -> Vec<image::RgbaImage> {
    use fixedfunc::vocab::{PipelineKind, Precision};
    let commands = fidelity::parse(&format!("{}{body}", header()));
    support::HEADLESS
        .iter()
        .map(|&b| {
            fidelity::run_one(
                PipelineKind::Native,
                Precision::Float,
                b,
                Frame::new(W, H),
                &commands,
            )
            .image
        })
        .collect()
}

/// Mesa's stipple of polygons in LINE mode, measured on the native path: the draw module
/// turns each triangle of its split into its boundary edges in the order v2→v0, v0→v1,
/// v1→v2 with the counter running on, reset at the start of each polygon. So a GL_QUADS
/// quad is stippled as the loop v3, v0, v1, v2 (its triangles (v0,v1,v3), (v1,v2,v3)), a
/// GL_POLYGON as the loop of its vertices from v0, and a GL_TRIANGLES triangle as the loop
/// v2, v0, v1 — pixel for pixel. The emulated path draws them so
/// (`stippled_polygon_outlines_match_mesa`).
#[test]
fn mesa_stipples_polygon_outlines_as_loops_from_its_split() {
    let quad = [(10.0, 8.0), (80.0, 12.5), (70.5, 55.0), (15.25, 50.0)];
    let tri = [(20.0, 20.0), (60.5, 25.0), (30.0, 58.0)];
    let pent = [
        (48.0, 4.0),
        (90.0, 30.0),
        (70.0, 60.0),
        (25.0, 60.0),
        (6.0, 30.0),
    ];
    let pick = |v: &[(f32, f32)], order: &[usize]| -> Vec<(f32, f32)> {
        order.iter().map(|&i| v[i]).collect()
    };
    for (prim, v, order) in [
        ("GL_QUADS", &quad[..], vec![3, 0, 1, 2]),
        ("GL_POLYGON", &pent[..], vec![0, 1, 2, 3, 4]),
        ("GL_TRIANGLES", &tri[..], vec![2, 0, 1]),
    ] {
        let stipple = "glLineStipple(1, 0x1F3D);\nglColor3f(1, 1, 1);\n";
        let outline = native(&format!(
            "{stipple}glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);\n{}",
            lines(prim, v, false)
        ));
        let as_loop = native(&format!(
            "{stipple}{}",
            lines("GL_LINE_LOOP", &pick(v, &order), false)
        ));
        let as_other_loop = native(&format!("{stipple}{}", lines("GL_LINE_LOOP", v, false)));
        for ((a, b), c) in outline.iter().zip(&as_loop).zip(&as_other_loop) {
            assert!(a == b, "{prim}: the outline is the loop {order:?}");
            if order[0] != 0 {
                assert!(
                    a != c,
                    "{prim}: the loop from v0 differs (the order is seen)"
                );
            }
        }
    }
}

/// The emulated path stipples polygons in LINE mode as Mesa does (`outline_dashes`): the
/// quads, polygon and triangles above, a strip, a fan and a quad strip, smooth and flat,
/// pixel for pixel.
#[test]
fn stippled_polygon_outlines_match_mesa() {
    let quads = [(10.0, 8.0), (80.0, 12.5), (70.5, 55.0), (15.25, 50.0)];
    let pent = [
        (48.0, 4.0),
        (90.0, 30.0),
        (70.0, 60.0),
        (25.0, 60.0),
        (6.0, 30.0),
    ];
    let strip: Vec<(f32, f32)> = (0..6)
        .map(|i| (8.0 + 15.5 * i as f32, if i % 2 == 1 { 55.0 } else { 9.5 }))
        .collect();
    for (prim, v) in [
        ("GL_QUADS", &quads[..]),
        ("GL_POLYGON", &pent[..]),
        ("GL_TRIANGLE_STRIP", &strip[..]),
        ("GL_TRIANGLE_FAN", &pent[..]),
        ("GL_QUAD_STRIP", &strip[..4]),
    ] {
        for shade in ["GL_SMOOTH", "GL_FLAT"] {
            check(
                &format!("outline-{prim}-{shade}"),
                &format!(
                    "glLineStipple(1, 0x1F3D);\nglShadeModel({shade});\n\
                     glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);\n{}",
                    lines(prim, v, true)
                ),
            );
        }
    }
}
