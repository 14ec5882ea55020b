//! `planar` on real contexts (EGL, llvmpipe), emulate and native, against the CPU truth.
//!
//! Planar shadows fall only on flat receivers, so masks are scored on the pixels where the
//! floor is the visible surface ([`projection::pixels_of`]). Tolerances, stated per test:
//! - against the truth: no wrong pixel farther than 1 pixel from a truth shadow edge, and
//!   at most 2 % of the floor's pixels wrong in all (edge pixels, where the rasterised
//!   projection and the ray-cast sample disagree by a fraction of a pixel);
//! - emulate against native: masks differ on at most 0.2 % of the pixels, images by at
//!   most 3/255 per channel on at most 1 % of the pixels (piglit's 3/2^bits);
//! - the blend: a shadowed floor pixel is round(½·v) ± 1 of the same pixel rendered by
//!   `none`.

mod projection;
mod support;

use fixedfunc::ff::Command;
use fixedfunc::metrics::{Class, BACKGROUND};
use fixedfunc::render::ImageSize;
use fixedfunc::scene::Scene;
use fixedfunc::techniques::planar::{receivers, Receiver};
use fixedfunc::techniques::{lookup, Prepared, TechniqueError};
use fixedfunc::vocab::{PipelineKind, PlanarMode};
use projection::{floor_scene, mask_difference, pixels_of, point_light, run, score, KINDS};
use support::{assert_images_match, Tolerance};

const SIZE: ImageSize = ImageSize {
    width: 192,
    height: 192,
};

const MODES: [&str; 2] = ["planar_mode = \"offset\"", "planar_mode = \"stencil\""];

/// Scores `scene`'s planar mask on the floor (object `floor`) on both pipelines, asserts
/// the tolerance of the module note, and returns the scores.
fn assert_floor_matches_truth(name: &str, scene: &Scene, floor: usize) -> Vec<projection::Score> {
    let pixels = pixels_of(scene, floor, SIZE);
    let mut scores = Vec::new();
    for kind in KINDS {
        let out = run(scene, "planar", kind, SIZE);
        let s = score(&out.mask, &out.truth.mask, &pixels, 1);
        assert!(
            s.pixels > 1000,
            "{name}: the floor covers {} pixels",
            s.pixels
        );
        assert_eq!(s.wrong_outside_band, 0, "{name} {kind:?}: {s:?}");
        assert!(s.wrong * 50 <= s.pixels, "{name} {kind:?}: {s:?}");
        scores.push(s);
    }
    scores
}

#[test]
fn ground_shadows_of_the_default_scene_match_the_truth_in_both_modes() {
    for mode in [PlanarMode::Offset, PlanarMode::Stencil] {
        let mut scene = Scene::default_scene();
        scene.shadow.planar_mode = mode;
        let scores = assert_floor_matches_truth(&format!("default {mode:?}"), &scene, 0);
        assert!(scores[0].shadowed_in_truth > 500, "{scores:?}");
    }
}

#[test]
fn emulate_and_native_agree_on_the_default_scene() {
    for mode in [PlanarMode::Offset, PlanarMode::Stencil] {
        let mut scene = Scene::default_scene();
        scene.shadow.planar_mode = mode;
        let e = run(&scene, "planar", PipelineKind::Emulate, SIZE);
        let n = run(&scene, "planar", PipelineKind::Native, SIZE);
        let n_pixels = (SIZE.width * SIZE.height) as usize;
        let differ = mask_difference(&e.mask, &n.mask);
        assert!(
            differ * 500 <= n_pixels,
            "{mode:?}: masks differ on {differ} pixels"
        );
        let tolerance = Tolerance {
            per_channel: 3,
            max_bad_pixels: n_pixels / 100,
        };
        assert_images_match(&format!("planar-{mode:?}"), &e.image, &n.image, tolerance);
    }
}

