//! One OSMesa context: an EGL surfaceless core 3.3 context running the emulated pipeline,
//! a render target the size of the caller's buffer (an EGL pbuffer, a window-system buffer
//! as Mesa's OSMesa buffer is, where a config has its buffers; a framebuffer object
//! otherwise), and the client state of the C front end (immediate mode, pixel storage, the
//! error flag of calls the model never sees).
//!
//! The image reaches the caller's buffer as Mesa's OSMesa puts it there: on glFinish and
//! glFlush, and when another buffer is made current. The buffer is written in its own
//! format (RGBA, BGRA, ARGB, RGB or BGR bytes), row by row with OSMESA_ROW_LENGTH, the
//! bottom row first unless OSMESA_Y_UP is 0.

use std::collections::{HashMap, HashSet};
use std::ffi::c_void;

use super::cargs::{CArg, CCall, ProgramMemory, CALLER_SLOT};
use super::AbiError;
use crate::ff::api::Entry;
use crate::ff::args::PixelShape;
use crate::ff::framebuffer::FramebufferTarget;
use crate::ff::front::{Client, Reply};
use crate::ff::lists::ListMode;
use crate::ff::pixel_layout;
use crate::ff::queries::{self, ObjectParam, QueryTarget};
use crate::ff::upload_bounds::{pixel_access, CallTime};
use crate::ff::{Command, GlErrorKind};
use crate::gpu::{
    Backend, ColorStorage, ContextRequest, DepthStencilBuffers, GpuContext, PbufferSpec, Profile,
    RasterPlacement, RenderTarget, TargetSpec, ThreadsBefore,
};
use crate::pipeline::emulate::EmulatedPipeline;
use crate::pipeline::queries::QueryFetch;
use crate::pipeline::Pipeline;
use crate::vocab::DepthBits;

/// OSMESA_RGBA, OSMESA_BGRA…: the byte order of the caller's buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorFormat {
    Rgba,
    Bgra,
    Argb,
    Rgb,
    Bgr,
    /// OSMESA_RGB_565: one GLushort per pixel, red in the top 5 bits, with
    /// GL_UNSIGNED_SHORT_5_6_5 only; rendered into an RGB565 colour buffer (RED_BITS 5,
    /// GREEN_BITS 6, no alpha), as Mesa's.
    Rgb565,
}

impl ColorFormat {
    pub const RGBA: u32 = 0x1908;
    pub const BGRA: u32 = 0x1;
    pub const ARGB: u32 = 0x2;
    pub const RGB: u32 = 0x1907;
    pub const BGR: u32 = 0x4;
    pub const RGB_565: u32 = 0x5;

    pub fn from_osmesa(v: u32) -> Option<ColorFormat> {
        Some(match v {
            Self::RGBA => ColorFormat::Rgba,
            Self::BGRA => ColorFormat::Bgra,
            Self::ARGB => ColorFormat::Argb,
            Self::RGB => ColorFormat::Rgb,
            Self::BGR => ColorFormat::Bgr,
            Self::RGB_565 => ColorFormat::Rgb565,
            _ => return None,
        })
    }

    pub fn osmesa(self) -> u32 {
        match self {
            ColorFormat::Rgba => Self::RGBA,
            ColorFormat::Bgra => Self::BGRA,
            ColorFormat::Argb => Self::ARGB,
            ColorFormat::Rgb => Self::RGB,
            ColorFormat::Bgr => Self::BGR,
            ColorFormat::Rgb565 => Self::RGB_565,
        }
    }

    /// Bytes per pixel.
    pub fn bytes(self) -> usize {
        match self {
            ColorFormat::Rgb | ColorFormat::Bgr => 3,
            ColorFormat::Rgb565 => 2,
            _ => 4,
        }
    }

    /// The RGBA components this format stores, in its order.
    fn order(self) -> &'static [usize] {
        match self {
            ColorFormat::Rgba => &[0, 1, 2, 3],
            ColorFormat::Bgra => &[2, 1, 0, 3],
            ColorFormat::Argb => &[3, 0, 1, 2],
            ColorFormat::Rgb => &[0, 1, 2],
            ColorFormat::Bgr => &[2, 1, 0],
            ColorFormat::Rgb565 => &[0, 1, 2],
        }
    }

    /// A row of RGBA pixels of `size`-byte components in this order ([`write`]); byte
    /// rows take a loop per format, the others the general one.
    ///
    /// [`write`]: ColorFormat::write
    fn write_row(self, src: &[u8], dst: &mut [u8], size: usize) {
        let pixels = src.chunks_exact(4);
        match (self, size) {
            (ColorFormat::Rgba, 1) => dst.copy_from_slice(&src[..dst.len()]),
            (ColorFormat::Bgra, 1) => {
                for (s, d) in pixels.zip(dst.chunks_exact_mut(4)) {
                    d.copy_from_slice(&[s[2], s[1], s[0], s[3]]);
                }
            }
            (ColorFormat::Argb, 1) => {
                for (s, d) in pixels.zip(dst.chunks_exact_mut(4)) {
                    d.copy_from_slice(&[s[3], s[0], s[1], s[2]]);
                }
            }
            (ColorFormat::Rgb, 1) => {
                for (s, d) in pixels.zip(dst.chunks_exact_mut(3)) {
                    d.copy_from_slice(&[s[0], s[1], s[2]]);
                }
            }
            (ColorFormat::Bgr, 1) => {
                for (s, d) in pixels.zip(dst.chunks_exact_mut(3)) {
                    d.copy_from_slice(&[s[2], s[1], s[0]]);
                }
            }
            // The RGB565 buffer read as bytes holds v8 = round(v·255/(2ⁿ − 1)) per
            // component; v = round(v8·(2ⁿ − 1)/255) recovers each exactly.
            (ColorFormat::Rgb565, 1) => {
                let bits = |v: u8, max: u16| (u16::from(v) * max + 127) / 255;
                for (s, d) in pixels.zip(dst.chunks_exact_mut(2)) {
                    let packed = bits(s[0], 31) << 11 | bits(s[1], 63) << 5 | bits(s[2], 31);
                    d.copy_from_slice(&packed.to_ne_bytes());
                }
            }
            _ => {
                let bpp = self.bytes() * size;
                for (s, d) in src.chunks_exact(4 * size).zip(dst.chunks_exact_mut(bpp)) {
                    self.write(s, d, size);
                }
            }
        }
    }

    /// An RGBA pixel of `size`-byte components in this order. Mesa's OSMesa orders only
    /// byte components: GL_UNSIGNED_SHORT and GL_FLOAT buffers hold R, G, B (and A) in
    /// that order whatever the format asked (measured, `tests/c/buffer_types.c`: OSMESA_BGRA and
    /// OSMESA_ARGB with GL_FLOAT give RGBA).
    fn write(self, rgba: &[u8], out: &mut [u8], size: usize) {
        let order = match (self, size) {
            (_, 1) => self.order(),
            (ColorFormat::Rgb | ColorFormat::Bgr, _) => &[0, 1, 2],
            _ => &[0, 1, 2, 3],
        };
        for (k, c) in order.iter().enumerate() {
            out[k * size..(k + 1) * size].copy_from_slice(&rgba[c * size..(c + 1) * size]);
        }
    }
}

