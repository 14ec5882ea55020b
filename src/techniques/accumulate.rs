//! `accumulate`: the era's soft shadow, as the Red Book drew it — N hard shadows, each
//! from another point of the area light (or another direction of a sun's disc), averaged
//! in the accumulation buffer.
//!
//! ```text
//! setup          the map texture as depth-compare's; glClearAccum(0, 0, 0, 0)
//! frame  clear:  glClear(ACCUM_BUFFER_BIT)
//!        for each light point p_k, k = 0 … N − 1:
//!          light: depth-compare's light pass from p_k (the light's view moved by p_k − centre)
//!          copy:  glCopyTexImage2D(DEPTH_COMPONENTxx) into the one map texture
//!          dim, lit: depth-compare's eye passes, the shadowing light a point at p_k
//!          accum: glAccum(GL_ACCUM, 1/N)
//!        return: glAccum(GL_RETURN, 1)
//! ```
//! **Light points.** The rectangle corner + s·edge_u + t·edge_v is cut into N strata of
//! a × b cells (a the largest divisor of N not above √N, the longer edge taking the larger
//! count: 16 → 4 × 4, 8 → 2 × 4, a prime N → 1 × N strips), and each point is jittered
//! inside its cell by a hash of (seed, k) with a fixed seed: the same N points every frame
//! and every run. Each point's view is the light's view translated by p_k − centre, so the
//! N frusta are parallel; the light's `fovy` has to leave a margin of half the light's size
//! around what it must cover (outside the map is lit, `map`).
//!
//! **Sun directions.** A sun (a directional light with `angular_diameter` α > 0) is
//! sampled the same way over the unit square — the same a × b strata, the same jitter and
//! seed — each point carried onto the cone of half-angle α/2 around −direction by
//! `scene::SunDisc::direction`, as the truth carries its samples (Shirley–Chiu's
//! concentric map onto the disc, then the cap uniformly in solid angle). Render k is a
//! hard directional light along −ω_k, its view (eye, up) turned about the view's `at` by
//! the rotation taking the sun's centre to ω_k, so each map is an orthographic box of the
//! same size turned by at most α/2.
//!
//! **Maps are remade per frame per sample.** One map texture serves every sample: sample k's
//! light pass and copy run just before its eye passes, every frame, so the N maps cost N
//! light passes a frame. That is how the era's programs ran it (N depth textures of 256²
//! would have filled a board's texture memory), and it makes the frame's time the
//! technique's true cost — the figure to set against geometry count. So the plan has no
//! `maps` passes: `render`'s "maps made" stays 0 and `--remake-maps` changes nothing; a
//! note on the render line says so.
//!
//! **The mask is a visibility.** The mask look (dim black, lit white, background pure blue)
//! is accumulated too: each geometry pixel returns as grey k/255 ≈ the fraction of the
//! light points that see it (glAccum weights 1/N, `ff::accum`'s truncations cost at most
//! N/32767 of the light), the background as (0, 0, ≈255). [`super::MaskSource::Visibility`]
//! decodes blue-dominated pixels (b − r ≥ 128) as background and the red of the others as
//! the visibility; the hard mask is its threshold at one half, as a filtered compare's.

use glam::{Quat, Vec3, Vec4};

use crate::ff::accum::AccumOp;
use crate::ff::{
    ClearMask, Command, CompareFunc, CompareMode, DepthTextureMode, PixelFormat, PixelType,
    TexParam, TextureTarget,
};
use crate::scene::{Light, LightKind, Scene, ShadowSettings, SunDisc};
use crate::vocab::TechniqueId;

use super::map::{bind_map, map_parameters, read_corner, MapSettings, MAP_IMAGE_SLOT};
use super::parts::{dim_then_added_light, light_pass, Look, ShadowLight};
use super::{
    check_light_count, MapImagePlan, MapImageSource, MaskPlan, MaskSource, Pass, Plan, Prepared,
    Technique, TechniqueError, MASK_SLOT,
};

pub const ID: TechniqueId = TechniqueId::Accumulate;

