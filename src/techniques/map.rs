//! What every shadow-map technique reads from the scene's `[shadow]` table, the texture
//! names and readback slots they use, the ramp textures, and the parameters of a map
//! texture.
//!
//! **Outside the map is lit.** Fragments whose (s/q, t/q) fall outside the light's volume
//! read the border: CLAMP_TO_BORDER with a white border (depth 1, the far plane; intensity
//! one) makes them lit, which is what the truth says of a surface the light's frustum does
//! not cover. The era's programs often left CLAMP and got streaks; the border is the
//! documented fix of the time (GL 1.3) and keeps the comparison about precision and bias.

use crate::vocab::{DepthBits, DepthRule, MapFilter, PolygonOffset, ReadbackRule, TechniqueId};
use std::sync::Arc;

use glam::Vec4;

use crate::ff::{
    Command, Filter, PixelFormat, PixelType, TexData, TexFormat, TexImage, TexParam, TextureTarget,
    Wrap,
};
use crate::scene::Scene;

use super::{FramebufferNeeds, TechniqueError};

/// The texture object names the techniques bind (GL 1.1 lets a program choose them).
pub const MAP_TEXTURE: u32 = 1;
/// The 256-texel 1D intensity ramp, CLAMP_TO_EDGE (the fragment's depth, or big digit).
pub const RAMP_TEXTURE: u32 = 2;
/// The same ramp with REPEAT (the little digit, at 256·s).
pub const REPEAT_RAMP_TEXTURE: u32 = 3;

/// The readback slot the map bytes go through (glReadPixels → glTexImage2D).
pub const MAP_SLOT: u32 = 1;
/// The readback slot `--depth-map` uses when a technique keeps no map bytes of its own.
pub const MAP_IMAGE_SLOT: u32 = 2;

/// The `[shadow]` settings a map technique uses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapSettings {
    /// Edge of the square map, in texels.
    pub size: u32,
    /// The light pass's depth buffer.
    pub depth: DepthBits,
    pub offset: Option<PolygonOffset>,
    pub filter: MapFilter,
    pub readback: ReadbackRule,
}

impl MapSettings {
    pub fn of(scene: &Scene) -> MapSettings {
        MapSettings {
            size: scene.shadow.map_size,
            depth: scene.shadow.depth,
            offset: scene.shadow.offset(),
            filter: scene.shadow.filter,
            readback: scene.shadow.readback,
        }
    }

    /// The shared framebuffer: large enough for the image and the map.
    pub fn framebuffer(&self, scene: &Scene, stencil: bool) -> FramebufferNeeds {
        FramebufferNeeds {
            width: scene.image.width.max(self.size),
            height: scene.image.height.max(self.size),
            depth: self.depth,
            stencil,
        }
    }

    /// Fails when a stencil technique is asked for a depth buffer without stencil (D16).
    pub fn check_stencil(&self, technique: TechniqueId) -> Result<(), TechniqueError> {
        match self.depth {
            DepthBits::D16 => Err(TechniqueError::NeedsStencil {
                technique,
                bits: 16,
            }),
            DepthBits::D24 | DepthBits::D32F => Ok(()),
        }
    }

    /// GL filter of the map.
    pub fn gl_filter(&self) -> Filter {
        match self.filter {
            MapFilter::Nearest => Filter::Nearest,
            MapFilter::Linear => Filter::Linear,
        }
    }

    /// The depth texture format matching the light pass's buffer.
    pub fn depth_format(&self) -> TexFormat {
        match self.depth {
            DepthBits::D16 => TexFormat::DepthComponent16,
            DepthBits::D24 => TexFormat::DepthComponent24,
            DepthBits::D32F => TexFormat::DepthComponent32F,
        }
    }
}

/// Parameters of the bound 2D map: `filter` for both filters (no mipmaps), CLAMP_TO_BORDER
/// with a white border (see the module note).
pub fn map_parameters(filter: Filter) -> Vec<Command> {
    let param = |param| Command::TexParameter {
        target: TextureTarget::Texture2D,
        param,
    };
    vec![
        param(TexParam::MinFilter(filter)),
        param(TexParam::MagFilter(filter)),
        param(TexParam::WrapS(Wrap::ClampToBorder)),
        param(TexParam::WrapT(Wrap::ClampToBorder)),
        param(TexParam::BorderColor(Vec4::ONE)),
    ]
}