/// The component type of the caller's buffer (OSMesaMakeCurrent's `type`), as Mesa's
/// OSMesa takes them: each is rendered at its own precision (a GL_FLOAT buffer is an
/// RGBA32F colour buffer, GL_UNSIGNED_SHORT an RGBA16 one; RED_BITS reports 32 or 16).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorType {
    UnsignedByte,
    UnsignedShort,
    Float,
    /// GL_UNSIGNED_SHORT_5_6_5, for OSMESA_RGB_565 only.
    UnsignedShort565,
}

impl ColorType {
    pub fn from_gl(ty: u32) -> Option<ColorType> {
        Some(match ty {
            0x1401 => ColorType::UnsignedByte,
            0x1403 => ColorType::UnsignedShort,
            0x1406 => ColorType::Float,
            0x8363 => ColorType::UnsignedShort565,
            _ => return None,
        })
    }

    fn storage(self) -> ColorStorage {
        match self {
            ColorType::UnsignedByte => ColorStorage::Rgba8,
            ColorType::UnsignedShort => ColorStorage::Rgba16,
            ColorType::Float => ColorStorage::Rgba32F,
            ColorType::UnsignedShort565 => ColorStorage::Rgb565,
        }
    }
}

/// The caller's buffer, as OSMesaMakeCurrent gave it.
#[derive(Clone, Copy, Debug)]
pub struct ClientBuffer {
    pub ptr: *mut c_void,
    pub ty: u32,
    pub width: i32,
    pub height: i32,
}

/// What a call returns to C.
#[derive(Clone, Copy, Debug)]
pub enum Ret {
    None,
    Enum(u32),
    Ptr(*const u8),
}

/// Whether the window holds an image the caller's buffer has not received.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum WindowImage {
    /// Written back (or nothing drawn yet): glFinish leaves the buffer untouched.
    WrittenBack,
    /// Drawn into, cleared or copied to since the last write-back.
    Drawn,
}

impl WindowImage {
    /// After `cmd`: whether it may have changed the image (Mesa marks its front buffer
    /// the same way and writes it to the caller's buffer only then).
    fn after(self, cmd: &Command) -> Self {
        match cmd {
            Command::Draw(_)
            | Command::Clear(_)
            | Command::Bitmap(_)
            | Command::DrawPixels(_)
            | Command::CopyPixels(_)
            | Command::Accum { .. }
            | Command::BlitFramebuffer(_) => WindowImage::Drawn,
            _ => self,
        }
    }
}

pub struct Context {
    // Field order: the pipeline and target hold GL objects of `gpu`, which drops last.
    pipeline: Option<EmulatedPipeline>,
    target: Option<RenderTarget>,
    gpu: GpuContext,
    pub format: ColorFormat,
    depth: DepthBits,
    stencil: bool,
    /// Which of the depth and stencil buffers exist (Mesa's choice, [`Context::new`]).
    buffers: DepthStencilBuffers,
    /// Accumulation bits were asked for: the window has an accumulation buffer of 16 bits
    /// per channel whatever was asked beyond 0 (Mesa's OSMesa measured alike).
    accum: bool,
    pub buffer: Option<ClientBuffer>,
    /// OSMESA_ROW_LENGTH in pixels (0: the buffer's width).
    pub row_length: i32,
    /// OSMESA_Y_UP: row 0 of the buffer is the bottom row. Mesa's default: true.
    pub y_up: bool,
    client: Client,
    made: Vec<Command>,
    /// The image as read back at the last glFinish, kept for the next.
    readback: Vec<u8>,
    /// Whether glFinish, glFlush or a make-current has an image to write back.
    image: WindowImage,
    /// The first error of a call the model never saw (a bad token, a call inside
    /// glBegin/glEnd), kept until glGetError as GL keeps its flag.
    error: Option<GlErrorKind>,
    warned: HashSet<Entry>,
    /// The depth values of OSMesaGetDepthBuffer (empty until the first call), refreshed at
    /// each write-back; its pointer is what the caller holds.
    pub depth_copy: Vec<u8>,
    /// The largest texture name generated or bound: glGenTextures continues after it, as
    /// Mesa's name table does (names grow; deleted ones are not reused).
    texture_max: u32,
    /// The names glGenTextures handed out that glDeleteTextures has not deleted: Mesa makes
    /// a texture object at glGenTextures, which glAreTexturesResident finds before any
    /// bind (glIsTexture, which asks for a target, does not).
    textures_generated: HashSet<u32>,
    /// glPrioritizeTextures of generated names not yet bound, clamped to [0, 1]: Mesa's
    /// object exists from glGenTextures and keeps the priority, which the first bind
    /// (making the model's object) carries over.
    unbound_priorities: HashMap<u32, f32>,
    /// FIXEDFUNC_TRACE is set: each executed command is written to the trace.
    tracing: bool,
    /// The framebuffer and renderbuffer names glGen* handed out.
    generated: super::framebuffers::Generated,
    /// llvmpipe's rasterizer threads for this context, bound one per CPU at the first
    /// write-back (`gpu::raster_threads`).
    rasterizers: Rasterizers,
}

