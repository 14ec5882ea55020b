//! The validated scene: every number finite and in range, every mesh loaded.

use crate::mesh::occluder::{OccluderSource, OccluderTexture, PlaneFrame};
use crate::mesh::{self, AircraftLayout, Mesh};
use crate::vocab::{
    default_offset, DepthBits, MapFilter, OffsetSource, PlanarMode, PolygonOffset, Precision,
    Projector, ReadbackRule, TechniqueId,
};
use glam::{Mat4, Vec3};

use std::path::PathBuf;
use std::sync::Arc;

use super::error::SceneWarning;
use super::limits::Limits;

/// A parsed, validated scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub camera: Camera,
    pub image: ImageSpec,
    pub lights: Vec<Light>,
    pub objects: Vec<Object>,
    pub shadow: ShadowSettings,
    /// The `[truth]` table: how the ray-cast ground truth is computed.
    pub truth: TruthSettings,
    /// What loading accepted but dropped (e.g. degenerate OBJ faces).
    pub warnings: Vec<SceneWarning>,
    /// The budgets it was loaded under; a run checks its own needs against them too.
    pub limits: Limits,
}

/// A gluLookAt view with a gluPerspective or glOrtho projection. Also a light's
/// shadow-map view.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    pub eye: Vec3,
    pub at: Vec3,
    pub up: Vec3,
    pub projection: Projection,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Projection {
    /// gluPerspective(fovy, aspect, near, far), fovy in degrees.
    Perspective { fovy: f32, near: f32, far: f32 },
    /// glOrtho(left, right, bottom, top, near, far).
    Orthographic {
        left: f32,
        right: f32,
        bottom: f32,
        top: f32,
        near: f32,
        far: f32,
    },
}

impl Camera {
    /// gluLookAt(eye, at, up).
    pub fn view(&self) -> Mat4 {
        glam::camera::rh::view::look_at_mat4(self.eye, self.at, self.up)
    }

    /// The projection matrix for a viewport of `aspect` = width / height (GL clip space,
    /// z in [−w, w]).
    pub fn projection_matrix(&self, aspect: f32) -> Mat4 {
        match self.projection {
            Projection::Perspective { fovy, near, far } => {
                glam::camera::rh::proj::opengl::perspective(fovy.to_radians(), aspect, near, far)
            }
            Projection::Orthographic {
                left,
                right,
                bottom,
                top,
                near,
                far,
            } => glam::camera::rh::proj::opengl::orthographic(left, right, bottom, top, near, far),
        }
    }
}

/// The output image.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImageSpec {
    pub width: u32,
    pub height: u32,
    /// Clear colour, RGB in [0, 1].
    pub background: Vec3,
}

/// A light and the view its shadow map is rendered from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Light {
    pub kind: LightKind,
    /// The shadow map's view: from the light's position (or the area light's centre, or a
    /// point back along a directional light) towards its target.
    pub view: Camera,
    pub colour: Vec3,
    pub intensity: f32,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LightKind {
    /// An omnidirectional light at `view.eye`.
    Point,
    /// A spot light at `view.eye` aimed at `view.at`; GL_SPOT_CUTOFF and GL_SPOT_EXPONENT.
    Spot { cutoff: f32, exponent: f32 },
    /// Light travelling along `direction` (GL position w = 0, pointing at −direction).
    /// A sun when `angular_diameter` > 0: the source is a disc of that full apparent
    /// diameter, in radians, centred on −direction (scene key `angular_diameter`, in
    /// degrees, (0, 30]); 0 is a hard directional light. The hard mask is the centre's.
    Directional {
        direction: Vec3,
        angular_diameter: f32,
    },
    /// A rectangle corner + s·edge_u + t·edge_v, s, t ∈ [0, 1], emitting on both sides.
    Area {
        corner: Vec3,
        edge_u: Vec3,
        edge_v: Vec3,
    },
}

