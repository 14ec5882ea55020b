//! Kilgard's shadow maps end to end: every technique on both pipelines against each other
//! and against the ray-cast truth, and the behaviours the slides and the notes document —
//! each a named test with its numbers. Images are 192×144 with the default 256² map; error
//! percentages are of the truth's geometry pixels (`metrics`).

use fixedfunc::gpu::Backend;
use fixedfunc::metrics::Mask;
use fixedfunc::render::{self, ImageSize, RemakeMaps, RenderError, RenderOptions, RenderOutcome};
use fixedfunc::scene::{OffsetSetting, Scene};
use fixedfunc::techniques;
use fixedfunc::vocab::{
    DepthBits, MapFilter, PipelineKind, PolygonOffset, ReadbackRule, TechniqueId,
};

const SIZE: ImageSize = ImageSize {
    width: 192,
    height: 144,
};

/// The bias of `steps` 8-bit steps in a 24-bit buffer on llvmpipe, where one polygon-offset
/// unit is two 24-bit steps (notes H7): units = steps · (2²⁴ − 1)/255 / 2.
fn units_for_8bit_steps(steps: f32) -> f32 {
    steps * 16_777_215.0 / 255.0 / 2.0
}

struct Run<'a> {
    technique: &'a str,
    pipeline: PipelineKind,
    offset: Option<(f32, f32)>,
    depth: DepthBits,
    scene: Scene,
    frames: u32,
    remake: RemakeMaps,
}

impl<'a> Run<'a> {
    fn new(technique: &'a str) -> Self {
        Run {
            technique,
            pipeline: PipelineKind::Emulate,
            offset: None,
            depth: DepthBits::D24,
            scene: Scene::default_scene(),
            frames: 1,
            remake: RemakeMaps::WhenMoved,
        }
    }
    fn on(mut self, pipeline: PipelineKind) -> Self {
        self.pipeline = pipeline;
        self
    }
    fn offset(mut self, factor: f32, units: f32) -> Self {
        self.offset = Some((factor, units));
        self
    }
    fn depth(mut self, depth: DepthBits) -> Self {
        self.depth = depth;
        self
    }
    fn scene(mut self, scene: Scene) -> Self {
        self.scene = scene;
        self
    }
    fn try_render(mut self) -> Result<RenderOutcome, RenderError> {
        self.scene.shadow.polygon_offset = OffsetSetting::command_line(
            self.offset
                .map(|(factor, units)| PolygonOffset { factor, units }),
        );
        self.scene.shadow.depth = self.depth;
        let options = RenderOptions {
            backend: Backend::Egl,
            pipeline: self.pipeline,
            technique: Some(techniques::parse_name(self.technique).expect("a technique")),
            size: Some(SIZE),
            frames: self.frames,
            remake_maps: self.remake,
            ..RenderOptions::default()
        };
        render::render(&self.scene, &options)
    }
    fn render(self) -> RenderOutcome {
        let name = format!("{} on {:?}", self.technique, self.pipeline);
        self.try_render()
            .unwrap_or_else(|e| panic!("{name} failed: {e}"))
    }
}

/// Geometry pixels (of the truth) where two masks disagree, and how many geometry pixels
/// there are.
fn differing(a: &RenderOutcome, b: &RenderOutcome) -> (u64, u64) {
    let truth: &Mask = &a.truth.mask;
    let (mut geometry, mut differ) = (0u64, 0u64);
    for ((t, x), y) in truth.data.iter().zip(&a.mask.data).zip(&b.mask.data) {
        if *t != fixedfunc::metrics::BACKGROUND {
            geometry += 1;
            differ += u64::from(x != y);
        }
    }
    (differ, geometry)
}

/// Percentage of the truth's geometry pixels where two masks disagree.
fn disagreement(a: &RenderOutcome, b: &RenderOutcome) -> f64 {
    let (differ, geometry) = differing(a, b);
    100.0 * differ as f64 / geometry as f64
}

/// The false-shadow share of truth-lit pixels, in percent.
fn false_shadow_percent(o: &RenderOutcome) -> f64 {
    let lit = o
        .truth
        .mask
        .data
        .iter()
        .filter(|&&v| v == fixedfunc::metrics::LIT)
        .count();
    100.0 * o.metrics.all.false_shadow as f64 / lit as f64
}

const TECHNIQUES_ON_BOTH: [&str; 4] = ["depth-compare", "dual8", "linear8", "multidigit16-combine"];

