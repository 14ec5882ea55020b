//! GL 1.2's 3D textures (EXT_texture3D): the converters of glTexImage3D, glTexSubImage3D
//! and glCopyTexSubImage3D (and their EXT names), and the model's rules that only volumes
//! have; `apply` and `texture_calls` hold the rules every target shares. The errors are
//! Mesa 22.3's (measured, `tests/c/tex3d.c`), in its order:
//! - a target other than TEXTURE_3D (glTexImage3D: or PROXY_TEXTURE_3D): INVALID_ENUM;
//! - a level outside [0, log2(MAX_3D_TEXTURE_SIZE)] = [0, 11], a size below 0, a border:
//!   INVALID_VALUE;
//! - an unknown format or type: INVALID_ENUM; an unknown internal format: INVALID_VALUE
//!   (a script names the formats instead);
//! - DEPTH_COMPONENT data for a colour format or colour data for a depth one, STENCIL_INDEX
//!   data, and a depth internal format at all (ARB_depth_texture has 1D and 2D depth
//!   textures only): INVALID_OPERATION;
//! - a side above MAX_3D_TEXTURE_SIZE >> level (level 1 holds at most 1024): INVALID_VALUE;
//! - a sub-image or copy into a level never specified: INVALID_OPERATION; a region outside
//!   the level (a copy: zoffset outside [0, depth)): INVALID_VALUE. An empty region at the
//!   level's edge is no error, one past it is.
//!
//! A proxy image (PROXY_TEXTURE_3D, GL 1.5 §3.8.11) raises the same errors but the size
//! one, and may have a border of 1 (included in its sizes, as GL's; Mesa, measured): a volume too large for its level leaves the proxy level unspecified (every query 0,
//! the internal format RGBA), one that fits specifies it as a real image would. A display
//! list never keeps a proxy call, which runs at once (Mesa's `save_TexImage3D`). The
//! proxies of glTexImage1D and glTexImage2D (PROXY_TEXTURE_1D, _2D, _CUBE_MAP) follow the
//! same rules and are modelled here with it.
//!
//! A volume's data is `depth` images of `height` rows, the first (r = 0) first; a
//! sub-image patches it image by image.

use super::api::Entry;
use super::args::{Args, LsbFirst};
use super::error::{GlError, GlResult};
use super::pixel_types;
use super::state::FixedState;
use super::texture::{
    blit, check_format_pair, check_proxy_arguments, check_volume_arguments, proxy_fits,
    volume_fits, TexFormat, TexLevel, TextureTarget, MAX_3D_TEXTURE_SIZE,
    MAX_CUBE_MAP_TEXTURE_SIZE, MAX_TEXTURE_SIZE,
};
use super::texture_calls::CopyTexSubImage;
use super::{Command, TexImage, TexSubImage};

/// The calls' Commands (`Ok(None)` for other calls).
pub fn volume_calls<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    Ok(Some(match c.entry() {
        Entry::TexImage3D | Entry::TexImage3DEXT => {
            c.count(10)?;
            let proxy = c.pname(0, &["GL_TEXTURE_3D", "GL_PROXY_TEXTURE_3D"])? != "GL_TEXTURE_3D";
            let shape = super::index_pixels::image_shape(
                c,
                (c.i32(3)?, c.i32(4)?, Some(c.i32(5)?)),
                7,
                LsbFirst::Honoured,
            )?;
            if let Some(refused) = pixel_types::refusal(c, shape.format, shape.ty) {
                return Ok(Some(refused));
            }
            let (format, ty, data) = pixel_types::model_tex_data(c, 9, shape)?;
            let image = TexImage {
                requested: super::calls::requested_format(c, 2),
                target: TextureTarget::Texture3D,
                level: c.i32(1)?,
                internal_format: super::calls::internal_format(c, 2)?,
                width: shape.width,
                height: shape.height,
                depth: c.i32(5)?,
                border: c.i32(6)?,
                format,
                ty,
                data,
            };
            if proxy {
                Command::ProxyTexImage(image)
            } else {
                Command::TexImage(super::texture_border::strip_image(image, 3))
            }
        }
        Entry::TexSubImage3D | Entry::TexSubImage3DEXT => {
            c.count(11)?;
            texture_3d(c)?;
            let refusal = super::texture_calls::sub_image_refusal;
            if let Some(refused) = refusal(c, TextureTarget::Texture3D, &[5, 6, 7])? {
                return Ok(Some(refused));
            }
            let shape = super::index_pixels::image_shape(
                c,
                (c.i32(5)?, c.i32(6)?, Some(c.i32(7)?)),
                8,
                LsbFirst::Honoured,
            )?;
            if let Some(refused) = pixel_types::refusal(c, shape.format, shape.ty) {
                return Ok(Some(refused));
            }
            let (format, ty, data) = pixel_types::model_sub_texels(c, 10, shape)?;
            Command::TexSubImage3D(TexSubImage {
                face: None,
                level: c.i32(1)?,
                x: c.i32(2)?,
                y: c.i32(3)?,
                z: c.i32(4)?,
                width: shape.width,
                height: shape.height,
                depth: c.i32(7)?,
                format,
                ty,
                data,
            })
        }
        Entry::CopyTexSubImage3D | Entry::CopyTexSubImage3DEXT => {
            c.count(9)?;
            texture_3d(c)?;
            Command::CopyTexSubImage(CopyTexSubImage {
                target: TextureTarget::Texture3D,
                level: c.i32(1)?,
                xoffset: c.i32(2)?,
                yoffset: c.i32(3)?,
                zoffset: c.i32(4)?,
                x: c.i32(5)?,
                y: c.i32(6)?,
                width: c.i32(7)?,
                height: c.i32(8)?,
            })
        }
        _ => return Ok(None),
    }))
}

