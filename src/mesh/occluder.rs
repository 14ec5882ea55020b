//! Occluder textures (Coleman, thesis 003 §4.3 and §5): for each shadow plane, a black on
//! white picture of the part of the object the plane stands for, seen orthographically
//! along the plane's normal. The thesis rendered that view in a modelling package and
//! finished it by hand; here a recipe makes it, so every path (fixed-function texgen, the
//! CPU model, a shader) reads the same texels.
//!
//! **The recipe** ([`OccluderRecipe`]): the triangles whose three corners all lie within
//! `depth` of the plane (|n · (p − o)| ≤ depth) are the part; each is projected onto the
//! plane's (right, up) frame, s = right · (p − o) / width, t = up · (p − o) / height, and a
//! texel is black when its centre ((i + ½) / size, (j + ½) / size) lies inside or on the
//! edge of a projected triangle. Then two stated dilations:
//! - `dilate`: every texel within `dilate` texels (Chebyshev distance) of a black one turns
//!   black — the raster edge then never falls short of the geometric one;
//! - `extend`: every black texel also blackens the `extend` texels below it (towards −up,
//!   t decreasing) — the thesis's "extend the shape of the tail fin downward so that the
//!   black silhouette penetrated down into the object rather than just touching the edge"
//!   (§5), done towards the object the plane is attached to.
//!
//! **Why the rasteriser is written by hand**: it is twenty lines of edge functions on
//! projected triangles into one byte per texel; the crates that rasterise (tiny-skia, the
//! GPU) bring anti-aliasing, colour spaces or a context that a pure, testable table does not
//! want, and its rule (texel centres, edges included) must be stated exactly for the CPU
//! model to agree with it.
//!
//! Texels are stored as GL reads them: row j = 0 is t = 0 (the bottom), 0 black (the
//! occluder: no light passes), 255 white (light passes).

use super::Mesh;
use glam::{Vec2, Vec3};
use std::path::{Path, PathBuf};

/// A shadow plane: an occluder texture of `width` × `height` laid on the plane through
/// `origin` with unit `normal`, its s axis along unit `right` and its t axis along unit
/// `up` (origin is the texture's corner s = t = 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlaneFrame {
    pub origin: Vec3,
    pub normal: Vec3,
    pub up: Vec3,
    pub right: Vec3,
    pub width: f32,
    pub height: f32,
}

/// Why a frame is not one: what [`PlaneFrame::check`] refuses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum FrameProblem {
    #[error("must not be the zero vector")]
    ZeroVector,
    #[error("is not perpendicular to `{other}` (the frame's axes must be orthogonal to within 1e-3 after normalising)")]
    NotOrthogonal { other: FrameAxis },
}

/// An axis of a frame, as named in the scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrameAxis {
    Normal,
    Up,
    Right,
}

impl std::fmt::Display for FrameAxis {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            FrameAxis::Normal => "normal",
            FrameAxis::Up => "up",
            FrameAxis::Right => "right",
        })
    }
}

/// |cos| above which two unit axes are not taken as perpendicular.
const ORTHOGONAL_TOLERANCE: f32 = 1e-3;

impl PlaneFrame {
    /// The frame with its three axes normalised, or which axis is wrong and why: a zero
    /// vector, two axes not perpendicular (|a · b| > 1e-3 once normalised).
    pub fn normalised(mut self) -> Result<PlaneFrame, (FrameAxis, FrameProblem)> {
        for (axis, v) in [
            (FrameAxis::Normal, &mut self.normal),
            (FrameAxis::Up, &mut self.up),
            (FrameAxis::Right, &mut self.right),
        ] {
            if v.length_squared() == 0.0 {
                return Err((axis, FrameProblem::ZeroVector));
            }
            *v = v.normalize();
        }
        for (a, va, b, vb) in [
            (FrameAxis::Up, self.up, FrameAxis::Normal, self.normal),
            (FrameAxis::Right, self.right, FrameAxis::Normal, self.normal),
            (FrameAxis::Right, self.right, FrameAxis::Up, self.up),
        ] {
            if va.dot(vb).abs() > ORTHOGONAL_TOLERANCE {
                return Err((a, FrameProblem::NotOrthogonal { other: b }));
            }
        }
        Ok(self)
    }

    /// (s, t) of `p` projected along the normal, and its signed distance n · (p − o).
    pub fn project(&self, p: Vec3) -> (Vec2, f32) {
        let d = p - self.origin;
        (
            Vec2::new(self.right.dot(d) / self.width, self.up.dot(d) / self.height),
            self.normal.dot(d),
        )
    }
}

