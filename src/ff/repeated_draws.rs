//! Draws remembered: a glDrawArrays, glDrawElements or glDrawRangeElements that reads
//! exactly what an earlier one read gives that draw's `Geometry` — one of the last
//! [`REMEMBERED`], so a frame of many objects, each its own draw, repeats every one of them
//! — and a pipeline that keeps uploaded geometry by its `Arc` uploads it once. Mesa keeps a
//! buffer object's store in a GPU buffer the same way; for client arrays it copies the
//! arrays at every draw, which this replaces by a comparison.
//!
//! The geometry is a function of the draw's arguments, the client arrays (pointers,
//! enables, the offsets into buffers they captured), the buffers' stores and the program's
//! memory where the arrays and indices point. The key holds the first two. The stores
//! change only through a buffer-object call — which forgets the draws that read a buffer
//! ([`RepeatedDraws::forget_buffer_reads`]) — or through a mapped pointer, so no draw is
//! remembered while a buffer it reads is mapped. The program's memory may change at any
//! time (GL reads client arrays when the draw is called, GL 1.5 §2.8), so a remembered
//! draw keeps a copy of the bytes it read there, and a later draw is the same only if
//! every one of those spans still holds the same bytes: the indices first (they fix which
//! elements the arrays' spans cover), then each array's span from its first element read
//! to its last. The copies are held to [`MAX_COPIED_BYTES`].

use std::sync::Arc;

use super::api::Entry;
use super::args::Args;
use super::buffers::Buffers;
use super::client::{ArrayData, ClientArrays, ClientMemory};
use super::geometry::{Geometry, Primitive};
use super::glenum::registry;

/// glDrawElements' index types: name, token and size in bytes.
const INDEX_TYPES: [(&str, u32, usize); 3] = [
    ("GL_UNSIGNED_BYTE", registry::UNSIGNED_BYTE, 1),
    ("GL_UNSIGNED_SHORT", registry::UNSIGNED_SHORT, 2),
    ("GL_UNSIGNED_INT", registry::UNSIGNED_INT, 4),
];

/// How many draws are remembered (the most recent ones).
pub const REMEMBERED: usize = 64;

/// The most bytes of the program's memory the remembered draws hold copies of; the oldest
/// are forgotten past it, and a draw that read more than a quarter of it is not remembered
/// (a comparison as long as the copy it replaces would gain little).
pub const MAX_COPIED_BYTES: usize = 64 << 20;

/// What a draw reads besides the buffers' stores and the program's memory. A lookup
/// borrows the client arrays (`Key<&ClientArrays>`); only a draw remembered copies them.
#[derive(Clone, Debug, PartialEq)]
pub struct Key<Arrays = ClientArrays> {
    entry: Entry,
    mode: Primitive,
    /// first and count (glDrawArrays); count (glDrawElements); count, start and end
    /// (glDrawRangeElements).
    counts: [i64; 3],
    /// The indices' type name and size in bytes.
    ty: Option<(&'static str, usize)>,
    /// The indices: program memory, or an offset into the element buffer.
    indices: Option<ArrayData>,
    arrays: Arrays,
}

impl Key<&ClientArrays> {
    /// The key a remembered draw keeps.
    fn owned(self) -> Key {
        Key {
            entry: self.entry,
            mode: self.mode,
            counts: self.counts,
            ty: self.ty,
            indices: self.indices,
            arrays: self.arrays.clone(),
        }
    }
}

impl Key {
    /// Whether this remembered key is the looked-up `k`.
    fn is(&self, k: &Key<&ClientArrays>) -> bool {
        self.entry == k.entry
            && self.mode == k.mode
            && self.counts == k.counts
            && self.ty == k.ty
            && self.indices == k.indices
            && self.arrays == *k.arrays
    }

    /// Whether any array or the indices are in a buffer object.
    fn reads_buffer(&self) -> bool {
        self.arrays
            .drawn()
            .map(|a| &a.data)
            .chain(self.indices.as_ref())
            .any(|d| matches!(d, ArrayData::Buffer { .. }))
    }

    /// The elements the arrays are read for, `first..end`, given the geometry the draw
    /// made: glDrawArrays reads from `first`, the indexed draws from 0 to the largest
    /// index (`ClientArrays::indexed`); either way one position per element.
    fn elements(&self, g: &Geometry) -> (usize, usize) {
        let first = match self.entry {
            Entry::DrawArrays => usize::try_from(self.counts[0]).unwrap_or(0),
            _ => 0,
        };
        (first, first + g.positions.len())
    }
}

/// Bytes a remembered draw read from the program's memory, and where.
#[derive(Debug)]
struct Snapshot {
    data: ArrayData,
    start: usize,
    bytes: Box<[u8]>,
}

impl Snapshot {
    /// Whether the memory still holds these bytes.
    fn holds(&self, mem: &dyn ClientMemory) -> bool {
        mem.read(&self.data, self.start, self.bytes.len())
            .is_some_and(|now| *now == *self.bytes)
    }
}

#[derive(Debug)]
struct Remembered {
    key: Key,
    snapshots: Vec<Snapshot>,
    geometry: Arc<Geometry>,
}

impl Remembered {
    fn copied_bytes(&self) -> usize {
        self.snapshots.iter().map(|c| c.bytes.len()).sum()
    }
}

/// What [`RepeatedDraws::get`] found.
pub enum Lookup {
    /// The geometry of the remembered draw the call repeats.
    Repeat(Arc<Geometry>),
    /// A new draw, with the key to remember it by.
    New(Option<Box<Key>>),
}

/// The last draws and their geometry, the most recent last.
#[derive(Debug, Default)]
pub struct RepeatedDraws {
    last: Vec<Remembered>,
    /// The bytes the copies hold.
    copied: usize,
}

impl RepeatedDraws {
    /// A buffer-object call may change a store: no remembered draw that reads a buffer
    /// survives it.
    pub fn forget_buffer_reads(&mut self) {
        self.last.retain(|r| !r.key.reads_buffer());
        self.copied = self.last.iter().map(Remembered::copied_bytes).sum();
    }

