//! The per-object error split (`metrics::per_object`, causes from `truth::shadow_causes`)
//! on real renders: every object that shows gets its line, the objects' counts add up to
//! the render's totals exactly, and a receiver that cannot shadow itself (the ground
//! plane) has no self-shadow while the shadow cast on it is counted as from others.

use fixedfunc::render::{render, ImageSize, RenderOptions};
use fixedfunc::scene::Scene;
use fixedfunc::vocab::{PipelineKind, TechniqueId};

#[test]
fn objects_add_up_to_the_render_totals() {
    let scene = Scene::default_scene();
    for technique in [TechniqueId::DepthCompare, TechniqueId::Projective] {
        let options = RenderOptions {
            pipeline: PipelineKind::Emulate,
            technique: Some(technique),
            size: Some(ImageSize {
                width: 192,
                height: 144,
            }),
            frames: 1,
            ..RenderOptions::default()
        };
        let outcome = render(&scene, &options).unwrap_or_else(|e| panic!("{technique}: {e}"));
        let names: Vec<String> = outcome
            .objects
            .iter()
            .map(|e| fixedfunc::render::object_name(&scene, e.object))
            .collect();
        assert_eq!(names, ["ground", "sphere", "torus"], "{technique}");
        let wrong: u64 = outcome
            .objects
            .iter()
            .map(|e| e.lit.wrong + e.self_shadow().wrong + e.other_occluder.wrong)
            .sum();
        let pixels: u64 = outcome.objects.iter().map(|e| e.pixels()).sum();
        let all = outcome.metrics.all;
        assert_eq!((wrong, pixels), (all.wrong, all.pixels), "{technique}");
        let ground = &outcome.objects[0];
        assert_eq!(ground.self_shadow().pixels, 0, "{technique}");
        assert!(
            ground.other_occluder.pixels > 100,
            "{technique}: {ground:?}"
        );
        // The sphere's unlit half: attached shadow, its own.
        assert!(outcome.objects[1].faces_away.pixels > 50, "{technique}");
    }
}
