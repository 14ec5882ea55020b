//! Analytic cases for the ground truth.

use super::*;
use crate::metrics::{Class, BACKGROUND, LIT, SHADOWED};
use crate::scene::{
    Camera, ImageSpec, Light, Material, Object, Projection, ShadowSettings, Shape, Transform,
};

fn object(shape: Shape, translate: Vec3, casts: bool) -> Object {
    Object {
        name: None,
        mesh: std::sync::Arc::new(shape.procedural_mesh().unwrap_or_default()),
        shape,
        transform: Transform {
            translate,
            ..Transform::default()
        },
        material: Material::default(),
        casts,
        receives: true,
    }
}

/// A camera looking straight down on the y = 0 plane through an orthographic box of
/// half-size `half`: pixel centres land on a regular grid of the plane.
fn top_down(size: u32, half: f32, lights: Vec<Light>, objects: Vec<Object>) -> Scene {
    Scene {
        camera: Camera {
            eye: Vec3::new(0.0, 10.0, 0.0),
            at: Vec3::ZERO,
            up: -Vec3::Z,
            projection: Projection::Orthographic {
                left: -half,
                right: half,
                bottom: -half,
                top: half,
                near: 1.0,
                far: 20.0,
            },
        },
        image: ImageSpec {
            width: size,
            height: size,
            background: Vec3::ZERO,
        },
        lights,
        objects,
        shadow: ShadowSettings::default(),
        truth: crate::scene::TruthSettings::default(),
        warnings: Vec::new(),
        limits: crate::scene::Limits::default(),
    }
}

fn point_light(p: Vec3) -> Light {
    Light {
        kind: LightKind::Point,
        view: Camera {
            eye: p,
            at: Vec3::ZERO,
            up: Vec3::Z,
            projection: Projection::Perspective {
                fovy: 90.0,
                near: 1.0,
                far: 50.0,
            },
        },
        colour: Vec3::ONE,
        intensity: 1.0,
    }
}

#[test]
fn square_occluder_shadow_matches_projection() {
    // Light at height 8 above the origin, square of side 2 at height 4: the shadow on the
    // ground is the square scaled by 8 / (8 − 4) = 2, side 4 → 16 square units.
    let occluder = object(
        Shape::Box {
            size: Vec3::new(2.0, 0.001, 2.0),
        },
        Vec3::new(0.0, 4.0, 0.0),
        true,
    );
    let ground = object(
        Shape::Plane {
            size: 10.0,
            tessellation: 4,
        },
        Vec3::ZERO,
        true,
    );
    let (size, half) = (200u32, 5.0f32);
    let mut scene = top_down(
        size,
        half,
        vec![point_light(Vec3::new(0.0, 8.0, 0.0))],
        vec![ground, occluder],
    );
    // Look from below the occluder so the primary rays see the ground only.
    scene.camera.eye = Vec3::new(0.0, 3.0, 0.0);
    scene.camera.projection = Projection::Orthographic {
        left: -half,
        right: half,
        bottom: -half,
        top: half,
        near: 0.5,
        far: 20.0,
    };
    let t = truth(&scene, &TruthOptions::default()).expect("truth");
    let pixel = 2.0 * half / size as f32;
    let shadowed = t.mask.data.iter().filter(|&&v| v == SHADOWED).count();
    let expected = 16.0 / (pixel * pixel);
    // Within one pixel row along the perimeter: |Δ| ≤ perimeter / pixel = 4·4 / pixel.
    let tolerance = 16.0 / pixel;
    assert!(
        (shadowed as f32 - expected).abs() <= tolerance,
        "{shadowed} vs {expected} ± {tolerance}"
    );
    assert!(t.mask.data.iter().all(|&v| v != BACKGROUND));
}

