//! The file's shape, as serde reads it: every table `deny_unknown_fields`, every value that
//! validation may reject wrapped in `Spanned` so its error can name the line.
//! Values stay optional here; `build` supplies defaults and checks what each kind needs.

use crate::vocab::{MapFilter, PlanarMode, Precision, Projector, ReadbackRule};
use serde::Deserialize;
use toml::Spanned;

pub(super) type S<T> = Option<Spanned<T>>;

/// Exactly `N` numbers, written as a TOML array. serde's `[f32; N]` takes the first N
/// values of a longer array and drops the rest without a word (`eye = [0, 9, 20, 1]`
/// loaded as [0, 9, 20]); this reads them all and refuses any other count, so the error
/// names the key and its line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Numbers<const N: usize>(pub [f32; N]);

impl<'de, const N: usize> Deserialize<'de> for Numbers<N> {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor<const N: usize>;
        impl<'de, const N: usize> serde::de::Visitor<'de> for Visitor<N> {
            type Value = Numbers<N>;

            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                write!(f, "an array of {N} numbers ({})", components(N))
            }

            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<Self::Value, A::Error> {
                let mut values = [0.0f32; N];
                let mut count = 0usize;
                while let Some(v) = seq.next_element::<f32>()? {
                    if let Some(slot) = values.get_mut(count) {
                        *slot = v;
                    }
                    count += 1;
                }
                if count == N {
                    Ok(Numbers(values))
                } else {
                    Err(serde::de::Error::custom(format!(
                        "expected {N} values ({}), found {count}",
                        components(N)
                    )))
                }
            }
        }
        deserializer.deserialize_seq(Visitor::<N>)
    }
}

/// What the numbers of a `Numbers<N>` are.
fn components(n: usize) -> &'static str {
    match n {
        2 => "width, height",
        3 => "x, y, z",
        _ => "numbers",
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawScene {
    pub camera: S<RawCamera>,
    pub image: S<RawImage>,
    #[serde(default)]
    pub light: Vec<Spanned<RawLight>>,
    #[serde(default)]
    pub object: Vec<Spanned<RawObject>>,
    pub shadow: S<RawShadow>,
    pub truth: S<RawTruth>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawCamera {
    pub eye: S<Numbers<3>>,
    pub at: S<Numbers<3>>,
    pub up: S<Numbers<3>>,
    pub fovy: S<f32>,
    pub near: S<f32>,
    pub far: S<f32>,
    pub ortho: S<RawOrtho>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawOrtho {
    pub left: Spanned<f32>,
    pub right: Spanned<f32>,
    pub bottom: Spanned<f32>,
    pub top: Spanned<f32>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawImage {
    pub width: S<u32>,
    pub height: S<u32>,
    pub background: S<Numbers<3>>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub(super) enum LightType {
    Point,
    Spot,
    Directional,
    Area,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawLight {
    #[serde(rename = "type")]
    pub kind: Spanned<LightType>,
    pub position: S<Numbers<3>>,
    pub at: S<Numbers<3>>,
    pub up: S<Numbers<3>>,
    pub fovy: S<f32>,
    pub near: S<f32>,
    pub far: S<f32>,
    pub cutoff: S<f32>,
    pub exponent: S<f32>,
    pub direction: S<Numbers<3>>,
    /// A sun's full apparent diameter, degrees.
    pub angular_diameter: S<f32>,
    pub extent: S<f32>,
    pub distance: S<f32>,
    pub corner: S<Numbers<3>>,
    pub edge_u: S<Numbers<3>>,
    pub edge_v: S<Numbers<3>>,
    pub centre: S<Numbers<3>>,
    pub size: S<Numbers<2>>,
    pub colour: S<Numbers<3>>,
    pub intensity: S<f32>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub(super) enum ShapeType {
    Plane,
    Box,
    Sphere,
    Torus,
    Teapot,
    Aircraft,
}

/// `layout` of an aircraft.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub(super) enum AircraftLayoutName {
    Fighter,
    F35,
}

/// `[[object.plane]]`: a shadow plane of the object (object space).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawPlane {
    pub origin: S<Numbers<3>>,
    pub normal: S<Numbers<3>>,
    pub up: S<Numbers<3>>,
    pub right: S<Numbers<3>>,
    pub width: S<f32>,
    pub height: S<f32>,
    pub occluder: S<RawOccluder>,
}

/// `[[object.section]]`: a part of the object for `occluder-planes` — the clip plane that
/// keeps it (none on the last, which takes the rest) and the planes it looks up.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSection {
    pub cut: S<Numbers<4>>,
    pub planes: S<Vec<Spanned<u32>>>,
}

/// `occluder = "silhouette" | "black"` or a table: `{ png = "file.png" }` or the
/// silhouette's recipe `{ size, depth, dilate, extend }`.
#[derive(Debug, Deserialize)]
#[serde(untagged)]
pub(super) enum RawOccluder {
    Named(String),
    Table(RawOccluderTable),
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawOccluderTable {
    pub png: Option<String>,
    pub size: Option<u32>,
    pub depth: Option<f32>,
    pub dilate: Option<u32>,
    pub extend: Option<u32>,
}

/// A size written as one number or as [x, y, z].
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(untagged)]
pub(super) enum Extent {
    Uniform(f32),
    PerAxis(Numbers<3>),
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawRotation {
    pub axis: Numbers<3>,
    pub degrees: f32,
}

/// `rotate = { axis, degrees }` or a list of them, applied left to right.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub(super) enum Rotations {
    One(RawRotation),
    Many(Vec<RawRotation>),
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawObject {
    pub name: Option<String>,
    pub shape: S<ShapeType>,
    pub mesh: S<String>,
    pub size: S<Extent>,
    pub tessellation: S<u32>,
    pub radius: S<f32>,
    pub slices: S<u32>,
    pub stacks: S<u32>,
    pub major_radius: S<f32>,
    pub minor_radius: S<f32>,
    pub rings: S<u32>,
    pub sides: S<u32>,
    pub length: S<f32>,
    pub layout: S<AircraftLayoutName>,
    #[serde(default)]
    pub plane: Vec<Spanned<RawPlane>>,
    #[serde(default)]
    pub section: Vec<Spanned<RawSection>>,
    pub translate: S<Numbers<3>>,
    pub rotate: S<Rotations>,
    pub scale: S<Extent>,
    pub colour: S<Numbers<3>>,
    pub specular: S<Numbers<3>>,
    pub shininess: S<f32>,
    pub casts: Option<bool>,
    pub receives: Option<bool>,
}

/// `depth_bits = 16`, `24` or `"32f"`.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub(super) enum DepthBitsValue {
    Int(i64),
    Text(String),
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawOffset {
    pub factor: f32,
    pub units: f32,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawShadow {
    pub technique: S<String>,
    pub map_size: S<u32>,
    pub depth_bits: S<DepthBitsValue>,
    pub polygon_offset: S<RawOffset>,
    pub precision: Option<Precision>,
    pub readback: Option<ReadbackRule>,
    pub filter: Option<MapFilter>,
    pub planar_mode: Option<PlanarMode>,
    pub projector: Option<Projector>,
    pub light_samples: S<u32>,
    pub slices: S<u32>,
    pub prefilter: Option<super::occlusion::Prefilter>,
    pub combine: Option<super::occlusion::Combine>,
    pub program: Option<super::planes::OccluderProgram>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawTruth {
    pub samples: S<u32>,
}
