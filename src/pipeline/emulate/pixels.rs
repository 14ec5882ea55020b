//! Pixel rectangles on the core profile: glBitmap, glDrawPixels and glCopyPixels become one
//! quad over the zoomed rectangle, drawn by the fixed-function program of the state with
//! its key's `pixels` saying what the image gives the fragment (`key::PixelSource`). The
//! image — converted on the CPU by `ff::pixels` (transfer scale, bias, shifts, clamps) — is
//! a texture on [`PIXEL_IMAGE_UNIT`]: an image's quad is Mesa's fan, read with NEAREST at
//! its interpolated coordinates (`pixel_fan`), a bitmap's a strip read with texelFetch.
//!
//! The quad is drawn under a copy of the state ([`rect_state`]) in which the raster
//! position stands for the vertex (GL 1.5 §3.6.4, §3.7): the current colour and texture
//! coordinates are the raster ones (texgen, lighting, clip planes and texture matrices off:
//! they were applied when the position was set); the modelview and projection put each
//! corner at its window position with eye z = 0 (the fog distance Mesa gives rectangles,
//! where GL gives CURRENT_RASTER_DISTANCE) and window z = CURRENT_RASTER_POSITION's z
//! (depth range [0, 1]); the viewport is the whole draw framebuffer (the window, or the
//! bound object's size), so the rectangle is clipped by the framebuffer and the scissor only; FILL, no culling, no
//! polygon offset. Everything per fragment — texturing, fog, alpha, stencil and depth tests,
//! blending, logic op, masks — is the state's.
//!
//! Where Mesa puts the rectangle (measured, `tests/fidelity_pixels.rs`): glDrawPixels and
//! glCopyPixels at the raster position rounded to the nearest integer (half away from zero),
//! glBitmap at ⌊x_r − x_o + 10⁻⁴⌋ (Mesa's epsilon). STENCIL_INDEX images write the stencil
//! buffer only (no colour, no depth, no tests but the scissor), one pass per bit plane under
//! the stencil write mask.

use std::sync::Arc;

use glam::{Mat4, Vec2, Vec4};
use glow::HasContext;

use super::key::{PixelSource, ShaderKey};
use super::pixel_fan::{self, RowOrder};
use super::polygon::PolygonPass;
use super::Emulate;
use crate::ff::framebuffer::FramebufferTarget;
use crate::ff::pixel_map::PixelMaps;
use crate::ff::pixel_types;
use crate::ff::{
    ColorMask, Command, CompareFunc, Converted, CopyKind, CopyPixels, DrawPixels, FixedState,
    Geometry, PixelFormat, PixelTransfer, PixelType, PixelZoom, PolygonMode, PolygonModes,
    Primitive, ReadPixels, StencilOp, StencilTest, Viewport, MAX_CLIP_PLANES,
};
use crate::pipeline::PipelineError;

/// The texture unit of a pixel rectangle's image (not a fixed-function unit, not the
/// scratch unit of `textures`).
pub const PIXEL_IMAGE_UNIT: u32 = 14;

/// The fog distance of a rectangle's fragments: 0, as Mesa's draws them (measured: LINEAR
/// fog from −1 to 1 fogs an image by exactly ½). GL 1.5 §3.6.4 gives them the raster
/// distance; `tests/fidelity_pixels.rs` pins the deviation.
const PIXEL_FOG_DISTANCE: f32 = 0.0;

/// Mesa's bitmap epsilon: the corner is ⌊x_r − x_o + 10⁻⁴⌋.
const BITMAP_EPSILON: f32 = 1e-4;

/// One rectangle to draw: its image, lower-left window corner and zoom, and the order
/// Mesa's copy of the image would hold its rows in (`pixel_fan`).
pub struct Rect<'a> {
    pub width: i32,
    pub height: i32,
    pub corner: Vec2,
    pub zoom: PixelZoom,
    pub image: &'a Converted,
    pub rows: RowOrder,
}

/// The corner of glDrawPixels and glCopyPixels: the raster position rounded (Mesa).
pub fn draw_corner(state: &FixedState) -> Vec2 {
    Vec2::new(state.raster.window.x.round(), state.raster.window.y.round())
}