/// Whether a context's rasterizer threads are still to be bound to their CPUs.
#[derive(Debug)]
enum Rasterizers {
    /// Not yet: the threads made after this snapshot are the context's.
    ToBind(ThreadsBefore),
    /// Bound, or left to the kernel (`FIXEDFUNC_RASTER_THREADS=kernel`).
    Placed,
}

/// Swaps the first and third byte of each 4-byte pixel: RGBA ↔ BGRA. On 4-aligned
/// pixels, as native words w: (w & 0xff00ff00) | (w >> 16 & 0xff) | (w & 0xff) << 16 on
/// little-endian, the same with the shifts the other way on big-endian. It runs over the
/// whole image at every write-back (65 536 pixels for 256×256), so it takes AVX2 where the
/// processor has it: the same loop becomes one byte shuffle (`vpshufb`) per eight pixels,
/// against x86-64's baseline SSE2 shifts and masks per four.
fn swap_red_blue(pixels: &mut [u8]) {
    if pixels.as_ptr().align_offset(4) != 0 {
        for p in pixels.chunks_exact_mut(4) {
            p.swap(0, 2);
        }
        return;
    }
    // SAFETY: every bit pattern is a valid u32; the slice starts 4-aligned, so `head` is
    // empty and each word is one pixel.
    let (_, words, tail) = unsafe { pixels.align_to_mut::<u32>() };
    debug_assert!(tail.is_empty() || tail.len() < 4);
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2 (checked just above).
        return unsafe { swap_red_blue_words_avx2(words) };
    }
    swap_red_blue_words(words);
}

#[inline(always)]
fn swap_red_blue_words(words: &mut [u32]) {
    for w in words.iter_mut() {
        let v = *w;
        *w = match cfg!(target_endian = "little") {
            true => (v & 0xff00_ff00) | ((v >> 16) & 0xff) | ((v & 0xff) << 16),
            false => (v & 0x00ff_00ff) | ((v >> 16) & 0xff00) | ((v & 0xff00) << 16),
        };
    }
}

/// The same loop compiled for AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn swap_red_blue_words_avx2(words: &mut [u32]) {
    swap_red_blue_words(words)
}

/// The pbuffer with `spec`'s buffers: 8-bit RGB with 8 alpha bits or none, and depth and
/// stencil buffers an EGL config has (24/8, 24, 16, none). None for the others (16-bit
/// and float colour, RGB565, a stencil buffer without depth, 32-bit float depth).
fn surface_spec(spec: TargetSpec) -> Option<PbufferSpec> {
    let alpha_bits = match spec.color {
        ColorStorage::Rgba8 => 8,
        ColorStorage::Rgb8 => 0,
        _ => return None,
    };
    let (depth_bits, stencil_bits) = match (spec.buffers, spec.depth, spec.stencil) {
        (DepthStencilBuffers::AsNamed, DepthBits::D24, _) => (24, 8),
        (DepthStencilBuffers::AsNamed | DepthStencilBuffers::DepthOnly, DepthBits::D16, false) => {
            (16, 0)
        }
        (DepthStencilBuffers::DepthOnly, DepthBits::D24, _) => (24, 0),
        (DepthStencilBuffers::NoDepth, _, false) => (0, 0),
        _ => return None,
    };
    Some(PbufferSpec {
        width: spec.width,
        height: spec.height,
        alpha_bits,
        depth_bits,
        stencil_bits,
    })
}

/// The largest buffer side (llvmpipe's MAX_TEXTURE_SIZE, which Mesa's OSMesa reports as
/// OSMESA_MAX_WIDTH and OSMESA_MAX_HEIGHT).
pub const MAX_SIZE: i32 = 16384;

impl Context {
    /// A context whose depth and stencil buffers are the ones Mesa's OSMesa makes for
    /// `depth_bits` and `stencil_bits` (its OSMesaCreateContextAttribs, measured alike):
    /// both asked, 24-bit depth with 8 stencil bits; stencil alone, an 8-bit stencil
    /// buffer and no depth buffer; depth 24 or more alone, 24-bit depth; 16 to 23, 16-bit
    /// depth; less, no depth buffer. A missing buffer answers 0 bits and its test always
    /// passes (GL 1.5 §4.1.5, §4.1.6).
    pub fn new(
        format: ColorFormat,
        depth_bits: i32,
        stencil_bits: i32,
        accum_bits: i32,
    ) -> Result<Self, AbiError> {
        let threads_before = ThreadsBefore::now();
        let gpu = GpuContext::new(&ContextRequest::new(Backend::Egl, Profile::Core33))?;
        let rasterizers = match RasterPlacement::from_env() {
            RasterPlacement::OnePerCpu => Rasterizers::ToBind(threads_before),
            RasterPlacement::Kernel => Rasterizers::Placed,
        };
        let stencil = stencil_bits > 0;
        let (depth, buffers) = match depth_bits {
            d if d > 0 && stencil => (DepthBits::D24, DepthStencilBuffers::AsNamed),
            _ if stencil => (DepthBits::D24, DepthStencilBuffers::NoDepth),
            d if d >= 24 => (DepthBits::D24, DepthStencilBuffers::DepthOnly),
            d if d >= 16 => (DepthBits::D16, DepthStencilBuffers::AsNamed),
            _ => (DepthBits::D16, DepthStencilBuffers::NoDepth),
        };
        Ok(Context {
            pipeline: None,
            target: None,
            gpu,
            format,
            depth,
            stencil,
            buffers,
            accum: accum_bits > 0,
            buffer: None,
            row_length: 0,
            y_up: true,
            client: Client::default(),
            made: Vec::new(),
            readback: Vec::new(),
            image: WindowImage::WrittenBack,
            error: None,
            warned: HashSet::new(),
            depth_copy: Vec::new(),
            texture_max: 0,
            textures_generated: HashSet::new(),
            unbound_priorities: HashMap::new(),
            tracing: super::trace::enabled(),
            generated: Default::default(),
            rasterizers,
        })
    }