pub const TECHNIQUE: Technique = Technique {
    summary: "the Red Book's soft shadow: N depth-compare renders from stratified points of \
              the area light (or directions of a sun), averaged with glAccum",
    plan,
};

/// The seed of the light points' jitter (fixed: the same points every run).
pub const SEED: u64 = 0x5EED_ACC0;

/// The rectangle of the scene's first light, or why there is none.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AreaRectangle {
    pub corner: Vec3,
    pub edge_u: Vec3,
    pub edge_v: Vec3,
}

impl AreaRectangle {
    /// The scene's first light's rectangle, or [`TechniqueError::NoAreaLight`] naming what
    /// the scene has instead.
    pub fn of(scene: &Scene) -> Result<AreaRectangle, TechniqueError> {
        let found = match scene.lights.first().map(|l| l.kind) {
            Some(LightKind::Area {
                corner,
                edge_u,
                edge_v,
            }) => {
                return Ok(AreaRectangle {
                    corner,
                    edge_u,
                    edge_v,
                })
            }
            None => "no light",
            Some(LightKind::Point) => "a point light",
            Some(LightKind::Spot { .. }) => "a spot light",
            Some(LightKind::Directional {
                angular_diameter, ..
            }) if angular_diameter > 0.0 => "a sun (a directional light with a disc)",
            Some(LightKind::Directional { .. }) => "a directional light",
        };
        Err(TechniqueError::NoAreaLight {
            technique: ID,
            found,
        })
    }

    /// corner + ½(edge_u + edge_v).
    pub fn centre(&self) -> Vec3 {
        self.corner + 0.5 * (self.edge_u + self.edge_v)
    }

    /// The point at (s, t) ∈ [0, 1]²: corner + s·edge_u + t·edge_v.
    pub fn at(&self, s: f32, t: f32) -> Vec3 {
        self.corner + s * self.edge_u + t * self.edge_v
    }
}

/// What `accumulate` samples: the area light's rectangle or the sun's disc of directions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SoftSource {
    Rectangle(AreaRectangle),
    Sun(SunDisc),
}

impl SoftSource {
    /// The scene's first light as a source to sample, or [`TechniqueError::NoAreaLight`]
    /// naming what the scene has instead (a hard directional light: "a directional light
    /// without `angular_diameter`").
    pub fn of(scene: &Scene) -> Result<SoftSource, TechniqueError> {
        match scene.lights.first() {
            Some(light) if matches!(light.kind, LightKind::Directional { .. }) => light
                .sun()
                .map(SoftSource::Sun)
                .ok_or(TechniqueError::NoAreaLight {
                    technique: ID,
                    found: "a directional light without `angular_diameter` (a sun needs one)",
                }),
            _ => AreaRectangle::of(scene).map(SoftSource::Rectangle),
        }
    }
}

/// The strata of N samples: (cells along edge_u, cells along edge_v), their product N —
/// a the largest divisor of N not above √N, b = N / a, the longer edge taking b.
pub fn strata(n: u32, u_is_longer: bool) -> (u32, u32) {
    let n = n.max(1);
    let a = (1..=n)
        .take_while(|d| d * d <= n)
        .filter(|d| n % d == 0)
        .max();
    let a = a.unwrap_or(1);
    let b = n / a;
    if u_is_longer {
        (b, a)
    } else {
        (a, b)
    }
}

/// splitmix64's finaliser: a well-mixed 64-bit hash of `x`.
fn mix(mut x: u64) -> u64 {
    x = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    x ^ (x >> 31)
}

/// A number in [0, 1) from the top 24 bits of a hash of (seed, k, axis).
fn unit(seed: u64, k: u32, axis: u64) -> f32 {
    let h = mix(seed ^ mix(u64::from(k) << 1 | axis));
    (h >> 40) as f32 / (1u64 << 24) as f32
}

/// The N light points: cell (i, j) of the strata holds sample k = j·a + i at
/// ((i + ξ)/a, (j + η)/b), ξ, η from the fixed seed.
pub fn light_points(area: &AreaRectangle, n: u32, seed: u64) -> Vec<Vec3> {
    let (a, b) = strata(n, area.edge_u.length() >= area.edge_v.length());
    (0..a * b)
        .map(|k| {
            let (i, j) = (k % a, k / a);
            let s = (i as f32 + unit(seed, k, 0)) / a as f32;
            let t = (j as f32 + unit(seed, k, 1)) / b as f32;
            area.at(s, t)
        })
        .collect()
}