/// How an occluder texture is made from the object's mesh (see the module note).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OccluderRecipe {
    /// Edge of the square texture in texels. Default 256 (the thesis's 256×256).
    pub size: u32,
    /// Half-thickness of the slab, along the normal, whose triangles make the silhouette
    /// (metres of object space). Default 0.1.
    pub depth: f32,
    /// Isotropic dilation, texels (Chebyshev). Default 1.
    pub dilate: u32,
    /// Extension towards −up, texels. Default 0.
    pub extend: u32,
}

impl Default for OccluderRecipe {
    fn default() -> Self {
        OccluderRecipe {
            size: 256,
            depth: 0.1,
            dilate: 1,
            extend: 0,
        }
    }
}

/// Where a plane's occluder texture comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum OccluderSource {
    /// Generated from the object's mesh.
    Silhouette(OccluderRecipe),
    /// Every texel black: the whole rectangle occludes (the thesis's handle planes, §5:
    /// "the occluder texture was assumed to be solid black").
    Black,
    /// A hand-made picture (any PNG, converted to 8-bit luminance; its top row is t = 1).
    Png(PathBuf),
}

/// An 8-bit luminance texture, rows bottom (t = 0) first.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OccluderTexture {
    pub width: u32,
    pub height: u32,
    pub texels: Vec<u8>,
}

/// The occluder's value: black occludes.
pub const OCCLUDES: u8 = 0;
/// The occluder's value where light passes.
pub const PASSES: u8 = 255;

/// Failures making an occluder texture.
#[derive(Debug, thiserror::Error)]
pub enum OccluderError {
    #[error("cannot read occluder picture {path}: {source}")]
    Png {
        path: PathBuf,
        #[source]
        source: Box<image::ImageError>,
    },
}

impl OccluderTexture {
    /// The texel holding (s, t) ∈ [0, 1]², NEAREST sampling; [`PASSES`] outside (the white
    /// border of CLAMP_TO_BORDER).
    pub fn nearest(&self, st: Vec2) -> u8 {
        if !(0.0..=1.0).contains(&st.x) || !(0.0..=1.0).contains(&st.y) {
            return PASSES;
        }
        let i = ((st.x * self.width as f32).floor() as i64).clamp(0, self.width as i64 - 1);
        let j = ((st.y * self.height as f32).floor() as i64).clamp(0, self.height as i64 - 1);
        self.texels[j as usize * self.width as usize + i as usize]
    }

    /// Texels that occlude.
    pub fn black_count(&self) -> usize {
        self.texels.iter().filter(|&&t| t == OCCLUDES).count()
    }
}

/// The texture of `source` for the plane `frame` of `mesh` (object space). `Black` is
/// `black_size`² texels (with LINEAR filtering and a white border, the look-up falls to ½
/// half a texel inside the rectangle's edge).
pub fn occluder_texture(
    mesh: &Mesh,
    frame: &PlaneFrame,
    source: &OccluderSource,
    black_size: u32,
) -> Result<OccluderTexture, OccluderError> {
    match source {
        OccluderSource::Silhouette(recipe) => Ok(silhouette(mesh, frame, recipe)),
        OccluderSource::Black => Ok(OccluderTexture {
            width: black_size,
            height: black_size,
            texels: vec![OCCLUDES; (black_size * black_size) as usize],
        }),
        OccluderSource::Png(path) => load_png(path),
    }
}

/// A PNG as 8-bit luminance, flipped so that its bottom row is t = 0.
pub fn load_png(path: &Path) -> Result<OccluderTexture, OccluderError> {
    let picture = image::open(path).map_err(|source| OccluderError::Png {
        path: path.to_path_buf(),
        source: Box::new(source),
    })?;
    let grey = image::imageops::flip_vertical(&picture.to_luma8());
    Ok(OccluderTexture {
        width: grey.width(),
        height: grey.height(),
        texels: grey.into_raw(),
    })
}

