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
        Command::PolygonStipple(Box::new(stipple())),
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

#[test]
fn line_stipple_prints_and_parses_back_with_its_factor_clamped() {
    let cmds = parse(
        "glLineStipple(0, 0x0F0F);\nglLineStipple(300, 65535);\nglLineStipple(3, 0x10001);\nglEnable(GL_LINE_STIPPLE);",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        cmds,
        [
            Command::LineStipple(LineStipple::new(1, 0x0F0F)),
            Command::LineStipple(LineStipple::new(256, 0xFFFF)),
            // GLushort: C keeps the low 16 bits.
            Command::LineStipple(LineStipple::new(3, 1)),
            Command::Enable(Capability::LineStipple),
        ]
    );
    let text = print(&cmds);
    assert!(text.contains("glLineStipple(256, 0xFFFF);"), "{text}");
    assert_eq!(parse(&text).unwrap_or_else(|e| panic!("{e}\n{text}")), cmds);
}

#[test]
fn stipple_state_is_queried_and_pushed() {
    use crate::ff::glenum::registry as r;
    let mut s = FixedState::new();
    let zeros = vec!["0"; 128].join(", ");
    for c in parse(&format!(
        "glPushAttrib(GL_LINE_BIT | GL_POLYGON_STIPPLE_BIT);\nglLineStipple(4, 0xAAAA);\nglEnable(GL_LINE_STIPPLE);\nglPolygonStipple((GLubyte[]){{{zeros}}});",
    ))
    .unwrap_or_else(|e| panic!("{e}"))
    {
        s.apply(&c).unwrap();
    }
    let int = |s: &FixedState, pname| s.get(pname).unwrap()[0].as_int();
    assert_eq!(int(&s, r::LINE_STIPPLE_PATTERN), 0xAAAA);
    assert_eq!(int(&s, r::LINE_STIPPLE_REPEAT), 4);
    assert_eq!(s.is_enabled(r::LINE_STIPPLE), Ok(true));
    assert!(!s.polygon_stipple.value.passes(3, 3));
    s.apply(&Command::PopAttrib).unwrap();
    assert_eq!(int(&s, r::LINE_STIPPLE_PATTERN), 0xFFFF);
    assert_eq!(int(&s, r::LINE_STIPPLE_REPEAT), 1);
    assert_eq!(s.is_enabled(r::LINE_STIPPLE), Ok(false));
    assert_eq!(s.polygon_stipple.value, PolygonStipple::DEFAULT);
}
