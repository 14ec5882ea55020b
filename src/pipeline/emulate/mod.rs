//! The emulated path: `FixedState` → `ShaderKey` → generated GLSL → a program cached by key,
//! on a core 3.3 context. Each Command is folded into the model state first (GL's error
//! semantics live there); a Draw then derives the key, looks the program up (compiling only
//! keys never seen), uploads the uniforms from the state, binds the enabled units'
//! textures, syncs the raster state through its shadow copy and draws. A draw of the
//! geometry just drawn, after nothing but matrix commands, repeats that draw's program and
//! pass with its transform uniforms sent anew (`repeat`).
//!
//! Two precisions (`ff::precision`): `Float` (the default) follows Mesa's native path —
//! fp32 stages clamped per stage, the alpha test on unorm8 values rounded half to even;
//! `Fixed8` computes the stages on 8-bit integers and the register combiners on 9-bit
//! signed values, as the era's hardware did.

pub mod accum;
pub mod assembly;
pub mod cache;
pub mod conv;
pub mod dashes;
pub mod draw;
pub mod glsl;
pub mod key;
pub mod line_stipple;
pub mod outline_dashes;
pub mod pixel_fan;
pub mod pixels;
pub mod polygon;
pub mod program;
pub mod repeat;
pub mod shadergen;
pub mod shared_vertices;
pub mod stencil_contents;
pub mod stipple_dashes;
pub mod sync;
pub mod texel_store;
pub mod texture_calls;
pub mod textures;
pub mod uniforms;
pub mod user_program;
pub mod vertex_layout;

use std::rc::Rc;
use std::sync::Arc;

use glow::HasContext;

use self::cache::ProgramCache;
use self::draw::{GeometryCache, Winding};
use self::key::{PointCut, PointKey, PositionSource, ShaderKey, SpriteKey};
use self::pixel_fan::RowOrder;
use self::program::Program;
use self::stencil_contents::StencilContents;
use self::sync::{CoreCalls, RasterSync};
use self::textures::Textures;
use super::core::{Core, Issue, PathPipeline};
use super::framebuffers::FramebufferMirror;
use super::{Counters, PipelineError, Readback};
use crate::ff::pixel_types::{Packer, ReadFrom};
use crate::ff::texture_calls::GetTexImage;
use crate::ff::{
    pixel_types, Command, FixedState, Geometry, PixelFormat, PixelType, ReadPixels, TextureTarget,
};
use crate::gpu::{GpuContext, Profile};
use crate::vocab::{PipelineKind, Precision};

/// What a draw pass sends: an uploaded (cached) geometry, or the dashes of a stippled
/// line draw.
enum Drawn<'a> {
    Geometry(&'a Arc<Geometry>),
    Dashes(&'a Geometry, &'a [line_stipple::Dash]),
}

/// Whether a draw syncs the raster state first.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Raster {
    Sync,
    /// GL holds this draw's raster state already: a repeated draw (`repeat`), after which
    /// no command that changes raster state has run.
    AsSent,
}

/// The emulated path's half of execution: programs, uploaded geometry and textures, and
/// the shadow copy of the raster state GL has.
pub struct Emulate {
    programs: ProgramCache<ShaderKey, Program>,
    geometry: GeometryCache,
    textures: Textures,
    raster: RasterSync,
    precision: Precision,
    framebuffers: FramebufferMirror,
    /// The bound target's size (the viewport GL starts with): pixel rectangles drawn into
    /// the window take it as the viewport (`pixels`).
    target: crate::ff::Viewport,
    /// The texture holding the last pixel rectangle's image (`pixels`).
    pixel_image: Option<glow::Texture>,
    /// The window's accumulation buffer, when it has one (`accum`).
    accum: Option<crate::ff::accum::AccumBuffer>,
    /// The generic attribute values last sent (`draw::SentAttribs`).
    sent: draw::SentAttribs,
    /// The window is GL's framebuffer 0, a window-system buffer Mesa stores top row first
    /// (a framebuffer object stores GL's bottom row first): triangles drawn into it keep
    /// their corners (`draw::Winding`).
    window_top_row_first: bool,
    /// A plan's own programs and the one in use (`user_program`).
    user: user_program::UserPrograms,
    /// The last plain draw, which the next draw of its geometry repeats while only the
    /// modelview and projection matrices change (`repeat`).
    memo: Option<repeat::DrawMemo>,
    /// How many draws repeated the memo's.
    repeated: u64,
    /// What the window's stencil buffer holds (`stencil_contents`).
    window_stencil: StencilContents,
}

