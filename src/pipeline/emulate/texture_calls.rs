//! glTexSubImage1D, glCopyTexImage1D, glCopyTexSubImage1D/2D/3D and glGetTexImage on the core
//! profile, where the legacy formats are stored as R8/RG8 plus a swizzle
//! (`conv::tex_format`). A copy reads the framebuffer as RGBA (or depth) and keeps what
//! the texture's base format takes (GL 1.5 §3.8.2, Table 3.15: L and I from R, A from A),
//! stored as the texture stores it; a core copy would put R where ALPHA8 keeps A.
//! glGetTexImage reads the storage back and gives it as GL would (§6.1.4): the base
//! components become R, G, B, A by Table 6.1 (L → R, I → R, A → A; missing colours 0,
//! missing alpha 1), and a LUMINANCE format takes L = R, as Mesa does (not ReadPixels'
//! R + G + B). glTexSubImage1D and glCopyTexSubImage1D, absent from glow, are called
//! through the context's own entry points.

use std::ffi::c_void;

use crate::ff::pixel_types::{self, ReadFrom};
use crate::ff::texture::{BaseFormat, PixelFormat, PixelType, TexFormat, TexLevel, TextureTarget};
use crate::ff::texture_calls::{CopyTexSubImage, GetTexImage};
use crate::ff::texture_storage;
use crate::ff::{CopyTexImage, FixedState, TexSubImage};
use crate::gpu::GpuContext;
use crate::pipeline::{PipelineError, Readback};

use super::conv;
use super::texel_store::{self, storage};
use super::textures::{apply_params, generate_mipmap, Textures};
use glow::HasContext;

/// The framebuffer rectangle as the texture of format `f` stores it, through the state's
/// pixel transfer (`texel_store`): colours read as unsigned bytes under the identity
/// transfer, as floats under another.
pub(super) fn read_as_stored(
    gl: &glow::Context,
    state: &FixedState,
    rect: [i32; 4],
    f: TexFormat,
) -> Vec<u8> {
    let [x, y, w, h] = rect;
    let n = (w.max(0) * h.max(0)) as usize;
    let read = |format: u32, ty: u32, size: usize| {
        let mut out = vec![0u8; n * size];
        unsafe {
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            gl.read_pixels(
                x,
                y,
                w,
                h,
                format,
                ty,
                glow::PixelPackData::Slice(Some(&mut out)),
            );
        }
        out
    };
    if f.is_depth() {
        return read(glow::DEPTH_COMPONENT, glow::FLOAT, 4);
    }
    if !state.pixel_transfer.colour_identity() {
        let floats = read(glow::RGBA, glow::FLOAT, 16);
        let colours: Vec<glam::Vec4> = floats
            .chunks_exact(16)
            .map(|p| {
                glam::Vec4::from_array(std::array::from_fn(|k| {
                    f32::from_ne_bytes([p[4 * k], p[4 * k + 1], p[4 * k + 2], p[4 * k + 3]])
                }))
            })
            .collect();
        return texel_store::store(&colours, f, &state.pixel_transfer, &state.pixel_maps);
    }
    let rgba = read(glow::RGBA, glow::UNSIGNED_BYTE, 4);
    let keep = texel_store::kept(f.base());
    rgba.chunks_exact(4)
        .flat_map(|p| keep.iter().map(move |&k| p[k]))
        .collect()
}

type TexSubImage1DFn = unsafe extern "system" fn(u32, i32, i32, i32, u32, u32, *const c_void);

/// glTexSubImage1D through the context's entry point.
fn sub_image_1d(
    ctx: &GpuContext,
    level: i32,
    x: i32,
    width: i32,
    (format, ty): (u32, u32),
    data: &[u8],
) -> Result<(), PipelineError> {
    let f = ctx.proc_address("glTexSubImage1D");
    if f.is_null() {
        return Err(PipelineError::Unsupported {
            what: "glTexSubImage1D (the driver has no entry point)",
            path: "emulated",
        });
    }
    // SAFETY: the address is the driver's glTexSubImage1D, whose C prototype this is;
    // `data` holds width texels of the format (the model checked it).
    unsafe {
        let f: TexSubImage1DFn = std::mem::transmute(f);
        ctx.gl().pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
        f(
            glow::TEXTURE_1D,
            level,
            x,
            width,
            format,
            ty,
            data.as_ptr().cast(),
        );
    }
    Ok(())
}

/// A sub-image's bytes as the level's storage holds them, with the storage's client
/// format and type (`texel_store`), or `None` when they go as they are.
pub(super) fn stored_sub_image(
    state: &FixedState,
    target: TextureTarget,
    name: u32,
    t: &TexSubImage,
) -> Option<((u32, u32), Vec<u8>)> {
    let internal = state
        .texture(target, name)?
        .level_in(target, t.level)?
        .internal_format;
    let bytes = texel_store::stored_image(
        t.data.as_ref()?,
        t.format,
        t.ty,
        internal,
        &state.pixel_transfer,
        &state.pixel_maps,
    )?;
    let (format, ty, _) = storage(internal);
    Some(((format, ty), bytes))
}