/// The silhouette of the triangles of `mesh` within `recipe.depth` of the plane,
/// rasterised at texel centres and dilated (module note).
pub fn silhouette(mesh: &Mesh, frame: &PlaneFrame, recipe: &OccluderRecipe) -> OccluderTexture {
    let n = recipe.size.max(1) as usize;
    let mut black = vec![false; n * n];
    for t in 0..mesh.triangle_count() {
        let projected = mesh.corners(t).map(|p| frame.project(p));
        if projected.iter().any(|(_, d)| d.abs() > recipe.depth) {
            continue;
        }
        cover(&mut black, n, projected.map(|(st, _)| st * n as f32));
    }
    let black = extend_down(
        &dilate(&black, n, recipe.dilate as usize),
        n,
        recipe.extend as usize,
    );
    OccluderTexture {
        width: n as u32,
        height: n as u32,
        texels: black
            .into_iter()
            .map(|b| if b { OCCLUDES } else { PASSES })
            .collect(),
    }
}

/// Marks the texels of the n × n grid whose centres lie inside or on triangle `v` (texel
/// units). Inside ⇔ the three edge functions e(a, b, p) = (b − a) × (p − a) share the sign
/// of the triangle's area (zero counts as inside); a zero-area triangle covers nothing.
fn cover(black: &mut [bool], n: usize, v: [Vec2; 3]) {
    let edge = |a: Vec2, b: Vec2, p: Vec2| (b - a).perp_dot(p - a);
    let area = edge(v[0], v[1], v[2]);
    if area == 0.0 || !area.is_finite() {
        return;
    }
    let lo = v[0].min(v[1]).min(v[2]);
    let hi = v[0].max(v[1]).max(v[2]);
    // Texel i's centre is i + ½: the columns with lo ≤ i + ½ ≤ hi.
    let first = |x: f32| ((x - 0.5).ceil().max(0.0)) as usize;
    let last = |x: f32| ((x - 0.5).floor().min(n as f32 - 1.0)) as i64;
    let (i0, i1) = (first(lo.x), last(hi.x));
    let (j0, j1) = (first(lo.y), last(hi.y));
    for j in j0 as i64..=j1 {
        for i in i0 as i64..=i1 {
            let p = Vec2::new(i as f32 + 0.5, j as f32 + 0.5);
            let e = [
                edge(v[0], v[1], p),
                edge(v[1], v[2], p),
                edge(v[2], v[0], p),
            ];
            if e.iter().all(|&x| x * area.signum() >= 0.0) {
                black[j as usize * n + i as usize] = true;
            }
        }
    }
}

/// Black wherever a black texel lies within `r` texels (max(|di|, |dj|) ≤ r).
fn dilate(black: &[bool], n: usize, r: usize) -> Vec<bool> {
    if r == 0 {
        return black.to_vec();
    }
    // Separable: rows, then columns.
    let along = |src: &[bool], step: (usize, usize)| -> Vec<bool> {
        let mut out = vec![false; n * n];
        for j in 0..n {
            for i in 0..n {
                if !src[j * n + i] {
                    continue;
                }
                let (lo, hi) = if step.0 == 1 {
                    (i.saturating_sub(r), (i + r).min(n - 1))
                } else {
                    (j.saturating_sub(r), (j + r).min(n - 1))
                };
                for k in lo..=hi {
                    let at = if step.0 == 1 { j * n + k } else { k * n + i };
                    out[at] = true;
                }
            }
        }
        out
    };
    along(&along(black, (1, 0)), (0, 1))
}

