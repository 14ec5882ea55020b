//! The client half of a front end (a script or the C library): immediate mode, client
//! arrays and display lists, between the calls and the Commands the pipelines execute.
//! Both front ends run every call through [`Client::call`], so a call means the same from
//! either door.

use std::borrow::Cow;
use std::sync::Arc;

use super::args::Args;
use super::buffers::Buffers;
use super::client::{ArrayData, ClientArrays, ClientEffect, ClientMemory, FirstCount};
use super::client_attrib::ClientAttribStack;
use super::command::Command;
use super::error::GlErrorKind;
use super::immediate::{decode, Immediate, Op, Start};
use super::lists::{compiled, Item, ListMode, Lists, MAX_LIST_NESTING};
use super::pixel_store::PixelStore;
use super::repeated_draws::{Lookup, RepeatedDraws};
use super::state::FixedState;
use crate::ff::api::{CType, Entry};

/// Immediate mode, client arrays, display lists, buffer objects, pixel storage and the
/// client attribute stack.
#[derive(Debug, Default)]
pub struct Client {
    pub immediate: Immediate,
    pub arrays: ClientArrays,
    pub lists: Lists,
    pub buffers: Buffers,
    /// GL_PACK_ALIGNMENT and GL_UNPACK_ALIGNMENT: every pixel read or write of either
    /// front end uses these.
    pub pixel_store: PixelStore,
    pub client_attrib: ClientAttribStack,
    /// The last draw from buffer objects, drawn again while nothing it reads changed.
    repeated_draws: RepeatedDraws,
}

/// What a call gives back to its caller. The C library returns or writes it out; a script
/// has no variable to put it in and ignores it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reply {
    /// Nothing (most calls).
    None,
    /// The returned value: glGenLists' first name; glIsList's, glIsBuffer's and
    /// glUnmapBuffer's GLboolean.
    Value(u32),
    /// glMapBuffer's returned pointer: the address of the buffer's store.
    Address(usize),
    /// Bytes the call stores through its pointer argument `arg`: glGenBuffers' names,
    /// glGetBufferParameteriv's integer, glGetBufferSubData's data.
    Write { arg: usize, bytes: Vec<u8> },
    /// glGetQueryObject{i,ui}v of a query the model found readable: the C library reads
    /// `param` of query `id` from the pipeline and stores it through argument 2, clamped
    /// to a GLint for the `iv` form (`ff::queries::object_value`).
    QueryObject {
        id: u32,
        param: super::queries::ObjectParam,
        target: super::queries::QueryTarget,
        signed: bool,
    },
}

impl Reply {
    /// The returned value of calls that return one (0 for the others).
    pub fn value(&self) -> u32 {
        match self {
            Reply::Value(v) => *v,
            _ => 0,
        }
    }
}

/// The front end's memory with buffer objects: an array or index pointer given with a
/// buffer bound reads the buffer's store.
struct WithBuffers<'a> {
    mem: &'a dyn ClientMemory,
    buffers: &'a Buffers,
}

impl ClientMemory for WithBuffers<'_> {
    fn read<'d>(&self, data: &'d ArrayData, offset: usize, len: usize) -> Option<Cow<'d, [u8]>> {
        match data {
            ArrayData::Buffer { name, offset: at } => self
                .buffers
                .read(*name, at.checked_add(offset)?, len)
                .map(|b| Cow::Owned(b.to_vec())),
            _ => self.mem.read(data, offset, len),
        }
    }
}