impl Textures {
    /// glTexSubImage1D into the active unit's 1D texture.
    pub fn sub_image_1d(
        &mut self,
        ctx: &GpuContext,
        state: &FixedState,
        t: &TexSubImage,
    ) -> Result<(), PipelineError> {
        let target = TextureTarget::Texture1D;
        let name = state.units[state.active_unit()].bound(target);
        let gl_t = self.edit(ctx.gl(), (target, name))?;
        // NULL: no texel changes (the mipmaps below are derived all the same).
        match (stored_sub_image(state, target, name, t), &t.data) {
            (Some((format, bytes)), _) => sub_image_1d(ctx, t.level, t.x, t.width, format, &bytes)?,
            (None, Some(given)) => {
                let format = (conv::pixel_format(t.format), conv::value(t.ty));
                sub_image_1d(ctx, t.level, t.x, t.width, format, given)?
            }
            (None, None) => {}
        }
        if let Some(object) = state.texture(target, name) {
            generate_mipmap(ctx.gl(), gl_t, object, t.level);
        }
        self.uploads += 1;
        Ok(())
    }

    /// glCopyTexImage1D: a new level from a framebuffer row.
    pub fn copy_image_1d(
        &mut self,
        ctx: &GpuContext,
        state: &FixedState,
        c: &CopyTexImage,
    ) -> Result<(), PipelineError> {
        let gl = ctx.gl();
        let target = TextureTarget::Texture1D;
        let name = state.units[state.active_unit()].bound(target);
        let bytes = read_as_stored(gl, state, [c.x, c.y, c.width, 1], c.internal_format);
        let gl_t = self.edit(gl, (target, name))?;
        let internal = conv::stored_format(c.internal_format, c.requested);
        let (format, ty, _) = storage(c.internal_format);
        unsafe {
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
            gl.tex_image_1d(
                gl_t,
                c.level,
                internal as i32,
                c.width,
                0,
                format,
                ty,
                glow::PixelUnpackData::Slice(Some(&bytes)),
            );
        }
        if let Some(object) = state.texture(target, name) {
            apply_params(gl, gl_t, object);
            generate_mipmap(gl, gl_t, object, c.level);
        }
        self.uploads += 1;
        Ok(())
    }

    /// glCopyTexSubImage1D/2D/3D: framebuffer texels into part of a level (3D: of its image
    /// at zoffset).
    pub fn copy_sub_image(
        &mut self,
        ctx: &GpuContext,
        state: &FixedState,
        c: &CopyTexSubImage,
    ) -> Result<(), PipelineError> {
        let gl = ctx.gl();
        let name = state.units[state.active_unit()].bound(c.target);
        let Some(object) = state.texture(c.target, name) else {
            return Ok(());
        };
        let Some(level) = object.level_in(c.target, c.level) else {
            return Ok(());
        };
        let f = level.internal_format;
        let bytes = read_as_stored(gl, state, [c.x, c.y, c.width, c.height], f);
        let gl_t = self.edit(gl, (c.target, name))?;
        let (format, ty, _) = storage(f);
        match c.target {
            TextureTarget::Texture1D => {
                sub_image_1d(ctx, c.level, c.xoffset, c.width, (format, ty), &bytes)?
            }
            TextureTarget::Texture2D | TextureTarget::CubeMap | TextureTarget::CubeFace(_) => unsafe {
                gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
                gl.tex_sub_image_2d(
                    super::textures::gl_image_target(c.target),
                    c.level,
                    c.xoffset,
                    c.yoffset,
                    c.width,
                    c.height,
                    format,
                    ty,
                    glow::PixelUnpackData::Slice(Some(&bytes)),
                );
            },
            // One image, at zoffset.
            TextureTarget::Texture3D => unsafe {
                gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
                gl.tex_sub_image_3d(
                    gl_t,
                    c.level,
                    c.xoffset,
                    c.yoffset,
                    c.zoffset,
                    c.width,
                    c.height,
                    1,
                    format,
                    ty,
                    glow::PixelUnpackData::Slice(Some(&bytes)),
                );
            },
        }
        generate_mipmap(gl, gl_t, object, c.level);
        self.uploads += 1;
        Ok(())
    }

