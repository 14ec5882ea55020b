//! Textures stored at the bits of the internal format the program named
//! (`ff::texture_storage`), against Mesa's native path: a 1×1 texel (0x9b, 0x57, 0xd3,
//! 0x6a) uploaded as each reduced or wide format and drawn with REPLACE over a 2×2 frame,
//! the paths compared exactly and the drawn texel against what Mesa 22.3.6 llvmpipe was
//! measured to draw through OSMesa. On the starting commit the emulated path stored every
//! RGB and RGBA format at 8 bits (RGBA4 drew the texel unchanged).

mod fidelity;
mod support;

use fidelity::{compare, Frame};
use support::Tolerance;

/// The internal format and the texel Mesa draws from it.
const CASES: &[(&str, [u8; 4])] = &[
    ("GL_R3_G3_B2", [0x92, 0x49, 0xaa, 0xff]),
    ("GL_RGB4", [0x99, 0x55, 0xcc, 0xff]),
    ("GL_RGB5", [0x9c, 0x5a, 0xd6, 0xff]),
    ("GL_RGBA2", [0x99, 0x55, 0xcc, 0x66]),
    ("GL_RGBA4", [0x99, 0x55, 0xcc, 0x66]),
    ("GL_RGB5_A1", [0x9c, 0x5a, 0xd6, 0x00]),
    ("GL_RGB10_A2", [0x9b, 0x57, 0xd3, 0x55]),
    ("GL_RGBA16", [0x9b, 0x57, 0xd3, 0x6a]),
    ("GL_LUMINANCE16", [0x9b, 0x9b, 0x9b, 0xff]),
    ("GL_ALPHA12", [0xff, 0xff, 0xff, 0x6a]),
    ("GL_LUMINANCE4_ALPHA4", [0x99, 0x99, 0x99, 0x66]),
];

#[test]
fn reduced_and_wide_formats_draw_as_mesa_stores_them() {
    for (format, texel) in CASES {
        let src = format!(
            "glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
glColor4f(1, 1, 1, 1);
glBindTexture(GL_TEXTURE_2D, 1);
glTexImage2D(GL_TEXTURE_2D, 0, {format}, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){{0x9b, 0x57, 0xd3, 0x6a}});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glEnable(GL_TEXTURE_2D);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
glBegin(GL_QUADS);
glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(1, 1); glVertex2f(-1, 1);
glEnd();
"
        );
        for p in compare(
            &format!("storage-{format}"),
            &src,
            Frame::new(2, 2),
            Tolerance::EXACT,
        ) {
            for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
                assert_eq!(
                    out.image.get_pixel(0, 0).0,
                    *texel,
                    "{format} {} {path}",
                    p.backend
                );
            }
        }
    }
}
