//! The window backend in a real X11 window (Xvfb when no display is set). winit allows one
//! event loop per process and thread, so everything runs in this one test function.

mod support;

use fixedfunc::gpu::{Backend, ContextRequest, FlatProgram, GpuContext, Profile, VirtualDisplay};
use fixedfunc::vocab::DepthBits;
use glow::HasContext;
use support::{assert_images_match, assert_no_gl_error, probe, target, Tolerance};

#[test]
fn window_contexts_render_present_and_save_what_the_window_shows() {
    let _display = VirtualDisplay::start_if_needed().expect("an X display or Xvfb");
    for profile in Profile::ALL {
        let mut ctx = GpuContext::new(&ContextRequest::new(Backend::Window, profile))
            .unwrap_or_else(|e| panic!("window {} context: {e}", profile.name()));
        assert_eq!(ctx.backend(), Backend::Window);
        let t = target(&ctx, 80, 60, DepthBits::D24, false);
        let flat = FlatProgram::new(&ctx).expect("flat program");
        unsafe {
            ctx.gl().clear_color(0.0, 0.4, 0.0, 1.0);
            ctx.gl()
                .clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
        }
        flat.draw(
            &ctx,
            &[[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [-1.0, 1.0, 0.0]],
            [1.0, 0.2, 0.6, 1.0],
        );
        let rendered = t.read_color(&ctx).expect("target readback");
        probe(&rendered, 2, 57, [255, 51, 153, 255], 0);
        probe(&rendered, 77, 2, [0, 102, 0, 255], 0);
        let shown = ctx.present(&t).expect("present");
        assert_images_match(
            &format!("window-{profile:?}"),
            &shown,
            &rendered,
            Tolerance::EXACT,
        );
        assert_no_gl_error(&ctx);
        flat.delete(&ctx);
        t.delete(&ctx);
    }
    // A headless context has nothing to present to, and says so.
    let mut egl = support::context(Backend::Egl, Profile::Core33);
    let t = target(&egl, 4, 4, DepthBits::D16, false);
    let e = egl.present(&t).expect_err("EGL has no window");
    assert!(e.to_string().contains("--backend window"), "{e}");
}