/// A closed box projects every shadow pixel at least twice (top and bottom faces, and the
/// sides): with the stencil trick each is blended once, v → round(½·v) ± 1.
#[test]
fn overlapping_projected_triangles_darken_a_floor_pixel_once() {
    let caster = "[[object]]\nname = \"box\"\nshape = \"box\"\nsize = [2, 2, 2]\ntranslate = [0, 2, 0]\nrotate = { axis = [0, 1, 0], degrees = 30 }\nreceives = false\n";
    for mode in MODES {
        let scene = floor_scene(&point_light([3.0, 9.0, 2.0]), caster, mode);
        for kind in KINDS {
            let lit = run(&scene, "none", kind, SIZE);
            let shadowed = run(&scene, "planar", kind, SIZE);
            let floor = pixels_of(&scene, 0, SIZE);
            let w = SIZE.width as i64;
            let inside = |i: usize| {
                let (x, y) = (i as i64 % w, i as i64 / w);
                (-1..=1).all(|dy| {
                    (-1..=1).all(|dx| {
                        let (u, v) = (x + dx, y + dy);
                        let j = (v * w + u) as usize;
                        (0..w).contains(&u)
                            && (0..w).contains(&v)
                            && floor[j]
                            && Class::of(shadowed.mask.data[j]) == Class::Shadowed
                    })
                })
            };
            let mut checked = 0;
            for i in (0..floor.len()).filter(|&i| inside(i)) {
                let (x, y) = (i as u32 % SIZE.width, i as u32 / SIZE.width);
                let v = lit.image.get_pixel(x, y).0;
                let got = shadowed.image.get_pixel(x, y).0;
                for c in 0..3 {
                    let once = (f32::from(v[c]) * 0.5).round() as i32;
                    assert!(
                        (i32::from(got[c]) - once).abs() <= 1,
                        "{mode} {kind:?} ({x},{y}) channel {c}: {} → {}, once would be {once} (twice {})",
                        v[c],
                        got[c],
                        (f32::from(v[c]) * 0.25).round()
                    );
                }
                checked += 1;
            }
            assert!(
                checked > 200,
                "{mode} {kind:?}: only {checked} shadow pixels"
            );
        }
    }
}

/// A small floor with a caster near its edge: the projection runs off the floor, and the
/// stencil keeps every background pixel exactly the clear colour.
#[test]
fn no_shadow_beyond_the_receivers_edge() {
    let text = r#"
[camera]
eye = [0, 10, 10]
at = [0, 0, 0]
fovy = 50
near = 2
far = 60
[image]
width = 128
height = 128
background = [0.25, 0.25, 0.375]
[[light]]
type = "point"
position = [-6, 6, 0]
at = [0, 0, 0]
[[object]]
name = "floor"
shape = "plane"
size = 4
tessellation = 2
casts = false
[[object]]
name = "post"
shape = "box"
size = [0.5, 3, 0.5]
translate = [0.5, 1.6, 0]
receives = false
"#;
    let background = [64u8, 64, 96, 255];
    for mode in ["offset", "stencil"] {
        let mut scene = projection::scene(text);
        scene.shadow.planar_mode = if mode == "offset" {
            PlanarMode::Offset
        } else {
            PlanarMode::Stencil
        };
        for kind in KINDS {
            let out = run(&scene, "planar", kind, SIZE);
            let mut off_floor = 0;
            for (i, &t) in out.truth.mask.data.iter().enumerate() {
                if t != BACKGROUND {
                    continue;
                }
                off_floor += 1;
                let (x, y) = (i as u32 % SIZE.width, i as u32 / SIZE.width);
                assert_eq!(
                    out.mask.data[i], BACKGROUND,
                    "{mode} {kind:?} mask ({x},{y})"
                );
                support::probe(&out.image, x, y, background, 0);
            }
            assert!(off_floor > SIZE.width * SIZE.height / 4);
            // The shadow does reach the floor's edge: it was clipped, not missing.
            let pixels = pixels_of(&scene, 0, SIZE);
            let s = score(&out.mask, &out.truth.mask, &pixels, 1);
            assert!(
                s.shadowed_in_truth > 100 && s.wrong_outside_band == 0,
                "{s:?}"
            );
        }
    }
}

