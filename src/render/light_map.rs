//! The light's map read back after the frames (`render --depth-map`), in the form the
//! technique compares it: float depth, one byte, or a 16-bit value of two 8-bit digits.
//! A map the program converted from FLOAT depth on the CPU is converted here by the same
//! rule, so the texels are the ones the technique uploaded. Rows stay bottom first, as GL
//! returns them; pictures of the map are drawn by `report`.

use crate::ff::PixelType;
use crate::pipeline::{self, Readback};
use crate::techniques::MapImageSource;

use super::RenderError;

/// In which form a map's texels are held (native byte order).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MapTexels {
    /// An `f32` depth in [0, 1] per texel.
    Depth,
    /// One byte per texel (an 8-bit map).
    Byte,
    /// A `u16` per texel: the big digit in the high byte, the little digit in the low one.
    Digits,
}

impl MapTexels {
    /// Bytes per texel.
    pub fn size(self) -> usize {
        match self {
            MapTexels::Depth => 4,
            MapTexels::Byte => 1,
            MapTexels::Digits => 2,
        }
    }
}

/// A square map of `size`² texels, bottom row first.
#[derive(Debug, Clone, PartialEq)]
pub struct LightMap {
    pub texels: MapTexels,
    pub size: u32,
    pub bytes: Vec<u8>,
}

impl LightMap {
    /// The map `source` names, from the pipeline's readbacks.
    pub(super) fn read<'r>(
        source: MapImageSource,
        readback: impl Fn(u32) -> Option<&'r Readback>,
    ) -> Result<LightMap, RenderError> {
        let (slot, size, from_float, texels) = match source {
            MapImageSource::DepthFloat { slot, size } => (slot, size, None, MapTexels::Depth),
            MapImageSource::Bytes {
                slot,
                size,
                from_float,
            } => (slot, size, from_float, MapTexels::Byte),
            MapImageSource::Digits {
                slot,
                size,
                from_float,
            } => (slot, size, from_float, MapTexels::Digits),
        };
        let n = size as usize * size as usize;
        let in_bytes = if from_float.is_some() {
            4
        } else {
            texels.size()
        };
        let r = readback(slot)
            .filter(|r| r.bytes.len() == n * in_bytes)
            .ok_or(RenderError::MapImage { slot })?;
        let bytes = match from_float {
            None => r.bytes.clone(),
            Some(rule) => {
                let ty = match texels {
                    MapTexels::Byte => PixelType::UnsignedByte,
                    MapTexels::Depth | MapTexels::Digits => PixelType::UnsignedShort,
                };
                pipeline::convert_depth(r, ty, rule).ok_or(RenderError::MapImage { slot })?
            }
        };
        Ok(LightMap {
            texels,
            size,
            bytes,
        })
    }

    /// The texels row by row, top row first (each texel `texels.size()` bytes).
    pub fn rows_top_first(&self) -> impl Iterator<Item = &[u8]> {
        let row = (self.size as usize * self.texels.size()).max(1);
        self.bytes.chunks_exact(row).rev()
    }
}
