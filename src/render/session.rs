//! One render held open: context, framebuffer, pipeline and plan, frames on demand.
//!
//! [`Session::new`] applies the options' overrides to a copy of the scene, prepares the
//! geometry once (`techniques::Prepared`), builds the technique's plan, creates a context of
//! the pipeline's profile on the backend (a private Xvfb for the window backend when no
//! display is set), the framebuffer the plan asks for (RGBA8, the light's depth bits,
//! stencil when a technique uses it; large enough for the image and the light's map, which
//! share it as on the era's hardware) and the pipeline (`pipeline::create_with`, the only
//! code naming a concrete path; behind the C library's front when the objects are
//! submitted in immediate mode or display lists: `render::submission`), then executes the
//! plan's setup once.
//!
//! [`Session::frame`] is timed from its first command to glFinish returning, so the
//! driver's work is inside the figure. Frame 1 is *cold* (programs compiled, buffers
//! uploaded, maps made); later frames are *steady*. The map passes run on frame 1 and then
//! only when the maps are stale: under an [`Orbit`](super::Orbit) each frame is re-planned
//! over the same geometry, and the maps are stale exactly when the new map passes differ
//! from those that made them — or every frame with [`RemakeMaps::Always`].
//!
//! [`Session::finish`] executes the mask plan, decodes the mask, reads the colour image
//! (the image's corner of the framebuffer) and the light's map when asked, takes the
//! counters, releases the GL objects, and judges the mask against the truth — and, for an
//! area light, the visibility too (a soft technique's accumulated one, a hard technique's
//! mask as 0 or 1: `metrics::visibility_errors`) and, for a scene of several objects, the
//! error by object (`render::object_split`; a study traces the truth's causes once and
//! hands them to every [`Session::finish_with_causes`]).
//!
//! **The accumulation buffer.** A plan whose commands use it (`Plan::needs_accumulation`)
//! gets one of the framebuffer's size. The emulated path keeps it beside the context and
//! draws into the render target as always. The native path has one only on an OSMesa
//! window buffer (Mesa gives framebuffer objects none): the session then asks OSMesa for a
//! window of the framebuffer's size (24 depth and 8 stencil bits) and draws into
//! framebuffer 0 instead of a target; on EGL it refuses with
//! `PipelineError::NoAccumBuffer`, which names `--backend osmesa`.

use glow::HasContext;
use std::time::Instant;

use image::RgbaImage;

use crate::gpu::{
    Backend, ContextRequest, GpuContext, RenderTarget, TargetSpec, VirtualDisplay, WindowBuffer,
};
use crate::metrics::{Mask, ShadowCauses, VisibilityImage};
use crate::pipeline::{Pipeline, PipelineError};
use crate::scene::{Scene, ShadowSettings};
use crate::techniques::{self, Pass, Plan, Prepared};
use crate::truth::{self, Truth};
use crate::vocab::{DepthBits, PipelineKind, TechniqueId};

use super::{
    apply_overrides, run, Footprint, FrameTimings, LightMap, PassTime, RemakeMaps, RenderError,
    RenderOptions, RenderOutcome, MAX_IMAGE_SIZE,
};

/// One render held open: context, framebuffer, pipeline and plan, frames on demand.
pub struct Session {
    scene: Scene,
    /// The scene as given (frame 1), from which an orbit computes later frames.
    base: Scene,
    prepared: Prepared,
    plan: Plan,
    /// The map passes that made the current maps: the maps are stale exactly when the next
    /// frame's map passes differ from these (the light, a caster or a setting moved).
    maps_from: Option<Vec<Pass>>,
    options: RenderOptions,
    // Dropped in this order: the pipeline and target are released explicitly first.
    pipeline: Box<dyn Pipeline>,
    target: Option<RenderTarget>,
    /// The OSMesa window the native path draws into when the plan accumulates (no target
    /// then).
    window: Option<WindowBuffer>,
    ctx: GpuContext,
    _display: Option<VirtualDisplay>,
    frames_ms: Vec<f64>,
    pass_ms: Vec<Vec<f64>>,
    maps_made: u32,
    released: bool,
    /// Set by [`Session::pass_images`] for the one frame whose passes it pictures.
    capture: Option<super::pass_images::Capture>,
}

