//! The shadow phase, one image row at a time: each pixel's primary hit, the light's
//! samples it faces (points of an area light, directions of a sun's disc), their shadow
//! rays gathered into packets of [`LANES`] (one pixel's samples share an origin;
//! consecutive pixels share a point light), and the counts each packet's answer adds to
//! its pixels. Counts are integers, so the result does not depend on how rows are spread
//! over threads.

use super::accel::{Accel, LaneMask, Packet, LANES};
use crate::metrics::{BACKGROUND, LIT, SHADOWED};
use crate::scene::SunDisc;
use glam::Vec3;

/// Where the light is, as seen from a point.
#[derive(Debug, Clone, Copy)]
pub(super) enum Emitter {
    None,
    Point(Vec3),
    Directional(Vec3),
    Area {
        corner: Vec3,
        u: Vec3,
        v: Vec3,
    },
    /// A directional light with a disc: its centre's direction is the hard mask's.
    Sun(SunDisc),
}

/// The primary hit of a pixel: the point and the leaf-order triangle of the primary BVH,
/// with a flag for a normal flipped to face the viewer (we see the side we see).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Hit {
    p: Vec3,
    /// Triangle index | [`Hit::FLIPPED`]; `u32::MAX` for no hit.
    triangle: u32,
}

impl Hit {
    const FLIPPED: u32 = 1 << 31;
    pub const NONE: Hit = Hit {
        p: Vec3::ZERO,
        triangle: u32::MAX,
    };

    pub fn new(p: Vec3, triangle: usize, flipped: bool) -> Hit {
        debug_assert!(triangle < Hit::FLIPPED as usize);
        Hit {
            p,
            triangle: triangle as u32 | if flipped { Hit::FLIPPED } else { 0 },
        }
    }
}

/// A hit read back with its triangle's facts: unit normal facing the viewer, a vertex of
/// the triangle, and whether it receives shadows.
#[derive(Debug, Clone, Copy)]
struct Surface {
    p: Vec3,
    n: Vec3,
    /// n · (light − corner) decides facing exactly where n · (light − p) would carry p's
    /// rounding (a light in the receiver's plane).
    corner: Vec3,
    receives: bool,
}

/// What a shadow ray counts towards: the hard mask's ray (to the point light, the area
/// light's centre or the sun's) or a sample of grid A or B.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
enum Role {
    #[default]
    Centre = 0,
    GridA = 1,
    GridB = 2,
}

/// Where a shadow ray goes: to a point (tmax = 1 along light − p) or along a direction.
#[derive(Debug, Clone, Copy)]
enum Toward {
    Point(Vec3),
    Direction(Vec3),
}

/// Sums over rows.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(super) struct Tally {
    pub rays: u64,
    pub geometry_pixels: u64,
    /// Σ (a − b)² over geometry pixels, a and b the samples grids A and B saw.
    pub squared_differences: u64,
}

impl Tally {
    pub fn add(self, other: &Tally) -> Tally {
        Tally {
            rays: self.rays + other.rays,
            geometry_pixels: self.geometry_pixels + other.geometry_pixels,
            squared_differences: self.squared_differences + other.squared_differences,
        }
    }

    /// √(mean over geometry pixels of ((A − B)/2)²), A = a / s², B = b / s².
    pub fn standard_error(&self, side: u32) -> f64 {
        if self.geometry_pixels == 0 {
            return 0.0;
        }
        let cells = f64::from(side * side);
        let mean = self.squared_differences as f64 / self.geometry_pixels as f64;
        mean.sqrt() / (2.0 * cells)
    }
}

/// Per-thread buffers, reused row after row: no ray allocates.
#[derive(Debug, Default)]
pub(super) struct Scratch {
    packet: Packet,
    /// (pixel in the row, role) of each lane.
    tags: [(u32, Role); LANES],
    stack: Vec<(u32, LaneMask)>,
    /// Per pixel of the row: [centre seen, grid A seen, grid B seen].
    counts: Vec<[u32; 3]>,
    rays: u64,
}

/// Everything a row's shading reads.
pub(super) struct Shader<'a> {
    pub all: &'a Accel,
    pub casters: Option<&'a Accel>,
    pub emitter: Emitter,
    /// The shadow-ray offset ε.
    pub epsilon: f32,
    /// Each area-light (or sun) grid is side × side.
    pub side: u32,
    pub seed: u32,
}

