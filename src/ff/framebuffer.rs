//! Framebuffer objects (ARB_framebuffer_object and EXT_framebuffer_object, GL 3.0 §4.4):
//! the objects, their attachments, renderbuffers, the draw and read bindings, the colour
//! buffer each framebuffer draws into and reads from (glDrawBuffer, glReadBuffer), and
//! completeness.
//!
//! Framebuffer 0 is the window: the caller's buffer on the C library, the bound render
//! target on the pipelines. The rules are Mesa's on a compatibility context with
//! ARB_framebuffer_object, measured on llvmpipe (`tests/c/fbo.c` prints each answer on
//! Mesa's OSMesa and on this layer):
//! - binding a name never generated makes the object (as EXT and GL 1.x names do); the FBO
//!   calls are never compiled into display lists;
//! - completeness (§4.4.4): an attachment whose image is missing or has a size of 0, a
//!   colour attachment of a depth or stencil format, a depth attachment without depth or a
//!   stencil attachment without stencil: INCOMPLETE_ATTACHMENT; no attachment at all:
//!   INCOMPLETE_MISSING_ATTACHMENT; depth and stencil in two different images:
//!   UNSUPPORTED (llvmpipe). Images of different sizes are complete (ARB_framebuffer_object),
//!   and so is a framebuffer whose draw buffer has no attachment (ARB_ES2_compatibility:
//!   Mesa checks no draw or read buffer). Luminance, intensity and alpha textures and
//!   renderbuffers are colour-renderable (ARB_framebuffer_object, compatibility profile);
//! - drawing, clearing, reading or copying with an incomplete framebuffer bound:
//!   INVALID_FRAMEBUFFER_OPERATION;
//! - glDrawBuffer on the window takes NONE, FRONT, BACK, LEFT, FRONT_LEFT, BACK_LEFT and
//!   FRONT_AND_BACK (Mesa's OSMesa buffer answers BACK too: every one draws into the one
//!   buffer), RIGHT and AUXi are INVALID_OPERATION; on an FBO only NONE and
//!   COLOR_ATTACHMENTi (i < 8) are allowed, anything else INVALID_OPERATION; glReadBuffer
//!   likewise (Mesa takes FRONT_AND_BACK there too). Each framebuffer keeps its own pair;
//!   a new FBO draws into and reads from COLOR_ATTACHMENT0, the window FRONT;
//! - deleting a texture or renderbuffer detaches it from the bound framebuffers (§4.4.2.3);
//!   deleting a bound framebuffer or renderbuffer binds 0.

use std::collections::BTreeMap;

use super::api::Entry;
use super::error::{GlError, GlResult};
use super::texture::{BaseFormat, TexFormat, TextureTarget};

/// GL_MAX_COLOR_ATTACHMENTS (Mesa llvmpipe: 8).
pub const MAX_COLOR_ATTACHMENTS: u8 = 8;
/// GL_MAX_RENDERBUFFER_SIZE (llvmpipe: 16384).
pub const MAX_RENDERBUFFER_SIZE: i32 = 16384;

/// The binding a framebuffer call names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FramebufferTarget {
    /// GL_FRAMEBUFFER: both bindings (a query reads the draw one).
    Both,
    /// GL_DRAW_FRAMEBUFFER.
    Draw,
    /// GL_READ_FRAMEBUFFER.
    Read,
}

/// Where an image is attached.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AttachmentPoint {
    /// COLOR_ATTACHMENTi; i ≥ MAX_COLOR_ATTACHMENTS is INVALID_OPERATION.
    Color(u8),
    Depth,
    Stencil,
    /// DEPTH_STENCIL_ATTACHMENT: the same image at DEPTH and STENCIL.
    DepthStencil,
}

/// What is attached.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Attached {
    Texture {
        target: TextureTarget,
        name: u32,
        level: i32,
        /// The image of a 3D level (glFramebufferTexture3D's zoffset); 0 for 1D and 2D.
        layer: i32,
    },
    Renderbuffer(u32),
}

