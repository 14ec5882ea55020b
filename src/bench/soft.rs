//! `bench --only soft`: the measurements behind Eisemann & Décoret's claims (seed 002,
//! *Occlusion Textures for Plausible Soft Shadows*, CGF 2008) — cost nearly independent of
//! the geometry, 4 to 16 slices enough, N-buffers the best trade-off between mipmaps and
//! summed-area tables, the probabilistic combination closer to the reference than the sum
//! or the maximum — with the era's baseline, `accumulate` (N hard shadows averaged in the
//! accumulation buffer), beside them. Six axes, each a table:
//!
//! - **slices** 4, 8, 16 (N-buffers, probabilistic, 256² occlusion textures);
//! - **texture size** 64², 128², 256², 512² (16 slices, N-buffers, probabilistic);
//! - **prefilter** mipmap, N-buffers, SAT (16 slices, probabilistic, 256²);
//! - **combine** probabilistic, sum, max (16 slices, N-buffers, 256²);
//! - **geometry**: `assets/scaling-{1,8,32,64}.toml` (copies of a 2,000-triangle torus) for
//!   `occlusion-textures` (16 slices, N-buffers) and `accumulate` at N = 4, 16, 64;
//! - **light size**: the soft scene's area light scaled ×0.5, ×1, ×2 about its centre
//!   ([`scale_area_light`]) for `occlusion-textures` (16 slices, N-buffers) and
//!   `accumulate` at N = 16.
//!
//! All on the embedded `assets/soft.toml` unless said, on the emulated path, at a
//! [`IMAGE`]² image. A configuration shared by several axes (16 slices, N-buffers,
//! probabilistic, 256² is in four) is rendered once and reported in each.
//!
//! **Time.** Per scene, every configuration's session is made first and their frames are
//! interleaved round-robin (`render::rounds`), so machine noise hits each alike. The maps
//! are remade every frame (`RemakeMaps::Always`): the slicing and prefiltering are the part
//! of the occlusion-texture technique that grows with the geometry, and `accumulate`
//! renders its N maps inside every frame anyway. The first frame (program compiles,
//! uploads) is reported apart as `cold`; the steady figure is the median [min–max] of the
//! others, each timed from its first command to glFinish returning (`Session::frame`).
//!
//! **Accuracy.** After the last frame, each session's mask plan runs once and its
//! visibility (k/255 of the light seen per pixel) is scored against the truth's
//! (`render::judge_visibility`, i.e. `metrics::visibility_errors`): RMSE over the geometry
//! pixels, the maximum |difference|, and the RMSE over the penumbra alone (truth visibility
//! strictly between 0 and 1). The truth is ray-cast once per scene (the scene's own
//! `[truth] samples`, stratified; its standard error is under 0.005) and shared by every
//! configuration of that scene. The geometry of each render is first checked against the
//! truth's (`render::judge`), so a truth that cannot judge is a skipped row, not a score.
//!
//! **Refusals.** A configuration its technique refuses (e.g. a prefilter not built yet), or
//! whose frame fails, becomes a skipped row with the reason; the other rows go on.
//!
//! **Run time.** 256², not 512²: at the default 10 repeats the whole group — seven truths
//! and 11 rounds of frames over 31 configurations — ran in 2 min 16 s on the project's two
//! llvmpipe cores (a round about 12 s; with other builds on the cores, about twice that),
//! where 512² makes the fill-limited frames 1.5 to 2 times slower and the ray casting four
//! times longer, too close to five minutes. Most of a round is `accumulate` at N = 64 on 64
//! copies (about 3.5 s a frame: 64 shadow maps of 128k triangles), which a smaller image
//! does not shorten.

use std::path::Path;

use glam::Vec3;
use serde::Serialize;

use crate::metrics::VisibilityErrors;
use crate::render::rounds::{self, Lane, Rules, Verdict};
use crate::render::{self, ImageSize, RemakeMaps, RenderError, RenderOptions, Session};
use crate::scene::{Combine, LightKind, Prefilter, Scene, SceneError};
use crate::stats::Summary;
use crate::truth::{self, Truth, TruthError, TruthOptions};
use crate::vocab::{PipelineKind, TechniqueId};