    /// The geometry of draw `c` if it repeats a remembered one; otherwise the key to
    /// remember the draw by (`None` for a call that is no such draw or reads a mapped
    /// buffer).
    pub fn get<A: Args>(
        &self,
        c: &A,
        arrays: &ClientArrays,
        buffers: &Buffers,
        mem: &dyn ClientMemory,
    ) -> Lookup {
        let Some(key) = key_of(c, arrays, buffers) else {
            return Lookup::New(None);
        };
        match self
            .last
            .iter()
            .rev()
            .find(|r| r.key.is(&key) && r.snapshots.iter().all(|snap| snap.holds(mem)))
        {
            Some(r) => Lookup::Repeat(Arc::clone(&r.geometry)),
            None => Lookup::New(Some(Box::new(key.owned()))),
        }
    }

    /// Remembers the geometry the draw of `key` made, unless it read more of the
    /// program's memory than a quarter of [`MAX_COPIED_BYTES`].
    pub fn remember(&mut self, key: Box<Key>, mem: &dyn ClientMemory, geometry: &Arc<Geometry>) {
        let key = *key;
        let Some(snapshots) = snapshots_of(&key, geometry, mem) else {
            return;
        };
        let entry = Remembered {
            key,
            snapshots,
            geometry: Arc::clone(geometry),
        };
        let size = entry.copied_bytes();
        if size > MAX_COPIED_BYTES / 4 {
            return;
        }
        self.last.retain(|r| r.key != entry.key);
        self.copied = self.last.iter().map(Remembered::copied_bytes).sum();
        while !self.last.is_empty()
            && (self.last.len() >= REMEMBERED || self.copied + size > MAX_COPIED_BYTES)
        {
            let oldest = self.last.remove(0);
            self.copied -= oldest.copied_bytes();
        }
        self.last.push(entry);
        self.copied += size;
    }
}

/// The key of draw `c`: `None` for a call other than the three draws, or a draw that
/// reads a buffer that is mapped (or gone).
fn key_of<'a, A: Args>(
    c: &A,
    arrays: &'a ClientArrays,
    buffers: &Buffers,
) -> Option<Key<&'a ClientArrays>> {
    let entry = c.entry();
    let mode: Primitive = c.enm(0).ok()?;
    let index_type = |i: usize| {
        let token = c.token(i).ok()?;
        let (name, _, size) = INDEX_TYPES.into_iter().find(|(_, t, _)| *t == token)?;
        Some((name, size))
    };
    let element = buffers.bound.element;
    let (counts, ty, indices) = match entry {
        Entry::DrawArrays => {
            let counts = [c.i32(1).ok()?.into(), c.i32(2).ok()?.into(), 0];
            (counts, None, None)
        }
        Entry::DrawElements => {
            let indices = Buffers::source(c, 3, element).ok()?;
            (
                [c.i32(1).ok()?.into(), 0, 0],
                Some(index_type(2)?),
                Some(indices),
            )
        }
        Entry::DrawRangeElements => {
            let counts = [
                c.i32(3).ok()?.into(),
                c.u32(1).ok()?.into(),
                c.u32(2).ok()?.into(),
            ];
            let indices = Buffers::source(c, 5, element).ok()?;
            (counts, Some(index_type(4)?), Some(indices))
        }
        _ => return None,
    };
    for data in arrays.drawn().map(|a| &a.data).chain(indices.as_ref()) {
        if let ArrayData::Buffer { name, .. } = data {
            if buffers.get(*name).is_none_or(|b| b.mapped.is_some()) {
                return None;
            }
        }
    }
    Some(Key {
        entry,
        mode,
        counts,
        ty,
        indices,
        arrays,
    })
}

/// Copies of what the draw of `key`, which made `g`, read from the program's memory: the
/// indices, then each array's span. `None` when a span cannot be named or read.
fn snapshots_of(key: &Key, g: &Geometry, mem: &dyn ClientMemory) -> Option<Vec<Snapshot>> {
    // The indices' span: count × size bytes (counts[0] is the indexed draws' count).
    let index_span = key.ty.and_then(|(_, size)| {
        let count = usize::try_from(key.counts[0]).ok()?;
        Some((0, count.checked_mul(size)?))
    });
    let (first, end) = key.elements(g);
    key.indices
        .iter()
        .map(|data| (data, index_span))
        .chain(key.arrays.spans(first, end))
        .filter(|(data, _)| matches!(data, ArrayData::Address(_)))
        .map(|(data, span)| {
            let (start, len) = span?;
            let bytes = mem.read(data, start, len)?;
            Some(Snapshot {
                data: data.clone(),
                start,
                bytes: bytes.into_owned().into_boxed_slice(),
            })
        })
        .collect()
}

#[cfg(test)]
mod tests;
