//! Mesa's primitive assembly on the native path, pinned: the facts the emulated path models
//! (`pipeline::emulate::assembly`), measured on Mesa 22.3.6 llvmpipe by drawing a primitive
//! natively and the same vertices natively as GL_TRIANGLES (or LINES) in a candidate
//! decomposition, and comparing the images. A matching candidate matches exactly (0/255 on
//! every pixel); a wrong one differs by up to ~180/255 on about a thousand pixels.
//!
//! - QUADS: v0–v2 from unclipped arrays, v1–v3 indexed, v1–v3 per chunk of 1024 quads with a
//!   vertex outside the clip volume; glBegin/glEnd draws as arrays do.
//! - QUAD_STRIP along 2i–(2i+3), POLYGON fanned from v0, plain or indexed, lit or not.
//! - Flat shading: the provoking vertices of GL 1.5 Table 2.8 for every type.

mod fidelity;
mod primitives;
mod support;

use fixedfunc::vocab::{DepthBits, PipelineKind, Precision};
use std::sync::Arc;

use fidelity::{run_one, Frame};
use fixedfunc::ff::{Command, FixedState, Geometry, Primitive, ShadeModel};
use fixedfunc::gpu::{Backend, Profile};
use fixedfunc::pipeline::emulate::assembly::{clipped, QUAD_CHUNK};
use fixedfunc::pipeline::native::{bindings as gl, NativeGl, NativePipeline};
use fixedfunc::pipeline::Pipeline;
use glam::{Vec3, Vec4};
use image::RgbaImage;
use primitives::{Case, Lighting, SIZE};
use support::Tolerance;

const V0V2: [u32; 6] = [0, 1, 2, 0, 2, 3];
const V1V3: [u32; 6] = [0, 1, 3, 1, 2, 3];

/// The native image of `commands` on `backend` (no GL error, model or driver).
fn native(backend: Backend, commands: &[Command]) -> RgbaImage {
    run_one(
        PipelineKind::Native,
        Precision::Float,
        backend,
        Frame::new(SIZE, SIZE),
        commands,
    )
    .image
}

/// `g` with its vertices picked in `order`, as non-indexed `primitive`.
fn picked(g: &Geometry, primitive: Primitive, order: &[u32]) -> Geometry {
    fn pick<T: Copy>(v: &[T], order: &[u32]) -> Vec<T> {
        order.iter().map(|&k| v[k as usize]).collect()
    }
    let mut out = Geometry::new(primitive, pick(&g.positions, order));
    out.colors = g.colors.as_deref().map(|c| pick(c, order));
    out.normals = g.normals.as_deref().map(|n| pick(n, order));
    for (o, t) in out.texcoords.iter_mut().zip(&g.texcoords) {
        *o = t.as_deref().map(|t| pick(t, order));
    }
    out
}

/// The commands drawing `g` after the setup of `case` and `extra`.
fn draw(case: &Case, extra: &[Command], g: Geometry) -> Vec<Command> {
    let mut c = primitives::setup(case);
    c.extend_from_slice(extra);
    c.push(Command::Draw(Arc::new(g)));
    c
}

/// The candidate triangles of `quads` quads whose quad i is split by `split(i)`.
fn quad_triangles(quads: u32, split: impl Fn(u32) -> [u32; 6]) -> Vec<u32> {
    (0..quads)
        .flat_map(|i| split(i).map(|k| 4 * i + k))
        .collect()
}

fn assert_same(name: &str, actual: &RgbaImage, expected: &RgbaImage) {
    support::assert_images_match(name, actual, expected, Tolerance::EXACT);
}

fn assert_differ(name: &str, a: &RgbaImage, b: &RgbaImage) {
    let differing = a.pixels().zip(b.pixels()).filter(|(p, q)| p != q).count();
    assert!(differing > 100, "{name}: the candidates look alike");
}

fn quads(lighting: Lighting, indexed: bool) -> Case {
    Case {
        primitive: Primitive::Quads,
        lighting,
        shade: ShadeModel::Smooth,
        indexed,
    }
}

