//! The server attribute stack: glPushAttrib / glPopAttrib (GL 1.5 §6.1.14, the "attribute"
//! column of Tables 6.5–6.28).
//!
//! A push records the whole model state with the mask; a pop copies back the fields of the
//! groups the mask names, and only those. Each group's fields are listed once, in
//! [`FixedState::restore_group`]. Groups whose state the model does not hold yet (FOG,
//! SCISSOR, EVAL, HINT, LIST, PIXEL_MODE, ACCUM_BUFFER, MULTISAMPLE, POLYGON_STIPPLE) are
//! accepted and restore nothing; a field added to the model for one of them is added to
//! its arm there. What GL puts in two groups (LIGHTING's enables are also ENABLE's) is
//! restored by either, from the same snapshot.
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

use super::error::{GlError, GlResult};
use super::glenum::{registry, GlEnum};
use super::state::FixedState;
use super::texture::TextureTarget;

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
        for group in frame.mask.groups() {
            self.restore_group(group, &frame.saved);
        }
        Ok(())
    }

    /// Copies one group's fields back from `s` (GL 1.5 Tables 6.5–6.28, "attribute").
    fn restore_group(&mut self, group: AttribGroup, s: &FixedState) {
        match group {
            // Current colour, normal, texture coordinates (the raster position and edge
            // flag are not modelled).
            AttribGroup::Current => self.current = s.current,
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
            // MATRIX_MODE, NORMALIZE, RESCALE_NORMAL (clip planes are not modelled).
            AttribGroup::Transform => {
                self.matrix_mode = s.matrix_mode;
                self.normalize = s.normalize;
                self.rescale_normal = s.rescale_normal;
            }
            AttribGroup::Viewport => {
                self.viewport = s.viewport;
                self.depth_range = s.depth_range;
            }
            // Alpha test, blending, colour write mask, clear colour (dither, logic op and
            // draw buffer are not modelled).
            AttribGroup::ColorBuffer => {
                self.alpha_test = s.alpha_test;
                self.blend = s.blend;
                self.color_mask = s.color_mask;
                self.clear.color = s.clear.color;
            }
            AttribGroup::DepthBuffer => {
                self.depth_test = s.depth_test;
                self.clear.depth = s.clear.depth;
            }
            AttribGroup::StencilBuffer => {
                self.stencil_test = s.stencil_test;
                self.clear.stencil = s.clear.stencil;
            }
            // Culling, front face, polygon modes, offset and its enables (smoothing and
            // the stipple enable are not modelled).
            AttribGroup::Polygon => {
                self.cull_face = s.cull_face;
                self.front_face = s.front_face;
                self.polygon_mode = s.polygon_mode;
                self.polygon_offset = s.polygon_offset;
                self.offset_enables = s.offset_enables;
            }
            AttribGroup::Line => self.line_width = s.line_width,
            AttribGroup::Point => self.point_size = s.point_size,
            // Not modelled yet: nothing saved, nothing restored.
            AttribGroup::PolygonStipple
            | AttribGroup::PixelMode
            | AttribGroup::Fog
            | AttribGroup::AccumBuffer
            | AttribGroup::Hint
            | AttribGroup::Eval
            | AttribGroup::List
            | AttribGroup::Scissor
            | AttribGroup::Multisample => {}
        }
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
    }

    /// TEXTURE_BIT: the active unit, every unit's enables, bindings, environment and
    /// texgen, the register combiners, and the parameters of the textures bound at the push.
    fn restore_textures(&mut self, s: &FixedState) {
        self.active_texture = s.active_texture;
        self.units = s.units;
        self.register_combiners = s.register_combiners;
        for unit in &s.units {
            for target in [TextureTarget::Texture1D, TextureTarget::Texture2D] {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::{
        BlendFactor, Capability, Command, CompareFunc, GlErrorKind, LightParam, MatrixMode,
        TexEnvMode, TexEnvParam, TexParam, Wrap,
    };
    use glam::Vec4;

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
            s.blend.value.src,
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
                Command::StencilMask(7),
                Command::ClearStencil(3),
                Command::PopAttrib,
            ],
        );
        assert_eq!(s, pushed);
    }
}
