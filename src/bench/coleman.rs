//! `bench --only coleman`: Coleman's draw-time experiments (thesis, §6) repeated on the
//! layer. The F-35 scene (`assets/f35.toml`, embedded) with its aircraft replaced by 1,
//! 10, 50, 100 and 200 instances placed at random (a fixed seed: every run draws the same
//! fleet), drawn by `occluder-planes` in its three forms — fixed function (per instance,
//! its three planes' texgen), the generated GLSL program (`program = "generic"`) and the
//! thesis's own shaders (`"coleman"`, which hard-code one aircraft's planes: the
//! one-aircraft rows only) — beside `depth-compare` and `projective`, on the emulated path;
//! and the same fleets scaled ×10 (the aircraft cover the image: fill-limited) and ×1/100
//! (a few pixels each: vertex-limited).
//!
//! Every session of a scale is made first and their frames are interleaved round-robin,
//! so machine noise hits each alike; the first frame (maps, uploads, program compiles) is
//! reported apart and the steady figure is the median of the others. The shadow maps are
//! remade every frame (`RemakeMaps::Always`): Coleman's frames re-rendered their shadow
//! maps too, and the occluder planes' texgen is recomputed every frame anyway.
//!
//! Placement: instance i stands at (x, h, z) with x, z uniform in ±`SPREAD` and h in
//! [3, 9] at every scale (×10 aircraft overlap and fill the image), turned by a uniform yaw and a bank within ±20°, from a 32-bit LCG
//! (Numerical Recipes' constants) seeded with `SEED`.
//!
//! His CPU-limit test ([`measure_submissions`]): the ×1 fleets drawn by `SUBMITTED` with
//! the aircraft (and the ground) submitted through each of GL's doors (`Submission`,
//! `render::submission`): immediate mode, a display list per object compiled once, and
//! the buffers every other row uses. Only the sessions of one fleet size are open at a
//! time (six contexts, not thirty): the comparison is within a row, whose frames are
//! interleaved as above.

use crate::scene::{Object, OccluderProgram, Rotation, Scene, SceneError};
use crate::stats::Summary;
use crate::vocab::{Named, PipelineKind, Submission, TechniqueId};
use glam::Vec3;
use serde::Serialize;
use std::path::Path;

use crate::render::{ImageSize, RemakeMaps, RenderError, RenderOptions, Session};

/// The fleet sizes, as in the thesis.
pub const INSTANCES: [usize; 5] = [1, 10, 50, 100, 200];
/// One column of the tables: a technique, and for `occluder-planes` its program form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Entrant {
    pub technique: TechniqueId,
    pub program: Option<OccluderProgram>,
}

impl Entrant {
    const fn plain(technique: TechniqueId) -> Entrant {
        Entrant {
            technique,
            program: None,
        }
    }

    const fn planes(program: OccluderProgram) -> Entrant {
        Entrant {
            technique: TechniqueId::OccluderPlanes,
            program: Some(program),
        }
    }

    /// The column's name: the technique's, with the form's after a slash.
    pub fn label(self) -> String {
        match self.program {
            Some(p) => format!("{}/{}", self.technique, p.name()),
            None => self.technique.to_string(),
        }
    }

    /// Whether the entrant runs `instances` aircraft: the thesis's shaders hard-code the
    /// planes of one.
    pub fn takes(self, instances: usize) -> bool {
        self.program != Some(OccluderProgram::Coleman) || instances == 1
    }
}

/// The columns compared.
pub const ENTRANTS: [Entrant; 5] = [
    Entrant::planes(OccluderProgram::FixedFunction),
    Entrant::planes(OccluderProgram::Generic),
    Entrant::planes(OccluderProgram::Coleman),
    Entrant::plain(TechniqueId::DepthCompare),
    Entrant::plain(TechniqueId::Projective),
];
/// The columns of the CPU-limit test: one pass against two.
pub const SUBMITTED: [Entrant; 2] = [
    Entrant::planes(OccluderProgram::FixedFunction),
    Entrant::plain(TechniqueId::DepthCompare),
];
/// The doors compared, in the table's order.
pub const SUBMISSIONS: [Submission; 3] = [
    Submission::Immediate,
    Submission::DisplayList,
    Submission::Buffers,
];
/// The aircraft's scale against the scene file's: as given, fill-limited, vertex-limited.
pub const SCALES: [f32; 3] = [1.0, 10.0, 0.01];
/// Half the side of the square the instances stand over, in scene units (metres).
pub const SPREAD: f32 = 18.0;
/// The placement's seed.
pub const SEED: u32 = 2006;