/// A colour buffer of glDrawBuffer / glReadBuffer (GL 1.5 Table 4.5, GL 3.0 Table 4.11).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ColorBuffer {
    None,
    Front,
    Back,
    Left,
    Right,
    FrontLeft,
    FrontRight,
    BackLeft,
    BackRight,
    FrontAndBack,
    /// AUXi.
    Aux(u8),
    /// COLOR_ATTACHMENTi.
    Attachment(u8),
}

impl ColorBuffer {
    /// Whether the buffer is allowed on the window (`fbo` false) or on an FBO, as Mesa's
    /// OSMesa answers (module note).
    pub fn allowed(self, fbo: bool) -> GlResult {
        let ok = match (fbo, self) {
            (_, ColorBuffer::None) => true,
            (true, ColorBuffer::Attachment(i)) => i < MAX_COLOR_ATTACHMENTS,
            (true, _) => false,
            (false, b) => matches!(
                b,
                ColorBuffer::Front
                    | ColorBuffer::Back
                    | ColorBuffer::Left
                    | ColorBuffer::FrontLeft
                    | ColorBuffer::BackLeft
                    | ColorBuffer::FrontAndBack
            ),
        };
        if ok {
            Ok(())
        } else if fbo {
            Err(GlError::invalid_operation(
                "an FBO draws into and reads from NONE or COLOR_ATTACHMENTi (i < 8)",
            ))
        } else {
            Err(GlError::invalid_operation(
                "the window has one colour buffer: FRONT, BACK, LEFT or FRONT_AND_BACK",
            ))
        }
    }
}

/// A renderbuffer's internal format, as given to glRenderbufferStorage (the query
/// returns it as given).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RenderbufferFormat {
    Rgba,
    Rgba8,
    Rgb,
    Rgb8,
    Rgba4,
    Rgb5A1,
    Rgb565,
    Rgba2,
    Rgb4,
    Rgb5,
    Rgb10,
    Rgb10A2,
    Rgba12,
    Rgba16,
    Rgba16F,
    Rgba32F,
    Red,
    R8,
    Rg8,
    Alpha,
    Alpha8,
    Luminance,
    Luminance8,
    Intensity,
    Intensity8,
    LuminanceAlpha,
    Luminance8Alpha8,
    DepthComponent,
    DepthComponent16,
    DepthComponent24,
    DepthComponent32,
    DepthComponent32F,
    StencilIndex,
    StencilIndex1,
    StencilIndex4,
    StencilIndex8,
    StencilIndex16,
    DepthStencil,
    Depth24Stencil8,
    Depth32FStencil8,
}

/// Bits per component of an image: red, green, blue, alpha, depth, stencil.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Bits {
    pub red: u8,
    pub green: u8,
    pub blue: u8,
    pub alpha: u8,
    pub depth: u8,
    pub stencil: u8,
}

const fn bits(red: u8, green: u8, blue: u8, alpha: u8, depth: u8, stencil: u8) -> Bits {
    Bits {
        red,
        green,
        blue,
        alpha,
        depth,
        stencil,
    }
}