    pub fn make_gl_current(&self) -> bool {
        self.gpu.make_current().is_ok()
    }

    /// OSMesaMakeCurrent's half after validation: the image so far goes to the old buffer,
    /// and the target follows the new buffer's size. The first call sets the viewport to
    /// the buffer, as GL's initial viewport is the window.
    pub fn bind_buffer(&mut self, buffer: ClientBuffer) -> Result<(), AbiError> {
        self.write_back();
        let (w, h) = (buffer.width as u32, buffer.height as u32);
        let storage = match (
            self.format,
            ColorType::from_gl(buffer.ty).map_or(ColorStorage::Rgba8, ColorType::storage),
        ) {
            // A buffer without alpha: Mesa's has ALPHA_BITS 0 and a destination alpha of 1.
            (ColorFormat::Rgb | ColorFormat::Bgr, ColorStorage::Rgba8) => ColorStorage::Rgb8,
            (ColorFormat::Rgb | ColorFormat::Bgr, ColorStorage::Rgba16) => ColorStorage::Rgb16,
            (ColorFormat::Rgb | ColorFormat::Bgr, ColorStorage::Rgba32F) => ColorStorage::Rgb32F,
            (_, storage) => storage,
        };
        let same = self
            .target
            .as_ref()
            .is_some_and(|t| (t.width(), t.height()) == (w, h) && t.spec().color == storage);
        if !same {
            if let Some(old) = self.target.take() {
                old.delete(&self.gpu);
            }
            let mut spec = TargetSpec::new(w, h, self.depth)
                .with_color(storage)
                .with_buffers(self.buffers);
            if self.stencil {
                spec = spec.with_stencil();
            }
            let target = self.make_target(spec)?;
            target.bind(&self.gpu);
            // A new buffer's stencil is undefined: made 0, so that clears of depth alone
            // can take the stencil along (`pipeline::emulate::stencil_contents`).
            let stencil = target.stencil_bits() > 0;
            if stencil {
                target.clear_stencil(&self.gpu);
            }
            let (framebuffer, color_buffer) = (target.framebuffer(), target.color_buffer());
            self.target = Some(target);
            match &mut self.pipeline {
                None => self.pipeline = Some(EmulatedPipeline::new(&self.gpu)?),
                Some(p) => {
                    p.forget_sent_state();
                    p.set_window_framebuffer(&self.gpu, framebuffer, color_buffer);
                }
            }
            if let (Some(p), true) = (self.pipeline.as_mut(), stencil) {
                p.window_stencil_zeroed();
            }
            if let Some(p) = &mut self.pipeline {
                p.set_accum_buffer(self.accum.then_some((w as usize, h as usize)));
            }
        }
        self.buffer = Some(buffer);
        if self.tracing {
            super::trace::buffer(buffer.width, buffer.height, self.accum);
        }
        Ok(())
    }

    /// The target of a buffer: a pbuffer surface where one has exactly the buffers of
    /// `spec`, else a framebuffer object. A pbuffer's framebuffer is a window-system one,
    /// as Mesa's OSMesa buffer is: Mesa rasterises both upside down in memory, and where a
    /// line's end lies on a pixel centre or corner, which pixel it lights depends on that
    /// orientation (`tests/c/line_ends.c`).
    fn make_target(&self, spec: TargetSpec) -> Result<RenderTarget, AbiError> {
        if let Some(surface) = surface_spec(spec) {
            if self.gpu.bind_window_surface(surface)? {
                return Ok(RenderTarget::surface(&self.gpu, spec)?);
            }
        }
        self.gpu.release_window_surface()?;
        Ok(RenderTarget::new(&self.gpu, spec)?)
    }

    /// Releases the GL objects (the context must be current).
    pub fn release(&mut self) {
        if self.tracing {
            super::trace::flush();
        }
        if let Some(mut p) = self.pipeline.take() {
            p.release(&self.gpu);
        }
        if let Some(t) = self.target.take() {
            t.delete(&self.gpu);
        }
    }

    pub fn record_error(&mut self, kind: GlErrorKind) {
        let model_pending = self
            .pipeline
            .as_ref()
            .is_some_and(|p| p.state().error().is_some());
        if self.error.is_none() && !model_pending {
            self.error = Some(kind);
        }
    }

    /// glGetError: the first error since the last call, from the C front end or the model.
    fn take_error(&mut self) -> u32 {
        let kind = self
            .error
            .take()
            .or_else(|| self.pipeline.as_mut()?.take_gl_error().map(|e| e.kind));
        kind.map_or(0, error_code)
    }

