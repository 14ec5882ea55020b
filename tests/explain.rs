//! `fixedfunc explain`: the printed frame is the frame `render` draws. The script replays
//! to `render`'s emulated image; the C program, compiled against Mesa's OSMesa, renders
//! `render --pipeline native`'s image on Mesa's library and `render --pipeline emulate`'s
//! on the layer's (3/255 on 99% of pixels); the markdown page carries the figures and the
//! state tables; bad names are refused with the valid ones.

mod support;

#[path = "c/harness.rs"]
mod harness;

use std::path::PathBuf;
use std::process::{Command, Output};

use fixedfunc::vocab::{Named, TechniqueId};
use harness::Library;
use image::RgbaImage;
use support::{assert_images_match, Tolerance};

/// Small images keep the runs short; the map (256², the scene's) shares the framebuffer.
const SIZE: (u32, u32) = (96, 96);

fn size_arg() -> String {
    format!("{}x{}", SIZE.0, SIZE.1)
}

fn work_dir() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("explain");
    std::fs::create_dir_all(&dir).expect("the test folder can be made");
    dir
}

fn fixedfunc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .args(args)
        .output()
        .expect("fixedfunc runs")
}

fn succeed(args: &[&str]) -> Output {
    let out = fixedfunc(args);
    assert!(
        out.status.success(),
        "fixedfunc {}: {}",
        args.join(" "),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// `explain --technique T --format F` (and `options`) written to a file in the work folder.
fn explain_with(technique: &str, format: &str, file: &str, options: &[&str]) -> PathBuf {
    let path = work_dir().join(file);
    let size = size_arg();
    let mut args = vec![
        "explain",
        "--technique",
        technique,
        "--format",
        format,
        "--size",
        &size,
        "--out",
        path.to_str().unwrap(),
    ];
    args.extend_from_slice(options);
    succeed(&args);
    path
}

fn explain(technique: &str, format: &str, file: &str) -> PathBuf {
    explain_with(technique, format, file, &[])
}

/// One frame of `render` on `pipeline` (with `options`), saved as `NAME-PIPELINE.png`.
fn render_with(technique: &str, pipeline: &str, name: &str, options: &[&str]) -> RgbaImage {
    let dir = work_dir();
    let out = dir.join(format!("{name}-render-{pipeline}.png"));
    let mask = dir.join(format!("{name}-render-{pipeline}-mask.png"));
    let size = size_arg();
    let mut args = vec![
        "render",
        "--technique",
        technique,
        "--pipeline",
        pipeline,
        "--size",
        &size,
        "--frames",
        "1",
        "--out",
        out.to_str().unwrap(),
        "--mask",
        mask.to_str().unwrap(),
    ];
    args.extend_from_slice(options);
    succeed(&args);
    image::open(&out).expect("render wrote a PNG").to_rgba8()
}

/// 3/255 per channel on 99% of the pixels.
fn within_3_on_99_percent() -> Tolerance {
    Tolerance {
        per_channel: 3,
        max_bad_pixels: (SIZE.0 * SIZE.1) as usize / 100,
    }
}

/// The image drew something besides the clear colour (a blank frame cannot pass).
fn assert_drawn(name: &str, img: &RgbaImage) {
    let background = img.get_pixel(0, 0).0;
    let drawn = img.pixels().filter(|p| p.0 != background).count();
    assert!(
        drawn > (SIZE.0 * SIZE.1 / 10) as usize,
        "{name}: only {drawn} pixels differ from the background"
    );
}

/// The scene a technique is explained and rendered on here (`None`: the default scene),
/// or `Err` with why it is left out of the replay tests: `accumulate` and
/// `occlusion-textures` need an area light, and the latter's shader programs have no GL 1.x
/// form to replay (`tests/soft_shadows.rs` and `tests/occlusion_textures.rs` cover them);
/// `occluder-planes` needs declared shadow planes, which the F-35 scene has.
fn scene_for(id: TechniqueId) -> Result<Option<&'static str>, &'static str> {
    match id {
        TechniqueId::Accumulate => Err("needs an area light or a sun; tests/soft_shadows.rs"),
        TechniqueId::OcclusionTextures => {
            Err("shader programs, no GL 1.x form; tests/occlusion_textures.rs")
        }
        TechniqueId::OccluderPlanes => Ok(Some(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/assets/f35.toml"
        ))),
        _ => Ok(None),
    }
}

/// `scene_for` as command-line arguments; `None` (saying why) for a technique left out.
fn scene_args(id: TechniqueId) -> Option<Vec<&'static str>> {
    match scene_for(id) {
        Ok(scene) => Some(scene.into_iter().collect()),
        Err(why) => {
            eprintln!("{}: left out: {why}", id.name());
            None
        }
    }
}

