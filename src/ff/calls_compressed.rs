//! The compressed-texture calls of GL 1.3 (and their ARB names) as Commands, with Mesa
//! 22.3's errors, measured with OSMesa (`tests/c/compressed.c`):
//! - glCompressedTexImage2D: a target other than TEXTURE_2D or PROXY_TEXTURE_2D, or a
//!   format that is not a decoded S3TC one (`compressed`; the generic COMPRESSED_RGB …
//!   and uncompressed formats too) is INVALID_ENUM; then a level outside [0, 14] or a size
//!   outside [0, MAX_TEXTURE_SIZE] INVALID_VALUE; a border INVALID_OPERATION; an
//!   imageSize other than the blocks' INVALID_VALUE. Sizes need not be multiples of 4.
//! - glCompressedTexSubImage2D: INVALID_ENUM for another target or a generic format,
//!   INVALID_OPERATION for an uncompressed one; the level's own checks are the model's
//!   (`apply_compressed`).
//! - glCompressedTexImage1D/3D and their sub-images: INVALID_ENUM, whatever the format —
//!   Mesa has no 1D or 3D S3TC image.
//!
//! The blocks are read as given: the unpack parameters do not apply (Mesa, without
//! ARB_compressed_texture_pixel_storage's block sizes). A call whose blocks exceed 64 MiB
//! is refused before anything is read (INVALID_VALUE from C, an error naming the budget in
//! a script).

use std::sync::Arc;

use super::api::{CType, Entry};
use super::args::Args;
use super::client::ArrayData;
use super::command::Command;
use super::compressed::{CompressedFormat, CompressedTexImage, CompressedTexSubImage};
use super::error::GlErrorKind;
use super::glenum::registry as r;
use super::glenum::GlEnum;
use super::texture::{MAX_TEXTURE_LEVEL, MAX_TEXTURE_SIZE};

/// The largest block data a call may carry.
pub const MAX_COMPRESSED_BYTES: u64 = 64 << 20;

/// The generic compressed internal formats (GL 1.3 Table 3.17), which glTexImage takes
/// and the compressed calls refuse with INVALID_ENUM.
const GENERIC: [u32; 6] = [
    r::COMPRESSED_ALPHA,
    r::COMPRESSED_LUMINANCE,
    r::COMPRESSED_LUMINANCE_ALPHA,
    r::COMPRESSED_INTENSITY,
    r::COMPRESSED_RGB,
    r::COMPRESSED_RGBA,
];

/// The calls' Commands (`Ok(None)` for other calls).
pub fn compressed_calls<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    let raise = |error| {
        Ok(Some(Command::Raise {
            error,
            call: c.entry(),
        }))
    };
    Ok(Some(match c.entry() {
        Entry::CompressedTexImage2D | Entry::CompressedTexImage2DARB => {
            c.count(8)?;
            let target = c.token(0)?;
            let level = c.i32(1)?;
            let (width, height, border, image_size) = (c.i32(3)?, c.i32(4)?, c.i32(5)?, c.i32(6)?);
            if target != r::TEXTURE_2D && target != r::PROXY_TEXTURE_2D {
                return raise(GlErrorKind::InvalidEnum);
            }
            let Some(format) = CompressedFormat::from_gl_value(c.token(2)?) else {
                return raise(GlErrorKind::InvalidEnum);
            };
            if let Err(e) = check_image(format, level, width, height, border, image_size) {
                return raise(e);
            }
            let proxy = target == r::PROXY_TEXTURE_2D;
            Command::CompressedTexImage2D(CompressedTexImage {
                proxy,
                level,
                format,
                width,
                height,
                data: if proxy {
                    None
                } else {
                    blocks(c, 7, image_size)?
                },
            })
        }
        Entry::CompressedTexSubImage2D | Entry::CompressedTexSubImage2DARB => {
            c.count(9)?;
            if c.token(0)? != r::TEXTURE_2D {
                return raise(GlErrorKind::InvalidEnum);
            }
            let token = c.token(6)?;
            let Some(format) = CompressedFormat::from_gl_value(token) else {
                return raise(if GENERIC.contains(&token) {
                    GlErrorKind::InvalidEnum
                } else {
                    GlErrorKind::InvalidOperation
                });
            };
            let image_size = c.i32(7)?;
            let (width, height) = (c.i32(4)?, c.i32(5)?);
            if width < 0 || height < 0 || image_size < 0 {
                return raise(GlErrorKind::InvalidValue);
            }
            if u64::try_from(image_size).ok() != Some(format.image_size(width, height)) {
                return raise(GlErrorKind::InvalidValue);
            }
            Command::CompressedTexSubImage2D(CompressedTexSubImage {
                level: c.i32(1)?,
                x: c.i32(2)?,
                y: c.i32(3)?,
                width,
                height,
                format,
                data: blocks(c, 8, image_size)?,
            })
        }
        Entry::CompressedTexImage1D
        | Entry::CompressedTexImage1DARB
        | Entry::CompressedTexImage3D
        | Entry::CompressedTexImage3DARB
        | Entry::CompressedTexSubImage1D
        | Entry::CompressedTexSubImage1DARB
        | Entry::CompressedTexSubImage3D
        | Entry::CompressedTexSubImage3DARB => return raise(GlErrorKind::InvalidEnum),
        _ => return Ok(None),
    }))
}

/// glCompressedTexImage2D's checks in Mesa's order (INVALID_VALUE for the level and
/// sizes, INVALID_OPERATION for a border, INVALID_VALUE for the byte count).
pub fn check_image(
    format: CompressedFormat,
    level: i32,
    width: i32,
    height: i32,
    border: i32,
    image_size: i32,
) -> Result<(), GlErrorKind> {
    if !(0..=MAX_TEXTURE_LEVEL).contains(&level)
        || !(0..=MAX_TEXTURE_SIZE).contains(&width)
        || !(0..=MAX_TEXTURE_SIZE).contains(&height)
    {
        return Err(GlErrorKind::InvalidValue);
    }
    if border != 0 {
        return Err(GlErrorKind::InvalidOperation);
    }
    if u64::try_from(image_size).ok() != Some(format.image_size(width, height)) {
        return Err(GlErrorKind::InvalidValue);
    }
    Ok(())
}

/// `n` bytes of blocks at argument `i`, or `None` for NULL; over [`MAX_COMPRESSED_BYTES`]
/// refused before reading.
fn blocks<A: Args>(c: &A, i: usize, n: i32) -> Result<Option<Arc<[u8]>>, A::Error> {
    let n = u64::try_from(n).unwrap_or(0);
    if n > MAX_COMPRESSED_BYTES {
        return Err(c.bad(i, "compressed data of at most 64 MiB"));
    }
    if matches!(c.array_data(i)?, ArrayData::Null) {
        return Ok(None);
    }
    let values = c.array_as(i, n as usize, CType::UByte)?;
    Ok(Some(values.into_iter().map(|v| v as u8).collect()))
}
