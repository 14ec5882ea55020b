//! The scene's world-space triangles in two BVHs: every triangle (primary visibility) and
//! the shadow casters only (shadow rays). Both are obvhs compressed wide BVHs (CWBVH: 8-wide
//! nodes quantised to 8 bits per plane); triangles are stored in the BVH's primitive order
//! so a leaf index reads them directly, with their edges and normal precomputed.
//!
//! **Primary rays** go through obvhs's own closest-hit traversal, one ray at a time.
//!
//! **Shadow rays** go through [`Accel::occluded`], a packet traversal written here (obvhs
//! traverses one ray at a time and has no packet query): up to [`LANES`] rays — one
//! pixel's samples of an area light, or neighbouring pixels' rays to one point — walk the
//! tree together, four to a glam `Vec4` (SSE on x86-64). At each node a pretest bounds the
//! whole packet against the 8 children at once and drops those no ray can enter (most of
//! them); each remaining child is tested against every live ray, each ray keeps its own
//! mask of the children it entered, and a ray leaves the packet at its first hit.
//!
//! **Exactness.** Per ray the arithmetic is obvhs's, operation for operation — the slab
//! test of `CwBvhNode::intersect_ray` (t = q · (extent / d) + (p − o) / d, t ≥ 10⁻⁴,
//! `_mm_max_ps`/`_mm_min_ps` in its operand order) and the Möller–Trumbore test of
//! `Triangle::intersect` (glam's operation order for dot and cross, no fused multiply-add)
//! — and a ray enters exactly the children its own slab test accepts, so every ray tests
//! the triangles it would have tested alone and finds the same occlusion, bit for bit;
//! only the order of the tests and the early exit differ, and an any-hit query does not
//! depend on them. The one deliberate difference: a −0 in a ray's direction is made +0
//! first ([`positive_zeros`]), which obvhs mishandles (a directional light straight down
//! cast no shadow). `packets_decide_every_ray_as_obvhs_alone` checks it on 18 000 rays.

use crate::scene::Scene;
use glam::{Vec3, Vec3A, Vec4};
use obvhs::cwbvh::node::CwBvhNode;
use obvhs::{cwbvh::builder::build_cwbvh_from_tris, cwbvh::CwBvh, ray::Ray, BvhBuildParams};
use std::time::Duration;

/// Rays in a packet.
pub(super) const LANES: usize = 32;

/// `Vec4`s per packet array.
const GROUPS: usize = LANES / 4;

/// A set of lanes, bit i for lane i.
pub(super) type LaneMask = u32;

/// Lanes at or below which a packet's rays leave it and finish a subtree one at a time
/// (they have stopped sharing nodes, and a node's pretest and decoding would be paid for
/// one or two rays).
const ALONE: u32 = 2;

/// obvhs's lower bound on a child's entry distance (`cwbvh::node::EPSILON`, private there).
const NODE_T_MIN: f32 = 1e-4;

/// A triangle as the intersection test reads it: v₀, e₁ = v₀ − v₁, e₂ = v₂ − v₀ and
/// n = e₁ × e₂ (unnormalised), computed once with glam's operations so each value equals
/// the one `obvhs::triangle::Triangle::intersect` computes per test.
#[derive(Debug, Clone, Copy)]
pub(super) struct Tri {
    pub v0: Vec3,
    e1: Vec3,
    e2: Vec3,
    n: Vec3,
}

impl Tri {
    fn new(a: Vec3, b: Vec3, c: Vec3) -> Tri {
        let (a, b, c) = (Vec3A::from(a), Vec3A::from(b), Vec3A::from(c));
        let e1 = a - b;
        let e2 = c - a;
        Tri {
            v0: a.into(),
            e1: e1.into(),
            e2: e2.into(),
            n: e1.cross(e2).into(),
        }
    }

