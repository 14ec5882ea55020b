//! Suns: directional lights with an angular size (`angular_diameter`, degrees in the scene,
//! radians in `LightKind::Directional`). The truth's visibility against the geometry of a
//! disc source at infinity — 1 on open ground, 0 in the umbra, in between across a
//! penumbra d · α wide under an edge d above the ground (the exact profile is the fraction
//! of a disc past a chord) — the hard directional mask as α → 0, the scene file's
//! refusals, and `accumulate`'s N directional renders judged against the truth on
//! `assets/sunlight.toml`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use fixedfunc::gpu::Backend;
use fixedfunc::metrics::{BACKGROUND, LIT};
use fixedfunc::render::{self, RenderOptions};
use fixedfunc::scene::{LightKind, Scene, SceneError};
use fixedfunc::truth::{self, Truth, TruthOptions};
use fixedfunc::vocab::{PipelineKind, TechniqueId};

fn fixedfunc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .args(args)
        .output()
        .expect("run fixedfunc")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

fn arg(p: &Path) -> &str {
    p.to_str().expect("temporary paths are UTF-8")
}

fn sunlight_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/sunlight.toml")
}

fn parse(text: &str) -> Result<Scene, SceneError> {
    Scene::parse(text, Path::new("sun.toml"))
}

/// Image width of the half-plane scenes, over x ∈ [−1, 1].
const WIDTH: u32 = 256;
const ROWS: u32 = 8;

/// Looking straight down (orthographic, x ∈ [−1, 1]) on a ground under a half-plane
/// occluder covering x < 0 at height `height`, lit by a sun overhead of `degrees`
/// across. The camera sits under the occluder, so it sees the ground only.
fn half_plane(height: f32, degrees: f32) -> Scene {
    let half_rows = ROWS as f32 / WIDTH as f32;
    let text = format!(
        r#"
[camera]
eye = [0, 0.5, 0]
at = [0, 0, 0]
up = [0, 0, -1]
ortho = {{ left = -1, right = 1, bottom = -{half_rows}, top = {half_rows} }}
near = 0.1
far = 5

[image]
width = {WIDTH}
height = {ROWS}

[[light]]
type = "directional"
direction = [0, -1, 0]
angular_diameter = {degrees}

[[object]]
shape = "plane"
size = 8

[[object]]
shape = "box"
size = [8, 0.01, 8]
translate = [-4, {height}, 0]
"#
    );
    parse(&text).expect("the half-plane scene parses")
}

/// The fraction of a disc of unit radius on the far side of the chord at signed offset u
/// from its centre: ½ + (u √(1 − u²) + asin u) / π, 0 below −1 and 1 above 1.
fn disc_past_chord(u: f64) -> f64 {
    let u = u.clamp(-1.0, 1.0);
    0.5 + (u * (1.0 - u * u).sqrt() + u.asin()) / std::f64::consts::PI
}

/// The world x of pixel column `x`.
fn column_x(x: u32) -> f64 {
    -1.0 + 2.0 * (f64::from(x) + 0.5) / f64::from(WIDTH)
}

fn sun_truth(scene: &Scene) -> Truth {
    truth::truth(scene, &TruthOptions::default()).expect("truth")
}

