//! Geometry as client-side vertex arrays (GL 1.1 §2.8): positions as 4 floats, optional
//! normals, colours, edge flags (GLboolean) and per-unit texture coordinates (glClientActiveTexture selects the
//! unit a TexCoordPointer names), drawn with glDrawArrays or glDrawElements(UNSIGNED_INT).
//! Every primitive of GL 1.x, QUADS, QUAD_STRIP and POLYGON included, is a valid mode on a
//! compatibility context.
//!
//! After a draw GL leaves the current normal, colour and texture coordinates of an enabled
//! array indeterminate (§2.8); the model keeps them, as Mesa does. [`restore_current`]
//! sends the model's values so both agree whatever the driver did.

use std::ffi::c_void;

use glam::{Vec3, Vec4};

use crate::ff::glenum::value_of;
use crate::ff::{FixedState, Geometry, MaterialSlot, VertexMaterials, MAX_TEXTURE_UNITS};

use super::bindings as gl;
use super::bindings::types::GLsizei;
use super::conv;

/// Flattens the attribute arrays (glam's SIMD layout is not a C array of floats).
fn flat4(v: &[Vec4]) -> Vec<f32> {
    v.iter().flat_map(|p| p.to_array()).collect()
}

fn flat3(v: &[Vec3]) -> Vec<f32> {
    v.iter().flat_map(|p| p.to_array()).collect()
}

/// The arrays one draw points GL at; they must outlive the draw call.
struct Arrays {
    positions: Vec<f32>,
    normals: Option<Vec<f32>>,
    colors: Option<Vec<f32>>,
    texcoords: Vec<(u8, Vec<f32>)>,
    edge_flags: Option<Vec<u8>>,
    /// RGB of each secondary colour (glSecondaryColorPointer takes size 3 or 4; 3 keeps
    /// the current value's alpha out of GL, as glSecondaryColor3f does).
    secondary_colors: Option<Vec<f32>>,
    fog_coords: Option<Vec<f32>>,
}

impl Arrays {
    fn of(g: &Geometry) -> Arrays {
        Arrays {
            positions: flat4(&g.positions),
            normals: g.normals.as_deref().map(flat3),
            colors: g.colors.as_deref().map(flat4),
            texcoords: g
                .texcoords
                .iter()
                .enumerate()
                .filter_map(|(u, t)| Some((u8::try_from(u).ok()?, flat4(t.as_deref()?))))
                .collect(),
            edge_flags: g
                .edge_flags
                .as_ref()
                .map(|f| f.iter().map(|&on| u8::from(on)).collect()),
            secondary_colors: g
                .secondary_colors
                .as_ref()
                .map(|c| c.iter().flat_map(|v| v.truncate().to_array()).collect()),
            fog_coords: g.fog_coords.clone(),
        }
    }
}

/// Draws `g` (already validated by the model: arrays of equal length, indices in range).
pub fn draw(g: &gl::Gl, geometry: &Geometry) {
    let arrays = Arrays::of(geometry);
    let mode = conv::value(geometry.primitive);
    // SAFETY: every pointer names a live Vec of the right length for the vertex count; the
    // model checked that indices stay inside the arrays. No buffer object is bound to
    // ARRAY_BUFFER or ELEMENT_ARRAY_BUFFER (the pipeline unbinds them), so the pointers are
    // client memory.
    unsafe {
        g.EnableClientState(gl::VERTEX_ARRAY);
        g.VertexPointer(4, gl::FLOAT, 0, arrays.positions.as_ptr().cast::<c_void>());
        if let Some(n) = &arrays.normals {
            g.EnableClientState(gl::NORMAL_ARRAY);
            g.NormalPointer(gl::FLOAT, 0, n.as_ptr().cast::<c_void>());
        }
        if let Some(c) = &arrays.colors {
            g.EnableClientState(gl::COLOR_ARRAY);
            g.ColorPointer(4, gl::FLOAT, 0, c.as_ptr().cast::<c_void>());
        }
        if let Some(f) = &arrays.edge_flags {
            g.EnableClientState(gl::EDGE_FLAG_ARRAY);
            g.EdgeFlagPointer(0, f.as_ptr().cast::<c_void>());
        }
        if let Some(c) = &arrays.secondary_colors {
            g.EnableClientState(gl::SECONDARY_COLOR_ARRAY);
            g.SecondaryColorPointer(3, gl::FLOAT, 0, c.as_ptr().cast::<c_void>());
        }
        if let Some(f) = &arrays.fog_coords {
            g.EnableClientState(gl::FOG_COORD_ARRAY);
            g.FogCoordPointer(gl::FLOAT, 0, f.as_ptr().cast::<c_void>());
        }
        for (unit, t) in &arrays.texcoords {
            g.ClientActiveTexture(conv::texture_unit(*unit));
            g.EnableClientState(gl::TEXTURE_COORD_ARRAY);
            g.TexCoordPointer(4, gl::FLOAT, 0, t.as_ptr().cast::<c_void>());
        }
        if let Some(m) = &geometry.materials {
            draw_with_materials(g, geometry, m, mode);
        } else {
            draw_arrays(g, geometry, mode);
        }
        // Leave no array enabled: the next draw enables exactly what it has.
        for (unit, _) in &arrays.texcoords {
            g.ClientActiveTexture(conv::texture_unit(*unit));
            g.DisableClientState(gl::TEXTURE_COORD_ARRAY);
        }
        g.ClientActiveTexture(gl::TEXTURE0);
        g.DisableClientState(gl::COLOR_ARRAY);
        g.DisableClientState(gl::EDGE_FLAG_ARRAY);
        g.DisableClientState(gl::SECONDARY_COLOR_ARRAY);
        g.DisableClientState(gl::FOG_COORD_ARRAY);
        g.DisableClientState(gl::NORMAL_ARRAY);
        g.DisableClientState(gl::VERTEX_ARRAY);
    }
}