impl Client {
    /// One call; the Commands it yields are appended to `out`. `state` is the model as
    /// the commands so far left it (current values, textures, what queries read); `mem`
    /// reads what client arrays point at. Returns what the call gives back.
    pub fn call<A: Args>(
        &mut self,
        c: &A,
        state: &FixedState,
        mem: &dyn ClientMemory,
        out: &mut Vec<Command>,
    ) -> Result<Reply, A::Error> {
        let entry = c.entry();
        if let Some(reply) = self.array_enable(c)? {
            return Ok(reply);
        }
        if super::front_state::handles(entry) {
            return self.front_state_call(c, state, out);
        }
        if let Some(value) = self.list_call(c)? {
            return Ok(Reply::Value(value));
        }
        if Buffers::handles(entry) {
            return self.buffer_call(c, mem);
        }
        if let Some(mode) = self.lists.compiling() {
            if compiled(entry) {
                // A draw without a vertex array: GL draws nothing, the list keeps nothing.
                let items = match self.compile(c, mem) {
                    Ok(items) => items,
                    Err(e) => match c.deferred(&e) {
                        Some(error) => vec![Item::Command(Command::Raise { error, call: entry })],
                        None => return Err(e),
                    },
                };
                // A proxy image is not compiled: GL runs it at once (Mesa's save_TexImage1D,
                // 2D and 3D).
                if let [Item::Command(proxy @ Command::ProxyTexImage(_))] = items.as_slice() {
                    out.push(proxy.clone());
                    return Ok(Reply::None);
                }
                if mode == ListMode::CompileAndExecute {
                    self.run(&items, 0, Start::of(state), out);
                }
                for item in items {
                    self.lists.record(item);
                }
                return Ok(Reply::None);
            }
        }
        match entry {
            Entry::CallList => {
                let list = c.u32(0)?;
                // GL 1.5 §5.4 ignores a name without a list; Mesa's glCallList refuses name
                // 0 with INVALID_VALUE (a list that calls list 0 runs on, as there).
                if list == 0 {
                    out.push(Command::Raise {
                        error: GlErrorKind::InvalidValue,
                        call: Entry::CallList,
                    });
                    return Ok(Reply::None);
                }
                let item = Item::Call(list);
                self.run(&[item], 0, Start::of(state), out);
                return Ok(Reply::None);
            }
            Entry::CallLists => {
                let item = Item::CallMany(list_names(c)?);
                self.run(&[item], 0, Start::of(state), out);
                return Ok(Reply::None);
            }
            Entry::ListBase => {
                // Not among the calls GL allows inside glBegin/glEnd (GL 1.5 §2.6.3).
                if self.immediate.is_open() {
                    return Err(c.immediate("glListBase inside glBegin/glEnd"));
                }
                out.push(Command::ListBase(c.u32(0)?));
                return Ok(Reply::None);
            }
            _ => {}
        }
        if !ClientArrays::handles(entry) {
            self.immediate
                .call(c, &state.current, &state.materials, out)?;
            return Ok(Reply::None);
        }
        // Inside glBegin/glEnd only glArrayElement of the array calls is allowed; the others
        // are INVALID_OPERATION and change nothing, checked before their arguments (GL 1.5
        // §2.6.3; EXT_compiled_vertex_array for the lock; Mesa measured alike).
        let refused_in_pair = match entry {
            Entry::ArrayElement => None,
            Entry::DrawArrays
            | Entry::DrawElements
            | Entry::DrawRangeElements
            | Entry::MultiDrawArrays
            | Entry::MultiDrawElements
            | Entry::InterleavedArrays => Some("a draw inside glBegin/glEnd"),
            Entry::LockArraysEXT | Entry::UnlockArraysEXT => {
                Some("locking the arrays inside glBegin/glEnd")
            }
            _ => Some("a client-state call inside glBegin/glEnd"),
        };
        if let (Some(rule), true) = (refused_in_pair, self.immediate.is_open()) {
            return Err(c.immediate(rule));
        }
        // A draw from a mapped buffer: GL 1.5 §2.9.3 makes it INVALID_OPERATION, llvmpipe's
        // Mesa draws it without an error (tests/c/buffers.c). Followed: Mesa; the draw
        // reads the store as it is.
        let mem = WithBuffers {
            mem,
            buffers: &self.buffers,
        };
        let key = match self
            .repeated_draws
            .get(c, &self.arrays, &self.buffers, &mem)
        {
            Lookup::Repeat(g) => {
                out.push(Command::Draw(g));
                return Ok(Reply::None);
            }
            Lookup::New(key) => key,
        };
        match self.arrays.call(c, &mem, self.buffers.bound)? {
            ClientEffect::State | ClientEffect::Draw(None) => {}
            ClientEffect::Draw(Some(g)) => {
                let g = Arc::new(g);
                if let Some(key) = key {
                    self.repeated_draws.remember(key, &mem, &g);
                }
                out.push(Command::Draw(g));
            }
            // A glMultiDraw* executed with a first count of 0 draws nothing (Mesa 22.3).
            ClientEffect::Draws(_, FirstCount::Empty) => {}
            ClientEffect::Draws(draws, FirstCount::NotEmpty) => {
                out.extend(draws.into_iter().map(|g| Command::Draw(Arc::new(g))));
            }
            ClientEffect::Element(e) => self
                .immediate
                .apply(
                    &Op::Element(Box::new(e)),
                    &state.current,
                    &state.materials,
                    out,
                )
                .map_err(|rule| c.immediate(rule))?,
        }
        Ok(Reply::None)
    }

