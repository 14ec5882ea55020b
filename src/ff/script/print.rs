//! Commands → script text, the inverse of `parse`: one GL call per line, valid C99.
//!
//! Floats print in Rust's shortest round-trip form (`0.1`, `1e-7`), which parses back to the
//! same f32; non-finite values print as `INFINITY`/`NAN` (<math.h>). Draws print as
//! glBegin/glEnd with every present attribute before every vertex.

use std::fmt::Write;

use glam::Vec4;

use super::names::{Family, GlName};
use crate::ff::*;

/// Prints commands as a script.
pub fn print(cmds: &[Command]) -> String {
    let mut out = String::new();
    for c in cmds {
        command(&mut out, c);
    }
    out
}

fn f(v: f32) -> String {
    if v.is_nan() {
        "NAN".into()
    } else if v.is_infinite() {
        if v > 0.0 { "INFINITY" } else { "-INFINITY" }.into()
    } else {
        format!("{v:?}")
    }
}

fn fs(vs: &[f32]) -> String {
    vs.iter().map(|v| f(*v)).collect::<Vec<_>>().join(", ")
}

fn arr(vs: &[f32]) -> String {
    format!("(GLfloat[]){{{}}}", fs(vs))
}

fn v4(v: Vec4) -> String {
    arr(&v.to_array())
}

/// The token of a value; every table covers its enum, so the fallback is never printed.
fn n<T: GlName>(v: T) -> &'static str {
    v.gl_name().unwrap_or("GL_NONE")
}

fn b(v: bool) -> &'static str {
    n(v)
}

fn capability(c: Capability) -> String {
    match c {
        Capability::Light(i) => Family::Light.print(i),
        other => n(other).to_string(),
    }
}

fn register(r: Register) -> String {
    match r {
        Register::Texture(u) => Family::Texture.print(u),
        other => n(other).to_string(),
    }
}

fn source(s: CombineSource) -> String {
    match s {
        CombineSource::TextureUnit(u) => Family::Texture.print(u),
        other => n(other).to_string(),
    }
}

fn line(out: &mut String, s: std::fmt::Arguments) {
    let _ = out.write_fmt(s);
    out.push_str(";\n");
}

fn command(out: &mut String, c: &Command) {
    match c {
        Command::Draw(g) => draw(out, g),
        Command::TexImage(t) => tex_image(out, t),
        Command::TexSubImage2D(t) => line(
            out,
            format_args!(
                "glTexSubImage2D(GL_TEXTURE_2D, {}, {}, {}, {}, {}, {}, {}, {})",
                t.level,
                t.x,
                t.y,
                t.width,
                t.height,
                n(t.format),
                n(t.ty),
                pixels(t.ty, &t.data)
            ),
        ),
        other => line(out, format_args!("{}", call(other))),
    }
}

