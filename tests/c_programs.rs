//! Unmodified C programs written for Mesa's OSMesa (`tests/c/`), compiled with `cc` against
//! the real `GL/osmesa.h` (Debian's libosmesa6-dev) and run twice: on Mesa's own
//! `libOSMesa.so.8`, and with `LD_LIBRARY_PATH=$(fixedfunc osmesa-dir)` on the layer's. The
//! images must match within 3/255 on 99% of pixels, and the error sequences exactly.
//! Each program runs in the variant that links the GL symbols directly and in the one
//! that resolves them through OSMesaGetProcAddress.

#[path = "c/harness.rs"]
mod harness;
mod support;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Mutex;

use harness::{fixedfunc_dir, read_ppm, run, Library};
use image::{Rgba, RgbaImage};
use support::{assert_images_match, Tolerance};

/// How the program reaches GL.
#[derive(Clone, Copy, Debug)]
enum Linking {
    Direct,
    ProcAddress,
}

fn source(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/c")
        .join(name)
}

fn work_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("c_programs")
        .join(name);
    std::fs::create_dir_all(&dir).expect("the test folder can be made");
    dir
}

/// Compiles `tests/c/NAME.c` as C99 with every warning an error, once per test run (the
/// tests run in parallel and share the executables).
fn compile(name: &str, linking: Linking) -> PathBuf {
    static BUILT: Mutex<Vec<(String, PathBuf)>> = Mutex::new(Vec::new());
    let key = format!("{name}-{linking:?}");
    let mut built = BUILT.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, exe)) = built.iter().find(|(k, _)| *k == key) {
        return exe.clone();
    }
    let exe = build(name, linking);
    built.push((key, exe.clone()));
    exe
}