impl RenderbufferFormat {
    /// The sizes Mesa's llvmpipe allocates (measured with glGetRenderbufferParameteriv;
    /// luminance and intensity report no red, green or blue bits there).
    pub fn bits(self) -> Bits {
        use RenderbufferFormat as F;
        match self {
            F::Rgba | F::Rgba8 => bits(8, 8, 8, 8, 0, 0),
            F::Rgb | F::Rgb8 => bits(8, 8, 8, 0, 0, 0),
            F::Rgba4 | F::Rgba2 => bits(4, 4, 4, 4, 0, 0),
            F::Rgb5A1 => bits(5, 5, 5, 1, 0, 0),
            F::Rgb565 => bits(5, 6, 5, 0, 0, 0),
            F::Rgb4 => bits(4, 4, 4, 0, 0, 0),
            F::Rgb5 => bits(5, 5, 5, 0, 0, 0),
            F::Rgb10 => bits(10, 10, 10, 0, 0, 0),
            F::Rgb10A2 => bits(10, 10, 10, 2, 0, 0),
            F::Rgba12 | F::Rgba16 | F::Rgba16F => bits(16, 16, 16, 16, 0, 0),
            F::Rgba32F => bits(32, 32, 32, 32, 0, 0),
            F::Red | F::R8 => bits(8, 0, 0, 0, 0, 0),
            F::Rg8 => bits(8, 8, 0, 0, 0, 0),
            F::Alpha | F::Alpha8 | F::LuminanceAlpha | F::Luminance8Alpha8 => {
                bits(0, 0, 0, 8, 0, 0)
            }
            F::Luminance | F::Luminance8 | F::Intensity | F::Intensity8 => bits(0, 0, 0, 0, 0, 0),
            F::DepthComponent | F::DepthComponent24 => bits(0, 0, 0, 0, 24, 0),
            F::DepthComponent16 => bits(0, 0, 0, 0, 16, 0),
            F::DepthComponent32 | F::DepthComponent32F => bits(0, 0, 0, 0, 32, 0),
            F::StencilIndex
            | F::StencilIndex1
            | F::StencilIndex4
            | F::StencilIndex8
            | F::StencilIndex16 => bits(0, 0, 0, 0, 0, 8),
            F::DepthStencil | F::Depth24Stencil8 => bits(0, 0, 0, 0, 24, 8),
            F::Depth32FStencil8 => bits(0, 0, 0, 0, 32, 8),
        }
    }

    /// What the image can be attached as.
    pub fn kind(self) -> ImageKind {
        let b = self.bits();
        match (b.depth > 0, b.stencil > 0) {
            (true, true) => ImageKind::DepthStencil,
            (true, false) => ImageKind::Depth,
            (false, true) => ImageKind::Stencil,
            (false, false) => ImageKind::Color,
        }
    }
}

/// The kind of an attached image.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageKind {
    Color,
    Depth,
    Stencil,
    DepthStencil,
}

impl ImageKind {
    fn of_texture(f: TexFormat) -> ImageKind {
        if f.base() == BaseFormat::Depth {
            ImageKind::Depth
        } else {
            ImageKind::Color
        }
    }
}

/// The bits of a texture image attached to a framebuffer (as Mesa's formats have them).
pub fn texture_bits(f: TexFormat) -> Bits {
    match f {
        TexFormat::Rgba8 => bits(8, 8, 8, 8, 0, 0),
        TexFormat::Rgb8 => bits(8, 8, 8, 0, 0, 0),
        TexFormat::Alpha8 | TexFormat::Luminance8Alpha8 => bits(0, 0, 0, 8, 0, 0),
        TexFormat::Luminance8 | TexFormat::Intensity8 => bits(0, 0, 0, 0, 0, 0),
        TexFormat::DepthComponent16 => bits(0, 0, 0, 0, 16, 0),
        TexFormat::DepthComponent24 => bits(0, 0, 0, 0, 24, 0),
        TexFormat::DepthComponent32F => bits(0, 0, 0, 0, 32, 0),
        TexFormat::Rgba32F => bits(32, 32, 32, 32, 0, 0),
    }
}

/// One renderbuffer. GL default: no storage, width and height 0, format RGBA.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Renderbuffer {
    pub format: RenderbufferFormat,
    pub width: i32,
    pub height: i32,
}

impl Default for Renderbuffer {
    fn default() -> Self {
        Renderbuffer {
            format: RenderbufferFormat::Rgba,
            width: 0,
            height: 0,
        }
    }
}

/// One framebuffer object. GL default: nothing attached, drawing into and reading from
/// COLOR_ATTACHMENT0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FramebufferObject {
    pub color: [Option<Attached>; MAX_COLOR_ATTACHMENTS as usize],
    pub depth: Option<Attached>,
    pub stencil: Option<Attached>,
    pub draw_buffer: ColorBuffer,
    pub read_buffer: ColorBuffer,
}

impl Default for FramebufferObject {
    fn default() -> Self {
        FramebufferObject {
            color: [None; MAX_COLOR_ATTACHMENTS as usize],
            depth: None,
            stencil: None,
            draw_buffer: ColorBuffer::Attachment(0),
            read_buffer: ColorBuffer::Attachment(0),
        }
    }
}

