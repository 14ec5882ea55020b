//! The viewer's loop: input in, a frame rendered only when something changed, the picture
//! shown, the truth's verdict added when it arrives.
//!
//! **Interactive** (no frame count): the loop sleeps on the event channel until the user
//! does something or a truth arrives, so an idle viewer uses no CPU; an input is answered
//! by one frame (and, for a new technique, depth format, pipeline, map size or precision,
//! a new session first).
//!
//! **Deterministic** (`frames` given, with or without a [`KeyScript`]): every turn of the
//! loop is one frame; the script's inputs for that frame apply first (the window's own
//! input is ignored, but for closing it), and the frame waits for its view's truth, so the
//! overlay's error is the truth's verdict on that very frame, as `render`'s is. After the
//! last frame what the window showed is returned.
//!
//! A change that fails (a technique the pipeline cannot run, a map too large) is undone
//! and said on the status bar; the previous session goes on.

use std::path::PathBuf;
use std::sync::mpsc;

use image::RgbaImage;

use crate::gpu::{Backend, Input};
use crate::metrics::{Mask, Metrics};
use crate::render::{self, error_text, ImageSize, LightMap, RenderError, RenderOptions, Session};
use crate::report;
use crate::scene::Scene;
use crate::truth::{Truth, TruthOptions};
use crate::vocab::{offset_text, Named};

use super::compose::{self, FrameParts};
use super::keys::{self, Action};
use super::script::KeyScript;
use super::settings::{Change, Show, ViewSettings};
use super::threads::{Event, TruthWorker, WindowThread};
use super::ViewError;

/// What the viewer is asked to do beyond the scene.
#[derive(Debug, Clone)]
pub struct ViewOptions {
    /// Where the scene is rendered (headless; the window only shows the result).
    pub backend: Backend,
    pub size: Option<ImageSize>,
    /// The scene's path as the user gave it (for the printed render command).
    pub scene_path: Option<String>,
    /// Inputs with the frame they arrive before.
    pub script: Option<KeyScript>,
    /// Render exactly this many frames, then stop (deterministic).
    pub frames: Option<u32>,
    /// Where `s` writes its pictures.
    pub save_dir: PathBuf,
    pub truth: TruthOptions,
    /// Edge band of the metrics, as `render`'s.
    pub band: u32,
}

/// What a viewer run ends with.
pub struct ViewEnd {
    pub frames: u32,
    /// What the window showed last.
    pub shown: Option<RgbaImage>,
    /// The status bar's lines of the last frame.
    pub status: Vec<String>,
    /// The render command of the last view.
    pub command: Vec<String>,
}

/// The latest frame and what is known about it.
struct Latest {
    image: RgbaImage,
    mask: Mask,
    map: Option<LightMap>,
    ms: f64,
}

struct Viewer<'a> {
    base: &'a Scene,
    options: &'a ViewOptions,
    initial: ViewSettings,
    settings: ViewSettings,
    /// The settings the session was made with (restored when a change fails).
    made_with: ViewSettings,
    session: Session,
    latest: Option<Latest>,
    /// The view (light and camera) the truth is wanted for, and its number.
    view: ((f32, f32), (f32, f32), u64),
    truth: Option<(u64, Truth)>,
    metrics: Option<Metrics>,
    truths: TruthWorker,
    message: String,
    saved: u32,
    say: &'a mut dyn FnMut(String),
}

fn session(
    base: &Scene,
    settings: &ViewSettings,
    options: &ViewOptions,
) -> Result<Session, RenderError> {
    Session::new(
        &settings.scene(base),
        &RenderOptions {
            backend: options.backend,
            pipeline: settings.pipeline,
            size: options.size,
            truth: options.truth,
            band: options.band,
            ..RenderOptions::default()
        },
    )
}

