//! The server attribute stack: glPushAttrib / glPopAttrib (GL 1.5 §6.1.14, the "attribute"
//! column of Tables 6.5–6.28).
//!
//! A push records the whole model state with the mask; a pop copies back the fields of the
//! groups the mask names, and only those. Each group's fields are listed once, in
//! `FixedState::restore_group`; a field added to the model is added to its group's arm
//! there. What GL puts in two groups (LIGHTING's enables are also ENABLE's) is restored by
//! either, from the same snapshot.
//!
//! Where Mesa 22.3 restores a field by calling the setter again, the pop follows it, errors
//! included (measured on OSMesa, `tests/c/mesa_answers.c`):
//! - COLOR_BUFFER_BIT saves the draw buffer of the last glDrawBuffer that succeeded, on
//!   whichever framebuffer (Mesa's context copy `Color.DrawBuffer[0]`); the pop sets it on
//!   the framebuffer bound then only when that copy differs from the saved value, and
//!   only if that framebuffer can draw into it: a FRONT saved on the window and popped
//!   over an FBO changes nothing and raises no error;
//! - PIXEL_MODE_BIT saves the last glReadBuffer's buffer likewise (`Pixel.ReadBuffer`); when
//!   the copy differs, the pop takes the saved value into it and calls glReadBuffer(saved)
//!   on the framebuffer bound, errors included: a FRONT popped over an FBO is
//!   INVALID_OPERATION;
//! - HINT_BIT restores every hint but GENERATE_MIPMAP_HINT, which Mesa's pop leaves as it
//!   is (GL 1.4 puts it in the hint group; followed: Mesa).
//!
//! A pop restores every group of its mask and records the first error raised.
//!
//! Matrices and their stacks belong to no group (only MATRIX_MODE is TRANSFORM state), and
//! texture images belong to no group: TEXTURE_BIT saves the bindings of every unit, the
//! active unit, the environments and texgen, and the parameters of the textures bound at
//! the push, which the pop writes back into those objects (Mesa's `pop_texture_group`).
//! The NV_register_combiners state is TEXTURE state (the extension's state tables:
//! "texture" and "texture/enable").
//!
//! There is no client attribute stack: the model holds no client state (vertex arrays
//! travel inside each draw), so glPushClientAttrib has nothing to save.

use super::command::{Capability, Command, EvalMap};
use super::error::{GlError, GlResult};
use super::fog::FogParam;
use super::fragment::Face;
use super::glenum::{registry, GlEnum};
use super::light::{LightModelParam, LightParam, MaterialParam};
use super::matrix::MatrixMode;
use super::state::{FixedState, TextureUnit};
use super::texenv::{CombineArg, TexEnvParam};
use super::texgen::{TexCoord, TexGenParam};
use super::texture::{TexParam, TextureTarget};

/// GL_MAX_ATTRIB_STACK_DEPTH: Mesa's `MAX_ATTRIB_STACK_DEPTH`, 16 on llvmpipe (the spec's
/// minimum too).
pub const MAX_ATTRIB_STACK_DEPTH: usize = 16;

/// One attribute group, named by its glPushAttrib bit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AttribGroup {
    Current,
    Point,
    Line,
    Polygon,
    PolygonStipple,
    PixelMode,
    Lighting,
    Fog,
    DepthBuffer,
    AccumBuffer,
    StencilBuffer,
    Viewport,
    Transform,
    Enable,
    ColorBuffer,
    Hint,
    Eval,
    List,
    Texture,
    Scissor,
    Multisample,
}

impl AttribGroup {
    /// Every group, in the order of their bits.
    pub const ALL: [AttribGroup; 21] = [
        AttribGroup::Current,
        AttribGroup::Point,
        AttribGroup::Line,
        AttribGroup::Polygon,
        AttribGroup::PolygonStipple,
        AttribGroup::PixelMode,
        AttribGroup::Lighting,
        AttribGroup::Fog,
        AttribGroup::DepthBuffer,
        AttribGroup::AccumBuffer,
        AttribGroup::StencilBuffer,
        AttribGroup::Viewport,
        AttribGroup::Transform,
        AttribGroup::Enable,
        AttribGroup::ColorBuffer,
        AttribGroup::Hint,
        AttribGroup::Eval,
        AttribGroup::List,
        AttribGroup::Texture,
        AttribGroup::Scissor,
        AttribGroup::Multisample,
    ];

    /// The group's bit (GL_CURRENT_BIT …).
    pub fn bit(self) -> u32 {
        self.gl_value().unwrap_or(0)
    }
}

/// glPushAttrib's mask: the GL bitfield as given. Bits that name no group are ignored, as
/// GL ignores them; GL_ALL_ATTRIB_BITS is every bit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct AttribMask(pub u32);

impl AttribMask {
    /// GL_ALL_ATTRIB_BITS.
    pub const ALL: AttribMask = AttribMask(registry::ALL_ATTRIB_BITS);

    /// The mask of these groups.
    pub fn of(groups: &[AttribGroup]) -> AttribMask {
        AttribMask(groups.iter().fold(0, |m, g| m | g.bit()))
    }

