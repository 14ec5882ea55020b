//! DITHER and glHint are state only (GL 1.5 §4.1.9, §5.6): both paths accept every hint
//! target and mode and the DITHER enable (the native path sends them to Mesa, which must
//! raise no GL error — the harness checks), and neither changes a picture: a smooth-shaded
//! quad with fog is drawn the same with the hints at NICEST and DITHER off as with the
//! defaults, exactly, on both paths. A hint target or mode Mesa rejected, or a hint that
//! changed the emulated code, fails it.

mod fidelity;
mod support;

use fidelity::{compare, ortho, Frame};
use support::Tolerance;

fn scene(state: &str) -> String {
    format!(
        "glViewport(0, 0, 16, 16);\n{}{state}glEnable(GL_FOG);\nglFogi(GL_FOG_MODE, GL_LINEAR);\n\
         glBegin(GL_QUADS);\nglColor3f(1, 0, 0);\nglVertex3f(0, 0, 0);\nglColor3f(0, 1, 0);\n\
         glVertex3f(16, 0, -0.5);\nglColor3f(0, 0, 1);\nglVertex3f(16, 16, -1);\nglColor3f(1, 1, 1);\n\
         glVertex3f(0, 16, -0.5);\nglEnd();\n",
        ortho(16, 16)
    )
}

#[test]
fn dither_and_hints_change_no_pixel() {
    let hints = [
        "GL_PERSPECTIVE_CORRECTION_HINT",
        "GL_POINT_SMOOTH_HINT",
        "GL_LINE_SMOOTH_HINT",
        "GL_POLYGON_SMOOTH_HINT",
        "GL_FOG_HINT",
    ];
    let mut state = "glDisable(GL_DITHER);\n".to_string();
    for h in hints {
        state += &format!(
            "glHint({h}, GL_FASTEST);\nglHint({h}, GL_DONT_CARE);\nglHint({h}, GL_NICEST);\n"
        );
    }
    let frame = Frame::new(16, 16);
    let plain = compare("hint-default", &scene(""), frame, Tolerance::EXACT);
    let hinted = compare("hint-nicest", &scene(&state), frame, Tolerance::EXACT);
    for (a, b) in plain.iter().zip(&hinted) {
        support::assert_images_match(
            &format!("hint-vs-default-{}", a.backend),
            &b.native.image,
            &a.native.image,
            Tolerance::EXACT,
        );
    }
}
