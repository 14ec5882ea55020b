//! GL errors as `glGetError` reports them.
//!
//! GL 1.5 §2.5: a command that raises an error has no other effect (except for
//! OUT_OF_MEMORY). The error flag is sticky: the first error is kept until it is read, later
//! ones are dropped. [`FixedState`](super::FixedState) follows that: `apply` returns the error
//! and records it only when no error is pending.

/// The GL error codes a fixed-function state change can raise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GlErrorKind {
    /// GL_INVALID_ENUM: an enum argument is out of range for this command.
    InvalidEnum,
    /// GL_INVALID_VALUE: a numeric argument is out of range.
    InvalidValue,
    /// GL_INVALID_OPERATION: the command is not allowed in the current state.
    InvalidOperation,
    /// GL_STACK_OVERFLOW: PushMatrix on a full stack.
    StackOverflow,
    /// GL_STACK_UNDERFLOW: PopMatrix on a stack holding one matrix.
    StackUnderflow,
    /// GL_INVALID_FRAMEBUFFER_OPERATION: drawing, clearing, reading or copying with an
    /// incomplete framebuffer bound (GL 3.0 §4.4.4).
    InvalidFramebufferOperation,
}

impl GlErrorKind {
    /// The GLenum glGetError returns.
    pub fn code(self) -> u32 {
        match self {
            GlErrorKind::InvalidEnum => 0x0500,
            GlErrorKind::InvalidValue => 0x0501,
            GlErrorKind::InvalidOperation => 0x0502,
            GlErrorKind::StackOverflow => 0x0503,
            GlErrorKind::StackUnderflow => 0x0504,
            GlErrorKind::InvalidFramebufferOperation => 0x0506,
        }
    }
}

/// A GL error with the rule that raised it (the evidence; `kind` is what glGetError returns).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, thiserror::Error)]
#[error("{kind:?}: {rule}")]
pub struct GlError {
    pub kind: GlErrorKind,
    /// The GL rule that was broken, in words.
    pub rule: &'static str,
}

impl GlError {
    pub const fn invalid_enum(rule: &'static str) -> Self {
        Self {
            kind: GlErrorKind::InvalidEnum,
            rule,
        }
    }
    pub const fn invalid_value(rule: &'static str) -> Self {
        Self {
            kind: GlErrorKind::InvalidValue,
            rule,
        }
    }
    pub const fn invalid_operation(rule: &'static str) -> Self {
        Self {
            kind: GlErrorKind::InvalidOperation,
            rule,
        }
    }
    pub const fn stack_overflow(rule: &'static str) -> Self {
        Self {
            kind: GlErrorKind::StackOverflow,
            rule,
        }
    }
    pub const fn invalid_framebuffer_operation(rule: &'static str) -> Self {
        Self {
            kind: GlErrorKind::InvalidFramebufferOperation,
            rule,
        }
    }
    pub const fn stack_underflow(rule: &'static str) -> Self {
        Self {
            kind: GlErrorKind::StackUnderflow,
            rule,
        }
    }
}

/// Shorthand for the state layer's results.
pub type GlResult<T = ()> = Result<T, GlError>;