/// The corner of glBitmap: ⌊x_r − x_o + ε⌋ (Mesa; GL 1.5 §3.7 without the ε). A NaN
/// coordinate (a NaN advance moved the position) floors to 0, as Mesa's `IFLOOR` takes it
/// (its bit trick subtracts two equal NaN patterns; measured, a bitmap after a NaN
/// advance is drawn at x = 0, `tests/c/float_params.c`).
pub fn bitmap_corner(state: &FixedState, origin: (f32, f32)) -> Vec2 {
    let r = state.raster.window;
    let corner = |v: f32, o: f32| {
        let c = (v - o + BITMAP_EPSILON).floor();
        if c.is_nan() {
            0.0
        } else {
            c
        }
    };
    Vec2::new(corner(r.x, origin.0), corner(r.y, origin.1))
}

/// The state a rectangle at `corner` is drawn under (see the module note); `target` is the
/// whole draw framebuffer, the viewport it is drawn with.
pub fn rect_state(
    state: &FixedState,
    target: Viewport,
    corner: Vec2,
    zoom: PixelZoom,
) -> FixedState {
    let mut s = state.clone();
    let r = state.raster;
    s.lighting = false;
    for p in s.clip_planes.iter_mut().take(MAX_CLIP_PLANES) {
        p.enabled = false;
    }
    for (u, unit) in s.units.iter_mut().enumerate() {
        for g in unit.texgen.iter_mut() {
            g.enabled = false;
        }
        s.texture_matrices[u].set_top(Mat4::IDENTITY);
    }
    s.current.color = r.color;
    s.current.texcoords = r.texcoords;
    // Positions are normalised device coordinates of the target; the modelview sends them
    // to eye space at z_e = −distance (w = 1), the projection keeps x, y and sets
    // z_c = 2·z_w − 1 with w_c = 1, so the window z is z_w under the depth range [0, 1].
    s.modelview.set_top(Mat4::from_cols(
        Vec4::X,
        Vec4::Y,
        Vec4::ZERO,
        Vec4::new(0.0, 0.0, -PIXEL_FOG_DISTANCE, 1.0),
    ));
    s.projection.set_top(Mat4::from_cols(
        Vec4::X,
        Vec4::Y,
        Vec4::ZERO,
        Vec4::new(0.0, 0.0, 2.0 * r.window.z - 1.0, 1.0),
    ));
    s.depth_range = crate::ff::DepthRange {
        near: 0.0,
        far: 1.0,
    };
    s.viewport = target;
    s.polygon_mode = PolygonModes {
        front: PolygonMode::Fill,
        back: PolygonMode::Fill,
    };
    s.cull_face.enabled = false;
    s.offset_enables = Default::default();
    // The uniforms read the corner and zoom from here (`UniformSource::PixelRect`).
    s.raster.window.x = corner.x;
    s.raster.window.y = corner.y;
    s.pixel_zoom = zoom;
    s
}

/// The state of one STENCIL_INDEX pass writing the bits `bit` of the value where the image
/// has them (bit 0: the whole value first set to 0): stencil ALWAYS, REPLACE with 0xFF
/// (or 0), the write mask restricted to the bit; no colour, no depth test.
fn stencil_pass(s: &FixedState, bit: u32) -> FixedState {
    let mut p = s.clone();
    let mask = s.stencil_test.value.write_mask;
    p.stencil_test.enabled = true;
    p.stencil_test.value = StencilTest {
        func: CompareFunc::Always,
        reference: if bit == 0 { 0 } else { 0xFF },
        // Read by the program as the pass's bit (`UniformSource::PixelStencilBit`).
        value_mask: bit,
        write_mask: if bit == 0 { mask } else { mask & bit },
        fail: StencilOp::Replace,
        depth_fail: StencilOp::Replace,
        depth_pass: StencilOp::Replace,
    };
    p.depth_test.enabled = false;
    p.alpha_test.enabled = false;
    p.color_mask = ColorMask {
        r: false,
        g: false,
        b: false,
        a: false,
    };
    p
}

