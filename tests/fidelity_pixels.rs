//! Pixel rectangles (GL 1.5 §3.6.4 glDrawPixels, §3.7 glBitmap, §4.3.3 glCopyPixels) on the
//! emulated path against Mesa's native path, on both headless backends.
//!
//! Tolerances: images within 3/255 per channel (piglit's 3/2^bits) on all but 1% of the
//! pixels where values pass through arithmetic (transfer scale and bias, blending, fog,
//! texturing); exactly (0/255, no pixel) where a rectangle only copies unorm8 values to the
//! colour buffer, since its placement rule — which pixel centres a rectangle covers, and
//! which image pixel each one reads — is exact.

mod fidelity;
mod support;

use fidelity::{compare, ortho, probe_gl, Frame};
use support::Tolerance;

const FRAME: Frame = Frame::new(64, 48);

const EXACT: Tolerance = Tolerance {
    per_channel: 0,
    max_bad_pixels: 0,
};

fn close() -> Tolerance {
    Tolerance {
        per_channel: 3,
        max_bad_pixels: (FRAME.width * FRAME.height / 100) as usize,
    }
}

/// The script's opening: viewport, clear to dark grey, 2D projection, and images read
/// with UNPACK_ALIGNMENT 1 (their literals are tightly packed; tests/c/pixels.c draws at
/// the default 4).
fn opening() -> String {
    format!(
        "glPixelStorei(GL_UNPACK_ALIGNMENT, 1);\nglViewport(0, 0, {w}, {h});\nglClearColor(0.1, 0.1, 0.1, 1);\nglClearDepth(1);\nglClearStencil(0);\nglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);\n{}",
        ortho(FRAME.width, FRAME.height),
        w = FRAME.width,
        h = FRAME.height
    )
}

/// The transfer also applies to glReadPixels (§4.3.2), which reads the frames compared
/// here on the native path: a script that sets it puts it back before it ends.
///
/// A `w`×`h` image of `components` bytes per pixel: a gradient with a marked corner, so a
/// flip or an offset of one pixel changes it.
fn gradient(w: usize, h: usize, components: usize) -> Vec<u8> {
    let mut out = Vec::new();
    for y in 0..h {
        for x in 0..w {
            for c in 0..components {
                let v = match c {
                    0 => x * 255 / w.max(2).saturating_sub(1).max(1),
                    1 => y * 255 / h.max(2).saturating_sub(1).max(1),
                    2 => ((x + y) * 37) % 256,
                    _ => 255 - ((x * 13 + y * 7) % 200),
                };
                out.push(if x == 0 && y == 0 {
                    255
                } else {
                    v.min(255) as u8
                });
            }
        }
    }
    out
}

fn ubytes(v: &[u8]) -> String {
    let items: Vec<String> = v.iter().map(|b| b.to_string()).collect();
    format!("(GLubyte[]){{{}}}", items.join(", "))
}

#[test]
fn draw_pixels_rgba_ubyte_unzoomed_and_flipped_is_exact() {
    let img = ubytes(&gradient(7, 5, 4));
    let src = format!(
        "{}glRasterPos2i(3, 4);\nglDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glRasterPos2f(20.4, 30.6);\nglPixelZoom(1, -1);\nglDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glPixelZoom(2, 3);\nglRasterPos2f(40.5, 2.5);\nglDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n",
        opening()
    );
    let pairs = compare("draw-pixels-rgba", &src, FRAME, EXACT);
    for p in pairs {
        // The marked corner (image pixel (0, 0), white) at the raster position.
        probe_gl(&p.native.image, 3, 4, [255, 255, 255, 255], 0);
        probe_gl(&p.emulate.image, 3, 4, [255, 255, 255, 255], 0);
    }
}

fn floats(v: &[f32]) -> String {
    let items: Vec<String> = v.iter().map(|f| format!("{f:?}")).collect();
    format!("(GLfloat[]){{{}}}", items.join(", "))
}

