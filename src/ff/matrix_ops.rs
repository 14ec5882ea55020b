//! The arithmetic of the matrix commands, operation for operation as Mesa 22.3's
//! `math/m_matrix.c` does it, so that the matrices glGet answers and the vertices they
//! place are Mesa's to the bit (measured against Mesa's OSMesa, `tests/c/matrices.c`):
//!
//! - glRotate builds Mesa's matrix: an axis-aligned rotation fills only its 2 × 2 block;
//!   any other axis is normalised and the matrix written as (1 − c)·u·uᵀ + c·I + s·S(u)
//!   term by term in Mesa's order; an axis shorter than 10⁻⁴, or an angle of 0, leaves the
//!   matrix as it is (no product at all).
//! - glTranslate updates the last column in place, m₁₂₊ᵢ = m_i·x + m₄₊ᵢ·y + m₈₊ᵢ·z + m₁₂₊ᵢ;
//!   glScale multiplies the first three columns in place (so 0·(−2) leaves −0).
//! - glRotate and glOrtho multiply an [`MatrixKind::Affine`] matrix with Mesa's 3 × 4
//!   product, which keeps the bottom row (0, 0, 0, 1) exactly; glFrustum, glMultMatrix and
//!   any product onto a [`MatrixKind::General`] matrix are the full 4 × 4 product,
//!   p_ij = a_i0·b_0j + a_i1·b_1j + a_i2·b_2j + a_i3·b_3j in that order (glam's).
//!
//! For finite values the two products agree; they differ where a NaN or an infinity meets
//! a zero (0·∞ is NaN), which is where the kinds matter.

use glam::{Mat4, Vec3};

/// How Mesa multiplies onto a matrix: what its type flags say of the commands it has
/// seen. The flags only gather: glLoadIdentity keeps them (`MatrixStack::load_identity`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MatrixKind {
    /// Only glRotate, glTranslate, glScale and glOrtho so far (Mesa's `MAT_FLAGS_3D`):
    /// products keep the bottom row (0, 0, 0, 1).
    Affine,
    /// After a glFrustum, glMultMatrix or glLoadMatrix: full 4 × 4 products. (Mesa analyses
    /// a loaded or multiplied matrix again when a draw needs it and may call it affine from
    /// then on; only a non-finite rotation or ortho after that tells the two apart. Not
    /// followed.)
    General,
}

/// A matrix command's product onto the current matrix `m` (of `kind`): the new matrix and
/// its kind.
pub fn multiply(m: Mat4, kind: MatrixKind, n: Mat4, product: Product) -> (Mat4, MatrixKind) {
    match (kind, product) {
        (MatrixKind::Affine, Product::AffineKept) => (affine_product(m, n), MatrixKind::Affine),
        _ => (m * n, MatrixKind::General),
    }
}

/// What a command's matrix does to the kind of the matrix it multiplies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Product {
    /// glRotate, glOrtho: an affine matrix stays affine (Mesa's 3 × 4 product).
    AffineKept,
    /// glFrustum, glMultMatrix: the result is general (the full product).
    General,
}

/// Mesa's `matmul34`: the top three rows of m·n with the bottom row set to (0, 0, 0, 1).
fn affine_product(m: Mat4, n: Mat4) -> Mat4 {
    let a = m.to_cols_array();
    let b = n.to_cols_array();
    let at = |row: usize, col: usize| a[col * 4 + row];
    let bt = |row: usize, col: usize| b[col * 4 + row];
    let mut p = [0.0f32; 16];
    for i in 0..3 {
        let (a0, a1, a2, a3) = (at(i, 0), at(i, 1), at(i, 2), at(i, 3));
        for j in 0..3 {
            p[j * 4 + i] = a0 * bt(0, j) + a1 * bt(1, j) + a2 * bt(2, j);
        }
        p[12 + i] = a0 * bt(0, 3) + a1 * bt(1, 3) + a2 * bt(2, 3) + a3;
    }
    p[15] = 1.0;
    Mat4::from_cols_array(&p)
}

/// glTranslate in place: m₁₂₊ᵢ = m_i·x + m₄₊ᵢ·y + m₈₊ᵢ·z + m₁₂₊ᵢ for every row i.
pub fn translate(m: Mat4, v: Vec3) -> Mat4 {
    let mut a = m.to_cols_array();
    for i in 0..4 {
        // (m_i·x + m₄₊ᵢ·y + m₈₊ᵢ·z) + m₁₂₊ᵢ: one addition, commutative, so the same bits.
        a[12 + i] += a[i] * v.x + a[4 + i] * v.y + a[8 + i] * v.z;
    }
    Mat4::from_cols_array(&a)
}

/// glScale in place: the first three columns times x, y and z.
pub fn scale(m: Mat4, v: Vec3) -> Mat4 {
    let mut a = m.to_cols_array();
    for (col, f) in [v.x, v.y, v.z].into_iter().enumerate() {
        for i in 0..4 {
            a[col * 4 + i] *= f;
        }
    }
    Mat4::from_cols_array(&a)
}

