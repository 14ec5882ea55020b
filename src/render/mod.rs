//! Rendering a scene with one technique on one pipeline and backend, and judging it: the
//! library half of `fixedfunc render` (no printing, no files, no exit codes).
//!
//! [`render`] does, in order:
//! 1. applies the options' overrides (image size, technique) to a copy of the scene;
//! 2. prepares the geometry once (`techniques::Prepared`) and builds the technique's plan
//!    once;
//! 3. creates a context of the pipeline's profile on the backend (a private Xvfb for the
//!    window backend when no display is set), the framebuffer the plan asks for (RGBA8, the
//!    light's depth bits, stencil when a technique uses it; large enough for the image and
//!    the light's map, which share it as on the era's hardware) and the pipeline
//!    (`pipeline::create`, the only code naming a concrete path), then executes the plan's
//!    setup once;
//! 4. runs `frames` frames; each frame is timed from its first command to glFinish
//!    returning, so the driver's work is inside the figure. Frame 1 is *cold* (programs
//!    compiled, buffers uploaded, maps made); frames 2…N are *steady*. The map passes run
//!    on frame 1 and then only when the maps are stale ([`RemakeMaps`]);
//! 5. executes the mask plan, decodes the mask, reads the colour image (the image's corner
//!    of the framebuffer), takes the counters, and reads the light's map when asked;
//! 6. ray-casts the truth (CPU) and compares the mask with it (`metrics::compare` with an
//!    edge band of `band` pixels).
//!
//! The steps are a [`Session`], so that a caller can hold several renders open and
//! interleave their frames (machine noise then hits all of them alike); [`render`] is one
//! session from start to end.
//!
//! A command the GL model rejects is a bug in the technique, not a driver problem: the
//! frame stops with [`RenderError::Gl`] naming the pass.

mod figures;
mod size;

pub use figures::Figures;
pub use size::{ImageSize, SizeProblem, MAX_IMAGE_SIZE};

use crate::vocab::{PipelineKind, Precision};
use std::time::Instant;

use image::RgbaImage;

use crate::bench::Summary;
use crate::ff::Command;
use crate::ff::GlError;
use crate::gpu::{
    Backend, ContextRequest, GpuContext, GpuError, RenderTarget, TargetSpec, VirtualDisplay,
};
use crate::metrics::{self, Mask, Metrics, MetricsError};
use crate::pipeline::{Counters, Pipeline, PipelineError};
use crate::scene::{Scene, ShadowSettings};
use crate::techniques::{self, MapImageSource, Plan, Prepared, TechniqueError};
use crate::truth::{self, Truth, TruthError, TruthOptions};

/// Failures of the render layer.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    #[error(transparent)]
    Technique(#[from] TechniqueError),
    #[error(transparent)]
    Gpu(#[from] GpuError),
    #[error(transparent)]
    Pipeline(#[from] PipelineError),
    #[error("pass `{pass}` of frame {frame}: the GL model rejected a command: {error}")]
    Gl {
        pass: &'static str,
        frame: u32,
        error: GlError,
    },
    #[error(transparent)]
    Truth(#[from] TruthError),
    #[error(transparent)]
    Metrics(#[from] MetricsError),
    #[error("the light's map is {size}² texels; at most {max}² fit a framebuffer")]
    MapTooLarge { size: u32, max: u32 },
    #[error("the session's framebuffer was already released")]
    Released,
    #[error("the new shadow settings need another framebuffer (depth bits, stencil or size changed): start a new session")]
    Restage,
    #[error("the depth-map readback is missing or malformed (slot {slot})")]
    MapImage { slot: u32 },
    #[error("image size `{text}`: {problem}")]
    Size { text: String, problem: SizeProblem },
}

/// The name the CLI uses for a pipeline path.
pub fn pipeline_name(kind: PipelineKind) -> &'static str {
    match kind {
        PipelineKind::Emulate => "emulate",
        PipelineKind::Native => "native",
    }
}

/// What to render and how.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    pub backend: Backend,
    pub pipeline: PipelineKind,
    /// Replaces the scene's `[shadow] technique`.
    pub technique: Option<String>,
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
    /// Arithmetic of the emulated pipeline's stages (the scene's `precision` when `None`).
    pub precision: Option<Precision>,
    /// Something moving from frame to frame (`None`: a static scene).
    pub orbit: Option<Orbit>,
}

/// A motion: the camera's or the light's eye turns about the vertical axis through the
/// point it looks at, by `degrees_per_frame` (frame 1 is the scene as written).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    pub target: OrbitTarget,
    pub degrees_per_frame: f32,
}

impl std::str::FromStr for Orbit {
    type Err = String;

    /// `camera:DEG` or `light:DEG` (degrees per frame, finite).
    fn from_str(text: &str) -> Result<Orbit, String> {
        let bad = || format!("`{text}`: expected camera:DEGREES or light:DEGREES (e.g. light:5)");
        let (what, deg) = text.split_once(':').ok_or_else(bad)?;
        let target = match what {
            "camera" => OrbitTarget::Camera,
            "light" => OrbitTarget::Light,
            _ => return Err(bad()),
        };
        let degrees_per_frame: f32 = deg.trim().parse().map_err(|_| bad())?;
        if !degrees_per_frame.is_finite() {
            return Err(bad());
        }
        Ok(Orbit {
            target,
            degrees_per_frame,
        })
    }
}

/// What an [`Orbit`] moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum OrbitTarget {
    /// The eye: the maps stay valid.
    Camera,
    /// The shadowing light (the scene's first): the maps go stale every frame.
    Light,
}