/// Every command but Draw, TexImage and TexSubImage2D, as one call without the ';'.
fn call(c: &Command) -> String {
    match c {
        Command::MatrixMode(m) => format!("glMatrixMode({})", n(*m)),
        Command::LoadIdentity => "glLoadIdentity()".into(),
        Command::LoadMatrix(m) => format!("glLoadMatrixf({})", arr(&m.to_cols_array())),
        Command::MultMatrix(m) => format!("glMultMatrixf({})", arr(&m.to_cols_array())),
        Command::PushMatrix => "glPushMatrix()".into(),
        Command::PopMatrix => "glPopMatrix()".into(),
        Command::Translate(v) => format!("glTranslatef({})", fs(&v.to_array())),
        Command::Rotate { angle_deg, axis } => {
            format!("glRotatef({}, {})", f(*angle_deg), fs(&axis.to_array()))
        }
        Command::Scale(v) => format!("glScalef({})", fs(&v.to_array())),
        Command::Frustum(v) => format!("glFrustum({})", volume(v)),
        Command::Ortho(v) => format!("glOrtho({})", volume(v)),
        Command::Viewport(v) => format!("glViewport({}, {}, {}, {})", v.x, v.y, v.width, v.height),
        Command::DepthRange { near, far } => format!("glDepthRange({}, {})", f(*near), f(*far)),
        Command::Enable(cap) => format!("glEnable({})", capability(*cap)),
        Command::Disable(cap) => format!("glDisable({})", capability(*cap)),
        Command::Color(c) => format!("glColor4f({})", fs(&c.to_array())),
        Command::Normal(v) => format!("glNormal3f({})", fs(&v.to_array())),
        Command::TexCoord { unit, coord } => format!(
            "glMultiTexCoord4f({}, {})",
            Family::Texture.print(*unit),
            fs(&coord.to_array())
        ),
        Command::Light { light, param } => light_call(Family::Light.print(*light), param),
        Command::LightModel(p) => match p {
            LightModelParam::Ambient(c) => {
                format!("glLightModelfv(GL_LIGHT_MODEL_AMBIENT, {})", v4(*c))
            }
            LightModelParam::LocalViewer(v) => {
                format!("glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, {})", b(*v))
            }
            LightModelParam::TwoSide(v) => {
                format!("glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, {})", b(*v))
            }
            LightModelParam::ColorControl(v) => {
                format!("glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, {})", n(*v))
            }
        },
        Command::Material { face, param } => material(n(*face), param),
        Command::ColorMaterial { face, mode } => {
            format!("glColorMaterial({}, {})", n(*face), n(*mode))
        }
        Command::ShadeModel(m) => format!("glShadeModel({})", n(*m)),
        Command::ActiveTexture(u) => format!("glActiveTexture({})", Family::Texture.print(*u)),
        Command::BindTexture { target, name } => format!("glBindTexture({}, {name})", n(*target)),
        Command::CopyTexImage2D(t) => format!(
            "glCopyTexImage2D(GL_TEXTURE_2D, {}, {}, {}, {}, {}, {}, {})",
            t.level,
            n(t.internal_format),
            t.x,
            t.y,
            t.width,
            t.height,
            t.border
        ),
        Command::TexParameter { target, param } => tex_param(n(*target), param),
        Command::TexGen { coord, param } => match param {
            TexGenParam::Mode(m) => {
                format!("glTexGeni({}, GL_TEXTURE_GEN_MODE, {})", n(*coord), n(*m))
            }
            TexGenParam::ObjectPlane(p) => {
                format!("glTexGenfv({}, GL_OBJECT_PLANE, {})", n(*coord), v4(*p))
            }
            TexGenParam::EyePlane(p) => {
                format!("glTexGenfv({}, GL_EYE_PLANE, {})", n(*coord), v4(*p))
            }
        },
        Command::TexEnv(p) => tex_env(p),
        Command::CombinerParameter(p) => match p {
            CombinerParam::NumGeneralCombiners(k) => {
                format!("glCombinerParameteriNV(GL_NUM_GENERAL_COMBINERS_NV, {k})")
            }
            CombinerParam::ColorSumClamp(v) => {
                format!("glCombinerParameteriNV(GL_COLOR_SUM_CLAMP_NV, {})", b(*v))
            }
            CombinerParam::ConstantColor0(c) => {
                format!("glCombinerParameterfvNV(GL_CONSTANT_COLOR0_NV, {})", v4(*c))
            }
            CombinerParam::ConstantColor1(c) => {
                format!("glCombinerParameterfvNV(GL_CONSTANT_COLOR1_NV, {})", v4(*c))
            }
        },
        Command::CombinerInput {
            stage,
            portion,
            variable,
            input,
        } => format!(
            "glCombinerInputNV({}, {}, {}, {})",
            Family::Combiner.print(*stage),
            n(*portion),
            n(*variable),
            combiner_input(input)
        ),
        Command::CombinerOutput {
            stage,
            portion,
            output: o,
        } => format!(
            "glCombinerOutputNV({}, {}, {}, {}, {}, {}, {}, {}, {}, {})",
            Family::Combiner.print(*stage),
            n(*portion),
            register(o.ab),
            register(o.cd),
            register(o.sum),
            n(o.scale),
            n(o.bias),
            n(o.ab_product),
            n(o.cd_product),
            n(o.sum_or_mux)
        ),
        Command::FinalCombinerInput { variable, input } => {
            format!(
                "glFinalCombinerInputNV({}, {})",
                n(*variable),
                combiner_input(input)
            )
        }
        Command::AlphaFunc { func, reference } => {
            format!("glAlphaFunc({}, {})", n(*func), f(*reference))
        }
        Command::DepthFunc(func) => format!("glDepthFunc({})", n(*func)),
        Command::DepthMask(v) => format!("glDepthMask({})", b(*v)),
        Command::StencilFunc {
            func,
            reference,
            mask,
        } => {
            format!("glStencilFunc({}, {reference}, 0x{mask:X})", n(*func))
        }
        Command::StencilOp {
            fail,
            depth_fail,
            depth_pass,
        } => {
            format!(
                "glStencilOp({}, {}, {})",
                n(*fail),
                n(*depth_fail),
                n(*depth_pass)
            )
        }
        Command::StencilMask(m) => format!("glStencilMask(0x{m:X})"),
        Command::BlendFunc { src, dst } => format!("glBlendFunc({}, {})", n(*src), n(*dst)),
        Command::ColorMask(m) => format!(
            "glColorMask({}, {}, {}, {})",
            b(m.r),
            b(m.g),
            b(m.b),
            b(m.a)
        ),
        Command::PolygonOffset { factor, units } => {
            format!("glPolygonOffset({}, {})", f(*factor), f(*units))
        }
        Command::PolygonMode { face, mode } => format!("glPolygonMode({}, {})", n(*face), n(*mode)),
        Command::CullFace(face) => format!("glCullFace({})", n(*face)),
        Command::FrontFace(face) => format!("glFrontFace({})", n(*face)),
        Command::LineWidth(w) => format!("glLineWidth({})", f(*w)),
        Command::PointSize(s) => format!("glPointSize({})", f(*s)),
        Command::Clear(m) => format!("glClear({})", clear_mask(*m)),
        Command::ClearColor(c) => format!("glClearColor({})", fs(&c.to_array())),
        Command::ClearDepth(d) => format!("glClearDepth({})", f(*d)),
        Command::ClearStencil(s) => format!("glClearStencil({s})"),
        Command::ReadPixels(r) => format!(
            "glReadPixels({}, {}, {}, {}, {}, {}, readback_{})",
            r.x,
            r.y,
            r.width,
            r.height,
            n(r.format),
            n(r.ty),
            r.slot
        ),
        // Printed by `command`.
        Command::Draw(_) | Command::TexImage(_) | Command::TexSubImage2D(_) => String::new(),
    }
}