    /// One GL call from C.
    pub fn call(&mut self, entry: Entry, args: &[CArg]) -> Ret {
        if self.pipeline.is_none() {
            // No buffer made current yet: GL calls have no context to act on.
            return Ret::None;
        }
        let inside = self.client.immediate.is_open() && entry.attrib_call().is_none();
        if !inside && self.client.lists.compiling().is_none() && crate::ff::calls::direct(entry) {
            return self.direct(entry, args);
        }
        match entry {
            Entry::GetError if !inside => return Ret::Enum(self.take_error()),
            Entry::Finish | Entry::Flush if !inside => {
                self.write_back();
                return Ret::None;
            }
            Entry::GetString if !inside => {
                return match super::strings::get(args, &self.gpu) {
                    Some(p) => Ret::Ptr(p),
                    None => {
                        self.record_error(GlErrorKind::InvalidEnum);
                        Ret::Ptr(std::ptr::null())
                    }
                };
            }
            Entry::GenTextures if !inside => {
                self.gen_textures(args);
                return Ret::None;
            }
            Entry::DeleteTextures if !inside => {
                for name in names_at(args) {
                    self.textures_generated.remove(&name);
                    self.unbound_priorities.remove(&name);
                }
            }
            // A list being compiled only (not executed) keeps the call for later.
            Entry::PrioritizeTextures
                if !inside && self.client.lists.compiling() != Some(ListMode::Compile) =>
            {
                self.prioritize_unbound(args)
            }
            Entry::AreTexturesResident if !inside => {
                // Mesa answers FALSE, with no error, when either array is NULL (after the
                // n < 0 check), before it looks at any name.
                let count_ok = matches!(args.first(), Some(CArg::Int(n)) if *n >= 0);
                let null_at =
                    |i: usize| matches!(args.get(i), Some(CArg::Ptr(p, _)) if p.is_null());
                if count_ok && (null_at(1) || null_at(2)) {
                    return Ret::Enum(0);
                }
                // Every name a texture object, generated or bound: all resident (TRUE, the
                // residences untouched). Otherwise the model's check gives the error.
                let state = self.pipeline.as_ref().map(|p| p.state());
                let names = names_at(args);
                let known = |n: &u32| {
                    *n != 0
                        && (self.textures_generated.contains(n)
                            || state.is_some_and(|s| s.textures.contains_key(n)))
                };
                if matches!(args.first(), Some(CArg::Int(n)) if *n >= 0) && names.iter().all(known)
                {
                    return Ret::Enum(1);
                }
            }
            _ if super::framebuffers::handles(entry) && !inside => {
                let Some(p) = self.pipeline.as_ref() else {
                    return Ret::None;
                };
                return match super::framebuffers::answer(
                    entry,
                    args,
                    p.state(),
                    &mut self.generated,
                ) {
                    Ok(v) => Ret::Enum(v),
                    Err(kind) => {
                        self.record_error(kind);
                        Ret::Enum(0)
                    }
                };
            }
            _ if super::framebuffers::handles(entry) => {
                self.record_error(GlErrorKind::InvalidOperation);
                return Ret::Enum(0);
            }
            _ => {}
        }
        let Some(p) = self.pipeline.as_ref() else {
            return Ret::None;
        };
        let mut c = CCall::new(entry, args, self.client.pixel_store.unpack);
        let when = match self.client.lists.compiling() {
            Some(_) => CallTime::Compiled,
            None => CallTime::Now,
        };
        c.access = pixel_access(&c, p.state(), when);
        let mut made = std::mem::take(&mut self.made);
        let outcome = self.client.call(&c, p.state(), &ProgramMemory, &mut made);
        let reply = outcome.as_ref().cloned().unwrap_or(Reply::None);
        if let Err(kind) = outcome {
            if c.was_unsupported() && self.warned.insert(entry) {
                eprintln!(
                    "fixedfunc: {entry} is not implemented by this layer; it records \
                     GL_INVALID_OPERATION and does nothing"
                );
            }
            self.record_error(kind);
        }
        for cmd in made.drain(..) {
            self.execute(&cmd);
        }
        self.made = made;
        match entry {
            Entry::ReadPixels => {
                let inside = self.read_inside(args);
                self.copy_pixels_out(args.get(6), inside)
            }
            Entry::GetTexImage => self.copy_pixels_out(args.get(4), None),
            _ => {}
        }
        match reply {
            Reply::QueryObject {
                id,
                param,
                target,
                signed,
            } => {
                self.query_object_out(args.get(2), id, param, target, signed);
                Ret::None
            }
            Reply::None => Ret::Enum(0),
            Reply::Value(v) => Ret::Enum(v),
            Reply::Address(a) => Ret::Ptr(a as *const u8),
            Reply::Write { arg, bytes } => {
                if let Some(CArg::Ptr(dst, _)) = args.get(arg).copied() {
                    // The stipple is packed as a 32×32 bitmap (§6.1.7).
                    if entry == Entry::GetPolygonStipple && !dst.is_null() {
                        self.pack_out(dst, &bytes, PixelShape::bitmap(32, 32));
                    } else if !dst.is_null() {
                        // SAFETY: the program's array holds what the call stores (n names,
                        // one integer, `size` bytes), as GL requires of it.
                        unsafe {
                            std::ptr::copy_nonoverlapping(
                                bytes.as_ptr(),
                                dst.cast::<u8>().cast_mut(),
                                bytes.len(),
                            );
                        }
                    }
                }
                Ret::None
            }
        }
    }

    /// A call of [`calls::direct`](crate::ff::calls::direct) with no pair open and no list
    /// being compiled: its Command, or its error, as the front end would give them.
    fn direct(&mut self, entry: Entry, args: &[CArg]) -> Ret {
        let c = CCall::new(entry, args, self.client.pixel_store.unpack);
        match crate::ff::calls::command(&c) {
            Ok(cmd) => self.execute(&cmd),
            Err(kind) => self.record_error(kind),
        }
        Ret::Enum(0)
    }

    /// A vertex attribute inside glBegin/glEnd, straight to the open pair
    /// (`vertex_calls`); `false` when the call takes the general path. Inside the pair an
    /// attribute or a vertex yields no command.
    #[inline]
    pub fn attribute_in_pair(&mut self, entry: Entry, args: &[CArg]) -> bool {
        super::vertex_calls::in_pair(&mut self.client, entry, args)
    }

    /// A command, and after a glBindTexture that makes a generated name's object the
    /// priority glPrioritizeTextures gave it before (`prioritize_unbound`).
    fn execute(&mut self, cmd: &Command) {
        self.execute_one(cmd);
        if let Command::BindTexture { name, .. } = cmd {
            if let Some(priority) = self.unbound_priorities.remove(name) {
                self.execute_one(&Command::PrioritizeTextures(vec![(*name, priority)]));
            }
        }
    }

