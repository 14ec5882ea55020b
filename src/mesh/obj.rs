//! Wavefront OBJ through tobj: faces triangulated as fans (v0, vᵢ, vᵢ₊₁), one index per
//! vertex (position and normal indices merged), negative (relative) indices resolved by
//! tobj. Materials are ignored: the scene file gives the material.
//!
//! A face index of 0, a negative one that reaches before the first element, or one past
//! u32 is refused with its line before tobj reads the file: tobj would take 0 as "no
//! normal", and wrap the others round to indices whose bounds check overflows.
//!
//! Degenerate faces (repeated vertices or zero area) are dropped and counted; the caller
//! reports the count as a warning. A file whose faces are all degenerate, or that has none,
//! is an error. Normals are computed from the faces for every object of the file that has
//! none (or not one per vertex).

use super::{Mesh, MeshError, ObjElement};
use glam::Vec3;
use std::path::Path;

/// A loaded OBJ file and what loading it did.
#[derive(Debug, Clone, PartialEq)]
pub struct ObjMesh {
    pub mesh: Mesh,
    /// Degenerate triangles dropped.
    pub degenerate: usize,
    /// Whether any normals had to be computed.
    pub computed_normals: bool,
}

/// Loads `path`.
pub fn load_obj(path: &Path) -> Result<ObjMesh, MeshError> {
    let text = std::fs::read_to_string(path).map_err(|source| MeshError::Unreadable {
        path: path.to_path_buf(),
        source,
    })?;
    load_obj_str(&text, path)
}

/// Parses OBJ text; `path` only names the source in errors.
pub fn load_obj_str(text: &str, path: &Path) -> Result<ObjMesh, MeshError> {
    check_face_indices(text, path)?;
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let mut reader = std::io::BufReader::new(text.as_bytes());
    let (models, _materials) = tobj::load_obj_buf(&mut reader, &options, |_| {
        Err(tobj::LoadError::GenericFailure)
    })
    .map_err(|source| MeshError::Malformed {
        path: path.to_path_buf(),
        source,
    })?;
    let mut result = ObjMesh {
        mesh: Mesh::default(),
        degenerate: 0,
        computed_normals: false,
    };
    for model in models {
        let m = &model.mesh;
        let positions: Vec<Vec3> = m
            .positions
            .chunks_exact(3)
            .map(|c| Vec3::new(c[0], c[1], c[2]))
            .collect();
        let has_normals = m.normals.len() == m.positions.len() && !m.normals.is_empty();
        let mut part = Mesh {
            normals: if has_normals {
                m.normals
                    .chunks_exact(3)
                    .map(|c| Vec3::new(c[0], c[1], c[2]).normalize_or_zero())
                    .collect()
            } else {
                Vec::new()
            },
            positions,
            triangles: m
                .indices
                .chunks_exact(3)
                .map(|c| [c[0], c[1], c[2]])
                .collect(),
        };
        result.degenerate += part.drop_degenerate();
        if !has_normals {
            part.compute_normals();
            result.computed_normals = true;
        }
        if u32::try_from(result.mesh.positions.len() + part.positions.len()).is_err() {
            return Err(MeshError::TooLarge {
                path: path.to_path_buf(),
            });
        }
        result.mesh.append(&part);
    }
    if result.mesh.triangles.is_empty() {
        return Err(MeshError::NoFaces {
            path: path.to_path_buf(),
            degenerate: result.degenerate,
        });
    }
    Ok(result)
}

/// Refuses the face indices tobj mishandles (see the module note). Lines are split as
/// tobj splits them; what is not an integer is left to tobj to refuse.
fn check_face_indices(text: &str, path: &Path) -> Result<(), MeshError> {
    const WHAT: [ObjElement; 3] = [
        ObjElement::Position,
        ObjElement::TexCoord,
        ObjElement::Normal,
    ];
    // Positions, texture coordinates and normals defined so far.
    let mut defined = [0i64; 3];
    for (n, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => defined[0] += 1,
            Some("vt") => defined[1] += 1,
            Some("vn") => defined[2] += 1,
            Some("f") => {
                for word in words {
                    for (k, part) in word.split('/').enumerate().take(3) {
                        let Ok(index) = part.parse::<i64>() else {
                            continue;
                        };
                        if index == 0 || index > i64::from(u32::MAX) || defined[k] + index < 0 {
                            return Err(MeshError::BadIndex {
                                path: path.to_path_buf(),
                                line: n + 1,
                                index,
                                what: WHAT[k],
                            });
                        }
                    }
                }
            }
            _ => {}
        }
    }
    Ok(())
}
