//! Every primitive type of GL 1.x, emulated against Mesa's native path: for each type a test
//! draws the scene of `primitives` (irregular vertices in perspective, a colour per vertex
//! unlit, a normal per vertex under one positional light lit) in smooth and flat shading,
//! as plain arrays and indexed, on EGL and OSMesa, and compares the emulated image with the
//! native one. Quads also run with a vertex outside the clip volume, which changes Mesa's
//! split (`pipeline::emulate::assembly`). The last test is the filed case: a lit, textured
//! (eye-linear texgen on a checker), Gouraud-shaded GL_QUADS floor.
//!
//! Tolerance: piglit's 3/255 per channel, with at most `MAX_BAD` pixels beyond it (see
//! `TOLERANCE`). A wrong split of a quad or polygon differs by up to ~180/255 on hundreds to
//! thousands of the 96×96 pixels, a wrong provoking vertex on whole triangles.

mod fidelity;
mod primitives;
mod support;

use fixedfunc::vocab::{PipelineKind, Precision};
use std::sync::Arc;

use fidelity::{run_one, Frame, Output};
use fixedfunc::ff::{
    Capability, ColorMaterialMode, Command, Face, Geometry, LightModelParam, PolygonMode,
    Primitive, ShadeModel, TexCoord, TexGenMode, TexGenParam,
};
use fixedfunc::gpu::Backend;
use glam::{Vec3, Vec4};
use primitives::{Case, Lighting, SIZE};
use support::Tolerance;

/// 3/255 per channel (piglit); no pixel may exceed it.
const TOLERANCE: Tolerance = Tolerance {
    per_channel: 3,
    max_bad_pixels: 0,
};

fn run(kind: PipelineKind, backend: Backend, commands: &[Command]) -> Output {
    run_one(
        kind,
        Precision::Float,
        backend,
        Frame::new(SIZE, SIZE),
        commands,
    )
}

/// Emulate against native on both headless backends; `run_one` ends each run by asserting
/// that neither the model nor the driver recorded a GL error.
fn compare(name: &str, commands: &[Command], tol: Tolerance) {
    for backend in support::HEADLESS {
        let emulated = run(PipelineKind::Emulate, backend, commands);
        let native = run(PipelineKind::Native, backend, commands);
        // The primitive must be in view, or the comparison proves nothing.
        let covered = native
            .image
            .pixels()
            .filter(|p| p.0 != [0, 0, 0, 255])
            .count();
        println!("{name} {backend}: {covered} pixels covered");
        assert!(
            covered >= 40,
            "{name} {backend}: only {covered} pixels drawn"
        );
        support::assert_images_match(
            &format!("primitives-{name}-{backend}"),
            &emulated.image,
            &native.image,
            tol,
        );
    }
}

/// Smooth and flat, lit and unlit, plain and indexed.
fn check(primitive: Primitive) {
    for case in Case::all_of(primitive) {
        compare(&case.name(), &primitives::commands(&case), TOLERANCE);
    }
}

#[test]
fn points() {
    check(Primitive::Points);
}

/// Flat: segment i takes vertex 2i+1 (1-based 2i).
#[test]
fn lines() {
    check(Primitive::Lines);
}

/// Flat: segment i takes vertex i+1.
#[test]
fn line_strip() {
    check(Primitive::LineStrip);
}

/// Flat: segment i takes vertex i+1, and the closing segment vertex 1 (the first).
#[test]
fn line_loop() {
    check(Primitive::LineLoop);
    // Scripts name it too.
    let c = fidelity::parse(
        "glBegin(GL_LINE_LOOP);\nglVertex2f(0, 0); glVertex2f(1, 0); glVertex2f(0, 1);\nglEnd();\n",
    );
    assert!(
        matches!(&c[..], [Command::Draw(g)] if g.primitive == Primitive::LineLoop),
        "{c:?}"
    );
}

/// Flat: triangle i takes vertex 3i (1-based).
#[test]
fn triangles() {
    check(Primitive::Triangles);
}

/// Flat: triangle i takes vertex i+2 (1-based).
#[test]
fn triangle_strip() {
    check(Primitive::TriangleStrip);
}

/// Flat: triangle i takes vertex i+2 (1-based).
#[test]
fn triangle_fan() {
    check(Primitive::TriangleFan);
}

/// Mesa's split: v0–v2 unclipped non-indexed, v1–v3 indexed or with a vertex outside the
/// clip volume (the scene scaled ×1.9 pushes corners out). Flat: quad i takes 4i (its last
/// vertex) over both of its triangles.
#[test]
fn quads() {
    check(Primitive::Quads);
    let out = [Command::Scale(Vec3::new(1.9, 1.9, 1.0))];
    for case in Case::all_of(Primitive::Quads) {
        let name = format!("{}-clipped", case.name());
        compare(&name, &primitives::commands_with(&case, &out), TOLERANCE);
    }
}

/// Split along 2i–(2i+3); flat: quad i takes vertex 2i+2 (1-based).
#[test]
fn quad_strip() {
    check(Primitive::QuadStrip);
}

