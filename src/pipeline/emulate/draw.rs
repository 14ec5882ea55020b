//! Geometry on the GPU: one vertex array object per `Geometry` (kept while the `Arc` lives,
//! so meshes are uploaded once per context). The types core GL has are drawn as they are,
//! indexed; the three it lacks — QUADS, QUAD_STRIP, POLYGON — become triangles split as
//! Mesa's native path splits them (`assembly`, where the measurements are), uploaded as
//! unshared triangle corners carrying the edge attribute of `polygon` (so LINE and POINT
//! modes can drop what the split added) and their polygon's provoking vertex as the shade
//! attributes (so a flat polygon has one colour, whichever triangle a fragment is in). The
//! colours of a split polygon are uploaded twice, each corner's own and its provoking
//! vertex's, and each draw binds the pair its shade model reads.
//! TRIANGLES whose edge-flag array has a FALSE are uploaded as corners too
//! (`polygon::Outline`).
//!
//! Mesa's QUADS split depends on the draw: indexed quads are split v1–v3; non-indexed ones
//! v0–v2, except each chunk of 1024 quads that has a vertex outside the clip volume, split
//! v1–v3. Non-indexed QUADS are therefore uploaded in both splits, and each draw picks per
//! chunk from the current matrices; everything else has one split. A non-indexed draw of
//! a core type that repeats its vertices is uploaded indexed (`shared_vertices`). The arrays
//! of a geometry kept for more draws are interleaved in one buffer (`vertex_layout`).

use std::collections::HashMap;
use std::sync::Arc;

use glam::Vec4;
use glow::HasContext;

use super::assembly::{self, Diagonal};
use super::polygon::{split_corners, Corner, Outline, PolygonPass};
use super::shadergen::{
    material_location, ATTRIB_COLOR, ATTRIB_COUNT, ATTRIB_EDGE, ATTRIB_FOG_COORD, ATTRIB_NORMAL,
    ATTRIB_POSITION, ATTRIB_SECONDARY, ATTRIB_SHADE_NORMAL, ATTRIB_SHADE_POSITION,
    ATTRIB_TEXCOORD0,
};
use super::shared_vertices::{self, Shared};
use super::vertex_layout::{self, Floats};
use crate::ff::{
    Face, FixedState, FrontFace, Geometry, PolygonMode, Primitive, ShadeModel, MAX_TEXTURE_UNITS,
};
use crate::pipeline::PipelineError;

/// Triangle corners per quad.
const QUAD_CORNERS: i32 = 6;

pub struct GpuGeometry {
    source: Arc<Geometry>,
    vao: glow::VertexArray,
    buffers: Vec<glow::Buffer>,
    shape: Shape,
    arrays: Arrays,
    /// The colour arrays of a split polygon: (location, own values, provoking values).
    colors: Vec<(u32, glow::Buffer, glow::Buffer)>,
    /// Which of them are bound: the provoking values (after a flat draw) or the own.
    bound_flat: std::cell::Cell<bool>,
    /// Uploaded as drawn, not yet looked at for shared vertices (`shared_vertices`).
    unshared: bool,
}

/// Which attributes a geometry has arrays for; the others take the current values.
#[derive(Clone, Copy, Debug, Default)]
pub struct Arrays {
    pub normals: bool,
    pub colors: bool,
    pub secondary_colors: bool,
    pub fog_coords: bool,
    pub texcoords: [bool; MAX_TEXTURE_UNITS],
}

impl Arrays {
    pub fn of(g: &Geometry) -> Arrays {
        Arrays {
            normals: g.normals.is_some(),
            colors: g.colors.is_some(),
            secondary_colors: g.secondary_colors.is_some(),
            fog_coords: g.fog_coords.is_some(),
            texcoords: std::array::from_fn(|u| g.texcoords[u].is_some()),
        }
    }
}

