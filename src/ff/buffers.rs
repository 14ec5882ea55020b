//! Buffer objects (GL 1.5 §2.9, ARB_vertex_buffer_object) as client-side byte stores.
//!
//! A buffer's data lives on the CPU, in a heap allocation the buffer owns: a draw whose
//! arrays (or indices) name a buffer reads the bytes into its `Command::Draw` geometry
//! exactly as it reads client arrays, so the pipelines never see a buffer. This is client
//! state of the front end ([`Client::buffers`](super::front::Client)): names, the
//! ARRAY_BUFFER and ELEMENT_ARRAY_BUFFER bindings, and each buffer's size, usage and
//! mapping.
//!
//! glMapBuffer hands the C program the address of that allocation; writes through it are
//! seen by later draws because draws read the same bytes. The allocation changes only on
//! glBufferData (which unmaps first, as Mesa does), never while the buffer is mapped.
//!
//! Calls that give values back (glGenBuffers' names, glGetBufferParameteriv's integer,
//! glGetBufferSubData's bytes, glMapBuffer's address) return them as a [`Reply`]; the C
//! library writes them out, a script ignores them.

use std::collections::BTreeMap;

use super::api::{CType, Entry};
use super::args::Args;
use super::client::{ArrayData, ClientMemory};
use super::front::Reply;
use super::glenum::GlEnum;

/// A buffer binding point (GL 1.5 Table 2.7).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    Array,
    ElementArray,
}

impl GlEnum for Target {
    const TABLE: &'static [(&'static str, u32, Self)] = &[
        ("GL_ARRAY_BUFFER", 0x8892, Target::Array),
        ("GL_ELEMENT_ARRAY_BUFFER", 0x8893, Target::ElementArray),
    ];
}

/// glBufferData's usage hint (GL 1.5 §2.9.2). GL default: STATIC_DRAW.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Usage {
    StreamDraw,
    StreamRead,
    StreamCopy,
    StaticDraw,
    StaticRead,
    StaticCopy,
    DynamicDraw,
    DynamicRead,
    DynamicCopy,
}

impl GlEnum for Usage {
    const TABLE: &'static [(&'static str, u32, Self)] = &[
        ("GL_STREAM_DRAW", 0x88E0, Usage::StreamDraw),
        ("GL_STREAM_READ", 0x88E1, Usage::StreamRead),
        ("GL_STREAM_COPY", 0x88E2, Usage::StreamCopy),
        ("GL_STATIC_DRAW", 0x88E4, Usage::StaticDraw),
        ("GL_STATIC_READ", 0x88E5, Usage::StaticRead),
        ("GL_STATIC_COPY", 0x88E6, Usage::StaticCopy),
        ("GL_DYNAMIC_DRAW", 0x88E8, Usage::DynamicDraw),
        ("GL_DYNAMIC_READ", 0x88E9, Usage::DynamicRead),
        ("GL_DYNAMIC_COPY", 0x88EA, Usage::DynamicCopy),
    ];
}

/// glMapBuffer's access (GL 1.5 §2.9.3). GL default: READ_WRITE.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    ReadOnly,
    WriteOnly,
    ReadWrite,
}

impl GlEnum for Access {
    const TABLE: &'static [(&'static str, u32, Self)] = &[
        ("GL_READ_ONLY", 0x88B8, Access::ReadOnly),
        ("GL_WRITE_ONLY", 0x88B9, Access::WriteOnly),
        ("GL_READ_WRITE", 0x88BA, Access::ReadWrite),
    ];
}

/// glGetBufferParameteriv's names (GL 1.5 Table 2.8).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BufferParam {
    Size,
    Usage,
    Access,
    Mapped,
}

impl GlEnum for BufferParam {
    const TABLE: &'static [(&'static str, u32, Self)] = &[
        ("GL_BUFFER_SIZE", 0x8764, BufferParam::Size),
        ("GL_BUFFER_USAGE", 0x8765, BufferParam::Usage),
        ("GL_BUFFER_ACCESS", 0x88BB, BufferParam::Access),
        ("GL_BUFFER_MAPPED", 0x88BC, BufferParam::Mapped),
    ];
}