    pub fn contains(self, group: AttribGroup) -> bool {
        self.0 & group.bit() != 0
    }

    /// The groups the mask names, in bit order.
    pub fn groups(self) -> impl Iterator<Item = AttribGroup> {
        AttribGroup::ALL
            .into_iter()
            .filter(move |g| self.contains(*g))
    }
}

/// One glPushAttrib: the mask and the state when it was pushed (its own attribute stack
/// left out).
#[derive(Debug, Clone, PartialEq)]
pub struct AttribFrame {
    pub mask: AttribMask,
    saved: Box<FixedState>,
}

impl FixedState {
    /// ATTRIB_STACK_DEPTH.
    pub fn attrib_depth(&self) -> usize {
        self.attrib_stack.len()
    }

    /// glPushAttrib: STACK_OVERFLOW on a full stack, with no other effect.
    pub(crate) fn push_attrib(&mut self, mask: AttribMask) -> GlResult {
        if self.attrib_stack.len() >= MAX_ATTRIB_STACK_DEPTH {
            return Err(GlError::stack_overflow(
                "PushAttrib on a stack holding MAX_ATTRIB_STACK_DEPTH entries",
            ));
        }
        let stack = std::mem::take(&mut self.attrib_stack);
        let saved = Box::new(self.clone());
        self.attrib_stack = stack;
        self.attrib_stack.push(AttribFrame { mask, saved });
        Ok(())
    }

    /// glPopAttrib: restores the groups of the top entry's mask; STACK_UNDERFLOW on an
    /// empty stack, with no other effect.
    pub(crate) fn pop_attrib(&mut self) -> GlResult {
        let frame = self.attrib_stack.pop().ok_or(GlError::stack_underflow(
            "PopAttrib on an empty attribute stack",
        ))?;
        let mut first_error = Ok(());
        for group in frame.mask.groups() {
            let restored = self.restore_group(group, &frame.saved);
            if first_error.is_ok() {
                first_error = restored;
            }
        }
        first_error
    }

    /// Copies one group's fields back from `s` (GL 1.5 Tables 6.5–6.28, "attribute"); the
    /// error of a setter called again as Mesa calls it (the draw and read buffers).
    fn restore_group(&mut self, group: AttribGroup, s: &FixedState) -> GlResult {
        match group {
            // Current colour, normal, texture coordinates and the raster position (the edge
            // flag is not modelled).
            AttribGroup::Current => {
                self.current = s.current;
                self.raster = s.raster;
            }
            AttribGroup::Enable => self.restore_enables(s),
            AttribGroup::Lighting => {
                self.lighting = s.lighting;
                self.lights = s.lights;
                self.light_model = s.light_model;
                self.materials = s.materials;
                self.color_material = s.color_material;
                self.shade_model = s.shade_model;
            }
            AttribGroup::Texture => self.restore_textures(s),
            // MATRIX_MODE, NORMALIZE, RESCALE_NORMAL, the clip planes and their enables.
            AttribGroup::Transform => {
                self.matrix_mode = s.matrix_mode;
                self.normalize = s.normalize;
                self.rescale_normal = s.rescale_normal;
                self.clip_planes = s.clip_planes;
            }
            AttribGroup::Viewport => {
                self.viewport = s.viewport;
                self.depth_range = s.depth_range;
            }
            // Alpha test, blending and its colour, logic op, dither, colour write mask,
            // clear colour, and the draw buffer as Mesa restores it (module note).
            AttribGroup::ColorBuffer => {
                self.alpha_test = s.alpha_test;
                self.blend = s.blend;
                self.blend_color = s.blend_color;
                self.logic_op = s.logic_op;
                self.index_logic_op = s.index_logic_op;
                self.dither = s.dither;
                self.color_mask = s.color_mask;
                self.clear.color = s.clear.color;
                self.index_mask = s.index_mask;
                // Mesa sets the clear index again only when it differs.
                if self.clear_index != s.clear_index {
                    self.clear_index = super::color_index::restored_clear_index(s.clear_index);
                }
                let saved = s.framebuffers.last_set.draw;
                if self.framebuffers.last_set.draw != saved {
                    // A buffer the bound framebuffer cannot draw into is left out silently.
                    if self.framebuffers.set_color_buffer(false, saved).is_err() {
                        return Ok(());
                    }
                }
            }
            AttribGroup::DepthBuffer => {
                self.depth_test = s.depth_test;
                self.clear.depth = s.clear.depth;
            }
            AttribGroup::StencilBuffer => {
                self.stencil_test = s.stencil_test;
                self.clear.stencil = s.clear.stencil;
            }
            // Culling, front face, polygon modes, offset and its enables, smoothing and the
            // stipple enable.
            AttribGroup::Polygon => {
                self.smooth.polygon = s.smooth.polygon;
                self.cull_face = s.cull_face;
                self.front_face = s.front_face;
                self.polygon_mode = s.polygon_mode;
                self.polygon_offset = s.polygon_offset;
                self.offset_enables = s.offset_enables;
                self.polygon_stipple.enabled = s.polygon_stipple.enabled;
            }
            AttribGroup::PolygonStipple => self.polygon_stipple.value = s.polygon_stipple.value,
            // Width and the stipple with its enable (Table 6.11).
            AttribGroup::Line => {
                self.line_width = s.line_width;
                self.line_stipple = s.line_stipple;
                self.smooth.line = s.smooth.line;
            }
            // Size, parameters and smoothing (GL 1.4 Table 6.11).
            AttribGroup::Point => {
                self.point_size = s.point_size;
                self.point_params = s.point_params;
                self.smooth.point = s.smooth.point;
                self.point_sprite = s.point_sprite;
            }
            // The fog. GL 2.1's Table 6.11 puts COLOR_SUM in "fog/enable" and
            // FOG_COORD_SRC in "fog"; Mesa 22.3 restores neither (measured,
            // tests/query_native.rs and tests/c/secondary.c), nor does the model.
            AttribGroup::Fog => {
                let source = self.fog.value.coord_source;
                self.fog = s.fog;
                self.fog.value.coord_source = source;
            }
            AttribGroup::Scissor => self.scissor = s.scissor,
            // Every hint but GENERATE_MIPMAP_HINT (module note).
            AttribGroup::Hint => {
                let mipmap = self.hints.generate_mipmap;
                self.hints = s.hints;
                self.hints.generate_mipmap = mipmap;
            }
            // glPixelTransfer, glPixelZoom (Table 6.16) and the read buffer as Mesa
            // restores it (module note). The pixel maps belong to no group (Table 6.17's
            // "—"; Mesa 22.3 measured: tests/c/pixelstore.c).
            AttribGroup::PixelMode => {
                self.pixel_transfer = s.pixel_transfer;
                self.pixel_zoom = s.pixel_zoom;
                let saved = s.framebuffers.last_set.read;
                if self.framebuffers.last_set.read != saved {
                    self.framebuffers.last_set.read = saved;
                    return self.framebuffers.set_color_buffer(true, saved);
                }
            }
            // ACCUM_CLEAR_VALUE (Table 6.20).
            AttribGroup::AccumBuffer => self.clear.accum = s.clear.accum,
            AttribGroup::Multisample => {
                self.multisample = s.multisample;
                self.sample_coverage = s.sample_coverage;
            }
            // The evaluator enables (Table 6.28); the maps and grids are not modelled.
            AttribGroup::Eval => self.eval = s.eval,
            AttribGroup::List => self.list_base = s.list_base,
        }
        Ok(())
    }