impl Orbit {
    /// `scene` as it stands at frame `n` (1-based): the target's eye turned by
    /// (n − 1)·degrees about +Y through its `at`; a directional light's direction turns too.
    pub fn scene_at(&self, scene: &Scene, n: u32) -> Scene {
        let turn = glam::Mat3::from_rotation_y(
            (self.degrees_per_frame * n.saturating_sub(1) as f32).to_radians(),
        );
        let mut scene = scene.clone();
        match self.target {
            OrbitTarget::Camera => {
                let c = &mut scene.camera;
                c.eye = c.at + turn * (c.eye - c.at);
            }
            OrbitTarget::Light => {
                if let Some(light) = scene.lights.first_mut() {
                    let v = &mut light.view;
                    v.eye = v.at + turn * (v.eye - v.at);
                    if let crate::scene::LightKind::Directional { direction } = &mut light.kind {
                        *direction = turn * *direction;
                    }
                }
            }
        }
        scene
    }
}

/// When a technique's maps are made again.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum RemakeMaps {
    /// Only when the light or a caster moved since the maps were made: scenes are static,
    /// so once, on the first frame.
    #[default]
    WhenMoved,
    /// Every frame, as the era's demos did.
    Always,
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
            precision: None,
            orbit: None,
        }
    }
}

/// Where a render is, for progress displays.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Progress {
    /// `done` of `total` frames rendered.
    Frame { done: u32, total: u32 },
    /// The ground truth is being ray-cast.
    Truth,
}

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
    pub technique: &'static str,
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
    /// The light's map as pictures (label, image), when asked for.
    pub map_images: Vec<(String, RgbaImage)>,
    /// What the technique says about this scene (known failure modes it triggers).
    pub notes: Vec<String>,
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
        }
    }
}

/// `scene` with the options' size and technique applied.
pub fn apply_overrides(scene: &Scene, size: Option<ImageSize>, technique: Option<&str>) -> Scene {
    let mut scene = scene.clone();
    if let Some(size) = size {
        scene.image.width = size.width;
        scene.image.height = size.height;
    }
    if let Some(name) = technique {
        scene.shadow.technique = name.to_string();
    }
    scene
}

/// Renders `scene` as `options` say and judges the mask against the truth.
pub fn render(scene: &Scene, options: &RenderOptions) -> Result<RenderOutcome, RenderError> {
    render_with_progress(scene, options, |_| {})
}

/// [`render`], calling `progress` after each frame and before the truth.
pub fn render_with_progress(
    scene: &Scene,
    options: &RenderOptions,
    mut progress: impl FnMut(Progress),
) -> Result<RenderOutcome, RenderError> {
    let mut session = Session::new(scene, options)?;
    let total = options.frames.max(1);
    for done in 1..=total {
        session.frame()?;
        progress(Progress::Frame { done, total });
    }
    progress(Progress::Truth);
    session.finish(None)
}

/// One render held open: context, framebuffer, pipeline and plan, frames on demand.
pub struct Session {
    scene: Scene,
    /// The scene as given (frame 1), from which an orbit computes later frames.
    base: Scene,
    prepared: Prepared,
    technique: &'static str,
    plan: Plan,
    /// The map passes that made the current maps: the maps are stale exactly when the next
    /// frame's map passes differ from these (the light, a caster or a setting moved).
    maps_from: Option<Vec<crate::techniques::Pass>>,
    options: RenderOptions,
    // Dropped in this order: the pipeline and target are released explicitly first.
    pipeline: Box<dyn Pipeline>,
    target: Option<RenderTarget>,
    ctx: GpuContext,
    _display: Option<VirtualDisplay>,
    frames_ms: Vec<f64>,
    pass_ms: Vec<Vec<f64>>,
    maps_made: u32,
    released: bool,
}