/// How the uploaded vertices are drawn.
enum Shape {
    /// A core mode over the element buffer, of `index_type` (UNSIGNED_SHORT when every
    /// index fits: llvmpipe's draw module takes 32-bit indices through a slower path that
    /// allocates per draw — measured, `bench --only abi`, buffers mode). TRIANGLES also
    /// hold their `Winding::Reversed` copy, from byte `reversed_at` of the same buffer.
    Elements {
        mode: u32,
        count: i32,
        index_type: u32,
        reversed_at: Option<i32>,
    },
    /// A core mode over the vertices in order (a geometry without indices).
    Arrays { mode: u32, count: i32 },
    /// Triangle corners of split polygons, drawn as TRIANGLES: each uploaded split with its
    /// first corner; every split has `count` corners.
    Corners {
        blocks: Vec<(Diagonal, i32)>,
        count: i32,
    },
}

/// The order an indexed TRIANGLES geometry's corners reach llvmpipe in. llvmpipe bins a
/// triangle that is counter-clockwise in its own pixel rows (top row first) as it is, and
/// swaps the first two corners of a clockwise one first (`triangle_cw`/`triangle_both`
/// rotate (v0, v1, v2) to (v1, v0, v2) under the last-vertex convention). A framebuffer
/// object stores GL's bottom row first, so a triangle counter-clockwise in GL's window
/// space is clockwise there: every face such a pass keeps is swapped, 13 instructions per
/// drawn triangle more than Mesa's own OSMesa, whose window-system buffer is stored top
/// row first (callgrind, `bench --only abi` buffers mode: 36.05 M vs 35.57 M instructions
/// per frame). `Reversed` gives llvmpipe (v1, v0, v2) and core GL the opposite front
/// face: the same faces are front, culled and lit as either, the provoking vertex (the
/// last) is the same, and the triangle llvmpipe bins is the one it would have made
/// itself — the same pixels. A window-system buffer (GL's framebuffer 0, the C library's
/// pbuffer) is stored top row first, as Mesa's OSMesa buffer: its triangles keep their
/// corners (`Emulate::draw_geometry`). Only clipping at the near or far plane (or a user plane)
/// starts its polygon at v1 instead of v0, which may move an interior edge of the clipped
/// polygon's fan by rounding.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Winding {
    AsGiven,
    Reversed,
}

impl Winding {
    /// `Reversed` for a filled pass that culls one face and keeps faces that are
    /// counter-clockwise in GL's window space: the front faces under FrontFace(CCW) and
    /// CullFace(BACK), the back faces under FrontFace(CW) and CullFace(FRONT).
    pub fn for_pass(pass: &PolygonPass, front_face: FrontFace) -> Winding {
        let kept_ccw = matches!(
            (pass.cull, front_face),
            (Some(Face::Back), FrontFace::Ccw) | (Some(Face::Front), FrontFace::Cw)
        );
        if pass.mode == PolygonMode::Fill && kept_ccw {
            Winding::Reversed
        } else {
            Winding::AsGiven
        }
    }

    /// The front face core GL is given: the model's, or its opposite for reversed corners.
    pub fn front_face(self, model: FrontFace) -> FrontFace {
        match (self, model) {
            (Winding::AsGiven, f) => f,
            (Winding::Reversed, FrontFace::Ccw) => FrontFace::Cw,
            (Winding::Reversed, FrontFace::Cw) => FrontFace::Ccw,
        }
    }
}

/// `indices`, then with `reverse` their copy with each whole triangle's first two corners
/// swapped (`Winding::Reversed`; a partial triangle at the end, which GL draws nothing of,
/// kept as it is).
fn indices_and_reversed<T: Copy>(indices: &[T], reverse: bool) -> std::borrow::Cow<'_, [T]> {
    if !reverse {
        return std::borrow::Cow::Borrowed(indices);
    }
    let mut all = Vec::with_capacity(2 * indices.len());
    all.extend_from_slice(indices);
    all.extend_from_slice(indices);
    for t in all[indices.len()..].chunks_exact_mut(3) {
        t.swap(0, 1);
    }
    std::borrow::Cow::Owned(all)
}