/// Commands executed by generated programs on a core 3.3 context.
pub type EmulatedPipeline = PathPipeline<Emulate>;

impl EmulatedPipeline {
    /// A pipeline on a core-profile context. The model's viewport starts as the GL viewport
    /// current now (GL's initial viewport is the window; here, the bound target).
    pub fn new(ctx: &GpuContext) -> Result<EmulatedPipeline, PipelineError> {
        if ctx.profile() != Profile::Core33 {
            return Err(PipelineError::WrongProfile {
                path: "emulated",
                needs: Profile::Core33.name(),
                got: ctx.profile().name(),
            });
        }
        let core = Core::for_bound_target(ctx);
        let target = core.state.viewport;
        let window_top_row_first =
            unsafe { ctx.gl().get_parameter_i32(glow::DRAW_FRAMEBUFFER_BINDING) } == 0;
        let path = Emulate {
            window_top_row_first,
            target,
            pixel_image: None,
            accum: None,
            sent: draw::SentAttribs::default(),
            user: user_program::UserPrograms::default(),
            programs: ProgramCache::default(),
            geometry: GeometryCache::default(),
            textures: Textures::default(),
            raster: RasterSync::new(CoreCalls::load(ctx)),
            precision: Precision::Float,
            framebuffers: FramebufferMirror::new(true),
            memo: None,
            repeated: 0,
            window_stencil: StencilContents::Unknown,
        };
        Ok(PathPipeline::from_parts(core, path))
    }

    /// The same pipeline computing its stages in `precision` (`ff::precision`).
    pub fn with_precision(mut self, precision: Precision) -> Self {
        self.path.precision = precision;
        self.path.memo = None;
        self
    }

    /// Forgets the raster state last sent, so the next draw sends all of it: for a caller
    /// that changed GL state behind the pipeline (bound another target).
    pub fn forget_sent_state(&mut self) {
        self.path.raster.invalidate();
        // A repeated draw does not sync the raster state (`repeat`).
        self.path.memo = None;
        self.forget_bound_framebuffers();
    }

    /// Forgets only the framebuffers last bound: for a caller that bound another to read
    /// from it (glReadPixels changes the read binding, the read buffer and the pack
    /// alignment, none of them raster state, and every read of the pipeline sets its own
    /// pack alignment).
    pub fn forget_bound_framebuffers(&mut self) {
        self.path.framebuffers.invalidate();
    }

    /// The window's stencil buffer holds 0 everywhere: a caller cleared it so
    /// (`RenderTarget::clear_stencil`), for a new window (`stencil_contents`).
    pub fn window_stencil_zeroed(&mut self) {
        self.path.window_stencil = StencilContents::Uniform(0);
    }

    /// The framebuffer that stands for the window (framebuffer 0) from now on, and its
    /// colour buffer: for a caller that replaced its render target, bound now. RED_BITS …
    /// STENCIL_BITS follow its buffers.
    pub fn set_window_framebuffer(
        &mut self,
        ctx: &GpuContext,
        window: Option<glow::Framebuffer>,
        color_buffer: u32,
    ) {
        self.path.framebuffers.set_window(window, color_buffer);
        self.path.window_top_row_first = window.is_none();
        self.path.memo = None;
        self.core.state.framebuffers.window_bits =
            crate::pipeline::framebuffers::bound_bits(ctx.gl());
    }

    /// Gives the window an accumulation buffer of `size` (zeroed; kept when the size is
    /// unchanged), or none: ACCUM_RED_BITS … follow (`ff::accum::ACCUM_BITS` or 0).
    pub fn set_accum_buffer(&mut self, size: Option<(usize, usize)>) {
        use crate::ff::accum::{AccumBuffer, ACCUM_BITS};
        self.path.memo = None;
        self.path.accum = match (self.path.accum.take(), size) {
            (Some(b), Some(s)) if b.size() == s => Some(b),
            (_, Some((w, h))) => Some(AccumBuffer::new(w, h)),
            (_, None) => None,
        };
        self.core.state.framebuffers.window_accum_bits = match size {
            Some(_) => ACCUM_BITS,
            None => 0,
        };
    }

