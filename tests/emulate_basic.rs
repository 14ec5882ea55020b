//! The emulated pipeline on real core contexts: colours, lighting, texturing, alpha test,
//! readback slots and the program cache, against values computed from the GL rules.

mod support;

use fixedfunc::ff::script;
use fixedfunc::gpu::Profile;
use fixedfunc::pipeline::emulate::EmulatedPipeline;
use fixedfunc::pipeline::Pipeline;
use fixedfunc::vocab::DepthBits;
use support::{assert_no_gl_error, context, probe, target};

/// Runs `source` on a 16×16 D24S8 target of each headless backend; returns the images.
fn run(source: &str, check: impl Fn(&image::RgbaImage, &EmulatedPipeline)) {
    let commands = script::parse(source).unwrap_or_else(|e| panic!("{e}"));
    for backend in support::HEADLESS {
        let ctx = context(backend, Profile::Core33);
        let t = target(&ctx, 16, 16, DepthBits::D24, true);
        let mut p = EmulatedPipeline::new(&ctx).expect("pipeline");
        p.execute(&ctx, &commands).expect("execute");
        assert_eq!(p.take_gl_error(), None, "{backend}");
        let img = t.read_color(&ctx).expect("colour");
        check(&img, &p);
        assert_no_gl_error(&ctx);
        p.release(&ctx);
    }
}

const QUAD: &str = "glBegin(GL_QUADS);
glVertex3f(-1, -1, 0); glVertex3f(1, -1, 0); glVertex3f(1, 1, 0); glVertex3f(-1, 1, 0);
glEnd();";

#[test]
fn a_coloured_quad_fills_the_target_exactly() {
    let src = format!(
        "glClearColor(0, 0, 0, 1);\nglClear(GL_COLOR_BUFFER_BIT);\nglColor4f(1, 0.2f, 0.6f, 1);\n{QUAD}"
    );
    run(&src, |img, p| {
        probe(img, 0, 0, [255, 51, 153, 255], 0);
        probe(img, 15, 15, [255, 51, 153, 255], 0);
        assert_eq!(p.counters().programs_compiled, 1);
        assert_eq!(p.counters().draws, 1);
    });
}

/// c = a_m·a_scene + max(n·L, 0)·d_m·d_l = 0.2·0.2 + (0.8, 0.4, 0.2) = (0.84, 0.44, 0.24).
#[test]
fn a_directional_light_follows_the_lighting_equation() {
    let src = format!(
        "glEnable(GL_LIGHTING);
glEnable(GL_LIGHT0);
glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){{0, 0, 1, 0}});
glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (GLfloat[]){{0.8f, 0.4f, 0.2f, 1}});
glNormal3f(0, 0, 1);
{QUAD}"
    );
    run(&src, |img, _| probe(img, 8, 8, [214, 112, 61, 255], 1));
}

/// REPLACE with a 2×2 RGBA texture, NEAREST: each quadrant shows its texel.
#[test]
fn replace_shows_each_texel() {
    let src = "glBindTexture(GL_TEXTURE_2D, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){255,0,0,255, 0,255,0,255, 0,0,255,255, 255,255,255,255});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
glEnable(GL_TEXTURE_2D);
glBegin(GL_QUADS);
glTexCoord2f(0, 0); glVertex3f(-1, -1, 0);
glTexCoord2f(1, 0); glVertex3f(1, -1, 0);
glTexCoord2f(1, 1); glVertex3f(1, 1, 0);
glTexCoord2f(0, 1); glVertex3f(-1, 1, 0);
glEnd();";
    run(src, |img, _| {
        // Image rows run top first: the bottom-left texel (red) is at the bottom left.
        probe(img, 2, 13, [255, 0, 0, 255], 0);
        probe(img, 13, 13, [0, 255, 0, 255], 0);
        probe(img, 2, 2, [0, 0, 255, 255], 0);
        probe(img, 13, 2, [255, 255, 255, 255], 0);
    });
}

/// Mesa's alpha test (Precision::Float): alpha and reference as unorm8 rounded half to
/// even. GREATER 0.5 (ref 128): 128.5/255 rounds to 128 and fails; 128.6/255 passes.
#[test]
fn alpha_test_compares_rounded_unorm8_values() {
    let src = "glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
glAlphaFunc(GL_GREATER, 0.5f);
glEnable(GL_ALPHA_TEST);
glBegin(GL_QUADS);
glColor4f(1, 1, 1, 0.503921568f); glVertex3f(-1, -1, 0); glVertex3f(0, -1, 0); glVertex3f(0, 1, 0); glVertex3f(-1, 1, 0);
glColor4f(1, 1, 1, 0.504313725f); glVertex3f(0, -1, 0); glVertex3f(1, -1, 0); glVertex3f(1, 1, 0); glVertex3f(0, 1, 0);
glEnd();";
    run(src, |img, _| {
        probe(img, 3, 8, [0, 0, 0, 0], 0);
        probe(img, 12, 8, [255, 255, 255, 129], 0);
    });
}

