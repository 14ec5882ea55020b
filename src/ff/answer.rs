//! The answers of the query calls for both front ends: glGet{Boolean,Integer,Float,Double}v,
//! glIsEnabled, glGetPointerv and the per-object getters, from the model (`ff::query`, with
//! GL's and Mesa's type conversions) and, for the client state the model does not hold
//! (vertex-array enables and pointers, pixel storage, the client attribute stack, display
//! lists), from the front end. Each answer is the bytes the getter stores through its
//! pointer, in the type the entry point names; the C library writes them to the program's
//! array, a script (whose compound literal cannot be read back) drops them. A token of the
//! wrong set is GL's INVALID_ENUM from either front end, the call then storing nothing.

use super::api::Entry;
use super::args::Args;
use super::client::{type_token, ArrayData};
use super::client_attrib::MAX_CLIENT_ATTRIB_STACK_DEPTH;
use super::front::{Client, Reply};
use super::glenum::GlEnum;
use super::glenum::{pname_of, registry as r, value_of, Family};
use super::lists::{ListMode, MAX_LIST_NESTING};
use super::pixel_map::PixelMapName;
use super::pixel_store::PNAMES;
use super::query::{Queried, QueryValue};
use super::{FixedState, GlErrorKind};

/// GL_CLIENT_ATTRIB_STACK_DEPTH and GL_MAX_CLIENT_ATTRIB_STACK_DEPTH (Table 6.38).
const CLIENT_ATTRIB_STACK_DEPTH: u32 = 0x0BB1;
const MAX_CLIENT_ATTRIB_STACK_DEPTH_PNAME: u32 = 0x0D3B;

/// The element type a getter stores.
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

/// Whether `entry` is a query this module answers.
pub fn handles(entry: Entry) -> bool {
    matches!(
        entry,
        Entry::GetBooleanv
            | Entry::GetIntegerv
            | Entry::GetFloatv
            | Entry::GetDoublev
            | Entry::IsEnabled
            | Entry::GetPointerv
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
            | Entry::GetPolygonStipple
            | Entry::GetPixelMapfv
            | Entry::GetPixelMapuiv
            | Entry::GetPixelMapusv
    )
}

/// Answers one query: glIsEnabled's value, or the bytes stored through the out pointer.
/// The outer error is the front end's (a script's unreadable argument); the inner one the
/// GL error the call raises.
pub fn answer<A: Args>(
    c: &A,
    state: &FixedState,
    client: &Client,
) -> Result<Result<Reply, GlErrorKind>, A::Error> {
    let entry = c.entry();
    let t = |i: usize| c.token(i);
    let found: Result<(Queried, usize), GlErrorKind> = match entry {
        Entry::IsEnabled => {
            c.count(1)?;
            let cap = t(0)?;
            let on = match client_enable(cap, client) {
                Some(on) => Ok(on),
                None => state.is_enabled(cap),
            };
            return Ok(on.map(|on| Reply::Value(u32::from(on))));
        }
        Entry::GetPointerv => {
            c.count(2)?;
            return Ok(pointer(t(0)?, client).map(|a| Reply::Write {
                arg: 1,
                bytes: a.to_ne_bytes().to_vec(),
            }));
        }
        Entry::GetBooleanv | Entry::GetIntegerv | Entry::GetFloatv | Entry::GetDoublev => {
            c.count(2)?;
            let pname = t(0)?;
            match client_get(pname, client) {
                Some(v) => Ok((v, 1)),
                None => state.get(pname).map(|v| (v, 1)),
            }
        }
        Entry::GetLightfv | Entry::GetLightiv => {
            c.count(3)?;
            state.get_light(t(0)?, t(1)?).map(|v| (v, 2))
        }
        Entry::GetMaterialfv | Entry::GetMaterialiv => {
            c.count(3)?;
            state.get_material(t(0)?, t(1)?).map(|v| (v, 2))
        }
        Entry::GetTexEnvfv | Entry::GetTexEnviv => {
            c.count(3)?;
            state.get_tex_env(t(0)?, t(1)?).map(|v| (v, 2))
        }
        Entry::GetTexGenfv | Entry::GetTexGeniv | Entry::GetTexGendv => {
            c.count(3)?;
            state.get_tex_gen(t(0)?, t(1)?).map(|v| (v, 2))
        }
        Entry::GetTexParameterfv | Entry::GetTexParameteriv => {
            c.count(3)?;
            state.get_tex_parameter(t(0)?, t(1)?).map(|v| (v, 2))
        }
        Entry::GetTexLevelParameterfv | Entry::GetTexLevelParameteriv => {
            c.count(4)?;
            let (target, level, pname) = (t(0)?, c.i32(1)?, t(2)?);
            state
                .get_tex_level_parameter(target, level, pname)
                .map(|v| (v, 3))
        }
        Entry::GetClipPlane => {
            c.count(2)?;
            Family::ClipPlane
                .from_value(t(0)?)
                .ok_or(GlErrorKind::InvalidEnum)
                .map(|i| {
                    let p = state.clip_planes[usize::from(i)].value;
                    (p.to_array().map(QueryValue::Float).to_vec(), 1)
                })
        }
        // Tight, most significant bit first: the C front end packs it as a 32×32 bitmap
        // with the pack parameters (§6.1.7).
        Entry::GetPolygonStipple => {
            c.count(1)?;
            return Ok(Ok(Reply::Write {
                arg: 0,
                bytes: state.polygon_stipple.value.to_bytes(),
            }));
        }
        Entry::GetPixelMapfv | Entry::GetPixelMapuiv | Entry::GetPixelMapusv => {
            c.count(2)?;
            let map: PixelMapName = match PixelMapName::from_gl_value(t(0)?) {
                Some(m) => m,
                None => return Ok(Err(GlErrorKind::InvalidEnum)),
            };
            return Ok(Ok(Reply::Write {
                arg: 1,
                bytes: pixel_map_bytes(entry, map, state.pixel_maps.get(map)),
            }));
        }
        _ => return Err(c.unsupported()),
    };
    Ok(found.map(|(values, arg)| Reply::Write {
        arg,
        bytes: encode(&values, Out::of(entry)),
    }))
}