/// A sphere half below the floor and a box above the light: only the part of the sphere
/// between the floor and the light casts (CPU slab clipping), exactly as the truth says.
#[test]
fn casters_below_the_plane_and_above_the_light_cast_what_the_truth_says() {
    let objects = r#"
[[object]]
name = "sunk"
shape = "sphere"
radius = 1.2
translate = [-1, 0.1, 2]
receives = false
[[object]]
name = "above"
shape = "box"
size = [3, 0.5, 3]
translate = [1, 11, 0]
receives = false
"#;
    for mode in MODES {
        let scene = floor_scene(&point_light([5.0, 5.0, -2.0]), objects, mode);
        let scores = assert_floor_matches_truth(mode, &scene, 0);
        assert!(
            scores.iter().all(|s| s.shadowed_in_truth > 100),
            "{scores:?}"
        );
    }
}

/// Every matrix the plan loads or multiplies and every vertex it draws is finite.
fn assert_finite_plan(scene: &Scene) {
    let prepared = Prepared::new(scene);
    let plan = (lookup("planar").unwrap().plan)(scene, &prepared).expect("plan");
    for c in plan.frame_commands().chain(&plan.mask.commands) {
        match c {
            Command::LoadMatrix(m) | Command::MultMatrix(m) => assert!(m.is_finite(), "{m}"),
            Command::Draw(g) => assert!(g.positions.iter().all(|p| p.is_finite())),
            _ => {}
        }
    }
}

/// Renders once on each pipeline and asserts the floor is shadowed all over — the truth's
/// rule for n·L ≤ 0. The truth itself agrees on at least `truth_share` of the floor: with
/// a light exactly in the plane its n·L = −y of the ray's hit point, ±10⁻⁷ of rounding, so
/// it calls scattered pixels lit; the technique's result does not depend on rounding.
fn assert_floor_unlit(scene: &Scene, truth_share: f64) {
    let floor = pixels_of(scene, 0, SIZE);
    for kind in KINDS {
        let out = run(scene, "planar", kind, SIZE);
        let shadowed = (0..floor.len())
            .filter(|&i| floor[i] && Class::of(out.mask.data[i]) == Class::Shadowed)
            .count();
        let s = score(&out.mask, &out.truth.mask, &floor, 0);
        assert_eq!(shadowed, s.pixels, "{kind:?}: the whole floor is unlit");
        assert!(
            s.shadowed_in_truth as f64 >= truth_share * s.pixels as f64,
            "{kind:?}: {s:?}"
        );
    }
}

#[test]
fn light_on_the_receiver_plane() {
    let caster = "[[object]]\nshape = \"box\"\nsize = 1\ntranslate = [0, 2, 0]\n";
    let scene = floor_scene(&point_light([-10.0, 0.0, 0.0]), caster, "");
    let r = receivers(&scene).expect("a defined result");
    assert_eq!(r[0], Receiver::Unlit { object: 0 });
    assert_finite_plan(&scene);
    let plan = (lookup("planar").unwrap().plan)(&scene, &Prepared::new(&scene)).unwrap();
    assert!(
        plan.notes
            .iter()
            .any(|n| n.contains("`floor`") && n.contains("p·l ≤ 0")),
        "{:?}",
        plan.notes
    );
    assert_floor_unlit(&scene, 0.9);
}

#[test]
fn directional_light_parallel_to_the_plane() {
    let light = "[[light]]\ntype = \"directional\"\ndirection = [1, 0, 0]\n";
    let caster = "[[object]]\nshape = \"box\"\nsize = 1\ntranslate = [0, 2, 0]\n";
    let scene = floor_scene(light, caster, "");
    assert_eq!(
        receivers(&scene).expect("a defined result")[0],
        Receiver::Unlit { object: 0 }
    );
    assert_finite_plan(&scene);
    // n·L = (0, 1, 0)·(−1, 0, 0) = 0 exactly: the truth agrees everywhere.
    assert_floor_unlit(&scene, 1.0);
}