#[test]
fn sphere_terminator_is_where_n_dot_l_is_zero() {
    // A finely tessellated unit sphere lit from +x by a distant directional light, seen from
    // +y: lit where n · L > 0 (x > 0 on the visible hemisphere), shadowed where < 0.
    let sphere = object(
        Shape::Sphere {
            radius: 1.0,
            slices: 256,
            stacks: 128,
        },
        Vec3::ZERO,
        true,
    );
    let light = Light {
        kind: LightKind::Directional {
            direction: -Vec3::X,
            angular_diameter: 0.0,
        },
        view: Camera {
            eye: Vec3::new(10.0, 0.0, 0.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
            projection: Projection::Perspective {
                fovy: 30.0,
                near: 1.0,
                far: 20.0,
            },
        },
        colour: Vec3::ONE,
        intensity: 1.0,
    };
    let size = 128u32;
    let scene = top_down(size, 1.0, vec![light], vec![sphere]);
    let t = truth(&scene, &TruthOptions::default()).expect("truth");
    let mut checked = 0;
    for y in 0..size {
        for x in 0..size {
            let px = -1.0 + 2.0 * (x as f32 + 0.5) / size as f32;
            let pz = -1.0 + 2.0 * (y as f32 + 0.5) / size as f32;
            let r2 = px * px + pz * pz;
            if r2 > 0.95 {
                continue;
            }
            let n = Vec3::new(px, (1.0 - r2).sqrt(), pz);
            let ndotl = n.x;
            let class = t.mask.class(x, y);
            if ndotl > 0.03 {
                assert_eq!(class, Class::Lit, "({x}, {y}) n·L = {ndotl}");
                checked += 1;
            } else if ndotl < -0.03 {
                assert_eq!(class, Class::Shadowed, "({x}, {y}) n·L = {ndotl}");
                checked += 1;
            }
        }
    }
    assert!(checked > 10_000, "{checked}");
}

#[test]
fn shadow_edge_decided_the_same_every_run() {
    // The occluder's edge projects exactly onto a column of pixel centres: x = 0 on the
    // ground under a light straight above the edge. Repeated runs and thread counts agree.
    let occluder = object(
        Shape::Box {
            size: Vec3::new(2.0, 0.001, 2.0),
        },
        Vec3::new(1.0, 2.0, 0.0),
        true,
    );
    let ground = object(
        Shape::Plane {
            size: 4.0,
            tessellation: 1,
        },
        Vec3::ZERO,
        true,
    );
    let mut scene = top_down(
        33,
        2.0 * 33.0 / 32.0,
        vec![point_light(Vec3::new(0.0, 4.0, 0.0))],
        vec![ground, occluder],
    );
    scene.camera.eye = Vec3::new(0.0, 1.0, 0.0);
    let reference = truth(&scene, &TruthOptions::default()).expect("truth");
    for threads in [1, 2, 3] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool");
        for _ in 0..3 {
            let again = pool
                .install(|| truth(&scene, &TruthOptions::default()))
                .expect("truth");
            assert_eq!(again.mask, reference.mask, "{threads} threads");
            assert_eq!(again.visibility, reference.visibility);
        }
    }
}

#[test]
fn backgrounds_facing_away_and_non_casters() {
    let ground = object(
        Shape::Plane {
            size: 2.0,
            tessellation: 1,
        },
        Vec3::ZERO,
        true,
    );
    let mut blocker = object(
        Shape::Box {
            size: Vec3::splat(3.0),
        },
        Vec3::new(0.0, 4.0, 0.0),
        false,
    );
    blocker.receives = false;
    let mut scene = top_down(
        16,
        2.0,
        vec![point_light(Vec3::new(0.0, 8.0, 0.0))],
        vec![ground],
    );
    scene.camera.eye = Vec3::new(0.0, 2.0, 0.0);
    let lit = truth(&scene, &TruthOptions::default()).expect("truth");
    assert_eq!(
        lit.mask.class(0, 0),
        Class::Background,
        "corner beyond the plane"
    );
    assert_eq!(lit.mask.class(8, 8), Class::Lit);
    scene.objects.push(blocker);
    let still = truth(&scene, &TruthOptions::default()).expect("truth");
    assert_eq!(
        still.mask, lit.mask,
        "a non-caster above the camera changes nothing"
    );
    // Light below the ground: the visible side faces away.
    scene.lights = vec![point_light(Vec3::new(0.0, -5.0, 0.0))];
    let below = truth(&scene, &TruthOptions::default()).expect("truth");
    assert_eq!(below.mask.class(8, 8), Class::Shadowed);
    assert_eq!(
        truth(
            &scene,
            &TruthOptions {
                light: 3,
                ..TruthOptions::default()
            }
        ),
        Err(TruthError::NoSuchLight { index: 3, count: 1 })
    );
}