/// Each black texel also blackens the `r` texels below it (j − 1 … j − r).
fn extend_down(black: &[bool], n: usize, r: usize) -> Vec<bool> {
    let mut out = black.to_vec();
    for j in 0..n {
        for i in 0..n {
            if black[j * n + i] {
                for k in j.saturating_sub(r)..j {
                    out[k * n + i] = true;
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn z_frame() -> PlaneFrame {
        PlaneFrame {
            origin: Vec3::ZERO,
            normal: Vec3::Z,
            up: Vec3::Y,
            right: Vec3::X,
            width: 4.0,
            height: 4.0,
        }
    }

    fn square(lo: Vec2, hi: Vec2, z: f32) -> Mesh {
        Mesh {
            positions: vec![
                lo.extend(z),
                Vec3::new(hi.x, lo.y, z),
                hi.extend(z),
                Vec3::new(lo.x, hi.y, z),
            ],
            normals: vec![Vec3::Z; 4],
            triangles: vec![[0, 1, 2], [0, 2, 3]],
        }
    }

    fn recipe(size: u32, dilate: u32, extend: u32) -> OccluderRecipe {
        OccluderRecipe {
            size,
            depth: 0.1,
            dilate,
            extend,
        }
    }

    #[test]
    fn a_square_covers_the_texels_whose_centres_it_holds() {
        // 8 texels over 4 m: texel i spans [i/2, (i+1)/2) m, centre at i/2 + 1/4.
        // The square [1, 2]² m holds centres 1.25, 1.75 → texels 2 and 3 per axis.
        let mesh = square(Vec2::splat(1.0), Vec2::splat(2.0), 0.0);
        let tex = silhouette(&mesh, &z_frame(), &recipe(8, 0, 0));
        let black: Vec<(usize, usize)> = (0..64)
            .filter(|k| tex.texels[*k] == OCCLUDES)
            .map(|k| (k % 8, k / 8))
            .collect();
        assert_eq!(black, vec![(2, 2), (3, 2), (2, 3), (3, 3)]);
        // Edges count: the square [0.75, 1.25]² m has the centres 0.75 and 1.25 (texels 1
        // and 2) on its edges.
        let edge = square(Vec2::splat(0.75), Vec2::splat(1.25), 0.0);
        let tex = silhouette(&edge, &z_frame(), &recipe(8, 0, 0));
        assert_eq!(
            tex.black_count(),
            4,
            "centres 0.75 and 1.25 are on the edges"
        );
    }

    #[test]
    fn triangles_beyond_the_depth_or_edge_on_cover_nothing() {
        let far = square(Vec2::splat(1.0), Vec2::splat(2.0), 0.5);
        assert_eq!(
            silhouette(&far, &z_frame(), &recipe(8, 0, 0)).black_count(),
            0
        );
        // A wall standing on the plane projects to a line: zero area.
        let wall = Mesh {
            positions: vec![
                Vec3::new(1.0, 1.0, 0.0),
                Vec3::new(2.0, 1.0, 0.0),
                Vec3::new(2.0, 1.0, 0.05),
            ],
            normals: vec![Vec3::Y; 3],
            triangles: vec![[0, 1, 2]],
        };
        assert_eq!(
            silhouette(&wall, &z_frame(), &recipe(8, 0, 0)).black_count(),
            0
        );
    }

    #[test]
    fn dilation_grows_by_r_each_way_and_extension_only_downwards() {
        let mesh = square(Vec2::splat(1.0), Vec2::splat(2.0), 0.0);
        // 2×2 texels grown by 1: 4×4.
        assert_eq!(
            silhouette(&mesh, &z_frame(), &recipe(8, 1, 0)).black_count(),
            16
        );
        // Extended by 2 downwards: rows 0..=3 of columns 2, 3.
        let tex = silhouette(&mesh, &z_frame(), &recipe(8, 0, 2));
        assert_eq!(tex.black_count(), 8);
        assert_eq!(tex.nearest(Vec2::new(0.3, 0.01)), OCCLUDES);
        assert_eq!(tex.nearest(Vec2::new(0.3, 0.6)), PASSES);
        // Clamped at the border: a big extension stops at row 0.
        assert_eq!(
            silhouette(&mesh, &z_frame(), &recipe(8, 0, 50)).black_count(),
            8
        );
    }

    #[test]
    fn frames_are_normalised_and_bad_ones_named() {
        let mut f = z_frame();
        f.up = Vec3::new(0.0, 3.0, 0.0);
        assert_eq!(f.normalised().unwrap().up, Vec3::Y);
        f.right = Vec3::ZERO;
        assert_eq!(
            f.normalised(),
            Err((FrameAxis::Right, FrameProblem::ZeroVector))
        );
        let mut g = z_frame();
        g.up = Vec3::new(0.0, 1.0, 0.1);
        assert_eq!(
            g.normalised(),
            Err((
                FrameAxis::Up,
                FrameProblem::NotOrthogonal {
                    other: FrameAxis::Normal
                }
            ))
        );
    }

    #[test]
    fn rows_start_at_the_bottom() {
        // A triangle in the top-left corner (s small, t large) → high row index.
        let mesh = Mesh {
            positions: vec![
                Vec3::new(0.0, 3.0, 0.0),
                Vec3::new(1.0, 4.0, 0.0),
                Vec3::new(0.0, 4.0, 0.0),
            ],
            normals: vec![Vec3::Z; 3],
            triangles: vec![[0, 1, 2]],
        };
        let tex = silhouette(&mesh, &z_frame(), &recipe(4, 0, 0));
        assert_eq!(tex.texels[3 * 4], OCCLUDES, "row 3 = t ∈ [0.75, 1]");
        assert_eq!(tex.texels[0], PASSES);
    }
}
