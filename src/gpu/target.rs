//! Render targets: a framebuffer object with a colour renderbuffer (RGBA8 unless asked
//! for RGBA16 or RGBA32F, `ColorStorage`) and a depth attachment chosen by `DepthBits`
//! (or exactly the depth and stencil buffers asked, `DepthStencilBuffers`), plus pixel
//! readback.
//!
//! Row order: `read_color` returns an image with the top row first (image convention);
//! depth and stencil readbacks keep GL's order, bottom row first, because they feed
//! `glTexImage2D` as they are. The bits actually obtained are queried from the framebuffer
//! (`GL_FRAMEBUFFER_ATTACHMENT_{DEPTH,STENCIL}_SIZE`) and reported, never assumed.

use glow::HasContext;

use super::readback::{depth_to_u16, depth_to_u32, depth_to_u8};
use super::{conv, GpuContext, GpuError};
use crate::vocab::{DepthBits, ReadbackRule};

/// The colour buffer's storage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ColorStorage {
    /// RGBA8 (the default).
    #[default]
    Rgba8,
    /// RGBA16, 16-bit unsigned normalised (an OSMesa GL_UNSIGNED_SHORT buffer).
    Rgba16,
    /// RGBA32F (an OSMesa GL_FLOAT buffer).
    Rgba32F,
    /// RGB8, no alpha (an OSMesa OSMESA_RGB or OSMESA_BGR buffer of GL_UNSIGNED_BYTE): the
    /// framebuffer has ALPHA_BITS 0 and blending reads a destination alpha of 1, as on
    /// Mesa's buffer of that format.
    Rgb8,
    /// RGB16 (an OSMESA_RGB or OSMESA_BGR buffer of GL_UNSIGNED_SHORT), no alpha.
    Rgb16,
    /// RGB32F (an OSMESA_RGB or OSMESA_BGR buffer of GL_FLOAT), no alpha.
    Rgb32F,
    /// RGB565 (an OSMESA_RGB_565 buffer), read back as bytes.
    Rgb565,
}

impl ColorStorage {
    /// The GL internal format, and the type and bytes per component a readback uses.
    fn gl(self) -> (u32, u32, usize) {
        match self {
            ColorStorage::Rgba8 => (glow::RGBA8, glow::UNSIGNED_BYTE, 1),
            ColorStorage::Rgba16 => (glow::RGBA16, glow::UNSIGNED_SHORT, 2),
            ColorStorage::Rgba32F => (glow::RGBA32F, glow::FLOAT, 4),
            ColorStorage::Rgb8 => (glow::RGB8, glow::UNSIGNED_BYTE, 1),
            ColorStorage::Rgb16 => (glow::RGB16, glow::UNSIGNED_SHORT, 2),
            ColorStorage::Rgb32F => (glow::RGB32F, glow::FLOAT, 4),
            ColorStorage::Rgb565 => (glow::RGB565, glow::UNSIGNED_BYTE, 1),
        }
    }

    /// Bytes per component.
    pub fn component_bytes(self) -> usize {
        self.gl().2
    }
}

/// Which depth and stencil renderbuffers a target has.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum DepthStencilBuffers {
    /// The buffer `depth` names, with 8 stencil bits when `stencil` asks; a D24 buffer
    /// always carries them (one DEPTH24_STENCIL8). The default.
    #[default]
    AsNamed,
    /// `depth`'s buffer alone, without stencil bits even for D24 (DEPTH_COMPONENT24).
    DepthOnly,
    /// No depth buffer (the depth test always passes, GL 1.5 §4.1.5); an 8-bit stencil
    /// buffer (STENCIL_INDEX8) when `stencil` asks.
    NoDepth,
}

/// Size and buffers of a target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TargetSpec {
    pub width: u32,
    pub height: u32,
    pub depth: DepthBits,
    /// Ask for 8 stencil bits. D24 always has them; D16 has none.
    pub stencil: bool,
    /// GL default here: RGBA8.
    pub color: ColorStorage,
    /// How `depth` and `stencil` become renderbuffers. Default: [`DepthStencilBuffers::AsNamed`].
    pub buffers: DepthStencilBuffers,
}

impl TargetSpec {
    pub fn new(width: u32, height: u32, depth: DepthBits) -> Self {
        TargetSpec {
            width,
            height,
            depth,
            stencil: false,
            color: ColorStorage::Rgba8,
            buffers: DepthStencilBuffers::AsNamed,
        }
    }

