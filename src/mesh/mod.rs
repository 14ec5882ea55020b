//! Triangle meshes: positions, per-vertex normals and index triples, the only geometry the
//! pipeline draws and the ground truth ray-casts.
//!
//! Every shape ends up as a [`Mesh`] in object space; [`Mesh::transformed`] applies the
//! object's model matrix M (positions by M, normals by the inverse transpose of M's upper
//! 3×3, renormalised — GL 1.x §2.11.3). Windings are counter-clockwise seen from outside,
//! GL's default front face.
//!
//! Normals come from the surface when a shape knows it analytically (sphere, torus, plane,
//! box) and otherwise from [`Mesh::compute_normals`]: the area-weighted average of the faces
//! around each vertex (the sum of unnormalised cross products, normalised once).
//!
//! Degenerate triangles (repeated indices or zero area) are never kept:
//! [`Mesh::drop_degenerate`] removes them and returns how many it removed, so loaders can
//! report the count.

mod aircraft;
mod aircraft_f35;
mod obj;
pub mod occluder;
mod shapes;
mod teapot;

pub use aircraft::aircraft;
pub use aircraft_f35::aircraft_f35;
pub use obj::{load_obj, load_obj_str, ObjMesh};
pub use shapes::{cuboid, plane, sphere, torus};
pub use teapot::teapot;

use crate::ff::{Geometry, Primitive};
use glam::{Mat3, Mat4, Vec3};
use std::collections::HashMap;
use std::path::PathBuf;

/// Which procedural aircraft (`shape = "aircraft"`, `layout = …`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AircraftLayout {
    /// The fighter of [`aircraft`] (x forward, y up), `length` units long. The default.
    Fighter { length: f32 },
    /// [`aircraft_f35`] in the model space of Coleman's F-35 (z up, metres), which the
    /// thesis's three shadow planes fit.
    F35,
}

impl AircraftLayout {
    /// The object-space mesh.
    pub fn mesh(self) -> Mesh {
        match self {
            AircraftLayout::Fighter { length } => aircraft(length),
            AircraftLayout::F35 => aircraft_f35(),
        }
    }
}

/// An indexed triangle mesh with one normal per vertex.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    pub positions: Vec<Vec3>,
    /// Unit normals, one per position.
    pub normals: Vec<Vec3>,
    /// Counter-clockwise (front-facing) index triples into `positions`.
    pub triangles: Vec<[u32; 3]>,
}

/// Failures of the mesh layer: loading an OBJ file.
#[derive(Debug, thiserror::Error)]
pub enum MeshError {
    #[error("cannot read OBJ file {path}: {source}")]
    Unreadable {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("OBJ file {path} is malformed: {source}")]
    Malformed {
        path: PathBuf,
        #[source]
        source: tobj::LoadError,
    },
    #[error("OBJ file {path} has no faces (after dropping {degenerate} degenerate ones)")]
    NoFaces { path: PathBuf, degenerate: usize },
    #[error("OBJ file {path} has more than 2^32 vertices")]
    TooLarge { path: PathBuf },
    #[error(
        "OBJ file {path} line {line}: face index {index} names no {what} (indices count from 1; \
         negative ones count back from the last one defined above)"
    )]
    BadIndex {
        path: PathBuf,
        line: usize,
        index: i64,
        what: ObjElement,
    },
}

/// What an OBJ face index names: `v/vt/vn`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ObjElement {
    Position,
    TexCoord,
    Normal,
}

impl std::fmt::Display for ObjElement {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            ObjElement::Position => "position",
            ObjElement::TexCoord => "texture coordinate",
            ObjElement::Normal => "normal",
        })
    }
}

impl Mesh {
    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// The three corner positions of triangle `t`.
    pub fn corners(&self, t: usize) -> [Vec3; 3] {
        let [a, b, c] = self.triangles[t];
        [
            self.positions[a as usize],
            self.positions[b as usize],
            self.positions[c as usize],
        ]
    }

    /// The mesh as one indexed GL_TRIANGLES draw: positions (x, y, z, 1), the unit normals
    /// as the normal array (absent when the mesh has none, so the current normal applies),
    /// and the index triples flattened in order, windings kept.
    pub fn to_geometry(&self) -> Geometry {
        let normals = (!self.normals.is_empty() && self.normals.len() == self.positions.len())
            .then(|| self.normals.clone());
        Geometry {
            primitive: Primitive::Triangles,
            positions: self.positions.iter().map(|p| p.extend(1.0)).collect(),
            normals,
            indices: Some(self.triangles.iter().flatten().copied().collect()),
            ..Geometry::default()
        }
    }