impl Drop for Session {
    fn drop(&mut self) {
        self.release();
    }
}

impl Session {
    /// Plans the technique, creates the context, framebuffer and pipeline, and executes
    /// the plan's setup.
    pub fn new(scene: &Scene, options: &RenderOptions) -> Result<Session, RenderError> {
        let scene = apply_overrides(scene, options.size, options.technique.as_deref());
        let technique = techniques::lookup(&scene.shadow.technique)?;
        let prepared = Prepared::new(&scene);
        let plan = (technique.plan)(&scene, &prepared)?;
        let fb = plan.framebuffer;
        if fb.width > MAX_IMAGE_SIZE || fb.height > MAX_IMAGE_SIZE {
            return Err(RenderError::MapTooLarge {
                size: scene.shadow.map_size,
                max: MAX_IMAGE_SIZE,
            });
        }
        let display = match options.backend {
            Backend::Window => VirtualDisplay::start_if_needed()?,
            Backend::Egl | Backend::OsMesa => None,
        };
        let ctx = GpuContext::new(&ContextRequest::new(
            options.backend,
            crate::pipeline::profile(options.pipeline),
        ))?;
        let mut spec = TargetSpec::new(fb.width, fb.height, fb.depth);
        if fb.stencil {
            spec = spec.with_stencil();
        }
        let target = RenderTarget::new(&ctx, spec)?;
        // Bound once: the binding is the context's state, and a later bind would reset the
        // viewport behind the emulated pipeline's shadow copy. The pipeline starts from the
        // target's viewport, as GL starts from the window's.
        target.bind(&ctx);
        let precision = options.precision.unwrap_or(scene.shadow.precision);
        let mut pipeline = crate::pipeline::create_with(options.pipeline, &ctx, precision)?;
        let setup = run(pipeline.as_mut(), &ctx, "setup", 0, &plan.setup);
        let pass_ms = vec![Vec::new(); plan.pass_count()];
        let mut session = Session {
            base: scene.clone(),
            scene,
            prepared,
            technique: technique.name,
            plan,
            maps_from: None,
            options: options.clone(),
            pipeline,
            target: Some(target),
            ctx,
            _display: display,
            frames_ms: Vec::new(),
            pass_ms,
            maps_made: 0,
            released: false,
        };
        if let Err(e) = setup {
            session.release();
            return Err(e);
        }
        Ok(session)
    }

