//! Key scripts (`view --script KEYS`): the user's input written down with the frame it
//! arrives before, so that a run is deterministic.
//!
//! ```text
//! # frame  event
//! 2 key t            # next technique, before frame 2 is rendered
//! 3 key u
//! 3 key left shift   # shift+left: the camera turns
//! 4 drag 20 -10      # the light turns (dx, dy in pixels, y down)
//! 5 drag 8 0 shift   # the camera turns
//! ```
//!
//! Frames count from 1; events of one frame apply in the order written; frames must not
//! go backwards. Keys are named as the help names them (`t`, `T`, `left`, `esc`…).

use std::fmt;

use crate::gpu::{Input, KeyName};

/// One scripted input, and the frame it arrives before.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScriptedInput {
    pub frame: u32,
    pub input: Input,
}

/// A key script, in order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct KeyScript {
    pub inputs: Vec<ScriptedInput>,
}

/// What is wrong with a script, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ScriptError {
    pub line: usize,
    pub problem: String,
}

impl fmt::Display for ScriptError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.problem)
    }
}

impl std::error::Error for ScriptError {}

const FORMS: &str = "expected `FRAME key KEY [shift]` or `FRAME drag DX DY [shift]` \
                     (KEY a character or left, right, up, down, esc)";

impl KeyScript {
    /// Reads a script; the first error names its line and the forms a line may take.
    pub fn parse(text: &str) -> Result<KeyScript, ScriptError> {
        let mut inputs: Vec<ScriptedInput> = Vec::new();
        for (i, raw) in text.lines().enumerate() {
            let line = i + 1;
            let words: Vec<&str> = raw
                .split('#')
                .next()
                .unwrap_or("")
                .split_whitespace()
                .collect();
            if words.is_empty() {
                continue;
            }
            let err = |problem: String| ScriptError { line, problem };
            let frame: u32 = words[0].parse().ok().filter(|f| *f >= 1).ok_or_else(|| {
                err(format!(
                    "`{}` is not a frame number (1, 2, …); {FORMS}",
                    words[0]
                ))
            })?;
            if let Some(last) = inputs.last() {
                if frame < last.frame {
                    return Err(err(format!(
                        "frame {frame} comes after frame {}: frames must not go backwards",
                        last.frame
                    )));
                }
            }
            let shift_at = |n: usize| match words.get(n) {
                None => Ok(false),
                Some(&"shift") if words.len() == n + 1 => Ok(true),
                Some(w) => Err(err(format!("unexpected `{w}`; {FORMS}"))),
            };
            let input = match words.get(1) {
                Some(&"key") => {
                    let name = words
                        .get(2)
                        .ok_or_else(|| err(format!("no key; {FORMS}")))?;
                    let key = KeyName::parse(name)
                        .ok_or_else(|| err(format!("unknown key `{name}`; {FORMS}")))?;
                    Input::Key {
                        key,
                        shift: shift_at(3)?,
                    }
                }
                Some(&"drag") => {
                    let number = |n: usize| {
                        words
                            .get(n)
                            .and_then(|w| w.parse::<f64>().ok())
                            .filter(|v| v.is_finite())
                            .ok_or_else(|| err(format!("the drag needs finite DX and DY; {FORMS}")))
                    };
                    Input::Drag {
                        dx: number(2)?,
                        dy: number(3)?,
                        shift: shift_at(4)?,
                    }
                }
                Some(w) => return Err(err(format!("unknown event `{w}`; {FORMS}"))),
                None => return Err(err(format!("no event after the frame; {FORMS}"))),
            };
            inputs.push(ScriptedInput { frame, input });
        }
        Ok(KeyScript { inputs })
    }

    /// The inputs that arrive before frame `frame`.
    pub fn at(&self, frame: u32) -> impl Iterator<Item = Input> + '_ {
        self.inputs
            .iter()
            .filter(move |s| s.frame == frame)
            .map(|s| s.input)
    }

    /// The last frame an input arrives before.
    pub fn last_frame(&self) -> u32 {
        self.inputs.last().map_or(0, |s| s.frame)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scripts_read_in_order_with_comments_and_shift() {
        let s = KeyScript::parse(
            "# a comment\n\n2 key t\n2 key left shift # camera\n4 drag 20 -10\n5 drag 1.5 0 shift\n",
        )
        .unwrap();
        assert_eq!(s.inputs.len(), 4);
        let at2: Vec<Input> = s.at(2).collect();
        assert_eq!(
            at2,
            vec![
                Input::Key {
                    key: KeyName::Char('t'),
                    shift: false
                },
                Input::Key {
                    key: KeyName::Left,
                    shift: true
                }
            ]
        );
        assert_eq!(s.at(3).count(), 0);
        assert_eq!(s.last_frame(), 5);
        assert_eq!(
            s.at(5).next(),
            Some(Input::Drag {
                dx: 1.5,
                dy: 0.0,
                shift: true
            })
        );
    }

    #[test]
    fn a_bad_line_is_named_with_the_forms_a_line_may_take() {
        for (text, line, says) in [
            ("1 key t\nx key t", 2, "frame number"),
            ("0 key t", 1, "frame number"),
            ("3 key t\n2 key u", 2, "backwards"),
            ("1 key", 1, "no key"),
            ("1 key ctrl", 1, "unknown key `ctrl`"),
            ("1 drag 1", 1, "finite DX and DY"),
            ("1 drag 1 nan", 1, "finite DX and DY"),
            ("1 press t", 1, "unknown event `press`"),
            ("1 key t shift now", 1, "unexpected `shift`"),
            ("1", 1, "no event"),
        ] {
            let e = KeyScript::parse(text).unwrap_err();
            assert_eq!(e.line, line, "{text}: {e}");
            assert!(e.problem.contains(says), "{text}: {e}");
            if says != "backwards" {
                assert!(e.to_string().contains("FRAME key KEY"), "{text}: {e}");
            }
        }
    }
}