/// glGetPixelMap{f,ui,us}v's values, as Mesa's `_mesa_GetnPixelMap*` converts them: an
/// index map's (I_TO_I, S_TO_S) integers as they are for GLushort (clamped to [0, 65535]);
/// a colour map's c as round_even(c · 65535) for GLushort. For GLuint every map but S_TO_S
/// goes through Mesa's `FLOAT_TO_UINT`, (GLuint)(c · (2³² − 1)) — an index too, a Mesa
/// fault followed (measured: I_TO_I 7 reads 4294967289, the low 32 bits of 7 · (2³² − 1));
/// S_TO_S is copied as bytes, so its float's bits are read (3 reads 1077936128).
fn pixel_map_bytes(entry: Entry, map: PixelMapName, values: &[f32]) -> Vec<u8> {
    let index = map.holds_integers();
    values
        .iter()
        .flat_map(|v| match entry {
            Entry::GetPixelMapfv => v.to_ne_bytes().to_vec(),
            Entry::GetPixelMapuiv if map == PixelMapName::SToS => {
                v.to_bits().to_ne_bytes().to_vec()
            }
            Entry::GetPixelMapuiv => (super::query::c_long((f64::from(*v) * 4294967295.0).trunc())
                as u32)
                .to_ne_bytes()
                .to_vec(),
            _ if index => (v.clamp(0.0, 65535.0) as u16).to_ne_bytes().to_vec(),
            _ => ((v * 65535.0).round_ties_even() as u16)
                .to_ne_bytes()
                .to_vec(),
        })
        .collect()
}

/// The values in the getter's type (GL 1.5 §6.1.2 conversions, `QueryValue`), as bytes.
fn encode(values: &Queried, out: Out) -> Vec<u8> {
    let mut bytes = Vec::new();
    for v in values {
        match out {
            Out::Boolean => bytes.push(u8::from(v.as_bool())),
            Out::Int => bytes.extend(v.as_int().to_ne_bytes()),
            Out::Float => bytes.extend(v.as_float().to_ne_bytes()),
            Out::Double => bytes.extend(v.as_double().to_ne_bytes()),
        }
    }
    bytes
}

/// glIsEnabled of a client array (GL 1.5 Table 6.7), or `None` for server state.
fn client_enable(cap: u32, c: &Client) -> Option<bool> {
    let a = &c.arrays;
    Some(match cap {
        r::VERTEX_ARRAY => a.vertex.enabled,
        r::NORMAL_ARRAY => a.normal.enabled,
        r::COLOR_ARRAY => a.color.enabled,
        r::TEXTURE_COORD_ARRAY => a.texcoord[usize::from(a.client_active)].enabled,
        r::EDGE_FLAG_ARRAY => a.edge_flag.enabled,
        r::SECONDARY_COLOR_ARRAY => a.secondary_color.enabled,
        r::FOG_COORD_ARRAY => a.fog_coord.enabled,
        r::INDEX_ARRAY => a.index.enabled,
        _ => return None,
    })
}