/// Uploads [`indices_and_reversed`] into the bound element buffer.
fn upload_indices<T: bytemuck::Pod>(gl: &glow::Context, indices: &[T], reverse: bool) {
    let data = indices_and_reversed(indices, reverse);
    // SAFETY: a plain GL call on the current context; the data is sized by itself.
    unsafe {
        gl.buffer_data_u8_slice(
            glow::ELEMENT_ARRAY_BUFFER,
            bytemuck::cast_slice(&data),
            glow::STATIC_DRAW,
        )
    };
}

/// The core mode of the primitives core GL draws itself; `None` for the split ones.
pub fn core_mode(primitive: Primitive) -> Option<u32> {
    match primitive {
        Primitive::Points => Some(glow::POINTS),
        Primitive::Lines => Some(glow::LINES),
        Primitive::LineStrip => Some(glow::LINE_STRIP),
        Primitive::LineLoop => Some(glow::LINE_LOOP),
        Primitive::Triangles => Some(glow::TRIANGLES),
        Primitive::TriangleStrip => Some(glow::TRIANGLE_STRIP),
        Primitive::TriangleFan => Some(glow::TRIANGLE_FAN),
        Primitive::Quads | Primitive::QuadStrip | Primitive::Polygon => None,
    }
}

/// The splits uploaded for `g`: both diagonals for non-indexed QUADS (the draw chooses),
/// v1–v3 for indexed QUADS, one (diagonal-free) split for QUAD_STRIP and POLYGON.
fn uploaded_splits(g: &Geometry) -> Vec<Diagonal> {
    match (g.primitive, &g.indices) {
        (Primitive::Quads, None) => vec![Diagonal::V0V2, Diagonal::V1V3],
        (Primitive::Quads, Some(_)) => vec![Diagonal::V1V3],
        _ => vec![Diagonal::V0V2],
    }
}

/// The corners of every split uploaded for `g` (vertices `base` in submission order), one
/// split after the other, and each split with its first corner.
fn corners_of(g: &Geometry, base: &[u32]) -> (Vec<Corner>, Vec<(Diagonal, i32)>) {
    let mut corners = Vec::new();
    let mut blocks = Vec::new();
    for diagonal in uploaded_splits(g) {
        blocks.push((diagonal, count(corners.len())));
        let flag = |v: u32| g.edge_flag(v, true);
        corners.extend(split_corners(g.primitive, base, diagonal, flag).unwrap_or_default());
    }
    (corners, blocks)
}

/// What a vertex's shade attribute reads for an array.
#[derive(Clone, Copy)]
enum Shade {
    /// The provoking vertex's values, at a location of their own (positions, normals).
    Attribute(u32),
    /// The own values, or the provoking vertex's in flat draws of split polygons: the
    /// location's buffer is switched (colours, per-vertex materials).
    Switched,
    /// Only the own values (fog coordinates, texture coordinates).
    Own,
}

/// One attribute array of a geometry and the locations that read it.
struct AttributeArray<'a> {
    floats: Floats<'a>,
    location: u32,
    shade: Shade,
}

/// How a geometry's arrays are uploaded (`vertex_layout`).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Layout {
    /// One buffer, vertex after vertex; positions of w = 1 as three floats.
    Interleaved,
    /// One buffer per array, each uploaded as the geometry holds it.
    PerArray,
}

