//! Texture completeness (GL 1.5 §3.8.10) against Mesa's native path: an incomplete texture
//! disables its unit (§3.8.15), so the fragment gets the colour the unit receives, as if
//! texturing were off for it. Each case draws one 4×4 quad with primary colour red
//! (1, 0, 0, 1) through REPLACE of a texture whose level 0 is green (level 1 blue, level 2
//! white, level 3 grey): a complete texture shows green (the quad magnifies, so level 0 is
//! sampled whatever the MIN_FILTER), an incomplete one red. Paths compared exactly, and
//! each against its verdict exactly.
//!
//! Measured on Mesa 22.3.6 llvmpipe (EGL and OSMesa), the native path, and asserted here
//! on both paths: level 0 alone under the default NEAREST_MIPMAP_LINEAR, a chain with a
//! level of the wrong size, a missing level, a level in another internal format, a chain
//! that stops before 1×1, a texture object never given an image, and a depth texture made
//! by CopyTexImage2D without a MIN_FILTER are incomplete (red); a full chain, level 0 alone
//! under LINEAR or NEAREST, a 1D full chain, and GENERATE_MIPMAP set before the level-0
//! image are complete (green). On the starting commit the emulated path sampled every
//! texture with a level 0 (green in all the incomplete cases).

mod fidelity;
mod support;

use fidelity::{compare, ortho, Frame};
use support::Tolerance;

const RED: [u8; 4] = [255, 0, 0, 255];
const GREEN: [u8; 4] = [0, 255, 0, 255];

/// The texels of level `level`: green, blue, white, grey, then black (RGBA bytes).
fn texel(level: u32) -> [u8; 4] {
    match level {
        0 => GREEN,
        1 => [0, 0, 255, 255],
        2 => [255, 255, 255, 255],
        3 => [128, 128, 128, 255],
        _ => [0, 0, 0, 255],
    }
}

/// glTexImage2D of a w×h level in `texel(level)`, stored as `internal`.
fn image_2d(level: u32, internal: &str, w: u32, h: u32) -> String {
    image_2d_in(level, texel(level), internal, w, h)
}

/// glTexImage2D of a w×h level in one colour `t`.
fn image_2d_in(level: u32, t: [u8; 4], internal: &str, w: u32, h: u32) -> String {
    let bytes: Vec<String> = (0..w * h).flat_map(|_| t.map(|b| b.to_string())).collect();
    format!(
        "glTexImage2D(GL_TEXTURE_2D, {level}, {internal}, {w}, {h}, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){{{}}});\n",
        bytes.join(", ")
    )
}

/// A 2D chain from 4×4 to 1×1 (levels 0, 1, 2) with `patch` applied per level:
/// `patch(level)` gives the internal format and size, or `None` to leave the level out.
fn chain(patch: impl Fn(u32) -> Option<(&'static str, u32, u32)>) -> String {
    (0..3)
        .filter_map(|l| patch(l).map(|(f, w, h)| image_2d(l, f, w, h)))
        .collect()
}

fn full(l: u32) -> Option<(&'static str, u32, u32)> {
    let s = 4 >> l;
    Some(("GL_RGBA8", s, s))
}

/// The frame: clear black, ortho 4×4, red primary colour, REPLACE.
fn frame_start() -> String {
    format!(
        "glClearColor(0, 0, 0, 1);\nglClear(GL_COLOR_BUFFER_BIT);\n{}glColor4f(1, 0, 0, 1);\nglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);\n",
        ortho(4, 4)
    )
}

const QUAD: &str = "glBegin(GL_QUADS);
glTexCoord2f(0, 0); glVertex2f(0, 0);
glTexCoord2f(1, 0); glVertex2f(4, 0);
glTexCoord2f(1, 1); glVertex2f(4, 4);
glTexCoord2f(0, 1); glVertex2f(0, 4);
glEnd();
";

/// One 2D case: bind texture 1, run `setup`, enable TEXTURE_2D, draw, then compare the
/// paths exactly and every pixel of both with `expected`.
fn case_2d(name: &str, setup: &str, expected: [u8; 4]) {
    let src = format!(
        "{}glBindTexture(GL_TEXTURE_2D, 1);\n{setup}glEnable(GL_TEXTURE_2D);\n{QUAD}",
        frame_start()
    );
    check(name, &src, expected);
}

fn check(name: &str, src: &str, expected: [u8; 4]) {
    for p in compare(name, src, Frame::new(4, 4), Tolerance::EXACT) {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            for (x, y, px) in out.image.enumerate_pixels() {
                assert_eq!(
                    px.0, expected,
                    "{name} {} {path} at ({x},{y}): {:?}",
                    p.backend, px.0
                );
            }
        }
    }
}

