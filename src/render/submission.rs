//! A session's object draws submitted as a program of the era would have drawn them
//! (`RenderOptions::submission`): the plan's commands run as planned, but each
//! `Command::Draw` of a prepared object (a scene mesh, `techniques::Prepared`) becomes the
//! GL calls of its door, made through the front the C library calls — `ff::front::Client`
//! with C arguments (`abi::cargs::CCall`) and, inside glBegin/glEnd, the C library's
//! per-vertex path (`abi::vertex_calls::in_pair`) — so a frame pays what a C program
//! would pay this layer for them:
//!
//! - *immediate*: glBegin(mode); for each vertex, in index order, glColor4f,
//!   glSecondaryColor3f, glFogCoordf, glEdgeFlag, glTexCoord4f / glMultiTexCoord4f,
//!   glNormal3f (those the geometry has arrays of) and glVertex3f (glVertex4f when w ≠ 1);
//!   glEnd. The front folds the calls into a new geometry at glEnd, which the pipeline
//!   uploads at its draw: calls per vertex and an upload per draw, every frame.
//! - *display-list*: at the first object draw glGenLists(n), then for each object
//!   glNewList(i, GL_COMPILE), its immediate-mode calls, glEndList; every draw is then one
//!   glCallList(i), whose geometry the list holds (`ff::list_pairs`) and the pipeline
//!   uploads once.
//! - *buffers*: the commands as planned (no wrapper is made): the prepared geometry,
//!   uploaded once and kept while its `Arc` lives.
//!
//! The commands between object draws are executed as they come, so each glBegin reads
//! the current values the plan left (GL 1.5 §2.7); after glEnd or glCallList the values
//! the pair left current follow as commands (the front emits them), as in GL. Other
//! draws (full-screen quads, a technique's own geometry) run as planned. A call the front
//! rejects is recorded as its GL error, as the C library records it, and is reported by
//! [`Pipeline::take_gl_error`] before the pipeline's own.

use std::collections::HashMap;
use std::sync::Arc;

use crate::abi::cargs::{CArg, CCall, ProgramMemory};
use crate::abi::vertex_calls;
use crate::ff::api::Entry;
use crate::ff::front::{Client, Reply};
use crate::ff::glenum::GlEnum;
use crate::ff::{Command, FixedState, Geometry, GlError, GlErrorKind};
use crate::gpu::GpuContext;
use crate::pipeline::queries::QueryFetch;
use crate::pipeline::{Counters, Pipeline, PipelineError, Readback};
use crate::vocab::{PipelineKind, Submission};

/// GL_COMPILE, glNewList's mode that compiles without executing (GL 1.5 §5.4); the
/// registry's value (checked below).
const GL_COMPILE: u32 = 0x1300;
/// GL_TEXTURE0: glMultiTexCoord's first unit.
const GL_TEXTURE0: u32 = 0x84C0;

/// `pipeline` with the objects' draws submitted by `submission`; `pipeline` itself for
/// [`Submission::Buffers`].
pub fn submitting(
    pipeline: Box<dyn Pipeline>,
    submission: Submission,
    objects: &[Arc<Geometry>],
) -> Box<dyn Pipeline> {
    let door = match submission {
        Submission::Buffers => return pipeline,
        Submission::Immediate => Door::Immediate,
        Submission::DisplayList => Door::DisplayList,
    };
    // A geometry GL would reject, or whose primitive has no glBegin token, runs as planned
    // (the pipeline gives the error).
    let valid: Vec<(usize, Arc<Geometry>)> = objects
        .iter()
        .filter(|g| g.validate().is_ok() && g.primitive.gl_value().is_some())
        .cloned()
        .enumerate()
        .collect();
    Box::new(Submitter {
        by_address: valid
            .iter()
            .map(|(i, g)| (Arc::as_ptr(g) as usize, *i))
            .collect(),
        objects: valid.into_iter().map(|(_, g)| g).collect(),
        door,
        first_list: None,
        front: Front::default(),
        inner: pipeline,
    })
}

/// The doors that go through the front.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Door {
    Immediate,
    DisplayList,
}

/// A pipeline behind the C library's front for its object draws (see the module note).
struct Submitter {
    inner: Box<dyn Pipeline>,
    door: Door,
    /// The objects the front submits; holding them keeps their addresses unique.
    objects: Vec<Arc<Geometry>>,
    /// An object's index in `objects` by the address of its geometry.
    by_address: HashMap<usize, usize>,
    /// glGenLists' first name once the lists are compiled: object i is list first + i.
    first_list: Option<u32>,
    front: Front,
}

/// The C library's front: its client state, the commands a call made, its first error.
#[derive(Default)]
struct Front {
    client: Client,
    made: Vec<Command>,
    error: Option<GlErrorKind>,
}

impl Front {
    /// One C call, routed as `abi::dispatch` routes it: an attribute inside glBegin/glEnd
    /// straight into the pair, anything else through `Client::call` (its commands to
    /// `made`, its error recorded).
    fn call(&mut self, entry: Entry, args: &[CArg], state: &FixedState) -> Reply {
        if vertex_calls::in_pair(&mut self.client, entry, args) {
            return Reply::None;
        }
        let c = CCall::new(entry, args, self.client.pixel_store.unpack);
        match self.client.call(&c, state, &ProgramMemory, &mut self.made) {
            Ok(reply) => reply,
            Err(kind) => {
                self.error.get_or_insert(kind);
                Reply::None
            }
        }
    }