fn build(name: &str, linking: Linking) -> PathBuf {
    let dir = work_dir(name);
    let exe = dir.join(format!("{name}-{linking:?}"));
    let mut cc = Command::new("cc");
    cc.args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-O1", "-o"])
        .arg(&exe)
        .arg(source(&format!("{name}.c")));
    if let Linking::ProcAddress = linking {
        cc.arg("-DRESOLVE_WITH_PROC_ADDRESS");
    }
    let out = cc.args(["-lOSMesa", "-lm"]).output().expect("cc runs");
    assert!(
        out.status.success(),
        "cc {name}.c failed (needs gcc and libosmesa6-dev):\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

fn render(name: &str, linking: Linking, library: Library, args: &[&str]) -> RgbaImage {
    let exe = compile(name, linking);
    let out = work_dir(name).join(format!("{linking:?}-{library:?}.ppm"));
    let mut all = vec![out.to_str().unwrap()];
    all.extend_from_slice(args);
    run(&exe, library, &all);
    read_ppm(&out)
}

/// Pixels whose largest channel is at least 100 and twice the others: the program drew
/// something of that colour (so a blank image cannot pass).
fn count_dominant(img: &RgbaImage, channel: usize) -> usize {
    img.pixels()
        .filter(|p| {
            let c = p.0[channel];
            c >= 100 && (0..3).all(|k| k == channel || u16::from(p.0[k]) * 2 <= u16::from(c))
        })
        .count()
}

/// 3/255 per channel on 99% of the pixels.
fn within_3_on_99_percent(img: &RgbaImage) -> Tolerance {
    Tolerance {
        per_channel: 3,
        max_bad_pixels: (img.width() * img.height()) as usize / 100,
    }
}

/// What a program printed on stdout, on Mesa and on the layer.
fn texts(name: &str) -> (String, String) {
    let exe = compile(name, Linking::Direct);
    let text = |library| String::from_utf8_lossy(&run(&exe, library, &[]).stdout).into_owned();
    (text(Library::Mesa), text(Library::Fixedfunc))
}

/// What a program printed and the image it wrote, on Mesa and on the layer.
fn texts_and_images(name: &str) -> [(String, RgbaImage); 2] {
    let exe = compile(name, Linking::Direct);
    let dir = work_dir(name);
    [Library::Mesa, Library::Fixedfunc].map(|library| {
        let out = dir.join(format!("{library:?}.ppm"));
        let text = run(&exe, library, &[out.to_str().unwrap()]).stdout;
        (String::from_utf8_lossy(&text).into_owned(), read_ppm(&out))
    })
}

/// Every pixel within 1/255 of Mesa's in every channel: the programs whose images the
/// layer draws as Mesa's own rasteriser does.
const WITHIN_ONE_EVERYWHERE: Tolerance = Tolerance {
    per_channel: 1,
    max_bad_pixels: 0,
};

/// The layer printed what Mesa printed, line by line (at least `min_lines` of it).
fn assert_same_text(mesa: &str, ours: &str, min_lines: usize, what: &str) {
    assert!(
        mesa.lines().count() > min_lines,
        "the program printed too little:\n{mesa}"
    );
    for (m, o) in mesa.lines().zip(ours.lines()) {
        assert_eq!(o, m, "{what} differs from Mesa's");
    }
    assert_eq!(ours.lines().count(), mesa.lines().count());
}

/// Mesa printed each of `lines`: the answers a program is built around, checked on Mesa
/// itself before the layer is compared with it.
fn assert_mesa_printed(mesa_text: &str, lines: &[&str]) {
    for line in lines {
        assert!(
            mesa_text.contains(line),
            "Mesa did not print {line:?}:\n{mesa_text}"
        );
    }
}

/// `tests/c/NAME.c` printed on Mesa each of `lines`, and on the layer what Mesa printed,
/// line by line (at least `min_lines` of it).
fn assert_prints_as_on_mesa(name: &str, lines: &[&str], min_lines: usize, what: &str) {
    let (mesa, ours) = texts(name);
    assert_mesa_printed(&mesa, lines);
    assert_same_text(&mesa, &ours, min_lines, what);
}

/// Each of the six 64×64 panels (three across, two up) shows something on Mesa.
fn assert_six_panels_drawn(mesa: &RgbaImage) {
    let background = Rgba([26, 26, 26, 255]);
    for panel in 0..6u32 {
        let (x0, y0) = ((panel % 3) * 64, 64 - (panel / 3) * 64);
        let drawn = (0..64)
            .flat_map(|y| (0..64).map(move |x| (x0 + x, y0 + y)))
            .filter(|&(x, y)| *mesa.get_pixel(x, y) != background)
            .count();
        assert!(
            drawn > 200,
            "panel {panel} is empty on Mesa ({drawn} pixels)"
        );
    }
}

#[test]
fn the_classic_osmesa_demo_renders_as_on_mesa() {
    for linking in [Linking::Direct, Linking::ProcAddress] {
        let mesa = render("osdemo", linking, Library::Mesa, &["300", "200"]);
        let ours = render("osdemo", linking, Library::Fixedfunc, &["300", "200"]);
        for channel in 0..3 {
            assert!(
                count_dominant(&mesa, channel) > 1000,
                "Mesa drew no torus, cone or sphere of channel {channel}"
            );
        }
        assert_images_match(
            &format!("osdemo-{linking:?}"),
            &ours,
            &mesa,
            within_3_on_99_percent(&mesa),
        );
    }
}

#[test]
fn errors_follow_mesa_call_by_call() {
    let (mesa, ours) = texts("errors");
    assert_same_text(&mesa, &ours, 30, "the layer's error");
}

#[test]
fn client_arrays_draw_as_on_mesa() {
    let mesa = render("arrays", Linking::Direct, Library::Mesa, &[]);
    let ours = render("arrays", Linking::Direct, Library::Fixedfunc, &[]);
    // Each panel is drawn through another path.
    assert_six_panels_drawn(&mesa);
    assert_images_match("arrays", &ours, &mesa, within_3_on_99_percent(&mesa));
}

/// The dominant-colour pixels of panel `i` (three across, two up, 64×64, panel 0 at the
/// bottom left) for each of red, green and blue.
fn panel_colours(img: &RgbaImage, i: u32) -> [usize; 3] {
    let (x0, y0) = ((i % 3) * 64, 64 - (i / 3) * 64);
    let panel = image::imageops::crop_imm(img, x0, y0, 64, 64).to_image();
    [0, 1, 2].map(|c| count_dominant(&panel, c))
}

#[test]
fn client_arrays_rewritten_in_place_draw_their_new_bytes_as_on_mesa() {
    let mesa = render("rewrites", Linking::Direct, Library::Mesa, &[]);
    let ours = render("rewrites", Linking::Direct, Library::Fixedfunc, &[]);
    assert_images_match("rewrites", &ours, &mesa, within_3_on_99_percent(&mesa));
    // What each panel must show, whatever Mesa showed: an unchanged draw repeats the
    // red triangle, each rewrite shows its new bytes.
    for img in [&mesa, &ours] {
        let [red0, ..] = panel_colours(img, 0);
        let [red1, ..] = panel_colours(img, 1);
        assert!(
            red0 > 1000 && red1 == red0,
            "panels 0 and 1: {red0} and {red1} red pixels"
        );
        let [red2, green2, _] = panel_colours(img, 2);
        assert!(
            red2 == 0 && green2 > 1000,
            "panel 2 is green after the colour rewrite"
        );
        let [_, green3, _] = panel_colours(img, 3);
        assert!(
            green3 < green2 * 3 / 4,
            "panel 3: the apex moved down ({green3} vs {green2})"
        );
        let [_, green4, _] = panel_colours(img, 4);
        assert!(
            green4 > green3,
            "panel 4: the fourth vertex widens the triangle"
        );
        let [_, _, blue5] = panel_colours(img, 5);
        assert!(
            blue5 > 50,
            "panel 5: the rewritten apex is blue ({blue5} pixels)"
        );
    }
}

#[test]
fn materials_set_inside_a_pair_light_per_vertex_as_on_mesa() {
    let (mesa, ours) = texts("materials");
    // Mesa lit the three corners with their own diffuse colours (the pixel rows differ).
    assert_mesa_printed(&mesa, &["front diffuse after       0 0 1 1"]);
    assert!(
        mesa.contains("(184, 57, 35)"),
        "the red corner is not red on Mesa:\n{mesa}"
    );
    assert_same_text(&mesa, &ours, 7, "a per-vertex material");
}

/// `tests/c/lit_colours.c`: glMaterial on colours COLOR_MATERIAL tracks leaves them the
/// current colour (and sets the others), as glGetMaterial answers and the panels drawn
/// after the tracking show; Mesa's image exactly.
#[test]
fn lit_and_fogged_colours_come_from_where_mesa_takes_them() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("lit_colours");
    assert_mesa_printed(
        &mesa_text,
        &[
            "tracking ended: front diffuse            1 0 0 1 err 0x0",
            "after the tracking                       255 0 0 255 err 0x0",
            "front diffuse tracked: front ambient     0 0 1 1 err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 20, "a lit or fogged colour");
    assert_images_match("lit_colours", &ours, &mesa, Tolerance::EXACT);
}

#[test]
fn display_lists_run_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("lists");
    assert!(
        mesa_text.contains("glCallLists through the base       0x0500"),
        "the recorded bad call raised no error on Mesa:\n{mesa_text}"
    );
    assert_eq!(
        ours_text, mesa_text,
        "glGetError and glIsList answers differ"
    );
    let lit = mesa.pixels().filter(|p| p.0[..3] != [0, 0, 0]).count();
    assert!(lit > 4000, "Mesa drew too little ({lit} pixels)");
    assert_images_match("lists", &ours, &mesa, within_3_on_99_percent(&mesa));
}

#[test]
fn state_queries_answer_as_on_mesa() {
    let (mesa, ours) = texts("state");
    assert_same_text(&mesa, &ours, 70, "the layer's answer");
}

/// glPushAttrib / glPushClientAttrib save, and the pops restore, only the groups the mask
/// names: one group, several, every group, or bits of no group.
#[test]
fn attribute_pops_restore_only_the_groups_pushed_as_on_mesa() {
    assert_prints_as_on_mesa(
        "attrib_masks",
        &["CURRENT                            color 1 1 1 viewport 3 4 20 10 fog 1"],
        18,
        "the state after a pop",
    );
}

/// Client-state calls and glListBase inside glBegin/glEnd: INVALID_OPERATION, nothing
/// changed.
#[test]
fn client_state_calls_inside_a_pair_fail_as_on_mesa() {
    let (mesa, ours) = texts("begin_client");
    assert_mesa_printed(
        &mesa,
        &["glVertexPointer(3, GL_FLOAT, 0, va)          err 0x502  pointer set 0"],
    );
    assert_same_text(
        &mesa,
        &ours,
        16,
        "the error and state after a call inside a pair",
    );
}

/// The depth and stencil buffers each OSMesaCreateContextExt size pair makes, and a
/// missing buffer's test always passing.
#[test]
fn window_depth_and_stencil_buffers_are_the_ones_mesa_makes() {
    assert_prints_as_on_mesa(
        "window_buffers",
        &[
            "ext(0, 8)      DEPTH_BITS 0 STENCIL_BITS 8 overlap 0 255 0",
            "ext(24, 0)     DEPTH_BITS 24 STENCIL_BITS 0 overlap 255 0 0 stencil NEVER 0 0 255",
        ],
        18,
        "the window's buffers",
    );
}

/// glFinish and glFlush write the caller's buffer only after something was drawn; the
/// colour bits follow the buffer's type.
#[test]
fn the_buffer_is_written_only_after_drawing_as_on_mesa() {
    assert_prints_as_on_mesa(
        "buffer_writes",
        &[
            "glFinish, nothing drawn: ab ab",
            "GL_FLOAT: bits 32 32 32 32",
        ],
        15,
        "the buffer's bytes",
    );
}

/// OSMesaMakeCurrent(NULL, NULL, …) releases the current context.
#[test]
fn making_no_context_current_releases_it_as_on_mesa() {
    assert_prints_as_on_mesa(
        "release",
        &["release: 1 current 0 buffer 0 ff"],
        6,
        "the release",
    );
}

/// OSMesaGetDepthBuffer: Mesa's layout, one pointer whose values follow glFinish.
#[test]
fn the_depth_buffer_pointer_follows_drawing_as_on_mesa() {
    assert_prints_as_on_mesa(
        "depth_buffer",
        &["  cleared to 0.75 and 0x5A: 0x5abfffff"],
        18,
        "the depth buffer's values",
    );
}

/// glRotatef about one axis: Mesa's exact 2 × 2 block.
#[test]
fn rotations_about_one_axis_are_exact_as_on_mesa() {
    let (mesa, ours) = texts("rotations");
    assert_same_text(&mesa, &ours, 40, "the rotation matrix");
}

/// A program traced with FIXEDFUNC_TRACE replays to the image it rendered, and `fixedfunc
/// shaders` reads the trace.
#[test]
fn a_trace_replays_to_the_same_image() {
    for (name, args, size) in [
        ("osdemo", vec!["120", "90"], "120x90"),
        ("arrays", vec![], "192x128"),
        ("lists", vec![], "160x160"),
    ] {
        assert_trace_replays(name, &compile(name, Linking::Direct), &args, size);
    }
}

/// The program run on the layer with FIXEDFUNC_TRACE writes a script that `replay`
/// renders to the image the program rendered (3/255 on 99%), and `shaders` reads.
fn assert_trace_replays(name: &str, exe: &Path, args: &[&str], size: &str) {
    let dir = work_dir(name);
    let (image, trace, replayed) = (
        dir.join("traced.ppm"),
        dir.join("calls.c"),
        dir.join("replayed.png"),
    );
    let mut cmd = Command::new(exe);
    cmd.arg(&image)
        .args(args)
        .env("LD_LIBRARY_PATH", fixedfunc_dir())
        .env("FIXEDFUNC_TRACE", &trace);
    let out = cmd.output().expect("the program runs");
    assert!(
        out.status.success(),
        "{name}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&trace).expect("the trace was written");
    assert!(
        text.contains(&format!("--size {size}")),
        "{name}: {text:.300}"
    );
    // A window with an accumulation buffer is replayed with one.
    let accum: &[&str] = if text.contains(&format!("--size {size} --accum")) {
        &["--accum"]
    } else {
        &[]
    };
    let replay = Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .arg("replay")
        .arg(&trace)
        .args(accum)
        .args(["--size", size, "--out"])
        .arg(&replayed)
        .output()
        .expect("fixedfunc runs");
    assert!(
        replay.status.success(),
        "{name}: replay failed: {}",
        String::from_utf8_lossy(&replay.stderr)
    );
    let traced = read_ppm(&image);
    // The PPM carries no alpha: compare colours only.
    let mut back = image::open(&replayed).expect("a PNG").to_rgba8();
    back.pixels_mut().for_each(|p| p.0[3] = 255);
    assert_images_match(
        &format!("trace-{name}"),
        &back,
        &traced,
        within_3_on_99_percent(&traced),
    );
    let shaders = Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .arg("shaders")
        .arg(&trace)
        .output()
        .expect("fixedfunc runs");
    let listing = String::from_utf8_lossy(&shaders.stdout);
    assert!(
        shaders.status.success() && listing.contains("#version 330"),
        "{name}: shaders failed: {}",
        String::from_utf8_lossy(&shaders.stderr)
    );
}

#[test]
fn buffer_objects_draw_and_fail_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("buffers");
    assert!(
        mesa_text.contains("second glMapBuffer                       0x0502"),
        "mapping a mapped buffer raised no error on Mesa:\n{mesa_text}"
    );
    assert_eq!(
        ours_text, mesa_text,
        "glGetError, glIsBuffer or glGetBufferParameteriv answers differ"
    );
    // Each panel is drawn through buffers another way.
    assert_six_panels_drawn(&mesa);
    assert_images_match("buffers", &ours, &mesa, within_3_on_99_percent(&mesa));
}

#[test]
fn framebuffer_objects_answer_and_draw_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("fbo");
    // Mesa's own answers that the program is built around.
    assert_mesa_printed(
        &mesa_text,
        &[
            "empty fbo                                0x8cd7",
            "texture without image                    0x8cd6",
            "depth only, draw buffer 0                0x8cd5",
            "fbo pixel at the overlap                 255 0 0 255",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 100, "a framebuffer answer");
    // The window shows the texture drawn through the FBO: red and green quads on blue.
    assert!(count_dominant(&mesa, 0) > 200 && count_dominant(&mesa, 1) > 200);
    assert_images_match("fbo", &ours, &mesa, within_3_on_99_percent(&mesa));
}

/// `tests/c/shadow.c` links no library: it dlopen()s libOSMesa.so.8 and resolves every
/// GL call through OSMesaGetProcAddress.
fn build_dlopen(name: &str) -> PathBuf {
    let exe = work_dir(name).join(format!("{name}-dlopen"));
    let out = Command::new("cc")
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-O1", "-o"])
        .arg(&exe)
        .arg(source(&format!("{name}.c")))
        .args(["-lm", "-ldl"])
        .output()
        .expect("cc runs");
    assert!(
        out.status.success(),
        "cc {name}.c failed (needs gcc and libosmesa6-dev):\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

#[test]
fn a_dlopened_shadow_map_program_renders_as_on_mesa_and_replays() {
    let exe = build_dlopen("shadow");
    let dir = work_dir("shadow");
    let [(mesa_text, mesa), (ours_text, ours)] = [Library::Mesa, Library::Fixedfunc].map(|lib| {
        let out = dir.join(format!("{lib:?}.ppm"));
        let text = run(&exe, lib, &[out.to_str().unwrap()]).stdout;
        (String::from_utf8_lossy(&text).into_owned(), read_ppm(&out))
    });
    // On Mesa each panel shows the box's shadow, the lit ground and the tinted box, with
    // no GL error, whether the map was copied or drawn through the FBO.
    assert_eq!(
        mesa_text.matches("shadow  lit  tinted  err 0x0").count(),
        4,
        "Mesa's panels:\n{mesa_text}"
    );
    assert_same_text(&mesa_text, &ours_text, 6, "a shadow-map panel");
    assert_images_match("shadow", &ours, &mesa, within_3_on_99_percent(&mesa));
    assert_trace_replays("shadow", &exe, &[], "128x128");
}

/// tests/c/calls.c: pixel storage, the client attribute stack, the GL 1.1 texture calls
/// (glGetTexImage's bytes with GL_PACK_ALIGNMENT, glTexSubImage1D, the 1D and 2D copies)
/// and the integer and transposed variants print what Mesa prints, line by line; the
/// framebuffer copied into a texture with glCopyTexSubImage2D and drawn back is Mesa's
/// image within 3/255 on 99%; and the program's trace replays to its image.
#[test]
fn texture_calls_client_attrib_stack_and_variants_answer_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("calls");
    assert!(
        mesa_text.contains("the 17th push                                0x0503")
            && mesa_text.contains("texel row 2                                  128 128 128 128 128 128 128 128 255 0 0 255"),
        "Mesa printed something else:\n{mesa_text}"
    );
    assert_same_text(&mesa_text, &ours_text, 80, "the layer's answer");
    // The copied quadrants fill the middle of the drawn texture: red, green, blue, yellow.
    for channel in [0, 1, 2] {
        assert!(count_dominant(&mesa, channel) > 1000, "channel {channel}");
    }
    assert_images_match("calls", &ours, &mesa, within_3_on_99_percent(&mesa));

    assert_trace_replays("calls", &compile("calls", Linking::Direct), &[], "128x128");
    let trace =
        std::fs::read_to_string(work_dir("calls").join("calls.c")).expect("the trace was written");
    assert!(
        trace.contains("glPixelStorei(GL_UNPACK_ALIGNMENT, 1);"),
        "the trace lacks the unpack alignment: {trace:.400}"
    );
}

#[test]
fn pixel_rectangles_draw_and_answer_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("pixels");
    assert!(
        mesa_text.contains("glDrawPixels negative width                  0x0501"),
        "a negative width raised no INVALID_VALUE on Mesa:\n{mesa_text}"
    );
    assert_same_text(&mesa_text, &ours_text, 25, "a query or error answer");
    // Each panel shows its rectangle on Mesa.
    assert_six_panels_drawn(&mesa);
    assert_images_match("pixels", &ours, &mesa, within_3_on_99_percent(&mesa));
}

/// GL_ABGR_EXT images (EXT_abgr, which Mesa lists and the layer now lists too) draw, read
/// and texture as on Mesa, in bytes, the four-component packed types and floats.
#[test]
fn abgr_images_draw_read_and_texture_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("abgr");
    assert_mesa_printed(
        &mesa_text,
        &[
            "GL_EXT_abgr listed                       1",
            "glReadPixels UNSIGNED_BYTE               err 0x0: 10 100 150 200",
        ],
    );
    assert_same_text(
        &mesa_text,
        &ours_text,
        12,
        "an ABGR call's error or readback",
    );
    assert_images_match("abgr", &ours, &mesa, Tolerance::EXACT);
}

/// Zoomed images show, pixel for pixel, the image pixels Mesa's show where a pixel centre
/// lies on a boundary between two of them (zoom 0.5, 1.5, 0.3 …: Mesa's rasteriser rounds
/// which one), drawn and copied, in the window and in a framebuffer object larger than
/// the window, colour, depth and stencil.
#[test]
fn zoomed_pixel_rectangles_pick_mesas_image_pixels() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("pixel_zoom");
    assert!(
        mesa_text.contains("object status                            0x8cd5"),
        "the framebuffer object was incomplete on Mesa:\n{mesa_text}"
    );
    assert_same_text(
        &mesa_text,
        &ours_text,
        5,
        "a readback of the framebuffer object",
    );
    assert_images_match("pixel_zoom", &ours, &mesa, Tolerance::EXACT);
}

