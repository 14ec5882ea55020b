//! `FixedState::apply`: one Command folded into the state with GL's error semantics.
//!
//! Every arm validates first and mutates last, so an error leaves the state unchanged
//! (GL 1.5 §2.5). The first error is kept in the sticky flag until read; each call also
//! returns its own result. Light positions, spot directions and eye planes use the
//! modelview current at the call (§2.11.4, §2.14.1).

use std::sync::Arc;

use glam::Vec4;

use super::command::{Capability, Command, CopyTexImage, ReadPixels, TexImage, TexSubImage};
use super::error::{GlError, GlResult};
use super::fragment::{DepthRange, Face, Viewport};
use super::geometry::Geometry;
use super::light::MAX_LIGHTS;
use super::matrix::{frustum, ortho, plane_to_eye};
use super::matrix_ops::{rotation, scale, translate, Product};
use super::state::{FixedState, PolygonModes, MAX_TEXTURE_UNITS};
use super::texenv::TexEnvParam;
use super::texture::{
    check_format_pair, check_image_size, volume_size, PixelData, TexLevel, TextureObject,
    TextureTarget,
};
use super::texture_volume::{
    blit_volume, check_sub_volume, check_volume_image, check_volume_level,
};

impl FixedState {
    /// Applies one command. On error the state is unchanged, the error is returned, and it is
    /// recorded unless an earlier error is still pending.
    pub fn apply(&mut self, cmd: &Command) -> GlResult {
        let result = self.execute(cmd);
        if let Err(e) = result {
            self.error.get_or_insert(e);
        }
        result
    }

