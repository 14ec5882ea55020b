//! One accepted Command as the legacy GL calls of the era.
//!
//! The model has already folded the command in (and accepted it), so GL's matrices equal
//! the model's when a light position or eye plane is sent: both are passed as given and GL
//! transforms them itself. Two places differ from a plain one-to-one translation:
//! - **The Mesa texture-matrix bug** (Mesa 22.3 llvmpipe, DESIGN "Measured facts"): after
//!   glPopMatrix restores a non-identity texture matrix, Mesa draws with the identity until
//!   texture state changes, although glGetFloatv(TEXTURE_MATRIX) is right. Every pop of a
//!   texture stack is followed by glLoadMatrixf of the matrix GL itself reports (after a
//!   different one: Mesa ignores a load of the matrix already on top), which marks the
//!   texture matrix dirty again.
//! - **Nested glPopAttrib** (Mesa 22.3): Mesa restores only the groups changed since the
//!   push, and a pop resets that record to the one saved at the push, so a change made while
//!   an inner entry was on the stack is not undone by the outer pop
//!   (`tests/query_native.rs`, `mesa_nested_pop_attrib_skips_groups_changed_inside`).
//!   After the real glPopAttrib the popped groups are sent again from the model
//!   (`FixedState::group_commands`).
//! - **Register combiners** have no native path (Mesa dropped NV_register_combiners): their
//!   commands change only the model, and a draw with REGISTER_COMBINERS_NV enabled is
//!   refused with `PipelineError::Unsupported` instead of drawing something else.
//! - **Shader programs** (`ff::program`) are refused with `PipelineError::ShaderPrograms`.

use glam::Mat4;

use crate::ff::{AttribMask, ClearMask, Command, FogParam, MatrixMode, PointParam};
use crate::pipeline::PipelineError;

use super::bindings as gl;
use super::bindings::types::GLbitfield;
use super::{
    conv, draw, lighting, readback, texenv, texture_calls, texture_volume, textures, Native,
};
use crate::pipeline::core::Core;