    fn execute_one(&mut self, cmd: &Command) {
        let Some(p) = self.pipeline.as_mut() else {
            return;
        };
        if self.tracing {
            super::trace::command(cmd, self.client.pixel_store);
        }
        if let Command::BindTexture { name, .. } = cmd {
            self.texture_max = self.texture_max.max(*name);
        }
        self.image = self.image.after(cmd);
        if let Err(e) = p.execute(&self.gpu, std::slice::from_ref(cmd)) {
            eprintln!("fixedfunc: {}: {e}", cmd.entry());
            self.record_error(GlErrorKind::InvalidOperation);
        }
        // The flag keeps the first error only: one the C front end recorded earlier wins
        // over any the model raised since.
        if self.error.is_some() {
            if let Some(p) = self.pipeline.as_mut() {
                let _ = p.take_gl_error();
            }
        }
    }

    /// glPrioritizeTextures(n, names, priorities) of names glGenTextures gave and no bind
    /// has made objects yet: kept, clamped to [0, 1] (GL 1.5 §3.8.12), for the first bind.
    /// Names never generated are left out, as Mesa finds no object for them; those that
    /// are objects take the model's command.
    fn prioritize_unbound(&mut self, args: &[CArg]) {
        let Some(CArg::Ptr(priorities, _)) = args.get(2).copied() else {
            return;
        };
        if priorities.is_null() {
            return;
        }
        let state = self.pipeline.as_ref().map(|p| p.state());
        for (k, name) in names_at(args).into_iter().enumerate() {
            let object = state.is_some_and(|s| s.textures.contains_key(&name));
            if self.textures_generated.contains(&name) && !object {
                // SAFETY: the program's array holds n priorities (the call's contract).
                let p = unsafe { priorities.cast::<f32>().add(k).read_unaligned() };
                self.unbound_priorities.insert(name, p.clamp(0.0, 1.0));
            }
        }
    }

    /// glGenTextures(n, names): n names after the largest in use; n < 0 is INVALID_VALUE.
    fn gen_textures(&mut self, args: &[CArg]) {
        let (Some(CArg::Int(n)), Some(CArg::Ptr(dst, _))) = (args.first(), args.get(1)) else {
            return;
        };
        if *n < 0 {
            return self.record_error(GlErrorKind::InvalidValue);
        }
        if dst.is_null() {
            return;
        }
        for k in 0..*n as usize {
            self.texture_max = self.texture_max.saturating_add(1);
            self.textures_generated.insert(self.texture_max);
            // SAFETY: the program's array holds n names (glGenTextures' contract).
            unsafe {
                dst.cast::<u32>()
                    .cast_mut()
                    .add(k)
                    .write_unaligned(self.texture_max)
            };
        }
    }

    /// The part of a glReadPixels rectangle (x, y, width, height) inside the read
    /// framebuffer (the window, or the object bound for reading), when the rectangle
    /// reaches beyond it, as (first column, first row, columns, rows) of the rectangle:
    /// Mesa clips the read to the buffer (`_mesa_clip_readpixels`) and writes nothing of
    /// the pixels outside, which keep what the program's memory held (GL leaves them
    /// undefined). None: the whole rectangle is written.
    fn read_inside(&self, args: &[CArg]) -> Option<[usize; 4]> {
        let state = self.pipeline.as_ref()?.state();
        let (fw, fh) = match state.framebuffers.read {
            0 => {
                let target = self.target.as_ref()?;
                (i64::from(target.width()), i64::from(target.height()))
            }
            _ => {
                let (w, h) = state.framebuffer_size(FramebufferTarget::Read)?;
                (i64::from(w), i64::from(h))
            }
        };
        let int = |i: usize| match args.get(i) {
            Some(CArg::Int(v)) => Some(*v),
            _ => None,
        };
        let (x, y, w, h) = (int(0)?, int(1)?, int(2)?, int(3)?);
        if w <= 0 || h <= 0 {
            return None;
        }
        let (x0, y0) = ((-x).max(0).min(w), (-y).max(0).min(h));
        let (x1, y1) = ((fw - x).clamp(x0, w), (fh - y).clamp(y0, h));
        if (x0, y0, x1, y1) == (0, 0, w, h) {
            return None;
        }
        let u = |v: i64| usize::try_from(v).unwrap_or(0);
        Some([u(x0), u(y0), u(x1 - x0), u(y1 - y0)])
    }

    /// glReadPixels and glGetTexImage into the caller's memory: the bytes the pipeline
    /// read, rows padded to GL_PACK_ALIGNMENT. A call that failed, or a glGetTexImage of a
    /// level never specified, stored nothing and leaves the memory alone.
    fn copy_pixels_out(&mut self, dst: Option<&CArg>, inside: Option<[usize; 4]>) {
        let Some(CArg::Ptr(dst, _)) = dst.copied() else {
            return;
        };
        let Some(r) = self
            .pipeline
            .as_mut()
            .and_then(|p| p.take_readback(CALLER_SLOT))
        else {
            return;
        };
        if dst.is_null() {
            return;
        }
        let width = i32::try_from(r.width).unwrap_or(i32::MAX);
        let shape = PixelShape::groups(width, 0, r.format, r.ty);
        let row = shape.group_bytes() * r.width as usize;
        let height = r.bytes.len().checked_div(row).unwrap_or(0);
        let shape = match r.depth {
            // A 3D level: its images, laid out by PACK_IMAGE_HEIGHT and PACK_SKIP_IMAGES.
            Some(depth) => PixelShape {
                height: i32::try_from(r.height).unwrap_or(i32::MAX),
                depth: Some(i32::try_from(depth).unwrap_or(i32::MAX)),
                ..shape
            },
            None => PixelShape {
                height: i32::try_from(height).unwrap_or(i32::MAX),
                ..shape
            },
        };
        match inside {
            Some(part) if r.depth.is_none() => self.pack_part_out(dst, &r.bytes, shape, part),
            _ => self.pack_out(dst, &r.bytes, shape),
        }
    }

