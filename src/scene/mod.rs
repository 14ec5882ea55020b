//! Scene files: TOML through serde, every table `deny_unknown_fields`, into a validated
//! [`Scene`] whose errors name the file, line, column, key and the valid alternatives.
//!
//! Reading is two steps. `raw` is the file's shape as serde sees it, values wrapped in
//! `toml::Spanned` so that a value rejected later still knows its byte span; serde itself
//! reports syntax errors, unknown keys, wrong types and unknown enum names (its message
//! lists the expected alternatives, and toml gives the span). `build` then checks what
//! serde cannot — finite numbers, positive sizes, tessellation counts, near < far,
//! fovy ∈ (0, 180), an up vector not parallel to the view, keys that do not belong to a
//! shape or light type, known technique names — and loads OBJ files relative to the scene
//! file. Degenerate OBJ faces are dropped and counted in [`Scene::warnings`], not rejected.
//!
//! `[shadow] technique` is parsed into a `vocab::TechniqueId`; an unknown name is an error
//! at its line that lists every known name.
//!
//! The built-in [`Scene::default_scene`] is `assets/default.toml` written in Rust (a test
//! keeps them equal): mesa-demos shadowtex's layout — a tessellated ground, a sphere and a
//! torus under a 40° spot light whose shadow frustum is near 4, far 24.

mod build;
mod check;
mod error;
mod limits;
mod occlusion;
mod planes;
mod raw;
mod sun;
#[cfg(test)]
mod tests;
mod types;

pub use error::{Location, Problem, SceneError, SceneWarning, WarningKind};
pub use limits::{
    grouped, human_bytes, Limits, BYTES_PER_TRIANGLE, DEFAULT_MAX_TRIANGLES, DEFAULT_MEMORY_BYTES,
    GPU_BYTES_PER_TRIANGLE, MAX_IMAGE_SIZE,
};
pub use occlusion::{Combine, Prefilter, SLICE_COUNTS};
pub use planes::{plane_lookups, OccluderProgram, PlaneLookup, MAX_SCENE_PLANES};
pub use sun::{concentric, SunDisc, MAX_SUN_DIAMETER_DEGREES};
pub use types::*;

use glam::Vec3;
use std::path::Path;
use std::sync::Arc;

impl Scene {
    /// Reads and validates the scene file at `path`.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        Scene::load_with(path, Limits::default())
    }

    /// [`Scene::load`] under other budgets (`--max-triangles`, `--memory-budget`).
    pub fn load_with(path: &Path, limits: Limits) -> Result<Scene, SceneError> {
        let text = std::fs::read_to_string(path).map_err(|source| SceneError::Read {
            file: path.to_path_buf(),
            source,
        })?;
        Scene::parse_with(&text, path, limits)
    }

    /// Validates scene text as if read from `origin` (named in errors; OBJ paths are
    /// relative to its folder).
    pub fn parse(text: &str, origin: &Path) -> Result<Scene, SceneError> {
        Scene::parse_with(text, origin, Limits::default())
    }

    /// [`Scene::parse`] under other budgets: the triangles of the objects are counted
    /// from their parameters, and refused over `limits`, before any mesh is built.
    pub fn parse_with(text: &str, origin: &Path, limits: Limits) -> Result<Scene, SceneError> {
        let mut ctx = check::Ctx::new(text, origin, limits);
        let raw: raw::RawScene = toml::from_str(text).map_err(|e| {
            let span = e.span().unwrap_or(0..0);
            SceneError::Parse {
                at: ctx.at(span.clone()),
                key: error::key_at(text, span.start),
                msg: e.message().trim().to_string(),
            }
        })?;
        build::scene(&mut ctx, raw)
    }

    /// The built-in scene (equal to `assets/default.toml`).
    pub fn default_scene() -> Scene {
        let object = |name: &str, shape: Shape, transform: Transform, material: Material| Object {
            name: Some(name.to_string()),
            mesh: Arc::new(shape.procedural_mesh().unwrap_or_default()),
            shape,
            transform,
            material,
            casts: true,
            receives: true,
        };
        let at = |x: f32, y: f32, z: f32| Transform {
            translate: Vec3::new(x, y, z),
            ..Transform::default()
        };
        Scene {
            camera: Camera {
                eye: Vec3::new(0.0, 9.0, 20.0),
                at: Vec3::ZERO,
                up: Vec3::Y,
                projection: Projection::Perspective {
                    fovy: 40.0,
                    near: 4.0,
                    far: 50.0,
                },
            },
            image: ImageSpec {
                width: 512,
                height: 512,
                background: Vec3::new(0.25, 0.25, 0.375),
            },
            lights: vec![Light {
                kind: LightKind::Spot {
                    cutoff: 40.0,
                    exponent: 0.0,
                },
                view: Camera {
                    eye: Vec3::new(6.0, 10.0, 6.0),
                    at: Vec3::ZERO,
                    up: Vec3::Y,
                    projection: Projection::Perspective {
                        fovy: 80.0,
                        near: 4.0,
                        far: 24.0,
                    },
                },
                colour: Vec3::ONE,
                intensity: 1.0,
            }],
            objects: vec![
                object(
                    "ground",
                    Shape::Plane {
                        size: 16.0,
                        tessellation: 32,
                    },
                    Transform::default(),
                    Material {
                        colour: Vec3::new(0.75, 0.75, 0.75),
                        ..Material::default()
                    },
                ),
                object(
                    "sphere",
                    Shape::Sphere {
                        radius: 1.25,
                        slices: 32,
                        stacks: 16,
                    },
                    at(-2.0, 1.75, 1.0),
                    Material {
                        colour: Vec3::new(0.875, 0.25, 0.125),
                        specular: Vec3::splat(0.5),
                        shininess: 32.0,
                    },
                ),
                object(
                    "torus",
                    Shape::Torus {
                        major_radius: 1.25,
                        minor_radius: 0.375,
                        rings: 32,
                        sides: 16,
                    },
                    Transform {
                        rotate: vec![Rotation {
                            axis: Vec3::X,
                            degrees: 60.0,
                        }],
                        ..at(1.75, 1.5, -1.25)
                    },
                    Material {
                        colour: Vec3::new(0.25, 0.5, 0.875),
                        specular: Vec3::splat(0.5),
                        shininess: 32.0,
                    },
                ),
            ],
            shadow: ShadowSettings::default(),
            truth: TruthSettings::default(),
            warnings: Vec::new(),
            limits: Limits::default(),
        }
    }
}
