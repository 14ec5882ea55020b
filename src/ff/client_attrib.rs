//! The client attribute stack (GL 1.5 §6.1.14): glPushClientAttrib(mask) saves the groups
//! of client state the mask names, glPopClientAttrib restores what the matching push
//! saved. Two groups exist: GL_CLIENT_PIXEL_STORE_BIT (the pack and unpack state,
//! [`PixelStore`]) and GL_CLIENT_VERTEX_ARRAY_BIT (every array's enable, pointer, size,
//! type and stride, the client active texture unit and, as Mesa saves them with the
//! arrays, the ARRAY_BUFFER and ELEMENT_ARRAY_BUFFER bindings). The stack holds
//! MAX_CLIENT_ATTRIB_STACK_DEPTH = 16 entries (Mesa's); a push on a full stack is
//! STACK_OVERFLOW and a pop of an empty one STACK_UNDERFLOW, each doing nothing else.
//! Neither call is compiled into a display list (§5.4): they run at once.

use super::buffers::Bindings;
use super::client::ClientArrays;
use super::error::GlErrorKind;
use super::pixel_store::PixelStore;

/// GL_MAX_CLIENT_ATTRIB_STACK_DEPTH (Mesa: 16; GL asks for at least 16).
pub const MAX_CLIENT_ATTRIB_STACK_DEPTH: usize = 16;

/// The groups a glPushClientAttrib mask names (GL_CLIENT_ALL_ATTRIB_BITS names both; the
/// other bits name nothing and are ignored, as Mesa ignores them).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClientAttribMask {
    pub pixel_store: bool,
    pub vertex_array: bool,
}

impl ClientAttribMask {
    /// The groups whose bits `mask` sets; other bits name nothing.
    pub fn from_bits(mask: u32) -> Self {
        use super::glenum::registry as r;
        Self {
            pixel_store: mask & r::CLIENT_PIXEL_STORE_BIT != 0,
            vertex_array: mask & r::CLIENT_VERTEX_ARRAY_BIT != 0,
        }
    }
}

/// The client state the stack saves and restores, as the front end holds it.
#[derive(Clone, Debug, PartialEq)]
pub struct ClientGroups {
    pub pixel_store: PixelStore,
    pub arrays: ClientArrays,
    pub bindings: Bindings,
}

/// One pushed entry: each group the mask named, as it was.
#[derive(Clone, Debug, PartialEq)]
struct Saved {
    pixel_store: Option<PixelStore>,
    arrays: Option<(ClientArrays, Bindings)>,
}

/// The stack. GL default: empty.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ClientAttribStack {
    saved: Vec<Saved>,
}

impl ClientAttribStack {
    /// GL_CLIENT_ATTRIB_STACK_DEPTH.
    pub fn depth(&self) -> usize {
        self.saved.len()
    }

    /// glPushClientAttrib(mask).
    pub fn push(&mut self, mask: ClientAttribMask, now: &ClientGroups) -> Result<(), GlErrorKind> {
        if self.saved.len() >= MAX_CLIENT_ATTRIB_STACK_DEPTH {
            return Err(GlErrorKind::StackOverflow);
        }
        self.saved.push(Saved {
            pixel_store: mask.pixel_store.then_some(now.pixel_store),
            arrays: mask
                .vertex_array
                .then(|| (now.arrays.clone(), now.bindings)),
        });
        Ok(())
    }

    /// glPopClientAttrib: the groups the matching push saved are put back into `now`.
    pub fn pop(&mut self, now: &mut ClientGroups) -> Result<(), GlErrorKind> {
        let saved = self.saved.pop().ok_or(GlErrorKind::StackUnderflow)?;
        if let Some(p) = saved.pixel_store {
            now.pixel_store = p;
        }
        if let Some((arrays, bindings)) = saved.arrays {
            now.arrays = arrays;
            now.bindings = bindings;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn groups() -> ClientGroups {
        ClientGroups {
            pixel_store: PixelStore::default(),
            arrays: ClientArrays::default(),
            bindings: Bindings::default(),
        }
    }

    const ALL: ClientAttribMask = ClientAttribMask {
        pixel_store: true,
        vertex_array: true,
    };

    #[test]
    fn a_pop_restores_only_the_groups_pushed() {
        let mut stack = ClientAttribStack::default();
        let mut now = groups();
        let mask = ClientAttribMask {
            pixel_store: true,
            vertex_array: false,
        };
        stack.push(mask, &now).unwrap();
        now.pixel_store.unpack.alignment = 1;
        now.pixel_store.unpack.row_length = 9;
        now.pixel_store.pack.skip_images = 2;
        now.arrays.vertex.enabled = true;
        now.arrays.client_active = 3;
        now.bindings.array = 7;
        stack.pop(&mut now).unwrap();
        assert_eq!(now.pixel_store, PixelStore::default());
        assert!(now.arrays.vertex.enabled);
        assert_eq!((now.arrays.client_active, now.bindings.array), (3, 7));

        stack.push(ALL, &now).unwrap();
        now.arrays = ClientArrays::default();
        now.bindings = Bindings::default();
        stack.pop(&mut now).unwrap();
        assert!(now.arrays.vertex.enabled);
        assert_eq!((now.arrays.client_active, now.bindings.array), (3, 7));
    }

    #[test]
    fn sixteen_entries_then_overflow_and_underflow_change_nothing() {
        let mut stack = ClientAttribStack::default();
        let mut now = groups();
        for _ in 0..MAX_CLIENT_ATTRIB_STACK_DEPTH {
            stack.push(ALL, &now).unwrap();
        }
        assert_eq!(stack.push(ALL, &now), Err(GlErrorKind::StackOverflow));
        assert_eq!(stack.depth(), 16);
        for _ in 0..MAX_CLIENT_ATTRIB_STACK_DEPTH {
            stack.pop(&mut now).unwrap();
        }
        now.pixel_store.pack.alignment = 8;
        assert_eq!(stack.pop(&mut now), Err(GlErrorKind::StackUnderflow));
        assert_eq!((stack.depth(), now.pixel_store.pack.alignment), (0, 8));
    }
}