/// The arrays `g` has, each with its location: positions, normals, fog and texture
/// coordinates, colours, then per-vertex materials (glMaterial inside glBegin/glEnd).
fn attribute_arrays(g: &Geometry, layout: Layout) -> Vec<AttributeArray<'_>> {
    let array = |floats, location, shade| AttributeArray {
        floats,
        location,
        shade,
    };
    let positions = match layout {
        Layout::Interleaved => Floats::positions(&g.positions),
        Layout::PerArray => Floats::of4(&g.positions),
    };
    let mut arrays = vec![array(
        positions,
        ATTRIB_POSITION,
        Shade::Attribute(ATTRIB_SHADE_POSITION),
    )];
    if let Some(n) = &g.normals {
        let shade = Shade::Attribute(ATTRIB_SHADE_NORMAL);
        arrays.push(array(Floats::of3(n), ATTRIB_NORMAL, shade));
    }
    if let Some(f) = &g.fog_coords {
        arrays.push(array(Floats::of1(f), ATTRIB_FOG_COORD, Shade::Own));
    }
    for (u, tc) in g.texcoords.iter().enumerate() {
        if let Some(tc) = tc {
            let location = ATTRIB_TEXCOORD0 + u as u32;
            arrays.push(array(Floats::of4(tc), location, Shade::Own));
        }
    }
    for (values, location) in [
        (&g.colors, ATTRIB_COLOR),
        (&g.secondary_colors, ATTRIB_SECONDARY),
    ] {
        if let Some(c) = values {
            arrays.push(array(Floats::of4(c), location, Shade::Switched));
        }
    }
    let mask = g.materials.as_ref().map_or(0, |m| m.mask());
    for (slot, values) in g.materials.iter().flat_map(|m| m.present()) {
        let location = material_location(mask, slot.bit());
        arrays.push(array(Floats::of4(values), location, Shade::Switched));
    }
    arrays
}

