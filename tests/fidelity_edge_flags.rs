//! Edge flags (GL 1.5 §2.6.2, §3.5.4) on the emulated path against Mesa's native path: in
//! LINE polygon mode an edge starting at a vertex whose flag is FALSE is not drawn, in POINT
//! mode such a vertex is not drawn (Mesa's draw module tests the vertex's flag for points as
//! for lines; pinned below), and only TRIANGLES, QUADS and POLYGON read the flags. Flags
//! come from glEdgeFlag inside glBegin/glEnd, from the current flag, from EDGE_FLAG_ARRAY
//! (glDrawArrays, glDrawElements, glArrayElement) and from display lists; the cases cover
//! separate front and back modes and culling. Tolerance: exact, every pixel equal. Point
//! cases keep vertices off pixel-centre ties (a translation of 0.3): there llvmpipe
//! rasterises a point of odd size on a core context one pixel lower and to the left than
//! on a compatibility one, for GL_POINTS as for POINT mode, edge flags or not.

mod fidelity;
mod support;

use fidelity::{compare, run_one, Frame};
use fixedfunc::vocab::{PipelineKind, Precision};
use support::Tolerance;

const W: u32 = 128;
const H: u32 = 96;

fn header() -> String {
    format!(
        "glClearColor(0, 0, 0, 1);\nglClear(GL_COLOR_BUFFER_BIT);\n{}glColor3f(1, 1, 1);\nglPointSize(3);\n",
        fidelity::ortho(W, H)
    )
}

/// A vertex (x, y) and its edge flag.
type Flagged = (f32, f32, bool);

/// `glBegin(primitive)` over the vertices, each with `glEdgeFlag` before it.
fn flagged(primitive: &str, v: &[(f32, f32, bool)]) -> String {
    let mut s = format!("glBegin({primitive});\n");
    for (x, y, f) in v {
        s += &format!(
            "glEdgeFlag({});glVertex2f({x}, {y});\n",
            if *f { "GL_TRUE" } else { "GL_FALSE" }
        );
    }
    s + "glEnd();\n"
}

/// The same vertices with every flag TRUE.
fn unflagged(v: &[(f32, f32, bool)]) -> Vec<(f32, f32, bool)> {
    v.iter().map(|&(x, y, _)| (x, y, true)).collect()
}

fn lit(img: &image::RgbaImage) -> usize {
    img.pixels().filter(|q| q.0[..3] != [0, 0, 0]).count()
}

/// Both paths draw `body` with equal pixels; the native image has something drawn.
fn check(name: &str, body: &str) -> Vec<fidelity::Pair> {
    let pairs = compare(
        name,
        &format!("{}{body}", header()),
        Frame::new(W, H),
        Tolerance::EXACT,
    );
    for p in &pairs {
        let n = lit(&p.native.image);
        assert!(n > 10, "{name} {}: only {n} pixels drawn", p.backend);
    }
    pairs
}

fn native(body: &str) -> image::RgbaImage {
    let cmds = fidelity::parse(&format!("{}{body}", header()));
    run_one(
        PipelineKind::Native,
        Precision::Float,
        support::HEADLESS[0],
        Frame::new(W, H),
        &cmds,
    )
    .image
}

/// Two triangles, a quad and a pentagon with some FALSE flags, spread over the frame.
fn shapes() -> Vec<(&'static str, Vec<Flagged>)> {
    vec![
        (
            "GL_TRIANGLES",
            vec![
                (6.0, 6.0, true),
                (40.0, 8.5, false),
                (20.25, 40.0, true),
                (44.0, 10.0, false),
                (60.5, 44.0, false),
                (30.0, 44.0, true),
            ],
        ),
        (
            "GL_QUADS",
            vec![
                (70.0, 6.0, true),
                (120.5, 9.0, false),
                (116.0, 40.25, true),
                (74.0, 38.0, false),
            ],
        ),
        (
            "GL_POLYGON",
            vec![
                (30.0, 52.0, false),
                (70.0, 50.0, true),
                (80.5, 70.0, false),
                (50.0, 90.0, true),
                (20.25, 76.0, true),
            ],
        ),
    ]
}

#[test]
fn line_mode_leaves_out_the_edges_of_false_flags() {
    for (prim, v) in shapes() {
        let mode = "glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);\n";
        let pairs = check(
            &format!("edge-flags-line-{prim}"),
            &format!("{mode}{}", flagged(prim, &v)),
        );
        let all = native(&format!("{mode}{}", flagged(prim, &unflagged(&v))));
        assert!(
            lit(&pairs[0].native.image) < lit(&all),
            "{prim}: FALSE flags leave edges out"
        );
    }
}

