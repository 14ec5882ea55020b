//! Texture environment fidelity: piglit gl-1.3/texture-env (81 colours × base formats ×
//! modes, blended over grey), ext_texture_env_combine/combine.c (modes, sources, operands,
//! scales with a stride; DOT3 tolerance 0.02), texturing/crossbar, and the bugs other
//! emulators have: INTERPOLATE argument order and the per-stage clamp (Regal, H13/H14), DOT3
//! scale handling, an invalid TexEnv mode keeping the previous one. Each case runs on the
//! emulated and the native path on EGL and OSMesa and is checked against a CPU model of the
//! GL 1.3 tables, with stored texels (k/255) as the model's inputs.

mod fidelity;
mod support;

use fidelity::{compare, ortho, probe_rgb, unorm8, Frame};
use fixedfunc::vocab::{PipelineKind, Precision};
use support::Tolerance;

/// piglit's 0.01 in 8-bit steps, as `piglit_set_tolerance_for_bits(8)` sets it: 3/255.
const TOL8: u8 = 3;

/// {0, 0.5, 1}⁴ as stored bytes (0.5 is 128 in a texture; the same byte as a colour).
fn colours() -> Vec<[u8; 4]> {
    let v = [0u8, 128, 255];
    (0..81)
        .map(|i| [v[i % 3], v[i / 3 % 3], v[i / 9 % 3], v[i / 27]])
        .collect()
}