impl GpuGeometry {
    /// Uploads `g`: its vertices as drawn, or — given `shared`, for a non-indexed draw of
    /// a type core GL draws — each distinct vertex once, drawn through `shared`'s indices.
    pub fn upload(
        gl: &glow::Context,
        g: &Arc<Geometry>,
        shared: Option<Shared>,
    ) -> Result<GpuGeometry, PipelineError> {
        let split = Outline::of(g) == Outline::Corners;
        let mode = if split { None } else { core_mode(g.primitive) };
        let (corners, blocks) = if split {
            let base: Vec<u32> = g
                .indices
                .clone()
                .unwrap_or_else(|| (0..g.positions.len() as u32).collect());
            corners_of(g, &base)
        } else {
            (Vec::new(), Vec::new())
        };
        let order: Vec<u32> = corners.iter().map(|c| c.vertex).collect();
        let provoking: Vec<u32> = corners.iter().map(|c| c.provoking).collect();
        // A non-indexed draw of a core type that repeats vertices is drawn indexed, each
        // distinct vertex uploaded once (`shared_vertices`).
        let shared = shared.filter(|_| mode.is_some() && g.indices.is_none());
        let unshared = shared.is_none() && mode.is_some() && g.indices.is_none();
        // Interleaved where the upload is kept for more draws (`vertex_layout`): not a
        // split polygon's (its colours switch buffers) nor one that may be drawn once.
        let layout = match !split && !unshared {
            true => Layout::Interleaved,
            false => Layout::PerArray,
        };
        let (order, provoking) = match &shared {
            _ if split => (Some(order.as_slice()), Some(provoking.as_slice())),
            Some(s) => (Some(s.vertices.as_slice()), None),
            None => (None, None),
        };
        let indices = g.indices.as_ref().or(shared.as_ref().map(|s| &s.indices));
        let mut buffers = Vec::new();
        // SAFETY: plain GL calls on the current context; every buffer is sized by its data.
        unsafe {
            let vao = gl.create_vertex_array().map_err(PipelineError::Object)?;
            gl.bind_vertex_array(Some(vao));
            let mut buffer = |data: &[u8]| -> Result<glow::Buffer, PipelineError> {
                let b = gl.create_buffer().map_err(PipelineError::Object)?;
                gl.bind_buffer(glow::ARRAY_BUFFER, Some(b));
                gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, data, glow::STATIC_DRAW);
                buffers.push(b);
                Ok(b)
            };
            let point = |b: glow::Buffer, location: u32, size: usize, stride: i32, at: i32| {
                gl.bind_buffer(glow::ARRAY_BUFFER, Some(b));
                gl.vertex_attrib_pointer_f32(location, size as i32, glow::FLOAT, false, stride, at);
                gl.enable_vertex_attrib_array(location);
            };
            let arrays = attribute_arrays(g, layout);
            let mut colors = Vec::new();
            if layout == Layout::Interleaved {
                // One buffer (`vertex_layout`); the shade attributes of the types core GL
                // draws read the same values (core GL's provoking vertex is GL 1.x's).
                let floats: Vec<&Floats> = arrays.iter().map(|a| &a.floats).collect();
                let all = vertex_layout::interleave(&floats, order, g.positions.len());
                let b = buffer(bytemuck::cast_slice(&all.floats))?;
                for (a, &at) in arrays.iter().zip(&all.offsets) {
                    point(b, a.location, a.floats.size, all.stride, at);
                    if let Shade::Attribute(shade) = a.shade {
                        point(b, shade, a.floats.size, all.stride, at);
                    }
                }
            } else {
                // One buffer per array. Own values per corner; shade values from the
                // provoking vertex (split polygons) or the same buffer; a split polygon's
                // colours and materials keep their provoking values for flat draws.
                for a in &arrays {
                    let size = a.floats.size;
                    let own = buffer(bytemuck::cast_slice(&a.floats.values(order)))?;
                    point(own, a.location, size, 0, 0);
                    match (a.shade, provoking) {
                        (Shade::Attribute(shade), Some(p)) => point(
                            buffer(bytemuck::cast_slice(&a.floats.values(Some(p))))?,
                            shade,
                            size,
                            0,
                            0,
                        ),
                        (Shade::Attribute(shade), None) => point(own, shade, size, 0, 0),
                        (Shade::Switched, Some(p)) => colors.push((
                            a.location,
                            own,
                            buffer(bytemuck::cast_slice(&a.floats.values(Some(p))))?,
                        )),
                        (Shade::Switched | Shade::Own, _) => {}
                    }
                }
            }
            if split {
                let edges: Vec<f32> = corners.iter().flat_map(|c| c.edge).collect();
                let b = buffer(bytemuck::cast_slice(&edges))?;
                point(b, ATTRIB_EDGE, 4, 0, 0);
            }
            let shape = match (mode, indices) {
                (Some(mode), Some(indices)) => {
                    let ebo = gl.create_buffer().map_err(PipelineError::Object)?;
                    gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, Some(ebo));
                    let short = crate::ff::max_index(indices) <= u32::from(u16::MAX);
                    let (index_type, size) = match short {
                        true => (glow::UNSIGNED_SHORT, 2),
                        false => (glow::UNSIGNED_INT, 4),
                    };
                    let count = count(indices.len());
                    // TRIANGLES: the indices, then their reversed copy (`Winding`), from
                    // byte count × size (when GL's offset can name it).
                    let reversed_at = (mode == glow::TRIANGLES && count >= 3)
                        .then(|| count.checked_mul(size))
                        .flatten();
                    let reverse = reversed_at.is_some();
                    if short {
                        let narrow: Vec<u16> = indices.iter().map(|&i| i as u16).collect();
                        upload_indices(gl, &narrow, reverse);
                    } else {
                        upload_indices(gl, indices, reverse);
                    }
                    buffers.push(ebo);
                    Shape::Elements {
                        mode,
                        count,
                        index_type,
                        reversed_at,
                    }
                }
                (Some(mode), None) => Shape::Arrays {
                    mode,
                    count: count(g.positions.len()),
                },
                (None, _) => Shape::Corners {
                    count: count(corners.len() / blocks.len().max(1)),
                    blocks,
                },
            };
            gl.bind_vertex_array(None);
            Ok(GpuGeometry {
                source: g.clone(),
                vao,
                buffers,
                shape,
                arrays: Arrays::of(g),
                colors,
                bound_flat: std::cell::Cell::new(false),
                unshared,
            })
        }
    }

    /// The winding a pass draws this geometry with: `Winding::for_pass` where the geometry
    /// has reversed corners (indexed TRIANGLES), as given otherwise.
    pub fn winding(&self, pass: &PolygonPass, state: &FixedState) -> Winding {
        match self.shape {
            Shape::Elements {
                reversed_at: Some(_),
                ..
            } => Winding::for_pass(pass, state.front_face),
            _ => Winding::AsGiven,
        }
    }

    /// Draws with the current values standing in for the missing arrays; non-indexed QUADS
    /// take the diagonal Mesa would take under the current matrices (`assembly`). Indexed
    /// TRIANGLES take the corner order `winding` (the one core GL's front face was set for).
    pub fn draw(
        &self,
        gl: &glow::Context,
        sent: &mut SentAttribs,
        state: &FixedState,
        winding: Winding,
    ) {
        // SAFETY: plain GL calls on the current context; every range lies in the uploaded
        // buffers (counts come from the upload).
        unsafe {
            gl.bind_vertex_array(Some(self.vao));
            let flat = state.shade_model == ShadeModel::Flat;
            if !self.colors.is_empty() && self.bound_flat.get() != flat {
                for &(location, own, provoking) in &self.colors {
                    let b = if flat { provoking } else { own };
                    gl.bind_buffer(glow::ARRAY_BUFFER, Some(b));
                    gl.vertex_attrib_pointer_f32(location, 4, glow::FLOAT, false, 0, 0);
                }
                self.bound_flat.set(flat);
            }
            set_current_values(gl, sent, state, self.arrays);
            match &self.shape {
                Shape::Elements {
                    mode,
                    count,
                    index_type,
                    reversed_at,
                } if *count > 0 => {
                    let offset = match (winding, reversed_at) {
                        (Winding::Reversed, Some(at)) => *at,
                        _ => 0,
                    };
                    gl.draw_elements(*mode, *count, *index_type, offset);
                }
                Shape::Arrays { mode, count } if *count > 0 => {
                    gl.draw_arrays(*mode, 0, *count);
                }
                Shape::Elements { .. } | Shape::Arrays { .. } => {}
                Shape::Corners { blocks, count } => {
                    for (first, n) in self.corner_ranges(blocks, *count, state) {
                        if n > 0 {
                            gl.draw_arrays(glow::TRIANGLES, first, n);
                        }
                    }
                }
            }
        }
    }

    /// The (first corner, corner count) ranges one draw sends.
    fn corner_ranges(
        &self,
        blocks: &[(Diagonal, i32)],
        count: i32,
        state: &FixedState,
    ) -> Vec<(i32, i32)> {
        if self.source.primitive != Primitive::Quads {
            return blocks
                .first()
                .map(|&(_, f)| (f, count))
                .into_iter()
                .collect();
        }
        let clip = assembly::DrawRoute::of(state);
        assembly::quad_diagonals(&self.source, &clip, state.shade_model)
            .into_iter()
            .filter_map(|(quads, diagonal)| {
                let &(_, first) = blocks.iter().find(|(d, _)| *d == diagonal)?;
                let start = i32::try_from(quads.start).ok()?;
                let len = i32::try_from(quads.len()).ok()?;
                let offset = QUAD_CORNERS.checked_mul(start)?.checked_add(first)?;
                Some((offset, QUAD_CORNERS.checked_mul(len)?))
            })
            .collect()
    }

    pub fn delete(self, gl: &glow::Context) {
        // SAFETY: the objects were created on this context and are deleted once.
        unsafe {
            gl.delete_vertex_array(self.vao);
            for b in self.buffers {
                gl.delete_buffer(b);
            }
        }
    }
}

