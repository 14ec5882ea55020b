//! What a render produced: the image, the mask and its judgement, the frame times and the
//! pipeline's counters — the values behind `render`'s figures line and every study row.

use crate::vocab::{OffsetSource, PipelineKind, PolygonOffset, TechniqueId};
use image::RgbaImage;

use crate::gpu::Backend;
use crate::metrics::{Mask, Metrics};
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
    /// What the technique says about this scene (known failure modes it triggers).
    pub notes: Vec<String>,
    /// The light pass's polygon offset and where it came from.
    pub offset: Option<PolygonOffset>,
    pub offset_source: OffsetSource,
    /// glGetString(GL_RENDERER) and glGetString(GL_VERSION) of the context it ran on.
    pub gl_renderer: String,
    pub gl_version: String,
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
            offset: self
                .technique
                .uses_offset()
                .then_some((self.offset, self.offset_source)),
        }
    }
}