fn f(b: u8) -> f64 {
    f64::from(b) / 255.0
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Base {
    Alpha,
    Luminance,
    LuminanceAlpha,
    Intensity,
    Rgb,
    Rgba,
}

impl Base {
    const ALL: [Base; 6] = [
        Base::Alpha,
        Base::Luminance,
        Base::LuminanceAlpha,
        Base::Intensity,
        Base::Rgb,
        Base::Rgba,
    ];

    /// (internal format, external format, bytes of one texel from an RGBA colour).
    fn upload(self, c: [u8; 4]) -> (&'static str, &'static str, Vec<u8>) {
        match self {
            Base::Alpha => ("GL_ALPHA8", "GL_ALPHA", vec![c[3]]),
            Base::Luminance => ("GL_LUMINANCE8", "GL_LUMINANCE", vec![c[0]]),
            Base::LuminanceAlpha => (
                "GL_LUMINANCE8_ALPHA8",
                "GL_LUMINANCE_ALPHA",
                vec![c[0], c[3]],
            ),
            Base::Intensity => ("GL_INTENSITY8", "GL_LUMINANCE", vec![c[0]]),
            Base::Rgb => ("GL_RGB8", "GL_RGB", c[..3].to_vec()),
            Base::Rgba => ("GL_RGBA8", "GL_RGBA", c.to_vec()),
        }
    }

    /// The texel as GL 1.3 table 3.15 assigns it: (colour, alpha) components, `None` where
    /// the base format has none.
    fn components(self, c: [u8; 4]) -> (Option<[f64; 3]>, Option<f64>) {
        let l = f(c[0]);
        match self {
            Base::Alpha => (None, Some(f(c[3]))),
            Base::Luminance => (Some([l; 3]), None),
            Base::LuminanceAlpha => (Some([l; 3]), Some(f(c[3]))),
            Base::Intensity => (Some([l; 3]), Some(l)),
            Base::Rgb => (Some([f(c[0]), f(c[1]), f(c[2])]), None),
            Base::Rgba => (Some([f(c[0]), f(c[1]), f(c[2])]), Some(f(c[3]))),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Mode {
    Replace,
    Modulate,
    Decal,
    Blend,
    Add,
}

impl Mode {
    fn gl(self) -> &'static str {
        match self {
            Mode::Replace => "GL_REPLACE",
            Mode::Modulate => "GL_MODULATE",
            Mode::Decal => "GL_DECAL",
            Mode::Blend => "GL_BLEND",
            Mode::Add => "GL_ADD",
        }
    }
}

/// GL 1.3 tables 3.22 and 3.23: the colour of texture unit 0 for fragment colour `cf`,
/// texel `t` of format `base`, env colour `cc`.
fn tex_env(mode: Mode, base: Base, cf: [f64; 4], t: [u8; 4], cc: [f64; 4]) -> [f64; 4] {
    let (ct, at) = base.components(t);
    let mut out = cf;
    for i in 0..3 {
        out[i] = match (mode, ct) {
            (_, None) => cf[i],
            (Mode::Replace, Some(c)) => c[i],
            (Mode::Modulate, Some(c)) => cf[i] * c[i],
            (Mode::Decal, Some(c)) => match at {
                Some(a) => cf[i] * (1.0 - a) + c[i] * a,
                None => c[i],
            },
            (Mode::Blend, Some(c)) => cf[i] * (1.0 - c[i]) + cc[i] * c[i],
            (Mode::Add, Some(c)) => (cf[i] + c[i]).min(1.0),
        };
    }
    out[3] = match (mode, at, base) {
        (_, None, _) | (Mode::Decal, _, _) => cf[3],
        (Mode::Replace, Some(a), _) => a,
        (Mode::Blend, Some(a), Base::Intensity) => cf[3] * (1.0 - a) + cc[3] * a,
        (Mode::Add, Some(a), Base::Intensity) => (cf[3] + a).min(1.0),
        (_, Some(a), _) => cf[3] * a,
    };
    out
}

/// texture-env: rows are the 81 fragment colours, columns the 81 texels (one texel each,
/// NEAREST), blended SRC_ALPHA over 0.5 grey as glean does.
fn texture_env_script(base: Base, mode: Mode, env: [u8; 4]) -> String {
    let cs = colours();
    let (internal, external, _) = base.upload(cs[0]);
    let texels: Vec<String> = cs
        .iter()
        .flat_map(|&c| base.upload(c).2)
        .map(|b| b.to_string())
        .collect();
    let mut s = format!(
        "glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
glClear(GL_COLOR_BUFFER_BIT);
{}glBindTexture(GL_TEXTURE_2D, 1);
glTexImage2D(GL_TEXTURE_2D, 0, {internal}, 81, 1, 0, {external}, GL_UNSIGNED_BYTE, (GLubyte[]){{{}}});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, {});
glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, (GLfloat[]){{{}, {}, {}, {}}});
glEnable(GL_TEXTURE_2D);
glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
glEnable(GL_BLEND);
glBegin(GL_QUADS);
",
        ortho(81, 81),
        texels.join(","),
        mode.gl(),
        f(env[0]),
        f(env[1]),
        f(env[2]),
        f(env[3]),
    );
    for (row, c) in cs.iter().enumerate() {
        s += &format!(
            "glColor4f({}, {}, {}, {});\nglTexCoord2f(0, 0.5f); glVertex2f(0, {row}); glTexCoord2f(1, 0.5f); glVertex2f(81, {row}); glTexCoord2f(1, 0.5f); glVertex2f(81, {}); glTexCoord2f(0, 0.5f); glVertex2f(0, {});\n",
            f(c[0]),
            f(c[1]),
            f(c[2]),
            f(c[3]),
            row + 1,
            row + 1
        );
    }
    s + "glEnd();\n"
}

/// gl-1.3/texture-env: every fragment colour × texel for each base format and mode (DECAL
/// on RGB/RGBA only), BLEND with every 20th colour as env colour (glean: every 5th). Each
/// pixel is checked against the table formula blended over grey, tol 3/255 per RGB channel
/// (piglit 0.01); emulate and native images agree within the same 3/255.
#[test]
fn texture_env_81_colours_by_base_format_and_mode() {
    let cs = colours();
    let grey = f(128);
    for base in Base::ALL {
        for mode in [
            Mode::Replace,
            Mode::Modulate,
            Mode::Decal,
            Mode::Blend,
            Mode::Add,
        ] {
            if mode == Mode::Decal && !matches!(base, Base::Rgb | Base::Rgba) {
                continue;
            }
            let envs: Vec<[u8; 4]> = if mode == Mode::Blend {
                cs.iter().step_by(20).copied().collect()
            } else {
                vec![[0, 0, 0, 0]]
            };
            for env in envs {
                let name = format!("texenv-{base:?}-{mode:?}-{env:?}");
                let tol = Tolerance {
                    per_channel: TOL8,
                    max_bad_pixels: 0,
                };
                let src = texture_env_script(base, mode, env);
                for p in compare(&name, &src, Frame::new(81, 81), tol) {
                    for out in [&p.emulate, &p.native] {
                        for (row, c) in cs.iter().enumerate() {
                            for (col, t) in cs.iter().enumerate() {
                                let cf = c.map(f);
                                let r = tex_env(mode, base, cf, *t, env.map(f));
                                let e: [u8; 3] = std::array::from_fn(|i| {
                                    unorm8(r[i] * r[3] + grey * (1.0 - r[3]))
                                });
                                probe_rgb(&out.image, col as u32, row as u32, e, TOL8);
                            }
                        }
                    }
                }
            }
        }
    }
}

/// combine.c's fragment colour and unit-0 env colour.
const FRAG: [f64; 4] = [0.0, 0.25, 0.5, 0.75];
const ENV: [f64; 4] = [0.25, 0.5, 0.75, 1.0];

const SOURCES: [&str; 4] = [
    "GL_TEXTURE",
    "GL_CONSTANT",
    "GL_PRIMARY_COLOR",
    "GL_PREVIOUS",
];
const RGB_OPS: [&str; 4] = [
    "GL_SRC_COLOR",
    "GL_ONE_MINUS_SRC_COLOR",
    "GL_SRC_ALPHA",
    "GL_ONE_MINUS_SRC_ALPHA",
];
const RGB_FUNCS: [&str; 8] = [
    "GL_REPLACE",
    "GL_MODULATE",
    "GL_ADD",
    "GL_ADD_SIGNED",
    "GL_INTERPOLATE",
    "GL_SUBTRACT",
    "GL_DOT3_RGB",
    "GL_DOT3_RGBA",
];

/// One COMBINE state of unit 0: functions, sources and operands of Arg0..2, scales.
#[derive(Clone, Copy, Debug)]
struct Combine {
    rgb: usize,
    alpha: usize,
    src_rgb: [usize; 3],
    op_rgb: [usize; 3],
    src_a: [usize; 3],
    op_a: [usize; 3],
    rgb_scale: f64,
    alpha_scale: f64,
}

/// The combine function on three arguments (GL 1.3 table 3.24).
fn combine_fn(func: usize, a: [f64; 3]) -> f64 {
    match func {
        0 => a[0],
        1 => a[0] * a[1],
        2 => a[0] + a[1],
        3 => a[0] + a[1] - 0.5,
        4 => a[0] * a[2] + a[1] * (1.0 - a[2]),
        _ => a[0] - a[1],
    }
}

/// The CPU model of combine.c: arguments from the sources and operands, the function, the
/// scale, then the clamp to [0, 1]; DOT3_RGBA puts the dot product in alpha too (its scale
/// is RGB_SCALE, so the generator gives DOT3_RGBA equal scales).
fn combine_model(c: &Combine, tex: [f64; 4]) -> [f64; 4] {
    let src = |s: usize| match s {
        0 => tex,
        1 => ENV,
        _ => FRAG,
    };
    let rgb_arg = |i: usize, ch: usize| {
        let v = src(c.src_rgb[i]);
        match c.op_rgb[i] {
            0 => v[ch],
            1 => 1.0 - v[ch],
            2 => v[3],
            _ => 1.0 - v[3],
        }
    };
    let a_arg = |i: usize| {
        let v = src(c.src_a[i])[3];
        if c.op_a[i] == 0 {
            v
        } else {
            1.0 - v
        }
    };
    let mut out = [0.0; 4];
    if c.rgb >= 6 {
        let dot: f64 = (0..3)
            .map(|ch| (rgb_arg(0, ch) - 0.5) * (rgb_arg(1, ch) - 0.5))
            .sum::<f64>()
            * 4.0;
        let v = (dot * c.rgb_scale).clamp(0.0, 1.0);
        out = [v; 4];
    } else {
        for (ch, o) in out.iter_mut().enumerate().take(3) {
            let a = [rgb_arg(0, ch), rgb_arg(1, ch), rgb_arg(2, ch)];
            *o = (combine_fn(c.rgb, a) * c.rgb_scale).clamp(0.0, 1.0);
        }
    }
    if c.rgb != 7 {
        let a = [a_arg(0), a_arg(1), a_arg(2)];
        out[3] = (combine_fn(c.alpha, a) * c.alpha_scale).clamp(0.0, 1.0);
    }
    out
}

/// A deterministic stride through the state space (xorshift), `n` states.
fn combine_states(n: usize, seed: u64) -> Vec<Combine> {
    let mut x = seed;
    let mut next = move |m: usize| {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x % m as u64) as usize
    };
    let scales = [1.0, 2.0, 4.0];
    (0..n)
        .map(|i| {
            let rgb = i % 8;
            let rgb_scale = scales[next(3)];
            Combine {
                rgb,
                alpha: next(6),
                src_rgb: [next(4), next(4), next(4)],
                op_rgb: [next(4), next(4), next(4)],
                src_a: [next(4), next(4), next(4)],
                op_a: [next(2), next(2), next(2)],
                rgb_scale,
                alpha_scale: if rgb == 7 { rgb_scale } else { scales[next(3)] },
            }
        })
        .collect()
}