#[test]
fn area_light_penumbra() {
    // A 2×2 area light at height 8 over a half-plane occluder: visibility runs from 1 in
    // full light to 0 in umbra, with values in between in the penumbra.
    let occluder = object(
        Shape::Box {
            size: Vec3::new(4.0, 0.001, 8.0),
        },
        Vec3::new(-2.0, 4.0, 0.0),
        true,
    );
    let ground = object(
        Shape::Plane {
            size: 8.0,
            tessellation: 1,
        },
        Vec3::ZERO,
        true,
    );
    let light = Light {
        kind: LightKind::Area {
            corner: Vec3::new(-1.0, 8.0, -1.0),
            edge_u: Vec3::new(2.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.0, 2.0),
        },
        view: Camera {
            eye: Vec3::new(0.0, 8.0, 0.0),
            at: Vec3::ZERO,
            up: Vec3::Z,
            projection: Projection::Perspective {
                fovy: 90.0,
                near: 1.0,
                far: 50.0,
            },
        },
        colour: Vec3::ONE,
        intensity: 1.0,
    };
    let mut scene = top_down(64, 4.0, vec![light], vec![ground, occluder]);
    scene.camera.eye = Vec3::new(0.0, 3.0, 0.0);
    let t = truth(
        &scene,
        &TruthOptions {
            light: 0,
            area_samples: Some(64),
            ..TruthOptions::default()
        },
    )
    .expect("truth");
    let row = 32usize * 64;
    let v = &t.visibility[row..row + 64];
    assert!(v[2] < 0.01 && v[61] > 0.99, "umbra {} lit {}", v[2], v[61]);
    // Penumbra width on the ground: the light's 2 units scaled by 4 / (8 − 4) = 1 → 2 units,
    // centred on x = 0: x ∈ (−1, 1) has partial visibility, increasing with x.
    let partial: Vec<f32> = v[24..40].to_vec();
    assert!(partial.iter().all(|&x| x > 0.0 && x < 1.0), "{partial:?}");
    assert!(
        partial.windows(2).all(|w| w[1] >= w[0] - 0.1),
        "{partial:?}"
    );
}

#[test]
fn default_scene_has_all_three_values() {
    let mut scene = Scene::default_scene();
    scene.image.width = 128;
    scene.image.height = 128;
    let t = truth(&scene, &TruthOptions::default()).expect("truth");
    for v in [LIT, SHADOWED, BACKGROUND] {
        assert!(t.mask.data.contains(&v), "{v}");
    }
    assert!(t.shadow_rays > 0 && t.primary_rays == 128 * 128);
    assert_eq!(t.visibility_image().dimensions(), (128, 128));
}

/// The default scene's camera with other near and far planes (nothing in the scene lies
/// nearer than 4 or beyond 31 from the eye, so the mask must not change).
fn default_with_depth_range(near: f32, far: f32) -> Scene {
    let mut scene = Scene::default_scene();
    scene.image.width = 128;
    scene.image.height = 96;
    scene.camera.projection = Projection::Perspective {
        fovy: 40.0,
        near,
        far,
    };
    scene
}

/// Item: a far/near ratio of 2.5·10⁵ to 5·10⁷ used to empty the truth (every primary ray
/// missed through the f32 inverse of P·V). The masks must equal the near-4/far-50 mask
/// but for at most 0.1% of the pixels (samples on a silhouette, where rounding the ray's
/// origin differently may tip a pixel).
#[test]
fn large_far_over_near_ratios_keep_the_truth() {
    let reference = truth(
        &default_with_depth_range(4.0, 50.0),
        &TruthOptions::default(),
    )
    .expect("truth");
    let background = |t: &Truth| t.mask.data.iter().filter(|&&v| v == BACKGROUND).count();
    let pixels = reference.mask.data.len();
    assert!(
        background(&reference) < pixels * 3 / 4,
        "the reference sees the scene"
    );
    for (near, far) in [(4.0, 1e6), (4.0, 1e9), (0.01, 1e8), (1e-6, 50.0)] {
        let t = truth(
            &default_with_depth_range(near, far),
            &TruthOptions::default(),
        )
        .expect("truth");
        let differ = t
            .mask
            .data
            .iter()
            .zip(&reference.mask.data)
            .filter(|(a, b)| a != b)
            .count();
        assert!(
            differ * 1000 <= pixels,
            "near {near}, far {far}: {differ} of {pixels} pixels differ \
             (background {} vs {})",
            background(&t),
            background(&reference)
        );
        assert!(t.shadow_rays > 0, "near {near}, far {far}: no shadow rays");
    }
}

