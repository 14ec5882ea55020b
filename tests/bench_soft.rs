//! What the soft benchmark promises besides time, on a tiny run (128² image, 2 frames):
//! every entry becomes a row or a skipped row with a reason; a measured row has positive
//! times and visibility errors that are finite fractions of the light; a configuration the
//! technique refuses is skipped, not fatal; a row shared by two axes is reported in both.

use fixedfunc::bench::soft::{
    measure, occlusion, Axis, Case, Entry, Knobs, SceneId, Step, BASE_COMBINE, OCCLUSION_BASE,
};
use fixedfunc::scene::Prefilter;
use fixedfunc::vocab::TechniqueId;

#[test]
fn a_tiny_soft_run_gives_rows_with_times_and_visibility_errors() {
    let entry = |axis, scene, knobs| Entry {
        axis,
        case: Case { scene, knobs },
    };
    // A refused configuration: more renders than the accumulation buffer's precision
    // allows (`ShadowSettings::MAX_LIGHT_SAMPLES`).
    let refused = Knobs::Accumulate { light_samples: 300 };
    let entries = [
        entry(Axis::Slices, SceneId::SOFT, OCCLUSION_BASE),
        entry(Axis::LightSize, SceneId::SOFT, OCCLUSION_BASE),
        entry(
            Axis::LightSize,
            SceneId::Soft { light_scale: 2.0 },
            Knobs::Accumulate { light_samples: 4 },
        ),
        entry(Axis::LightSize, SceneId::SOFT, refused),
    ];
    let mut steps = Vec::new();
    let (rows, skipped) = measure(&entries, 128, 1, |s| steps.push(s)).expect("the group runs");
    // Two scenes: a truth and two rounds (cold + 1 steady) each.
    assert_eq!(steps.len(), 2 * 3, "{steps:?}");
    assert!(matches!(steps[0], Step::Truth { .. }));

    assert_eq!(rows.len(), 3, "{rows:#?}\nskipped: {skipped:#?}");
    for r in &rows {
        assert!(r.cold_ms > 0.0 && r.frame.min > 0.0, "{r:?}");
        assert!(r.frame.min <= r.frame.median && r.frame.median <= r.frame.max);
        assert_eq!(r.frame.samples, 1);
        let v = &r.visibility;
        assert!(v.rmse.is_finite() && (0.0..=1.0).contains(&v.rmse), "{v:?}");
        assert!(
            (0.0..=1.0).contains(&v.max_abs) && v.rmse <= v.max_abs,
            "{v:?}"
        );
        assert!(v.pixels > 0);
        // The soft scene's casters have penumbrae of every width: the truth sees them.
        let p = v.penumbra_rmse.expect("a penumbra");
        assert!(p.is_finite() && (0.0..=1.0).contains(&p), "{v:?}");
    }
    // The shared configuration was rendered once and reported on both axes.
    let shared: Vec<_> = rows
        .iter()
        .filter(|r| r.setting == OCCLUSION_BASE)
        .collect();
    assert_eq!(shared.len(), 2);
    assert_eq!(shared[0].frame, shared[1].frame);
    assert_eq!(shared[0].technique, TechniqueId::OcclusionTextures);
    let accumulate = rows
        .iter()
        .find(|r| r.technique == TechniqueId::Accumulate)
        .expect("the accumulate row");
    assert_eq!(accumulate.scene, SceneId::Soft { light_scale: 2.0 });
    // A 4-sample accumulation is a coarse soft shadow, but a soft shadow: well within the
    // hard mask's error, and not a blank image.
    assert!(accumulate.visibility.rmse < 0.2, "{accumulate:?}");

    // The JSON rows (`bench --only soft --json`) name the scene and the keys as scene files do.
    let json = serde_json::to_value(shared[0]).expect("a row serialises");
    assert_eq!(json["scene"]["scene"], "soft");
    assert_eq!(json["technique"], "occlusion-textures");
    assert_eq!(json["setting"]["prefilter"], "nbuffers");
    assert_eq!(json["setting"]["combine"], "probabilistic");
    assert_eq!(json["setting"]["slices"], 16);
    assert!(json["visibility"]["rmse"].is_number());

    assert_eq!(skipped.len(), 1, "{skipped:#?}");
    assert_eq!(skipped[0].setting, refused);
    assert!(skipped[0].reason.contains("300"), "{}", skipped[0].reason);
}

#[test]
fn the_summed_area_table_is_a_row_or_a_reason() {
    let knobs = occlusion(16, 64, Prefilter::Sat, BASE_COMBINE);
    let entries = [Entry {
        axis: Axis::Prefilter,
        case: Case {
            scene: SceneId::SOFT,
            knobs,
        },
    }];
    let (rows, skipped) = measure(&entries, 64, 1, |_| {}).expect("the group runs");
    assert_eq!(rows.len() + skipped.len(), 1);
    if let Some(s) = skipped.first() {
        assert!(s.reason.contains("sat"), "{}", s.reason);
    }
}