impl FramebufferObject {
    /// The attachment at `point` (DEPTH_STENCIL reads the depth one).
    pub fn attachment(&self, point: AttachmentPoint) -> Option<Attached> {
        match point {
            AttachmentPoint::Color(i) => self.color.get(usize::from(i)).copied().flatten(),
            AttachmentPoint::Depth | AttachmentPoint::DepthStencil => self.depth,
            AttachmentPoint::Stencil => self.stencil,
        }
    }

    fn attachments_mut(&mut self) -> impl Iterator<Item = &mut Option<Attached>> {
        self.color
            .iter_mut()
            .chain(std::iter::once(&mut self.depth))
            .chain(std::iter::once(&mut self.stencil))
    }

    /// Every image attached, with the point it is at.
    pub fn attached(&self) -> impl Iterator<Item = (AttachmentPoint, Attached)> + '_ {
        let colors = self
            .color
            .iter()
            .enumerate()
            .filter_map(|(i, a)| a.map(|a| (AttachmentPoint::Color(i as u8), a)));
        colors
            .chain(self.depth.map(|a| (AttachmentPoint::Depth, a)))
            .chain(self.stencil.map(|a| (AttachmentPoint::Stencil, a)))
    }
}

/// glCheckFramebufferStatus's answers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Completeness {
    Complete,
    IncompleteAttachment,
    MissingAttachment,
    Unsupported,
}

/// What completeness needs to know of an attached image: its kind and size, or `None`
/// when the image does not exist.
pub type ImageInfo = Option<(ImageKind, i32, i32)>;

/// The framebuffer state of a context.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Framebuffers {
    pub objects: BTreeMap<u32, FramebufferObject>,
    pub renderbuffers: BTreeMap<u32, Renderbuffer>,
    /// DRAW_FRAMEBUFFER_BINDING and READ_FRAMEBUFFER_BINDING. GL default: 0.
    pub draw: u32,
    pub read: u32,
    /// RENDERBUFFER_BINDING. GL default: 0.
    pub renderbuffer: u32,
    /// The window's draw and read buffers. GL default: FRONT (a single-buffered
    /// window, as Mesa's OSMesa buffer).
    pub window_draw: WindowBuffers,
    /// The buffers of the last glDrawBuffer and glReadBuffer that succeeded, on whichever
    /// framebuffer was bound (Mesa's context copies `Color.DrawBuffer[0]` and
    /// `Pixel.ReadBuffer`): what glPushAttrib saves under COLOR_BUFFER_BIT and
    /// PIXEL_MODE_BIT, and what glPopAttrib compares with (`ff::attrib`). GL default:
    /// FRONT, FRONT.
    pub last_set: WindowBuffers,
    /// The window's bits (GL_RED_BITS … GL_STENCIL_BITS with framebuffer 0 bound): the
    /// pipelines read them from the target bound when they start.
    pub window_bits: Bits,
    /// The window's accumulation bits per channel (GL_ACCUM_RED_BITS …): 0 unless the
    /// window was made with an accumulation buffer (`ff::accum::ACCUM_BITS`). GL default: 0.
    pub window_accum_bits: u8,
    /// The largest framebuffer and renderbuffer names bound so far (glGen* continues
    /// after them, as Mesa's name tables do).
    pub max_framebuffer: u32,
    pub max_renderbuffer: u32,
}

/// The window's colour-buffer selections.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WindowBuffers {
    pub draw: ColorBuffer,
    pub read: ColorBuffer,
}

impl Default for WindowBuffers {
    fn default() -> Self {
        WindowBuffers {
            draw: ColorBuffer::Front,
            read: ColorBuffer::Front,
        }
    }
}

impl Framebuffers {
    /// glBindFramebuffer: makes the object on the first bind of a name.
    pub fn bind(&mut self, target: FramebufferTarget, name: u32) {
        if name != 0 {
            self.objects.entry(name).or_default();
            self.max_framebuffer = self.max_framebuffer.max(name);
        }
        match target {
            FramebufferTarget::Both => {
                self.draw = name;
                self.read = name;
            }
            FramebufferTarget::Draw => self.draw = name,
            FramebufferTarget::Read => self.read = name,
        }
    }

