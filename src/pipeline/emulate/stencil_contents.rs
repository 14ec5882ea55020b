//! What the window's stencil buffer holds, known while every one of its values is the same.
//!
//! llvmpipe clears a packed depth-stencil buffer (Z24S8) in one pass of stores when depth
//! and stencil are cleared together; a clear of depth alone keeps each pixel's stencil
//! bits, a read, a mask and a write per pixel. Programs of the era ask for stencil bits
//! and clear colour and depth each frame without ever drawing with the stencil test
//! (`benches/c/abi_bench.c`; on Mesa's own OSMesa, clearing stencil as well took a
//! `lists` frame's rasterisation from 0.928 to 0.891 ms). While the window's stencil
//! buffer holds one value `v` everywhere, a clear of depth is issued as a clear of depth
//! and stencil to `v`: the buffer's contents afterwards are the same, whatever the
//! stencil write mask and scissor box (bits cleared to `v`'s bits where they were
//! already), in the cheaper pass.
//!
//! What makes the values one value and what may not (into the window, framebuffer 0; a
//! program's framebuffer object is not tracked):
//! - a glClear with STENCIL_BUFFER_BIT, scissor test off and every stencil bit writable:
//!   the clear value, masked to the buffer's 8 bits; under a scissor box or a partial
//!   mask, unknown;
//! - fragments with the stencil test enabled (draws, bitmaps, pixel rectangles: GL 1.5
//!   §4.1.5 leaves the buffer unmodified when the test is disabled): unknown;
//! - pixel rectangles and copies (a STENCIL_INDEX image writes stencil without the test)
//!   and framebuffer blits: unknown, whatever their format.
//!
//! The buffer starts unknown (GL leaves a new buffer's contents undefined); the C library
//! clears a new window's stencil to 0 and says so (`EmulatedPipeline::window_stencil`).

use crate::ff::{ClearMask, Command, FixedState};

/// The stencil bits this tracking assumes (the C library's buffers: 8, or none, where a
/// stencil clear does nothing).
const STENCIL_MASK: u32 = 0xFF;

/// The window's stencil values as far as the pipeline knows them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StencilContents {
    /// Every value is this one.
    Uniform(u8),
    /// Anything.
    Unknown,
}

impl StencilContents {
    /// What the buffer holds after `cmd`, issued on `state` (the model with `cmd` applied).
    pub fn after(self, cmd: &Command, state: &FixedState) -> StencilContents {
        if state.framebuffers.draw != 0 {
            return self;
        }
        match cmd {
            Command::Clear(mask) if mask.stencil => {
                let whole = state.scissor_box().is_none();
                let all_bits = state.stencil_test.value.write_mask & STENCIL_MASK == STENCIL_MASK;
                match whole && all_bits {
                    true => {
                        StencilContents::Uniform((state.clear.stencil as u32 & STENCIL_MASK) as u8)
                    }
                    false => StencilContents::Unknown,
                }
            }
            Command::Draw(_) | Command::Bitmap(_) if state.stencil_test.enabled => {
                StencilContents::Unknown
            }
            Command::DrawPixels(_) | Command::CopyPixels(_) | Command::BlitFramebuffer(_) => {
                StencilContents::Unknown
            }
            _ => self,
        }
    }

    /// The clear to issue for `mask` on `state`: with stencil added, to the value held
    /// everywhere, where depth is cleared (and written) without it in the window.
    pub fn clear(self, mask: ClearMask, state: &FixedState) -> (ClearMask, Option<u8>) {
        match self {
            StencilContents::Uniform(v)
                if mask.depth
                    && !mask.stencil
                    && state.depth_test.value.write
                    && state.framebuffers.draw == 0 =>
            {
                let with = ClearMask {
                    stencil: true,
                    ..mask
                };
                (with, Some(v))
            }
            _ => (mask, None),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn depth_only() -> ClearMask {
        ClearMask {
            color: true,
            depth: true,
            ..ClearMask::default()
        }
    }

    #[test]
    fn a_depth_clear_takes_the_stencil_along_only_while_it_is_one_value() {
        let state = FixedState::default();
        let known = StencilContents::Uniform(7);
        let (mask, value) = known.clear(depth_only(), &state);
        assert!(mask.stencil && mask.depth && mask.color);
        assert_eq!(value, Some(7));
        assert_eq!(
            StencilContents::Unknown.clear(depth_only(), &state),
            (depth_only(), None)
        );
        // Nothing to gain without depth, nor with depth writes off (depth stays too).
        let color = ClearMask {
            color: true,
            ..ClearMask::default()
        };
        assert_eq!(known.clear(color, &state), (color, None));
        let mut no_depth_writes = state.clone();
        no_depth_writes.depth_test.value.write = false;
        assert_eq!(known.clear(depth_only(), &no_depth_writes).1, None);
        // A program's framebuffer object has a stencil buffer of its own.
        let mut fbo = state.clone();
        fbo.framebuffers.draw = 3;
        assert_eq!(known.clear(depth_only(), &fbo).1, None);
    }

    #[test]
    fn clears_and_stencil_tested_fragments_change_what_is_known() {
        let mut state = FixedState::default();
        let all = Command::Clear(ClearMask::ALL);
        state.clear.stencil = 0x1_05; // masked to the buffer's 8 bits
        assert_eq!(
            StencilContents::Unknown.after(&all, &state),
            StencilContents::Uniform(5)
        );
        // A scissored or partly masked stencil clear leaves values unknown.
        let mut masked = state.clone();
        masked.stencil_test.value.write_mask = 0x0F;
        let known = StencilContents::Uniform(5);
        assert_eq!(known.after(&all, &masked), StencilContents::Unknown);
        // A draw without the stencil test leaves the buffer; with it, anything.
        let draw = Command::Draw(std::sync::Arc::new(crate::ff::Geometry::new(
            crate::ff::Primitive::Triangles,
            Vec::new(),
        )));
        assert_eq!(known.after(&draw, &state), known);
        let mut tested = state.clone();
        tested.stencil_test.enabled = true;
        assert_eq!(known.after(&draw, &tested), StencilContents::Unknown);
        // Into a framebuffer object: the window's buffer is untouched.
        tested.framebuffers.draw = 2;
        assert_eq!(known.after(&draw, &tested), known);
    }
}
