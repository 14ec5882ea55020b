//! Drawing the dashes of a stippled line draw (`line_stipple`): each dash is one GL_LINES
//! segment whose ends carry the draw's attributes interpolated at their parameter, the
//! provoking vertex's position and normal as the shade attributes and, under flat shading,
//! its colours in place of their own (so a flat dash has its segment's colour, GL 1.5
//! Table 2.8), and the window coordinates the CPU computed. The dashes
//! depend on the matrices and the viewport, so they are uploaded for one draw and deleted
//! after it, unlike the cached geometry of `draw`.

use glam::{Vec3, Vec4};
use glow::HasContext;

use super::draw::{set_current_values, Arrays, SentAttribs};
use super::line_stipple::{Dash, DashEnd};
use super::shadergen::{
    ATTRIB_COLOR, ATTRIB_FOG_COORD, ATTRIB_NORMAL, ATTRIB_POSITION, ATTRIB_SECONDARY,
    ATTRIB_SHADE_NORMAL, ATTRIB_SHADE_POSITION, ATTRIB_TEXCOORD0, ATTRIB_WINDOW,
};
use crate::ff::{FixedState, Geometry, ShadeModel};
use crate::pipeline::PipelineError;

/// One attribute array's floats for the dash ends, and for their provoking vertices.
struct Array {
    size: i32,
    own: Vec<f32>,
    shade: Option<(u32, Vec<f32>)>,
}

/// `a + s·(b − a)` per component.
fn mix<const N: usize>(a: [f32; N], b: [f32; N], s: f32) -> [f32; N] {
    std::array::from_fn(|k| a[k] + s * (b[k] - a[k]))
}

/// The values of `values` (one per vertex) at each dash end, and at each dash's provoking
/// vertex; `None` when an index is out of range (the model validated the draw).
fn gather<const N: usize, T: Copy>(
    values: &[T],
    dashes: &[Dash],
    flat: impl Fn(T) -> [f32; N],
) -> Option<(Vec<f32>, Vec<f32>)> {
    let at = |i: u32| values.get(i as usize).copied().map(&flat);
    let mut own = Vec::with_capacity(dashes.len() * 2 * N);
    let mut shade = Vec::with_capacity(dashes.len() * 2 * N);
    for d in dashes {
        let p = at(d.provoking)?;
        for e in &d.ends {
            own.extend(mix(at(e.from)?, at(e.to)?, e.s));
            shade.extend(p);
        }
    }
    Some((own, shade))
}

/// The arrays of the dashes of `g`: position, normal, colours, fog coordinate and texture
/// coordinates that `g` has, the position and normal with their shade copies, the colours
/// the provoking vertex's under `flat` shading.
fn arrays(g: &Geometry, dashes: &[Dash], flat: bool) -> Option<Vec<(u32, Array)>> {
    let mut out = Vec::new();
    let (own, shade) = gather(&g.positions, dashes, |v: Vec4| v.to_array())?;
    out.push((
        ATTRIB_POSITION,
        Array {
            size: 4,
            own,
            shade: Some((ATTRIB_SHADE_POSITION, shade)),
        },
    ));
    if let Some(n) = &g.normals {
        let (own, shade) = gather(n, dashes, |v: Vec3| v.to_array())?;
        out.push((
            ATTRIB_NORMAL,
            Array {
                size: 3,
                own,
                shade: Some((ATTRIB_SHADE_NORMAL, shade)),
            },
        ));
    }
    for (values, location) in [
        (&g.colors, ATTRIB_COLOR),
        (&g.secondary_colors, ATTRIB_SECONDARY),
    ] {
        if let Some(c) = values {
            let (own, shade) = gather(c, dashes, |v: Vec4| v.to_array())?;
            let array = Array {
                size: 4,
                own: if flat { shade } else { own },
                shade: None,
            };
            out.push((location, array));
        }
    }
    if let Some(f) = &g.fog_coords {
        let (own, _) = gather(f, dashes, |v: f32| [v])?;
        let array = Array {
            size: 1,
            own,
            shade: None,
        };
        out.push((ATTRIB_FOG_COORD, array));
    }
    for (u, t) in g.texcoords.iter().enumerate() {
        if let Some(t) = t {
            let (own, _) = gather(t, dashes, |v: Vec4| v.to_array())?;
            let array = Array {
                size: 4,
                own,
                shade: None,
            };
            out.push((ATTRIB_TEXCOORD0 + u as u32, array));
        }
    }
    let window = dashes
        .iter()
        .flat_map(|d| d.ends.iter().flat_map(|e: &DashEnd| e.window.to_array()))
        .collect();
    out.push((
        ATTRIB_WINDOW,
        Array {
            size: 4,
            own: window,
            shade: None,
        },
    ));
    Some(out)
}

/// Uploads the dashes of `g`, draws them as GL_LINES with the bound program, and deletes
/// what it uploaded.
pub fn draw(
    gl: &glow::Context,
    sent: &mut SentAttribs,
    state: &FixedState,
    g: &Geometry,
    dashes: &[Dash],
) -> Result<(), PipelineError> {
    if dashes.is_empty() {
        return Ok(());
    }
    let Some(arrays) = arrays(g, dashes, state.shade_model == ShadeModel::Flat) else {
        return Ok(());
    };
    let count = i32::try_from(dashes.len() * 2).unwrap_or(i32::MAX);
    let mut buffers = Vec::new();
    // SAFETY: plain GL calls on the current context; every buffer is sized by its data
    // and the draw reads `count` vertices of each.
    unsafe {
        let vao = gl.create_vertex_array().map_err(PipelineError::Object)?;
        gl.bind_vertex_array(Some(vao));
        let mut result = Ok(());
        for (location, a) in &arrays {
            let mut send = |location: u32, data: &[f32]| -> Result<(), PipelineError> {
                let b = gl.create_buffer().map_err(PipelineError::Object)?;
                buffers.push(b);
                gl.bind_buffer(glow::ARRAY_BUFFER, Some(b));
                let bytes: Vec<u8> = data.iter().flat_map(|f| f.to_ne_bytes()).collect();
                gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &bytes, glow::STREAM_DRAW);
                gl.vertex_attrib_pointer_f32(location, a.size, glow::FLOAT, false, 0, 0);
                gl.enable_vertex_attrib_array(location);
                Ok(())
            };
            result = result.and(send(*location, &a.own));
            if let Some((shade, data)) = &a.shade {
                result = result.and(send(*shade, data));
            }
        }
        if result.is_ok() {
            set_current_values(gl, sent, state, Arrays::of(g));
            gl.draw_arrays(glow::LINES, 0, count);
        }
        gl.bind_vertex_array(None);
        gl.delete_vertex_array(vao);
        for b in buffers {
            gl.delete_buffer(b);
        }
        result
    }
}