    /// glEnable/glDisable of a client array (VERTEX_ARRAY … FOG_COORD_ARRAY): Mesa's
    /// compatibility context takes them as glEnableClientState/glDisableClientState — no
    /// error, though GL 1.5 §2.8 names only those calls —, compiled into a list as any
    /// glEnable (run as the list runs), INVALID_OPERATION inside glBegin/glEnd. None for
    /// any other call or token.
    fn array_enable<A: Args>(&mut self, c: &A) -> Result<Option<Reply>, A::Error> {
        let on = match c.entry() {
            Entry::Enable => true,
            Entry::Disable => false,
            _ => return Ok(None),
        };
        let Ok(cap) = c.token(0) else {
            return Ok(None);
        };
        let Some(enabled) = self.arrays.enable_of(cap) else {
            return Ok(None);
        };
        if let Some(mode) = self.lists.compiling() {
            self.lists.record(Item::ArrayEnable { cap, on });
            if mode == ListMode::Compile {
                return Ok(Some(Reply::None));
            }
        } else if self.immediate.is_open() {
            return Err(c.immediate("glEnable or glDisable inside glBegin/glEnd"));
        }
        *enabled = on;
        Ok(Some(Reply::None))
    }

    /// A buffer-object call: run at once, never compiled (GL 1.5 §5.4), and not allowed
    /// inside glBegin/glEnd.
    fn buffer_call<A: Args>(&mut self, c: &A, mem: &dyn ClientMemory) -> Result<Reply, A::Error> {
        if self.immediate.is_open() {
            return Err(c.immediate("a buffer-object call inside glBegin/glEnd"));
        }
        self.repeated_draws.forget_buffer_reads();
        let reply = self.buffers.call(c, mem)?;
        if matches!(c.entry(), Entry::DeleteBuffers | Entry::DeleteBuffersARB) {
            for name in self.arrays.buffer_names() {
                if self.buffers.get(name).is_none() {
                    self.arrays.forget_buffer(name);
                }
            }
        }
        Ok(reply)
    }