    /// The columns and rows `part` (first column, first row, columns, rows) of a read
    /// rectangle of `shape`, tightly packed in `bytes`, into the program's memory where
    /// the whole rectangle's pack layout puts them; nothing else is written.
    fn pack_part_out(&self, dst: *const c_void, bytes: &[u8], shape: PixelShape, part: [usize; 4]) {
        let [x0, y0, w, h] = part;
        if w == 0 || h == 0 {
            return;
        }
        let group = shape.group_bytes();
        let row = group * usize::try_from(shape.width).unwrap_or(0);
        let tight: Vec<u8> = bytes
            .chunks_exact(row.max(1))
            .skip(y0)
            .take(h)
            .flat_map(|r| r[x0 * group..(x0 + w) * group].iter().copied())
            .collect();
        let mut p = self.client.pixel_store.pack;
        if p.row_length == 0 {
            p.row_length = usize::try_from(shape.width).unwrap_or(0);
        }
        p.skip_pixels += x0;
        p.skip_rows += y0;
        let part_shape = PixelShape {
            width: i32::try_from(w).unwrap_or(i32::MAX),
            height: i32::try_from(h).unwrap_or(i32::MAX),
            ..shape
        };
        let extent = pixel_layout::layout(part_shape, &p).extent;
        // SAFETY: the part's rows lie inside the whole rectangle's, which the program's
        // buffer holds under its pack parameters (GL's contract for glReadPixels).
        let out = unsafe { std::slice::from_raw_parts_mut(dst.cast::<u8>().cast_mut(), extent) };
        pixel_layout::pack(&tight, out, part_shape, &p);
    }

    /// glGetQueryObject{i,ui}v: what the pipeline counted for query `id`, stored through
    /// the program's pointer (GL 1.5 §6.1.12: QUERY_RESULT waits for the count).
    fn query_object_out(
        &mut self,
        dst: Option<&CArg>,
        id: u32,
        param: ObjectParam,
        target: QueryTarget,
        signed: bool,
    ) {
        let Some(CArg::Ptr(dst, _)) = dst.copied() else {
            return;
        };
        let fetched = match (param, self.pipeline.as_mut()) {
            (ObjectParam::Target, _) | (_, None) => 0,
            (ObjectParam::Result, Some(p)) => p
                .query_result(&self.gpu, id, QueryFetch::Result)
                .unwrap_or(0),
            (ObjectParam::ResultAvailable, Some(p)) => p
                .query_result(&self.gpu, id, QueryFetch::Available)
                .unwrap_or(0),
        };
        if dst.is_null() {
            return;
        }
        let v = queries::object_value(param, target, fetched, signed);
        // SAFETY: the program's pointer holds one GLint or GLuint (glGetQueryObject's
        // contract).
        unsafe { dst.cast::<u32>().cast_mut().write_unaligned(v) };
    }

    /// Tight rows `bytes` of `shape` into the caller's memory at `dst`, laid out by the
    /// pack parameters (GL 1.5 §4.3.2, `pixel_layout`).
    fn pack_out(&self, dst: *const c_void, bytes: &[u8], shape: PixelShape) {
        let p = self.client.pixel_store.pack;
        let extent = pixel_layout::layout(shape, &p).extent;
        // SAFETY: the program's buffer holds the rows the pack parameters place (up to the
        // last row's last byte), as GL requires of the memory a pixel call writes.
        let out = unsafe { std::slice::from_raw_parts_mut(dst.cast::<u8>().cast_mut(), extent) };
        pixel_layout::pack(bytes, out, shape, &p);
    }

    /// The image so far into the caller's buffer (and the trace to its file), when
    /// something was drawn since the last write-back: as on Mesa, a glFinish with nothing
    /// drawn leaves whatever the caller put in the buffer.
    pub fn write_back(&mut self) {
        if self.tracing {
            super::trace::flush();
        }
        if self.image == WindowImage::WrittenBack {
            return;
        }
        let (Some(target), Some(buffer)) = (&self.target, self.buffer) else {
            return;
        };
        self.image = WindowImage::WrittenBack;
        // Every rasterizer thread has run (and named itself) by the first frame's end.
        if let Rasterizers::ToBind(before) = &self.rasterizers {
            before.bind_new_rasterizers();
            self.rasterizers = Rasterizers::Placed;
        }
        let (w, h) = (buffer.width as usize, buffer.height as usize);
        let row_pixels = if self.row_length > 0 {
            self.row_length as usize
        } else {
            w
        };
        let storage = target.spec().color;
        // A buffer with GL's layout — bytes of RGBA or BGRA order, rows bottom first
        // (OSMESA_Y_UP, the default), ROW_LENGTH as PACK_ROW_LENGTH — is filled by
        // glReadPixels itself, in the colour buffer's own byte order (one copy, 256 KiB a
        // frame for 256×256), red and blue then swapped in place where the buffer's order
        // is the other. Any other is read into `readback` and reordered.
        let direct = matches!(self.format, ColorFormat::Rgba | ColorFormat::Bgra)
            && storage == ColorStorage::Rgba8
            && self.y_up
            && w > 0
            && h > 0;
        let mut rows = std::mem::take(&mut self.readback);
        let read = match direct {
            true => {
                let len = ((h - 1) * row_pixels + w) * 4;
                // SAFETY: the caller's buffer holds height rows of ROW_LENGTH pixels of 4
                // bytes (OSMesaMakeCurrent's contract); the read writes the first `width`
                // of each.
                let out = unsafe { std::slice::from_raw_parts_mut(buffer.ptr.cast::<u8>(), len) };
                let order = target.byte_order();
                let read = target.read_color_bytes_into_rows(&self.gpu, order, row_pixels, out);
                let wanted = match self.format {
                    ColorFormat::Bgra => glow::BGRA,
                    _ => glow::RGBA,
                };
                if read.is_ok() && order != wanted {
                    for row in out.chunks_mut(row_pixels * 4) {
                        swap_red_blue(&mut row[..w * 4]);
                    }
                }
                read
            }
            false => target.read_color_stored_into(&self.gpu, &mut rows),
        };
        // The read bound the target: the pipeline binds the program's framebuffers again.
        if let Some(p) = self.pipeline.as_mut() {
            p.forget_bound_framebuffers();
        }
        if let Err(e) = &read {
            eprintln!("fixedfunc: reading the image back failed: {e}");
        }
        if read.is_ok() && !direct {
            let size = storage.component_bytes();
            let bpp = self.format.bytes() * size;
            // `rows` is GL's order, row y from the bottom; Y_UP keeps that order.
            for (y, src) in rows.chunks_exact(w * 4 * size).enumerate().take(h) {
                let dst_row = if self.y_up { y } else { h - 1 - y };
                // SAFETY: the caller's buffer holds height rows of ROW_LENGTH pixels in its
                // format (OSMesaMakeCurrent's contract).
                let dst = unsafe {
                    std::slice::from_raw_parts_mut(
                        buffer.ptr.cast::<u8>().add(dst_row * row_pixels * bpp),
                        w * bpp,
                    )
                };
                self.format.write_row(src, dst, size);
            }
        }
        self.readback = rows;
        if !self.depth_copy.is_empty() {
            self.refresh_depth_copy();
        }
    }