/// tests/c/pixels.c traced with FIXEDFUNC_TRACE replays to the image it rendered: the
/// trace writes its raster positions, bitmaps, images (unpacked from the program's rows),
/// copies, transfer and zoom calls as the script dialect, and `replay` draws them again.
#[test]
fn a_pixels_trace_replays_to_the_same_image() {
    assert_trace_replays(
        "pixels",
        &compile("pixels", Linking::Direct),
        &[],
        "192x128",
    );
    let text =
        std::fs::read_to_string(work_dir("pixels").join("calls.c")).expect("the trace was written");
    for call in [
        "glDrawPixels(19, 12, GL_RGB",
        "glBitmap(10, 10",
        "glCopyPixels(5, 5, 19, 12, GL_COLOR)",
        "glPixelZoom(2.0, -2.0)",
    ] {
        assert!(text.contains(call), "the trace lacks {call}: {text:.400}");
    }
}

/// tests/c/pixelstore.c: every glPixelStore parameter on every reader and writer of client
/// pixels — row lengths, skips, alignments, swapped bytes, LSB-first bitmaps and stipples
/// — drawn as Mesa draws them, and the bytes glReadPixels, glGetTexImage and
/// glGetPolygonStipple write into sentinel-filled memory printed as Mesa prints them.
#[test]
fn pixel_storage_reads_and_writes_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("pixelstore");
    assert!(
        mesa_text.contains("negative UNPACK_ROW_LENGTH                   0x0501")
            && mesa_text.contains("stipple LSB first        ee ee ee ee ee ee 0f 0f"),
        "Mesa printed something else:\n{mesa_text}"
    );
    assert_same_text(
        &mesa_text,
        &ours_text,
        30,
        "a pixel-store answer or packed byte",
    );
    assert_six_panels_drawn(&mesa);
    assert_images_match("pixelstore", &ours, &mesa, within_3_on_99_percent(&mesa));
}

/// tests/c/pixelstore.c traced: the trace holds each image unpacked to tight rows, so the
/// replay, reading them with the default parameters, draws the same image.
#[test]
fn a_pixelstore_trace_replays_to_the_same_image() {
    assert_trace_replays(
        "pixelstore",
        &compile("pixelstore", Linking::Direct),
        &[],
        "192x128",
    );
    let text = std::fs::read_to_string(work_dir("pixelstore").join("calls.c"))
        .expect("the trace was written");
    assert!(
        !text.contains("GL_UNPACK_ROW_LENGTH") && text.contains("glDrawPixels(17, 20, GL_RGB"),
        "the trace is not in tight rows: {text:.400}"
    );
}

/// tests/c/buffer_types.c: GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and GL_FLOAT buffers in RGBA,
/// BGRA and ARGB, each at its own precision (RED_BITS 8, 16, 32), print the pixels Mesa's
/// OSMesa gives, to the last bit of a 16-bit component and the fourth decimal of a float.
#[test]
fn short_and_float_buffers_hold_what_mesa_writes() {
    let (mesa, ours) = texts("buffer_types");
    assert!(
        mesa.contains("RGBA float: make current 1")
            && mesa.contains("flat                     0.1000 0.2000 0.7000 1.0000"),
        "Mesa printed something else:\n{mesa}"
    );
    assert_same_text(&mesa, &ours, 40, "a pixel of a short or float buffer");
}

