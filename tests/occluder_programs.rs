//! `occluder-planes`' program forms (`[shadow] program = "coleman" | "generic"`) on real
//! contexts (EGL, llvmpipe, emulated pipeline): their masks against each other and against
//! the fixed-function form, and Coleman's refusal off the F-35.
//!
//! Tolerances, stated per test (mask pixels of a different class, out of 256² = 65 536):
//! - "coleman" against "generic" on `assets/f35.toml`: at most 0.1% (65 pixels);
//! - each against the fixed-function form on the emulated path, on `assets/f35.toml`, on
//!   `assets/teapot-planes.toml` (generic) and on the F-35 under a point light (generic):
//!   at most 0.5% (327 pixels). The fixed-function form filters the behind-the-plane test
//!   over a ramp of 10⁻⁴ of the plane (a 2-slice 3D texture) and looks the occluder up
//!   through 8-bit texgen'd coordinates; the programs test s_I > 0 sharply in float: they
//!   part only along shadow edges.
//!
//! Measured (Mesa llvmpipe, EGL): F-35 coleman vs generic 14 pixels (0.021%), coleman vs
//! fixed-function 14, generic vs fixed-function 0; teapot generic vs fixed-function 1; F-35
//! under a point light generic vs fixed-function 11. Each test prints its figures
//! (`--nocapture`).

mod projection;
mod support;

use fixedfunc::metrics::Mask;
use fixedfunc::render::{render, ImageSize, RenderOptions};
use fixedfunc::scene::{LightKind, OccluderProgram, Scene};
use fixedfunc::techniques::{lookup, parse_name, Prepared, TechniqueError};
use fixedfunc::vocab::PipelineKind;
use glam::Vec3;
use projection::{mask_difference, run, shadowed};
use std::path::Path;

const SIZE: ImageSize = ImageSize {
    width: 256,
    height: 256,
};
const PIXELS: usize = (SIZE.width * SIZE.height) as usize;

/// Coleman against generic: 0.1% of the pixels.
const PROGRAMS_AGREE: usize = PIXELS / 1000;
/// A program form against the fixed-function form: 0.5% of the pixels.
const FORMS_AGREE: usize = PIXELS / 200;

fn asset(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("assets")
        .join(name);
    Scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

fn with_program(scene: &Scene, program: OccluderProgram) -> Scene {
    let mut s = scene.clone();
    s.shadow.occluder_program = program;
    s
}

/// The mask of `program` on the emulated path.
fn mask(scene: &Scene, program: OccluderProgram) -> Mask {
    run(
        &with_program(scene, program),
        "occluder-planes",
        PipelineKind::Emulate,
        SIZE,
    )
    .mask
}

/// Pixels of a different class between `a` and `b`, printed, and at most `allowed`.
fn assert_masks_agree(what: &str, a: &Mask, b: &Mask, allowed: usize) {
    let differ = mask_difference(a, b);
    eprintln!(
        "{what}: {differ} of {PIXELS} mask pixels differ ({:.3}%); shadowed {} vs {}",
        100.0 * differ as f64 / PIXELS as f64,
        shadowed(a),
        shadowed(b)
    );
    assert!(
        differ <= allowed,
        "{what}: {differ} > {allowed} pixels differ"
    );
}

#[test]
fn coleman_generic_and_fixed_function_draw_the_same_f35_mask() {
    let f35 = asset("f35.toml");
    let fixed = mask(&f35, OccluderProgram::FixedFunction);
    let coleman = mask(&f35, OccluderProgram::Coleman);
    let generic = mask(&f35, OccluderProgram::Generic);
    // Thousands of shadowed pixels: the aircraft on itself and on the ground.
    assert!(shadowed(&fixed) > PIXELS / 50, "{}", shadowed(&fixed));
    assert_masks_agree("f35 coleman vs generic", &coleman, &generic, PROGRAMS_AGREE);
    assert_masks_agree(
        "f35 coleman vs fixed-function",
        &coleman,
        &fixed,
        FORMS_AGREE,
    );
    assert_masks_agree(
        "f35 generic vs fixed-function",
        &generic,
        &fixed,
        FORMS_AGREE,
    );
}

#[test]
fn generic_draws_the_teapots_eight_planes_as_the_fixed_function_form() {
    let teapot = asset("teapot-planes.toml");
    let fixed = mask(&teapot, OccluderProgram::FixedFunction);
    let generic = mask(&teapot, OccluderProgram::Generic);
    assert!(shadowed(&fixed) > PIXELS / 1000, "{}", shadowed(&fixed));
    assert_masks_agree(
        "teapot generic vs fixed-function",
        &generic,
        &fixed,
        FORMS_AGREE,
    );
}

/// The F-35 under a point light above and beside it: the ray goes from each point towards
/// the light's position (the fixed-function form through the texture matrix).
#[test]
fn generic_follows_a_point_light_as_the_fixed_function_form() {
    let mut f35 = asset("f35.toml");
    let light = &mut f35.lights[0];
    light.kind = LightKind::Point;
    light.view.eye = Vec3::new(-9.0, 24.0, 6.0);
    let fixed = mask(&f35, OccluderProgram::FixedFunction);
    let generic = mask(&f35, OccluderProgram::Generic);
    assert!(shadowed(&fixed) > PIXELS / 50, "{}", shadowed(&fixed));
    assert_masks_agree(
        "f35 point light generic vs fixed-function",
        &generic,
        &fixed,
        FORMS_AGREE,
    );
    // Coleman's shaders take the light as a direction: refused, generic named.
    let err = plan_error(&with_program(&f35, OccluderProgram::Coleman));
    assert!(
        err.contains("point light") && err.contains("generic"),
        "{err}"
    );
}

fn plan_error(scene: &Scene) -> String {
    let plan = lookup("occluder-planes").expect("a technique").plan;
    match plan(scene, &Prepared::new(scene)) {
        Ok(_) => panic!("planned"),
        Err(e) => {
            assert!(matches!(e, TechniqueError::ColemanDoesNotFit { .. }), "{e}");
            e.to_string()
        }
    }
}

#[test]
fn coleman_is_refused_off_the_f35_with_what_to_use_instead() {
    let teapot = with_program(&asset("teapot-planes.toml"), OccluderProgram::Coleman);
    let err = plan_error(&teapot);
    assert!(
        err.contains("program = \"coleman\"")
            && err.contains("not `shape = \"aircraft\", layout = \"f35\"`")
            && err.contains("program = \"generic\""),
        "{err}"
    );
}

/// The native pipeline has no programs: the render fails (compare and studies count the
/// form as not applicable there).
#[test]
fn the_native_pipeline_refuses_the_program_forms() {
    let f35 = with_program(&asset("f35.toml"), OccluderProgram::Generic);
    let options = RenderOptions {
        pipeline: PipelineKind::Native,
        technique: Some(parse_name("occluder-planes").expect("a technique")),
        size: Some(ImageSize {
            width: 64,
            height: 64,
        }),
        frames: 1,
        ..RenderOptions::default()
    };
    let Err(err) = render(&f35, &options) else {
        panic!("the native pipeline ran a program");
    };
    assert!(err.to_string().to_lowercase().contains("program"), "{err}");
}
