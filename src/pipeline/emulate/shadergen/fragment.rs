//! The fragment stage: texture lookups (projective, depth compare), the texture environment
//! of each enabled unit in order (GL 1.5 §3.8.13 and ARB_texture_env_combine), the colour
//! sum, fog (§3.10), the alpha test.
//! Every stage's result is clamped to [0, 1] (H14); INTERPOLATE is a0·a2 + a1·(1 − a2) (H13).

use crate::ff::{
    BaseFormat, Combine, CombineFunc, CombineOperand, CombineSource, CompareFunc, DepthTextureMode,
    FogMode, TextureTarget,
};
use crate::pipeline::emulate::glsl::GlslWriter;
use crate::pipeline::emulate::key::{
    ClampKey, EnvKey, FragmentKey, FragmentUnitKey, InLevel, PointCut, SpriteKey, SpriteOrigin,
    TexelKey,
};
use crate::pipeline::emulate::polygon::EdgeRule;
use crate::pipeline::emulate::uniforms::UniformSource;
use crate::vocab::Precision;

pub fn generate(key: &FragmentKey) -> GlslWriter {
    let mut w = GlslWriter::new();
    let flat = if key.flat { "flat " } else { "" };
    w.declare(&format!("{flat}in vec4 v_color;"));
    w.declare("out vec4 frag_color;");
    if let Some(rule) = key.edges {
        emit_edge_rule(&mut w, rule);
    }
    if key.polygon_stipple {
        emit_polygon_stipple(&mut w);
    }
    match key.point_cut {
        Some(PointCut::Legacy) => emit_legacy_point(&mut w),
        Some(PointCut::Round) => emit_point_coverage(&mut w),
        None => {}
    }
    if key.two_side {
        w.declare(&format!("{flat}in vec4 v_back_color;"));
        w.line("vec4 primary = gl_FrontFacing ? v_color : v_back_color;");
    } else {
        w.line("vec4 primary = v_color;");
    }
    // No clamp here: the vertex stage saturates every colour it writes, and interpolation
    // (and the clipper's) is a convex combination, so primary is in [0, 1] already, as in
    // Mesa's fixed-function fragment program, which does not clamp its colour input.
    if let Some(source) = key.pixels {
        super::pixels::emit(&mut w, source);
    }
    if key.color_sum {
        emit_secondary(&mut w, key, flat);
    }
    if key.precision == Precision::Fixed8 {
        // Fixed8: the stages work on integers 0..=255 (ff::precision).
        w.declare(FIXED8_HELPERS);
        w.line("primary = q8(primary);");
        if key.color_sum {
            w.line("secondary = q8(secondary);");
        }
    }
    for unit in &key.units {
        emit_texel(&mut w, unit, key.combiners.is_some(), key.sprite);
        if key.precision == Precision::Fixed8 {
            w.line(format!("t{0} = q8(t{0});", unit.unit));
        }
    }
    if let Some(mode) = key.fog {
        emit_fog_factor(&mut w, mode);
    }
    w.line("vec4 previous = primary;");
    match &key.combiners {
        Some(c) => super::combiners::emit(&mut w, key, c),
        None => {
            for unit in &key.units {
                emit_env(&mut w, key, unit);
            }
            if key.color_sum {
                // Colour sum (GL 1.2 §3.9): C = clamp(C_tex + C_sec) on RGB; alpha as is.
                // Mesa deviates under fog: its program fogs the sum unclamped (the target
                // clamps the result), measured: 0.75 + 0.75 under LINEAR fog f = ½ towards
                // black gives 191, where the clamped sum gives 128. Float follows Mesa.
                let m = Arith(key.precision);
                let sum = "previous.rgb + secondary.rgb";
                let sum = match (key.precision, key.fog) {
                    (Precision::Float, Some(_)) => sum.to_string(),
                    _ => m.clamp(sum),
                };
                w.line(format!("previous.rgb = {sum};"));
            }
            if key.fog.is_some() {
                emit_fog_blend(&mut w, key.precision);
            }
        }
    }
    if key.point_cut == Some(PointCut::Round) {
        // Before the alpha test, which sees the scaled alpha as Mesa's does.
        match key.precision {
            Precision::Float => w.line("previous.a *= point_coverage;"),
            Precision::Fixed8 => {
                w.line("previous.a = min(floor(previous.a * point_coverage + 0.5), 255.0);")
            }
        }
    }
    if let Some(func) = key.alpha_test {
        emit_alpha_test(&mut w, func, key.precision);
    }
    match key.precision {
        Precision::Float => w.line("frag_color = previous;"),
        Precision::Fixed8 => w.line("frag_color = previous / 255.0;"),
    }
    w
}

