//! The attribute stack, emulate against native: each scene pushes, changes lighting,
//! texture, enables, depth, stencil or colour-buffer state, draws, pops and draws again, so
//! both the changed and the restored state reach the image. Tolerance: the suite's
//! 3/255 per channel on at least 99% of the pixels (`TOL`), and probes where the expected
//! colour is known. Also the stack's errors on both paths: the 17th push overflows, a pop
//! of the empty stack underflows, and neither reaches the driver or changes the image.

mod fidelity;
mod support;

use fidelity::{compare, ortho, probe_gl, probe_rgb, run_one, Frame};
use fixedfunc::ff::{AttribMask, Command, GlErrorKind, MAX_ATTRIB_STACK_DEPTH};
use fixedfunc::pipeline;
use fixedfunc::vocab::{DepthBits, PipelineKind, Precision};
use support::Tolerance;

const SIZE: u32 = 64;

/// 3/255 per channel on ≥ 99% of the 64 × 64 pixels.
const TOL: Tolerance = Tolerance {
    per_channel: 3,
    max_bad_pixels: (SIZE * SIZE / 100) as usize,
};

/// A quad over pixels [x0, x1) × [y0, y1) at object depth z, with a normal facing +z.
fn quad(x0: u32, y0: u32, x1: u32, y1: u32, z: f32) -> String {
    format!(
        "glNormal3f(0, 0, 1);\nglBegin(GL_QUADS);\nglTexCoord2f(0, 0); glVertex3f({x0}, {y0}, {z});\nglTexCoord2f(1, 0); glVertex3f({x1}, {y0}, {z});\nglTexCoord2f(1, 1); glVertex3f({x1}, {y1}, {z});\nglTexCoord2f(0, 1); glVertex3f({x0}, {y1}, {z});\nglEnd();\n"
    )
}

fn frame() -> Frame {
    Frame::new(SIZE, SIZE).with_stencil()
}

fn clear() -> String {
    "glClearColor(0, 0, 0, 1);\nglClearDepth(1);\nglClearStencil(0);\nglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);\n".into()
}

/// LIGHTING_BIT | ENABLE_BIT: a red light 1 and a blue material inside, the white light 0
/// and the default grey material after the pop. Left half drawn inside, right half after.
#[test]
fn lighting_restored_by_pop() {
    let src = format!(
        "{}{}glEnable(GL_LIGHTING);\nglEnable(GL_LIGHT0);\nglLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){{0, 0, 1, 0}});\n\
         glPushAttrib(GL_LIGHTING_BIT | GL_ENABLE_BIT);\n\
         glDisable(GL_LIGHT0);\nglEnable(GL_LIGHT1);\n\
         glLightfv(GL_LIGHT1, GL_DIFFUSE, (GLfloat[]){{1, 0.2, 0.2, 1}});\n\
         glLightfv(GL_LIGHT1, GL_POSITION, (GLfloat[]){{16, 32, 20, 1}});\n\
         glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.01);\n\
         glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (GLfloat[]){{0.3, 0.5, 1, 1}});\n\
         glLightModelfv(GL_LIGHT_MODEL_AMBIENT, (GLfloat[]){{0, 0, 0, 1}});\n\
         glShadeModel(GL_FLAT);\n{}glPopAttrib();\n{}",
        clear(),
        ortho(SIZE, SIZE),
        quad(0, 0, 32, 64, 0.0),
        quad(32, 0, 64, 64, 0.0),
    );
    for p in compare("attrib-lighting", &src, frame(), TOL) {
        // After the pop: white light 0 along +z on the default material, 0.8 diffuse + 0.2 ×
        // 0.2 ambient = 0.84 grey.
        probe_rgb(&p.native.image, 48, 32, [214, 214, 214], 2);
        probe_rgb(&p.emulate.image, 48, 32, [214, 214, 214], 2);
    }
}