/// Level 0 only, MIN_FILTER left at NEAREST_MIPMAP_LINEAR: incomplete, red.
#[test]
fn level_0_only_with_the_default_filter_is_incomplete() {
    case_2d(
        "complete-level0-default",
        &image_2d(0, "GL_RGBA8", 4, 4),
        RED,
    );
}

/// Level 0 only with MIN_FILTER LINEAR (or NEAREST): complete, green.
#[test]
fn level_0_only_with_a_non_mipmap_filter_is_complete() {
    for filter in ["GL_LINEAR", "GL_NEAREST"] {
        case_2d(
            &format!("complete-level0-{filter}"),
            &format!(
                "{}glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, {filter});\n",
                image_2d(0, "GL_RGBA8", 4, 4)
            ),
            GREEN,
        );
    }
}

/// 4×4, 2×2, 1×1 under the default filter: complete, green; and minified to one pixel the
/// quad shows a deeper level (which one is the filter's business: the paths agree).
#[test]
fn full_mip_chain_is_complete() {
    case_2d("complete-full-chain", &chain(full), GREEN);
    let src = format!(
        "{}glBindTexture(GL_TEXTURE_2D, 1);\n{}glEnable(GL_TEXTURE_2D);\nglBegin(GL_QUADS);\nglTexCoord2f(0, 0); glVertex2f(0, 0);\nglTexCoord2f(1, 0); glVertex2f(1, 0);\nglTexCoord2f(1, 1); glVertex2f(1, 1);\nglTexCoord2f(0, 1); glVertex2f(0, 1);\nglEnd();\n",
        frame_start(),
        chain(full)
    );
    for p in compare(
        "complete-full-chain-minified",
        &src,
        Frame::new(4, 4),
        Tolerance::EXACT,
    ) {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            let px = out.image.get_pixel(0, 3).0;
            assert!(
                px != RED && px != GREEN,
                "{} {path}: the minified quad shows {px:?}, not a deeper level",
                p.backend
            );
        }
    }
}

/// Level 1 is 2×1 instead of 2×2: incomplete, red.
#[test]
fn chain_with_a_wrong_size_level_is_incomplete() {
    let setup = chain(|l| {
        if l == 1 {
            Some(("GL_RGBA8", 2, 1))
        } else {
            full(l)
        }
    });
    case_2d("complete-wrong-size", &setup, RED);
}

/// Level 1 left out (levels 0 and 2 given): incomplete, red. Levels 0 and 1 only (no
/// 1×1): incomplete, red.
#[test]
fn chain_with_a_missing_level_is_incomplete() {
    let setup = chain(|l| if l == 1 { None } else { full(l) });
    case_2d("complete-missing-level", &setup, RED);
    let setup = chain(|l| if l == 2 { None } else { full(l) });
    case_2d("complete-no-1x1", &setup, RED);
}

/// Level 2 in RGB8 while levels 0 and 1 are RGBA8: incomplete, red.
#[test]
fn chain_with_mismatched_formats_is_incomplete() {
    let setup = chain(|l| {
        if l == 2 {
            Some(("GL_RGB8", 1, 1))
        } else {
            full(l)
        }
    });
    case_2d("complete-format-differs", &setup, RED);
}

/// TEXTURE_2D enabled on a unit whose bound object (the default texture 0, or a fresh
/// name) never got an image: incomplete, red.
#[test]
fn texture_without_an_image_is_incomplete() {
    for (name, bind) in [("default", 0), ("fresh", 7)] {
        let src = format!(
            "{}glBindTexture(GL_TEXTURE_2D, {bind});\nglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);\nglEnable(GL_TEXTURE_2D);\n{QUAD}",
            frame_start()
        );
        check(&format!("complete-no-image-{name}"), &src, RED);
    }
}

/// GENERATE_MIPMAP TRUE before the level-0 image: GL derives levels 1 and 2, so the default
/// filter finds a complete chain, green. Set after the image, nothing is generated until
/// the base level changes again: incomplete, red.
#[test]
fn generate_mipmap_completes_the_chain() {
    let on = "glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);\n";
    let level0 = image_2d(0, "GL_RGBA8", 4, 4);
    case_2d("complete-generate-before", &format!("{on}{level0}"), GREEN);
    case_2d("complete-generate-after", &format!("{level0}{on}"), RED);
}

