//! The gpu layer's error paths: missing libraries name their Debian package, impossible
//! target sizes state the limit, unknown backend names list the valid ones. Never a panic.

mod support;

use fixedfunc::gpu::{
    Backend, ContextRequest, GpuContext, GpuError, Profile, RenderTarget, TargetSpec,
};
use fixedfunc::vocab::DepthBits;
use glow::HasContext;

fn error_of(request: ContextRequest) -> GpuError {
    match GpuContext::new(&request) {
        Ok(_) => panic!("{request:?} should have failed"),
        Err(e) => e,
    }
}

#[test]
fn a_missing_egl_library_names_the_debian_packages() {
    let e = error_of(
        ContextRequest::new(Backend::Egl, Profile::Core33).with_library("libEGL-absent.so.9"),
    );
    assert!(matches!(
        e,
        GpuError::LibraryMissing {
            backend: Backend::Egl,
            ..
        }
    ));
    let text = e.to_string();
    assert!(text.contains("libEGL-absent.so.9"), "{text}");
    assert!(
        text.contains("apt-get install libegl1 libegl-mesa0"),
        "{text}"
    );
}

#[test]
fn a_missing_osmesa_library_names_its_package_and_its_removal() {
    let e = error_of(
        ContextRequest::new(Backend::OsMesa, Profile::Compatibility)
            .with_library("libOSMesa-absent.so.8"),
    );
    let text = e.to_string();
    assert!(text.contains("apt-get install libosmesa6"), "{text}");
    assert!(text.contains("removed from Mesa 25.1"), "{text}");
    assert!(text.contains("--backend egl"), "{text}");
}

#[test]
fn impossible_target_sizes_state_the_limit() {
    for backend in support::HEADLESS {
        let ctx = support::context(backend, Profile::Core33);
        let limit = unsafe { ctx.gl().get_parameter_i32(glow::MAX_RENDERBUFFER_SIZE) } as u32;
        for (w, h) in [(0, 16), (16, 0), (limit + 1, 4), (4, limit + 1)] {
            let e = RenderTarget::new(&ctx, TargetSpec::new(w, h, DepthBits::D24))
                .expect_err("impossible size accepted");
            match &e {
                GpuError::TargetSize { limit: l, .. } => assert_eq!(*l, limit),
                other => panic!("{w}x{h}: unexpected {other}"),
            }
            assert!(e.to_string().contains(&limit.to_string()), "{e}");
        }
        // D16 has no stencil to give.
        let e = RenderTarget::new(&ctx, TargetSpec::new(4, 4, DepthBits::D16).with_stencil());
        assert!(matches!(e, Err(GpuError::IncompleteFramebuffer { .. })));
        support::assert_no_gl_error(&ctx);
    }
}

#[test]
fn an_unknown_backend_lists_the_valid_ones() {
    let e = "vulkan"
        .parse::<Backend>()
        .expect_err("vulkan is not a backend");
    assert_eq!(
        e.to_string(),
        "unknown backend `vulkan`; valid backends: egl, osmesa, window"
    );
    assert_eq!("OSMesa".parse::<Backend>().ok(), Some(Backend::OsMesa));
    // The command line says the same.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .args(["info", "--backend", "vulkan"])
        .output()
        .expect("run fixedfunc");
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("egl") && stderr.contains("osmesa") && stderr.contains("window"),
        "{stderr}"
    );
}