    /// `obvhs::triangle::Triangle::intersect`: t of the hit in [tmin, tmax], else ∞.
    fn intersect(&self, ray: &Ray) -> f32 {
        let (e1, e2, n) = (
            Vec3A::from(self.e1),
            Vec3A::from(self.e2),
            Vec3A::from(self.n),
        );
        let c = Vec3A::from(self.v0) - ray.origin;
        let r = ray.direction.cross(c);
        let inv_det = 1.0 / n.dot(ray.direction);
        let u = r.dot(e2) * inv_det;
        let v = r.dot(e1) * inv_det;
        let w = 1.0 - u - v;
        // Sign bits: u, v, w ≥ +0 (−0 counts as outside, as in obvhs).
        let outside = (u.to_bits() | v.to_bits() | w.to_bits()) & 0x8000_0000 != 0;
        if inv_det != 0.0 && !outside {
            let t = n.dot(c) * inv_det;
            if t >= ray.tmin && t <= ray.tmax {
                return t;
            }
        }
        f32::INFINITY
    }
}

/// Up to [`LANES`] shadow rays o + t·d, t ∈ [0, tmax): lane i of every array is ray i.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Packet {
    o: [[f32; LANES]; 3],
    d: [[f32; LANES]; 3],
    tmax: [f32; LANES],
    len: usize,
}

impl Packet {
    /// Lane `lane` as obvhs's ray.
    fn ray(&self, lane: usize) -> Ray {
        let v = |a: &[[f32; LANES]; 3]| Vec3A::new(a[0][lane], a[1][lane], a[2][lane]);
        Ray::new(v(&self.o), v(&self.d), 0.0, self.tmax[lane])
    }

    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_full(&self) -> bool {
        self.len == LANES
    }

    pub fn clear(&mut self) {
        self.len = 0;
    }

    /// Adds the ray origin + t·dir, t ∈ [0, tmax); returns its lane. The packet must not be
    /// full.
    #[inline]
    pub fn push(&mut self, origin: Vec3, dir: Vec3, tmax: f32) -> usize {
        let lane = self.len;
        let dir = positive_zeros(dir);
        for axis in 0..3 {
            self.o[axis][lane] = origin[axis];
            self.d[axis][lane] = dir[axis];
        }
        self.tmax[lane] = tmax;
        self.len += 1;
        lane
    }
}

/// A packet as the traversal reads it: four lanes to a `Vec4` (SSE on x86-64), with
/// obvhs's reciprocal directions and, over the lanes in use, the bounds the children's
/// pretest needs.
struct Lanes {
    o: [[Vec4; GROUPS]; 3],
    d: [[Vec4; GROUPS]; 3],
    /// obvhs's `Ray::inv_direction`: 1/d, or ±1/ε where |d| ≤ ε (`safe_inverse`).
    inv: [[Vec4; GROUPS]; 3],
    tmax: [Vec4; GROUPS],
    /// Per axis (x, y, z, −): least and greatest origin and reciprocal direction, and the
    /// greatest tmax, over the lanes in use.
    o_min: Vec4,
    o_max: Vec4,
    inv_min: Vec4,
    inv_max: Vec4,
    tmax_max: f32,
    /// The lanes in use.
    live: LaneMask,
}