    /// glNewList, glEndList, glGenLists, glDeleteLists, glIsList: run at once, never
    /// compiled, and not allowed inside glBegin/glEnd. `None` for any other call.
    fn list_call<A: Args>(&mut self, c: &A) -> Result<Option<u32>, A::Error> {
        let entry = c.entry();
        let listing = matches!(
            entry,
            Entry::NewList | Entry::EndList | Entry::GenLists | Entry::DeleteLists | Entry::IsList
        );
        if !listing {
            return Ok(None);
        }
        if self.immediate.is_open() {
            return Err(c.immediate("display-list management inside glBegin/glEnd"));
        }
        Ok(Some(match entry {
            Entry::NewList => {
                // Inside a list's compilation glNewList is INVALID_OPERATION whatever its
                // arguments: Mesa's compile table holds a glNewList that only raises it
                // (measured: a bad mode or name 0 there too).
                if self.lists.compiling().is_some() {
                    return Err(c.immediate("glNewList while a list is being compiled"));
                }
                let name = c.u32(0)?;
                if name == 0 {
                    return Err(c.bad(0, "a list name other than 0"));
                }
                let mode = match c.pname(1, &["GL_COMPILE", "GL_COMPILE_AND_EXECUTE"])? {
                    "GL_COMPILE" => ListMode::Compile,
                    _ => ListMode::CompileAndExecute,
                };
                self.lists.begin(name, mode).map_err(|r| c.immediate(r))?;
                0
            }
            Entry::EndList => {
                self.lists.end().map_err(|r| c.immediate(r))?;
                0
            }
            Entry::GenLists => {
                let range = c.i32(0)?;
                if range < 0 {
                    return Err(c.bad(0, "a range of 0 or more"));
                }
                self.lists.generate(range as u32)
            }
            Entry::DeleteLists => {
                let (list, range) = (c.u32(0)?, c.i32(1)?);
                if range < 0 {
                    return Err(c.bad(1, "a range of 0 or more"));
                }
                self.lists.delete(list, range as u32);
                0
            }
            _ => u32::from(self.lists.is_list(c.u32(0)?)),
        }))
    }

    /// What a list keeps of a call: data read now, as GL reads it at compile time (a
    /// glMultiDraw* keeps one draw per list).
    fn compile<A: Args>(&mut self, c: &A, mem: &dyn ClientMemory) -> Result<Vec<Item>, A::Error> {
        if let Some(op) = decode(c)? {
            return Ok(vec![Item::Immediate(op)]);
        }
        Ok(vec![match c.entry() {
            Entry::CallList => Item::Call(c.u32(0)?),
            Entry::CallLists => Item::CallMany(list_names(c)?),
            Entry::ListBase => Item::Command(Command::ListBase(c.u32(0)?)),
            e if ClientArrays::handles(e) => match self.arrays.call(
                c,
                &WithBuffers {
                    mem,
                    buffers: &self.buffers,
                },
                self.buffers.bound,
            )? {
                ClientEffect::Element(el) => Item::Immediate(Op::Element(Box::new(el))),
                ClientEffect::Draw(Some(g)) => Item::Command(Command::Draw(Arc::new(g))),
                ClientEffect::Draws(draws, _) => {
                    return Ok(draws
                        .into_iter()
                        .map(|g| Item::Command(Command::Draw(Arc::new(g))))
                        .collect())
                }
                ClientEffect::Draw(None) | ClientEffect::State => return Ok(Vec::new()),
            },
            _ => Item::Command(super::calls::command(c)?),
        }])
    }