    /// The scene as rendered (overrides applied).
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The technique's name.
    pub fn technique(&self) -> &'static str {
        self.technique
    }

    /// Replaces the scene's `[shadow]` settings (bias, map size, filter…) and re-plans: the
    /// context, framebuffer, pipeline and compiled programs stay; the maps are stale, so
    /// the next frame makes them again. The framebuffer must suit the new plan (same depth
    /// bits and stencil, large enough), else [`RenderError::Restage`].
    pub fn restage(&mut self, shadow: &ShadowSettings) -> Result<(), RenderError> {
        let mut scene = self.scene.clone();
        scene.shadow = ShadowSettings {
            technique: scene.shadow.technique.clone(),
            ..shadow.clone()
        };
        let technique = techniques::lookup(&scene.shadow.technique)?;
        let plan = (technique.plan)(&scene, &self.prepared)?;
        let (old, new) = (self.plan.framebuffer, plan.framebuffer);
        if old.depth != new.depth
            || old.stencil != new.stencil
            || new.width > old.width
            || new.height > old.height
        {
            return Err(RenderError::Restage);
        }
        self.ctx.make_current()?;
        run(self.pipeline.as_mut(), &self.ctx, "setup", 0, &plan.setup)?;
        self.pass_ms = vec![Vec::new(); plan.pass_count()];
        self.plan = plan;
        self.base = scene.clone();
        self.scene = scene;
        self.maps_made = 0;
        self.maps_from = None;
        Ok(())
    }

    /// Executes the mask plan now and decodes the technique's mask of the last frame.
    pub fn mask(&mut self) -> Result<Mask, RenderError> {
        self.ctx.make_current()?;
        let frames = self.frames_ms.len() as u32;
        let p = self.pipeline.as_mut();
        run(p, &self.ctx, "mask", frames, &self.plan.mask.commands)?;
        Ok(self.plan.mask.decode(|slot| p.readback(slot))?)
    }

    /// Renders one frame and returns its time in milliseconds.
    pub fn frame(&mut self) -> Result<f64, RenderError> {
        self.ctx.make_current()?;
        let n = self.frames_ms.len() as u32 + 1;
        let mut stale = self.maps_from.is_none();
        if let Some(orbit) = self.options.orbit {
            // The scene moved: plan again (cheap: commands over the same geometry). Only a
            // re-planned frame can change the map passes, so only it compares them.
            let scene = orbit.scene_at(&self.base, n);
            let technique = techniques::lookup(&scene.shadow.technique)?;
            self.plan = (technique.plan)(&scene, &self.prepared)?;
            self.scene = scene;
            stale = stale || self.maps_from.as_ref() != Some(&self.plan.maps);
        }
        let make_maps = stale || self.options.remake_maps == RemakeMaps::Always;
        let start = Instant::now();
        let maps = self.plan.maps.len();
        for (i, pass) in self.plan.maps.iter().chain(&self.plan.passes).enumerate() {
            if i < maps && !make_maps {
                continue;
            }
            let pass_start = Instant::now();
            run(
                self.pipeline.as_mut(),
                &self.ctx,
                pass.name,
                n,
                &pass.commands,
            )?;
            if self.options.pass_times {
                self.ctx.finish();
                self.pass_ms[i].push(pass_start.elapsed().as_secs_f64() * 1e3);
            }
        }
        self.ctx.finish();
        let ms = start.elapsed().as_secs_f64() * 1e3;
        if make_maps && maps > 0 {
            self.maps_made += 1;
            self.maps_from = Some(self.plan.maps.clone());
        }
        self.frames_ms.push(ms);
        Ok(ms)
    }

    /// Executes the mask plan, reads the image (and the map when asked), releases the GL
    /// objects, and judges the mask against `truth` (ray-cast now when `None`).
    pub fn finish(mut self, truth: Option<&Truth>) -> Result<RenderOutcome, RenderError> {
        let gpu = self.read_results();
        self.release();
        let (image, mask, map_images) = gpu?;
        let truth = match truth {
            Some(t) => t.clone(),
            None => truth::truth(&self.scene, &self.options.truth)?,
        };
        let metrics = metrics::compare(&mask, &truth.mask, self.options.band)?;
        let cold_ms = self.frames_ms.first().copied().unwrap_or(0.0);
        let steady = self.frames_ms.get(1..).unwrap_or(&[]).to_vec();
        let names = self
            .plan
            .maps
            .iter()
            .map(|p| (p.name, true))
            .chain(self.plan.passes.iter().map(|p| (p.name, false)));
        let pass_times = if self.options.pass_times {
            names
                .zip(&self.pass_ms)
                .map(|((name, map), ms)| PassTime {
                    name,
                    map,
                    ms: ms.clone(),
                })
                .collect()
        } else {
            Vec::new()
        };
        Ok(RenderOutcome {
            technique: self.technique,
            pipeline: self.options.pipeline,
            backend: self.options.backend,
            context_path: self.ctx.path().to_string(),
            image,
            mask,
            truth,
            metrics,
            timings: FrameTimings::new(cold_ms, steady),
            passes: self.plan.pass_count(),
            counters: self.pipeline.counters(),
            maps_made: self.maps_made,
            pass_times,
            map_images,
            notes: self.plan.notes.clone(),
        })
    }

    fn read_results(&mut self) -> Result<GpuResults, RenderError> {
        self.ctx.make_current()?;
        let target = self.target.as_ref().ok_or(RenderError::Released)?;
        let frames = self.frames_ms.len() as u32;
        let p = self.pipeline.as_mut();
        // The picture first: mask plans may draw over it.
        let (w, h) = (self.scene.image.width, self.scene.image.height);
        let full = target.read_color(&self.ctx)?;
        // The image is the framebuffer's lower-left w×h: the last h rows, top row first.
        let mut image = image::imageops::crop_imm(&full, 0, full.height() - h, w, h).to_image();
        // What a screen shows: destination alpha holds whatever the passes computed there
        // (alpha-tested comparisons leave their values behind); the picture is opaque.
        for px in image.pixels_mut() {
            px.0[3] = 255;
        }
        run(p, &self.ctx, "mask", frames, &self.plan.mask.commands)?;
        let mask = self.plan.mask.decode(|slot| p.readback(slot))?;
        let mut map_images = Vec::new();
        if self.options.depth_map {
            if let Some(m) = &self.plan.map_image {
                for pass in &self.plan.maps {
                    run(p, &self.ctx, pass.name, frames, &pass.commands)?;
                }
                run(p, &self.ctx, "depth-map", frames, &m.commands)?;
                map_images = map_pictures(m.source, |slot| p.readback(slot))?;
            }
        }
        Ok((image, mask, map_images))
    }

    fn release(&mut self) {
        if std::mem::replace(&mut self.released, true) {
            return;
        }
        if self.ctx.make_current().is_ok() {
            self.pipeline.release(&self.ctx);
            if let Some(t) = self.target.take() {
                t.delete(&self.ctx);
            }
        }
    }
}