/// The image's edge in pixels (square).
pub const IMAGE: u32 = 256;
/// The slice counts of the paper (§3.1: "four to 16 slices").
pub const SLICES: [u32; 3] = [4, 8, 16];
/// The occlusion textures' edges.
pub const MAP_SIZES: [u32; 4] = [64, 128, 256, 512];
/// The prefilters of §3.2.
pub const PREFILTERS: [Prefilter; 3] = [Prefilter::Mipmap, Prefilter::Nbuffers, Prefilter::Sat];
/// The combination rules of §3.3.
pub const COMBINES: [Combine; 3] = [Combine::Probabilistic, Combine::Sum, Combine::Max];
/// The copies of the torus in the scaling scenes.
pub const COPIES: [u32; 4] = [1, 8, 32, 64];
/// `accumulate`'s renders per frame on the geometry axis.
pub const LIGHT_SAMPLES: [u32; 3] = [4, 16, 64];
/// The area light's scale on the light-size axis.
pub const LIGHT_SCALES: [f32; 3] = [0.5, 1.0, 2.0];

/// What the occlusion-texture axes hold fixed while one key varies: 16 slices, 256²
/// textures, N-buffers, the probabilistic rule.
pub const BASE_SLICES: u32 = 16;
pub const BASE_MAP_SIZE: u32 = 256;
pub const BASE_PREFILTER: Prefilter = Prefilter::Nbuffers;
pub const BASE_COMBINE: Combine = Combine::Probabilistic;
/// The base configuration, shared by five rows (rendered once).
pub const OCCLUSION_BASE: Knobs =
    occlusion(BASE_SLICES, BASE_MAP_SIZE, BASE_PREFILTER, BASE_COMBINE);
/// `accumulate` on the light-size axis.
pub const ACCUMULATE_BASE: Knobs = Knobs::Accumulate { light_samples: 16 };

const SOFT: &str = include_str!("../../assets/soft.toml");
const SCALING: [(u32, &str); 4] = [
    (1, include_str!("../../assets/scaling-1.toml")),
    (8, include_str!("../../assets/scaling-8.toml")),
    (32, include_str!("../../assets/scaling-32.toml")),
    (64, include_str!("../../assets/scaling-64.toml")),
];

/// Failures of the soft group (a configuration that fails is a skipped row instead).
#[derive(Debug, thiserror::Error)]
pub enum SoftError {
    #[error("the embedded {file}: {source}")]
    Scene {
        file: String,
        source: Box<SceneError>,
    },
    #[error("{file}: light 0 is not an area light, so its size cannot be scaled")]
    NotAreaLight { file: String },
    #[error("no embedded scaling scene has {copies} copies (there are 1, 8, 32 and 64)")]
    NoScalingScene { copies: u32 },
    #[error("the truth of {file}: {source}")]
    Truth { file: String, source: TruthError },
}

/// Which measurement a row belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Axis {
    Slices,
    MapSize,
    Prefilter,
    Combine,
    Geometry,
    LightSize,
}

impl Axis {
    pub const ALL: [Axis; 6] = [
        Axis::Slices,
        Axis::MapSize,
        Axis::Prefilter,
        Axis::Combine,
        Axis::Geometry,
        Axis::LightSize,
    ];

    /// What the axis varies, for a table's title.
    pub fn title(self) -> &'static str {
        match self {
            Axis::Slices => "slice count (occlusion-textures: N-buffers, probabilistic, 256²)",
            Axis::MapSize => "occlusion-texture size (16 slices, N-buffers, probabilistic)",
            Axis::Prefilter => "prefilter (16 slices, probabilistic, 256²)",
            Axis::Combine => "combination rule (16 slices, N-buffers, 256²)",
            Axis::Geometry => {
                "geometry count (assets/scaling-N.toml: N copies of a 2,000-triangle torus)"
            }
            Axis::LightSize => "light size (the soft scene's area light scaled about its centre)",
        }
    }
}

/// The scene a configuration renders.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "scene")]
pub enum SceneId {
    /// `assets/soft.toml` with its area light scaled by `light_scale` about its centre.
    Soft { light_scale: f32 },
    /// `assets/scaling-<copies>.toml`.
    Scaling { copies: u32 },
}

impl SceneId {
    pub const SOFT: SceneId = SceneId::Soft { light_scale: 1.0 };

    /// The scene's file, as its rows name it.
    pub fn file(self) -> String {
        match self {
            SceneId::Soft { .. } => "assets/soft.toml".to_string(),
            SceneId::Scaling { copies } => format!("assets/scaling-{copies}.toml"),
        }
    }