impl Drop for Session {
    fn drop(&mut self) {
        self.release();
    }
}

/// The plan of the scene's technique.
fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, RenderError> {
    let technique = techniques::technique(scene.shadow.technique);
    Ok((technique.plan)(scene, prepared)?)
}

impl Session {
    /// Plans the technique, creates the context, framebuffer and pipeline, and executes
    /// the plan's setup.
    pub fn new(scene: &Scene, options: &RenderOptions) -> Result<Session, RenderError> {
        let scene = apply_overrides(scene, options.size, options.technique);
        let (width, height) = (scene.image.width, scene.image.height);
        if width > MAX_IMAGE_SIZE || height > MAX_IMAGE_SIZE {
            return Err(RenderError::ImageTooLarge {
                width,
                height,
                max: MAX_IMAGE_SIZE,
            });
        }
        Footprint::of(&scene, 1).check(&scene.limits)?;
        let prepared = Prepared::new(&scene);
        let plan = plan(&scene, &prepared)?;
        let fb = plan.framebuffer;
        if fb.width > MAX_IMAGE_SIZE || fb.height > MAX_IMAGE_SIZE {
            return Err(RenderError::MapTooLarge {
                size: scene.shadow.map_size,
                max: MAX_IMAGE_SIZE,
            });
        }
        let accumulation = plan.needs_accumulation();
        let window = match (accumulation, options.pipeline) {
            (true, PipelineKind::Native) => {
                if options.backend != Backend::OsMesa {
                    return Err(PipelineError::NoAccumBuffer {
                        backend: options.backend,
                    }
                    .into());
                }
                if fb.depth != DepthBits::D24 {
                    return Err(RenderError::WindowDepth { depth: fb.depth });
                }
                Some(WindowBuffer {
                    width: fb.width,
                    height: fb.height,
                })
            }
            _ => None,
        };
        let display = match options.backend {
            Backend::Window => VirtualDisplay::start_if_needed()?,
            Backend::Egl | Backend::OsMesa => None,
        };
        let mut request =
            ContextRequest::new(options.backend, crate::pipeline::profile(options.pipeline));
        if let Some(w) = window {
            request = request.with_window(w);
        }
        let ctx = GpuContext::new(&request)?;
        let target = match window {
            Some(_) => None,
            None => {
                let mut spec = TargetSpec::new(fb.width, fb.height, fb.depth);
                if fb.stencil {
                    spec = spec.with_stencil();
                }
                let target = RenderTarget::new(&ctx, spec)?;
                // Bound once: the binding is the context's state, and a later bind would
                // reset the viewport behind the emulated pipeline's shadow copy. The
                // pipeline starts from the target's viewport, as GL starts from the
                // window's.
                target.bind(&ctx);
                Some(target)
            }
        };
        let precision = scene.shadow.precision;
        let pipeline = if accumulation {
            let size = (fb.width, fb.height);
            crate::pipeline::create_with_accumulation(options.pipeline, &ctx, precision, size)?
        } else {
            crate::pipeline::create_with(options.pipeline, &ctx, precision)?
        };
        let mut pipeline =
            super::submission::submitting(pipeline, options.submission, &prepared.objects);
        let setup = run(pipeline.as_mut(), &ctx, "setup", 0, &plan.setup);
        let pass_ms = vec![Vec::new(); plan.pass_count()];
        let mut session = Session {
            base: scene.clone(),
            scene,
            prepared,
            plan,
            maps_from: None,
            options: options.clone(),
            pipeline,
            target,
            window,
            ctx,
            _display: display,
            frames_ms: Vec::new(),
            pass_ms,
            maps_made: 0,
            released: false,
            capture: None,
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

    /// The technique.
    pub fn technique(&self) -> TechniqueId {
        self.scene.shadow.technique
    }

    /// Times the map passes ran since the session was made or restaged.
    pub fn maps_made(&self) -> u32 {
        self.maps_made
    }

    /// How the context was obtained (backend and platform).
    pub fn context_path(&self) -> &str {
        self.ctx.path()
    }

    /// Replaces the scene's `[shadow]` settings (bias, map size, filter…) but its technique,
    /// and re-plans: the context, framebuffer, pipeline and compiled programs stay; the
    /// maps are stale, so the next frame makes them again. The framebuffer must suit the
    /// new plan (same depth bits and stencil, large enough), else [`RenderError::Restage`].
    pub fn restage(&mut self, shadow: &ShadowSettings) -> Result<(), RenderError> {
        let mut scene = self.scene.clone();
        scene.shadow = ShadowSettings {
            technique: scene.shadow.technique,
            ..shadow.clone()
        };
        let plan = plan(&scene, &self.prepared)?;
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
        Ok(self.masks()?.0)
    }

    /// Executes the mask plan now: the technique's mask of the last frame, and its
    /// visibility when the technique accumulates one (`MaskSource::Visibility`).
    pub fn masks(&mut self) -> Result<(Mask, Option<VisibilityImage>), RenderError> {
        self.ctx.make_current()?;
        let frames = self.frames_ms.len() as u32;
        let p = self.pipeline.as_mut();
        run(p, &self.ctx, "mask", frames, &self.plan.mask.commands)?;
        let mask = self.plan.mask.decode(|slot| p.readback(slot))?;
        let visibility = self.plan.mask.decode_visibility(|slot| p.readback(slot))?;
        Ok((mask, visibility))
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
            self.plan = plan(&scene, &self.prepared)?;
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
            if let Some(capture) = self.capture.as_mut() {
                let target = self.target.as_ref();
                capture.after_pass(self.pipeline.as_mut(), &self.ctx, target, i, pass, n)?;
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

    /// One more frame with what each pass leaves pictured (`render::pass_images`): the
    /// maps are made again so that their passes are in it, and after it the variants of
    /// its alpha-tested passes are replayed and its eye passes executed once more, so the
    /// framebuffer holds its picture again. The frame counts as any frame: its time, its
    /// maps and the variants' programs are in this session's figures — use
    /// [`pass_images::capture`](super::pass_images::capture) to keep a measured session's
    /// figures clean. With an orbit it is the orbit's next frame.
    pub fn pass_images(&mut self) -> Result<super::PassImages, RenderError> {
        if self.window.is_some() {
            return Err(RenderError::WindowPassImages);
        }
        self.capture = Some(super::pass_images::Capture::new(&self.plan, &self.scene));
        self.maps_from = None;
        let frame = self.frame();
        let capture = self.capture.take();
        frame?;
        // Cannot fail: set four lines above, and `frame` only borrows it (`as_mut`).
        let capture = capture.expect("set above, and only taken here");
        let target = self.target.as_ref().ok_or(RenderError::Released)?;
        let frame = self.frames_ms.len() as u32;
        capture.finish(self.pipeline.as_mut(), &self.ctx, target, &self.plan, frame)
    }

    /// Executes the mask plan, reads the image (and the map when asked), releases the GL
    /// objects, and judges the mask against `truth` (ray-cast now when `None`), splitting
    /// the error by object for a scene of several (`render::object_causes`).
    pub fn finish(self, truth: Option<&Truth>) -> Result<RenderOutcome, RenderError> {
        self.finish_split(truth, Split::Trace)
    }

    /// As [`finish`](Self::finish) against `truth`, with the per-object split made from
    /// `causes`, the causes of that truth (`render::object_causes`, traced once by a study
    /// for all its sessions); `None`: no split.
    pub fn finish_with_causes(
        self,
        truth: &Truth,
        causes: Option<&ShadowCauses>,
    ) -> Result<RenderOutcome, RenderError> {
        self.finish_split(Some(truth), Split::Given(causes))
    }

    fn finish_split(
        mut self,
        truth: Option<&Truth>,
        split: Split<'_>,
    ) -> Result<RenderOutcome, RenderError> {
        let gpu = self.read_results();
        // What ran it, while the context is current (`read_results` made it so).
        // SAFETY: glGetString on the current context.
        let (gl_renderer, gl_version) = unsafe {
            let gl = self.ctx.gl();
            (
                gl.get_parameter_string(glow::RENDERER),
                gl.get_parameter_string(glow::VERSION),
            )
        };
        self.release();
        let (image, (mask, soft), light_map) = gpu?;
        let truth = match truth {
            Some(t) => t.clone(),
            None => truth::truth(&self.scene, &self.options.truth)?,
        };
        let mut metrics = super::judge(&mask, &truth, self.options.band)?;
        let visibility = super::judge_visibility(&mask, soft, &truth)?;
        metrics.visibility_rmse = visibility.as_ref().map(|v| v.errors.rmse);
        let objects = match split {
            Split::Trace => {
                let light = self.options.truth.light;
                let causes = super::object_causes(&self.scene, light, &truth.mask)?;
                super::object_split(&mask, causes.as_ref())?
            }
            Split::Given(causes) => super::object_split(&mask, causes)?,
        };
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
            technique: self.technique(),
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
            light_map,
            visibility,
            objects,
            notes: self.plan.notes.clone(),
            offset: self.scene.shadow.offset(),
            offset_source: self.scene.shadow.offset_source(),
            gl_renderer,
            gl_version,
        })
    }

    fn read_results(&mut self) -> Result<GpuResults, RenderError> {
        // The picture first: mask plans may draw over it.
        let image = self.image()?;
        let mask = self.masks()?;
        let light_map = if self.options.depth_map {
            self.light_map()?
        } else {
            None
        };
        Ok((image, mask, light_map))
    }

    /// The colour image of the last frame: the framebuffer's lower-left corner of the
    /// scene's image size, top row first, made opaque (destination alpha holds whatever the
    /// passes computed there — alpha-tested comparisons leave their values behind — while a
    /// screen shows the picture opaque).
    pub fn image(&mut self) -> Result<RgbaImage, RenderError> {
        self.ctx.make_current()?;
        let (w, h) = (self.scene.image.width, self.scene.image.height);
        let full = match (&self.target, self.window) {
            (_, Some(window)) if !self.released => {
                self.ctx.read_window_color(window.width, window.height)?
            }
            (Some(target), _) => target.read_color(&self.ctx)?,
            _ => return Err(RenderError::Released),
        };
        // The image is the framebuffer's lower-left w×h: the last h rows, top row first.
        let mut image = image::imageops::crop_imm(&full, 0, full.height() - h, w, h).to_image();
        for px in image.pixels_mut() {
            px.0[3] = 255;
        }
        Ok(image)
    }

    /// The light's map as the technique made it (its map passes run again, then the plan's
    /// depth-map read-out), or `None` for a technique without one. Draws over the image: read
    /// the image first.
    pub fn light_map(&mut self) -> Result<Option<LightMap>, RenderError> {
        self.ctx.make_current()?;
        let frames = self.frames_ms.len() as u32;
        let Some(m) = &self.plan.map_image else {
            return Ok(None);
        };
        let p = self.pipeline.as_mut();
        for pass in &self.plan.maps {
            run(p, &self.ctx, pass.name, frames, &pass.commands)?;
        }
        run(p, &self.ctx, "depth-map", frames, &m.commands)?;
        Ok(Some(LightMap::read(m.source, |slot| p.readback(slot))?))
    }

    /// Moves the light(s) and camera to those of `scene`, which must hold the session's own
    /// objects (the same meshes, as an [`Orbit`](super::Orbit) or a viewer makes them) and
    /// differ from its scene only in where things are seen from: the next frame is planned
    /// over the same prepared geometry, and its maps are made again exactly when its map
    /// passes differ from those that made the current maps.
    pub fn move_to(&mut self, scene: Scene) -> Result<(), RenderError> {
        let same_objects = scene.objects.len() == self.scene.objects.len()
            && scene
                .objects
                .iter()
                .zip(&self.scene.objects)
                .all(|(a, b)| std::sync::Arc::ptr_eq(&a.mesh, &b.mesh));
        if !same_objects || scene.shadow != self.scene.shadow || scene.image != self.scene.image {
            return Err(RenderError::NotAMove);
        }
        self.plan = plan(&scene, &self.prepared)?;
        if self.maps_from.as_ref() != Some(&self.plan.maps) {
            self.maps_from = None;
        }
        self.base = scene.clone();
        self.scene = scene;
        Ok(())
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

/// Where [`Session::finish`]'s per-object split gets the truth's shadow causes.
enum Split<'a> {
    /// Traced from the scene and the truth now.
    Trace,
    /// Traced already (`None`: no split).
    Given(Option<&'a ShadowCauses>),
}

type GpuResults = (RgbaImage, (Mask, Option<VisibilityImage>), Option<LightMap>);
