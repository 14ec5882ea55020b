//! `FixedState::apply` for the framebuffer commands (`ff::framebuffer`), and the checks
//! the drawing, clearing, reading and copying commands make of the bound framebuffers:
//! an incomplete one is INVALID_FRAMEBUFFER_OPERATION (GL 3.0 §4.4.4), a colour read
//! with the read buffer NONE INVALID_OPERATION (§4.3.1), as Mesa answers both.

use super::command::Command;
use super::error::{GlError, GlResult};
use super::framebuffer::{
    texture_image_info, Attached, AttachmentPoint, Bits, ColorBuffer, Completeness,
    FramebufferTarget, MAX_COLOR_ATTACHMENTS, MAX_RENDERBUFFER_SIZE,
};
use super::state::FixedState;
use super::texture::{
    PixelFormat, TexFormat, TexLevel, TextureTarget, MAX_3D_TEXTURE_LEVEL, MAX_3D_TEXTURE_SIZE,
};

/// The largest texture level a framebuffer attachment may name: log2 of the largest
/// texture size (llvmpipe: 16384 = 2^14).
const MAX_TEXTURE_LEVEL: i32 = 14;

impl FixedState {
    /// Applies a framebuffer command; `Ok(false)` for commands of other areas.
    pub(crate) fn apply_framebuffer(&mut self, cmd: &Command) -> GlResult<bool> {
        let fb = &mut self.framebuffers;
        match cmd {
            Command::BindFramebuffer { target, name } => fb.bind(*target, *name),
            Command::DeleteFramebuffers(names) => fb.delete(names),
            Command::BindRenderbuffer(name) => fb.bind_renderbuffer(*name),
            Command::DeleteRenderbuffers(names) => fb.delete_renderbuffers(names),
            Command::RenderbufferStorage {
                format,
                width,
                height,
            } => {
                let name = fb.renderbuffer;
                if name == 0 {
                    return Err(GlError::invalid_operation(
                        "glRenderbufferStorage needs a renderbuffer bound",
                    ));
                }
                let range = 0..=MAX_RENDERBUFFER_SIZE;
                if !range.contains(width) || !range.contains(height) {
                    return Err(GlError::invalid_value(
                        "a renderbuffer is 0 to MAX_RENDERBUFFER_SIZE (16384) a side",
                    ));
                }
                let rb = fb.renderbuffers.entry(name).or_default();
                rb.format = *format;
                rb.width = *width;
                rb.height = *height;
            }
            Command::FramebufferTexture {
                target,
                attachment,
                texture,
                level,
                layer,
            } => {
                let attached = match texture {
                    None => None,
                    Some((tt, name)) => {
                        // A cube face names a face of a cube map object.
                        let known = self
                            .textures
                            .get(name)
                            .is_some_and(|t| t.target == tt.binding());
                        if !known {
                            return Err(GlError::invalid_operation(
                                "the texture name has no texture of that target",
                            ));
                        }
                        let max_level = match tt {
                            TextureTarget::Texture3D => MAX_3D_TEXTURE_LEVEL,
                            _ => MAX_TEXTURE_LEVEL,
                        };
                        if !(0..=max_level).contains(level) {
                            return Err(GlError::invalid_value(
                                "a texture level from 0 to log2(MAX_TEXTURE_SIZE) (3D: MAX_3D_TEXTURE_SIZE)",
                            ));
                        }
                        // glFramebufferTexture3D: a zoffset below MAX_3D_TEXTURE_SIZE, the
                        // level's depth or not (completeness decides that; Mesa measured).
                        if !(0..MAX_3D_TEXTURE_SIZE).contains(layer) {
                            return Err(GlError::invalid_value(
                                "a 3D texture's zoffset from 0 to MAX_3D_TEXTURE_SIZE − 1",
                            ));
                        }
                        Some(Attached::Texture {
                            target: *tt,
                            name: *name,
                            level: *level,
                            layer: *layer,
                        })
                    }
                };
                self.attach(*target, *attachment, attached)?;
            }
            Command::FramebufferRenderbuffer {
                target,
                attachment,
                renderbuffer,
            } => {
                let attached = match renderbuffer {
                    0 => None,
                    r if fb.renderbuffers.contains_key(r) => Some(Attached::Renderbuffer(*r)),
                    _ => {
                        return Err(GlError::invalid_operation(
                            "the name has no renderbuffer (bind it once to make it)",
                        ))
                    }
                };
                self.attach(*target, *attachment, attached)?;
            }
            Command::DrawBuffer(b) => fb.set_color_buffer(false, *b)?,
            Command::ReadBuffer(b) => fb.set_color_buffer(true, *b)?,
            Command::GenerateMipmap(target) => {
                let tex = self.bound_texture_mut(*target)?;
                if tex.base().is_none() {
                    return Err(GlError::invalid_operation(
                        "glGenerateMipmap needs an image at the base level",
                    ));
                }
                // A cube map's six base levels must be alike (cube complete, GL 3.0
                // §3.9.7; Mesa: INVALID_OPERATION).
                if tex.target == TextureTarget::CubeMap && !tex.faces_alike() {
                    return Err(GlError::invalid_operation(
                        "glGenerateMipmap of a cube map whose faces differ",
                    ));
                }
                tex.generate_levels();
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    fn attach(
        &mut self,
        target: FramebufferTarget,
        point: AttachmentPoint,
        attached: Option<Attached>,
    ) -> GlResult {
        if let AttachmentPoint::Color(i) = point {
            if i >= MAX_COLOR_ATTACHMENTS {
                return Err(GlError::invalid_operation(
                    "COLOR_ATTACHMENTi beyond MAX_COLOR_ATTACHMENTS (8)",
                ));
            }
        }
        let fb = self.framebuffers.bound_object_mut(target)?;
        match point {
            AttachmentPoint::Color(i) => fb.color[usize::from(i)] = attached,
            AttachmentPoint::Depth => fb.depth = attached,
            AttachmentPoint::Stencil => fb.stencil = attached,
            AttachmentPoint::DepthStencil => {
                fb.depth = attached;
                fb.stencil = attached;
            }
        }
        Ok(())
    }

    /// glCheckFramebufferStatus of the framebuffer bound to `target`.
    pub fn framebuffer_status(&self, target: FramebufferTarget) -> Completeness {
        self.framebuffers.status(target, |tt, name, level, layer| {
            let l = self.attached_level(tt, name, level)?;
            // A 3D layer at or past the depth is no image (INCOMPLETE_ATTACHMENT).
            if layer >= l.depth {
                return None;
            }
            texture_image_info(l.internal_format, l.width, l.height)
        })
    }

    /// The format of an attached texture image, if it exists.
    fn attached_format(&self, tt: TextureTarget, name: u32, level: i32) -> Option<TexFormat> {
        Some(self.attached_level(tt, name, level)?.internal_format)
    }

    /// The image an attachment names, if it exists: level `level` of image target `tt`
    /// (a cube face names a face of a cube map object) of texture `name`.
    fn attached_level(&self, tt: TextureTarget, name: u32, level: i32) -> Option<&TexLevel> {
        self.textures
            .get(&name)
            .filter(|t| t.target == tt.binding())?
            .level_in(tt, level)
    }

    /// The width and height of the framebuffer object bound to `target` (a query of
    /// `Both` reads the draw binding): the smallest of its attached images' (where every
    /// image is, `_mesa_update_framebuffer_visual`); `None` for the window or an object
    /// without a sized image.
    pub fn framebuffer_size(&self, target: FramebufferTarget) -> Option<(i32, i32)> {
        let f = &self.framebuffers;
        let name = f.bound(target);
        let fb = f.objects.get(&name).filter(|_| name != 0)?;
        fb.attached()
            .filter_map(|(_, a)| match a {
                Attached::Texture {
                    target,
                    name,
                    level,
                    ..
                } => self
                    .attached_level(target, name, level)
                    .map(|l| (l.width, l.height)),
                Attached::Renderbuffer(r) => {
                    f.renderbuffers.get(&r).map(|rb| (rb.width, rb.height))
                }
            })
            .reduce(|(w0, h0), (w1, h1)| (w0.min(w1), h0.min(h1)))
    }

    /// RED_BITS … STENCIL_BITS of the framebuffer bound for drawing; `window` is what the
    /// window has.
    pub fn draw_bits(&self, window: Bits) -> Bits {
        self.framebuffers.draw_bits(window, |tt, name, level| {
            self.attached_format(tt, name, level)
        })
    }

    /// ACCUM_RED_BITS … ACCUM_ALPHA_BITS of the framebuffer bound for drawing: the window's,
    /// 0 with a framebuffer object bound (objects have no accumulation buffer; Mesa
    /// measured alike).
    pub fn accum_bits(&self) -> u8 {
        if self.framebuffers.draw == 0 {
            self.framebuffers.window_accum_bits
        } else {
            0
        }
    }

    /// Before a draw or a clear: the draw framebuffer must be complete.
    pub(crate) fn check_draw_framebuffer(&self) -> GlResult {
        match self.framebuffer_status(FramebufferTarget::Draw) {
            Completeness::Complete => Ok(()),
            _ => Err(GlError::invalid_framebuffer_operation(
                "the draw framebuffer is incomplete",
            )),
        }
    }

    /// Before glReadPixels or a copy of `format`: the read framebuffer must be complete,
    /// and a colour read needs a read buffer.
    pub(crate) fn check_read_framebuffer(&self, format: Option<PixelFormat>) -> GlResult {
        if self.framebuffer_status(FramebufferTarget::Read) != Completeness::Complete {
            return Err(GlError::invalid_framebuffer_operation(
                "the read framebuffer is incomplete",
            ));
        }
        let colour = format
            .is_none_or(|f| !matches!(f, PixelFormat::DepthComponent | PixelFormat::StencilIndex));
        if colour && self.framebuffers.color_buffer(FramebufferTarget::Read) == ColorBuffer::None {
            return Err(GlError::invalid_operation(
                "a colour read with the read buffer NONE",
            ));
        }
        // A depth or stencil read of a window without that buffer (GL 1.5 §4.3.2). The
        // model knows the window only as measured on GL: a state that never measured it
        // (no colour bits either) refuses nothing.
        let measured = self.framebuffers.window_bits.red > 0;
        if self.framebuffers.read == 0 && measured {
            let window = self.framebuffers.window_bits;
            let missing = match format {
                Some(PixelFormat::DepthComponent) => window.depth == 0,
                Some(PixelFormat::StencilIndex) => window.stencil == 0,
                _ => false,
            };
            if missing {
                return Err(GlError::invalid_operation(
                    "a depth or stencil read of a window without that buffer",
                ));
            }
        }
        Ok(())
    }
}