#[test]
fn every_technique_agrees_between_the_emulated_and_the_native_path() {
    // Exact: the same mask and the same image, pixel for pixel. Measured (Mesa 22.3.6
    // llvmpipe, 192×144, 10 693 geometry pixels, offset (1, three 8-bit steps)): 0 mask
    // pixels and 0 image pixels differ for each of the four, and the error against the
    // truth is the same figure on both paths (0.888 %, 0.804 %, 5.714 %, 0.888 %). Both
    // paths rasterise the same triangles with the same depths and compare the same texels;
    // a difference here is a bug of one path, not a tolerance.
    let units = units_for_8bit_steps(3.0);
    for technique in TECHNIQUES_ON_BOTH {
        let emulate = Run::new(technique).offset(1.0, units).render();
        let native = Run::new(technique)
            .offset(1.0, units)
            .on(PipelineKind::Native)
            .render();
        let (d, geometry) = differing(&emulate, &native);
        assert_eq!(
            d, 0,
            "{technique}: masks differ on {d} of {geometry} geometry pixels"
        );
        let images = emulate
            .image
            .pixels()
            .zip(native.image.pixels())
            .filter(|(a, b)| a != b)
            .count();
        assert_eq!(images, 0, "{technique}: images differ on {images} pixels");
        assert_eq!(
            emulate.metrics.all, native.metrics.all,
            "{technique}: the figures against the truth differ"
        );
    }
}

#[test]
fn register_combiners_and_arb_combine_make_the_same_16_bit_comparison() {
    // multidigit16 has no native path (NV_register_combiners); its oracle is the same
    // comparison done with ARB combine + DOT3 + stencil, on Mesa's native path.
    let units = 256.0;
    let combiners = Run::new("multidigit16").offset(1.0, units).render();
    let combine = Run::new("multidigit16-combine")
        .offset(1.0, units)
        .on(PipelineKind::Native)
        .render();
    // Exact. Measured (Mesa 22.3.6 llvmpipe): 0 of 10 693 geometry pixels differ (and the
    // images are identical too): both make the same two-digit decision on the same map.
    let (d, geometry) = differing(&combiners, &combine);
    assert_eq!(d, 0, "masks differ on {d} of {geometry} geometry pixels");
}

#[test]
fn multidigit16_is_refused_by_the_native_path_with_the_reason() {
    let err = Run::new("multidigit16")
        .on(PipelineKind::Native)
        .try_render()
        .expect_err("the native path has no register combiners");
    assert!(err.to_string().contains("NV_register_combiners"), "{err}");
}

#[test]
fn each_technique_against_the_truth_at_a_well_chosen_bias() {
    // (technique, factor, units, stated maximum error % of geometry pixels). The bias is
    // each technique's own: 24-bit units for the depth maps, three 8-bit steps for dual8
    // (two clear steps between map and ramp, see below), two ramp steps for linear8.
    let cases = [
        ("depth-compare", 1.0, 4.0, 1.5),
        ("dual8", 1.0, units_for_8bit_steps(3.0), 1.5),
        ("linear8", 1.0, 4.0, 1.5),
        ("multidigit16", 1.0, 256.0, 1.5),
        ("multidigit16-combine", 1.0, 256.0, 1.5),
    ];
    for (technique, factor, units, max) in cases {
        let o = Run::new(technique).offset(factor, units).render();
        let e = o.metrics.all.wrong_percent;
        eprintln!("{technique} ({factor}, {units}): {e:.2}%");
        assert!(
            e <= max,
            "{technique}: {e:.2}% wrong, stated maximum {max}%"
        );
        assert!(o.metrics.all.coverage == 0, "{technique}: coverage errors");
    }
}

#[test]
fn dual8_at_kilgards_usual_offset_shadows_nearly_every_lit_surface() {
    // (1, 4) on a 24-bit light buffer: the map truncates to ⌊255·z⌋, the ramp floors at
    // ⌊256·s⌋ ≥ the map, the ADD_SIGNED tie is shadowed — acne everywhere.
    let o = Run::new("dual8").offset(1.0, 4.0).render();
    let f = false_shadow_percent(&o);
    assert!(f >= 85.0, "only {f:.1}% of truth-lit pixels shadowed");
    // depth-compare with the same offset is fine.
    let dc = Run::new("depth-compare").offset(1.0, 4.0).render();
    assert!(false_shadow_percent(&dc) < 2.0);
}

