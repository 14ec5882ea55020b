//! The blit rules against Mesa's measured error order and sizes.

use super::*;
use crate::ff::framebuffer::Bits;
use crate::ff::{Command, GlErrorKind};

fn blit(mask: BlitMask, filter: FilterArg) -> Command {
    let r = BlitRect {
        x0: 0,
        y0: 0,
        x1: 8,
        y1: 8,
    };
    Command::BlitFramebuffer(Blit {
        src: r,
        dst: r,
        mask,
        filter,
    })
}

const COLOR: BlitMask = BlitMask {
    color: true,
    depth: false,
    stencil: false,
    other: 0,
};
const DEPTH: BlitMask = BlitMask {
    color: false,
    depth: true,
    stencil: false,
    other: 0,
};
const NEAREST: FilterArg = FilterArg::Known(BlitFilter::Nearest);
const LINEAR: FilterArg = FilterArg::Known(BlitFilter::Linear);

fn error(state: &mut FixedState, cmd: &Command) -> Option<GlErrorKind> {
    state.apply(cmd).err().map(|e| e.kind)
}

fn window() -> FixedState {
    let mut s = FixedState::default();
    s.framebuffers.window_bits = Bits {
        red: 8,
        green: 8,
        blue: 8,
        alpha: 8,
        depth: 24,
        stencil: 8,
    };
    s
}

/// The rows of `tests/c/blit.c` as Mesa printed them.
#[test]
fn errors_come_in_mesas_order() {
    use GlErrorKind as E;
    let mut s = window();
    let bad_bits = BlitMask {
        other: 0x1,
        ..COLOR
    };
    let cases = [
        (bad_bits, NEAREST, Some(E::InvalidValue)),
        (BlitMask::default(), NEAREST, None),
        (DEPTH, LINEAR, Some(E::InvalidOperation)),
        (COLOR, LINEAR, None),
        (COLOR, FilterArg::Other(0x2700), Some(E::InvalidEnum)),
        (
            COLOR,
            FilterArg::Known(BlitFilter::ScaledResolveFastest),
            Some(E::InvalidOperation),
        ),
        (bad_bits, FilterArg::Other(0x0DE1), Some(E::InvalidEnum)),
        (
            BlitMask {
                other: 0x1,
                ..DEPTH
            },
            LINEAR,
            Some(E::InvalidValue),
        ),
    ];
    for (mask, filter, want) in cases {
        assert_eq!(
            error(&mut s, &blit(mask, filter)),
            want,
            "{mask:?} {filter:?}"
        );
        let _ = s.take_error();
    }
}

#[test]
fn depth_formats_must_match_and_missing_buffers_are_left_out() {
    use crate::ff::framebuffer::RenderbufferFormat as F;
    let mut s = window();
    s.apply(&Command::BindRenderbuffer(1)).unwrap();
    for (rb, format) in [(1, F::DepthComponent16), (2, F::DepthComponent24)] {
        s.apply(&Command::BindRenderbuffer(rb)).unwrap();
        s.apply(&Command::RenderbufferStorage {
            format,
            width: 8,
            height: 8,
        })
        .unwrap();
        s.apply(&Command::BindFramebuffer {
            target: FramebufferTarget::Draw,
            name: rb,
        })
        .unwrap();
        s.apply(&Command::FramebufferRenderbuffer {
            target: FramebufferTarget::Draw,
            attachment: AttachmentPoint::Depth,
            renderbuffer: rb,
        })
        .unwrap();
    }
    // Draw: D24 (no stencil, no colour image): window D24S8 depth matches, stencil and
    // colour are left out.
    let all = BlitMask {
        color: true,
        depth: true,
        stencil: true,
        other: 0,
    };
    assert_eq!(error(&mut s, &blit(all, NEAREST)), None);
    s.apply(&Command::BindFramebuffer {
        target: FramebufferTarget::Draw,
        name: 1,
    })
    .unwrap();
    assert_eq!(
        error(&mut s, &blit(DEPTH, NEAREST)),
        Some(GlErrorKind::InvalidOperation)
    );
}