/// One buffer object. GL defaults (Table 2.8): size 0, STATIC_DRAW, READ_WRITE, unmapped.
#[derive(Clone, Debug, PartialEq)]
pub struct Buffer {
    /// The data store: a heap allocation whose address glMapBuffer hands out.
    data: Box<[u8]>,
    pub usage: Usage,
    /// The access of the current mapping; `None` when unmapped.
    pub mapped: Option<Access>,
}

impl Default for Buffer {
    fn default() -> Self {
        Buffer {
            data: Box::default(),
            usage: Usage::StaticDraw,
            mapped: None,
        }
    }
}

impl Buffer {
    pub fn size(&self) -> usize {
        self.data.len()
    }
}

/// The names bound to the two targets; 0 is no buffer (client memory). GL default: 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Bindings {
    pub array: u32,
    pub element: u32,
}

/// The buffer objects of a front end.
#[derive(Debug, Default)]
pub struct Buffers {
    /// Buffer objects: names that have been bound (GL 1.5 §2.9.1: glBindBuffer of an
    /// unused name creates the object).
    objects: BTreeMap<u32, Buffer>,
    /// The largest name glGenBuffers has returned: names up to it are never handed out
    /// again. A generated name is not an object until bound (glIsBuffer is false for it,
    /// as in Mesa).
    generated: u32,
    pub bound: Bindings,
}

impl Buffers {
    /// Whether `entry` is a buffer-object call.
    pub fn handles(entry: Entry) -> bool {
        use Entry::*;
        matches!(
            entry,
            GenBuffers
                | GenBuffersARB
                | DeleteBuffers
                | DeleteBuffersARB
                | BindBuffer
                | BindBufferARB
                | BufferData
                | BufferDataARB
                | BufferSubData
                | BufferSubDataARB
                | GetBufferSubData
                | GetBufferSubDataARB
                | MapBuffer
                | MapBufferARB
                | UnmapBuffer
                | UnmapBufferARB
                | IsBuffer
                | IsBufferARB
                | GetBufferParameteriv
                | GetBufferParameterivARB
                | GetBufferPointerv
                | GetBufferPointervARB
        )
    }

    /// The buffer object named `name`, if there is one.
    pub fn get(&self, name: u32) -> Option<&Buffer> {
        self.objects.get(&name)
    }

    /// `len` bytes of buffer `name` from `offset`; `None` outside its store.
    pub fn read(&self, name: u32, offset: usize, len: usize) -> Option<&[u8]> {
        self.objects
            .get(&name)?
            .data
            .get(offset..offset.checked_add(len)?)
    }

    /// The data a pointer argument names: with a buffer bound to the target it reads from,
    /// the argument is a byte offset into that buffer (GL 1.5 §2.9.4), captured now;
    /// without, client memory.
    pub fn source<A: Args>(c: &A, i: usize, bound: u32) -> Result<ArrayData, A::Error> {
        if bound == 0 {
            c.array_data(i)
        } else {
            Ok(ArrayData::Buffer {
                name: bound,
                offset: c.offset(i)?,
            })
        }
    }