/// Under an edge d above the ground, a point x past the edge's shadow sees the sun's disc
/// cut by a chord at offset x / (d tan(α/2)) (radius 1), so the visibility is that
/// disc fraction: 0 for x < −d tan(α/2), 1 for x > d tan(α/2), a penumbra 2 d tan(α/2)
/// ≈ d α wide (the cap's tan θ against the disc's radius differs by θ²/3 ≈ 10⁻⁴ here).
/// Measured at the default 242 samples, 256 pixels over 2 units, for (d, α) = (2, 4°),
/// (4, 4°), (4, 2°): the largest difference from the exact profile 0.022, 0.027, 0.022
/// (bound 0.06); the penumbra's width (columns strictly between 0 and 1) within 0.0,
/// −1.1 and 0.0 pixels of d α (bound 3 pixels, 0.023 units).
#[test]
fn a_sun_over_a_half_plane_gives_the_disc_past_a_chord() {
    let pixel = 2.0 / f64::from(WIDTH);
    for (height, degrees) in [(2.0f32, 4.0f32), (4.0, 4.0), (4.0, 2.0)] {
        let scene = half_plane(height, degrees);
        let alpha = f64::from(degrees).to_radians();
        let reach = f64::from(height) * (0.5 * alpha).tan();
        let t = sun_truth(&scene);
        assert!(t.area.is_some(), "a sun's truth is judged by visibility");
        let mut worst = 0.0f64;
        let mut partial_columns = 0.0f64;
        for y in 0..ROWS {
            let row = &t.visibility[(y * WIDTH) as usize..((y + 1) * WIDTH) as usize];
            for (x, &v) in row.iter().enumerate() {
                let wx = column_x(x as u32);
                let exact = disc_past_chord(wx / reach);
                worst = worst.max((f64::from(v) - exact).abs());
                if wx > 2.0 * reach {
                    assert_eq!(v, 1.0, "open ground at x = {wx}");
                }
                if wx < -2.0 * reach {
                    assert_eq!(v, 0.0, "umbra at x = {wx}");
                }
                partial_columns += f64::from(u8::from(v > 0.0 && v < 1.0));
            }
        }
        let width = partial_columns / f64::from(ROWS) * pixel;
        let expected = f64::from(height) * alpha;
        println!(
            "d = {height}, α = {degrees}°: max |v − exact| {worst:.4}, penumbra {width:.4} \
             (d α = {expected:.4}, {:+.2} pixels)",
            (width - expected) / pixel
        );
        assert!(worst < 0.06, "max |v − exact| {worst}");
        assert!(
            (width - expected).abs() <= 3.0 * pixel,
            "penumbra {width} against d α = {expected}"
        );
        // The hard mask is the centre's: shadowed exactly where x < 0.
        for x in 0..WIDTH {
            let expect_lit = column_x(x) > 0.0;
            assert_eq!(t.mask.data[x as usize] == LIT, expect_lit, "column {x}");
        }
    }
}

