//! `Precision::Fixed8` texture combine, op by op, against the stated rules of
//! `ff::precision` (the contract): for REPLACE, MODULATE, ADD, ADD_SIGNED, INTERPOLATE,
//! SUBTRACT, DOT3_RGB and DOT3_RGBA at RGB_SCALE / ALPHA_SCALE 1, 2 and 4, every operand
//! triple over the boundary values 0, 1, 64, 127, 128, 129, 191, 254, 255 (the ends, the ½
//! tie 127/128/129, the quarter points where the widened factor c + (c >> 7) changes) is
//! rendered on the GPU and compared with `precision::combine_rgb` / `combine_component`
//! bit for bit (tolerance 0, every channel of every pixel).
//!
//! Layout: texture n (unit n, n = 0, 1, 2) holds argument n, one RGBA8 texel per pixel; unit
//! 1 combines TEXTURE0, TEXTURE1 and TEXTURE2 (crossbar), unit 0 and unit 2 pass values on
//! (REPLACE of their texel, then COMBINE REPLACE of PREVIOUS). One row per function × scale;
//! the 729 triples fill the four channels of 183 pixels.

mod fidelity;
mod support;

use fidelity::{run_one, Frame};
use fixedfunc::ff::precision::{combine_component, combine_rgb};
use fixedfunc::ff::CombineFunc;
use fixedfunc::vocab::{PipelineKind, Precision};

const VALUES: [u8; 9] = [0, 1, 64, 127, 128, 129, 191, 254, 255];
const WIDTH: usize = 183;

const FUNCS: [(CombineFunc, &str); 8] = [
    (CombineFunc::Replace, "GL_REPLACE"),
    (CombineFunc::Modulate, "GL_MODULATE"),
    (CombineFunc::Add, "GL_ADD"),
    (CombineFunc::AddSigned, "GL_ADD_SIGNED"),
    (CombineFunc::Interpolate, "GL_INTERPOLATE"),
    (CombineFunc::Subtract, "GL_SUBTRACT"),
    (CombineFunc::Dot3Rgb, "GL_DOT3_RGB"),
    (CombineFunc::Dot3Rgba, "GL_DOT3_RGBA"),
];
const SCALES: [u32; 3] = [1, 2, 4];

/// Texel p of argument n: channel c carries the n-th value of triple 4p + c.
fn arguments() -> [Vec<[u8; 4]>; 3] {
    std::array::from_fn(|n| {
        (0..WIDTH)
            .map(|p| {
                std::array::from_fn(|c| {
                    let t = 4 * p + c;
                    if t >= VALUES.len().pow(3) {
                        return 0;
                    }
                    let digit = [t / 81, t / 9 % 9, t % 9][n];
                    VALUES[digit]
                })
            })
            .collect()
    })
}

/// DOT3 has no ALPHA form: its rows combine alpha with MODULATE (DOT3_RGBA ignores it).
fn alpha_func(func: CombineFunc) -> (CombineFunc, &'static str) {
    match func {
        CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => (CombineFunc::Modulate, "GL_MODULATE"),
        f => FUNCS.into_iter().find(|(g, _)| *g == f).expect("listed"),
    }
}

fn texture(unit: usize, texels: &[[u8; 4]]) -> String {
    let data: Vec<String> = texels.iter().flatten().map(u8::to_string).collect();
    format!(
        "glActiveTexture(GL_TEXTURE{unit});
glBindTexture(GL_TEXTURE_2D, {});
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, {WIDTH}, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){{{}}});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glEnable(GL_TEXTURE_2D);
",
        unit + 1,
        data.join(",")
    )
}

fn script(args: &[Vec<[u8; 4]>; 3]) -> String {
    let rows = FUNCS.len() * SCALES.len();
    let mut s = format!(
        "glClearColor(0, 0, 0, 0);\nglClear(GL_COLOR_BUFFER_BIT);\n{}",
        fidelity::ortho(WIDTH as u32, rows as u32)
    );
    for (n, a) in args.iter().enumerate() {
        s += &texture(n, a);
    }
    s += "glActiveTexture(GL_TEXTURE0);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
glActiveTexture(GL_TEXTURE2);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_REPLACE);
glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PREVIOUS);
glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PREVIOUS);
glActiveTexture(GL_TEXTURE1);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
";
    for a in 0..3 {
        s += &format!(
            "glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE{a}_RGB, GL_TEXTURE{a});
glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND{a}_RGB, GL_SRC_COLOR);
glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE{a}_ALPHA, GL_TEXTURE{a});
glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND{a}_ALPHA, GL_SRC_ALPHA);
"
        );
    }
    let mut row = 0;
    for (func, name) in FUNCS {
        for scale in SCALES {
            s += &format!(
                "glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, {name});
glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, {});
glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, {scale});
glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, {scale});
glBegin(GL_QUADS);
",
                alpha_func(func).1
            );
            for (x, y) in [(0, row), (WIDTH, row), (WIDTH, row + 1), (0, row + 1)] {
                let st = if x == 0 { 0 } else { 1 };
                for unit in 0..3 {
                    s += &format!("glMultiTexCoord2f(GL_TEXTURE{unit}, {st}, 0.5f); ");
                }
                s += &format!("glVertex2f({x}, {y});\n");
            }
            s += "glEnd();\n";
            row += 1;
        }
    }
    s
}

/// What the stated rules give for pixel p of a row.
fn expected(args: &[Vec<[u8; 4]>; 3], p: usize, func: CombineFunc, scale: u32) -> [u8; 4] {
    let rgb = combine_rgb(
        func,
        std::array::from_fn(|n| [args[n][p][0], args[n][p][1], args[n][p][2]]),
        scale,
    );
    let alpha = match func {
        CombineFunc::Dot3Rgba => rgb[0],
        _ => combine_component(alpha_func(func).0, args.clone().map(|a| a[p][3]), scale),
    };
    [rgb[0], rgb[1], rgb[2], alpha]
}

#[test]
fn fixed8_combine_matches_the_stated_rules_bit_for_bit() {
    let args = arguments();
    let commands = fidelity::parse(&script(&args));
    let rows = (FUNCS.len() * SCALES.len()) as u32;
    for backend in support::HEADLESS {
        let out = run_one(
            PipelineKind::Emulate,
            Precision::Fixed8,
            backend,
            Frame::new(WIDTH as u32, rows),
            &commands,
        );
        let mut mismatches = Vec::new();
        let mut row = 0;
        for (func, _) in FUNCS {
            for scale in SCALES {
                for p in 0..WIDTH {
                    let want = expected(&args, p, func, scale);
                    let got = out.image.get_pixel(p as u32, rows - 1 - row).0;
                    if got != want {
                        let a: Vec<[u8; 4]> = args.iter().map(|a| a[p]).collect();
                        mismatches.push(format!(
                            "{func:?} ×{scale} args {a:?}: GPU {got:?}, rule {want:?}"
                        ));
                    }
                }
                row += 1;
            }
        }
        assert!(
            mismatches.is_empty(),
            "{backend}: {} of {} pixels differ from the Fixed8 rules; first: {:#?}",
            mismatches.len(),
            WIDTH * rows as usize,
            &mismatches[..mismatches.len().min(8)]
        );
    }
}