impl Lanes {
    fn of(packet: &Packet) -> Lanes {
        // Lanes not in use repeat lane 0, so the bounds over all lanes are the bounds over
        // the lanes in use.
        let padded;
        let rays = if packet.len == LANES {
            packet
        } else {
            let mut p = *packet;
            for lane in packet.len.max(1)..LANES {
                for axis in 0..3 {
                    p.o[axis][lane] = p.o[axis][0];
                    p.d[axis][lane] = p.d[axis][0];
                }
                p.tmax[lane] = p.tmax[0];
            }
            padded = p;
            &padded
        };
        let groups = |a: &[f32; LANES]| -> [Vec4; GROUPS] {
            std::array::from_fn(|g| Vec4::from_slice(&a[4 * g..4 * g + 4]))
        };
        let o = [groups(&rays.o[0]), groups(&rays.o[1]), groups(&rays.o[2])];
        let d = [groups(&rays.d[0]), groups(&rays.d[1]), groups(&rays.d[2])];
        // ±1/ε = ±2²³ exactly.
        let (epsilon, over_epsilon) = (Vec4::splat(f32::EPSILON), Vec4::splat(1.0 / f32::EPSILON));
        let reciprocal = |d: Vec4| {
            Vec4::select(
                d.abs().cmple(epsilon),
                d.signum() * over_epsilon,
                Vec4::ONE / d,
            )
        };
        let inv = [
            d[0].map(reciprocal),
            d[1].map(reciprocal),
            d[2].map(reciprocal),
        ];
        let least = |a: &[[Vec4; GROUPS]; 3]| {
            let m = |axis: usize| {
                a[axis]
                    .iter()
                    .fold(a[axis][0], |m, v| m.min(*v))
                    .min_element()
            };
            Vec4::new(m(0), m(1), m(2), 0.0)
        };
        let most = |a: &[[Vec4; GROUPS]; 3]| {
            let m = |axis: usize| {
                a[axis]
                    .iter()
                    .fold(a[axis][0], |m, v| m.max(*v))
                    .max_element()
            };
            Vec4::new(m(0), m(1), m(2), 0.0)
        };
        let tmax = groups(&rays.tmax);
        Lanes {
            o,
            d,
            inv,
            tmax,
            o_min: least(&o),
            o_max: most(&o),
            inv_min: least(&inv),
            inv_max: most(&inv),
            tmax_max: tmax.iter().fold(tmax[0], |m, v| m.max(*v)).max_element(),
            live: ((1u64 << packet.len) - 1) as LaneMask,
        }
    }
}

/// `v` with −0 components made +0 (−0 + 0 = +0). obvhs picks a slab's near plane by
/// d < 0 but takes 1/d's sign from d's sign bit (`safe_inverse(−0) = −1/ε`), so a ray
/// with a −0 component entered no box at all: every shadow ray of a directional light
/// straight down (−direction = (−0, 1, −0)) went through every occluder.
pub(super) fn positive_zeros(v: Vec3) -> Vec3 {
    v + Vec3::ZERO
}

/// One BVH and its triangles in leaf order, with the scene facts each triangle carries.
pub(super) struct Accel {
    bvh: CwBvh,
    tris: Vec<Tri>,
    /// Unit geometric normal ((b − a) × (c − a), normalised) per triangle, in leaf order.
    pub normals: Vec<Vec3>,
    /// Whether the triangle's object receives shadows, in leaf order.
    pub receives: Vec<bool>,
    /// The index in the scene's objects of the triangle's object, in leaf order.
    pub objects: Vec<u32>,
}

impl Accel {
    /// Builds over the triangles of the objects `keep` selects; `None` when there are none.
    pub fn build(scene: &Scene, keep: impl Fn(&crate::scene::Object) -> bool) -> Option<Accel> {
        Accel::build_where(scene, |_, o| keep(o))
    }

    /// Builds over the triangles of the objects `keep(index, object)` selects.
    pub fn build_where(
        scene: &Scene,
        keep: impl Fn(usize, &crate::scene::Object) -> bool,
    ) -> Option<Accel> {
        let mut corners = Vec::new();
        let mut receives = Vec::new();
        let mut objects = Vec::new();
        for (index, object) in scene.objects.iter().enumerate() {
            if !keep(index, object) {
                continue;
            }
            let mesh = object.world_mesh();
            for t in 0..mesh.triangle_count() {
                corners.push(mesh.corners(t));
                receives.push(object.receives);
                objects.push(index as u32);
            }
        }
        if corners.is_empty() {
            return None;
        }
        let for_build: Vec<obvhs::triangle::Triangle> = corners
            .iter()
            .map(|[a, b, c]| obvhs::triangle::Triangle {
                v0: (*a).into(),
                v1: (*b).into(),
                v2: (*c).into(),
            })
            .collect();
        let bvh = build_cwbvh_from_tris(
            &for_build,
            BvhBuildParams::medium_build(),
            &mut Duration::default(),
        );
        drop(for_build);
        let order: Vec<usize> = bvh.primitive_indices.iter().map(|&i| i as usize).collect();
        let tris: Vec<Tri> = order
            .iter()
            .map(|&i| {
                let [a, b, c] = corners[i];
                Tri::new(a, b, c)
            })
            .collect();
        let receives = order.iter().map(|&i| receives[i]).collect();
        let objects = order.iter().map(|&i| objects[i]).collect();
        let normals = order
            .iter()
            .map(|&i| {
                let [a, b, c] = corners[i].map(Vec3A::from);
                Vec3::from((b - a).cross(c - a)).normalize_or_zero()
            })
            .collect();
        Some(Accel {
            bvh,
            tris,
            normals,
            receives,
            objects,
        })
    }