    /// ENABLE_BIT: every glEnable flag the model has.
    fn restore_enables(&mut self, s: &FixedState) {
        self.lighting = s.lighting;
        for (l, saved) in self.lights.iter_mut().zip(&s.lights) {
            l.enabled = saved.enabled;
        }
        self.color_material.enabled = s.color_material.enabled;
        self.normalize = s.normalize;
        self.rescale_normal = s.rescale_normal;
        for (u, saved) in self.units.iter_mut().zip(&s.units) {
            u.texture_1d = saved.texture_1d;
            u.texture_2d = saved.texture_2d;
            u.texture_3d = saved.texture_3d;
            u.texture_cube_map = saved.texture_cube_map;
            for (g, sg) in u.texgen.iter_mut().zip(&saved.texgen) {
                g.enabled = sg.enabled;
            }
        }
        self.alpha_test.enabled = s.alpha_test.enabled;
        self.depth_test.enabled = s.depth_test.enabled;
        self.stencil_test.enabled = s.stencil_test.enabled;
        self.blend.enabled = s.blend.enabled;
        self.cull_face.enabled = s.cull_face.enabled;
        self.offset_enables = s.offset_enables;
        self.register_combiners.enabled = s.register_combiners.enabled;
        self.fog.enabled = s.fog.enabled;
        self.scissor.enabled = s.scissor.enabled;
        for (p, saved) in self.clip_planes.iter_mut().zip(&s.clip_planes) {
            p.enabled = saved.enabled;
        }
        self.logic_op.enabled = s.logic_op.enabled;
        self.index_logic_op = s.index_logic_op;
        self.dither = s.dither;
        self.eval = s.eval;
        self.polygon_stipple.enabled = s.polygon_stipple.enabled;
        self.line_stipple.enabled = s.line_stipple.enabled;
        self.smooth = s.smooth;
        self.point_sprite.enabled = s.point_sprite.enabled;
        self.multisample = s.multisample;
        let (now, then) = (&mut self.sample_coverage, s.sample_coverage);
        now.coverage = then.coverage;
        now.alpha_to_coverage = then.alpha_to_coverage;
        now.alpha_to_one = then.alpha_to_one;
    }

    /// TEXTURE_BIT: the active unit, every unit's enables, bindings, environment and
    /// texgen, the register combiners, and the parameters of the textures bound at the push.
    fn restore_textures(&mut self, s: &FixedState) {
        self.active_texture = s.active_texture;
        self.units = s.units;
        self.register_combiners = s.register_combiners;
        for unit in &s.units {
            for target in TextureTarget::ALL {
                let name = unit.bound(target);
                if let (Some(saved), Some(now)) =
                    (s.texture(target, name), self.texture_mut(target, name))
                {
                    now.params = saved.params;
                }
            }
        }
    }
}