#[test]
fn dual8_needs_two_clear_8bit_steps_between_map_and_ramp() {
    // M = ⌊255·(z + b)⌋, F = ⌊256·z⌋ ≤ ⌊255·z⌋ + 1; the alpha test passes reliably only for
    // M − F ≥ 2 (a 1-step lead is lost to the unorm8 rounding of ½ + 1/255 — notes H1), so
    // the map needs b = 3 steps: then its shadows match depth-compare's with that offset.
    let two = units_for_8bit_steps(2.0);
    let three = units_for_8bit_steps(3.0);
    let dual_two = Run::new("dual8").offset(1.0, two).render();
    let dual_three = Run::new("dual8").offset(1.0, three).render();
    let reference = Run::new("depth-compare").offset(1.0, three).render();
    let at_two = false_shadow_percent(&dual_two);
    assert!(at_two >= 5.0, "two steps: only {at_two:.2}% acne");
    let d = disagreement(&dual_three, &reference);
    assert!(
        d <= 1.0,
        "three steps: differs from depth-compare on {d:.2}%"
    );
}

#[test]
fn a_near_light_plane_breaks_8_bit_maps_where_multidigit16_keeps_the_shadows() {
    // The near-plane scene with the light's near plane at 0.1 and far at 100: every
    // receiver's window depth is above 254/255, so the 8-bit map is 255 everywhere and the
    // ramp ties it: everything shadowed. 16 bits keep the shadows.
    let mut scene = Scene::load(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/near-plane.toml"
    )))
    .expect("near-plane scene");
    if let fixedfunc::scene::Projection::Perspective { ref mut near, .. } =
        scene.lights[0].view.projection
    {
        *near = 0.1;
    }
    let run = |t| Run::new(t).scene(scene.clone()).offset(1.0, 256.0).render();
    let dual = run("dual8");
    let digits = run("multidigit16");
    let reference = run("depth-compare");
    let d8 = false_shadow_percent(&dual);
    assert!(d8 >= 80.0, "dual8 shadows only {d8:.1}% of lit pixels");
    let m16 = digits.metrics.all.wrong_percent;
    assert!(m16 <= 1.5, "multidigit16 {m16:.2}% wrong");
    let d = disagreement(&digits, &reference);
    assert!(d <= 0.5, "multidigit16 vs depth-compare: {d:.2}%");
}

#[test]
fn depth_bits_change_the_required_offset_units_as_the_resolvable_difference_says() {
    // o = m·factor + r·units: r is 2⁸× larger at 16 bits than at 24, so 16-bit units do the
    // work of 256 24-bit units; D32F's r = 2^(e − 23) is half of llvmpipe's 24-bit step for
    // depths in [½, 1), so it needs twice the units. Compared: acne (false shadows) with
    // factor 0, which only the units can cure — equal within 2% of each other.
    let acne = |depth, units: f32| {
        Run::new("depth-compare")
            .offset(0.0, units)
            .depth(depth)
            .render()
            .metrics
            .all
            .false_shadow as f64
    };
    let close = |a: f64, b: f64, what: &str| {
        assert!(
            (a - b).abs() <= 0.02 * a.max(b) + 5.0,
            "{what}: {a} vs {b} false-shadow pixels"
        );
    };
    for units in [4.0, 16.0] {
        let d16 = acne(DepthBits::D16, units);
        let d24 = acne(DepthBits::D24, 256.0 * units);
        close(
            d16,
            d24,
            &format!("D16 {units} units vs D24 {}", 256.0 * units),
        );
        let d24_small = acne(DepthBits::D24, units);
        assert!(d24_small > d16 * 1.1, "24 bits need more units than 16");
    }
    let d24 = acne(DepthBits::D24, 4096.0);
    let d32 = acne(DepthBits::D32F, 8192.0);
    close(d24, d32, "D24 4096 units vs D32F 8192");
}

#[test]
fn maps_are_made_once_on_a_static_scene_unless_asked_every_frame() {
    let mut run = Run::new("dual8").offset(1.0, 4.0);
    run.frames = 4;
    let once = run.render();
    assert_eq!(once.maps_made, 1);
    // Setup uploads the ramp; the map is uploaded once.
    assert_eq!(once.counters.texture_uploads, 2);
    let mut run = Run::new("dual8").offset(1.0, 4.0);
    run.frames = 4;
    run.remake = RemakeMaps::Always;
    let every = run.render();
    assert_eq!(every.maps_made, 4);
    assert_eq!(every.counters.texture_uploads, 5);
    // The pictures do not depend on how often the map is made.
    assert_eq!(once.image, every.image);
    let none = Run::new("none").render();
    assert_eq!(none.maps_made, 0);
}