/// The 256-texel 1D INTENSITY8 ramp, texel i = i (value i/255), NEAREST, bound as `name` on
/// the active unit: at coordinate s it reads floor(256·s) (clamped to 255 with
/// CLAMP_TO_EDGE; wrapped with REPEAT) — the fragment's 8-bit digit.
pub fn ramp(name: u32, wrap: Wrap) -> Vec<Command> {
    let param = |param| Command::TexParameter {
        target: TextureTarget::Texture1D,
        param,
    };
    let texels: Arc<[u8]> = (0..=255u8).collect::<Vec<u8>>().into();
    vec![
        Command::BindTexture {
            target: TextureTarget::Texture1D,
            name,
        },
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture1D,
            level: 0,
            internal_format: TexFormat::Intensity8,
            width: 256,
            height: 1,
            depth: 1,
            border: 0,
            format: PixelFormat::Luminance,
            ty: PixelType::UnsignedByte,
            data: TexData::Bytes(texels),
        }),
        param(TexParam::MinFilter(Filter::Nearest)),
        param(TexParam::MagFilter(Filter::Nearest)),
        param(TexParam::WrapS(wrap)),
    ]
}

/// glReadPixels of the map's `size`² corner into [`MAP_SLOT`].
pub fn read_map(size: u32, format: PixelFormat, ty: PixelType) -> Command {
    read_corner(size, format, ty, MAP_SLOT)
}

/// glReadPixels of the framebuffer's `size`² corner (where map passes draw) into `slot`.
pub fn read_corner(size: u32, format: PixelFormat, ty: PixelType, slot: u32) -> Command {
    Command::ReadPixels(crate::ff::ReadPixels {
        x: 0,
        y: 0,
        width: size as i32,
        height: size as i32,
        format,
        ty,
        slot,
    })
}

/// How an integer depth map travels from the depth buffer to the texture: one `ty`
/// (UNSIGNED_BYTE for 8-bit maps, UNSIGNED_SHORT for the two digits) per texel, by the
/// scene's readback rule. `Driver`: glReadPixels with the integer type, the driver's own
/// conversion (Mesa truncates bytes and rounds shorts, `gpu::readback`). `Truncate` /
/// `Round`: glReadPixels as FLOAT and the program converts on the CPU
/// ([`TexData::ConvertedDepth`]) — the same rule on every driver.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DepthTransfer {
    pub ty: PixelType,
    pub rule: ReadbackRule,
}

impl DepthTransfer {
    /// The readback into [`MAP_SLOT`].
    pub fn read(&self, size: u32) -> Command {
        let ty = match self.rule {
            ReadbackRule::Driver => self.ty,
            ReadbackRule::Cpu(_) => PixelType::Float,
        };
        read_map(size, PixelFormat::DepthComponent, ty)
    }

    /// What glTexImage2D reads.
    pub fn data(&self) -> TexData {
        match self.rule {
            ReadbackRule::Driver => TexData::Readback(MAP_SLOT),
            ReadbackRule::Cpu(rule) => TexData::ConvertedDepth {
                slot: MAP_SLOT,
                ty: self.ty,
                rule,
            },
        }
    }

    /// The CPU rule, when the program converts.
    pub fn conversion(&self) -> Option<DepthRule> {
        match self.rule {
            ReadbackRule::Cpu(rule) => Some(rule),
            ReadbackRule::Driver => None,
        }
    }
}

/// glTexImage2D of `data` into the bound map.
pub fn upload_map(
    size: u32,
    internal_format: TexFormat,
    format: PixelFormat,
    data: TexData,
) -> Command {
    Command::TexImage(TexImage {
        requested: None,
        target: TextureTarget::Texture2D,
        level: 0,
        internal_format,
        width: size as i32,
        height: size as i32,
        depth: 1,
        border: 0,
        format,
        ty: PixelType::UnsignedByte,
        data,
    })
}

impl MapSettings {
    /// The `copy` pass of the depth-texture techniques: glCopyTexImage2D of the corner's
    /// depth (map × map at (0, 0)) into the map on unit 0, in the map's depth format.
    pub fn copy_depth_pass(&self) -> super::Pass {
        super::Pass {
            name: "copy",
            commands: vec![
                Command::ActiveTexture(0),
                bind_map(),
                Command::CopyTexImage2D(crate::ff::CopyTexImage {
                    face: None,
                    requested: None,
                    level: 0,
                    internal_format: self.depth_format(),
                    x: 0,
                    y: 0,
                    width: self.size as i32,
                    height: self.size as i32,
                    border: 0,
                }),
            ],
        }
    }
}

/// Binds the map on the active unit.
pub fn bind_map() -> Command {
    Command::BindTexture {
        target: TextureTarget::Texture2D,
        name: MAP_TEXTURE,
    }
}