impl Shader<'_> {
    #[inline(always)]
    fn surface(&self, hit: &Hit) -> Option<Surface> {
        if hit.triangle == u32::MAX {
            return None;
        }
        let id = (hit.triangle & !Hit::FLIPPED) as usize;
        let n = self.all.normals[id];
        Some(Surface {
            p: hit.p,
            n: if hit.triangle & Hit::FLIPPED != 0 {
                -n
            } else {
                n
            },
            corner: self.all.corner(id),
            receives: self.all.receives[id],
        })
    }

    /// Shades one row (`first` = the index of its first pixel in the image) into `mask` and
    /// `visibility`.
    pub fn row(
        &self,
        first: u32,
        hits: &[Hit],
        mask: &mut [u8],
        visibility: &mut [f32],
        scratch: &mut Scratch,
    ) -> Tally {
        scratch.rays = 0;
        scratch.packet.clear();
        // One loop per kind of light, so each inlines its own `cast`.
        match self.emitter {
            Emitter::None => self.row_hard(None, hits, mask, visibility, scratch),
            Emitter::Point(q) => {
                self.row_hard(Some(Toward::Point(q)), hits, mask, visibility, scratch)
            }
            Emitter::Directional(d) => {
                self.row_hard(Some(Toward::Direction(d)), hits, mask, visibility, scratch)
            }
            Emitter::Area { corner, u, v } => {
                let centre = Toward::Point(corner + 0.5 * (u + v));
                // The sample at (s, t) of the unit square: corner + s·u + t·v.
                let sample = |s: f32, t: f32| Toward::Point(corner + u * s + v * t);
                let out = (mask, visibility);
                return self.row_soft(centre, sample, first, hits, out, scratch);
            }
            Emitter::Sun(sun) => {
                let centre = Toward::Direction(sun.towards);
                // The sample at (s, t): the concentric map onto the disc, then the cap
                // (`scene::sun`).
                let sample = |s: f32, t: f32| Toward::Direction(sun.direction(s, t));
                let out = (mask, visibility);
                return self.row_soft(centre, sample, first, hits, out, scratch);
            }
        }
        Tally {
            rays: scratch.rays,
            ..Tally::default()
        }
    }

    /// A row lit by a point, a direction or nothing (`None`: every visible surface lit):
    /// each pixel's value is written as soon as it is known, a ray's when its packet is
    /// traced.
    fn row_hard(
        &self,
        toward: Option<Toward>,
        hits: &[Hit],
        mask: &mut [u8],
        visibility: &mut [f32],
        scratch: &mut Scratch,
    ) {
        let mut out = Written { mask, visibility };
        for (x, hit) in hits.iter().enumerate() {
            let Some(surface) = self.surface(hit) else {
                out.mask[x] = BACKGROUND;
                out.visibility[x] = 0.0;
                continue;
            };
            match toward {
                None => out.record(x as u32, Role::Centre, true),
                Some(toward) => self.cast(
                    &surface,
                    toward,
                    (x as u32, Role::Centre),
                    scratch,
                    &mut out,
                ),
            }
        }
        self.flush(scratch, &mut out);
    }

    /// A row lit by an area light or a sun: the centre's ray for the mask, and each grid's
    /// samples — `sample(s, t)` for (s, t) jittered in the cells of the unit square —
    /// counted per pixel.
    fn row_soft(
        &self,
        centre: Toward,
        sample: impl Fn(f32, f32) -> Toward,
        first: u32,
        hits: &[Hit],
        (mask, visibility): (&mut [u8], &mut [f32]),
        scratch: &mut Scratch,
    ) -> Tally {
        let mut counts = std::mem::take(&mut scratch.counts);
        counts.clear();
        counts.resize(hits.len(), [0; 3]);
        let mut record = Counted(&mut counts);
        let side = self.side;
        let cell = 1.0 / side as f32;
        for (x, hit) in hits.iter().enumerate() {
            let Some(surface) = self.surface(hit) else {
                continue;
            };
            let x = x as u32;
            self.cast(&surface, centre, (x, Role::Centre), scratch, &mut record);
            for (grid, role) in [(0, Role::GridA), (1, Role::GridB)] {
                let stream = self.seed.wrapping_mul(2).wrapping_add(grid);
                let base = pixel_hash(stream, first + x);
                for b in 0..side {
                    for a in 0..side {
                        let (ja, jb) = jitter(base, b * side + a);
                        let q = sample((a as f32 + ja) * cell, (b as f32 + jb) * cell);
                        self.cast(&surface, q, (x, role), scratch, &mut record);
                    }
                }
            }
        }
        self.flush(scratch, &mut record);
        let mut tally = Tally {
            rays: scratch.rays,
            ..Tally::default()
        };
        let cells = (side * side) as f32;
        for (x, hit) in hits.iter().enumerate() {
            let [centre, a, b] = counts[x];
            (mask[x], visibility[x]) = if hit.triangle == u32::MAX {
                (BACKGROUND, 0.0)
            } else {
                tally.geometry_pixels += 1;
                tally.squared_differences += u64::from(a.abs_diff(b)).pow(2);
                (value(centre), (a + b) as f32 / (2.0 * cells))
            };
        }
        scratch.counts = counts;
        tally
    }

    /// Whether `surface` sees the light `toward` a point or along a direction: facing it
    /// (n · L from the triangle's plane, exact for a light in that plane), and, on a
    /// receiver, nothing in between — a shadow ray from p + ε n, queued in the packet. What
    /// is known now is recorded now; a ray's answer when its packet is traced.
    #[inline(always)]
    fn cast(
        &self,
        surface: &Surface,
        toward: Toward,
        (x, role): (u32, Role),
        scratch: &mut Scratch,
        record: &mut impl Record,
    ) {
        let (facing, to_light, tmax) = match toward {
            Toward::Point(q) => (surface.n.dot(q - surface.corner), q - surface.p, 1.0),
            Toward::Direction(d) => (surface.n.dot(d), d, f32::INFINITY),
        };
        if facing <= 0.0 {
            record.record(x, role, false);
            return;
        }
        match self.casters {
            Some(_) if surface.receives => {
                let origin = surface.p + self.epsilon * surface.n;
                let to_light = if tmax.is_finite() {
                    to_light - self.epsilon * surface.n
                } else {
                    to_light
                };
                let lane = scratch.packet.push(origin, to_light, tmax);
                scratch.tags[lane] = (x, role);
                if scratch.packet.is_full() {
                    self.flush(scratch, record);
                }
            }
            _ => record.record(x, role, true),
        }
    }

    /// Traces the queued rays and records each one's answer.
    fn flush(&self, scratch: &mut Scratch, record: &mut impl Record) {
        let (Some(casters), n @ 1..) = (self.casters, scratch.packet.len()) else {
            return;
        };
        let occluded = casters.occluded(&scratch.packet, &mut scratch.stack);
        for (lane, &(x, role)) in scratch.tags[..n].iter().enumerate() {
            record.record(x, role, occluded & (1 << lane) == 0);
        }
        scratch.rays += n as u64;
        scratch.packet.clear();
    }
}

