//! Geometry for `Command::Draw`: vertex arrays as glBegin/glEnd or glDrawArrays/Elements
//! would deliver them. Other layers (meshes) convert into this; it depends on nothing else.

use std::sync::Arc;

use glam::{Vec3, Vec4};

use super::error::{GlError, GlResult};
use super::state::MAX_TEXTURE_UNITS;

/// glBegin modes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Primitive {
    Points,
    Lines,
    LineStrip,
    /// A strip closed by a segment from the last vertex back to the first.
    LineLoop,
    #[default]
    Triangles,
    TriangleStrip,
    TriangleFan,
    Quads,
    QuadStrip,
    Polygon,
}

/// One draw's vertices. A missing attribute array means "the current value" (glColor,
/// glNormal, glMultiTexCoord issued before the draw).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Geometry {
    pub primitive: Primitive,
    /// Object coordinates (x, y, z, w).
    pub positions: Vec<Vec4>,
    pub normals: Option<Vec<Vec3>>,
    pub colors: Option<Vec<Vec4>>,
    /// (s, t, r, q) per unit.
    pub texcoords: [Option<Vec<Vec4>>; MAX_TEXTURE_UNITS],
    /// Per-vertex edge flags (glEdgeFlag inside glBegin/glEnd, EDGE_FLAG_ARRAY): `false`
    /// marks the edge starting at the vertex as no boundary edge (GL 1.5 §2.6.2); only
    /// TRIANGLES, QUADS and POLYGON in LINE or POINT polygon mode read them.
    pub edge_flags: Option<Vec<bool>>,
    /// Secondary colours (GL 1.4 §2.7): added to the primary after texturing under
    /// COLOR_SUM with lighting off.
    pub secondary_colors: Option<Vec<Vec4>>,
    /// Fog coordinates (GL 1.4 §2.7): the fog distance under FOG_COORD_SRC = FOG_COORD.
    pub fog_coords: Option<Vec<f32>>,
    /// Indices into the arrays; `None` draws them in order.
    pub indices: Option<Vec<u32>>,
    /// Materials per vertex: glMaterial called inside glBegin/glEnd (GL 1.5 §2.14.3).
    pub materials: Option<Box<VertexMaterials>>,
}

/// The last geometry a draw found valid, held so that a draw of the same `Arc` again is
/// not checked again: a repeated draw (`ff::repeated_draws`) would otherwise scan its
/// indices for the largest at every call. Holding a clone keeps the geometry shared, and a
/// shared `Arc<Geometry>` cannot change. A memo, not GL state: it compares equal to any.
#[derive(Debug, Clone, Default)]
pub struct ValidatedDraw(Option<Arc<Geometry>>);