    /// glBindRenderbuffer.
    pub fn bind_renderbuffer(&mut self, name: u32) {
        if name != 0 {
            self.renderbuffers.entry(name).or_default();
            self.max_renderbuffer = self.max_renderbuffer.max(name);
        }
        self.renderbuffer = name;
    }

    /// The name a framebuffer call on `target` acts on (a query of FRAMEBUFFER reads the
    /// draw binding).
    pub fn bound(&self, target: FramebufferTarget) -> u32 {
        match target {
            FramebufferTarget::Both | FramebufferTarget::Draw => self.draw,
            FramebufferTarget::Read => self.read,
        }
    }

    /// The object bound to `target`, or INVALID_OPERATION for the window.
    pub fn bound_object_mut(
        &mut self,
        target: FramebufferTarget,
    ) -> GlResult<&mut FramebufferObject> {
        let name = self.bound(target);
        if name == 0 {
            return Err(GlError::invalid_operation(
                "framebuffer 0 (the window) has no attachments to change",
            ));
        }
        Ok(self.objects.entry(name).or_default())
    }

    /// glDeleteFramebuffers: a bound one leaves its binding at 0.
    pub fn delete(&mut self, names: &[u32]) {
        for name in names.iter().filter(|n| **n != 0) {
            if self.objects.remove(name).is_some() {
                if self.draw == *name {
                    self.draw = 0;
                }
                if self.read == *name {
                    self.read = 0;
                }
            }
        }
    }

    /// glDeleteRenderbuffers: each is detached from the bound framebuffers, and a bound
    /// one leaves the binding at 0.
    pub fn delete_renderbuffers(&mut self, names: &[u32]) {
        for name in names.iter().filter(|n| **n != 0) {
            if self.renderbuffers.remove(name).is_none() {
                continue;
            }
            if self.renderbuffer == *name {
                self.renderbuffer = 0;
            }
            self.detach_where(|a| a == Attached::Renderbuffer(*name));
        }
    }

    /// glDeleteTextures: each is detached from the bound framebuffers (§4.4.2.3).
    pub fn detach_textures(&mut self, names: &[u32]) {
        for name in names.iter().filter(|n| **n != 0) {
            self.detach_where(|a| matches!(a, Attached::Texture { name: n, .. } if n == *name));
        }
    }

    fn detach_where(&mut self, hit: impl Fn(Attached) -> bool) {
        for bound in [self.draw, self.read] {
            if let Some(fb) = self.objects.get_mut(&bound) {
                for slot in fb.attachments_mut() {
                    if slot.is_some_and(&hit) {
                        *slot = None;
                    }
                }
            }
        }
    }

    /// The draw (or read) buffer of the framebuffer bound to `target`.
    pub fn color_buffer(&self, target: FramebufferTarget) -> ColorBuffer {
        let name = self.bound(target);
        let read = target == FramebufferTarget::Read;
        match self.objects.get(&name) {
            Some(fb) if name != 0 => {
                if read {
                    fb.read_buffer
                } else {
                    fb.draw_buffer
                }
            }
            _ if read => self.window_draw.read,
            _ => self.window_draw.draw,
        }
    }

    /// glDrawBuffer (`read` false) or glReadBuffer of the bound framebuffer.
    pub fn set_color_buffer(&mut self, read: bool, buffer: ColorBuffer) -> GlResult {
        let target = if read {
            FramebufferTarget::Read
        } else {
            FramebufferTarget::Draw
        };
        let name = self.bound(target);
        buffer.allowed(name != 0)?;
        let slot = match self.objects.get_mut(&name) {
            Some(fb) if name != 0 => {
                if read {
                    &mut fb.read_buffer
                } else {
                    &mut fb.draw_buffer
                }
            }
            _ if read => &mut self.window_draw.read,
            _ => &mut self.window_draw.draw,
        };
        *slot = buffer;
        if read {
            self.last_set.read = buffer;
        } else {
            self.last_set.draw = buffer;
        }
        Ok(())
    }