    /// The first vertex of leaf-order triangle `id`.
    pub fn corner(&self, id: usize) -> Vec3 {
        self.tris[id].v0
    }

    pub fn triangle_count(&self) -> usize {
        self.tris.len()
    }

    /// The nearest hit on origin + t·dir, t ∈ [tmin, tmax]: (t, leaf-order triangle index).
    pub fn closest(&self, origin: Vec3, dir: Vec3, tmin: f32, tmax: f32) -> Option<(f32, usize)> {
        let ray = Ray::new(origin.into(), positive_zeros(dir).into(), tmin, tmax);
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

    /// The rays of `packet` that meet a triangle, as bits (bit i: lane i), each exactly
    /// as obvhs's `ray_traverse_miss` would decide it alone (see the module note). `stack`
    /// is scratch space, kept by the caller so no ray allocates.
    pub fn occluded(&self, packet: &Packet, stack: &mut Vec<(u32, LaneMask)>) -> LaneMask {
        if packet.len == 0 || self.bvh.nodes.is_empty() {
            return 0;
        }
        let rays = Lanes::of(packet);
        let live = rays.live;
        let order = priority_key(packet);
        let mut hit: LaneMask = 0;
        stack.clear();
        stack.push((0, live));
        while let Some((index, entered)) = stack.pop() {
            let lanes = entered & !hit;
            if lanes == 0 {
                continue;
            }
            if lanes.count_ones() <= ALONE {
                // Too few rays left to share the work: each finishes the subtree alone.
                let mut rest = lanes;
                while rest != 0 {
                    let lane = rest.trailing_zeros() as usize;
                    rest &= rest - 1;
                    if self.occluded_below(index, &packet.ray(lane)) {
                        hit |= 1 << lane;
                    }
                }
                continue;
            }
            let node = &self.bvh.nodes[index as usize];
            let masks = child_masks(node, &rays, lanes);
            // Leaves first (a hit retires lanes before more nodes are pushed), then the
            // inner children pushed so that obvhs's first choice is popped first: obvhs
            // visits slot i in decreasing order of i ^ octant bits.
            for key in (0..8u8).rev() {
                let slot = usize::from(key ^ order);
                let meta = node.child_meta[slot];
                let lanes = masks[slot] & !hit;
                if lanes == 0 || node.imask & (1 << slot) != 0 {
                    continue;
                }
                let first = node.primitive_base_idx + u32::from(meta & 0x1f);
                let count = (meta >> 5).count_ones();
                for id in first..first + count {
                    hit |= self.tris[id as usize].occludes(&rays, lanes);
                }
                if live & !hit == 0 {
                    return hit;
                }
            }
            for key in 0..8u8 {
                let slot = usize::from(key ^ order);
                let lanes = masks[slot] & !hit;
                if lanes != 0 && node.imask & (1 << slot) != 0 {
                    let before = (u32::from(node.imask) & ((1u32 << slot) - 1)).count_ones();
                    stack.push((node.child_base_idx + before, lanes));
                }
            }
        }
        hit
    }
}

impl Accel {
    /// Whether `ray` meets a triangle in the subtree of node `index`: obvhs's own
    /// single-ray traversal (`ray_traverse_miss`'s), started at that node instead of the
    /// root — what the ray alone does below a node it entered.
    fn occluded_below(&self, index: u32, ray: &Ray) -> bool {
        use glam::{uvec2, UVec2};
        let mut state = self.bvh.new_traversal(ray.direction);
        // The root's group is (0, bit 31): one child, at index 0 of the group. Node
        // `index` is the same group based at `index`.
        state.current_group = uvec2(index, 0x8000_0000);
        let mut node;
        let mut occluded = false;
        let tris = &self.tris;
        'traversal: {
            obvhs::traverse!(
                self.bvh,
                node,
                state,
                node.intersect_ray(ray, state.oct_inv4),
                {
                    if tris[state.primitive_id as usize].intersect(ray) < ray.tmax {
                        occluded = true;
                        break 'traversal;
                    }
                }
            );
        }
        occluded
    }
}

