//! Display lists (GL 1.5 §5.4): glNewList … glEndList record calls, glCallList(s) replays
//! them, nested up to GL_MAX_LIST_NESTING (64, Mesa's) deep.
//!
//! A list keeps each call as it was when compiled, data read then (GL: "the values are
//! those in effect when the list is compiled", so a vertex array or a pointer argument is
//! read at compile time): a state call as its `Command`, an immediate-mode call as its
//! decoded [`Op`], a draw from client arrays as the `Command::Draw` of the values read. A
//! call whose arguments GL rejects is kept as `Command::Raise`, raising the error when the
//! list runs (GL checks a listed call when it executes; Mesa does the same). Calls GL
//! executes at once instead of compiling — client state, glGenLists, glDeleteLists,
//! glIsList, glReadPixels, queries — are not recorded ([`compiled`]).

use std::collections::HashMap;
use std::sync::Arc;

use super::api::Entry;
use super::command::Command;
use super::geometry::{Geometry, Primitive};
use super::immediate::Op;
use super::list_pairs::{assemble, Pair};
use super::state::CurrentValues;

/// GL_MAX_LIST_NESTING as Mesa sets it.
pub const MAX_LIST_NESTING: usize = 64;

/// One recorded call.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    Command(Command),
    Immediate(Op),
    /// glCallList(n).
    Call(u32),
    /// glCallLists: the names before the list base is added.
    CallMany(Vec<u32>),
    /// A glBegin … glEnd assembled at glEndList (`list_pairs`).
    Pair(Box<Pair>),
    /// glEnable/glDisable of a client array's token (`Client::array_enable`).
    ArrayEnable {
        cap: u32,
        on: bool,
    },
}

/// GL_COMPILE or GL_COMPILE_AND_EXECUTE.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ListMode {
    Compile,
    CompileAndExecute,
}

/// The lists of a context and the one being compiled.
#[derive(Debug, Default)]
pub struct Lists {
    lists: HashMap<u32, Arc<Vec<Item>>>,
    compiling: Option<(u32, ListMode, Vec<Item>)>,
}

/// A listed QUADS draw made indexed (vertex i at index i), as Mesa's list compiler stores
/// every draw of a list as one indexed draw from its vertex buffer: its quads then reach the
/// rasteriser split (v0,v1,v3),(v1,v2,v3), like any indexed QUADS (`emulate::assembly`),
/// where the same calls run outside a list split unclipped smooth quads (v0,v1,v2),(v0,v2,v3).
fn indexed_quads(item: Item) -> Item {
    let index = |g: &mut Arc<Geometry>| {
        if g.primitive != Primitive::Quads || g.indices.is_some() {
            return;
        }
        if let Ok(n) = u32::try_from(g.vertex_count()) {
            Arc::make_mut(g).indices = Some((0..n).collect());
        }
    };
    match item {
        Item::Command(Command::Draw(mut g)) => {
            index(&mut g);
            Item::Command(Command::Draw(g))
        }
        Item::Pair(mut pair) => {
            index(&mut pair.geometry);
            Item::Pair(pair)
        }
        other => other,
    }
}

/// Whether GL compiles `entry` into a list being made (the others run at once).
pub fn compiled(entry: Entry) -> bool {
    !matches!(
        entry,
        Entry::NewList
            | Entry::EndList
            | Entry::GenLists
            | Entry::DeleteLists
            | Entry::IsList
            | Entry::ReadPixels
            | Entry::GetTexImage
            | Entry::DeleteTextures
            | Entry::VertexPointer
            | Entry::NormalPointer
            | Entry::ColorPointer
            | Entry::TexCoordPointer
            | Entry::EdgeFlagPointer
            | Entry::ClientActiveTexture
            | Entry::ClientActiveTextureARB
            | Entry::EnableClientState
            | Entry::DisableClientState
            | Entry::InterleavedArrays
            | Entry::LockArraysEXT
            | Entry::UnlockArraysEXT
    ) && !super::framebuffer::never_compiled(entry)
        && !super::queries::never_compiled(entry)
}

impl Lists {
    /// The mode of the list being compiled, if one is.
    pub fn compiling(&self) -> Option<ListMode> {
        self.compiling.as_ref().map(|(_, m, _)| *m)
    }

    /// The name of the list being compiled (LIST_INDEX), if one is.
    pub fn compiling_name(&self) -> Option<u32> {
        self.compiling.as_ref().map(|(n, _, _)| *n)
    }

    /// glNewList (the caller has checked name ≠ 0 and the mode).
    pub fn begin(&mut self, name: u32, mode: ListMode) -> Result<(), &'static str> {
        if self.compiling.is_some() {
            return Err("glNewList while a list is being compiled");
        }
        self.compiling = Some((name, mode, Vec::new()));
        Ok(())
    }

    /// glEndList: the list replaces any list of that name, its glBegin … glEnd pairs
    /// assembled.
    pub fn end(&mut self) -> Result<(), &'static str> {
        let (name, _, items) = self.compiling.take().ok_or("glEndList without glNewList")?;
        let items = assemble(items).into_iter().map(indexed_quads).collect();
        self.lists.insert(name, Arc::new(items));
        Ok(())
    }

    /// Appends a call to the list being compiled.
    pub fn record(&mut self, item: Item) {
        if let Some((_, _, items)) = &mut self.compiling {
            items.push(item);
        }
    }

    /// glGenLists(range): the first of `range` consecutive unused names, each made an
    /// empty list; 0 when range is 0 or no such run exists below 2³².
    pub fn generate(&mut self, range: u32) -> u32 {
        if range == 0 {
            return 0;
        }
        let mut first: u32 = 1;
        loop {
            let Some(last) = first.checked_add(range - 1) else {
                return 0;
            };
            match (first..=last).find(|n| self.lists.contains_key(n)) {
                None => break,
                Some(used) => first = used + 1,
            }
        }
        for n in first..first + range {
            self.lists.insert(n, Arc::new(Vec::new()));
        }
        first
    }

    /// glDeleteLists(list, range).
    pub fn delete(&mut self, list: u32, range: u32) {
        for n in list..list.saturating_add(range) {
            self.lists.remove(&n);
        }
    }

    /// glIsList.
    pub fn is_list(&self, name: u32) -> bool {
        self.lists.contains_key(&name)
    }

    pub fn get(&self, name: u32) -> Option<Arc<Vec<Item>>> {
        self.lists.get(&name).cloned()
    }
}

/// Follows the current values through a command, so that a glBegin later in the same
/// list reads what the list's own glColor, glNormal or glEnd left current.
pub fn follow(current: &mut CurrentValues, cmd: &Command) {
    match cmd {
        Command::Color(c) => current.color = *c,
        Command::Normal(n) => current.normal = *n,
        Command::EdgeFlag(f) => current.edge_flag = *f,
        Command::SecondaryColor(c) => current.secondary_color = *c,
        Command::FogCoord(x) => current.fog_coord = *x,
        Command::Index(c) => current.index = *c,
        Command::TexCoord { unit, coord } => {
            if let Some(t) = current.texcoords.get_mut(usize::from(*unit)) {
                *t = *coord;
            }
        }
        _ => {}
    }
}