/// A setting sun: its centre 1° above the ground's plane, α = 4°, nothing casting. Each of
/// its samples counts only when the ground faces it (n · ω > 0), as an area light's points
/// do, so the visibility is the part of the disc above the horizon: the disc past the chord
/// at tan 1° / tan 2° ≈ 0.4998 of its radius, 0.8044. Measured at 242 samples: mean 0.8040
/// over the 32² pixels (bound ± 0.005), each pixel 0.781 to 0.831 (bound ± 0.05: each
/// pixel's grids are jittered anew); the hard mask lit (the centre is above).
#[test]
fn a_setting_sun_is_seen_by_the_part_of_its_disc_above_the_horizon() {
    let elevation = 1f64.to_radians();
    let text = format!(
        r#"
[camera]
eye = [0, 2, 0]
at = [0, 0, 0]
up = [0, 0, -1]
ortho = {{ left = -1, right = 1, bottom = -1, top = 1 }}
near = 0.5
far = 5

[image]
width = 32
height = 32

[[light]]
type = "directional"
direction = [{}, {}, 0]
angular_diameter = 4

[[object]]
shape = "plane"
size = 8
"#,
        elevation.cos(),
        -elevation.sin()
    );
    let scene = parse(&text).expect("parses");
    let t = sun_truth(&scene);
    let exact = disc_past_chord(elevation.tan() / 2f64.to_radians().tan());
    let (lo, hi) = t
        .visibility
        .iter()
        .fold((1.0f32, 0.0f32), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    let mean = t.visibility.iter().map(|&v| f64::from(v)).sum::<f64>() / t.visibility.len() as f64;
    println!("a sun 1° up: visibility {lo:.4} to {hi:.4}, mean {mean:.4}, exact {exact:.4}");
    assert!((mean - exact).abs() < 0.005, "mean {mean} against {exact}");
    assert!(f64::from(lo) > exact - 0.05 && f64::from(hi) < exact + 0.05);
    assert!(t.mask.data.iter().all(|&m| m == LIT));
}

/// As α → 0 the sun is the hard directional light: the same mask bit for bit (both are
/// the centre's rays) and a visibility equal to it wherever no sample ray grazes an edge
/// (α = 10⁻⁴ degrees spreads the rays by ≈ 10⁻⁵ units here; measured: 0 pixels differ,
/// bound 0.1%).
#[test]
fn a_vanishing_sun_is_the_hard_directional_light() {
    let mut scene = Scene::load(&sunlight_path()).expect("assets/sunlight.toml loads");
    scene.image.width = 128;
    scene.image.height = 128;
    let mut hard = scene.clone();
    let direction = match scene.lights[0].kind {
        LightKind::Directional { direction, .. } => direction,
        other => panic!("a directional light: {other:?}"),
    };
    hard.lights[0].kind = LightKind::Directional {
        direction,
        angular_diameter: 0.0,
    };
    scene.lights[0].kind = LightKind::Directional {
        direction,
        angular_diameter: 1e-4f32.to_radians(),
    };
    let (sun, hard) = (sun_truth(&scene), sun_truth(&hard));
    assert!(hard.area.is_none() && sun.area.is_some());
    assert_eq!(sun.mask, hard.mask, "the hard mask is the centre's");
    let differ = sun
        .visibility
        .iter()
        .zip(&hard.visibility)
        .filter(|(a, b)| a != b)
        .count();
    println!("α = 1e-4°: {differ} of {} visibilities differ", 128 * 128);
    assert!(differ <= 128 * 128 / 1000, "{differ} pixels differ");
    let geometry = sun.mask.data.iter().filter(|&&m| m != BACKGROUND).count();
    assert!(geometry > 128 * 128 / 2);
}

/// The sunlight scene loads as a sun of 4°, and its truth has umbra, penumbra and light.
#[test]
fn the_sunlight_scene_has_umbra_penumbra_and_light() {
    let mut scene = Scene::load(&sunlight_path()).expect("assets/sunlight.toml loads");
    let sun = scene.lights[0].sun().expect("a sun");
    assert!((sun.angular_diameter.to_degrees() - 4.0).abs() < 1e-4);
    scene.image.width = 128;
    scene.image.height = 128;
    let t = sun_truth(&scene);
    let geometry: Vec<f32> = t
        .visibility
        .iter()
        .zip(&t.mask.data)
        .filter(|(_, &m)| m != BACKGROUND)
        .map(|(&v, _)| v)
        .collect();
    let count = |f: &dyn Fn(f32) -> bool| geometry.iter().filter(|&&v| f(v)).count();
    let (umbra, penumbra, lit) = (
        count(&|v| v == 0.0),
        count(&|v| v > 0.0 && v < 1.0),
        count(&|v| v == 1.0),
    );
    println!("128²: umbra {umbra}, penumbra {penumbra}, lit {lit}");
    assert!(umbra > 200 && penumbra > 100 && lit > 5_000);
}

/// A scene file's refusals name the line and the key; `truth` exits 2 with them.
#[test]
fn bad_angular_diameters_are_refused_at_their_line() {
    for (value, words) in [
        ("45", &["(0, 30] degrees", "not 45"][..]),
        ("0", &["(0, 30] degrees", "not 0"][..]),
        ("-2", &["not -2"][..]),
        ("inf", &["finite"][..]),
    ] {
        let text = format!(
            "[[light]]\ntype = \"directional\"\ndirection = [0, -1, 0]\n\nangular_diameter = {value}\n"
        );
        let err = parse(&text).expect_err(value);
        let msg = err.to_string();
        assert_eq!(err.location().map(|at| at.line), Some(5), "{msg}");
        assert!(msg.contains("light[0].angular_diameter"), "{msg}");
        for w in words {
            assert!(msg.contains(w), "`{w}` missing from {msg}");
        }
    }
    let dir = tempfile::tempdir().expect("temp dir");
    let scene = dir.path().join("wide-sun.toml");
    std::fs::write(
        &scene,
        "[[light]]\ntype = \"directional\"\ndirection = [0, -1, 0]\nangular_diameter = 31\n",
    )
    .expect("write the scene");
    let mask = dir.path().join("mask.png");
    let run = fixedfunc(&["truth", arg(&scene), "--mask", arg(&mask)]);
    let stderr = text(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("wide-sun.toml:4:") && stderr.contains("angular_diameter"),
        "{stderr}"
    );
}

/// `truth --visibility` of a sun says how it was sampled and writes the grey image.
#[test]
fn truth_reports_a_sun_and_writes_its_visibility() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (mask, vis) = (dir.path().join("m.png"), dir.path().join("v.png"));
    let run = fixedfunc(&[
        "truth",
        arg(&sunlight_path()),
        "--size",
        "96x96",
        "--samples",
        "32",
        "--mask",
        arg(&mask),
        "--visibility",
        arg(&vis),
    ]);
    let stdout = text(&run.stdout);
    assert!(run.status.success(), "{}", text(&run.stderr));
    assert!(
        stdout.contains("sun of 4.00°: 32 samples per pixel"),
        "{stdout}"
    );
    let image = image::open(&vis).expect("the visibility").to_luma_alpha8();
    assert_eq!(image.dimensions(), (96, 96));
    assert!(image
        .pixels()
        .any(|p| p.0[1] == 255 && (8..248).contains(&p.0[0])));
}