/// The current values standing in for the arrays a draw lacks (constant attributes of the
/// bound vertex array object).
pub fn set_current_values(
    gl: &glow::Context,
    sent: &mut SentAttribs,
    state: &FixedState,
    arrays: Arrays,
) {
    let cur = &state.current;
    if !arrays.normals {
        let n = cur.normal;
        for location in [ATTRIB_NORMAL, ATTRIB_SHADE_NORMAL] {
            sent.set(gl, location, [n.x, n.y, n.z, 0.0]);
        }
    }
    // A NaN in the current colour drawn unlit becomes 0, where the program's clamp sends a
    // per-vertex NaN to 1 (Mesa's native path, measured: `shadergen::vertex::SATURATE`).
    // Lit, the current colour feeds COLOR_MATERIAL, whose NaN the lighting clamps to 1.
    if !arrays.colors {
        let color = if state.lighting {
            cur.color
        } else {
            nan_to_zero(cur.color)
        };
        sent.set(gl, ATTRIB_COLOR, color.to_array());
    }
    if !arrays.secondary_colors {
        sent.set(
            gl,
            ATTRIB_SECONDARY,
            nan_to_zero(cur.secondary_color).to_array(),
        );
    }
    if !arrays.fog_coords {
        sent.set(gl, ATTRIB_FOG_COORD, [cur.fog_coord, 0.0, 0.0, 1.0]);
    }
    for (u, (has, t)) in arrays.texcoords.iter().zip(&cur.texcoords).enumerate() {
        if !has {
            sent.set(gl, ATTRIB_TEXCOORD0 + u as u32, t.to_array());
        }
    }
}

