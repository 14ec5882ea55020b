//! The attribute-stack calls: glPushAttrib(mask) with the group bits joined by '|' (or
//! GL_ALL_ATTRIB_BITS, or an integer, as C allows), and glPopAttrib().

use super::parse::Call;
use super::ScriptError;
use crate::ff::api::Entry;
use crate::ff::glenum::GlEnum;
use crate::ff::{AttribGroup, AttribMask, Command};

type Res<T> = Result<T, ScriptError>;

/// glPushAttrib / glPopAttrib; `Ok(None)` for calls of other areas.
pub(super) fn attrib(c: &Call) -> Res<Option<Command>> {
    Ok(Some(match c.entry {
        Entry::PushAttrib => {
            c.count(1)?;
            Command::PushAttrib(mask(c)?)
        }
        Entry::PopAttrib => {
            c.count(0)?;
            Command::PopAttrib
        }
        _ => return Ok(None),
    }))
}

fn mask(c: &Call) -> Res<AttribMask> {
    let Some(names) = c.or_names(0) else {
        return c
            .u32(0)
            .map(AttribMask)
            .map_err(|_| c.bad(0, "attribute bits joined by '|', or an integer"));
    };
    let mut bits = 0;
    for name in names {
        bits |= match name {
            "GL_ALL_ATTRIB_BITS" => AttribMask::ALL.0,
            other => AttribGroup::from_gl_name(other)
                .map(AttribGroup::bit)
                .ok_or_else(|| {
                    let mut expected = AttribGroup::names();
                    expected.push("GL_ALL_ATTRIB_BITS");
                    ScriptError::UnknownEnum {
                        line: c.line,
                        call: c.name,
                        arg: 1,
                        name: other.to_string(),
                        expected,
                    }
                })?,
        };
    }
    Ok(AttribMask(bits))
}