    /// The parsed scene (light scaled for `Soft`).
    pub fn scene(self) -> Result<Scene, SoftError> {
        let file = self.file();
        let text = match self {
            SceneId::Soft { .. } => SOFT,
            SceneId::Scaling { copies } => SCALING
                .iter()
                .find(|(n, _)| *n == copies)
                .map(|(_, text)| *text)
                .ok_or(SoftError::NoScalingScene { copies })?,
        };
        let mut scene = Scene::parse(text, Path::new(&file)).map_err(|e| SoftError::Scene {
            file: file.clone(),
            source: Box::new(e),
        })?;
        if let SceneId::Soft { light_scale } = self {
            if light_scale != 1.0 {
                scale_area_light(&mut scene, light_scale)
                    .ok_or(SoftError::NotAreaLight { file })?;
            }
        }
        Ok(scene)
    }
}

/// A technique and its `[shadow]` keys.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Knobs {
    OcclusionTextures {
        slices: u32,
        /// The occlusion textures' edge (`[shadow] map_size`).
        map_size: u32,
        #[serde(serialize_with = "prefilter_str")]
        prefilter: Prefilter,
        #[serde(serialize_with = "combine_str")]
        combine: Combine,
    },
    Accumulate {
        light_samples: u32,
    },
}

impl Knobs {
    pub fn technique(self) -> TechniqueId {
        match self {
            Knobs::OcclusionTextures { .. } => TechniqueId::OcclusionTextures,
            Knobs::Accumulate { .. } => TechniqueId::Accumulate,
        }
    }

    /// Writes the technique and its keys into `scene`'s `[shadow]`.
    pub fn apply(self, scene: &mut Scene) {
        scene.shadow.technique = self.technique();
        match self {
            Knobs::OcclusionTextures {
                slices,
                map_size,
                prefilter,
                combine,
            } => {
                scene.shadow.slices = slices;
                scene.shadow.map_size = map_size;
                scene.shadow.prefilter = prefilter;
                scene.shadow.combine = combine;
            }
            Knobs::Accumulate { light_samples } => scene.shadow.light_samples = light_samples,
        }
    }

    /// The keys as a table cell: `16 sl nbuffers probabilistic 256²`, `N = 16`.
    pub fn label(self) -> String {
        match self {
            Knobs::OcclusionTextures {
                slices,
                map_size,
                prefilter,
                combine,
            } => format!(
                "{slices} sl {} {} {map_size}²",
                prefilter_name(prefilter),
                combine_name(combine)
            ),
            Knobs::Accumulate { light_samples } => format!("N = {light_samples}"),
        }
    }
}

/// The scene key's spelling (`[shadow] prefilter`).
pub fn prefilter_name(prefilter: Prefilter) -> &'static str {
    match prefilter {
        Prefilter::Mipmap => "mipmap",
        Prefilter::Nbuffers => "nbuffers",
        Prefilter::Sat => "sat",
    }
}

/// The scene key's spelling (`[shadow] combine`).
pub fn combine_name(combine: Combine) -> &'static str {
    match combine {
        Combine::Probabilistic => "probabilistic",
        Combine::Sum => "sum",
        Combine::Max => "max",
    }
}

fn prefilter_str<S: serde::Serializer>(p: &Prefilter, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(prefilter_name(*p))
}

fn combine_str<S: serde::Serializer>(c: &Combine, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(combine_name(*c))
}

/// One configuration: a scene and a technique with its keys.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Case {
    pub scene: SceneId,
    pub knobs: Knobs,
}

/// One row of one axis's table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Entry {
    pub axis: Axis,
    pub case: Case,
}

/// `occlusion-textures` with these keys.
pub const fn occlusion(
    slices: u32,
    map_size: u32,
    prefilter: Prefilter,
    combine: Combine,
) -> Knobs {
    Knobs::OcclusionTextures {
        slices,
        map_size,
        prefilter,
        combine,
    }
}