/// The script: one 1×1 texel `tex` on unit 0, then per state its TexEnv calls and a quad on
/// pixel (i mod 32, i div 32).
fn combine_script(states: &[Combine], tex: [u8; 4]) -> String {
    let alpha_funcs = &RGB_FUNCS[..6];
    let mut s = format!(
        "glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
{}glBindTexture(GL_TEXTURE_2D, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){{{}, {}, {}, {}}});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glEnable(GL_TEXTURE_2D);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, (GLfloat[]){{0.25f, 0.5f, 0.75f, 1}});
glColor4f(0, 0.25f, 0.5f, 0.75f);
",
        ortho(32, 32),
        tex[0],
        tex[1],
        tex[2],
        tex[3]
    );
    for (i, c) in states.iter().enumerate() {
        s += &format!(
            "glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, {});\nglTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, {});\nglTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, {});\nglTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, {});\n",
            RGB_FUNCS[c.rgb], alpha_funcs[c.alpha], c.rgb_scale, c.alpha_scale
        );
        for a in 0..3 {
            s += &format!(
                "glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE{a}_RGB, {});\nglTexEnvi(GL_TEXTURE_ENV, GL_OPERAND{a}_RGB, {});\nglTexEnvi(GL_TEXTURE_ENV, GL_SOURCE{a}_ALPHA, {});\nglTexEnvi(GL_TEXTURE_ENV, GL_OPERAND{a}_ALPHA, {});\n",
                SOURCES[c.src_rgb[a]], RGB_OPS[c.op_rgb[a]], SOURCES[c.src_a[a]], RGB_OPS[2 + c.op_a[a]]
            );
        }
        let (x, y) = (i % 32, i / 32);
        s += &format!(
            "glBegin(GL_QUADS);\nglVertex2f({x}, {y}); glVertex2f({}, {y}); glVertex2f({}, {}); glVertex2f({x}, {});\nglEnd();\n",
            x + 1,
            x + 1,
            y + 1,
            y + 1
        );
    }
    s
}

