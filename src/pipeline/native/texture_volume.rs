//! GL 1.2's 3D texture calls as the real ones on the bound texture (the model checked
//! them first): glTexImage3D (a proxy image too, which Mesa checks again and nothing
//! draws) and glTexSubImage3D, with UNPACK_ALIGNMENT 1 and the other unpack parameters at
//! their defaults (the model's data is tight images of tight rows, the first image first).

use std::ffi::c_void;

use crate::ff::glenum::registry;
use crate::ff::{TexImage, TexSubImage};

use super::bindings as gl;
use super::conv;

/// glTexImage3D of TEXTURE_3D or of PROXY_TEXTURE_3D; `None` data is a NULL pointer
/// (storage only).
pub fn tex_image_3d(g: &gl::Gl, t: &TexImage, target: Target) {
    let pixels = t
        .data
        .bytes()
        .map_or(std::ptr::null(), |d| d.as_ptr().cast::<c_void>());
    let target = match target {
        Target::Texture => gl::TEXTURE_3D,
        Target::Proxy => registry::PROXY_TEXTURE_3D,
    };
    // SAFETY: `pixels` is NULL or holds width·height·depth groups (model-checked);
    // UNPACK_ALIGNMENT is 1 and IMAGE_HEIGHT and SKIP_IMAGES are never set here.
    unsafe {
        g.PixelStorei(gl::UNPACK_ALIGNMENT, 1);
        g.TexImage3D(
            target,
            t.level,
            conv::int(conv::value(t.internal_format)),
            t.width,
            t.height,
            t.depth,
            t.border,
            conv::value(t.format),
            conv::value(t.ty),
            pixels,
        );
    }
}

/// Which target a glTexImage3D names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    Texture,
    Proxy,
}

/// glTexSubImage3D into the bound 3D texture.
pub fn tex_sub_image_3d(g: &gl::Gl, t: &TexSubImage) {
    // SAFETY: the model checked that `data` holds the region's bytes.
    unsafe {
        g.PixelStorei(gl::UNPACK_ALIGNMENT, 1);
        g.TexSubImage3D(
            gl::TEXTURE_3D,
            t.level,
            t.x,
            t.y,
            t.z,
            t.width,
            t.height,
            t.depth,
            conv::value(t.format),
            conv::value(t.ty),
            t.data
                .as_ref()
                .map_or(std::ptr::null(), |d| d.as_ptr().cast::<c_void>()),
        );
    }
}