    /// glCheckFramebufferStatus of the framebuffer bound to `target`; `image` tells what
    /// a texture attachment's image is — (target, name, level, layer), `None` for no
    /// image, as for a 3D layer at or past the level's depth (the textures live in the
    /// state beside this).
    pub fn status(
        &self,
        target: FramebufferTarget,
        texture_image: impl Fn(TextureTarget, u32, i32, i32) -> ImageInfo,
    ) -> Completeness {
        let name = self.bound(target);
        let Some(fb) = self.objects.get(&name).filter(|_| name != 0) else {
            return Completeness::Complete;
        };
        let mut any = false;
        for (point, a) in fb.attached() {
            any = true;
            let info = match a {
                Attached::Texture {
                    target,
                    name,
                    level,
                    layer,
                } => texture_image(target, name, level, layer),
                Attached::Renderbuffer(r) => self
                    .renderbuffers
                    .get(&r)
                    .map(|rb| (rb.format.kind(), rb.width, rb.height)),
            };
            let Some((kind, w, h)) = info else {
                return Completeness::IncompleteAttachment;
            };
            let fits = match point {
                AttachmentPoint::Color(_) => kind == ImageKind::Color,
                AttachmentPoint::Depth | AttachmentPoint::DepthStencil => {
                    matches!(kind, ImageKind::Depth | ImageKind::DepthStencil)
                }
                AttachmentPoint::Stencil => {
                    matches!(kind, ImageKind::Stencil | ImageKind::DepthStencil)
                }
            };
            if !fits || w <= 0 || h <= 0 {
                return Completeness::IncompleteAttachment;
            }
        }
        if !any {
            return Completeness::MissingAttachment;
        }
        if let (Some(d), Some(s)) = (fb.depth, fb.stencil) {
            if d != s {
                return Completeness::Unsupported;
            }
        }
        Completeness::Complete
    }

    /// The bits of the framebuffer bound for drawing (GL_RED_BITS … GL_STENCIL_BITS):
    /// the window's, or those of the FBO's draw buffer and depth and stencil images.
    pub fn draw_bits(
        &self,
        window: Bits,
        texture_format: impl Fn(TextureTarget, u32, i32) -> Option<TexFormat>,
    ) -> Bits {
        let Some(fb) = self.objects.get(&self.draw).filter(|_| self.draw != 0) else {
            return window;
        };
        let image_bits = |a: Option<Attached>| -> Bits {
            match a {
                Some(Attached::Texture {
                    target,
                    name,
                    level,
                    ..
                }) => texture_format(target, name, level).map_or(Bits::default(), texture_bits),
                Some(Attached::Renderbuffer(r)) => self
                    .renderbuffers
                    .get(&r)
                    .filter(|rb| rb.width > 0)
                    .map_or(Bits::default(), |rb| rb.format.bits()),
                None => Bits::default(),
            }
        };
        let color = match fb.draw_buffer {
            ColorBuffer::Attachment(i) => image_bits(fb.attachment(AttachmentPoint::Color(i))),
            _ => Bits::default(),
        };
        Bits {
            depth: image_bits(fb.depth).depth,
            stencil: image_bits(fb.stencil).stencil,
            ..color
        }
    }
}

/// The framebuffer calls GL never compiles into a display list (GL 3.0 §5.4; Mesa
/// executes them at once); glDrawBuffer and glReadBuffer are compiled.
pub fn never_compiled(entry: Entry) -> bool {
    use Entry as E;
    matches!(
        entry,
        E::GenFramebuffers
            | E::GenFramebuffersEXT
            | E::BindFramebuffer
            | E::BindFramebufferEXT
            | E::DeleteFramebuffers
            | E::DeleteFramebuffersEXT
            | E::IsFramebuffer
            | E::IsFramebufferEXT
            | E::CheckFramebufferStatus
            | E::CheckFramebufferStatusEXT
            | E::FramebufferTexture1D
            | E::FramebufferTexture1DEXT
            | E::FramebufferTexture2D
            | E::FramebufferTexture2DEXT
            | E::FramebufferTexture3D
            | E::FramebufferTexture3DEXT
            | E::FramebufferRenderbuffer
            | E::FramebufferRenderbufferEXT
            | E::GetFramebufferAttachmentParameteriv
            | E::GetFramebufferAttachmentParameterivEXT
            | E::GenRenderbuffers
            | E::GenRenderbuffersEXT
            | E::BindRenderbuffer
            | E::BindRenderbufferEXT
            | E::DeleteRenderbuffers
            | E::DeleteRenderbuffersEXT
            | E::IsRenderbuffer
            | E::IsRenderbufferEXT
            | E::RenderbufferStorage
            | E::RenderbufferStorageEXT
            | E::GetRenderbufferParameteriv
            | E::GetRenderbufferParameterivEXT
            | E::GenerateMipmap
            | E::GenerateMipmapEXT
    )
}