    /// How many geometries are uploaded (each kept while something else holds it).
    pub fn uploaded_geometries(&self) -> usize {
        self.path.geometry.uploaded()
    }

    /// The key the next draw would use (for `fixedfunc shaders` and tests).
    pub fn current_key(&self) -> ShaderKey {
        ShaderKey::from_state(&self.core.state, self.path.precision)
    }
}

impl Emulate {
    /// One draw: one pass, or two when the faces have different polygon modes
    /// (`polygon`); each pass's edge rule is part of its key. Stippled line primitives are
    /// drawn as the dashes Mesa cuts them into (`line_stipple`).
    fn draw(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        geometry: &Arc<Geometry>,
    ) -> Result<(), PipelineError> {
        if self.user.current().is_some() {
            return self.draw_with_program(gl, state, geometry);
        }
        if let Some(memo) = self.memo.as_ref().filter(|m| m.repeats(geometry)) {
            let (program, pass) = (Rc::clone(&memo.program), memo.pass);
            program.bind_transform(gl, state);
            self.repeated += 1;
            return self.draw_geometry(gl, state, &pass, geometry, Raster::AsSent);
        }
        self.memo = None;
        let base = ShaderKey::from_state(state, self.precision);
        let mut passes = polygon::passes(
            state.polygon_mode,
            state.cull_face.get(),
            state.offset_enables,
            geometry.primitive,
            polygon::Outline::of(geometry),
        );
        if polygon::hides_outline(geometry, state.current.edge_flag) {
            passes.retain(|p| p.mode == crate::ff::PolygonMode::Fill);
        }
        // Antialiased points and lines, as Mesa draws them (its draw module's aapoint and
        // aaline stages): round points are the program's work (`PointShape::Round`), smooth
        // lines the core context's own LINE_SMOOTH (`sync`), the same aaline stage.
        // POLYGON_SMOOTH changes nothing on llvmpipe (measured: a blended triangle is the
        // same pixels with it), so it is state only.
        let points = PointKey::of(state);
        let stipple = state.line_stipple.get();
        if let (Some(stipple), true) = (stipple, stipple_dashes::is_line(geometry.primitive)) {
            let dashes = stipple_dashes::of_draw(state, stipple, geometry);
            let mut pass = passes[0];
            pass.positions = PositionSource::Window;
            let mut key = base;
            key.vertex.positions = PositionSource::Window;
            return self
                .draw_pass(gl, state, &key, &pass, Drawn::Dashes(geometry, &dashes))
                .map(|_| ());
        }
        // Polygons in LINE mode under LINE_STIPPLE: their outlines cut into dashes as Mesa
        // cuts them (`outline_dashes`), drawn after the draw's other passes.
        let outline = match stipple {
            Some(stipple) => passes.iter().find(|p| p.draws_lines).copied().map(|p| {
                let segments = outline_dashes::outline_segments(geometry, state);
                (
                    p,
                    stipple_dashes::of_segments(state, stipple, geometry, &segments),
                )
            }),
            None => None,
        };
        if outline.is_some() {
            passes.retain(|p| !p.draws_lines);
        }
        // One pass of the geometry itself is what a repeated draw can repeat (`repeat`).
        let repeatable = outline.is_none() && passes.len() == 1;
        // The geometry's own passes read its per-vertex materials; dashes, drawn from window
        // positions without them, take the material state (the base key kept only for
        // them; the last pass takes the key itself).
        let (mut own, base) = match outline {
            Some(_) => (base.clone(), Some(base)),
            None => (base, None),
        };
        own.with_vertex_materials(geometry)?;
        let mut own = Some(own);
        let mut passes = passes.into_iter().peekable();
        while let Some(pass) = passes.next() {
            let next = passes.peek().is_some();
            let Some(mut key) = (if next { own.clone() } else { own.take() }) else {
                break;
            };
            key.fragment.edges = pass.edges;
            key.vertex.point_size = pass.draws_points().then_some(points);
            key.fragment.point_cut = pass
                .draws_points()
                .then(|| PointCut::of(points.shape))
                .flatten();
            // Mesa 22.3 replaces the coordinates in the fragment program itself
            // (`nir_lower_texcoord_replace`), whatever the primitive: a triangle drawn under
            // POINT_SPRITE reads gl_PointCoord too, the texel at (0, 0) on llvmpipe
            // (measured, `tests/c/point_sprites.c`), which the same read gives here.
            key.fragment.sprite = SpriteKey::of(state);
            key.fragment.polygon_stipple = pass.fills_polygons && state.polygon_stipple.enabled;
            let program = self.draw_pass(gl, state, &key, &pass, Drawn::Geometry(geometry))?;
            if repeatable {
                self.memo = Some(repeat::DrawMemo {
                    geometry: Arc::clone(geometry),
                    pass,
                    program,
                });
            }
        }
        if let Some((mut pass, dashes)) = outline {
            pass.positions = PositionSource::Window;
            pass.cull = None;
            pass.edges = None;
            pass.offset = false;
            if let Some(mut key) = base {
                key.vertex.positions = PositionSource::Window;
                self.draw_pass(gl, state, &key, &pass, Drawn::Dashes(geometry, &dashes))?;
            }
        }
        Ok(())
    }

