//! Polygon modes and polygon offset for LINE and POINT: piglit general/polygon-offset (nine
//! FILL/LINE/POINT combinations, units ±1) and general/polygon-mode-offset (separate front
//! and back modes, CW/CCW winding, OFFSET_FILL or OFFSET_LINE). The emulated path draws
//! separate modes in two culled passes and keeps a split quad's or polygon's outline
//! (`pipeline::emulate::polygon`); both paths must give piglit's colours, and each other's
//! image exactly — except where Mesa's native path deviates from the spec (below).

mod fidelity;
mod support;

use fidelity::{compare, run_both, run_one, script_file, Frame};
use fixedfunc::vocab::{PipelineKind, Precision};
use image::{GenericImageView, RgbaImage};
use support::Tolerance;

const RED: [u8; 3] = [255, 0, 0];
const BLUE: [u8; 3] = [0, 0, 255];
const WHITE: [u8; 3] = [255, 255, 255];

/// general/polygon-offset: in every cell the probe 3 pixels inside the top-right corner
/// (piglit's SIZE − line_width/4, inside a 12-pixel line or point) is red for units +1 (the
/// blue quad pushed behind) and blue for units −1, whatever the two quads' modes. Exact
/// colours; paths exact against each other.
#[test]
fn polygon_offset_applies_in_fill_line_and_point_modes() {
    let pairs = compare(
        "polygon-offset-modes",
        &script_file("polygon_offset_modes"),
        Frame::new(600, 150),
        Tolerance::EXACT,
    );
    let modes = ["FILL", "LINE", "POINT"];
    for p in pairs {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            for cell in 0..18u32 {
                let (x, y) = (cell % 9, cell / 9);
                let over = cell >= 9;
                let (red, blue) = (modes[(cell % 9 / 3) as usize], modes[(cell % 3) as usize]);
                let expected = if over { BLUE } else { RED };
                let (px, py) = (60 * x + 20 + 40 - 3, 60 * y + 20 + 40 - 3);
                let got = out.image.get_pixel(px, 149 - py).0;
                assert_eq!(
                    got[..3],
                    expected,
                    "{} {path}: red {red}, blue {blue}, units {}: {got:?}",
                    p.backend,
                    if over { -1 } else { 1 }
                );
            }
        }
    }
}

/// The configurations of polygon-mode-offset that Mesa 22.3 llvmpipe fails natively: 3 (a
/// back face filled while the front mode is LINE loses its OFFSET_FILL, pinned below by
/// its depth) and 4 (`mesa_offsets_filled_polygons_when_only_line_offset_is_on`).
const MESA_FAILS: [u32; 2] = [3, 4];

/// general/polygon-mode-offset: every configuration shows a white outline one pixel inside
/// its 64×64 viewport and a blue centre; the centre lies on the diagonal along which the
/// white polygon is split into triangles, so it also checks that LINE mode draws no split
/// edge. Emulate: all seven configurations, exact colours. Native: the same, except
/// configurations 3 and 4, pinned as Mesa draws them (no outline: the blue fill ends up no
/// deeper than the white lines and covers them under LEQUAL). Between paths: exact outside
/// configurations 3 and 4.
#[test]
fn separate_front_and_back_modes_with_fill_and_line_offset() {
    const W: u32 = 64;
    let pairs = run_both(&script_file("polygon_mode_offset"), Frame::new(7 * W, W));
    for p in pairs {
        for config in (0..7).filter(|c| !MESA_FAILS.contains(c)) {
            let crop = |img: &RgbaImage| img.view(config * W, 0, W, W).to_image();
            support::assert_images_match(
                &format!("polygon-mode-offset-{}-{config}", p.backend),
                &crop(&p.emulate.image),
                &crop(&p.native.image),
                Tolerance::EXACT,
            );
        }
        let depth = |out: &fidelity::Output, x: u32, y: u32| out.depth[(y * 7 * W + x) as usize];
        let (line, inside) = ((3 * W + W / 2, 1), (3 * W + W / 2, 3));
        let e = &p.emulate;
        assert!(depth(e, inside.0, inside.1) > depth(e, line.0, line.1));
        let n = &p.native;
        assert_eq!(
            depth(n, inside.0, inside.1),
            depth(n, line.0, line.1),
            "{}: Mesa changed — update the pin and DESIGN",
            p.backend
        );
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            for config in 0..7 {
                let mesa = path == "native" && MESA_FAILS.contains(&config);
                let edge = if mesa { BLUE } else { WHITE };
                let x0 = config * W;
                let m = W / 2;
                let probes = [
                    (m, 1, edge, "bottom edge"),
                    (m, W - 2, edge, "top edge"),
                    (1, m, edge, "left edge"),
                    (W - 2, m, edge, "right edge"),
                    (m, m, BLUE, "centre"),
                ];
                for (x, y, colour, what) in probes {
                    let got = out.image.get_pixel(x0 + x, W - 1 - y).0;
                    assert_eq!(
                        got[..3],
                        colour,
                        "{} {path} config {config} {what}: {got:?}",
                        p.backend
                    );
                }
            }
        }
    }
}