/// Where a sample's answer goes.
trait Record {
    /// Sample `role` of pixel `x` sees the light (`seen`) or not.
    fn record(&mut self, x: u32, role: Role, seen: bool);
}

/// A hard shadow's row: each answer is the pixel's value.
struct Written<'a> {
    mask: &'a mut [u8],
    visibility: &'a mut [f32],
}

impl Record for Written<'_> {
    #[inline(always)]
    fn record(&mut self, x: u32, _: Role, seen: bool) {
        self.mask[x as usize] = if seen { LIT } else { SHADOWED };
        self.visibility[x as usize] = if seen { 1.0 } else { 0.0 };
    }
}

/// An area light's or a sun's row: answers counted per pixel and role.
struct Counted<'a>(&'a mut [[u32; 3]]);

impl Record for Counted<'_> {
    #[inline(always)]
    fn record(&mut self, x: u32, role: Role, seen: bool) {
        self.0[x as usize][role as usize] += u32::from(seen);
    }
}

fn value(seen: u32) -> u8 {
    if seen > 0 {
        LIT
    } else {
        SHADOWED
    }
}

/// The PCG output hash (RXS-M-XS), a bijection of u32.
fn pcg(mut x: u32) -> u32 {
    x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    let word = ((x >> ((x >> 28) + 4)) ^ x).wrapping_mul(277_803_737);
    (word >> 22) ^ word
}

/// The hash every sample of `pixel` in jitter stream `stream` (2 · seed + grid) starts
/// from.
fn pixel_hash(stream: u32, pixel: u32) -> u32 {
    pcg(pcg(stream) ^ pixel)
}

/// Two numbers in [0, 1) for sample `k` of the pixel whose hash is `base`, the halves of
/// one 32-bit hash, each the centre of one of 2¹⁶ steps: the same every run.
fn jitter(base: u32, k: u32) -> (f32, f32) {
    let h = pcg(base ^ k);
    let step = 1.0 / 65536.0;
    (
        ((h >> 16) as f32 + 0.5) * step,
        ((h & 0xffff) as f32 + 0.5) * step,
    )
}
