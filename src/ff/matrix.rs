//! Matrices and matrix stacks (GL 1.5 §2.11).
//!
//! Every matrix command multiplies the top of the current stack on the right: `M ← M·N`
//! (§2.11.2), so the last command issued is the first applied to a vertex. Matrices are
//! column-major, as `glLoadMatrixf` reads them and as glam stores them.
//!
//! Stack depths are Mesa's (modelview 32, projection 32, texture 10; the GL minimums of
//! Table 6.43 are 32, 2 and 2): a program that runs on Mesa's native path runs here, and
//! overflows where Mesa overflows (a test reads the native GL_MAX_*_STACK_DEPTH).

use glam::{Mat4, Vec4};

use super::error::{GlError, GlResult};
use super::matrix_ops::{MatrixKind, Product};

/// GL_MAX_MODELVIEW_STACK_DEPTH (Mesa's MAX_MODELVIEW_STACK_DEPTH).
pub const MODELVIEW_STACK_DEPTH: usize = 32;
/// GL_MAX_PROJECTION_STACK_DEPTH (Mesa's MAX_PROJECTION_STACK_DEPTH; GL's minimum is 2).
pub const PROJECTION_STACK_DEPTH: usize = 32;
/// GL_MAX_TEXTURE_STACK_DEPTH per texture unit (Mesa's MAX_TEXTURE_STACK_DEPTH; GL's
/// minimum is 2).
pub const TEXTURE_STACK_DEPTH: usize = 10;

/// The stack that matrix commands act on (glMatrixMode). `Texture` means the texture matrix
/// of the texture unit active when each matrix command runs (GL 1.5 §2.11.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MatrixMode {
    Modelview,
    Projection,
    Texture,
}

/// The six planes of glFrustum / glOrtho.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViewVolume {
    pub left: f32,
    pub right: f32,
    pub bottom: f32,
    pub top: f32,
    pub near: f32,
    pub far: f32,
}

/// A matrix stack: never empty, the last element is the current matrix, with the kind
/// that decides how Mesa multiplies onto it (`matrix_ops`); glPushMatrix copies both.
#[derive(Debug, Clone, PartialEq)]
pub struct MatrixStack {
    stack: Vec<(Mat4, MatrixKind)>,
    max_depth: usize,
}

impl MatrixStack {
    /// A stack holding one identity matrix (GL default).
    pub fn new(max_depth: usize) -> Self {
        Self {
            stack: vec![(Mat4::IDENTITY, MatrixKind::Affine)],
            max_depth: max_depth.max(1),
        }
    }

    /// The current matrix.
    pub fn top(&self) -> Mat4 {
        self.current().0
    }

    fn current(&self) -> (Mat4, MatrixKind) {
        self.stack
            .last()
            .copied()
            .unwrap_or((Mat4::IDENTITY, MatrixKind::Affine))
    }

    fn set(&mut self, m: Mat4, kind: MatrixKind) {
        match self.stack.last_mut() {
            Some(top) => *top = (m, kind),
            None => self.stack.push((m, kind)),
        }
    }

    /// glLoadMatrix (and any matrix set whole): the current matrix, of general kind.
    pub fn set_top(&mut self, m: Mat4) {
        self.set(m, MatrixKind::General);
    }

    /// glLoadIdentity. The kind stays: Mesa's `_math_matrix_set_identity` clears only the
    /// dirty bits of the type flags, so a matrix that was general (a glFrustum, glLoadMatrix
    /// or glMultMatrix before) is still multiplied in full (measured: glRotatef(NaN) after
    /// glLoadMatrixf and glLoadIdentity leaves NaN in the bottom row).
    pub fn load_identity(&mut self) {
        let (_, kind) = self.current();
        self.set(Mat4::IDENTITY, kind);
    }

    /// M ← M·N for a command whose matrix is N (`matrix_ops::multiply`).
    pub fn multiply(&mut self, n: Mat4, product: Product) {
        let (m, kind) = self.current();
        let (p, kind) = super::matrix_ops::multiply(m, kind, n, product);
        self.set(p, kind);
    }

    /// A command that changes the current matrix in place (glTranslate, glScale): its kind
    /// stays.
    pub fn update(&mut self, f: impl FnOnce(Mat4) -> Mat4) {
        let (m, kind) = self.current();
        self.set(f(m), kind);
    }

    /// Number of matrices on the stack (GL_*_STACK_DEPTH; 1 initially).
    pub fn depth(&self) -> usize {
        self.stack.len()
    }

    pub fn max_depth(&self) -> usize {
        self.max_depth
    }

    /// glPushMatrix: duplicates the top; STACK_OVERFLOW when full.
    pub fn push(&mut self) -> GlResult {
        if self.stack.len() >= self.max_depth {
            return Err(GlError::stack_overflow("PushMatrix on a full matrix stack"));
        }
        self.stack.push(self.current());
        Ok(())
    }

    /// glPopMatrix: STACK_UNDERFLOW when only one matrix is left.
    pub fn pop(&mut self) -> GlResult {
        if self.stack.len() <= 1 {
            return Err(GlError::stack_underflow(
                "PopMatrix on a stack holding one matrix",
            ));
        }
        self.stack.pop();
        Ok(())
    }
}