/// Unclipped quads from arrays are split v0–v2, indexed ones v1–v3, lit or unlit, on both
/// backends.
#[test]
fn quads_split_v0_v2_from_arrays_and_v1_v3_indexed() {
    for backend in support::HEADLESS {
        for lighting in [Lighting::Unlit, Lighting::Lit] {
            let plain = primitives::geometry(&quads(lighting, false));
            let a = picked(&plain, Primitive::Triangles, &quad_triangles(2, |_| V0V2));
            let b = picked(&plain, Primitive::Triangles, &quad_triangles(2, |_| V1V3));
            let case = quads(lighting, false);
            let (a, b) = (
                native(backend, &draw(&case, &[], a)),
                native(backend, &draw(&case, &[], b)),
            );
            assert_differ("v0-v2 against v1-v3", &a, &b);
            let arrays = native(backend, &primitives::commands(&case));
            assert_same(&format!("quads-arrays-{lighting:?}-{backend}"), &arrays, &a);
            let indexed = native(backend, &primitives::commands(&quads(lighting, true)));
            assert_same(
                &format!("quads-indexed-{lighting:?}-{backend}"),
                &indexed,
                &b,
            );
        }
    }
}

/// The edge of the clip volume, not of any guard band: shifted so that vertex 6 lies 1.4
/// pixels inside the right edge, the quads split v0–v2; 0.1 pixel outside, both quads (the
/// whole draw) split v1–v3.
#[test]
fn a_vertex_outside_the_clip_volume_turns_the_draw_to_v1_v3() {
    let case = quads(Lighting::Unlit, false);
    let g = primitives::geometry(&case);
    for (t, outside) in [(0.45f32, false), (0.5, true)] {
        let extra = [Command::Translate(Vec3::new(t, 0.3 * t, 0.0))];
        let mut state = FixedState::new();
        for c in primitives::setup(&case).iter().chain(&extra) {
            let _ = state.apply(c);
        }
        let mvp = state.projection_matrix() * state.modelview_matrix();
        let out: Vec<usize> = (0..8).filter(|&k| clipped(mvp, g.positions[k])).collect();
        assert_eq!(out, if outside { vec![6] } else { vec![] }, "shift {t}");
        let split = if outside { V1V3 } else { V0V2 };
        let expected = picked(&g, Primitive::Triangles, &quad_triangles(2, |_| split));
        let backend = Backend::Egl;
        assert_same(
            &format!("quads-shift-{t}"),
            &native(backend, &draw(&case, &extra, g.clone())),
            &native(backend, &draw(&case, &extra, expected)),
        );
    }
}

/// 40×40 quads (6400 vertices) in view but for the last, pushed out: the first 1024 quads
/// (4096 vertices) still split v0–v2, the rest v1–v3. Lit with texture coordinates too, so
/// the chunk is counted in vertices, not bytes.
#[test]
fn quads_are_decided_per_chunk_of_1024() {
    let n = 40u32;
    let h = 2.0 / n as f32;
    let mut positions = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let (x, y) = (-1.0 + h * i as f32, -1.0 + h * j as f32);
            let push = if i == n - 1 && j == n - 1 { 30.0 } else { 0.0 };
            for (a, b) in [(0.0, 0.0), (0.9, 0.1), (1.0, 0.95), (0.05, 0.8)] {
                positions.push(Vec4::new(x + a * h * (1.0 + push), y + b * h, 0.0, 1.0));
            }
        }
    }
    let k = positions.len();
    for lighting in [Lighting::Unlit, Lighting::Lit] {
        let case = quads(lighting, false);
        let mut g = Geometry::new(Primitive::Quads, positions.clone());
        match lighting {
            Lighting::Unlit => g.colors = Some((0..k).map(primitives::color).collect()),
            Lighting::Lit => {
                g.normals = Some((0..k).map(primitives::normal).collect());
                g.texcoords[0] = Some((0..k).map(primitives::texcoord).collect());
            }
        }
        let extra = [Command::Scale(Vec3::new(0.75, 0.75, 1.0))];
        let chunk = QUAD_CHUNK as u32;
        let split = |i| if i < chunk { V0V2 } else { V1V3 };
        let expected = picked(&g, Primitive::Triangles, &quad_triangles(n * n, split));
        let backend = Backend::Egl;
        assert_same(
            &format!("quads-chunks-{lighting:?}"),
            &native(backend, &draw(&case, &extra, g)),
            &native(backend, &draw(&case, &extra, expected)),
        );
    }
}