/// A fan from the first vertex; flat: the polygon takes vertex 1 (its first).
#[test]
fn polygon() {
    check(Primitive::Polygon);
}

/// A floor quad of the filed case, (x, z) corners at y = −1 in eye space, one normal.
fn floor(corners: [[f32; 2]; 4], indexed: bool) -> Geometry {
    let positions = corners
        .iter()
        .map(|c| Vec4::new(c[0], -1.0, c[1], 1.0))
        .collect();
    let mut g = Geometry::new(Primitive::Quads, positions);
    if indexed {
        g.indices = Some(vec![0, 1, 2, 3]);
    }
    g
}

/// The filed case: GL_QUADS lit by one positional light (one normal, up), eye-linear
/// texgen on S and T over an 8×8 checker (MODULATE), depth test, perspective, Gouraud
/// shading. Mesa splits the floor v0–v2 while it fits in the view and v1–v3 once a corner
/// leaves it or it is drawn indexed; the emulation must follow. Tolerance: 3/255 on 99% of
/// the pixels. Measured with every quad split v0–v2 (the old emulation): 1448 pixels beyond
/// 3/255 (worst 60) with the floor beyond the view, 242 (worst 10) indexed; with Mesa's
/// rule, all exact but one pixel beyond the view, on a texel boundary of the NEAREST checker
/// where the two paths' eye-linear coordinates round apart (55/255).
#[test]
fn lit_textured_quad_of_the_filed_case() {
    let inside = [[-0.9, -2.3], [1.0, -2.1], [0.9, -4.6], [-1.4, -5.0]];
    let beyond = [[-4.0, -1.2], [3.5, -1.5], [2.0, -9.0], [-3.0, -8.0]];
    let gen = |coord, plane| {
        [
            Command::TexGen {
                coord,
                param: TexGenParam::Mode(TexGenMode::EyeLinear),
            },
            Command::TexGen {
                coord,
                param: TexGenParam::EyePlane(plane),
            },
            Command::Enable(Capability::TextureGen(coord)),
        ]
    };
    for (name, corners, indexed) in [
        ("inside", inside, false),
        ("beyond", beyond, false),
        ("indexed", inside, true),
    ] {
        let case = Case {
            primitive: Primitive::Quads,
            lighting: Lighting::Lit,
            shade: ShadeModel::Smooth,
            indexed,
        };
        // The scene's projection and light; the floor is given in eye coordinates.
        let mut c: Vec<Command> = primitives::setup(&case)
            .into_iter()
            .take_while(|c| !matches!(c, Command::Translate(_)))
            .collect();
        c.extend(primitives::checker());
        c.extend(gen(TexCoord::S, Vec4::new(1.3, 0.0, 0.2, 0.1)));
        c.extend(gen(TexCoord::T, Vec4::new(0.1, 0.0, 1.1, 0.0)));
        c.push(Command::Normal(Vec3::Y));
        c.push(Command::Draw(Arc::new(floor(corners, indexed))));
        let tol = Tolerance {
            per_channel: 3,
            max_bad_pixels: (SIZE * SIZE) as usize / 100,
        };
        compare(&format!("filed-case-{name}"), &c, tol);
    }
}

/// Flat split polygons under the other state that reads their provoking vertex: lit with
/// COLOR_MATERIAL (a colour and a normal per vertex), two-sided lighting seen from behind,
/// and LINE and POINT polygon modes (the outline only, one colour per polygon).
#[test]
fn flat_polygons_under_color_material_two_side_and_polygon_modes() {
    let rear = [
        Command::LightModel(LightModelParam::TwoSide(true)),
        Command::Rotate {
            angle_deg: 180.0,
            axis: Vec3::Y,
        },
    ];
    let material = [
        Command::ColorMaterial {
            face: Face::FrontAndBack,
            mode: ColorMaterialMode::AmbientAndDiffuse,
        },
        Command::Enable(Capability::ColorMaterial),
    ];
    let mode = |mode| Command::PolygonMode {
        face: Face::FrontAndBack,
        mode,
    };
    let variants: [(&str, Vec<Command>); 4] = [
        ("color-material", material.to_vec()),
        ("two-side-rear", rear.to_vec()),
        ("line-mode", vec![mode(PolygonMode::Line)]),
        ("point-mode", vec![mode(PolygonMode::Point)]),
    ];
    for primitive in [Primitive::Quads, Primitive::QuadStrip, Primitive::Polygon] {
        for case in Case::all_of(primitive) {
            if case.lighting == Lighting::Unlit || case.shade == ShadeModel::Smooth {
                continue;
            }
            // A colour per vertex beside the normals, for COLOR_MATERIAL to track.
            let mut g = primitives::geometry(&case);
            g.colors = primitives::geometry(&Case {
                lighting: Lighting::Unlit,
                ..case
            })
            .colors;
            let g = Arc::new(g);
            for (name, extra) in &variants {
                let mut c = primitives::setup(&case);
                c.extend_from_slice(extra);
                c.push(Command::Draw(g.clone()));
                compare(&format!("{}-{name}", case.name()), &c, TOLERANCE);
            }
        }
    }
}
