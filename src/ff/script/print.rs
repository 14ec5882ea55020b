//! Commands → script text, the inverse of `parse`: one GL call per line, valid C99.
//!
//! Floats print in Rust's shortest round-trip form (`0.1`, `1e-7`), which parses back to the
//! same f32; non-finite values print as `INFINITY`/`NAN` (<math.h>). Draws print as
//! glBegin/glEnd with every present attribute before every vertex.

use crate::ff::queries::QueryCommand;
use std::fmt::Write;

use glam::Vec4;

use super::names::{Family, GlEnum};
use crate::ff::api::Entry;
use crate::ff::*;

/// Prints commands as a script (read back with GL's default GL_UNPACK_ALIGNMENT, 4).
pub fn print(cmds: &[Command]) -> String {
    print_aligned(cmds, 4)
}

/// Prints commands as a script read with GL_UNPACK_ALIGNMENT `unpack_alignment`: pixel
/// data (held as tightly packed rows) is printed with each row padded to it by zeros
/// (GL 1.5 §3.6.4), so that parsing reads the same rows back.
pub fn print_aligned(cmds: &[Command], unpack_alignment: usize) -> String {
    let mut out = String::new();
    for c in cmds {
        command(&mut out, c, unpack_alignment);
    }
    out
}

/// `data`'s rows of `row` bytes each padded to `alignment` (the last row is not padded:
/// GL reads only its pixels).
pub(super) fn padded(data: &[u8], row: usize, alignment: usize) -> std::borrow::Cow<'_, [u8]> {
    let stride = crate::ff::pixel_store::PixelStore::stride(row, alignment);
    if row == 0 || stride == row || data.len() <= row {
        return std::borrow::Cow::Borrowed(data);
    }
    let mut out = Vec::with_capacity(data.len() / row * stride);
    let rows: Vec<&[u8]> = data.chunks(row).collect();
    for (k, r) in rows.iter().enumerate() {
        out.extend_from_slice(r);
        if k + 1 < rows.len() {
            out.resize(out.len() + stride - row, 0);
        }
    }
    std::borrow::Cow::Owned(out)
}

/// The bytes of an image of `width × height` groups (images one after the other) as a
/// script writes them at `alignment`: rows padded ([`padded`]); a COLOR_INDEX image, read
/// as one run an image (`pixel_layout`), as its runs, each but the last padded to the
/// image's padded rows.
pub(super) fn image_bytes(
    data: &[u8],
    format: PixelFormat,
    ty: PixelType,
    (width, height): (i32, i32),
    alignment: usize,
) -> std::borrow::Cow<'_, [u8]> {
    let row = width.max(0) as usize * ty.group_bytes(format);
    if format != PixelFormat::ColorIndex {
        return padded(data, row, alignment);
    }
    let run = row * height.max(0) as usize;
    let image = crate::ff::pixel_store::PixelStore::stride(row, alignment) * height.max(0) as usize;
    if run == 0 || data.len() <= run {
        return std::borrow::Cow::Borrowed(data);
    }
    let runs: Vec<&[u8]> = data.chunks(run).collect();
    let mut out = Vec::with_capacity(runs.len() * image);
    for (k, r) in runs.iter().enumerate() {
        out.extend_from_slice(r);
        if k + 1 < runs.len() {
            out.resize(out.len() + image - run, 0);
        }
    }
    std::borrow::Cow::Owned(out)
}

/// C's spelling of a non-finite value (math.h's NAN and INFINITY); None for a number.
fn non_finite(v: f64) -> Option<&'static str> {
    match v {
        v if v.is_nan() => Some("NAN"),
        v if v.is_infinite() && v > 0.0 => Some("INFINITY"),
        v if v.is_infinite() => Some("-INFINITY"),
        _ => None,
    }
}

pub(super) fn f(v: f32) -> String {
    non_finite(f64::from(v)).map_or_else(|| format!("{v:?}"), String::from)
}

/// A GLdouble argument, every digit kept (Rust's shortest round-trip form).
fn double(v: f64) -> String {
    non_finite(v).map_or_else(|| format!("{v:?}"), String::from)
}

pub(super) fn fs(vs: &[f32]) -> String {
    vs.iter().map(|v| f(*v)).collect::<Vec<_>>().join(", ")
}

fn arr(vs: &[f32]) -> String {
    format!("(GLfloat[]){{{}}}", fs(vs))
}

fn v4(v: Vec4) -> String {
    arr(&v.to_array())
}

/// The token of a value; every table covers its enum, so the fallback is never printed.
pub(super) fn n<T: GlEnum>(v: T) -> &'static str {
    v.gl_name().unwrap_or("GL_NONE")
}

fn b(v: bool) -> &'static str {
    n(v)
}

