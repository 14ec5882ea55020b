//! The attribute-stack calls: glPushAttrib(mask) with the group bits joined by '|' (or
//! GL_ALL_ATTRIB_BITS, or an integer, as C allows), and glPopAttrib().

use super::api::Entry;
use super::args::Args;
use super::glenum::GlEnum;
use super::{AttribGroup, AttribMask, Command};

/// glPushAttrib / glPopAttrib; `Ok(None)` for calls of other areas.
pub fn attrib<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    Ok(Some(match c.entry() {
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

fn mask<A: Args>(c: &A) -> Result<AttribMask, A::Error> {
    // The bits by name; GL_ALL_ATTRIB_BITS is every bit, and bits outside the groups are
    // kept as given (GL ignores them; a script may write the mask as an integer).
    let mut names = AttribGroup::names();
    names.push("GL_ALL_ATTRIB_BITS");
    match c.bits(0, &names) {
        Ok(found) => Ok(AttribMask(found.iter().fold(0, |bits, n| {
            bits | match *n {
                "GL_ALL_ATTRIB_BITS" => AttribMask::ALL.0,
                other => AttribGroup::from_gl_name(other).map_or(0, AttribGroup::bit),
            }
        }))),
        Err(e) => c.u32(0).map(AttribMask).map_err(|_| e),
    }
}