/// obvhs's child order for the packet's first ray: the octant bits `ray_get_octant_inv4`
/// puts in each byte (4 for +x, 2 for +y, 1 for +z).
fn priority_key(packet: &Packet) -> u8 {
    let bit = |axis: usize, value: u8| if packet.d[axis][0] < 0.0 { 0 } else { value };
    bit(0, 4) | bit(1, 2) | bit(2, 1)
}

/// A node's quantised child planes (0 to 255) as floats: `[axis][half]`, lane i of half h
/// is child slot 4h + i.
fn planes(node: &CwBvhNode) -> ([[Vec4; 2]; 3], [[Vec4; 2]; 3]) {
    (
        [
            bytes_to_floats(&node.child_min_x),
            bytes_to_floats(&node.child_min_y),
            bytes_to_floats(&node.child_min_z),
        ],
        [
            bytes_to_floats(&node.child_max_x),
            bytes_to_floats(&node.child_max_y),
            bytes_to_floats(&node.child_max_z),
        ],
    )
}

/// Eight bytes as eight floats, two `Vec4`s: on x86-64 by SSE2 unpacking (the byte-by-byte
/// conversion was a third of a node's cost).
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[inline(always)]
fn bytes_to_floats(a: &[u8; 8]) -> [Vec4; 2] {
    use std::arch::x86_64::{
        _mm_cvtepi32_ps, _mm_cvtsi64_si128, _mm_setzero_si128, _mm_unpackhi_epi16,
        _mm_unpacklo_epi16, _mm_unpacklo_epi8,
    };
    // SAFETY: SSE2 is enabled (the cfg above); these intrinsics read and write registers
    // only.
    unsafe {
        let zero = _mm_setzero_si128();
        let words = _mm_unpacklo_epi8(_mm_cvtsi64_si128(i64::from_le_bytes(*a)), zero);
        [
            Vec4::from(_mm_cvtepi32_ps(_mm_unpacklo_epi16(words, zero))),
            Vec4::from(_mm_cvtepi32_ps(_mm_unpackhi_epi16(words, zero))),
        ]
    }
}

#[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
#[inline(always)]
fn bytes_to_floats(a: &[u8; 8]) -> [Vec4; 2] {
    let f = |i: usize| f32::from(a[i]);
    [
        Vec4::new(f(0), f(1), f(2), f(3)),
        Vec4::new(f(4), f(5), f(6), f(7)),
    ]
}

