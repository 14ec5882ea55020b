//! The calls a front end answers from its own state, for both front ends alike: pixel
//! storage, the client attribute stack, the queries (`ff::answer`), and the calls whose
//! work is the C library's (glGetError, glGetString, glFinish, glFlush, glGenTextures,
//! glIsTexture), of which a script checks the arguments. None is compiled into a display
//! list (GL 1.5 §5.4) and none is allowed between glBegin and glEnd. A GL error such a call
//! raises reaches the pipeline as `Command::Raise`, so that the error flag holds it in
//! either front end.

use super::answer;
use super::api::Entry;
use super::args::Args;
use super::client_attrib::{ClientAttribMask, ClientGroups};
use super::command::Command;
use super::error::GlErrorKind;
use super::front::{Client, Reply};
use super::glenum::registry as r;
use super::glenum::GlEnum;
use super::queries::Answer;
use super::texture::TextureTarget;
use super::FixedState;

/// Whether `entry` is one of these calls.
pub fn handles(entry: Entry) -> bool {
    answer::handles(entry)
        || matches!(
            entry,
            Entry::PixelStorei
                | Entry::PixelStoref
                | Entry::PushClientAttrib
                | Entry::PopClientAttrib
                | Entry::GetError
                | Entry::GetString
                | Entry::Finish
                | Entry::Flush
                | Entry::GenTextures
                | Entry::IsTexture
                | Entry::AreTexturesResident
                | Entry::PrioritizeTextures
                | Entry::GetCompressedTexImage
                | Entry::GetCompressedTexImageARB
        )
        || super::framebuffer::answered_by_front_end(entry)
        || super::queries::never_compiled(entry)
}

impl Client {
    /// One of the calls [`handles`] names.
    pub(super) fn front_state_call<A: Args>(
        &mut self,
        c: &A,
        state: &FixedState,
        out: &mut Vec<Command>,
    ) -> Result<Reply, A::Error> {
        let entry = c.entry();
        if self.immediate.is_open() {
            return Err(c.immediate("a client-state call or query inside glBegin/glEnd"));
        }
        let gl = match entry {
            Entry::PixelStorei | Entry::PixelStoref => {
                self.pixel_store.call(c)?;
                Ok(Reply::None)
            }
            Entry::PushClientAttrib => {
                c.count(1)?;
                const BITS: [&str; 3] = [
                    "GL_CLIENT_PIXEL_STORE_BIT",
                    "GL_CLIENT_VERTEX_ARRAY_BIT",
                    "GL_CLIENT_ALL_ATTRIB_BITS",
                ];
                let mask = match c.bits(0, &BITS) {
                    Ok(found) => {
                        let mut mask = ClientAttribMask::default();
                        for bit in found {
                            let all = bit == "GL_CLIENT_ALL_ATTRIB_BITS";
                            mask.pixel_store |= all || bit == "GL_CLIENT_PIXEL_STORE_BIT";
                            mask.vertex_array |= all || bit == "GL_CLIENT_VERTEX_ARRAY_BIT";
                        }
                        mask
                    }
                    // Bits of no group, as an integer: ignored, as Mesa ignores them.
                    Err(e) => c.u32(0).map(ClientAttribMask::from_bits).map_err(|_| e)?,
                };
                let now = self.client_groups();
                self.client_attrib.push(mask, &now).map(|_| Reply::None)
            }
            Entry::PopClientAttrib => {
                c.count(0)?;
                let mut now = self.client_groups();
                let popped = self.client_attrib.pop(&mut now);
                self.pixel_store = now.pixel_store;
                self.arrays = now.arrays;
                self.buffers.bound = now.bindings;
                popped.map(|_| Reply::None)
            }
            Entry::GetError | Entry::Finish | Entry::Flush => {
                c.count(0).map(|_| Ok(Reply::None))?
            }
            Entry::GetString => {
                c.count(1)?;
                match c.token(0)? {
                    r::VENDOR | r::RENDERER | r::VERSION | r::EXTENSIONS => Ok(Reply::None),
                    _ => Err(GlErrorKind::InvalidEnum),
                }
            }
            Entry::GenTextures => {
                c.count(2)?;
                if c.i32(0)? < 0 {
                    return Err(c.bad(0, "a count of 0 or more"));
                }
                Ok(Reply::None)
            }
            Entry::IsTexture => {
                c.count(1)?;
                let name = c.u32(0)?;
                Ok(Reply::Value(u32::from(
                    name != 0 && state.textures.contains_key(&name),
                )))
            }
            Entry::AreTexturesResident | Entry::PrioritizeTextures => {
                self.residence(c, state, out)?
            }
            Entry::GetCompressedTexImage | Entry::GetCompressedTexImageARB => {
                c.count(3)?;
                compressed_image(state, c.token(0)?, c.i32(1)?)
                    .map(|bytes| Reply::Write { arg: 2, bytes })
            }
            e if super::queries::never_compiled(e) => {
                let signed = matches!(e, Entry::GetQueryObjectiv | Entry::GetQueryObjectivARB);
                super::queries::answer(c, state, out)?.map(|a| match a {
                    Answer::Reply(r) => r,
                    Answer::Object { id, param, target } => Reply::QueryObject {
                        id,
                        param,
                        target,
                        signed,
                    },
                })
            }
            e if super::framebuffer::answered_by_front_end(e) => {
                super::framebuffer::script_answer(c, state)?
            }
            _ => answer::answer(c, state, self)?,
        };
        Ok(gl.unwrap_or_else(|error| {
            out.push(Command::Raise { error, call: entry });
            Reply::None
        }))
    }

