//! Draws from buffer objects remembered: a glDrawArrays or glDrawElements whose arrays and
//! indices all lie in buffer objects gives the same `Geometry` as an earlier such draw —
//! one of the last [`REMEMBERED`], so a frame of many objects, each its own draw, repeats
//! every one of them — when nothing it reads has changed, so the draw hands the pipeline the same `Arc` and a
//! pipeline that keeps uploaded geometry by its `Arc` uploads it once (Mesa keeps a buffer
//! object's store in a GPU buffer the same way).
//!
//! The geometry is a function of the draw's arguments, the client arrays (pointers,
//! enables, the offsets into buffers they captured) and the buffers' stores. The key holds
//! the first two; the stores change only through a buffer-object call — which forgets the
//! draw ([`BufferDraws::forget`]) — or through a mapped pointer, so no draw is remembered
//! while a buffer it reads is mapped. A draw that reads client memory (which the program
//! may change at any time) is never remembered.

use std::sync::Arc;

use super::api::Entry;
use super::args::Args;
use super::buffers::Buffers;
use super::client::{ArrayData, ClientArrays};
use super::geometry::{Geometry, Primitive};

/// glDrawElements' index types.
const INDEX_TYPES: [&str; 3] = ["GL_UNSIGNED_BYTE", "GL_UNSIGNED_SHORT", "GL_UNSIGNED_INT"];

/// What a draw reads besides the buffers' stores.
#[derive(Clone, Debug, PartialEq)]
struct Key {
    entry: Entry,
    mode: Primitive,
    /// first and count (glDrawArrays); count (glDrawElements).
    counts: [i32; 2],
    /// glDrawElements' index type.
    ty: Option<&'static str>,
    /// glDrawElements' indices (an offset into the element buffer).
    indices: Option<ArrayData>,
    arrays: ClientArrays,
}

/// How many draws from buffer objects are remembered (the most recent ones).
pub const REMEMBERED: usize = 64;

/// The last draws from buffer objects and their geometry, the most recent last.
#[derive(Debug, Default)]
pub struct BufferDraws {
    last: Vec<(Key, Arc<Geometry>)>,
}

impl BufferDraws {
    /// A buffer-object call may change a store: no remembered draw survives it.
    pub fn forget(&mut self) {
        self.last.clear();
    }

    /// The geometry of draw `c` if it repeats the remembered one; `None` otherwise.
    pub fn get<A: Args>(
        &self,
        c: &A,
        arrays: &ClientArrays,
        buffers: &Buffers,
    ) -> Option<Arc<Geometry>> {
        let key = key_of(c, arrays, buffers)?;
        self.last
            .iter()
            .rev()
            .find(|(k, _)| *k == key)
            .map(|(_, g)| Arc::clone(g))
    }

    /// Remembers the geometry draw `c` made, if every array it reads is in a buffer.
    pub fn remember<A: Args>(
        &mut self,
        c: &A,
        arrays: &ClientArrays,
        buffers: &Buffers,
        geometry: &Arc<Geometry>,
    ) {
        let Some(key) = key_of(c, arrays, buffers) else {
            return;
        };
        self.last.retain(|(k, _)| *k != key);
        if self.last.len() >= REMEMBERED {
            self.last.remove(0);
        }
        self.last.push((key, Arc::clone(geometry)));
    }
}