/// QUAD_STRIP quad i is split along 2i–(2i+3) and POLYGON fanned from v0, plain, indexed,
/// lit, unlit, clipped or not. Exact, but for clipped draws 1/255: the clipper makes new
/// vertices in the order of its own triangles, which moves a rounding here and there.
#[test]
fn quad_strips_split_along_2i_to_2i_plus_3_and_polygons_fan_from_v0() {
    let strip = [0u32, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4];
    let fan = [0u32, 1, 2, 0, 2, 3, 0, 3, 4];
    for (primitive, tris) in [
        (Primitive::QuadStrip, &strip[..]),
        (Primitive::Polygon, &fan[..]),
    ] {
        for lighting in [Lighting::Unlit, Lighting::Lit] {
            for indexed in [false, true] {
                for extra in [vec![], vec![Command::Scale(Vec3::new(1.9, 1.9, 1.0))]] {
                    let case = Case {
                        primitive,
                        lighting,
                        shade: ShadeModel::Smooth,
                        indexed,
                    };
                    let plain = primitives::geometry(&Case {
                        indexed: false,
                        ..case
                    });
                    let expected = picked(&plain, Primitive::Triangles, tris);
                    let name = format!("{}-{}", case.name(), extra.len());
                    let tol = Tolerance {
                        per_channel: extra.len() as u8,
                        max_bad_pixels: 0,
                    };
                    support::assert_images_match(
                        &name,
                        &native(Backend::Egl, &primitives::commands_with(&case, &extra)),
                        &native(Backend::Egl, &draw(&case, &extra, expected)),
                        tol,
                    );
                }
            }
        }
    }
}

/// Each sub-primitive of `p` over `n` vertices with its provoking vertex, as GL 1.5 Table
/// 2.8 has it (0-based here): split polygons as triangles sharing their polygon's vertex.
fn table_2_8(p: Primitive, n: u32) -> Vec<(Vec<u32>, u32)> {
    let seq = |count: u32, f: &dyn Fn(u32) -> (Vec<u32>, u32)| (0..count).map(f).collect();
    match p {
        Primitive::Points => seq(n, &|i| (vec![i], i)),
        Primitive::Lines => seq(n / 2, &|i| (vec![2 * i, 2 * i + 1], 2 * i + 1)),
        Primitive::LineStrip => seq(n - 1, &|i| (vec![i, i + 1], i + 1)),
        Primitive::LineLoop => {
            let mut s: Vec<_> = seq(n - 1, &|i| (vec![i, i + 1], i + 1));
            s.push((vec![n - 1, 0], 0));
            s
        }
        Primitive::Triangles => seq(n / 3, &|i| (vec![3 * i, 3 * i + 1, 3 * i + 2], 3 * i + 2)),
        Primitive::TriangleStrip => seq(n - 2, &|i| (vec![i, i + 1, i + 2], i + 2)),
        Primitive::TriangleFan => seq(n - 2, &|i| (vec![0, i + 1, i + 2], i + 2)),
        Primitive::Quads => (0..n / 4)
            .flat_map(|i| {
                [[0, 1, 2], [0, 2, 3]].map(|t| (t.map(|k| 4 * i + k).to_vec(), 4 * i + 3))
            })
            .collect(),
        Primitive::QuadStrip => (0..(n - 2) / 2)
            .flat_map(|i| {
                [[0, 1, 3], [0, 3, 2]].map(|t| (t.map(|k| 2 * i + k).to_vec(), 2 * i + 3))
            })
            .collect(),
        Primitive::Polygon => seq(n - 2, &|i| (vec![0, i + 1, i + 2], 0)),
    }
}

/// The colour each vertex of `case` gets, drawn alone as a (3-pixel) point.
fn vertex_colors(backend: Backend, case: &Case) -> Vec<Vec4> {
    let g = primitives::geometry(&Case {
        indexed: false,
        ..*case
    });
    (0..g.positions.len() as u32)
        .map(|k| {
            let img = native(
                backend,
                &draw(case, &[], picked(&g, Primitive::Points, &[k])),
            );
            let p = img
                .pixels()
                .find(|p| p.0 != [0, 0, 0, 255])
                .unwrap_or_else(|| panic!("vertex {k} of {} not in view", case.name()));
            Vec4::from_array(p.0.map(|c| f32::from(c) / 255.0))
        })
        .collect()
}

