//! Framebuffer objects (`ff::framebuffer`, `pipeline::framebuffers`) on the emulated path
//! against Mesa's native path, on both headless backends: `framebuffer_objects.c` draws
//! into a texture through an FBO with a depth renderbuffer, into a depth texture through a
//! depth-only FBO, generates mipmaps from the rendered texture and shows both textures on
//! the window, then draws with the window's draw buffer NONE. Exact pixels are expected
//! (the same llvmpipe rasterises both; the textures are sampled NEAREST); the tolerance is
//! 1/255 on every pixel.

mod fidelity;
mod support;

use fidelity::{compare, probe_rgb, script_file, Frame};
use support::Tolerance;

const FRAME: Frame = Frame::new(64, 32);

#[test]
fn render_to_texture_depth_only_fbos_and_draw_buffer_none_match_native() {
    let tol = Tolerance {
        per_channel: 1,
        max_bad_pixels: 0,
    };
    let pairs = compare(
        "framebuffer_objects",
        &script_file("framebuffer_objects"),
        FRAME,
        tol,
    );
    for p in pairs {
        for out in [&p.emulate, &p.native] {
            // The rendered texture's clear colour shows on the left (top row first).
            probe_rgb(&out.image, 1, 1, [51, 51, 153], 1);
            // The draw with NONE left the background between the quads.
            probe_rgb(&out.image, 24, 2, [26, 26, 26], 1);
            // The depth map: the triangle's depths, nearer at its lower-left corner.
            let near = out.image.get_pixel(33, 30).0[0];
            let far = out.image.get_pixel(45, 20).0[0];
            assert!(near < far, "{}: depth {near} vs {far}", p.backend);
        }
    }
}

/// `blit_framebuffer.c`: glBlitFramebuffer between the window and an FBO — colour scaled
/// NEAREST and LINEAR, depth and stencil copied and used by a draw in the FBO, copies back
/// flipped, scissored and scaled up, a depth copy into the window — renders as Mesa's
/// native blits do. Both paths issue GL's own blit on the same llvmpipe, so the colour is
/// exact and the window's depth equal value for value.
#[test]
fn framebuffer_blits_match_native() {
    let exact = Tolerance {
        per_channel: 0,
        max_bad_pixels: 0,
    };
    let frame = Frame::new(64, 64).with_stencil();
    let pairs = compare(
        "blit_framebuffer",
        &script_file("blit_framebuffer"),
        frame,
        exact,
    );
    for p in pairs {
        assert_eq!(
            p.emulate.depth, p.native.depth,
            "{}: window depth",
            p.backend
        );
        for out in [&p.emulate, &p.native] {
            // Flipped in x: the FBO's (11, 8), the scene's triangle, lands at (20, 8); the
            // scissored copy leaves (2, 40) the scene's blue.
            probe_rgb(&out.image, 20, 8, [255, 0, 255], 0);
            probe_rgb(&out.image, 2, 40, [0, 0, 255], 0);
            // The quad drawn in the FBO under the copied stencil and depth shows cyan.
            let cyan = out
                .image
                .pixels()
                .filter(|q| q.0[..3] == [0, 255, 255])
                .count();
            assert!(cyan > 40, "{}: {cyan} cyan pixels", p.backend);
        }
    }
}