/// Item: `--light 99` on a scene without lights used to give an all-lit mask.
#[test]
fn a_light_past_the_end_of_a_lightless_scene_is_an_error() {
    let mut scene = Scene::default_scene();
    scene.image.width = 16;
    scene.image.height = 16;
    scene.lights.clear();
    let options = |light| TruthOptions {
        light,
        ..TruthOptions::default()
    };
    let err = truth(&scene, &options(99)).expect_err("no light 99");
    assert_eq!(
        err,
        TruthError::NoSuchLight {
            index: 99,
            count: 0
        }
    );
    assert_eq!(
        err.to_string(),
        "light 99 asked for, but the scene has no lights"
    );
    // Light 0 of a lightless scene is what `none` draws: everything visible lit.
    let lit = truth(&scene, &options(0)).expect("light 0");
    assert!(lit.mask.data.iter().all(|&v| v == LIT || v == BACKGROUND));
    scene.lights = Scene::default_scene().lights;
    scene.lights.push(scene.lights[0]);
    let err = truth(&scene, &options(2)).expect_err("no light 2");
    assert!(
        err.to_string().contains("2 lights (indices 0 to 1)"),
        "{err}"
    );
}

/// The half-plane scene of `area_light_penumbra` at `size`²: a 2 × 2 light at height 8
/// centred over the origin, a thin occluder covering x < 0 at height 4, the ground seen
/// from below the occluder. Its exact visibility at ground x is clamp((x + 1)/2, 0, 1):
/// the ray to the light's point at lx passes height 4 at (x + lx)/2, blocked when < 0.
fn half_plane(size: u32) -> Scene {
    let occluder = object(
        Shape::Box {
            size: Vec3::new(4.0, 0.001, 8.0),
        },
        Vec3::new(-2.0, 4.0, 0.0),
        true,
    );
    let ground = object(
        Shape::Plane {
            size: 8.0,
            tessellation: 1,
        },
        Vec3::ZERO,
        true,
    );
    let light = area_light(Vec3::new(0.0, 8.0, 0.0), Vec3::ZERO, 2.0);
    let mut scene = top_down(size, 4.0, vec![light], vec![ground, occluder]);
    scene.camera.eye = Vec3::new(0.0, 3.0, 0.0);
    scene
}

/// The exact visibility of `half_plane(size)` at pixel column `x` (the thin occluder's
/// 0.001 thickness moves it by < 10⁻³).
fn half_plane_visibility(size: u32, x: usize) -> f32 {
    let ground_x = -4.0 + (x as f32 + 0.5) * 8.0 / size as f32;
    ((ground_x + 1.0) / 2.0).clamp(0.0, 1.0)
}

/// A square area light of side `side` centred at `centre`, facing `at` (the scene
/// parser's `centre + size + at` construction).
fn area_light(centre: Vec3, at: Vec3, side: f32) -> Light {
    let n = (at - centre).normalize();
    let hint = if n.cross(Vec3::Y).length() < 1e-6 {
        Vec3::Z
    } else {
        Vec3::Y
    };
    let u = hint.cross(n).normalize();
    let v = n.cross(u);
    let (edge_u, edge_v) = (u * side, v * side);
    Light {
        kind: LightKind::Area {
            corner: centre - 0.5 * (edge_u + edge_v),
            edge_u,
            edge_v,
        },
        view: Camera {
            eye: centre,
            at,
            up: if hint == Vec3::Y { Vec3::Y } else { -Vec3::Z },
            projection: Projection::Perspective {
                fovy: 90.0,
                near: 1.0,
                far: 50.0,
            },
        },
        colour: Vec3::ONE,
        intensity: 1.0,
    }
}

