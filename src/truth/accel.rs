//! The scene's world-space triangles in two BVHs: every triangle (primary visibility) and
//! the shadow casters only (shadow rays). Both are obvhs compressed wide BVHs (CWBVH: 8-wide
//! nodes, SIMD node tests); triangles are stored in the BVH's primitive order so a leaf
//! index reads them directly.

use crate::scene::Scene;
use glam::Vec3;
use glam::Vec3A;
use obvhs::{
    cwbvh::builder::build_cwbvh_from_tris, cwbvh::CwBvh, ray::Ray, triangle::Triangle,
    BvhBuildParams,
};
use std::time::Duration;

/// One BVH and its triangles in leaf order, with the scene facts each triangle carries.
pub(super) struct Accel {
    bvh: CwBvh,
    tris: Vec<Triangle>,
    /// Unit geometric normal ((b − a) × (c − a), normalised) per triangle, in leaf order.
    pub normals: Vec<Vec3>,
    /// Whether the triangle's object receives shadows, in leaf order.
    pub receives: Vec<bool>,
}

pub(super) fn to_bvh(v: Vec3) -> Vec3A {
    Vec3A::new(v.x, v.y, v.z)
}

fn from_bvh(v: Vec3A) -> Vec3 {
    Vec3::new(v.x, v.y, v.z)
}

impl Accel {
    /// Builds over the triangles of the objects `keep` selects; `None` when there are none.
    pub fn build(scene: &Scene, keep: impl Fn(&crate::scene::Object) -> bool) -> Option<Accel> {
        let mut tris = Vec::new();
        let mut receives = Vec::new();
        for object in scene.objects.iter().filter(|o| keep(o)) {
            let mesh = object.world_mesh();
            for t in 0..mesh.triangle_count() {
                let [a, b, c] = mesh.corners(t);
                tris.push(Triangle {
                    v0: to_bvh(a),
                    v1: to_bvh(b),
                    v2: to_bvh(c),
                });
                receives.push(object.receives);
            }
        }
        if tris.is_empty() {
            return None;
        }
        let bvh = build_cwbvh_from_tris(
            &tris,
            BvhBuildParams::medium_build(),
            &mut Duration::default(),
        );
        let order: Vec<usize> = bvh.primitive_indices.iter().map(|&i| i as usize).collect();
        let tris: Vec<Triangle> = order.iter().map(|&i| tris[i]).collect();
        let receives = order.iter().map(|&i| receives[i]).collect();
        let normals = tris
            .iter()
            .map(|t| from_bvh((t.v1 - t.v0).cross(t.v2 - t.v0)).normalize_or_zero())
            .collect();
        Some(Accel {
            bvh,
            tris,
            normals,
            receives,
        })
    }

    /// The first vertex of leaf-order triangle `id`.
    pub fn corner(&self, id: usize) -> Vec3 {
        from_bvh(self.tris[id].v0)
    }

    pub fn triangle_count(&self) -> usize {
        self.tris.len()
    }

    /// The nearest hit on origin + t·dir, t ∈ [tmin, tmax]: (t, leaf-order triangle index).
    pub fn closest(&self, origin: Vec3, dir: Vec3, tmin: f32, tmax: f32) -> Option<(f32, usize)> {
        let ray = Ray::new(to_bvh(origin), to_bvh(dir), tmin, tmax);
        let mut hit = obvhs::ray::RayHit::none();
        let tris = &self.tris;
        if self
            .bvh
            .ray_traverse(ray, &mut hit, |r, id| tris[id].intersect(r))
        {
            Some((hit.t, hit.primitive_id as usize))
        } else {
            None
        }
    }

    /// Whether nothing lies on origin + t·dir for t ∈ [0, tmax] (stops at the first hit).
    pub fn unoccluded(&self, origin: Vec3, dir: Vec3, tmax: f32) -> bool {
        let ray = Ray::new(to_bvh(origin), to_bvh(dir), 0.0, tmax);
        let tris = &self.tris;
        self.bvh
            .ray_traverse_miss(ray, |r, id| tris[id].intersect(r))
    }
}