/// The framebuffer calls whose answer is a value or written memory: names (glGen*),
/// glIs*, glCheckFramebufferStatus and the two getters. The C library answers them from
/// the model (`abi::framebuffers`); a script names its objects and cannot read memory
/// back, so there each checks its arguments ([`script_answer`]).
pub fn answered_by_front_end(entry: Entry) -> bool {
    use Entry as E;
    matches!(
        entry,
        E::GenFramebuffers
            | E::GenFramebuffersEXT
            | E::GenRenderbuffers
            | E::GenRenderbuffersEXT
            | E::IsFramebuffer
            | E::IsFramebufferEXT
            | E::IsRenderbuffer
            | E::IsRenderbufferEXT
            | E::CheckFramebufferStatus
            | E::CheckFramebufferStatusEXT
            | E::GetFramebufferAttachmentParameteriv
            | E::GetFramebufferAttachmentParameterivEXT
            | E::GetRenderbufferParameteriv
            | E::GetRenderbufferParameterivEXT
    )
}

/// One of [`answered_by_front_end`]'s calls in a script: the arguments checked as GL
/// checks them, glIs* and glCheckFramebufferStatus answered from the model.
pub fn script_answer<A: super::args::Args>(
    c: &A,
    state: &super::FixedState,
) -> Result<Result<super::front::Reply, super::GlErrorKind>, A::Error> {
    use super::front::Reply;
    use Entry as E;
    let f = &state.framebuffers;
    Ok(Ok(match c.entry() {
        E::GenFramebuffers
        | E::GenFramebuffersEXT
        | E::GenRenderbuffers
        | E::GenRenderbuffersEXT => {
            c.count(2)?;
            if c.i32(0)? < 0 {
                return Err(c.bad(0, "a count of 0 or more"));
            }
            Reply::None
        }
        E::IsFramebuffer | E::IsFramebufferEXT => {
            c.count(1)?;
            let name = c.u32(0)?;
            Reply::Value(u32::from(name != 0 && f.objects.contains_key(&name)))
        }
        E::IsRenderbuffer | E::IsRenderbufferEXT => {
            c.count(1)?;
            let name = c.u32(0)?;
            Reply::Value(u32::from(name != 0 && f.renderbuffers.contains_key(&name)))
        }
        E::CheckFramebufferStatus | E::CheckFramebufferStatusEXT => {
            c.count(1)?;
            Reply::Value(state.framebuffer_status(c.enm(0)?).code())
        }
        E::GetFramebufferAttachmentParameteriv | E::GetFramebufferAttachmentParameterivEXT => {
            c.count(4)?;
            let _: FramebufferTarget = c.enm(0)?;
            Reply::None
        }
        _ => {
            c.count(3)?;
            c.pname(0, &["GL_RENDERBUFFER", "GL_RENDERBUFFER_EXT"])?;
            Reply::None
        }
    }))
}

impl Completeness {
    /// The GLenum glCheckFramebufferStatus returns.
    pub fn code(self) -> u32 {
        use super::glenum::registry as r;
        match self {
            Completeness::Complete => r::FRAMEBUFFER_COMPLETE,
            Completeness::IncompleteAttachment => r::FRAMEBUFFER_INCOMPLETE_ATTACHMENT,
            Completeness::MissingAttachment => r::FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT,
            Completeness::Unsupported => r::FRAMEBUFFER_UNSUPPORTED,
        }
    }
}

