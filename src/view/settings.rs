//! What the viewer shows and how it renders it, and what each [`Action`] changes.
//!
//! The settings are the scene's `[shadow]` table, the technique and pipeline, how far the
//! light and the camera were turned ([`Turn`]s from the scene as loaded) and which view is
//! shown. [`ViewSettings::act`] applies an action and says how much work it costs
//! ([`Change`]): a new session (technique, pipeline, depth bits, map size, precision: the
//! context, framebuffer or programs differ), a restaged one (offset, filter: the same
//! framebuffer), a moved one (light, camera), or only a new picture.
//!
//! [`ViewSettings::render_command`] writes the `fixedfunc render` command line that
//! reproduces the view: only what differs from the scene as loaded is given, so the
//! figures of both say where the offset came from alike.

use crate::gpu::Backend;
use crate::render::{pipeline_name, ImageSize, OrbitTarget, Turn};
use crate::scene::{OffsetSetting, Scene, ShadowSettings};
use crate::vocab::{
    offset_text, DepthBits, MapFilter, Named, PipelineKind, PolygonOffset, Precision, TechniqueId,
};

use super::keys::Action;

/// The factor step of `f` / `F`.
pub const FACTOR_STEP: f32 = 0.25;
/// Degrees an arrow key turns the light or camera.
pub const ARROW_DEGREES: f32 = 5.0;
/// Degrees a pixel of drag turns the light or camera.
pub const DRAG_DEGREES_PER_PIXEL: f32 = 0.5;
/// Map sizes `m` / `M` stay within.
pub const MAP_SIZES: (u32, u32) = (16, 4096);

/// What the window shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Show {
    Image,
    Mask,
    /// The mask against the truth: false shadow orange, missed blue.
    Error,
    /// The light's map (for a technique that makes one).
    Map,
    /// Image, error and map side by side.
    SideBySide,
}

impl Show {
    pub const ALL: [Show; 5] = [
        Show::Image,
        Show::Mask,
        Show::Error,
        Show::Map,
        Show::SideBySide,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Show::Image => "image",
            Show::Mask => "mask",
            Show::Error => "error",
            Show::Map => "map",
            Show::SideBySide => "side by side",
        }
    }
}

/// How much work a change costs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Change {
    /// Nothing to redo.
    None,
    /// The same frame, shown another way.
    Picture,
    /// The light or camera moved: the session moves (maps remade only if the light moved).
    Move,
    /// Offset or filter: the session is restaged over the same framebuffer.
    Restage,
    /// A new session: another context, framebuffer or pipeline.
    Rebuild,
}

/// What the viewer renders and shows.
#[derive(Debug, Clone, PartialEq)]
pub struct ViewSettings {
    pub pipeline: PipelineKind,
    /// The `[shadow]` table, technique included.
    pub shadow: ShadowSettings,
    /// Degrees (azimuth, elevation) the light and camera are turned from the scene's.
    pub light: (f32, f32),
    pub camera: (f32, f32),
    pub show: Show,
    pub help: bool,
}

impl ViewSettings {
    /// The settings of `scene` as loaded.
    pub fn of(scene: &Scene, pipeline: PipelineKind) -> ViewSettings {
        ViewSettings {
            pipeline,
            shadow: scene.shadow.clone(),
            light: (0.0, 0.0),
            camera: (0.0, 0.0),
            show: Show::Image,
            help: false,
        }
    }

    pub fn technique(&self) -> TechniqueId {
        self.shadow.technique
    }

    /// The scene to render: `base` with these settings and turns.
    pub fn scene(&self, base: &Scene) -> Scene {
        let mut scene = base.clone();
        for turn in self.turns() {
            scene = turn.apply(&scene);
        }
        scene.shadow = self.shadow.clone();
        scene
    }

    /// The light's and the camera's turns, when not zero.
    pub fn turns(&self) -> Vec<Turn> {
        [
            (OrbitTarget::Light, self.light),
            (OrbitTarget::Camera, self.camera),
        ]
        .into_iter()
        .filter(|(_, (az, el))| *az != 0.0 || *el != 0.0)
        .map(|(target, (azimuth, elevation))| Turn {
            target,
            azimuth,
            elevation,
        })
        .collect()
    }

