//! Occlusion queries (GL 1.5 §4.1.6, ARB_occlusion_query; ARB_occlusion_query2's
//! ANY_SAMPLES_PASSED and ARB_ES3_compatibility's conservative form, which Mesa's
//! compatibility context takes too).
//!
//! The model keeps what the calls check: the query objects by name, whether each has been
//! begun ("ever bound": glIsQuery and glGetQueryObject* answer only for those, as in Mesa),
//! the target it was begun with, and the one occlusion query active. The three occlusion
//! targets share one binding, as in Mesa: beginning one while another is active is
//! INVALID_OPERATION. The count itself is GL's: each path begins a query of its own GL
//! around the same draws (`Pipeline::query_result`), so it counts what the path's
//! rasteriser passes through the depth and stencil tests — draws, glDrawPixels,
//! glCopyPixels and glBitmap, never glClear, glAccum or a blit.
//!
//! Errors, as Mesa 22.3 gives them: a target outside the three is INVALID_ENUM (also for
//! glGetQueryiv); glBeginQuery with an occlusion query active, of id 0, of an active
//! query, or of a query begun before with another target is INVALID_OPERATION; glEndQuery
//! with none active, or with another target than the active one's, is INVALID_OPERATION;
//! glGetQueryObject* of a name that is no query, never begun or active is
//! INVALID_OPERATION, checked before the parameter name (then INVALID_ENUM). A name never
//! generated is made a query by glBeginQuery (compatibility profile). glDeleteQueries of
//! the active query ends it. glBeginQuery and glEndQuery are compiled into display lists;
//! the others run at once.

use std::collections::BTreeMap;

use super::api::{CType, Entry};
use super::args::Args;
use super::command::Command;
use super::error::{GlError, GlErrorKind, GlResult};
use super::front::Reply;
use super::glenum::GlEnum;
use super::state::FixedState;

/// A query target the layer counts for (all three count samples; the two "any" forms
/// answer 0 or 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QueryTarget {
    SamplesPassed,
    AnySamplesPassed,
    AnySamplesPassedConservative,
}

impl GlEnum for QueryTarget {
    const TABLE: &'static [(&'static str, u32, Self)] = &[
        ("GL_SAMPLES_PASSED", 0x8914, QueryTarget::SamplesPassed),
        (
            "GL_ANY_SAMPLES_PASSED",
            0x8C2F,
            QueryTarget::AnySamplesPassed,
        ),
        (
            "GL_ANY_SAMPLES_PASSED_CONSERVATIVE",
            0x8D6A,
            QueryTarget::AnySamplesPassedConservative,
        ),
    ];
}

impl QueryTarget {
    /// GL_QUERY_COUNTER_BITS as Mesa's llvmpipe answers it: 64 for the sample count, 1 for
    /// the two boolean forms.
    pub fn counter_bits(self) -> i32 {
        match self {
            QueryTarget::SamplesPassed => 64,
            _ => 1,
        }
    }

    /// Whether the result is a boolean (any sample passed) rather than a count.
    pub fn is_boolean(self) -> bool {
        self != QueryTarget::SamplesPassed
    }
}

/// glGetQueryiv's parameter names (GL 1.5 Table 6.32).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum TargetParam {
    CurrentQuery,
    CounterBits,
}

impl GlEnum for TargetParam {
    const TABLE: &'static [(&'static str, u32, Self)] = &[
        ("GL_CURRENT_QUERY", 0x8865, TargetParam::CurrentQuery),
        ("GL_QUERY_COUNTER_BITS", 0x8864, TargetParam::CounterBits),
    ];
}

/// glGetQueryObject*'s parameter names: the result and its availability (GL 1.5), and
/// the target the query was begun with (GL 4.5's QUERY_TARGET, which Mesa answers too).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ObjectParam {
    Result,
    ResultAvailable,
    Target,
}

impl GlEnum for ObjectParam {
    const TABLE: &'static [(&'static str, u32, Self)] = &[
        ("GL_QUERY_RESULT", 0x8866, ObjectParam::Result),
        (
            "GL_QUERY_RESULT_AVAILABLE",
            0x8867,
            ObjectParam::ResultAvailable,
        ),
        ("GL_QUERY_TARGET", 0x82EA, ObjectParam::Target),
    ];
}

/// The query commands the model and the paths take.
#[derive(Clone, Debug, PartialEq)]
pub enum QueryCommand {
    /// glGenQueries: names `first..first + count` are reserved (not yet queries that
    /// glIsQuery knows).
    Gen { first: u32, count: u32 },
    /// glDeleteQueries: 0 and names that are no query are ignored.
    Delete(Vec<u32>),
    /// glBeginQuery(target, id).
    Begin { target: QueryTarget, id: u32 },
    /// glEndQuery(target).
    End(QueryTarget),
}

