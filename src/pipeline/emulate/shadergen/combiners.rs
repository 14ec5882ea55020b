//! NV_register_combiners as GLSL, mirroring `ff::combiner_model` step for step (the CPU
//! model is the oracle the GPU output is tested against). Registers are vec4 variables;
//! each stage computes every portion's AB, CD and SUM/MUX from the registers as they were
//! when it began, then writes its outputs through clamp((r + bias)·scale, −1, 1).

use crate::ff::{
    CombinerInput, CombinerOutput, ComponentUsage, Mapping, Product, Register, SumOrMux,
};
use crate::pipeline::emulate::glsl::GlslWriter;
use crate::pipeline::emulate::key::{CombinersKey, FragmentKey};
use crate::pipeline::emulate::uniforms::UniformSource;
use crate::vocab::Precision;

/// Fixed8: q9(v) = clamp(⌊255v + ½⌋, −256, 255)/255 after every mapping, product and
/// output (ff::precision); Float: the value itself.
const Q9: &str = "vec3 q9(vec3 v) { return clamp(floor(v * 255.0 + 0.5), -256.0, 255.0) / 255.0; }
float q9(float v) { return clamp(floor(v * 255.0 + 0.5), -256.0, 255.0) / 255.0; }";

fn q9(p: Precision, e: String) -> String {
    match p {
        Precision::Float => e,
        Precision::Fixed8 => format!("q9({e})"),
    }
}

fn register(w: &mut GlslWriter, r: Register) -> String {
    match r {
        Register::Zero
        | Register::Discard
        | Register::ETimesF
        | Register::Spare0PlusSecondaryColor => "vec4(0.0)".into(),
        Register::ConstantColor0 => w.uniform(UniformSource::CombinerConstant(0)),
        Register::ConstantColor1 => w.uniform(UniformSource::CombinerConstant(1)),
        Register::Fog => "rc_fog".into(),
        Register::PrimaryColor => "rc_primary".into(),
        Register::SecondaryColor => "rc_secondary".into(),
        Register::Spare0 => "rc_spare0".into(),
        Register::Spare1 => "rc_spare1".into(),
        Register::Texture(n) => format!("rc_tex{n}"),
    }
}

/// The mapping applied to expression `e` (per component).
fn mapping(m: Mapping, e: &str) -> String {
    match m {
        Mapping::UnsignedIdentity => format!("max({e}, 0.0)"),
        Mapping::UnsignedInvert => format!("(1.0 - clamp({e}, 0.0, 1.0))"),
        Mapping::ExpandNormal => format!("(2.0 * max({e}, 0.0) - 1.0)"),
        Mapping::ExpandNegate => format!("(-2.0 * max({e}, 0.0) + 1.0)"),
        Mapping::HalfBiasNormal => format!("(max({e}, 0.0) - 0.5)"),
        Mapping::HalfBiasNegate => format!("(-max({e}, 0.0) + 0.5)"),
        Mapping::SignedIdentity => format!("({e})"),
        Mapping::SignedNegate => format!("(-({e}))"),
    }
}

fn rgb_input(w: &mut GlslWriter, p: Precision, i: CombinerInput) -> String {
    let r = register(w, i.register);
    let e = match i.usage {
        ComponentUsage::Rgb => format!("{r}.rgb"),
        ComponentUsage::Alpha => format!("vec3({r}.a)"),
        ComponentUsage::Blue => format!("vec3({r}.b)"),
    };
    q9(p, mapping(i.mapping, &e))
}

fn alpha_input(w: &mut GlslWriter, p: Precision, i: CombinerInput) -> String {
    let r = register(w, i.register);
    let e = match i.usage {
        ComponentUsage::Blue => format!("{r}.b"),
        ComponentUsage::Alpha | ComponentUsage::Rgb => format!("{r}.a"),
    };
    q9(p, mapping(i.mapping, &e))
}