/// The N sun directions (towards the sun): the unit square cut into the strata of N equal
/// cells, (i, j) holding sample k = j·a + i at ((i + ξ)/a, (j + η)/b) with the light
/// points' jitter, carried onto the cone by [`SunDisc::direction`].
pub fn sun_directions(sun: &SunDisc, n: u32, seed: u64) -> Vec<Vec3> {
    let (a, b) = strata(n, true);
    (0..a * b)
        .map(|k| {
            let (i, j) = (k % a, k / a);
            let s = (i as f32 + unit(seed, k, 0)) / a as f32;
            let t = (j as f32 + unit(seed, k, 1)) / b as f32;
            sun.direction(s, t)
        })
        .collect()
}

/// The scene with its first light made a hard directional light from `towards` (light
/// travelling along −towards), its view turned about `at` by the rotation R taking the
/// sun's centre to `towards`: eye′ = at + R (eye − at), up′ = R up.
fn sun_sample_scene(scene: &Scene, sun: &SunDisc, towards: Vec3) -> Scene {
    let mut sample = scene.clone();
    if let Some(light) = sample.lights.first_mut() {
        let turn = Quat::from_rotation_arc(sun.towards, towards);
        let mut view = light.view;
        view.eye = view.at + turn * (view.eye - view.at);
        view.up = turn * view.up;
        *light = Light {
            kind: LightKind::Directional {
                direction: -towards,
                angular_diameter: 0.0,
            },
            view,
            ..*light
        };
    }
    sample
}

/// The N single-light scenes a frame renders, one per sample of `source`.
fn sample_scenes(scene: &Scene, source: &SoftSource, n: u32) -> Vec<Scene> {
    match source {
        SoftSource::Rectangle(area) => light_points(area, n, SEED)
            .into_iter()
            .map(|p| sample_scene(scene, area, p))
            .collect(),
        SoftSource::Sun(sun) => sun_directions(sun, n, SEED)
            .into_iter()
            .map(|w| sun_sample_scene(scene, sun, w))
            .collect(),
    }
}

/// The scene with its first light made a point light at `point`, its view translated by
/// `point` − the rectangle's centre (parallel frusta), colour and intensity kept.
fn sample_scene(scene: &Scene, area: &AreaRectangle, point: Vec3) -> Scene {
    let mut sample = scene.clone();
    if let Some(light) = sample.lights.first_mut() {
        let shift = point - area.centre();
        let mut view = light.view;
        view.eye += shift;
        view.at += shift;
        *light = Light {
            kind: LightKind::Point,
            view,
            ..*light
        };
    }
    sample
}