/// `accumulate` takes a sun: N hard directional renders from stratified directions of the
/// disc (the truth's mapping), averaged with glAccum, judged by visibility against the
/// truth; `depth-compare` on the same scene is judged by visibility too (its hard mask as 0
/// or 1). Measured on `assets/sunlight.toml` at 512², N = 64, emulated on EGL:
///
/// | figure                         | accumulate | bound  | depth-compare |
/// |--------------------------------|-----------:|-------:|--------------:|
/// | visibility RMSE, all geometry  |     0.0473 |  0.060 |        0.0647 |
/// | RMSE on the ground             |     0.0045 |  0.008 |        0.0348 |
/// | RMSE in the ground's penumbra  |     0.0344 |  0.050 |        0.2687 |
///
/// (2733 penumbra pixels on the ground. The scene's 512² map over ±8 units, 0.03 a texel,
/// matters: at 256² over ±12 the ground's penumbra RMSE was 0.098.)
///
/// Most of the whole-scene figure is not the sampling: both techniques light the box's,
/// the plate's and the sphere's faces turned away from the sun (the truth's n · ω ≤ 0;
/// `render` counts them as "facing away" self-shadow errors), so the ground — facing the
/// whole sun, shadowed only by casters — is where the N directions are judged.
#[test]
fn accumulate_renders_a_sun_within_the_bound_of_the_truth() {
    let scene = Scene::load(&sunlight_path()).expect("assets/sunlight.toml loads");
    let figures = |technique: TechniqueId| {
        let options = RenderOptions {
            backend: Backend::Egl,
            pipeline: PipelineKind::Emulate,
            technique: Some(technique),
            frames: 1,
            ..RenderOptions::default()
        };
        let mut scene = scene.clone();
        scene.shadow.light_samples = 64;
        let outcome = render::render(&scene, &options).expect("renders");
        let v = outcome.visibility.expect("a sun is judged by visibility");
        let causes = truth::shadow_causes(&scene, 0, &outcome.truth.mask).expect("causes");
        let (mut all, mut penumbra) = ((0.0f64, 0u32), (0.0f64, 0u32));
        for (i, (&t, &o)) in outcome
            .truth
            .visibility
            .iter()
            .zip(&causes.object)
            .enumerate()
        {
            let Some(ours) = v.image.data[i] else {
                continue;
            };
            if o != 0 {
                continue; // not the ground
            }
            let d = f64::from(ours) / 255.0 - f64::from(t);
            all = (all.0 + d * d, all.1 + 1);
            if t > 0.0 && t < 1.0 {
                penumbra = (penumbra.0 + d * d, penumbra.1 + 1);
            }
        }
        let rmse = |(sum, n): (f64, u32)| (sum / f64::from(n.max(1))).sqrt();
        let f = (v.errors.rmse, rmse(all), rmse(penumbra));
        println!(
            "{technique}, assets/sunlight.toml 512²: visibility RMSE {:.4}, on the ground {:.4}, \
             in the ground's penumbra {:.4} ({} pixels) ({:?})",
            f.0, f.1, f.2, penumbra.1, v.source
        );
        assert!(
            penumbra.1 > 1_000,
            "{} penumbra pixels on the ground",
            penumbra.1
        );
        f
    };
    let soft = figures(TechniqueId::Accumulate);
    let hard = figures(TechniqueId::DepthCompare);
    assert!(soft.0 < 0.06, "visibility RMSE {}", soft.0);
    assert!(soft.1 < 0.008, "on the ground {}", soft.1);
    assert!(soft.2 < 0.05, "in the ground's penumbra {}", soft.2);
    assert!(
        hard.0 > soft.0 && hard.2 > 2.0 * soft.2,
        "{hard:?} against {soft:?}"
    );
}
