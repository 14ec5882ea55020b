//! glBlitFramebuffer (EXT_framebuffer_blit, GL 3.0 §4.3.3): a rectangle of the read
//! framebuffer copied into a rectangle of the draw framebuffer, scaled with NEAREST or
//! LINEAR, flipped where a rectangle's corners are given in reverse, clipped to the
//! scissor box — and to nothing else: the colour, depth and stencil masks, blending and
//! the other fragment operations do not apply (measured on Mesa: a blit under
//! glColorMask(1, 0, 1, 1) writes green).
//!
//! The model checks the call as Mesa's compatibility context does (`_mesa_BlitFramebuffer`,
//! measured with `tests/c/blit.c`), in Mesa's order — so the filter and the mask travel
//! to the model as given, an unknown filter or bit included:
//! 1. either framebuffer incomplete: INVALID_FRAMEBUFFER_OPERATION (even with a mask of 0);
//! 2. a filter other than NEAREST, LINEAR and the SCALED_RESOLVE pair: INVALID_ENUM;
//! 3. SCALED_RESOLVE_FASTEST/NICEST_EXT with a single-sampled read framebuffer (all are):
//!    INVALID_OPERATION;
//! 4. a mask bit other than COLOR, DEPTH and STENCIL_BUFFER_BIT: INVALID_VALUE;
//! 5. DEPTH or STENCIL with a filter other than NEAREST: INVALID_OPERATION;
//! 6. a buffer the mask names that either framebuffer lacks is silently left out; for
//!    stencil (both have a stencil image) the stencil bits must be equal and, where both
//!    images also hold depth, the depth bits and type too; for depth likewise the depth
//!    bits and type (24-bit unorm against 32-bit float differs), and the stencil bits
//!    where both hold stencil: else INVALID_OPERATION. Colour images never mismatch here:
//!    Mesa refuses only integer against non-integer formats, and the model has none.
//!
//! Nothing of the state changes: the pixels are the paths' to copy (both issue GL's own
//! glBlitFramebuffer, with the scissor state synced first).
//!
//! One difference stays, measured and left alone: Mesa's OSMesa window is a y-flipped
//! buffer (gallium's winsys orientation), so a NEAREST sample that falls exactly between
//! two rows — every sample of a 2:1 copy — takes the other row from that window than from
//! a framebuffer object, which is what the layer's window is (measured: a 64→32 depth copy
//! one row apart). Scales of odd over even sizes never tie; `tests/c/blit.c` uses them.

use super::error::{GlError, GlResult};
use super::framebuffer::{
    Attached, AttachmentPoint, Completeness, FramebufferTarget, RenderbufferFormat,
};
use super::state::FixedState;
use super::texture::TexFormat;

/// glBlitFramebuffer's filter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BlitFilter {
    Nearest,
    Linear,
    /// EXT_framebuffer_multisample_blit_scaled: only for a multisampled read framebuffer.
    ScaledResolveFastest,
    ScaledResolveNicest,
}

/// The filter argument as given: a token outside [`BlitFilter`] is INVALID_ENUM, but only
/// after the completeness check (module note), so it is carried to the model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FilterArg {
    Known(BlitFilter),
    /// Any other GLenum value.
    Other(u32),
}

/// The mask argument: the buffers named, and any other bits as given (INVALID_VALUE in
/// the model, after the completeness and filter checks).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct BlitMask {
    pub color: bool,
    pub depth: bool,
    pub stencil: bool,
    /// Bits of no buffer.
    pub other: u32,
}

impl BlitMask {
    /// The mask of a GLbitfield.
    pub fn from_bits(bits: u32) -> BlitMask {
        use super::glenum::registry as r;
        BlitMask {
            color: bits & r::COLOR_BUFFER_BIT != 0,
            depth: bits & r::DEPTH_BUFFER_BIT != 0,
            stencil: bits & r::STENCIL_BUFFER_BIT != 0,
            other: bits & !(r::COLOR_BUFFER_BIT | r::DEPTH_BUFFER_BIT | r::STENCIL_BUFFER_BIT),
        }
    }

    /// The GLbitfield.
    pub fn bits(self) -> u32 {
        use super::glenum::registry as r;
        let bit = |on: bool, b: u32| if on { b } else { 0 };
        bit(self.color, r::COLOR_BUFFER_BIT)
            | bit(self.depth, r::DEPTH_BUFFER_BIT)
            | bit(self.stencil, r::STENCIL_BUFFER_BIT)
            | self.other
    }
}

impl FilterArg {
    /// The GLenum value.
    pub fn value(self) -> u32 {
        match self {
            FilterArg::Known(f) => super::glenum::gl(f),
            FilterArg::Other(v) => v,
        }
    }
}

/// A rectangle by its corners (x0, y0) and (x1, y1), window coordinates of its
/// framebuffer; x1 < x0 (or y1 < y0) flips the copy along that axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BlitRect {
    pub x0: i32,
    pub y0: i32,
    pub x1: i32,
    pub y1: i32,
}

