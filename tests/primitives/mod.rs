//! The scene of the primitive tests: one irregular vertex set per GL 1.x primitive type,
//! seen tilted through a perspective projection, unlit (a different colour at every vertex)
//! or lit (one positional light, a different normal at every vertex), in smooth or flat
//! shading, drawn as plain arrays or indexed. Nothing is symmetric — no parallelograms, no
//! colour that is an affine function of position, no two equal normals — so a wrong split of
//! a quad or a polygon, or a wrong provoking vertex, changes pixels.
//!
//! Every vertex list ends with vertices GL ignores where the type has them (a partial
//! trailing triangle, quad or strip pair, an odd line vertex).
#![allow(dead_code)]

use std::sync::Arc;

use fixedfunc::ff::{
    Capability, ClearMask, Command, CompareFunc, Face, Filter, Geometry, LightParam, MaterialParam,
    MatrixMode, PixelFormat, PixelType, Primitive, ShadeModel, TexData, TexEnvMode, TexEnvParam,
    TexFormat, TexImage, TexParam, TextureTarget, ViewVolume, Wrap,
};
use glam::{Vec3, Vec4};

/// Every primitive type of GL 1.x.
pub const ALL: [Primitive; 10] = [
    Primitive::Points,
    Primitive::Lines,
    Primitive::LineStrip,
    Primitive::LineLoop,
    Primitive::Triangles,
    Primitive::TriangleStrip,
    Primitive::TriangleFan,
    Primitive::Quads,
    Primitive::QuadStrip,
    Primitive::Polygon,
];

/// The frame the scene is drawn into.
pub const SIZE: u32 = 96;

/// How the vertices are coloured.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lighting {
    /// A colour array; LIGHTING off.
    Unlit,
    /// A normal array; LIGHT0 positional with attenuation, specular, LIGHTING on.
    Lit,
}

/// One rendering of one primitive type.
#[derive(Clone, Copy, Debug)]
pub struct Case {
    pub primitive: Primitive,
    pub lighting: Lighting,
    pub shade: ShadeModel,
    pub indexed: bool,
}

impl Case {
    /// A name for image files: `quads-lit-flat-indexed`.
    pub fn name(&self) -> String {
        format!(
            "{}-{}-{}{}",
            primitive_name(self.primitive),
            match self.lighting {
                Lighting::Unlit => "unlit",
                Lighting::Lit => "lit",
            },
            match self.shade {
                ShadeModel::Smooth => "smooth",
                ShadeModel::Flat => "flat",
            },
            if self.indexed { "-indexed" } else { "" }
        )
    }

    /// The four shading/lighting combinations of `primitive`, each plain and indexed.
    pub fn all_of(primitive: Primitive) -> Vec<Case> {
        let mut out = Vec::new();
        for lighting in [Lighting::Unlit, Lighting::Lit] {
            for shade in [ShadeModel::Smooth, ShadeModel::Flat] {
                for indexed in [false, true] {
                    out.push(Case {
                        primitive,
                        lighting,
                        shade,
                        indexed,
                    });
                }
            }
        }
        out
    }
}

pub fn primitive_name(p: Primitive) -> &'static str {
    match p {
        Primitive::Points => "points",
        Primitive::Lines => "lines",
        Primitive::LineStrip => "line-strip",
        Primitive::LineLoop => "line-loop",
        Primitive::Triangles => "triangles",
        Primitive::TriangleStrip => "triangle-strip",
        Primitive::TriangleFan => "triangle-fan",
        Primitive::Quads => "quads",
        Primitive::QuadStrip => "quad-strip",
        Primitive::Polygon => "polygon",
    }
}