/// glEnable or glDisable.
fn toggle(cap: Capability, on: bool) -> Command {
    if on {
        Command::Enable(cap)
    } else {
        Command::Disable(cap)
    }
}

impl FixedState {
    /// The commands that set the groups of `mask` to this state's values, from any state
    /// with the same texture objects: what a path that cannot trust its driver's glPopAttrib
    /// sends after it (the native path, `pipeline::native`). Light positions, spot
    /// directions and eye planes are sent under an identity modelview, so the stored
    /// eye-space values arrive unchanged; the modelview matrix, the matrix mode and the
    /// active unit are put back at the end. Register-combiner state is left out (no driver
    /// has it).
    pub fn group_commands(&self, mask: AttribMask) -> Vec<Command> {
        let mut out = Vec::new();
        for group in mask.groups() {
            self.push_group_commands(group, &mut out);
        }
        out.push(Command::ActiveTexture(self.active_unit() as u8));
        out.push(Command::MatrixMode(self.matrix_mode));
        out
    }

    fn push_group_commands(&self, group: AttribGroup, out: &mut Vec<Command>) {
        match group {
            AttribGroup::Current => {
                out.push(Command::Color(self.current.color));
                out.push(Command::Normal(self.current.normal));
                out.push(Command::EdgeFlag(self.current.edge_flag));
                out.push(Command::SecondaryColor(self.current.secondary_color));
                out.push(Command::FogCoord(self.current.fog_coord));
                out.push(Command::Index(self.current.index));
                for (u, t) in self.current.texcoords.iter().enumerate() {
                    out.push(Command::TexCoord {
                        unit: u as u8,
                        coord: *t,
                    });
                }
            }
            AttribGroup::Enable => self.enable_commands(out),
            AttribGroup::Lighting => self.lighting_commands(out),
            AttribGroup::Texture => self.texture_commands(out),
            AttribGroup::Transform => {
                out.push(toggle(Capability::Normalize, self.normalize));
                out.push(toggle(Capability::RescaleNormal, self.rescale_normal));
                // The planes are stored in eye coordinates: sent under an identity
                // modelview they arrive unchanged.
                out.push(Command::MatrixMode(MatrixMode::Modelview));
                out.push(Command::LoadIdentity);
                for (i, p) in self.clip_planes.iter().enumerate() {
                    out.push(Command::ClipPlane {
                        plane: i as u8,
                        equation: p.value,
                    });
                    out.push(toggle(Capability::ClipPlane(i as u8), p.enabled));
                }
                out.push(Command::LoadMatrix(self.modelview.top()));
            }
            AttribGroup::Viewport => {
                out.push(Command::Viewport(self.viewport));
                out.push(Command::DepthRange {
                    near: self.depth_range.near,
                    far: self.depth_range.far,
                });
            }
            AttribGroup::ColorBuffer => {
                let (a, b) = (self.alpha_test, self.blend);
                out.push(toggle(Capability::AlphaTest, a.enabled));
                out.push(Command::AlphaFunc {
                    func: a.value.func,
                    reference: a.value.reference,
                });
                out.push(toggle(Capability::Blend, b.enabled));
                out.push(Command::BlendFuncSeparate {
                    src_rgb: b.value.src_rgb,
                    dst_rgb: b.value.dst_rgb,
                    src_alpha: b.value.src_alpha,
                    dst_alpha: b.value.dst_alpha,
                });
                out.push(Command::BlendEquation(b.value.equation));
                out.push(Command::BlendColor(self.blend_color));
                out.push(toggle(Capability::ColorLogicOp, self.logic_op.enabled));
                out.push(Command::LogicOp(self.logic_op.value));
                out.push(toggle(Capability::Dither, self.dither));
                out.push(Command::ColorMask(self.color_mask));
                out.push(Command::ClearColor(self.clear.color));
                out.push(Command::IndexMask(self.index_mask));
                out.push(Command::ClearIndex(self.clear_index as f32));
            }
            AttribGroup::DepthBuffer => {
                let d = self.depth_test;
                out.push(toggle(Capability::DepthTest, d.enabled));
                out.push(Command::DepthFunc(d.value.func));
                out.push(Command::DepthMask(d.value.write));
                out.push(Command::ClearDepth(self.clear.depth));
            }
            AttribGroup::StencilBuffer => {
                let t = self.stencil_test;
                out.push(toggle(Capability::StencilTest, t.enabled));
                out.push(Command::StencilFunc {
                    func: t.value.func,
                    reference: t.value.reference,
                    mask: t.value.value_mask,
                });
                out.push(Command::StencilOp {
                    fail: t.value.fail,
                    depth_fail: t.value.depth_fail,
                    depth_pass: t.value.depth_pass,
                });
                out.push(Command::StencilMask(t.value.write_mask));
                out.push(Command::ClearStencil(self.clear.stencil));
            }
            AttribGroup::Polygon => {
                out.push(toggle(Capability::CullFace, self.cull_face.enabled));
                out.push(Command::CullFace(self.cull_face.value));
                out.push(Command::FrontFace(self.front_face));
                for (face, mode) in [
                    (Face::Front, self.polygon_mode.front),
                    (Face::Back, self.polygon_mode.back),
                ] {
                    out.push(Command::PolygonMode { face, mode });
                }
                out.push(Command::PolygonOffset {
                    factor: self.polygon_offset.factor,
                    units: self.polygon_offset.units,
                });
                let e = self.offset_enables;
                out.push(toggle(Capability::PolygonOffsetFill, e.fill));
                out.push(toggle(Capability::PolygonOffsetLine, e.line));
                out.push(toggle(Capability::PolygonOffsetPoint, e.point));
                out.push(toggle(
                    Capability::PolygonStipple,
                    self.polygon_stipple.enabled,
                ));
                out.push(toggle(Capability::PolygonSmooth, self.smooth.polygon));
            }
            AttribGroup::PolygonStipple => out.push(Command::PolygonStipple(Box::new(
                self.polygon_stipple.value,
            ))),
            AttribGroup::Line => {
                out.push(Command::LineWidth(self.line_width));
                out.push(toggle(Capability::LineStipple, self.line_stipple.enabled));
                out.push(Command::LineStipple(self.line_stipple.value));
                out.push(toggle(Capability::LineSmooth, self.smooth.line));
            }
            AttribGroup::Point => {
                out.push(Command::PointSize(self.point_size));
                for p in self.point_params.commands() {
                    out.push(Command::PointParameter(p));
                }
                out.push(toggle(Capability::PointSmooth, self.smooth.point));
                out.push(toggle(Capability::PointSprite, self.point_sprite.enabled));
                for u in 0..self.units.len() {
                    out.push(Command::ActiveTexture(u as u8));
                    out.push(Command::TexEnv(TexEnvParam::CoordReplace(
                        self.point_sprite.replaces(u),
                    )));
                }
            }
            AttribGroup::Fog => {
                let f = self.fog;
                out.push(toggle(Capability::Fog, f.enabled));
                for p in [
                    FogParam::Mode(f.value.mode),
                    FogParam::Density(f.value.density),
                    FogParam::Start(f.value.start),
                    FogParam::End(f.value.end),
                    FogParam::Color(f.value.color),
                    FogParam::Index(f.value.index),
                    FogParam::CoordSource(f.value.coord_source),
                ] {
                    out.push(Command::Fog(p));
                }
            }
            AttribGroup::Scissor => {
                out.push(toggle(Capability::ScissorTest, self.scissor.enabled));
                if let Some(b) = self.scissor.value {
                    out.push(Command::Scissor(b));
                }
            }
            AttribGroup::Hint => {
                for (target, mode) in self.hints.all() {
                    out.push(Command::Hint { target, mode });
                }
            }
            AttribGroup::PixelMode => self.pixel_mode_commands(out),
            AttribGroup::AccumBuffer => out.push(Command::ClearAccum(self.clear.accum)),
            AttribGroup::Multisample => {
                self.sample_enable_commands(out);
                let c = self.sample_coverage;
                out.push(Command::SampleCoverage {
                    value: c.value,
                    invert: c.invert,
                });
            }
            AttribGroup::Eval => self.eval_commands(out),
            AttribGroup::List => {}
        }
    }