/// Every colour format with every type, each at its own place: the conversion of Tables
/// 2.9 and 3.8 (unorm c/(2ⁿ − 1), L → RGB, A alone, RGB's alpha 1, R, G or B alone).
#[test]
fn every_colour_format_and_type_matches() {
    let formats = [
        ("GL_RGBA", 4),
        ("GL_RGB", 3),
        ("GL_LUMINANCE", 1),
        ("GL_LUMINANCE_ALPHA", 2),
        ("GL_ALPHA", 1),
        ("GL_RED", 1),
        ("GL_GREEN", 1),
        ("GL_BLUE", 1),
    ];
    let (w, h) = (5usize, 4usize);
    let mut src = opening();
    src.push_str("glEnable(GL_BLEND);\nglBlendFunc(GL_ONE, GL_ZERO);\n");
    for (i, (format, k)) in formats.iter().enumerate() {
        let bytes = gradient(w, h, *k);
        let types = [
            ("GL_UNSIGNED_BYTE", ubytes(&bytes)),
            (
                "GL_UNSIGNED_SHORT",
                format!(
                    "(GLushort[]){{{}}}",
                    bytes
                        .iter()
                        .map(|b| (u32::from(*b) * 257).to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            ),
            (
                "GL_UNSIGNED_INT",
                format!(
                    "(GLuint[]){{{}}}",
                    bytes
                        .iter()
                        .map(|b| (u64::from(*b) * 16843009).to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            ),
            (
                "GL_FLOAT",
                floats(
                    &bytes
                        .iter()
                        .map(|b| f32::from(*b) / 255.0)
                        .collect::<Vec<_>>(),
                ),
            ),
        ];
        for (j, (ty, data)) in types.iter().enumerate() {
            src.push_str(&format!(
                "glRasterPos2i({}, {});\nglDrawPixels({w}, {h}, {format}, {ty}, {data});\n",
                2 + 7 * j,
                2 + 5 * i
            ));
        }
    }
    compare("draw-pixels-formats", &src, FRAME, EXACT);
}

/// glPixelTransfer scale and bias on every component (clamped after), with a zoom of 1.5
/// (pixel centres on image-pixel boundaries round alike on both paths or within 1%).
#[test]
fn transfer_scale_bias_and_fractional_zoom_match() {
    let img = ubytes(&gradient(8, 6, 4));
    let src = format!(
        "{}glPixelTransferf(GL_RED_SCALE, 1.5);\nglPixelTransferf(GL_GREEN_BIAS, -0.25);\n\
         glPixelTransferf(GL_BLUE_SCALE, 0.5);\nglPixelTransferf(GL_BLUE_BIAS, 0.3);\n\
         glPixelTransferf(GL_ALPHA_SCALE, 0);\nglPixelTransferf(GL_ALPHA_BIAS, 0.75);\n\
         glRasterPos2i(2, 2);\nglDrawPixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glPixelZoom(1.5, 2.5);\nglRasterPos2i(20, 10);\nglDrawPixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glPixelZoom(-2, -1.5);\nglRasterPos2i(60, 40);\nglDrawPixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glPixelTransferf(GL_RED_SCALE, 1);\nglPixelTransferf(GL_GREEN_BIAS, 0);\nglPixelTransferf(GL_BLUE_SCALE, 1);\n\
         glPixelTransferf(GL_BLUE_BIAS, 0);\nglPixelTransferf(GL_ALPHA_SCALE, 1);\nglPixelTransferf(GL_ALPHA_BIAS, 0);\n",
        opening()
    );
    let pairs = compare("draw-pixels-transfer", &src, FRAME, close());
    for p in pairs {
        // Alpha = 0·a + 0.75 everywhere in the first image; the white corner: red 1.5 → 1,
        // blue 0.5 + 0.3.
        let px = p.native.image.get_pixel(2, FRAME.height - 1 - 2).0;
        assert_eq!(px, [255, 191, 204, 191], "native corner");
        let px = p.emulate.image.get_pixel(2, FRAME.height - 1 - 2).0;
        assert_eq!(px, [255, 191, 204, 191], "emulated corner");
    }
}

/// Zooms whose pixel centres fall on boundaries between image pixels — 0.5, 0.3, 0.7,
/// 2.5 — draw and copy the image pixels Mesa's native path draws, exactly (Mesa's own
/// rounding decides; `pipeline::emulate::pixel_fan`).
#[test]
fn zoom_ties_pick_the_native_paths_image_pixels() {
    let img = ubytes(&gradient(12, 10, 4));
    let src = format!(
        "{}glPixelZoom(0.5, 0.5);\nglRasterPos2i(1, 1);\nglDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glPixelZoom(0.3, 0.7);\nglRasterPos2i(10, 2);\nglDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glPixelZoom(2.5, -0.5);\nglRasterPos2i(20, 46);\nglDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glPixelZoom(0.5, 1.5);\nglRasterPos2i(2, 20);\nglCopyPixels(20, 36, 12, 10, GL_COLOR);\n",
        opening()
    );
    compare("zoom-ties", &src, FRAME, EXACT);
}

/// Fragments of an image go through texturing (raster texture coordinates), fog (raster
/// distance), the alpha test and blending as Mesa draws them.
#[test]
fn images_are_textured_fogged_alpha_tested_and_blended() {
    let img = ubytes(&gradient(10, 8, 4));
    let tex = ubytes(&[
        255, 128, 0, 255, 0, 255, 128, 255, 64, 64, 255, 255, 255, 255, 255, 255,
    ]);
    let src = format!(
        "{}glBindTexture(GL_TEXTURE_2D, 1);\n\
         glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, {tex});\n\
         glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);\n\
         glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);\n\
         glEnable(GL_TEXTURE_2D);\nglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);\n\
         glTexCoord2f(0.75, 0.25);\nglRasterPos2i(2, 2);\nglDrawPixels(10, 8, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glDisable(GL_TEXTURE_2D);\n\
         glEnable(GL_ALPHA_TEST);\nglAlphaFunc(GL_GREATER, 0.5);\n\
         glRasterPos2i(16, 2);\nglDrawPixels(10, 8, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glDisable(GL_ALPHA_TEST);\nglEnable(GL_BLEND);\nglBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);\n\
         glRasterPos2i(30, 2);\nglDrawPixels(10, 8, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glDisable(GL_BLEND);\n\
         glEnable(GL_FOG);\nglFogi(GL_FOG_MODE, GL_LINEAR);\nglFogf(GL_FOG_START, -1);\nglFogf(GL_FOG_END, 1);\n\
         glFogfv(GL_FOG_COLOR, (GLfloat[]){{0, 0, 1, 1}});\n\
         glRasterPos3f(44, 2, -0.5);\nglDrawPixels(10, 8, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n",
        opening()
    );
    compare("draw-pixels-fragment-ops", &src, FRAME, close());
}

/// A glReadPixels: it makes Mesa draw the bitmaps it holds back (see
/// `mesa_draws_held_bitmaps_with_the_state_at_their_flush`).
const FLUSH: &str = "glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, readback_9);\n";

/// Bitmaps: the raster colour at set bits (MSB first, rows padded in the script's bytes
/// as the model holds them), moved by (xmove, ymove) after each; NULL moves only; alpha
/// test and blending apply to the raster colour; an invalid raster position draws nothing
/// and does not move.
#[test]
fn bitmaps_draw_the_raster_colour_and_move() {
    // An 11×6 glyph: a frame with a diagonal.
    let mut rows = Vec::new();
    for y in 0..6 {
        let mut bits = 0u16;
        for x in 0..11 {
            if y == 0 || y == 5 || x == 0 || x == 10 || x == y * 2 {
                bits |= 1 << (15 - x);
            }
        }
        rows.extend(bits.to_be_bytes());
    }
    let glyph = ubytes(&rows);
    let src = format!(
        "{}glColor3f(1, 0.5, 0.25);\nglRasterPos2f(3.5, 3.25);\n\
         glBitmap(11, 6, 0, 0, 13, 0, {glyph});\nglBitmap(11, 6, 1.5, -2, 13, 1.5, {glyph});\n\
         glColor4f(0, 1, 0, 0.25);\nglRasterPos2i(3, 20);\n\
         glBitmap(0, 0, 0, 0, 20, 0, NULL);\n\
         glEnable(GL_BLEND);\nglBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);\n\
         glBitmap(11, 6, 0, 0, 13, 0, {glyph});\n{FLUSH}glDisable(GL_BLEND);\n\
         glEnable(GL_ALPHA_TEST);\nglAlphaFunc(GL_GREATER, 0.5);\nglBitmap(11, 6, 0, 0, 13, 0, {glyph});\n\
         {FLUSH}glDisable(GL_ALPHA_TEST);\n\
         glColor3f(1, 1, 1);\nglRasterPos2i(200, 20);\nglBitmap(11, 6, 0, 0, 13, 0, {glyph});\n\
         glWindowPos2i(40, 30);\nglColor3f(0, 0, 1);\nglBitmap(11, 6, 0, 0, 0, 0, {glyph});\n",
        opening()
    );
    let pairs = compare("bitmap", &src, FRAME, EXACT);
    for p in pairs {
        for img in [&p.native.image, &p.emulate.image] {
            // ⌊3.5⌋ = 3, ⌊3.25⌋ = 3: the glyph's corner bit in the raster colour.
            probe_gl(img, 3, 3, [255, 128, 64, 255], 1);
            // The glyph drawn from the window position, in the colour current at
            // glWindowPos (white; the blue set after it is not the raster colour).
            probe_gl(img, 40, 30, [255, 255, 255, 255], 0);
            // Blended green at 0.25 over the background 0.1: (0.1·0.75, 0.25 + 0.075, …).
            probe_gl(img, 23, 20, [19, 83, 19, 207], 1);
            // The alpha-tested glyph (alpha 0.25 fails GREATER 0.5) left the background.
            probe_gl(img, 36, 20, [26, 26, 26, 255], 0);
        }
    }
}

/// Mesa deviation, pinned: Mesa 22.3 holds glBitmap's fragments back (its bitmap cache)
/// and draws them later — at a glReadPixels, or a bitmap of another raster colour —
/// with the per-fragment state current *then*. Measured: after a NULL glBitmap move, a
/// blended bitmap, then an alpha-tested one of the same raster colour, then a bitmap of
/// another colour once both are off: the blended one is drawn unblended (the alpha test
/// is applied).
/// GL 1.5 §3.7 draws with the state at the call, which the emulated path follows.
#[test]
fn mesa_draws_held_bitmaps_with_the_state_at_their_flush() {
    let src = format!(
        "{}glColor4f(0, 1, 0, 0.25);\nglRasterPos2i(3, 10);\nglBitmap(0, 0, 0, 0, 7, 0, NULL);\n\
         glEnable(GL_BLEND);\nglBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);\n\
         glBitmap(8, 1, 0, 0, 0, 0, (GLubyte[]){{255}});\nglDisable(GL_BLEND);\n\
         glEnable(GL_ALPHA_TEST);\nglAlphaFunc(GL_GREATER, 0.5);\nglBitmap(8, 1, 0, 0, 0, 1, (GLubyte[]){{255}});\n\
         glDisable(GL_ALPHA_TEST);\nglColor3f(1, 1, 1);\nglRasterPos2i(30, 30);\n\
         glBitmap(8, 1, 0, 0, 0, 0, (GLubyte[]){{255}});\n",
        opening()
    );
    for p in fidelity::run_both(&src, FRAME) {
        // GL: 0.25·(0, 1, 0) + 0.75·0.1 on RGB; the alpha-tested row not drawn.
        probe_gl(&p.emulate.image, 12, 10, [19, 83, 19, 207], 1);
        probe_gl(&p.emulate.image, 12, 11, [26, 26, 26, 255], 0);
        // Mesa: the raster colour, unblended (the alpha test it applied).
        probe_gl(&p.native.image, 12, 10, [0, 255, 0, 64], 0);
        probe_gl(&p.native.image, 12, 11, [26, 26, 26, 255], 0);
    }
}

/// Mesa deviation, pinned: Mesa fogs a pixel rectangle's fragments with fog distance 0
/// (LINEAR from −1 to 1 gives f = ½ whatever the raster distance); GL 1.5 §3.6.4 gives
/// them CURRENT_RASTER_DISTANCE. The emulated path follows Mesa (both images equal).
#[test]
fn mesa_fogs_rectangles_at_distance_zero() {
    let src = format!(
        "{}glEnable(GL_FOG);\nglFogi(GL_FOG_MODE, GL_LINEAR);\nglFogf(GL_FOG_START, -1);\nglFogf(GL_FOG_END, 1);\n\
         glFogfv(GL_FOG_COLOR, (GLfloat[]){{0, 0, 1, 1}});\nglColor3f(1, 1, 1);\n\
         glRasterPos3f(40, 20, -0.9);\nglDrawPixels(2, 1, GL_RGB, GL_UNSIGNED_BYTE, (GLubyte[]){{255, 0, 0, 255, 0, 0}});\n",
        opening()
    );
    let pairs = compare("fog-distance", &src, FRAME, EXACT);
    for p in pairs {
        // The raster distance is ≈ 44.7 (f = 0 by GL: pure fog colour); Mesa: ½ red + ½ blue.
        probe_gl(&p.native.image, 40, 20, [128, 0, 128, 255], 1);
    }
}

const STENCIL_FRAME: Frame = Frame::new(64, 48).with_stencil();

/// A red quad at window depth `z` over the whole frame, drawn with `test`: where it shows,
/// the depth (or stencil) buffer passed it.
fn reveal(z: f32, color: &str) -> String {
    format!(
        "glColor3f({color});\nglBegin(GL_QUADS);\nglVertex3f(0, 0, {d});\nglVertex3f(64, 0, {d});\nglVertex3f(64, 48, {d});\nglVertex3f(0, 48, {d});\nglEnd();\n",
        d = -(2.0 * z - 1.0)
    )
}

/// DEPTH_COMPONENT images in every type, with DEPTH_SCALE and DEPTH_BIAS and a zoom: the
/// depth buffers agree within 2⁻¹⁶ and a quad drawn at depth ½ with LESS shows the same.
#[test]
fn depth_images_match() {
    let (w, h) = (12usize, 8usize);
    let depths: Vec<f32> = (0..w * h)
        .map(|i| ((i % w) as f32 / (w - 1) as f32 + (i / w) as f32 / h as f32) / 2.0)
        .collect();
    let ushorts: Vec<String> = depths
        .iter()
        .map(|d| ((d * 65535.0).round() as u32).to_string())
        .collect();
    let src = format!(
        "{}glEnable(GL_DEPTH_TEST);\nglDepthFunc(GL_ALWAYS);\nglColor3f(0, 1, 0);\n\
         glRasterPos2i(2, 2);\nglDrawPixels({w}, {h}, GL_DEPTH_COMPONENT, GL_FLOAT, {});\n\
         glRasterPos2i(20, 2);\nglDrawPixels({w}, {h}, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, (GLushort[]){{{}}});\n\
         glPixelTransferf(GL_DEPTH_SCALE, 0.5);\nglPixelTransferf(GL_DEPTH_BIAS, 0.4);\nglPixelZoom(2, 2);\n\
         glRasterPos2i(36, 20);\nglDrawPixels({w}, {h}, GL_DEPTH_COMPONENT, GL_FLOAT, {});\n\
         glPixelTransferf(GL_DEPTH_SCALE, 1);\nglPixelTransferf(GL_DEPTH_BIAS, 0);\nglPixelZoom(1, 1);\n\
         glDepthFunc(GL_LESS);\n{}",
        opening(),
        floats(&depths),
        ushorts.join(", "),
        floats(&depths),
        reveal(0.5, "1, 0, 0")
    );
    let pairs = compare("draw-pixels-depth", &src, STENCIL_FRAME, close());
    for p in pairs {
        assert_eq!(p.native.depth.len(), p.emulate.depth.len());
        let worst = p
            .native
            .depth
            .iter()
            .zip(&p.emulate.depth)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0f32, f32::max);
        assert!(
            worst <= 1.0 / 65536.0,
            "{}: depth differs by {worst}",
            p.backend
        );
    }
}

/// STENCIL_INDEX images (UNSIGNED_BYTE and UNSIGNED_SHORT, a flipped zoom, the stencil
/// write mask) write the stencil buffer only; quads with EQUAL tests show the values,
/// identical on both paths. Mesa deviation, pinned: INDEX_SHIFT and INDEX_OFFSET are not
/// applied to stencil images (GL 1.5 §3.6.4 applies them); the layer follows Mesa.
#[test]
fn stencil_images_match_and_mesa_ignores_index_shift_and_offset_for_stencil() {
    let (w, h) = (10usize, 6usize);
    let values: Vec<u32> = (0..w * h).map(|i| (i % 5) as u32).collect();
    let list = |v: &[u32]| v.iter().map(u32::to_string).collect::<Vec<_>>().join(", ");
    let mut src = format!(
        "{}glColor3f(1, 1, 1);\nglRasterPos2i(2, 2);\nglDrawPixels({w}, {h}, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, (GLubyte[]){{{}}});\n\
         glPixelTransferi(GL_INDEX_SHIFT, 1);\nglPixelTransferi(GL_INDEX_OFFSET, 1);\nglPixelZoom(2, -2);\n\
         glRasterPos2i(20, 40);\nglDrawPixels({w}, {h}, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT, (GLushort[]){{{}}});\n\
         glPixelTransferi(GL_INDEX_SHIFT, 0);\nglPixelTransferi(GL_INDEX_OFFSET, 0);\nglPixelZoom(1, 1);\n\
         glStencilMask(6);\nglRasterPos2i(44, 2);\nglDrawPixels({w}, {h}, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, (GLubyte[]){{{}}});\n\
         glStencilMask(255);\nglEnable(GL_STENCIL_TEST);\nglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);\n",
        opening(),
        list(&values),
        list(&values),
        list(&values.iter().map(|v| v * 3).collect::<Vec<_>>()),
    );
    for (k, c) in [
        (1, "1, 0, 0"),
        (2, "0, 1, 0"),
        (3, "0, 0, 1"),
        (4, "1, 1, 0"),
        (5, "0, 1, 1"),
        (6, "1, 0, 1"),
        (7, "1, 1, 1"),
        (9, "0.5, 0.5, 0.5"),
    ] {
        src.push_str(&format!(
            "glStencilFunc(GL_EQUAL, {k}, 255);\n{}",
            reveal(0.0, c)
        ));
    }
    let pairs = compare("draw-pixels-stencil", &src, STENCIL_FRAME, EXACT);
    for p in pairs {
        // mesa_ignores_index_shift_and_offset_for_stencil: value 1 stays 1 (red) under
        // shift 1 and offset 1, where GL would make it 3 (blue).
        for img in [&p.native.image, &p.emulate.image] {
            probe_gl(img, 22, 39, [255, 0, 0, 255], 0);
        }
    }
}

/// glCopyPixels of colour (with zoom, a flip and transfer), depth and stencil, from
/// rectangles drawn first; an invalid raster position copies nothing.
#[test]
fn copy_pixels_match() {
    let img = ubytes(&gradient(8, 6, 4));
    let mut src = format!(
        "{}glRasterPos2i(1, 1);\nglDrawPixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glRasterPos2i(12, 1);\nglCopyPixels(1, 1, 8, 6, GL_COLOR);\n\
         glPixelZoom(2, -1);\nglRasterPos2i(24, 12);\nglCopyPixels(1, 1, 8, 6, GL_COLOR);\n\
         glPixelZoom(1, 1);\nglPixelTransferf(GL_RED_SCALE, 0.5);\nglRasterPos2i(44, 1);\nglCopyPixels(1, 1, 8, 6, GL_COLOR);\n\
         glPixelTransferf(GL_RED_SCALE, 1);\n\
         glRasterPos2i(100, 100);\nglCopyPixels(1, 1, 8, 6, GL_COLOR);\n\
         glEnable(GL_DEPTH_TEST);\nglDepthFunc(GL_ALWAYS);\nglRasterPos3f(1, 20, 0.5);\n\
         glDrawPixels(2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, (GLfloat[]){{0.2, 0.4, 0.6, 0.8}});\n\
         glRasterPos2i(30, 30);\nglCopyPixels(1, 20, 2, 2, GL_DEPTH);\n\
         glRasterPos2i(2, 40);\nglDrawPixels(3, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, (GLubyte[]){{1, 2, 3}});\n\
         glRasterPos2i(10, 40);\nglCopyPixels(2, 40, 3, 1, GL_STENCIL);\n\
         glDepthFunc(GL_LESS);\n{}\
         glEnable(GL_STENCIL_TEST);\nglStencilFunc(GL_EQUAL, 2, 255);\n",
        opening(),
        reveal(0.5, "1, 0, 0")
    );
    src.push_str(&reveal(0.0, "0, 0, 1"));
    let pairs = compare("copy-pixels", &src, STENCIL_FRAME, EXACT);
    for p in pairs {
        // The stencil copy's middle value 2 passes EQUAL 2: blue at (11, 40) on both.
        for img in [&p.native.image, &p.emulate.image] {
            probe_gl(img, 11, 40, [0, 0, 255, 255], 0);
        }
    }
}

/// glReadPixels applies the transfer too (GL 1.5 §4.3.2): colours in UNSIGNED_BYTE (RGBA,
/// and LUMINANCE summed after the transfer), GREEN in UNSIGNED_SHORT and RGB in FLOAT,
/// depths in FLOAT, the same bytes on
/// both paths (floats within 1e-6).
#[test]
fn read_pixels_applies_the_transfer() {
    let img = ubytes(&gradient(8, 4, 4));
    let src = format!(
        "{}glEnable(GL_DEPTH_TEST);\nglDepthFunc(GL_ALWAYS);\nglRasterPos2i(0, 0);\n\
         glDrawPixels(8, 4, GL_RGBA, GL_UNSIGNED_BYTE, {img});\n\
         glDrawPixels(2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, (GLfloat[]){{0.25, 0.5}});\n\
         glPixelTransferf(GL_RED_SCALE, 0.5);\nglPixelTransferf(GL_GREEN_BIAS, 0.25);\nglPixelTransferf(GL_ALPHA_SCALE, 2);\n\
         glPixelTransferf(GL_DEPTH_SCALE, 2);\nglPixelTransferf(GL_DEPTH_BIAS, -0.25);\n\
         glReadPixels(0, 0, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, readback_1);\n\
         glReadPixels(0, 0, 8, 4, GL_LUMINANCE, GL_UNSIGNED_BYTE, readback_2);\n\
         glReadPixels(0, 0, 8, 4, GL_RGB, GL_FLOAT, readback_3);\n\
         glReadPixels(0, 0, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, readback_4);\n\
         glReadPixels(0, 0, 8, 4, GL_GREEN, GL_UNSIGNED_SHORT, readback_5);\n\
         glPixelTransferf(GL_RED_SCALE, 1);\nglPixelTransferf(GL_GREEN_BIAS, 0);\nglPixelTransferf(GL_ALPHA_SCALE, 1);\n\
         glPixelTransferf(GL_DEPTH_SCALE, 1);\nglPixelTransferf(GL_DEPTH_BIAS, 0);\n",
        opening()
    );
    for p in fidelity::run_both(&src, STENCIL_FRAME) {
        for slot in [1, 2, 5] {
            assert_eq!(
                p.emulate.readbacks[&slot].bytes, p.native.readbacks[&slot].bytes,
                "{}: readback {slot}",
                p.backend
            );
        }
        for slot in [3, 4] {
            let f = |b: &[u8]| -> Vec<f32> {
                b.chunks_exact(4)
                    .map(|c| f32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
                    .collect()
            };
            let (e, n) = (
                f(&p.emulate.readbacks[&slot].bytes),
                f(&p.native.readbacks[&slot].bytes),
            );
            assert_eq!(e.len(), n.len());
            for (a, b) in e.iter().zip(&n) {
                assert!(
                    (a - b).abs() <= 1e-6,
                    "{}: readback {slot}: {a} vs {b}",
                    p.backend
                );
            }
        }
        // The depths 0.25 and 0.5 read as 2·d − 0.25.
        let d = &p.native.readbacks[&4].bytes;
        let d0 = f32::from_ne_bytes([d[0], d[1], d[2], d[3]]);
        assert!((d0 - 0.25).abs() < 1e-6, "native depth {d0}");
    }
}
