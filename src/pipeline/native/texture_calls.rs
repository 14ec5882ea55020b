//! glTexSubImage1D, glCopyTexImage1D, glCopyTexSubImage1D/2D/3D and glGetTexImage as the real
//! legacy calls on the bound texture (the model checked them first). glGetTexImage reads
//! with PACK_ALIGNMENT 1 into a readback slot: the driver's own conversions from each
//! legacy internal format to the asked format and type are the oracle.

use std::ffi::c_void;

use crate::ff::texture::{volume_size, TextureTarget};
use crate::ff::texture_calls::{CopyTexSubImage, GetTexImage};
use crate::ff::{CopyTexImage, FixedState, TexSubImage};
use crate::pipeline::Readback;

use super::bindings as gl;
use super::conv;

/// glTexSubImage1D into the bound 1D texture.
pub fn tex_sub_image_1d(g: &gl::Gl, t: &TexSubImage) {
    // SAFETY: the model checked that `data` holds the row's bytes (NULL: GL reads nothing).
    unsafe {
        g.PixelStorei(gl::UNPACK_ALIGNMENT, 1);
        g.TexSubImage1D(
            gl::TEXTURE_1D,
            t.level,
            t.x,
            t.width,
            conv::value(t.format),
            conv::value(t.ty),
            t.data
                .as_ref()
                .map_or(std::ptr::null(), |d| d.as_ptr().cast::<c_void>()),
        );
    }
}

/// glCopyTexImage1D from the current read framebuffer.
pub fn copy_tex_image_1d(g: &gl::Gl, c: &CopyTexImage) {
    // SAFETY: plain GL call on the current context.
    unsafe {
        g.CopyTexImage1D(
            gl::TEXTURE_1D,
            c.level,
            conv::value(c.internal_format),
            c.x,
            c.y,
            c.width,
            c.border,
        );
    }
}

/// glCopyTexSubImage1D/2D from the current read framebuffer.
pub fn copy_tex_sub_image(g: &gl::Gl, c: &CopyTexSubImage) {
    // SAFETY: plain GL calls on the current context.
    unsafe {
        match c.target {
            TextureTarget::Texture1D => {
                g.CopyTexSubImage1D(gl::TEXTURE_1D, c.level, c.xoffset, c.x, c.y, c.width)
            }
            TextureTarget::Texture2D | TextureTarget::CubeMap | TextureTarget::CubeFace(_) => g
                .CopyTexSubImage2D(
                    conv::value(c.target),
                    c.level,
                    c.xoffset,
                    c.yoffset,
                    c.x,
                    c.y,
                    c.width,
                    c.height,
                ),
            TextureTarget::Texture3D => g.CopyTexSubImage3D(
                gl::TEXTURE_3D,
                c.level,
                c.xoffset,
                c.yoffset,
                c.zoffset,
                c.x,
                c.y,
                c.width,
                c.height,
            ),
        }
    }
}

/// glGetTexImage of a specified level (`None` for a level never specified: GL stores
/// nothing).
pub fn get_tex_image(g: &gl::Gl, state: &FixedState, r: &GetTexImage) -> Option<Readback> {
    let level = state.get_tex_image_level(r)?;
    let (w, h, d) = (level.width, level.height, level.depth);
    let mut bytes = vec![0u8; volume_size(r.format, r.ty, w, h, d)];
    let (target, depth) = match r.target {
        TextureTarget::Texture1D => (gl::TEXTURE_1D, None),
        TextureTarget::Texture2D | TextureTarget::CubeMap | TextureTarget::CubeFace(_) => {
            (conv::value(r.target), None)
        }
        TextureTarget::Texture3D => (gl::TEXTURE_3D, Some(d.max(0) as u32)),
    };
    // SAFETY: `bytes` holds the level's width·height·depth groups, PACK_ALIGNMENT is 1 and
    // the image parameters are never set here.
    unsafe {
        g.PixelStorei(gl::PACK_ALIGNMENT, 1);
        g.GetTexImage(
            target,
            r.level,
            conv::value(r.format),
            conv::value(r.ty),
            bytes.as_mut_ptr().cast::<c_void>(),
        );
    }
    Some(Readback {
        width: w as u32,
        height: h as u32,
        depth,
        format: r.format,
        ty: r.ty,
        bytes,
    })
}
