//! Texture objects on the native path: the model's names (u32, chosen by the caller as in
//! GL 1.0 style code) map to real objects from glGenTextures, made on the first BindTexture
//! of a name; name 0 is GL's own default texture of each target.
//!
//! Uploads use UNPACK_ALIGNMENT 1 (the model's pixel data is tightly packed, bottom row
//! first, which is GL's own row order). Every parameter is passed through, except
//! TEXTURE_COMPARE_FAIL_VALUE_ARB: Mesa does not expose ARB_shadow_ambient, so the model
//! records the fail value and the native path ignores it (a failed compare gives 0 here).

use std::collections::HashMap;
use std::ffi::c_void;

use crate::ff::compressed::{CompressedTexImage, CompressedTexSubImage};
use crate::ff::{CopyTexImage, TexImage, TexParam, TexSubImage, TextureTarget};

use super::bindings as gl;
use super::bindings::types::GLuint;
use super::conv;

/// The model's texture names and the GL objects made for them.
#[derive(Debug, Default)]
pub struct Textures {
    objects: HashMap<u32, GLuint>,
}

impl Textures {
    /// glBindTexture, generating the GL object on the first bind of a name.
    pub fn bind(&mut self, g: &gl::Gl, target: TextureTarget, name: u32) {
        let object = if name == 0 {
            0
        } else {
            *self.objects.entry(name).or_insert_with(|| {
                let mut id: GLuint = 0;
                // SAFETY: one name is written into `id`.
                unsafe { g.GenTextures(1, &mut id) };
                id
            })
        };
        // SAFETY: plain GL call on the current context.
        unsafe { g.BindTexture(conv::value(target), object) };
    }

    /// The GL object of a model name, if one was made.
    pub fn id(&self, name: u32) -> Option<GLuint> {
        self.objects.get(&name).copied()
    }

    /// How many GL objects exist.
    pub fn len(&self) -> usize {
        self.objects.len()
    }

    /// glDeleteTextures of these model names (GL reverts units bound to them to 0).
    pub fn delete(&mut self, g: &gl::Gl, names: &[u32]) {
        for name in names {
            if let Some(id) = self.objects.remove(name) {
                // SAFETY: `id` came from GenTextures on this context.
                unsafe { g.DeleteTextures(1, &id) };
            }
        }
    }

    /// glPrioritizeTextures of the objects made for these model names.
    pub fn prioritize(&mut self, g: &gl::Gl, given: &[(u32, f32)]) {
        for (name, priority) in given {
            if let Some(id) = self.objects.get(name) {
                // SAFETY: one name and one priority, read as GL reads them.
                unsafe { g.PrioritizeTextures(1, id, priority) };
            }
        }
    }

    /// glDeleteTextures on every object made.
    pub fn delete_all(&mut self, g: &gl::Gl) {
        for (_, id) in self.objects.drain() {
            // SAFETY: `id` came from GenTextures on this context.
            unsafe { g.DeleteTextures(1, &id) };
        }
    }
}

/// glTexImage1D / glTexImage2D / glTexImage3D into the bound texture; `None` data is a
/// NULL pointer (storage only). The model checked the data length against the size.
pub fn tex_image(g: &gl::Gl, t: &TexImage) {
    if t.target == TextureTarget::Texture3D {
        return super::texture_volume::tex_image_3d(g, t, super::texture_volume::Target::Texture);
    }
    // A readback slot was resolved to bytes before the model saw the command.
    let pixels = t
        .data
        .bytes()
        .map_or(std::ptr::null(), |d| d.as_ptr().cast::<c_void>());
    // The format as the program named it, so that Mesa stores the level at its bits
    // (`ff::texture_storage`).
    let internal = conv::int(
        t.requested
            .unwrap_or_else(|| conv::value(t.internal_format)),
    );
    let format = conv::value(t.format);
    let ty = conv::value(t.ty);
    // SAFETY: `pixels` is NULL or holds width·height·components·size bytes (model-checked);
    // UNPACK_ALIGNMENT is 1.
    unsafe {
        g.PixelStorei(gl::UNPACK_ALIGNMENT, 1);
        match t.target {
            TextureTarget::Texture1D => g.TexImage1D(
                gl::TEXTURE_1D,
                t.level,
                internal,
                t.width,
                t.border,
                format,
                ty,
                pixels,
            ),
            TextureTarget::Texture2D | TextureTarget::CubeMap | TextureTarget::CubeFace(_) => g
                .TexImage2D(
                    conv::value(t.target),
                    t.level,
                    internal,
                    t.width,
                    t.height,
                    t.border,
                    format,
                    ty,
                    pixels,
                ),
            // Sent by `texture_volume` above.
            TextureTarget::Texture3D => {}
        }
    }
}

/// glTexSubImage2D into the bound 2D texture or cube face.
pub fn tex_sub_image(g: &gl::Gl, t: &TexSubImage) {
    // SAFETY: the model checked that `data` holds the region's bytes.
    unsafe {
        g.PixelStorei(gl::UNPACK_ALIGNMENT, 1);
        g.TexSubImage2D(
            conv::value(t.target_2d()),
            t.level,
            t.x,
            t.y,
            t.width,
            t.height,
            conv::value(t.format),
            conv::value(t.ty),
            t.data
                .as_ref()
                .map_or(std::ptr::null(), |d| d.as_ptr().cast::<c_void>()),
        );
    }
}