    /// glGetTexImage of a specified level (`None` for one never specified), in the read
    /// form of the call's format and type, and the storage its values come from.
    pub fn get_image(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        g: &GetTexImage,
    ) -> Result<Option<(Readback, ReadFrom)>, PipelineError> {
        let Some(level) = state.get_tex_image_level(g) else {
            return Ok(None);
        };
        let name = state.units[state.active_unit()].bound(g.target);
        let f = level.internal_format;
        let (w, h) = (level.width.max(0) as usize, level.height.max(0) as usize);
        let d = level.depth.max(0) as usize;
        // A byte read is Mesa's own conversion to bytes from any storage (5-bit 3 → 24).
        let from = match g.ty {
            PixelType::UnsignedByte => ReadFrom::Unorm8,
            _ => stored_as(level),
        };
        let (format, ty, size) = match (from, storage(f)) {
            (ReadFrom::Unorm8, s) => s,
            _ => (glow::RGBA, conv::value(g.ty), 4 * g.ty.size()),
        };
        let mut stored = vec![0u8; w * h * d * size];
        self.edit(gl, (g.target, name))?;
        unsafe {
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            gl.get_tex_image(
                super::textures::gl_image_target(g.target),
                g.level,
                format,
                ty,
                glow::PixelPackData::Slice(Some(&mut stored)),
            );
        }
        let bytes = match from {
            ReadFrom::Unorm8 => convert(&stored, f, g.format, g.ty),
            _ => from_core_read(&stored, f.base(), g.format, g.ty),
        };
        let readback = Readback {
            width: w as u32,
            height: h as u32,
            depth: (g.target == TextureTarget::Texture3D).then_some(d as u32),
            format: g.format,
            ty: g.ty,
            bytes,
        };
        Ok(Some((readback, from)))
    }
}

/// The RGBA components (0 R, 1 G, 2 B, 3 A) glGetTexImage gives of each texel in
/// `format`, in order (Table 6.1: luminance is R).
fn picked(format: PixelFormat) -> &'static [usize] {
    match format {
        PixelFormat::Rgba => &[0, 1, 2, 3],
        PixelFormat::Rgb => &[0, 1, 2],
        PixelFormat::Bgra => &[2, 1, 0, 3],
        PixelFormat::Abgr => &[3, 2, 1, 0],
        PixelFormat::Bgr => &[2, 1, 0],
        PixelFormat::Luminance => &[0],
        PixelFormat::LuminanceAlpha => &[0, 3],
        PixelFormat::Alpha => &[3],
        PixelFormat::Red => &[0],
        PixelFormat::Green => &[1],
        PixelFormat::Blue => &[2],
        // Not read here (glGetTexImage refuses them at the call).
        PixelFormat::DepthComponent | PixelFormat::StencilIndex | PixelFormat::ColorIndex => &[],
    }
}

/// What `level`'s texels are stored in, as Mesa converts from it: 8 bits a component
/// (the base formats and their 8-bit sizes), 16 bits (RGB12, RGBA16, LUMINANCE16 …), or
/// packed fields of other widths (RGB5, R3_G3_B2, RGBA4, RGB10 …, which Mesa unpacks to
/// floats) — `texture_storage`.
fn stored_as(level: &TexLevel) -> ReadFrom {
    let Some(b) = level.requested.and_then(texture_storage::stored_bits) else {
        return ReadFrom::Unorm8;
    };
    let bits = [b.red, b.green, b.blue, b.alpha, b.luminance, b.intensity];
    let kept = || bits.into_iter().filter(|&b| b != 0);
    if kept().all(|b| b == 8) {
        ReadFrom::Unorm8
    } else if kept().all(|b| b == 16) {
        ReadFrom::Unorm16
    } else {
        ReadFrom::Float
    }
}

/// The texels of a level read from the core texture as RGBA in the read form's `ty` (one
/// of UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT, FLOAT: `pixel_types::read_form`), as
/// glGetTexImage gives them in `format`: the core read is Mesa's own conversion from the
/// stored bits (5-bit 5 as UNSIGNED_SHORT: round(5/31·65535) = 10570, where the byte 41
/// widened would give 10537), its zeros and ones included (an RGB5 texel's alpha 1.0 reads
/// 0 as UNSIGNED_INT, through Mesa's float packing). A legacy base is kept in the core
/// texture's red (and green: `texel_store`).
fn from_core_read(read: &[u8], base: BaseFormat, format: PixelFormat, ty: PixelType) -> Vec<u8> {
    let c = ty.size();
    let mut out = Vec::new();
    for t in read.chunks_exact(4 * c) {
        let channel = |k: usize| &t[k * c..(k + 1) * c];
        // A legacy base's blue is 0 in every storage (R16, RG8, L4A4's RGBA4).
        let (r, zero, one) = (channel(0), channel(2), channel(3));
        // Table 6.1: the base components as R, G, B, A.
        let rgba: [&[u8]; 4] = match base {
            BaseFormat::Rgba | BaseFormat::Rgb => [r, channel(1), channel(2), channel(3)],
            BaseFormat::LuminanceAlpha => [r, zero, zero, channel(1)],
            BaseFormat::Luminance | BaseFormat::Intensity => [r, zero, zero, one],
            BaseFormat::Alpha | BaseFormat::Depth => [zero, zero, zero, r],
        };
        for &k in picked(format) {
            out.extend_from_slice(rgba[k]);
        }
    }
    out
}

