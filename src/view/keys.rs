//! The viewer's keys, as one table: each binding's key, the [`Action`] it takes and the
//! line `h` and `--help` show for it. Nothing else maps keys, so the help cannot drift
//! from what the keys do.

use crate::gpu::KeyName;

/// What a key asks the viewer to do.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    /// The next (+1) or previous (−1) technique.
    Technique(i8),
    /// glPolygonOffset factor up (+1) or down (−1) by [`FACTOR_STEP`](super::FACTOR_STEP).
    Factor(i8),
    /// glPolygonOffset units up or down by one LSB of the current depth format.
    Units(i8),
    /// glPolygonOffset units doubled (+1) or halved (−1): the 8-bit maps need thousands.
    UnitsScale(i8),
    /// No polygon offset at all: the acne, on purpose.
    NoOffset,
    /// Back to the technique's default offset.
    DefaultOffset,
    /// Depth bits of the light pass: 16 → 24 → 32F → 16.
    DepthBits,
    /// Map size doubled (+1) or halved (−1).
    MapSize(i8),
    /// Map filter: nearest ↔ linear.
    Filter,
    /// Stage arithmetic: float ↔ fixed8.
    Precision,
    /// Pipeline: emulate ↔ native.
    Pipeline,
    /// What the window shows: the next view, or one by number (image, mask, error, map,
    /// side by side).
    NextShow,
    Show(u8),
    /// The light turned by (azimuth, elevation) degrees.
    TurnLight(i8, i8),
    /// The camera turned by (azimuth, elevation) degrees.
    TurnCamera(i8, i8),
    Reset,
    Save,
    PrintCommand,
    Help,
    Quit,
}

/// One key and what it does.
#[derive(Debug, Clone, Copy)]
pub struct Binding {
    pub key: KeyName,
    /// Whether shift must be held (only for keys whose character does not change with
    /// shift: the arrows).
    pub shift: bool,
    pub action: Action,
    pub help: &'static str,
}

const fn key(c: char, action: Action, help: &'static str) -> Binding {
    Binding {
        key: KeyName::Char(c),
        shift: false,
        action,
        help,
    }
}

const fn named(key: KeyName, shift: bool, action: Action, help: &'static str) -> Binding {
    Binding {
        key,
        shift,
        action,
        help,
    }
}

/// Every key the viewer answers.
pub const BINDINGS: &[Binding] = &[
    key('t', Action::Technique(1), "next technique"),
    key('T', Action::Technique(-1), "previous technique"),
    key('f', Action::Factor(1), "polygon-offset factor up"),
    key('F', Action::Factor(-1), "polygon-offset factor down"),
    key('u', Action::Units(1), "polygon-offset units up one LSB"),
    key('U', Action::Units(-1), "polygon-offset units down one LSB"),
    key('*', Action::UnitsScale(1), "polygon-offset units doubled"),
    key('/', Action::UnitsScale(-1), "polygon-offset units halved"),
    key('o', Action::NoOffset, "no polygon offset (shows the acne)"),
    key('0', Action::DefaultOffset, "the technique's default offset"),
    key('d', Action::DepthBits, "depth bits 16 / 24 / 32F"),
    key('m', Action::MapSize(1), "map size doubled"),
    key('M', Action::MapSize(-1), "map size halved"),
    key('l', Action::Filter, "map filter nearest / linear"),
    key('x', Action::Precision, "precision float / fixed8"),
    key('n', Action::Pipeline, "pipeline emulate / native"),
    key('v', Action::NextShow, "next view"),
    key('1', Action::Show(0), "view: image"),
    key('2', Action::Show(1), "view: mask"),
    key(
        '3',
        Action::Show(2),
        "view: error (false shadow orange, missed blue)",
    ),
    key('4', Action::Show(3), "view: the light's map"),
    key('5', Action::Show(4), "view: side by side"),
    named(KeyName::Left, false, Action::TurnLight(-1, 0), "light left"),
    named(
        KeyName::Right,
        false,
        Action::TurnLight(1, 0),
        "light right",
    ),
    named(KeyName::Up, false, Action::TurnLight(0, 1), "light up"),
    named(KeyName::Down, false, Action::TurnLight(0, -1), "light down"),
    named(
        KeyName::Left,
        true,
        Action::TurnCamera(-1, 0),
        "camera left",
    ),
    named(
        KeyName::Right,
        true,
        Action::TurnCamera(1, 0),
        "camera right",
    ),
    named(KeyName::Up, true, Action::TurnCamera(0, 1), "camera up"),
    named(
        KeyName::Down,
        true,
        Action::TurnCamera(0, -1),
        "camera down",
    ),
    key('r', Action::Reset, "reset everything"),
    key('s', Action::Save, "save what is shown as a PNG"),
    key(
        'p',
        Action::PrintCommand,
        "print the render command of this view",
    ),
    key('h', Action::Help, "show / hide this help"),
    key('q', Action::Quit, "quit"),
    named(KeyName::Escape, false, Action::Quit, "quit"),
];

/// The action of `key` (with shift held or not), if it has one.
pub fn action(key: KeyName, shift: bool) -> Option<Action> {
    let arrow = matches!(
        key,
        KeyName::Left | KeyName::Right | KeyName::Up | KeyName::Down
    );
    BINDINGS
        .iter()
        .find(|b| b.key == key && (!arrow || b.shift == shift))
        .map(|b| b.action)
}

/// The help: one line per binding, then the mouse.
pub fn help_lines() -> Vec<String> {
    let mut lines: Vec<String> = BINDINGS
        .iter()
        .map(|b| {
            let name = if b.shift {
                format!("shift+{}", b.key)
            } else {
                b.key.to_string()
            };
            format!("{name:>11}  {}", b.help)
        })
        .collect();
    lines.push(format!("{:>11}  turn the light", "drag"));
    lines.push(format!("{:>11}  turn the camera", "shift+drag"));
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_key_means_one_thing_and_the_help_lists_it() {
        for (i, a) in BINDINGS.iter().enumerate() {
            for b in &BINDINGS[i + 1..] {
                assert!(
                    !(a.key == b.key && a.shift == b.shift),
                    "{} bound twice",
                    a.key
                );
            }
        }
        assert_eq!(
            action(KeyName::Char('t'), false),
            Some(Action::Technique(1))
        );
        assert_eq!(
            action(KeyName::Char('T'), true),
            Some(Action::Technique(-1))
        );
        assert_eq!(action(KeyName::Left, true), Some(Action::TurnCamera(-1, 0)));
        assert_eq!(action(KeyName::Left, false), Some(Action::TurnLight(-1, 0)));
        assert_eq!(action(KeyName::Char('#'), false), None);
        let help = help_lines();
        assert_eq!(help.len(), BINDINGS.len() + 2);
        assert!(help
            .iter()
            .any(|l| l.contains("shift+left") && l.contains("camera")));
    }
}
