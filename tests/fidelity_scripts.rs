//! Every script of `tests/scripts/fidelity` replayed on both pipelines and both headless
//! backends: the model records no GL error, the driver none either, and the emulated image
//! matches the native one within the tolerance the table states for that script (with the
//! reason when it is not exact). A script missing from the table fails the test, so a new
//! case cannot go unreplayed. The same files run through `fixedfunc replay`.

mod fidelity;
mod support;

use std::path::{Path, PathBuf};
use std::process::Command;

use fidelity::{run_both, Frame};
use support::Tolerance;

/// How one script is replayed and compared.
struct Case {
    name: &'static str,
    frame: Frame,
    tolerance: Tolerance,
}

const fn case(name: &'static str, w: u32, h: u32, per_channel: u8, max_bad: usize) -> Case {
    Case {
        name,
        frame: Frame::new(w, h),
        tolerance: Tolerance {
            per_channel,
            max_bad_pixels: max_bad,
        },
    }
}

/// The table. Tolerances are per channel (of 255) and a count of pixels allowed beyond it.
const CASES: [Case; 25] = [
    case("alpha_test_boundaries", 8, 1, 0, 0),
    // GL's own glBlitFramebuffer on both paths (tests/fidelity_framebuffers.rs).
    Case {
        frame: Frame::new(64, 64).with_stencil(),
        ..case("blit_framebuffer", 64, 64, 0, 0)
    },
    // Fixed-point vs fp32 combine arithmetic: 1/255.
    case("combine_bugs_crossbar", 8, 1, 1, 0),
    case("depth_tex_compare", 128, 16, 0, 0),
    // Also the quad of the diagonal tests (`fidelity_clip_planes`, `fidelity_polygon_mode`):
    // unclipped and filled, split v0–v2 on both paths.
    case("four_colour_quad", 32, 32, 1, 0),
    // fp32 fog factors on both paths; 3/255 on 99% as in tests/fidelity_fog.rs.
    case("fog", 64, 32, 3, 20),
    // Pixel rectangles into a framebuffer object smaller than the window: window
    // coordinates are the bound framebuffer's.
    case("fbo_pixel_rectangles", 64, 64, 0, 0),
    // The same llvmpipe rasterises both paths; NEAREST sampling (tests/fidelity_framebuffers.rs).
    case("framebuffer_objects", 64, 32, 1, 0),
    // Mesa 22.3 fails configurations 3 and 4 natively (tests/fidelity_polygon_mode.rs):
    // their outlines, 4 × 61 pixels each, are blue there and white on the emulated path.
    case("polygon_mode_offset", 448, 64, 0, 2 * 4 * 61),
    // glMultiDraw* become one draw per list in the front end, on either path; the last
    // bit of an interpolated colour differs on 7 pixels (1/255).
    case("multi_draw", 48, 32, 1, 0),
    case("polygon_offset_modes", 600, 150, 0, 0),
    case("separate_specular", 64, 32, 0, 0),
    // A list drawn again is drawn indexed, each distinct vertex once, smooth and flat.
    case("shared_vertices", 64, 32, 0, 0),
    Case {
        frame: Frame::new(4, 1).with_stencil(),
        ..case("stencil_wrap", 4, 1, 0, 0)
    },
    case("texdepth", 4, 72, 0, 0),
    // ARB_shadow_ambient is emulated only: the failed compares (144 of the 288 pixels; the
    // fail value stays on texture 1 through all three modes) read 0.4 there, 0 natively.
    case("texdepth_ambient", 4, 72, 0, 144),
    case("texdepth_copied", 4, 72, 0, 0),
    case("texdepth_homogeneous", 4, 72, 0, 0),
    // NEAREST on a checker edge: the last bit of the interpolated coordinate (1%).
    case("texgen_eye_linear", 50, 50, 0, 25),
    case("texgen_eye_plane_1", 16, 16, 0, 0),
    case("texgen_eye_plane_2", 16, 16, 0, 0),
    case("texgen_eye_plane_3", 16, 16, 0, 0),
    case("texgen_object_linear", 50, 50, 0, 25),
    case("texgen_sphere_map", 50, 50, 0, 25),
    // Culled indexed triangles, some drawn with reversed corners (tests/fidelity_winding.rs).
    case("winding", 256, 128, 0, 0),
];

fn scripts() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/scripts/fidelity");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("fidelity scripts")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "c"))
        .collect();
    files.sort();
    files
}

fn case_of(path: &Path) -> &'static Case {
    let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("");
    CASES
        .iter()
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("{name}.c is not in the table of tests/fidelity_scripts.rs"))
}

/// Both paths × EGL and OSMesa: no GL error (asserted inside the harness) and emulate ≈
/// native within the table's tolerance.
#[test]
fn every_fidelity_script_replays_on_both_paths() {
    for path in scripts() {
        let case = case_of(&path);
        let source = std::fs::read_to_string(&path).expect("script");
        for p in run_both(&source, case.frame) {
            support::assert_images_match(
                &format!("replay-{}-{}", case.name, p.backend),
                &p.emulate.image,
                &p.native.image,
                case.tolerance,
            );
        }
    }
}

/// `fixedfunc replay FILE --pipeline emulate|native` runs every script (EGL) and reports
/// no recorded GL error.
#[test]
fn fixedfunc_replay_runs_every_fidelity_script() {
    let out_dir = support::output_dir();
    for path in scripts() {
        let case = case_of(&path);
        for pipeline in ["emulate", "native"] {
            let png = out_dir.join(format!("replay-cli-{}-{pipeline}.png", case.name));
            let size = format!("{}x{}", case.frame.width, case.frame.height);
            let out = Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
                .args(["replay"])
                .arg(&path)
                .args(["--pipeline", pipeline, "--size", &size, "--out"])
                .arg(&png)
                .output()
                .expect("run fixedfunc");
            let stdout = String::from_utf8_lossy(&out.stdout);
            assert!(
                out.status.success(),
                "{} {pipeline}: {}",
                case.name,
                String::from_utf8_lossy(&out.stderr)
            );
            assert!(
                !stdout.contains("GL error"),
                "{} {pipeline}: {stdout}",
                case.name
            );
            let img = image::open(&png).expect("replay image").to_rgba8();
            assert_eq!(img.dimensions(), (case.frame.width, case.frame.height));
        }
    }
}