    /// OSMesaGetDepthBuffer: (width, height, bytes per value) of the depth buffer, whose
    /// values `depth_copy` holds as Mesa's OSMesa lays them out: 2 bytes for 16-bit depth,
    /// 4 for 24-bit with the depth in the low 24 bits and the stencil in the top byte
    /// (Z24_UNORM_S8_UINT, or Z24X8 without stencil). As Mesa's, the copy is made at the
    /// first call and refreshed at each write-back of the image, so the pointer stays the
    /// same; `None` without a depth buffer.
    pub fn read_depth(&mut self) -> Option<(i32, i32, i32)> {
        if self.buffers == DepthStencilBuffers::NoDepth {
            return None;
        }
        let target = self.target.as_ref()?;
        let (w, h) = (target.width() as i32, target.height() as i32);
        let per = if self.depth == DepthBits::D16 { 2 } else { 4 };
        if self.depth_copy.is_empty() {
            self.refresh_depth_copy();
        }
        Some((w, h, per))
    }

    /// Reads the depth buffer into `depth_copy` in place (a new allocation only when its
    /// size changed).
    fn refresh_depth_copy(&mut self) {
        let Some(target) = self.target.as_ref() else {
            return;
        };
        let rule = crate::vocab::ReadbackRule::Driver;
        let bytes: Option<Vec<u8>> = match (self.depth, self.buffers) {
            (_, DepthStencilBuffers::NoDepth) => None,
            (DepthBits::D16, _) => target
                .read_depth_u16(&self.gpu, rule)
                .ok()
                .map(|v| v.iter().flat_map(|x| x.to_ne_bytes()).collect()),
            // GL packs 24_8 as depth << 8 | stencil; Mesa's buffer holds stencil << 24 | depth:
            // a rotation right by 8 bits.
            (_, DepthStencilBuffers::AsNamed) => {
                target.read_depth_stencil_u32(&self.gpu).ok().map(|v| {
                    v.iter()
                        .flat_map(|x| x.rotate_right(8).to_ne_bytes())
                        .collect()
                })
            }
            // A 32-bit read holds the 24 bits in its top bits.
            (_, DepthStencilBuffers::DepthOnly) => target
                .read_depth_u32(&self.gpu, rule)
                .ok()
                .map(|v| v.iter().flat_map(|x| (x >> 8).to_ne_bytes()).collect()),
        };
        if let Some(bytes) = bytes {
            if self.depth_copy.len() == bytes.len() {
                self.depth_copy.copy_from_slice(&bytes);
            } else {
                self.depth_copy = bytes;
            }
        }
        // The read bound the target: the pipeline binds the program's framebuffers again.
        if let Some(p) = self.pipeline.as_mut() {
            p.forget_bound_framebuffers();
        }
    }
}

/// The GLenum glGetError returns for a kind.
pub fn error_code(kind: GlErrorKind) -> u32 {
    kind.code()
}

/// The `n` texture names of a glDeleteTextures or glAreTexturesResident call (arguments
/// n, names); none for a negative n or a NULL array.
fn names_at(args: &[CArg]) -> Vec<u32> {
    let (Some(CArg::Int(n)), Some(CArg::Ptr(names, _))) = (args.first(), args.get(1)) else {
        return Vec::new();
    };
    let Ok(n) = usize::try_from(*n) else {
        return Vec::new();
    };
    if names.is_null() {
        return Vec::new();
    }
    // SAFETY: the program's array holds n names (the calls' contract).
    (0..n)
        .map(|k| unsafe { names.cast::<u32>().add(k).read_unaligned() })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::swap_red_blue;

    /// Every length and start (aligned or not, shorter and longer than one AVX2 step)
    /// swaps bytes 0 and 2 of each pixel and nothing else.
    #[test]
    fn red_and_blue_swap_in_every_pixel_at_every_length_and_alignment() {
        let bytes: Vec<u8> = (0..4 * 300 + 1).map(|i| (i * 7 + 3) as u8).collect();
        for start in 0..4 {
            for pixels in [0usize, 1, 7, 8, 9, 31, 32, 33, 257, 299] {
                let mut got = bytes[start..start + 4 * pixels].to_vec();
                let mut all = bytes.clone();
                let region = &mut all[start..start + 4 * pixels];
                swap_red_blue(region);
                got.chunks_exact_mut(4).for_each(|p| p.swap(0, 2));
                assert_eq!(region, &got[..], "start {start}, {pixels} pixels");
            }
        }
    }
}