/// Every axis's rows, in table order (see the module note).
pub fn plan() -> Vec<Entry> {
    let mut entries = Vec::new();
    let mut push = |axis, scene, knobs| {
        entries.push(Entry {
            axis,
            case: Case { scene, knobs },
        })
    };
    let (slices, map_size, prefilter, combine) =
        (BASE_SLICES, BASE_MAP_SIZE, BASE_PREFILTER, BASE_COMBINE);
    for s in SLICES {
        push(
            Axis::Slices,
            SceneId::SOFT,
            occlusion(s, map_size, prefilter, combine),
        );
    }
    for m in MAP_SIZES {
        push(
            Axis::MapSize,
            SceneId::SOFT,
            occlusion(slices, m, prefilter, combine),
        );
    }
    for p in PREFILTERS {
        push(
            Axis::Prefilter,
            SceneId::SOFT,
            occlusion(slices, map_size, p, combine),
        );
    }
    for c in COMBINES {
        push(
            Axis::Combine,
            SceneId::SOFT,
            occlusion(slices, map_size, prefilter, c),
        );
    }
    for copies in COPIES {
        let scene = SceneId::Scaling { copies };
        push(Axis::Geometry, scene, OCCLUSION_BASE);
        for light_samples in LIGHT_SAMPLES {
            push(Axis::Geometry, scene, Knobs::Accumulate { light_samples });
        }
    }
    for light_scale in LIGHT_SCALES {
        let scene = SceneId::Soft { light_scale };
        push(Axis::LightSize, scene, OCCLUSION_BASE);
        push(Axis::LightSize, scene, ACCUMULATE_BASE);
    }
    entries
}

/// Scales light 0, an area light, by `factor` about its centre: the edges × `factor`, the
/// corner moved so that corner + (edge_u + edge_v)/2 stays put (the light's view, from the
/// centre, is unchanged). `None` when light 0 is not an area light.
pub fn scale_area_light(scene: &mut Scene, factor: f32) -> Option<()> {
    let light = scene.lights.first_mut()?;
    let LightKind::Area {
        corner,
        edge_u,
        edge_v,
    } = &mut light.kind
    else {
        return None;
    };
    let centre: Vec3 = *corner + 0.5 * (*edge_u + *edge_v);
    *edge_u *= factor;
    *edge_v *= factor;
    *corner = centre - 0.5 * (*edge_u + *edge_v);
    Some(())
}

/// A measured row.
#[derive(Debug, Clone, Serialize)]
pub struct SoftRow {
    pub axis: Axis,
    pub scene: SceneId,
    pub technique: TechniqueId,
    pub setting: Knobs,
    pub triangles: usize,
    pub image: u32,
    /// The first frame, milliseconds.
    pub cold_ms: f64,
    /// The steady frames, milliseconds.
    pub frame: Summary,
    /// The visibility of the frame after the last, against the truth's.
    pub visibility: VisibilityErrors,
}

/// A configuration that was refused or failed.
#[derive(Debug, Clone, Serialize)]
pub struct SoftSkipped {
    pub axis: Axis,
    pub scene: SceneId,
    pub technique: TechniqueId,
    pub setting: Knobs,
    pub reason: String,
}

/// What [`measure`] is doing, one step per call.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Step {
    /// The truth of `scene` was ray-cast.
    Truth { scene: SceneId },
    /// Round `round` of `scene`'s interleaved frames is done.
    Round { scene: SceneId, round: u32 },
}

/// How many [`Step`]s [`measure`] reports for `entries` at `repeats`: per scene, the
/// truth and one per round of frames.
pub fn steps(entries: &[Entry], repeats: usize) -> u64 {
    let scenes = unique(entries.iter().map(|e| e.case.scene)).len() as u64;
    scenes * (1 + frames(repeats) as u64)
}

/// Frames per session: `repeats` steady ones after the cold one.
fn frames(repeats: usize) -> u32 {
    repeats.max(1) as u32 + 1
}

/// `items` without repeats, in first-seen order (a handful of items: quadratic is fine).
fn unique<T: PartialEq>(items: impl IntoIterator<Item = T>) -> Vec<T> {
    let mut out: Vec<T> = Vec::new();
    for item in items {
        if !out.contains(&item) {
            out.push(item);
        }
    }
    out
}

/// What one configuration gave.
enum Outcome {
    Measured {
        triangles: usize,
        cold_ms: f64,
        frame: Summary,
        visibility: VisibilityErrors,
    },
    Skipped(String),
}

/// A lane's tag: its scene's triangles and its frame times.
struct Tag {
    triangles: usize,
    ms: Vec<f64>,
}

/// Failed frames retire their lane; each frame's time is kept; each round is a step.
struct Timing<'a, F> {
    scene: SceneId,
    progress: &'a mut F,
}

impl<F: FnMut(Step)> Rules<Tag> for Timing<'_, F> {
    fn failed(&mut self, _tag: &Tag, _error: &RenderError) -> Verdict {
        Verdict::Retire
    }

    fn turn(&mut self, _round: u32, tag: &mut Tag, ms: Option<f64>) {
        tag.ms.extend(ms);
    }

    fn round_done(&mut self, round: u32) {
        (self.progress)(Step::Round {
            scene: self.scene,
            round,
        });
    }
}