#[test]
fn readback_slots_hold_depth_bytes_and_programs_are_reused() {
    let src = format!(
        "glClearDepth(1);
glClear(GL_DEPTH_BUFFER_BIT);
glEnable(GL_DEPTH_TEST);
glDepthFunc(GL_ALWAYS);
glBegin(GL_QUADS);
glVertex3f(-1, -1, 0); glVertex3f(1, -1, 0); glVertex3f(1, 1, 0); glVertex3f(-1, 1, 0);
glEnd();
{QUAD}
glReadPixels(0, 0, 2, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, readback_7);"
    );
    run(&src, |_, p| {
        let r = p.readback(7).expect("slot 7");
        // Window z 0.5 → ⌊255·0.5⌋ = 127 (UNSIGNED_BYTE truncates on Mesa).
        assert_eq!(r.bytes, vec![127, 127]);
        let c = p.counters();
        assert_eq!((c.draws, c.programs_compiled), (2, 1));
        assert!(c.state_calls_skipped > 0, "{c:?}");
    });
}

/// Geometry drawn once and dropped (immediate mode through the C library: a new geometry
/// every glEnd) does not pile up: the upload cache keeps what something still holds.
#[test]
fn dropped_geometry_does_not_accumulate() {
    use fixedfunc::ff::{Command, Geometry, Primitive};
    use glam::Vec4;
    use std::sync::Arc;

    let ctx = context(fixedfunc::gpu::Backend::Egl, Profile::Core33);
    let _t = target(&ctx, 16, 16, DepthBits::D24, false);
    let mut p = EmulatedPipeline::new(&ctx).unwrap();
    let triangle = || {
        Arc::new(Geometry::new(
            Primitive::Triangles,
            vec![
                Vec4::new(-1.0, -1.0, 0.0, 1.0),
                Vec4::new(1.0, -1.0, 0.0, 1.0),
                Vec4::W,
            ],
        ))
    };
    let kept = triangle();
    for _ in 0..2000 {
        p.execute(
            &ctx,
            &[Command::Draw(triangle()), Command::Draw(kept.clone())],
        )
        .unwrap();
    }
    assert_no_gl_error(&ctx);
    let n = p.uploaded_geometries();
    assert!(
        (1..=200).contains(&n),
        "{n} geometries still uploaded after 2000 dropped ones"
    );
}

/// A display list's glBegin … glEnd is assembled at glEndList: every glCallList draws the
/// same geometry, uploaded once; a redefined list uploads its new vertices.
#[test]
fn a_display_list_is_uploaded_once_until_it_is_redefined() {
    let list = format!("glNewList(1, GL_COMPILE);\nglColor3f(0, 1, 0);\n{QUAD}\nglEndList();\n");
    let src = format!("{list}glCallList(1);\nglCallList(1);\nglCallList(1);\n{list}glCallList(1);");
    run(&src, |img, p| {
        probe(img, 8, 8, [0, 255, 0, 255], 0);
        assert_eq!(p.counters().draws, 4);
        assert_eq!(p.counters().geometry_uploads, 2);
    });
}

/// A draw from buffer objects that nothing changed since the last such draw uploads
/// nothing; glBufferSubData makes the next draw upload again.
#[test]
fn a_draw_from_unchanged_buffers_is_uploaded_once() {
    let src = "glColor3f(0, 0, 1);\n\
        glBindBuffer(GL_ARRAY_BUFFER, 1);\n\
        glBufferData(GL_ARRAY_BUFFER, 32, (GLfloat[]){-1, -1, 1, -1, 1, 1, -1, 1}, GL_STATIC_DRAW);\n\
        glVertexPointer(2, GL_FLOAT, 0, NULL);\n\
        glEnableClientState(GL_VERTEX_ARRAY);\n\
        glDrawArrays(GL_QUADS, 0, 4);\nglDrawArrays(GL_QUADS, 0, 4);\nglDrawArrays(GL_QUADS, 0, 4);\n\
        glBufferSubData(GL_ARRAY_BUFFER, 0, 8, (GLfloat[]){-1, -1});\n\
        glDrawArrays(GL_QUADS, 0, 4);";
    run(src, |img, p| {
        probe(img, 8, 8, [0, 0, 255, 255], 0);
        assert_eq!(p.counters().draws, 4);
        assert_eq!(p.counters().geometry_uploads, 2);
    });
}
