//! Antialiasing enables against Mesa's native path. POLYGON_SMOOTH changes nothing on
//! llvmpipe, so blended polygons with it match exactly; antialiased points and lines are
//! not drawn by the emulated path, which refuses the draw (an error naming the
//! capability) rather than draw them aliased.

mod fidelity;
mod support;

use fidelity::{compare, ortho, Frame};
use fixedfunc::pipeline::{Pipeline, PipelineError};
use fixedfunc::vocab::PipelineKind;
use support::Tolerance;

const W: u32 = 64;
const H: u32 = 48;

fn triangles() -> String {
    format!(
        "{}glClearColor(0, 0, 0, 1);\nglClear(GL_COLOR_BUFFER_BIT);\n\
         glEnable(GL_BLEND);\nglBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);\n\
         glEnable(GL_POLYGON_SMOOTH);\nglShadeModel(GL_SMOOTH);\n\
         glBegin(GL_TRIANGLES);\n\
         glColor4f(1, 1, 0, 0.8); glVertex2f(3.3, 2.7);\n\
         glColor4f(0, 1, 1, 0.6); glVertex2f(60.2, 9.4);\n\
         glColor4f(1, 0, 1, 1); glVertex2f(21.7, 45.1);\n\
         glEnd();\n\
         glBegin(GL_QUADS);\n\
         glColor4f(1, 0.5, 0, 0.7); glVertex2f(30.5, 20.25); glVertex2f(58.75, 24.5);\n\
         glVertex2f(55.1, 44.9); glVertex2f(33.3, 40.0);\n\
         glEnd();\n",
        ortho(W, H)
    )
}

#[test]
fn polygon_smooth_changes_nothing_on_llvmpipe() {
    let pairs = compare(
        "polygon_smooth",
        &triangles(),
        Frame::new(W, H),
        Tolerance::EXACT,
    );
    let off = triangles().replace("glEnable(GL_POLYGON_SMOOTH);\n", "");
    let plain = compare(
        "polygon_smooth_off",
        &off,
        Frame::new(W, H),
        Tolerance::EXACT,
    );
    for (with, without) in pairs.iter().zip(&plain) {
        assert_eq!(
            with.native.image.as_raw(),
            without.native.image.as_raw(),
            "Mesa's native path draws the same pixels with and without POLYGON_SMOOTH"
        );
        let lit = with
            .native
            .image
            .pixels()
            .filter(|p| p.0[..3] != [0, 0, 0])
            .count();
        assert!(lit > 500, "the polygons were drawn ({lit} pixels)");
    }
}

#[test]
fn emulated_path_refuses_smooth_points_and_lines() {
    let ctx = support::context(
        support::HEADLESS[0],
        fixedfunc::pipeline::profile(PipelineKind::Emulate),
    );
    let _target = support::target(&ctx, W, H, fixedfunc::vocab::DepthBits::D24, false);
    for (cap, primitive, what) in [
        ("GL_POINT_SMOOTH", "GL_POINTS", "POINT_SMOOTH"),
        ("GL_LINE_SMOOTH", "GL_LINES", "LINE_SMOOTH"),
        ("GL_LINE_SMOOTH", "GL_LINE_LOOP", "LINE_SMOOTH"),
    ] {
        let mut p = fixedfunc::pipeline::emulate::EmulatedPipeline::new(&ctx).expect("pipeline");
        let source = format!(
            "{}glEnable({cap});\nglBegin({primitive});\nglVertex2f(4, 4); glVertex2f(40, 30);\nglEnd();\n",
            ortho(W, H)
        );
        let e = p
            .execute(&ctx, &fidelity::parse(&source))
            .expect_err("refused, not drawn aliased");
        match e {
            PipelineError::Unsupported { what: w, path } => {
                assert_eq!(path, "emulate");
                assert!(w.starts_with(what), "{w}");
            }
            other => panic!("{cap}: {other}"),
        }
        // A filled polygon is no point or line: drawn as usual.
        let mut p = fixedfunc::pipeline::emulate::EmulatedPipeline::new(&ctx).expect("pipeline");
        let filled = format!(
            "{}glEnable({cap});\nglBegin(GL_TRIANGLES);\nglVertex2f(4, 4); glVertex2f(40, 30); glVertex2f(9, 40);\nglEnd();\n",
            ortho(W, H)
        );
        p.execute(&ctx, &fidelity::parse(&filled))
            .expect("a filled triangle is drawn under point and line smoothing");
    }
}