/// Runs the viewer on `base` from `settings` until the user quits or the frames are done;
/// `say` prints a line (the help, printed commands, saved files).
pub fn run(
    base: &Scene,
    settings: ViewSettings,
    options: &ViewOptions,
    say: &mut dyn FnMut(String),
) -> Result<ViewEnd, ViewError> {
    let (events, heard) = mpsc::channel::<Event>();
    let window = WindowThread::spawn(events.clone())?;
    let truths = TruthWorker::spawn(events, options.truth);
    let first = session(base, &settings, options)?;
    let mut v = Viewer {
        base,
        options,
        initial: settings.clone(),
        made_with: settings.clone(),
        settings,
        session: first,
        latest: None,
        view: ((f32::NAN, 0.0), (0.0, 0.0), 0),
        truth: None,
        metrics: None,
        truths,
        message: format!("window: {}", window.describe),
        saved: 0,
        say,
    };
    let deterministic = options.frames.is_some();
    let mut frames = 0u32;
    let mut shown: Option<RgbaImage> = None;
    let mut change = Change::Rebuild;
    let mut quit = false;
    loop {
        if deterministic {
            for input in options.script.iter().flat_map(|s| s.at(frames + 1)) {
                change = change.max(v.input(input, shown.as_ref(), &mut quit)?);
            }
            while let Ok(event) = heard.try_recv() {
                change = change.max(v.event(event, true, shown.as_ref(), &mut quit)?);
            }
        } else if change == Change::None {
            let Ok(event) = heard.recv() else { break };
            change = v.event(event, false, shown.as_ref(), &mut quit)?;
            while let Ok(event) = heard.try_recv() {
                change = change.max(v.event(event, false, shown.as_ref(), &mut quit)?);
            }
        }
        if quit {
            break;
        }
        if change >= Change::Move || v.latest.is_none() || deterministic {
            v.apply(change)?;
            v.render()?;
        }
        if deterministic {
            v.wait_for_truth(&heard)?;
        }
        if change > Change::None || deterministic {
            let picture = v.picture()?;
            shown = Some(window.show(picture)?);
            frames += 1;
        }
        change = Change::None;
        if options.frames.is_some_and(|n| frames >= n) {
            break;
        }
    }
    Ok(ViewEnd {
        frames,
        shown,
        status: v.status(),
        command: v.command(),
    })
}

