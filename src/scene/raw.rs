//! The file's shape, as serde reads it: every table `deny_unknown_fields`, every value that
//! validation may reject wrapped in `Spanned` so its error can name the line.
//! Values stay optional here; `build` supplies defaults and checks what each kind needs.

use crate::vocab::{MapFilter, PlanarMode, Precision, Projector, ReadbackRule};
use serde::Deserialize;
use toml::Spanned;

pub(super) type S<T> = Option<Spanned<T>>;

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
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawCamera {
    pub eye: S<[f32; 3]>,
    pub at: S<[f32; 3]>,
    pub up: S<[f32; 3]>,
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
    pub background: S<[f32; 3]>,
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
    pub position: S<[f32; 3]>,
    pub at: S<[f32; 3]>,
    pub up: S<[f32; 3]>,
    pub fovy: S<f32>,
    pub near: S<f32>,
    pub far: S<f32>,
    pub cutoff: S<f32>,
    pub exponent: S<f32>,
    pub direction: S<[f32; 3]>,
    pub extent: S<f32>,
    pub distance: S<f32>,
    pub corner: S<[f32; 3]>,
    pub edge_u: S<[f32; 3]>,
    pub edge_v: S<[f32; 3]>,
    pub centre: S<[f32; 3]>,
    pub size: S<[f32; 2]>,
    pub colour: S<[f32; 3]>,
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

/// A size written as one number or as [x, y, z].
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(untagged)]
pub(super) enum Extent {
    Uniform(f32),
    PerAxis([f32; 3]),
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawRotation {
    pub axis: [f32; 3],
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
    pub translate: S<[f32; 3]>,
    pub rotate: S<Rotations>,
    pub scale: S<Extent>,
    pub colour: S<[f32; 3]>,
    pub specular: S<[f32; 3]>,
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
}