const F35: &str = include_str!("../../assets/f35.toml");

/// Failures of the Coleman group.
#[derive(Debug, thiserror::Error)]
pub enum ColemanError {
    #[error("the embedded f35 scene: {0}")]
    Scene(Box<SceneError>),
    #[error("the embedded f35 scene has no object named `f35`")]
    NoAircraft,
    #[error(transparent)]
    Render(#[from] RenderError),
}

/// One technique, fleet size and scale.
#[derive(Debug, Clone, Serialize)]
pub struct ColemanRow {
    pub technique: TechniqueId,
    /// `occluder-planes`' form (`fixed-function`, `generic`, `coleman`); none for the others.
    pub program: Option<&'static str>,
    /// How the objects' draws were submitted (buffers outside the CPU-limit test).
    pub submission: Submission,
    pub instances: usize,
    pub scale: f32,
    pub triangles: usize,
    pub cold_ms: f64,
    pub frame: Summary,
}

/// A session that could not be made or failed a frame.
#[derive(Debug, Clone, Serialize)]
pub struct ColemanSkipped {
    pub technique: TechniqueId,
    pub program: Option<&'static str>,
    pub submission: Submission,
    pub instances: usize,
    pub scale: f32,
    pub reason: String,
}

/// The F-35 scene with `instances` aircraft at `scale` (see the module note).
pub fn fleet(instances: usize, scale: f32) -> Result<Scene, ColemanError> {
    let mut scene = Scene::parse(F35, Path::new("assets/f35.toml"))
        .map_err(|e| ColemanError::Scene(Box::new(e)))?;
    let Some(at) = scene
        .objects
        .iter()
        .position(|o| o.name.as_deref() == Some("f35"))
    else {
        return Err(ColemanError::NoAircraft);
    };
    let aircraft: Object = scene.objects.remove(at);
    let mut rng = Lcg(SEED);
    for i in 0..instances {
        let mut copy = aircraft.clone();
        copy.name = Some(format!("f35-{}", i + 1));
        let (x, z) = (rng.signed() * SPREAD, rng.signed() * SPREAD);
        let h = 3.0 + 6.0 * rng.unit();
        copy.transform.translate = Vec3::new(x, h, z);
        let mut rotate = vec![
            Rotation {
                axis: Vec3::Y,
                degrees: 360.0 * rng.unit(),
            },
            Rotation {
                axis: Vec3::Z,
                degrees: 20.0 * rng.signed(),
            },
        ];
        // The file's last rotation turns model space (z up) to the scene's (y up).
        rotate.extend(aircraft.transform.rotate.last().cloned());
        copy.transform.rotate = rotate;
        copy.transform.scale = aircraft.transform.scale * scale;
        scene.objects.push(copy);
    }
    Ok(scene)
}

/// Times every technique on every fleet of every scale; `tick` after each round.
pub fn measure(
    repeats: usize,
    mut tick: impl FnMut(),
) -> Result<(Vec<ColemanRow>, Vec<ColemanSkipped>), ColemanError> {
    let mut results = (Vec::new(), Vec::new());
    for scale in SCALES {
        let mut lanes = Vec::new();
        for instances in INSTANCES {
            let mut scene = fleet(instances, scale)?;
            for entrant in ENTRANTS.into_iter().filter(|e| e.takes(instances)) {
                let to = Column {
                    entrant,
                    submission: Submission::Buffers,
                    instances,
                    scale,
                };
                lanes.extend(open(&mut scene, to, &mut results.1));
            }
        }
        interleave(lanes, repeats, &mut tick, &mut results);
    }
    Ok(results)
}

/// The CPU-limit test: `SUBMITTED` on the ×1 fleets of `instances` aircraft through every
/// door of `SUBMISSIONS`, one fleet size at a time; `tick` after each round.
pub fn measure_submissions(
    repeats: usize,
    instances: &[usize],
    mut tick: impl FnMut(),
) -> Result<(Vec<ColemanRow>, Vec<ColemanSkipped>), ColemanError> {
    let mut results = (Vec::new(), Vec::new());
    for &n in instances {
        let mut scene = fleet(n, 1.0)?;
        let mut lanes = Vec::new();
        for entrant in SUBMITTED.into_iter().filter(|e| e.takes(n)) {
            for submission in SUBMISSIONS {
                let to = Column {
                    entrant,
                    submission,
                    instances: n,
                    scale: 1.0,
                };
                lanes.extend(open(&mut scene, to, &mut results.1));
            }
        }
        interleave(lanes, repeats, &mut tick, &mut results);
    }
    Ok(results)
}

/// What one session measures.
#[derive(Clone, Copy)]
struct Column {
    entrant: Entrant,
    submission: Submission,
    instances: usize,
    scale: f32,
}

impl Column {
    fn skipped(self, reason: String) -> ColemanSkipped {
        ColemanSkipped {
            technique: self.entrant.technique,
            program: self.entrant.program.map(|p| p.name()),
            submission: self.submission,
            instances: self.instances,
            scale: self.scale,
            reason,
        }
    }
}

/// One open session and its frame times.
struct Lane {
    to: Column,
    triangles: usize,
    session: Session,
    ms: Vec<f64>,
}

/// The session of `to` on `scene` (its occluder program set to the entrant's), or its
/// failure in `skipped`.
fn open(scene: &mut Scene, to: Column, skipped: &mut Vec<ColemanSkipped>) -> Option<Lane> {
    scene.shadow.occluder_program = to.entrant.program.unwrap_or_default();
    let options = RenderOptions {
        pipeline: PipelineKind::Emulate,
        technique: Some(to.entrant.technique),
        size: Some(ImageSize {
            width: 512,
            height: 512,
        }),
        remake_maps: RemakeMaps::Always,
        submission: to.submission,
        ..RenderOptions::default()
    };
    match Session::new(scene, &options) {
        Ok(session) => Some(Lane {
            to,
            triangles: scene.objects.iter().map(|o| o.mesh.triangle_count()).sum(),
            session,
            ms: Vec::new(),
        }),
        Err(e) => {
            skipped.push(to.skipped(e.to_string()));
            None
        }
    }
}

/// `repeats` + 1 frames of every lane, round-robin (`tick` after each round); a row per
/// lane: the first frame cold, the others summarised.
fn interleave(
    mut lanes: Vec<Lane>,
    repeats: usize,
    tick: &mut impl FnMut(),
    (rows, skipped): &mut (Vec<ColemanRow>, Vec<ColemanSkipped>),
) {
    for _ in 0..repeats.max(1) + 1 {
        lanes.retain_mut(|lane| match lane.session.frame() {
            Ok(t) => {
                lane.ms.push(t);
                true
            }
            Err(e) => {
                skipped.push(lane.to.skipped(e.to_string()));
                false
            }
        });
        tick();
    }
    for lane in lanes {
        let (Some(&cold_ms), Some(frame)) =
            (lane.ms.first(), lane.ms.get(1..).and_then(Summary::of))
        else {
            continue;
        };
        let to = lane.to;
        rows.push(ColemanRow {
            technique: to.entrant.technique,
            program: to.entrant.program.map(|p| p.name()),
            submission: to.submission,
            instances: to.instances,
            scale: to.scale,
            triangles: lane.triangles,
            cold_ms,
            frame,
        });
    }
}

/// x ← 1664525 x + 1013904223 (mod 2³²).
struct Lcg(u32);

impl Lcg {
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f32 {
        self.0 = self.0.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        (self.0 >> 8) as f32 / (1u32 << 24) as f32
    }

