//! Whether a call's client pixels may be read at all. Mesa checks an upload's sizes
//! before it touches the program's memory (`_mesa_legal_texture_dimensions`, the
//! sub-image region checks), so a program may pass a short array with sizes GL refuses
//! and get only the error: glTexImage2D of width MAX_TEXTURE_SIZE + 1 from a 64-byte
//! array is INVALID_VALUE, not a read past the array. The model raises the errors itself
//! when it applies the call; this only decides that nothing is read first.
//!
//! The rules (GL 1.5 §3.8.1, Mesa 22.3's limits):
//! - glTexImage1D/2D/3D: a level in [0, the target's highest], a border of 0 or 1, each
//!   size in [2·border, (max >> level) + 2·border] with max the target's
//!   MAX_TEXTURE_SIZE, MAX_CUBE_MAP_TEXTURE_SIZE or MAX_3D_TEXTURE_SIZE (Mesa's
//!   `_mesa_legal_texture_dimensions`). A proxy target reads nothing: its call specifies
//!   no image (§3.8.1, "Alternate texture image specification").
//! - glTexSubImage1D/2D/3D and glCompressedTexSubImage2D: the bound texture has the
//!   level and each size is at most the level's, so no more is read than the level holds.
//!   While a display list is compiled the state at the call is not the state the list
//!   runs in: only sizes no level of the target can hold are refused then.

use super::api::Entry;
use super::args::Args;
use super::glenum::GlEnum;
use super::state::FixedState;
use super::texture::{
    TextureTarget, MAX_3D_TEXTURE_SIZE, MAX_CUBE_MAP_TEXTURE_SIZE, MAX_TEXTURE_SIZE,
};

/// Whether a call reads the pixels its pointer names.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PixelAccess {
    /// The sizes are ones GL accepts: the pointer is read (NULL stays NULL).
    #[default]
    Read,
    /// The call fails, or specifies no image: the pointer is taken as NULL.
    Skip,
}

/// Where the state at the call stands to the state the call runs in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CallTime {
    /// The call runs now, on this state.
    Now,
    /// The call is compiled into a display list: it runs later, on another state.
    Compiled,
}

/// The largest width, height or depth an image of `target` may have at level 0.
fn max_size(target: TextureTarget) -> i32 {
    match target {
        TextureTarget::Texture1D | TextureTarget::Texture2D => MAX_TEXTURE_SIZE,
        TextureTarget::Texture3D => MAX_3D_TEXTURE_SIZE,
        TextureTarget::CubeMap | TextureTarget::CubeFace(_) => MAX_CUBE_MAP_TEXTURE_SIZE,
    }
}

/// Whether a level-`level` image of `sizes` with `border` has sizes GL accepts for
/// `target` (Mesa's `_mesa_legal_texture_dimensions`, with the level range first).
pub fn image_fits(target: TextureTarget, level: i32, sizes: &[i32], border: i32) -> bool {
    if !(0..=target.max_level()).contains(&level) || !(0..=1).contains(&border) {
        return false;
    }
    let max = (max_size(target) >> level) + 2 * border;
    sizes.iter().all(|s| (2 * border..=max).contains(s))
}

/// The image target of argument 0, if it names one (a proxy or a bad token does not).
fn target<A: Args>(c: &A) -> Option<TextureTarget> {
    c.token(0).ok().and_then(TextureTarget::from_gl_value)
}

/// The integers at `at`, or `None` when one is not an integer.
fn ints<A: Args, const N: usize>(c: &A, at: [usize; N]) -> Option<[i32; N]> {
    let mut out = [0; N];
    for (o, i) in out.iter_mut().zip(at) {
        *o = c.i32(i).ok()?;
    }
    Some(out)
}

/// Whether a sub-image of `sizes` at `level` of the bound `target` reads no more than the
/// level holds (see the module note).
fn sub_image_fits(
    state: &FixedState,
    when: CallTime,
    target: TextureTarget,
    level: i32,
    sizes: &[i32],
) -> bool {
    if sizes.iter().any(|s| *s < 0) {
        return false;
    }
    match when {
        CallTime::Compiled => sizes.iter().all(|s| *s <= max_size(target) + 2),
        CallTime::Now => {
            let name = state.units[state.active_unit()].bound(target);
            let Some(l) = state
                .texture(target, name)
                .and_then(|t| t.level_in(target, level))
            else {
                return false;
            };
            let held = [l.width, l.height, l.depth];
            sizes.iter().zip(held).all(|(s, h)| *s <= h)
        }
    }
}

/// Whether `c`'s client pixels may be read, on `state` as the call finds it.
pub fn pixel_access<A: Args>(c: &A, state: &FixedState, when: CallTime) -> PixelAccess {
    let fits = match c.entry() {
        Entry::TexImage1D => ints(c, [1, 3, 4])
            .is_some_and(|[level, w, b]| target(c).is_some_and(|t| image_fits(t, level, &[w], b))),
        Entry::TexImage2D => ints(c, [1, 3, 4, 5]).is_some_and(|[level, w, h, b]| {
            target(c).is_some_and(|t| image_fits(t, level, &[w, h], b))
        }),
        Entry::TexImage3D | Entry::TexImage3DEXT => {
            ints(c, [1, 3, 4, 5, 6]).is_some_and(|[level, w, h, d, b]| {
                target(c).is_some_and(|t| image_fits(t, level, &[w, h, d], b))
            })
        }
        Entry::TexSubImage1D => ints(c, [1, 3]).is_some_and(|[level, w]| {
            target(c).is_some_and(|t| sub_image_fits(state, when, t, level, &[w]))
        }),
        Entry::TexSubImage2D
        | Entry::CompressedTexSubImage2D
        | Entry::CompressedTexSubImage2DARB => ints(c, [1, 4, 5]).is_some_and(|[level, w, h]| {
            target(c).is_some_and(|t| sub_image_fits(state, when, t, level, &[w, h]))
        }),
        Entry::TexSubImage3D | Entry::TexSubImage3DEXT => {
            ints(c, [1, 5, 6, 7]).is_some_and(|[level, w, h, d]| {
                target(c).is_some_and(|t| sub_image_fits(state, when, t, level, &[w, h, d]))
            })
        }
        _ => true,
    };
    if fits {
        PixelAccess::Read
    } else {
        PixelAccess::Skip
    }
}
