//! Geometry on the GPU: one vertex array object per `Geometry` (kept while the `Arc` lives,
//! so meshes are uploaded once per context), with the primitives core GL lacks rewritten
//! as triangles: QUADS split along v0–v2 as Mesa does ((0,1,2), (0,2,3)), QUAD_STRIP as
//! pairs of triangles, POLYGON as a fan from v0 (GL polygons are convex). Those three are
//! uploaded as unshared triangle corners carrying the edge attribute of `polygon`, so LINE
//! and POINT modes can drop what the split added.

use std::collections::HashMap;
use std::sync::Arc;

use glow::HasContext;

use super::polygon::split_corners;
use super::shadergen::{
    ATTRIB_COLOR, ATTRIB_EDGE, ATTRIB_NORMAL, ATTRIB_POSITION, ATTRIB_TEXCOORD0,
};
use crate::ff::{FixedState, Geometry, Primitive, MAX_TEXTURE_UNITS};
use crate::pipeline::PipelineError;

pub struct GpuGeometry {
    _source: Arc<Geometry>,
    vao: glow::VertexArray,
    buffers: Vec<glow::Buffer>,
    mode: u32,
    count: i32,
    has_normals: bool,
    has_colors: bool,
    has_texcoords: [bool; MAX_TEXTURE_UNITS],
}

/// Element indices for `primitive` in core GL terms, and the core mode.
pub fn core_indices(primitive: Primitive, indices: &[u32]) -> (u32, Vec<u32>) {
    let n = indices.len();
    match primitive {
        Primitive::Points => (glow::POINTS, indices.to_vec()),
        Primitive::Lines => (glow::LINES, indices.to_vec()),
        Primitive::LineStrip => (glow::LINE_STRIP, indices.to_vec()),
        Primitive::LineLoop => (glow::LINE_LOOP, indices.to_vec()),
        Primitive::Triangles => (glow::TRIANGLES, indices.to_vec()),
        Primitive::TriangleStrip => (glow::TRIANGLE_STRIP, indices.to_vec()),
        Primitive::TriangleFan => (glow::TRIANGLE_FAN, indices.to_vec()),
        Primitive::Polygon => (glow::TRIANGLE_FAN, indices.to_vec()),
        Primitive::Quads => {
            let tris = indices
                .chunks_exact(4)
                .flat_map(|q| [q[0], q[1], q[2], q[0], q[2], q[3]])
                .collect();
            (glow::TRIANGLES, tris)
        }
        Primitive::QuadStrip => {
            // Quad i has vertices 2i, 2i+1, 2i+3, 2i+2 in polygon order (GL 1.5 §2.6.1).
            let tris = (0..n.saturating_sub(2) / 2)
                .flat_map(|i| {
                    let v = |k: usize| indices[2 * i + k];
                    [v(0), v(1), v(3), v(0), v(3), v(2)]
                })
                .collect();
            (glow::TRIANGLES, tris)
        }
    }
}

/// The arrays' bytes in `order` (the corners of split polygons) or as they are.
fn bytes_of<T: Copy>(values: &[T], order: Option<&[u32]>, to: impl Fn(&T) -> Vec<f32>) -> Vec<u8> {
    let pick = |i: &u32| values.get(*i as usize).map(&to).unwrap_or_default();
    match order {
        Some(order) => order
            .iter()
            .flat_map(pick)
            .flat_map(f32::to_ne_bytes)
            .collect(),
        None => values
            .iter()
            .flat_map(to)
            .flat_map(f32::to_ne_bytes)
            .collect(),
    }
}

