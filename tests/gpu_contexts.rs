//! Every headless backend gives a core 3.3 and a compatibility context that render and read
//! back exact pixels; D16, D24 and D32F targets depth-test, round-trip depths and (where
//! asked) stencil; EGL and OSMesa agree bit for bit.

mod support;

use fixedfunc::gpu::{Backend, ContextRequest, EglPlatform, FlatProgram, GpuContext, Profile};
use fixedfunc::vocab::{DepthBits, DepthRule, ReadbackRule};
use glow::HasContext;
use support::{assert_images_match, assert_no_gl_error, context, probe, target, Tolerance};

const TRIANGLE: [[f32; 3]; 3] = [[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [-1.0, 1.0, 0.0]];

/// Two triangles covering the whole target at NDC depth z.
fn full_screen(z: f32) -> [[f32; 3]; 6] {
    [
        [-1.0, -1.0, z],
        [1.0, -1.0, z],
        [1.0, 1.0, z],
        [-1.0, -1.0, z],
        [1.0, 1.0, z],
        [-1.0, 1.0, z],
    ]
}

fn clear(ctx: &GpuContext, rgba: [f32; 4]) {
    let gl = ctx.gl();
    unsafe {
        gl.clear_color(rgba[0], rgba[1], rgba[2], rgba[3]);
        gl.clear_depth_f64(1.0);
        gl.clear_stencil(0);
        gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT | glow::STENCIL_BUFFER_BIT);
    }
}

#[test]
fn each_headless_backend_and_profile_draws_exact_pixels() {
    for backend in support::HEADLESS {
        for profile in Profile::ALL {
            let ctx = context(backend, profile);
            let t = target(&ctx, 64, 64, DepthBits::D24, false);
            let flat = FlatProgram::new(&ctx).expect("flat program");
            clear(&ctx, [0.0, 0.0, 0.4, 1.0]);
            flat.draw(&ctx, &TRIANGLE, [1.0, 0.2, 0.6, 1.0]);
            let img = t.read_color(&ctx).expect("read colour");
            // Bottom-left is inside the triangle, top-right outside (image rows top first).
            probe(&img, 4, 59, [255, 51, 153, 255], 0);
            probe(&img, 59, 4, [0, 0, 102, 255], 0);
            // Pixel centres with x + y < 63 are covered; the 64 centres exactly on the
            // hypotenuse (x + y = 63) lie on a right edge, which the top-left rule excludes.
            let covered = img.pixels().filter(|p| p.0 == [255, 51, 153, 255]).count();
            assert_eq!(
                covered,
                (0..64).map(|y| 63 - y).sum::<usize>(),
                "{backend} {profile:?}"
            );
            assert_no_gl_error(&ctx);
        }
    }
}

#[test]
fn every_depth_format_separates_overlapping_triangles() {
    for backend in support::HEADLESS {
        let ctx = context(backend, Profile::Core33);
        let flat = FlatProgram::new(&ctx).expect("flat program");
        for depth in DepthBits::ALL {
            let t = target(&ctx, 32, 32, depth, false);
            assert_eq!(t.depth_bits(), depth.bits(), "{backend} {depth:?}");
            unsafe {
                ctx.gl().enable(glow::DEPTH_TEST);
                ctx.gl().depth_func(glow::LESS);
            }
            clear(&ctx, [0.0, 0.0, 0.0, 1.0]);
            flat.draw(&ctx, &full_screen(0.5), [1.0, 0.0, 0.0, 1.0]);
            flat.draw(&ctx, &TRIANGLE, [0.0, 1.0, 0.0, 1.0]); // nearer: z = 0
            flat.draw(&ctx, &full_screen(0.8), [0.0, 0.0, 1.0, 1.0]); // behind both
            let img = t.read_color(&ctx).expect("read colour");
            probe(&img, 2, 29, [0, 255, 0, 255], 0);
            probe(&img, 29, 2, [255, 0, 0, 255], 0);
            unsafe { ctx.gl().disable(glow::DEPTH_TEST) };
            assert_no_gl_error(&ctx);
            t.delete(&ctx);
        }
    }
}