    /// One pass of a draw: the key's program bound with its uniforms, the units' textures,
    /// the raster state synced, the geometry drawn (primitives and pixel rectangles alike).
    /// Returns the program.
    fn draw_pass(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        key: &ShaderKey,
        pass: &polygon::PolygonPass,
        drawn: Drawn,
    ) -> Result<Rc<Program>, PipelineError> {
        let program = self.programs.get_or_build(key, |k| Program::build(gl, k))?;
        program.bind(gl, state);
        let units: Vec<_> = key
            .fragment
            .units
            .iter()
            .map(|u| (u.unit, u.target))
            .collect();
        self.textures.bind_units(gl, state, &units)?;
        match drawn {
            Drawn::Geometry(g) => self.draw_geometry(gl, state, pass, g, Raster::Sync)?,
            Drawn::Dashes(g, d) => {
                self.raster.sync(gl, state, Some(pass), Winding::AsGiven);
                dashes::draw(gl, &mut self.sent, state, g, d)?;
            }
        }
        Ok(program)
    }

    /// A draw with the plan's program in use (`user_program`): its built-ins from the
    /// state, its samplers' textures, the raster state of each polygon pass, the geometry.
    fn draw_with_program(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        geometry: &Arc<Geometry>,
    ) -> Result<(), PipelineError> {
        let Some(program) = self.user.current().cloned() else {
            return Ok(());
        };
        program.bind(gl, state);
        self.textures
            .bind_units(gl, state, &program.texture_units())?;
        let passes = polygon::passes(
            state.polygon_mode,
            state.cull_face.get(),
            state.offset_enables,
            geometry.primitive,
            polygon::Outline::of(geometry),
        );
        for pass in passes {
            self.draw_geometry(gl, state, &pass, geometry, Raster::Sync)?;
        }
        Ok(())
    }

    /// How the framebuffer `name` stores its rows: the window top row first when it is
    /// GL's window-system framebuffer 0 (`window_top_row_first`), objects bottom row first.
    fn row_order(&self, name: u32) -> RowOrder {
        match name == 0 && self.window_top_row_first {
            true => RowOrder::TopFirst,
            false => RowOrder::BottomFirst,
        }
    }

    /// The raster state of `pass` synced (unless `raster` says GL has it already) and the
    /// geometry drawn, in the corner order the pass draws it with (`draw::Winding`, which
    /// core GL's front face follows).
    fn draw_geometry(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        pass: &polygon::PolygonPass,
        geometry: &Arc<Geometry>,
        raster: Raster,
    ) -> Result<(), PipelineError> {
        let rows = self.row_order(state.framebuffers.draw);
        let gpu = self.geometry.get(gl, geometry)?;
        let winding = match rows {
            RowOrder::TopFirst => Winding::AsGiven,
            RowOrder::BottomFirst => gpu.winding(pass, state),
        };
        if raster == Raster::Sync {
            self.raster.sync(gl, state, Some(pass), winding);
        }
        gpu.draw(gl, &mut self.sent, state, winding);
        Ok(())
    }

