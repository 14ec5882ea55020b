//! Script tables for the raster position and pixel rectangles: every position variant
//! reads its C type, the commands print and parse back to themselves (and compile as C),
//! a rectangle beyond the budget is refused before its pixels are read.

use std::sync::Arc;

use glam::{Vec3, Vec4};

use super::*;
use crate::ff::*;

fn pixel_commands() -> Vec<Command> {
    use PixelTransferParam as P;
    let mut cmds = vec![
        Command::RasterPos(Vec4::new(1.5, -2.0, 0.25, 2.0)),
        Command::WindowPos(Vec3::new(3.0, 4.5, 0.75)),
        Command::Bitmap(Bitmap {
            width: 10,
            height: 2,
            origin: (1.5, -0.5),
            advance: (11.0, 0.0),
            bits: Some(Arc::from(vec![0xff, 0xc0, 0x80, 0x40])),
        }),
        Command::Bitmap(Bitmap {
            width: 0,
            height: 0,
            origin: (0.0, 0.0),
            advance: (-3.0, 7.25),
            bits: None,
        }),
        Command::DrawPixels(DrawPixels {
            width: 2,
            height: 1,
            format: PixelFormat::LuminanceAlpha,
            ty: PixelType::UnsignedShort,
            data: Arc::from(
                [1u16, 65535, 300, 0]
                    .iter()
                    .flat_map(|v| v.to_le_bytes())
                    .collect::<Vec<u8>>(),
            ),
        }),
        Command::DrawPixels(DrawPixels {
            width: 1,
            height: 1,
            format: PixelFormat::DepthComponent,
            ty: PixelType::Float,
            data: Arc::from(0.375f32.to_le_bytes().to_vec()),
        }),
        Command::CopyPixels(CopyPixels {
            x: 1,
            y: 2,
            width: 3,
            height: 4,
            kind: CopyKind::Stencil,
        }),
        Command::PixelZoom { x: -1.0, y: 2.5 },
    ];
    for i in 0..4 {
        cmds.push(Command::PixelTransfer(P::Scale(i, 0.5 + f32::from(i))));
        cmds.push(Command::PixelTransfer(P::Bias(i, -0.25)));
    }
    cmds.extend(
        [
            P::DepthScale(2.0),
            P::DepthBias(0.125),
            P::IndexShift(-3),
            P::IndexOffset(9),
            P::MapColor(true),
            P::MapStencil(false),
        ]
        .map(Command::PixelTransfer),
    );
    cmds
}

#[test]
fn pixel_commands_print_and_parse_back() {
    let cmds = pixel_commands();
    let text = print(&cmds);
    assert!(
        text.contains("glBitmap(0, 0, 0.0, 0.0, -3.0, 7.25, NULL);"),
        "{text}"
    );
    assert!(
        text.contains("glCopyPixels(1, 2, 3, 4, GL_STENCIL);"),
        "{text}"
    );
    assert_eq!(parse(&text).unwrap_or_else(|e| panic!("{e}\n{text}")), cmds);
}

#[test]
fn position_variants_convert_as_c_does() {
    let cases = [
        (
            "glRasterPos2i(3, -4);",
            Command::RasterPos(Vec4::new(3.0, -4.0, 0.0, 1.0)),
        ),
        (
            "glRasterPos3sv((GLshort[]){1, 2, 3});",
            Command::RasterPos(Vec4::new(1.0, 2.0, 3.0, 1.0)),
        ),
        (
            "glRasterPos4dv((GLdouble[]){0.5, 1, 2, 4});",
            Command::RasterPos(Vec4::new(0.5, 1.0, 2.0, 4.0)),
        ),
        // An integer parameter truncates a fractional argument, as C converts it.
        (
            "glRasterPos2s(2.9, -1.9);",
            Command::RasterPos(Vec4::new(2.0, -1.0, 0.0, 1.0)),
        ),
        (
            "glWindowPos2dARB(3.5, 4);",
            Command::WindowPos(Vec3::new(3.5, 4.0, 0.0)),
        ),
        (
            "glWindowPos3fvMESA((GLfloat[]){1, 2, 0.5});",
            Command::WindowPos(Vec3::new(1.0, 2.0, 0.5)),
        ),
        (
            "glPixelTransferi(GL_MAP_STENCIL, 2);",
            Command::PixelTransfer(PixelTransferParam::MapStencil(true)),
        ),
        (
            "glPixelTransferf(GL_INDEX_SHIFT, 2.7);",
            Command::PixelTransfer(PixelTransferParam::IndexShift(2)),
        ),
    ];
    for (src, want) in cases {
        assert_eq!(
            parse(src).unwrap_or_else(|e| panic!("{src}: {e}")),
            vec![want],
            "{src}"
        );
    }
}

