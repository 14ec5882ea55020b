//! The scissor test (GL 1.5 §4.1.2) and its hold on glClear (§4.2.3), emulated against
//! native on both headless backends, exact (every pixel is one of five flat colours).
//!
//! SCISSOR_TEST enabled before any glScissor restricts nothing (the box is still the whole
//! window, here the target: blue everywhere) — on the model and the emulated path by rule,
//! on the native path because the target sets the box when it is made: Mesa on a
//! surfaceless context starts it at (0, 0, 0, 0), which left the native image without its
//! blue until it did (measured: 308 of 512 pixels differed); a clear inside the box
//! (4, 2, 12, 8) is red there only; a full-window green quad inside (10, 6, 16, 8) is green
//! there only; after glDisable a white quad reaches the corner outside both boxes. A clear
//! that ignored the scissor would leave no blue, a draw that ignored it no red: both fail
//! the probes as well as the comparison.

mod fidelity;
mod support;

use fidelity::{compare, ortho, probe_gl, Frame};
use support::Tolerance;

const BLUE: [u8; 4] = [0, 0, 255, 255];
const RED: [u8; 4] = [255, 0, 0, 255];
const GREEN: [u8; 4] = [0, 255, 0, 255];
const WHITE: [u8; 4] = [255, 255, 255, 255];

#[test]
fn scissor_restricts_clears_and_draws() {
    let src = format!(
        "{}glEnable(GL_SCISSOR_TEST);
glClearColor(0, 0, 1, 1);
glClear(GL_COLOR_BUFFER_BIT);
glScissor(4, 2, 12, 8);
glClearColor(1, 0, 0, 1);
glClear(GL_COLOR_BUFFER_BIT);
glScissor(10, 6, 16, 8);
glColor3f(0, 1, 0);
glRectf(0, 0, 32, 16);
glDisable(GL_SCISSOR_TEST);
glColor3f(1, 1, 1);
glRectf(30, 0, 32, 2);
",
        ortho(32, 16)
    );
    for p in compare("scissor", &src, Frame::new(32, 16), Tolerance::EXACT) {
        for out in [&p.emulate, &p.native] {
            // (x, y) from the bottom-left.
            for (x, y, want) in [
                (0, 0, BLUE),
                (4, 2, RED),
                (9, 9, RED),
                (15, 5, RED),
                (16, 5, BLUE),
                (10, 6, GREEN),
                (25, 13, GREEN),
                (26, 13, BLUE),
                (25, 14, BLUE),
                (31, 15, BLUE),
                (31, 0, WHITE),
                (30, 1, WHITE),
            ] {
                probe_gl(&out.image, x, y, want, 0);
            }
        }
    }
}