    /// Runs one buffer-object call; `mem` reads the data glBufferData and glBufferSubData
    /// copy from. Errors are GL 1.5 §2.9's: INVALID_ENUM for a target, usage, access or
    /// parameter name outside the set; INVALID_VALUE for a negative count, size or offset
    /// or a range past the store; INVALID_OPERATION with buffer 0 bound, for a mapped
    /// buffer where it must not be, and for unmapping an unmapped one.
    pub fn call<A: Args>(&mut self, c: &A, mem: &dyn ClientMemory) -> Result<Reply, A::Error> {
        use Entry::*;
        Ok(match c.entry() {
            GenBuffers | GenBuffersARB => {
                let n = count(c, 0)?;
                let mut bytes = Vec::new();
                bytes
                    .try_reserve_exact(n.saturating_mul(4))
                    .map_err(|_| c.bad(0, "a count that can be allocated"))?;
                // Names past 2³² − 1: GL's OUT_OF_MEMORY, INVALID_VALUE here.
                let names = self
                    .generate(n)
                    .ok_or_else(|| c.bad(0, "a count of names still free"))?;
                bytes.extend(names.flat_map(u32::to_ne_bytes));
                Reply::Write { arg: 1, bytes }
            }
            DeleteBuffers | DeleteBuffersARB => {
                let n = count(c, 0)?;
                let names = if n == 0 {
                    Vec::new()
                } else {
                    c.array_as(1, n, CType::UInt)?
                };
                for name in names {
                    self.delete(name as u32);
                }
                Reply::None
            }
            BindBuffer | BindBufferARB => {
                let target: Target = c.enm(0)?;
                let name = c.u32(1)?;
                if name != 0 {
                    self.objects.entry(name).or_default();
                }
                *self.binding(target) = name;
                Reply::None
            }
            BufferData | BufferDataARB => {
                let name = self.bound_name(c)?;
                let size = c.int(1)?;
                if size < 0 {
                    return Err(c.bad(1, "a size of 0 or more"));
                }
                let usage: Usage = c.enm(3)?;
                let source = c.array_data(2)?;
                let size = usize::try_from(size).map_err(|_| c.bad(1, "a size"))?;
                // A store that cannot be allocated is GL's OUT_OF_MEMORY, which the layer
                // has not got: INVALID_VALUE, and the buffer is left as it was.
                let mut store = Vec::new();
                store
                    .try_reserve_exact(size)
                    .map_err(|_| c.bad(1, "a size that can be allocated"))?;
                let data: Box<[u8]> = match source {
                    // NULL: a store of `size` bytes whose contents GL leaves undefined.
                    ArrayData::Null => {
                        store.resize(size, 0);
                        store.into()
                    }
                    src => mem
                        .read(&src, 0, size)
                        .ok_or_else(|| c.bad(2, "at least `size` bytes of data"))?
                        .into_owned()
                        .into(),
                };
                // A mapped buffer is unmapped first, not an error (Mesa's
                // _mesa_buffer_unmap_all_mappings).
                let buffer = self.object(name);
                *buffer = Buffer {
                    data,
                    usage,
                    mapped: None,
                };
                Reply::None
            }
            BufferSubData | BufferSubDataARB => {
                let name = self.bound_name(c)?;
                let range = self.range(c, name)?;
                let bytes = match c.array_data(3)? {
                    ArrayData::Null if range.is_empty() => Vec::new(),
                    src => mem
                        .read(&src, 0, range.len())
                        .ok_or_else(|| c.bad(3, "at least `size` bytes of data"))?
                        .into_owned(),
                };
                self.object(name).data[range].copy_from_slice(&bytes);
                Reply::None
            }
            GetBufferSubData | GetBufferSubDataARB => {
                let name = self.bound_name(c)?;
                let range = self.range(c, name)?;
                Reply::Write {
                    arg: 3,
                    bytes: self.object(name).data[range].to_vec(),
                }
            }
            MapBuffer | MapBufferARB => {
                // Mesa checks the access before the target.
                let access: Access = c.enm(1)?;
                let name = self.bound_name(c)?;
                let buffer = self.object(name);
                if buffer.mapped.is_some() {
                    return Err(c.immediate("the buffer is already mapped"));
                }
                buffer.mapped = Some(access);
                Reply::Address(buffer.data.as_mut_ptr() as usize)
            }
            UnmapBuffer | UnmapBufferARB => {
                let name = self.bound_name(c)?;
                let buffer = self.object(name);
                if buffer.mapped.take().is_none() {
                    return Err(c.immediate("the buffer is not mapped"));
                }
                // The store never moves or changes behind the program's back: TRUE.
                Reply::Value(1)
            }
            IsBuffer | IsBufferARB => {
                Reply::Value(u32::from(self.objects.contains_key(&c.u32(0)?)))
            }
            GetBufferParameteriv | GetBufferParameterivARB => {
                let name = self.bound_name(c)?;
                let param: BufferParam = c.enm(1)?;
                let b = self.object(name);
                let value = match param {
                    BufferParam::Size => b.size() as i32,
                    BufferParam::Usage => b.usage.gl_value().unwrap_or(0) as i32,
                    // GL 1.5 keeps the last access given; Mesa answers the current
                    // mapping's access, READ_WRITE when unmapped. Followed: Mesa.
                    BufferParam::Access => b
                        .mapped
                        .unwrap_or(Access::ReadWrite)
                        .gl_value()
                        .unwrap_or(0) as i32,
                    BufferParam::Mapped => i32::from(b.mapped.is_some()),
                };
                Reply::Write {
                    arg: 2,
                    bytes: value.to_ne_bytes().to_vec(),
                }
            }
            // GL 1.5 §2.9.3: BUFFER_MAP_POINTER, the mapping's address, NULL unmapped.
            GetBufferPointerv | GetBufferPointervARB => {
                // Mesa's order here: the target, the parameter name (INVALID_ENUM), then
                // buffer 0 bound (INVALID_OPERATION); glGetBufferParameteriv checks the
                // binding before the parameter name.
                let _: Target = c.enm(0)?;
                c.pname(1, &["GL_BUFFER_MAP_POINTER"])?;
                let name = self.bound_name(c)?;
                let b = self.object(name);
                let address = match b.mapped {
                    Some(_) => b.data.as_ptr() as usize,
                    None => 0,
                };
                Reply::Write {
                    arg: 2,
                    bytes: address.to_ne_bytes().to_vec(),
                }
            }
            _ => return Err(c.unsupported()),
        })
    }

