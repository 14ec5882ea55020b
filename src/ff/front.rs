//! The client half of a front end (a script or the C library): immediate mode, client
//! arrays and display lists, between the calls and the Commands the pipelines execute.
//! Both front ends run every call through [`Client::call`], so a call means the same from
//! either door.

use std::sync::Arc;

use super::args::Args;
use super::client::{ClientArrays, ClientEffect, ClientMemory};
use super::command::Command;
use super::error::GlErrorKind;
use super::immediate::{decode, Immediate, Op};
use super::lists::{compiled, follow, Item, ListMode, Lists, MAX_LIST_NESTING};
use super::state::CurrentValues;
use crate::ff::api::{CType, Entry};

/// Immediate mode, client arrays and display lists.
#[derive(Debug, Default)]
pub struct Client {
    pub immediate: Immediate,
    pub arrays: ClientArrays,
    pub lists: Lists,
}

impl Client {
    /// One call; the Commands it yields are appended to `out`. `current` is the model's
    /// current values; `mem` reads what client arrays point at. Returns the call's value
    /// (glGenLists, glIsList; 0 for the others).
    pub fn call<A: Args>(
        &mut self,
        c: &A,
        current: &CurrentValues,
        mem: &dyn ClientMemory,
        out: &mut Vec<Command>,
    ) -> Result<u32, A::Error> {
        let entry = c.entry();
        if let Some(value) = self.list_call(c)? {
            return Ok(value);
        }
        if let Some(mode) = self.lists.compiling() {
            if compiled(entry) {
                let item = match self.compile(c, mem) {
                    Ok(Some(item)) => item,
                    // A draw without a vertex array: GL draws nothing, the list keeps
                    // nothing.
                    Ok(None) => return Ok(0),
                    Err(e) => match c.deferred(&e) {
                        Some(error) => Item::Command(Command::Raise { error, call: entry }),
                        None => return Err(e),
                    },
                };
                if mode == ListMode::CompileAndExecute {
                    self.run(std::slice::from_ref(&item), 0, *current, out);
                }
                self.lists.record(item);
                return Ok(0);
            }
        }
        match entry {
            Entry::CallList => {
                let item = Item::Call(c.u32(0)?);
                self.run(&[item], 0, *current, out);
                return Ok(0);
            }
            Entry::CallLists => {
                let item = Item::CallMany(list_names(c)?);
                self.run(&[item], 0, *current, out);
                return Ok(0);
            }
            Entry::ListBase => {
                self.lists.base = c.u32(0)?;
                return Ok(0);
            }
            _ => {}
        }
        if !ClientArrays::handles(entry) {
            self.immediate.call(c, current, out)?;
            return Ok(0);
        }
        let draws = matches!(
            entry,
            Entry::DrawArrays
                | Entry::DrawElements
                | Entry::DrawRangeElements
                | Entry::InterleavedArrays
        );
        if draws && self.immediate.is_open() {
            return Err(c.immediate("a draw inside glBegin/glEnd"));
        }
        match self.arrays.call(c, mem)? {
            ClientEffect::State | ClientEffect::Draw(None) => {}
            ClientEffect::Draw(Some(g)) => out.push(Command::Draw(Arc::new(g))),
            ClientEffect::Element(e) => self
                .immediate
                .apply(&Op::Element(Box::new(e)), current, out)
                .map_err(|rule| c.immediate(rule))?,
        }
        Ok(0)
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

    /// What a list keeps of a call: data read now, as GL reads it at compile time.
    fn compile<A: Args>(
        &mut self,
        c: &A,
        mem: &dyn ClientMemory,
    ) -> Result<Option<Item>, A::Error> {
        if let Some(op) = decode(c)? {
            return Ok(Some(Item::Immediate(op)));
        }
        Ok(Some(match c.entry() {
            Entry::CallList => Item::Call(c.u32(0)?),
            Entry::CallLists => Item::CallMany(list_names(c)?),
            Entry::ListBase => Item::Base(c.u32(0)?),
            e if ClientArrays::handles(e) => match self.arrays.call(c, mem)? {
                ClientEffect::Element(el) => Item::Immediate(Op::Element(Box::new(el))),
                ClientEffect::Draw(Some(g)) => Item::Command(Command::Draw(Arc::new(g))),
                ClientEffect::Draw(None) | ClientEffect::State => return Ok(None),
            },
            _ => Item::Command(super::calls::command(c)?),
        }))
    }

    /// Runs list items: commands go to `out` (a command inside glBegin/glEnd raises
    /// INVALID_OPERATION instead), immediate-mode calls to the open glBegin, calls of
    /// other lists recurse up to GL_MAX_LIST_NESTING deep; a name without a list does
    /// nothing.
    fn run(
        &mut self,
        items: &[Item],
        depth: usize,
        mut current: CurrentValues,
        out: &mut Vec<Command>,
    ) {
        for item in items {
            let before = out.len();
            match item {
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
                    if self.immediate.apply(op, &current, out).is_err() {
                        out.push(Command::Raise {
                            error: GlErrorKind::InvalidOperation,
                            call: Entry::Begin,
                        });
                    }
                }
                Item::Call(name) => self.call_list(*name, depth, current, out),
                Item::CallMany(names) => {
                    for n in names {
                        let name = self.lists.base.wrapping_add(*n);
                        let mut cur = current;
                        for cmd in &out[before..] {
                            follow(&mut cur, cmd);
                        }
                        self.call_list(name, depth, cur, out);
                    }
                }
                Item::Base(b) => self.lists.base = *b,
            }
            for cmd in &out[before..] {
                follow(&mut current, cmd);
            }
        }
    }

    fn call_list(
        &mut self,
        name: u32,
        depth: usize,
        current: CurrentValues,
        out: &mut Vec<Command>,
    ) {
        if depth >= MAX_LIST_NESTING {
            return;
        }
        if let Some(items) = self.lists.get(name) {
            self.run(&items, depth + 1, current, out);
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