impl Native {
    /// Issues the GL calls of `cmd`, which the model accepted.
    pub(super) fn issue_calls(
        &mut self,
        core: &mut Core,
        cmd: &Command,
    ) -> Result<(), PipelineError> {
        let g = self.gl.raw();
        // SAFETY (all unsafe blocks of this match): plain GL calls on the current context;
        // pointer arguments point at local arrays of the size the entry point reads.
        match cmd {
            Command::MatrixMode(m) => unsafe { g.MatrixMode(conv::value(*m)) },
            Command::LoadIdentity => unsafe { g.LoadIdentity() },
            Command::LoadMatrix(m) => unsafe { g.LoadMatrixf(m.to_cols_array().as_ptr()) },
            Command::MultMatrix(m) => unsafe { g.MultMatrixf(m.to_cols_array().as_ptr()) },
            Command::PushMatrix => unsafe { g.PushMatrix() },
            Command::PopMatrix => {
                unsafe { g.PopMatrix() };
                if core.state.matrix_mode == MatrixMode::Texture {
                    reload_texture_matrix(g);
                }
            }
            Command::Translate(v) => unsafe { g.Translatef(v.x, v.y, v.z) },
            Command::Rotate { angle_deg, axis } => unsafe {
                g.Rotatef(*angle_deg, axis.x, axis.y, axis.z)
            },
            Command::Scale(v) => unsafe { g.Scalef(v.x, v.y, v.z) },
            Command::Frustum(v) => unsafe {
                g.Frustum(
                    v.left.into(),
                    v.right.into(),
                    v.bottom.into(),
                    v.top.into(),
                    v.near.into(),
                    v.far.into(),
                )
            },
            Command::Ortho(v) => unsafe {
                g.Ortho(
                    v.left.into(),
                    v.right.into(),
                    v.bottom.into(),
                    v.top.into(),
                    v.near.into(),
                    v.far.into(),
                )
            },
            Command::Viewport(v) => unsafe { g.Viewport(v.x, v.y, v.width, v.height) },
            Command::DepthRange { near, far } => unsafe {
                g.DepthRange((*near).into(), (*far).into())
            },
            Command::Enable(c) => {
                if let Some(cap) = conv::capability(*c) {
                    unsafe { g.Enable(cap) }
                }
            }
            Command::Disable(c) => {
                if let Some(cap) = conv::capability(*c) {
                    unsafe { g.Disable(cap) }
                }
            }
            Command::Color(c) => unsafe { g.Color4f(c.x, c.y, c.z, c.w) },
            Command::Normal(n) => unsafe { g.Normal3f(n.x, n.y, n.z) },
            Command::EdgeFlag(on) => unsafe { g.EdgeFlag(u8::from(*on)) },
            Command::SecondaryColor(c) => unsafe { g.SecondaryColor3f(c.x, c.y, c.z) },
            Command::FogCoord(x) => unsafe { g.FogCoordf(*x) },
            Command::Index(c) => unsafe { g.Indexf(*c) },
            Command::ClearIndex(c) => unsafe { g.ClearIndex(*c) },
            Command::IndexMask(m) => unsafe { g.IndexMask(*m) },
            Command::SampleCoverage { value, invert } => unsafe {
                g.SampleCoverage(*value, u8::from(*invert))
            },
            Command::TexCoord { unit, coord: t } => unsafe {
                g.MultiTexCoord4f(conv::texture_unit(*unit), t.x, t.y, t.z, t.w)
            },
            Command::Light { light, param } => lighting::light(g, *light, *param),
            Command::LightModel(p) => lighting::light_model(g, *p),
            Command::Material { face, param } => lighting::material(g, *face, *param),
            Command::ColorMaterial { face, mode } => unsafe {
                g.ColorMaterial(conv::value(*face), conv::value(*mode))
            },
            Command::ShadeModel(m) => unsafe { g.ShadeModel(conv::value(*m)) },
            Command::ActiveTexture(u) => unsafe { g.ActiveTexture(conv::texture_unit(*u)) },
            Command::BindTexture { target, name } => self.textures.bind(g, *target, *name),
            Command::DeleteTextures(names) => self.textures.delete(g, names),
            Command::PrioritizeTextures(given) => self.textures.prioritize(g, given),
            Command::TexImage(t) => {
                textures::tex_image(g, t);
                core.counters.texture_uploads += 1;
            }
            Command::TexSubImage2D(t) => {
                textures::tex_sub_image(g, t);
                core.counters.texture_uploads += 1;
            }
            // The real calls: Mesa decodes the blocks itself (the oracle of `ff::compressed`).
            Command::CompressedTexImage2D(t) => {
                textures::compressed_tex_image(g, t);
                core.counters.texture_uploads += 1;
            }
            Command::CompressedTexSubImage2D(t) => {
                textures::compressed_tex_sub_image(g, t);
                core.counters.texture_uploads += 1;
            }
            Command::CopyTexImage2D(c) => {
                textures::copy_tex_image(g, c);
                core.counters.texture_uploads += 1;
            }
            Command::TexParameter { target, param } => {
                textures::tex_parameter(g, *target, *param);
            }
            Command::TexGen { coord, param } => texenv::texgen(g, *coord, *param),
            Command::TexEnv(p) => texenv::texenv(g, *p),
            // NV_register_combiners: model only (see the module note).
            Command::CombinerParameter(_)
            | Command::CombinerInput { .. }
            | Command::CombinerOutput { .. }
            | Command::FinalCombinerInput { .. } => {}
            Command::AlphaFunc { func, reference } => unsafe {
                g.AlphaFunc(conv::value(*func), *reference)
            },
            Command::DepthFunc(f) => unsafe { g.DepthFunc(conv::value(*f)) },
            Command::DepthMask(b) => unsafe { g.DepthMask(u8::from(*b)) },
            Command::StencilFunc {
                func,
                reference,
                mask,
            } => unsafe { g.StencilFunc(conv::value(*func), *reference, *mask) },
            Command::StencilOp {
                fail,
                depth_fail,
                depth_pass,
            } => unsafe {
                g.StencilOp(
                    conv::value(*fail),
                    conv::value(*depth_fail),
                    conv::value(*depth_pass),
                )
            },
            Command::StencilMask(m) => unsafe { g.StencilMask(*m) },
            Command::BlendFunc { src, dst } => unsafe {
                g.BlendFunc(conv::value(*src), conv::value(*dst))
            },
            Command::ColorMask(m) => unsafe {
                g.ColorMask(u8::from(m.r), u8::from(m.g), u8::from(m.b), u8::from(m.a))
            },
            Command::PolygonOffset { factor, units } => unsafe { g.PolygonOffset(*factor, *units) },
            Command::PolygonMode { face, mode } => unsafe {
                g.PolygonMode(conv::value(*face), conv::value(*mode))
            },
            Command::CullFace(f) => unsafe { g.CullFace(conv::value(*f)) },
            Command::FrontFace(f) => unsafe { g.FrontFace(conv::value(*f)) },
            Command::LineWidth(w) => unsafe { g.LineWidth(*w) },
            Command::LineStipple(l) => unsafe { g.LineStipple(i32::from(l.factor), l.pattern) },
            // The mask's 128 bytes, rows of 4 (the native path keeps UNPACK_ALIGNMENT 1).
            Command::PolygonStipple(s) => unsafe {
                g.PixelStorei(gl::UNPACK_ALIGNMENT, 1);
                g.PolygonStipple(s.to_bytes().as_ptr())
            },
            Command::PointSize(s) => unsafe { g.PointSize(*s) },
            Command::Fog(p) => fog(g, *p),
            Command::PointParameter(p) => point_parameter(g, *p),
            // GL transforms the plane by the inverse modelview itself, as the model did.
            Command::ClipPlane { plane, equation } => {
                let e = equation.as_dvec4().to_array();
                unsafe { g.ClipPlane(conv::clip_plane_name(*plane), e.as_ptr()) }
            }
            Command::BlendFuncSeparate {
                src_rgb,
                dst_rgb,
                src_alpha,
                dst_alpha,
            } => unsafe {
                g.BlendFuncSeparate(
                    conv::value(*src_rgb),
                    conv::value(*dst_rgb),
                    conv::value(*src_alpha),
                    conv::value(*dst_alpha),
                )
            },
            Command::BlendEquation(e) => unsafe { g.BlendEquation(conv::value(*e)) },
            Command::BlendColor(c) => unsafe { g.BlendColor(c.x, c.y, c.z, c.w) },
            Command::Hint { target, mode } => unsafe {
                g.Hint(conv::value(*target), conv::value(*mode))
            },
            Command::LogicOp(op) => unsafe { g.LogicOp(conv::value(*op)) },
            Command::Scissor(b) => unsafe { g.Scissor(b.x, b.y, b.width, b.height) },
            Command::Clear(mask) => unsafe { g.Clear(clear_bits(*mask)) },
            Command::ClearColor(c) => unsafe { g.ClearColor(c.x, c.y, c.z, c.w) },
            Command::ClearDepth(d) => unsafe { g.ClearDepth(*d) },
            Command::ClearStencil(s) => unsafe { g.ClearStencil(*s) },
            Command::ClearAccum(c) => unsafe { g.ClearAccum(c.x, c.y, c.z, c.w) },
            Command::Accum { op, value } => unsafe { g.Accum(conv::value(*op), *value) },
            Command::ReadPixels(r) => {
                let bytes = readback::read_pixels(g, r);
                core.readbacks.insert(r.slot, bytes);
            }
            // The model rejects it before anything is issued.
            Command::Raise { .. } => {}
            Command::TexSubImage1D(t) => {
                texture_calls::tex_sub_image_1d(g, t);
                core.counters.texture_uploads += 1;
            }
            Command::CopyTexImage1D(c) => {
                texture_calls::copy_tex_image_1d(g, c);
                core.counters.texture_uploads += 1;
            }
            Command::CopyTexSubImage(c) => {
                texture_calls::copy_tex_sub_image(g, c);
                core.counters.texture_uploads += 1;
            }
            Command::GetTexImage(r) => {
                if let Some(read) = texture_calls::get_tex_image(g, &core.state, r) {
                    core.readbacks.insert(r.slot, read);
                }
            }
            Command::TexSubImage3D(t) => {
                texture_volume::tex_sub_image_3d(g, t);
                core.counters.texture_uploads += 1;
            }
            // The model answers every proxy query; only the 3D one is passed on (Mesa checks
            // it again, nothing draws it).
            Command::ProxyTexImage(t) if t.target == crate::ff::TextureTarget::Texture3D => {
                texture_volume::tex_image_3d(g, t, texture_volume::Target::Proxy)
            }
            Command::ProxyTexImage(_) => {}
            Command::Draw(geometry) => {
                if core.state.register_combiners.enabled {
                    return Err(PipelineError::Unsupported {
                        what: "NV_register_combiners (REGISTER_COMBINERS_NV enabled at a draw)",
                        path: "native",
                    });
                }
                draw::draw(g, geometry);
                draw::restore_current(g, &core.state, geometry);
                draw::restore_materials(g, &core.state, geometry);
                core.counters.draws += 1;
            }
            // Issued by the framebuffer mirror (`pipeline::framebuffers`).
            Command::BindFramebuffer { .. }
            | Command::DeleteFramebuffers(_)
            | Command::BindRenderbuffer(_)
            | Command::DeleteRenderbuffers(_)
            | Command::RenderbufferStorage { .. }
            | Command::FramebufferTexture { .. }
            | Command::FramebufferRenderbuffer { .. }
            | Command::DrawBuffer(_)
            | Command::ReadBuffer(_) => {}
            // The front end adds the base to glCallLists' names before the draws arrive.
            Command::ListBase(_) => {}
            // Issued by the path's query mirror (`pipeline::queries`).
            Command::Query(_) => {}
            // Mesa's fixed function has no programs (`ff::program`).
            Command::UseProgram(_) | Command::Uniform { .. } => {
                return Err(PipelineError::ShaderPrograms)
            }
            Command::GenerateMipmap(t) => unsafe { g.GenerateMipmap(conv::value(*t)) },
            Command::BlitFramebuffer(b) => {
                let (s, d) = (b.src, b.dst);
                unsafe {
                    g.BlitFramebuffer(
                        s.x0,
                        s.y0,
                        s.x1,
                        s.y1,
                        d.x0,
                        d.y0,
                        d.x1,
                        d.y1,
                        b.mask.bits(),
                        b.filter.value(),
                    )
                }
            }
            Command::PushAttrib(mask) => {
                unsafe { g.PushAttrib(mask.0) };
                self.attrib_masks.push(*mask);
            }
            Command::RasterPos(_)
            | Command::WindowPos(_)
            | Command::Bitmap(_)
            | Command::DrawPixels(_)
            | Command::CopyPixels(_)
            | Command::PixelTransfer(_)
            | Command::PixelMap(_)
            | Command::PixelZoom { .. } => {
                super::pixels::issue(g, cmd);
            }
            Command::PopAttrib => {
                unsafe { g.PopAttrib() };
                // The model accepted the pop, so a mask was pushed; the groups are sent
                // again from the model (see the module note).
                let mask = self.attrib_masks.pop().unwrap_or(AttribMask(0));
                for c in core.state.group_commands(mask) {
                    self.issue_calls(core, &c)?;
                }
            }
        }
        Ok(())
    }
}