#[test]
fn point_mode_leaves_out_the_vertices_of_false_flags() {
    for (prim, v) in shapes() {
        let mode = "glTranslatef(0.3, 0.3, 0);\nglPolygonMode(GL_FRONT_AND_BACK, GL_POINT);\n";
        check(
            &format!("edge-flags-point-{prim}"),
            &format!("{mode}{}", flagged(prim, &v)),
        );
    }
}

/// Measured on Mesa 22.3.6 llvmpipe: in POINT mode a vertex whose edge flag is FALSE is
/// not drawn (`draw_pipe_unfilled.c`'s `points` tests the flag). One quad, points of
/// 5 pixels at its corners, v1 flagged FALSE: three points drawn.
#[test]
fn mesa_drops_the_points_of_false_flags() {
    let v = [
        (20.0, 20.0, true),
        (100.0, 20.0, false),
        (100.0, 70.0, true),
        (20.0, 70.0, true),
    ];
    let body = format!(
        "glPointSize(5);\nglPolygonMode(GL_FRONT_AND_BACK, GL_POINT);\n{}",
        flagged("GL_QUADS", &v)
    );
    let img = native(&body);
    let at = |x: u32, y: u32| img.get_pixel(x, H - 1 - y).0[0];
    assert_eq!(at(20, 20), 255, "v0 drawn");
    assert_eq!(at(100, 20), 0, "v1 (FALSE) not drawn");
    assert_eq!(at(100, 70), 255, "v2 drawn");
    assert_eq!(at(20, 70), 255, "v3 drawn");
    assert_eq!(lit(&img), 75, "three 5×5 points");
}

/// The current flag FALSE outside glBegin/glEnd: every vertex of TRIANGLES, QUADS and
/// POLYGON takes it, so nothing is drawn in LINE or POINT mode; filled polygons are drawn
/// whole.
#[test]
fn the_current_flag_applies_to_every_vertex() {
    let mut draws = String::new();
    for (prim, v) in shapes() {
        let mut s = format!("glBegin({prim});\n");
        for (x, y, _) in v {
            s += &format!("glVertex2f({x}, {y});\n");
        }
        draws += &(s + "glEnd();\n");
    }
    for mode in ["GL_LINE", "GL_POINT"] {
        let m = format!("glTranslatef(0.3, 0.3, 0);\nglPolygonMode(GL_FRONT_AND_BACK, {mode});\n");
        let shown = native(&format!("{m}{draws}"));
        assert!(lit(&shown) > 10, "{mode}: TRUE draws the outlines");
        let pairs = compare(
            &format!("edge-flags-current-{mode}"),
            &format!("{}{m}glEdgeFlag(GL_FALSE);\n{draws}", header()),
            Frame::new(W, H),
            Tolerance::EXACT,
        );
        for p in &pairs {
            assert_eq!(
                lit(&p.native.image),
                0,
                "{} {mode}: nothing drawn",
                p.backend
            );
        }
    }
    check(
        "edge-flags-current-fill",
        &format!("glEdgeFlag(GL_FALSE);\n{draws}"),
    );
}

/// Strips and fans: GL 1.5 §2.6.2 flags only the vertices of polygons, separate
/// triangles and separate quads, so every edge of a strip or fan would be a boundary edge.
/// Mesa 22.3.6 deviates: its draw module tests the vertex's flag on every triangle it
/// decomposes, strips and fans included, so with the current flag FALSE a TRIANGLE_STRIP,
/// TRIANGLE_FAN or QUAD_STRIP in LINE mode shows nothing — and the emulated path follows
/// it (`Geometry::reads_edge_flags`; each flag in turn in `tests/c/edge_strips.c`). Pinned:
/// both paths' blank image, and both drawing the strips whole with the flag TRUE.
#[test]
fn strips_and_fans_honour_edge_flags_as_mesa_does() {
    let strips = "glBegin(GL_TRIANGLE_STRIP);\nglVertex2f(70, 10);\nglVertex2f(120, 14);\nglVertex2f(80, 50);\nglVertex2f(118, 60);\nglEnd();\n\
        glBegin(GL_TRIANGLE_FAN);\nglVertex2f(40, 60);\nglVertex2f(70, 62);\nglVertex2f(60, 90);\nglVertex2f(20, 88);\nglEnd();\n\
        glBegin(GL_QUAD_STRIP);\nglVertex2f(80, 66);\nglVertex2f(80, 92);\nglVertex2f(100, 70);\nglVertex2f(100, 90);\nglVertex2f(124, 66);\nglVertex2f(124, 92);\nglEnd();\n";
    let m = "glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);\n";
    let pairs = check("edge-flags-strips-true", &format!("{m}{strips}"));
    let flagged = fidelity::run_both(
        &format!("{}{m}glEdgeFlag(GL_FALSE);\n{strips}", header()),
        Frame::new(W, H),
    );
    for (t, f) in pairs.iter().zip(&flagged) {
        assert!(lit(&t.native.image) > 0, "{}: strips drawn", t.backend);
        assert_eq!(
            lit(&f.native.image),
            0,
            "{}: Mesa changed — it now ignores flags on strips; follow it",
            f.backend
        );
        assert_eq!(
            lit(&f.emulate.image),
            0,
            "{}: the emulated strips draw edges whose flag is FALSE",
            f.backend
        );
    }
}