/// `fog_f`: the fog factor of the interpolated distance z = v_fog, clamped to [0, 1]
/// (GL 1.5 §3.10), by exp2 with Mesa's pre-scaled parameters (`Fog::factor_params`):
/// LINEAR z·a + b; EXP 2^(−z·d·log₂e); EXP2 2^(−(z·d/√ln 2)²).
fn emit_fog_factor(w: &mut GlslWriter, mode: FogMode) {
    w.declare("in float v_fog;");
    let p = w.uniform(UniformSource::FogParams);
    let f = match mode {
        FogMode::Linear => format!("v_fog * {p}.x + {p}.y"),
        FogMode::Exp => format!("exp2(-(v_fog * {p}.z))"),
        FogMode::Exp2 => format!("exp2(-((v_fog * {p}.w) * (v_fog * {p}.w)))"),
    };
    w.line(format!("float fog_f = clamp({f}, 0.0, 1.0);"));
}

/// C = f·C_r + (1 − f)·C_f on RGB, alpha unchanged (§3.10); after texturing and the colour
/// sum, before the alpha test. Fixed8 rounds the blend to the nearest integer.
fn emit_fog_blend(w: &mut GlslWriter, precision: Precision) {
    let c = w.uniform(UniformSource::FogColor);
    match precision {
        Precision::Float => {
            w.line(format!("previous.rgb = mix({c}.rgb, previous.rgb, fog_f);"));
        }
        Precision::Fixed8 => w.line(format!(
            "previous.rgb = floor(mix(q8({c}).rgb, previous.rgb, fog_f) + 0.5);"
        )),
    }
}

/// `secondary`: the secondary colour of the face (the separate specular), clamped.
fn emit_secondary(w: &mut GlslWriter, key: &FragmentKey, flat: &str) {
    w.declare(&format!("{flat}in vec4 v_secondary;"));
    if key.two_side {
        w.declare(&format!("{flat}in vec4 v_back_secondary;"));
        w.line("vec4 secondary = gl_FrontFacing ? v_secondary : v_back_secondary;");
    } else {
        w.line("vec4 secondary = v_secondary;");
    }
    w.line("secondary = clamp(secondary, 0.0, 1.0);");
}

/// LINE mode keeps the fragments of boundary edges (a component of e.xyz exactly 0);
/// POINT mode keeps the corner that owns the vertex (e.w ≠ 0) — `polygon`.
fn emit_edge_rule(w: &mut GlslWriter, rule: EdgeRule) {
    w.declare("noperspective in vec4 v_edge;");
    match rule {
        EdgeRule::BoundaryEdges => {
            w.line("if (!any(equal(v_edge.xyz, vec3(0.0)))) discard;");
        }
        EdgeRule::OwnedVertices => w.line("if (v_edge.w == 0.0) discard;"),
    }
}