/// The kind and size of a texture image, for completeness.
pub fn texture_image_info(format: TexFormat, width: i32, height: i32) -> ImageInfo {
    Some((ImageKind::of_texture(format), width, height))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn no_textures(_: TextureTarget, _: u32, _: i32, _: i32) -> ImageInfo {
        None
    }

    #[test]
    fn completeness_follows_mesa() {
        let mut f = Framebuffers::default();
        assert_eq!(
            f.status(FramebufferTarget::Both, no_textures),
            Completeness::Complete
        );
        f.bind(FramebufferTarget::Both, 3);
        assert_eq!(
            f.status(FramebufferTarget::Both, no_textures),
            Completeness::MissingAttachment
        );
        f.bind_renderbuffer(1);
        f.bound_object_mut(FramebufferTarget::Both).unwrap().depth =
            Some(Attached::Renderbuffer(1));
        // No storage yet.
        assert_eq!(
            f.status(FramebufferTarget::Both, no_textures),
            Completeness::IncompleteAttachment
        );
        f.renderbuffers.insert(
            1,
            Renderbuffer {
                format: RenderbufferFormat::DepthComponent24,
                width: 4,
                height: 4,
            },
        );
        // Depth only, draw buffer COLOR_ATTACHMENT0 without an image: complete on Mesa.
        assert_eq!(
            f.status(FramebufferTarget::Both, no_textures),
            Completeness::Complete
        );
        // A depth image as the colour.
        f.bound_object_mut(FramebufferTarget::Both).unwrap().color[0] =
            Some(Attached::Renderbuffer(1));
        assert_eq!(
            f.status(FramebufferTarget::Both, no_textures),
            Completeness::IncompleteAttachment
        );
        f.bound_object_mut(FramebufferTarget::Both).unwrap().color[0] = None;
        // Separate depth and stencil images: unsupported on llvmpipe.
        f.renderbuffers.insert(
            2,
            Renderbuffer {
                format: RenderbufferFormat::StencilIndex8,
                width: 4,
                height: 4,
            },
        );
        f.bound_object_mut(FramebufferTarget::Both).unwrap().stencil =
            Some(Attached::Renderbuffer(2));
        assert_eq!(
            f.status(FramebufferTarget::Both, no_textures),
            Completeness::Unsupported
        );
    }

    #[test]
    fn deleting_detaches_from_bound_framebuffers_only() {
        let mut f = Framebuffers::default();
        let tex = Attached::Texture {
            target: TextureTarget::Texture2D,
            name: 5,
            level: 0,
            layer: 0,
        };
        f.bind(FramebufferTarget::Both, 1);
        f.bound_object_mut(FramebufferTarget::Both).unwrap().color[0] = Some(tex);
        f.bind(FramebufferTarget::Both, 2);
        f.bound_object_mut(FramebufferTarget::Both).unwrap().color[0] = Some(tex);
        f.detach_textures(&[5]);
        assert_eq!(f.objects[&2].color[0], None);
        assert_eq!(f.objects[&1].color[0], Some(tex));
        f.delete(&[2]);
        assert_eq!((f.draw, f.read), (0, 0));
    }

    #[test]
    fn color_buffers_per_framebuffer() {
        let mut f = Framebuffers::default();
        assert!(f.set_color_buffer(false, ColorBuffer::Right).is_err());
        assert!(f
            .set_color_buffer(false, ColorBuffer::Attachment(0))
            .is_err());
        f.set_color_buffer(false, ColorBuffer::None).unwrap();
        f.bind(FramebufferTarget::Both, 1);
        assert_eq!(
            f.color_buffer(FramebufferTarget::Draw),
            ColorBuffer::Attachment(0)
        );
        assert!(f.set_color_buffer(false, ColorBuffer::Front).is_err());
        assert!(f
            .set_color_buffer(false, ColorBuffer::Attachment(8))
            .is_err());
        f.set_color_buffer(false, ColorBuffer::Attachment(1))
            .unwrap();
        f.bind(FramebufferTarget::Both, 0);
        assert_eq!(f.color_buffer(FramebufferTarget::Draw), ColorBuffer::None);
    }
}