fn volume(v: &ViewVolume) -> String {
    fs(&[v.left, v.right, v.bottom, v.top, v.near, v.far])
}

fn clear_mask(m: ClearMask) -> String {
    let bits: Vec<&str> = [
        (m.color, "GL_COLOR_BUFFER_BIT"),
        (m.depth, "GL_DEPTH_BUFFER_BIT"),
        (m.stencil, "GL_STENCIL_BUFFER_BIT"),
    ]
    .iter()
    .filter(|(on, _)| *on)
    .map(|(_, name)| *name)
    .collect();
    if bits.is_empty() {
        "0".into()
    } else {
        bits.join(" | ")
    }
}

fn light_call(l: String, p: &LightParam) -> String {
    match p {
        LightParam::Ambient(c) => format!("glLightfv({l}, GL_AMBIENT, {})", v4(*c)),
        LightParam::Diffuse(c) => format!("glLightfv({l}, GL_DIFFUSE, {})", v4(*c)),
        LightParam::Specular(c) => format!("glLightfv({l}, GL_SPECULAR, {})", v4(*c)),
        LightParam::Position(c) => format!("glLightfv({l}, GL_POSITION, {})", v4(*c)),
        LightParam::SpotDirection(d) => {
            format!("glLightfv({l}, GL_SPOT_DIRECTION, {})", arr(&d.to_array()))
        }
        LightParam::SpotExponent(v) => format!("glLightf({l}, GL_SPOT_EXPONENT, {})", f(*v)),
        LightParam::SpotCutoff(v) => format!("glLightf({l}, GL_SPOT_CUTOFF, {})", f(*v)),
        LightParam::ConstantAttenuation(v) => {
            format!("glLightf({l}, GL_CONSTANT_ATTENUATION, {})", f(*v))
        }
        LightParam::LinearAttenuation(v) => {
            format!("glLightf({l}, GL_LINEAR_ATTENUATION, {})", f(*v))
        }
        LightParam::QuadraticAttenuation(v) => {
            format!("glLightf({l}, GL_QUADRATIC_ATTENUATION, {})", f(*v))
        }
    }
}