/// The object-space (x, y) of each vertex of `p`, in submission order (z = 0).
pub fn layout(p: Primitive) -> &'static [[f32; 2]] {
    match p {
        Primitive::Points => &[
            [-0.9, -0.8],
            [-0.3, 0.7],
            [0.2, -0.4],
            [0.8, 0.5],
            [0.5, -0.9],
            [-0.6, 0.1],
        ],
        // Three segments and an odd vertex.
        Primitive::Lines => &[
            [-1.0, -0.9],
            [0.9, -0.6],
            [-0.8, 0.8],
            [0.7, 0.2],
            [-0.2, -0.3],
            [0.3, 0.95],
            [0.9, 0.9],
        ],
        Primitive::LineStrip => &[
            [-1.0, -0.8],
            [0.6, -0.9],
            [0.9, 0.4],
            [-0.3, 0.9],
            [-0.7, 0.0],
        ],
        Primitive::LineLoop => &[[-0.9, -0.7], [0.8, -0.9], [0.6, 0.8], [-0.5, 0.6]],
        // Two triangles and a partial third.
        Primitive::Triangles => &[
            [-1.0, -0.9],
            [0.1, -0.8],
            [-0.6, 0.7],
            [0.2, -0.6],
            [1.0, 0.1],
            [0.3, 0.95],
            [0.9, -0.9],
            [0.95, -0.5],
        ],
        Primitive::TriangleStrip => &[
            [-1.0, -0.7],
            [-0.8, 0.6],
            [-0.2, -0.9],
            [0.1, 0.8],
            [0.6, -0.6],
            [0.9, 0.5],
        ],
        // A hub and five rim vertices, counter-clockwise.
        Primitive::TriangleFan => &[
            [-0.1, -0.2],
            [0.9, -0.8],
            [0.95, 0.5],
            [0.2, 0.95],
            [-0.8, 0.7],
            [-0.95, -0.6],
        ],
        // Two irregular convex quads, counter-clockwise, and a partial third.
        Primitive::Quads => &[
            [-1.0, -0.9],
            [-0.05, -0.7],
            [-0.15, 0.8],
            [-0.9, 0.5],
            [0.05, -0.95],
            [0.95, -0.6],
            [1.0, 0.9],
            [0.1, 0.4],
            [0.0, 0.95],
            [0.5, 0.95],
            [0.3, 0.7],
        ],
        // (top, bottom) pairs: quad i is 2i, 2i+1, 2i+3, 2i+2, counter-clockwise; an odd
        // trailing vertex.
        Primitive::QuadStrip => &[
            [-1.0, 0.8],
            [-0.9, -0.9],
            [-0.3, 0.95],
            [-0.2, -0.6],
            [0.7, 0.6],
            [0.5, -0.95],
            [0.9, 0.0],
        ],
        Primitive::Polygon => &[
            [-0.9, -0.6],
            [0.4, -0.95],
            [0.95, 0.1],
            [0.3, 0.9],
            [-0.7, 0.7],
        ],
    }
}

/// Vertex k's colour: far from any affine function of position.
pub fn color(k: usize) -> Vec4 {
    const C: [[f32; 3]; 11] = [
        [1.0, 0.1, 0.1],
        [0.1, 0.9, 0.2],
        [0.2, 0.3, 1.0],
        [0.95, 0.85, 0.1],
        [0.8, 0.2, 0.9],
        [0.1, 0.8, 0.85],
        [0.6, 0.4, 0.1],
        [0.3, 0.1, 0.5],
        [0.9, 0.6, 0.7],
        [0.4, 0.9, 0.5],
        [0.2, 0.5, 0.3],
    ];
    let c = C[k % C.len()];
    Vec4::new(c[0], c[1], c[2], 1.0)
}

/// Vertex k's normal: all different, all facing the viewer more or less.
pub fn normal(k: usize) -> Vec3 {
    let k = k as f32;
    Vec3::new(0.7 * (1.7 * k).cos(), 0.7 * (2.3 * k + 0.4).sin(), 1.0).normalize()
}

/// The geometry of `case`. Indexed: the arrays hold the vertices in reverse order behind
/// one unused vertex, and the indices restore the submission order.
pub fn geometry(case: &Case) -> Geometry {
    let xy = layout(case.primitive);
    let n = xy.len();
    let positions: Vec<Vec4> = xy.iter().map(|p| Vec4::new(p[0], p[1], 0.0, 1.0)).collect();
    let colors: Vec<Vec4> = (0..n).map(color).collect();
    let normals: Vec<Vec3> = (0..n).map(normal).collect();
    let mut g = Geometry::new(case.primitive, positions);
    match case.lighting {
        Lighting::Unlit => g.colors = Some(colors),
        Lighting::Lit => g.normals = Some(normals),
    }
    if case.indexed {
        fn reversed<T: Copy>(v: &[T], unused: T) -> Vec<T> {
            std::iter::once(unused)
                .chain(v.iter().rev().copied())
                .collect()
        }
        g.positions = reversed(&g.positions, Vec4::new(5.0, 5.0, 0.0, 1.0));
        g.colors = g.colors.map(|c| reversed(&c, Vec4::ONE));
        g.normals = g.normals.map(|v| reversed(&v, Vec3::Z));
        g.indices = Some((0..n as u32).map(|k| n as u32 - k).collect());
    }
    g
}