/// TEXTURE_BIT: inside, texture 1's magnification filter becomes LINEAR, texture 2 is bound
/// with REPLACE; the pop rebinds texture 1, puts NEAREST back into it and MODULATE back into
/// the unit. A 2 × 2 checker magnified over each half shows the filter.
#[test]
fn texture_bindings_env_and_parameters_restored_by_pop() {
    let checker = "(GLubyte[]){255, 255, 255, 255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255, 255}";
    let src = format!(
        "{}{}glColor4f(1, 0.5, 0.25, 1);\n\
         glBindTexture(GL_TEXTURE_2D, 1);\n\
         glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, {checker});\n\
         glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);\n\
         glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);\n\
         glBindTexture(GL_TEXTURE_2D, 2);\n\
         glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){{0, 255, 0, 255}});\n\
         glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);\n\
         glBindTexture(GL_TEXTURE_2D, 1);\n\
         glEnable(GL_TEXTURE_2D);\n\
         glPushAttrib(GL_TEXTURE_BIT);\n\
         glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);\n\
         {}\
         glBindTexture(GL_TEXTURE_2D, 2);\n\
         glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);\n\
         {}\
         glPopAttrib();\n{}",
        clear(),
        ortho(SIZE, SIZE),
        quad(0, 32, 32, 64, 0.0),
        quad(0, 0, 32, 32, 0.0),
        quad(32, 0, 64, 64, 0.0),
    );
    for p in compare("attrib-texture", &src, frame(), TOL) {
        for out in [&p.native, &p.emulate] {
            // Inside: texture 2 replaces: green.
            probe_rgb(&out.image, 16, 16, [0, 255, 0], 0);
            // After the pop: NEAREST checker, modulated by the colour: the corner texel
            // (white) gives the colour itself, exactly.
            probe_rgb(&out.image, 34, 2, [255, 128, 64], 1);
            probe_rgb(&out.image, 62, 2, [0, 0, 0], 0);
        }
    }
}

/// ENABLE_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT | COLOR_BUFFER_BIT: inside, the depth
/// test (GREATER, no depth writes), the stencil test writing 1 and a ZERO, ONE blend;
/// after the pop none is on, so the second quad covers everything; a third quad drawn with
/// a fresh stencil test EQUAL 1 shows where the first wrote the stencil.
#[test]
fn enables_depth_stencil_and_blend_restored_by_pop() {
    let src = format!(
        "{}{}glPushAttrib(GL_ENABLE_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_COLOR_BUFFER_BIT);\n\
         glEnable(GL_DEPTH_TEST);\nglDepthFunc(GL_GREATER);\nglDepthMask(GL_FALSE);\n\
         glEnable(GL_STENCIL_TEST);\nglStencilFunc(GL_ALWAYS, 1, 0xFF);\nglStencilOp(GL_KEEP, GL_REPLACE, GL_REPLACE);\n\
         glEnable(GL_BLEND);\nglBlendFunc(GL_ZERO, GL_ONE);\n\
         glColor3f(1, 0, 0);\n{}\
         glPopAttrib();\n\
         glColor3f(0, 0, 1);\n{}\
         glEnable(GL_STENCIL_TEST);\nglStencilFunc(GL_EQUAL, 1, 0xFF);\n\
         glColor3f(0, 1, 0);\n{}",
        clear(),
        ortho(SIZE, SIZE),
        quad(0, 0, 32, 64, 0.0),
        quad(0, 0, 64, 32, 0.5),
        quad(0, 0, 64, 64, -0.5),
    );
    for p in compare("attrib-enables", &src, frame(), TOL) {
        for out in [&p.native, &p.emulate] {
            // The first quad failed GREATER against depth 1 but wrote stencil 1 (z-fail
            // REPLACE) under a blend that kept the black: green only where it was.
            probe_gl(&out.image, 16, 48, [0, 255, 0, 255], 0);
            probe_gl(&out.image, 48, 48, [0, 0, 0, 255], 0);
            // The blue quad after the pop: no depth test, no blend.
            probe_gl(&out.image, 48, 16, [0, 0, 255, 255], 0);
        }
    }
}