/// One query object.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QueryObject {
    /// The target of its first glBeginQuery; `None` until begun.
    pub target: Option<QueryTarget>,
}

/// The query objects of a context and the active occlusion query.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Queries {
    objects: BTreeMap<u32, QueryObject>,
    /// The largest name ever made a query object, deleted or not: Mesa's name table
    /// never lowers its largest key, and new names follow it.
    largest: u32,
    /// The active occlusion query: its name and the target it was begun with.
    pub active: Option<(u32, QueryTarget)>,
}

impl Queries {
    /// `n` names after the largest ever used (Mesa's _mesa_HashFindFreeKeyBlock); `None`
    /// when they would pass 2³² − 1.
    pub fn free_block(&self, n: u32) -> Option<u32> {
        self.largest.checked_add(n)?;
        Some(self.largest + 1)
    }

    fn object(&mut self, id: u32) -> &mut QueryObject {
        self.largest = self.largest.max(id);
        self.objects.entry(id).or_default()
    }

    /// glIsQuery: a name that has been begun.
    pub fn is_query(&self, id: u32) -> bool {
        self.objects.get(&id).is_some_and(|q| q.target.is_some())
    }

    /// The query glGetQueryObject* may read: begun and not active.
    pub fn readable(&self, id: u32) -> Option<QueryTarget> {
        let target = self.objects.get(&id)?.target?;
        (self.active.map(|(a, _)| a) != Some(id)).then_some(target)
    }
}

impl FixedState {
    /// Applies a query command; `Ok(false)` for commands of other areas.
    pub(crate) fn apply_query(&mut self, cmd: &Command) -> GlResult<bool> {
        let Command::Query(q) = cmd else {
            return Ok(false);
        };
        let queries = &mut self.queries;
        match q {
            QueryCommand::Gen { first, count } => {
                for id in *first..first.saturating_add(*count) {
                    queries.object(id);
                }
            }
            QueryCommand::Delete(ids) => {
                for id in ids {
                    if queries.objects.remove(id).is_some()
                        && queries.active.map(|(a, _)| a) == Some(*id)
                    {
                        queries.active = None;
                    }
                }
            }
            QueryCommand::Begin { target, id } => {
                if queries.active.is_some() {
                    return Err(GlError::invalid_operation(
                        "glBeginQuery while an occlusion query is active",
                    ));
                }
                if *id == 0 {
                    return Err(GlError::invalid_operation("glBeginQuery of query 0"));
                }
                let object = queries.object(*id);
                if object.target.is_some_and(|t| t != *target) {
                    return Err(GlError::invalid_operation(
                        "glBeginQuery of a query begun before with another target",
                    ));
                }
                object.target = Some(*target);
                queries.active = Some((*id, *target));
            }
            QueryCommand::End(target) => match queries.active {
                Some((_, t)) if t == *target => queries.active = None,
                _ => {
                    return Err(GlError::invalid_operation(
                        "glEndQuery without a glBeginQuery of that target",
                    ))
                }
            },
        }
        Ok(true)
    }
}

/// Whether `entry` is a query-object call.
pub fn handles(entry: Entry) -> bool {
    use Entry::*;
    matches!(
        entry,
        GenQueries
            | GenQueriesARB
            | DeleteQueries
            | DeleteQueriesARB
            | IsQuery
            | IsQueryARB
            | BeginQuery
            | BeginQueryARB
            | EndQuery
            | EndQueryARB
            | GetQueryiv
            | GetQueryivARB
            | GetQueryObjectiv
            | GetQueryObjectivARB
            | GetQueryObjectuiv
            | GetQueryObjectuivARB
    )
}

/// The query calls that run at once, never compiled into a list (all but glBeginQuery and
/// glEndQuery, which Mesa compiles).
pub fn never_compiled(entry: Entry) -> bool {
    handles(entry) && command_of(entry)
}

fn command_of(entry: Entry) -> bool {
    !matches!(
        entry,
        Entry::BeginQuery | Entry::BeginQueryARB | Entry::EndQuery | Entry::EndQueryARB
    )
}

/// The Command of glBeginQuery and glEndQuery; `None` for other calls.
pub fn command<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    Ok(Some(Command::Query(match c.entry() {
        Entry::BeginQuery | Entry::BeginQueryARB => {
            c.count(2)?;
            QueryCommand::Begin {
                target: c.enm(0)?,
                id: c.u32(1)?,
            }
        }
        Entry::EndQuery | Entry::EndQueryARB => {
            c.count(1)?;
            QueryCommand::End(c.enm(0)?)
        }
        _ => return Ok(None),
    })))
}