/// The flags as an array: glDrawArrays, glDrawElements and glArrayElement.
#[test]
fn edge_flag_arrays_through_arrays_elements_and_array_element() {
    let quad = "glVertexPointer(2, GL_FLOAT, 0, (GLfloat[]){10, 10, 60, 12, 56, 44, 12, 40, 70, 10, 120, 14, 118, 44, 72, 46});\n\
        glEdgeFlagPointer(0, (GLboolean[]){1, 0, 1, 1, 0, 1, 0, 1});\n\
        glEnableClientState(GL_VERTEX_ARRAY);\nglEnableClientState(GL_EDGE_FLAG_ARRAY);\n";
    for mode in ["GL_LINE", "GL_POINT"] {
        let m = format!("glTranslatef(0.3, 0.3, 0);\nglPolygonMode(GL_FRONT_AND_BACK, {mode});\n");
        let pairs = check(
            &format!("edge-flags-draw-arrays-{mode}"),
            &format!("{m}{quad}glDrawArrays(GL_QUADS, 0, 8);\nglDrawArrays(GL_TRIANGLES, 0, 6);\n"),
        );
        let without = native(&format!(
            "{m}{quad}glDisableClientState(GL_EDGE_FLAG_ARRAY);\nglDrawArrays(GL_QUADS, 0, 8);\nglDrawArrays(GL_TRIANGLES, 0, 6);\n"
        ));
        assert!(
            pairs[0].native.image != without,
            "{mode}: the array is read"
        );
        check(
            &format!("edge-flags-draw-elements-{mode}"),
            &format!(
                "{m}{quad}glDrawElements(GL_QUADS, 8, GL_UNSIGNED_BYTE, (GLubyte[]){{4, 5, 6, 7, 0, 1, 2, 3}});\n\
                 glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, (GLubyte[]){{5, 6, 4}});\n"
            ),
        );
        check(
            &format!("edge-flags-array-element-{mode}"),
            &format!(
                "{m}{quad}glBegin(GL_POLYGON);\nglArrayElement(0);\nglArrayElement(1);\nglArrayElement(5);\nglArrayElement(6);\nglArrayElement(2);\nglArrayElement(3);\nglEnd();\n"
            ),
        );
    }
}

/// A display list keeps the flags of its pair and of its glEdgeFlag outside a pair.
#[test]
fn display_lists_keep_edge_flags() {
    let (_, v) = shapes().remove(2);
    let body = format!(
        "glNewList(1, GL_COMPILE);\n{}glEndList();\n\
         glNewList(2, GL_COMPILE);\nglEdgeFlag(GL_FALSE);\nglEndList();\n\
         glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);\nglCallList(1);\n\
         glTranslatef(40, -45, 0);\nglCallList(2);\nglBegin(GL_TRIANGLES);\nglVertex2f(10, 50);\nglEdgeFlag(GL_TRUE);glVertex2f(40, 52);\nglVertex2f(20, 80);\nglEnd();\n",
        flagged("GL_POLYGON", &v)
    );
    check("edge-flags-lists", &body);
}

/// Separate front and back modes (front LINE, back POINT) and culling: each face's flags
/// apply in its own mode; a culled face draws nothing.
#[test]
fn separate_modes_and_culling() {
    let (_, tris) = shapes().remove(0);
    let (_, quad) = shapes().remove(1);
    // The quad reversed: a back face.
    let back: Vec<_> = quad.iter().rev().copied().collect();
    let draws = format!(
        "{}{}",
        flagged("GL_TRIANGLES", &tris),
        flagged("GL_QUADS", &back)
    );
    let modes = "glTranslatef(0.3, 0.3, 0);\nglPolygonMode(GL_FRONT, GL_LINE);\nglPolygonMode(GL_BACK, GL_POINT);\n";
    check("edge-flags-front-back", &format!("{modes}{draws}"));
    for face in ["GL_FRONT", "GL_BACK"] {
        check(
            &format!("edge-flags-cull-{face}"),
            &format!(
                "{modes}glEnable(GL_CULL_FACE);\nglCullFace({face});\n{}{}",
                draws,
                flagged(
                    "GL_TRIANGLES",
                    &[
                        (70.0, 60.0, false),
                        (120.0, 62.0, true),
                        (90.0, 92.0, true),
                        (70.0, 60.0, true),
                        (90.0, 92.0, false),
                        (60.0, 90.0, true)
                    ]
                )
            ),
        );
    }
}