    /// Applies every command, stopping at none: returns the first error, as glGetError
    /// would after the sequence.
    pub fn apply_all<'a>(&mut self, cmds: impl IntoIterator<Item = &'a Command>) -> GlResult {
        let mut first = Ok(());
        for c in cmds {
            if let Err(e) = self.apply(c) {
                if first.is_ok() {
                    first = Err(e);
                }
            }
        }
        first
    }

    fn execute(&mut self, cmd: &Command) -> GlResult {
        if self.apply_framebuffer(cmd)? || self.apply_query(cmd)? {
            return Ok(());
        }
        let mv = self.modelview.top();
        let unit = self.active_unit();
        match cmd {
            Command::Raise { error, .. } => {
                return Err(GlError {
                    kind: *error,
                    rule: "the call's arguments, checked as its display list runs",
                })
            }
            Command::MatrixMode(m) => self.matrix_mode = *m,
            Command::LoadIdentity => self.current_stack_mut().load_identity(),
            Command::LoadMatrix(m) => self.current_stack_mut().set_top(*m),
            Command::MultMatrix(m) => self.current_stack_mut().multiply(*m, Product::General),
            Command::PushMatrix => self.current_stack_mut().push()?,
            Command::PopMatrix => self.current_stack_mut().pop()?,
            Command::Translate(v) => self.current_stack_mut().update(|m| translate(m, *v)),
            Command::Rotate { angle_deg, axis } => {
                if let Some(r) = rotation(*angle_deg, *axis) {
                    self.current_stack_mut().multiply(r, Product::AffineKept)
                }
            }
            Command::Scale(v) => self.current_stack_mut().update(|m| scale(m, *v)),
            Command::Frustum(v) => {
                let n = frustum(*v)?;
                self.current_stack_mut().multiply(n, Product::General)
            }
            Command::Ortho(v) => {
                let n = ortho(*v)?;
                self.current_stack_mut().multiply(n, Product::AffineKept)
            }
            Command::Viewport(v) => self.viewport = check_viewport(*v)?,
            Command::DepthRange { near, far } => {
                self.depth_range = DepthRange {
                    near: unit_clamp(*near),
                    far: unit_clamp(*far),
                }
            }
            Command::Enable(c) => self.set_capability(*c, true)?,
            Command::Disable(c) => self.set_capability(*c, false)?,
            Command::Color(c) => self.set_color(*c)?,
            Command::Normal(n) => self.current.normal = *n,
            Command::EdgeFlag(f) => self.current.edge_flag = *f,
            Command::SecondaryColor(c) => self.current.secondary_color = *c,
            Command::FogCoord(f) => self.current.fog_coord = *f,
            Command::Index(c) => self.current.index = *c,
            Command::ClearIndex(c) => self.clear_index = super::color_index::clear_index(*c),
            Command::IndexMask(m) => self.index_mask = *m,
            Command::SampleCoverage { value, invert } => self.sample_coverage.set(*value, *invert),
            Command::TexCoord { unit, coord } => {
                let u = check_unit(*unit)?;
                self.current.texcoords[u] = *coord;
            }
            Command::Light { light, param } => {
                let i = usize::from(*light);
                if i >= MAX_LIGHTS {
                    return Err(GlError::invalid_enum("LIGHTi beyond MAX_LIGHTS"));
                }
                let mut l = self.lights[i].value;
                l.set(*param, mv)?;
                self.lights[i].value = l;
            }
            Command::LightModel(p) => self.light_model.set(*p),
            Command::Material { face, param } => match self.color_material.get() {
                Some(tracking) => self.materials.set_untracked(*face, *param, tracking)?,
                None => self.materials.set(*face, *param)?,
            },
            Command::ColorMaterial { face, mode } => {
                self.color_material.value = super::light::ColorMaterial {
                    face: *face,
                    mode: *mode,
                };
                if self.color_material.enabled {
                    self.track_color_material()?;
                }
            }
            Command::ShadeModel(m) => self.shade_model = *m,
            Command::ActiveTexture(u) => self.active_texture = check_unit(*u)?,
            Command::BindTexture { target, name } => self.bind_texture(*target, *name)?,
            Command::PrioritizeTextures(given) => {
                for (name, priority) in given.iter().filter(|(n, _)| *n != 0) {
                    if let Some(t) = self.textures.get_mut(name) {
                        t.params
                            .set(super::texture::TexParam::Priority(*priority))?;
                    }
                }
            }
            Command::DeleteTextures(names) => {
                self.framebuffers.detach_textures(names);
                for &name in names.iter().filter(|n| **n != 0) {
                    if self.textures.remove(&name).is_some() {
                        for u in &mut self.units {
                            if u.bound_1d == name {
                                u.bound_1d = 0;
                            }
                            if u.bound_2d == name {
                                u.bound_2d = 0;
                            }
                            if u.bound_3d == name {
                                u.bound_3d = 0;
                            }
                            if u.bound_cube_map == name {
                                u.bound_cube_map = 0;
                            }
                        }
                    }
                }
            }
            Command::TexImage(t) => self.tex_image(t)?,
            Command::TexSubImage2D(t) => self.tex_sub_image(t, t.target_2d())?,
            Command::CopyTexImage2D(c) => {
                self.check_read_framebuffer(None)?;
                self.copy_tex_image(c)?
            }
            Command::TexParameter { target, param } => {
                let name = self.units[unit].bound(*target);
                let tex = self
                    .texture_mut(*target, name)
                    .ok_or(GlError::invalid_operation(
                        "bound name belongs to another target",
                    ))?;
                let mut p = tex.params;
                p.set(*param)?;
                tex.params = p;
            }
            Command::TexGen { coord, param } => {
                let slot = &mut self.units[unit].texgen[coord.index()].value;
                let mut g = *slot;
                g.set(*coord, *param, mv)?;
                *slot = g;
            }
            Command::TexEnv(TexEnvParam::CoordReplace(on)) => {
                self.point_sprite.set_replace(unit, *on)
            }
            Command::TexEnv(p) => {
                let mut env = self.units[unit].env;
                env.set(*p, MAX_TEXTURE_UNITS)?;
                self.units[unit].env = env;
            }
            Command::CombinerParameter(p) => self.register_combiners.value.set_parameter(*p)?,
            Command::CombinerInput {
                stage,
                portion,
                variable,
                input,
            } => self.register_combiners.value.set_input(
                *stage,
                *portion,
                *variable,
                *input,
                MAX_TEXTURE_UNITS,
            )?,
            Command::CombinerOutput {
                stage,
                portion,
                output,
            } => self.register_combiners.value.set_output(
                *stage,
                *portion,
                *output,
                MAX_TEXTURE_UNITS,
            )?,
            Command::FinalCombinerInput { variable, input } => self
                .register_combiners
                .value
                .set_final_input(*variable, *input, MAX_TEXTURE_UNITS)?,
            Command::AlphaFunc { func, reference } => {
                self.alpha_test.value.func = *func;
                self.alpha_test.value.reference = reference.clamp(0.0, 1.0);
            }
            Command::DepthFunc(f) => self.depth_test.value.func = *f,
            Command::DepthMask(b) => self.depth_test.value.write = *b,
            Command::StencilFunc {
                func,
                reference,
                mask,
            } => {
                let s = &mut self.stencil_test.value;
                s.func = *func;
                s.reference = *reference;
                s.value_mask = *mask;
            }
            Command::StencilOp {
                fail,
                depth_fail,
                depth_pass,
            } => {
                let s = &mut self.stencil_test.value;
                s.fail = *fail;
                s.depth_fail = *depth_fail;
                s.depth_pass = *depth_pass;
            }
            Command::StencilMask(m) => self.stencil_test.value.write_mask = *m,
            // GL 1.5 Table 4.2 makes SRC_ALPHA_SATURATE a source factor only; Mesa 22.3.6
            // accepts it as a destination factor too (as GL 4.4 does), and the layer follows
            // Mesa (tests/c/errors.c, checked against Mesa's OSMesa).
            Command::BlendFunc { src, dst } => {
                let b = &mut self.blend.value;
                (b.src_rgb, b.dst_rgb, b.src_alpha, b.dst_alpha) = (*src, *dst, *src, *dst);
            }
            Command::BlendFuncSeparate {
                src_rgb,
                dst_rgb,
                src_alpha,
                dst_alpha,
            } => {
                let b = &mut self.blend.value;
                (b.src_rgb, b.dst_rgb, b.src_alpha, b.dst_alpha) =
                    (*src_rgb, *dst_rgb, *src_alpha, *dst_alpha);
            }
            Command::BlendEquation(e) => self.blend.value.equation = *e,
            Command::BlendColor(c) => self.blend_color = c.clamp(Vec4::ZERO, Vec4::ONE),
            Command::ColorMask(m) => self.color_mask = *m,
            Command::PolygonOffset { factor, units } => {
                self.polygon_offset = crate::vocab::PolygonOffset {
                    factor: *factor,
                    units: *units,
                }
            }
            Command::PolygonMode { face, mode } => {
                let PolygonModes { front, back } = self.polygon_mode;
                self.polygon_mode = match face {
                    Face::Front => PolygonModes { front: *mode, back },
                    Face::Back => PolygonModes { front, back: *mode },
                    Face::FrontAndBack => PolygonModes {
                        front: *mode,
                        back: *mode,
                    },
                };
            }
            Command::CullFace(f) => self.cull_face.value = *f,
            Command::PolygonStipple(p) => self.polygon_stipple.value = **p,
            Command::LineStipple(l) => self.line_stipple.value = *l,
            Command::FrontFace(f) => self.front_face = *f,
            Command::LineWidth(w) => self.line_width = positive(*w, "LineWidth must be > 0")?,
            Command::PointSize(s) => self.point_size = positive(*s, "PointSize must be > 0")?,
            Command::PointParameter(p) => {
                let mut params = self.point_params;
                params.set(*p)?;
                self.point_params = params;
            }
            Command::LogicOp(op) => self.logic_op.value = *op,
            Command::Hint { target, mode } => self.hints.set(*target, *mode),
            Command::Scissor(b) => {
                if b.width < 0 || b.height < 0 {
                    return Err(GlError::invalid_value(
                        "Scissor width and height must be ≥ 0",
                    ));
                }
                self.scissor.value = Some(*b);
            }
            Command::ClipPlane { plane, equation } => {
                let slot = self
                    .clip_planes
                    .get_mut(usize::from(*plane))
                    .ok_or(GlError::invalid_enum("CLIP_PLANEi beyond MAX_CLIP_PLANES"))?;
                slot.value = plane_to_eye(*equation, mv);
            }
            Command::Fog(p) => {
                let mut fog = self.fog.value;
                fog.set(*p)?;
                self.fog.value = fog;
            }
            Command::Clear(_) => self.check_draw_framebuffer()?,
            // Clamped to [0, 1]: ±∞ → 1, 0; NaN → 0 (glam's clamp is max then min, and
            // Rust's max drops a NaN). Mesa measured alike (`tests/fidelity_nonfinite.rs`).
            // Kept as given, as Mesa keeps it: a fixed-point buffer clears to the colour
            // clamped (the drivers clamp), a float one (an OSMesa GL_FLOAT buffer) to the
            // colour itself; glGet answers it clamped (measured, tests/c/buffer_types.c).
            Command::ClearColor(c) => self.clear.color = *c,
            Command::ClearDepth(d) => {
                self.clear.depth = if d.is_nan() { 0.0 } else { d.clamp(0.0, 1.0) }
            }
            Command::ClearStencil(s) => self.clear.stencil = *s,
            // Clamped to [−1, 1] (§4.2.3); NaN → −1 as Mesa's CLAMP gives (measured: 2, −3
            // read back as 1, −1).
            Command::ClearAccum(c) => self.clear.accum = c.clamp(Vec4::NEG_ONE, Vec4::ONE),
            Command::Accum { .. } => {
                if self.accum_bits() == 0 {
                    return Err(GlError::invalid_operation(
                        "glAccum without an accumulation buffer (none with a framebuffer \
                         object bound)",
                    ));
                }
            }
            Command::ReadPixels(r) => {
                check_read_pixels(r)?;
                self.check_read_framebuffer(Some(r.format))?
            }
            Command::Draw(g) => {
                self.check_draw_framebuffer()?;
                self.draw(g)?
            }
            Command::PushAttrib(mask) => self.push_attrib(*mask)?,
            Command::TexSubImage1D(t) => self.tex_sub_image(t, TextureTarget::Texture1D)?,
            Command::TexSubImage3D(t) => self.tex_sub_image(t, TextureTarget::Texture3D)?,
            Command::ProxyTexImage(t) => self.proxy_tex_image(t)?,
            Command::CompressedTexImage2D(t) => self.compressed_tex_image(t)?,
            Command::CompressedTexSubImage2D(t) => self.compressed_tex_sub_image(t)?,
            Command::CopyTexImage1D(c) => {
                self.check_read_framebuffer(None)?;
                self.copy_tex_image_1d(c)?
            }
            Command::CopyTexSubImage(c) => {
                self.check_read_framebuffer(None)?;
                self.copy_tex_sub_image(c)?
            }
            Command::GetTexImage(g) => {
                self.check_get_tex_image(g)?;
            }
            Command::PopAttrib => self.pop_attrib()?,
            Command::ListBase(base) => self.list_base = *base,
            Command::BindFramebuffer { .. }
            | Command::DeleteFramebuffers(_)
            | Command::BindRenderbuffer(_)
            | Command::DeleteRenderbuffers(_)
            | Command::RenderbufferStorage { .. }
            | Command::FramebufferTexture { .. }
            | Command::FramebufferRenderbuffer { .. }
            | Command::DrawBuffer(_)
            | Command::ReadBuffer(_)
            | Command::GenerateMipmap(_)
            | Command::Query(_) => {}
            // A program and its uniforms are the pipeline's (`ff::program`): the model of
            // the fixed-function state does not change.
            Command::UseProgram(_) | Command::Uniform { .. } => {}
            Command::RasterPos(p) => self.set_raster_pos(*p),
            Command::WindowPos(p) => self.set_window_pos(*p),
            Command::Bitmap(b) => {
                self.check_draw_framebuffer()?;
                self.bitmap(b)?
            }
            Command::DrawPixels(d) => {
                d.check()?;
                self.check_draw_framebuffer()?
            }
            Command::CopyPixels(c) => {
                super::pixels::check_rect("CopyPixels", c.width, c.height)?;
                self.check_draw_framebuffer()?;
                self.check_read_framebuffer(None)?
            }
            Command::BlitFramebuffer(b) => self.check_blit(b)?,
            Command::PixelTransfer(p) => self.pixel_transfer.set(*p),
            Command::PixelMap(m) => self.pixel_maps.set(m)?,
            Command::PixelZoom { x, y } => {
                self.pixel_zoom = super::pixels::PixelZoom { x: *x, y: *y }
            }
        }
        Ok(())
    }

    fn set_capability(&mut self, cap: Capability, on: bool) -> GlResult {
        let unit = self.active_unit();
        match cap {
            Capability::Lighting => self.lighting = on,
            Capability::Light(i) => {
                let light = self
                    .lights
                    .get_mut(usize::from(i))
                    .ok_or(GlError::invalid_enum("LIGHTi beyond MAX_LIGHTS"))?;
                light.enabled = on;
            }
            Capability::ColorMaterial => {
                self.color_material.enabled = on;
                if on {
                    self.track_color_material()?;
                }
            }
            Capability::Normalize => self.normalize = on,
            Capability::RescaleNormal => self.rescale_normal = on,
            Capability::Texture1D => self.units[unit].texture_1d = on,
            Capability::Texture2D => self.units[unit].texture_2d = on,
            Capability::Texture3D => self.units[unit].texture_3d = on,
            Capability::TextureCubeMap => self.units[unit].texture_cube_map = on,
            Capability::TextureGen(c) => self.units[unit].texgen[c.index()].enabled = on,
            Capability::AlphaTest => self.alpha_test.enabled = on,
            Capability::DepthTest => self.depth_test.enabled = on,
            Capability::StencilTest => self.stencil_test.enabled = on,
            Capability::Blend => self.blend.enabled = on,
            Capability::CullFace => self.cull_face.enabled = on,
            Capability::PolygonOffsetFill => self.offset_enables.fill = on,
            Capability::PolygonOffsetLine => self.offset_enables.line = on,
            Capability::PolygonOffsetPoint => self.offset_enables.point = on,
            Capability::RegisterCombiners => self.register_combiners.enabled = on,
            Capability::Fog => self.fog.enabled = on,
            Capability::ScissorTest => self.scissor.enabled = on,
            Capability::ColorLogicOp => self.logic_op.enabled = on,
            Capability::IndexLogicOp => self.index_logic_op = on,
            Capability::Dither => self.dither = on,
            Capability::PointSmooth => self.smooth.point = on,
            Capability::PointSprite => self.point_sprite.enabled = on,
            Capability::LineSmooth => self.smooth.line = on,
            Capability::PolygonSmooth => self.smooth.polygon = on,
            Capability::ColorSum => self.color_sum = on,
            Capability::Multisample => self.multisample = on,
            Capability::SampleCoverage => self.sample_coverage.coverage = on,
            Capability::SampleAlphaToCoverage => self.sample_coverage.alpha_to_coverage = on,
            Capability::SampleAlphaToOne => self.sample_coverage.alpha_to_one = on,
            Capability::SampleCoverageInvert => self.sample_coverage.invert = on,
            Capability::AutoNormal => self.eval.auto_normal = on,
            Capability::Map(m) if on => self.eval.maps |= m.bit(),
            Capability::Map(m) => self.eval.maps &= !m.bit(),
            Capability::PolygonStipple => self.polygon_stipple.enabled = on,
            Capability::LineStipple => self.line_stipple.enabled = on,
            Capability::ClipPlane(i) => {
                let plane = self
                    .clip_planes
                    .get_mut(usize::from(i))
                    .ok_or(GlError::invalid_enum("CLIP_PLANEi beyond MAX_CLIP_PLANES"))?;
                plane.enabled = on;
            }
        }
        Ok(())
    }

    /// glColor; under COLOR_MATERIAL the tracked material colours follow (§2.14.3).
    fn set_color(&mut self, c: Vec4) -> GlResult {
        self.current.color = c;
        if self.color_material.enabled {
            self.track_color_material()?;
        }
        Ok(())
    }

    fn track_color_material(&mut self) -> GlResult {
        let cm = self.color_material.value;
        self.materials
            .set(cm.face, cm.mode.param(self.current.color))
    }

    fn bind_texture(&mut self, target: TextureTarget, name: u32) -> GlResult {
        if name != 0 {
            match self.textures.get(&name) {
                Some(t) if t.target != target => {
                    return Err(GlError::invalid_operation(
                        "BindTexture: the name was first bound to another target",
                    ));
                }
                Some(_) => {}
                None => {
                    self.textures.insert(name, TextureObject::new(target));
                }
            }
        }
        let u = &mut self.units[self.active_unit()];
        match target {
            TextureTarget::Texture1D => u.bound_1d = name,
            TextureTarget::Texture2D => u.bound_2d = name,
            TextureTarget::Texture3D => u.bound_3d = name,
            TextureTarget::CubeMap => u.bound_cube_map = name,
            TextureTarget::CubeFace(_) => {
                return Err(GlError::invalid_enum(
                    "a cube map face is an image target, not bindable",
                ))
            }
        }
        Ok(())
    }

    pub(super) fn bound_mut(&mut self, target: TextureTarget) -> GlResult<&mut TextureObject> {
        let name = self.units[self.active_unit()].bound(target);
        self.texture_mut(target, name)
            .ok_or(GlError::invalid_operation(
                "bound name belongs to another target",
            ))
    }

    fn tex_image(&mut self, t: &TexImage) -> GlResult {
        match t.target {
            TextureTarget::Texture3D => check_volume_image(t)?,
            TextureTarget::CubeMap => {
                return Err(GlError::invalid_enum(
                    "TEXTURE_CUBE_MAP is not an image target: name a face",
                ))
            }
            _ => check_image_size(t.level, t.width, t.height, t.border)?,
        }
        if t.target.face().is_some() && t.width != t.height {
            return Err(GlError::invalid_value(
                "a cube map face is square (width = height)",
            ));
        }
        if t.target == TextureTarget::Texture1D && t.height != 1 {
            return Err(GlError::invalid_value("TexImage1D has height 1"));
        }
        check_format_pair(t.internal_format, t.format)?;
        if t.target == TextureTarget::Texture3D {
            check_volume_level(t)?;
        }
        if let Some(d) = t.data.bytes() {
            if d.len() != volume_size(t.format, t.ty, t.width, t.height, t.depth) {
                return Err(GlError::invalid_value(
                    "pixel data length differs from width·height·depth·components·size",
                ));
            }
        }
        let level = TexLevel {
            internal_format: t.internal_format,
            width: t.width,
            height: t.height,
            depth: t.depth,
            border: 0,
            data: t.data.bytes().map(|bytes| PixelData {
                format: t.format,
                ty: t.ty,
                bytes: bytes.clone(),
            }),
            compressed: None,
            requested: t.requested,
        };
        let tex = self.bound_mut(t.target.binding())?;
        tex.set_level_in(t.target, t.level, level);
        tex.level_changed_in(t.target, t.level);
        Ok(())
    }

    /// glTexSubImage1D/2D/3D (1D and 2D: z 0, depth 1). A 3D call checks its level
    /// range and sizes first, as Mesa does (INVALID_VALUE before a missing level's
    /// INVALID_OPERATION).
    fn tex_sub_image(&mut self, t: &TexSubImage, target: TextureTarget) -> GlResult {
        if target == TextureTarget::Texture3D {
            check_sub_volume(t)?;
        }
        let tex = self.bound_mut(target.binding())?;
        let level = tex
            .level_in_mut(target, t.level)
            .ok_or(GlError::invalid_operation(
                "glTexSubImage of an unspecified level",
            ))?;
        if t.width < 0
            || t.height < 0
            || t.depth < 0
            || t.x < 0
            || t.y < 0
            || t.z < 0
            || t.x + t.width > level.width
            || t.y + t.height > level.height
            || t.z + t.depth > level.depth
        {
            return Err(GlError::invalid_value(
                "glTexSubImage region outside the image",
            ));
        }
        check_format_pair(level.internal_format, t.format)?;
        // NULL: checked, nothing stored; Mesa still derives the mipmaps of a base level
        // under GENERATE_MIPMAP (its `check_gen_mipmap` follows the store either way).
        let Some(bytes) = &t.data else {
            tex.level_changed_in(target, t.level);
            return Ok(());
        };
        if bytes.len() != volume_size(t.format, t.ty, t.width, t.height, t.depth) {
            return Err(GlError::invalid_value(
                "pixel data length differs from width·height·depth·components·size",
            ));
        }
        level.data = match level.data.take() {
            Some(d) if d.format == t.format && d.ty == t.ty => {
                let mut bytes = d.bytes.to_vec();
                blit_volume(&mut bytes, (level.width, level.height), t);
                Some(PixelData {
                    bytes: Arc::from(bytes),
                    ..d
                })
            }
            // The whole image replaced: the new bytes are the CPU copy.
            _ if (t.width, t.height, t.depth) == (level.width, level.height, level.depth) => {
                Some(PixelData {
                    format: t.format,
                    ty: t.ty,
                    bytes: bytes.clone(),
                })
            }
            // Mixed formats or unknown texels: only the GPU copy is authoritative.
            _ => None,
        };
        tex.level_changed_in(target, t.level);
        Ok(())
    }

    fn copy_tex_image(&mut self, c: &CopyTexImage) -> GlResult {
        check_image_size(c.level, c.width, c.height, c.border)?;
        if c.face.is_some() && c.width != c.height {
            return Err(GlError::invalid_value(
                "a cube map face is square (width = height)",
            ));
        }
        let level = TexLevel {
            internal_format: c.internal_format,
            width: c.width,
            height: c.height,
            depth: 1,
            border: 0,
            data: None,
            compressed: None,
            requested: c.requested,
        };
        let target = c.target_2d();
        let tex = self.bound_mut(target.binding())?;
        tex.set_level_in(target, c.level, level);
        tex.level_changed_in(target, c.level);
        Ok(())
    }

    /// A draw changes no state: the current values stay as glColor, glNormal and
    /// glMultiTexCoord left them, as Mesa leaves them after glDrawArrays/glDrawElements
    /// (GL 1.5 §2.8 makes them indeterminate; `tests/c/state.c` checks Mesa's). What
    /// glBegin/glEnd leaves current is set by the commands immediate mode emits after its
    /// draw (`ff::immediate`).
    fn draw(&mut self, g: &std::sync::Arc<Geometry>) -> GlResult {
        self.validated_draw.validate(g)
    }
}