/// Times and judges every entry's configuration at an `image`² image, `repeats` steady
/// frames each (see the module note), reporting each [`Step`] to `progress`.
pub fn measure(
    entries: &[Entry],
    image: u32,
    repeats: usize,
    mut progress: impl FnMut(Step),
) -> Result<(Vec<SoftRow>, Vec<SoftSkipped>), SoftError> {
    let cases = unique(entries.iter().map(|e| e.case));
    let mut outcomes: Vec<(Case, Outcome)> = Vec::with_capacity(cases.len());
    for scene_id in unique(cases.iter().map(|c| c.scene)) {
        let of_scene: Vec<Case> = cases
            .iter()
            .copied()
            .filter(|c| c.scene == scene_id)
            .collect();
        let measured = measure_scene(scene_id, &of_scene, image, repeats, &mut progress)?;
        outcomes.extend(of_scene.into_iter().zip(measured));
    }
    let mut rows = Vec::new();
    let mut skipped = Vec::new();
    for entry in entries {
        let Some((_, outcome)) = outcomes.iter().find(|(c, _)| *c == entry.case) else {
            continue;
        };
        let Case { scene, knobs } = entry.case;
        match outcome {
            Outcome::Measured {
                triangles,
                cold_ms,
                frame,
                visibility,
            } => rows.push(SoftRow {
                axis: entry.axis,
                scene,
                technique: knobs.technique(),
                setting: knobs,
                triangles: *triangles,
                image,
                cold_ms: *cold_ms,
                frame: *frame,
                visibility: *visibility,
            }),
            Outcome::Skipped(reason) => skipped.push(SoftSkipped {
                axis: entry.axis,
                scene,
                technique: knobs.technique(),
                setting: knobs,
                reason: reason.clone(),
            }),
        }
    }
    Ok((rows, skipped))
}

/// One scene: its truth, then its configurations' sessions interleaved, then each judged.
/// The outcomes are in the order of `cases`.
fn measure_scene<F: FnMut(Step)>(
    scene_id: SceneId,
    cases: &[Case],
    image: u32,
    repeats: usize,
    progress: &mut F,
) -> Result<Vec<Outcome>, SoftError> {
    let size = ImageSize {
        width: image,
        height: image,
    };
    let scene = render::apply_overrides(&scene_id.scene()?, Some(size), None);
    let truth =
        truth::truth(&scene, &TruthOptions::default()).map_err(|source| SoftError::Truth {
            file: scene_id.file(),
            source,
        })?;
    progress(Step::Truth { scene: scene_id });
    let triangles = scene.objects.iter().map(|o| o.mesh.triangle_count()).sum();
    let options = RenderOptions {
        pipeline: PipelineKind::Emulate,
        remake_maps: RemakeMaps::Always,
        ..RenderOptions::default()
    };
    let mut lanes: Vec<Lane<Tag>> = cases
        .iter()
        .map(|case| {
            let mut configured = scene.clone();
            case.knobs.apply(&mut configured);
            Lane {
                tag: Tag {
                    triangles,
                    ms: Vec::new(),
                },
                session: Session::new(&configured, &options),
            }
        })
        .collect();
    let mut rules = Timing {
        scene: scene_id,
        progress,
    };
    // Failed frames retire their lane (`Timing::failed`), so the rounds never stop; were
    // they to, the lane keeps the error as its reason like any other.
    if let Err(stop) = rounds::run(&mut lanes, frames(repeats), &mut rules) {
        if let Some(lane) = lanes.get_mut(stop.lane) {
            lane.session = Err(stop.error);
        }
    }
    Ok(lanes.into_iter().map(|lane| judge(lane, &truth)).collect())
}