/// The enabled arrays drawn in one call.
///
/// # Safety
/// The arrays set on `g` hold every vertex and index of `geometry`.
unsafe fn draw_arrays(g: &gl::Gl, geometry: &Geometry, mode: u32) {
    unsafe {
        match &geometry.indices {
            Some(idx) => g.DrawElements(
                mode,
                count(idx.len()),
                gl::UNSIGNED_INT,
                idx.as_ptr().cast::<c_void>(),
            ),
            None => g.DrawArrays(mode, 0, count(geometry.positions.len())),
        }
    }
}

/// A draw whose vertices carry materials, as the program gave it: glBegin, then per
/// element the glMaterial calls whose value changes at it and glArrayElement, then glEnd.
/// The material state is the model's again afterwards ([`restore_materials`]).
///
/// # Safety
/// As [`draw_arrays`].
unsafe fn draw_with_materials(g: &gl::Gl, geometry: &Geometry, m: &VertexMaterials, mode: u32) {
    let order: Vec<u32> = match &geometry.indices {
        Some(idx) => idx.clone(),
        None => (0..geometry.positions.len() as u32).collect(),
    };
    unsafe {
        g.Begin(mode);
        for (k, &i) in order.iter().enumerate() {
            for (slot, v) in m.changes_at(&order, k) {
                send_material(g, slot, v);
            }
            g.ArrayElement(i as i32);
        }
        g.End();
    }
}

/// glMaterialfv of one slot's value (shininess is its first component).
fn send_material(g: &gl::Gl, slot: MaterialSlot, v: Vec4) {
    let (face, pname) = slot.names();
    let (Some(face), Some(pname)) = (value_of(face), value_of(pname)) else {
        return;
    };
    let values = v.to_array();
    // SAFETY: a plain GL call with four floats.
    unsafe { g.Materialfv(face, pname, values.as_ptr()) };
}

/// Sends the model's material for every slot a draw's vertices carried: GL's material is
/// the last vertex's after such a draw, the model's until the commands after the draw.
pub fn restore_materials(g: &gl::Gl, state: &FixedState, geometry: &Geometry) {
    for (slot, _) in geometry.materials.iter().flat_map(|m| m.present()) {
        send_material(g, slot, state.materials.value(slot));
    }
}

/// A vertex count as GLsizei; counts beyond i32 are clamped (GL could not draw them anyway).
fn count(n: usize) -> GLsizei {
    GLsizei::try_from(n).unwrap_or(GLsizei::MAX)
}

/// Sends the model's current normal, colour and texture coordinates after a draw whose
/// arrays made GL's values indeterminate. The colour goes last: under COLOR_MATERIAL it
/// also sets the tracked material from the current colour, as the model has it.
pub fn restore_current(g: &gl::Gl, state: &FixedState, geometry: &Geometry) {
    let c = &state.current;
    // SAFETY: plain GL calls on the current context.
    unsafe {
        if geometry.normals.is_some() {
            g.Normal3f(c.normal.x, c.normal.y, c.normal.z);
        }
        if geometry.edge_flags.is_some() {
            g.EdgeFlag(u8::from(c.edge_flag));
        }
        if geometry.secondary_colors.is_some() {
            let s = c.secondary_color;
            g.SecondaryColor3f(s.x, s.y, s.z);
        }
        if geometry.fog_coords.is_some() {
            g.FogCoordf(c.fog_coord);
        }
        for unit in 0..MAX_TEXTURE_UNITS {
            if geometry.texcoords[unit].is_some() {
                let t = c.texcoords[unit];
                g.MultiTexCoord4f(gl::TEXTURE0 + unit as u32, t.x, t.y, t.z, t.w);
            }
        }
        if geometry.colors.is_some() {
            g.Color4f(c.color.x, c.color.y, c.color.z, c.color.w);
        }
    }
}