    fn client_groups(&self) -> ClientGroups {
        ClientGroups {
            pixel_store: self.pixel_store,
            arrays: self.arrays.clone(),
            bindings: self.buffers.bound,
        }
    }

    /// glAreTexturesResident(n, textures, residences) and glPrioritizeTextures(n,
    /// textures, priorities) (GL 1.5 §3.8.12): every texture is resident, so the first
    /// returns TRUE and leaves `residences` alone; the priorities are kept as each
    /// object's TEXTURE_PRIORITY (`Command::PrioritizeTextures`). n < 0 is INVALID_VALUE;
    /// glAreTexturesResident of 0 or a name that is no texture is INVALID_VALUE too.
    fn residence<A: Args>(
        &self,
        c: &A,
        state: &FixedState,
        out: &mut Vec<Command>,
    ) -> Result<Result<Reply, GlErrorKind>, A::Error> {
        c.count(3)?;
        let n = c.i32(0)?;
        if n < 0 {
            return Err(c.bad(0, "a count of 0 or more"));
        }
        if c.entry() == Entry::PrioritizeTextures {
            let names = c.array_as(1, n as usize, super::api::CType::UInt)?;
            let priorities = c.array_as(2, n as usize, super::api::CType::Float)?;
            out.push(Command::PrioritizeTextures(
                names
                    .iter()
                    .zip(priorities)
                    .map(|(name, p)| (*name as u32, p as f32))
                    .collect(),
            ));
            return Ok(Ok(Reply::None));
        }
        let names = c.array_as(1, n as usize, super::api::CType::UInt)?;
        let known = names
            .iter()
            .all(|v| *v != 0.0 && state.textures.contains_key(&(*v as u32)));
        Ok(if known {
            Ok(Reply::Value(1))
        } else {
            Err(GlErrorKind::InvalidValue)
        })
    }
}

/// glGetCompressedTexImage(target, level, img): the blocks of a compressed level of the
/// texture bound to `target` on the active unit, as given (GL 1.3 §6.1.4). A proxy or
/// unknown target is INVALID_ENUM; a level outside the target's range or never specified
/// INVALID_VALUE, an uncompressed one INVALID_OPERATION (Mesa, measured).
fn compressed_image(state: &FixedState, target: u32, level: i32) -> Result<Vec<u8>, GlErrorKind> {
    let t = TextureTarget::from_gl_value(target).ok_or(GlErrorKind::InvalidEnum)?;
    let name = state.units[state.active_unit()].bound(t);
    let l = state
        .texture(t, name)
        .filter(|_| (0..=t.max_level()).contains(&level))
        .and_then(|o| o.level_in(t, level))
        .ok_or(GlErrorKind::InvalidValue)?;
    l.compressed
        .as_ref()
        .map(|c| c.bytes.to_vec())
        .ok_or(GlErrorKind::InvalidOperation)
}
