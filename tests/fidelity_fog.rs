//! Fog (GL 1.5 §3.10) on the emulated path against Mesa's native fixed-function fog, on
//! both headless backends.
//!
//! - `fog.c`: LINEAR, EXP and EXP2 over receding textured quads, then LINEAR lines and
//!   points. Tolerance 3/255 per channel on ≥ 99% of the pixels (piglit's 3/2^bits):
//!   applying fog before the texture (MODULATE by grey 128) instead of after it moves the
//!   fogged pixels by (1 − f)·C_f/2 — half the fog colour where f = 0, 127/255 on blue —
//!   and fails it; so do a wrong
//!   mode formula or a per-vertex factor. `Precision::Fixed8` is held to the same bound.
//! - The distance rule: with FOG_COORDINATE_SOURCE = FRAGMENT_DEPTH Mesa fogs by |z_eye|
//!   (`ffvertex_prog.c`, FDM_EYE_PLANE_ABS), measured here: a quad at z_eye = −10 spanning
//!   the whole view under LINEAR 0…20 is fogged by exactly f = ½ at its centre and at its
//!   corners, where the radial distance √(x² + y² + z²) would give f ≈ 0.29.

mod fidelity;
mod support;

use fidelity::{compare, probe_rgb, run_both, script_file, Frame};
use fixedfunc::vocab::{PipelineKind, Precision};
use support::Tolerance;

const FRAME: Frame = Frame::new(64, 32);

#[test]
fn fog_modes_match_native_on_quads_lines_and_points() {
    let tol = Tolerance {
        per_channel: 3,
        max_bad_pixels: (FRAME.width * FRAME.height / 100) as usize,
    };
    let pairs = compare("fog", &script_file("fog"), FRAME, tol);
    // Precision::Fixed8 fogs the 0..=255 stage values and rounds to the nearest integer:
    // the same tolerance against Mesa.
    let fixed8 = fidelity::run_one(
        PipelineKind::Emulate,
        Precision::Fixed8,
        support::HEADLESS[0],
        FRAME,
        &fidelity::parse(&script_file("fog")),
    );
    support::assert_images_match("fog-fixed8", &fixed8.image, &pairs[0].native.image, tol);
    for p in pairs {
        // Not vacuous: the far end of the LINEAR quad (z_eye ≈ −24, f = 0) is the fog
        // colour (0.2, 0.4, 1) on both paths; its near end (z ≈ −2, f = 18/19) is close
        // to the textured colour (1, 0.8, 0.6)·128/255.
        for out in [&p.emulate, &p.native] {
            probe_rgb(&out.image, 23, 31, [51, 102, 255], 2);
            let far = out.image.get_pixel(23, 0).0;
            let near = out.image.get_pixel(23, 31).0;
            assert!(
                near[2] < far[2] && near[0] > far[0],
                "{}: near {near:?} vs far {far:?}",
                p.backend
            );
        }
    }
}

/// A white quad at z_eye = −10 covering the whole 64×32 view of glFrustum(−1, 1, −½, ½,
/// 1, 30), LINEAR fog from 0 to 20 towards black: f = (20 − 10)/20 = ½ at every pixel by
/// |z_eye|, so every pixel is 127.5 → 127 or 128. The radial distance would put the corners
/// (|x|, |y| up to 10, 5) at d ≈ 15 and f ≈ 0.25.
#[test]
fn fog_distance_is_the_absolute_eye_z() {
    let src = "glViewport(0, 0, 64, 32);
glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glFrustum(-1, 1, -0.5, 0.5, 1, 30);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glEnable(GL_FOG);
glFogi(GL_FOG_MODE, GL_LINEAR);
glFogf(GL_FOG_START, 0);
glFogf(GL_FOG_END, 20);
glFogfv(GL_FOG_COLOR, (GLfloat[]){0, 0, 0, 1});
glColor3f(1, 1, 1);
glBegin(GL_QUADS);
glVertex3f(-10, -5, -10);
glVertex3f(10, -5, -10);
glVertex3f(10, 5, -10);
glVertex3f(-10, 5, -10);
glEnd();
";
    for p in run_both(src, FRAME) {
        for out in [&p.emulate, &p.native] {
            for (x, y) in [(0, 0), (63, 31), (32, 16), (0, 31), (63, 0)] {
                probe_rgb(&out.image, x, y, [128, 128, 128], 1);
            }
        }
    }
}

/// A receding quad, orange towards blue fog, LINEAR 1…20; `extra` comes before the draw.
fn receding(extra: &str) -> String {
    format!(
        "glViewport(0, 0, 64, 32);
glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glFrustum(-1, 1, -0.5, 0.5, 1, 30);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glEnable(GL_FOG);
glFogi(GL_FOG_MODE, GL_LINEAR);
glFogf(GL_FOG_START, 1);
glFogf(GL_FOG_END, 20);
glFogfv(GL_FOG_COLOR, (GLfloat[]){{0.1, 0.3, 0.9, 1}});
{extra}glColor4f(1, 0.5, 0.1, 0.75);
glBegin(GL_QUADS);
glVertex3f(-2, -1, -2);
glVertex3f(2, -1, -2);
glVertex3f(25, 12.5, -25);
glVertex3f(-25, 12.5, -25);
glEnd();
"
    )
}

/// Under register combiners the final combiner applies fog (NV_register_combiners): with
/// A = FOG.a (the factor f), B = PRIMARY_COLOR, C = FOG.rgb (the fog colour), D = 0 and
/// G = PRIMARY_COLOR.a, the emulated combiners compute f·C + (1 − f)·C_f, which is GL's fog —
/// so they must draw what Mesa's native fog draws without combiners (which Mesa lacks).
/// 3/255 on ≥ 99% of the pixels; a FOG register still reading (0, 0, 0, 1) gives the bare
/// primary colour and fails by up to 204/255 on blue where f = 0.
#[test]
fn the_combiners_fog_register_holds_the_fog_colour_and_factor() {
    let combiners =
        "glFinalCombinerInputNV(GL_VARIABLE_A_NV, GL_FOG, GL_UNSIGNED_IDENTITY_NV, GL_ALPHA);
glFinalCombinerInputNV(GL_VARIABLE_B_NV, GL_PRIMARY_COLOR_NV, GL_UNSIGNED_IDENTITY_NV, GL_RGB);
glFinalCombinerInputNV(GL_VARIABLE_C_NV, GL_FOG, GL_UNSIGNED_IDENTITY_NV, GL_RGB);
glFinalCombinerInputNV(GL_VARIABLE_D_NV, GL_ZERO, GL_UNSIGNED_IDENTITY_NV, GL_RGB);
glFinalCombinerInputNV(GL_VARIABLE_G_NV, GL_PRIMARY_COLOR_NV, GL_UNSIGNED_IDENTITY_NV, GL_ALPHA);
glEnable(GL_REGISTER_COMBINERS_NV);
";
    let plain = fidelity::parse(&receding(""));
    let with_combiners = fidelity::parse(&receding(combiners));
    let tol = Tolerance {
        per_channel: 3,
        max_bad_pixels: (FRAME.width * FRAME.height / 100) as usize,
    };
    for backend in support::HEADLESS {
        let native = fidelity::run_one(
            PipelineKind::Native,
            Precision::Float,
            backend,
            FRAME,
            &plain,
        );
        let emulate = fidelity::run_one(
            PipelineKind::Emulate,
            Precision::Float,
            backend,
            FRAME,
            &with_combiners,
        );
        support::assert_images_match(
            &format!("fog-combiners-{backend}"),
            &emulate.image,
            &native.image,
            tol,
        );
    }
}