    /// Applies `action`; `initial` is what `r` resets to.
    pub fn act(&mut self, action: Action, initial: &ViewSettings) -> Change {
        let s = &mut self.shadow;
        match action {
            Action::Technique(step) => {
                let all = TechniqueId::NAMES;
                let i = all.iter().position(|(_, t)| *t == s.technique).unwrap_or(0) as i64;
                let next = (i + i64::from(step)).rem_euclid(all.len() as i64) as usize;
                s.technique = all[next].1;
                Change::Rebuild
            }
            Action::Factor(step) => {
                let o = self.offset_or_zero();
                self.set_offset(PolygonOffset {
                    factor: o.factor + f32::from(step) * FACTOR_STEP,
                    ..o
                })
            }
            Action::Units(step) => {
                let o = self.offset_or_zero();
                self.set_offset(PolygonOffset {
                    units: o.units + f32::from(step) * self.units_per_lsb(),
                    ..o
                })
            }
            Action::UnitsScale(step) => {
                let o = self.offset_or_zero();
                let units = if step > 0 {
                    o.units * 2.0
                } else {
                    o.units / 2.0
                };
                self.set_offset(PolygonOffset { units, ..o })
            }
            Action::NoOffset => {
                s.polygon_offset = OffsetSetting::command_line(None);
                Change::Restage
            }
            Action::DefaultOffset => {
                s.polygon_offset = initial.shadow.polygon_offset;
                Change::Restage
            }
            Action::DepthBits => {
                let all = DepthBits::ALL;
                let i = all.iter().position(|d| *d == s.depth).unwrap_or(0);
                s.depth = all[(i + 1) % all.len()];
                Change::Rebuild
            }
            Action::MapSize(step) => {
                let size = if step > 0 {
                    s.map_size.saturating_mul(2)
                } else {
                    s.map_size / 2
                };
                let size = size.clamp(MAP_SIZES.0, MAP_SIZES.1);
                if size == s.map_size {
                    return Change::None;
                }
                s.map_size = size;
                Change::Rebuild
            }
            Action::Filter => {
                s.filter = match s.filter {
                    MapFilter::Nearest => MapFilter::Linear,
                    MapFilter::Linear => MapFilter::Nearest,
                };
                Change::Restage
            }
            Action::Precision => {
                s.precision = match s.precision {
                    Precision::Float => Precision::Fixed8,
                    Precision::Fixed8 => Precision::Float,
                };
                Change::Rebuild
            }
            Action::Pipeline => {
                self.pipeline = match self.pipeline {
                    PipelineKind::Emulate => PipelineKind::Native,
                    PipelineKind::Native => PipelineKind::Emulate,
                };
                Change::Rebuild
            }
            Action::NextShow => {
                let i = Show::ALL.iter().position(|v| *v == self.show).unwrap_or(0);
                self.show = Show::ALL[(i + 1) % Show::ALL.len()];
                Change::Picture
            }
            Action::Show(n) => {
                self.show = Show::ALL[usize::from(n).min(Show::ALL.len() - 1)];
                Change::Picture
            }
            Action::TurnLight(az, el) => turn(&mut self.light, az, el),
            Action::TurnCamera(az, el) => turn(&mut self.camera, az, el),
            Action::Help => {
                self.help = !self.help;
                Change::Picture
            }
            Action::Reset => {
                let rebuild = self.pipeline != initial.pipeline
                    || self.shadow.technique != initial.shadow.technique
                    || self.shadow.depth != initial.shadow.depth
                    || self.shadow.map_size != initial.shadow.map_size
                    || self.shadow.precision != initial.shadow.precision;
                *self = initial.clone();
                if rebuild {
                    Change::Rebuild
                } else {
                    Change::Restage
                }
            }
            Action::Save | Action::PrintCommand | Action::Quit => Change::None,
        }
    }

    /// A drag of (dx, dy) pixels (y down): the light, or the camera with shift.
    pub fn drag(&mut self, dx: f64, dy: f64, shift: bool) -> Change {
        let which = if shift {
            &mut self.camera
        } else {
            &mut self.light
        };
        which.0 += dx as f32 * DRAG_DEGREES_PER_PIXEL;
        which.1 -= dy as f32 * DRAG_DEGREES_PER_PIXEL;
        Change::Move
    }

    /// One LSB of the current depth format in glPolygonOffset units (Mesa: one unit is
    /// two LSBs of a 16- or 24-bit buffer; at 32F one unit is 2⁻²⁴ in [0.5, 1), the
    /// format's step there).
    pub fn units_per_lsb(&self) -> f32 {
        if self.shadow.depth.is_float() {
            1.0
        } else {
            0.5
        }
    }

    fn offset_or_zero(&self) -> PolygonOffset {
        self.shadow.offset().unwrap_or(PolygonOffset {
            factor: 0.0,
            units: 0.0,
        })
    }

    fn set_offset(&mut self, offset: PolygonOffset) -> Change {
        self.shadow.polygon_offset = OffsetSetting::command_line(Some(offset));
        Change::Restage
    }