    /// Runs list items: commands go to `out` (a command inside glBegin/glEnd raises
    /// INVALID_OPERATION instead), immediate-mode calls to the open glBegin, calls of
    /// other lists recurse up to GL_MAX_LIST_NESTING deep; a name without a list does
    /// nothing.
    fn run(&mut self, items: &[Item], depth: usize, mut start: Start, out: &mut Vec<Command>) {
        for item in items {
            let before = out.len();
            match item {
                Item::Command(Command::Material { face, param }) if self.immediate.is_open() => {
                    match param {
                        crate::ff::MaterialParam::Shininess(v)
                            if super::light::shininess_refused(*v) =>
                        {
                            out.push(Command::Raise {
                                error: GlErrorKind::InvalidValue,
                                call: Entry::Materialf,
                            })
                        }
                        _ => {
                            let op = Op::Material(*face, *param);
                            let _ =
                                self.immediate
                                    .apply(&op, &start.current, &start.materials, out);
                        }
                    }
                }
                Item::Command(cmd) => {
                    if self.immediate.is_open() && !matches!(cmd, Command::Raise { .. }) {
                        out.push(Command::Raise {
                            error: GlErrorKind::InvalidOperation,
                            call: cmd.entry(),
                        });
                    } else {
                        out.push(cmd.clone());
                    }
                }
                Item::Immediate(op) => {
                    if self
                        .immediate
                        .apply(op, &start.current, &start.materials, out)
                        .is_err()
                    {
                        out.push(Command::Raise {
                            error: GlErrorKind::InvalidOperation,
                            call: Entry::Begin,
                        });
                    }
                }
                Item::Call(name) => self.call_list(*name, depth, start, out),
                Item::CallMany(names) => {
                    for n in names {
                        let mut now = start;
                        for cmd in &out[before..] {
                            now.follow(cmd);
                        }
                        let name = now.list_base.wrapping_add(*n);
                        self.call_list(name, depth, now, out);
                    }
                }
                Item::ArrayEnable { cap, on } => {
                    if let Some(enabled) = self.arrays.enable_of(*cap) {
                        *enabled = *on;
                    }
                }
                Item::Pair(pair) => {
                    if self.immediate.is_open() {
                        self.run(&pair.items, depth, start, out);
                    } else {
                        pair.replay(&start.current, out);
                    }
                }
            }
            for cmd in &out[before..] {
                start.follow(cmd);
            }
        }
    }

    fn call_list(&mut self, name: u32, depth: usize, start: Start, out: &mut Vec<Command>) {
        if depth >= MAX_LIST_NESTING {
            return;
        }
        if let Some(items) = self.lists.get(name) {
            self.run(&items, depth + 1, start, out);
        }
    }
}

/// glCallLists' names: n values of the given type (GL 1.5 §5.4: BYTE … FLOAT, or 2, 3 or
/// 4 bytes big-endian each).
fn list_names<A: Args>(c: &A) -> Result<Vec<u32>, A::Error> {
    let n = c.i32(0)?;
    if n < 0 {
        return Err(c.bad(0, "a count of 0 or more"));
    }
    let n = n as usize;
    const TYPES: [&str; 10] = [
        "GL_BYTE",
        "GL_UNSIGNED_BYTE",
        "GL_SHORT",
        "GL_UNSIGNED_SHORT",
        "GL_INT",
        "GL_UNSIGNED_INT",
        "GL_FLOAT",
        "GL_2_BYTES",
        "GL_3_BYTES",
        "GL_4_BYTES",
    ];
    let ty = c.pname(1, &TYPES)?;
    if n == 0 {
        return Ok(Vec::new());
    }
    let (per, typed) = match ty {
        "GL_BYTE" => (1, Some(CType::Byte)),
        "GL_UNSIGNED_BYTE" => (1, Some(CType::UByte)),
        "GL_SHORT" => (2, Some(CType::Short)),
        "GL_UNSIGNED_SHORT" => (2, Some(CType::UShort)),
        "GL_INT" => (4, Some(CType::Int)),
        "GL_UNSIGNED_INT" => (4, Some(CType::UInt)),
        "GL_FLOAT" => (4, Some(CType::Float)),
        "GL_2_BYTES" => (2, None),
        "GL_3_BYTES" => (3, None),
        _ => (4, None),
    };
    match typed {
        Some(t) => Ok(c
            .array_as(2, n, t)?
            .into_iter()
            .map(|v| v as i64 as u32)
            .collect()),
        None => {
            let bytes = c.array_as(2, n * per, CType::UByte)?;
            Ok(bytes
                .chunks_exact(per)
                .map(|b| {
                    b.iter()
                        .fold(0u32, |acc, x| (acc << 8) | (*x as u32 & 0xff))
                })
                .collect())
        }
    }
}