/// glRotate's matrix (θ in degrees, counter-clockwise looking down −axis), or None when
/// the command leaves the matrix as it is: an angle of 0, or an axis shorter than 10⁻⁴ (a
/// NaN axis is not shorter: it gives a NaN rotation, as on Mesa). s and c are the float
/// sine and cosine of θ·π/180 taken in double precision.
pub fn rotation(angle_deg: f32, axis: Vec3) -> Option<Mat4> {
    if angle_deg == 0.0 {
        return None;
    }
    let a = (f64::from(angle_deg) * std::f64::consts::PI / 180.0) as f32;
    let (s, c) = (a.sin(), a.cos());
    // Columns of the block for the two axes the rotation turns (i → j).
    let block = |i: usize, j: usize, s: f32| {
        let mut m = Mat4::IDENTITY;
        m.col_mut(i)[i] = c;
        m.col_mut(j)[j] = c;
        m.col_mut(i)[j] = s;
        m.col_mut(j)[i] = -s;
        m
    };
    // About the negative axis: the opposite turn.
    let toward = |v: f32| if v < 0.0 { -s } else { s };
    let Vec3 { x, y, z } = axis;
    match (x == 0.0, y == 0.0, z == 0.0) {
        (true, true, false) => return Some(block(0, 1, toward(z))),
        (true, false, true) => return Some(block(2, 0, toward(y))),
        (false, true, true) => return Some(block(1, 2, toward(x))),
        _ => {}
    }
    let mag = (x * x + y * y + z * z).sqrt();
    if mag <= 1.0e-4 {
        return None;
    }
    let (x, y, z) = (x / mag, y / mag, z / mag);
    let (xx, yy, zz, xy, yz, zx) = (x * x, y * y, z * z, x * y, y * z, z * x);
    let (xs, ys, zs) = (x * s, y * s, z * s);
    let one_c = 1.0 - c;
    // Row-major as Mesa writes it: M(row, col).
    let rows = [
        [one_c * xx + c, one_c * xy - zs, one_c * zx + ys],
        [one_c * xy + zs, one_c * yy + c, one_c * yz - xs],
        [one_c * zx - ys, one_c * yz + xs, one_c * zz + c],
    ];
    let mut m = Mat4::IDENTITY;
    for (row, values) in rows.iter().enumerate() {
        for (col, v) in values.iter().enumerate() {
            m.col_mut(col)[row] = *v;
        }
    }
    Some(m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec4;

    #[test]
    fn rotation_is_counter_clockwise_about_the_axis() {
        let r = rotation(90.0, Vec3::new(0.0, 0.0, 2.0)).unwrap();
        assert!((r * Vec4::X).abs_diff_eq(Vec4::Y, 1e-6));
        let r = rotation(120.0, Vec3::ONE).unwrap();
        assert!((r * Vec4::X).abs_diff_eq(Vec4::Y, 1e-6));
        assert_eq!(rotation(30.0, Vec3::ZERO), None);
        assert_eq!(rotation(30.0, Vec3::splat(1e-5)), None);
        assert_eq!(rotation(0.0, Vec3::X), None);
        assert!(rotation(30.0, Vec3::new(f32::NAN, 0.0, 1.0))
            .unwrap()
            .is_nan());
    }

    #[test]
    fn an_affine_product_keeps_the_bottom_row_where_the_full_one_spreads_a_nan() {
        let r = rotation(f32::NAN, Vec3::Z).unwrap();
        let (m, kind) = multiply(Mat4::IDENTITY, MatrixKind::Affine, r, Product::AffineKept);
        assert_eq!(kind, MatrixKind::Affine);
        assert_eq!(m.row(3), Vec4::W);
        let (m, kind) = multiply(Mat4::IDENTITY, MatrixKind::General, r, Product::AffineKept);
        assert_eq!(kind, MatrixKind::General);
        assert!(m.row(3).is_nan());
    }

    #[test]
    fn finite_products_agree_and_in_place_commands_keep_signed_zeros() {
        let m = Mat4::from_cols_array(&[
            1.5, -0.25, 0.5, 0.0, 0.75, 2.0, -1.0, 0.0, 0.1, 0.3, 0.9, 0.0, 4.0, -5.0, 6.0, 1.0,
        ]);
        let n = rotation(33.0, Vec3::new(0.2, 0.7, -0.1)).unwrap();
        assert_eq!(affine_product(m, n), m * n);
        let s = scale(Mat4::IDENTITY, Vec3::new(0.3, 1.7, -2.2));
        assert!(s.col(2)[3].is_sign_negative(), "0·(−2.2) is −0");
        let t = translate(Mat4::IDENTITY, Vec3::new(f32::INFINITY, 0.0, 0.0));
        assert_eq!(t.col(0), Vec4::X, "the first columns are untouched");
    }
}