/// `v` with each NaN component 0.
fn nan_to_zero(v: Vec4) -> Vec4 {
    Vec4::select(v.is_nan_mask(), Vec4::ZERO, v)
}

/// The generic attribute values last sent with glVertexAttrib4f — context state in core
/// GL, not a vertex array's — so that a draw sends only the ones that changed (each sent
/// value costs the driver a revalidation of the vertex state). Compared bit for bit, so a
/// −0 after a +0 is sent.
pub struct SentAttribs([Option<[u32; 4]>; ATTRIB_SLOTS]);

/// The attribute locations the generated programs use (`shadergen::ATTRIB_*`).
const ATTRIB_SLOTS: usize = ATTRIB_COUNT as usize;

impl Default for SentAttribs {
    fn default() -> Self {
        SentAttribs([None; ATTRIB_SLOTS])
    }
}

impl SentAttribs {
    fn set(&mut self, gl: &glow::Context, location: u32, v: [f32; 4]) {
        let bits = v.map(f32::to_bits);
        let Some(slot) = self.0.get_mut(location as usize) else {
            return;
        };
        if *slot != Some(bits) {
            // SAFETY: a constant attribute value on the current context.
            unsafe { gl.vertex_attrib_4_f32(location, v[0], v[1], v[2], v[3]) };
            *slot = Some(bits);
        }
    }
}

/// A count as GLsizei; beyond i32 it is clamped (GL could not draw it anyway).
fn count(n: usize) -> i32 {
    i32::try_from(n).unwrap_or(i32::MAX)
}

/// Uploaded geometries by the address of their `Arc` (kept alive by the entry, so the
/// address cannot be reused while cached).
#[derive(Default)]
pub struct GeometryCache {
    entries: HashMap<usize, GpuGeometry>,
    /// Entries after the last sweep; the next sweep comes when the cache has doubled.
    live_after_sweep: usize,
    /// Geometries uploaded since the pipeline began.
    uploads: u64,
}

impl GeometryCache {
    /// The uploaded form of `g`, uploaded on its first draw. A geometry drawn again (a
    /// scene's mesh, frame after frame) is uploaded once — and at its second draw once
    /// more with its repeated vertices shared, if it has enough (`shared_vertices`: most
    /// geometries are drawn once, and sharing costs a hash per vertex); one that
    /// only the cache still holds can never be drawn again (an immediate-mode draw of the
    /// C library, whose geometry is new each time) and is deleted when the cache has
    /// doubled since the last sweep, so memory stays proportional to the geometry alive.
    pub fn get(
        &mut self,
        gl: &glow::Context,
        g: &Arc<Geometry>,
    ) -> Result<&GpuGeometry, PipelineError> {
        if self.entries.len() >= 2 * self.live_after_sweep + 64 {
            self.sweep(gl);
        }
        let key = Arc::as_ptr(g) as usize;
        match self.entries.entry(key) {
            std::collections::hash_map::Entry::Occupied(mut e) => {
                if e.get().unshared {
                    e.get_mut().unshared = false;
                    if let Some(shared) = shared_vertices::of(g) {
                        let again = GpuGeometry::upload(gl, g, Some(shared))?;
                        std::mem::replace(e.get_mut(), again).delete(gl);
                    }
                }
                Ok(e.into_mut())
            }
            std::collections::hash_map::Entry::Vacant(e) => {
                self.uploads += 1;
                Ok(e.insert(GpuGeometry::upload(gl, g, None)?))
            }
        }
    }