impl GpuGeometry {
    pub fn upload(gl: &glow::Context, g: &Arc<Geometry>) -> Result<GpuGeometry, PipelineError> {
        let base: Vec<u32> = g
            .indices
            .clone()
            .unwrap_or_else(|| (0..g.positions.len() as u32).collect());
        let corners = split_corners(g.primitive, &base);
        let order: Option<Vec<u32>> = corners
            .as_ref()
            .map(|c| c.iter().map(|(v, _)| *v).collect());
        let order = order.as_deref();
        let (mode, indices) = match order {
            Some(o) => (glow::TRIANGLES, (0..o.len() as u32).collect()),
            None => core_indices(g.primitive, &base),
        };
        let mut buffers = Vec::new();
        unsafe {
            let vao = gl.create_vertex_array().map_err(PipelineError::Object)?;
            gl.bind_vertex_array(Some(vao));
            let mut array =
                |location: u32, size: i32, data: Vec<u8>| -> Result<(), PipelineError> {
                    let b = gl.create_buffer().map_err(PipelineError::Object)?;
                    gl.bind_buffer(glow::ARRAY_BUFFER, Some(b));
                    gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &data, glow::STATIC_DRAW);
                    gl.vertex_attrib_pointer_f32(location, size, glow::FLOAT, false, 0, 0);
                    gl.enable_vertex_attrib_array(location);
                    buffers.push(b);
                    Ok(())
                };
            array(
                ATTRIB_POSITION,
                4,
                bytes_of(&g.positions, order, |v| v.to_array().to_vec()),
            )?;
            if let Some(n) = &g.normals {
                array(
                    ATTRIB_NORMAL,
                    3,
                    bytes_of(n, order, |v| v.to_array().to_vec()),
                )?;
            }
            if let Some(c) = &g.colors {
                array(
                    ATTRIB_COLOR,
                    4,
                    bytes_of(c, order, |v| v.to_array().to_vec()),
                )?;
            }
            let mut has_texcoords = [false; MAX_TEXTURE_UNITS];
            for (u, tc) in g.texcoords.iter().enumerate() {
                if let Some(tc) = tc {
                    array(
                        ATTRIB_TEXCOORD0 + u as u32,
                        4,
                        bytes_of(tc, order, |v| v.to_array().to_vec()),
                    )?;
                    has_texcoords[u] = true;
                }
            }
            if let Some(c) = &corners {
                array(ATTRIB_EDGE, 4, bytes_of(c, None, |(_, e)| e.to_vec()))?;
            }
            let ebo = gl.create_buffer().map_err(PipelineError::Object)?;
            gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, Some(ebo));
            let index_bytes: Vec<u8> = indices.iter().flat_map(|i| i.to_ne_bytes()).collect();
            gl.buffer_data_u8_slice(glow::ELEMENT_ARRAY_BUFFER, &index_bytes, glow::STATIC_DRAW);
            buffers.push(ebo);
            gl.bind_vertex_array(None);
            Ok(GpuGeometry {
                _source: g.clone(),
                vao,
                buffers,
                mode,
                count: indices.len() as i32,
                has_normals: g.normals.is_some(),
                has_colors: g.colors.is_some(),
                has_texcoords,
            })
        }
    }

    /// Draws with the current values standing in for the missing arrays.
    pub fn draw(&self, gl: &glow::Context, state: &FixedState) {
        unsafe {
            gl.bind_vertex_array(Some(self.vao));
            let cur = &state.current;
            if !self.has_normals {
                gl.vertex_attrib_4_f32(
                    ATTRIB_NORMAL,
                    cur.normal.x,
                    cur.normal.y,
                    cur.normal.z,
                    0.0,
                );
            }
            if !self.has_colors {
                let c = cur.color;
                gl.vertex_attrib_4_f32(ATTRIB_COLOR, c.x, c.y, c.z, c.w);
            }
            for u in 0..MAX_TEXTURE_UNITS {
                if !self.has_texcoords[u] {
                    let t = cur.texcoords[u];
                    gl.vertex_attrib_4_f32(ATTRIB_TEXCOORD0 + u as u32, t.x, t.y, t.z, t.w);
                }
            }
            if self.count > 0 {
                gl.draw_elements(self.mode, self.count, glow::UNSIGNED_INT, 0);
            }
            gl.bind_vertex_array(None);
        }
    }

    pub fn delete(self, gl: &glow::Context) {
        unsafe {
            gl.delete_vertex_array(self.vao);
            for b in self.buffers {
                gl.delete_buffer(b);
            }
        }
    }
}

/// Uploaded geometries by the address of their `Arc` (kept alive by the entry, so the
/// address cannot be reused while cached).
#[derive(Default)]
pub struct GeometryCache {
    entries: HashMap<usize, GpuGeometry>,
}

impl GeometryCache {
    pub fn get(
        &mut self,
        gl: &glow::Context,
        g: &Arc<Geometry>,
    ) -> Result<&GpuGeometry, PipelineError> {
        let key = Arc::as_ptr(g) as usize;
        match self.entries.entry(key) {
            std::collections::hash_map::Entry::Occupied(e) => Ok(e.into_mut()),
            std::collections::hash_map::Entry::Vacant(e) => {
                Ok(e.insert(GpuGeometry::upload(gl, g)?))
            }
        }
    }

    pub fn release(&mut self, gl: &glow::Context) {
        for (_, g) in self.entries.drain() {
            g.delete(gl);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn legacy_primitives_become_triangles() {
        let quad = core_indices(Primitive::Quads, &[0, 1, 2, 3]);
        assert_eq!(quad, (glow::TRIANGLES, vec![0, 1, 2, 0, 2, 3]));
        let strip = core_indices(Primitive::QuadStrip, &[0, 1, 2, 3, 4, 5]);
        assert_eq!(strip.1, vec![0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4]);
        assert_eq!(
            core_indices(Primitive::Polygon, &[0, 1, 2, 3]).0,
            glow::TRIANGLE_FAN
        );
        // A trailing partial quad is dropped, as glBegin(GL_QUADS) does.
        assert_eq!(core_indices(Primitive::Quads, &[0, 1, 2, 3, 4]).1.len(), 6);
    }
}
