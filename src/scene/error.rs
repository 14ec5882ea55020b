//! The scene layer's one error type. Every variant says where (file, line, column) and,
//! for validation failures, which key and what would have been accepted.

use super::limits::{grouped, human_bytes};
use crate::mesh::occluder::{FrameProblem, OccluderError};
use crate::mesh::MeshError;
use glam::Vec3;
use std::fmt;
use std::path::PathBuf;

/// A position in a scene file (1-based line and column, in characters).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    pub file: String,
    pub line: usize,
    pub col: usize,
}

impl Location {
    /// The location of byte `offset` in `text`.
    pub fn of_offset(file: &str, text: &str, offset: usize) -> Location {
        let offset = offset.min(text.len());
        let before = text.get(..offset).unwrap_or(text);
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let col = before.get(line_start..).map_or(0, |s| s.chars().count()) + 1;
        Location {
            file: file.to_string(),
            line,
            col,
        }
    }
}

/// The key assigned on the line holding byte `offset` (`width` in `width = "wide"`), if the
/// offset is to the right of its `=`.
pub(super) fn key_at(text: &str, offset: usize) -> Option<String> {
    let offset = offset.min(text.len());
    let start = text.get(..offset)?.rfind('\n').map_or(0, |i| i + 1);
    let before = text.get(start..offset)?;
    let (key, _) = before.split_once('=')?;
    let key = key.trim();
    (!key.is_empty()).then(|| key.to_string())
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file, self.line, self.col)
    }
}

/// What is wrong with a value that parsed but does not make a scene.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Problem {
    #[error("must be a finite number")]
    NotFinite,
    #[error("must be greater than zero, not {0}")]
    NotPositive(f32),
    #[error("must be at least {min}, not {value}")]
    TooSmall { min: u32, value: u32 },
    #[error("near ({near}) must be less than far ({far})")]
    NearNotBeforeFar { near: f32, far: f32 },
    #[error("({high}) must be greater than `{low_key}` ({low})")]
    NotAbove {
        low_key: String,
        low: f32,
        high: f32,
    },
    #[error("must be at most {max}, not {value}")]
    TooLarge { max: u32, value: u32 },
    #[error("must be in [{low}, {high}], not {value}")]
    OutOfRange { low: f32, high: f32, value: f32 },
    #[error("must be in (0, 180) degrees, not {0}")]
    FovyOutOfRange(f32),
    #[error("must be in (0, {max}] degrees, not {value}")]
    DegreesOutOfRange { max: f32, value: f32 },
    #[error("is parallel to the view direction {view}; give an up vector that is not")]
    UpAlongView { view: Vec3 },
    #[error("must not be the zero vector")]
    ZeroVector,
    #[error("coincides with `{other}` (both {point}): they must differ, the view looks from one to the other")]
    Coincides { other: String, point: Vec3 },
    #[error("is parallel to `{other}` ({edge}): an area light's two edges must span a rectangle")]
    ParallelEdges { other: String, edge: Vec3 },
    #[error(
        "would make the scene {} triangles (≈ {}); the budget is {} triangles and {}; \
         raise it with --max-triangles / --memory-budget",
        grouped(*.triangles), human_bytes(*.bytes), grouped(*.max_triangles),
        human_bytes(*.memory_bytes)
    )]
    OverBudget {
        triangles: u64,
        bytes: u64,
        max_triangles: u64,
        memory_bytes: u64,
    },
    #[error("`{name}` is not a known technique; known techniques: {}", .known.join(", "))]
    UnknownTechnique {
        name: String,
        known: Vec<&'static str>,
    },
    #[error("is not used by a {what}; a {what} takes: {}", .valid.join(", "))]
    NotUsedBy {
        what: String,
        valid: Vec<&'static str>,
    },
    #[error("is required by a {what}")]
    Missing { what: String },
    #[error("cannot be combined with `{other}`")]
    Conflicts { other: &'static str },
    #[error("{0}")]
    Frame(FrameProblem),
    #[error("makes {count} shadow planes for {receiver} to look up; the fixed-function pipeline has {max} texture units (GL_MAX_TEXTURE_UNITS), one per plane (`[[object.section]]` cuts an object into parts that each look up fewer)")]
    TooManyPlanes {
        count: usize,
        max: usize,
        receiver: String,
    },
    #[error("makes {count} shadow planes in the scene, and it may hold {max} (each has a texture of its own)")]
    TooManyScenePlanes { count: usize, max: usize },
    #[error("names plane {index}, and the object has {count} (`[[object.plane]]` 0 to {last})", last = .count.saturating_sub(1))]
    NoSuchPlane { index: u32, count: usize },
    #[error("is on the last section, which takes the rest of the object: the last `[[object.section]]` has no `cut`")]
    CutOnLastSection,
    #[error("makes {count} sections; section k is drawn with up to k + 1 clip planes, and GL_MAX_CLIP_PLANES is {max}")]
    TooManySections { count: usize, max: usize },
    #[error("must be one of {}, not {value}", .expected.join(", "))]
    NotOneOf {
        value: String,
        expected: Vec<&'static str>,
    },
}

/// Everything that can go wrong loading a scene.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    #[error("cannot read scene file {file}: {source}")]
    Read {
        file: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// TOML syntax, an unknown field, a wrong type or an unknown enum value; serde's message
    /// names the key and lists the valid alternatives.
    #[error("{at}: {}{msg}", .key.as_ref().map(|k| format!("`{k}`: ")).unwrap_or_default())]
    Parse {
        at: Location,
        /// The key written on the offending line, when there is one.
        key: Option<String>,
        msg: String,
    },
    #[error("{at}: `{key}` {problem}")]
    Invalid {
        at: Location,
        key: String,
        problem: Problem,
    },
    #[error("{at}: `{key}`: {source}")]
    Occluder {
        at: Location,
        key: String,
        #[source]
        source: OccluderError,
    },
    #[error("{at}: `{key}`: {source}")]
    Mesh {
        at: Location,
        key: String,
        #[source]
        source: MeshError,
    },
}

impl SceneError {
    /// Where in the file the error is, when it is in a file.
    pub fn location(&self) -> Option<&Location> {
        match self {
            SceneError::Read { .. } => None,
            SceneError::Parse { at, .. }
            | SceneError::Invalid { at, .. }
            | SceneError::Occluder { at, .. }
            | SceneError::Mesh { at, .. } => Some(at),
        }
    }
}

/// Something accepted but worth telling: the scene loads.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneWarning {
    pub at: Location,
    pub key: String,
    pub kind: WarningKind,
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WarningKind {
    #[error("{count} degenerate faces dropped")]
    DegenerateFaces { count: usize },
}

impl fmt::Display for SceneWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: `{}`: {}", self.at, self.key, self.kind)
    }
}