    /// Deletes the entries whose geometry only the cache holds.
    fn sweep(&mut self, gl: &glow::Context) {
        let dead: Vec<usize> = self
            .entries
            .iter()
            .filter(|(_, e)| Arc::strong_count(&e.source) == 1)
            .map(|(k, _)| *k)
            .collect();
        for k in dead {
            if let Some(e) = self.entries.remove(&k) {
                e.delete(gl);
            }
        }
        self.live_after_sweep = self.entries.len();
    }

    /// How many geometries were uploaded since the pipeline began.
    pub fn uploads(&self) -> u64 {
        self.uploads
    }

    /// How many geometries are uploaded.
    pub fn uploaded(&self) -> usize {
        self.entries.len()
    }

    pub fn release(&mut self, gl: &glow::Context) {
        for (_, g) in self.entries.drain() {
            g.delete(gl);
        }
        self.live_after_sweep = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::{OffsetEnables, PolygonModes};
    use crate::pipeline::emulate::polygon;

    #[test]
    fn reversed_triangles_swap_their_first_two_corners() {
        let given = [0u16, 1, 2, 3, 4, 5, 6, 7];
        assert_eq!(
            *indices_and_reversed(&given, true),
            [0, 1, 2, 3, 4, 5, 6, 7, 1, 0, 2, 4, 3, 5, 6, 7]
        );
        assert_eq!(*indices_and_reversed(&given, false), given);
        assert!(indices_and_reversed::<u32>(&[], true).is_empty());
    }

    /// Reversed exactly where a filled pass keeps only faces counter-clockwise in GL's
    /// window space; core GL is then given the opposite front face.
    #[test]
    fn a_pass_reverses_the_corners_of_kept_counter_clockwise_faces() {
        let fill = |cull| {
            polygon::passes(
                PolygonModes {
                    front: PolygonMode::Fill,
                    back: PolygonMode::Fill,
                },
                cull,
                OffsetEnables::default(),
                Primitive::Triangles,
                Outline::Core,
            )[0]
        };
        let cases = [
            (Some(Face::Back), FrontFace::Ccw, Winding::Reversed),
            (Some(Face::Front), FrontFace::Cw, Winding::Reversed),
            (Some(Face::Front), FrontFace::Ccw, Winding::AsGiven),
            (Some(Face::Back), FrontFace::Cw, Winding::AsGiven),
            (Some(Face::FrontAndBack), FrontFace::Ccw, Winding::AsGiven),
            (None, FrontFace::Ccw, Winding::AsGiven),
        ];
        for (cull, front, expected) in cases {
            assert_eq!(
                Winding::for_pass(&fill(cull), front),
                expected,
                "{cull:?} {front:?}"
            );
        }
        let mut line = fill(Some(Face::Back));
        line.mode = PolygonMode::Line;
        assert_eq!(Winding::for_pass(&line, FrontFace::Ccw), Winding::AsGiven);
        assert_eq!(Winding::Reversed.front_face(FrontFace::Ccw), FrontFace::Cw);
        assert_eq!(Winding::Reversed.front_face(FrontFace::Cw), FrontFace::Ccw);
        assert_eq!(Winding::AsGiven.front_face(FrontFace::Cw), FrontFace::Cw);
    }

    #[test]
    fn core_types_are_drawn_as_they_are_and_the_legacy_ones_split() {
        assert_eq!(core_mode(Primitive::LineLoop), Some(glow::LINE_LOOP));
        assert_eq!(core_mode(Primitive::TriangleFan), Some(glow::TRIANGLE_FAN));
        for p in [Primitive::Quads, Primitive::QuadStrip, Primitive::Polygon] {
            assert_eq!(core_mode(p), None);
        }
        let mut g = Geometry::new(Primitive::Quads, Vec::new());
        assert_eq!(uploaded_splits(&g), [Diagonal::V0V2, Diagonal::V1V3]);
        g.indices = Some(Vec::new());
        assert_eq!(uploaded_splits(&g), [Diagonal::V1V3]);
        g.primitive = Primitive::QuadStrip;
        assert_eq!(uploaded_splits(&g).len(), 1);
    }
}