impl Light {
    /// The sun's disc when this is a directional light with an angular size; `None` for
    /// every other light, a hard directional one included.
    pub fn sun(&self) -> Option<super::SunDisc> {
        match self.kind {
            LightKind::Directional {
                direction,
                angular_diameter,
            } if angular_diameter > 0.0 => Some(super::SunDisc::new(direction, angular_diameter)),
            _ => None,
        }
    }

    /// Whether the light has a size, so that its shadows are judged by visibility: an
    /// area light or a sun.
    pub fn is_soft(&self) -> bool {
        matches!(self.kind, LightKind::Area { .. }) || self.sun().is_some()
    }

    /// The point the hard shadow is cast from: the position, or an area light's centre;
    /// `None` for a directional light.
    pub fn position(&self) -> Option<Vec3> {
        match self.kind {
            LightKind::Point | LightKind::Spot { .. } => Some(self.view.eye),
            LightKind::Area {
                corner,
                edge_u,
                edge_v,
            } => Some(corner + 0.5 * (edge_u + edge_v)),
            LightKind::Directional { .. } => None,
        }
    }
}

/// A shape with its parameters, as written in the scene.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    Plane {
        size: f32,
        tessellation: u32,
    },
    Box {
        size: Vec3,
    },
    Sphere {
        radius: f32,
        slices: u32,
        stacks: u32,
    },
    Torus {
        major_radius: f32,
        minor_radius: f32,
        rings: u32,
        sides: u32,
    },
    Teapot {
        size: f32,
        tessellation: u32,
    },
    Aircraft {
        layout: AircraftLayout,
    },
    /// An OBJ file, resolved against the scene file's folder.
    Obj {
        path: PathBuf,
    },
}

impl Shape {
    /// The object-space mesh of a procedural shape (`None` for an OBJ, which the loader
    /// reads).
    pub fn procedural_mesh(&self) -> Option<Mesh> {
        Some(match *self {
            Shape::Plane { size, tessellation } => mesh::plane(size, tessellation),
            Shape::Box { size } => mesh::cuboid(size),
            Shape::Sphere {
                radius,
                slices,
                stacks,
            } => mesh::sphere(radius, slices, stacks),
            Shape::Torus {
                major_radius,
                minor_radius,
                rings,
                sides,
            } => mesh::torus(major_radius, minor_radius, rings, sides),
            Shape::Teapot { size, tessellation } => mesh::teapot(size, tessellation),
            Shape::Aircraft { layout } => layout.mesh(),
            Shape::Obj { .. } => return None,
        })
    }
}

/// glTranslate(translate) · glRotate(r₁) · glRotate(r₂) · … · glScale(scale).
#[derive(Debug, Clone, PartialEq)]
pub struct Transform {
    pub translate: Vec3,
    pub rotate: Vec<Rotation>,
    pub scale: Vec3,
}

impl Default for Transform {
    fn default() -> Self {
        Transform {
            translate: Vec3::ZERO,
            rotate: Vec::new(),
            scale: Vec3::ONE,
        }
    }
}

/// glRotate(degrees, axis); the axis is normalised.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rotation {
    pub axis: Vec3,
    pub degrees: f32,
}

impl Transform {
    /// M = T · R₁ · R₂ · … · S.
    pub fn matrix(&self) -> Mat4 {
        let rotation = self.rotate.iter().fold(Mat4::IDENTITY, |m, r| {
            m * Mat4::from_axis_angle(r.axis, r.degrees.to_radians())
        });
        Mat4::from_translation(self.translate) * rotation * Mat4::from_scale(self.scale)
    }
}

/// Fixed-function material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// GL_AMBIENT_AND_DIFFUSE, RGB. Default 0.8 grey (GL's diffuse default).
    pub colour: Vec3,
    /// GL_SPECULAR, RGB. Default black.
    pub specular: Vec3,
    /// GL_SHININESS in [0, 128]. Default 0.
    pub shininess: f32,
}

impl Default for Material {
    fn default() -> Self {
        Material {
            colour: Vec3::splat(0.8),
            specular: Vec3::ZERO,
            shininess: 0.0,
        }
    }
}