/// Stored texels as glGetTexImage gives them in `format` and `ty`.
fn convert(stored: &[u8], f: TexFormat, format: PixelFormat, ty: PixelType) -> Vec<u8> {
    let mut out = Vec::new();
    if f.is_depth() {
        for d in stored.chunks_exact(4) {
            let z = f32::from_ne_bytes([d[0], d[1], d[2], d[3]]).clamp(0.0, 1.0);
            push_depth(&mut out, z, ty);
        }
        return out;
    }
    let (_, _, size) = storage(f);
    for t in stored.chunks_exact(size) {
        // Table 6.1: the base components as R, G, B, A (unorm8).
        let rgba = match f.base() {
            BaseFormat::Rgba => [t[0], t[1], t[2], t[3]],
            BaseFormat::Rgb => [t[0], t[1], t[2], 255],
            BaseFormat::LuminanceAlpha => [t[0], 0, 0, t[1]],
            BaseFormat::Luminance | BaseFormat::Intensity => [t[0], 0, 0, 255],
            BaseFormat::Alpha | BaseFormat::Depth => [0, 0, 0, t[0]],
        };
        let picked = picked(format);
        for &k in picked {
            push_unorm8(&mut out, rgba[k], ty);
        }
    }
    out
}

/// A unorm8 component in `ty`: exact widening (c·257, c·16843009), or c·(1/255) in f32
/// (Mesa's product, which can differ from the quotient c/255 by one ulp: 51 gives
/// 0x3E4CCCCE, not 0x3E4CCCCD).
fn push_unorm8(out: &mut Vec<u8>, c: u8, ty: PixelType) {
    match ty {
        PixelType::UnsignedByte => out.push(c),
        PixelType::UnsignedShort => out.extend((u16::from(c) * 257).to_ne_bytes()),
        PixelType::UnsignedInt => out.extend((u32::from(c) * 16_843_009).to_ne_bytes()),
        PixelType::Float => out.extend((f32::from(c) * (1.0f32 / 255.0)).to_ne_bytes()),
        // Signed types by `pixel_types`' rule; a packed type is packed from FLOAT reads.
        PixelType::Byte | PixelType::Short | PixelType::Int | PixelType::Packed(_) => out.extend(
            pixel_types::component_bytes(f32::from(c) * (1.0f32 / 255.0), ty),
        ),
    }
}

/// A depth value in `ty`, by the readback rules of the driver (⌊255·z⌋, round(65535·z)).
fn push_depth(out: &mut Vec<u8>, z: f32, ty: PixelType) {
    match ty {
        PixelType::UnsignedByte => out.push((255.0 * z).floor() as u8),
        PixelType::UnsignedShort => out.extend(((65535.0 * z).round() as u16).to_ne_bytes()),
        PixelType::UnsignedInt => {
            out.extend(((4_294_967_295.0 * f64::from(z)).round() as u32).to_ne_bytes())
        }
        PixelType::Float => out.extend(z.to_ne_bytes()),
        PixelType::Byte | PixelType::Short | PixelType::Int | PixelType::Packed(_) => {
            out.extend(pixel_types::component_bytes(z, ty))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stored_legacy_texels_come_back_as_gl_gives_them() {
        // ALPHA8 stored as R8: RGBA (0, 0, 0, A); LUMINANCE8 as LUMINANCE: L itself.
        assert_eq!(
            convert(
                &[9],
                TexFormat::Alpha8,
                PixelFormat::Rgba,
                PixelType::UnsignedByte
            ),
            [0, 0, 0, 9]
        );
        assert_eq!(
            convert(
                &[9],
                TexFormat::Luminance8,
                PixelFormat::Rgba,
                PixelType::UnsignedByte
            ),
            [9, 0, 0, 255]
        );
        // RGBA texels as LUMINANCE: L = R, not R + G + B.
        assert_eq!(
            convert(
                &[10, 20, 30, 40],
                TexFormat::Rgba8,
                PixelFormat::Luminance,
                PixelType::UnsignedByte
            ),
            [10]
        );
        let wide = convert(
            &[255, 1],
            TexFormat::Luminance8Alpha8,
            PixelFormat::LuminanceAlpha,
            PixelType::UnsignedShort,
        );
        assert_eq!(
            wide,
            [0xffff_u16.to_ne_bytes(), 257_u16.to_ne_bytes()].concat()
        );
    }
}