impl PartialEq for ValidatedDraw {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl ValidatedDraw {
    /// [`Geometry::validate`], skipped for the geometry validated last.
    pub fn validate(&mut self, g: &Arc<Geometry>) -> GlResult {
        if self.0.as_ref().is_some_and(|v| Arc::ptr_eq(v, g)) {
            return Ok(());
        }
        g.validate()?;
        self.0 = Some(g.clone());
        Ok(())
    }
}

/// A material value a vertex can carry: a colour of a face, or a face's shininess.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MaterialSlot {
    Color(MaterialSide, MaterialColor),
    Shininess(MaterialSide),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MaterialSide {
    Front,
    Back,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MaterialColor {
    Ambient,
    Diffuse,
    Specular,
    Emission,
}

impl MaterialSlot {
    /// Every slot, in bit order ([`MaterialSlot::bit`]).
    pub const ALL: [MaterialSlot; 10] = {
        use MaterialColor::*;
        use MaterialSide::*;
        [
            MaterialSlot::Color(Front, Ambient),
            MaterialSlot::Color(Front, Diffuse),
            MaterialSlot::Color(Front, Specular),
            MaterialSlot::Color(Front, Emission),
            MaterialSlot::Color(Back, Ambient),
            MaterialSlot::Color(Back, Diffuse),
            MaterialSlot::Color(Back, Specular),
            MaterialSlot::Color(Back, Emission),
            MaterialSlot::Shininess(Front),
            MaterialSlot::Shininess(Back),
        ]
    };

    /// The slot's position in [`MaterialSlot::ALL`]: its bit in a mask of slots, and its
    /// attribute's offset in the emulated program.
    pub fn bit(self) -> usize {
        let side = |s: MaterialSide| match s {
            MaterialSide::Front => 0,
            MaterialSide::Back => 1,
        };
        match self {
            MaterialSlot::Color(s, c) => 4 * side(s) + c as usize,
            MaterialSlot::Shininess(s) => 8 + side(s),
        }
    }
}

/// The per-vertex materials of a draw, one array per slot that a glMaterial inside the
/// pair set (each vertex holds the value current when it was specified); the other slots
/// take the material state. Shininess arrays hold (s, 0, 0, 1).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct VertexMaterials {
    pub arrays: [Option<Vec<Vec4>>; 10],
}

impl VertexMaterials {
    /// The slots with an array, as a mask of [`MaterialSlot::bit`]s.
    pub fn mask(&self) -> u16 {
        self.arrays
            .iter()
            .enumerate()
            .filter(|(_, a)| a.is_some())
            .fold(0, |m, (i, _)| m | 1 << i)
    }

    /// The slots with an array and their values.
    pub fn present(&self) -> impl Iterator<Item = (MaterialSlot, &[Vec4])> + '_ {
        MaterialSlot::ALL
            .into_iter()
            .zip(&self.arrays)
            .filter_map(|(slot, a)| Some((slot, a.as_deref()?)))
    }

    /// The values that change at the k-th vertex of `order` (vertex indices in drawing
    /// order): every slot at the first, then those that differ from the vertex before —
    /// the glMaterial calls a pair drawing `order` makes before that vertex.
    pub fn changes_at<'a>(
        &'a self,
        order: &'a [u32],
        k: usize,
    ) -> impl Iterator<Item = (MaterialSlot, Vec4)> + 'a {
        let at =
            |values: &[Vec4], k: usize| order.get(k).and_then(|&i| values.get(i as usize)).copied();
        self.present().filter_map(move |(slot, values)| {
            let v = at(values, k)?;
            let before = k.checked_sub(1).and_then(|p| at(values, p));
            (before != Some(v)).then_some((slot, v))
        })
    }
}

impl Geometry {
    /// A non-indexed geometry with positions only.
    pub fn new(primitive: Primitive, positions: Vec<Vec4>) -> Self {
        Self {
            primitive,
            positions,
            ..Self::default()
        }
    }

    /// Vertices the primitive assembly sees (indices if present, else positions).
    pub fn vertex_count(&self) -> usize {
        self.indices.as_ref().map_or(self.positions.len(), Vec::len)
    }

    /// Attribute arrays must match the positions in length and indices must be in range
    /// (INVALID_VALUE: GL cannot check client arrays, we can).
    pub fn validate(&self) -> GlResult {
        let n = self.positions.len();
        let same = |len: Option<usize>| len.is_none_or(|l| l == n);
        let ok = same(self.normals.as_ref().map(Vec::len))
            && same(self.colors.as_ref().map(Vec::len))
            && same(self.edge_flags.as_ref().map(Vec::len))
            && same(self.secondary_colors.as_ref().map(Vec::len))
            && same(self.fog_coords.as_ref().map(Vec::len))
            && self
                .texcoords
                .iter()
                .all(|t| same(t.as_ref().map(Vec::len)))
            && self
                .materials
                .as_ref()
                .is_none_or(|m| m.arrays.iter().all(|a| same(a.as_ref().map(Vec::len))));
        if !ok {
            return Err(GlError::invalid_value(
                "attribute arrays differ in length from positions",
            ));
        }
        if let Some(idx) = &self.indices {
            if !idx.is_empty() && max_index(idx) as usize >= n {
                return Err(GlError::invalid_value("index beyond the vertex arrays"));
            }
        }
        Ok(())
    }