/// The state of `case`: perspective, the scene tilted, depth test, the light, the shade
/// model. Ends ready for the draw.
pub fn setup(case: &Case) -> Vec<Command> {
    let mut c = vec![
        Command::ClearColor(Vec4::new(0.0, 0.0, 0.0, 1.0)),
        Command::ClearDepth(1.0),
        Command::Clear(ClearMask::ALL),
        Command::MatrixMode(MatrixMode::Projection),
        Command::LoadIdentity,
        Command::Frustum(ViewVolume {
            left: -0.55,
            right: 0.55,
            bottom: -0.55,
            top: 0.55,
            near: 1.0,
            far: 10.0,
        }),
        Command::MatrixMode(MatrixMode::Modelview),
        Command::LoadIdentity,
        Command::Enable(Capability::DepthTest),
        Command::DepthFunc(CompareFunc::Less),
        Command::ShadeModel(case.shade),
        Command::PointSize(3.0),
    ];
    if case.lighting == Lighting::Lit {
        c.extend(light());
    }
    c.extend([
        Command::Translate(Vec3::new(0.05, -0.02, -3.0)),
        Command::Rotate {
            angle_deg: 38.0,
            axis: Vec3::new(1.0, 0.45, 0.1),
        },
    ]);
    c
}

/// LIGHT0 at eye (1.6, 1.2, 0.4), attenuated, with a specular highlight; set while the
/// modelview is the identity.
pub fn light() -> Vec<Command> {
    let light = |param| Command::Light { light: 0, param };
    let material = |param| Command::Material {
        face: Face::FrontAndBack,
        param,
    };
    vec![
        Command::Enable(Capability::Lighting),
        Command::Enable(Capability::Light(0)),
        light(LightParam::Position(Vec4::new(1.6, 1.2, 0.4, 1.0))),
        light(LightParam::Ambient(Vec4::new(0.1, 0.1, 0.12, 1.0))),
        light(LightParam::Diffuse(Vec4::new(1.0, 0.95, 0.85, 1.0))),
        light(LightParam::Specular(Vec4::new(1.0, 1.0, 1.0, 1.0))),
        light(LightParam::LinearAttenuation(0.12)),
        material(MaterialParam::Diffuse(Vec4::new(0.85, 0.6, 0.35, 1.0))),
        material(MaterialParam::Specular(Vec4::new(0.7, 0.7, 0.7, 1.0))),
        material(MaterialParam::Shininess(12.0)),
    ]
}

/// The setup and the draw of `case`.
pub fn commands(case: &Case) -> Vec<Command> {
    let mut c = setup(case);
    c.push(Command::Draw(Arc::new(geometry(case))));
    c
}

/// An 8×8 RGBA checker of two unequal colours on unit 0, NEAREST, REPEAT, MODULATE.
pub fn checker() -> Vec<Command> {
    let mut texels = Vec::with_capacity(8 * 8 * 4);
    for y in 0..8 {
        for x in 0..8 {
            texels.extend(if (x + y) % 2 == 0 {
                [250, 235, 200, 255]
            } else {
                [70, 110, 160, 255]
            });
        }
    }
    let param = |param| Command::TexParameter {
        target: TextureTarget::Texture2D,
        param,
    };
    vec![
        Command::BindTexture {
            target: TextureTarget::Texture2D,
            name: 1,
        },
        Command::TexImage(TexImage {
            requested: None,
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::Rgba8,
            width: 8,
            height: 8,
            depth: 1,
            border: 0,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            data: TexData::Bytes(Arc::from(texels)),
        }),
        param(TexParam::MinFilter(Filter::Nearest)),
        param(TexParam::MagFilter(Filter::Nearest)),
        param(TexParam::WrapS(Wrap::Repeat)),
        param(TexParam::WrapT(Wrap::Repeat)),
        Command::TexEnv(TexEnvParam::Mode(TexEnvMode::Modulate)),
        Command::Enable(Capability::Texture2D),
    ]
}

/// Texture coordinates for vertex k that no affine map of position gives.
pub fn texcoord(k: usize) -> Vec4 {
    let k = k as f32;
    Vec4::new(
        1.5 * (0.9 * k + 0.3).sin() + 0.1 * k,
        1.2 * (1.3 * k).cos(),
        0.0,
        1.0,
    )
}

/// The setup of `case`, then `extra` (state or matrices), then the draw.
pub fn commands_with(case: &Case, extra: &[Command]) -> Vec<Command> {
    let mut c = setup(case);
    c.extend_from_slice(extra);
    c.push(Command::Draw(Arc::new(geometry(case))));
    c
}
