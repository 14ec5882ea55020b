//! What a window hears: key presses, mouse drags and the window being closed or exposed,
//! in the project's own terms (no winit type leaves the `gpu` layer), and a [`Waker`] that
//! another thread uses to end a window's wait for input.
//!
//! A drag is reported as the cursor's movement in pixels while the left button is held,
//! with the shift key's state at that moment; key presses carry the logical key (the
//! character the keyboard layout gives, so shift+t is `T`) and shift. Key releases and
//! repeats of modifier keys alone are not reported.

use std::fmt;

/// A key, by what it means rather than where it sits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum KeyName {
    /// A key that types a character (shift applied: `T`, `+`).
    Char(char),
    Left,
    Right,
    Up,
    Down,
    Escape,
}

impl KeyName {
    /// The name scripts use: the character itself, or `left`, `right`, `up`, `down`, `esc`.
    pub fn parse(text: &str) -> Option<KeyName> {
        match text {
            "left" => Some(KeyName::Left),
            "right" => Some(KeyName::Right),
            "up" => Some(KeyName::Up),
            "down" => Some(KeyName::Down),
            "esc" | "escape" => Some(KeyName::Escape),
            _ => {
                let mut chars = text.chars();
                match (chars.next(), chars.next()) {
                    (Some(c), None) if !c.is_whitespace() => Some(KeyName::Char(c)),
                    _ => None,
                }
            }
        }
    }
}

impl fmt::Display for KeyName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            KeyName::Char(c) => write!(f, "{c}"),
            KeyName::Left => f.write_str("left"),
            KeyName::Right => f.write_str("right"),
            KeyName::Up => f.write_str("up"),
            KeyName::Down => f.write_str("down"),
            KeyName::Escape => f.write_str("esc"),
        }
    }
}

/// One thing the user did to the window.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Input {
    Key {
        key: KeyName,
        shift: bool,
    },
    /// The cursor moved by (dx, dy) pixels (y down) with the left button held.
    Drag {
        dx: f64,
        dy: f64,
        shift: bool,
    },
    /// The window must be drawn again (exposed, resized by the window manager).
    Exposed,
    /// The user closed the window.
    Closed,
}

/// Ends a window's wait for input from any thread (a no-op once the window is gone).
#[derive(Clone)]
pub struct Waker {
    #[cfg(feature = "window")]
    pub(super) proxy: Option<winit::event_loop::EventLoopProxy<()>>,
}

impl Waker {
    /// Wakes the window's thread if it waits for input.
    pub fn wake(&self) {
        #[cfg(feature = "window")]
        if let Some(p) = &self.proxy {
            let _ = p.send_event(());
        }
    }
}

impl fmt::Debug for Waker {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("Waker")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn key_names_read_as_scripts_write_them() {
        assert_eq!(KeyName::parse("t"), Some(KeyName::Char('t')));
        assert_eq!(KeyName::parse("+"), Some(KeyName::Char('+')));
        assert_eq!(KeyName::parse("left"), Some(KeyName::Left));
        assert_eq!(KeyName::parse("esc"), Some(KeyName::Escape));
        for bad in ["", "tt", " ", "shift"] {
            assert_eq!(KeyName::parse(bad), None, "{bad:?}");
        }
        for k in [KeyName::Char('F'), KeyName::Down, KeyName::Escape] {
            assert_eq!(KeyName::parse(&k.to_string()), Some(k));
        }
    }
}