impl Viewer<'_> {
    /// Takes one event; returns the work it asks for.
    fn event(
        &mut self,
        event: Event,
        scripted: bool,
        shown: Option<&RgbaImage>,
        quit: &mut bool,
    ) -> Result<Change, ViewError> {
        match event {
            Event::Input(Input::Closed) => {
                *quit = true;
                Ok(Change::None)
            }
            Event::Input(_) if scripted => Ok(Change::None),
            Event::Input(input) => self.input(input, shown, quit),
            Event::Truth { id, result } => self.truth_arrived(id, *result),
        }
    }

    fn input(
        &mut self,
        input: Input,
        shown: Option<&RgbaImage>,
        quit: &mut bool,
    ) -> Result<Change, ViewError> {
        let action = match input {
            Input::Key { key, shift } => match keys::action(key, shift) {
                Some(a) => a,
                None => return Ok(Change::None),
            },
            Input::Drag { dx, dy, shift } => return Ok(self.settings.drag(dx, dy, shift)),
            Input::Exposed => return Ok(Change::Picture),
            Input::Closed => {
                *quit = true;
                return Ok(Change::None);
            }
        };
        match action {
            Action::Quit => *quit = true,
            Action::Save => self.save(shown)?,
            Action::PrintCommand => {
                let line = self
                    .command()
                    .iter()
                    .map(|w| report::provenance::shell_word(w))
                    .collect::<Vec<_>>()
                    .join(" ");
                (self.say)(line);
                self.message = "the render command is printed on stdout".into();
            }
            Action::Help if !self.settings.help => {
                for line in keys::help_lines() {
                    (self.say)(line);
                }
            }
            _ => {}
        }
        Ok(self.settings.act(action, &self.initial))
    }

    fn truth_arrived(
        &mut self,
        id: u64,
        result: Result<Truth, crate::truth::TruthError>,
    ) -> Result<Change, ViewError> {
        if id != self.view.2 {
            return Ok(Change::None);
        }
        let truth = result?;
        self.truth = Some((id, truth));
        self.judge();
        Ok(Change::Picture)
    }

    fn judge(&mut self) {
        self.metrics = match (&self.latest, &self.truth) {
            (Some(l), Some((id, t))) if *id == self.view.2 => {
                match render::judge(&l.mask, t, self.options.band) {
                    Ok(m) => Some(m),
                    Err(e) => {
                        self.message = e.to_string();
                        None
                    }
                }
            }
            _ => None,
        };
    }

    /// Brings the session to the settings: a new one, restaged or moved.
    fn apply(&mut self, change: Change) -> Result<(), ViewError> {
        if change == Change::Rebuild && self.settings != self.made_with {
            let wanted = self.settings.clone();
            match session(self.base, &wanted, self.options) {
                Ok(s) => {
                    self.session = s;
                    self.made_with = wanted;
                }
                Err(e) => {
                    self.message = format!("kept the previous settings: {e}");
                    let (show, help) = (self.settings.show, self.settings.help);
                    self.settings = ViewSettings {
                        show,
                        help,
                        ..self.made_with.clone()
                    };
                }
            }
        }
        let scene = self.settings.scene(self.base);
        if scene.shadow != self.session.scene().shadow {
            match self.session.restage(&self.settings.shadow) {
                Ok(()) => {}
                Err(RenderError::Restage) => {
                    self.session = session(self.base, &self.settings, self.options)?;
                }
                Err(e) => return Err(e.into()),
            }
        }
        self.made_with = self.settings.clone();
        let sized = render::apply_overrides(&scene, self.options.size, None);
        self.session.move_to(sized)?;
        Ok(())
    }

    /// Renders a frame and reads what the view needs; asks for the truth of a new view.
    fn render(&mut self) -> Result<(), ViewError> {
        let ms = self.session.frame()?;
        let image = self.session.image()?;
        let mask = self.session.mask()?;
        let map = if matches!(self.settings.show, Show::Map | Show::SideBySide) {
            self.session.light_map()?
        } else {
            None
        };
        self.latest = Some(Latest {
            image,
            mask,
            map,
            ms,
        });
        let view = (self.settings.light, self.settings.camera);
        if (view.0, view.1) != (self.view.0, self.view.1) {
            self.view = (view.0, view.1, self.view.2 + 1);
            self.truth = None;
            let scene = self.session.scene().clone();
            if !self.truths.request(self.view.2, scene) {
                self.message = "the truth worker has stopped: no error figures".into();
            }
        }
        self.judge();
        Ok(())
    }

    /// Waits until the truth of the current view has arrived (deterministic runs).
    fn wait_for_truth(&mut self, heard: &mpsc::Receiver<Event>) -> Result<(), ViewError> {
        while self.truth.as_ref().is_none_or(|(id, _)| *id != self.view.2) {
            match heard.recv() {
                Ok(Event::Truth { id, result }) => {
                    self.truth_arrived(id, *result)?;
                }
                Ok(Event::Input(_)) => {}
                Err(_) => return Err(ViewError::TruthWorkerGone),
            }
        }
        Ok(())
    }

    /// The picture of the latest frame with its status bar (and the help, when asked).
    fn picture(&mut self) -> Result<RgbaImage, ViewError> {
        let wants_map = matches!(self.settings.show, Show::Map | Show::SideBySide);
        if let Some(latest) = self.latest.as_mut() {
            if wants_map && latest.map.is_none() {
                latest.map = self.session.light_map()?;
            }
        }
        let Some(latest) = &self.latest else {
            return Err(ViewError::NoFrame);
        };
        let truth = self
            .truth
            .as_ref()
            .filter(|(id, _)| *id == self.view.2)
            .map(|(_, t)| &t.mask);
        let top = compose::top(
            self.settings.show,
            &FrameParts {
                image: &latest.image,
                mask: &latest.mask,
                truth,
                map: latest.map.as_ref(),
            },
        );
        let help = self.settings.help.then(keys::help_lines);
        Ok(compose::picture(&top, &self.status(), help.as_deref())?)
    }

    /// The status bar: settings; error, time and maps; view, turns and the last message.
    fn status(&self) -> Vec<String> {
        let s = &self.settings.shadow;
        let technique = s.technique;
        let mut first = format!(
            "{technique} · {}",
            render::pipeline_name(self.settings.pipeline)
        );
        if technique.uses_offset() {
            let offset = s.offset();
            first += &format!(" · offset {} ({})", offset_text(offset), s.offset_source());
            if let Some(o) = offset {
                first += &format!(" = {}", s.depth.offset_units_in_steps(o.units));
            }
        }
        first += &format!(
            " · depth {} · map {}² · {} · {}",
            s.depth.name(),
            s.map_size,
            s.filter.name(),
            s.precision.name()
        );
        let error = match &self.metrics {
            Some(m) => error_text(m.all.wrong_percent, m.all.false_shadow, m.all.missed_shadow),
            None => "error: ray-casting the truth…".to_string(),
        };
        let (ms, maps) = self
            .latest
            .as_ref()
            .map_or((0.0, 0), |l| (l.ms, self.session.maps_made()));
        let second = format!("{error} · {ms:.2} ms/frame · {maps} maps made");
        let (l, c) = (self.settings.light, self.settings.camera);
        let third = format!(
            "view {} · light {}°,{}° · camera {}°,{}° · h keys · {}",
            self.settings.show.name(),
            l.0,
            l.1,
            c.0,
            c.1,
            self.message
        );
        vec![first, second, third]
    }

    /// The render command of the current view.
    fn command(&self) -> Vec<String> {
        self.settings.render_command(
            self.options.scene_path.as_deref(),
            &self.initial,
            self.options.backend,
            self.options.size,
        )
    }

    /// Writes what the window shows to the next free `view-N.png` in the save folder.
    fn save(&mut self, shown: Option<&RgbaImage>) -> Result<(), ViewError> {
        let Some(picture) = shown else {
            self.message = "nothing shown yet to save".into();
            return Ok(());
        };
        let path = loop {
            self.saved += 1;
            let path = self
                .options
                .save_dir
                .join(format!("view-{}.png", self.saved));
            if !path.exists() {
                break path;
            }
        };
        report::save_png(picture, &path)?;
        (self.say)(format!("saved {}", path.display()));
        self.message = format!("saved {}", path.display());
        Ok(())
    }
}
