//! The query calls of the C library: glGet{Boolean,Integer,Float,Double}v, glIsEnabled and
//! the per-object getters, answered from the model (`ff::query`, with GL's and Mesa's type
//! conversions) and, for client state the model does not hold (vertex-array enables and
//! pointers, pixel storage, display lists), from the front end. Each answer is written to
//! the program's array in the type the entry point names.

use super::cargs::CArg;
use crate::ff::api::Entry;
use crate::ff::client::type_token;
use crate::ff::front::Client;
use crate::ff::glenum::{registry as r, value_of};
use crate::ff::lists::{ListMode, MAX_LIST_NESTING};
use crate::ff::query::{Queried, QueryValue};
use crate::ff::{FixedState, GlErrorKind};

/// The element type a getter writes.
#[derive(Clone, Copy)]
enum Out {
    Boolean,
    Int,
    Float,
    Double,
}

impl Out {
    fn of(entry: Entry) -> Out {
        match entry {
            Entry::GetBooleanv => Out::Boolean,
            Entry::GetFloatv
            | Entry::GetLightfv
            | Entry::GetMaterialfv
            | Entry::GetTexEnvfv
            | Entry::GetTexGenfv
            | Entry::GetTexParameterfv
            | Entry::GetTexLevelParameterfv => Out::Float,
            Entry::GetDoublev | Entry::GetTexGendv | Entry::GetClipPlane => Out::Double,
            _ => Out::Int,
        }
    }
}

/// What the front end keeps that glGet reads besides the model.
pub struct ClientState<'a> {
    /// The window's bits (GL_RED_BITS … GL_STENCIL_BITS with framebuffer 0 bound).
    pub window: crate::ff::framebuffer::Bits,
    pub client: &'a Client,
    pub pack_alignment: usize,
    pub unpack_alignment: usize,
}

/// Whether `entry` is a query this module answers.
pub fn handles(entry: Entry) -> bool {
    matches!(
        entry,
        Entry::GetBooleanv
            | Entry::GetIntegerv
            | Entry::GetFloatv
            | Entry::GetDoublev
            | Entry::IsEnabled
            | Entry::GetLightfv
            | Entry::GetLightiv
            | Entry::GetMaterialfv
            | Entry::GetMaterialiv
            | Entry::GetTexEnvfv
            | Entry::GetTexEnviv
            | Entry::GetTexGenfv
            | Entry::GetTexGeniv
            | Entry::GetTexGendv
            | Entry::GetTexParameterfv
            | Entry::GetTexParameteriv
            | Entry::GetTexLevelParameterfv
            | Entry::GetTexLevelParameteriv
            | Entry::GetClipPlane
    )
}

fn arg(args: &[CArg], i: usize) -> u32 {
    match args.get(i) {
        Some(CArg::Int(v)) => *v as u32,
        _ => 0,
    }
}

/// Answers one query: glIsEnabled's value, or the values written to the program's array.
pub fn answer(
    entry: Entry,
    args: &[CArg],
    state: &FixedState,
    front: &ClientState,
) -> Result<u32, GlErrorKind> {
    if entry == Entry::IsEnabled {
        let cap = arg(args, 0);
        return match client_enable(cap, front.client) {
            Some(on) => Ok(u32::from(on)),
            None => state.is_enabled(cap).map(u32::from),
        };
    }
    let (values, out_at) = match entry {
        Entry::GetBooleanv | Entry::GetIntegerv | Entry::GetFloatv | Entry::GetDoublev => {
            let pname = arg(args, 0);
            let v = match client_get(pname, front).or_else(|| bits(pname, state, front)) {
                Some(v) => v,
                None => state.get(pname)?,
            };
            (v, 1)
        }
        Entry::GetLightfv | Entry::GetLightiv => (state.get_light(arg(args, 0), arg(args, 1))?, 2),
        Entry::GetMaterialfv | Entry::GetMaterialiv => {
            (state.get_material(arg(args, 0), arg(args, 1))?, 2)
        }
        Entry::GetTexEnvfv | Entry::GetTexEnviv => {
            (state.get_tex_env(arg(args, 0), arg(args, 1))?, 2)
        }
        Entry::GetTexGenfv | Entry::GetTexGeniv | Entry::GetTexGendv => {
            (state.get_tex_gen(arg(args, 0), arg(args, 1))?, 2)
        }
        Entry::GetTexParameterfv | Entry::GetTexParameteriv => {
            (state.get_tex_parameter(arg(args, 0), arg(args, 1))?, 2)
        }
        Entry::GetTexLevelParameterfv | Entry::GetTexLevelParameteriv => {
            let level = match args.get(1) {
                Some(CArg::Int(v)) => *v as i32,
                _ => 0,
            };
            (
                state.get_tex_level_parameter(arg(args, 0), level, arg(args, 2))?,
                3,
            )
        }
        Entry::GetClipPlane => {
            let i = crate::ff::glenum::Family::ClipPlane
                .from_value(arg(args, 0))
                .ok_or(GlErrorKind::InvalidEnum)?;
            let p = state.clip_planes[usize::from(i)].value;
            (p.to_array().map(QueryValue::Float).to_vec(), 1)
        }
        _ => return Err(GlErrorKind::InvalidOperation),
    };
    write(args.get(out_at), &values, Out::of(entry));
    Ok(0)
}