/// What a query call that runs at once asks of its front end.
pub enum Answer {
    /// The call's reply; its commands (glGenQueries' reservation, glDeleteQueries) are
    /// in `out`.
    Reply(Reply),
    /// glGetQueryObject*: the caller reads the result of query `id` from the pipeline
    /// and stores it through argument 2.
    Object {
        id: u32,
        param: ObjectParam,
        target: QueryTarget,
    },
}

/// glGenQueries, glDeleteQueries, glIsQuery, glGetQueryiv and glGetQueryObject*, checked
/// against the model. A GL error is the inner `Err`.
pub fn answer<A: Args>(
    c: &A,
    state: &FixedState,
    out: &mut Vec<Command>,
) -> Result<Result<Answer, GlErrorKind>, A::Error> {
    use Entry::*;
    let queries = &state.queries;
    Ok(Ok(match c.entry() {
        GenQueries | GenQueriesARB => {
            c.count(2)?;
            let n = c.i32(0)?;
            let Ok(n) = u32::try_from(n) else {
                return Ok(Err(GlErrorKind::InvalidValue));
            };
            let Some(first) = queries.free_block(n) else {
                return Ok(Err(GlErrorKind::InvalidValue));
            };
            if n > 0 {
                out.push(Command::Query(QueryCommand::Gen { first, count: n }));
            }
            let bytes = (first..first + n).flat_map(u32::to_ne_bytes).collect();
            Answer::Reply(Reply::Write { arg: 1, bytes })
        }
        DeleteQueries | DeleteQueriesARB => {
            c.count(2)?;
            let n = c.i32(0)?;
            let Ok(n) = usize::try_from(n) else {
                return Ok(Err(GlErrorKind::InvalidValue));
            };
            let ids = if n == 0 {
                Vec::new()
            } else {
                c.array_as(1, n, CType::UInt)?
            };
            let ids: Vec<u32> = ids.into_iter().map(|v| v as u32).collect();
            if !ids.is_empty() {
                out.push(Command::Query(QueryCommand::Delete(ids)));
            }
            Answer::Reply(Reply::None)
        }
        IsQuery | IsQueryARB => {
            c.count(1)?;
            Answer::Reply(Reply::Value(u32::from(queries.is_query(c.u32(0)?))))
        }
        GetQueryiv | GetQueryivARB => {
            c.count(3)?;
            let Ok(target) = c.enm::<QueryTarget>(0) else {
                return Ok(Err(GlErrorKind::InvalidEnum));
            };
            let Ok(param) = c.enm::<TargetParam>(1) else {
                return Ok(Err(GlErrorKind::InvalidEnum));
            };
            let value = match param {
                // Mesa: the active query's name only when begun with this very target.
                TargetParam::CurrentQuery => match queries.active {
                    Some((id, t)) if t == target => id as i32,
                    _ => 0,
                },
                TargetParam::CounterBits => target.counter_bits(),
            };
            Answer::Reply(Reply::Write {
                arg: 2,
                bytes: value.to_ne_bytes().to_vec(),
            })
        }
        GetQueryObjectiv | GetQueryObjectivARB | GetQueryObjectuiv | GetQueryObjectuivARB => {
            c.count(3)?;
            let id = c.u32(0)?;
            let Some(target) = queries.readable(id) else {
                return Ok(Err(GlErrorKind::InvalidOperation));
            };
            let Ok(param) = c.enm::<ObjectParam>(1) else {
                return Ok(Err(GlErrorKind::InvalidEnum));
            };
            Answer::Object { id, param, target }
        }
        _ => return Err(c.unsupported()),
    }))
}

/// The value glGetQueryObject* stores for `param`, given what the path answered
/// (`fetched`: the sample count for the result, 0 or 1 for its availability, unread for
/// the target): the "any" forms give 0 or 1; the signed getter clamps to 2³¹ − 1, as Mesa
/// does.
pub fn object_value(param: ObjectParam, target: QueryTarget, fetched: u64, signed: bool) -> u32 {
    let v = match param {
        ObjectParam::Target => u64::from(target.gl_value().unwrap_or(0)),
        ObjectParam::ResultAvailable => fetched.min(1),
        ObjectParam::Result if target.is_boolean() => fetched.min(1),
        ObjectParam::Result => fetched,
    };
    if signed {
        v.min(i32::MAX as u64) as u32
    } else {
        v.min(u64::from(u32::MAX)) as u32
    }
}
