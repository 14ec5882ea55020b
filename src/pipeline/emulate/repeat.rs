//! Repeated draws of one geometry under new matrices. A frame of the era draws one mesh
//! many times, each copy placed by glPushMatrix, glTranslate, glScale and glPopMatrix
//! (a display list or a buffer object called once per object). Between two such draws only
//! the modelview matrix differs, and of everything a draw derives from the state — its
//! `ShaderKey` and program, its polygon passes, its textures' bindings, its uniforms — only
//! the uniforms that read the modelview or projection matrix
//! ([`UniformSource::reads_transform`](super::uniforms::UniformSource::reads_transform))
//! can change: the key reads no modelview or projection matrix (only whether a texture
//! matrix is the identity), and a draw changes no state (`FixedState::draw`).
//!
//! So the last plain draw is remembered ([`DrawMemo`]): its geometry, its one pass and its
//! program. The next draw of the same geometry (the same `Arc`), when every command
//! between them was a draw or left everything but the modelview and projection matrices
//! alone ([`keeps`]), binds that program, sends its transform uniforms and draws; any
//! other command forgets the memo, and so does a caller that touches GL behind the
//! pipeline. What GL draws is the same either way: the raster state the first draw synced
//! is still GL's (no command that changes it has run), and the current values are set at
//! every draw.

use std::rc::Rc;
use std::sync::Arc;

use super::polygon::PolygonPass;
use super::program::Program;
use crate::ff::{Command, FixedState, Geometry, MatrixMode};

/// The last plain draw: one pass of one geometry with a generated program.
pub struct DrawMemo {
    pub geometry: Arc<Geometry>,
    pub pass: PolygonPass,
    pub program: Rc<Program>,
}

impl DrawMemo {
    /// Whether a draw of `geometry` can repeat this one.
    pub fn repeats(&self, geometry: &Arc<Geometry>) -> bool {
        Arc::ptr_eq(&self.geometry, geometry)
    }
}

/// Whether `cmd`, just accepted by the model, keeps the memo: a draw (it changes no
/// state), the choice of a matrix stack, and a change to the modelview or projection
/// stack. A change to a texture matrix does not keep it: whether the matrix is the
/// identity is part of the key.
pub fn keeps(cmd: &Command, state: &FixedState) -> bool {
    match cmd {
        Command::Draw(_) | Command::MatrixMode(_) => true,
        Command::LoadIdentity
        | Command::LoadMatrix(_)
        | Command::MultMatrix(_)
        | Command::PushMatrix
        | Command::PopMatrix
        | Command::Translate(_)
        | Command::Rotate { .. }
        | Command::Scale(_)
        | Command::Frustum(_)
        | Command::Ortho(_) => matches!(
            state.matrix_mode,
            MatrixMode::Modelview | MatrixMode::Projection
        ),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn only_draws_and_modelview_or_projection_changes_keep_the_memo() {
        let mut state = FixedState::default();
        let translate = Command::Translate(Vec3::X);
        assert!(keeps(&translate, &state));
        assert!(keeps(&Command::PushMatrix, &state));
        assert!(keeps(&Command::MatrixMode(MatrixMode::Texture), &state));
        state.matrix_mode = MatrixMode::Projection;
        assert!(keeps(&Command::LoadIdentity, &state));
        state.matrix_mode = MatrixMode::Texture;
        assert!(!keeps(&translate, &state), "a texture matrix is in the key");
        assert!(!keeps(&Command::PopMatrix, &state));
        state.matrix_mode = MatrixMode::Modelview;
        assert!(!keeps(
            &Command::ShadeModel(crate::ff::ShadeModel::Flat),
            &state
        ));
        assert!(!keeps(
            &Command::Enable(crate::ff::Capability::Lighting),
            &state
        ));
    }
}