    /// `fixedfunc render …` reproducing this view of `scene` (its path; the built-in
    /// default scene when `None`) as `initial` loaded it.
    pub fn render_command(
        &self,
        scene: Option<&str>,
        initial: &ViewSettings,
        backend: Backend,
        size: Option<ImageSize>,
    ) -> Vec<String> {
        let mut words = vec!["fixedfunc".to_string(), "render".to_string()];
        words.extend(scene.map(str::to_string));
        let mut give = |flag: &str, value: String| {
            words.push(flag.to_string());
            words.push(value);
        };
        let (s, i) = (&self.shadow, &initial.shadow);
        give("--technique", s.technique.to_string());
        give("--pipeline", pipeline_name(self.pipeline).to_string());
        if backend != Backend::Egl {
            give("--backend", backend.to_string());
        }
        if let Some(size) = size {
            give("--size", format!("{}x{}", size.width, size.height));
        }
        if s.polygon_offset != i.polygon_offset {
            give("--offset", offset_text(s.offset()));
        }
        if s.depth != i.depth {
            give("--depth-bits", s.depth.name().to_string());
        }
        if s.map_size != i.map_size {
            give("--map-size", s.map_size.to_string());
        }
        if s.filter != i.filter {
            give("--filter", s.filter.name().to_string());
        }
        if s.precision != i.precision {
            give("--precision", s.precision.name().to_string());
        }
        for turn in self.turns() {
            give("--turn", turn.to_string());
        }
        words
    }
}

fn turn(which: &mut (f32, f32), az: i8, el: i8) -> Change {
    which.0 += f32::from(az) * ARROW_DEGREES;
    which.1 += f32::from(el) * ARROW_DEGREES;
    Change::Move
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settings() -> ViewSettings {
        let mut scene = Scene::default_scene();
        scene.shadow.technique = TechniqueId::DepthCompare;
        ViewSettings::of(&scene, PipelineKind::Emulate)
    }

    #[test]
    fn each_action_changes_its_setting_at_its_cost() {
        let initial = settings();
        let mut v = initial.clone();
        assert_eq!(v.act(Action::Technique(1), &initial), Change::Rebuild);
        assert_eq!(v.technique(), TechniqueId::Dual8);
        assert_eq!(v.act(Action::Technique(-1), &initial), Change::Rebuild);
        v.act(Action::Technique(-1), &initial);
        v.act(Action::Technique(-1), &initial);
        assert_eq!(
            v.technique(),
            TechniqueId::OcclusionTextures,
            "wraps around"
        );
        let mut v = initial.clone();
        let kilgard = v.shadow.offset().expect("depth-compare has a default");
        assert_eq!(v.act(Action::Units(1), &initial), Change::Restage);
        assert_eq!(
            v.shadow.offset().map(|o| o.units),
            Some(kilgard.units + 0.5)
        );
        assert_eq!(v.act(Action::Factor(-1), &initial), Change::Restage);
        assert_eq!(
            v.shadow.offset().map(|o| o.factor),
            Some(kilgard.factor - FACTOR_STEP)
        );
        v.act(Action::NoOffset, &initial);
        assert_eq!(v.shadow.offset(), None);
        v.act(Action::DefaultOffset, &initial);
        assert_eq!(v.shadow.offset(), Some(kilgard));
        assert_eq!(v.act(Action::DepthBits, &initial), Change::Rebuild);
        assert_eq!(v.shadow.depth, DepthBits::D32F);
        assert_eq!(v.units_per_lsb(), 1.0);
        for _ in 0..12 {
            v.act(Action::MapSize(1), &initial);
        }
        assert_eq!(v.shadow.map_size, MAP_SIZES.1);
        assert_eq!(v.act(Action::MapSize(1), &initial), Change::None);
        assert_eq!(v.act(Action::Show(9), &initial), Change::Picture);
        assert_eq!(v.show, Show::SideBySide);
        assert_eq!(v.act(Action::TurnLight(1, -1), &initial), Change::Move);
        assert_eq!(v.light, (ARROW_DEGREES, -ARROW_DEGREES));
        assert_eq!(v.drag(10.0, 4.0, true), Change::Move);
        assert_eq!(v.camera, (5.0, -2.0));
        assert_eq!(v.act(Action::Reset, &initial), Change::Rebuild);
        assert_eq!(v, initial);
    }

    #[test]
    fn the_render_command_gives_only_what_the_view_changed() {
        let initial = settings();
        let mut v = initial.clone();
        let words = v.render_command(None, &initial, Backend::Egl, None);
        assert_eq!(
            words.join(" "),
            "fixedfunc render --technique depth-compare --pipeline emulate"
        );
        v.act(Action::Units(1), &initial);
        v.act(Action::DepthBits, &initial);
        v.act(Action::TurnLight(1, 0), &initial);
        let words = v.render_command(Some("a.toml"), &initial, Backend::Egl, None);
        assert_eq!(
            words.join(" "),
            "fixedfunc render a.toml --technique depth-compare --pipeline emulate \
             --offset 1,4.5 --depth-bits 32f --turn light:5,0"
        );
    }
}
