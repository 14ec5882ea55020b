//! glTexSubImage1D, glCopyTexImage1D, glCopyTexSubImage1D/2D and glGetTexImage on both
//! paths: for every internal format the layer stores (the legacy ones emulated as R8/RG8
//! plus swizzle), a texture is given known texels, part of it is overwritten by a copy of
//! the framebuffer, and glGetTexImage reads it back in every format and type; the emulated
//! path's bytes must be the native path's (Mesa's own conversions) exactly, and the
//! textures drawn back must match exactly.

mod fidelity;
mod support;

use fidelity::{ortho, run_both, Frame};

const FORMATS: [(&str, &str, usize); 6] = [
    ("GL_RGBA8", "GL_RGBA", 4),
    ("GL_RGB8", "GL_RGB", 3),
    ("GL_LUMINANCE8", "GL_LUMINANCE", 1),
    ("GL_INTENSITY8", "GL_LUMINANCE", 1),
    ("GL_ALPHA8", "GL_ALPHA", 1),
    ("GL_LUMINANCE8_ALPHA8", "GL_LUMINANCE_ALPHA", 2),
];

const READ_AS: [&str; 5] = [
    "GL_RGBA",
    "GL_RGB",
    "GL_LUMINANCE",
    "GL_LUMINANCE_ALPHA",
    "GL_ALPHA",
];

const TYPES: [&str; 3] = ["GL_UNSIGNED_BYTE", "GL_UNSIGNED_SHORT", "GL_FLOAT"];

/// The script: a framebuffer of four colours, then per format a 4×4 2D texture and a 4×1
/// 1D texture, copies into them, readbacks into slots, and the 2D textures drawn in a row.
fn script() -> String {
    let mut s = ortho(96, 16);
    s.push_str("glPixelStorei(GL_UNPACK_ALIGNMENT, 1);\n");
    s.push_str("glClearColor(0.2f, 0.4f, 0.6f, 0.8f);\nglClear(GL_COLOR_BUFFER_BIT);\n");
    s.push_str(
        "glBegin(GL_QUADS);\nglColor4f(1, 0.5f, 0, 0.25f);\nglVertex2i(0, 0); glVertex2i(2, 0); glVertex2i(2, 2); glVertex2i(0, 2);\nglEnd();\n",
    );
    let mut slot = 0;
    for (k, (internal, format, n)) in FORMATS.iter().enumerate() {
        let texels: Vec<String> = (0..16 * n)
            .map(|i| ((i * 37 + 11) % 256).to_string())
            .collect();
        let name = 1 + 2 * k;
        s.push_str(&format!(
            "glBindTexture(GL_TEXTURE_2D, {name});\n\
             glTexImage2D(GL_TEXTURE_2D, 0, {internal}, 4, 4, 0, {format}, GL_UNSIGNED_BYTE, (GLubyte[]){{{}}});\n\
             glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);\n\
             glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);\n\
             glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, 2, 2);\n",
            texels.join(", ")
        ));
        let row: Vec<String> = texels.iter().take(4 * n).cloned().collect();
        s.push_str(&format!(
            "glBindTexture(GL_TEXTURE_1D, {});\n\
             glTexImage1D(GL_TEXTURE_1D, 0, {internal}, 4, 0, {format}, GL_UNSIGNED_BYTE, (GLubyte[]){{{}}});\n\
             glTexSubImage1D(GL_TEXTURE_1D, 0, 2, 1, {format}, GL_UNSIGNED_BYTE, (GLubyte[]){{{}}});\n\
             glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 0, 1, 0, 1);\n",
            name + 1,
            row.join(", "),
            vec!["200"; *n].join(", ")
        ));
        // Every type for RGBA, bytes for the other formats; the 1D texture as RGBA and ALPHA.
        for read in READ_AS {
            let types: &[&str] = if read == "GL_RGBA" {
                &TYPES
            } else {
                &TYPES[..1]
            };
            for ty in types {
                s.push_str(&format!(
                    "glGetTexImage(GL_TEXTURE_2D, 0, {read}, {ty}, readback_{slot});\n"
                ));
                slot += 1;
            }
            if matches!(read, "GL_RGBA" | "GL_ALPHA") {
                s.push_str(&format!(
                    "glGetTexImage(GL_TEXTURE_1D, 0, {read}, GL_UNSIGNED_BYTE, readback_{slot});\n"
                ));
                slot += 1;
            }
        }
    }
    // A new 1D level copied from a row: every format again, read as RGBA.
    for (internal, _, _) in FORMATS {
        s.push_str(&format!(
            "glCopyTexImage1D(GL_TEXTURE_1D, 0, {internal}, 0, 1, 4, 0);\n\
             glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback_{slot});\n"
        ));
        slot += 1;
    }
    s.push_str(
        "glEnable(GL_TEXTURE_2D);\nglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);\n",
    );
    for k in 0..FORMATS.len() {
        let x = 16 * k;
        s.push_str(&format!(
            "glBindTexture(GL_TEXTURE_2D, {});\nglBegin(GL_QUADS);\n\
             glTexCoord2f(0, 0); glVertex2i({x}, 0); glTexCoord2f(1, 0); glVertex2i({}, 0);\n\
             glTexCoord2f(1, 1); glVertex2i({}, 16); glTexCoord2f(0, 1); glVertex2i({x}, 16);\nglEnd();\n",
            1 + 2 * k,
            x + 16,
            x + 16
        ));
    }
    assert!(slot < 64, "the fidelity harness reads slots 0..64");
    s
}

#[test]
fn copies_and_readbacks_of_every_stored_format_match_the_native_path() {
    let src = script();
    for p in run_both(&src, Frame::new(96, 16)) {
        assert_eq!(p.emulate.readbacks.len(), p.native.readbacks.len());
        assert_eq!(p.native.readbacks.len(), 6 * 9 + 6);
        for (slot, native) in &p.native.readbacks {
            let emulated = &p.emulate.readbacks[slot];
            assert_eq!(
                (
                    emulated.width,
                    emulated.height,
                    emulated.format,
                    emulated.ty
                ),
                (native.width, native.height, native.format, native.ty),
                "{}: readback_{slot}",
                p.backend
            );
            assert_eq!(
                emulated.bytes, native.bytes,
                "{}: readback_{slot} ({:?} {:?})",
                p.backend, native.format, native.ty
            );
        }
        support::assert_images_match(
            &format!("texture-calls-{}", p.backend),
            &p.emulate.image,
            &p.native.image,
            support::Tolerance::EXACT,
        );
    }
}