/// For each of the node's 8 child slots, the lanes of `lanes` whose ray enters the child's
/// box, decided as `CwBvhNode::intersect_ray_simd` decides it.
///
/// obvhs's near plane is q_near · (extent / d) + (p − o) / d with q_near the low plane for
/// d ≥ 0, the high one for d < 0; with no −0 in d ([`positive_zeros`]) that plane's t is
/// the smaller of the two planes' (each rounding is monotonic), so min and max pick
/// exactly obvhs's values. `Vec4::max(a, b)` is `_mm_max_ps(a, b)`, in obvhs's operand
/// order.
///
/// First a pretest rejects, for the whole packet at once, the children no lane can enter
/// (most of them): with s = extent / d and h = (p − o) / d bounded over the lanes —
/// s_min = extent · (1/d)_min, h within the products of the bounds of p − o and 1/d —
/// each lane's near t is at least min over q ∈ {lo, hi} of q · s_min + h_min and its far t
/// at most max of q · s_max + h_max, because every rounding step is monotonic and q ≥ 0.
/// A child whose bounds give t₀ > t₁ is missed by every lane, so the pretest only skips
/// work; the lanes' own tests decide.
#[inline(always)]
fn child_masks(node: &CwBvhNode, rays: &Lanes, lanes: LaneMask) -> [LaneMask; 8] {
    let extent = Vec4::from((Vec3::from(node.compute_extent()), 0.0));
    let p = Vec4::from((node.p, 0.0));
    let (lo, hi) = planes(node);
    let t_min = Vec4::splat(NODE_T_MIN);

    // The packet's pretest, four children per Vec4.
    let (s_min, s_max) = (extent * rays.inv_min, extent * rays.inv_max);
    let (near_p, far_p) = (p - rays.o_max, p - rays.o_min);
    let corners = [
        near_p * rays.inv_min,
        near_p * rays.inv_max,
        far_p * rays.inv_min,
        far_p * rays.inv_max,
    ];
    let h_min = corners[0].min(corners[1]).min(corners[2].min(corners[3]));
    let h_max = corners[0].max(corners[1]).max(corners[2].max(corners[3]));
    let mut candidates = 0u32;
    for half in 0..2 {
        let mut near = [Vec4::ZERO; 3];
        let mut far = [Vec4::ZERO; 3];
        for axis in 0..3 {
            let (s0, h0) = (Vec4::splat(s_min[axis]), Vec4::splat(h_min[axis]));
            let (s1, h1) = (Vec4::splat(s_max[axis]), Vec4::splat(h_max[axis]));
            let (l, u) = (lo[axis][half], hi[axis][half]);
            near[axis] = (l * s0 + h0).min(u * s0 + h0);
            far[axis] = (l * s1 + h1).max(u * s1 + h1);
        }
        let t0 = near[0].max(near[1].max(near[2])).max(t_min);
        let t1 = far[0]
            .min(far[1].min(far[2]))
            .min(Vec4::splat(rays.tmax_max));
        candidates |= (!t0.cmpgt(t1).bitmask() & 0xf) << (4 * half);
    }
    for (slot, meta) in node.child_meta.iter().enumerate() {
        if *meta == 0 {
            candidates &= !(1 << slot);
        }
    }
    if candidates == 0 {
        return [0; 8];
    }

    // Each lane's own test: obvhs's arithmetic, one lane per ray.
    let mut scale = [[Vec4::ZERO; GROUPS]; 3];
    let mut shift = [[Vec4::ZERO; GROUPS]; 3];
    for axis in 0..3 {
        for g in 0..GROUPS {
            let inv = rays.inv[axis][g];
            scale[axis][g] = Vec4::splat(extent[axis]) * inv;
            shift[axis][g] = (Vec4::splat(p[axis]) - rays.o[axis][g]) * inv;
        }
    }
    let mut masks: [LaneMask; 8] = [0; 8];
    while candidates != 0 {
        let slot = candidates.trailing_zeros() as usize;
        candidates &= candidates - 1;
        let (child_half, i) = (slot / 4, slot % 4);
        let q = |axis: usize| (lo[axis][child_half][i], hi[axis][child_half][i]);
        let q = [q(0), q(1), q(2)];
        let mut bits = 0u32;
        for g in 0..GROUPS {
            if (lanes >> (4 * g)) & 0xf == 0 {
                continue;
            }
            let mut near = [Vec4::ZERO; 3];
            let mut far = [Vec4::ZERO; 3];
            for axis in 0..3 {
                let (s, h) = (scale[axis][g], shift[axis][g]);
                let l = Vec4::splat(q[axis].0) * s + h;
                let u = Vec4::splat(q[axis].1) * s + h;
                near[axis] = l.min(u);
                far[axis] = l.max(u);
            }
            let t0 = near[0].max(near[1].max(near[2])).max(t_min);
            let t1 = far[0].min(far[1].min(far[2])).min(rays.tmax[g]);
            bits |= t0.cmple(t1).bitmask() << (4 * g);
        }
        masks[slot] = (bits as LaneMask) & lanes;
    }
    masks
}