/// One glBlitFramebuffer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Blit {
    pub src: BlitRect,
    pub dst: BlitRect,
    pub mask: BlitMask,
    pub filter: FilterArg,
}

/// What the blit rules need of a depth or stencil image: its bits and whether its depth is
/// floating point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct DepthStencilImage {
    depth: u8,
    stencil: u8,
    float_depth: bool,
}

impl DepthStencilImage {
    /// Depth bits and type equal (what glBlitFramebuffer's depth copy needs).
    fn same_depth(self, other: Self) -> bool {
        self.depth == other.depth && self.float_depth == other.float_depth
    }
}

impl FixedState {
    /// glBlitFramebuffer's errors, in Mesa's order (module note).
    pub(crate) fn check_blit(&self, b: &Blit) -> GlResult {
        let complete = |t| self.framebuffer_status(t) == Completeness::Complete;
        if !complete(FramebufferTarget::Draw) || !complete(FramebufferTarget::Read) {
            return Err(GlError::invalid_framebuffer_operation(
                "glBlitFramebuffer with an incomplete read or draw framebuffer",
            ));
        }
        let filter = match b.filter {
            FilterArg::Known(f) => f,
            FilterArg::Other(_) => {
                return Err(GlError::invalid_enum(
                    "a blit filter is NEAREST or LINEAR (SCALED_RESOLVE_*_EXT for \
                     multisampled framebuffers)",
                ))
            }
        };
        if matches!(
            filter,
            BlitFilter::ScaledResolveFastest | BlitFilter::ScaledResolveNicest
        ) {
            return Err(GlError::invalid_operation(
                "SCALED_RESOLVE filters need a multisampled read framebuffer",
            ));
        }
        if b.mask.other != 0 {
            return Err(GlError::invalid_value(
                "a blit mask holds only COLOR_, DEPTH_ and STENCIL_BUFFER_BIT",
            ));
        }
        if (b.mask.depth || b.mask.stencil) && filter != BlitFilter::Nearest {
            return Err(GlError::invalid_operation(
                "depth and stencil are blitted with NEAREST only",
            ));
        }
        let read = FramebufferTarget::Read;
        let draw = FramebufferTarget::Draw;
        if b.mask.stencil {
            let images = (
                self.blit_image(read, AttachmentPoint::Stencil),
                self.blit_image(draw, AttachmentPoint::Stencil),
            );
            if let (Some(r), Some(d)) = images {
                let depth_differs = r.depth > 0 && d.depth > 0 && !r.same_depth(d);
                if r.stencil != d.stencil || depth_differs {
                    return Err(GlError::invalid_operation(
                        "blitted stencil images of different formats",
                    ));
                }
            }
        }
        if b.mask.depth {
            let images = (
                self.blit_image(read, AttachmentPoint::Depth),
                self.blit_image(draw, AttachmentPoint::Depth),
            );
            if let (Some(r), Some(d)) = images {
                let stencil_differs = r.stencil > 0 && d.stencil > 0 && r.stencil != d.stencil;
                if !r.same_depth(d) || stencil_differs {
                    return Err(GlError::invalid_operation(
                        "blitted depth images of different formats",
                    ));
                }
            }
        }
        Ok(())
    }

    /// The depth or stencil image at `point` of the framebuffer bound to `target`: the
    /// window's when it has those bits (its 32-bit depth is floating point, as the
    /// targets' D32F is), else the attached image's format.
    fn blit_image(
        &self,
        target: FramebufferTarget,
        point: AttachmentPoint,
    ) -> Option<DepthStencilImage> {
        let f = &self.framebuffers;
        let name = f.bound(target);
        let window = f.window_bits;
        if name == 0 {
            let present = match point {
                AttachmentPoint::Stencil => window.stencil > 0,
                _ => window.depth > 0,
            };
            return present.then_some(DepthStencilImage {
                depth: window.depth,
                stencil: window.stencil,
                float_depth: window.depth == 32,
            });
        }
        let attached = f.objects.get(&name)?.attachment(point)?;
        match attached {
            Attached::Renderbuffer(r) => {
                let rb = f.renderbuffers.get(&r)?;
                let bits = rb.format.bits();
                Some(DepthStencilImage {
                    depth: bits.depth,
                    stencil: bits.stencil,
                    float_depth: matches!(
                        rb.format,
                        RenderbufferFormat::DepthComponent32F
                            | RenderbufferFormat::Depth32FStencil8
                    ),
                })
            }
            Attached::Texture {
                target: tt,
                name,
                level,
                ..
            } => {
                let format = self.texture(tt, name)?.level(level)?.internal_format;
                let bits = super::framebuffer::texture_bits(format);
                Some(DepthStencilImage {
                    depth: bits.depth,
                    stencil: bits.stencil,
                    float_depth: format == TexFormat::DepthComponent32F,
                })
            }
        }
    }
}

#[cfg(test)]
#[path = "blit_tests.rs"]
mod blit_tests;