/// `tests/c/accum.c`: the accumulation buffer's arithmetic, errors and answers printed as
/// Mesa prints them, and its motion-blurred, scissored and masked image.
#[test]
fn the_accumulation_buffer_blurs_and_answers_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("accum");
    // Mesa's own answers that the program is built around (ff::accum's rules).
    assert_mesa_printed(
        &mesa_text,
        &[
            "no accum: glAccum                        err 0x502",
            "ACCUM_RED_BITS                           16  err 0x0",
            "fbo: glAccum                             err 0x502",
            "two frames at 0.5                        127 191 32 127  err 0x0",
            "ADD 1.5 wraps                            0 0 13 38  err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 30, "an accumulation answer");
    // The layer computes Mesa's 16-bit arithmetic exactly (measured: no pixel differs),
    // so the image is held to equality, beyond the usual 3/255 on 99%.
    let exact = Tolerance {
        per_channel: 0,
        max_bad_pixels: 0,
    };
    assert_images_match("accum", &ours, &mesa, exact);
}

/// A traced run of `tests/c/accum.c` replays (with `--accum`) to the image it rendered.
#[test]
fn an_accumulation_trace_replays_to_the_same_image() {
    let exe = compile("accum", Linking::Direct);
    assert_trace_replays("accum", &exe, &[], "64x64");
    let trace = std::fs::read_to_string(work_dir("accum").join("calls.c")).expect("a trace");
    for call in [
        "--size 64x64 --accum",
        "glAccum(GL_ACCUM, 0.125)",
        "glAccum(GL_RETURN, 1.0)",
    ] {
        assert!(trace.contains(call), "the trace lacks {call:?}");
    }
}

/// `tests/c/stipple.c`: stippled lines of every line primitive, wide, coloured, from
/// arrays, elements and a display list, and the stipple's answers and errors, printed as
/// Mesa prints them — the printed rows hold the lit bits of x-major lines, so those are
/// exact. The image is held to the usual 3/255 on 99%, not to equality: Mesa's OSMesa
/// renders its window y-flipped (Gallium's Y_0_TOP orientation for window framebuffers,
/// with the bottom edge rule), the layer into a framebuffer object as the fidelity tests'
/// native path does, and lines on exact pixel boundaries fall on other sides (measured:
/// 37 of 9216 pixels, along a vertical segment at x = 90.0 and the ends of dashes whose
/// ends lie on diamond corners; tests/fidelity_line_stipple.rs matches Mesa exactly on
/// framebuffer objects).
#[test]
fn stippled_lines_draw_and_answer_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("stipple");
    assert_mesa_printed(
        &mesa_text,
        &[
            "LINE_STIPPLE_PATTERN default             65535  err 0x0",
            "REPEAT after factor 0                    1  err 0x0",
            "REPEAT after factor 1000                 256  err 0x0",
            "glLineStipple inside glBegin             err 0x502",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 15, "a line stipple answer");
    assert_images_match("stipple", &ours, &mesa, within_3_on_99_percent(&mesa));
}

/// `tests/c/edgeflags.c`: polygons drawn in LINE and POINT mode with edges hidden by
/// glEdgeFlag, glEdgeFlagv, the current flag, GL_EDGE_FLAG_ARRAY (arrays, elements,
/// glArrayElement) and a display list, and the edge-flag answers, stacks and errors, printed
/// as Mesa prints them (the lit counts included); images within 3/255 on 99%, as the other
/// programs; and its trace replays.
#[test]
fn edge_flags_draw_and_answer_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("edgeflags");
    assert_mesa_printed(
        &mesa_text,
        &[
            "EDGE_FLAG default                        1  err 0x0",
            "CURRENT_BIT popped                       0  err 0x0",
            "glEdgeFlagv(2)                           0  err 0x0",
            "glEdgeFlagPointer stride -1              err 0x501",
            "after glInterleavedArrays                0  err 0x0",
            "polygon, current flag FALSE              0 lit  err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 25, "an edge-flag answer");
    assert_images_match("edgeflags", &ours, &mesa, within_3_on_99_percent(&mesa));
    assert_trace_replays(
        "edgeflags",
        &compile("edgeflags", Linking::Direct),
        &[],
        "128x96",
    );
}

/// `tests/c/blit.c`: glBlitFramebuffer between the window and framebuffer objects —
/// scaled NEAREST and LINEAR, flipped, scissored, of colour, depth and stencil — and its
/// errors, printed as Mesa prints them, with Mesa's image; and its trace replays.
#[test]
fn framebuffer_blits_answer_and_draw_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("blit");
    // Mesa's own answers that the program is built around (ff::blit's rules).
    assert_mesa_printed(
        &mesa_text,
        &[
            "GL_EXT_framebuffer_blit                  1",
            "incomplete read, bad mask                err 0x506",
            "bad filter and bad mask                  err 0x500",
            "LINEAR depth and bad mask                err 0x501",
            "depth D24S8 into D32F                    err 0x502",
            "stencil D24S8 into D24                   err 0x0",
            "window (2,40) outside scissor            0 0 255 255  err 0x0",
            "window (60,60) colour mask               255 0 255 255  err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 75, "a blit answer");
    assert_images_match("blit", &ours, &mesa, within_3_on_99_percent(&mesa));
    assert_trace_replays("blit", &compile("blit", Linking::Direct), &[], "64x64");
    let trace = std::fs::read_to_string(work_dir("blit").join("calls.c")).expect("a trace");
    assert!(
        trace.contains(
            "glBlitFramebuffer(0, 0, 32, 32, 32, 64, 64, 32, GL_COLOR_BUFFER_BIT, GL_LINEAR)"
        ),
        "the trace lacks the flipped LINEAR blit: {trace:.400}"
    );
}

/// `tests/c/multidraw.c`: glMultiDrawArrays and glMultiDrawElements from client arrays,
/// client index lists, an element-array buffer's offsets and a display list draw Mesa's
/// image exactly, with Mesa's errors in Mesa's order; and the trace replays. Mesa 22.3
/// draws nothing of a multi-draw whose first list is empty, and so does the layer.
#[test]
fn multi_draws_answer_and_draw_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("multidraw");
    for line in [
        "first list empty: pixels drawn           0  err 0x0",
        "arrays bad mode, drawcount -1            err 0x501",
        "elements count -1, type FLOAT            err 0x500",
        "... raised when the list runs            err 0x501",
    ] {
        assert!(
            mesa_text.contains(line),
            "Mesa did not print {line:?}:\n{mesa_text}"
        );
    }
    assert_same_text(&mesa_text, &ours_text, 26, "a multi-draw answer");
    assert_six_panels_drawn_96x64(&mesa);
    let exact = Tolerance {
        per_channel: 0,
        max_bad_pixels: 0,
    };
    assert_images_match("multidraw", &ours, &mesa, exact);
    assert_trace_replays(
        "multidraw",
        &compile("multidraw", Linking::Direct),
        &[],
        "96x64",
    );
}

/// Each of the six 32×32 panels of `multidraw.c` shows something on Mesa (more than 30
/// pixels: the sixth holds one thin triangle).
fn assert_six_panels_drawn_96x64(img: &RgbaImage) {
    let background = Rgba([26, 26, 26, 255]);
    let drawn: Vec<usize> = (0..6u32)
        .map(|panel| {
            let (x0, y0) = ((panel % 3) * 32, 32 - (panel / 3) * 32);
            (0..32)
                .flat_map(|y| (0..32).map(move |x| (x0 + x, y0 + y)))
                .filter(|&(x, y)| *img.get_pixel(x, y) != background)
                .count()
        })
        .collect();
    assert!(
        drawn.iter().filter(|n| **n > 30).count() == 6,
        "panels drawn: {drawn:?}"
    );
}

/// `tests/c/queries.c`: occlusion queries (GL 1.5, ARB_occlusion_query and
/// ARB_occlusion_query2) count the samples of immediate mode, client arrays, a display list,
/// glDrawPixels, glBitmap and glCopyPixels through the scissor, alpha, stencil and depth
/// tests as Mesa counts them, with Mesa's answers and errors; the image is Mesa's exactly, and
/// the trace replays.
#[test]
fn occlusion_queries_count_and_answer_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("queries");
    // Mesa's own answers that the program is built around (ff::queries' rules).
    assert_mesa_printed(
        &mesa_text,
        &[
            "counter bits, SAMPLES_PASSED             64  err 0x0",
            "behind, partly hidden                    768 ready 1  err 0x0",
            "stencil mark, then through it            800 ready 1  err 0x0",
            "glBitmap outline 8x8                     10 ready 1  err 0x0",
            "glCopyPixels 6x6; glClear uncounted      36 ready 1  err 0x0",
            "compiled, not run: glIsQuery             0  err 0x0",
            "begin a name never generated             err 0x0",
            "names after the deletes                  201 202  err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 50, "a query answer");
    assert_images_match("queries", &ours, &mesa, Tolerance::EXACT);
    assert_trace_replays(
        "queries",
        &compile("queries", Linking::Direct),
        &[],
        "64x64",
    );
}

/// `tests/c/smooth.c`: POINT_SMOOTH and LINE_SMOOTH as Mesa's draw module draws them —
/// round points of every size with the aapoint stage's alpha factor (above 1 inside the
/// inner circle, so translucent points brighten there and pass an alpha test their colour
/// fails), through the depth test and in polygon POINT mode; smooth lines of widths 1 to 4,
/// strips, loops, translucent, in polygon LINE mode and from a display list. Mesa's image
/// exactly, Mesa's limits and state, and the trace replays.
#[test]
fn smooth_points_and_lines_draw_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("smooth");
    assert_mesa_printed(
        &mesa_text,
        &[
            "SMOOTH_POINT_SIZE_RANGE                  1 255  err 0x0",
            "SMOOTH_LINE_WIDTH_RANGE                  1 255  err 0x0",
            "after glPopAttrib                        0 0  err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 6, "a smooth-point answer");
    // Every 32×32 panel of Mesa's image shows its case: pixels away from the background.
    let background = mesa.get_pixel(0, 0).0;
    for row in 0..4 {
        for col in 0..4 {
            let drawn = (0..32 * 32)
                .filter(|i| {
                    let p = mesa.get_pixel(col * 32 + i % 32, row * 32 + i / 32).0;
                    (0..3).any(|k| p[k].abs_diff(background[k]) > 30)
                })
                .count();
            assert!(drawn >= 20, "panel ({col}, {row}) of Mesa's image is empty");
        }
    }
    assert_images_match("smooth", &ours, &mesa, Tolerance::EXACT);
    assert_trace_replays(
        "smooth",
        &compile("smooth", Linking::Direct),
        &[],
        "128x128",
    );
}

/// `tests/c/point_params.c`: glPointParameter's attenuation, size limits and fade
/// threshold cover Mesa's pixels, point by point, aliased and smooth, with Mesa's errors
/// and answers; a field of attenuated points in perspective is Mesa's image within 1/255,
/// and the trace replays.
#[test]
fn point_parameters_size_points_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("point_params");
    assert_mesa_printed(
        &mesa_text,
        &[
            "max 4 no atten: 16 err 0",
            "atten quad z -1.5: 225",
            "fade 20: 36 max 255",
            "smooth atten size1 z -6: 1",
            "min -1 err 501",
            "bad pname err 500",
            "pop min 8",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 25, "a point-parameter answer");
    assert_images_match("point_params", &ours, &mesa, WITHIN_ONE_EVERYWHERE);
    assert_trace_replays(
        "point_params",
        &compile("point_params", Linking::Direct),
        &[],
        "64x64",
    );
}

/// `tests/c/point_edges.c`: aliased points cover the pixels of llvmpipe's rule for legacy
/// points — centres at every 1/512 pixel across two pixels for sides 1 to 6, points whose
/// centre lies on the right or top plane of a viewport smaller than the buffer (drawn
/// beyond it, where a square clipped by its centre would lose them or move them in), the
/// corners of triangles in POINT mode and those clipping makes, the same under distance
/// attenuation: Mesa's image pixel for pixel, and the trace replays.
#[test]
fn points_at_pixel_ties_and_view_volume_planes_cover_mesas_pixels() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("point_edges");
    assert_mesa_printed(
        &mesa_text,
        &[
            "side 5 from 0.0 at 1/512 steps lit 800",
            "planes at (  8,  64) attenuated 0 lit 129",
            "polygon points side 3          lit 75",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 18, "a count of lit pixels");
    assert_images_match("point_edges", &ours, &mesa, Tolerance::EXACT);
    assert_trace_replays(
        "point_edges",
        &compile("point_edges", Linking::Direct),
        &[],
        "256x256",
    );
}

/// `tests/c/edge_strips.c`: edge flags hide edges of triangle strips, triangle fans and
/// quad strips as on Mesa, whose draw module flags the triangles it cuts strips and fans
/// into (GL 1.5 §2.6.2 would draw every edge of strips and fans: a deviation of Mesa's
/// the layer follows) — each flag cleared in turn through glBegin/glEnd, edge-flag arrays
/// drawn and indexed, blended POINT mode drawing a vertex once per triangle, the current
/// flag FALSE, separate front and back modes, a stippled outline, flat colours. Every
/// printed count is Mesa's; the image is within 3/255 on 99% of pixels (a quad strip's
/// corner where two flagged edges meet takes the colour of the other edge: the layer
/// draws a quad strip's two triangles in the other order, the one its filled quads need).
#[test]
fn edge_flags_hide_edges_of_strips_and_fans_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("edge_strips");
    assert_mesa_printed(
        &mesa_text,
        &[
            "strip      flag 1 cleared      lit 154",
            "fan        current flag FALSE  lit 0",
            "quad strip flag 1 cleared      lit 109",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 39, "a count of lit pixels");
    assert_images_match("edge_strips", &ours, &mesa, within_3_on_99_percent(&mesa));
    assert_trace_replays(
        "edge_strips",
        &compile("edge_strips", Linking::Direct),
        &[],
        "256x256",
    );
}

/// `tests/c/cube_fbo.c`: each face of a cube map attached to a framebuffer object by its
/// own textarget (EXT_framebuffer_object takes a face in the 2D call), complete, its face
/// answered by FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, cleared and drawn into; a 2D
/// texture named as a face, a cube map named as a 2D texture and a face through the 1D call
/// refused as on Mesa; the faces read back and sampled by direction in the window: every
/// printed line as Mesa's, the image pixel for pixel, and the trace replays.
#[test]
fn cube_map_faces_are_rendered_to_through_framebuffer_objects_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("cube_fbo");
    assert_mesa_printed(
        &mesa_text,
        &[
            "face 2 attached err 0x0 status 0x8cd5 face 0x8517 name 1",
            "face 5 drawn          pixel 255   0 255 255 err 0x0",
            "a face through the 1D call               err 0x502",
            "face 3 read back       corner 128 128   0 inside 255 255   0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 22, "a face's answer");
    assert_images_match("cube_fbo", &ours, &mesa, Tolerance::EXACT);
    assert_trace_replays(
        "cube_fbo",
        &compile("cube_fbo", Linking::Direct),
        &[],
        "96x64",
    );
}

/// `tests/c/secondary.c`: GL 1.4's secondary colour and fog coordinate through every
/// front door (immediate mode, client arrays, a buffer object, glArrayElement, a display
/// list) with Mesa's errors, conversions and answers — FOG_COORD_SRC left as it is by
/// glPopAttrib, the raster distance under each source — and eleven panels (the colour sum
/// unlit, flat, textured and under lighting, fog by coordinate and by depth, stippled
/// lines and points, glBitmap and glDrawPixels) drawn as Mesa draws them within 1/255; the
/// trace replays.
#[test]
fn secondary_colours_and_fog_coordinates_draw_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("secondary");
    assert_mesa_printed(
        &mesa_text,
        &[
            "secondary initial                  0 0 0 1 err 0",
            "secondary 3ub                      1 0.501961 0 1 err 0",
            "fog coord as int                         4  err 0x0",
            "fog coord src ZERO                       err 0x500",
            "secondary pointer size 2 err 501",
            "fog coord pointer type 1400 err 500",
            "pop fog src                              33873  err 0x0",
            "raster distance fog coord          -5 -7 -7 -7 err 0",
            "window pos distance fog coord      -5 -7 -7 -7 err 0",
            "secondary after element            0 1 0 0.784314 err 0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 80, "a secondary-colour answer");
    assert_images_match("secondary", &ours, &mesa, WITHIN_ONE_EVERYWHERE);
    assert_trace_replays(
        "secondary",
        &compile("secondary", Linking::Direct),
        &[],
        "96x96",
    );
}

/// `tests/c/color_index.c`: colour-index state (glIndex*, glClearIndex, glIndexMask,
/// glIndexPointer with glArrayElement) and multisample coverage (glSampleCoverage, the
/// sample enables) kept, converted, grouped and refused as Mesa keeps them in an RGBA
/// context — the clear index truncated to an unsigned integer and restored through a
/// float — and a frame drawn with all of it set, Mesa's image exactly; the trace replays.
#[test]
fn colour_index_and_coverage_state_answer_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("color_index");
    assert_mesa_printed(
        &mesa_text,
        &[
            "index initial                  1 err 0",
            "index 3.7 as int                         4  err 0x0",
            "clear index 2.6                2 err 0",
            "pop clear index -1 changed     0 err 0",
            "index pointer type 1400 err 500",
            "interleaved index array                  0  err 0x0",
            "coverage NaN                   0 err 0",
            "coverage inside glBegin                  err 0x502",
            "pop enable alpha to one                  1  err 0x0",
        ],
    );
    assert_same_text(
        &mesa_text,
        &ours_text,
        60,
        "a colour-index or coverage answer",
    );
    assert_images_match("color_index", &ours, &mesa, Tolerance::EXACT);
    assert_trace_replays(
        "color_index",
        &compile("color_index", Linking::Direct),
        &[],
        "32x32",
    );
}

/// `tests/c/transfer.c`: the pixel transfer on texture images, copies and reads (scales,
/// biases, MAP_COLOR by the nearest entry; none on glGetTexImage nor on depth images) and
/// texture images whose client format differs from their internal one, texel by texel as
/// Mesa stores them, and the panels drawn with each, Mesa's image exactly; the trace
/// replays.
#[test]
fn pixel_transfers_reach_texture_images_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("transfer");
    assert_mesa_printed(
        &mesa_text,
        &[
            "teximage scaled and biased         100 226 200 255 err 0",
            "teximage mapped                    64 128 191 255 err 0",
            "readpixels mapped                  64 128 128 255 err 0",
            "depth teximage 0.5 err 0",
            "alpha into rgba                    0 0 0 100 err 0",
            "copy into alpha                    0 0 0 204 err 0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 20, "a transferred texel");
    assert_images_match("transfer", &ours, &mesa, Tolerance::EXACT);
    assert_trace_replays(
        "transfer",
        &compile("transfer", Linking::Direct),
        &[],
        "64x32",
    );
}

/// `tests/c/buffer_values.c`: what glClear leaves under glDepthMask and glStencilMask with
/// the tests off, what stencil images and colours drawn through MAP_COLOR leave, and what
/// glReadPixels gives of stencil indices through the index arithmetic and MAP_STENCIL, of
/// depths in every integer type and of alpha alone (and refuses colour indices), and the
/// depths unsigned bytes draw, line by line as Mesa prints it; Mesa's image exactly.
#[test]
fn buffer_values_are_written_and_read_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("buffer_values");
    assert_mesa_printed(
        &mesa_text,
        &[
            "masked clear, tests off                  stencil 0x35 depth 0.25 err 0x0",
            "draw stencil ubyte                       0 37 200 255 err 0x0",
            "read stencil, shift -1                   50 50 50 50 err 0x0",
            "read depth 0.5                           63 16383 1073741951 127 32768 2147483776 err 0x0",
            "read alpha 231/255                       231 0xe7e7 0xe7e7e7e7 0.905882418 err 0x0",
            "draw mapped, red 131 green 127           230 128 | 230 128 | 230 128 | 230 128",
            "draw depth ubyte 97                      0x61616261",
            "read COLOR_INDEX                         err 0x502",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 25, "a buffer value");
    assert_images_match("buffer_values", &ours, &mesa, Tolerance::EXACT);
}

/// `tests/c/outline.c`: stippled outlines — polygons in LINE mode under LINE_STIPPLE, every
/// polygon primitive type, smooth and flat, edge flags, culling, separate front and back
/// modes, wide lines, a hidden-line pass over polygon offset — light as many pixels per
/// panel as on Mesa and draw Mesa's image but for dash ends one pixel apart at four
/// corners (the same dashes drawn as a GL_LINE_LOOP differ from Mesa's alike: the line
/// stipple's own deviation, not the outline's order); the trace replays.
#[test]
fn stippled_outlines_draw_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("outline");
    assert_mesa_printed(
        &mesa_text,
        &[
            "line mode with stipple                   err 0x0",
            "quads 60",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 12, "a stippled outline");
    assert_images_match(
        "outline",
        &ours,
        &mesa,
        Tolerance {
            per_channel: 1,
            max_bad_pixels: 8,
        },
    );
    assert_trace_replays(
        "outline",
        &compile("outline", Linking::Direct),
        &[],
        "128x96",
    );
}

/// `tests/c/tex3d.c`: GL 1.2's 3D textures — glTexImage3D, glTexSubImage3D,
/// glCopyTexSubImage3D, PROXY_TEXTURE_3D, the image pixel-store parameters, mipmaps,
/// display lists and glFramebufferTexture3D answer and fail as on Mesa; panels sampling
/// a volume by r, between images, through texgen R in perspective, wrapped, minified,
/// patched and drawn into are Mesa's image exactly, and the trace replays.
#[test]
fn volumes_answer_and_draw_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("tex3d");
    assert_mesa_printed(
        &mesa_text,
        &[
            "GL_EXT_texture3D listed                  1",
            "MAX_3D_TEXTURE_SIZE                      2048  err 0x0",
            "level 1 width 2048                       err 0x501",
            "a depth format                           err 0x502",
            "proxy TEXTURE_WIDTH                      0  err 0x0",
            "packed with image height 3, skip 1       238 238 238 238 238 238 8 9 10 11 238 238 14 4 16 5 238 238 238 238",
            "proxy width while compiling              16  err 0x0",
            "what the list gave                       40 1 2 3 4 5 6 7",
            "status                                   0x8cd6",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 100, "a 3D texture answer");
    // Every panel of the two bottom rows of Mesa's image shows a texture, not the
    // background.
    let background = mesa.get_pixel(0, 0).0;
    for row in 0..2 {
        for col in 0..8 {
            let p = mesa.get_pixel(col * 16 + 8, 63 - (row * 16 + 8)).0;
            assert!(
                (0..3).any(|k| p[k].abs_diff(background[k]) > 30),
                "panel ({col}, {row}) of Mesa's image is empty"
            );
        }
    }
    assert_images_match("tex3d", &ours, &mesa, Tolerance::EXACT);
    assert_trace_replays("tex3d", &compile("tex3d", Linking::Direct), &[], "128x64");
}

/// `tests/c/cubemap.c`: GL 1.3's cube maps — the face targets of the 2D image calls,
/// TEXTURE_BINDING_CUBE_MAP, MAX_CUBE_MAP_TEXTURE_SIZE, the enable on the attribute
/// stack, REFLECTION_MAP and NORMAL_MAP — answer and fail as on Mesa; panels sampling
/// faces by direction, over a 2D texture, by texgen on lit spheres, with a negative q,
/// incomplete, patched and minified are Mesa's image within 3/255 on 99% of pixels (a
/// lit sphere's silhouette pixel differs by a face), and the trace replays.
#[test]
fn cube_maps_answer_and_draw_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("cubemap");
    assert_mesa_printed(
        &mesa_text,
        &[
            "MAX_CUBE_MAP_TEXTURE_SIZE                16384  err 0x0",
            "glTexImage2D(TEXTURE_CUBE_MAP)           err 0x500",
            "glBindTexture(a face)                    err 0x500",
            "a 2x4 face                               err 0x501",
            "glGetTexImage(-Z)                        255 0 255  err 0x0",
            "glCopyTexImage2D(+Y) 2x4                 err 0x501",
            "Q REFLECTION_MAP                         err 0x500",
            "R TEXTURE_GEN_MODE                       0x8511  err 0x0",
            "glGenerateMipmap, faces differ           err 0x502",
            "panels                                   err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 40, "a cube map answer");
    // Each of Mesa's eight 32×32 panels shows something other than the background at
    // its centre.
    let background = [26, 26, 26];
    for panel in 0..8u32 {
        let (x, y) = ((panel % 4) * 32 + 16, 63 - ((panel / 4) * 32 + 16));
        let p = mesa.get_pixel(x, y).0;
        assert!(
            (0..3).any(|k| p[k].abs_diff(background[k]) > 20),
            "panel {panel} of Mesa's image is empty"
        );
    }
    assert_images_match("cubemap", &ours, &mesa, within_3_on_99_percent(&mesa));
    assert_trace_replays(
        "cubemap",
        &compile("cubemap", Linking::Direct),
        &[],
        "128x64",
    );
}

/// `tests/c/formats.c`: GL 1.0's component counts and GL 1.1's sized internal formats in
/// glTexImage2D, and GL 1.4's MIRRORED_REPEAT, sample as on Mesa (texels exact in 4 bits),
/// with Mesa's errors (a component count in glCopyTexImage2D is INVALID_ENUM); Mesa's
/// image exactly; the trace replays.
#[test]
fn internal_formats_of_every_era_sample_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("formats");
    assert_mesa_printed(
        &mesa_text,
        &[
            "component count 3            221 34 153 255 err 0",
            "component count 5                        err 0x501",
            "mirrored repeat linear       175 62 153 255 err 0",
            "copy with component count 4              err 0x500",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 15, "a texel");
    assert_images_match("formats", &ours, &mesa, Tolerance::EXACT);
    assert_trace_replays(
        "formats",
        &compile("formats", Linking::Direct),
        &[],
        "64x32",
    );
}

/// `tests/c/stored_bits.c`: glGetTexImage in wide types reads what the texture stores —
/// packed 4-, 5-, 3-, 10-bit fields through Mesa's floats (an RGB5 alpha of 1.0 as
/// UNSIGNED_INT wraps to 0), 16-bit components widened as integers — and an RGBA32F
/// framebuffer reads as INT with Mesa's float packing, every value Mesa's.
#[test]
fn textures_of_other_than_8_bits_read_back_as_on_mesa() {
    let (mesa, ours) = texts("stored_bits");
    assert_mesa_printed(
        &mesa,
        &["RGBA32F read as INT                      err 0x0: -2147483648 1145252992 214748368 0"],
    );
    assert_same_text(&mesa, &ours, 80, "a texel read back");
}

/// `tests/c/pixel_types.c`: GL 1.0's signed types, GL 1.2's packed types and BGR/BGRA,
/// into textures and glDrawPixels and out of glReadPixels and glGetTexImage, with the
/// pairs each call refuses; every byte as Mesa gives it (its 5-bit fields widened by
/// repeating their bits, 8-bit storage narrowed and widened by its integer rules), Mesa's
/// image exactly, and the trace replays.
#[test]
fn signed_packed_and_bgra_pixels_convert_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("pixel_types");
    assert_mesa_printed(
        &mesa_text,
        &[
            "5_6_5                      000OOOOOOOOOOOOOOO",
            "internal format BGRA                     err 0x501",
            "RGBA byte                  0 0 0 0 2 126 129 255 201 0 64 193 0 255 255 255 err 0",
            "in 5_5_5_1                 107 140 24 255 181 214 66 255 0 24 107 255 74 66 148 255 err 0",
            "read RGBA int              ff ff ff 7f 00 00 00 00 40 40 40 40 ff ff ff 7f err 0",
            "texture LUMINANCE 5_6_5                  err 0x502",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 70, "a converted pixel");
    assert_images_match("pixel_types", &ours, &mesa, Tolerance::EXACT);
    assert_trace_replays(
        "pixel_types",
        &compile("pixel_types", Linking::Direct),
        &[],
        "64x32",
    );
}

/// `tests/c/compressed.c`: S3TC blocks of every decoded format uploaded with
/// glCompressedTexImage2D, decoded texel for texel as Mesa decodes them and given back as
/// given; the level queries, sub-images, display lists, the compression hint and 30 errors
/// as Mesa answers them; Mesa's image exactly; the trace replays.
#[test]
fn compressed_textures_decode_and_answer_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("compressed");
    assert_mesa_printed(
        &mesa_text,
        &[
            "listed DXT1 1 DXT3 1 DXT5 1 err 0",
            "hint popped                              4354  err 0x0",
            "sub-image at (2, 0)                      err 0x502",
            "border 1                                 err 0x502",
            "the list run                             err 0x501",
            "the list's image               compressed 1 size 32 format 0x83f1 bits 4 4 err 0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 85, "a compressed-texture answer");
    assert_images_match("compressed", &ours, &mesa, Tolerance::EXACT);
    assert_trace_replays(
        "compressed",
        &compile("compressed", Linking::Direct),
        &[],
        "64x32",
    );
}

/// `tests/c/quad_splits.c`: the diagonal of GL_QUADS as Mesa splits them — (v0,v1,v2),
/// (v0,v2,v3) for smooth quads drawn directly, (v0,v1,v3),(v1,v2,v3) for quads from a
/// display list and for flat-shaded ones (`emulate::assembly`, `ff::lists`); the sampled
/// grey levels printed as Mesa prints them, images within 3/255 on all but 0.2% of pixels.
#[test]
fn quads_split_along_mesas_diagonal_in_lists_and_under_flat_shading() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("quad_splits");
    assert_mesa_printed(
        &mesa_text,
        &[
            "smooth, glBegin/glEnd        below  64  64  64  above   0   0   0  lit  780  err 0x0",
            "smooth, list of glBegin      below 150 150 150  above  86  86  86  lit 1600  err 0x0",
            "flat bow-tie, glDrawArrays   below 255 255   0  above 255 255   0  lit 1200  err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 7, "a quad's split");
    let strict = Tolerance {
        per_channel: 3,
        max_bad_pixels: (mesa.width() * mesa.height()) as usize / 500,
    };
    assert_images_match("quad_splits", &ours, &mesa, strict);
}

/// `tests/c/conversions.c`: glColor of every integer type read back as exact floats and
/// integers (Mesa's single-precision macros, `CType::normalized`), signed colour arrays
/// fetched as SNORM (a zero byte stays zero, `CType::normalized_array`), and NaN line
/// widths and point sizes kept (NaN is not ≤ 0): printed as Mesa prints them, bit for bit.
#[test]
fn integer_colours_and_nan_sizes_convert_as_on_mesa() {
    let (mesa_text, ours_text) = texts("conversions");
    assert_mesa_printed(
        &mesa_text,
        &[
            "GL_BYTE array            255   0 129   0  err 0x0",
            "glLineWidth(NaN)         nan  err 0x0",
            "glPointSize(-1)          nan  err 0x501",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 13, "a converted value");
}

/// `tests/c/wide_viewport.c`: wide points (square and smooth) and wide lines at the edge of
/// a viewport smaller than the buffer are drawn whole beyond it, as on Mesa (the size goes
/// to glPointSize, not gl_PointSize, `uniform_point_size`); a point whose centre lies
/// outside is not drawn; a viewport beyond MAX_VIEWPORT_DIMS is clamped. Counts, bounding
/// boxes and the viewport printed as Mesa prints them.
#[test]
fn wide_points_and_lines_reach_beyond_a_small_viewport_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("wide_viewport");
    assert_mesa_printed(
        &mesa_text,
        &[
            "size 7 on the corner           49 lit  [36,36]-[42,42]  err 0x0",
            "size 7, centre outside          0 lit  [64,64]-[-1,-1]  err 0x0",
            "width 7 along the left edge    70 lit  [16,25]-[22,34]  err 0x0",
            "viewport 100000 x 70000      -5 -6 16384 16384  err 0x0",
        ],
    );
    assert_same_text(
        &mesa_text,
        &ours_text,
        7,
        "a wide point or line, or the viewport",
    );
    assert_images_match("wide_viewport", &ours, &mesa, within_3_on_99_percent(&mesa));
}

/// `tests/c/eval_enables.c`: glEnable(AUTO_NORMAL) and the MAPn_* enables of an era's init
/// code are kept without an error, answered by glIsEnabled and glGetBooleanv and restored by
/// ENABLE_BIT and EVAL_BIT, as Mesa answers (evaluating is left out).
#[test]
fn evaluator_enables_are_kept_and_answered_as_on_mesa() {
    let (mesa_text, ours_text) = texts("eval_enables");
    assert_mesa_printed(
        &mesa_text,
        &[
            "glEnable(AUTO_NORMAL)                    err 0x0",
            "AUTO_NORMAL after EVAL_BIT           1 1  err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 13, "an evaluator enable");
}

/// `tests/c/line_ends.c`: lines whose ends lie exactly on pixel centres or corners, in
/// every direction and width, light the pixels Mesa's OSMesa lights — its buffer is a
/// window-system one, rasterised upside down in memory, and the layer draws into a pbuffer
/// of the same kind (`abi::context`) — with smooth points' ties alike. Each case's lit
/// pixels (count and hash) printed as Mesa prints them, bit for bit; the trace replays
/// (`fixedfunc replay` draws into a window-system buffer too).
#[test]
fn lines_with_ends_on_pixel_centres_light_mesas_pixels() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("line_ends");
    assert_mesa_printed(
        &mesa_text,
        &[
            "down at 10.5                     lit   10  hash 5dfb1074eeb11773  err 0x0",
            "left at 10                       lit    9  hash 3c529a40747e5726  err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 29, "a line's pixels");
    let exact = Tolerance {
        per_channel: 3,
        max_bad_pixels: 0,
    };
    assert_images_match("line_ends", &ours, &mesa, exact);
    assert_trace_replays(
        "line_ends",
        &compile("line_ends", Linking::Direct),
        &[],
        "64x64",
    );
}

/// `tests/c/array_enables.c`: glEnable/glDisable of VERTEX_ARRAY … SECONDARY_COLOR_ARRAY
/// act as glEnableClientState/glDisableClientState without an error, as Mesa's
/// compatibility context takes them (GL 1.5 names only the ClientState calls), in and out
/// of display lists, restored by the client attribute stack and not by ENABLE_BIT; the
/// triangle drawn from an array enabled so matches Mesa's image.
#[test]
fn client_array_tokens_in_gl_enable_act_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("array_enables");
    assert_mesa_printed(
        &mesa_text,
        &[
            "glEnable(0x8074)                         err 0x0",
            "glDrawArrays from the enabled array      err 0x0",
            "COLOR_ARRAY after glCallList             1  err 0x0",
            "glEnable(NORMAL_ARRAY) in glBegin        err 0x502",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 30, "a client array's enable");
    assert_images_match("array_enables", &ours, &mesa, within_3_on_99_percent(&mesa));
}

/// `tests/c/clear_depth.c`: glClearDepth keeps its double, as Mesa does: the cleared depth
/// (0.3 clears a 24-bit buffer to 0x4CCCCC, not the 0x4CCCCD of 0.3 as a float) and
/// DEPTH_CLEAR_VALUE through every getter, printed as Mesa prints them, bit for bit.
#[test]
fn clear_depth_is_kept_as_a_double_as_on_mesa() {
    assert_prints_as_on_mesa(
        "clear_depth",
        &["glClearDepth(0.29999999999999999)  cleared 0x4ccccc4c  double 0.29999999999999999  float 0.300000012  int 644245094  err 0x0"],
        8,
        "a cleared depth or its query",
    );
}

/// `tests/c/stencil_clears.c`: a clear of depth alone keeps the window's stencil values as
/// they are — after stencil-tested draws, scissored and masked stencil clears, full ones,
/// a STENCIL_INDEX rectangle and its copy, a framebuffer object's own draws, a new buffer —
/// while the layer clears depth and stencil together where the stencil holds one value
/// (`pipeline::emulate::stencil_contents`): every stencil and depth value as Mesa's.
#[test]
fn depth_clears_keep_the_stencil_as_on_mesa() {
    assert_prints_as_on_mesa(
        "stencil_clears",
        &[
            "  cleared depth 0.25               stencil   5   5   5   5   5   5   0   0   0   0   0   0   0   0   0   0  depth 40000040 40000040  err 0x0",
            "  cleared depth 1.00               stencil   7   7   7   7   7   7   7   7   9   9   9   9   7   7   7   7  depth ffffffff ffffffff  err 0x0",
        ],
        22,
        "a stencil or depth value",
    );
}

/// `tests/c/proc_aliases.c`: OSMesaGetProcAddress finds the extension names the registry
/// makes aliases of GL 1.x calls (glBlendEquationEXT, glActiveTextureARB …), as Mesa's
/// does, and calling through them is calling the core function.
#[test]
fn extension_names_of_core_calls_resolve_as_on_mesa() {
    assert_prints_as_on_mesa(
        "proc_aliases",
        &[
            "glBlendEquationEXT           found",
            "BLEND_EQUATION 0x8008  TEXTURE_BINDING_2D 5  err 0x0",
        ],
        26,
        "an extension name's address or effect",
    );
}

/// `tests/c/read_outside.c`: glReadPixels of rectangles reaching beyond the window, or
/// beyond a framebuffer object's smallest attachment, write only the pixels inside, under
/// every pack layout, as Mesa's OSMesa clips the read; the memory of the pixels outside
/// keeps what the program put there (GL leaves it undefined).
#[test]
fn reads_beyond_the_window_leave_the_memory_outside_as_on_mesa() {
    assert_prints_as_on_mesa(
        "read_outside",
        &[
            "top right corner                   hash 7aeaf9aedf7312bb  err 0x0  rows: ff0000ff ff0000ff eeeeeeee eeeeeeee",
            "object: top right corner           hash bbaf9437580bc939  err 0x0  rows: 0000ffff eeeeeeee eeeeeeee eeeeeeee",
        ],
        13,
        "a read beyond the window",
    );
}

/// A `Cpus_allowed_list` ("0-3,6") as the CPUs it names.
fn cpu_list(list: &str) -> Vec<usize> {
    let mut cpus = Vec::new();
    for part in list.split(',').filter(|p| !p.is_empty()) {
        let (a, b) = part.split_once('-').unwrap_or((part, part));
        let (a, b): (usize, usize) = (a.trim().parse().unwrap(), b.trim().parse().unwrap());
        cpus.extend(a..=b);
    }
    cpus
}

/// `tests/c/raster_threads.c` run with `placement` as FIXEDFUNC_RASTER_THREADS (unset for
/// None): the process's CPUs and, for each llvmpipe rasterizer thread k, (k, its CPUs).
fn rasterizer_cpus(
    library: Library,
    placement: Option<&str>,
) -> (Vec<usize>, Vec<(usize, Vec<usize>)>) {
    let exe = compile("raster_threads", Linking::Direct);
    let mut cmd = Command::new(&exe);
    match library {
        Library::Fixedfunc => cmd.env("LD_LIBRARY_PATH", fixedfunc_dir()),
        Library::Mesa => cmd.env_remove("LD_LIBRARY_PATH"),
    };
    match placement {
        Some(p) => cmd.env("FIXEDFUNC_RASTER_THREADS", p),
        None => cmd.env_remove("FIXEDFUNC_RASTER_THREADS"),
    };
    let out = cmd.output().expect("the program runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    let mut process = None;
    let mut threads = Vec::new();
    for line in text.lines() {
        let (name, list) = line.split_once(' ').unwrap_or((line, ""));
        match name.strip_prefix("llvmpipe-") {
            Some(k) => threads.push((k.parse().unwrap(), cpu_list(list))),
            None if name == "process" => process = Some(cpu_list(list)),
            None => panic!("unexpected line {line:?}"),
        }
    }
    (process.expect("the process's CPUs are printed"), threads)
}

/// The layer binds llvmpipe's rasterizer thread k to the k-th CPU the process may use
/// (`gpu::raster_threads`), so a frame's bins are drawn on every CPU at once, where the
/// kernel may queue two rasterizers on one CPU; Mesa's OSMesa, and the layer under
/// FIXEDFUNC_RASTER_THREADS=kernel, leave every thread free to run anywhere.
#[test]
fn rasterizer_threads_are_bound_one_per_cpu_unless_left_to_the_kernel() {
    let (cpus, spread) = rasterizer_cpus(Library::Fixedfunc, None);
    if cpus.len() >= 2 {
        assert!(
            !spread.is_empty(),
            "llvmpipe makes rasterizer threads on {cpus:?}"
        );
        for (k, on) in &spread {
            assert_eq!(
                on,
                &vec![cpus[k % cpus.len()]],
                "llvmpipe-{k} on its own CPU"
            );
        }
    }
    for (library, placement) in [(Library::Fixedfunc, Some("kernel")), (Library::Mesa, None)] {
        let (cpus, threads) = rasterizer_cpus(library, placement);
        for (k, on) in &threads {
            assert_eq!(
                on, &cpus,
                "llvmpipe-{k} free on {library:?} ({placement:?})"
            );
        }
    }
}

/// `tests/c/float_params.c`: float and non-finite parameters as Mesa 22.3 takes them — a
/// NaN passes the range checks of the spot and attenuation values and SHININESS and reads
/// back NaN, a NaN alpha reference and priority read back 0, glPixelStoref converts as
/// `(GLint) lroundf`, a token with a fraction is rounded by glTexParameterf, truncated by the
/// vector forms and refused by glLightModelf, and the vector forms of scalar parameters
/// (glTexGeniv(TEXTURE_GEN_MODE), glLightModelfv(TWO_SIDE)) are taken; every line as Mesa
/// prints it, and the quads lit under a NaN spot cutoff, spot exponent, shininess and
/// attenuation as Mesa draws them.
#[test]
fn float_and_nonfinite_parameters_are_taken_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("float_params");
    assert_mesa_printed(
        &mesa_text,
        &[
            "glLightf(SPOT_CUTOFF, nan)             err 0x0  reads nan",
            "glMaterialf(SHININESS, NaN)              err 0x0",
            "ALPHA_TEST_REF after NaN (int)           0  err 0x0",
            "glPixelStoref(UNPACK_ROW_LENGTH, 5e+09)  err 0x0  reads 705032704",
            "glTexParameterf WRAP_S +0.50  err 0x500 0x2901  fv err 0x0 0x812f",
            "TEXTURE_GEN_MODE S 0x2402 T 0x2401 R 0x2400",
            "LIGHT_MODEL_TWO_SIDE                     1  err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 60, "a float parameter's effect");
    assert_images_match("float_params", &ours, &mesa, within_3_on_99_percent(&mesa));
}

/// `tests/c/matrices.c`: the matrix commands' arithmetic is Mesa's to the bit — glRotatef
/// about axis-aligned and general axes at angles of every size (a rotation by −77.7° about
/// a general axis differed in the last bits when built by GL's formula rather than Mesa's),
/// glScalef's −0 in the bottom row, chains through the double variants, glFrustum,
/// glOrtho and glMultMatrix — and non-finite values keep or spread NaN as Mesa's affine
/// and full products do, Mesa's gathered type flags included.
#[test]
fn matrix_commands_compute_as_mesa_does() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("matrices");
    assert_mesa_printed(
        &mesa_text,
        &[
            "rot NaN                      nan nan nan 0x0p+0 nan nan nan 0x0p+0 0x0p+0 0x0p+0 0x1p+0 0x0p+0 0x0p+0 0x0p+0 0x0p+0 0x1p+0",
            "load, identity, rot NaN      nan nan nan nan nan nan nan nan 0x0p+0 0x0p+0 0x1p+0 0x0p+0 0x0p+0 0x0p+0 0x0p+0 0x1p+0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 115, "a matrix");
    assert_images_match("matrices", &ours, &mesa, within_3_on_99_percent(&mesa));
}

/// `tests/c/anisotropy.c`: EXT_texture_filter_anisotropic as Mesa 22.3 has it — named in
/// the extension string, a maximum of 16, a value below 1 INVALID_VALUE, one above the
/// maximum and a NaN clamped to it, the integer query rounded, every target, restored by
/// glPopAttrib(TEXTURE_BIT) — and a checkerboard floor at a grazing angle sampled with
/// anisotropy 1, 4 and 16 as Mesa samples it, within 1/255; the trace replays.
#[test]
fn anisotropic_filtering_is_taken_and_drawn_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("anisotropy");
    assert_mesa_printed(
        &mesa_text,
        &[
            "extension named 1",
            "maximum 16 16 err 0x0",
            "0.5                      err 0x501 float 1 int 1",
            "2.7                      err 0x0 float 2.7 int 3",
            "NaN                      err 0x0 float 16 int 16",
            "after glPopAttrib 5 err 0x0",
            "inside glBegin/glEnd err 0x502",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 20, "an anisotropy answer");
    assert_images_match("anisotropy", &ours, &mesa, WITHIN_ONE_EVERYWHERE);
    assert_trace_replays(
        "anisotropy",
        &compile("anisotropy", Linking::Direct),
        &[],
        "96x64",
    );
}

/// `tests/c/point_sprites.c`: ARB_point_sprite as Mesa 22.3 has it — COORD_REPLACE TRUE or
/// FALSE only (a float truncated, 0.5 is FALSE), per unit, restored by POINT_BIT and not
/// TEXTURE_BIT, the enable by ENABLE_BIT and POINT_BIT, compiled into lists — and sprites
/// drawn as Mesa draws them, pixel for pixel: both origins, centres off the pixel grid,
/// square under POINT_SMOOTH, the texture matrix bypassed, a unit that keeps its
/// coordinates beside one that replaces them, attenuated sizes, glPolygonMode(POINT)'s
/// corners, and a triangle under POINT_SPRITE reading the texel at (0, 0) as Mesa's
/// program reads it (a Mesa deviation: GL replaces the coordinates of points only); the
/// trace replays.
#[test]
fn point_sprites_are_drawn_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("point_sprites");
    assert_mesa_printed(
        &mesa_text,
        &[
            "extension named 1",
            "glTexEnvf 0.5 (FALSE)                err 0x0 reads 0",
            "glTexEnvf 2                          err 0x501 reads 1",
            "unit 1 after POINT_BIT               COORD_REPLACE 1 1 err 0x0",
            "unit 1 after TEXTURE_BIT             COORD_REPLACE 0 0 err 0x0",
            "after ENABLE_BIT                     POINT_SPRITE 1 1 err 0x0",
            "list called                          COORD_REPLACE 1 1 err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 25, "a point-sprite answer");
    assert_images_match("point_sprites", &ours, &mesa, WITHIN_ONE_EVERYWHERE);
    // The triangle under POINT_SPRITE is the texel at (0, 0), blue, on Mesa itself.
    let corner = mesa.get_pixel(104, 60).0;
    assert!(corner[2] > 200 && corner[0] < 60, "{corner:?}");
    assert_trace_replays(
        "point_sprites",
        &compile("point_sprites", Linking::Direct),
        &[],
        "128x96",
    );
}

/// `tests/c/npot.c`: the extension string names ARB_texture_non_power_of_two, as Mesa's
/// does, so that a program that checks it uploads its textures as they are — and they draw
/// as on Mesa within 1/255 on every pixel: a 7×5 chain given level by level and the same
/// chain generated (3×2, 1×1), REPEAT across seven texels, CLAMP and CLAMP_TO_EDGE, a 13×11
/// glCopyTexImage2D, a proxy, 1D and 3D images, a square cube face and the error of an
/// oblong one.
#[test]
fn non_power_of_two_textures_are_announced_and_drawn_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("npot");
    assert_mesa_printed(
        &mesa_text,
        &[
            "extension named 1",
            "generated level 1            3 x 2 err 0x0",
            "cube face 3x5                            err 0x501",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 10, "a texture of any size");
    assert_images_match("npot", &ours, &mesa, WITHIN_ONE_EVERYWHERE);
}

/// `tests/c/index_pixels.c`: COLOR_INDEX images in an RGBA context — glDrawPixels of
/// every index type and GL_BITMAP through the I_TO maps with no transfer, read as one run
/// an image; glTexImage2D and glTexSubImage2D shifted and offset but neither scaled nor
/// mapped — and the material's COLOR_INDEXES, FOG_INDEX and CURRENT_RASTER_INDEX with
/// their attribute groups, printed and drawn as on Mesa; the trace replays.
#[test]
fn colour_index_images_and_state_are_taken_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("index_pixels");
    assert_mesa_printed(
        &mesa_text,
        &[
            "DrawPixels UNSIGNED_BYTE                 err 0x0",
            "BYTE                   255,231,10,179 129,64,8,153 50,129,4,129 0,255,2,255 255,231,10,179 0,255,26,255",
            "shifted                51,128,230,128 255,230,178,178 51,128,5,128 0,255,26,255",
            "front                  1.5 2.70000005 -3.20000005 | 2 3 -3 err 0x0",
            "FOG_INDEX 2.6          2.5999999 3 err 0x0",
            "CURRENT_RASTER_INDEX                     1  err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 40, "a colour-index image or state");
    assert_images_match("index_pixels", &ours, &mesa, WITHIN_ONE_EVERYWHERE);
    let exe = compile("index_pixels", Linking::Direct);
    assert_trace_replays("index_pixels", &exe, &[], "64x32");
}

/// `tests/c/extensions.c`: the earlier names of what GL 1.2–1.4 made core — EXT blend
/// colour, equations, subtract and separate factors (and INGR's), NV blend square, EXT
/// range and multi draws, the GL 1.1 texture calls under EXT names, EXT rescale normal, NV
/// reflection texgen, EXT shadow functions, EXT ADD, SGIS border clamp, IBM mirrored
/// repeat, APPLE packed pixels, ARB multisample — named in the extension string as in
/// Mesa's, their entry points found and their tokens taken as Mesa takes them, and panels
/// blended and drawn through those entry points as Mesa draws them, within 1/255.
#[test]
fn earlier_extension_names_are_announced_and_act_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("extensions");
    assert_mesa_printed(
        &mesa_text,
        &[
            "GL_EXT_blend_minmax              named 1",
            "glBlendFuncSeparateINGR          found 1",
            "glBlendEquationEXT ZERO                  err 0x500",
            "BLEND_EQUATION_EXT                       32779  err 0x0",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 60, "an extension's answer");
    assert_images_match("extensions", &ours, &mesa, WITHIN_ONE_EVERYWHERE);
}

/// `tests/c/mesa_answers.c`: state and error answers as Mesa 22.3 gives them — glPopAttrib
/// restoring the draw and read buffers and the list base (and leaving
/// GENERATE_MIPMAP_HINT, as Mesa does), glTexSubImage at a level out of range
/// INVALID_VALUE before the format and a missing image, and n = 0 with NULL arrays no
/// error.
#[test]
fn state_and_errors_answer_as_on_mesa() {
    let (mesa, ours) = texts("mesa_answers");
    assert_mesa_printed(
        &mesa,
        &[
            "draw buffer after pop                    1028  err 0x0",
            "read buffer after pop                    1028  err 0x0",
            "pop window FRONT over an FBO             err 0x0",
            "pop window read FRONT over an FBO        err 0x502",
            "list base after pop                      3  err 0x0",
            "mipmap hint after pop (kept)             4353  err 0x0",
            "TexSubImage2D level -1, bad format       err 0x501",
            "TexSubImage3D level 11 (no image)        err 0x502",
            "glDeleteTextures(0, NULL)                err 0x0",
            "glAreTexturesResident(0, NULL, NULL)     0",
            "priority 0.25 after bind                 0.25  err 0x0",
            "GetTexImage base 0x1908 in 0x1904        20 128 0.0784313753 0.501960814  err 0x0 0x0",
            "GetTexImage base 0x1909 in 0x1903        10 250 0.0392156877 0.980392218  err 0x0 0x0",
            "vertex pointer after delete              0x8  err 0x0",
            "GetBufferPointerv(bad pname), unbound    err 0x500",
            "GetBufferParameteriv(bad pname), unbound err 0x502",
            "DrawArrays(first -1, count 3)            err 0x0",
            "MultiDrawArrays counts {0, 4, 2}         lit 0  err 0x0",
            "MultiDrawElements counts {0, 4}          lit 0  err 0x0",
        ],
    );
    assert_same_text(&mesa, &ours, 90, "the answer");
}

/// `tests/c/single_components.c`: RED, GREEN and BLUE texture data, whole images and a
/// sub-image, stored as RGBA with the missing components 0 and alpha 1: Mesa's image
/// exactly, its errors and the values read back.
#[test]
fn single_component_texture_data_is_stored_as_on_mesa() {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images("single_components");
    assert_mesa_printed(
        &mesa_text,
        &[
            "depth red                                err 0x502",
            "back 0 8 0 255 0 24 0 255 0 40 0 255 0 56 0 255",
        ],
    );
    assert_same_text(&mesa_text, &ours_text, 8, "a single-component image");
    assert_images_match("single_components", &ours, &mesa, Tolerance::EXACT);
}