#[test]
fn depth_readback_round_trips_known_depths() {
    for backend in support::HEADLESS {
        let ctx = context(backend, Profile::Core33);
        let flat = FlatProgram::new(&ctx).expect("flat program");
        for depth in DepthBits::ALL {
            // Nine columns at window depths k/8 (readpix-z's steps of 0.125).
            let t = target(&ctx, 9, 1, depth, false);
            unsafe {
                ctx.gl().enable(glow::DEPTH_TEST);
                ctx.gl().depth_func(glow::ALWAYS);
            }
            clear(&ctx, [0.0; 4]);
            for k in 0..9 {
                let window_z = k as f32 / 8.0;
                let z = 2.0 * window_z - 1.0;
                let x0 = -1.0 + 2.0 * k as f32 / 9.0;
                let x1 = x0 + 2.0 / 9.0;
                let quad = [
                    [x0, -1.0, z],
                    [x1, -1.0, z],
                    [x1, 1.0, z],
                    [x0, -1.0, z],
                    [x1, 1.0, z],
                    [x0, 1.0, z],
                ];
                flat.draw(&ctx, &quad, [1.0; 4]);
            }
            let tol = 1.0 / 2f32.powi(depth.bits() as i32 - 1);
            let read = t.read_depth_f32(&ctx).expect("read depth");
            for (k, z) in read.iter().enumerate() {
                let want = k as f32 / 8.0;
                assert!(
                    (z - want).abs() <= tol,
                    "{backend} {depth:?}: column {k} reads {z}, want {want} ± {tol}"
                );
            }
            unsafe { ctx.gl().disable(glow::DEPTH_TEST) };
            assert_no_gl_error(&ctx);
            t.delete(&ctx);
        }
    }
}

#[test]
fn stencil_works_where_it_was_asked_for() {
    for backend in support::HEADLESS {
        let ctx = context(backend, Profile::Compatibility);
        let flat = FlatProgram::new(&ctx).expect("flat program");
        for depth in [DepthBits::D24, DepthBits::D32F] {
            let t = target(&ctx, 16, 16, depth, true);
            assert_eq!(t.stencil_bits(), 8, "{backend} {depth:?}");
            let gl = ctx.gl();
            clear(&ctx, [0.0, 0.0, 0.0, 1.0]);
            unsafe {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::ALWAYS, 0, 0xFF);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::INCR);
            }
            flat.draw(&ctx, &TRIANGLE, [0.0; 4]);
            flat.draw(&ctx, &TRIANGLE, [0.0; 4]);
            unsafe {
                gl.stencil_func(glow::EQUAL, 2, 0xFF);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            flat.draw(&ctx, &full_screen(0.0), [1.0, 1.0, 1.0, 1.0]);
            unsafe { gl.disable(glow::STENCIL_TEST) };
            let img = t.read_color(&ctx).expect("colour");
            probe(&img, 1, 14, [255, 255, 255, 255], 0);
            probe(&img, 14, 1, [0, 0, 0, 255], 0);
            let stencil = t.read_stencil(&ctx).expect("stencil");
            assert_eq!(stencil[0], 2, "bottom-left inside the triangle");
            assert_eq!(stencil[16 * 16 - 1], 0, "top-right outside");
            assert_no_gl_error(&ctx);
            t.delete(&ctx);
        }
        // D24 without asking still has its 8 packed bits; D16 has none.
        let t = target(&ctx, 4, 4, DepthBits::D16, false);
        assert_eq!(t.stencil_bits(), 0);
        assert!(t.read_stencil(&ctx).is_err());
    }
}