/// Argument 0 is GL_TEXTURE_3D.
fn texture_3d<A: Args>(c: &A) -> Result<(), A::Error> {
    c.pname(0, &["GL_TEXTURE_3D"]).map(|_| ())
}

/// glTexImage3D's checks before the formats: [`check_volume_arguments`].
pub(crate) fn check_volume_image(t: &TexImage) -> GlResult {
    check_volume_arguments(t.level, [t.width, t.height, t.depth], t.border)
}

/// glTexImage3D's checks after the format pair: no depth internal format (ARB_depth_texture
/// has none for TEXTURE_3D; Mesa: INVALID_OPERATION), then every side within
/// MAX_3D_TEXTURE_SIZE >> level (INVALID_VALUE).
pub(crate) fn check_volume_level(t: &TexImage) -> GlResult {
    check_volume_format(t.internal_format)?;
    if !volume_fits(t.level, [t.width, t.height, t.depth]) {
        return Err(GlError::invalid_value(
            "width, height and depth must be in [0, MAX_3D_TEXTURE_SIZE >> level]",
        ));
    }
    Ok(())
}

/// A depth internal format is no 3D texture format (INVALID_OPERATION).
fn check_volume_format(internal: TexFormat) -> GlResult {
    if internal.is_depth() {
        return Err(GlError::invalid_operation(
            "depth textures are 1D or 2D (ARB_depth_texture): no TEXTURE_3D depth format",
        ));
    }
    Ok(())
}

/// glTexSubImage3D's checks before the level is looked up (Mesa's order): the level in
/// [0, log2(MAX_3D_TEXTURE_SIZE)], no size below 0 — INVALID_VALUE.
pub(crate) fn check_sub_volume(t: &TexSubImage) -> GlResult {
    super::texture_calls::level_in_range(TextureTarget::Texture3D, t.level)?;
    if t.width < 0 || t.height < 0 || t.depth < 0 {
        return Err(GlError::invalid_value(
            "width, height and depth must be 0 or more",
        ));
    }
    Ok(())
}

/// Patches the tight `t.depth` images of `t.data` into `dst`, the tight images of a level
/// `width × height` texels each, at (x, y, z); the region is checked by the caller.
pub(crate) fn blit_volume(dst: &mut [u8], (width, height): (i32, i32), t: &TexSubImage) {
    let Some(data) = &t.data else {
        return;
    };
    let pixel = t.format.components() * t.ty.size();
    let level_image = width.max(0) as usize * height.max(0) as usize * pixel;
    let sub_image = t.width.max(0) as usize * t.height.max(0) as usize * pixel;
    let rect = [t.x, t.y, t.width, t.height].map(|v| v.max(0) as usize);
    for k in 0..t.depth.max(0) as usize {
        let at = (t.z.max(0) as usize + k) * level_image;
        let (Some(to), Some(from)) = (
            dst.get_mut(at..at + level_image),
            data.get(k * sub_image..(k + 1) * sub_image),
        ) else {
            return;
        };
        blit(to, width.max(0) as usize, from, rect, pixel);
    }
}

impl FixedState {
    /// glTexImage1D/2D/3D of a proxy target (GL 1.5 §3.8.11): the argument and format
    /// errors of a real image; then the proxy level is the image's (data aside) if it fits
    /// its level, else unspecified, without an error. A cube map's image fits only when
    /// square (Mesa, measured: `tests/c/proxy_tex.c`; a real face is INVALID_VALUE).
    pub(crate) fn proxy_tex_image(&mut self, t: &TexImage) -> GlResult {
        let max_level = t.target.max_level();
        check_proxy_arguments(t.level, max_level, [t.width, t.height, t.depth], t.border)?;
        check_format_pair(t.internal_format, t.format)?;
        let (w, h, d, b) = (t.width, t.height, t.depth, t.border);
        let (proxy, fits) = match t.target {
            TextureTarget::Texture3D => {
                check_volume_format(t.internal_format)?;
                let fits = proxy_fits(t.level, MAX_3D_TEXTURE_SIZE, &[w, h, d], b);
                (&mut self.proxy_3d, fits)
            }
            TextureTarget::Texture1D => {
                let fits = proxy_fits(t.level, MAX_TEXTURE_SIZE, &[w], b);
                (&mut self.proxy_1d, fits)
            }
            TextureTarget::Texture2D => {
                let fits = proxy_fits(t.level, MAX_TEXTURE_SIZE, &[w, h], b);
                (&mut self.proxy_2d, fits)
            }
            TextureTarget::CubeMap | TextureTarget::CubeFace(_) => {
                let fits = proxy_fits(t.level, MAX_CUBE_MAP_TEXTURE_SIZE, &[w, h], b);
                (&mut self.proxy_cube_map, fits && w == h)
            }
        };
        if fits {
            proxy.set_level(
                t.level,
                TexLevel {
                    internal_format: t.internal_format,
                    width: t.width,
                    height: t.height,
                    depth: t.depth,
                    border: t.border,
                    data: None,
                    compressed: None,
                    requested: t.requested,
                },
            );
        } else if let Some(l) = usize::try_from(t.level)
            .ok()
            .and_then(|l| proxy.levels.get_mut(l))
        {
            *l = None;
        }
        Ok(())
    }
}