/// ext_texture_env_combine/combine.c on unit 0: 256 states (each its own program on both
/// paths, so the stride is kept short) striding through functions,
/// sources, operands and RGB/ALPHA scales {1, 2, 4}, with two of combine.c's texture
/// colours. Each pixel against the model: tol 0.01 (3/255), DOT3 0.02 (5/255) as piglit;
/// emulate vs native images within 2/255.
#[test]
fn combine_modes_sources_operands_and_scales() {
    for (seed, tex) in [
        (0x9e37_79b9_u64, [64u8, 128, 191, 255]),
        (0x1234_5678, [255, 191, 0, 64]),
    ] {
        let states = combine_states(256, seed);
        let texf = tex.map(f);
        let tol = Tolerance {
            per_channel: 2,
            max_bad_pixels: 0,
        };
        let src = combine_script(&states, tex);
        for p in compare(&format!("combine-{seed:x}"), &src, Frame::new(32, 32), tol) {
            for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
                for (i, c) in states.iter().enumerate() {
                    let e = combine_model(c, texf).map(unorm8);
                    let tol = if c.rgb >= 6 { 5 } else { TOL8 };
                    let got = out.image.get_pixel(i as u32 % 32, 31 - i as u32 / 32).0;
                    let ok = got.iter().zip(e).all(|(&g, e)| g.abs_diff(e) <= tol);
                    assert!(
                        ok,
                        "{} {path} state {i} {c:?}: {got:?}, model {e:?} ± {tol}",
                        p.backend
                    );
                }
            }
        }
    }
}

