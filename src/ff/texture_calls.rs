//! The texture calls of GL 1.1 beyond the 2D image and sub-image: glTexSubImage1D,
//! glCopyTexImage1D, glCopyTexSubImage1D, glCopyTexSubImage2D (GL 1.5 §3.8.2) and
//! glGetTexImage (§6.1.4): their Commands, converters and model rules. A copy leaves the
//! level's texels known only to the GPU (the model's CPU copy goes); glGetTexImage reads a
//! level into a readback slot (a C program's memory, packed with GL_PACK_ALIGNMENT, or a
//! script's `readback_<n>`).
//!
//! Errors, in Mesa's order: a target other than the call's INVALID_ENUM; a level outside
//! [0, log2(MAX_TEXTURE_SIZE)] INVALID_VALUE; a negative size INVALID_VALUE; a sub-image
//! of a level never specified INVALID_OPERATION; a region outside the level INVALID_VALUE.
//! glGetTexImage: STENCIL_INDEX INVALID_ENUM, DEPTH_COMPONENT of a colour texture or a
//! colour format (RED, GREEN and BLUE included) of a depth texture INVALID_OPERATION; a level never specified stores
//! nothing, without an error (Mesa).
//!
//! glTexSubImage1D/2D/3D check, in Mesa 22.3's `texsubimage_error_check` order: the target
//! (INVALID_ENUM), the level range and negative sizes (INVALID_VALUE,
//! [`sub_image_refusal`], before the format and type are looked at), then, as the model
//! applies the call, a level never specified (INVALID_OPERATION) and the region.

use super::api::Entry;
use super::args::{Args, LsbFirst};
use super::error::{GlError, GlResult};
use super::glenum::GlEnum;
use super::pixel_types;
use super::state::FixedState;
use super::texture::{
    check_format_pair, check_image_size, PixelFormat, PixelType, TexLevel, TextureTarget,
};
use super::{Command, CopyTexImage, TexSubImage};

/// glCopyTexSubImage1D/2D/3D: the framebuffer rectangle at (x, y) into the bound
/// texture's level at (xoffset, yoffset) (1D: yoffset 0, height 1), in the image at
/// `zoffset` (0 but for 3D).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct CopyTexSubImage {
    pub target: TextureTarget,
    pub level: i32,
    pub xoffset: i32,
    pub yoffset: i32,
    pub zoffset: i32,
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
}

/// glGetTexImage of the bound texture's level, into readback slot `slot`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct GetTexImage {
    pub target: TextureTarget,
    pub level: i32,
    pub format: PixelFormat,
    pub ty: PixelType,
    pub slot: u32,
}

/// glGetTexImage's target: an image target, TEXTURE_CUBE_MAP not (a face is; Mesa:
/// INVALID_ENUM).
fn image_target<A: Args>(c: &A) -> Result<TextureTarget, A::Error> {
    let t: TextureTarget = c.enm(0)?;
    if t == TextureTarget::CubeMap {
        return Err(c.unknown(0, vec!["GL_TEXTURE_CUBE_MAP_POSITIVE_X"]));
    }
    Ok(t)
}

fn target<A: Args>(c: &A, want: TextureTarget) -> Result<TextureTarget, A::Error> {
    let t: TextureTarget = c.enm(0)?;
    if t == want {
        Ok(t)
    } else {
        Err(c.unknown(0, vec![want.gl_name().unwrap_or("GL_TEXTURE_2D")]))
    }
}

/// glTexSubImage's INVALID_VALUE for a level outside [0, the target's highest] or a
/// negative size (`sizes`: the arguments of width, height and depth the call has), which
/// Mesa raises before it looks at the format and type; `None` when both are in range.
pub(crate) fn sub_image_refusal<A: Args>(
    c: &A,
    target: TextureTarget,
    sizes: &[usize],
) -> Result<Option<Command>, A::Error> {
    let level_refused = level_in_range(target, c.i32(1)?).is_err();
    let mut negative = false;
    for i in sizes {
        negative |= c.i32(*i)? < 0;
    }
    Ok((level_refused || negative).then(|| Command::Raise {
        error: super::error::GlErrorKind::InvalidValue,
        call: c.entry(),
    }))
}