/// Flat shading, every type, lit and unlit: the native image equals its decomposition into
/// unlit flat triangles, lines or points each coloured with the colour its provoking vertex
/// (Table 2.8) has alone — the closing segment of a loop takes vertex 1, a polygon vertex 1,
/// a quad 4i, a strip quad 2i+2 over both of their triangles.
#[test]
fn flat_shading_takes_the_provoking_vertices_of_table_2_8() {
    let backend = Backend::Egl;
    for primitive in primitives::ALL {
        for lighting in [Lighting::Unlit, Lighting::Lit] {
            let case = Case {
                primitive,
                lighting,
                shade: ShadeModel::Flat,
                indexed: false,
            };
            let colors = vertex_colors(backend, &case);
            let g = primitives::geometry(&case);
            let parts = table_2_8(primitive, g.positions.len() as u32);
            let order: Vec<u32> = parts.iter().flat_map(|(c, _)| c.clone()).collect();
            let reduced = match primitive {
                Primitive::Points => Primitive::Points,
                Primitive::Lines | Primitive::LineStrip | Primitive::LineLoop => Primitive::Lines,
                _ => Primitive::Triangles,
            };
            let mut expected = Geometry::new(reduced, picked(&g, reduced, &order).positions);
            expected.colors = Some(
                parts
                    .iter()
                    .flat_map(|(c, p)| vec![colors[*p as usize]; c.len()])
                    .collect(),
            );
            let unlit = Case {
                lighting: Lighting::Unlit,
                ..case
            };
            assert_same(
                &format!("flat-{}", case.name()),
                &native(backend, &primitives::commands(&case)),
                &native(backend, &draw(&unlit, &[], expected)),
            );
        }
    }
}

/// glBegin/glEnd of the same vertices draws exactly what the native path's arrays draw, for
/// every type, smooth and flat, lit and unlit.
#[test]
fn immediate_mode_draws_as_arrays_do() {
    let backend = Backend::Egl;
    for primitive in primitives::ALL {
        for case in Case::all_of(primitive).into_iter().filter(|c| !c.indexed) {
            let arrays = native(backend, &primitives::commands(&case));
            assert_same(
                &format!("immediate-{}", case.name()),
                &immediate(backend, &case),
                &arrays,
            );
        }
    }
}

/// The setup of `case` through the native pipeline, then the geometry as glBegin/glEnd
/// through the raw bindings.
fn immediate(backend: Backend, case: &Case) -> RgbaImage {
    let ctx = support::context(backend, Profile::Compatibility);
    let t = support::target(&ctx, SIZE, SIZE, DepthBits::D24, false);
    let mut pipe = NativePipeline::new(&ctx).expect("native pipeline");
    pipe.execute(&ctx, &primitives::setup(case))
        .expect("setup commands");
    let native = NativeGl::load(&ctx).expect("compatibility context");
    let g = native.raw();
    let geo = primitives::geometry(case);
    let mode = match case.primitive {
        Primitive::Points => gl::POINTS,
        Primitive::Lines => gl::LINES,
        Primitive::LineStrip => gl::LINE_STRIP,
        Primitive::LineLoop => gl::LINE_LOOP,
        Primitive::Triangles => gl::TRIANGLES,
        Primitive::TriangleStrip => gl::TRIANGLE_STRIP,
        Primitive::TriangleFan => gl::TRIANGLE_FAN,
        Primitive::Quads => gl::QUADS,
        Primitive::QuadStrip => gl::QUAD_STRIP,
        Primitive::Polygon => gl::POLYGON,
    };
    // SAFETY: immediate-mode calls on the current compatibility context.
    unsafe {
        g.Begin(mode);
        for (k, p) in geo.positions.iter().enumerate() {
            if let Some(c) = &geo.colors {
                g.Color4f(c[k].x, c[k].y, c[k].z, c[k].w);
            }
            if let Some(n) = &geo.normals {
                g.Normal3f(n[k].x, n[k].y, n[k].z);
            }
            g.Vertex4f(p.x, p.y, p.z, p.w);
        }
        g.End();
    }
    let img = t.read_color(&ctx).expect("colour readback");
    support::assert_no_gl_error(&ctx);
    pipe.release(&ctx);
    t.delete(&ctx);
    img
}