    /// Appends `other`, re-basing its indices.
    pub fn append(&mut self, other: &Mesh) {
        let base = self.positions.len() as u32;
        self.positions.extend_from_slice(&other.positions);
        self.normals.extend_from_slice(&other.normals);
        self.triangles.extend(
            other
                .triangles
                .iter()
                .map(|t| [t[0] + base, t[1] + base, t[2] + base]),
        );
    }

    /// This mesh under the model matrix `m`: p' = M p, n' = normalize((M₃⁻¹)ᵀ n).
    /// A mirroring matrix (det < 0) also reverses every winding so fronts stay fronts.
    pub fn transformed(&self, m: &Mat4) -> Mesh {
        let linear = Mat3::from_mat4(*m);
        let normal_matrix = linear.inverse().transpose();
        let mirrored = linear.determinant() < 0.0;
        Mesh {
            positions: self
                .positions
                .iter()
                .map(|p| m.transform_point3(*p))
                .collect(),
            normals: self
                .normals
                .iter()
                .map(|n| (normal_matrix * *n).normalize_or_zero())
                .collect(),
            triangles: if mirrored {
                self.triangles.iter().map(|t| [t[0], t[2], t[1]]).collect()
            } else {
                self.triangles.clone()
            },
        }
    }

    /// Removes triangles with a repeated index, an out-of-range index or zero area
    /// (|(b − a) × (c − a)| = 0 in f32); returns how many were removed.
    pub fn drop_degenerate(&mut self) -> usize {
        let before = self.triangles.len();
        let positions = &self.positions;
        self.triangles.retain(|t| {
            let n = positions.len() as u32;
            if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || t.iter().any(|&i| i >= n) {
                return false;
            }
            let [a, b, c] = t.map(|i| positions[i as usize]);
            let cross = (b - a).cross(c - a);
            cross.length_squared() > 0.0 && cross.is_finite()
        });
        before - self.triangles.len()
    }

    /// Replaces the normals by the area-weighted average of the adjacent face normals:
    /// n_v = normalize(Σ (b − a) × (c − a)) over the triangles using v.
    pub fn compute_normals(&mut self) {
        let mut sums = vec![Vec3::ZERO; self.positions.len()];
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| self.positions[i as usize]);
            let n = (b - a).cross(c - a);
            for &i in t {
                sums[i as usize] += n;
            }
        }
        self.normals = sums.into_iter().map(|n| n.normalize_or_zero()).collect();
    }

    /// Merges vertices with bit-identical positions (the first one's normal is kept) and
    /// re-indexes the triangles. Used after tessellating patches whose shared edges are
    /// evaluated from the same control points in the same order.
    pub fn weld(&mut self) {
        let mut first: HashMap<[u32; 3], u32> = HashMap::new();
        let mut remap = Vec::with_capacity(self.positions.len());
        let mut positions = Vec::new();
        let mut normals = Vec::new();
        for (i, p) in self.positions.iter().enumerate() {
            let key = position_key(*p);
            let index = *first.entry(key).or_insert_with(|| {
                positions.push(*p);
                normals.push(self.normals.get(i).copied().unwrap_or(Vec3::ZERO));
                (positions.len() - 1) as u32
            });
            remap.push(index);
        }
        for t in &mut self.triangles {
            *t = t.map(|i| remap[i as usize]);
        }
        self.positions = positions;
        self.normals = normals;
    }

    /// Whether every edge is shared by exactly two triangles, vertices being identified by
    /// their exact position (so a box with per-face vertices still counts as closed).
    pub fn is_closed(&self) -> bool {
        let key = |i: u32| position_key(self.positions[i as usize]);
        let mut edges: HashMap<([u32; 3], [u32; 3]), u32> = HashMap::new();
        for t in &self.triangles {
            for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                let (ka, kb) = (key(a), key(b));
                let edge = if ka < kb { (ka, kb) } else { (kb, ka) };
                *edges.entry(edge).or_insert(0) += 1;
            }
        }
        !edges.is_empty() && edges.values().all(|&n| n == 2)
    }

    /// Axis-aligned bounds (min, max); `None` for an empty mesh.
    pub fn bounds(&self) -> Option<(Vec3, Vec3)> {
        let first = *self.positions.first()?;
        Some(
            self.positions
                .iter()
                .fold((first, first), |(lo, hi), p| (lo.min(*p), hi.max(*p))),
        )
    }
}

/// The bits of a position with −0 folded into +0 (x + 0 = +0 for x = −0), so vertices
/// reached through a negation weld with those computed directly.
fn position_key(p: Vec3) -> [u32; 3] {
    (p + Vec3::ZERO).to_array().map(f32::to_bits)
}

#[cfg(test)]
mod tests;
