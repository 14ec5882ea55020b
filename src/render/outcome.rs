//! What a render produced: the image, the mask and its judgement, the frame times and the
//! pipeline's counters — the values behind `render`'s figures line and every study row.

use crate::vocab::{OffsetSource, PipelineKind, PolygonOffset, TechniqueId};
use image::RgbaImage;

use crate::gpu::Backend;
use crate::metrics::{Mask, Metrics, VisibilityErrors, VisibilityImage};
use crate::pipeline::Counters;
use crate::stats::Summary;
use crate::truth::Truth;

use super::{Figures, LightMap};

/// Per-frame wall times in milliseconds.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameTimings {
    /// Every frame, in order.
    pub frames_ms: Vec<f64>,
    /// The first frame (programs compiled, geometry uploaded).
    pub cold_ms: f64,
    /// Frames 2…N; `None` with one frame.
    pub steady: Option<Summary>,
}

impl FrameTimings {
    /// The first frame's time and the later frames' times.
    pub fn new(cold_ms: f64, steady_ms: Vec<f64>) -> FrameTimings {
        let steady = Summary::of(&steady_ms);
        let mut frames_ms = vec![cold_ms];
        frames_ms.extend(steady_ms);
        FrameTimings {
            frames_ms,
            cold_ms,
            steady,
        }
    }

    /// The figure a report shows: the steady median, or the cold frame when it is alone.
    pub fn typical_ms(&self) -> f64 {
        self.steady.map_or(self.cold_ms, |s| s.median)
    }
}

/// Everything a render produced.
#[derive(Debug, Clone)]
pub struct RenderOutcome {
    pub technique: TechniqueId,
    pub pipeline: PipelineKind,
    pub backend: Backend,
    /// How the context was obtained (e.g. the EGL platform).
    pub context_path: String,
    /// The colour image of the last frame, top row first.
    pub image: RgbaImage,
    /// The technique's shadow mask.
    pub mask: Mask,
    pub truth: Truth,
    pub metrics: Metrics,
    pub timings: FrameTimings,
    /// Passes in a frame that makes its maps.
    pub passes: usize,
    /// The pipeline's counters after every frame and the mask readback.
    pub counters: Counters,
    /// How many times the map passes ran.
    pub maps_made: u32,
    /// Per pass (in plan order), the times of the frames it ran in, when asked for.
    pub pass_times: Vec<PassTime>,
    /// The light's map as read back, when asked for and the technique makes one
    /// (`report::light_map_pictures` shows it).
    pub light_map: Option<LightMap>,
    /// For an area-light scene: the technique's visibility and its errors against the
    /// truth's; `None` for any other light.
    pub visibility: Option<VisibilityOutcome>,
    /// For a scene of several objects, each object's share of the error: its self-shadow,
    /// the shadow others cast on it, its lit surface (`metrics::per_object`); empty for a
    /// scene of one object.
    pub objects: Vec<crate::metrics::ObjectErrors>,
    /// What the technique says about this scene (known failure modes it triggers).
    pub notes: Vec<String>,
    /// The light pass's polygon offset and where it came from.
    pub offset: Option<PolygonOffset>,
    pub offset_source: OffsetSource,
    /// glGetString(GL_RENDERER) and glGetString(GL_VERSION) of the context it ran on.
    pub gl_renderer: String,
    pub gl_version: String,
}

/// A technique's visibility of an area light, and how far it is from the truth's.
#[derive(Debug, Clone, PartialEq)]
pub struct VisibilityOutcome {
    pub image: VisibilityImage,
    pub source: VisibilitySource,
    pub errors: VisibilityErrors,
}

/// Where a technique's visibility comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum VisibilitySource {
    /// Its mask plan gave a fraction per pixel (accumulated over the light's samples, or
    /// looked up in prefiltered occlusion textures).
    Soft,
    /// Its hard mask from the light's centre: 1 lit, 0 shadowed.
    HardMask,
}

/// One pass's times.
#[derive(Debug, Clone, PartialEq)]
pub struct PassTime {
    pub name: &'static str,
    /// Whether it is a map pass (runs only when the maps are made).
    pub map: bool,
    pub ms: Vec<f64>,
}

impl RenderOutcome {
    /// The one-line summary.
    pub fn figures(&self) -> Figures {
        Figures {
            technique: self.technique,
            pipeline: self.pipeline,
            backend: self.backend,
            wrong_percent: self.metrics.all.wrong_percent,
            false_shadow: self.metrics.all.false_shadow,
            missed_shadow: self.metrics.all.missed_shadow,
            timings: self.timings.clone(),
            passes: self.passes,
            programs: self.counters.programs_compiled,
            maps_made: self.maps_made,
            visibility_rmse: self.visibility.as_ref().map(|v| v.errors.rmse),
            offset: self
                .technique
                .uses_offset()
                .then_some((self.offset, self.offset_source)),
        }
    }
}
