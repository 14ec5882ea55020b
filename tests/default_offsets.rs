//! Every shadow-map technique renders the default scene with its own default polygon
//! offset when neither the scene nor the command line gives one (`vocab::default_offset`),
//! and gets the error the README's technique table documents — not acne; `--offset none`
//! still shows the acne. Real EGL contexts (llvmpipe), the default scene at its own size
//! (512²), one frame, every depth format the technique supports.
//!
//! Tolerance: the README gives 0.72–0.87% at 24 bits; a technique passes under 1.5%, and
//! acne is over 10% (it is 46% for `depth-compare`).

use fixedfunc::gpu::Backend;
use fixedfunc::render::{render, RenderOptions};
use fixedfunc::scene::{OffsetSetting, Scene};
use fixedfunc::vocab::{default_offset, DepthBits, OffsetSource, PipelineKind, TechniqueId};

const SHADOW_MAP_TECHNIQUES: [TechniqueId; 5] = [
    TechniqueId::DepthCompare,
    TechniqueId::Dual8,
    TechniqueId::Linear8,
    TechniqueId::Multidigit16,
    TechniqueId::Multidigit16Combine,
];

fn options(technique: TechniqueId) -> RenderOptions {
    RenderOptions {
        backend: Backend::Egl,
        pipeline: PipelineKind::Emulate,
        technique: Some(technique),
        frames: 1,
        ..RenderOptions::default()
    }
}

#[test]
fn each_shadow_map_technique_renders_the_default_scene_right_with_its_default_offset() {
    for technique in SHADOW_MAP_TECHNIQUES {
        for depth in DepthBits::ALL {
            // The multi-digit maps need stencil, which 16-bit buffers lack.
            let digits = matches!(
                technique,
                TechniqueId::Multidigit16 | TechniqueId::Multidigit16Combine
            );
            if digits && depth == DepthBits::D16 {
                continue;
            }
            let mut scene = Scene::default_scene();
            scene.shadow.depth = depth;
            assert_eq!(scene.shadow.polygon_offset, OffsetSetting::TechniqueDefault);
            let outcome = render(&scene, &options(technique)).expect("renders");
            assert_eq!(outcome.offset, default_offset(technique, depth));
            assert_eq!(outcome.offset_source, OffsetSource::TechniqueDefault);
            let error = outcome.metrics.all.wrong_percent;
            assert!(
                error < 1.5,
                "{technique} at {} bits with {:?}: {error:.2}% wrong",
                depth.bits(),
                outcome.offset
            );
            let line = outcome.figures().to_string();
            assert!(line.contains("(technique default)"), "{line}");
        }
    }
}

#[test]
fn no_offset_given_on_purpose_shows_the_acne() {
    let mut scene = Scene::default_scene();
    scene.shadow.polygon_offset = OffsetSetting::command_line(None);
    let outcome = render(&scene, &options(TechniqueId::DepthCompare)).expect("renders");
    assert_eq!(outcome.offset, None);
    assert_eq!(outcome.offset_source, OffsetSource::CommandLine);
    let m = outcome.metrics.all;
    assert!(
        m.wrong_percent > 10.0 && m.false_shadow > 10 * m.missed_shadow,
        "acne is false shadow: {m:?}"
    );
    assert!(outcome
        .figures()
        .to_string()
        .contains("offset none (command line)"));
}