/// The calls' Commands (`Ok(None)` for other calls).
pub fn texture_calls<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    Ok(Some(match c.entry() {
        Entry::TexSubImage1D => {
            c.count(7)?;
            target(c, TextureTarget::Texture1D)?;
            if let Some(refused) = sub_image_refusal(c, TextureTarget::Texture1D, &[3])? {
                return Ok(Some(refused));
            }
            let shape =
                super::index_pixels::image_shape(c, (c.i32(3)?, 1, None), 4, LsbFirst::Honoured)?;
            if let Some(refused) = pixel_types::refusal(c, shape.format, shape.ty) {
                return Ok(Some(refused));
            }
            let (format, ty, data) = pixel_types::model_sub_texels(c, 6, shape)?;
            Command::TexSubImage1D(TexSubImage {
                face: None,
                level: c.i32(1)?,
                x: c.i32(2)?,
                y: 0,
                z: 0,
                width: shape.width,
                height: 1,
                depth: 1,
                format,
                ty,
                data,
            })
        }
        Entry::CopyTexImage1D => {
            c.count(7)?;
            target(c, TextureTarget::Texture1D)?;
            let copy = CopyTexImage {
                face: None,
                requested: super::calls::requested_format(c, 2),
                level: c.i32(1)?,
                internal_format: c.enm(2)?,
                x: c.i32(3)?,
                y: c.i32(4)?,
                width: c.i32(5)?,
                height: 1,
                border: c.i32(6)?,
            };
            Command::CopyTexImage1D(super::texture_border::strip_copy(copy, 1))
        }
        Entry::CopyTexSubImage1D => {
            c.count(6)?;
            Command::CopyTexSubImage(CopyTexSubImage {
                target: target(c, TextureTarget::Texture1D)?,
                level: c.i32(1)?,
                xoffset: c.i32(2)?,
                yoffset: 0,
                zoffset: 0,
                x: c.i32(3)?,
                y: c.i32(4)?,
                width: c.i32(5)?,
                height: 1,
            })
        }
        Entry::CopyTexSubImage2D => {
            c.count(8)?;
            Command::CopyTexSubImage(CopyTexSubImage {
                target: super::calls::image_2d_target(c)?,
                level: c.i32(1)?,
                xoffset: c.i32(2)?,
                yoffset: c.i32(3)?,
                zoffset: 0,
                x: c.i32(4)?,
                y: c.i32(5)?,
                width: c.i32(6)?,
                height: c.i32(7)?,
            })
        }
        Entry::GetTexImage => {
            c.count(5)?;
            let (format, ty) = (c.enm(2)?, c.enm(3)?);
            if format == PixelFormat::ColorIndex {
                return Err(c.unknown(2, vec!["GL_RGBA"]));
            }
            if let Some(refused) = pixel_types::refusal(c, format, ty) {
                return Ok(Some(refused));
            }
            Command::GetTexImage(GetTexImage {
                target: image_target(c)?,
                level: c.i32(1)?,
                format,
                ty,
                slot: c.slot(4)?,
            })
        }
        _ => return Ok(None),
    }))
}

/// A level in [0, log2 of the target's largest size] (MAX_TEXTURE_SIZE; for 3D,
/// MAX_3D_TEXTURE_SIZE), else INVALID_VALUE.
pub(crate) fn level_in_range(target: TextureTarget, level: i32) -> GlResult {
    if (0..=target.max_level()).contains(&level) {
        Ok(())
    } else {
        Err(GlError::invalid_value(
            "level must be in [0, log2(MAX_TEXTURE_SIZE)] (3D: MAX_3D_TEXTURE_SIZE)",
        ))
    }
}

impl FixedState {
    fn bound_object_mut(
        &mut self,
        target: TextureTarget,
    ) -> GlResult<&mut super::texture::TextureObject> {
        let name = self.units[self.active_unit()].bound(target);
        self.texture_mut(target, name)
            .ok_or(GlError::invalid_operation(
                "bound name belongs to another target",
            ))
    }

    /// glCopyTexImage1D: a new level of `width` × 1 texels whose values only the GPU holds.
    pub(crate) fn copy_tex_image_1d(&mut self, c: &CopyTexImage) -> GlResult {
        check_image_size(c.level, c.width, 1, c.border)?;
        let tex = self.bound_object_mut(TextureTarget::Texture1D)?;
        tex.set_level(
            c.level,
            TexLevel {
                internal_format: c.internal_format,
                width: c.width,
                height: 1,
                depth: 1,
                border: 0,
                data: None,
                compressed: None,
                requested: c.requested,
            },
        );
        tex.level_changed(c.level);
        Ok(())
    }

    /// glCopyTexSubImage1D/2D/3D: the level must exist and hold the region, and a 3D
    /// level the image at `zoffset`.
    pub(crate) fn copy_tex_sub_image(&mut self, c: &CopyTexSubImage) -> GlResult {
        level_in_range(c.target, c.level)?;
        if c.width < 0 || c.height < 0 {
            return Err(GlError::invalid_value("negative width or height"));
        }
        let tex = self.bound_object_mut(c.target.binding())?;
        let level = tex
            .level_in_mut(c.target, c.level)
            .ok_or(GlError::invalid_operation(
                "glCopyTexSubImage of a level never specified",
            ))?;
        if c.xoffset < 0
            || c.yoffset < 0
            || c.zoffset < 0
            || c.xoffset + c.width > level.width
            || c.yoffset + c.height > level.height
            || c.zoffset >= level.depth
        {
            return Err(GlError::invalid_value(
                "glCopyTexSubImage region outside the level",
            ));
        }
        level.data = None;
        tex.level_changed_in(c.target, c.level);
        Ok(())
    }