/// A depth value clamped to [0, 1] as glDepthRange and glClearDepth do (GL 1.5 §2.11.1,
/// §4.2.3); NaN → 0, like the colour clamps (glam's `clamp` is `max` then `min`, and Rust's
/// `max` drops a NaN operand; `f32::clamp` would keep the NaN). Mesa 22.3.6 llvmpipe
/// measured alike: glDepthRange(NaN, 1) puts z = 0 at window depth 0.5, as near 0 does
/// (`tests/fidelity_nonfinite.rs`).
fn unit_clamp(v: f32) -> f32 {
    if v.is_nan() {
        0.0
    } else {
        v.clamp(0.0, 1.0)
    }
}

/// SRC_ALPHA_SATURATE is a source factor only (GL 1.5 Table 4.2): INVALID_ENUM as a
/// destination.
fn check_unit(unit: u8) -> GlResult<usize> {
    let u = usize::from(unit);
    if u >= MAX_TEXTURE_UNITS {
        return Err(GlError::invalid_enum("TEXTUREi beyond MAX_TEXTURE_UNITS"));
    }
    Ok(u)
}

/// MAX_VIEWPORT_DIMS, Mesa's on llvmpipe (`query`).
pub const MAX_VIEWPORT_SIDE: i32 = 16384;

/// glViewport: a negative side is INVALID_VALUE; a side beyond MAX_VIEWPORT_DIMS is
/// clamped to it (GL 1.5 §2.11.1), as the answers then show.
fn check_viewport(v: Viewport) -> GlResult<Viewport> {
    if v.width < 0 || v.height < 0 {
        return Err(GlError::invalid_value(
            "Viewport width and height must be ≥ 0",
        ));
    }
    Ok(Viewport {
        width: v.width.min(MAX_VIEWPORT_SIDE),
        height: v.height.min(MAX_VIEWPORT_SIDE),
        ..v
    })
}

/// A width or size GL refuses when ≤ 0 (GL 1.5 §3.4, §3.3): NaN is not ≤ 0, so it is
/// kept, as Mesa keeps it (it then draws one pixel wide).
fn positive(v: f32, rule: &'static str) -> GlResult<f32> {
    if v <= 0.0 {
        Err(GlError::invalid_value(rule))
    } else {
        Ok(v)
    }
}

fn check_read_pixels(r: &ReadPixels) -> GlResult {
    if r.width < 0 || r.height < 0 {
        return Err(GlError::invalid_value(
            "ReadPixels width and height must be ≥ 0",
        ));
    }
    Ok(())
}
