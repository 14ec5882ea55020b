//! User clip planes (GL 1.5 §2.12) emulated with gl_ClipDistance against Mesa's native
//! clipping on both headless backends, exact on ≥ 99% of the pixels (the plane edges lie on
//! pixel boundaries, so only a rasteriser difference could move a pixel).
//!
//! The planes are specified under one modelview and used under another: CLIP_PLANE0
//! (1, 0, 0, 0) under a 90° turn about z keeps eye y ≥ 0 (the top half), and
//! CLIP_PLANE0 + 7 (−1, 0, 0, 0) under glTranslatef(½, 0, 0) keeps eye x ≤ ½. A pipeline
//! that transformed the planes by the modelview of the draw (the identity) would keep the
//! right half and x ≤ 0 instead and fail both the comparison and the probes; one limited
//! to 6 planes would reject CLIP_PLANE0 + 7 as INVALID_ENUM and fail the run.

mod fidelity;
mod support;

use fidelity::{compare, probe_gl, script_file, Frame};
use fixedfunc::ff::MAX_CLIP_PLANES;
use fixedfunc::gpu::Profile;
use glow::HasContext;
use support::Tolerance;

const FRAME: Frame = Frame::new(32, 32);

#[test]
fn clip_planes_are_fixed_in_eye_space_when_specified() {
    let src = "glViewport(0, 0, 32, 32);
glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glOrtho(-1, 1, -1, 1, -1, 1);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glRotatef(90, 0, 0, 1);
glClipPlane(GL_CLIP_PLANE0, (GLdouble[]){1, 0, 0, 0});
glLoadIdentity();
glTranslatef(0.5, 0, 0);
glClipPlane(GL_CLIP_PLANE0 + 7, (GLdouble[]){-1, 0, 0, 0});
glLoadIdentity();
glEnable(GL_CLIP_PLANE0);
glEnable(GL_CLIP_PLANE0 + 7);
glBegin(GL_QUADS);
glColor3f(1, 0.5, 0);
glVertex2f(-1, -1);
glVertex2f(1, -1);
glColor3f(0, 0.5, 1);
glVertex2f(1, 1);
glVertex2f(-1, 1);
glEnd();
glDisable(GL_CLIP_PLANE0);
glDisable(GL_CLIP_PLANE0 + 7);
glColor3f(1, 1, 1);
glBegin(GL_TRIANGLES);
glVertex2f(0.75, -1);
glVertex2f(1, -1);
glVertex2f(1, -0.75);
glEnd();
";
    let tol = Tolerance {
        per_channel: 0,
        max_bad_pixels: (FRAME.width * FRAME.height / 100) as usize,
    };
    for p in compare("clip-planes", src, FRAME, tol) {
        for out in [&p.emulate, &p.native] {
            // Kept: y ≥ 16 and x < 24 (pixel centres); the rest is the clear colour, but
            // for the unclipped white corner drawn after the planes were disabled.
            let lit = |x: u32, y: u32| {
                let px = out.image.get_pixel(x, 31 - y).0;
                px[..3] != [0, 0, 0]
            };
            for (x, y, kept) in [
                (0, 16, true),
                (23, 31, true),
                (23, 16, true),
                (24, 20, false),
                (0, 15, false),
                (10, 0, false),
                (31, 31, false),
            ] {
                assert_eq!(lit(x, y), kept, "{} pixel ({x}, {y})", p.backend);
            }
            probe_gl(&out.image, 31, 0, [255, 255, 255, 255], 0);
        }
    }
}

/// GL_MAX_CLIP_PLANES of the native path's compatibility context is the model's.
#[test]
fn max_clip_planes_is_mesas() {
    for backend in support::HEADLESS {
        let ctx = support::context(backend, Profile::Compatibility);
        let n = unsafe { ctx.gl().get_parameter_i32(glow::MAX_CLIP_DISTANCES) };
        assert_eq!(n as usize, MAX_CLIP_PLANES, "{backend}");
        support::assert_no_gl_error(&ctx);
    }
}

/// A smooth quad of four colours whose red first corner a plane cuts off: Mesa's draw
/// module clips the quad and splits it (v0,v1,v3),(v1,v2,v3), so the kept corner is
/// shaded from green, blue and white alone; split (v0,v1,v2),(v0,v2,v3), as an unclipped
/// quad is, red would tint every pixel kept (`pipeline::emulate::assembly`).
#[test]
fn a_quad_cut_by_a_clip_plane_is_split_as_mesa_splits_it() {
    let head = "glViewport(0, 0, 32, 32);
glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glClipPlane(GL_CLIP_PLANE0, (GLdouble[]){1, 1, 0, 0.25});
glEnable(GL_CLIP_PLANE0);
";
    let src = format!("{head}{}", script_file("four_colour_quad"));
    let tol = Tolerance {
        per_channel: 1,
        max_bad_pixels: (FRAME.width * FRAME.height / 100) as usize,
    };
    for p in compare("clip-plane-quad", &src, FRAME, tol) {
        let out = &p.emulate;
        // Pixel (24, 8), window y from the bottom: in the triangle (v1, v2, v3) and
        // kept; red only from v3's white there.
        let px = out.image.get_pixel(24, 31 - 8).0;
        assert!(
            px[1] > 100,
            "{}: green from v1 at (24, 8): {px:?}",
            p.backend
        );
        assert!(
            px[0] < 64,
            "{}: no red from the clipped v0: {px:?}",
            p.backend
        );
    }
}