/// 1D: level 0 alone under the default filter is incomplete (red); the chain 4, 2, 1 is
/// complete (green).
#[test]
fn one_d_textures_follow_the_same_rules() {
    let level = |l: u32, w: u32| {
        let t = texel(l);
        let bytes: Vec<String> = (0..w).flat_map(|_| t.map(|b| b.to_string())).collect();
        format!(
            "glTexImage1D(GL_TEXTURE_1D, {l}, GL_RGBA8, {w}, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){{{}}});\n",
            bytes.join(", ")
        )
    };
    for (name, images, expected) in [
        ("complete-1d-level0", level(0, 4), RED),
        (
            "complete-1d-chain",
            [level(0, 4), level(1, 2), level(2, 1)].concat(),
            GREEN,
        ),
    ] {
        let src = format!(
            "{}glBindTexture(GL_TEXTURE_1D, 1);\n{images}glEnable(GL_TEXTURE_1D);\n{QUAD}",
            frame_start()
        );
        check(name, &src, expected);
    }
}

/// Unit 1 incomplete behind a complete unit 0: unit 1 passes unit 0's result on (green
/// from unit 0's REPLACE, not red and not unit 1's blue).
#[test]
fn incomplete_unit_passes_the_previous_colour_on() {
    let src = format!(
        "{}glActiveTexture(GL_TEXTURE0);\nglBindTexture(GL_TEXTURE_2D, 1);\n{}glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);\nglEnable(GL_TEXTURE_2D);\nglActiveTexture(GL_TEXTURE1);\nglBindTexture(GL_TEXTURE_2D, 2);\n{}glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);\nglEnable(GL_TEXTURE_2D);\nglMultiTexCoord2f(GL_TEXTURE1, 0.5, 0.5);\n{QUAD}",
        frame_start(),
        image_2d(0, "GL_RGBA8", 4, 4),
        image_2d_in(0, texel(1), "GL_RGBA8", 4, 4),
    );
    check("complete-second-unit", &src, GREEN);
}

/// The copied depth texture without a MIN_FILTER: CopyTexImage2D(DEPTH_COMPONENT) of a depth
/// buffer cleared to 0.25, compare LEQUAL against r = 0.5 (fails: white would become black)
/// under REPLACE. Incomplete under NEAREST_MIPMAP_LINEAR, so the draw is untextured: red.
/// With MIN_FILTER NEAREST it is complete and the compare shows: black (fail, LUMINANCE).
#[test]
fn copied_depth_texture_without_min_filter_is_incomplete() {
    for (name, filter, expected) in [
        ("complete-copied-depth-default", "", RED),
        (
            "complete-copied-depth-nearest",
            "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);\n",
            [0, 0, 0, 255],
        ),
    ] {
        let src = format!(
            "{}glClearDepth(0.25);\nglClear(GL_DEPTH_BUFFER_BIT);\nglBindTexture(GL_TEXTURE_2D, 1);\nglCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, 4, 4, 0);\n{filter}glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);\nglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);\nglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);\nglEnable(GL_TEXTURE_2D);\nglBegin(GL_QUADS);\nglTexCoord3f(0, 0, 0.5); glVertex2f(0, 0);\nglTexCoord3f(1, 0, 0.5); glVertex2f(4, 0);\nglTexCoord3f(1, 1, 0.5); glVertex2f(4, 4);\nglTexCoord3f(0, 1, 0.5); glVertex2f(0, 4);\nglEnd();\n",
            frame_start()
        );
        check(name, &src, expected);
    }
}

/// TEXTURE_MAX_LEVEL 0 makes level 0 alone a complete mipmap texture under the default
/// filter (the common idiom for a texture without mipmaps): green.
#[test]
fn max_level_0_completes_a_lone_level_0() {
    case_2d(
        "complete-max-level-0",
        &format!(
            "{}glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);\n",
            image_2d(0, "GL_RGBA8", 4, 4)
        ),
        GREEN,
    );
}

/// TEXTURE_BASE_LEVEL 1: level 1 (blue, 2×2) is the base. Without level 0 the texture is
/// complete under NEAREST, incomplete under a mipmap filter until level 2 (1×1) is given.
#[test]
fn base_level_1_is_the_base() {
    let blue = texel(1);
    let base = "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);\n";
    let nearest = "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);\n";
    let level1 = image_2d(1, "GL_RGBA8", 2, 2);
    case_2d(
        "complete-base-1-nearest",
        &format!("{level1}{base}{nearest}"),
        blue,
    );
    case_2d(
        "complete-base-1-mipmap-short",
        &format!("{level1}{base}"),
        RED,
    );
    let level2 = image_2d(2, "GL_RGBA8", 1, 1);
    case_2d(
        "complete-base-1-mipmap",
        &format!("{level1}{level2}{base}"),
        blue,
    );
}