/// glReadPixels under a pixel transfer that is not the identity (GL 1.5 §4.3.2: the
/// scales and biases apply to colours read, then MAP_COLOR's maps by the nearest entry
/// (`ff::pixel_map`), DEPTH_SCALE and DEPTH_BIAS to depths, INDEX_SHIFT, INDEX_OFFSET and
/// MAP_STENCIL to stencil indices): the colour read as RGBA
/// floats, transferred on the CPU, clamped for fixed-point types, L = R + G + B clamped to
/// [0, 1] for every type (Mesa's `_mesa_pack_rgba_span_float`; measured, a FLOAT read of
/// RED_SCALE 2 over (0.625, 0.5, 0.25) gives L = 1) and stored in the requested type
/// ([`encode_even`]); depth read as floats in FLOAT only. `None` for the identity transfer
/// or another format or type (read as they are).
pub fn transferred_read(
    gl: &glow::Context,
    r: &ReadPixels,
    t: &PixelTransfer,
    maps: &PixelMaps,
) -> Option<Vec<u8>> {
    let colour_identity = t.colour_identity();
    let depth_identity = t.depth_scale == 1.0 && t.depth_bias == 0.0;
    let read_as = |format, ty| super::read(gl, &ReadPixels { format, ty, ..*r });
    let f32s = |b: Vec<u8>| -> Vec<f32> {
        b.chunks_exact(4)
            .map(|c| f32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
            .collect()
    };
    match r.format {
        PixelFormat::DepthComponent if !depth_identity && r.ty == PixelType::Float => Some(
            f32s(read_as(PixelFormat::DepthComponent, PixelType::Float))
                .into_iter()
                .flat_map(|d| t.depth(d).to_ne_bytes())
                .collect(),
        ),
        PixelFormat::StencilIndex if !t.stencil_identity() => Some(
            read_as(PixelFormat::StencilIndex, PixelType::UnsignedByte)
                .into_iter()
                .flat_map(|s| stencil_bytes(t.stencil_read(s, maps), r.ty))
                .collect(),
        ),
        PixelFormat::DepthComponent | PixelFormat::StencilIndex => None,
        _ if colour_identity => None,
        format => {
            let rgba = f32s(read_as(PixelFormat::Rgba, PixelType::Float));
            let mut out = Vec::new();
            for p in rgba.chunks_exact(4) {
                // FLOAT reads are not clamped (Mesa, as GL 3.0's CLAMP_READ_COLOR =
                // FIXED_ONLY: measured, RED_SCALE 2 on 0.625 reads 1.25); fixed-point ones are.
                let mut c = t.colour_nearest(Vec4::from_slice(p), maps);
                if r.ty != PixelType::Float {
                    c = c.clamp(Vec4::ZERO, Vec4::ONE);
                }
                let l = (c.x + c.y + c.z).clamp(0.0, 1.0);
                let values: Vec<f32> = match format {
                    PixelFormat::Rgba => c.to_array().to_vec(),
                    PixelFormat::Rgb => vec![c.x, c.y, c.z],
                    PixelFormat::Luminance => vec![l],
                    PixelFormat::LuminanceAlpha => vec![l, c.w],
                    PixelFormat::Red => vec![c.x],
                    PixelFormat::Green => vec![c.y],
                    PixelFormat::Blue => vec![c.z],
                    _ => vec![c.w],
                };
                for v in values {
                    out.extend(encode_even(v, r.ty));
                }
            }
            Some(out)
        }
    }
}

/// A transferred colour component in the pixel type: unorm v·M rounded half to even, as
/// Mesa's `_mesa_float_to_unorm` stores it (measured: 145/255 · 0.5 reads as 72, where
/// ⌊v·255 + ½⌋ gives 73), clamped to [0, 1] first; a FLOAT as it is.
fn encode_even(v: f32, ty: PixelType) -> Vec<u8> {
    let u = v.clamp(0.0, 1.0);
    match ty {
        PixelType::UnsignedByte => vec![(u * 255.0).round_ties_even() as u8],
        PixelType::UnsignedShort => ((u * 65535.0).round_ties_even() as u16)
            .to_ne_bytes()
            .to_vec(),
        PixelType::UnsignedInt => ((f64::from(u) * f64::from(u32::MAX)).round_ties_even() as u32)
            .to_ne_bytes()
            .to_vec(),
        PixelType::Float => v.to_ne_bytes().to_vec(),
        // Signed types by `pixel_types`' rule; a packed type is packed from FLOAT reads.
        PixelType::Byte | PixelType::Short | PixelType::Int | PixelType::Packed(_) => {
            pixel_types::component_bytes(v, ty)
        }
    }
}

/// A stencil value in the type the model reads stencil indices in (`pixel_types::
/// model_form`: the signed types come as UNSIGNED_INT).
fn stencil_bytes(s: u8, ty: PixelType) -> Vec<u8> {
    match ty {
        PixelType::UnsignedByte => vec![s],
        PixelType::UnsignedShort => u16::from(s).to_ne_bytes().to_vec(),
        PixelType::Float => f32::from(s).to_ne_bytes().to_vec(),
        _ => u32::from(s).to_ne_bytes().to_vec(),
    }
}

/// The image as a texture's bytes, `width` pixels a row: (internal format, format, type,
/// bytes), its rows in `rows` order (the converted image holds them bottom first).
fn image_bytes(image: &Converted, width: i32, rows: RowOrder) -> (u32, u32, u32, Vec<u8>) {
    let (internal, format, ty, bytes): (u32, u32, u32, Vec<u8>) = match image {
        Converted::Color(c) => (
            glow::RGBA32F,
            glow::RGBA,
            glow::FLOAT,
            c.iter()
                .flat_map(|v| v.to_array())
                .flat_map(f32::to_ne_bytes)
                .collect(),
        ),
        Converted::Depth(d) => (
            glow::R32F,
            glow::RED,
            glow::FLOAT,
            d.iter().flat_map(|v| v.to_ne_bytes()).collect(),
        ),
        Converted::Stencil(s) => (glow::R8, glow::RED, glow::UNSIGNED_BYTE, s.clone()),
    };
    let bytes = match rows {
        RowOrder::BottomFirst => bytes,
        RowOrder::TopFirst => {
            let texel = match image {
                Converted::Color(_) => 16,
                Converted::Depth(_) => 4,
                Converted::Stencil(_) => 1,
            };
            let row = texel * width.max(1) as usize;
            bytes.chunks(row).rev().flatten().copied().collect()
        }
    };
    (internal, format, ty, bytes)
}

impl Emulate {
    /// glBitmap, glDrawPixels or glCopyPixels, which the model accepted; nothing with an
    /// invalid raster position (§3.6.4, §3.7). A bitmap comes with the state from before
    /// its advance (`PathPipeline::bitmap`): it is drawn at the raster position `state`
    /// holds.
    pub(super) fn pixel_command(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        cmd: &Command,
    ) -> Result<(), PipelineError> {
        if !state.raster.valid {
            return Ok(());
        }
        match cmd {
            Command::Bitmap(b) if b.bits.is_some() => {
                let (w, h) = (b.width.max(0) as usize, b.height.max(0) as usize);
                let bits = (0..h)
                    .flat_map(|y| (0..w).map(move |x| (x, y)))
                    .map(|(x, y)| u8::from(b.bit(x, y)))
                    .collect();
                let image = Converted::Stencil(bits);
                let rect = Rect {
                    width: b.width,
                    height: b.height,
                    corner: bitmap_corner(state, b.origin),
                    zoom: PixelZoom::DEFAULT,
                    image: &image,
                    rows: RowOrder::BottomFirst,
                };
                self.pixel_rect(gl, state, rect, PixelSource::Bitmap)
            }
            Command::DrawPixels(d) => {
                let image = d.convert(&state.pixel_transfer, &state.pixel_maps);
                let size = (d.width, d.height);
                self.draw_converted(gl, state, size, &image, RowOrder::BottomFirst)
            }
            // Mesa copies the read framebuffer's rows as they are stored.
            Command::CopyPixels(c) => {
                let image = self.read_rect(gl, state, c);
                let rows = self.row_order(state.framebuffers.read);
                self.draw_converted(gl, state, (c.width, c.height), &image, rows)
            }
            _ => Ok(()),
        }
    }

    /// A converted image at the rounded raster position with the pixel zoom.
    fn draw_converted(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        (width, height): (i32, i32),
        image: &Converted,
        rows: RowOrder,
    ) -> Result<(), PipelineError> {
        let source = match image {
            Converted::Color(_) => PixelSource::Color,
            Converted::Depth(_) => PixelSource::Depth,
            Converted::Stencil(_) => PixelSource::StencilBit,
        };
        let rect = Rect {
            width,
            height,
            corner: draw_corner(state),
            zoom: state.pixel_zoom,
            image,
            rows,
        };
        self.pixel_rect(gl, state, rect, source)
    }

    /// glCopyPixels' source (§4.3.3): the read buffer's rectangle as glReadPixels of RGBA
    /// floats, depth floats or stencil bytes would give it, through the pixel transfer.
    fn read_rect(&mut self, gl: &glow::Context, state: &FixedState, c: &CopyPixels) -> Converted {
        let (format, ty) = match c.kind {
            CopyKind::Color => (PixelFormat::Rgba, PixelType::Float),
            CopyKind::Depth => (PixelFormat::DepthComponent, PixelType::Float),
            CopyKind::Stencil => (PixelFormat::StencilIndex, PixelType::UnsignedByte),
        };
        let r = ReadPixels {
            x: c.x,
            y: c.y,
            width: c.width,
            height: c.height,
            format,
            ty,
            slot: 0,
        };
        let data = super::read(gl, &r);
        DrawPixels {
            width: c.width,
            height: c.height,
            format,
            ty,
            data: Arc::from(data),
        }
        .convert(&state.pixel_transfer, &state.pixel_maps)
    }

    /// Uploads `image` (`width` × `height`) to the pixel-image texture on its unit.
    fn upload_image(
        &mut self,
        gl: &glow::Context,
        width: i32,
        height: i32,
        image: &(u32, u32, u32, Vec<u8>),
    ) -> Result<(), PipelineError> {
        let (texture, new) = match self.pixel_image {
            Some(t) => (t, false),
            None => {
                let t = unsafe { gl.create_texture() }.map_err(PipelineError::Object)?;
                self.pixel_image = Some(t);
                (t, true)
            }
        };
        let (internal, format, ty, bytes) = image;
        unsafe {
            gl.active_texture(glow::TEXTURE0 + PIXEL_IMAGE_UNIT);
            gl.bind_texture(glow::TEXTURE_2D, Some(texture));
            if new {
                // Level 0 alone, complete under NEAREST (read unfiltered), and Mesa's
                // drawpixels sampler: NEAREST, CLAMP_TO_EDGE (`pixel_fan`). A new image
                // keeps the object's parameters.
                for (name, value) in [
                    (glow::TEXTURE_MIN_FILTER, glow::NEAREST),
                    (glow::TEXTURE_MAG_FILTER, glow::NEAREST),
                    (glow::TEXTURE_WRAP_S, glow::CLAMP_TO_EDGE),
                    (glow::TEXTURE_WRAP_T, glow::CLAMP_TO_EDGE),
                ] {
                    gl.tex_parameter_i32(glow::TEXTURE_2D, name, value as i32);
                }
                gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAX_LEVEL, 0);
            }
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
            gl.tex_image_2d(
                glow::TEXTURE_2D,
                0,
                *internal as i32,
                width,
                height,
                0,
                *format,
                *ty,
                glow::PixelUnpackData::Slice(Some(bytes)),
            );
        }
        Ok(())
    }

    /// Draws one rectangle (see the module note); nothing for an empty one.
    pub(super) fn pixel_rect(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        rect: Rect<'_>,
        source: PixelSource,
    ) -> Result<(), PipelineError> {
        if rect.width == 0 || rect.height == 0 {
            return Ok(());
        }
        let size = match state.framebuffers.draw {
            0 => None,
            _ => state.framebuffer_size(FramebufferTarget::Draw),
        }
        .unwrap_or((self.target.width, self.target.height));
        let bytes = image_bytes(rect.image, rect.width, rect.rows);
        self.upload_image(gl, rect.width, rect.height, &bytes)?;
        // Mesa draws into the whole framebuffer, clipped by the scissor alone.
        let whole = Viewport {
            x: 0,
            y: 0,
            width: size.0,
            height: size.1,
        };
        let mut base = rect_state(state, whole, rect.corner, rect.zoom);
        // Mesa adds the current secondary colour to glBitmap's fragments under COLOR_SUM,
        // and nothing to an image's (measured, tests/c/secondary.c); the fog distance
        // stays PIXEL_FOG_DISTANCE whatever FOG_COORD_SRC says (measured likewise).
        if source != PixelSource::Bitmap {
            base.color_sum = false;
        }
        base.fog.value.coord_source = crate::ff::FogCoordSource::FragmentDepth;
        // A bitmap (never zoomed, at an integral corner) covers the same pixels through
        // the fan and reads its image with texelFetch, not the fan's coordinates.
        let fan = pixel_fan::fan(
            rect.corner,
            (rect.width, rect.height),
            rect.zoom,
            size,
            self.row_order(state.framebuffers.draw),
            rect.rows,
        );
        let pixel_fan = (source != PixelSource::Bitmap).then_some(fan.t);
        let quad = Arc::new(Geometry::new(Primitive::TriangleFan, fan.corners.to_vec()));
        let passes: Vec<FixedState> = match source {
            PixelSource::StencilBit => std::iter::once(0)
                .chain((0..8).map(|b| 1u32 << b))
                .filter(|bit| *bit == 0 || base.stencil_test.value.write_mask & bit != 0)
                .map(|bit| stencil_pass(&base, bit))
                .collect(),
            _ => vec![base],
        };
        let pass = PolygonPass {
            mode: PolygonMode::Fill,
            cull: None,
            offset: false,
            edges: None,
            fills_polygons: false,
            draws_lines: false,
            positions: super::key::PositionSource::Transformed,
        };
        for s in &passes {
            let mut key = ShaderKey::from_state(s, self.precision);
            key.fragment.pixels = Some(source);
            key.vertex.pixel_fan = pixel_fan;
            self.draw_pass(gl, s, &key, &pass, super::Drawn::Geometry(&quad))?;
        }
        Ok(())
    }
}