    pub fn with_buffers(mut self, buffers: DepthStencilBuffers) -> Self {
        self.buffers = buffers;
        self
    }

    pub fn with_stencil(mut self) -> Self {
        self.stencil = true;
        self
    }

    pub fn with_color(mut self, color: ColorStorage) -> Self {
        self.color = color;
        self
    }
}

/// A framebuffer object and its renderbuffers, or a window-system surface's framebuffer 0
/// ([`RenderTarget::surface`]). Owned by the context that made it; call
/// [`RenderTarget::delete`] before dropping that context to free the GL objects early.
#[derive(Debug)]
pub struct RenderTarget {
    spec: TargetSpec,
    /// None: framebuffer 0, the surface the context is current with.
    framebuffer: Option<glow::Framebuffer>,
    /// The colour renderbuffer of a framebuffer object.
    color: Option<glow::Renderbuffer>,
    /// The colour buffer drawn and read: COLOR_ATTACHMENT0, or the surface's FRONT or BACK.
    color_buffer: u32,
    /// None: the target has neither depth nor stencil buffer.
    depth: Option<glow::Renderbuffer>,
    depth_bits: u32,
    stencil_bits: u32,
}

impl RenderTarget {
    /// Creates the target and leaves it bound as the draw and read framebuffer, with the
    /// viewport and the scissor box covering it.
    pub fn new(ctx: &GpuContext, spec: TargetSpec) -> Result<RenderTarget, GpuError> {
        let gl = ctx.gl();
        let limit = unsafe { gl.get_parameter_i32(glow::MAX_RENDERBUFFER_SIZE) }.max(0) as u32;
        let size_ok = |s: u32| (1..=limit).contains(&s);
        if !size_ok(spec.width) || !size_ok(spec.height) {
            return Err(GpuError::TargetSize {
                width: spec.width,
                height: spec.height,
                limit,
            });
        }
        if spec.stencil
            && spec.depth == DepthBits::D16
            && spec.buffers != DepthStencilBuffers::NoDepth
        {
            return Err(GpuError::IncompleteFramebuffer {
                depth: spec.depth,
                stencil: true,
                status: glow::FRAMEBUFFER_UNSUPPORTED,
            });
        }
        let (w, h) = (spec.width as i32, spec.height as i32);
        let storage = match spec.buffers {
            DepthStencilBuffers::AsNamed => Some(conv::depth_storage(spec.depth, spec.stencil)),
            DepthStencilBuffers::DepthOnly => Some(conv::depth_only_storage(spec.depth)),
            DepthStencilBuffers::NoDepth => spec
                .stencil
                .then_some((glow::STENCIL_INDEX8, glow::STENCIL_ATTACHMENT)),
        };
        let target = unsafe {
            let framebuffer = gl.create_framebuffer().map_err(GpuError::Object)?;
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(framebuffer));
            let color = gl.create_renderbuffer().map_err(GpuError::Object)?;
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(color));
            gl.renderbuffer_storage(glow::RENDERBUFFER, spec.color.gl().0, w, h);
            gl.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0,
                glow::RENDERBUFFER,
                Some(color),
            );
            let depth = match storage {
                Some((format, attachment)) => {
                    let depth = gl.create_renderbuffer().map_err(GpuError::Object)?;
                    gl.bind_renderbuffer(glow::RENDERBUFFER, Some(depth));
                    gl.renderbuffer_storage(glow::RENDERBUFFER, format, w, h);
                    gl.framebuffer_renderbuffer(
                        glow::FRAMEBUFFER,
                        attachment,
                        glow::RENDERBUFFER,
                        Some(depth),
                    );
                    Some(depth)
                }
                None => None,
            };
            let mut target = RenderTarget {
                spec,
                framebuffer: Some(framebuffer),
                color: Some(color),
                color_buffer: glow::COLOR_ATTACHMENT0,
                depth,
                depth_bits: 0,
                stencil_bits: 0,
            };
            let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
            if status != glow::FRAMEBUFFER_COMPLETE {
                target.delete(ctx);
                return Err(GpuError::IncompleteFramebuffer {
                    depth: spec.depth,
                    stencil: spec.stencil,
                    status,
                });
            }
            let query = |attachment, pname| {
                gl.get_framebuffer_attachment_parameter_i32(glow::FRAMEBUFFER, attachment, pname)
                    .max(0) as u32
            };
            let attachment = storage.map(|(_, a)| a);
            if attachment.is_some_and(|a| a != glow::STENCIL_ATTACHMENT) {
                target.depth_bits = query(
                    glow::DEPTH_ATTACHMENT,
                    glow::FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE,
                );
            }
            if matches!(
                attachment,
                Some(glow::DEPTH_STENCIL_ATTACHMENT | glow::STENCIL_ATTACHMENT)
            ) {
                target.stencil_bits = query(
                    glow::STENCIL_ATTACHMENT,
                    glow::FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
                );
            }
            gl.viewport(0, 0, w, h);
            // The scissor box starts as the window (GL 1.5 §4.1.2); the target is the
            // window here. A surfaceless context has no window, and Mesa starts the box at
            // (0, 0, 0, 0) there (measured, `tests/fidelity_scissor.rs`): SCISSOR_TEST
            // enabled before any glScissor would then discard everything.
            gl.scissor(0, 0, w, h);
            target
        };
        ctx.check_error("RenderTarget::new")?;
        Ok(target)
    }

    /// Framebuffer 0 of the surface the context is current with (`GpuContext::
    /// bind_window_surface`), `spec` its size and colour storage, as a target: bound, with
    /// the viewport and the scissor box covering it. Its bits are the surface's.
    pub fn surface(ctx: &GpuContext, spec: TargetSpec) -> Result<RenderTarget, GpuError> {
        let gl = ctx.gl();
        let target = unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            // The buffer GL draws into by default is the surface's (a pbuffer has one, EGL
            // 1.5 §3.5.2); reads come from it too (Mesa starts READ_BUFFER at FRONT).
            let color_buffer = gl.get_parameter_i32(glow::DRAW_BUFFER) as u32;
            gl.read_buffer(color_buffer);
            let query = |attachment, pname| {
                let kind = gl.get_framebuffer_attachment_parameter_i32(
                    glow::FRAMEBUFFER,
                    attachment,
                    glow::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                );
                match kind == glow::NONE as i32 {
                    true => 0,
                    false => gl
                        .get_framebuffer_attachment_parameter_i32(
                            glow::FRAMEBUFFER,
                            attachment,
                            pname,
                        )
                        .max(0) as u32,
                }
            };
            let target = RenderTarget {
                spec,
                framebuffer: None,
                color: None,
                color_buffer,
                depth: None,
                depth_bits: query(glow::DEPTH, glow::FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE),
                stencil_bits: query(glow::STENCIL, glow::FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE),
            };
            gl.viewport(0, 0, spec.width as i32, spec.height as i32);
            gl.scissor(0, 0, spec.width as i32, spec.height as i32);
            target
        };
        ctx.check_error("RenderTarget::surface")?;
        Ok(target)
    }

    pub fn spec(&self) -> TargetSpec {
        self.spec
    }

    pub fn width(&self) -> u32 {
        self.spec.width
    }

    pub fn height(&self) -> u32 {
        self.spec.height
    }

    /// Depth bits the driver actually gave (GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE).
    pub fn depth_bits(&self) -> u32 {
        self.depth_bits
    }

    /// Stencil bits the driver actually gave; 0 when there is no stencil buffer.
    pub fn stencil_bits(&self) -> u32 {
        self.stencil_bits
    }

    /// The framebuffer object; None for a surface's framebuffer 0.
    pub fn framebuffer(&self) -> Option<glow::Framebuffer> {
        self.framebuffer
    }

    /// The colour buffer drawn and read (COLOR_ATTACHMENT0, or a surface's FRONT or BACK).
    pub fn color_buffer(&self) -> u32 {
        self.color_buffer
    }

    /// GL_RGBA or GL_BGRA: the byte order of 8-bit colour in the buffer, in which a read of
    /// it is one copy.
    pub fn byte_order(&self) -> u32 {
        match self.framebuffer {
            // Mesa's 8-bit window-system buffers are ARGB8888, B8G8R8A8 in memory (its dri
            // configs; GL_IMPLEMENTATION_COLOR_READ_FORMAT answers RGBA regardless): read
            // as BGRA, a 256×256 buffer is one copy, 8× faster than as RGBA on llvmpipe.
            None => glow::BGRA,
            Some(_) => glow::RGBA,
        }
    }

    /// Binds the target for drawing and reading and sets the viewport to cover it.
    pub fn bind(&self, ctx: &GpuContext) {
        let gl = ctx.gl();
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, self.framebuffer);
            gl.viewport(0, 0, self.spec.width as i32, self.spec.height as i32);
        }
    }

    /// Clears the target's stencil buffer to 0, all of it: the scissor test off and every
    /// stencil bit writable (GL's defaults, left so), the target bound by [`bind`].
    /// A new buffer's contents are undefined in GL; this makes its stencil known.
    ///
    /// [`bind`]: RenderTarget::bind
    pub fn clear_stencil(&self, ctx: &GpuContext) {
        let gl = ctx.gl();
        // SAFETY: plain GL calls on the current context.
        unsafe {
            gl.disable(glow::SCISSOR_TEST);
            gl.stencil_mask(!0);
            gl.clear_stencil(0);
            gl.clear(glow::STENCIL_BUFFER_BIT);
        }
    }

    /// Frees the GL objects. The context must be current.
    pub fn delete(self, ctx: &GpuContext) {
        let gl = ctx.gl();
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            if let Some(framebuffer) = self.framebuffer {
                gl.delete_framebuffer(framebuffer);
            }
            if let Some(color) = self.color {
                gl.delete_renderbuffer(color);
            }
            if let Some(depth) = self.depth {
                gl.delete_renderbuffer(depth);
            }
        }
    }

    /// The colour buffer in its own storage (RGBA of 1, 2 or 4 bytes per component:
    /// unorm8, unorm16 or f32, native byte order), GL's order, bottom row first.
    pub fn read_color_stored(&self, ctx: &GpuContext) -> Result<Vec<u8>, GpuError> {
        let (_, ty, size) = self.spec.color.gl();
        let (w, h) = (self.spec.width, self.spec.height);
        let mut data = vec![0u8; (w * h * 4) as usize * size];
        self.read(ctx, glow::RGBA, ty, &mut data)?;
        Ok(data)
    }

    /// [`read_color_stored`](Self::read_color_stored) into `out`, resized to fit (a
    /// buffer kept from frame to frame is not allocated again).
    pub fn read_color_stored_into(
        &self,
        ctx: &GpuContext,
        out: &mut Vec<u8>,
    ) -> Result<(), GpuError> {
        let (_, ty, size) = self.spec.color.gl();
        out.resize(self.pixel_count() * 4 * size, 0);
        self.read(ctx, glow::RGBA, ty, out)
    }

    /// The colour buffer as bytes of `format` (RGBA or BGRA, 4 per pixel), bottom row
    /// first, straight into rows of `row_pixels` pixels (PACK_ROW_LENGTH) of `out`: one
    /// copy, for a caller whose buffer has GL's layout. `out` must hold
    /// (height − 1)·row_pixels + width pixels.
    pub fn read_color_bytes_into_rows(
        &self,
        ctx: &GpuContext,
        format: u32,
        row_pixels: usize,
        out: &mut [u8],
    ) -> Result<(), GpuError> {
        let gl = ctx.gl();
        let row_length = i32::try_from(row_pixels)
            .map_err(|_| GpuError::Object("row length beyond GL's range".into()))?;
        unsafe {
            gl.pixel_store_i32(glow::PACK_ROW_LENGTH, row_length);
        }
        let read = self.read(ctx, format, glow::UNSIGNED_BYTE, out);
        // The program's own reads set their pack state; this one leaves GL's default.
        unsafe { gl.pixel_store_i32(glow::PACK_ROW_LENGTH, 0) };
        read
    }

    /// The colour buffer as RGBA8 bytes in GL's order, bottom row first.
    pub fn read_color_rows(&self, ctx: &GpuContext) -> Result<Vec<u8>, GpuError> {
        let (w, h) = (self.spec.width, self.spec.height);
        let mut data = vec![0u8; (w * h * 4) as usize];
        self.read(ctx, glow::RGBA, glow::UNSIGNED_BYTE, &mut data)?;
        Ok(data)
    }

    /// The colour buffer as RGBA8, top row first.
    pub fn read_color(&self, ctx: &GpuContext) -> Result<image::RgbaImage, GpuError> {
        let (w, h) = (self.spec.width, self.spec.height);
        let data = self.read_color_rows(ctx)?;
        let row = (w * 4) as usize;
        let flipped: Vec<u8> = data.chunks_exact(row).rev().flatten().copied().collect();
        image::RgbaImage::from_raw(w, h, flipped).ok_or(GpuError::Object(
            "colour readback has the wrong length".into(),
        ))
    }

    /// Depth as GL_FLOAT, bottom row first. For D16/D24 this is the stored integer n as
    /// n / (2^bits − 1) (GL 4.6 §8.4.4.2 / Table 8.7 inverse); for D32F the stored float.
    pub fn read_depth_f32(&self, ctx: &GpuContext) -> Result<Vec<f32>, GpuError> {
        let mut bytes = vec![0u8; self.pixel_count() * 4];
        self.read(ctx, glow::DEPTH_COMPONENT, glow::FLOAT, &mut bytes)?;
        Ok(bytes
            .chunks_exact(4)
            .map(|b| f32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
            .collect())
    }

    /// Depth as u8, bottom row first, converted by `rule` (see [`ReadbackRule`]).
    pub fn read_depth_u8(&self, ctx: &GpuContext, rule: ReadbackRule) -> Result<Vec<u8>, GpuError> {
        match rule {
            ReadbackRule::Driver => {
                let mut data = vec![0u8; self.pixel_count()];
                self.read(ctx, glow::DEPTH_COMPONENT, glow::UNSIGNED_BYTE, &mut data)?;
                Ok(data)
            }
            ReadbackRule::Cpu(rule) => Ok(self
                .read_depth_f32(ctx)?
                .into_iter()
                .map(|z| depth_to_u8(z, rule))
                .collect()),
        }
    }

    /// Depth as u16, bottom row first, converted by `rule`.
    pub fn read_depth_u16(
        &self,
        ctx: &GpuContext,
        rule: ReadbackRule,
    ) -> Result<Vec<u16>, GpuError> {
        match rule {
            ReadbackRule::Driver => {
                let mut bytes = vec![0u8; self.pixel_count() * 2];
                self.read(ctx, glow::DEPTH_COMPONENT, glow::UNSIGNED_SHORT, &mut bytes)?;
                Ok(bytes
                    .chunks_exact(2)
                    .map(|b| u16::from_ne_bytes([b[0], b[1]]))
                    .collect())
            }
            ReadbackRule::Cpu(rule) => Ok(self
                .read_depth_f32(ctx)?
                .into_iter()
                .map(|z| depth_to_u16(z, rule))
                .collect()),
        }
    }

    /// Depth as u32, bottom row first, converted by `rule`.
    pub fn read_depth_u32(
        &self,
        ctx: &GpuContext,
        rule: ReadbackRule,
    ) -> Result<Vec<u32>, GpuError> {
        match rule {
            ReadbackRule::Driver => {
                let mut bytes = vec![0u8; self.pixel_count() * 4];
                self.read(ctx, glow::DEPTH_COMPONENT, glow::UNSIGNED_INT, &mut bytes)?;
                Ok(bytes
                    .chunks_exact(4)
                    .map(|b| u32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
                    .collect())
            }
            ReadbackRule::Cpu(rule) => Ok(self
                .read_depth_f32(ctx)?
                .into_iter()
                .map(|z| depth_to_u32(z, rule))
                .collect()),
        }
    }

    /// Depth and stencil packed as GL_UNSIGNED_INT_24_8 (depth in the top 24 bits,
    /// stencil in the low 8), bottom row first.
    pub fn read_depth_stencil_u32(&self, ctx: &GpuContext) -> Result<Vec<u32>, GpuError> {
        if self.stencil_bits == 0 {
            return Err(GpuError::NoStencil);
        }
        let mut bytes = vec![0u8; self.pixel_count() * 4];
        self.read(
            ctx,
            glow::DEPTH_STENCIL,
            glow::UNSIGNED_INT_24_8,
            &mut bytes,
        )?;
        Ok(bytes
            .chunks_exact(4)
            .map(|b| u32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
            .collect())
    }

    /// Stencil indices, bottom row first.
    pub fn read_stencil(&self, ctx: &GpuContext) -> Result<Vec<u8>, GpuError> {
        if self.stencil_bits == 0 {
            return Err(GpuError::NoStencil);
        }
        let mut data = vec![0u8; self.pixel_count()];
        self.read(ctx, glow::STENCIL_INDEX, glow::UNSIGNED_BYTE, &mut data)?;
        Ok(data)
    }

    fn pixel_count(&self) -> usize {
        (self.spec.width * self.spec.height) as usize
    }

    fn read(&self, ctx: &GpuContext, format: u32, ty: u32, out: &mut [u8]) -> Result<(), GpuError> {
        let gl = ctx.gl();
        unsafe {
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, self.framebuffer);
            // The target reads its one colour buffer, whatever a program selected before.
            gl.read_buffer(self.color_buffer);
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            gl.read_pixels(
                0,
                0,
                self.spec.width as i32,
                self.spec.height as i32,
                format,
                ty,
                glow::PixelPackData::Slice(Some(out)),
            );
        }
        ctx.check_error("glReadPixels")
    }
}