/// H13, H14, DOT3 scale and texturing/crossbar (`combine_bugs_crossbar.c`, one pixel per
/// case): INTERPOLATE(1, 0, 0.251) = 64; ADD clamped then MODULATE 0.5 = 128; DOT3 × 2 =
/// 127; five crossbar cases 0.5 (127 or 128). Tolerance 2/255 per RGB channel (below
/// piglit's 0.01 and far from each bug's value: 191, 191, 64 or 32); paths within 1/255.
#[test]
fn interpolate_order_stage_clamp_dot3_scale_and_crossbar() {
    let src = fidelity::script_file("combine_bugs_crossbar");
    let expected: [u8; 8] = [64, 128, 127, 127, 128, 127, 127, 127];
    let tol = Tolerance {
        per_channel: 1,
        max_bad_pixels: 0,
    };
    for p in compare("combine-bugs", &src, Frame::new(8, 1), tol) {
        for out in [&p.emulate, &p.native] {
            for (x, e) in expected.iter().enumerate() {
                probe_rgb(&out.image, x as u32, 0, [*e; 3], 2);
            }
        }
    }
}

/// An invalid TexEnv value (COMBINE_ALPHA = DOT3_RGB, INVALID_ENUM) keeps the previous
/// one on both paths: alpha stays REPLACE(TEXTURE) = 191, not the default MODULATE
/// (191·0.5 = 96) nor anything from DOT3. Exact (tol 0) on alpha.
#[test]
fn invalid_tex_env_value_keeps_the_previous_one() {
    use fixedfunc::ff::GlErrorKind;
    let src = format!(
        "glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
{}glBindTexture(GL_TEXTURE_2D, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){{191, 191, 191, 191}});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glEnable(GL_TEXTURE_2D);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_TEXTURE);
glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB);
glColor4f(1, 1, 1, 0.5f);
glBegin(GL_QUADS);
glVertex2f(0, 0); glVertex2f(1, 0); glVertex2f(1, 1); glVertex2f(0, 1);
glEnd();
",
        ortho(1, 1)
    );
    let commands = fidelity::parse(&src);
    for backend in support::HEADLESS {
        for kind in [PipelineKind::Emulate, PipelineKind::Native] {
            let ctx = support::context(backend, fixedfunc::pipeline::profile(kind));
            let t = support::target(&ctx, 1, 1, fixedfunc::vocab::DepthBits::D24, false);
            let mut p: Box<dyn fixedfunc::pipeline::Pipeline> = match kind {
                PipelineKind::Emulate => Box::new(
                    fixedfunc::pipeline::emulate::EmulatedPipeline::new(&ctx)
                        .unwrap()
                        .with_precision(Precision::Float),
                ),
                PipelineKind::Native => fixedfunc::pipeline::create(kind, &ctx).unwrap(),
            };
            p.execute(&ctx, &commands).expect("execute");
            let err = p.take_gl_error().expect("INVALID_ENUM recorded");
            assert_eq!(err.kind, GlErrorKind::InvalidEnum, "{backend} {kind:?}");
            let img = t.read_color(&ctx).unwrap();
            // RGB: the default COMBINE_RGB MODULATE(TEXTURE, PREVIOUS) = 191 · 1.
            support::probe(&img, 0, 0, [191, 191, 191, 191], 0);
            support::assert_no_gl_error(&ctx);
            p.release(&ctx);
        }
    }
}