    fn binding(&mut self, target: Target) -> &mut u32 {
        match target {
            Target::Array => &mut self.bound.array,
            Target::ElementArray => &mut self.bound.element,
        }
    }

    /// The object bound to argument 0's target: INVALID_ENUM for a bad target,
    /// INVALID_OPERATION when 0 is bound (GL 1.5 §2.9.2).
    fn bound_name<A: Args>(&mut self, c: &A) -> Result<u32, A::Error> {
        let target: Target = c.enm(0)?;
        match *self.binding(target) {
            0 => Err(c.immediate("no buffer object is bound to the target")),
            name => Ok(name),
        }
    }

    fn object(&mut self, name: u32) -> &mut Buffer {
        self.objects.entry(name).or_default()
    }

    /// The (offset, size) of arguments 1 and 2 as a byte range of buffer `name`. Mesa's
    /// order: a negative offset or size, or a range past the store, is INVALID_VALUE; then
    /// a mapped buffer is INVALID_OPERATION (GL 1.5 §2.9.2).
    fn range<A: Args>(&mut self, c: &A, name: u32) -> Result<std::ops::Range<usize>, A::Error> {
        let (offset, size) = (c.int(1)?, c.int(2)?);
        if offset < 0 {
            return Err(c.bad(1, "an offset of 0 or more"));
        }
        if size < 0 {
            return Err(c.bad(2, "a size of 0 or more"));
        }
        let buffer = self.object(name);
        let end = offset.checked_add(size).unwrap_or(i64::MAX);
        if end > buffer.size() as i64 {
            return Err(c.bad(2, "a range inside the buffer"));
        }
        if buffer.mapped.is_some() {
            return Err(c.immediate("the buffer is mapped"));
        }
        Ok(offset as usize..end as usize)
    }

    /// glGenBuffers: `n` names never used, after the largest in use or generated (as
    /// Mesa's _mesa_HashFindFreeKeyBlock finds them); `None` when they would pass
    /// 2³² − 1.
    fn generate(&mut self, n: usize) -> Option<impl Iterator<Item = u32>> {
        let last = self
            .objects
            .keys()
            .next_back()
            .copied()
            .unwrap_or(0)
            .max(self.generated);
        let end = last.checked_add(u32::try_from(n).ok()?)?;
        self.generated = end;
        Some((last..end).map(|k| k + 1))
    }

    /// glDeleteBuffers of one name: 0 and unused names are ignored; a deleted bound
    /// buffer's bindings revert to 0 (GL 1.5 §2.9.1), a mapped one is unmapped.
    fn delete(&mut self, name: u32) {
        if self.objects.remove(&name).is_some() {
            for b in [&mut self.bound.array, &mut self.bound.element] {
                if *b == name {
                    *b = 0;
                }
            }
        }
    }
}

/// A count argument: INVALID_VALUE when negative.
fn count<A: Args>(c: &A, i: usize) -> Result<usize, A::Error> {
    let n = c.i32(i)?;
    usize::try_from(n).map_err(|_| c.bad(i, "a count of 0 or more"))
}