/// The window depth at pixel (32, 1) of a 64×64 frame after `body` (ortho ±1, z = 0,
/// DepthFunc LEQUAL), on `kind`.
fn depth_after(kind: PipelineKind, backend: fixedfunc::gpu::Backend, body: &str) -> f32 {
    let src = format!(
        "glEnable(GL_DEPTH_TEST);
glDepthFunc(GL_LEQUAL);
glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
{}{body}",
        fidelity::ortho(64, 64)
    );
    let out = run_one(
        kind,
        Precision::Float,
        backend,
        Frame::new(64, 64),
        &fidelity::parse(&src),
    );
    out.depth[64 + 32]
}

/// Mesa deviation, pinned. GL 1.5 §3.5.5: POLYGON_OFFSET_LINE offsets polygons rasterised
/// as lines, not filled ones. A filled quad at z = 0 with only OFFSET_LINE on and offset
/// (1, −1) must stay at z = 0. Emulate: exactly the depth of the quad without offset.
/// Mesa 22.3.6 llvmpipe (EGL and OSMesa): the depth of the quad with OFFSET_FILL, 0.5 −
/// 1.5 LSB of D24 instead of 0.5 + 1 LSB (the core path would do the same, which is why
/// the emulated path sends only the enable of the mode it rasterises). Exact float
/// equality of the depths read back.
#[test]
fn mesa_offsets_filled_polygons_when_only_line_offset_is_on() {
    let quad = |enable: &str| {
        format!(
            "glEnable({enable});\nglPolygonOffset(1, -1);\nglBegin(GL_QUADS);\nglVertex2f(0, 0); glVertex2f(64, 0); glVertex2f(64, 64); glVertex2f(0, 64);\nglEnd();\n"
        )
    };
    for backend in support::HEADLESS {
        for kind in [PipelineKind::Emulate, PipelineKind::Native] {
            let plain = depth_after(kind, backend, &quad("GL_DEPTH_TEST"));
            let fill = depth_after(kind, backend, &quad("GL_POLYGON_OFFSET_FILL"));
            assert!(fill < plain, "{backend} {kind:?}: OFFSET_FILL moves it");
            for enable in ["GL_POLYGON_OFFSET_LINE", "GL_POLYGON_OFFSET_POINT"] {
                let got = depth_after(kind, backend, &quad(enable));
                match kind {
                    PipelineKind::Emulate => {
                        assert_eq!(got, plain, "{backend} emulate {enable}: spec")
                    }
                    PipelineKind::Native => assert_eq!(
                        got, fill,
                        "{backend} native {enable}: Mesa 22.3 offsets the fill; \
                         if this fails, Mesa changed — update DESIGN and this pin"
                    ),
                }
            }
        }
    }
}

/// A filled front quad of four colours drawn while back faces are LINE, or under
/// POLYGON_STIPPLE: Mesa's draw module runs its pipeline stages for every triangle then and
/// splits the quad (v0,v1,v3),(v1,v2,v3), not (v0,v1,v2),(v0,v2,v3) as in plain FILL mode
/// (`pipeline::emulate::assembly`). With back faces culled the back mode is moot and the
/// quad is split v0–v2: every case against the native path.
#[test]
fn a_filled_quad_is_split_as_mesa_splits_it_in_its_draw_stages() {
    let quad = script_file("four_colour_quad");
    let head = "glViewport(0, 0, 32, 32);
glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
";
    // Every other row of the stipple pattern set: pixel row 28 (even) is drawn.
    let stipple = format!(
        "glPolygonStipple((GLubyte[]){{{}}});\nglEnable(GL_POLYGON_STIPPLE);\n",
        (0..128)
            .map(|i| if (i / 4) % 2 == 0 { "255" } else { "0" })
            .collect::<Vec<_>>()
            .join(", ")
    );
    let frame = Frame::new(32, 32);
    let tol = Tolerance {
        per_channel: 1,
        max_bad_pixels: 10,
    };
    for (name, set, v0_v2) in [
        (
            "back-lines-quad",
            "glPolygonMode(GL_BACK, GL_LINE);\n".to_string(),
            false,
        ),
        (
            "back-culled-quad",
            "glPolygonMode(GL_BACK, GL_LINE);\nglEnable(GL_CULL_FACE);\n".to_string(),
            true,
        ),
        ("stippled-quad", stipple, false),
    ] {
        for p in compare(name, &format!("{head}{set}{quad}"), frame, tol) {
            // Pixel (20, 28), window y from the bottom, at (0.28, 0.78) in NDC: in the
            // triangle (v1, v2, v3) of a v1–v3 split, green 0.41 (105) from green v1 and
            // white v3; in (v0, v2, v3) of a v0–v2 split, green 0.28 (71) from v3 alone.
            let px = p.emulate.image.get_pixel(20, 31 - 28).0;
            assert_eq!(px[1] < 88, v0_v2, "{name} {}: {px:?}", p.backend);
        }
    }
}