/// CURRENT_BIT | POLYGON_BIT | VIEWPORT_BIT | TRANSFORM_BIT: inside, a red colour, front
/// faces culled, a quarter viewport and the projection matrix mode; the quad drawn inside is
/// culled, the one after the pop is drawn white over the whole viewport. The matrix mode is
/// restored, so the glLoadIdentity after the pop resets the modelview, not the projection.
#[test]
fn current_polygon_viewport_and_transform_restored_by_pop() {
    let src = format!(
        "{}{}glPushAttrib(GL_CURRENT_BIT | GL_POLYGON_BIT | GL_VIEWPORT_BIT | GL_TRANSFORM_BIT);\n\
         glColor3f(1, 0, 0);\nglEnable(GL_CULL_FACE);\nglCullFace(GL_FRONT);\n\
         glViewport(0, 0, 32, 32);\nglMatrixMode(GL_PROJECTION);\n{}\
         glPopAttrib();\nglLoadIdentity();\n{}",
        clear(),
        ortho(SIZE, SIZE),
        quad(0, 0, 64, 64, 0.0),
        quad(8, 8, 56, 56, 0.0),
    );
    for p in compare("attrib-current", &src, frame(), TOL) {
        for out in [&p.native, &p.emulate] {
            probe_gl(&out.image, 32, 32, [255, 255, 255, 255], 0);
            probe_gl(&out.image, 4, 4, [0, 0, 0, 255], 0);
        }
    }
}

/// A nested pop (Mesa skips groups changed while an inner entry was on the stack; the
/// native path sends them again): the blend enabled under the inner entry is off after
/// both pops, so the last quad is drawn unblended.
#[test]
fn nested_pops_restore_what_changed_inside() {
    let src = format!(
        "{}{}glPushAttrib(GL_COLOR_BUFFER_BIT);\nglPushAttrib(0);\n\
         glEnable(GL_BLEND);\nglBlendFunc(GL_ZERO, GL_ONE);\nglPopAttrib();\nglPopAttrib();\n\
         glColor3f(1, 1, 0);\n{}",
        clear(),
        ortho(SIZE, SIZE),
        quad(0, 0, 64, 64, 0.0),
    );
    for p in compare("attrib-nested", &src, frame(), TOL) {
        for out in [&p.native, &p.emulate] {
            probe_gl(&out.image, 32, 32, [255, 255, 0, 255], 0);
        }
    }
}

/// The 17th push is STACK_OVERFLOW and a pop of the empty stack STACK_UNDERFLOW on both
/// paths; neither reaches the driver (the native path would stop on a driver error), and
/// the state drawn with afterwards is the one before them.
#[test]
fn overflow_and_underflow_on_both_paths() {
    let draw = fidelity::parse(&format!(
        "{}{}glColor3f(0, 1, 1);\n{}",
        clear(),
        ortho(SIZE, SIZE),
        quad(0, 0, 64, 64, 0.0)
    ));
    for backend in support::HEADLESS {
        for kind in [PipelineKind::Emulate, PipelineKind::Native] {
            let ctx = support::context(backend, pipeline::profile(kind));
            let t = support::target(&ctx, SIZE, SIZE, DepthBits::D24, true);
            let mut p = pipeline::create(kind, &ctx).expect("pipeline");
            let push = Command::PushAttrib(AttribMask::ALL);
            let pushes = vec![push; MAX_ATTRIB_STACK_DEPTH];
            p.execute(&ctx, &pushes).unwrap();
            assert_eq!(p.take_gl_error(), None);
            p.execute(&ctx, &[Command::PushAttrib(AttribMask::ALL)])
                .unwrap();
            let e = p.take_gl_error().expect("overflow");
            assert_eq!(e.kind, GlErrorKind::StackOverflow, "{backend} {kind:?}");
            assert_eq!(p.state().attrib_depth(), MAX_ATTRIB_STACK_DEPTH);
            let pops = vec![Command::PopAttrib; MAX_ATTRIB_STACK_DEPTH + 1];
            p.execute(&ctx, &pops).unwrap();
            let e = p.take_gl_error().expect("underflow");
            assert_eq!(e.kind, GlErrorKind::StackUnderflow, "{backend} {kind:?}");
            p.execute(&ctx, &draw).unwrap();
            assert_eq!(p.take_gl_error(), None);
            let img = t.read_color(&ctx).expect("readback");
            support::assert_no_gl_error(&ctx);
            support::probe(&img, 32, 32, [0, 255, 255, 255], 0);
            p.release(&ctx);
            t.delete(&ctx);
        }
    }
    // The harness's own single-path run agrees (the overflow leaves nothing behind).
    let out = run_one(
        PipelineKind::Emulate,
        Precision::Float,
        support::HEADLESS[0],
        frame(),
        &draw,
    );
    probe_gl(&out.image, 1, 1, [0, 255, 255, 255], 0);
}