    /// glGetTexImage's checks; `Ok(false)` when the level was never specified (nothing is
    /// stored).
    pub fn check_get_tex_image(&self, g: &GetTexImage) -> GlResult<bool> {
        level_in_range(g.target, g.level)?;
        if g.format == PixelFormat::StencilIndex {
            return Err(GlError::invalid_enum(
                "STENCIL_INDEX is not a texture image format",
            ));
        }
        let name = self.units[self.active_unit()].bound(g.target);
        let Some(level) = self
            .texture(g.target, name)
            .and_then(|t| t.level_in(g.target, g.level))
        else {
            return Ok(false);
        };
        // RED, GREEN and BLUE read one component of Table 6.1's R, G, B, A (§6.1.4), as
        // any colour format does: only a depth texture refuses them.
        let single = matches!(
            g.format,
            PixelFormat::Red | PixelFormat::Green | PixelFormat::Blue
        );
        if single && level.internal_format.is_depth() {
            return Err(GlError::invalid_operation(
                "a depth texture is read as DEPTH_COMPONENT only",
            ));
        }
        if !single {
            check_format_pair(level.internal_format, g.format)
                .map_err(|e| GlError::invalid_operation(e.rule))?;
        }
        Ok(true)
    }

    /// The level glGetTexImage reads, if it was specified.
    pub fn get_tex_image_level(&self, g: &GetTexImage) -> Option<&TexLevel> {
        let name = self.units[self.active_unit()].bound(g.target);
        self.texture(g.target, name)?.level_in(g.target, g.level)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::{GlErrorKind, TexData, TexFormat, TexImage};

    fn with_2d(w: i32, h: i32) -> FixedState {
        let mut s = FixedState::default();
        s.apply(&Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::Rgba8,
            width: w,
            height: h,
            depth: 1,
            border: 0,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            data: TexData::Bytes(vec![7u8; (w * h * 4) as usize].into()),
        }))
        .unwrap();
        s
    }

    fn copy(level: i32, xoffset: i32, width: i32, height: i32) -> Command {
        Command::CopyTexSubImage(CopyTexSubImage {
            target: TextureTarget::Texture2D,
            level,
            xoffset,
            yoffset: 0,
            zoffset: 0,
            x: 0,
            y: 0,
            width,
            height,
        })
    }

    #[test]
    fn copies_need_a_level_that_holds_the_region() {
        let mut s = with_2d(4, 4);
        let kind = |s: &mut FixedState, c| s.apply(&c).unwrap_err().kind;
        assert_eq!(
            kind(&mut s, copy(1, 0, 2, 2)),
            GlErrorKind::InvalidOperation
        );
        assert_eq!(kind(&mut s, copy(0, 3, 2, 2)), GlErrorKind::InvalidValue);
        assert_eq!(kind(&mut s, copy(0, 0, -1, 2)), GlErrorKind::InvalidValue);
        assert_eq!(kind(&mut s, copy(15, 0, 1, 1)), GlErrorKind::InvalidValue);
        // A failed copy keeps the CPU copy; a copy drops it.
        assert!(s.default_2d.level(0).unwrap().data.is_some());
        s.apply(&copy(0, 2, 2, 4)).unwrap();
        assert!(s.default_2d.level(0).unwrap().data.is_none());
    }

    #[test]
    fn get_tex_image_checks_format_against_the_level() {
        let s = with_2d(2, 2);
        let get = |level, format| GetTexImage {
            target: TextureTarget::Texture2D,
            level,
            format,
            ty: PixelType::UnsignedByte,
            slot: 0,
        };
        assert_eq!(s.check_get_tex_image(&get(0, PixelFormat::Rgb)), Ok(true));
        assert_eq!(s.check_get_tex_image(&get(3, PixelFormat::Rgb)), Ok(false));
        let kind = |g| s.check_get_tex_image(&g).unwrap_err().kind;
        assert_eq!(kind(get(-1, PixelFormat::Rgb)), GlErrorKind::InvalidValue);
        assert_eq!(
            kind(get(0, PixelFormat::StencilIndex)),
            GlErrorKind::InvalidEnum
        );
        assert_eq!(
            kind(get(0, PixelFormat::DepthComponent)),
            GlErrorKind::InvalidOperation
        );
    }
}
