//! Framebuffer objects on either path: the model's framebuffer and renderbuffer names
//! (`ff::framebuffer`) mapped to GL objects made on this context, and the bindings and
//! colour buffers GL has brought up to the model's before anything draws, clears, reads
//! or copies.
//!
//! The model's framebuffer 0 is the window: whatever framebuffer was bound when the
//! first framebuffer command arrived (the caller's render target; the C library names a
//! new one with [`FramebufferMirror::set_window`] when its buffer changes size). Until a
//! framebuffer command arrives the mirror touches nothing, so callers that bind their own
//! targets between executions see no change. The window's colour buffers FRONT, BACK,
//! LEFT and FRONT_AND_BACK all draw into the target's one colour attachment (Mesa's
//! OSMesa buffer does the same).
//!
//! Renderbuffer formats a core context lacks are stored as their nearest core format on
//! the emulated path: luminance, intensity and alpha as R8, luminance-alpha as RG8, the
//! unsized depth, stencil and depth-stencil formats as 24-bit depth and 8-bit stencil
//! (llvmpipe allocates the same sizes for them).

use std::collections::HashMap;
use std::num::NonZeroU32;

use glow::HasContext;

use super::PipelineError;
use crate::ff::framebuffer::{
    Attached, AttachmentPoint, Bits, ColorBuffer, FramebufferTarget, RenderbufferFormat,
};
use crate::ff::glenum::gl;
use crate::ff::{Command, FixedState, TextureTarget};

/// The bits of the framebuffer bound now, which stands for the window: its colour,
/// depth and stencil attachments' sizes (a default framebuffer's FRONT_LEFT, DEPTH and
/// STENCIL).
pub fn bound_bits(gl: &glow::Context) -> Bits {
    let bound = unsafe { gl.get_parameter_i32(glow::DRAW_FRAMEBUFFER_BINDING) } != 0;
    let (color, depth, stencil) = if bound {
        (
            glow::COLOR_ATTACHMENT0,
            glow::DEPTH_ATTACHMENT,
            glow::STENCIL_ATTACHMENT,
        )
    } else {
        (glow::BACK_LEFT, glow::DEPTH, glow::STENCIL)
    };
    let size = |attachment: u32, pname: u32| -> u8 {
        let kind = unsafe {
            gl.get_framebuffer_attachment_parameter_i32(
                glow::DRAW_FRAMEBUFFER,
                attachment,
                glow::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
            )
        };
        if kind == glow::NONE as i32 {
            return 0;
        }
        let v = unsafe {
            gl.get_framebuffer_attachment_parameter_i32(glow::DRAW_FRAMEBUFFER, attachment, pname)
        };
        u8::try_from(v).unwrap_or(0)
    };
    let bits = Bits {
        red: size(color, glow::FRAMEBUFFER_ATTACHMENT_RED_SIZE),
        green: size(color, glow::FRAMEBUFFER_ATTACHMENT_GREEN_SIZE),
        blue: size(color, glow::FRAMEBUFFER_ATTACHMENT_BLUE_SIZE),
        alpha: size(color, glow::FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE),
        depth: size(depth, glow::FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE),
        stencil: size(stencil, glow::FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE),
    };
    // A query GL refused (no such attachment) leaves an error the pipeline must not see.
    unsafe { while gl.get_error() != glow::NO_ERROR {} }
    bits
}

/// Whether `cmd` draws into or reads from the bound framebuffers (GL must bind what the
/// model binds before it is issued).
pub fn uses_framebuffer(cmd: &Command) -> bool {
    matches!(
        cmd,
        Command::Draw(_)
            | Command::Clear(_)
            | Command::ReadPixels(_)
            | Command::CopyTexImage2D(_)
            | Command::CopyTexImage1D(_)
            | Command::CopyTexSubImage(_)
            | Command::Bitmap(_)
            | Command::DrawPixels(_)
            | Command::CopyPixels(_)
            | Command::Accum { .. }
            | Command::BlitFramebuffer(_)
    )
}

/// The GL objects of the model's framebuffers and renderbuffers.
#[derive(Default)]
pub struct FramebufferMirror {
    /// Set by the first framebuffer command: the GL framebuffer standing for name 0.
    window: Option<Option<glow::Framebuffer>>,
    /// The window's one colour buffer: COLOR_ATTACHMENT0 of a framebuffer object, or the
    /// buffer a surface's framebuffer 0 draws into (FRONT or BACK).
    window_buffer: u32,
    objects: HashMap<u32, glow::Framebuffer>,
    renderbuffers: HashMap<u32, glow::Renderbuffer>,
    /// (draw framebuffer, read framebuffer, draw buffer, read buffer) as GL has them.
    sent: Option<(u32, u32, u32, u32)>,
    /// Whether renderbuffer formats must be core ones.
    core_formats: bool,
}

/// A GL texture object of the path, by the model's target and name.
pub type TextureLookup<'a> = &'a mut dyn FnMut(TextureTarget, u32) -> Option<u32>;

