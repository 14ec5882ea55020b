//! The fragment stage: texture lookups (projective, depth compare), the texture environment
//! of each enabled unit in order (GL 1.5 §3.8.13 and ARB_texture_env_combine), the alpha test.
//! Every stage's result is clamped to [0, 1] (H14); INTERPOLATE is a0·a2 + a1·(1 − a2) (H13).

use crate::ff::{
    BaseFormat, Combine, CombineFunc, CombineOperand, CombineSource, CompareFunc, DepthTextureMode,
    TextureTarget,
};
use crate::pipeline::emulate::glsl::GlslWriter;
use crate::pipeline::emulate::key::{EnvKey, FragmentKey, FragmentUnitKey, TexelKey};
use crate::pipeline::emulate::uniforms::UniformSource;

pub fn generate(key: &FragmentKey) -> GlslWriter {
    let mut w = GlslWriter::new();
    let flat = if key.flat { "flat " } else { "" };
    w.declare(&format!("{flat}in vec4 v_color;"));
    w.declare("out vec4 frag_color;");
    if key.two_side {
        w.declare(&format!("{flat}in vec4 v_back_color;"));
        w.line("vec4 primary = gl_FrontFacing ? v_color : v_back_color;");
    } else {
        w.line("vec4 primary = v_color;");
    }
    w.line("primary = clamp(primary, 0.0, 1.0);");
    for unit in &key.units {
        emit_texel(&mut w, unit, key.combiners.is_some());
    }
    w.line("vec4 previous = primary;");
    match &key.combiners {
        Some(c) => super::combiners::emit(&mut w, key, c),
        None => {
            for unit in &key.units {
                emit_env(&mut w, key, unit);
            }
        }
    }
    if let Some(func) = key.alpha_test {
        emit_alpha_test(&mut w, func);
    }
    w.line("frag_color = previous;");
    w
}

fn has_color(base: BaseFormat) -> bool {
    !matches!(base, BaseFormat::Alpha)
}

fn has_alpha(base: BaseFormat) -> bool {
    matches!(
        base,
        BaseFormat::Alpha | BaseFormat::LuminanceAlpha | BaseFormat::Intensity | BaseFormat::Rgba
    )
}

/// The projected coordinates divide by q. Rule for q ≈ 0: |q| is raised to 1e-20 (keeping
/// its sign) and the quotient clamped to ±1e6, so no NaN or Inf reaches a lookup; the
/// wrap mode then decides the texel, as hardware of the era did with huge coordinates.
fn projected(w: &mut GlslWriter) {
    w.declare(
        "vec4 project(vec4 tc) {\n    float q = (abs(tc.w) < 1e-20) ? ((tc.w < 0.0) ? -1e-20 : 1e-20) : tc.w;\n    return vec4(clamp(tc.xyz / q, -1e6, 1e6), q);\n}",
    );
}

/// t{u}: the unit's texel as GL's texture environment sees it — or, for register
/// combiners, as their texture register holds it (depth: (0,0,0,D); compare: (L,L,L,L)).
fn emit_texel(w: &mut GlslWriter, unit: &FragmentUnitKey, combiners: bool) {
    let u = unit.unit;
    w.declare(&format!("in vec4 v_tc{u};"));
    projected(w);
    w.line(format!("vec4 p{u} = project(v_tc{u});"));
    let one_d = unit.target == TextureTarget::Texture1D;
    let (sampler_type, coord) = match (unit.texel, one_d) {
        (TexelKey::Compare(_), false) => (
            "sampler2DShadow",
            format!("vec3(p{u}.xy, clamp(p{u}.z, 0.0, 1.0))"),
        ),
        (TexelKey::Compare(_), true) => (
            "sampler1DShadow",
            format!("vec3(p{u}.x, 0.0, clamp(p{u}.z, 0.0, 1.0))"),
        ),
        (_, false) => ("sampler2D", format!("p{u}.xy")),
        (_, true) => ("sampler1D", format!("p{u}.x")),
    };
    let s = w.uniform_typed(UniformSource::Sampler(u), sampler_type);
    let as_mode = |m: DepthTextureMode, v: &str| match m {
        DepthTextureMode::Luminance => format!("vec4(vec3({v}), 1.0)"),
        DepthTextureMode::Intensity => format!("vec4({v})"),
        DepthTextureMode::Alpha => format!("vec4(0.0, 0.0, 0.0, {v})"),
    };
    match unit.texel {
        // The texture's swizzle already gives (L,L,L,1), (I,I,I,I), (0,0,0,A), (L,L,L,A).
        TexelKey::Color(_) => w.line(format!("vec4 t{u} = texture({s}, {coord});")),
        TexelKey::Depth(_) if combiners => {
            w.line(format!(
                "vec4 t{u} = vec4(0.0, 0.0, 0.0, texture({s}, {coord}).r);"
            ));
        }
        TexelKey::Depth(m) => {
            w.line(format!("float d{u} = texture({s}, {coord}).r;"));
            w.line(format!("vec4 t{u} = {};", as_mode(m, &format!("d{u}"))));
        }
        TexelKey::Compare(m) => {
            // ARB_shadow_ambient: a failing compare gives the fail value instead of 0; with
            // LINEAR filtering the pass fraction f blends: fail + f·(1 − fail).
            let fail = w.uniform(UniformSource::CompareFail(u));
            w.line(format!("float c{u} = texture({s}, {coord});"));
            w.line(format!("c{u} = {fail} + c{u} * (1.0 - {fail});"));
            let m = if combiners {
                DepthTextureMode::Intensity
            } else {
                m
            };
            w.line(format!("vec4 t{u} = {};", as_mode(m, &format!("c{u}"))));
        }
    }
}

