//! glPixelMap (GL 1.5 §3.6.3, Table 3.3): the lookup tables MAP_COLOR and MAP_STENCIL
//! switch on, and where they apply (§3.6.5, after scale and bias).
//!
//! Ten maps are kept, as GL's RGBA-mode pipeline uses them: I_TO_I, S_TO_S, I_TO_R/G/B/A
//! (read by COLOR_INDEX images, `index_pixels`) and
//! R_TO_R, G_TO_G, B_TO_B, A_TO_A. Each holds 1 to [`MAX_PIXEL_MAP_TABLE`] entries; GL's
//! initial map is one entry of 0. Stored as Mesa's `store_pixelmap` stores them: the
//! colour maps' values clamped to [0, 1], S_TO_S's rounded to integers, I_TO_I's as given.
//! glPixelMapuiv and glPixelMapusv give a colour map c/(2³² − 1) and c/(2¹⁶ − 1), an index
//! map the integers themselves.
//!
//! Lookup of a colour component c in [0, 1] (after scale, bias and the clamp): GL 1.5
//! §3.6.5 says the nearest entry. Mesa 22.3 on llvmpipe takes two rules, and the layer
//! follows both: glDrawPixels and glCopyPixels sample the maps as a 256-texel texture whose
//! texel j holds entry `⌊j · size / 256⌋` (Mesa's `load_color_map_texture`), at the
//! texel j = min(⌊256·c⌋, 255) (measured, tests/c/pixelstore.c: red 51/255 through a
//! 5-entry map takes entry 0; tests/c/buffer_values.c: 72/255 through a 4-entry map takes
//! entry 1, where ⌊c · (size − 1)⌋ gives 0), glReadPixels and the texture images
//! (glTexImage, glCopyTexImage) the nearest, `roundEven(c · (size − 1))` (Mesa's
//! `_mesa_map_rgba`; measured, tests/c/transfer.c: the same red takes entry 1).

use std::sync::Arc;

use super::error::{GlError, GlResult};

/// Mesa's MAX_PIXEL_MAP_TABLE (GL's minimum is 32).
pub const MAX_PIXEL_MAP_TABLE: usize = 256;

/// The maps of Table 3.3 (the RGBA-mode ones and the index ones).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelMapName {
    IToI,
    SToS,
    IToR,
    IToG,
    IToB,
    IToA,
    RToR,
    GToG,
    BToB,
    AToA,
}

impl PixelMapName {
    pub const ALL: [PixelMapName; 10] = [
        PixelMapName::IToI,
        PixelMapName::SToS,
        PixelMapName::IToR,
        PixelMapName::IToG,
        PixelMapName::IToB,
        PixelMapName::IToA,
        PixelMapName::RToR,
        PixelMapName::GToG,
        PixelMapName::BToB,
        PixelMapName::AToA,
    ];

    fn index(self) -> usize {
        self as usize
    }

    /// The maps indexed by a colour index or stencil value, whose size must be a power of
    /// two (the index is masked by size − 1).
    pub fn indexed_by_integers(self) -> bool {
        matches!(
            self,
            PixelMapName::IToI
                | PixelMapName::SToS
                | PixelMapName::IToR
                | PixelMapName::IToG
                | PixelMapName::IToB
                | PixelMapName::IToA
        )
    }

    /// The maps whose values are integers (indices), not colours.
    pub fn holds_integers(self) -> bool {
        matches!(self, PixelMapName::IToI | PixelMapName::SToS)
    }
}

/// The values of a glPixelMap call, as the caller's type gave them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MapValues {
    Float,
    UInt,
    UShort,
}

/// One glPixelMap: the map and its values as stored (see the module note).
#[derive(Clone, Debug, PartialEq)]
pub struct PixelMap {
    pub map: PixelMapName,
    pub values: Arc<[f32]>,
}