/// Works around the Mesa texture-matrix bug: loads the matrix GL reports for the current
/// texture stack, so the restored matrix is the one drawn with. Mesa skips a glLoadMatrixf
/// whose matrix equals the top (memcmp), so a different matrix is loaded first: both loads
/// then mark the texture matrix dirty.
fn reload_texture_matrix(g: &gl::Gl) {
    let mut m = [0.0f32; 16];
    // SAFETY: TEXTURE_MATRIX writes 16 floats.
    unsafe { g.GetFloatv(gl::TEXTURE_MATRIX, m.as_mut_ptr()) };
    let identity = Mat4::IDENTITY.to_cols_array();
    let other = if m == identity { [0.0; 16] } else { identity };
    // SAFETY: LoadMatrixf reads 16 floats.
    unsafe {
        g.LoadMatrixf(other.as_ptr());
        g.LoadMatrixf(m.as_ptr());
    }
}

/// glFog with the parameter's own entry point (glFogi for the mode, glFogfv for the colour).
fn point_parameter(g: &gl::Gl, p: PointParam) {
    // SAFETY: plain GL calls; DISTANCE_ATTENUATION reads 3 floats from a local array.
    unsafe {
        match p {
            PointParam::SizeMin(v) => g.PointParameterf(gl::POINT_SIZE_MIN, v),
            PointParam::SizeMax(v) => g.PointParameterf(gl::POINT_SIZE_MAX, v),
            PointParam::FadeThreshold(v) => g.PointParameterf(gl::POINT_FADE_THRESHOLD_SIZE, v),
            PointParam::DistanceAttenuation(a) => {
                g.PointParameterfv(gl::POINT_DISTANCE_ATTENUATION, a.as_ptr())
            }
            PointParam::SpriteCoordOrigin(o) => {
                g.PointParameteri(gl::POINT_SPRITE_COORD_ORIGIN, conv::int(o))
            }
        }
    }
}