/// clamp((r + bias)·scale, −1, 1); in Fixed8 the bias −½ is −128/255 and q9 clamps.
fn output_expr(p: Precision, o: &CombinerOutput, v: &str) -> String {
    match p {
        Precision::Float => format!(
            "clamp(({v} + {:?}) * {:?}, -1.0, 1.0)",
            o.bias.value(),
            o.scale.factor()
        ),
        Precision::Fixed8 => format!(
            "q9(({v} + {:?}) * {:?})",
            if o.bias.value() == 0.0 {
                0.0
            } else {
                -128.0 / 255.0
            },
            o.scale.factor()
        ),
    }
}

/// Every register a key reads or writes, so only those are declared.
fn used_textures(key: &CombinersKey) -> Vec<u8> {
    let mut regs: Vec<Register> = key.final_inputs.iter().map(|i| i.register).collect();
    for s in &key.stages {
        for p in [&s.rgb, &s.alpha] {
            regs.extend(p.inputs.iter().map(|i| i.register));
            regs.extend([p.output.ab, p.output.cd, p.output.sum]);
        }
    }
    let mut units: Vec<u8> = regs
        .into_iter()
        .filter_map(|r| match r {
            Register::Texture(n) => Some(n),
            _ => None,
        })
        .collect();
    units.sort_unstable();
    units.dedup();
    units
}

pub fn emit(w: &mut GlslWriter, fragment: &FragmentKey, key: &CombinersKey) {
    let enabled = |n: u8| fragment.units.iter().any(|u| u.unit == n);
    let p = fragment.precision;
    // Registers hold values in [−1, 1]; Fixed8's stage values are integers 0..=255.
    let unit = match p {
        Precision::Float => "",
        Precision::Fixed8 => " / 255.0",
    };
    if p == Precision::Fixed8 {
        w.declare(Q9);
    }
    w.line("// NV_register_combiners");
    w.line(format!("vec4 rc_primary = primary{unit};"));
    // SECONDARY_COLOR: the separate specular when lighting makes one, else 0.
    if fragment.color_sum {
        w.line(format!("vec4 rc_secondary = secondary{unit};"));
    } else {
        w.line("vec4 rc_secondary = vec4(0.0);");
    }
    // FOG = (fog colour, fog factor f) when fog is on — the final combiner applies fog
    // (NV_register_combiners) — else (0, 0, 0, 1). SPARE0.a starts as texture 0's alpha.
    if fragment.fog.is_some() {
        let c = w.uniform(UniformSource::FogColor);
        w.line(format!("vec4 rc_fog = vec4({c}.rgb, fog_f);"));
    } else {
        w.line("vec4 rc_fog = vec4(0.0, 0.0, 0.0, 1.0);");
    }
    w.line(format!(
        "vec4 rc_spare0 = vec4(0.0, 0.0, 0.0, {});",
        if enabled(0) {
            format!("t0.a{unit}")
        } else {
            "0.0".into()
        }
    ));
    w.line("vec4 rc_spare1 = vec4(0.0);");
    let mut units: Vec<u8> = fragment.units.iter().map(|u| u.unit).collect();
    units.extend(used_textures(key));
    units.sort_unstable();
    units.dedup();
    for n in units {
        let init = if enabled(n) {
            format!("t{n}{unit}")
        } else {
            "vec4(0.0)".into()
        };
        w.line(format!("vec4 rc_tex{n} = {init};"));
    }
    for (s, stage) in key.stages.iter().enumerate() {
        emit_stage(w, p, s, stage);
    }
    emit_final(w, p, key);
}