/// Whether a technique runs on Mesa's fixed-function path; the reason when it does not
/// (as `compare` skips it).
fn native_skip(id: TechniqueId) -> Option<&'static str> {
    (id == TechniqueId::Multidigit16)
        .then_some("NV_register_combiners has no native path on Mesa (emulated only)")
}

/// The `--size` the script's header asks `replay` for.
fn replay_size(script: &str) -> String {
    let at = script
        .find("replay FILE --size ")
        .expect("the header names replay's size");
    script[at + "replay FILE --size ".len()..]
        .split(|c: char| !(c.is_ascii_digit() || c == 'x'))
        .next()
        .unwrap()
        .to_string()
}

/// The image's corner of a replayed framebuffer (its lower-left `SIZE`, top row first),
/// made opaque as `render` makes its image.
fn corner(full: &RgbaImage) -> RgbaImage {
    let mut img =
        image::imageops::crop_imm(full, 0, full.height() - SIZE.1, SIZE.0, SIZE.1).to_image();
    img.pixels_mut().for_each(|p| p.0[3] = 255);
    img
}

/// `explain --format script` replayed on the emulated path is `render`'s image, for every
/// technique (the replay's framebuffer is the plan's, the image its corner).
#[test]
fn the_script_replays_to_the_image_render_draws() {
    for id in TechniqueId::all() {
        let t = id.name();
        let Some(scene) = scene_args(id) else {
            continue;
        };
        let script = explain_with(t, "script", &format!("{t}.script.c"), &scene);
        let text = std::fs::read_to_string(&script).unwrap();
        assert!(
            text.contains("/* ---- pass 1 of "),
            "{t}: no pass headings:\n{text:.600}"
        );
        let png = work_dir().join(format!("{t}-replay.png"));
        let replay = succeed(&[
            "replay",
            script.to_str().unwrap(),
            "--size",
            &replay_size(&text),
            "--strict",
            "--out",
            png.to_str().unwrap(),
        ]);
        assert!(
            String::from_utf8_lossy(&replay.stdout).contains("draws"),
            "{t}: {}",
            String::from_utf8_lossy(&replay.stdout)
        );
        let replayed = corner(&image::open(&png).unwrap().to_rgba8());
        let rendered = render_with(t, "emulate", t, &scene);
        assert_drawn(t, &rendered);
        assert_images_match(
            &format!("explain-script-{t}"),
            &replayed,
            &rendered,
            within_3_on_99_percent(),
        );
    }
}

/// `explain --format c` compiles against Mesa's OSMesa; on Mesa's library it renders
/// `render --pipeline native`'s image, on the layer's `render --pipeline emulate`'s — for
/// every technique that runs natively. `multidigit16` is skipped on Mesa with the reason,
/// and its program says so and fails there; on the layer it renders as `render` does.
#[test]
fn the_c_program_renders_on_mesa_and_on_the_layer_as_render_does() {
    for id in TechniqueId::all() {
        let t = id.name();
        let Some(scene) = scene_args(id) else {
            continue;
        };
        let source = explain_with(t, "c", &format!("{t}.c"), &scene);
        let exe = work_dir().join(format!("{t}-program"));
        harness::compile(&source, &exe);
        let image = |library: Library| {
            let ppm = work_dir().join(format!("{t}-{library:?}.ppm"));
            harness::run(&exe, library, &[ppm.to_str().unwrap()]);
            harness::read_ppm(&ppm)
        };
        let ours = image(Library::Fixedfunc);
        let emulated = render_with(t, "emulate", t, &scene);
        assert_drawn(t, &emulated);
        assert_images_match(
            &format!("explain-c-{t}-fixedfunc"),
            &ours,
            &emulated,
            within_3_on_99_percent(),
        );
        if let Some(reason) = native_skip(id) {
            eprintln!("{t} on Mesa: skipped: {reason}");
            let out = harness::output(&exe, Library::Mesa, &[]);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{t} on Mesa: {stderr}");
            assert!(
                stderr.contains("no NV_register_combiners"),
                "{t} on Mesa: {stderr}"
            );
            continue;
        }
        let mesa = image(Library::Mesa);
        let native = render_with(t, "native", t, &scene);
        assert_images_match(
            &format!("explain-c-{t}-mesa"),
            &mesa,
            &native,
            within_3_on_99_percent(),
        );
    }
}

