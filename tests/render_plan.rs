//! The `none` plan, checked as data (no GL): one pass, one Draw per object, lighting and
//! exactly the scene's lights enabled, no texture unit touched — and every command accepted
//! by the GL 1.x state model, frame after frame.

use std::sync::Arc;

use fixedfunc::ff::{Capability, Command, FixedState, LightParam};
use fixedfunc::scene::{LightKind, Scene};
use fixedfunc::techniques::{self, Plan, Prepared};
use glam::Vec3;

fn plan_of(scene: &Scene) -> (Plan, Prepared) {
    let prepared = Prepared::new(scene);
    let technique = techniques::lookup("none").expect("none is registered");
    let plan = (technique.plan)(scene, &prepared).expect("none plans any scene");
    (plan, prepared)
}

fn enables(plan: &Plan) -> Vec<Capability> {
    plan.frame_commands()
        .filter_map(|c| match c {
            Command::Enable(cap) => Some(*cap),
            _ => None,
        })
        .collect()
}

fn touches_texturing(c: &Command) -> bool {
    matches!(
        c,
        Command::ActiveTexture(_)
            | Command::BindTexture { .. }
            | Command::TexImage(_)
            | Command::TexSubImage2D(_)
            | Command::CopyTexImage2D(_)
            | Command::TexParameter { .. }
            | Command::TexGen { .. }
            | Command::TexEnv(_)
            | Command::TexCoord { .. }
            | Command::Enable(
                Capability::Texture1D | Capability::Texture2D | Capability::TextureGen(_)
            )
    )
}

#[test]
fn default_scene_is_one_lit_pass_with_one_draw_per_object() {
    let scene = Scene::default_scene();
    let (plan, prepared) = plan_of(&scene);
    assert_eq!(plan.passes.len(), 1);

    let on = enables(&plan);
    assert!(on.contains(&Capability::Lighting));
    assert!(on.contains(&Capability::DepthTest));
    let lights: Vec<u8> = on
        .iter()
        .filter_map(|c| match c {
            Capability::Light(i) => Some(*i),
            _ => None,
        })
        .collect();
    let expected: Vec<u8> = (0..scene.lights.len() as u8).collect();
    assert_eq!(lights, expected, "exactly the scene's lights");
    assert!(
        !on.contains(&Capability::Normalize),
        "no transform of the default scene scales"
    );
    assert!(!plan.frame_commands().any(touches_texturing));

    let draws: Vec<&Arc<_>> = plan
        .frame_commands()
        .filter_map(|c| match c {
            Command::Draw(g) => Some(g),
            _ => None,
        })
        .collect();
    assert_eq!(draws.len(), scene.objects.len());
    for (draw, made) in draws.iter().zip(&prepared.objects) {
        assert!(Arc::ptr_eq(draw, made), "geometry is made once and shared");
    }
}

#[test]
fn spot_light_carries_the_scene_cutoff_and_direction() {
    let scene = Scene::default_scene();
    let (plan, _) = plan_of(&scene);
    let LightKind::Spot { cutoff, .. } = scene.lights[0].kind else {
        panic!("the default light is a spot");
    };
    let params: Vec<LightParam> = plan
        .frame_commands()
        .filter_map(|c| match c {
            Command::Light { light: 0, param } => Some(*param),
            _ => None,
        })
        .collect();
    assert!(params.contains(&LightParam::SpotCutoff(cutoff)));
    let view = scene.lights[0].view;
    assert!(params.contains(&LightParam::SpotDirection((view.at - view.eye).normalize())));
    assert!(params.contains(&LightParam::Position(view.eye.extend(1.0))));
}

#[test]
fn a_scene_without_lights_enables_no_lighting() {
    let mut scene = Scene::default_scene();
    scene.lights.clear();
    let (plan, _) = plan_of(&scene);
    assert_eq!(plan.passes.len(), 1);
    let on = enables(&plan);
    assert!(!on.contains(&Capability::Lighting), "{on:?}");
    assert!(!on.iter().any(|c| matches!(c, Capability::Light(_))));
    assert!(!plan
        .frame_commands()
        .any(|c| matches!(c, Command::Light { .. } | Command::Material { .. })));
    let colours = plan
        .frame_commands()
        .filter(|c| matches!(c, Command::Color(_)))
        .count();
    assert_eq!(colours, scene.objects.len(), "unlit objects get glColor");
}

#[test]
fn a_scaled_object_turns_normalize_on() {
    let mut scene = Scene::default_scene();
    scene.objects[1].transform.scale = Vec3::new(1.0, 2.0, 1.0);
    let (plan, _) = plan_of(&scene);
    assert!(enables(&plan).contains(&Capability::Normalize));
}

#[test]
fn the_state_model_accepts_every_frame_and_the_mask_readback() {
    for lights in [true, false] {
        let mut scene = Scene::default_scene();
        if !lights {
            scene.lights.clear();
        }
        let (plan, _) = plan_of(&scene);
        let mut state = FixedState::new();
        for frame in 0..3 {
            for c in plan.frame_commands() {
                assert_eq!(state.apply(c), Ok(()), "frame {frame}: {c:?}");
            }
        }
        assert_eq!(state.apply_all(&plan.mask.commands), Ok(()));
        assert_eq!(state.modelview_matrix(), scene.camera.view());
        assert_eq!(state.error(), None);
    }
}