impl FramebufferMirror {
    /// A mirror for a core context (`core_formats`) or a compatibility one.
    pub fn new(core_formats: bool) -> Self {
        FramebufferMirror {
            core_formats,
            window_buffer: glow::COLOR_ATTACHMENT0,
            ..Default::default()
        }
    }

    /// The framebuffer that stands for the window from now on, and its colour buffer
    /// (`RenderTarget::color_buffer`).
    pub fn set_window(&mut self, window: Option<glow::Framebuffer>, color_buffer: u32) {
        if self.window.is_some() {
            self.window = Some(window);
        }
        self.window_buffer = color_buffer;
        self.sent = None;
    }

    /// Forgets what GL has bound (a caller bound something else behind the pipeline).
    pub fn invalidate(&mut self) {
        self.sent = None;
    }

    /// The GL work of a framebuffer command the model accepted; `false` for other
    /// commands.
    pub fn issue(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        cmd: &Command,
        texture: TextureLookup,
    ) -> Result<bool, PipelineError> {
        match cmd {
            Command::BindFramebuffer { .. } | Command::DrawBuffer(_) | Command::ReadBuffer(_) => {
                self.activate(gl);
            }
            Command::DeleteFramebuffers(names) => {
                for name in names {
                    if let Some(fb) = self.objects.remove(name) {
                        unsafe { gl.delete_framebuffer(fb) };
                    }
                }
            }
            Command::BindRenderbuffer(name) => {
                self.activate(gl);
                if *name != 0 {
                    self.renderbuffer(gl, *name)?;
                }
            }
            Command::DeleteRenderbuffers(names) => {
                for name in names {
                    if let Some(rb) = self.renderbuffers.remove(name) {
                        unsafe { gl.delete_renderbuffer(rb) };
                    }
                }
            }
            Command::RenderbufferStorage { format, .. } => {
                let name = state.framebuffers.renderbuffer;
                let rb = self.renderbuffer(gl, name)?;
                let stored = state.framebuffers.renderbuffers.get(&name);
                let (w, h) = stored.map_or((0, 0), |r| (r.width, r.height));
                unsafe {
                    gl.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
                    gl.renderbuffer_storage(glow::RENDERBUFFER, self.storage(*format), w, h);
                }
            }
            Command::FramebufferTexture {
                target, attachment, ..
            }
            | Command::FramebufferRenderbuffer {
                target, attachment, ..
            } => self.reattach(gl, state, *target, *attachment, texture)?,
            _ => return Ok(false),
        }
        self.sent = None;
        Ok(true)
    }