    /// AUTO_NORMAL and the MAPn_* enables.
    fn eval_commands(&self, out: &mut Vec<Command>) {
        out.push(toggle(Capability::AutoNormal, self.eval.auto_normal));
        for m in EvalMap::all() {
            out.push(toggle(Capability::Map(m), self.eval.maps & m.bit() != 0));
        }
    }

    fn enable_commands(&self, out: &mut Vec<Command>) {
        out.push(toggle(Capability::Lighting, self.lighting));
        for (i, l) in self.lights.iter().enumerate() {
            out.push(toggle(Capability::Light(i as u8), l.enabled));
        }
        out.push(toggle(
            Capability::ColorMaterial,
            self.color_material.enabled,
        ));
        out.push(toggle(Capability::Normalize, self.normalize));
        out.push(toggle(Capability::RescaleNormal, self.rescale_normal));
        for (u, unit) in self.units.iter().enumerate() {
            out.push(Command::ActiveTexture(u as u8));
            self.unit_enable_commands(unit, out);
        }
        out.push(toggle(Capability::AlphaTest, self.alpha_test.enabled));
        out.push(toggle(Capability::DepthTest, self.depth_test.enabled));
        out.push(toggle(Capability::StencilTest, self.stencil_test.enabled));
        out.push(toggle(Capability::Blend, self.blend.enabled));
        out.push(toggle(Capability::CullFace, self.cull_face.enabled));
        let e = self.offset_enables;
        out.push(toggle(Capability::PolygonOffsetFill, e.fill));
        out.push(toggle(Capability::PolygonOffsetLine, e.line));
        out.push(toggle(Capability::PolygonOffsetPoint, e.point));
        out.push(toggle(Capability::Fog, self.fog.enabled));
        out.push(toggle(Capability::ScissorTest, self.scissor.enabled));
        for (i, p) in self.clip_planes.iter().enumerate() {
            out.push(toggle(Capability::ClipPlane(i as u8), p.enabled));
        }
        out.push(toggle(Capability::ColorLogicOp, self.logic_op.enabled));
        out.push(toggle(Capability::IndexLogicOp, self.index_logic_op));
        out.push(toggle(Capability::Dither, self.dither));
        out.push(toggle(
            Capability::PolygonStipple,
            self.polygon_stipple.enabled,
        ));
        out.push(toggle(Capability::LineStipple, self.line_stipple.enabled));
        out.push(toggle(Capability::PointSmooth, self.smooth.point));
        out.push(toggle(Capability::PointSprite, self.point_sprite.enabled));
        out.push(toggle(Capability::LineSmooth, self.smooth.line));
        out.push(toggle(Capability::PolygonSmooth, self.smooth.polygon));
        self.sample_enable_commands(out);
        self.eval_commands(out);
    }