fn emit_env(w: &mut GlslWriter, key: &FragmentKey, unit: &FragmentUnitKey) {
    let u = unit.unit;
    let base = unit.texel.env_base();
    let (c, a) = (has_color(base), has_alpha(base));
    let t = format!("t{u}");
    w.line(format!("// unit {u}: {:?} on {base:?}", unit.env));
    let (rgb, alpha): (String, String) = match unit.env {
        EnvKey::Replace => (
            if c {
                format!("{t}.rgb")
            } else {
                "previous.rgb".into()
            },
            if a {
                format!("{t}.a")
            } else {
                "previous.a".into()
            },
        ),
        EnvKey::Modulate => (
            if c {
                format!("previous.rgb * {t}.rgb")
            } else {
                "previous.rgb".into()
            },
            if a {
                format!("previous.a * {t}.a")
            } else {
                "previous.a".into()
            },
        ),
        // DECAL is defined for RGB and RGBA only; otherwise the fragment passes unchanged
        // (what Mesa does; DESIGN "Measured facts").
        EnvKey::Decal => match base {
            BaseFormat::Rgb => (format!("{t}.rgb"), "previous.a".into()),
            BaseFormat::Rgba => (
                format!("mix(previous.rgb, {t}.rgb, {t}.a)"),
                "previous.a".into(),
            ),
            _ => ("previous.rgb".into(), "previous.a".into()),
        },
        EnvKey::Blend => {
            let cc = w.uniform(UniformSource::EnvColor(u));
            (
                if c {
                    format!("previous.rgb * (1.0 - {t}.rgb) + {cc}.rgb * {t}.rgb")
                } else {
                    "previous.rgb".into()
                },
                match base {
                    BaseFormat::Intensity => format!("previous.a * (1.0 - {t}.a) + {cc}.a * {t}.a"),
                    _ if a => format!("previous.a * {t}.a"),
                    _ => "previous.a".into(),
                },
            )
        }
        EnvKey::Add => (
            if c {
                format!("previous.rgb + {t}.rgb")
            } else {
                "previous.rgb".into()
            },
            match base {
                BaseFormat::Intensity => format!("previous.a + {t}.a"),
                _ if a => format!("previous.a * {t}.a"),
                _ => "previous.a".into(),
            },
        ),
        EnvKey::Combine { rgb, alpha } => return emit_combine(w, key, u, rgb, alpha),
    };
    w.line(format!("previous = clamp(vec4({rgb}, {alpha}), 0.0, 1.0);"));
}

/// The value of a combine source for unit `u`.
fn source(w: &mut GlslWriter, key: &FragmentKey, u: u8, s: CombineSource) -> String {
    match s {
        CombineSource::Texture => format!("t{u}"),
        // ARB_texture_env_crossbar: another unit's texel; undefined by the spec when that
        // unit is disabled — here white.
        CombineSource::TextureUnit(n) => {
            if key.units.iter().any(|k| k.unit == n) {
                format!("t{n}")
            } else {
                "vec4(1.0)".into()
            }
        }
        CombineSource::Constant => w.uniform(UniformSource::EnvColor(u)),
        CombineSource::PrimaryColor => "primary".into(),
        CombineSource::Previous => "previous".into(),
    }
}