#[test]
fn bad_pixel_calls_are_refused_with_the_rule() {
    // 2^31 pixels: refused before any pixel is read or allocated.
    let e = parse("glDrawPixels(65536, 32768, GL_RGBA, GL_UNSIGNED_BYTE, NULL);").unwrap_err();
    assert!(e.to_string().contains("2^24"), "{e}");
    let e = parse("glBitmap(100000, 100000, 0, 0, 0, 0, NULL);").unwrap_err();
    assert!(e.to_string().contains("2^24"), "{e}");
    let e = parse("glCopyPixels(0, 0, 1, 1, GL_RGBA);").unwrap_err();
    assert!(e.to_string().contains("GL_COLOR"), "{e}");
    let e = parse("glBegin(GL_POINTS);\nglRasterPos2i(1, 1);\nglEnd();").unwrap_err();
    assert!(e.to_string().contains("line 2"), "{e}");
    // A negative size reaches the model, which records GL's INVALID_VALUE.
    let cmds = parse("glDrawPixels(-1, 1, GL_RGB, GL_UNSIGNED_BYTE, (GLubyte[]){});").unwrap();
    let mut s = FixedState::new();
    assert_eq!(
        s.apply(&cmds[0]).unwrap_err().kind,
        GlErrorKind::InvalidValue
    );
}

/// The printed calls compile as C99 against the system's GL headers.
#[test]
fn printed_pixel_calls_are_valid_c() {
    let dir = std::env::temp_dir().join(format!("ff-pixels-c-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temporary directory");
    let body = print(&pixel_commands());
    let src = format!(
        "#define GL_GLEXT_PROTOTYPES 1\n#include <GL/gl.h>\n#include <GL/glext.h>\n#include <stddef.h>\n\
         void script(void) {{\n{body}}}\n"
    );
    let file = dir.join("script.c");
    std::fs::write(&file, src).expect("write script.c");
    let out = std::process::Command::new("gcc")
        .args(["-std=c99", "-fsyntax-only", "-Wall", "-Werror"])
        .arg(&file)
        .output()
        .expect("gcc missing: apt-get install gcc");
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// A display list keeps a bitmap's bits and a raster position's object coordinates; each
/// glCallList draws the bitmap and moves the position again (GL 1.5 §5.4: both are
/// compiled).
#[test]
fn lists_keep_bitmaps_and_positions() {
    let cmds = parse(
        "glNewList(1, GL_COMPILE);\nglRasterPos2f(0.2, 0.4);\nglBitmap(8, 1, 0, 0, 5, 0, (GLubyte[]){255});\nglEndList();\n\
         glCallList(1);\nglBitmap(0, 0, 0, 0, 0, 3, NULL);\nglCallList(1);\n",
    )
    .unwrap();
    let bitmaps = cmds
        .iter()
        .filter(|c| matches!(c, Command::Bitmap(b) if b.bits.is_some()))
        .count();
    assert_eq!(bitmaps, 2, "{cmds:?}");
    let mut s = FixedState::new();
    s.apply(&Command::Viewport(Viewport {
        x: 0,
        y: 0,
        width: 10,
        height: 10,
    }))
    .unwrap();
    s.apply_all(&cmds).unwrap();
    // (0.2, 0.4) in NDC is window (6, 7); the second list sets it again, then moves it by 5.
    assert!(s.raster.valid);
    assert_eq!(s.raster.window.truncate(), Vec3::new(11.0, 7.0, 0.5));
}