/// glGetPointerv (GL 1.5 §6.1.11): an array's pointer as it was given (an offset when a
/// buffer was bound; a script's literal has no address and answers NULL). Feedback and
/// selection are left out: NULL.
fn pointer(pname: u32, c: &Client) -> Result<usize, GlErrorKind> {
    const FEEDBACK_BUFFER_POINTER: u32 = 0x0DF0;
    const SELECTION_BUFFER_POINTER: u32 = 0x0DF3;
    let a = &c.arrays;
    let data = match pname {
        r::VERTEX_ARRAY_POINTER => &a.vertex.data,
        r::NORMAL_ARRAY_POINTER => &a.normal.data,
        r::COLOR_ARRAY_POINTER => &a.color.data,
        r::TEXTURE_COORD_ARRAY_POINTER => &a.texcoord[usize::from(a.client_active)].data,
        r::EDGE_FLAG_ARRAY_POINTER => &a.edge_flag.data,
        r::SECONDARY_COLOR_ARRAY_POINTER => &a.secondary_color.data,
        r::FOG_COORD_ARRAY_POINTER => &a.fog_coord.data,
        r::INDEX_ARRAY_POINTER => &a.index.data,
        FEEDBACK_BUFFER_POINTER | SELECTION_BUFFER_POINTER => &ArrayData::Null,
        _ => return Err(GlErrorKind::InvalidEnum),
    };
    Ok(match data {
        ArrayData::Address(p) => *p,
        ArrayData::Buffer { offset, .. } | ArrayData::Orphaned(offset) => *offset,
        ArrayData::Null | ArrayData::Bytes(_) => 0,
    })
}

/// The client state glGet answers (Tables 6.7, 6.20, 6.33, 6.38), or `None` for server
/// state.
fn client_get(pname: u32, c: &Client) -> Option<Queried> {
    let a = &c.arrays;
    let int = |v: i64| Some(vec![QueryValue::Int(v as i32)]);
    let enm = |v: u32| Some(vec![QueryValue::Enum(v)]);
    let ty = |t| value_of(type_token(t)).unwrap_or(r::FLOAT);
    let unit = &a.texcoord[usize::from(a.client_active)];
    if let Some(on) = client_enable(pname, c) {
        return Some(vec![QueryValue::Bool(on)]);
    }
    // Table 6.20: every pixel-store parameter; SWAP_BYTES and LSB_FIRST are booleans.
    if let Some(name) = pname_of(pname, PNAMES) {
        let v = c.pixel_store.get(name)?;
        return Some(vec![
            if name.ends_with("SWAP_BYTES") || name.ends_with("LSB_FIRST") {
                QueryValue::Bool(v != 0)
            } else {
                QueryValue::Int(v as i32)
            },
        ]);
    }
    match pname {
        CLIENT_ATTRIB_STACK_DEPTH => int(c.client_attrib.depth() as i64),
        MAX_CLIENT_ATTRIB_STACK_DEPTH_PNAME => int(MAX_CLIENT_ATTRIB_STACK_DEPTH as i64),
        r::CLIENT_ACTIVE_TEXTURE => enm(r::TEXTURE0 + u32::from(a.client_active)),
        r::ARRAY_ELEMENT_LOCK_FIRST_EXT => int(a.lock.map_or(0, |l| l.first).into()),
        r::ARRAY_ELEMENT_LOCK_COUNT_EXT => int(a.lock.map_or(0, |l| l.count).into()),
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
        r::EDGE_FLAG_ARRAY_STRIDE => int(i64::from(a.edge_flag.stride)),
        r::SECONDARY_COLOR_ARRAY_SIZE => int(i64::from(a.secondary_color.size)),
        r::SECONDARY_COLOR_ARRAY_TYPE => enm(ty(a.secondary_color.ty)),
        r::SECONDARY_COLOR_ARRAY_STRIDE => int(i64::from(a.secondary_color.stride)),
        r::FOG_COORD_ARRAY_TYPE => enm(ty(a.fog_coord.ty)),
        r::FOG_COORD_ARRAY_STRIDE => int(i64::from(a.fog_coord.stride)),
        r::INDEX_ARRAY_TYPE => enm(ty(a.index.ty)),
        r::INDEX_ARRAY_STRIDE => int(i64::from(a.index.stride)),
        r::INDEX_ARRAY_BUFFER_BINDING => int(i64::from(buffer_of(&a.index.data))),
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
        r::EDGE_FLAG_ARRAY_BUFFER_BINDING => int(i64::from(buffer_of(&a.edge_flag.data))),
        r::SECONDARY_COLOR_ARRAY_BUFFER_BINDING => {
            int(i64::from(buffer_of(&a.secondary_color.data)))
        }
        r::FOG_COORD_ARRAY_BUFFER_BINDING => int(i64::from(buffer_of(&a.fog_coord.data))),
        _ => None,
    }
}

/// The buffer an array pointer was given in (GL 1.5 Table 6.8), 0 for client memory.
fn buffer_of(data: &ArrayData) -> u32 {
    match data {
        ArrayData::Buffer { name, .. } => *name,
        _ => 0,
    }
}