/// Mesa's own integer depth readback: UNSIGNED_BYTE truncates (⌊255z⌋), UNSIGNED_SHORT
/// rounds (⌊65535z + ½⌋) except at rare ties. Our named rules reproduce both.
#[test]
fn driver_depth_readback_follows_the_named_rules() {
    for backend in support::HEADLESS {
        let ctx = context(backend, Profile::Compatibility);
        let flat = FlatProgram::new(&ctx).expect("flat program");
        let t = target(&ctx, 1024, 1, DepthBits::D24, false);
        unsafe {
            ctx.gl().enable(glow::DEPTH_TEST);
            ctx.gl().depth_func(glow::ALWAYS);
        }
        clear(&ctx, [0.0; 4]);
        // A depth ramp: window z from 0 at the left edge to 1 at the right.
        let ramp = [
            [-1.0, -1.0, -1.0],
            [1.0, -1.0, 1.0],
            [1.0, 1.0, 1.0],
            [-1.0, -1.0, -1.0],
            [1.0, 1.0, 1.0],
            [-1.0, 1.0, -1.0],
        ];
        flat.draw(&ctx, &ramp, [1.0; 4]);
        let bytes_driver = t.read_depth_u8(&ctx, ReadbackRule::Driver).unwrap();
        let bytes_ours = t
            .read_depth_u8(&ctx, ReadbackRule::Cpu(DepthRule::Truncate))
            .unwrap();
        assert_eq!(
            bytes_driver, bytes_ours,
            "{backend}: UNSIGNED_BYTE is ⌊255z⌋"
        );
        let shorts_driver = t.read_depth_u16(&ctx, ReadbackRule::Driver).unwrap();
        let shorts_ours = t
            .read_depth_u16(&ctx, ReadbackRule::Cpu(DepthRule::Round))
            .unwrap();
        let same = shorts_driver
            .iter()
            .zip(&shorts_ours)
            .filter(|(a, b)| a == b)
            .count();
        let within_one = shorts_driver
            .iter()
            .zip(&shorts_ours)
            .all(|(a, b)| a.abs_diff(*b) <= 1);
        assert!(
            within_one,
            "{backend}: UNSIGNED_SHORT within 1 of ⌊65535z + ½⌋"
        );
        assert!(
            same >= 1014,
            "{backend}: only {same}/1024 shorts follow ⌊65535z + ½⌋"
        );
        let ints = t.read_depth_u32(&ctx, ReadbackRule::Driver).unwrap();
        let floats = t.read_depth_f32(&ctx).unwrap();
        for (i, z) in ints.iter().zip(&floats) {
            let from_int = *i as f64 / u32::MAX as f64;
            assert!(
                (from_int - *z as f64).abs() < 1e-6,
                "UNSIGNED_INT {i} vs float {z}"
            );
        }
        assert_no_gl_error(&ctx);
    }
}

#[test]
fn egl_and_osmesa_render_bit_identical_images() {
    let mut images = Vec::new();
    for backend in [Backend::Egl, Backend::OsMesa] {
        let ctx = context(backend, Profile::Core33);
        let t = target(&ctx, 97, 61, DepthBits::D24, false);
        let flat = FlatProgram::new(&ctx).expect("flat program");
        unsafe { ctx.gl().enable(glow::DEPTH_TEST) };
        clear(&ctx, [0.1, 0.2, 0.3, 1.0]);
        flat.draw(
            &ctx,
            &[[-0.9, -0.7, 0.3], [0.8, -0.2, -0.4], [-0.1, 0.95, 0.9]],
            [0.7, 0.3, 0.1, 1.0],
        );
        flat.draw(
            &ctx,
            &[[-0.5, 0.6, 0.0], [0.9, 0.9, 0.0], [0.2, -0.9, 0.0]],
            [0.2, 0.9, 0.5, 0.5],
        );
        images.push(t.read_color(&ctx).expect("colour"));
        assert_no_gl_error(&ctx);
    }
    assert_images_match("egl-vs-osmesa", &images[1], &images[0], Tolerance::EXACT);
}

/// The default EGL path is the surfaceless platform; the device platform (the fallback) works
/// too when forced, and says which path it took.
#[test]
fn egl_takes_the_surfaceless_platform_and_can_fall_back_to_a_device() {
    let ctx = context(Backend::Egl, Profile::Core33);
    assert_eq!(ctx.path(), "EGL_MESA_platform_surfaceless");
    let request = ContextRequest::new(Backend::Egl, Profile::Compatibility)
        .with_egl_platform(EglPlatform::Device);
    let ctx = GpuContext::new(&request).expect("EGL device platform");
    assert_eq!(ctx.path(), "EGL_EXT_platform_device");
    let t = target(&ctx, 8, 8, DepthBits::D24, false);
    let flat = FlatProgram::new(&ctx).expect("flat program");
    clear(&ctx, [0.0, 0.0, 0.0, 1.0]);
    flat.draw(&ctx, &full_screen(0.0), [0.0, 1.0, 0.0, 1.0]);
    probe(
        &t.read_color(&ctx).expect("colour"),
        4,
        4,
        [0, 255, 0, 255],
        0,
    );
    assert_no_gl_error(&ctx);
}
