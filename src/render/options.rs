//! What a render is asked to do beyond the scene: where it runs (backend, pipeline), how
//! long (frames), how it is judged (truth, band), what it records (pass times, the light's
//! map) and what moves. The scene's own tables — `[shadow]` above all — are the one source
//! of the technique's settings; the only overrides are the two a command line gives for a
//! single run, the technique and the image size, applied to a copy by [`apply_overrides`].

use crate::gpu::Backend;
use crate::scene::Scene;
use crate::truth::TruthOptions;
use crate::vocab::{PipelineKind, Submission, TechniqueId};

use super::{ImageSize, Orbit};

/// What to render and how.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    pub backend: Backend,
    pub pipeline: PipelineKind,
    /// Replaces the scene's `[shadow] technique`.
    pub technique: Option<TechniqueId>,
    /// Replaces the scene's `[image]` width and height.
    pub size: Option<ImageSize>,
    /// Frames rendered and timed (at least 1).
    pub frames: u32,
    /// Which light the truth judges, and area-light samples.
    pub truth: TruthOptions,
    /// Half-width k of the edge band the metrics exclude in `outside_band`.
    pub band: u32,
    /// When the map passes run again after frame 1.
    pub remake_maps: RemakeMaps,
    /// Time every pass on its own (a glFinish after each; the frame time includes them).
    pub pass_times: bool,
    /// Read the light's map after the frames (`render --depth-map`).
    pub depth_map: bool,
    /// Something moving from frame to frame (`None`: a static scene).
    pub orbit: Option<Orbit>,
    /// How the objects' draws reach the pipeline (`render::submission`): through the C
    /// library's front in immediate mode or display lists, or from buffers as planned.
    pub submission: Submission,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            backend: Backend::Egl,
            pipeline: PipelineKind::Emulate,
            technique: None,
            size: None,
            frames: 1,
            truth: TruthOptions::default(),
            band: 1,
            remake_maps: RemakeMaps::WhenMoved,
            pass_times: false,
            depth_map: false,
            orbit: None,
            submission: Submission::Buffers,
        }
    }
}

/// When a technique's maps are made again.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum RemakeMaps {
    /// Only when the light or a caster moved since the maps were made: scenes are static,
    /// so once, on the first frame.
    #[default]
    WhenMoved,
    /// Every frame, as the era's demos did.
    Always,
}

impl crate::vocab::Named for RemakeMaps {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("when-moved", RemakeMaps::WhenMoved),
        ("always", RemakeMaps::Always),
    ];

    fn help(self) -> &'static str {
        match self {
            RemakeMaps::WhenMoved => "Only when the light or a caster moved since the maps were made: scenes are static, so once, on the first frame",
            RemakeMaps::Always => "Every frame, as the era's demos did",
        }
    }
}

/// `scene` with the options' size and technique applied (the meshes are shared, not
/// copied).
pub fn apply_overrides(
    scene: &Scene,
    size: Option<ImageSize>,
    technique: Option<TechniqueId>,
) -> Scene {
    let mut scene = scene.clone();
    if let Some(size) = size {
        scene.image.width = size.width;
        scene.image.height = size.height;
    }
    if let Some(id) = technique {
        scene.shadow.technique = id;
    }
    scene
}