/// The key of draw `c`: `None` for a call other than glDrawArrays and glDrawElements, an
/// array or index list in client memory, or a buffer read that is mapped.
fn key_of<A: Args>(c: &A, arrays: &ClientArrays, buffers: &Buffers) -> Option<Key> {
    let entry = c.entry();
    let mode: Primitive = c.enm(0).ok()?;
    let (counts, ty, indices) = match entry {
        Entry::DrawArrays => ([c.i32(1).ok()?, c.i32(2).ok()?], None, None),
        Entry::DrawElements => {
            let ty = c.pname(2, &INDEX_TYPES).ok()?;
            let indices = Buffers::source(c, 3, buffers.bound.element).ok()?;
            ([c.i32(1).ok()?, 0], Some(ty), Some(indices))
        }
        _ => return None,
    };
    // Every array a draw reads (the colour-index array is read by glArrayElement only).
    let enabled = [
        &arrays.vertex,
        &arrays.normal,
        &arrays.color,
        &arrays.edge_flag,
        &arrays.secondary_color,
        &arrays.fog_coord,
    ]
    .into_iter()
    .chain(arrays.texcoord.iter())
    .filter(|a| a.enabled)
    .map(|a| &a.data);
    for data in enabled.chain(indices.as_ref()) {
        match data {
            ArrayData::Buffer { name, .. } => {
                if buffers.get(*name).is_none_or(|b| b.mapped.is_some()) {
                    return None;
                }
            }
            _ => return None,
        }
    }
    Some(Key {
        entry,
        mode,
        counts,
        ty,
        indices,
        arrays: arrays.clone(),
    })
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use crate::ff::script::parse;
    use crate::ff::{Command, Geometry};

    fn draws(src: &str) -> Vec<Arc<Geometry>> {
        parse(src)
            .unwrap()
            .into_iter()
            .filter_map(|c| match c {
                Command::Draw(g) => Some(g),
                _ => None,
            })
            .collect()
    }

    const SETUP: &str = "glBindBuffer(GL_ARRAY_BUFFER, 1);\n\
        glBufferData(GL_ARRAY_BUFFER, 24, (GLfloat[]){0, 0, 1, 0, 0, 1}, GL_STATIC_DRAW);\n\
        glVertexPointer(2, GL_FLOAT, 0, NULL);\n\
        glEnableClientState(GL_VERTEX_ARRAY);\n\
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 2);\n\
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, 6, (GLushort[]){0, 1, 2}, GL_STATIC_DRAW);\n";
    const DRAW: &str = "glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, NULL);\n";

    #[test]
    fn a_repeated_draw_from_unchanged_buffers_gives_the_same_geometry() {
        let g = draws(&format!(
            "{SETUP}{DRAW}{DRAW}glDrawArrays(GL_TRIANGLES, 0, 3);"
        ));
        assert!(Arc::ptr_eq(&g[0], &g[1]));
        assert!(
            !Arc::ptr_eq(&g[1], &g[2]),
            "another draw is another geometry"
        );
        assert_eq!(g[0].indices.as_deref(), Some(&[0, 1, 2][..]));
    }

    #[test]
    fn a_changed_store_or_pointer_makes_a_new_geometry() {
        let sub = "glBufferSubData(GL_ARRAY_BUFFER, 0, 8, (GLfloat[]){-1, -1});\n";
        let g = draws(&format!("{SETUP}{DRAW}{sub}{DRAW}"));
        assert!(!Arc::ptr_eq(&g[0], &g[1]));
        assert_eq!((g[1].positions[0].x, g[1].positions[0].y), (-1.0, -1.0));
        let map = "glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY); glUnmapBuffer(GL_ARRAY_BUFFER);\n";
        let g = draws(&format!("{SETUP}{DRAW}{map}{DRAW}"));
        assert!(!Arc::ptr_eq(&g[0], &g[1]), "a mapping may write the store");
        let moved = "glVertexPointer(2, GL_FLOAT, 0, (const GLvoid *)8);\n";
        let short = "glDrawElements(GL_TRIANGLES, 1, GL_UNSIGNED_SHORT, NULL);\n";
        let g = draws(&format!("{SETUP}{DRAW}{moved}{short}"));
        assert!(!Arc::ptr_eq(&g[0], &g[1]));
        assert_eq!(g[1].positions[0].x, 1.0);
    }

    #[test]
    fn every_object_of_a_frame_repeats_its_own_draw() {
        // Two objects drawn in turn from one buffer, frame after frame.
        let other = "glDrawArrays(GL_TRIANGLES, 0, 3);\n";
        let g = draws(&format!("{SETUP}{DRAW}{other}{DRAW}{other}"));
        assert!(Arc::ptr_eq(&g[0], &g[2]));
        assert!(Arc::ptr_eq(&g[1], &g[3]));
    }

    #[test]
    fn a_draw_reading_any_array_from_client_memory_is_not_remembered() {
        let client = "glBindBuffer(GL_ARRAY_BUFFER, 0);\n\
            glSecondaryColorPointer(3, GL_FLOAT, 0, (GLfloat[]){1, 0, 0, 0, 1, 0, 0, 0, 1});\n\
            glEnableClientState(GL_SECONDARY_COLOR_ARRAY);\n";
        let g = draws(&format!("{SETUP}{client}{DRAW}{DRAW}"));
        assert!(!Arc::ptr_eq(&g[0], &g[1]));
    }
}