/// One object of the scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Object {
    pub name: Option<String>,
    pub shape: Shape,
    /// The shape's mesh in object space, shared by every copy of the scene (a moved or
    /// re-sized copy holds the same vertices).
    pub mesh: Arc<Mesh>,
    pub transform: Transform,
    pub material: Material,
    /// Whether it casts shadows (is drawn into shadow maps and occludes in the truth).
    pub casts: bool,
    /// Whether shadows fall on it.
    pub receives: bool,
}

impl Object {
    /// The mesh in world space.
    pub fn world_mesh(&self) -> Mesh {
        self.mesh.transformed(&self.transform.matrix())
    }
}

/// A shadow plane of an object (Coleman's occluder planes): its frame in the object's own
/// space, where its occluder texture came from, and the texture.
#[derive(Debug, Clone, PartialEq)]
pub struct OccluderPlane {
    /// Unit axes (validated orthogonal), origin at the texture's corner s = t = 0.
    pub frame: PlaneFrame,
    pub source: OccluderSource,
    /// Made once when the scene is read (generated from the mesh, or the PNG).
    pub texture: Arc<OccluderTexture>,
}

/// The shadow planes declared under one `[[object]]` (`[[object.plane]]`), or supplied by
/// its shape (the `f35` aircraft layout's three planes).
#[derive(Debug, Clone, PartialEq)]
pub struct ObjectPlanes {
    /// Index into [`Scene::objects`].
    pub object: usize,
    pub planes: Vec<OccluderPlane>,
    /// `[[object.section]]`: the object cut into parts, each looking up only its own
    /// planes (Coleman's teapot, thesis §5). Empty: the whole object looks up all of them.
    pub sections: Vec<PlaneSection>,
}

/// One part of an object for `occluder-planes`: drawn with the clip planes that keep it,
/// it looks up `planes` (indices into the object's own planes) and every other caster's.
/// Section k keeps `cut` ≥ 0 and the other side of every earlier section's cut; the last
/// section has no cut and takes the rest, so the sections cover the object.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneSection {
    /// glClipPlane's equation in object space: (a, b, c, d) keeps a·x + b·y + c·z + d ≥ 0.
    pub cut: Option<glam::Vec4>,
    pub planes: Vec<usize>,
}

/// A polygon offset as the scene and the command line leave it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OffsetSetting {
    /// Neither gave one: the technique's default at the map's depth bits
    /// (`vocab::default_offset`).
    TechniqueDefault,
    /// Given by the scene or the command line (`by` is never `TechniqueDefault`); `None`
    /// is no offset.
    Given {
        offset: Option<PolygonOffset>,
        by: OffsetSource,
    },
}

impl OffsetSetting {
    /// Given on the command line (or by a sweep's grid).
    pub fn command_line(offset: Option<PolygonOffset>) -> OffsetSetting {
        OffsetSetting::Given {
            offset,
            by: OffsetSource::CommandLine,
        }
    }
}

/// The `[shadow]` table.
#[derive(Debug, Clone, PartialEq)]
pub struct ShadowSettings {
    /// Default None.
    pub technique: TechniqueId,
    /// Shadow map edge in texels. Default 256 (mesa-demos shadowtex).
    pub map_size: u32,
    /// Default D24.
    pub depth: DepthBits,
    /// The light pass's polygon offset: given, or the technique's default
    /// ([`ShadowSettings::offset`] resolves it).
    pub polygon_offset: OffsetSetting,
    /// Default Float.
    pub precision: Precision,
    /// How integer depth maps are read back. Default Driver: glReadPixels with the integer
    /// type, as the era's programs did (Mesa truncates bytes and rounds shorts).
    pub readback: ReadbackRule,
    /// Default Nearest.
    pub filter: MapFilter,
    /// `planar`'s depth handling. Default Offset.
    pub planar_mode: PlanarMode,
    /// `projective`'s projection. Default PseudoDepth.
    pub projector: Projector,
    /// `accumulate`'s hard-shadow renders per frame, one from each stratified point of the
    /// area light, 1 to [`ShadowSettings::MAX_LIGHT_SAMPLES`]. Default
    /// [`ShadowSettings::DEFAULT_LIGHT_SAMPLES`].
    pub light_samples: u32,
    /// The objects' shadow planes, for `occluder-planes` (declared per object, gathered
    /// here with the object's index). Default none.
    pub planes: Vec<ObjectPlanes>,
    /// `occlusion-textures`' slice count: 4, 8 or 16 ([`super::SLICE_COUNTS`]). Default 16.
    pub slices: u32,
    /// `occlusion-textures`' prefilter. Default Mipmap.
    pub prefilter: super::Prefilter,
    /// `occlusion-textures`' combination rule. Default Probabilistic (equation 5).
    pub combine: super::Combine,
    /// `occluder-planes`' form (`[shadow] program`). Default FixedFunction.
    pub occluder_program: super::OccluderProgram,
}