    /// Brings GL's bindings and colour buffers up to the model's (nothing until a
    /// framebuffer command has arrived).
    pub fn sync(&mut self, gl: &glow::Context, state: &FixedState) -> Result<(), PipelineError> {
        let Some(window) = self.window else {
            return Ok(());
        };
        let f = &state.framebuffers;
        let window_buffer = self.window_buffer;
        let buffer = |name: u32, b: ColorBuffer| match (name, b) {
            (_, ColorBuffer::None) => glow::NONE,
            (0, _) => window_buffer,
            (_, ColorBuffer::Attachment(i)) => glow::COLOR_ATTACHMENT0 + u32::from(i),
            // The model allows nothing else on an FBO.
            _ => glow::NONE,
        };
        let want = (
            f.draw,
            f.read,
            buffer(f.draw, f.color_buffer(FramebufferTarget::Draw)),
            buffer(f.read, f.color_buffer(FramebufferTarget::Read)),
        );
        if self.sent == Some(want) {
            return Ok(());
        }
        let draw = self.framebuffer(gl, want.0, window)?;
        let read = self.framebuffer(gl, want.1, window)?;
        unsafe {
            gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, draw);
            gl.draw_buffer(want.2);
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, read);
            gl.read_buffer(want.3);
        }
        self.sent = Some(want);
        Ok(())
    }

    /// Deletes every GL object made.
    pub fn release(&mut self, gl: &glow::Context) {
        for (_, fb) in self.objects.drain() {
            unsafe { gl.delete_framebuffer(fb) };
        }
        for (_, rb) in self.renderbuffers.drain() {
            unsafe { gl.delete_renderbuffer(rb) };
        }
        self.sent = None;
    }

    fn activate(&mut self, gl: &glow::Context) {
        if self.window.is_none() {
            let bound = unsafe { gl.get_parameter_framebuffer(glow::DRAW_FRAMEBUFFER_BINDING) };
            if bound.is_none() {
                // A surface's framebuffer 0: the buffer it draws into now.
                self.window_buffer = unsafe { gl.get_parameter_i32(glow::DRAW_BUFFER) } as u32;
            }
            self.window = Some(bound);
        }
    }

    fn framebuffer(
        &mut self,
        gl: &glow::Context,
        name: u32,
        window: Option<glow::Framebuffer>,
    ) -> Result<Option<glow::Framebuffer>, PipelineError> {
        if name == 0 {
            return Ok(window);
        }
        if let Some(fb) = self.objects.get(&name) {
            return Ok(Some(*fb));
        }
        let fb = unsafe { gl.create_framebuffer() }.map_err(PipelineError::Object)?;
        self.objects.insert(name, fb);
        Ok(Some(fb))
    }

    fn renderbuffer(
        &mut self,
        gl: &glow::Context,
        name: u32,
    ) -> Result<glow::Renderbuffer, PipelineError> {
        if let Some(rb) = self.renderbuffers.get(&name) {
            return Ok(*rb);
        }
        let rb = unsafe { gl.create_renderbuffer() }.map_err(PipelineError::Object)?;
        self.renderbuffers.insert(name, rb);
        Ok(rb)
    }

    /// The internal format GL stores a renderbuffer in (module note).
    fn storage(&self, format: RenderbufferFormat) -> u32 {
        use RenderbufferFormat as F;
        if !self.core_formats {
            return gl(format);
        }
        match format {
            F::Rgba => glow::RGBA8,
            F::Rgb => glow::RGB8,
            F::Red => glow::R8,
            F::Alpha | F::Alpha8 | F::Luminance | F::Luminance8 | F::Intensity | F::Intensity8 => {
                glow::R8
            }
            F::LuminanceAlpha | F::Luminance8Alpha8 => glow::RG8,
            F::DepthComponent => glow::DEPTH_COMPONENT24,
            F::StencilIndex
            | F::StencilIndex1
            | F::StencilIndex4
            | F::StencilIndex8
            | F::StencilIndex16 => glow::STENCIL_INDEX8,
            F::DepthStencil => glow::DEPTH24_STENCIL8,
            other => gl(other),
        }
    }

    /// Attaches to the GL object what the model has at `point` of the bound framebuffer.
    fn reattach(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        target: FramebufferTarget,
        point: AttachmentPoint,
        texture: TextureLookup,
    ) -> Result<(), PipelineError> {
        self.activate(gl);
        let name = state.framebuffers.bound(target);
        let Some(model) = state.framebuffers.objects.get(&name).filter(|_| name != 0) else {
            return Ok(());
        };
        let fb = self.framebuffer(gl, name, None)?;
        let points: &[(AttachmentPoint, u32)] = match point {
            AttachmentPoint::Color(i) => &[(AttachmentPoint::Color(i), 0)],
            AttachmentPoint::Depth => &[(AttachmentPoint::Depth, glow::DEPTH_ATTACHMENT)],
            AttachmentPoint::Stencil => &[(AttachmentPoint::Stencil, glow::STENCIL_ATTACHMENT)],
            AttachmentPoint::DepthStencil => &[
                (AttachmentPoint::Depth, glow::DEPTH_ATTACHMENT),
                (AttachmentPoint::Stencil, glow::STENCIL_ATTACHMENT),
            ],
        };
        unsafe { gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, fb) };
        for (p, gl_point) in points {
            let gl_point = match p {
                AttachmentPoint::Color(i) => glow::COLOR_ATTACHMENT0 + u32::from(*i),
                _ => *gl_point,
            };
            match model.attachment(*p) {
                None => unsafe {
                    gl.framebuffer_renderbuffer(
                        glow::DRAW_FRAMEBUFFER,
                        gl_point,
                        glow::RENDERBUFFER,
                        None,
                    )
                },
                Some(Attached::Renderbuffer(r)) => {
                    let rb = self.renderbuffer(gl, r)?;
                    unsafe {
                        gl.framebuffer_renderbuffer(
                            glow::DRAW_FRAMEBUFFER,
                            gl_point,
                            glow::RENDERBUFFER,
                            Some(rb),
                        )
                    }
                }
                Some(Attached::Texture {
                    target: tt,
                    name,
                    level,
                    layer,
                }) => {
                    let t = texture(tt, name)
                        .and_then(NonZeroU32::new)
                        .map(glow::NativeTexture);
                    // One image of a 3D level or one face of a cube map; glFramebufferTexture
                    // would attach them all.
                    match tt {
                        TextureTarget::CubeFace(f) => unsafe {
                            gl.framebuffer_texture_2d(
                                glow::DRAW_FRAMEBUFFER,
                                gl_point,
                                glow::TEXTURE_CUBE_MAP_POSITIVE_X + f.index() as u32,
                                t,
                                level,
                            )
                        },
                        TextureTarget::Texture3D => unsafe {
                            gl.framebuffer_texture_layer(
                                glow::DRAW_FRAMEBUFFER,
                                gl_point,
                                t,
                                level,
                                layer,
                            )
                        },
                        _ => unsafe {
                            gl.framebuffer_texture(glow::DRAW_FRAMEBUFFER, gl_point, t, level)
                        },
                    }
                }
            }
        }
        self.sent = None;
        Ok(())
    }
}