fn capability(c: Capability) -> String {
    match c {
        Capability::Light(i) => Family::Light.print(i),
        Capability::ClipPlane(i) => Family::ClipPlane.print(i),
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

fn command(out: &mut String, c: &Command, unpack_alignment: usize) {
    match c {
        Command::Draw(g) => draw(out, g),
        Command::TexImage(t) => tex_image(out, t, n(t.target), unpack_alignment),
        Command::ProxyTexImage(t) => {
            let target = match t.target {
                TextureTarget::Texture1D => "GL_PROXY_TEXTURE_1D",
                TextureTarget::Texture3D => "GL_PROXY_TEXTURE_3D",
                TextureTarget::CubeMap | TextureTarget::CubeFace(_) => "GL_PROXY_TEXTURE_CUBE_MAP",
                TextureTarget::Texture2D => "GL_PROXY_TEXTURE_2D",
            };
            tex_image(out, t, target, unpack_alignment)
        }
        Command::TexSubImage3D(t) => line(
            out,
            format_args!(
                "{}(GL_TEXTURE_3D, {}, {}, {}, {}, {}, {}, {}, {}, {}, {})",
                Entry::TexSubImage3D,
                t.level,
                t.x,
                t.y,
                t.z,
                t.width,
                t.height,
                t.depth,
                n(t.format),
                n(t.ty),
                sub_image_pixels(t, unpack_alignment)
            ),
        ),
        Command::CompressedTexImage2D(t) => line(
            out,
            format_args!(
                "{}({}, {}, {}, {}, {}, 0, {}, {})",
                Entry::CompressedTexImage2D,
                if t.proxy {
                    "GL_PROXY_TEXTURE_2D"
                } else {
                    "GL_TEXTURE_2D"
                },
                t.level,
                n(t.format),
                t.width,
                t.height,
                t.format.image_size(t.width, t.height),
                blocks(&t.data)
            ),
        ),
        Command::CompressedTexSubImage2D(t) => line(
            out,
            format_args!(
                "{}(GL_TEXTURE_2D, {}, {}, {}, {}, {}, {}, {}, {})",
                Entry::CompressedTexSubImage2D,
                t.level,
                t.x,
                t.y,
                t.width,
                t.height,
                n(t.format),
                t.format.image_size(t.width, t.height),
                blocks(&t.data)
            ),
        ),
        Command::TexSubImage2D(t) => line(
            out,
            format_args!(
                "{}({}, {}, {}, {}, {}, {}, {}, {}, {})",
                Entry::TexSubImage2D,
                n(t.target_2d()),
                t.level,
                t.x,
                t.y,
                t.width,
                t.height,
                n(t.format),
                n(t.ty),
                sub_image_pixels(t, unpack_alignment)
            ),
        ),
        Command::TexSubImage1D(t) => line(
            out,
            format_args!(
                "{}(GL_TEXTURE_1D, {}, {}, {}, {}, {}, {})",
                Entry::TexSubImage1D,
                t.level,
                t.x,
                t.width,
                n(t.format),
                n(t.ty),
                t.data
                    .as_ref()
                    .map_or("NULL".to_string(), |d| pixels(t.ty, d))
            ),
        ),
        Command::Raise { error, call } => out.push_str(&format!(
            "/* {call}: {error:?} raised here by a display list */\n"
        )),
        Command::UseProgram(_) | Command::Uniform { .. } => {
            out.push_str(&program_comment(c));
            out.push('\n');
        }
        Command::Bitmap(_) | Command::DrawPixels(_) | Command::PolygonStipple(_) => line(
            out,
            format_args!("{}", super::print_pixels::call(c, unpack_alignment)),
        ),
        other => line(out, format_args!("{}", call(other))),
    }
}

/// Every command but Draw, TexImage and TexSubImage2D, as one call without the ';'.
fn call(c: &Command) -> String {
    match c {
        Command::MatrixMode(m) => format!("{}({})", Entry::MatrixMode, n(*m)),
        Command::LoadIdentity => format!("{}()", Entry::LoadIdentity),
        Command::LoadMatrix(m) => format!("{}({})", Entry::LoadMatrixf, arr(&m.to_cols_array())),
        Command::MultMatrix(m) => format!("{}({})", Entry::MultMatrixf, arr(&m.to_cols_array())),
        Command::PushMatrix => format!("{}()", Entry::PushMatrix),
        Command::DeleteTextures(names) => name_list(Entry::DeleteTextures, names),
        Command::PrioritizeTextures(given) => {
            let names: Vec<String> = given.iter().map(|(n, _)| n.to_string()).collect();
            let priorities: Vec<String> = given.iter().map(|(_, p)| f(*p)).collect();
            format!(
                "{}({}, (GLuint[]){{{}}}, (GLfloat[]){{{}}})",
                Entry::PrioritizeTextures,
                given.len(),
                names.join(", "),
                priorities.join(", ")
            )
        }
        Command::PopMatrix => format!("{}()", Entry::PopMatrix),
        Command::Translate(v) => format!("{}({})", Entry::Translatef, fs(&v.to_array())),
        Command::Rotate { angle_deg, axis } => {
            format!(
                "{}({}, {})",
                Entry::Rotatef,
                f(*angle_deg),
                fs(&axis.to_array())
            )
        }
        Command::Scale(v) => format!("{}({})", Entry::Scalef, fs(&v.to_array())),
        Command::Frustum(v) => format!("{}({})", Entry::Frustum, volume(v)),
        Command::Ortho(v) => format!("{}({})", Entry::Ortho, volume(v)),
        Command::Viewport(v) => format!(
            "{}({}, {}, {}, {})",
            Entry::Viewport,
            v.x,
            v.y,
            v.width,
            v.height
        ),
        Command::DepthRange { near, far } => {
            format!("{}({}, {})", Entry::DepthRange, f(*near), f(*far))
        }
        Command::Enable(cap) => format!("{}({})", Entry::Enable, capability(*cap)),
        Command::Disable(cap) => format!("{}({})", Entry::Disable, capability(*cap)),
        Command::Color(c) => format!("{}({})", Entry::Color4f, fs(&c.to_array())),
        Command::Normal(v) => format!("{}({})", Entry::Normal3f, fs(&v.to_array())),
        Command::EdgeFlag(on) => format!("{}({})", Entry::EdgeFlag, b(*on)),
        // glSecondaryColor has no alpha: a size-4 array element's alpha is not printed.
        Command::SecondaryColor(c) => {
            format!(
                "{}({})",
                Entry::SecondaryColor3f,
                fs(&c.truncate().to_array())
            )
        }
        Command::FogCoord(x) => format!("{}({})", Entry::FogCoordf, f(*x)),
        Command::Index(c) => format!("{}({})", Entry::Indexf, f(*c)),
        Command::ClearIndex(c) => format!("{}({})", Entry::ClearIndex, f(*c)),
        Command::IndexMask(m) => format!("{}(0x{m:X})", Entry::IndexMask),
        Command::SampleCoverage { value, invert } => {
            format!("{}({}, {})", Entry::SampleCoverage, f(*value), b(*invert))
        }
        Command::TexCoord { unit, coord } => format!(
            "{}({}, {})",
            Entry::MultiTexCoord4f,
            Family::Texture.print(*unit),
            fs(&coord.to_array())
        ),
        Command::Light { light, param } => light_call(Family::Light.print(*light), param),
        Command::LightModel(p) => match p {
            LightModelParam::Ambient(c) => {
                format!(
                    "{}(GL_LIGHT_MODEL_AMBIENT, {})",
                    Entry::LightModelfv,
                    v4(*c)
                )
            }
            LightModelParam::LocalViewer(v) => {
                format!(
                    "{}(GL_LIGHT_MODEL_LOCAL_VIEWER, {})",
                    Entry::LightModeli,
                    b(*v)
                )
            }
            LightModelParam::TwoSide(v) => {
                format!("{}(GL_LIGHT_MODEL_TWO_SIDE, {})", Entry::LightModeli, b(*v))
            }
            LightModelParam::ColorControl(v) => {
                format!(
                    "{}(GL_LIGHT_MODEL_COLOR_CONTROL, {})",
                    Entry::LightModeli,
                    n(*v)
                )
            }
        },
        Command::Material { face, param } => material(n(*face), param),
        Command::ColorMaterial { face, mode } => {
            format!("{}({}, {})", Entry::ColorMaterial, n(*face), n(*mode))
        }
        Command::ShadeModel(m) => format!("{}({})", Entry::ShadeModel, n(*m)),
        Command::ActiveTexture(u) => {
            format!("{}({})", Entry::ActiveTexture, Family::Texture.print(*u))
        }
        Command::BindTexture { target, name } => {
            format!("{}({}, {name})", Entry::BindTexture, n(*target))
        }
        Command::CopyTexImage2D(t) => format!(
            "{}({}, {}, {}, {}, {}, {}, {}, {})",
            Entry::CopyTexImage2D,
            n(t.target_2d()),
            t.level,
            internal_format(t.internal_format, t.requested),
            t.x,
            t.y,
            t.width,
            t.height,
            t.border
        ),
        Command::TexParameter { target, param } => tex_param(n(*target), param),
        Command::TexGen { coord, param } => match param {
            TexGenParam::Mode(m) => {
                format!(
                    "{}({}, GL_TEXTURE_GEN_MODE, {})",
                    Entry::TexGeni,
                    n(*coord),
                    n(*m)
                )
            }
            TexGenParam::ObjectPlane(p) => {
                format!(
                    "{}({}, GL_OBJECT_PLANE, {})",
                    Entry::TexGenfv,
                    n(*coord),
                    v4(*p)
                )
            }
            TexGenParam::EyePlane(p) => {
                format!(
                    "{}({}, GL_EYE_PLANE, {})",
                    Entry::TexGenfv,
                    n(*coord),
                    v4(*p)
                )
            }
        },
        Command::TexEnv(p) => tex_env(p),
        Command::CombinerParameter(p) => match p {
            CombinerParam::NumGeneralCombiners(k) => {
                format!(
                    "{}(GL_NUM_GENERAL_COMBINERS_NV, {k})",
                    Entry::CombinerParameteriNV
                )
            }
            CombinerParam::ColorSumClamp(v) => {
                format!(
                    "{}(GL_COLOR_SUM_CLAMP_NV, {})",
                    Entry::CombinerParameteriNV,
                    b(*v)
                )
            }
            CombinerParam::ConstantColor0(c) => {
                format!(
                    "{}(GL_CONSTANT_COLOR0_NV, {})",
                    Entry::CombinerParameterfvNV,
                    v4(*c)
                )
            }
            CombinerParam::ConstantColor1(c) => {
                format!(
                    "{}(GL_CONSTANT_COLOR1_NV, {})",
                    Entry::CombinerParameterfvNV,
                    v4(*c)
                )
            }
        },
        Command::CombinerInput {
            stage,
            portion,
            variable,
            input,
        } => format!(
            "{}({}, {}, {}, {})",
            Entry::CombinerInputNV,
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
            "{}({}, {}, {}, {}, {}, {}, {}, {}, {}, {})",
            Entry::CombinerOutputNV,
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
                "{}({}, {})",
                Entry::FinalCombinerInputNV,
                n(*variable),
                combiner_input(input)
            )
        }
        Command::AlphaFunc { func, reference } => {
            format!("{}({}, {})", Entry::AlphaFunc, n(*func), f(*reference))
        }
        Command::DepthFunc(func) => format!("{}({})", Entry::DepthFunc, n(*func)),
        Command::DepthMask(v) => format!("{}({})", Entry::DepthMask, b(*v)),
        Command::StencilFunc {
            func,
            reference,
            mask,
        } => {
            format!(
                "{}({}, {reference}, 0x{mask:X})",
                Entry::StencilFunc,
                n(*func)
            )
        }
        Command::StencilOp {
            fail,
            depth_fail,
            depth_pass,
        } => {
            format!(
                "{}({}, {}, {})",
                Entry::StencilOp,
                n(*fail),
                n(*depth_fail),
                n(*depth_pass)
            )
        }
        Command::StencilMask(m) => format!("{}(0x{m:X})", Entry::StencilMask),
        Command::BlendFunc { src, dst } => {
            format!("{}({}, {})", Entry::BlendFunc, n(*src), n(*dst))
        }
        Command::ColorMask(m) => format!(
            "{}({}, {}, {}, {})",
            Entry::ColorMask,
            b(m.r),
            b(m.g),
            b(m.b),
            b(m.a)
        ),
        Command::PolygonOffset { factor, units } => {
            format!("{}({}, {})", Entry::PolygonOffset, f(*factor), f(*units))
        }
        Command::PolygonMode { face, mode } => {
            format!("{}({}, {})", Entry::PolygonMode, n(*face), n(*mode))
        }
        Command::CullFace(face) => format!("{}({})", Entry::CullFace, n(*face)),
        Command::FrontFace(face) => format!("{}({})", Entry::FrontFace, n(*face)),
        Command::LineWidth(w) => format!("{}({})", Entry::LineWidth, f(*w)),
        Command::PointSize(s) => format!("{}({})", Entry::PointSize, f(*s)),
        Command::Fog(p) => fog(p),
        Command::PointParameter(p) => point_parameter(p),
        Command::BlendColor(c) => format!("{}({})", Entry::BlendColor, fs(&c.to_array())),
        Command::BlendEquation(e) => format!("{}({})", Entry::BlendEquation, n(*e)),
        Command::BlendFuncSeparate {
            src_rgb,
            dst_rgb,
            src_alpha,
            dst_alpha,
        } => format!(
            "{}({}, {}, {}, {})",
            Entry::BlendFuncSeparate,
            n(*src_rgb),
            n(*dst_rgb),
            n(*src_alpha),
            n(*dst_alpha)
        ),
        Command::Hint { target, mode } => {
            format!("{}({}, {})", Entry::Hint, n(*target), n(*mode))
        }
        Command::LogicOp(op) => format!("{}({})", Entry::LogicOp, n(*op)),
        // glClipPlane reads doubles: the f32 values print exactly as doubles.
        Command::ClipPlane { plane, equation } => format!(
            "{}({}, (GLdouble[]){{{}}})",
            Entry::ClipPlane,
            Family::ClipPlane.print(*plane),
            fs(&equation.to_array())
        ),
        Command::Scissor(b) => format!(
            "{}({}, {}, {}, {})",
            Entry::Scissor,
            b.x,
            b.y,
            b.width,
            b.height
        ),
        Command::Clear(m) => format!("{}({})", Entry::Clear, clear_mask(*m)),
        Command::ClearColor(c) => format!("{}({})", Entry::ClearColor, fs(&c.to_array())),
        Command::ClearDepth(d) => format!("{}({})", Entry::ClearDepth, double(*d)),
        Command::ClearStencil(s) => format!("{}({s})", Entry::ClearStencil),
        Command::ClearAccum(c) => format!("{}({})", Entry::ClearAccum, fs(&c.to_array())),
        Command::Accum { op, value } => format!("{}({}, {})", Entry::Accum, n(*op), f(*value)),
        Command::ReadPixels(r) => format!(
            "{}({}, {}, {}, {}, {}, {}, readback_{})",
            Entry::ReadPixels,
            r.x,
            r.y,
            r.width,
            r.height,
            n(r.format),
            n(r.ty),
            r.slot
        ),
        Command::PushAttrib(m) => format!("{}({})", Entry::PushAttrib, attrib_mask(*m)),
        Command::PopAttrib => format!("{}()", Entry::PopAttrib),
        Command::BindFramebuffer { target, name } => {
            format!("{}({}, {name})", Entry::BindFramebuffer, n(*target))
        }
        Command::DeleteFramebuffers(names) => name_list(Entry::DeleteFramebuffers, names),
        Command::Query(q) => query(q),
        Command::UseProgram(_) | Command::Uniform { .. } => program_comment(c),
        Command::BindRenderbuffer(name) => {
            format!("{}(GL_RENDERBUFFER, {name})", Entry::BindRenderbuffer)
        }
        Command::DeleteRenderbuffers(names) => name_list(Entry::DeleteRenderbuffers, names),
        Command::RenderbufferStorage {
            format,
            width,
            height,
        } => format!(
            "{}(GL_RENDERBUFFER, {}, {width}, {height})",
            Entry::RenderbufferStorage,
            n(*format)
        ),
        Command::FramebufferTexture {
            target,
            attachment,
            texture,
            level,
            layer,
        } => {
            let (textarget, name) = texture.unwrap_or((crate::ff::TextureTarget::Texture2D, 0));
            let layer = match textarget {
                crate::ff::TextureTarget::Texture3D => format!(", {layer}"),
                _ => String::new(),
            };
            format!(
                "{}({}, {}, {}, {name}, {level}{layer})",
                c.entry(),
                n(*target),
                n(*attachment),
                n(textarget)
            )
        }
        Command::FramebufferRenderbuffer {
            target,
            attachment,
            renderbuffer,
        } => format!(
            "{}({}, {}, GL_RENDERBUFFER, {renderbuffer})",
            Entry::FramebufferRenderbuffer,
            n(*target),
            n(*attachment)
        ),
        Command::DrawBuffer(b) => format!("{}({})", Entry::DrawBuffer, n(*b)),
        Command::ReadBuffer(b) => format!("{}({})", Entry::ReadBuffer, n(*b)),
        Command::ListBase(base) => format!("{}({base})", Entry::ListBase),
        Command::GenerateMipmap(t) => format!("{}({})", Entry::GenerateMipmap, n(*t)),
        Command::BlitFramebuffer(b) => blit(b),
        Command::CopyTexImage1D(c) => format!(
            "{}(GL_TEXTURE_1D, {}, {}, {}, {}, {}, {})",
            Entry::CopyTexImage1D,
            c.level,
            internal_format(c.internal_format, c.requested),
            c.x,
            c.y,
            c.width,
            c.border
        ),
        Command::CopyTexSubImage(c) => match c.target {
            TextureTarget::Texture1D => format!(
                "{}(GL_TEXTURE_1D, {}, {}, {}, {}, {})",
                Entry::CopyTexSubImage1D,
                c.level,
                c.xoffset,
                c.x,
                c.y,
                c.width
            ),
            TextureTarget::Texture2D | TextureTarget::CubeMap | TextureTarget::CubeFace(_) => {
                format!(
                    "{}({}, {}, {}, {}, {}, {}, {}, {})",
                    Entry::CopyTexSubImage2D,
                    n(c.target),
                    c.level,
                    c.xoffset,
                    c.yoffset,
                    c.x,
                    c.y,
                    c.width,
                    c.height
                )
            }
            TextureTarget::Texture3D => format!(
                "{}(GL_TEXTURE_3D, {}, {}, {}, {}, {}, {}, {}, {})",
                Entry::CopyTexSubImage3D,
                c.level,
                c.xoffset,
                c.yoffset,
                c.zoffset,
                c.x,
                c.y,
                c.width,
                c.height
            ),
        },
        Command::GetTexImage(g) => format!(
            "{}({}, {}, {}, {}, readback_{})",
            Entry::GetTexImage,
            n(g.target),
            g.level,
            n(g.format),
            n(g.ty),
            g.slot
        ),
        Command::RasterPos(_)
        | Command::WindowPos(_)
        | Command::Bitmap(_)
        | Command::DrawPixels(_)
        | Command::CopyPixels(_)
        | Command::PixelTransfer(_)
        | Command::PixelZoom { .. }
        | Command::PolygonStipple(_) => super::print_pixels::call(c, 1),
        Command::PixelMap(m) => format!(
            "{}({}, {}, {})",
            Entry::PixelMapfv,
            n(m.map),
            m.values.len(),
            arr(&m.values)
        ),
        Command::LineStipple(l) => {
            format!("{}({}, 0x{:04X})", Entry::LineStipple, l.factor, l.pattern)
        }
        // Printed by `command`.
        Command::Draw(_)
        | Command::TexImage(_)
        | Command::ProxyTexImage(_)
        | Command::TexSubImage3D(_)
        | Command::TexSubImage2D(_)
        | Command::CompressedTexImage2D(_)
        | Command::CompressedTexSubImage2D(_)
        | Command::TexSubImage1D(_)
        | Command::Raise { .. } => String::new(),
    }
}

/// `glBlitFramebuffer(…)`: a mask with bits of no buffer, or a filter outside the set, as
/// the number given (the model refuses it; a replay refuses it alike).
fn blit(b: &crate::ff::blit::Blit) -> String {
    use crate::ff::blit::FilterArg;
    let (s, d) = (b.src, b.dst);
    let mask = if b.mask.other != 0 {
        format!("0x{:X}", b.mask.bits())
    } else {
        clear_mask(ClearMask {
            color: b.mask.color,
            depth: b.mask.depth,
            stencil: b.mask.stencil,
            accum: false,
        })
    };
    let filter = match b.filter {
        FilterArg::Known(f) => n(f).to_string(),
        FilterArg::Other(v) => format!("0x{v:04X}"),
    };
    format!(
        "{}({}, {}, {}, {}, {}, {}, {}, {}, {mask}, {filter})",
        Entry::BlitFramebuffer,
        s.x0,
        s.y0,
        s.x1,
        s.y1,
        d.x0,
        d.y0,
        d.x1,
        d.y1
    )
}

/// `glDelete…(n, (GLuint[]){a, b})`.
/// A query command; glGenQueries prints the names it gave, which a replay gives again
/// (the model hands them out in the same order).
fn query(q: &QueryCommand) -> String {
    match q {
        QueryCommand::Gen { first, count } => {
            let names: Vec<u32> = (*first..first.saturating_add(*count)).collect();
            name_list(Entry::GenQueries, &names)
        }
        QueryCommand::Delete(names) => name_list(Entry::DeleteQueries, names),
        QueryCommand::Begin { target, id } => {
            format!("{}({}, {id})", Entry::BeginQuery, n(*target))
        }
        QueryCommand::End(target) => format!("{}({})", Entry::EndQuery, n(*target)),
    }
}

fn name_list(entry: Entry, names: &[u32]) -> String {
    let list: Vec<String> = names.iter().map(u32::to_string).collect();
    format!(
        "{entry}({}, (GLuint[]){{{}}})",
        names.len(),
        list.join(", ")
    )
}

fn point_parameter(p: &PointParam) -> String {
    let (pname, v) = match p {
        PointParam::DistanceAttenuation([a, b, c]) => {
            return format!(
                "{}(GL_POINT_DISTANCE_ATTENUATION, (GLfloat[]){{{}, {}, {}}})",
                Entry::PointParameterfv,
                f(*a),
                f(*b),
                f(*c)
            )
        }
        PointParam::SpriteCoordOrigin(o) => {
            let name = if *o == crate::ff::point::LOWER_LEFT {
                "GL_LOWER_LEFT"
            } else {
                "GL_UPPER_LEFT"
            };
            return format!(
                "{}(GL_POINT_SPRITE_COORD_ORIGIN, {name})",
                Entry::PointParameteri
            );
        }
        PointParam::SizeMin(v) => ("GL_POINT_SIZE_MIN", v),
        PointParam::SizeMax(v) => ("GL_POINT_SIZE_MAX", v),
        PointParam::FadeThreshold(v) => ("GL_POINT_FADE_THRESHOLD_SIZE", v),
    };
    format!("{}({pname}, {})", Entry::PointParameterf, f(*v))
}

fn fog(p: &FogParam) -> String {
    let (pname, v) = match p {
        FogParam::Mode(m) => return format!("{}(GL_FOG_MODE, {})", Entry::Fogi, n(*m)),
        FogParam::CoordSource(s) => return format!("{}(GL_FOG_COORD_SRC, {})", Entry::Fogi, n(*s)),
        FogParam::Color(c) => return format!("{}(GL_FOG_COLOR, {})", Entry::Fogfv, v4(*c)),
        FogParam::Density(v) => ("GL_FOG_DENSITY", v),
        FogParam::Start(v) => ("GL_FOG_START", v),
        FogParam::End(v) => ("GL_FOG_END", v),
        FogParam::Index(v) => ("GL_FOG_INDEX", v),
    };
    format!("{}({pname}, {})", Entry::Fogf, f(*v))
}

fn volume(v: &ViewVolume) -> String {
    fs(&[v.left, v.right, v.bottom, v.top, v.near, v.far])
}

fn clear_mask(m: ClearMask) -> String {
    let bits: Vec<&str> = [
        (m.color, "GL_COLOR_BUFFER_BIT"),
        (m.depth, "GL_DEPTH_BUFFER_BIT"),
        (m.stencil, "GL_STENCIL_BUFFER_BIT"),
        (m.accum, "GL_ACCUM_BUFFER_BIT"),
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

/// GL_ALL_ATTRIB_BITS, or the group bits joined by '|', or 0; a mask with bits of no group
/// (which GL ignores) prints as one hex number, so it reads back the same.
fn attrib_mask(m: AttribMask) -> String {
    if m == AttribMask::ALL {
        return "GL_ALL_ATTRIB_BITS".into();
    }
    if m.0 & !AttribMask::of(&AttribGroup::ALL).0 != 0 {
        return format!("{:#x}", m.0);
    }
    let parts: Vec<&str> = m.groups().map(n).collect();
    if parts.is_empty() {
        "0".into()
    } else {
        parts.join(" | ")
    }
}

fn light_call(l: String, p: &LightParam) -> String {
    match p {
        LightParam::Ambient(c) => format!("{}({l}, GL_AMBIENT, {})", Entry::Lightfv, v4(*c)),
        LightParam::Diffuse(c) => format!("{}({l}, GL_DIFFUSE, {})", Entry::Lightfv, v4(*c)),
        LightParam::Specular(c) => format!("{}({l}, GL_SPECULAR, {})", Entry::Lightfv, v4(*c)),
        LightParam::Position(c) => format!("{}({l}, GL_POSITION, {})", Entry::Lightfv, v4(*c)),
        LightParam::SpotDirection(d) => {
            format!(
                "{}({l}, GL_SPOT_DIRECTION, {})",
                Entry::Lightfv,
                arr(&d.to_array())
            )
        }
        LightParam::SpotExponent(v) => {
            format!("{}({l}, GL_SPOT_EXPONENT, {})", Entry::Lightf, f(*v))
        }
        LightParam::SpotCutoff(v) => format!("{}({l}, GL_SPOT_CUTOFF, {})", Entry::Lightf, f(*v)),
        LightParam::ConstantAttenuation(v) => {
            format!("{}({l}, GL_CONSTANT_ATTENUATION, {})", Entry::Lightf, f(*v))
        }
        LightParam::LinearAttenuation(v) => {
            format!("{}({l}, GL_LINEAR_ATTENUATION, {})", Entry::Lightf, f(*v))
        }
        LightParam::QuadraticAttenuation(v) => {
            format!(
                "{}({l}, GL_QUADRATIC_ATTENUATION, {})",
                Entry::Lightf,
                f(*v)
            )
        }
    }
}

fn material(face: &str, p: &MaterialParam) -> String {
    let (pname, v) = match p {
        MaterialParam::Shininess(s) => {
            return format!("{}({face}, GL_SHININESS, {})", Entry::Materialf, f(*s))
        }
        MaterialParam::ColorIndexes(i) => {
            return format!(
                "{}({face}, GL_COLOR_INDEXES, {})",
                Entry::Materialfv,
                arr(&i.to_array())
            )
        }
        MaterialParam::Ambient(v) => ("GL_AMBIENT", v),
        MaterialParam::Diffuse(v) => ("GL_DIFFUSE", v),
        MaterialParam::AmbientAndDiffuse(v) => ("GL_AMBIENT_AND_DIFFUSE", v),
        MaterialParam::Specular(v) => ("GL_SPECULAR", v),
        MaterialParam::Emission(v) => ("GL_EMISSION", v),
    };
    format!("{}({face}, {pname}, {})", Entry::Materialfv, v4(*v))
}

fn tex_param(target: &str, p: &TexParam) -> String {
    let (pname, value) = match p {
        TexParam::BorderColor(c) => {
            return format!(
                "{}({target}, GL_TEXTURE_BORDER_COLOR, {})",
                Entry::TexParameterfv,
                v4(*c)
            )
        }
        TexParam::CompareFailValue(v) => {
            return format!(
                "{}({target}, GL_TEXTURE_COMPARE_FAIL_VALUE_ARB, {})",
                Entry::TexParameterf,
                f(*v)
            )
        }
        TexParam::MinFilter(v) => ("GL_TEXTURE_MIN_FILTER", n(*v)),
        TexParam::MagFilter(v) => ("GL_TEXTURE_MAG_FILTER", n(*v)),
        TexParam::WrapS(v) => ("GL_TEXTURE_WRAP_S", n(*v)),
        TexParam::WrapT(v) => ("GL_TEXTURE_WRAP_T", n(*v)),
        TexParam::WrapR(v) => ("GL_TEXTURE_WRAP_R", n(*v)),
        TexParam::CompareMode(v) => ("GL_TEXTURE_COMPARE_MODE", n(*v)),
        TexParam::CompareFunc(v) => ("GL_TEXTURE_COMPARE_FUNC", n(*v)),
        TexParam::DepthTextureMode(v) => ("GL_DEPTH_TEXTURE_MODE", n(*v)),
        TexParam::GenerateMipmap(v) => ("GL_GENERATE_MIPMAP", b(*v)),
        TexParam::BaseLevel(v) | TexParam::MaxLevel(v) => {
            let pname = match p {
                TexParam::BaseLevel(_) => "GL_TEXTURE_BASE_LEVEL",
                _ => "GL_TEXTURE_MAX_LEVEL",
            };
            return format!("{}({target}, {pname}, {v})", Entry::TexParameteri);
        }
        TexParam::MinLod(v)
        | TexParam::MaxLod(v)
        | TexParam::LodBias(v)
        | TexParam::Priority(v)
        | TexParam::MaxAnisotropy(v) => {
            let pname = match p {
                TexParam::MinLod(_) => "GL_TEXTURE_MIN_LOD",
                TexParam::MaxLod(_) => "GL_TEXTURE_MAX_LOD",
                TexParam::LodBias(_) => "GL_TEXTURE_LOD_BIAS",
                TexParam::MaxAnisotropy(_) => "GL_TEXTURE_MAX_ANISOTROPY_EXT",
                _ => "GL_TEXTURE_PRIORITY",
            };
            return format!("{}({target}, {pname}, {})", Entry::TexParameterf, f(*v));
        }
    };
    format!("{}({target}, {pname}, {value})", Entry::TexParameteri)
}

fn arg_digit(a: CombineArg) -> usize {
    a.index()
}

fn tex_env(p: &TexEnvParam) -> String {
    let e = |pname: String, v: String| format!("{}(GL_TEXTURE_ENV, {pname}, {v})", Entry::TexEnvi);
    match p {
        TexEnvParam::Mode(m) => e("GL_TEXTURE_ENV_MODE".into(), n(*m).into()),
        TexEnvParam::Color(c) => format!(
            "{}(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, {})",
            Entry::TexEnvfv,
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
        TexEnvParam::RgbScale(s) => format!(
            "{}(GL_TEXTURE_ENV, GL_RGB_SCALE, {})",
            Entry::TexEnvf,
            f(*s)
        ),
        TexEnvParam::AlphaScale(s) => {
            format!(
                "{}(GL_TEXTURE_ENV, GL_ALPHA_SCALE, {})",
                Entry::TexEnvf,
                f(*s)
            )
        }
        TexEnvParam::LodBias(b) => format!(
            "{}(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, {})",
            Entry::TexEnvf,
            f(*b)
        ),
        TexEnvParam::CoordReplace(on) => format!(
            "{}(GL_POINT_SPRITE, GL_COORD_REPLACE, {})",
            Entry::TexEnvi,
            if *on { "GL_TRUE" } else { "GL_FALSE" }
        ),
    }
}

fn combiner_input(i: &CombinerInput) -> String {
    format!("{}, {}, {}", register(i.register), n(i.mapping), n(i.usage))
}

/// A compound literal for pixel bytes: the element type of `ty` when the length allows,
/// else GLubyte (both parse back to the same bytes).
pub(super) fn pixels(ty: PixelType, data: &[u8]) -> String {
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
        PixelType::UnsignedInt | PixelType::Packed(_) if size == 4 => (
            "GLuint",
            chunks
                .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]).to_string())
                .collect(),
        ),
        PixelType::Packed(_) => (
            "GLushort",
            chunks
                .map(|c| u16::from_le_bytes([c[0], c[1]]).to_string())
                .collect(),
        ),
        PixelType::Short => (
            "GLshort",
            chunks
                .map(|c| i16::from_le_bytes([c[0], c[1]]).to_string())
                .collect(),
        ),
        PixelType::Int => (
            "GLint",
            chunks
                .map(|c| i32::from_le_bytes([c[0], c[1], c[2], c[3]]).to_string())
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

/// A texture's internal format as the program named it: a component count, the name it
/// gave, or the sized format's name.
fn internal_format(f: TexFormat, requested: Option<u32>) -> String {
    match requested {
        Some(v @ 1..=4) => v.to_string(),
        Some(v) => TexFormat::TABLE
            .iter()
            .find(|(_, value, _)| *value == v)
            .map_or(n(f), |(name, _, _)| name)
            .to_string(),
        None => n(f).to_string(),
    }
}

/// Compressed blocks as a GLubyte literal, or NULL.
fn blocks(data: &Option<std::sync::Arc<[u8]>>) -> String {
    data.as_ref().map_or_else(
        || "NULL".to_string(),
        |d| pixels(PixelType::UnsignedByte, d),
    )
}

/// A glTexSubImage2D/3D's pixels, rows padded to the unpack alignment, or NULL.
fn sub_image_pixels(t: &TexSubImage, unpack_alignment: usize) -> String {
    t.data.as_ref().map_or("NULL".to_string(), |d| {
        let shape = (t.width, t.height);
        pixels(
            t.ty,
            &image_bytes(d, t.format, t.ty, shape, unpack_alignment),
        )
    })
}

/// glTexImage1D/2D/3D of `target` (its token: a proxy image prints its proxy target).
fn tex_image(out: &mut String, t: &TexImage, target: &str, unpack_alignment: usize) {
    let data = match &t.data {
        TexData::Null => "NULL".to_string(),
        TexData::Bytes(d) => {
            let shape = (t.width, t.height);
            pixels(
                t.ty,
                &image_bytes(d, t.format, t.ty, shape, unpack_alignment),
            )
        }
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
        TextureTarget::Texture1D => (Entry::TexImage1D.name(), format!("{}", t.width)),
        TextureTarget::Texture2D | TextureTarget::CubeMap | TextureTarget::CubeFace(_) => (
            Entry::TexImage2D.name(),
            format!("{}, {}", t.width, t.height),
        ),
        TextureTarget::Texture3D => (
            Entry::TexImage3D.name(),
            format!("{}, {}, {}", t.width, t.height, t.depth),
        ),
    };
    line(
        out,
        format_args!(
            "{name}({target}, {}, {}, {size}, {}, {}, {}, {data})",
            t.level,
            internal_format(t.internal_format, t.requested),
            t.border,
            n(t.format),
            n(t.ty)
        ),
    );
}

/// glBegin/glEnd; indexed geometry as glDrawElements over client arrays.
fn draw(out: &mut String, g: &Geometry) {
    if let Some(idx) = &g.indices {
        return draw_arrays(out, g, Some(idx));
    }
    // Per-vertex materials print as the pair that made them (`material_pair`).
    if g.materials.is_some() {
        return draw_arrays(out, g, None);
    }
    // A draw with attribute arrays prints as client arrays too: glColor and its kin inside
    // glBegin/glEnd would also set the current values, which a draw does not.
    if g.colors.is_some()
        || g.normals.is_some()
        || g.edge_flags.is_some()
        || g.secondary_colors.is_some()
        || g.fog_coords.is_some()
        || g.texcoords.iter().any(Option::is_some)
    {
        return draw_arrays(out, g, None);
    }
    line(out, format_args!("{}({})", Entry::Begin, n(g.primitive)));
    for i in 0..g.positions.len() {
        let Some(p) = g.positions.get(i) else {
            continue;
        };
        if let Some(c) = g.colors.as_ref().and_then(|v| v.get(i)) {
            line(
                out,
                format_args!("  {}({})", Entry::Color4f, fs(&c.to_array())),
            );
        }
        if let Some(nrm) = g.normals.as_ref().and_then(|v| v.get(i)) {
            line(
                out,
                format_args!("  {}({})", Entry::Normal3f, fs(&nrm.to_array())),
            );
        }
        for (u, t) in g.texcoords.iter().enumerate() {
            if let Some(t) = t.as_ref().and_then(|v| v.get(i)) {
                let unit = Family::Texture.print(u as u8);
                line(
                    out,
                    format_args!(
                        "  {}({unit}, {})",
                        Entry::MultiTexCoord4f,
                        fs(&t.to_array())
                    ),
                );
            }
        }
        if p.w == 1.0 {
            line(
                out,
                format_args!("  {}({})", Entry::Vertex3f, fs(&p.truncate().to_array())),
            );
        } else {
            line(
                out,
                format_args!("  {}({})", Entry::Vertex4f, fs(&p.to_array())),
            );
        }
    }
    line(out, format_args!("{}()", Entry::End));
}

/// Geometry with attribute arrays or indices as the era drew it: client arrays over the
/// vertices, then glDrawArrays or glDrawElements, then the arrays disabled again. (Mesa
/// splits indexed quads differently from glBegin/glEnd ones, so an indexed draw stays
/// indexed.)
fn draw_arrays(out: &mut String, g: &Geometry, indices: Option<&[u32]>) {
    let flat4 = |v: &[glam::Vec4]| -> Vec<f32> { v.iter().flat_map(|x| x.to_array()).collect() };
    let mut enabled = vec!["GL_VERTEX_ARRAY"];
    line(
        out,
        format_args!(
            "{}(4, GL_FLOAT, 0, {})",
            Entry::VertexPointer,
            arr(&flat4(&g.positions))
        ),
    );
    if let Some(c) = &g.colors {
        line(
            out,
            format_args!(
                "{}(4, GL_FLOAT, 0, {})",
                Entry::ColorPointer,
                arr(&flat4(c))
            ),
        );
        enabled.push("GL_COLOR_ARRAY");
    }
    if let Some(nrm) = &g.normals {
        let flat: Vec<f32> = nrm.iter().flat_map(|x| x.to_array()).collect();
        line(
            out,
            format_args!("{}(GL_FLOAT, 0, {})", Entry::NormalPointer, arr(&flat)),
        );
        enabled.push("GL_NORMAL_ARRAY");
    }
    if let Some(flags) = &g.edge_flags {
        let list: Vec<&str> = flags.iter().map(|f| if *f { "1" } else { "0" }).collect();
        line(
            out,
            format_args!(
                "{}(0, (GLboolean[]){{{}}})",
                Entry::EdgeFlagPointer,
                list.join(", ")
            ),
        );
        enabled.push("GL_EDGE_FLAG_ARRAY");
    }
    if let Some(c) = &g.secondary_colors {
        line(
            out,
            format_args!(
                "{}(4, GL_FLOAT, 0, {})",
                Entry::SecondaryColorPointer,
                arr(&flat4(c))
            ),
        );
        enabled.push("GL_SECONDARY_COLOR_ARRAY");
    }
    if let Some(f) = &g.fog_coords {
        line(
            out,
            format_args!("{}(GL_FLOAT, 0, {})", Entry::FogCoordPointer, arr(f)),
        );
        enabled.push("GL_FOG_COORD_ARRAY");
    }
    for name in &enabled {
        line(out, format_args!("{}({name})", Entry::EnableClientState));
    }
    let units: Vec<(usize, &Vec<glam::Vec4>)> = g
        .texcoords
        .iter()
        .enumerate()
        .filter_map(|(u, t)| t.as_ref().map(|t| (u, t)))
        .collect();
    for (u, t) in &units {
        let unit = Family::Texture.print(*u as u8);
        line(out, format_args!("{}({unit})", Entry::ClientActiveTexture));
        line(
            out,
            format_args!(
                "{}(4, GL_FLOAT, 0, {})",
                Entry::TexCoordPointer,
                arr(&flat4(t))
            ),
        );
        line(
            out,
            format_args!("{}(GL_TEXTURE_COORD_ARRAY)", Entry::EnableClientState),
        );
    }
    match (indices, &g.materials) {
        (_, Some(m)) => material_pair(out, g, indices, m),
        (Some(idx), None) => {
            let list: Vec<String> = idx.iter().map(u32::to_string).collect();
            line(
                out,
                format_args!(
                    "{}({}, {}, GL_UNSIGNED_INT, (GLuint[]){{{}}})",
                    Entry::DrawElements,
                    n(g.primitive),
                    idx.len(),
                    list.join(", ")
                ),
            );
        }
        (None, None) => line(
            out,
            format_args!(
                "{}({}, 0, {})",
                Entry::DrawArrays,
                n(g.primitive),
                g.positions.len()
            ),
        ),
    }
    for (u, _) in &units {
        let unit = Family::Texture.print(*u as u8);
        line(out, format_args!("{}({unit})", Entry::ClientActiveTexture));
        line(
            out,
            format_args!("{}(GL_TEXTURE_COORD_ARRAY)", Entry::DisableClientState),
        );
    }
    if !units.is_empty() {
        line(
            out,
            format_args!("{}(GL_TEXTURE0)", Entry::ClientActiveTexture),
        );
    }
    for name in &enabled {
        line(out, format_args!("{}({name})", Entry::DisableClientState));
    }
}

/// A draw whose vertices carry materials, over the arrays just set: glBegin, then per
/// element the glMaterial calls whose value changes at it and glArrayElement, then glEnd —
/// the pair gives each vertex its material again (`ff::immediate`).
fn material_pair(out: &mut String, g: &Geometry, indices: Option<&[u32]>, m: &VertexMaterials) {
    let order: Vec<u32> = match indices {
        Some(idx) => idx.to_vec(),
        None => (0..g.positions.len() as u32).collect(),
    };
    line(out, format_args!("{}({})", Entry::Begin, n(g.primitive)));
    for (k, &i) in order.iter().enumerate() {
        for (slot, v) in m.changes_at(&order, k) {
            let (face, pname) = slot.names();
            match slot {
                MaterialSlot::Shininess(_) => line(
                    out,
                    format_args!("  {}({face}, {pname}, {})", Entry::Materialf, fs(&[v.x])),
                ),
                MaterialSlot::Color(..) => line(
                    out,
                    format_args!("  {}({face}, {pname}, {})", Entry::Materialfv, v4(v)),
                ),
            }
        }
        line(out, format_args!("  {}({i})", Entry::ArrayElement));
    }
    line(out, format_args!("{}()", Entry::End));
}

/// A shader-program command as a comment: no script can build a program (`ff::program`).
fn program_comment(c: &Command) -> String {
    match c {
        Command::UseProgram(Some(p)) => format!("/* {}(\"{}\") */", Entry::UseProgram, p.name),
        Command::UseProgram(None) => format!("/* {}(0) */", Entry::UseProgram),
        Command::Uniform { name, value } => format!("/* glUniform(\"{name}\", {value:?}) */"),
        _ => String::new(),
    }
}