    /// `g`'s vertices as immediate-mode calls: glBegin, each vertex's attributes (the
    /// arrays it has) then its position, glEnd. `g` is valid (indices within the arrays).
    fn pair(&mut self, g: &Geometry, state: &FixedState) {
        let mode = g.primitive.gl_value().unwrap_or_default();
        self.call(Entry::Begin, &[mode.into()], state);
        match &g.indices {
            Some(indices) => {
                for &i in indices {
                    self.vertex(g, i as usize, state);
                }
            }
            None => {
                for i in 0..g.positions.len() {
                    self.vertex(g, i, state);
                }
            }
        }
        self.call(Entry::End, &[], state);
    }

    /// Vertex `i` of `g`: its attributes, then glVertex.
    fn vertex(&mut self, g: &Geometry, i: usize, state: &FixedState) {
        if let Some(c) = at(&g.colors, i) {
            self.call(Entry::Color4f, &[c.x, c.y, c.z, c.w].map(CArg::from), state);
        }
        if let Some(c) = at(&g.secondary_colors, i) {
            self.call(
                Entry::SecondaryColor3f,
                &[c.x, c.y, c.z].map(CArg::from),
                state,
            );
        }
        if let Some(f) = at(&g.fog_coords, i) {
            self.call(Entry::FogCoordf, &[f.into()], state);
        }
        if let Some(flag) = at(&g.edge_flags, i) {
            self.call(Entry::EdgeFlag, &[u8::from(flag).into()], state);
        }
        for (unit, coords) in g.texcoords.iter().enumerate() {
            let Some(t) = at(coords, i) else { continue };
            let stqr = [t.x, t.y, t.z, t.w].map(CArg::from);
            match unit {
                0 => self.call(Entry::TexCoord4f, &stqr, state),
                u => {
                    let target = CArg::from(GL_TEXTURE0 + u as u32);
                    let [s, t, r, q] = stqr;
                    self.call(Entry::MultiTexCoord4f, &[target, s, t, r, q], state)
                }
            };
        }
        if let Some(n) = at(&g.normals, i) {
            self.call(Entry::Normal3f, &[n.x, n.y, n.z].map(CArg::from), state);
        }
        if let Some(p) = g.positions.get(i) {
            if p.w == 1.0 {
                self.call(Entry::Vertex3f, &[p.x, p.y, p.z].map(CArg::from), state);
            } else {
                self.call(
                    Entry::Vertex4f,
                    &[p.x, p.y, p.z, p.w].map(CArg::from),
                    state,
                );
            }
        }
    }
}

/// Element `i` of an attribute array, if the geometry has the array.
fn at<T: Copy>(array: &Option<Vec<T>>, i: usize) -> Option<T> {
    array.as_ref().and_then(|a| a.get(i).copied())
}

impl Submitter {
    /// glGenLists, then each object's calls between glNewList(GL_COMPILE) and glEndList.
    fn compile_lists(&mut self) {
        let state = self.inner.state();
        let n = self.objects.len() as u32;
        let first = self.front.call(Entry::GenLists, &[n.into()], state).value();
        for (i, g) in self.objects.iter().enumerate() {
            let name = first.wrapping_add(i as u32);
            let args = [name.into(), GL_COMPILE.into()];
            self.front.call(Entry::NewList, &args, state);
            self.front.pair(g, state);
            self.front.call(Entry::EndList, &[], state);
        }
        self.first_list = Some(first);
    }

    /// Object `i`'s draw through the door: its calls, their commands executed.
    fn draw(&mut self, ctx: &GpuContext, i: usize) -> Result<(), PipelineError> {
        if self.door == Door::DisplayList && self.first_list.is_none() {
            self.compile_lists();
        }
        let state = self.inner.state();
        match (self.door, self.first_list) {
            (Door::DisplayList, Some(first)) => {
                let name = first.wrapping_add(i as u32);
                self.front.call(Entry::CallList, &[name.into()], state);
            }
            _ => {
                if let Some(g) = self.objects.get(i) {
                    self.front.pair(g, state);
                }
            }
        }
        let made = std::mem::take(&mut self.front.made);
        let result = self.inner.execute(ctx, &made);
        self.front.made = made;
        self.front.made.clear();
        result
    }
}

impl Pipeline for Submitter {
    fn kind(&self) -> PipelineKind {
        self.inner.kind()
    }

    /// The commands in order; each object draw replaced by its door's calls.
    fn execute(&mut self, ctx: &GpuContext, commands: &[Command]) -> Result<(), PipelineError> {
        let mut from = 0;
        for (at, cmd) in commands.iter().enumerate() {
            let Command::Draw(g) = cmd else { continue };
            let Some(&i) = self.by_address.get(&(Arc::as_ptr(g) as usize)) else {
                continue;
            };
            self.inner.execute(ctx, &commands[from..at])?;
            from = at + 1;
            self.draw(ctx, i)?;
        }
        self.inner.execute(ctx, &commands[from..])
    }

    fn readback(&self, slot: u32) -> Option<&Readback> {
        self.inner.readback(slot)
    }

    fn state(&self) -> &FixedState {
        self.inner.state()
    }

    fn take_gl_error(&mut self) -> Option<GlError> {
        match self.front.error.take() {
            Some(kind) => Some(GlError {
                kind,
                rule: "a call of the objects' immediate-mode or display-list submission",
            }),
            None => self.inner.take_gl_error(),
        }
    }

    fn counters(&self) -> Counters {
        self.inner.counters()
    }

    fn query_result(&mut self, ctx: &GpuContext, id: u32, what: QueryFetch) -> Option<u64> {
        self.inner.query_result(ctx, id, what)
    }

    fn release(&mut self, ctx: &GpuContext) {
        self.inner.release(ctx);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::glenum::value_of;

    #[test]
    fn the_tokens_are_gls() {
        assert_eq!(value_of("GL_COMPILE"), Some(GL_COMPILE));
        assert_eq!(value_of("GL_TEXTURE0"), Some(GL_TEXTURE0));
    }
}