    fn clear(&mut self, gl: &glow::Context, state: &FixedState, mask: crate::ff::ClearMask) {
        self.raster.sync(gl, state, None, Winding::AsGiven);
        let mut c = state.clear;
        // Depth cleared with the stencil where that leaves the same contents, in llvmpipe's
        // one-pass clear (`stencil_contents`).
        let (mask, stencil) = self.window_stencil.clear(mask, state);
        if let Some(v) = stencil {
            c.stencil = i32::from(v);
        }
        let mut bits = 0;
        unsafe {
            if mask.color {
                gl.clear_color(c.color.x, c.color.y, c.color.z, c.color.w);
                bits |= glow::COLOR_BUFFER_BIT;
            }
            if mask.depth {
                gl.clear_depth_f64(c.depth);
                bits |= glow::DEPTH_BUFFER_BIT;
            }
            if mask.stencil {
                gl.clear_stencil(c.stencil);
                bits |= glow::STENCIL_BUFFER_BIT;
            }
            // Clear obeys the masks and the scissor box, not the viewport (§4.2.3).
            gl.clear(bits);
        }
    }
}

impl Issue for Emulate {
    const KIND: PipelineKind = PipelineKind::Emulate;

    /// Draws, clears, texture images and readbacks reach GL now; everything else lives in
    /// the model and reaches GL at the next draw.
    fn issue(
        &mut self,
        ctx: &GpuContext,
        core: &mut Core,
        cmd: &Command,
    ) -> Result<(), PipelineError> {
        let gl = ctx.gl();
        let state = &core.state;
        if !repeat::keeps(cmd, state) {
            self.memo = None;
        }
        self.window_stencil = self.window_stencil.after(cmd, state);
        let textures = &mut self.textures;
        if self
            .framebuffers
            .issue(gl, state, cmd, &mut |t, n| textures.gl_name(gl, t, n))?
        {
            return Ok(());
        }
        if super::framebuffers::uses_framebuffer(cmd) {
            self.framebuffers.sync(gl, state)?;
        }
        match cmd {
            Command::GenerateMipmap(t) => self.textures.generate_mipmap(gl, state, *t)?,
            Command::UseProgram(p) => self.user.use_program(gl, p.as_ref())?,
            Command::Uniform { name, value } => self.user.uniform(gl, name, value)?,
            Command::Draw(g) => {
                self.draw(gl, state, g)?;
                core.counters.draws += 1;
            }
            Command::Clear(mask) => {
                self.clear(gl, state, *mask);
                if let (true, Some(b)) = (mask.accum && state.accum_bits() > 0, &mut self.accum) {
                    accum::clear(b, state);
                }
            }
            Command::BlitFramebuffer(b) => {
                // The scissor box clips the blit (and no other raster state applies).
                self.raster.sync(gl, state, None, Winding::AsGiven);
                let (s, d) = (b.src, b.dst);
                unsafe {
                    gl.blit_framebuffer(
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
            Command::Accum { op, value } => {
                if let Some(b) = &mut self.accum {
                    accum::accum(gl, b, state, *op, *value)?;
                    // RETURN set the scissor and the colour mask behind the shadow copy.
                    self.raster.invalidate();
                }
            }
            Command::TexImage(t) => self.textures.upload_level(gl, state, t.target, t.level)?,
            // The model keeps a compressed level decoded: it uploads as any 8-bit level.
            Command::CompressedTexImage2D(t) if !t.proxy => {
                self.textures
                    .upload_level(gl, state, TextureTarget::Texture2D, t.level)?
            }
            // Only the region's texels, decoded, as a glTexSubImage2D.
            Command::CompressedTexSubImage2D(t) => {
                if let Some(region) = t.texels() {
                    self.textures
                        .sub_image(gl, state, TextureTarget::Texture2D, &region)?
                }
            }
            Command::DeleteTextures(names) => self.textures.delete(gl, names),
            Command::TexSubImage2D(t) => self.textures.sub_image(gl, state, t.target_2d(), t)?,
            Command::TexSubImage3D(t) => {
                self.textures
                    .sub_image(gl, state, TextureTarget::Texture3D, t)?
            }
            Command::CopyTexImage2D(c) => self.textures.copy_level(gl, state, c)?,
            Command::TexParameter { target, .. } => {
                self.textures.sync_params(gl, state, *target)?
            }
            Command::ReadPixels(asked) => {
                // BGR(A), signed and packed types: read in the read form, packed on
                // the CPU (`ff::pixel_types`).
                let (format, ty) = pixel_types::read_form(asked.format, asked.ty);
                let r = &ReadPixels {
                    format,
                    ty,
                    ..*asked
                };
                let mut readback = read_pixels(gl, r);
                if let Some(bytes) =
                    pixels::transferred_read(gl, r, &state.pixel_transfer, &state.pixel_maps)
                {
                    readback.bytes = bytes;
                }
                let from = match state.draw_bits(state.framebuffers.window_bits).red {
                    8 => ReadFrom::Unorm8,
                    _ => ReadFrom::Float,
                };
                as_asked(
                    &mut readback,
                    asked.format,
                    asked.ty,
                    from,
                    Packer::ReadPixels,
                );
                core.readbacks.insert(r.slot, readback);
            }
            Command::TexSubImage1D(t) => self.textures.sub_image_1d(ctx, state, t)?,
            Command::CopyTexImage1D(c) => self.textures.copy_image_1d(ctx, state, c)?,
            Command::CopyTexSubImage(c) => self.textures.copy_sub_image(ctx, state, c)?,
            Command::GetTexImage(asked) => {
                let (format, ty) = pixel_types::read_form(asked.format, asked.ty);
                let g = &GetTexImage {
                    format,
                    ty,
                    ..*asked
                };
                if let Some((mut r, from)) = self.textures.get_image(gl, state, g)? {
                    as_asked(&mut r, asked.format, asked.ty, from, Packer::GetTexImage);
                    core.readbacks.insert(g.slot, r);
                }
            }
            // The model restored the groups; the raster state and uniforms follow it at the
            // next draw, the texture objects' parameters now.
            Command::PopAttrib => self.textures.sync_bound_params(gl, state)?,
            Command::Bitmap(_) | Command::DrawPixels(_) | Command::CopyPixels(_) => {
                self.pixel_command(gl, state, cmd)?
            }
            _ => {}
        }
        Ok(())
    }

    fn counters(&self, core: &Counters) -> Counters {
        let (sent, skipped) = self.raster.counts();
        Counters {
            programs_compiled: (self.programs.compiles() + self.user.compiles()) as u64,
            state_calls_sent: sent,
            state_calls_skipped: skipped + self.textures.binds_skipped,
            texture_uploads: self.textures.uploads,
            geometry_uploads: self.geometry.uploads(),
            repeated_draws: self.repeated,
            ..*core
        }
    }

    fn release(&mut self, ctx: &GpuContext) {
        let gl = ctx.gl();
        self.memo = None;
        for p in self.programs.drain() {
            p.delete(gl);
        }
        self.user.release(gl);
        self.geometry.release(gl);
        self.textures.release(gl);
        self.framebuffers.release(gl);
        if let Some(t) = self.pixel_image.take() {
            unsafe { gl.delete_texture(t) };
        }
        self.raster.invalidate();
    }
}

/// A readback in the read form of (`format`, `ty`) as glReadPixels and glGetTexImage give
/// it (`pixel_types::from_model`): from the colour storage `from`, from floats for depth.
fn as_asked(r: &mut Readback, format: PixelFormat, ty: PixelType, from: ReadFrom, packer: Packer) {
    let from = match format {
        PixelFormat::DepthComponent => ReadFrom::Float,
        _ => from,
    };
    r.bytes = pixel_types::from_model(&r.bytes, format, ty, from, packer);
    r.format = format;
    r.ty = ty;
}

/// The bytes of one ReadPixels, packed with PACK_ALIGNMENT 1, bottom row first.
fn read_pixels(gl: &glow::Context, r: &ReadPixels) -> Readback {
    Readback {
        width: r.width.max(0) as u32,
        height: r.height.max(0) as u32,
        depth: None,
        format: r.format,
        ty: r.ty,
        bytes: read(gl, r),
    }
}

/// glReadPixels with the core formats; LUMINANCE and ALPHA (absent from core ReadPixels)
/// come from an RGBA read: L = R + G + B clamped to 1 (GL 1.5 §4.3.2), A = A.
fn read(gl: &glow::Context, r: &ReadPixels) -> Vec<u8> {
    let (w, h) = (r.width.max(0) as usize, r.height.max(0) as usize);
    let size = r.ty.size();
    let read_raw = |format: u32, components: usize, ty: PixelType| {
        let mut out = vec![0u8; w * h * components * ty.size()];
        unsafe {
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            gl.read_pixels(
                r.x,
                r.y,
                r.width,
                r.height,
                format,
                conv::value(ty),
                glow::PixelPackData::Slice(Some(&mut out)),
            );
        }
        out
    };
    match r.format {
        // Bytes from bytes: A = A exactly, L = min(R + G + B, 255) (the sum of unorm8 values
        // is exact in integers), without a float round trip.
        PixelFormat::Luminance | PixelFormat::LuminanceAlpha | PixelFormat::Alpha
            if r.ty == PixelType::UnsignedByte =>
        {
            let rgba = read_raw(glow::RGBA, 4, PixelType::UnsignedByte);
            let mut out = Vec::with_capacity(w * h * r.format.components());
            for p in rgba.chunks_exact(4) {
                let l = (u16::from(p[0]) + u16::from(p[1]) + u16::from(p[2])).min(255) as u8;
                match r.format {
                    PixelFormat::Luminance => out.push(l),
                    PixelFormat::LuminanceAlpha => out.extend([l, p[3]]),
                    _ => out.push(p[3]),
                }
            }
            out
        }
        // Alpha in a wider unsigned type or as floats: the driver's RGBA read in that type,
        // its A, as Mesa converts the stored value straight to the type (measured: 231/255
        // as UNSIGNED_INT is 0xe7e7e7e7; through a float it would be 0xe7e7e8ff).
        PixelFormat::Alpha
            if matches!(
                r.ty,
                PixelType::UnsignedShort | PixelType::UnsignedInt | PixelType::Float
            ) =>
        {
            let rgba = read_raw(glow::RGBA, 4, r.ty);
            rgba.chunks_exact(4 * size)
                .flat_map(|p| p[3 * size..].to_vec())
                .collect()
        }
        PixelFormat::Luminance | PixelFormat::LuminanceAlpha | PixelFormat::Alpha => {
            let rgba = read_raw(glow::RGBA, 4, PixelType::Float);
            let mut out = Vec::with_capacity(w * h * r.format.components() * size);
            for c in rgba.chunks_exact(16) {
                let p: [f32; 4] = std::array::from_fn(|i| {
                    f32::from_ne_bytes([c[4 * i], c[4 * i + 1], c[4 * i + 2], c[4 * i + 3]])
                });
                let l = (p[0] + p[1] + p[2]).min(1.0);
                match r.format {
                    PixelFormat::Luminance => out.extend(encode(l, r.ty)),
                    PixelFormat::LuminanceAlpha => {
                        out.extend(encode(l, r.ty));
                        out.extend(encode(p[3], r.ty));
                    }
                    _ => out.extend(encode(p[3], r.ty)),
                }
            }
            out
        }
        other => read_raw(conv::pixel_format(other), other.components(), r.ty),
    }
}

/// A colour component as the pixel type stores it: unorm ⌊v·M + ½⌋ or f32.
fn encode(v: f32, ty: PixelType) -> Vec<u8> {
    let v = v.clamp(0.0, 1.0);
    match ty {
        PixelType::UnsignedByte => vec![(v * 255.0 + 0.5) as u8],
        PixelType::UnsignedShort => ((v * 65535.0 + 0.5) as u16).to_ne_bytes().to_vec(),
        PixelType::UnsignedInt => ((f64::from(v) * f64::from(u32::MAX) + 0.5) as u32)
            .to_ne_bytes()
            .to_vec(),
        PixelType::Float => v.to_ne_bytes().to_vec(),
        // Signed types by `pixel_types`' rule; a packed type is packed from FLOAT reads.
        PixelType::Byte | PixelType::Short | PixelType::Int | PixelType::Packed(_) => {
            crate::ff::pixel_types::component_bytes(v, ty)
        }
    }
}