    /// Uniform in [−1, 1).
    fn signed(&mut self) -> f32 {
        2.0 * self.unit() - 1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fleet_has_its_instances_and_the_same_placement_every_time() {
        let a = fleet(10, 1.0).expect("fleet");
        let b = fleet(10, 1.0).expect("fleet");
        let aircraft = |s: &Scene| {
            s.objects
                .iter()
                .filter(|o| o.name.as_deref().is_some_and(|n| n.starts_with("f35-")))
                .map(|o| o.transform.translate)
                .collect::<Vec<_>>()
        };
        assert_eq!(aircraft(&a).len(), 10);
        assert_eq!(aircraft(&a), aircraft(&b));
        let spread = aircraft(&a)
            .iter()
            .all(|p| p.x.abs() <= SPREAD && p.z.abs() <= SPREAD && (3.0..=9.0).contains(&p.y));
        assert!(spread, "{:?}", aircraft(&a));
    }

    #[test]
    fn scaling_scales_the_instances() {
        let small = fleet(1, 0.01).expect("fleet");
        let one = fleet(1, 1.0).expect("fleet");
        let last = |s: &Scene| {
            s.objects
                .last()
                .map(|o| o.transform.scale)
                .unwrap_or_default()
        };
        assert!((last(&small) - last(&one) * 0.01).length() < 1e-6);
    }
}
