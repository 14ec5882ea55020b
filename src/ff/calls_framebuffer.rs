//! The framebuffer-object calls, core/ARB and EXT names alike (`ff::framebuffer`):
//! binding, deleting, attaching, renderbuffer storage, glGenerateMipmap, glDrawBuffer and
//! glReadBuffer. Names are generated and objects queried by the front ends (the C
//! library answers glGen*, glIs*, glCheckFramebufferStatus and the getters from the
//! model; a script names its objects).

use super::api::{CType, Entry};
use super::args::Args;
use super::error::GlErrorKind;
use super::texture::TextureTarget;
use super::Command;

/// The Command of a framebuffer call; `Ok(None)` for calls of other areas.
pub fn framebuffer<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    use Entry as E;
    Ok(Some(match c.entry() {
        E::BindFramebuffer | E::BindFramebufferEXT => {
            c.count(2)?;
            Command::BindFramebuffer {
                target: c.enm(0)?,
                name: c.u32(1)?,
            }
        }
        E::DeleteFramebuffers | E::DeleteFramebuffersEXT => Command::DeleteFramebuffers(names(c)?),
        E::BindRenderbuffer | E::BindRenderbufferEXT => {
            c.count(2)?;
            c.pname(0, RENDERBUFFER)?;
            Command::BindRenderbuffer(c.u32(1)?)
        }
        E::DeleteRenderbuffers | E::DeleteRenderbuffersEXT => {
            Command::DeleteRenderbuffers(names(c)?)
        }
        E::RenderbufferStorage | E::RenderbufferStorageEXT => {
            c.count(4)?;
            c.pname(0, RENDERBUFFER)?;
            Command::RenderbufferStorage {
                format: c.enm(1)?,
                width: c.i32(2)?,
                height: c.i32(3)?,
            }
        }
        e @ (E::FramebufferTexture1D
        | E::FramebufferTexture1DEXT
        | E::FramebufferTexture2D
        | E::FramebufferTexture2DEXT) => {
            c.count(5)?;
            let target = c.enm(0)?;
            let attachment = c.enm(1)?;
            let textarget: TextureTarget = c.enm(2)?;
            let name = c.u32(3)?;
            let dimension = match e {
                E::FramebufferTexture1D | E::FramebufferTexture1DEXT => TextureTarget::Texture1D,
                _ => TextureTarget::Texture2D,
            };
            // A 2D call with a 1D textarget (or the other way round) names no image of
            // that call: INVALID_OPERATION, as Mesa (tests/c/fbo.c).
            if name != 0 && textarget != dimension {
                return Ok(Some(Command::Raise {
                    error: GlErrorKind::InvalidOperation,
                    call: e,
                }));
            }
            Command::FramebufferTexture {
                target,
                attachment,
                texture: (name != 0).then_some((textarget, name)),
                level: c.i32(4)?,
            }
        }
        E::FramebufferRenderbuffer | E::FramebufferRenderbufferEXT => {
            c.count(4)?;
            let target = c.enm(0)?;
            let attachment = c.enm(1)?;
            c.pname(2, RENDERBUFFER)?;
            Command::FramebufferRenderbuffer {
                target,
                attachment,
                renderbuffer: c.u32(3)?,
            }
        }
        E::GenerateMipmap | E::GenerateMipmapEXT => {
            c.count(1)?;
            Command::GenerateMipmap(c.enm(0)?)
        }
        E::DrawBuffer => {
            c.count(1)?;
            Command::DrawBuffer(c.enm(0)?)
        }
        E::ReadBuffer => {
            c.count(1)?;
            Command::ReadBuffer(c.enm(0)?)
        }
        _ => return Ok(None),
    }))
}

/// GL_RENDERBUFFER and its EXT name.
const RENDERBUFFER: &[&str] = &["GL_RENDERBUFFER", "GL_RENDERBUFFER_EXT"];

/// (n, names): n below 0 is INVALID_VALUE.
fn names<A: Args>(c: &A) -> Result<Vec<u32>, A::Error> {
    c.count(2)?;
    let n = c.i32(0)?;
    if n < 0 {
        return Err(c.bad(0, "a count of 0 or more"));
    }
    let names = c.array_as(1, n as usize, CType::UInt)?;
    Ok(names.into_iter().map(|v| v as u32).collect())
}