pub fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, TechniqueError> {
    check_light_count(scene)?;
    let source = SoftSource::of(scene)?;
    let n = scene.shadow.light_samples;
    let max = ShadowSettings::MAX_LIGHT_SAMPLES;
    if !(1..=max).contains(&n) {
        return Err(TechniqueError::LightSamples { samples: n, max });
    }
    let map = MapSettings::of(scene);
    let param = |param| Command::TexParameter {
        target: TextureTarget::Texture2D,
        param,
    };
    let mut setup = vec![Command::ActiveTexture(0), bind_map()];
    setup.extend(map_parameters(map.gl_filter()));
    setup.extend([
        param(TexParam::CompareMode(CompareMode::CompareRToTexture)),
        param(TexParam::CompareFunc(CompareFunc::Lequal)),
        param(TexParam::DepthTextureMode(DepthTextureMode::Luminance)),
        Command::ClearAccum(Vec4::ZERO),
    ]);
    let samples = sample_scenes(scene, &source, n);
    let lights = samples
        .iter()
        .map(|s| ShadowLight::of(s, ID))
        .collect::<Result<Vec<_>, _>>()?;
    let frame = |look: Look| -> Vec<Pass> {
        let mut passes = vec![Pass {
            name: "accum-clear",
            commands: vec![Command::Clear(ClearMask {
                color: false,
                depth: false,
                stencil: false,
                accum: true,
            })],
        }];
        for (sample, light) in samples.iter().zip(&lights) {
            passes.push(light_pass(
                sample, prepared, light, map.size, map.offset, false,
            ));
            passes.push(map.copy_depth_pass());
            let planes = [0, 1, 2, 3].map(|i| light.plane(i));
            passes.extend(dim_then_added_light(sample, prepared, planes, look));
            passes.push(Pass {
                name: "accum",
                // GL_ACCUM, 1/N: the colour buffer, weighted, added to the accumulation.
                commands: vec![Command::Accum {
                    op: AccumOp::Accum,
                    value: 1.0 / n as f32,
                }],
            });
        }
        passes.push(Pass {
            name: "return",
            // GL_RETURN, 1: the sum, the average of the N pictures, back to the colour buffer.
            commands: vec![Command::Accum {
                op: AccumOp::Return,
                value: 1.0,
            }],
        });
        passes
    };
    // The light's map as `--depth-map` shows it: from the rectangle's (or the sun's) centre.
    let centre = ShadowLight::of(scene, ID)?;
    let mut map_commands =
        light_pass(scene, prepared, &centre, map.size, map.offset, false).commands;
    map_commands.push(read_corner(
        map.size,
        PixelFormat::DepthComponent,
        PixelType::Float,
        MAP_IMAGE_SLOT,
    ));
    Ok(Plan {
        setup,
        maps: Vec::new(),
        passes: frame(Look::Shaded),
        mask: visibility_mask(scene, frame(Look::Mask)),
        framebuffer: map.framebuffer(scene, false),
        map_image: Some(MapImagePlan {
            commands: map_commands,
            source: MapImageSource::DepthFloat {
                slot: MAP_IMAGE_SLOT,
                size: map.size,
            },
        }),
        notes: vec![format!(
            "{n} light samples: each frame makes {n} maps (one texture, re-made per sample), \
             so \"maps made\" counts none and --remake-maps changes nothing"
        )],
    })
}