/// A lane's times and its visibility against `truth`, or why it has none.
fn judge(lane: Lane<Tag>, truth: &Truth) -> Outcome {
    let Tag { triangles, ms } = lane.tag;
    let mut session = match lane.session {
        Ok(session) => session,
        Err(e) => return Outcome::Skipped(e.to_string()),
    };
    let (Some(&cold_ms), Some(frame)) = (ms.first(), Summary::of(ms.get(1..).unwrap_or(&[])))
    else {
        return Outcome::Skipped("no steady frame was timed".to_string());
    };
    let visibility = session.masks().and_then(|(mask, soft)| {
        render::judge(&mask, truth, 1)?;
        render::judge_visibility(&mask, soft, truth)
    });
    match visibility {
        Ok(Some(v)) => Outcome::Measured {
            triangles,
            cold_ms,
            frame,
            visibility: v.errors,
        },
        Ok(None) => Outcome::Skipped("the truth has no area-light visibility".to_string()),
        Err(e) => Outcome::Skipped(e.to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(scene: &Scene) -> (Vec3, Vec3, Vec3) {
        match scene.lights[0].kind {
            LightKind::Area {
                corner,
                edge_u,
                edge_v,
            } => (corner, edge_u, edge_v),
            other => panic!("not an area light: {other:?}"),
        }
    }

    #[test]
    fn scaling_the_light_keeps_its_centre_and_scales_its_edges() {
        let one = SceneId::SOFT.scene().expect("soft scene");
        let (c1, u1, v1) = area(&one);
        for factor in [0.5, 2.0] {
            let scaled = SceneId::Soft {
                light_scale: factor,
            }
            .scene()
            .expect("scaled scene");
            let (c, u, v) = area(&scaled);
            let centre = |c: Vec3, u: Vec3, v: Vec3| c + 0.5 * (u + v);
            assert!((centre(c, u, v) - centre(c1, u1, v1)).length() < 1e-5);
            assert!((u - u1 * factor).length() < 1e-6 && (v - v1 * factor).length() < 1e-6);
            assert_eq!(scaled.lights[0].view, one.lights[0].view);
            assert_eq!(scaled.lights[0].position(), one.lights[0].position());
        }
    }

    #[test]
    fn a_light_without_size_is_not_scaled() {
        let mut scene = SceneId::SOFT.scene().expect("soft scene");
        scene.lights[0].kind = LightKind::Point;
        let before = scene.lights.clone();
        assert_eq!(scale_area_light(&mut scene, 2.0), None);
        assert_eq!(scene.lights, before);
        scene.lights.clear();
        assert_eq!(scale_area_light(&mut scene, 2.0), None);
    }

    #[test]
    fn every_embedded_scene_parses_with_an_area_light() {
        let mut scenes = vec![SceneId::SOFT];
        scenes.extend(COPIES.map(|copies| SceneId::Scaling { copies }));
        for id in scenes {
            let scene = id.scene().expect("embedded scene");
            assert!(
                matches!(scene.lights[0].kind, LightKind::Area { .. }),
                "{}",
                id.file()
            );
        }
        assert!(matches!(
            SceneId::Scaling { copies: 2 }.scene(),
            Err(SoftError::NoScalingScene { copies: 2 })
        ));
    }

    #[test]
    fn the_plan_covers_every_axis_and_shares_the_base_configuration() {
        let entries = plan();
        let count = |axis| entries.iter().filter(|e| e.axis == axis).count();
        assert_eq!(count(Axis::Slices), 3);
        assert_eq!(count(Axis::MapSize), 4);
        assert_eq!(count(Axis::Prefilter), 3);
        assert_eq!(count(Axis::Combine), 3);
        assert_eq!(count(Axis::Geometry), 4 * 4);
        assert_eq!(count(Axis::LightSize), 3 * 2);
        let base = Case {
            scene: SceneId::SOFT,
            knobs: OCCLUSION_BASE,
        };
        // slices 16, map 256, nbuffers, probabilistic, light ×1: one session for five rows.
        assert_eq!(entries.iter().filter(|e| e.case == base).count(), 5);
        let cases = unique(entries.iter().map(|e| e.case));
        assert_eq!(cases.len(), 10 + 1 + 4 * 4 + 2 * 2);
        // Per scene: the truth and 11 rounds; 7 scenes.
        assert_eq!(steps(&entries, 10), 7 * 12);
    }

    #[test]
    fn knobs_reach_the_scene() {
        let mut scene = SceneId::SOFT.scene().expect("soft scene");
        Knobs::OcclusionTextures {
            slices: 8,
            map_size: 128,
            prefilter: Prefilter::Mipmap,
            combine: Combine::Max,
        }
        .apply(&mut scene);
        let s = &scene.shadow;
        assert_eq!(s.technique, TechniqueId::OcclusionTextures);
        assert_eq!((s.slices, s.map_size), (8, 128));
        assert_eq!((s.prefilter, s.combine), (Prefilter::Mipmap, Combine::Max));
        Knobs::Accumulate { light_samples: 64 }.apply(&mut scene);
        assert_eq!(scene.shadow.technique, TechniqueId::Accumulate);
        assert_eq!(scene.shadow.light_samples, 64);
    }
}