/// A depth map the program converts itself (`--readback round`: read as FLOAT, rounded
/// on the CPU) compiles into the program as a helper and renders as `render` does with the
/// same rule, on both libraries.
#[test]
fn a_client_side_depth_conversion_is_part_of_the_program() {
    let options = ["--readback", "round"];
    let source = explain_with("dual8", "c", "dual8-round.c", &options);
    let text = std::fs::read_to_string(&source).unwrap();
    assert!(
        text.contains("static const void *fixedfunc_depth_ubyte_round(const void *depths)")
            && text.contains("fixedfunc_depth_ubyte_round(readback_1)")
            && text.contains("static GLfloat readback_1[65536];"),
        "{text:.3000}"
    );
    let exe = work_dir().join("dual8-round-program");
    harness::compile(&source, &exe);
    for (library, pipeline) in [(Library::Mesa, "native"), (Library::Fixedfunc, "emulate")] {
        let ppm = work_dir().join(format!("dual8-round-{library:?}.ppm"));
        harness::run(&exe, library, &[ppm.to_str().unwrap()]);
        let rendered = render_with("dual8", pipeline, "dual8-round", &options);
        assert_images_match(
            &format!("explain-c-dual8-round-{library:?}"),
            &harness::read_ppm(&ppm),
            &rendered,
            within_3_on_99_percent(),
        );
    }
}

/// The dual8 page gives the map's and the ramp's quantisation and the bias in 8-bit steps,
/// a state table per pass with the comparison's state, and the emulated path's GLSL.
#[test]
fn the_dual8_page_has_its_figures_state_tables_and_glsl() {
    let page = std::fs::read_to_string(explain("dual8", "markdown", "dual8.md")).unwrap();
    for expected in [
        "# `dual8` on the default scene, 96×96",
        "M = ⌊255·z⌋",
        "a step of 1/255",
        "F = ⌊256·r/q⌋",
        "a step of 1/256",
        "3 8-bit steps from the units, enough",
        "### Pass 5 of 5: lit (every frame)",
        "| state | draws 1–3 |",
        "| `GL_DEPTH_FUNC` | **GL_EQUAL** |",
        "| `GL_ALPHA_TEST_FUNC` | **GL_GREATER** |",
        "unit 1: `GL_COMBINE_ALPHA` | **GL_ADD_SIGNED** |",
        "texture 1: `level 0` | 256×256 GL_INTENSITY8 |",
        "#version 330",
    ] {
        assert!(
            page.contains(expected),
            "the dual8 page lacks {expected:?}:\n{page:.4000}"
        );
    }
    // One heading per section: the setup and five passes.
    assert_eq!(page.matches("\n### ").count(), 6, "{page:.3000}");
}

/// Unknown techniques and formats are refused with the valid names.
#[test]
fn bad_names_are_refused_with_the_valid_ones() {
    let out = fixedfunc(&["explain", "--technique", "shadow-volumes"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    for name in TechniqueId::names() {
        assert!(err.contains(name), "the error does not name {name}: {err}");
    }
    let out = fixedfunc(&["explain", "--technique", "dual8", "--format", "pdf"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    for name in ["c", "script", "markdown"] {
        assert!(err.contains(name), "the error does not name {name}: {err}");
    }
}