impl PixelMap {
    /// glPixelMap{f,ui,us}v(map, size, values): size outside 1..=MAX, or not a power of
    /// two for a map indexed by integers, is INVALID_VALUE (§3.6.3).
    pub fn new(map: PixelMapName, raw: &[f64], given: MapValues) -> Result<Self, GlError> {
        let n = raw.len();
        if n == 0 || n > MAX_PIXEL_MAP_TABLE {
            return Err(GlError::invalid_value(
                "glPixelMap size must be 1 to GL_MAX_PIXEL_MAP_TABLE",
            ));
        }
        if map.indexed_by_integers() && !n.is_power_of_two() {
            return Err(GlError::invalid_value(
                "glPixelMap size of an I or S map must be a power of two",
            ));
        }
        let values = raw
            .iter()
            .map(|v| {
                let v = match (given, map.holds_integers()) {
                    (MapValues::Float, _) | (_, true) => *v,
                    (MapValues::UInt, false) => v / 4294967295.0,
                    (MapValues::UShort, false) => v / 65535.0,
                };
                match map {
                    PixelMapName::IToI => v as f32,
                    PixelMapName::SToS => v.round() as f32,
                    _ => v.clamp(0.0, 1.0) as f32,
                }
            })
            .collect();
        Ok(Self { map, values })
    }
}

/// The ten maps. GL default: each one entry of 0.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelMaps {
    maps: [Arc<[f32]>; 10],
}

impl Default for PixelMaps {
    fn default() -> Self {
        let one: Arc<[f32]> = Arc::from([0.0f32]);
        Self {
            maps: std::array::from_fn(|_| one.clone()),
        }
    }
}

impl PixelMaps {
    pub fn get(&self, map: PixelMapName) -> &Arc<[f32]> {
        &self.maps[map.index()]
    }

    pub fn set(&mut self, m: &PixelMap) -> GlResult {
        self.maps[m.map.index()] = m.values.clone();
        Ok(())
    }

    /// One component c ∈ [0, 1] through `map` as glDrawPixels takes it: entry
    /// ⌊j · size / 256⌋ of the texel j = min(⌊256·c⌋, 255) (Mesa's rule, see the module
    /// note).
    pub fn lookup(&self, map: PixelMapName, c: f32) -> f32 {
        let t = self.get(map);
        let j = ((c.clamp(0.0, 1.0) * 256.0).floor() as usize).min(255);
        let i = j * t.len() / 256;
        t.get(i.min(t.len() - 1)).copied().unwrap_or(0.0)
    }

    /// One component c through `map` by the nearest entry, roundEven(c · (size − 1)): the
    /// rule of images read and texture images (see the module note).
    pub fn lookup_nearest(&self, map: PixelMapName, c: f32) -> f32 {
        let t = self.get(map);
        let i = (c.clamp(0.0, 1.0) * (t.len() - 1) as f32).round_ties_even() as usize;
        t.get(i.min(t.len() - 1)).copied().unwrap_or(0.0)
    }

    /// An RGBA colour through the four colour maps by the nearest entry (glReadPixels,
    /// texture images).
    pub fn color_nearest(&self, c: glam::Vec4) -> glam::Vec4 {
        glam::Vec4::new(
            self.lookup_nearest(PixelMapName::RToR, c.x),
            self.lookup_nearest(PixelMapName::GToG, c.y),
            self.lookup_nearest(PixelMapName::BToB, c.z),
            self.lookup_nearest(PixelMapName::AToA, c.w),
        )
    }

    /// An RGBA colour through R_TO_R, G_TO_G, B_TO_B and A_TO_A (§3.6.5, MAP_COLOR), as
    /// glDrawPixels and glCopyPixels take them.
    pub fn color(&self, c: glam::Vec4) -> glam::Vec4 {
        glam::Vec4::new(
            self.lookup(PixelMapName::RToR, c.x),
            self.lookup(PixelMapName::GToG, c.y),
            self.lookup(PixelMapName::BToB, c.z),
            self.lookup(PixelMapName::AToA, c.w),
        )
    }

    /// A stencil value through S_TO_S (MAP_STENCIL): entry s & (size − 1).
    pub fn stencil(&self, s: i64) -> f32 {
        self.entry_masked(PixelMapName::SToS, s as u64)
    }

    /// Entry i & (size − 1) of `map` (an index map's lookup, §3.6.5; a negative index
    /// taken as its two's-complement bits).
    pub fn entry_masked(&self, map: PixelMapName, i: u64) -> f32 {
        let t = self.get(map);
        let k = i & (t.len().max(1) as u64 - 1);
        t.get(k as usize).copied().unwrap_or(0.0)
    }
}

#[cfg(test)]
#[path = "pixel_map_tests.rs"]
mod pixel_map_tests;