/// BASE_LEVEL above MAX_LEVEL under a mipmap filter: incomplete, red. (Under NEAREST Mesa
/// 22.3.6 samples what its state tracker's history leaves: zero texels on a texture never
/// drawn complete — (0, 0, 0, 0) here, BASE_LEVEL 1 and MAX_LEVEL 0 over this chain — the
/// base level on one drawn complete before, and a mixture no rule gives over other chains
/// ((0x70, 0, 0x8f) measured over a green, blue, white, grey chain); the model calls it
/// incomplete; not compared.)
#[test]
fn base_level_above_max_level_is_incomplete() {
    case_2d(
        "complete-base-above-max",
        &format!(
            "{}glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);\nglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);\n",
            chain(full)
        ),
        RED,
    );
}

/// A 6×6 image with a border of 1 (blue border texels, green interior) is its 4×4
/// interior with border 0 (`ff::texture_border`, as Mesa strips it): complete under
/// NEAREST, green on both paths, no border texel drawn.
#[test]
fn a_bordered_image_is_its_interior() {
    let texels: Vec<String> = (0..36)
        .flat_map(|i: u32| {
            let (x, y) = (i % 6, i / 6);
            let edge = x == 0 || y == 0 || x == 5 || y == 5;
            if edge { texel(1) } else { GREEN }.map(|b| b.to_string())
        })
        .collect();
    case_2d(
        "complete-bordered-image",
        &format!(
            "glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){{{}}});\nglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);\n",
            texels.join(", ")
        ),
        GREEN,
    );
}

/// Minified to one pixel, MAX_LEVEL and the LOD clamps choose the level: the paths agree
/// exactly, and the level is the one the parameters name — MAX_LEVEL 1 and MAX_LOD 1 stop
/// at level 1 (blue); MIN_LOD 2 reads level 2 (white) even magnified; a unit LOD bias of 1
/// reads level 1 where the quad is not minified.
#[test]
fn level_and_lod_clamps_choose_the_level() {
    let nearest_mipmap =
        "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);\n";
    let one_pixel = "glBegin(GL_QUADS);
glTexCoord2f(0, 0); glVertex2f(0, 0);
glTexCoord2f(4, 0); glVertex2f(4, 0);
glTexCoord2f(4, 4); glVertex2f(4, 4);
glTexCoord2f(0, 4); glVertex2f(0, 4);
glEnd();
";
    for (name, param, expected, quad) in [
        (
            "lod-max-level-1",
            "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);\n",
            texel(1),
            one_pixel,
        ),
        (
            "lod-max-lod-1",
            "glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1.0);\n",
            texel(1),
            one_pixel,
        ),
        (
            "lod-min-lod-2",
            "glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 2.0);\n",
            texel(2),
            QUAD,
        ),
        // GL 1.4's unit LOD bias: the 4×4 texture over 4×4 pixels (λ = 0, magnified) is
        // read at λ = 1, level 1, under a bias of 1.
        (
            "lod-unit-bias-1",
            "glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1.0);\n",
            texel(1),
            QUAD,
        ),
        // A NaN bias makes λ NaN, which Mesa's sampler takes as magnification: level 0
        // where the quad is minified to level 2 (measured through OSMesa).
        (
            "lod-unit-bias-nan",
            "glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, NAN);\n",
            texel(0),
            one_pixel,
        ),
    ] {
        let src = format!(
            "{}glBindTexture(GL_TEXTURE_2D, 1);\n{}{nearest_mipmap}{param}glEnable(GL_TEXTURE_2D);\n{quad}",
            frame_start(),
            chain(full)
        );
        check(name, &src, expected);
    }
}

/// GENERATE_MIPMAP derives the levels above the base level when the base level changes,
/// and nothing when another level does: with BASE_LEVEL 1, re-specifying level 1 completes
/// the chain (blue); specifying level 0 leaves it incomplete (red).
#[test]
fn generate_mipmap_follows_the_base_level() {
    let setup = "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);\nglTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);\n";
    case_2d(
        "complete-generate-base-1",
        &format!("{setup}{}", image_2d(1, "GL_RGBA8", 2, 2)),
        texel(1),
    );
    case_2d(
        "complete-generate-level-0-base-1",
        &format!("{setup}{}", image_2d(0, "GL_RGBA8", 4, 4)),
        RED,
    );
}
