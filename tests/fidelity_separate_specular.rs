//! SEPARATE_SPECULAR_COLOR (GL 1.2 §2.13.1, colour sum §3.9) on the emulated path, beyond the
//! exact Float replay in `fidelity_scripts`: the highlight survives a dark MODULATE texture
//! only in the separate mode, and `Precision::Fixed8` — which sums the quantised secondary
//! colour on integers — matches Mesa too. Measured (Mesa 22.3.6 llvmpipe): R + G + B at the
//! highlight is 176 with SINGLE_COLOR and 536 with SEPARATE_SPECULAR_COLOR; Float and Fixed8
//! both differ from Mesa on 0 of the 2048 pixels.

mod fidelity;
mod support;

use fidelity::{parse, run_one, script_file, Frame};
use fixedfunc::vocab::{PipelineKind, Precision};
use support::{assert_images_match, Tolerance, HEADLESS};

const FRAME: Frame = Frame::new(64, 32);

#[test]
fn the_highlight_is_added_after_the_texture_only_when_separate() {
    let commands = parse(&script_file("separate_specular"));
    let native = run_one(
        PipelineKind::Native,
        Precision::Float,
        HEADLESS[0],
        FRAME,
        &commands,
    );
    // Each light stands over the middle of its quad: (16, 16) left, (48, 16) right.
    let peak = |x| {
        let p = native.image.get_pixel(x, 16).0;
        u32::from(p[0]) + u32::from(p[1]) + u32::from(p[2])
    };
    let (single, separate) = (peak(16), peak(48));
    assert!(
        separate > single + 200,
        "highlight: SINGLE_COLOR {single}, SEPARATE_SPECULAR_COLOR {separate} (sum of RGB)"
    );
    for precision in [Precision::Float, Precision::Fixed8] {
        let emulate = run_one(
            PipelineKind::Emulate,
            precision,
            HEADLESS[0],
            FRAME,
            &commands,
        );
        let tolerance = Tolerance {
            per_channel: 0,
            max_bad_pixels: 0,
        };
        assert_images_match(
            &format!("separate-specular-{precision:?}"),
            &emulate.image,
            &native.image,
            tolerance,
        );
    }
}