/// The default scene with its spot light replaced by a 2 × 2 area light at the same
/// place, facing the origin.
fn default_area(size: u32) -> Scene {
    let mut scene = Scene::default_scene();
    scene.image.width = size;
    scene.image.height = size;
    scene.lights = vec![area_light(Vec3::new(6.0, 10.0, 6.0), Vec3::ZERO, 2.0)];
    scene
}

fn samples(n: u32, seed: u32) -> TruthOptions {
    TruthOptions {
        area_samples: Some(n),
        seed,
        ..TruthOptions::default()
    }
}

/// Root mean square of a − b over the pixels `keep` selects.
fn rms(a: &[f32], b: &[f32], keep: impl Fn(usize) -> bool) -> f64 {
    let (sum, count) = a
        .iter()
        .zip(b)
        .enumerate()
        .filter(|(i, _)| keep(*i))
        .fold((0.0f64, 0usize), |(s, c), (_, (x, y))| {
            (s + f64::from(x - y).powi(2), c + 1)
        });
    (sum / count.max(1) as f64).sqrt()
}

/// The standard error the truth prints is its RMSE against the exact visibility: on the
/// half-plane, whose visibility is known in closed form, at three sample counts, within
/// 25% (the estimate and the error are both means over ~1000 penumbra pixels of noisy
/// squares: ±10% each). The estimate is also unbiased (mean error ≈ 0), and larger
/// counts are closer.
#[test]
fn the_standard_error_is_the_error_against_the_exact_visibility() {
    let size = 64;
    let scene = half_plane(size);
    let exact: Vec<f32> = (0..(size * size) as usize)
        .map(|i| half_plane_visibility(size, i % size as usize))
        .collect();
    let mut last = f64::INFINITY;
    for n in [8, 32, 128] {
        let t = truth(&scene, &samples(n, 0)).expect("truth");
        let area = t.area.expect("an area light");
        assert_eq!(area.samples(), n);
        assert_eq!(area.geometry_pixels, u64::from(size * size));
        let error = rms(&t.visibility, &exact, |_| true);
        let se = area.standard_error;
        assert!(
            (se - error).abs() <= 0.25 * error,
            "{n} samples: standard error {se:.5}, RMSE against the exact {error:.5}"
        );
        let mean: f64 = t
            .visibility
            .iter()
            .zip(&exact)
            .map(|(a, b)| f64::from(a - b))
            .sum::<f64>()
            / exact.len() as f64;
        assert!(
            mean.abs() < 0.2 * error,
            "{n} samples: mean error {mean:.5}"
        );
        assert!(error < last, "{n} samples: {error} not below {last}");
        last = error;
    }
}

/// Another seed gives another, independent estimate; the same seed the same one.
#[test]
fn seeds_give_independent_estimates_and_the_same_seed_the_same() {
    let scene = half_plane(32);
    let a = truth(&scene, &samples(18, 0)).expect("truth");
    let again = truth(&scene, &samples(18, 0)).expect("truth");
    let b = truth(&scene, &samples(18, 1)).expect("truth");
    assert_eq!(a.visibility, again.visibility);
    assert_eq!(a.mask, b.mask, "the hard mask does not sample");
    let differ = a
        .visibility
        .iter()
        .zip(&b.visibility)
        .filter(|(x, y)| x != y)
        .count();
    // Only penumbra pixels (a quarter of the columns) can differ, and most of them do.
    assert!(differ > 32 * 8 / 2 && differ <= 32 * 8 + 64, "{differ}");
}

