//! Antialiasing enables against Mesa's native path. POLYGON_SMOOTH changes nothing on
//! llvmpipe, so blended polygons with it match exactly; antialiased points and lines are
//! drawn as Mesa's draw module draws them (its aapoint and aaline stages).

mod fidelity;
mod support;

use fidelity::{compare, ortho, Frame};
use support::Tolerance;

const W: u32 = 64;
const H: u32 = 48;

fn triangles() -> String {
    format!(
        "{}glClearColor(0, 0, 0, 1);\nglClear(GL_COLOR_BUFFER_BIT);\n\
         glEnable(GL_BLEND);\nglBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);\n\
         glEnable(GL_POLYGON_SMOOTH);\nglShadeModel(GL_SMOOTH);\n\
         glBegin(GL_TRIANGLES);\n\
         glColor4f(1, 1, 0, 0.8); glVertex2f(3.3, 2.7);\n\
         glColor4f(0, 1, 1, 0.6); glVertex2f(60.2, 9.4);\n\
         glColor4f(1, 0, 1, 1); glVertex2f(21.7, 45.1);\n\
         glEnd();\n\
         glBegin(GL_QUADS);\n\
         glColor4f(1, 0.5, 0, 0.7); glVertex2f(30.5, 20.25); glVertex2f(58.75, 24.5);\n\
         glVertex2f(55.1, 44.9); glVertex2f(33.3, 40.0);\n\
         glEnd();\n",
        ortho(W, H)
    )
}

#[test]
fn polygon_smooth_changes_nothing_on_llvmpipe() {
    let pairs = compare(
        "polygon_smooth",
        &triangles(),
        Frame::new(W, H),
        Tolerance::EXACT,
    );
    let off = triangles().replace("glEnable(GL_POLYGON_SMOOTH);\n", "");
    let plain = compare(
        "polygon_smooth_off",
        &off,
        Frame::new(W, H),
        Tolerance::EXACT,
    );
    for (with, without) in pairs.iter().zip(&plain) {
        assert_eq!(
            with.native.image.as_raw(),
            without.native.image.as_raw(),
            "Mesa's native path draws the same pixels with and without POLYGON_SMOOTH"
        );
        let lit = with
            .native
            .image
            .pixels()
            .filter(|p| p.0[..3] != [0, 0, 0])
            .count();
        assert!(lit > 500, "the polygons were drawn ({lit} pixels)");
    }
}

/// Points and lines of several sizes and widths at fractional positions, opaque and
/// translucent, blended, with `cap` enabled.
fn smooth_primitives(cap: &str) -> String {
    let mut s = format!(
        "{}glClearColor(0.1, 0.1, 0.2, 1);\nglClear(GL_COLOR_BUFFER_BIT);\n\
         glEnable(GL_BLEND);\nglBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);\n\
         glEnable({cap});\n",
        ortho(W, H)
    );
    for (i, size) in [0.5f32, 1.0, 2.0, 2.5, 4.0, 7.5].iter().enumerate() {
        let (x, y) = (4.3 + 10.1 * i as f32, 6.6 + 0.29 * i as f32);
        let alpha = if i % 2 == 0 { 1.0 } else { 0.45 };
        s += &format!(
            "glPointSize({size});\nglColor4f(1, 0.8, 0.4, {alpha});\n\
             glBegin(GL_POINTS);\nglVertex2f({x}, {y});\nglEnd();\n"
        );
    }
    for (i, width) in [1.0f32, 1.5, 3.0].iter().enumerate() {
        let y = 18.2 + 9.7 * i as f32;
        s += &format!(
            "glLineWidth({width});\nglColor4f(0.4, 1, 0.9, 0.8);\n\
             glBegin(GL_LINE_LOOP);\nglVertex2f(3.3, {y});\nglVertex2f(60.6, {});\n\
             glVertex2f(31.1, {});\nglEnd();\n",
            y + 4.4,
            y + 7.9
        );
    }
    s
}

/// POINT_SMOOTH (the emulated path's round points, after Mesa's aapoint stage) and
/// LINE_SMOOTH (the core context's aaline stage) draw Mesa's pixels: within 1/255 on the
/// translucent points, whose alpha factor the program computes in its own order.
#[test]
fn smooth_points_and_lines_match_mesa() {
    for cap in ["GL_POINT_SMOOTH", "GL_LINE_SMOOTH"] {
        let name = cap.trim_start_matches("GL_").to_lowercase();
        let pairs = compare(
            &name,
            &smooth_primitives(cap),
            Frame::new(W, H),
            Tolerance {
                per_channel: 1,
                max_bad_pixels: 0,
            },
        );
        // Antialiased: the aliased draw of the same script (DITHER, on by default, in
        // place of the cap) differs from it.
        let plain = compare(
            &format!("{name}_off"),
            &smooth_primitives("GL_DITHER"),
            Frame::new(W, H),
            Tolerance::EXACT,
        );
        for (smooth, aliased) in pairs.iter().zip(&plain) {
            assert_ne!(
                smooth.native.image.as_raw(),
                aliased.native.image.as_raw(),
                "{cap} changes Mesa's pixels"
            );
        }
    }
}

/// Points whose sizes glPointParameter attenuates by eye distance and clamps, in
/// perspective, aliased and with `smooth` (POINT_SMOOTH: the aapoint radius of a
/// per-vertex size).
fn attenuated_points(smooth: bool) -> String {
    let mut s = String::from(
        "glMatrixMode(GL_PROJECTION);\nglLoadIdentity();\nglFrustum(-1, 1, -0.75, 0.75, 1, 100);\n\
         glMatrixMode(GL_MODELVIEW);\nglLoadIdentity();\n\
         glClearColor(0.1, 0.1, 0.2, 1);\nglClear(GL_COLOR_BUFFER_BIT);\n\
         glEnable(GL_BLEND);\nglBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);\n\
         glPointSize(11);\nglPointParameterf(GL_POINT_SIZE_MIN, 1.5);\n\
         glPointParameterf(GL_POINT_SIZE_MAX, 9);\n\
         glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, (GLfloat[]){0.1, 0.25, 0.03});\n",
    );
    if smooth {
        s += "glEnable(GL_POINT_SMOOTH);\n";
    }
    s += "glBegin(GL_POINTS);\n";
    for i in 0..12 {
        let z = -1.3 - 0.8 * i as f32;
        let (x, y) = ((-0.7 + 0.13 * i as f32) * -z, (0.3 - 0.05 * i as f32) * -z);
        s += &format!("glColor4f(1, 0.7, 0.3, 0.8);\nglVertex3f({x}, {y}, {z});\n");
    }
    s + "glEnd();\n"
}

/// glPointParameter's derived sizes draw Mesa's pixels on the emulated path, aliased and
/// smooth: within 1/255 (the smooth points' alpha factor, computed in the program's own
/// order).
#[test]
fn attenuated_points_match_mesa() {
    for smooth in [false, true] {
        let pairs = compare(
            if smooth {
                "attenuated_smooth_points"
            } else {
                "attenuated_points"
            },
            &attenuated_points(smooth),
            Frame::new(W, H),
            Tolerance {
                per_channel: 1,
                max_bad_pixels: 0,
            },
        );
        for pair in &pairs {
            let lit = pair.native.image.pixels().filter(|p| p.0[0] > 100).count();
            assert!(lit > 150, "the points were drawn ({lit} pixels)");
        }
    }
}