/// GL_RED_BITS … GL_STENCIL_BITS of the framebuffer bound for drawing.
fn bits(pname: u32, state: &FixedState, front: &ClientState) -> Option<Queried> {
    let b = state.draw_bits(front.window);
    let v = match pname {
        r::RED_BITS => b.red,
        r::GREEN_BITS => b.green,
        r::BLUE_BITS => b.blue,
        r::ALPHA_BITS => b.alpha,
        r::DEPTH_BITS => b.depth,
        r::STENCIL_BITS => b.stencil,
        _ => return None,
    };
    Some(vec![QueryValue::Int(i32::from(v))])
}

/// Writes the values in the getter's type (GL 1.5 §6.1.2 conversions, `QueryValue`).
fn write(dst: Option<&CArg>, values: &Queried, out: Out) {
    let Some(CArg::Ptr(p, _)) = dst else {
        return;
    };
    if p.is_null() {
        return;
    }
    let p = p.cast_mut();
    for (k, v) in values.iter().enumerate() {
        // SAFETY: the program's array holds as many values as the pname has (GL's
        // contract for every getter).
        unsafe {
            match out {
                Out::Boolean => *p.cast::<u8>().add(k) = u8::from(v.as_bool()),
                Out::Int => p.cast::<i32>().add(k).write_unaligned(v.as_int()),
                Out::Float => p.cast::<f32>().add(k).write_unaligned(v.as_float()),
                Out::Double => p.cast::<f64>().add(k).write_unaligned(v.as_double()),
            }
        }
    }
}

/// glIsEnabled of a client array (GL 1.5 Table 6.7), or `None` for server state.
fn client_enable(cap: u32, c: &Client) -> Option<bool> {
    let a = &c.arrays;
    Some(match cap {
        r::VERTEX_ARRAY => a.vertex.enabled,
        r::NORMAL_ARRAY => a.normal.enabled,
        r::COLOR_ARRAY => a.color.enabled,
        r::TEXTURE_COORD_ARRAY => a.texcoord[usize::from(a.client_active)].enabled,
        r::INDEX_ARRAY | r::EDGE_FLAG_ARRAY => false,
        _ => return None,
    })
}

/// The client state glGet answers (Tables 6.7, 6.20, 6.33), or `None` for server state.
fn client_get(pname: u32, f: &ClientState) -> Option<Queried> {
    let c = f.client;
    let a = &c.arrays;
    let int = |v: i64| Some(vec![QueryValue::Int(v as i32)]);
    let enm = |v: u32| Some(vec![QueryValue::Enum(v)]);
    let ty = |t| value_of(type_token(t)).unwrap_or(r::FLOAT);
    let unit = &a.texcoord[usize::from(a.client_active)];
    if let Some(on) = client_enable(pname, c) {
        return Some(vec![QueryValue::Bool(on)]);
    }
    match pname {
        r::PACK_ALIGNMENT => int(f.pack_alignment as i64),
        r::UNPACK_ALIGNMENT => int(f.unpack_alignment as i64),
        r::CLIENT_ACTIVE_TEXTURE => enm(r::TEXTURE0 + u32::from(a.client_active)),
        r::VERTEX_ARRAY_SIZE => int(i64::from(a.vertex.size)),
        r::VERTEX_ARRAY_TYPE => enm(ty(a.vertex.ty)),
        r::VERTEX_ARRAY_STRIDE => int(i64::from(a.vertex.stride)),
        r::NORMAL_ARRAY_TYPE => enm(ty(a.normal.ty)),
        r::NORMAL_ARRAY_STRIDE => int(i64::from(a.normal.stride)),
        r::COLOR_ARRAY_SIZE => int(i64::from(a.color.size)),
        r::COLOR_ARRAY_TYPE => enm(ty(a.color.ty)),
        r::COLOR_ARRAY_STRIDE => int(i64::from(a.color.stride)),
        r::TEXTURE_COORD_ARRAY_SIZE => int(i64::from(unit.size)),
        r::TEXTURE_COORD_ARRAY_TYPE => enm(ty(unit.ty)),
        r::TEXTURE_COORD_ARRAY_STRIDE => int(i64::from(unit.stride)),
        r::LIST_BASE => int(i64::from(c.lists.base)),
        r::LIST_INDEX => int(i64::from(c.lists.compiling_name().unwrap_or(0))),
        r::LIST_MODE => match c.lists.compiling() {
            Some(ListMode::CompileAndExecute) => enm(r::COMPILE_AND_EXECUTE),
            // GL's initial LIST_MODE is 0 in Mesa; GL_COMPILE while compiling.
            Some(ListMode::Compile) => enm(r::COMPILE),
            None => int(0),
        },
        r::MAX_LIST_NESTING => int(MAX_LIST_NESTING as i64),
        r::ARRAY_BUFFER_BINDING => int(i64::from(c.buffers.bound.array)),
        r::ELEMENT_ARRAY_BUFFER_BINDING => int(i64::from(c.buffers.bound.element)),
        r::VERTEX_ARRAY_BUFFER_BINDING => int(i64::from(buffer_of(&a.vertex.data))),
        r::NORMAL_ARRAY_BUFFER_BINDING => int(i64::from(buffer_of(&a.normal.data))),
        r::COLOR_ARRAY_BUFFER_BINDING => int(i64::from(buffer_of(&a.color.data))),
        r::TEXTURE_COORD_ARRAY_BUFFER_BINDING => int(i64::from(buffer_of(&unit.data))),
        _ => None,
    }
}

/// The buffer an array pointer was given in (GL 1.5 Table 6.8), 0 for client memory.
fn buffer_of(data: &crate::ff::client::ArrayData) -> u32 {
    match data {
        crate::ff::client::ArrayData::Buffer { name, .. } => *name,
        _ => 0,
    }
}
