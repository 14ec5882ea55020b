//! The occlusion queries of a path, on its own GL: one GL query object per query name the
//! model began, begun and ended where the program's glBeginQuery and glEndQuery fall among
//! the path's draws, so the count is what this path's rasteriser passed (`ff::queries`).
//! The model has checked every command already; this only mirrors it. Written once for
//! both paths: the calls are GL 1.5's (ANY_SAMPLES_PASSED GL 3.3's), which a core and a
//! compatibility context take alike.

use std::collections::HashMap;

use glow::HasContext;

use super::PipelineError;
use crate::ff::glenum::GlEnum;
use crate::ff::queries::{QueryCommand, QueryTarget};
use crate::gpu::GpuContext;

/// What glGetQueryObject* reads of a query.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QueryFetch {
    /// QUERY_RESULT: waits for the count.
    Result,
    /// QUERY_RESULT_AVAILABLE: 1 when the count is ready.
    Available,
}

/// The path's GL query objects by the program's query name, and the one active.
#[derive(Default)]
pub struct GlQueries {
    objects: HashMap<u32, glow::Query>,
    active: Option<(u32, QueryTarget)>,
}

impl GlQueries {
    /// Mirrors one query command the model accepted.
    pub fn issue(&mut self, ctx: &GpuContext, cmd: &QueryCommand) -> Result<(), PipelineError> {
        let gl = ctx.gl();
        match cmd {
            QueryCommand::Gen { .. } => {}
            QueryCommand::Delete(ids) => {
                for id in ids {
                    if self.active.map(|(a, _)| a) == Some(*id) {
                        self.end(ctx);
                    }
                    if let Some(q) = self.objects.remove(id) {
                        // SAFETY: a query this path made, on its current context.
                        unsafe { gl.delete_query(q) };
                    }
                }
            }
            QueryCommand::Begin { target, id } => {
                let q = match self.objects.get(id) {
                    Some(q) => *q,
                    None => {
                        // SAFETY: a plain GL call on the current context.
                        let q = unsafe { gl.create_query() }.map_err(PipelineError::Object)?;
                        self.objects.insert(*id, q);
                        q
                    }
                };
                // SAFETY: the model allows one occlusion query at a time, as GL does.
                unsafe { gl.begin_query(gl_target(*target), q) };
                self.active = Some((*id, *target));
            }
            QueryCommand::End(_) => self.end(ctx),
        }
        Ok(())
    }

    fn end(&mut self, ctx: &GpuContext) {
        if let Some((_, target)) = self.active.take() {
            // SAFETY: the query begun with `target` is active.
            unsafe { ctx.gl().end_query(gl_target(target)) };
        }
    }

    /// The count (or the availability) of query `id`; `None` for a name this path never
    /// began.
    pub fn fetch(&self, ctx: &GpuContext, id: u32, what: QueryFetch) -> Option<u64> {
        let q = *self.objects.get(&id)?;
        let pname = match what {
            QueryFetch::Result => glow::QUERY_RESULT,
            QueryFetch::Available => glow::QUERY_RESULT_AVAILABLE,
        };
        // SAFETY: a query this path made and ended, on its current context.
        Some(u64::from(unsafe {
            ctx.gl().get_query_parameter_u32(q, pname)
        }))
    }

    /// Deletes every query object.
    pub fn release(&mut self, ctx: &GpuContext) {
        self.end(ctx);
        for (_, q) in self.objects.drain() {
            // SAFETY: queries this path made, on its current context.
            unsafe { ctx.gl().delete_query(q) };
        }
    }
}

fn gl_target(t: QueryTarget) -> u32 {
    t.gl_value().unwrap_or(glow::SAMPLES_PASSED)
}