impl Default for ShadowSettings {
    fn default() -> Self {
        ShadowSettings {
            technique: TechniqueId::None,
            map_size: 256,
            depth: DepthBits::D24,
            polygon_offset: OffsetSetting::TechniqueDefault,
            precision: Precision::Float,
            readback: ReadbackRule::Driver,
            filter: MapFilter::Nearest,
            planar_mode: PlanarMode::Offset,
            projector: Projector::PseudoDepth,
            light_samples: ShadowSettings::DEFAULT_LIGHT_SAMPLES,
            planes: Vec::new(),
            slices: 16,
            prefilter: super::Prefilter::Mipmap,
            combine: super::Combine::Probabilistic,
            occluder_program: super::OccluderProgram::FixedFunction,
        }
    }
}

impl ShadowSettings {
    /// 16 renders: a 4 × 4 grid over the light, the Red Book's order of magnitude.
    pub const DEFAULT_LIGHT_SAMPLES: u32 = 16;

    /// 256 renders. Each adds q(255/255 · 32767/N) to a 16-bit accumulation value
    /// (`ff::accum`), so the weight of one render falls to 127/32767 at N = 256 and the
    /// truncation costs up to N/32767 of the light (0.8% at 256); beyond it the buffer's
    /// precision, not the sampling, would bound the soft shadow.
    pub const MAX_LIGHT_SAMPLES: u32 = 256;

    /// The polygon offset the light pass uses: the one given, else the technique's default
    /// for the map's depth bits.
    pub fn offset(&self) -> Option<PolygonOffset> {
        match self.polygon_offset {
            OffsetSetting::TechniqueDefault => default_offset(self.technique, self.depth),
            OffsetSetting::Given { offset, .. } => offset,
        }
    }

    /// Where [`ShadowSettings::offset`] comes from.
    pub fn offset_source(&self) -> OffsetSource {
        match self.polygon_offset {
            OffsetSetting::TechniqueDefault => OffsetSource::TechniqueDefault,
            OffsetSetting::Given { by, .. } => by,
        }
    }
}

/// The `[truth]` table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TruthSettings {
    /// Shadow rays per pixel towards an area light, 1 to [`TruthSettings::MAX_SAMPLES`],
    /// rounded up to two independent s × s stratified grids (see `truth`). Default
    /// [`TruthSettings::DEFAULT_SAMPLES`]. Point, spot and directional lights take one ray.
    pub samples: u32,
}

impl TruthSettings {
    /// 2 × 11²: keeps the truth's own visibility RMSE under 0.005 (0.0040 and 0.0016 on
    /// the two area-light scenes measured, 200 samples being the first under it); the
    /// figures, and the command that repeats them, are in the `truth` module's note.
    pub const DEFAULT_SAMPLES: u32 = 242;

    /// The budget: 8192 samples per pixel (2 × 64 × 64). Its standard error is far below
    /// the visibility image's 8-bit step, and at the default 512² it is already 2.1 × 10⁹
    /// shadow rays, about a minute of ray casting on 2 cores; more is refused up front,
    /// in the scene (`[truth] samples`) and on the command line (`truth --samples`).
    pub const MAX_SAMPLES: u32 = 8192;
}

impl Default for TruthSettings {
    fn default() -> Self {
        TruthSettings {
            samples: TruthSettings::DEFAULT_SAMPLES,
        }
    }
}
