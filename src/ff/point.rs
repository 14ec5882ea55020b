//! GL 1.4's point parameters (§3.3, glPointParameter): the derived size of a point is
//!
//!   size′ = clamp(size · √(1 / (a + b·d + c·d²)), POINT_SIZE_MIN, POINT_SIZE_MAX),
//!
//! d = |z_eye| as Mesa's fixed-function vertex program takes it (the eye distance along z,
//! `ffvertex_prog.c`), evaluated per vertex on the emulated path (`shadergen::vertex`).
//! Mesa clamps to [min, max] whether or not the size is attenuated (measured: glPointSize
//! 10 with POINT_SIZE_MAX 4 draws a 4×4 point), and draws POINT_FADE_THRESHOLD_SIZE as
//! state only: a point below it keeps its size and its alpha (measured: size 5.8 under a
//! threshold of 20 is a 6×6 point at full alpha). The model follows both.

use super::error::{GlError, GlResult};

/// One glPointParameter parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PointParam {
    /// POINT_SIZE_MIN: ≥ 0, else INVALID_VALUE.
    SizeMin(f32),
    /// POINT_SIZE_MAX: ≥ 0, else INVALID_VALUE.
    SizeMax(f32),
    /// POINT_FADE_THRESHOLD_SIZE: ≥ 0, else INVALID_VALUE.
    FadeThreshold(f32),
    /// POINT_DISTANCE_ATTENUATION: the coefficients (a, b, c).
    DistanceAttenuation([f32; 3]),
    /// POINT_SPRITE_COORD_ORIGIN (GL 2.0, which Mesa's compatibility context takes):
    /// LOWER_LEFT or UPPER_LEFT, where a sprite's t is 0 ([`PointSprite`]).
    SpriteCoordOrigin(u32),
}

/// The point parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointParams {
    /// GL default: 0.
    pub size_min: f32,
    /// GL default: the largest size, 255 on llvmpipe (Mesa's answer).
    pub size_max: f32,
    /// GL default: 1.
    pub fade_threshold: f32,
    /// GL default: (1, 0, 0), no attenuation.
    pub attenuation: [f32; 3],
    /// GL default: UPPER_LEFT.
    pub sprite_coord_origin: u32,
}

/// ARB_point_sprite (GL 2.0 §3.3.1): with POINT_SPRITE on, a point is drawn as a square
/// (POINT_SMOOTH has no effect: Mesa's rasterizer state turns smoothing off for sprites)
/// and each unit whose COORD_REPLACE is TRUE takes the texture coordinates
/// (s, t, 0, 1) of the fragment's place in the square in place of the vertex's — s from
/// 0 at the left edge to 1 at the right, t from 0 at the edge POINT_SPRITE_COORD_ORIGIN
/// names to 1 at the other — after the texture matrix, which they bypass. Both are in the
/// point attribute group; the enable also in the enable group (Mesa's glPopAttrib of
/// TEXTURE_BIT leaves COORD_REPLACE, measured).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct PointSprite {
    /// POINT_SPRITE. GL default: FALSE.
    pub enabled: bool,
    /// Bit u: unit u's COORD_REPLACE. GL default: FALSE on every unit.
    pub coord_replace: u8,
}

impl PointSprite {
    /// Whether unit `u` replaces its coordinates on a sprite.
    pub fn replaces(&self, u: usize) -> bool {
        self.coord_replace & (1 << u) != 0
    }

    /// Sets unit `u`'s COORD_REPLACE.
    pub fn set_replace(&mut self, u: usize, on: bool) {
        let bit = 1u8 << u;
        self.coord_replace = match on {
            true => self.coord_replace | bit,
            false => self.coord_replace & !bit,
        };
    }
}

/// GL_LOWER_LEFT and GL_UPPER_LEFT.
pub const LOWER_LEFT: u32 = 0x8CA1;
pub const UPPER_LEFT: u32 = 0x8CA2;

impl PointParams {
    pub const DEFAULT: Self = Self {
        size_min: 0.0,
        size_max: 255.0,
        fade_threshold: 1.0,
        attenuation: [1.0, 0.0, 0.0],
        sprite_coord_origin: UPPER_LEFT,
    };

    /// Whether sizes are attenuated by distance: (a, b, c) ≠ (1, 0, 0) (Mesa's
    /// `_Attenuated`).
    pub fn attenuated(&self) -> bool {
        self.attenuation != [1.0, 0.0, 0.0]
    }

    /// glPointParameter: a negative size or threshold is INVALID_VALUE (GL 1.5 §3.3), a
    /// bad origin INVALID_VALUE as in Mesa, and neither changes anything. `v < 0` as Mesa
    /// tests it: a NaN is accepted.
    pub fn set(&mut self, p: PointParam) -> GlResult {
        let non_negative = |v: f32, what: &'static str| {
            if v < 0.0 {
                Err(GlError::invalid_value(what))
            } else {
                Ok(v)
            }
        };
        match p {
            PointParam::SizeMin(v) => {
                self.size_min = non_negative(v, "POINT_SIZE_MIN must be ≥ 0")?
            }
            PointParam::SizeMax(v) => {
                self.size_max = non_negative(v, "POINT_SIZE_MAX must be ≥ 0")?
            }
            PointParam::FadeThreshold(v) => {
                self.fade_threshold = non_negative(v, "POINT_FADE_THRESHOLD_SIZE must be ≥ 0")?
            }
            PointParam::DistanceAttenuation(a) => self.attenuation = a,
            PointParam::SpriteCoordOrigin(o) => {
                if o != LOWER_LEFT && o != UPPER_LEFT {
                    return Err(GlError::invalid_value(
                        "POINT_SPRITE_COORD_ORIGIN must be LOWER_LEFT or UPPER_LEFT",
                    ));
                }
                self.sprite_coord_origin = o;
            }
        }
        Ok(())
    }

    /// The commands that set every parameter back to these values (glPopAttrib).
    pub fn commands(&self) -> [PointParam; 5] {
        [
            PointParam::SizeMin(self.size_min),
            PointParam::SizeMax(self.size_max),
            PointParam::FadeThreshold(self.fade_threshold),
            PointParam::DistanceAttenuation(self.attenuation),
            PointParam::SpriteCoordOrigin(self.sprite_coord_origin),
        ]
    }
}