    /// Whether edge flags hide edges of this primitive: every polygon type, as on Mesa.
    /// GL 1.5 §2.6.2 names independent triangles, quads and polygons only (strips and fans
    /// taking every edge as a boundary); Mesa's draw module flags each edge of the
    /// triangles it cuts strips and fans into by the edge's first vertex, and each edge of
    /// a quad strip's quad as a quad's (measured, `tests/c/edge_strips.c`).
    pub fn reads_edge_flags(&self) -> bool {
        matches!(
            self.primitive,
            Primitive::Triangles
                | Primitive::TriangleStrip
                | Primitive::TriangleFan
                | Primitive::Quads
                | Primitive::QuadStrip
                | Primitive::Polygon
        )
    }

    /// The edge flag of vertex `i` (an index into the arrays): its array's value, or
    /// `current` (the current edge flag) when the geometry has no array.
    pub fn edge_flag(&self, i: u32, current: bool) -> bool {
        match &self.edge_flags {
            Some(f) => f.get(i as usize).copied().unwrap_or(true),
            None => current,
        }
    }

    /// The last value of an attribute array, if the array exists and is not empty: what
    /// becomes current after the draw.
    pub fn last<T: Copy>(array: &Option<Vec<T>>) -> Option<T> {
        array.as_ref().and_then(|a| a.last().copied())
    }
}

/// The largest of `indices` (0 for none). It runs at every draw (`Geometry::validate`), so
/// it takes AVX2 where the processor has it: x86-64's baseline SSE2 has no unsigned 32-bit
/// maximum, and the plain loop compares one index at a time.
pub fn max_index(indices: &[u32]) -> u32 {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2 (checked just above).
        return unsafe { max_index_avx2(indices) };
    }
    max_index_plain(indices)
}

fn max_index_plain(indices: &[u32]) -> u32 {
    indices.iter().fold(0, |m, &i| m.max(i))
}

/// The same fold compiled for AVX2 (eight indices per `vpmaxud`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn max_index_avx2(indices: &[u32]) -> u32 {
    indices.iter().fold(0, |m, &i| m.max(i))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The memo skips only the `Arc` it holds; an invalid geometry errs at every draw.
    #[test]
    fn a_validated_draw_is_checked_once_per_arc() {
        let mut g = Geometry::new(Primitive::Triangles, vec![Vec4::ZERO; 3]);
        g.indices = Some(vec![0, 1, 2]);
        let valid = Arc::new(g.clone());
        let mut memo = ValidatedDraw::default();
        assert!(memo.validate(&valid).is_ok());
        assert!(memo.0.as_ref().is_some_and(|v| Arc::ptr_eq(v, &valid)));
        assert!(memo.validate(&valid).is_ok());
        g.indices = Some(vec![0, 1, 3]);
        let invalid = Arc::new(g);
        for _ in 0..2 {
            assert!(memo.validate(&invalid).is_err());
        }
        assert!(memo.0.as_ref().is_some_and(|v| Arc::ptr_eq(v, &valid)));
    }

    #[test]
    fn the_largest_index_is_found_at_every_length_and_magnitude() {
        assert_eq!(max_index(&[]), 0);
        for len in [1usize, 7, 8, 9, 31, 6912] {
            for top in [0u32, 1, 65_535, 65_536, u32::MAX] {
                let mut v: Vec<u32> = (0..len as u32).map(|i| i % 97).collect();
                let at = len / 2;
                v[at] = v[at].max(top);
                let expected = v.iter().copied().max().unwrap();
                assert_eq!(max_index(&v), expected, "len {len}, top {top}");
                assert_eq!(max_index_plain(&v), expected);
            }
        }
    }
}