fn emit_stage(w: &mut GlslWriter, pr: Precision, s: usize, stage: &crate::ff::GeneralStage) {
    w.line(format!("// general combiner {s}"));
    let p = &stage.rgb;
    let [a, b, c, d] = p.inputs.map(|i| rgb_input(w, pr, i));
    let prod = |x: &str, y: &str, k: Product| match k {
        Product::Componentwise => q9(pr, format!("({x} * {y})")),
        Product::Dot => q9(pr, format!("vec3(dot({x}, {y}))")),
    };
    w.line(format!(
        "vec3 s{s}_ab = {};",
        prod(&a, &b, p.output.ab_product)
    ));
    w.line(format!(
        "vec3 s{s}_cd = {};",
        prod(&c, &d, p.output.cd_product)
    ));
    w.line(format!(
        "vec3 s{s}_sum = {};",
        third(s, "", p.output.sum_or_mux)
    ));
    let p = &stage.alpha;
    let [a, b, c, d] = p.inputs.map(|i| alpha_input(w, pr, i));
    w.line(format!(
        "float s{s}_ab_a = {};",
        q9(pr, format!("{a} * {b}"))
    ));
    w.line(format!(
        "float s{s}_cd_a = {};",
        q9(pr, format!("{c} * {d}"))
    ));
    w.line(format!(
        "float s{s}_sum_a = {};",
        third(s, "_a", p.output.sum_or_mux)
    ));
    // Outputs after all inputs were read; DISCARD writes nothing.
    let o = &stage.rgb.output;
    for (reg, v) in [(o.ab, "ab"), (o.cd, "cd"), (o.sum, "sum")] {
        if reg != Register::Discard {
            let r = register(w, reg);
            w.line(format!(
                "{r}.rgb = {};",
                output_expr(pr, o, &format!("s{s}_{v}"))
            ));
        }
    }
    let o = &stage.alpha.output;
    for (reg, v) in [(o.ab, "ab_a"), (o.cd, "cd_a"), (o.sum, "sum_a")] {
        if reg != Register::Discard {
            let r = register(w, reg);
            w.line(format!(
                "{r}.a = {};",
                output_expr(pr, o, &format!("s{s}_{v}"))
            ));
        }
    }
}

/// SUM = AB + CD; MUX = (SPARE0.a ≥ ½) ? CD : AB (the corrected sense of August 2000).
fn third(s: usize, suffix: &str, k: SumOrMux) -> String {
    match k {
        SumOrMux::Sum => format!("s{s}_ab{suffix} + s{s}_cd{suffix}"),
        SumOrMux::Mux => format!("(rc_spare0.a >= 0.5) ? s{s}_cd{suffix} : s{s}_ab{suffix}"),
    }
}

fn emit_final(w: &mut GlslWriter, p: Precision, key: &CombinersKey) {
    w.line("// final combiner: min(A·B + (1 − A)·C + D, 1), alpha G");
    let fi = key.final_inputs;
    let sum = if key.color_sum_clamp {
        "clamp(max(rc_spare0.rgb, 0.0) + max(rc_secondary.rgb, 0.0), 0.0, 1.0)"
    } else {
        "max(rc_spare0.rgb, 0.0) + max(rc_secondary.rgb, 0.0)"
    };
    w.line(format!("vec4 rc_sum = vec4({sum}, 0.0);"));
    let e = rgb_input(w, p, fi[4]);
    let f = rgb_input(w, p, fi[5]);
    w.line(format!("vec4 rc_ef = vec4({e} * {f}, 0.0);"));
    let value = |w: &mut GlslWriter, i: CombinerInput| {
        let r = match i.register {
            Register::ETimesF => "rc_ef".to_string(),
            Register::Spare0PlusSecondaryColor => "rc_sum".to_string(),
            other => register(w, other),
        };
        let comp = match i.usage {
            ComponentUsage::Rgb => format!("{r}.rgb"),
            ComponentUsage::Alpha => format!("vec3({r}.a)"),
            ComponentUsage::Blue => format!("vec3({r}.b)"),
        };
        mapping(i.mapping, &comp)
    };
    let [a, b, c, d] = [0, 1, 2, 3].map(|k| value(w, fi[k]));
    let g = {
        let i = fi[6];
        let raw = match i.register {
            Register::ETimesF | Register::Spare0PlusSecondaryColor => "0.0".to_string(),
            other => {
                let r = register(w, other);
                if i.usage == ComponentUsage::Blue {
                    format!("{r}.b")
                } else {
                    format!("{r}.a")
                }
            }
        };
        mapping(i.mapping, &raw)
    };
    w.line(format!("vec3 rc_a = {a};"));
    let out = format!("vec4(min(rc_a * {b} + (1.0 - rc_a) * {c} + {d}, vec3(1.0)), {g})");
    match p {
        Precision::Float => w.line(format!("previous = {out};")),
        // Back to the stage units: integers 0..=255.
        Precision::Fixed8 => w.line(format!("previous = q8({out});")),
    }
}