/// Samples come from the options, else the scene's `[truth] samples`; 0 and more than the
/// budget are refused.
#[test]
fn samples_come_from_the_options_else_the_scene() {
    let mut scene = half_plane(16);
    let count = |t: Truth| t.area.expect("an area light").samples();
    assert_eq!(
        count(truth(&scene, &TruthOptions::default()).expect("truth")),
        TruthSettings::DEFAULT_SAMPLES
    );
    scene.truth.samples = 50;
    assert_eq!(
        count(truth(&scene, &TruthOptions::default()).expect("truth")),
        50
    );
    assert_eq!(count(truth(&scene, &samples(8, 0)).expect("truth")), 8);
    assert_eq!(
        count(truth(&scene, &samples(9, 0)).expect("truth")),
        18,
        "2s² ≥ 9"
    );
    for bad in [0, TruthSettings::MAX_SAMPLES + 1] {
        assert_eq!(
            truth(&scene, &samples(bad, 0)),
            Err(TruthError::Samples {
                samples: bad,
                max: TruthSettings::MAX_SAMPLES
            })
        );
    }
    // Point lights take one ray per pixel whatever the count.
    let mut point = Scene::default_scene();
    point.image.width = 32;
    point.image.height = 32;
    let one = truth(&point, &samples(1, 0)).expect("truth");
    let many = truth(&point, &samples(512, 0)).expect("truth");
    assert_eq!(
        one,
        Truth {
            timings: one.timings,
            ..many.clone()
        }
    );
    assert!(many.area.is_none());
}

/// Item: a directional light straight down (direction (0, −1, 0)) cast no shadow — its
/// shadow rays' −0 components made obvhs's slab test miss every box.
#[test]
fn a_light_straight_down_casts_its_shadow() {
    let occluder = object(
        Shape::Box {
            size: Vec3::new(2.0, 0.2, 2.0),
        },
        Vec3::new(0.0, 4.0, 0.0),
        true,
    );
    let ground = object(
        Shape::Plane {
            size: 8.0,
            tessellation: 2,
        },
        Vec3::ZERO,
        true,
    );
    let mut light = point_light(Vec3::new(0.0, 8.0, 0.0));
    light.kind = LightKind::Directional {
        direction: -Vec3::Y,
        angular_diameter: 0.0,
    };
    let mut scene = top_down(32, 4.0, vec![light], vec![ground, occluder]);
    scene.camera.eye = Vec3::new(0.0, 3.0, 0.0);
    let t = truth(&scene, &TruthOptions::default()).expect("truth");
    // The box's 2 × 2 shadow: 8 × 8 pixels of the 32², centred.
    let shadowed = t.mask.data.iter().filter(|&&v| v == SHADOWED).count();
    assert_eq!(shadowed, 64);
    assert_eq!(t.mask.class(16, 16), Class::Shadowed);
    assert_eq!(t.mask.class(2, 2), Class::Lit);
}

/// How many samples the default needs; prints the table quoted in the module note ("The
/// default, measured"): RMSE against a reference of 2048 samples with another seed, on the
/// half-plane (also against its exact visibility) and the default scene lit by an area
/// light, both at 256², and the truth's own standard error. Slow in a debug build:
/// `cargo test --release --lib truth::tests::default_samples_converge -- --ignored --nocapture`
#[test]
#[ignore]
fn default_samples_converge() {
    let size = 256;
    let reference_samples = 2048;
    let scenes = [
        ("half-plane", half_plane(size)),
        ("default-area", default_area(size)),
    ];
    println!(
        "scene         samples  RMSE vs ref  penumbra  vs exact  standard error  shadow rays/s"
    );
    for (name, scene) in &scenes {
        let reference = truth(scene, &samples(reference_samples, 1)).expect("reference");
        let ref_se = reference.area.expect("area").standard_error;
        let geometry = |i: usize| reference.mask.data[i] != BACKGROUND;
        let penumbra = |i: usize| {
            geometry(i) && reference.visibility[i] > 0.0 && reference.visibility[i] < 1.0
        };
        let exact: Option<Vec<f32>> = (*name == "half-plane").then(|| {
            (0..(size * size) as usize)
                .map(|i| half_plane_visibility(size, i % size as usize))
                .collect()
        });
        println!(
            "{name:<13} {:>7}  (reference; its standard error {ref_se:.5}{})",
            reference_samples,
            exact.as_ref().map_or(String::new(), |e| format!(
                ", RMSE vs exact {:.5}",
                rms(&reference.visibility, e, geometry)
            ))
        );
        for n in [8, 18, 32, 50, 72, 98, 128, 162, 200, 242, 288, 338] {
            let t = truth(scene, &samples(n, 0)).expect("truth");
            let area = t.area.expect("area");
            let against_ref = rms(&t.visibility, &reference.visibility, geometry);
            println!(
                "{name:<13} {n:>7}  {against_ref:>11.5}  {:>8.5}  {:>8}  {:>14.5}  {:>10.1} M",
                rms(&t.visibility, &reference.visibility, penumbra),
                exact.as_ref().map_or("-".to_string(), |e| format!(
                    "{:.5}",
                    rms(&t.visibility, e, geometry)
                )),
                area.standard_error,
                t.shadow_rays as f64 / t.timings.shadow.as_secs_f64() / 1e6,
            );
            if n == TruthSettings::DEFAULT_SAMPLES {
                assert!(against_ref < 0.005, "{name}: {against_ref}");
                assert!(
                    area.standard_error < 0.005,
                    "{name}: {}",
                    area.standard_error
                );
            }
        }
    }
}