impl Tri {
    /// The lanes of `lanes` whose ray meets this triangle at t ∈ [0, tmax):
    /// [`Tri::intersect`] per lane (glam's dot and cross, written out in glam's order), with
    /// a hit where `ray_traverse_miss` sees one (t < tmax).
    #[inline(always)]
    fn occludes(&self, rays: &Lanes, lanes: LaneMask) -> LaneMask {
        let s = |v: Vec3| [Vec4::splat(v.x), Vec4::splat(v.y), Vec4::splat(v.z)];
        let (v0, e1, e2, n) = (s(self.v0), s(self.e1), s(self.e2), s(self.n));
        let mut bits = 0u32;
        for g in 0..GROUPS {
            if (lanes >> (4 * g)) & 0xf == 0 {
                continue;
            }
            let d = [rays.d[0][g], rays.d[1][g], rays.d[2][g]];
            let c = [
                v0[0] - rays.o[0][g],
                v0[1] - rays.o[1][g],
                v0[2] - rays.o[2][g],
            ];
            let r = cross(d, c);
            let inv_det = Vec4::ONE / dot(n, d);
            let u = dot(r, e2) * inv_det;
            let v = dot(r, e1) * inv_det;
            let w = Vec4::ONE - u - v;
            let t = dot(n, c) * inv_det;
            let outside =
                u.is_negative_bitmask() | v.is_negative_bitmask() | w.is_negative_bitmask();
            let hit = inv_det.cmpne(Vec4::ZERO).bitmask()
                & !outside
                & t.cmpge(Vec4::ZERO).bitmask()
                & t.cmplt(rays.tmax[g]).bitmask();
            bits |= hit << (4 * g);
        }
        (bits as LaneMask) & lanes
    }
}

/// glam's `Vec3A::dot`, lane by lane: (a.x b.x + a.y b.y) + a.z b.z.
#[inline(always)]
fn dot(a: [Vec4; 3], b: [Vec4; 3]) -> Vec4 {
    (a[0] * b[0] + a[1] * b[1]) + a[2] * b[2]
}