/// glFrustum (GL 1.5 §2.11.2):
/// ```text
/// | 2n/(r−l)   0         (r+l)/(r−l)    0          |
/// | 0          2n/(t−b)  (t+b)/(t−b)    0          |
/// | 0          0         −(f+n)/(f−n)   −2fn/(f−n) |
/// | 0          0         −1             0          |
/// ```
/// INVALID_VALUE if n ≤ 0, f ≤ 0, l = r, b = t or n = f.
pub fn frustum(v: ViewVolume) -> GlResult<Mat4> {
    let ViewVolume {
        left: l,
        right: r,
        bottom: b,
        top: t,
        near: n,
        far: f,
    } = v;
    if n <= 0.0 || f <= 0.0 || l == r || b == t || n == f {
        return Err(GlError::invalid_value(
            "Frustum needs n > 0, f > 0, l ≠ r, b ≠ t, n ≠ f",
        ));
    }
    Ok(Mat4::from_cols(
        Vec4::new(2.0 * n / (r - l), 0.0, 0.0, 0.0),
        Vec4::new(0.0, 2.0 * n / (t - b), 0.0, 0.0),
        Vec4::new(
            (r + l) / (r - l),
            (t + b) / (t - b),
            -(f + n) / (f - n),
            -1.0,
        ),
        Vec4::new(0.0, 0.0, -2.0 * f * n / (f - n), 0.0),
    ))
}

/// glOrtho (GL 1.5 §2.11.2):
/// ```text
/// | 2/(r−l)  0        0         −(r+l)/(r−l) |
/// | 0        2/(t−b)  0         −(t+b)/(t−b) |
/// | 0        0        −2/(f−n)  −(f+n)/(f−n) |
/// | 0        0        0         1            |
/// ```
/// INVALID_VALUE if l = r, b = t or n = f.
pub fn ortho(v: ViewVolume) -> GlResult<Mat4> {
    let ViewVolume {
        left: l,
        right: r,
        bottom: b,
        top: t,
        near: n,
        far: f,
    } = v;
    if l == r || b == t || n == f {
        return Err(GlError::invalid_value("Ortho needs l ≠ r, b ≠ t, n ≠ f"));
    }
    Ok(Mat4::from_cols(
        Vec4::new(2.0 / (r - l), 0.0, 0.0, 0.0),
        Vec4::new(0.0, 2.0 / (t - b), 0.0, 0.0),
        Vec4::new(0.0, 0.0, -2.0 / (f - n), 0.0),
        Vec4::new(
            -(r + l) / (r - l),
            -(t + b) / (t - b),
            -(f + n) / (f - n),
            1.0,
        ),
    ))
}

/// M⁻¹, or the identity when M is singular or not finite (Mesa's `_math_matrix_analyse`
/// falls back to the identity when inversion fails; GL leaves the result undefined).
pub fn inverse_or_identity(m: Mat4) -> Mat4 {
    let det = m.determinant();
    if det == 0.0 || !det.is_finite() {
        return Mat4::IDENTITY;
    }
    let inv = m.inverse();
    if inv.is_finite() {
        inv
    } else {
        Mat4::IDENTITY
    }
}

/// A plane (a, b, c, d) given in object coordinates, in eye coordinates:
/// (a′ b′ c′ d′) = (a b c d)·M⁻¹ (GL 1.5 §2.11.4, eqn 2.4), M the modelview when the plane
/// is specified. As a column vector: p′ = (M⁻¹)ᵀ·p.
pub fn plane_to_eye(plane: Vec4, modelview: Mat4) -> Vec4 {
    inverse_or_identity(modelview).transpose() * plane
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frustum_maps_near_and_far_to_ndc_minus_one_and_one() {
        let m = frustum(ViewVolume {
            left: -1.0,
            right: 1.0,
            bottom: -1.0,
            top: 1.0,
            near: 1.0,
            far: 10.0,
        })
        .unwrap();
        let near = m * Vec4::new(0.0, 0.0, -1.0, 1.0);
        let far = m * Vec4::new(0.0, 0.0, -10.0, 1.0);
        assert!((near.z / near.w + 1.0).abs() < 1e-6);
        assert!((far.z / far.w - 1.0).abs() < 1e-6);
    }

    #[test]
    fn degenerate_volumes_are_invalid_value() {
        let v = ViewVolume {
            left: 0.0,
            right: 0.0,
            bottom: -1.0,
            top: 1.0,
            near: 1.0,
            far: 2.0,
        };
        assert!(frustum(v).is_err());
        assert!(ortho(v).is_err());
        let v = ViewVolume {
            left: -1.0,
            right: 1.0,
            bottom: -1.0,
            top: 1.0,
            near: 0.0,
            far: 2.0,
        };
        assert!(frustum(v).is_err());
        assert!(ortho(v).is_ok());
    }

    #[test]
    fn ortho_matches_glam() {
        let v = ViewVolume {
            left: -2.0,
            right: 3.0,
            bottom: -1.0,
            top: 4.0,
            near: 0.5,
            far: 9.0,
        };
        let ours = ortho(v).unwrap();
        let glam = glam::camera::rh::proj::opengl::orthographic(-2.0, 3.0, -1.0, 4.0, 0.5, 9.0);
        assert!(ours.abs_diff_eq(glam, 1e-6));
    }

    #[test]
    fn stack_overflow_and_underflow() {
        let mut s = MatrixStack::new(2);
        assert!(s.pop().is_err());
        s.push().unwrap();
        assert!(s.push().is_err());
        assert_eq!(s.depth(), 2);
    }

    #[test]
    fn singular_modelview_leaves_the_plane_unchanged() {
        let p = Vec4::new(1.0, 2.0, 3.0, 4.0);
        assert_eq!(plane_to_eye(p, Mat4::ZERO), p);
    }
}