fn material(face: &str, p: &MaterialParam) -> String {
    let (pname, v) = match p {
        MaterialParam::Shininess(s) => {
            return format!("glMaterialf({face}, GL_SHININESS, {})", f(*s))
        }
        MaterialParam::Ambient(v) => ("GL_AMBIENT", v),
        MaterialParam::Diffuse(v) => ("GL_DIFFUSE", v),
        MaterialParam::AmbientAndDiffuse(v) => ("GL_AMBIENT_AND_DIFFUSE", v),
        MaterialParam::Specular(v) => ("GL_SPECULAR", v),
        MaterialParam::Emission(v) => ("GL_EMISSION", v),
    };
    format!("glMaterialfv({face}, {pname}, {})", v4(*v))
}

fn tex_param(target: &str, p: &TexParam) -> String {
    let (pname, value) = match p {
        TexParam::BorderColor(c) => {
            return format!(
                "glTexParameterfv({target}, GL_TEXTURE_BORDER_COLOR, {})",
                v4(*c)
            )
        }
        TexParam::CompareFailValue(v) => {
            return format!(
                "glTexParameterf({target}, GL_TEXTURE_COMPARE_FAIL_VALUE_ARB, {})",
                f(*v)
            )
        }
        TexParam::MinFilter(v) => ("GL_TEXTURE_MIN_FILTER", n(*v)),
        TexParam::MagFilter(v) => ("GL_TEXTURE_MAG_FILTER", n(*v)),
        TexParam::WrapS(v) => ("GL_TEXTURE_WRAP_S", n(*v)),
        TexParam::WrapT(v) => ("GL_TEXTURE_WRAP_T", n(*v)),
        TexParam::CompareMode(v) => ("GL_TEXTURE_COMPARE_MODE", n(*v)),
        TexParam::CompareFunc(v) => ("GL_TEXTURE_COMPARE_FUNC", n(*v)),
        TexParam::DepthTextureMode(v) => ("GL_DEPTH_TEXTURE_MODE", n(*v)),
        TexParam::GenerateMipmap(v) => ("GL_GENERATE_MIPMAP", b(*v)),
    };
    format!("glTexParameteri({target}, {pname}, {value})")
}

fn arg_digit(a: CombineArg) -> usize {
    a.index()
}

fn tex_env(p: &TexEnvParam) -> String {
    let e = |pname: String, v: String| format!("glTexEnvi(GL_TEXTURE_ENV, {pname}, {v})");
    match p {
        TexEnvParam::Mode(m) => e("GL_TEXTURE_ENV_MODE".into(), n(*m).into()),
        TexEnvParam::Color(c) => format!(
            "glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, {})",
            v4(*c)
        ),
        TexEnvParam::CombineRgb(v) => e("GL_COMBINE_RGB".into(), n(*v).into()),
        TexEnvParam::CombineAlpha(v) => e("GL_COMBINE_ALPHA".into(), n(*v).into()),
        TexEnvParam::SourceRgb(a, s) => e(format!("GL_SOURCE{}_RGB", arg_digit(*a)), source(*s)),
        TexEnvParam::SourceAlpha(a, s) => {
            e(format!("GL_SOURCE{}_ALPHA", arg_digit(*a)), source(*s))
        }
        TexEnvParam::OperandRgb(a, o) => {
            e(format!("GL_OPERAND{}_RGB", arg_digit(*a)), n(*o).into())
        }
        TexEnvParam::OperandAlpha(a, o) => {
            e(format!("GL_OPERAND{}_ALPHA", arg_digit(*a)), n(*o).into())
        }
        TexEnvParam::RgbScale(s) => format!("glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, {})", f(*s)),
        TexEnvParam::AlphaScale(s) => {
            format!("glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, {})", f(*s))
        }
    }
}

