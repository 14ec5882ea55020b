//! A script of the era, parsed and folded into the state model through the public API.

use fixedfunc::ff::{script, Capability, CompareFunc, FixedState, TexCoord, TexEnvMode};
use glam::Vec4;

const KILGARD_8BIT_LIT_PASS: &str = r#"
// Dual-texture 8-bit comparison, lit pass (Kilgard, GDC 2000): unit 1 compares.
glDepthFunc(GL_EQUAL);
glActiveTexture(GL_TEXTURE1);
glEnable(GL_TEXTURE_1D);
glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
glTexGenfv(GL_S, GL_EYE_PLANE, (GLfloat[]){0, 0, -0.05f, 0.2f});
glEnable(GL_TEXTURE_GEN_S);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_ADD_SIGNED);
glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PREVIOUS);
glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_TEXTURE);
glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
glAlphaFunc(GL_GREATER, 0.5);
glEnable(GL_ALPHA_TEST);
glBegin(GL_QUADS);
  glVertex3f(-1, -1, 0); glVertex3f(1, -1, 0); glVertex3f(1, 1, 0); glVertex3f(-1, 1, 0);
glEnd();
glReadPixels(0, 0, 4, 4, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, readback_0);
"#;

#[test]
fn script_to_state() {
    let cmds = script::parse(KILGARD_8BIT_LIT_PASS).unwrap();
    let mut state = FixedState::new();
    state.apply_all(&cmds).unwrap();
    assert_eq!(state.error(), None);
    assert_eq!(state.active_unit(), 1);
    let unit = &state.units[1];
    assert_eq!(unit.env.mode, TexEnvMode::Combine);
    assert_eq!(
        unit.texgen(TexCoord::S).map(|g| g.eye_plane),
        Some(Vec4::new(0.0, 0.0, -0.05, 0.2))
    );
    assert_eq!(
        state.alpha_test.get().map(|a| (a.func, a.reference)),
        Some((CompareFunc::Greater, 0.5))
    );
    assert_eq!(state.depth_test.value.func, CompareFunc::Equal);
    assert!(cmds.contains(&fixedfunc::ff::Command::Enable(Capability::AlphaTest)));
    // The printer is the parser's inverse.
    assert_eq!(script::parse(&script::print(&cmds)).unwrap(), cmds);
}