#[test]
fn caster_touching_the_plane() {
    let caster = "[[object]]\nname = \"block\"\nshape = \"box\"\nsize = 2\ntranslate = [0, 1, 0]\nreceives = false\n";
    for mode in MODES {
        let scene = floor_scene(&point_light([4.0, 7.0, 1.0]), caster, mode);
        let Receiver::Shadowed {
            casters, matrix, ..
        } = &receivers(&scene).unwrap()[0]
        else {
            panic!("the floor faces the light");
        };
        assert!(matrix.is_finite());
        // The block's bottom face lies in the floor: only its sides and top are kept.
        let ys = casters[0].positions.iter().map(|p| p.y);
        assert!(
            ys.clone().all(|y| y.is_finite() && y > 0.0),
            "bottom face kept"
        );
        assert_finite_plan(&scene);
        assert_floor_matches_truth(mode, &scene, 0);
    }
}

#[test]
fn a_directional_light_casts_what_the_truth_says() {
    let light = "[[light]]\ntype = \"directional\"\ndirection = [0.4, -1, -0.3]\n";
    let caster = "[[object]]\nshape = \"torus\"\nmajor_radius = 1.5\nminor_radius = 0.4\ntranslate = [0, 2, 0]\nrotate = { axis = [1, 0, 0], degrees = 50 }\nreceives = false\n";
    let scene = floor_scene(light, caster, "planar_mode = \"stencil\"");
    assert_floor_matches_truth("directional", &scene, 0);
}

/// A floor and a wall, both flat receivers: each gets its own stencil number and its own
/// shadow, and a curved receiver is named in the notes.
#[test]
fn a_floor_and_a_wall_each_get_their_shadow() {
    let objects = r#"
[[object]]
name = "wall"
shape = "plane"
size = 16
tessellation = 4
translate = [0, 8, -8]
rotate = { axis = [1, 0, 0], degrees = 90 }
casts = false
[[object]]
name = "ball"
shape = "sphere"
radius = 1.2
translate = [0, 2.5, -5]
"#;
    let scene = floor_scene(
        &point_light([1.0, 6.0, 4.0]),
        objects,
        "planar_mode = \"stencil\"",
    );
    let r = receivers(&scene).unwrap();
    let ids: Vec<u8> = r
        .iter()
        .filter_map(|r| match r {
            Receiver::Shadowed { id, .. } => Some(*id),
            _ => None,
        })
        .collect();
    assert_eq!(ids, vec![1, 2]);
    assert_eq!(r[2], Receiver::Curved { object: 2 });
    let plan = (lookup("planar").unwrap().plan)(&scene, &Prepared::new(&scene)).unwrap();
    assert!(
        plan.notes.iter().any(|n| n.contains("`ball` is not flat")),
        "{:?}",
        plan.notes
    );
    for (index, name) in [(0, "floor"), (1, "wall")] {
        let pixels = pixels_of(&scene, index, SIZE);
        let out = run(&scene, "planar", PipelineKind::Emulate, SIZE);
        let s = score(&out.mask, &out.truth.mask, &pixels, 1);
        assert!(s.shadowed_in_truth > 20, "{name}: {s:?}");
        assert_eq!(s.wrong_outside_band, 0, "{name}: {s:?}");
    }
}

#[test]
fn a_sixteen_bit_depth_buffer_has_no_stencil_for_planar() {
    let mut scene = Scene::default_scene();
    scene.shadow.depth = fixedfunc::vocab::DepthBits::D16;
    let err = (lookup("planar").unwrap().plan)(&scene, &Prepared::new(&scene)).unwrap_err();
    assert!(matches!(err, TechniqueError::NeedsStencil { .. }), "{err}");
}

#[test]
fn planar_mode_is_checked_with_the_line_and_the_alternatives() {
    let text = "[shadow]\ntechnique = \"planar\"\nplanar_mode = \"sideways\"\n";
    let err = fixedfunc::scene::Scene::parse(text, std::path::Path::new("t.toml"))
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("t.toml:3") && err.contains("offset") && err.contains("stencil"),
        "{err}"
    );
    let ok =
        projection::scene("[shadow]\nplanar_mode = \"stencil\"\nprojector = \"perspective\"\n");
    assert_eq!(ok.shadow.planar_mode, PlanarMode::Stencil);
}
