//! How a geometry's attribute arrays are laid out in GPU buffers.
//!
//! A geometry kept for more than one draw (a display list's, a buffer object's, a mesh
//! drawn frame after frame) is uploaded *interleaved*: one buffer, each vertex's attributes
//! side by side, as Mesa's display lists store theirs. llvmpipe fetches vertices on the
//! program's thread, by index; one stream puts a vertex's attributes in one or two cache
//! lines instead of one per array. Positions whose w is 1 everywhere (every glVertex2/3
//! and every 2- or 3-component array) are stored as three floats: the vertex stage's
//! `vec4` input takes w = 1 for a 3-component array (GL 3.3 §2.8: missing components are
//! (0, 0, 0, 1)'s), so the values read are the same and a quarter fewer bytes are fetched.
//! A geometry uploaded for one draw (an immediate-mode draw, whose geometry is new each
//! time) keeps one buffer per array, uploaded straight from its vectors without a copy.

use std::borrow::Cow;

use glam::{Vec3, Vec4};

/// One attribute array: `size` floats per vertex, read from the first `size` of every
/// `stride` floats of the geometry's own vector (positions read as three of four floats
/// need no copy).
pub struct Floats<'a> {
    pub size: usize,
    stride: usize,
    data: &'a [f32],
}

impl<'a> Floats<'a> {
    pub fn of4(v: &'a [Vec4]) -> Floats<'a> {
        Floats::whole(4, bytemuck::cast_slice(v))
    }

    pub fn of3(v: &'a [Vec3]) -> Floats<'a> {
        Floats::whole(3, bytemuck::cast_slice(v))
    }

    pub fn of1(v: &'a [f32]) -> Floats<'a> {
        Floats::whole(1, v)
    }

    fn whole(size: usize, data: &'a [f32]) -> Floats<'a> {
        Floats {
            size,
            stride: size,
            data,
        }
    }

    /// Positions as three floats where every w is exactly 1 (the value a 3-component
    /// array gives the vertex stage's w), as four otherwise.
    pub fn positions(v: &'a [Vec4]) -> Floats<'a> {
        let ones = v.iter().all(|p| p.w.to_bits() == 1f32.to_bits());
        Floats {
            size: if ones { 3 } else { 4 },
            stride: 4,
            data: bytemuck::cast_slice(v),
        }
    }

    /// Vertex `i`'s floats (empty past the end).
    fn vertex(&self, i: u32) -> &'a [f32] {
        let at = i as usize * self.stride;
        self.data.get(at..at + self.size).unwrap_or_default()
    }

    /// The floats of the vertices in `order` (vertex indices; out of range gives nothing),
    /// or of all of them as they are.
    pub fn values(&self, order: Option<&[u32]>) -> Cow<'a, [f32]> {
        match order {
            None if self.size == self.stride => Cow::Borrowed(self.data),
            None => {
                let count = self.data.len() / self.stride;
                self.gather((0..count as u32).map(|i| self.vertex(i)))
            }
            Some(order) => self.gather(order.iter().map(|&i| self.vertex(i))),
        }
    }

    fn gather(&self, vertices: impl Iterator<Item = &'a [f32]>) -> Cow<'a, [f32]> {
        Cow::Owned(vertices.flatten().copied().collect())
    }
}

/// Several attribute arrays in one buffer: vertex after vertex, each vertex's attributes
/// in the order given; `offsets[k]` is array k's first byte, `stride` a vertex's bytes.
pub struct Interleaved {
    pub floats: Vec<f32>,
    pub stride: i32,
    pub offsets: Vec<i32>,
}

/// Interleaves `arrays` over the vertices in `order`, or over the first `vertices` in
/// order. A vertex an array lacks (past its end) reads zeros there.
pub fn interleave(arrays: &[&Floats], order: Option<&[u32]>, vertices: usize) -> Interleaved {
    let mut offsets = Vec::with_capacity(arrays.len());
    let mut stride = 0;
    for a in arrays {
        offsets.push((stride * 4) as i32);
        stride += a.size;
    }
    let count = order.map_or(vertices, <[u32]>::len);
    let mut floats: Vec<f32> = Vec::with_capacity(count * stride);
    let mut put = |i: u32| {
        for a in arrays {
            let v = a.vertex(i);
            floats.extend_from_slice(v);
            floats.resize(floats.len() + (a.size - v.len()), 0.0);
        }
    };
    match order {
        Some(order) => order.iter().for_each(|&i| put(i)),
        None => (0..count as u32).for_each(put),
    }
    Interleaved {
        floats,
        stride: (stride * 4) as i32,
        offsets,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_drop_w_only_when_every_w_is_one() {
        let ones = [Vec4::new(1.0, 2.0, 3.0, 1.0), Vec4::new(4.0, 5.0, 6.0, 1.0)];
        let f = Floats::positions(&ones);
        assert_eq!(f.size, 3);
        assert_eq!(&*f.values(None), &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        let homogeneous = [Vec4::new(1.0, 2.0, 3.0, 1.0), Vec4::new(4.0, 5.0, 6.0, 2.0)];
        assert_eq!(Floats::positions(&homogeneous).size, 4);
        // A NaN w is not 1: it is kept.
        let nan = [Vec4::new(0.0, 0.0, 0.0, f32::NAN)];
        assert_eq!(Floats::positions(&nan).size, 4);
    }

    #[test]
    fn interleaving_puts_each_vertex_attributes_side_by_side() {
        let p = [Vec3::new(1.0, 2.0, 3.0), Vec3::new(4.0, 5.0, 6.0)];
        let f = [7.0f32, 8.0];
        let (p, f) = (Floats::of3(&p), Floats::of1(&f));
        let all = interleave(&[&p, &f], None, 2);
        assert_eq!((all.stride, all.offsets.as_slice()), (16, &[0, 12][..]));
        let floats = all.floats.as_slice();
        assert_eq!(floats, &[1.0, 2.0, 3.0, 7.0, 4.0, 5.0, 6.0, 8.0]);
        // In an order, repeated and past the end (zeros).
        let some = interleave(&[&p, &f], Some(&[1, 1, 5]), 0);
        let floats = some.floats.as_slice();
        assert_eq!(
            floats,
            &[4.0, 5.0, 6.0, 8.0, 4.0, 5.0, 6.0, 8.0, 0.0, 0.0, 0.0, 0.0]
        );
    }
}
