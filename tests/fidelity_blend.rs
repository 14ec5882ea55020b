//! GL 1.4 / ARB_imaging blending (GL 1.5 §4.1.7): glBlendColor's CONSTANT factors,
//! glBlendEquation (FUNC_SUBTRACT, FUNC_REVERSE_SUBTRACT, MIN, MAX), glBlendFuncSeparate
//! and SRC_ALPHA_SATURATE, emulated against native on both headless backends, exact, and
//! each pixel against the formula computed here on unorm8 values (±1 for the rounding of
//! the blend unit). A wrong factor or equation fails its column by far more than 1.

mod fidelity;
mod support;

use fidelity::{compare, ortho, Frame};
use support::Tolerance;

/// The fragment colour and the cleared destination.
const S: [f64; 4] = [0.6, 0.3, 0.9, 0.5];
const D: [f64; 4] = [0.2, 0.4, 0.6, 0.8];
/// glBlendColor.
const K: [f64; 4] = [0.25, 0.5, 0.75, 0.25];

fn v(c: [f64; 4]) -> String {
    c.map(|x| format!("{x}")).join(", ")
}

/// (state calls, expected colour) per column.
fn cases() -> Vec<(&'static str, [f64; 4])> {
    let (s, d, k) = (S, D, K);
    let each = |f: &dyn Fn(usize) -> f64| -> [f64; 4] { std::array::from_fn(f) };
    let sat = (s[3]).min(1.0 - d[3]);
    vec![
        (
            "glBlendFuncSeparate(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR, GL_ONE, GL_ZERO);",
            each(&|c| {
                if c < 3 {
                    s[c] * k[c] + d[c] * (1.0 - k[c])
                } else {
                    s[3]
                }
            }),
        ),
        (
            "glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);",
            each(&|c| s[c] * k[3] + d[c] * (1.0 - k[3])),
        ),
        (
            "glBlendFunc(GL_ONE, GL_ONE); glBlendEquation(GL_FUNC_SUBTRACT);",
            each(&|c| s[c] - d[c]),
        ),
        (
            "glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);",
            each(&|c| d[c] - s[c]),
        ),
        (
            "glBlendFunc(GL_ZERO, GL_ZERO); glBlendEquation(GL_MIN);",
            each(&|c| s[c].min(d[c])),
        ),
        ("glBlendEquation(GL_MAX);", each(&|c| s[c].max(d[c]))),
        (
            "glBlendEquation(GL_FUNC_ADD); glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE);",
            each(&|c| {
                if c < 3 {
                    s[c] * sat + d[c]
                } else {
                    s[3] + d[3]
                }
            }),
        ),
        (
            "glBlendFuncSeparate(GL_ZERO, GL_ONE, GL_ONE, GL_ZERO);",
            each(&|c| if c < 3 { d[c] } else { s[3] }),
        ),
    ]
}

#[test]
fn blend_equations_and_constant_factors() {
    let cases = cases();
    let n = cases.len() as u32;
    let mut src = format!(
        "glViewport(0, 0, {n}, 1);\n{}glClearColor({});\nglClear(GL_COLOR_BUFFER_BIT);\n\
         glEnable(GL_BLEND);\nglBlendColor({});\nglColor4f({});\n",
        ortho(n, 1),
        v(D),
        v(K),
        v(S)
    );
    for (i, (calls, _)) in cases.iter().enumerate() {
        src += &format!("{calls}\nglRectf({i}, 0, {}, 1);\n", i + 1);
    }
    for p in compare("blend", &src, Frame::new(n, 1), Tolerance::EXACT) {
        for out in [&p.emulate, &p.native] {
            for (i, (calls, want)) in cases.iter().enumerate() {
                let want = want.map(fidelity::unorm8);
                let got = out.image.get_pixel(i as u32, 0).0;
                let ok = (0..4).all(|c| got[c].abs_diff(want[c]) <= 1);
                assert!(
                    ok,
                    "{} column {i} ({calls}): {got:?}, expected {want:?}",
                    p.backend
                );
            }
        }
    }
}