/// A flat torus over the ground under a low directional light: the ring's near half
/// shadows its far half (the object shadows itself), its underside faces away, and the
/// ground takes the shadow of the torus (shadow from another object).
fn torus_over_ground(with_ground: bool) -> Scene {
    let torus = object(
        Shape::Torus {
            major_radius: 1.5,
            minor_radius: 0.5,
            rings: 48,
            sides: 24,
        },
        Vec3::new(0.0, 0.6, 0.0),
        true,
    );
    let ground = object(
        Shape::Plane {
            size: 8.0,
            tessellation: 2,
        },
        Vec3::ZERO,
        true,
    );
    let mut light = point_light(Vec3::new(0.0, 8.0, 0.0));
    light.kind = LightKind::Directional {
        direction: Vec3::new(-1.0, -0.08, 0.1).normalize(),
        angular_diameter: 0.0,
    };
    let objects = if with_ground {
        vec![ground, torus]
    } else {
        vec![torus]
    };
    top_down(96, 4.0, vec![light], objects)
}

#[test]
fn shadow_causes_agree_with_the_mask_and_tell_self_from_others() {
    use crate::metrics::Cause;
    let scene = torus_over_ground(true);
    let t = truth(&scene, &TruthOptions::default()).expect("truth");
    let causes = shadow_causes(&scene, 0, &t.mask).expect("causes");
    let mut count = std::collections::HashMap::new();
    for (i, (&cause, &v)) in causes.cause.iter().zip(&t.mask.data).enumerate() {
        let expected = match cause {
            Cause::Background => BACKGROUND,
            Cause::Lit => LIT,
            _ => SHADOWED,
        };
        assert_eq!(v, expected, "pixel {i}: {cause:?}");
        *count.entry((causes.object[i], cause)).or_insert(0u32) += 1;
    }
    let n = |object: u32, cause| count.get(&(object, cause)).copied().unwrap_or(0);
    // The ground faces the light and cannot occlude itself: only the torus shadows it.
    assert!(n(0, Cause::OtherOccluder) > 100, "{count:?}");
    assert_eq!(n(0, Cause::FacesAway) + n(0, Cause::OwnOccluder), 0);
    // The torus shadows itself both ways, and nothing else is between it and the light.
    assert!(n(1, Cause::OwnOccluder) > 20, "{count:?}");
    assert!(n(1, Cause::FacesAway) > 20, "{count:?}");
    assert_eq!(n(1, Cause::OtherOccluder), 0, "{count:?}");

    // Without the ground, the torus's own shadow is the same pixels.
    let alone = torus_over_ground(false);
    let t_alone = truth(&alone, &TruthOptions::default()).expect("truth");
    let alone_causes = shadow_causes(&alone, 0, &t_alone.mask).expect("causes");
    for (i, &cause) in causes.cause.iter().enumerate() {
        if causes.object[i] == 1 && cause == Cause::OwnOccluder {
            assert_eq!(alone_causes.cause[i], Cause::OwnOccluder, "pixel {i}");
        }
    }
}

#[test]
fn shadow_causes_refuse_a_mask_of_another_size() {
    let scene = torus_over_ground(true);
    let mask = crate::metrics::Mask::filled(3, 3, LIT);
    assert!(matches!(
        shadow_causes(&scene, 0, &mask),
        Err(TruthError::MaskSize { .. })
    ));
}