type GpuResults = (RgbaImage, Mask, Vec<(String, RgbaImage)>);

/// Executes one pass's commands; a command the model rejected is a technique bug.
fn run(
    pipeline: &mut dyn Pipeline,
    ctx: &GpuContext,
    pass: &'static str,
    frame: u32,
    commands: &[Command],
) -> Result<(), RenderError> {
    pipeline.execute(ctx, commands)?;
    match pipeline.take_gl_error() {
        Some(error) => Err(RenderError::Gl { pass, frame, error }),
        None => Ok(()),
    }
}

/// The light's map as pictures (see [`MapImageSource`]); rows flipped to top first.
fn map_pictures<'r>(
    source: MapImageSource,
    readback: impl Fn(u32) -> Option<&'r crate::pipeline::Readback>,
) -> Result<Vec<(String, RgbaImage)>, RenderError> {
    let (slot, size, from_float, out_bytes) = match source {
        MapImageSource::DepthFloat { slot, size } => (slot, size, None, 4),
        MapImageSource::Bytes {
            slot,
            size,
            from_float,
        } => (slot, size, from_float, 1),
        MapImageSource::Digits {
            slot,
            size,
            from_float,
        } => (slot, size, from_float, 2),
    };
    let n = size as usize * size as usize;
    let in_bytes = if from_float.is_some() { 4 } else { out_bytes };
    let r = readback(slot)
        .filter(|r| r.bytes.len() == n * in_bytes)
        .ok_or(RenderError::MapImage { slot })?;
    // A converted map: the same conversion the upload used.
    let bytes: Vec<u8> = match from_float {
        None => r.bytes.clone(),
        Some(rule) => {
            let ty = if out_bytes == 1 {
                crate::ff::PixelType::UnsignedByte
            } else {
                crate::ff::PixelType::UnsignedShort
            };
            crate::pipeline::convert_depth(r, ty, rule).ok_or(RenderError::MapImage { slot })?
        }
    };
    let bytes_per = out_bytes;
    let row = size as usize * bytes_per;
    let texels: Vec<&[u8]> = bytes
        .chunks_exact(row)
        .rev()
        .flat_map(|line| line.chunks_exact(bytes_per))
        .collect();
    let grey = |v: u8| image::Rgba([v, v, v, 255]);
    let picture = |f: &dyn Fn(&[u8]) -> image::Rgba<u8>| {
        let mut img = RgbaImage::new(size, size);
        for (p, t) in img.pixels_mut().zip(&texels) {
            *p = f(t);
        }
        img
    };
    Ok(match source {
        MapImageSource::DepthFloat { .. } => vec![(
            "depth".to_string(),
            picture(&|t| {
                let z = f32::from_ne_bytes([t[0], t[1], t[2], t[3]]);
                grey((z.clamp(0.0, 1.0) * 255.0).round() as u8)
            }),
        )],
        MapImageSource::Bytes { .. } => vec![("depth".to_string(), picture(&|t| grey(t[0])))],
        MapImageSource::Digits { .. } => {
            let d = |t: &[u8]| u16::from_ne_bytes([t[0], t[1]]);
            vec![
                (
                    "big-digit".to_string(),
                    picture(&|t| grey((d(t) >> 8) as u8)),
                ),
                (
                    "little-digit".to_string(),
                    picture(&|t| pseudo_colour((d(t) & 0xff) as u8)),
                ),
            ]
        }
    })
}

/// A hue ramp over 0..=255 (blue → cyan → green → yellow → red), so that neighbouring
/// little-digit values read as different colours, like the slide's pseudo-colour inset.
pub fn pseudo_colour(v: u8) -> image::Rgba<u8> {
    let x = f32::from(v) / 255.0 * 4.0;
    let (r, g, b) = match x as u32 {
        0 => (0.0, x, 1.0),
        1 => (0.0, 1.0, 2.0 - x),
        2 => (x - 2.0, 1.0, 0.0),
        _ => (1.0, (4.0 - x).max(0.0), 0.0),
    };
    let c = |f: f32| (f.clamp(0.0, 1.0) * 255.0).round() as u8;
    image::Rgba([c(r), c(g), c(b), 255])
}