#[test]
fn the_readback_rule_is_the_drivers_or_the_programs_own() {
    // Mesa truncates UNSIGNED_BYTE depth (notes H4): reading FLOAT and truncating on the CPU
    // gives the same map, bit for bit; rounding lifts about half the texels by one step.
    let units = units_for_8bit_steps(3.0);
    let with = |rule| {
        let mut scene = Scene::default_scene();
        scene.shadow.readback = rule;
        let mut run = Run::new("dual8").offset(1.0, units).scene(scene);
        run.offset = Some((1.0, units));
        run.render()
    };
    let driver = with(ReadbackRule::Driver);
    let truncate = with(ReadbackRule::Cpu(fixedfunc::vocab::DepthRule::Truncate));
    let round = with(ReadbackRule::Cpu(fixedfunc::vocab::DepthRule::Round));
    assert_eq!(driver.mask, truncate.mask, "Mesa's byte readback truncates");
    assert_eq!(driver.image, truncate.image);
    assert_ne!(driver.mask, round.mask, "rounding changes the 8-bit map");
}

#[test]
fn linear_filtering_of_the_depth_texture_is_percentage_closer() {
    // LINEAR on a compared depth texture blends the four nearest compare results: the
    // shadow's edge gets partial values the NEAREST map never produces. Both paths agree,
    // and the mask (lit iff at least half lit) stays as accurate.
    let with = |filter, pipeline| {
        let mut scene = Scene::default_scene();
        scene.shadow.filter = filter;
        Run::new("depth-compare")
            .offset(1.0, 4.0)
            .scene(scene)
            .on(pipeline)
            .render()
    };
    let nearest = with(MapFilter::Nearest, PipelineKind::Emulate);
    let linear = with(MapFilter::Linear, PipelineKind::Emulate);
    let native = with(MapFilter::Linear, PipelineKind::Native);
    // Pixels of the ground strictly between its dim and lit colours: the ground is grey,
    // so count grey levels that neither image has in common with NEAREST.
    let levels = |o: &RenderOutcome| {
        let mut v: Vec<u8> = o
            .image
            .pixels()
            .filter(|p| p[0] == p[1] && p[1] == p[2])
            .map(|p| p[0])
            .collect();
        v.sort_unstable();
        v.dedup();
        v.len()
    };
    assert!(
        levels(&linear) > levels(&nearest) + 10,
        "LINEAR {} grey levels vs NEAREST {}",
        levels(&linear),
        levels(&nearest)
    );
    assert!(linear.metrics.all.wrong_percent <= 1.5);
    // Exact between the paths. Measured: 0 of 10 693 mask pixels and 0 image pixels differ
    // (both let the sampler blend the four compare results; 74 pixels, 0.69 %, wrong against
    // the truth on each).
    let (d, geometry) = differing(&linear, &native);
    assert_eq!(
        d, 0,
        "LINEAR masks differ on {d} of {geometry} pixels between paths"
    );
    assert_eq!(
        linear.image, native.image,
        "LINEAR images differ between paths"
    );
}

#[test]
fn maps_are_made_again_only_when_the_light_moves() {
    // Four frames with the camera turning: the map passes are the same every frame, so the
    // map is made once; with the light turning, every frame's map is stale. Either way the
    // last frame's mask is judged against the truth of the last frame's scene.
    use fixedfunc::render::{Orbit, OrbitTarget};
    let orbit = |target| {
        let mut scene = Scene::default_scene();
        scene.shadow.polygon_offset = OffsetSetting::command_line(Some(PolygonOffset {
            factor: 1.0,
            units: 4.0,
        }));
        render::render(
            &scene,
            &RenderOptions {
                technique: Some(TechniqueId::DepthCompare),
                size: Some(SIZE),
                frames: 4,
                orbit: Some(Orbit {
                    target,
                    degrees_per_frame: 10.0,
                }),
                ..RenderOptions::default()
            },
        )
        .expect("render")
    };
    let still = Run::new("depth-compare").offset(1.0, 4.0).render();
    let camera = orbit(OrbitTarget::Camera);
    let light = orbit(OrbitTarget::Light);
    assert_eq!(camera.maps_made, 1);
    assert_eq!(light.maps_made, 4);
    assert_ne!(camera.image, still.image, "the camera moved");
    assert_ne!(
        light.truth.mask, still.truth.mask,
        "the truth follows the light"
    );
    for o in [&camera, &light] {
        let e = o.metrics.all.wrong_percent;
        assert!(e <= 2.0, "{e:.2}% wrong after the motion");
    }
}