fn operand_rgb(v: &str, op: CombineOperand) -> String {
    match op {
        CombineOperand::SrcColor => format!("{v}.rgb"),
        CombineOperand::OneMinusSrcColor => format!("(1.0 - {v}.rgb)"),
        CombineOperand::SrcAlpha => format!("vec3({v}.a)"),
        CombineOperand::OneMinusSrcAlpha => format!("vec3(1.0 - {v}.a)"),
    }
}

fn operand_alpha(v: &str, op: CombineOperand) -> String {
    match op {
        CombineOperand::SrcAlpha | CombineOperand::SrcColor => format!("{v}.a"),
        CombineOperand::OneMinusSrcAlpha | CombineOperand::OneMinusSrcColor => {
            format!("(1.0 - {v}.a)")
        }
    }
}

/// The combine function on three arguments of GLSL type `ty` (vec3 or float).
fn combine_expr(func: CombineFunc, a: &[String; 3], ty: &str) -> String {
    match func {
        CombineFunc::Replace => a[0].clone(),
        CombineFunc::Modulate => format!("{} * {}", a[0], a[1]),
        CombineFunc::Add => format!("{} + {}", a[0], a[1]),
        CombineFunc::AddSigned => format!("{} + {} - {ty}(0.5)", a[0], a[1]),
        CombineFunc::Interpolate => {
            format!("{0} * {2} + {1} * ({ty}(1.0) - {2})", a[0], a[1], a[2])
        }
        CombineFunc::Subtract => format!("{} - {}", a[0], a[1]),
        // 4·((r0−½)(r1−½) + (g0−½)(g1−½) + (b0−½)(b1−½)) (ARB_texture_env_dot3).
        CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => {
            format!(
                "{ty}(4.0 * dot({} - vec3(0.5), {} - vec3(0.5)))",
                a[0], a[1]
            )
        }
    }
}

fn emit_combine(w: &mut GlslWriter, key: &FragmentKey, u: u8, rgb: Combine, alpha: Combine) {
    let args_rgb: [String; 3] = std::array::from_fn(|i| {
        let v = source(w, key, u, rgb.sources[i]);
        operand_rgb(&v, rgb.operands[i])
    });
    let args_alpha: [String; 3] = std::array::from_fn(|i| {
        let v = source(w, key, u, alpha.sources[i]);
        operand_alpha(&v, alpha.operands[i])
    });
    let rgb_scale = rgb.scale.factor();
    let rgb_expr = combine_expr(rgb.func, &args_rgb, "vec3");
    w.line(format!(
        "vec3 rgb{u} = clamp(({rgb_expr}) * {rgb_scale:?}, 0.0, 1.0);"
    ));
    let alpha_value = if rgb.func == CombineFunc::Dot3Rgba {
        // DOT3_RGBA writes the dot product to alpha too; COMBINE_ALPHA is ignored.
        format!("rgb{u}.r")
    } else {
        let alpha_scale = alpha.scale.factor();
        let e = combine_expr(alpha.func, &args_alpha, "float");
        format!("clamp(({e}) * {alpha_scale:?}, 0.0, 1.0)")
    };
    w.line(format!("previous = vec4(rgb{u}, {alpha_value});"));
}

/// Precision::Float, as Mesa's llvmpipe does it (measured): alpha and reference become
/// unorm8 by round-half-to-even and compare as integers. So GREATER 0.5 (ref → 128) first
/// passes at a ≥ 128.5625/255 (a·255 rounds to 129).
fn emit_alpha_test(w: &mut GlslWriter, func: CompareFunc) {
    let r = w.uniform(UniformSource::AlphaRef);
    w.line("float alpha8 = roundEven(clamp(previous.a, 0.0, 1.0) * 255.0);");
    w.line(format!(
        "float ref8 = roundEven(clamp({r}, 0.0, 1.0) * 255.0);"
    ));
    let pass = match func {
        CompareFunc::Never => "false",
        CompareFunc::Less => "alpha8 < ref8",
        CompareFunc::Equal => "alpha8 == ref8",
        CompareFunc::Lequal => "alpha8 <= ref8",
        CompareFunc::Greater => "alpha8 > ref8",
        CompareFunc::Notequal => "alpha8 != ref8",
        CompareFunc::Gequal => "alpha8 >= ref8",
        CompareFunc::Always => "true",
    };
    w.line(format!("if (!({pass})) discard;"));
}
