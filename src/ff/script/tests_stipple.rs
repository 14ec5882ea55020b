//! Script tables for stipple: glPolygonStipple prints its mask as 128 bytes and parses back
//! to itself, a mask of another length is refused with the call named, glGetPolygonStipple
//! and POLYGON_STIPPLE's enable are calls a script can spell.

use super::*;
use crate::ff::*;

fn stipple() -> PolygonStipple {
    let bytes: Vec<u8> = (0..128u32).map(|i| (i * 29 + 3) as u8).collect();
    PolygonStipple::from_bytes(&bytes).unwrap()
}

#[test]
fn polygon_stipple_prints_and_parses_back() {
    let cmds = vec![
        Command::PolygonStipple(stipple()),
        Command::Enable(Capability::PolygonStipple),
        Command::Disable(Capability::PolygonStipple),
    ];
    let text = print(&cmds);
    assert!(
        text.contains("glPolygonStipple((GLubyte[]){3, 32, 61,"),
        "{text}"
    );
    assert!(text.contains("glEnable(GL_POLYGON_STIPPLE);"), "{text}");
    assert_eq!(parse(&text).unwrap_or_else(|e| panic!("{e}\n{text}")), cmds);
}

#[test]
fn a_short_polygon_stipple_mask_is_refused() {
    let err = parse("glPolygonStipple((GLubyte[]){1, 2, 3});").unwrap_err();
    assert!(err.to_string().contains("glPolygonStipple"), "{err}");
}

#[test]
fn get_polygon_stipple_is_a_script_call() {
    let cmds = parse(
        "glPolygonStipple((GLubyte[]){0});\nglGetPolygonStipple((GLubyte[128]){0});\nglIsEnabled(GL_POLYGON_STIPPLE);",
    );
    // A one-byte literal is too short for the 128 bytes the mask reads.
    assert!(cmds.is_err());
    let ok = parse("glGetPolygonStipple((GLubyte[128]){0});\nglIsEnabled(GL_POLYGON_STIPPLE);")
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(ok.is_empty(), "queries change nothing: {ok:?}");
}
