//! The client half of a front end (a script or the C library): immediate mode and client
//! arrays, between the calls and the Commands the pipelines execute. Both front ends run
//! every call through [`Client::call`], so a call means the same from either door.

use std::sync::Arc;

use super::args::Args;
use super::client::{ClientArrays, ClientEffect, ClientMemory};
use super::command::Command;
use super::immediate::Immediate;
use super::state::CurrentValues;
use crate::ff::api::Entry;

/// Immediate mode and client arrays.
#[derive(Debug, Default)]
pub struct Client {
    pub immediate: Immediate,
    pub arrays: ClientArrays,
}

impl Client {
    /// One call; the Commands it yields are appended to `out`. `current` is the model's
    /// current values; `mem` reads what client arrays point at.
    pub fn call<A: Args>(
        &mut self,
        c: &A,
        current: &CurrentValues,
        mem: &dyn ClientMemory,
        out: &mut Vec<Command>,
    ) -> Result<(), A::Error> {
        if !ClientArrays::handles(c.entry()) {
            return self.immediate.call(c, current, out);
        }
        let draws = matches!(
            c.entry(),
            Entry::DrawArrays
                | Entry::DrawElements
                | Entry::DrawRangeElements
                | Entry::InterleavedArrays
        );
        if draws && self.immediate.is_open() {
            return Err(c.immediate("a draw inside glBegin/glEnd"));
        }
        match self.arrays.call(c, mem)? {
            ClientEffect::State | ClientEffect::Draw(None) => Ok(()),
            ClientEffect::Draw(Some(g)) => {
                out.push(Command::Draw(Arc::new(g)));
                Ok(())
            }
            ClientEffect::Element(e) => self.immediate.array_element(c, e, out),
        }
    }
}
