//! The generated legacy bindings drive Mesa's fixed-function path on both headless backends.

mod support;

use fixedfunc::gpu::Profile;
use fixedfunc::pipeline::native::{bindings as gl, NativeGl};
use fixedfunc::vocab::DepthBits;
use support::{assert_no_gl_error, context, probe, target};

#[test]
fn immediate_mode_draws_through_the_generated_bindings() {
    for backend in support::HEADLESS {
        let ctx = context(backend, Profile::Compatibility);
        let t = target(&ctx, 16, 16, DepthBits::D24, false);
        let native = NativeGl::load(&ctx).expect("compatibility context");
        let g = native.raw();
        unsafe {
            g.ClearColor(0.0, 0.0, 0.0, 1.0);
            g.Clear(gl::COLOR_BUFFER_BIT);
            g.MatrixMode(gl::PROJECTION);
            g.LoadIdentity();
            g.Ortho(0.0, 16.0, 0.0, 16.0, -1.0, 1.0);
            g.Begin(gl::QUADS);
            g.Color3f(1.0, 0.2, 0.6);
            g.Vertex2f(0.0, 0.0);
            g.Vertex2f(8.0, 0.0);
            g.Vertex2f(8.0, 16.0);
            g.Vertex2f(0.0, 16.0);
            g.End();
        }
        let img = t.read_color(&ctx).expect("colour");
        probe(&img, 3, 3, [255, 51, 153, 255], 0);
        probe(&img, 12, 3, [0, 0, 0, 255], 0);
        assert_no_gl_error(&ctx);
    }
    // A core context has no fixed function to load.
    let core = context(support::HEADLESS[0], Profile::Core33);
    assert!(NativeGl::load(&core).is_none());
}
