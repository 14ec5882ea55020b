//! Compressed images into the model's texture levels (GL 1.3 §3.8.3): a level keeps the
//! blocks as given and the texels decoded into its 8-bit storage (`compressed`), so both
//! paths upload and sample an ordinary RGB8 or RGBA8 level.
//!
//! glCompressedTexSubImage2D's checks of the level, in Mesa's answers (measured,
//! `tests/c/compressed.c`): a level never specified, or not compressed, or compressed in
//! another format is INVALID_OPERATION; a region outside the level INVALID_VALUE; an offset
//! that is not a multiple of 4, or a size that is not one unless it reaches the level's
//! edge, INVALID_OPERATION.

use std::sync::Arc;

use super::compressed::{
    decode, splice, CompressedImage, CompressedTexImage, CompressedTexSubImage,
};
use super::error::{GlError, GlResult};
use super::state::FixedState;
use super::texture::{blit, PixelData, PixelFormat, PixelType, TexFormat, TexLevel, TextureTarget};

impl FixedState {
    /// glCompressedTexImage2D (its argument checks made by the converter).
    pub(super) fn compressed_tex_image(&mut self, t: &CompressedTexImage) -> GlResult {
        if t.proxy {
            return Ok(());
        }
        let blocks = t.blocks();
        let texels = decode(t.format, t.width, t.height, &blocks);
        let level = TexLevel {
            internal_format: if t.format.has_alpha() {
                TexFormat::Rgba8
            } else {
                TexFormat::Rgb8
            },
            width: t.width,
            height: t.height,
            depth: 1,
            border: 0,
            data: Some(PixelData {
                format: PixelFormat::Rgba,
                ty: PixelType::UnsignedByte,
                bytes: texels.into(),
            }),
            compressed: Some(CompressedImage {
                format: t.format,
                bytes: blocks,
            }),
            requested: None,
        };
        let tex = self.bound_mut(TextureTarget::Texture2D)?;
        tex.set_level(t.level, level);
        tex.level_changed(t.level);
        Ok(())
    }

    /// glCompressedTexSubImage2D: the level's blocks spliced, the region's texels decoded
    /// into its copy.
    pub(super) fn compressed_tex_sub_image(&mut self, t: &CompressedTexSubImage) -> GlResult {
        let tex = self.bound_mut(TextureTarget::Texture2D)?;
        let level = tex.level_mut(t.level).ok_or(GlError::invalid_operation(
            "glCompressedTexSubImage2D of an unspecified level",
        ))?;
        let Some(image) = level.compressed.as_ref() else {
            return Err(GlError::invalid_operation(
                "glCompressedTexSubImage2D of an uncompressed level",
            ));
        };
        if image.format != t.format {
            return Err(GlError::invalid_operation(
                "glCompressedTexSubImage2D in another format than the level's",
            ));
        }
        if t.x < 0 || t.y < 0 || t.x + t.width > level.width || t.y + t.height > level.height {
            return Err(GlError::invalid_value(
                "glCompressedTexSubImage2D region outside the level",
            ));
        }
        let edge_or_block = |at: i32, size: i32, whole: i32| size % 4 == 0 || at + size == whole;
        if t.x % 4 != 0
            || t.y % 4 != 0
            || !edge_or_block(t.x, t.width, level.width)
            || !edge_or_block(t.y, t.height, level.height)
        {
            return Err(GlError::invalid_operation(
                "glCompressedTexSubImage2D of part of a block",
            ));
        }
        let (Some(data), Some(region)) = (&t.data, t.texels()) else {
            return Ok(());
        };
        let mut blocks = image.bytes.to_vec();
        splice(
            &mut blocks,
            level.width,
            t.format,
            (t.x, t.y),
            (t.width, t.height),
            data,
        );
        // Only the region's texels change: decoded once, written into the level's copy.
        if let (Some(texels), Some(decoded)) = (level.data.as_mut(), &region.data) {
            let mut bytes = texels.bytes.to_vec();
            let rect = [t.x, t.y, t.width, t.height].map(|v| v.max(0) as usize);
            blit(&mut bytes, level.width.max(0) as usize, decoded, rect, 4);
            texels.bytes = bytes.into();
        }
        level.compressed = Some(CompressedImage {
            format: t.format,
            bytes: Arc::from(blocks),
        });
        Ok(())
    }
}