    /// MULTISAMPLE and the three sample enables.
    fn sample_enable_commands(&self, out: &mut Vec<Command>) {
        let c = self.sample_coverage;
        out.push(toggle(Capability::Multisample, self.multisample));
        out.push(toggle(Capability::SampleCoverage, c.coverage));
        out.push(toggle(
            Capability::SampleAlphaToCoverage,
            c.alpha_to_coverage,
        ));
        out.push(toggle(Capability::SampleAlphaToOne, c.alpha_to_one));
    }

    fn unit_enable_commands(&self, unit: &TextureUnit, out: &mut Vec<Command>) {
        out.push(toggle(Capability::Texture1D, unit.texture_1d));
        out.push(toggle(Capability::Texture2D, unit.texture_2d));
        out.push(toggle(Capability::Texture3D, unit.texture_3d));
        out.push(toggle(Capability::TextureCubeMap, unit.texture_cube_map));
        for c in TexCoord::ALL {
            out.push(toggle(
                Capability::TextureGen(c),
                unit.texgen[c.index()].enabled,
            ));
        }
    }

    fn lighting_commands(&self, out: &mut Vec<Command>) {
        out.push(toggle(Capability::Lighting, self.lighting));
        out.push(Command::MatrixMode(MatrixMode::Modelview));
        out.push(Command::LoadIdentity);
        for (i, l) in self.lights.iter().enumerate() {
            let v = l.value;
            for param in [
                LightParam::Ambient(v.ambient),
                LightParam::Diffuse(v.diffuse),
                LightParam::Specular(v.specular),
                LightParam::Position(v.position),
                LightParam::SpotDirection(v.spot_direction),
                LightParam::SpotExponent(v.spot_exponent),
                LightParam::SpotCutoff(v.spot_cutoff),
                LightParam::ConstantAttenuation(v.constant_attenuation),
                LightParam::LinearAttenuation(v.linear_attenuation),
                LightParam::QuadraticAttenuation(v.quadratic_attenuation),
            ] {
                out.push(Command::Light {
                    light: i as u8,
                    param,
                });
            }
            out.push(toggle(Capability::Light(i as u8), l.enabled));
        }
        out.push(Command::LoadMatrix(self.modelview.top()));
        let m = self.light_model;
        out.push(Command::LightModel(LightModelParam::Ambient(m.ambient)));
        out.push(Command::LightModel(LightModelParam::LocalViewer(
            m.local_viewer,
        )));
        out.push(Command::LightModel(LightModelParam::TwoSide(m.two_side)));
        out.push(Command::LightModel(LightModelParam::ColorControl(
            m.color_control,
        )));
        for (face, mat) in [
            (Face::Front, self.materials.front),
            (Face::Back, self.materials.back),
        ] {
            for param in [
                MaterialParam::Ambient(mat.ambient),
                MaterialParam::Diffuse(mat.diffuse),
                MaterialParam::Specular(mat.specular),
                MaterialParam::Emission(mat.emission),
                MaterialParam::Shininess(mat.shininess),
                MaterialParam::ColorIndexes(mat.color_indexes),
            ] {
                out.push(Command::Material { face, param });
            }
        }
        let cm = self.color_material;
        out.push(Command::ColorMaterial {
            face: cm.value.face,
            mode: cm.value.mode,
        });
        out.push(toggle(Capability::ColorMaterial, cm.enabled));
        out.push(Command::ShadeModel(self.shade_model));
    }

