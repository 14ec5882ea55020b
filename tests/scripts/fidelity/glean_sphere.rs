//! The sphere of the three texgen scripts (`texgen_object_linear.c`, `texgen_eye_linear.c`,
//! `texgen_sphere_map.c`): glean's texgen test draws a sphere of radius 9.9 with 32 slices
//! and 16 stacks; the scripts bake it as one `glBegin(GL_QUADS)` … `glEnd()` block, the same
//! block in all three. This is the generator of that block; `tests/fidelity_sphere.rs`
//! asserts the checked-in scripts equal its output (so they cannot drift) and, with
//! `FIXEDFUNC_BLESS=1`, rewrites them.
//!
//! The rule. Stack i (0..=16) sits at polar angle θᵢ = π·(16 − i)/16 from +z, so stack 0 is
//! the −z pole and stack 16 the +z pole; slice j (0..=32) at azimuth φⱼ = 2π·j/32. The unit
//! normal is n = (sin θ cos φ, sin θ sin φ, cos θ) and the vertex 9.9·n. One quad per
//! (stack i, slice j), stacks outer, slices inner, one line each, its corners
//! (i, j), (i, j+1), (i+1, j+1), (i+1, j), each as `glNormal3f` (6 decimals) then
//! `glVertex3f` (5 decimals). Everything is computed in f64 and printed by Rust's
//! correctly rounded formatting, which keeps the sign of a negative zero — the file's
//! `-0.00000f`s are the tiny negative values of sin 2π and of 0 × (a negative cosine).

use std::fmt::Write as _;

pub const RADIUS: f64 = 9.9;
pub const SLICES: u32 = 32;
pub const STACKS: u32 = 16;

/// The normal and the vertex of stack `i`, slice `j`.
fn corner(i: u32, j: u32) -> ([f64; 3], [f64; 3]) {
    let pi = std::f64::consts::PI;
    let theta = pi * f64::from(STACKS - i) / f64::from(STACKS);
    let phi = 2.0 * pi * f64::from(j) / f64::from(SLICES);
    let n = [
        theta.sin() * phi.cos(),
        theta.sin() * phi.sin(),
        theta.cos(),
    ];
    (n, n.map(|c| RADIUS * c))
}

/// The block, from `glBegin(GL_QUADS);` to `glEnd();` and its newline.
pub fn quads() -> String {
    let mut out = String::from("glBegin(GL_QUADS);\n");
    for i in 0..STACKS {
        for j in 0..SLICES {
            let corners = [(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)];
            let calls: Vec<String> = corners
                .iter()
                .map(|&(a, b)| {
                    let (n, v) = corner(a, b);
                    format!(
                        "glNormal3f({:.6}f, {:.6}f, {:.6}f); glVertex3f({:.5}f, {:.5}f, {:.5}f);",
                        n[0], n[1], n[2], v[0], v[1], v[2]
                    )
                })
                .collect();
            let _ = writeln!(out, "{}", calls.join(" "));
        }
    }
    out.push_str("glEnd();\n");
    out
}

/// The scripts that draw the sphere, by file stem.
pub const SCRIPTS: [&str; 3] = [
    "texgen_object_linear",
    "texgen_eye_linear",
    "texgen_sphere_map",
];