/// glCompressedTexImage2D of TEXTURE_2D (or its proxy): the blocks as given, NULL's as
/// zeros.
pub fn compressed_tex_image(g: &gl::Gl, t: &CompressedTexImage) {
    let blocks = t.blocks();
    let target = if t.proxy {
        gl::PROXY_TEXTURE_2D
    } else {
        gl::TEXTURE_2D
    };
    // SAFETY: `blocks` holds the byte count passed.
    unsafe {
        g.CompressedTexImage2D(
            target,
            t.level,
            conv::value(t.format),
            t.width,
            t.height,
            0,
            blocks.len() as i32,
            blocks.as_ptr().cast::<c_void>(),
        )
    };
}

/// glCompressedTexSubImage2D into the bound 2D texture (NULL changes nothing).
pub fn compressed_tex_sub_image(g: &gl::Gl, t: &CompressedTexSubImage) {
    let Some(blocks) = &t.data else {
        return;
    };
    // SAFETY: `blocks` holds the byte count passed.
    unsafe {
        g.CompressedTexSubImage2D(
            gl::TEXTURE_2D,
            t.level,
            t.x,
            t.y,
            t.width,
            t.height,
            conv::value(t.format),
            blocks.len() as i32,
            blocks.as_ptr().cast::<c_void>(),
        )
    };
}

/// glCopyTexImage2D from the current read framebuffer into the bound 2D texture or cube face.
pub fn copy_tex_image(g: &gl::Gl, c: &CopyTexImage) {
    // SAFETY: plain GL call on the current context.
    unsafe {
        g.CopyTexImage2D(
            conv::value(c.target_2d()),
            c.level,
            c.requested
                .unwrap_or_else(|| conv::value(c.internal_format)),
            c.x,
            c.y,
            c.width,
            c.height,
            c.border,
        );
    }
}

/// glTexParameter on the bound texture of `target`. Returns `false` for the one parameter
/// with no native counterpart (the ARB_shadow_ambient fail value), which is not sent.
pub fn tex_parameter(g: &gl::Gl, target: TextureTarget, param: TexParam) -> bool {
    let t = conv::value(target);
    let int = |pname, value| {
        // SAFETY: plain GL call on the current context.
        unsafe { g.TexParameteri(t, pname, conv::int(value)) }
    };
    match param {
        TexParam::MinFilter(f) => int(gl::TEXTURE_MIN_FILTER, conv::value(f)),
        TexParam::MagFilter(f) => int(gl::TEXTURE_MAG_FILTER, conv::value(f)),
        TexParam::WrapS(w) => int(gl::TEXTURE_WRAP_S, conv::value(w)),
        TexParam::WrapT(w) => int(gl::TEXTURE_WRAP_T, conv::value(w)),
        TexParam::WrapR(w) => int(gl::TEXTURE_WRAP_R, conv::value(w)),
        TexParam::BorderColor(c) => {
            let c = c.to_array();
            // SAFETY: four floats.
            unsafe { g.TexParameterfv(t, gl::TEXTURE_BORDER_COLOR, c.as_ptr()) }
        }
        TexParam::CompareMode(m) => int(gl::TEXTURE_COMPARE_MODE, conv::value(m)),
        TexParam::CompareFunc(f) => int(gl::TEXTURE_COMPARE_FUNC, conv::value(f)),
        TexParam::DepthTextureMode(m) => int(gl::DEPTH_TEXTURE_MODE, conv::value(m)),
        // ARB_shadow_ambient is absent from Mesa: the model keeps the value, GL never sees it.
        TexParam::CompareFailValue(_) => return false,
        TexParam::GenerateMipmap(b) => int(gl::GENERATE_MIPMAP, u32::from(b)),
        // SAFETY (the four below): plain GL calls on the current context.
        TexParam::BaseLevel(l) => unsafe { g.TexParameteri(t, gl::TEXTURE_BASE_LEVEL, l) },
        TexParam::MaxLevel(l) => unsafe { g.TexParameteri(t, gl::TEXTURE_MAX_LEVEL, l) },
        TexParam::MinLod(v) => unsafe { g.TexParameterf(t, gl::TEXTURE_MIN_LOD, v) },
        TexParam::MaxLod(v) => unsafe { g.TexParameterf(t, gl::TEXTURE_MAX_LOD, v) },
        TexParam::LodBias(v) => unsafe { g.TexParameterf(t, gl::TEXTURE_LOD_BIAS, v) },
        TexParam::Priority(v) => unsafe { g.TexParameterf(t, gl::TEXTURE_PRIORITY, v) },
        TexParam::MaxAnisotropy(v) => unsafe {
            g.TexParameterf(t, glow::TEXTURE_MAX_ANISOTROPY_EXT, v)
        },
    }
    true
}
