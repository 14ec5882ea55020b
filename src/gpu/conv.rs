//! Our gpu-layer enums lowered to GL constants, with exhaustive matches.

use crate::vocab::DepthBits;

/// The renderbuffer format and the attachment point of a depth buffer.
pub fn depth_storage(depth: DepthBits, stencil: bool) -> (u32, u32) {
    match (depth, stencil) {
        (DepthBits::D16, _) => (glow::DEPTH_COMPONENT16, glow::DEPTH_ATTACHMENT),
        (DepthBits::D24, _) => (glow::DEPTH24_STENCIL8, glow::DEPTH_STENCIL_ATTACHMENT),
        (DepthBits::D32F, false) => (glow::DEPTH_COMPONENT32F, glow::DEPTH_ATTACHMENT),
        (DepthBits::D32F, true) => (glow::DEPTH32F_STENCIL8, glow::DEPTH_STENCIL_ATTACHMENT),
    }
}

/// The internal format of a depth buffer without stencil bits, on DEPTH_ATTACHMENT.
pub fn depth_only_storage(depth: DepthBits) -> (u32, u32) {
    let format = match depth {
        DepthBits::D16 => glow::DEPTH_COMPONENT16,
        DepthBits::D24 => glow::DEPTH_COMPONENT24,
        DepthBits::D32F => glow::DEPTH_COMPONENT32F,
    };
    (format, glow::DEPTH_ATTACHMENT)
}

/// The name of a glGetError code.
pub fn error_name(code: u32) -> &'static str {
    match code {
        glow::NO_ERROR => "GL_NO_ERROR",
        glow::INVALID_ENUM => "GL_INVALID_ENUM",
        glow::INVALID_VALUE => "GL_INVALID_VALUE",
        glow::INVALID_OPERATION => "GL_INVALID_OPERATION",
        glow::STACK_OVERFLOW => "GL_STACK_OVERFLOW",
        glow::STACK_UNDERFLOW => "GL_STACK_UNDERFLOW",
        glow::OUT_OF_MEMORY => "GL_OUT_OF_MEMORY",
        glow::INVALID_FRAMEBUFFER_OPERATION => "GL_INVALID_FRAMEBUFFER_OPERATION",
        _ => "unknown GL error",
    }
}