fn combiner_input(i: &CombinerInput) -> String {
    format!("{}, {}, {}", register(i.register), n(i.mapping), n(i.usage))
}

/// A compound literal for pixel bytes: the element type of `ty` when the length allows,
/// else GLubyte (both parse back to the same bytes).
fn pixels(ty: PixelType, data: &[u8]) -> String {
    let size = ty.size();
    // C has no literal for a NaN with another payload: such floats go out as their bytes.
    let odd_nan = ty == PixelType::Float
        && data.chunks_exact(4).any(|c| {
            let v = f32::from_le_bytes([c[0], c[1], c[2], c[3]]);
            v.is_nan() && v.to_bits() != f32::NAN.to_bits()
        });
    if size == 1 || data.len() % size != 0 || odd_nan {
        let v: Vec<String> = data.iter().map(|b| b.to_string()).collect();
        return format!("(GLubyte[]){{{}}}", v.join(", "));
    }
    let chunks = data.chunks_exact(size);
    let (name, v): (&str, Vec<String>) = match ty {
        PixelType::UnsignedShort => (
            "GLushort",
            chunks
                .map(|c| u16::from_le_bytes([c[0], c[1]]).to_string())
                .collect(),
        ),
        PixelType::UnsignedInt => (
            "GLuint",
            chunks
                .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]).to_string())
                .collect(),
        ),
        _ => (
            "GLfloat",
            chunks
                .map(|c| f(f32::from_le_bytes([c[0], c[1], c[2], c[3]])))
                .collect(),
        ),
    };
    format!("({name}[]){{{}}}", v.join(", "))
}

fn tex_image(out: &mut String, t: &TexImage) {
    let data = match &t.data {
        TexData::Null => "NULL".to_string(),
        TexData::Bytes(d) => pixels(t.ty, d),
        TexData::Readback(slot) => format!("readback_{slot}"),
        TexData::ConvertedDepth { slot, ty, rule } => {
            let name = super::parse::DEPTH_HELPERS
                .iter()
                .find(|(_, t, r)| t == ty && r == rule)
                .map_or("fixedfunc_depth_ushort_round", |(n, _, _)| n);
            format!("{name}(readback_{slot})")
        }
    };
    let (name, size) = match t.target {
        TextureTarget::Texture1D => ("glTexImage1D", format!("{}", t.width)),
        TextureTarget::Texture2D => ("glTexImage2D", format!("{}, {}", t.width, t.height)),
    };
    line(
        out,
        format_args!(
            "{name}({}, {}, {}, {size}, {}, {}, {}, {data})",
            n(t.target),
            t.level,
            n(t.internal_format),
            t.border,
            n(t.format),
            n(t.ty)
        ),
    );
}

/// glBegin/glEnd; indexed geometry is printed de-indexed.
fn draw(out: &mut String, g: &Geometry) {
    line(out, format_args!("glBegin({})", n(g.primitive)));
    let order: Vec<usize> = match &g.indices {
        Some(idx) => idx.iter().map(|&i| i as usize).collect(),
        None => (0..g.positions.len()).collect(),
    };
    for i in order {
        let Some(p) = g.positions.get(i) else {
            continue;
        };
        if let Some(c) = g.colors.as_ref().and_then(|v| v.get(i)) {
            line(out, format_args!("  glColor4f({})", fs(&c.to_array())));
        }
        if let Some(nrm) = g.normals.as_ref().and_then(|v| v.get(i)) {
            line(out, format_args!("  glNormal3f({})", fs(&nrm.to_array())));
        }
        for (u, t) in g.texcoords.iter().enumerate() {
            if let Some(t) = t.as_ref().and_then(|v| v.get(i)) {
                let unit = Family::Texture.print(u as u8);
                line(
                    out,
                    format_args!("  glMultiTexCoord4f({unit}, {})", fs(&t.to_array())),
                );
            }
        }
        if p.w == 1.0 {
            line(
                out,
                format_args!("  glVertex3f({})", fs(&p.truncate().to_array())),
            );
        } else {
            line(out, format_args!("  glVertex4f({})", fs(&p.to_array())));
        }
    }
    line(out, format_args!("glEnd()"));
}