/// glam's `Vec3A::cross`, lane by lane: each component a product minus a product.
#[inline(always)]
fn cross(a: [Vec4; 3], b: [Vec4; 3]) -> [Vec4; 3] {
    [
        a[1] * b[2] - b[1] * a[2],
        a[2] * b[0] - b[2] * a[0],
        a[0] * b[1] - b[0] * a[1],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use obvhs::triangle::Triangle;

    /// The scene's triangles as obvhs's own type, in `accel`'s leaf order.
    fn leaf_order_triangles(scene: &Scene, accel: &Accel) -> Vec<Triangle> {
        let mut all = Vec::new();
        for object in &scene.objects {
            let mesh = object.world_mesh();
            for t in 0..mesh.triangle_count() {
                let [a, b, c] = mesh.corners(t);
                all.push(Triangle {
                    v0: a.into(),
                    v1: b.into(),
                    v2: c.into(),
                });
            }
        }
        let order = &accel.bvh.primitive_indices;
        order.iter().map(|&i| all[i as usize]).collect()
    }

    /// The packet query answers each ray as obvhs's own single-ray any-hit query does:
    /// packets of 1 to 32 rays to a point and along a direction, from origins clustered
    /// tightly (rays that stay together down the tree), loosely, or across the scene, on the
    /// ground, on triangle corners (rays that start on a triangle and run along its
    /// neighbours) and in the air, in the default scene and with a finer sphere (a deeper
    /// tree).
    #[test]
    fn packets_decide_every_ray_as_obvhs_alone() {
        let mut fine = Scene::default_scene();
        fine.objects[1].shape = crate::scene::Shape::Sphere {
            radius: 1.25,
            slices: 128,
            stacks: 64,
        };
        fine.objects[1].mesh = std::sync::Arc::new(
            fine.objects[1]
                .shape
                .procedural_mesh()
                .expect("a procedural sphere"),
        );
        let lights = [
            (Vec3::new(6.0, 10.0, 6.0), 1.0),
            (Vec3::new(-0.3, 0.4, 1.0), f32::INFINITY),
        ];
        let mut stack = Vec::new();
        let mut checked = [0usize; 2];
        let mut seed = 1u32;
        let mut next = || {
            seed = seed.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
            (seed >> 8) as f32 / (1u32 << 24) as f32
        };
        for scene in [Scene::default_scene(), fine] {
            let accel = Accel::build(&scene, |_| true).expect("triangles");
            let tris = leaf_order_triangles(&scene, &accel);
            for round in 0..600 {
                let (light, tmax) = lights[round % 2];
                let len = [LANES, LANES - 1, 9, 2, 1][round % 5];
                let spread = [0.05, 0.5, 8.0][round % 3];
                let centre = Vec3::new(next() * 8.0 - 4.0, next() * 2.0, next() * 8.0 - 4.0);
                let mut packet = Packet::default();
                let mut rays = Vec::new();
                while packet.len() < len {
                    let jitter = Vec3::new(next() - 0.5, next() - 0.5, next() - 0.5) * spread;
                    let o = match rays.len() % 3 {
                        0 => (centre + jitter) * Vec3::new(1.0, 0.0, 1.0),
                        1 => accel.tris[(next() * tris.len() as f32) as usize].v0,
                        _ => centre + jitter,
                    };
                    let d = if tmax.is_finite() { light - o } else { light };
                    packet.push(o, d, tmax);
                    rays.push(Ray::new(o.into(), d.into(), 0.0, tmax));
                }
                let got = accel.occluded(&packet, &mut stack);
                assert_eq!(u64::from(got) >> rays.len(), 0, "no unused lane answers");
                for (l, ray) in rays.iter().enumerate() {
                    let alone = !accel
                        .bvh
                        .ray_traverse_miss(*ray, |r, id| tris[id].intersect(r));
                    assert_eq!(
                        got & (1 << l) != 0,
                        alone,
                        "round {round} lane {l}: {ray:?}"
                    );
                    checked[usize::from(alone)] += 1;
                }
            }
        }
        assert!(checked[0] > 2000 && checked[1] > 2000, "{checked:?}");
    }

    /// The precomputed edges and normal give obvhs's t, bit for bit.
    #[test]
    fn the_precomputed_test_is_obvhs_test() {
        let scene = Scene::default_scene();
        let accel = Accel::build(&scene, |_| true).expect("triangles");
        let tris = leaf_order_triangles(&scene, &accel);
        let eye = Vec3A::from(scene.camera.eye);
        for (i, (ours, theirs)) in accel.tris.iter().zip(&tris).enumerate() {
            let centre = (theirs.v0 + theirs.v1 + theirs.v2) / 3.0;
            for target in [centre, theirs.v1, (theirs.v1 + theirs.v2) / 2.0] {
                let ray = Ray::new(eye, target - eye, 0.0, 10.0);
                assert_eq!(
                    ours.intersect(&ray).to_bits(),
                    theirs.intersect(&ray).to_bits(),
                    "triangle {i}"
                );
            }
        }
    }

    /// Item: obvhs's slab test takes 1/d's sign from −0 but the near plane from d < 0, so a
    /// ray with a −0 component entered no box; the packets and `closest` see +0.
    #[test]
    fn a_negative_zero_direction_still_finds_what_is_in_its_way() {
        let scene = Scene::default_scene();
        let accel = Accel::build(&scene, |_| true).expect("triangles");
        // From under the sphere (centre (−2, 1.75, 1), radius 1.25) straight up.
        let (o, d) = (Vec3::new(-2.0, 0.01, 1.0), Vec3::new(-0.0, 1.0, -0.0));
        let ray = Ray::new(o.into(), d.into(), 0.0, f32::INFINITY);
        let tris = leaf_order_triangles(&scene, &accel);
        assert!(
            accel
                .bvh
                .ray_traverse_miss(ray, |r, id| tris[id].intersect(r)),
            "obvhs alone misses (if this fails, obvhs changed: drop `positive_zeros`)"
        );
        let mut packet = Packet::default();
        packet.push(o, d, f32::INFINITY);
        assert_eq!(accel.occluded(&packet, &mut Vec::new()), 1);
        assert!(accel.closest(o, d, 0.0, f32::INFINITY).is_some());
    }
}