fn fog(g: &gl::Gl, p: FogParam) {
    // SAFETY: plain GL calls; FOG_COLOR reads 4 floats from a local array.
    unsafe {
        match p {
            FogParam::Mode(m) => g.Fogi(gl::FOG_MODE, conv::int(conv::value(m))),
            FogParam::CoordSource(s) => g.Fogi(gl::FOG_COORD_SRC, conv::int(conv::value(s))),
            FogParam::Density(v) => g.Fogf(gl::FOG_DENSITY, v),
            FogParam::Start(v) => g.Fogf(gl::FOG_START, v),
            FogParam::End(v) => g.Fogf(gl::FOG_END, v),
            FogParam::Index(v) => g.Fogf(gl::FOG_INDEX, v),
            FogParam::Color(c) => g.Fogfv(gl::FOG_COLOR, c.to_array().as_ptr()),
        }
    }
}

/// glClear's bitfield.
fn clear_bits(mask: ClearMask) -> GLbitfield {
    let bit = |on: bool, b: GLbitfield| if on { b } else { 0 };
    bit(mask.color, gl::COLOR_BUFFER_BIT)
        | bit(mask.depth, gl::DEPTH_BUFFER_BIT)
        | bit(mask.stencil, gl::STENCIL_BUFFER_BIT)
        | bit(mask.accum, gl::ACCUM_BUFFER_BIT)
}

/// The GL entry point a command becomes, named in errors GL raises for it.
pub(super) fn gl_call(cmd: &Command) -> &'static str {
    cmd.entry().name()
}
