//! GL 1.x's CLAMP wrap (GL 1.5 §3.8.7) against Mesa's native path: the coordinate is
//! clamped to [0, 1] before the filter, so LINEAR blends the edge texel half and half with
//! the border colour wherever s ≥ 1 or s ≤ 0, and NEAREST takes the edge texel there (never
//! the border). Core GL has no CLAMP; the emulated path clamps in the program and samples
//! with CLAMP_TO_BORDER, its level of detail from the unclamped coordinates.
//!
//! Each case draws a 4×1 texture (blue, green, white, cyan; border red) over a 32×4 frame,
//! s from −0.5 to 1.5 (magnified) or from −20 to 20 (minified), under the four pairs of
//! MIN_FILTER and MAG_FILTER. Measured on Mesa 22.3.6 llvmpipe: magnified LINEAR gives
//! (128, 0, 128) left of s = 0 (half blue, half red) and (128, 128, 128) right of s = 1;
//! NEAREST gives blue and cyan there; with MIN_FILTER NEAREST and MAG_FILTER LINEAR the
//! magnified quad blends and the minified one does not. Paths compared exactly, and the
//! first and last pixels of each row against those values. On the starting commit the
//! emulated path read the border alone outside [0, 1] (red).

mod fidelity;
mod support;

use fidelity::{compare, Frame};
use support::Tolerance;

const W: u32 = 32;
const H: u32 = 4;

const BLEND_LEFT: [u8; 4] = [128, 0, 128, 255];
const BLEND_RIGHT: [u8; 4] = [128, 128, 128, 255];
const BLUE: [u8; 4] = [0, 0, 255, 255];
const CYAN: [u8; 4] = [0, 255, 255, 255];

/// The texture, CLAMP on s and t, REPLACE, and a quad over the frame with s from `s0` to
/// `s1` (t = 0.5) under `min`/`mag`.
fn source(min: &str, mag: &str, s0: f32, s1: f32) -> String {
    format!(
        "glClearColor(0, 0, 0, 1);
glClear(GL_COLOR_BUFFER_BIT);
glBindTexture(GL_TEXTURE_2D, 1);
glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, (GLubyte[]){{0, 0, 255, 0, 255, 0, 255, 255, 255, 0, 255, 255}});
glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, (GLfloat[]){{1, 0, 0, 1}});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, {min});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, {mag});
glEnable(GL_TEXTURE_2D);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
glBegin(GL_QUADS);
glTexCoord2f({s0}, 0.5); glVertex2f(-1, -1);
glTexCoord2f({s1}, 0.5); glVertex2f(1, -1);
glTexCoord2f({s1}, 0.5); glVertex2f(1, 1);
glTexCoord2f({s0}, 0.5); glVertex2f(-1, 1);
glEnd();
"
    )
}

/// Compares the paths exactly and the row's ends with `ends`.
fn case(name: &str, src: &str, ends: ([u8; 4], [u8; 4])) {
    for p in compare(name, src, Frame::new(W, H), Tolerance::EXACT) {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            let got = (out.image.get_pixel(0, 0).0, out.image.get_pixel(W - 1, 0).0);
            assert_eq!(got, ends, "{name} {} {path}", p.backend);
        }
    }
}

#[test]
fn linear_blends_the_edge_texel_with_the_border() {
    case(
        "clamp-linear",
        &source("GL_LINEAR", "GL_LINEAR", -0.5, 1.5),
        (BLEND_LEFT, BLEND_RIGHT),
    );
}

#[test]
fn nearest_takes_the_edge_texel() {
    case(
        "clamp-nearest",
        &source("GL_NEAREST", "GL_NEAREST", -0.5, 1.5),
        (BLUE, CYAN),
    );
}

/// MIN_FILTER NEAREST, MAG_FILTER LINEAR: magnified fragments blend, minified ones take
/// the edge texel; and the other way round.
#[test]
fn mixed_filters_follow_the_fragments_own_filter() {
    case(
        "clamp-min-nearest-magnified",
        &source("GL_NEAREST", "GL_LINEAR", -0.5, 1.5),
        (BLEND_LEFT, BLEND_RIGHT),
    );
    case(
        "clamp-min-nearest-minified",
        &source("GL_NEAREST", "GL_LINEAR", -20.0, 20.0),
        (BLUE, CYAN),
    );
    case(
        "clamp-min-linear-magnified",
        &source("GL_LINEAR", "GL_NEAREST", -0.5, 1.5),
        (BLUE, CYAN),
    );
    case(
        "clamp-min-linear-minified",
        &source("GL_LINEAR", "GL_NEAREST", -20.0, 20.0),
        (BLEND_LEFT, BLEND_RIGHT),
    );
}