/// The accumulated mask passes, then glReadPixels of the image as RGBA/UNSIGNED_BYTE,
/// decoded as a visibility.
fn visibility_mask(scene: &Scene, passes: Vec<Pass>) -> MaskPlan {
    let plan = super::colour_mask(scene, passes);
    let (width, height) = (scene.image.width, scene.image.height);
    MaskPlan {
        commands: plan.commands,
        source: MaskSource::Visibility {
            slot: MASK_SLOT,
            width,
            height,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area_scene(samples: u32) -> Scene {
        let mut scene = Scene::default_scene();
        let light = &mut scene.lights[0];
        let centre = light.view.eye;
        light.kind = LightKind::Area {
            corner: centre - Vec3::new(1.0, 0.0, 1.0),
            edge_u: Vec3::new(2.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.0, 2.0),
        };
        scene.shadow.technique = ID;
        scene.shadow.light_samples = samples;
        scene
    }

    /// The default scene lit by a sun of 3° along its spot light's axis.
    fn sun_scene(samples: u32) -> Scene {
        let mut scene = area_scene(samples);
        let light = &mut scene.lights[0];
        light.kind = LightKind::Directional {
            direction: light.view.at - light.view.eye,
            angular_diameter: 3f32.to_radians(),
        };
        scene
    }

    #[test]
    fn sun_directions_fill_the_disc_one_per_stratum_the_same_every_time() {
        let sun = SunDisc::new(Vec3::new(0.3, -1.0, 0.2), 4f32.to_radians());
        let ws = sun_directions(&sun, 16, SEED);
        assert_eq!(ws.len(), 16);
        assert_eq!(ws, sun_directions(&sun, 16, SEED));
        assert_ne!(ws, sun_directions(&sun, 16, SEED + 1));
        let mut mean = Vec3::ZERO;
        for (k, w) in ws.iter().enumerate() {
            let angle = w.dot(sun.towards).clamp(-1.0, 1.0).acos();
            assert!(angle <= sun.half_angle() + 1e-5, "{k}: {angle}");
            for v in &ws[k + 1..] {
                assert!(w.dot(*v) < 1.0 - 1e-9, "two samples share a direction");
            }
            mean += *w;
        }
        // Stratified over the disc: their mean sits near the centre (well within a tenth of
        // the half-angle; 16 independent samples would scatter by about a quarter).
        let off = (mean / 16.0)
            .normalize()
            .dot(sun.towards)
            .clamp(-1.0, 1.0)
            .acos();
        assert!(off < 0.1 * sun.half_angle(), "{off}");
    }

    #[test]
    fn a_sun_renders_once_per_direction_each_from_its_own_turned_view() {
        let scene = sun_scene(4);
        let prepared = Prepared::new(&scene);
        let plan = plan(&scene, &prepared).expect("plans a sun");
        let sun = scene.lights[0].sun().expect("a sun");
        let light = scene.lights[0];
        let accums = plan
            .passes
            .iter()
            .flat_map(|p| &p.commands)
            .filter(|c| matches!(c, Command::Accum { .. }))
            .count();
        assert_eq!(accums, 5, "four GL_ACCUM and one GL_RETURN");
        for w in sun_directions(&sun, 4, SEED) {
            let sample = sun_sample_scene(&scene, &sun, w);
            let turned = sample.lights[0];
            assert_eq!(
                turned.kind,
                LightKind::Directional {
                    direction: -w,
                    angular_diameter: 0.0
                }
            );
            // The view turned about `at`: the same distance, looking along −w.
            let (eye, at) = (turned.view.eye, turned.view.at);
            assert_eq!(at, light.view.at);
            assert!(((eye - at).length() - (light.view.eye - at).length()).abs() < 1e-4);
            assert!(((eye - at).normalize() - w).length() < 1e-5);
        }
        let views: Vec<&Command> = plan
            .passes
            .iter()
            .filter(|p| p.name == "light")
            .flat_map(|p| {
                p.commands
                    .iter()
                    .filter(|c| matches!(c, Command::LoadMatrix(_)))
            })
            .collect();
        assert_eq!(views.len(), 4);
        for (i, a) in views.iter().enumerate() {
            for b in &views[i + 1..] {
                assert_ne!(a, b);
            }
        }
    }

    #[test]
    fn strata_multiply_to_n_and_stay_near_square() {
        assert_eq!(strata(16, true), (4, 4));
        assert_eq!(strata(64, false), (8, 8));
        assert_eq!(strata(8, true), (4, 2));
        assert_eq!(strata(8, false), (2, 4));
        assert_eq!(strata(12, false), (3, 4));
        assert_eq!(strata(7, true), (7, 1));
        assert_eq!(strata(1, true), (1, 1));
    }

    #[test]
    fn one_point_per_cell_inside_the_rectangle_and_the_same_every_time() {
        let area = AreaRectangle {
            corner: Vec3::new(-1.0, 5.0, -2.0),
            edge_u: Vec3::new(2.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.0, 4.0),
        };
        let points = light_points(&area, 8, SEED);
        assert_eq!(points, light_points(&area, 8, SEED));
        assert_ne!(points, light_points(&area, 8, SEED + 1));
        // 2 cells along u (2 long), 4 along v (4 long): each a 1 × 1 square.
        let mut cells: Vec<(i32, i32)> = points
            .iter()
            .map(|p| {
                let (s, t) = (p.x + 1.0, p.z + 2.0);
                assert!((0.0..2.0).contains(&s) && (0.0..4.0).contains(&t), "{p}");
                assert_eq!(p.y, 5.0);
                (s.floor() as i32, t.floor() as i32)
            })
            .collect();
        cells.sort();
        cells.dedup();
        assert_eq!(cells.len(), 8, "every cell holds one point: {cells:?}");
    }

    #[test]
    fn each_sample_renders_from_its_own_point_and_is_accumulated_at_one_nth() {
        let scene = area_scene(4);
        let prepared = Prepared::new(&scene);
        let plan = plan(&scene, &prepared).expect("plans");
        assert!(plan.maps.is_empty());
        let accums: Vec<&Command> = plan
            .passes
            .iter()
            .flat_map(|p| &p.commands)
            .filter(|c| matches!(c, Command::Accum { .. }))
            .collect();
        assert_eq!(accums.len(), 5);
        assert_eq!(
            accums[0],
            &Command::Accum {
                op: AccumOp::Accum,
                value: 0.25
            }
        );
        assert_eq!(
            accums[4],
            &Command::Accum {
                op: AccumOp::Return,
                value: 1.0
            }
        );
        // Four light passes, each loading a different gluLookAt.
        let views: Vec<&Command> = plan
            .passes
            .iter()
            .filter(|p| p.name == "light")
            .flat_map(|p| {
                p.commands
                    .iter()
                    .filter(|c| matches!(c, Command::LoadMatrix(_)))
            })
            .collect();
        assert_eq!(views.len(), 4);
        for (i, a) in views.iter().enumerate() {
            for b in &views[i + 1..] {
                assert_ne!(a, b);
            }
        }
        assert!(matches!(plan.mask.source, MaskSource::Visibility { .. }));
        assert!(plan.needs_accumulation());
    }

    /// Accumulated mask pixels, bottom row first: the background (blue ahead of red by
    /// 128 or more, whatever the truncations left of 255), and greys read by their red.
    #[test]
    fn an_accumulated_mask_decodes_to_visibility_with_the_background_apart() {
        use crate::pipeline::Readback;
        // 3 × 2; bottom row: background (0, 0, 254), grey 127, grey 128; top row: black,
        // white, background (1, 1, 255).
        let bytes = [
            [0u8, 0, 254, 254],
            [127, 127, 127, 255],
            [128, 128, 128, 255],
            [0, 0, 0, 255],
            [255, 255, 255, 255],
            [1, 1, 255, 255],
        ]
        .concat();
        let stored = Readback {
            width: 3,
            height: 2,
            depth: None,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            bytes,
        };
        let plan = MaskPlan {
            commands: Vec::new(),
            source: MaskSource::Visibility {
                slot: MASK_SLOT,
                width: 3,
                height: 2,
            },
        };
        let readback = |slot| (slot == MASK_SLOT).then_some(&stored);
        let v = plan
            .decode_visibility(readback)
            .unwrap()
            .expect("a visibility");
        assert_eq!(
            v.data,
            vec![Some(0), Some(255), None, None, Some(127), Some(128)]
        );
        let mask = plan.decode(readback).unwrap();
        use crate::metrics::{BACKGROUND, LIT, SHADOWED};
        assert_eq!(
            mask.data,
            vec![SHADOWED, LIT, BACKGROUND, BACKGROUND, SHADOWED, LIT]
        );
        // A hard technique's plan has no visibility to decode.
        let colour = MaskPlan {
            commands: Vec::new(),
            source: MaskSource::Colour {
                slot: MASK_SLOT,
                width: 3,
                height: 2,
            },
        };
        assert_eq!(colour.decode_visibility(readback), Ok(None));
    }

    #[test]
    fn refusals_name_what_to_add_or_the_range() {
        let mut scene = Scene::default_scene();
        scene.shadow.technique = ID;
        let prepared = Prepared::new(&scene);
        let err = plan(&scene, &prepared).unwrap_err();
        assert!(
            err.to_string().contains("a spot light") && err.to_string().contains("type = \"area\""),
            "{err}"
        );
        scene.lights.clear();
        let err = plan(&scene, &prepared).unwrap_err().to_string();
        assert!(err.contains("no light"), "{err}");
        let scene = area_scene(0);
        let err = plan(&scene, &prepared).unwrap_err().to_string();
        assert!(err.contains("1 to 256"), "{err}");
        let mut hard = sun_scene(4);
        if let LightKind::Directional {
            angular_diameter, ..
        } = &mut hard.lights[0].kind
        {
            *angular_diameter = 0.0;
        }
        let err = plan(&hard, &prepared).unwrap_err().to_string();
        assert!(
            err.contains("a directional light without `angular_diameter`"),
            "{err}"
        );
    }
}