/// Polygon stipple (GL 1.5 §3.5.2): the fragment at window (x_w, y_w) survives iff bit
/// (x_w mod 32, y_w mod 32) of the pattern is 1; row y_w mod 32 holds pixel x in bit 31 − x.
fn emit_polygon_stipple(w: &mut GlslWriter) {
    let rows = w.uniform(UniformSource::PolygonStipple);
    w.line("uvec2 stipple_at = uvec2(gl_FragCoord.xy) & 31u;");
    w.line(format!(
        "if (((({rows}[stipple_at.y]) >> (31u - stipple_at.x)) & 1u) == 0u) discard;"
    ));
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
/// its sign) and the quotient clamped to ±1e6, so no Inf reaches a lookup; the wrap mode
/// then decides the texel, as hardware of the era did with huge coordinates. A NaN
/// coordinate (a NaN or infinite texgen plane, matrix or glTexCoord) becomes 0, explicitly
/// (GLSL's clamp of NaN is undefined): Mesa 22.3.6 llvmpipe's native path reads texel 0
/// under REPEAT for it (measured, `tests/fidelity_nonfinite.rs`).
fn projected(w: &mut GlslWriter) {
    w.declare(
        "vec4 project(vec4 tc) {\n    float q = (abs(tc.w) < 1e-20) ? ((tc.w < 0.0) ? -1e-20 : 1e-20) : tc.w;\n    vec3 c = tc.xyz / q;\n    return vec4(mix(clamp(c, -1e6, 1e6), vec3(0.0), isnan(c)), q);\n}",
    );
}

/// t{u}: the unit's texel as GL's texture environment sees it — or, for register
/// combiners, as their texture register holds it (depth: (0,0,0,D); compare: (L,L,L,L)).
fn emit_texel(
    w: &mut GlslWriter,
    unit: &FragmentUnitKey,
    combiners: bool,
    sprite: Option<SpriteKey>,
) {
    let u = unit.unit;
    match sprite.filter(|s| s.replaces(u)) {
        // A point sprite's coordinates (s, t, 0, 1): its place in the square (`ff::point`);
        // the vertex's coordinates are not read (the linker drops their output).
        Some(s) => {
            let t = match s.origin {
                SpriteOrigin::UpperLeft => "gl_PointCoord.y",
                SpriteOrigin::LowerLeft => "1.0 - gl_PointCoord.y",
            };
            w.line(format!("vec4 p{u} = vec4(gl_PointCoord.x, {t}, 0.0, 1.0);"));
        }
        None => {
            w.declare(&format!("in vec4 v_tc{u};"));
            projected(w);
            w.line(format!("vec4 p{u} = project(v_tc{u});"));
        }
    }
    // The coordinates the filter reads (s; s, t; s, t, r) and, for a compare, the r it
    // compares. CLAMP axes are clamped first (`clamp_coordinates`).
    let (vector, axes) = match unit.target {
        TextureTarget::Texture1D => ("float", "x"),
        TextureTarget::Texture2D => ("vec2", "xy"),
        TextureTarget::Texture3D => ("vec3", "xyz"),
        // The direction (s, t, r), divided by q as Mesa's fixed-function program divides
        // it (a negative q turns the direction round; measured, `fidelity_cube_map`).
        TextureTarget::CubeMap | TextureTarget::CubeFace(_) => ("vec3", "xyz"),
    };
    let filtered = match unit.clamp {
        Some(_) => format!("k{u}"),
        None => format!("p{u}.{axes}"),
    };
    let (sampler_type, coord) = match (unit.target, unit.texel) {
        (TextureTarget::Texture2D, TexelKey::Compare(_)) => (
            "sampler2DShadow",
            format!("vec3({filtered}, clamp(p{u}.z, 0.0, 1.0))"),
        ),
        (TextureTarget::Texture1D, TexelKey::Compare(_)) => (
            "sampler1DShadow",
            format!("vec3({filtered}, 0.0, clamp(p{u}.z, 0.0, 1.0))"),
        ),
        (TextureTarget::Texture2D, _) => ("sampler2D", filtered),
        (TextureTarget::Texture1D, _) => ("sampler1D", filtered),
        // (s, t, r)/q; no depth format is a 3D texture (`ff::texture_volume`), so the
        // texel is a colour.
        (TextureTarget::Texture3D, _) => ("sampler3D", filtered),
        // A depth cube map is sampled for its depth, never compared: the model keeps
        // compare off for cube maps (`key`).
        (TextureTarget::CubeMap | TextureTarget::CubeFace(_), _) => ("samplerCube", filtered),
    };
    let s = w.uniform_typed(UniformSource::Sampler(u), sampler_type);
    // texture(), or with CLAMP textureGrad() from the unclamped coordinates' derivatives:
    // the level of detail is the unclamped coordinates' (GL computes λ before it wraps).
    let sample = |coord: &str| match unit.clamp {
        Some(_) => format!("textureGrad({s}, {coord}, dFdx(w{u}), dFdy(w{u}))"),
        None => format!("texture({s}, {coord})"),
    };
    if let Some(clamp) = unit.clamp {
        w.line(format!("{vector} w{u} = p{u}.{axes};"));
        w.line(format!("{vector} k{u} = w{u};"));
        clamp_coordinates(w, u, unit.target, &s, clamp);
    }
    let as_mode = |m: DepthTextureMode, v: &str| match m {
        DepthTextureMode::Luminance => format!("vec4(vec3({v}), 1.0)"),
        DepthTextureMode::Intensity => format!("vec4({v})"),
        DepthTextureMode::Alpha => format!("vec4(0.0, 0.0, 0.0, {v})"),
    };
    match unit.texel {
        // The texture's swizzle already gives (L,L,L,1), (I,I,I,I), (0,0,0,A), (L,L,L,A).
        TexelKey::Color(_) => w.line(format!("vec4 t{u} = {};", sample(&coord))),
        TexelKey::Depth(_) if combiners => {
            w.line(format!(
                "vec4 t{u} = vec4(0.0, 0.0, 0.0, {}.r);",
                sample(&coord)
            ));
        }
        TexelKey::Depth(m) => {
            w.line(format!("float d{u} = {}.r;", sample(&coord)));
            w.line(format!("vec4 t{u} = {};", as_mode(m, &format!("d{u}"))));
        }
        TexelKey::Compare(m) => {
            // ARB_shadow_ambient: a failing compare gives the fail value instead of 0; with
            // LINEAR filtering the pass fraction f blends: fail + f·(1 − fail).
            let fail = w.uniform(UniformSource::CompareFail(u));
            w.line(format!("float c{u} = {};", sample(&coord)));
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

/// The largest coordinate below 1 that NEAREST reads as the edge texel: ⌊2ⁿ · s⌋ = 2ⁿ − 1
/// for every level up to 2²⁰ texels (GL 1.5 §3.8.8: i = 2ⁿ − 1 at s = 1 under CLAMP).
const BELOW_ONE: &str = "0.99999905";

/// Clamps k{u}'s CLAMP axes to [0, 1] for a blending filter (the edge texel meets the
/// border half and half at s = 1, sampled with CLAMP_TO_BORDER) or to [0, 1 − 2⁻²⁰] for
/// NEAREST (the edge texel). When MIN_FILTER and MAG_FILTER read differently, the fragment's
/// own choice decides: minified where textureQueryLOD's λ is above 0 (GL's c = 0 for
/// these pairs, §3.8.9).
fn clamp_coordinates(
    w: &mut GlslWriter,
    u: u8,
    target: TextureTarget,
    sampler: &str,
    clamp: ClampKey,
) {
    let top = |f: InLevel| match f {
        InLevel::Linear => "1.0",
        InLevel::Nearest => BELOW_ONE,
    };
    let hi = if clamp.minified == clamp.magnified {
        top(clamp.minified).to_string()
    } else {
        w.extension("GL_ARB_texture_query_lod");
        w.line(format!(
            "float hi{u} = textureQueryLOD({sampler}, w{u}).y > 0.0 ? {} : {};",
            top(clamp.minified),
            top(clamp.magnified)
        ));
        format!("hi{u}")
    };
    for (i, _) in clamp.axes.iter().enumerate().filter(|(_, a)| **a) {
        // A 1D texture's coordinate is a float, which GLSL 3.30 cannot swizzle.
        let c = match target {
            TextureTarget::Texture1D => String::new(),
            _ => format!(".{}", ["x", "y", "z"][i]),
        };
        w.line(format!("k{u}{c} = clamp(w{u}{c}, 0.0, {hi});"));
    }
}

/// Expression builders for the precision mode (see `ff::precision` for the Fixed8 rules).
/// In `Fixed8` every value in the fragment stage is an integer 0..=255 held in a float.
#[derive(Clone, Copy)]
struct Arith(Precision);

impl Arith {
    fn fixed(self) -> bool {
        self.0 == Precision::Fixed8
    }
    fn one_minus(self, x: &str) -> String {
        if self.fixed() {
            format!("(255.0 - {x})")
        } else {
            format!("(1.0 - {x})")
        }
    }
    fn mul(self, a: &str, b: &str) -> String {
        if self.fixed() {
            format!("f8_mul({a}, {b})")
        } else {
            format!("({a} * {b})")
        }
    }
    fn add_signed(self, a: &str, b: &str) -> String {
        if self.fixed() {
            format!("({a} + {b} - 128.0)")
        } else {
            format!("({a} + {b} - 0.5)")
        }
    }
    /// a0·a2 + a1·(1 − a2).
    fn lerp(self, a0: &str, a1: &str, a2: &str) -> String {
        if self.fixed() {
            format!("f8_lerp({a0}, {a1}, {a2})")
        } else {
            format!("({a0} * {a2} + {a1} * (1.0 - {a2}))")
        }
    }
    fn dot3(self, a: &str, b: &str) -> String {
        if self.fixed() {
            format!("floor(dot({a} - vec3(128.0), {b} - vec3(128.0)) / 64.0)")
        } else {
            format!("(4.0 * dot({a} - vec3(0.5), {b} - vec3(0.5)))")
        }
    }
    /// Every stage ends clamped to the representable range.
    fn clamp(self, v: &str) -> String {
        if self.fixed() {
            format!("clamp({v}, 0.0, 255.0)")
        } else {
            format!("clamp({v}, 0.0, 1.0)")
        }
    }
    /// A uniform colour in the stage's units.
    fn color(self, u: &str) -> String {
        if self.fixed() {
            format!("q8({u})")
        } else {
            u.to_string()
        }
    }
}

/// GLSL helpers of the Fixed8 rules: q(v) = ⌊255v + ½⌋; c' = c + (c >> 7);
/// MODULATE (a·b' + 127) >> 8; INTERPOLATE (a0·a2' + a1·(256 − a2') + 127) >> 8.
const FIXED8_HELPERS: &str = "vec4 q8(vec4 v) { return floor(clamp(v, 0.0, 1.0) * 255.0 + 0.5); }
float q8(float v) { return floor(clamp(v, 0.0, 1.0) * 255.0 + 0.5); }
vec3 f8_mul(vec3 a, vec3 b) { return floor((a * (b + floor(b / 128.0)) + 127.0) / 256.0); }
float f8_mul(float a, float b) { return floor((a * (b + floor(b / 128.0)) + 127.0) / 256.0); }
vec3 f8_lerp(vec3 a0, vec3 a1, vec3 a2) { vec3 w = a2 + floor(a2 / 128.0); return floor((a0 * w + a1 * (256.0 - w) + 127.0) / 256.0); }
float f8_lerp(float a0, float a1, float a2) { float w = a2 + floor(a2 / 128.0); return floor((a0 * w + a1 * (256.0 - w) + 127.0) / 256.0); }";

fn emit_env(w: &mut GlslWriter, key: &FragmentKey, unit: &FragmentUnitKey) {
    let m = Arith(key.precision);
    let u = unit.unit;
    let base = unit.texel.env_base();
    let (c, a) = (has_color(base), has_alpha(base));
    let (tc, ta) = (format!("t{u}.rgb"), format!("t{u}.a"));
    let (pc, pa) = ("previous.rgb".to_string(), "previous.a".to_string());
    w.line(format!("// unit {u}: {:?} on {base:?}", unit.env));
    let pick = |cond: bool, yes: String, no: &String| if cond { yes } else { no.clone() };
    let (rgb, alpha): (String, String) = match unit.env {
        EnvKey::Replace => (pick(c, tc.clone(), &pc), pick(a, ta.clone(), &pa)),
        EnvKey::Modulate => (pick(c, m.mul(&pc, &tc), &pc), pick(a, m.mul(&pa, &ta), &pa)),
        // DECAL is defined for RGB and RGBA only; otherwise the fragment passes unchanged
        // (what Mesa does; DESIGN "Measured facts").
        EnvKey::Decal => match base {
            BaseFormat::Rgb => (tc.clone(), pa.clone()),
            BaseFormat::Rgba => (m.lerp(&tc, &pc, &format!("vec3({ta})")), pa.clone()),
            _ => (pc.clone(), pa.clone()),
        },
        EnvKey::Blend => {
            let cc = w.uniform(UniformSource::EnvColor(u));
            let cc = m.color(&cc);
            (
                pick(c, m.lerp(&format!("{cc}.rgb"), &pc, &tc), &pc),
                match base {
                    BaseFormat::Intensity => m.lerp(&format!("{cc}.a"), &pa, &ta),
                    _ if a => m.mul(&pa, &ta),
                    _ => pa.clone(),
                },
            )
        }
        EnvKey::Add => (
            pick(c, format!("({pc} + {tc})"), &pc),
            match base {
                BaseFormat::Intensity => format!("({pa} + {ta})"),
                _ if a => m.mul(&pa, &ta),
                _ => pa.clone(),
            },
        ),
        EnvKey::Combine { rgb, alpha } => return emit_combine(w, key, u, rgb, alpha),
    };
    let v = m.clamp(&format!("vec4({rgb}, {alpha})"));
    w.line(format!("previous = {v};"));
}

/// The value of a combine source for unit `u`.
fn source(w: &mut GlslWriter, key: &FragmentKey, u: u8, s: CombineSource) -> String {
    match s {
        CombineSource::Texture => format!("t{u}"),
        // ARB_texture_env_crossbar: another unit's texel; undefined by the spec when that
        // unit is disabled or its texture incomplete (both leave it out of the key) —
        // here (0, 0, 0, 0), as Mesa's fixed-function shader reads it
        // (ff_fragment_shader's constant 0 for a unit without a texture).
        CombineSource::TextureUnit(n) => {
            if key.units.iter().any(|k| k.unit == n) {
                format!("t{n}")
            } else {
                Arith(key.precision).color("vec4(0.0)")
            }
        }
        CombineSource::Constant => {
            let c = w.uniform(UniformSource::EnvColor(u));
            Arith(key.precision).color(&c)
        }
        CombineSource::PrimaryColor => "primary".into(),
        CombineSource::Previous => "previous".into(),
    }
}

fn operand_rgb(m: Arith, v: &str, op: CombineOperand) -> String {
    match op {
        CombineOperand::SrcColor => format!("{v}.rgb"),
        CombineOperand::OneMinusSrcColor => m.one_minus(&format!("{v}.rgb")),
        CombineOperand::SrcAlpha => format!("vec3({v}.a)"),
        CombineOperand::OneMinusSrcAlpha => format!("vec3({})", m.one_minus(&format!("{v}.a"))),
    }
}

fn operand_alpha(m: Arith, v: &str, op: CombineOperand) -> String {
    match op {
        CombineOperand::SrcAlpha | CombineOperand::SrcColor => format!("{v}.a"),
        CombineOperand::OneMinusSrcAlpha | CombineOperand::OneMinusSrcColor => {
            m.one_minus(&format!("{v}.a"))
        }
    }
}

/// The combine function on three arguments (vec3 or float expressions).
fn combine_expr(m: Arith, func: CombineFunc, a: &[String; 3], vec: bool) -> String {
    match func {
        CombineFunc::Replace => a[0].clone(),
        CombineFunc::Modulate => m.mul(&a[0], &a[1]),
        CombineFunc::Add => format!("({} + {})", a[0], a[1]),
        CombineFunc::AddSigned => m.add_signed(&a[0], &a[1]),
        CombineFunc::Interpolate => m.lerp(&a[0], &a[1], &a[2]),
        CombineFunc::Subtract => format!("({} - {})", a[0], a[1]),
        CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => {
            let d = m.dot3(&a[0], &a[1]);
            if vec {
                format!("vec3({d})")
            } else {
                d
            }
        }
    }
}

fn emit_combine(w: &mut GlslWriter, key: &FragmentKey, u: u8, rgb: Combine, alpha: Combine) {
    let m = Arith(key.precision);
    let args_rgb: [String; 3] = std::array::from_fn(|i| {
        let v = source(w, key, u, rgb.sources[i]);
        operand_rgb(m, &v, rgb.operands[i])
    });
    let args_alpha: [String; 3] = std::array::from_fn(|i| {
        let v = source(w, key, u, alpha.sources[i]);
        operand_alpha(m, &v, alpha.operands[i])
    });
    let rgb_expr = combine_expr(m, rgb.func, &args_rgb, true);
    let rgb_v = m.clamp(&format!("({rgb_expr}) * {:?}", rgb.scale.factor()));
    w.line(format!("vec3 rgb{u} = {rgb_v};"));
    let alpha_value = if rgb.func == CombineFunc::Dot3Rgba {
        // DOT3_RGBA writes the dot product to alpha too, scaled by ALPHA_SCALE, not
        // RGB_SCALE (GL 1.5 §3.8.13; Mesa alike); COMBINE_ALPHA is ignored.
        let d = combine_expr(m, rgb.func, &args_rgb, false);
        m.clamp(&format!("({d}) * {:?}", alpha.scale.factor()))
    } else {
        let e = combine_expr(m, alpha.func, &args_alpha, false);
        m.clamp(&format!("({e}) * {:?}", alpha.scale.factor()))
    };
    w.line(format!("previous = vec4(rgb{u}, {alpha_value});"));
}

/// An aliased point as llvmpipe's rule for legacy points covers it: the pixels whose
/// centres c lie at X − side/2 < c ≤ X + side/2 in x and in y, where X is the window
/// position x snapped to 1/256 pixel, X₂₅₆ = ⌊256·(x − ½) + ½⌋ + 128, and compared in
/// those steps. The core context rasterises a square two pixels wider about x, which holds
/// them all. The position and side come from the vertex stage without perspective
/// (`v_point`): a point's own vertex gives them whole, and where clipping makes a corner
/// of a polygon drawn in POINT mode they are interpolated in window space, as the corner.
fn emit_legacy_point(w: &mut GlslWriter) {
    w.declare("noperspective in vec3 v_point;");
    w.line("vec2 point_at = floor((v_point.xy - 0.5) * 256.0 + 0.5) + 128.0;");
    w.line("vec2 point_from = gl_FragCoord.xy * 256.0 - point_at;");
    w.line("float point_half = 128.0 * v_point.z;");
    w.line(
        "if (any(lessThanEqual(point_from, vec2(-point_half))) || any(greaterThan(point_from, vec2(point_half)))) discard;",
    );
}

/// A round point (POINT_SMOOTH) as Mesa's aapoint stage draws it: with (s, t) running from
/// −1 to 1 across the square of side 2r (`PointShape::Round`), d = s² + t² and
/// k = 1 − 2/r + 1/r², a fragment with d > 1 is discarded and the others' alpha is scaled
/// by (1 − d)/(1 − k) where d ≤ k, by 1 elsewhere. The factor exceeds 1 inside the inner
/// circle and is 1 on the fringe, so a point of opaque colour is a disc without coverage
/// at its rim: Mesa 22.3's selection, followed as it is (measured on llvmpipe).
fn emit_point_coverage(w: &mut GlslWriter) {
    w.declare("flat in float v_point_r;");
    w.line("vec2 point_st = gl_PointCoord * 2.0 - 1.0;");
    w.line("float point_d = point_st.x * point_st.x + point_st.y * point_st.y;");
    w.line("if (1.0 < point_d) discard;");
    w.line("float point_r = v_point_r;");
    w.line("float point_k = 1.0 - 2.0 * (1.0 / point_r) + (1.0 / point_r) * (1.0 / point_r);");
    w.line(
        "float point_coverage = point_k >= point_d ? (1.0 / (1.0 - point_k)) * (1.0 - point_d) : 1.0;",
    );
}

/// Precision::Float, as Mesa's llvmpipe does it (measured): alpha and reference become
/// unorm8 by round-half-to-even and compare as integers. So GREATER 0.5 (ref → 128) first
/// passes at a ≥ 128.5625/255 (a·255 rounds to 129). Precision::Fixed8: the stage's
/// integer alpha against q(ref) = ⌊255·ref + ½⌋.
fn emit_alpha_test(w: &mut GlslWriter, func: CompareFunc, precision: Precision) {
    let r = w.uniform(UniformSource::AlphaRef);
    match precision {
        Precision::Float => {
            w.line("float alpha8 = roundEven(clamp(previous.a, 0.0, 1.0) * 255.0);");
            w.line(format!(
                "float ref8 = roundEven(clamp({r}, 0.0, 1.0) * 255.0);"
            ));
        }
        Precision::Fixed8 => {
            w.line("float alpha8 = previous.a;");
            w.line(format!("float ref8 = q8({r});"));
        }
    }
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