    fn texture_commands(&self, out: &mut Vec<Command>) {
        out.push(Command::MatrixMode(MatrixMode::Modelview));
        out.push(Command::LoadIdentity);
        for (u, unit) in self.units.iter().enumerate() {
            out.push(Command::ActiveTexture(u as u8));
            for target in TextureTarget::ALL {
                let name = unit.bound(target);
                out.push(Command::BindTexture { target, name });
                if let Some(t) = self.texture(target, name) {
                    let p = t.params;
                    for param in [
                        TexParam::MinFilter(p.min_filter),
                        TexParam::MagFilter(p.mag_filter),
                        TexParam::WrapS(p.wrap_s),
                        TexParam::WrapT(p.wrap_t),
                        TexParam::WrapR(p.wrap_r),
                        TexParam::BorderColor(p.border_color),
                        TexParam::CompareMode(p.compare_mode),
                        TexParam::CompareFunc(p.compare_func),
                        TexParam::DepthTextureMode(p.depth_texture_mode),
                        TexParam::CompareFailValue(p.compare_fail_value),
                        TexParam::GenerateMipmap(p.generate_mipmap),
                        TexParam::BaseLevel(p.base_level),
                        TexParam::MaxLevel(p.max_level),
                        TexParam::MinLod(p.min_lod),
                        TexParam::MaxLod(p.max_lod),
                        TexParam::LodBias(p.lod_bias),
                        TexParam::Priority(p.priority),
                        TexParam::MaxAnisotropy(p.max_anisotropy),
                    ] {
                        out.push(Command::TexParameter { target, param });
                    }
                }
            }
            let e = unit.env;
            out.push(Command::TexEnv(TexEnvParam::Mode(e.mode)));
            out.push(Command::TexEnv(TexEnvParam::Color(e.color)));
            out.push(Command::TexEnv(TexEnvParam::CombineRgb(e.rgb.func)));
            out.push(Command::TexEnv(TexEnvParam::CombineAlpha(e.alpha.func)));
            for a in CombineArg::ALL {
                let i = a.index();
                out.push(Command::TexEnv(TexEnvParam::SourceRgb(a, e.rgb.sources[i])));
                out.push(Command::TexEnv(TexEnvParam::SourceAlpha(
                    a,
                    e.alpha.sources[i],
                )));
                out.push(Command::TexEnv(TexEnvParam::OperandRgb(
                    a,
                    e.rgb.operands[i],
                )));
                out.push(Command::TexEnv(TexEnvParam::OperandAlpha(
                    a,
                    e.alpha.operands[i],
                )));
            }
            out.push(Command::TexEnv(TexEnvParam::RgbScale(e.rgb.scale.factor())));
            out.push(Command::TexEnv(TexEnvParam::AlphaScale(
                e.alpha.scale.factor(),
            )));
            out.push(Command::TexEnv(TexEnvParam::LodBias(e.lod_bias)));
            for c in TexCoord::ALL {
                let g = unit.texgen[c.index()].value;
                for param in [
                    TexGenParam::Mode(g.mode),
                    TexGenParam::ObjectPlane(g.object_plane),
                    TexGenParam::EyePlane(g.eye_plane),
                ] {
                    out.push(Command::TexGen { coord: c, param });
                }
            }
            self.unit_enable_commands(unit, out);
        }
        out.push(Command::LoadMatrix(self.modelview.top()));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::{
        BlendFactor, Capability, Command, CompareFunc, GlErrorKind, LightParam, MatrixMode,
        TexEnvMode, TexEnvParam, TexParam, Wrap,
    };
    use glam::Vec4;

    /// LIST_BIT restores the list base; HINT_BIT every hint but GENERATE_MIPMAP_HINT,
    /// which Mesa 22.3's pop leaves as it is.
    #[test]
    fn list_base_is_restored_and_the_mipmap_hint_kept() {
        use crate::ff::fragment::{HintMode, HintTarget};
        let mut s = FixedState::default();
        let mask = AttribMask::of(&[AttribGroup::List, AttribGroup::Hint]);
        apply(
            &mut s,
            &[
                Command::ListBase(3),
                Command::PushAttrib(mask),
                Command::ListBase(9),
                Command::Hint {
                    target: HintTarget::GenerateMipmap,
                    mode: HintMode::Fastest,
                },
                Command::Hint {
                    target: HintTarget::Fog,
                    mode: HintMode::Nicest,
                },
                Command::PopAttrib,
            ],
        );
        assert_eq!(s.list_base, 3);
        assert_eq!(s.hints.generate_mipmap, HintMode::Fastest);
        assert_eq!(s.hints.fog, HintMode::DontCare);
    }

    fn apply(s: &mut FixedState, cmds: &[Command]) {
        for c in cmds {
            s.apply(c).unwrap();
        }
    }

    #[test]
    fn overflow_and_underflow_leave_the_state() {
        let mut s = FixedState::new();
        assert_eq!(
            s.apply(&Command::PopAttrib).unwrap_err().kind,
            GlErrorKind::StackUnderflow
        );
        for _ in 0..MAX_ATTRIB_STACK_DEPTH {
            s.apply(&Command::PushAttrib(AttribMask::ALL)).unwrap();
        }
        s.take_error();
        let before = s.clone();
        assert_eq!(
            s.apply(&Command::PushAttrib(AttribMask::ALL))
                .unwrap_err()
                .kind,
            GlErrorKind::StackOverflow
        );
        s.take_error();
        assert_eq!(s, before);
        assert_eq!(s.attrib_depth(), MAX_ATTRIB_STACK_DEPTH);
    }

    #[test]
    fn a_pop_restores_the_pushed_groups_only() {
        let mut s = FixedState::new();
        apply(
            &mut s,
            &[
                Command::PushAttrib(AttribMask::of(&[
                    AttribGroup::Enable,
                    AttribGroup::DepthBuffer,
                ])),
                Command::Enable(Capability::DepthTest),
                Command::DepthFunc(CompareFunc::Greater),
                Command::BlendFunc {
                    src: BlendFactor::SrcAlpha,
                    dst: BlendFactor::One,
                },
                Command::Enable(Capability::Blend),
                Command::MatrixMode(MatrixMode::Projection),
                Command::PopAttrib,
            ],
        );
        assert!(!s.depth_test.enabled);
        assert!(!s.blend.enabled, "ENABLE_BIT restores BLEND");
        assert_eq!(s.depth_test.value.func, CompareFunc::Less);
        assert_eq!(
            s.blend.value.src_rgb,
            BlendFactor::SrcAlpha,
            "COLOR_BUFFER not pushed"
        );
        assert_eq!(
            s.matrix_mode,
            MatrixMode::Projection,
            "TRANSFORM not pushed"
        );
        assert_eq!(s.attrib_depth(), 0);
    }

    #[test]
    fn texture_bit_restores_units_bindings_and_bound_parameters() {
        let mut s = FixedState::new();
        let t2d = TextureTarget::Texture2D;
        apply(
            &mut s,
            &[
                Command::BindTexture {
                    target: t2d,
                    name: 1,
                },
                Command::TexParameter {
                    target: t2d,
                    param: TexParam::WrapS(Wrap::Clamp),
                },
                Command::PushAttrib(AttribMask::of(&[AttribGroup::Texture])),
                Command::TexParameter {
                    target: t2d,
                    param: TexParam::WrapS(Wrap::ClampToEdge),
                },
                Command::ActiveTexture(1),
                Command::BindTexture {
                    target: t2d,
                    name: 2,
                },
                Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Replace)),
                Command::Enable(Capability::Texture2D),
                Command::Light {
                    light: 0,
                    param: LightParam::Diffuse(Vec4::ZERO),
                },
                Command::PopAttrib,
            ],
        );
        assert_eq!(s.active_texture, 0);
        assert_eq!(s.units[1].bound_2d, 0);
        assert!(!s.units[1].texture_2d);
        assert_eq!(s.units[1].env.mode, TexEnvMode::Modulate);
        assert_eq!(s.texture(t2d, 1).unwrap().params.wrap_s, Wrap::Clamp);
        assert!(s.textures.contains_key(&2), "objects are not deleted");
        assert_eq!(s.lights[0].value.diffuse, Vec4::ZERO, "LIGHTING not pushed");
    }

    /// The group commands of a state, applied to another with the same texture objects,
    /// give back the first state.
    #[test]
    fn group_commands_rebuild_the_groups() {
        let mut a = FixedState::new();
        apply(
            &mut a,
            &[
                Command::BindTexture {
                    target: TextureTarget::Texture2D,
                    name: 1,
                },
                Command::Translate(glam::Vec3::new(1.0, 2.0, 3.0)),
                Command::PushAttrib(AttribMask::ALL),
            ],
        );
        let mut b = a.clone();
        apply(
            &mut a,
            &[
                Command::Light {
                    light: 3,
                    param: LightParam::Position(Vec4::new(1.0, 0.0, 2.0, 1.0)),
                },
                Command::Enable(Capability::Light(3)),
                Command::TexParameter {
                    target: TextureTarget::Texture2D,
                    param: TexParam::WrapS(Wrap::ClampToEdge),
                },
                Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Replace)),
                Command::Enable(Capability::PointSprite),
                Command::ActiveTexture(3),
                Command::TexEnv(TexEnvParam::CoordReplace(true)),
                Command::ActiveTexture(2),
                Command::MatrixMode(MatrixMode::Texture),
                Command::Color(Vec4::new(0.5, 0.25, 0.125, 1.0)),
                Command::LineWidth(2.0),
                Command::StencilMask(3),
            ],
        );
        for c in a.group_commands(AttribMask::ALL) {
            b.apply(&c).unwrap();
        }
        // The rebuild loads the modelview back whole (glLoadMatrix), which makes it a
        // general matrix for the products after it (`matrix_ops::MatrixKind`).
        let modelview = a.modelview.top();
        a.modelview.set_top(modelview);
        assert_eq!(b, a);
    }

    #[test]
    fn all_attrib_bits_round_trips_the_state() {
        let mut s = FixedState::new();
        s.apply(&Command::PushAttrib(AttribMask::ALL)).unwrap();
        let pushed = {
            let mut p = s.clone();
            p.attrib_stack.clear();
            p
        };
        apply(
            &mut s,
            &[
                Command::Color(Vec4::new(0.1, 0.2, 0.3, 0.4)),
                Command::Enable(Capability::Lighting),
                Command::LineWidth(3.0),
                Command::PointSize(4.0),
                Command::Enable(Capability::PointSprite),
                Command::TexEnv(TexEnvParam::CoordReplace(true)),
                Command::StencilMask(7),
                Command::ClearStencil(3),
                Command::PopAttrib,
            ],
        );
        assert_eq!(s, pushed);
    }
}
