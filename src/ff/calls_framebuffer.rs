//! The framebuffer-object calls, core/ARB and EXT names alike (`ff::framebuffer`):
//! binding, deleting, attaching, renderbuffer storage, glGenerateMipmap, glDrawBuffer and
//! glReadBuffer. Names are generated and objects queried by the front ends (the C
//! library answers glGen*, glIs*, glCheckFramebufferStatus and the getters from the
//! model; a script names its objects).

use super::api::{CType, Entry};
use super::args::Args;
use super::blit::{Blit, BlitFilter, BlitMask, BlitRect, FilterArg};
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
            // that call: INVALID_OPERATION, as Mesa (tests/c/fbo.c). A cube map's face is
            // an image of the 2D call (EXT_framebuffer_object), of the 1D call none.
            let named = textarget == dimension
                || (dimension == TextureTarget::Texture2D && textarget.face().is_some());
            if name != 0 && !named {
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
                layer: 0,
            }
        }
        e @ (E::FramebufferTexture3D | E::FramebufferTexture3DEXT) => {
            c.count(6)?;
            let target = c.enm(0)?;
            let attachment = c.enm(1)?;
            let textarget: TextureTarget = c.enm(2)?;
            let name = c.u32(3)?;
            // Only a TEXTURE_3D textarget names an image of a 3D call (Mesa:
            // INVALID_OPERATION, measured).
            if name != 0 && textarget != TextureTarget::Texture3D {
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
                layer: c.i32(5)?,
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
            let target: TextureTarget = c.enm(0)?;
            // A cube map's faces are generated together: a face alone is INVALID_ENUM.
            if target.face().is_some() {
                return Err(c.unknown(0, vec!["GL_TEXTURE_CUBE_MAP"]));
            }
            Command::GenerateMipmap(target)
        }
        E::BlitFramebuffer | E::BlitFramebufferEXT => {
            c.count(10)?;
            let int = |k: usize| c.i32(k);
            Command::BlitFramebuffer(Blit {
                src: BlitRect {
                    x0: int(0)?,
                    y0: int(1)?,
                    x1: int(2)?,
                    y1: int(3)?,
                },
                dst: BlitRect {
                    x0: int(4)?,
                    y0: int(5)?,
                    x1: int(6)?,
                    y1: int(7)?,
                },
                mask: blit_mask(c)?,
                filter: blit_filter(c)?,
            })
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

/// The buffer bits of a blit mask.
const BLIT_BITS: [&str; 3] = [
    "GL_COLOR_BUFFER_BIT",
    "GL_DEPTH_BUFFER_BIT",
    "GL_STENCIL_BUFFER_BIT",
];

/// glBlitFramebuffer's mask: the buffer bits joined by '|', or (any other bit set) the
/// value as given, checked by the model after completeness (`ff::blit`).
fn blit_mask<A: Args>(c: &A) -> Result<BlitMask, A::Error> {
    let value = match c.bits(8, &BLIT_BITS) {
        Ok(names) => names
            .iter()
            .filter_map(|n| crate::ff::glenum::value_of(n))
            .fold(0, |m, b| m | b),
        Err(e) => c.u32(8).map_err(|_| e)?,
    };
    Ok(BlitMask::from_bits(value))
}

/// glBlitFramebuffer's filter: a token outside NEAREST, LINEAR and the SCALED_RESOLVE pair
/// is kept as its value for the model to refuse after completeness (`ff::blit`).
fn blit_filter<A: Args>(c: &A) -> Result<FilterArg, A::Error> {
    match c.enm::<BlitFilter>(9) {
        Ok(f) => Ok(FilterArg::Known(f)),
        Err(e) => {
            let value = c.token(9).or_else(|_| c.u32(9)).map_err(|_| e)?;
            Ok(FilterArg::Other(value))
        }
    }
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
