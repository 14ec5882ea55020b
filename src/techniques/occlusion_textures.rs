//! `occlusion-textures`: Eisemann & Décoret's plausible soft shadows (seed 002, CGF 2008)
//! for the scene's rectangular area light. The only technique with its own GLSL besides
//! Coleman's (`shaders/eisemann/`, run through `Command::UseProgram`, emulate pipeline only).
//!
//! ```text
//! maps   slices: per RGBA texture k: glBindFramebuffer(F); glFramebufferTexture2D(COLOR0,
//!                occlusion k); glViewport(size); glClear(COLOR) to 0; glDisable(DEPTH_TEST);
//!                glBlendFunc(ONE, ONE); program eisemann/slices (slices 4k … 4k+3);
//!                modelview = the light's frame; draw the casters
//!        filter: glBindFramebuffer(0); per texture: glGenerateMipmap (the mipmap prefilter)
//! frame  dim:    depth-compare's dim pass (the shadowing light off), fixed function
//!        lit:    glDepthFunc(EQUAL); glBlendFunc(ONE, ONE); program eisemann/visibility:
//!                light 0's diffuse term × visibility; units 0… the occlusion textures
//! mask   one pass of eisemann/visibility in the mask look: the visibility as grey over the
//!        mask background (`MaskSource::Visibility`)
//! ```
//!
//! **The light's frame.** x along the light's first edge, y along the second, z the
//! distance from the light's plane towards the scene (n = edge_u × edge_v, turned towards
//! the casters); the light is |x| ≤ a, |y| ≤ b on z = 0. The slicing view (Figure 5) puts
//! its centre of projection `cop` behind the light's centre, with `cop` the casters' far
//! depth, and a near window on the light's plane of the light's aspect, `margin` ≥ 1 times
//! the light, just large enough that every caster's bounding-box corner projects inside:
//! margin = max(1, max over corners of |x|/a · cop/(z + cop), |y|/b · cop/(z + cop)).
//! Beyond the window an occlusion texture reads its border, 0: nothing occludes there.
//!
//! **Slices** are uniform in depth between the casters' nearest and farthest
//! bounding-box depths (clamped to the light's front side), as the paper's implementation
//! ("uniformly placed slices").

use std::sync::Arc;

use glam::{Mat4, Vec2, Vec3, Vec4};

use crate::ff::framebuffer::{AttachmentPoint, FramebufferTarget};
use crate::ff::program::with_defines;
use crate::ff::{
    BlendFactor, Capability, ClearMask, Command, CompareFunc, Filter, PixelFormat, PixelType,
    SamplerBinding, ShaderProgram, TexData, TexFormat, TexImage, TexParam, TextureTarget,
    UniformValue, Viewport, Wrap,
};
use crate::scene::{Combine, Prefilter, Scene};
use crate::vocab::{DepthBits, TechniqueId};

use super::accumulate::{AreaRectangle, SoftSource};
use super::occlusion_sun::{gauss_pass, gauss_setup, sun_view};
use super::parts::{dim_pass, eye_start, lighting, objects, reset, LightSet, Look, Paint};
use super::{
    check_light_count, FramebufferNeeds, MaskPlan, MaskSource, Pass, Plan, Prepared, Technique,
    TechniqueError, MASK_SLOT,
};

pub const ID: TechniqueId = TechniqueId::OcclusionTextures;

pub const TECHNIQUE: Technique = Technique {
    summary: "Eisemann & Décoret's occlusion textures: the scene sliced from the area light \
              into prefiltered RGBA textures, one eye pass combining them (soft shadows)",
    plan,
};

/// The texture name of occlusion texture k: `OCCLUSION_TEXTURE_BASE + k`.
pub const OCCLUSION_TEXTURE_BASE: u32 = 96;
/// The texture names of the N-buffer levels (`nbuffer_texture`).
pub const NBUFFER_TEXTURE_BASE: u32 = 112;
/// The texture names of the summed-area tables (`sat_texture`).
pub const SAT_TEXTURE_BASE: u32 = 120;
/// The framebuffer object the slices are drawn into.
pub const SLICE_FRAMEBUFFER: u32 = 96;

impl OcclusionSettings {
    fn combine_define(&self) -> u32 {
        match self.combine {
            Combine::Probabilistic => 0,
            Combine::Sum => 1,
            Combine::Max => 2,
        }
    }

    /// N-buffer levels: box sizes 2^0 … 2^(levels − 1) = the texture's edge.
    pub fn levels(&self) -> u32 {
        self.size.max(1).ilog2() + 1
    }

    /// The summed-area table's doubling steps per axis: ⌈log2(size)⌉, so that the last
    /// step's reach 2^steps covers the whole row.
    pub fn sat_steps_per_axis(&self) -> u32 {
        self.size.max(1).next_power_of_two().ilog2()
    }

    /// The summed-area table's doubling steps: along x, then along y.
    pub fn sat_steps(&self) -> u32 {
        2 * self.sat_steps_per_axis()
    }

    /// The parity of the texture the last doubling step writes (a table of one texel,
    /// no steps, is the occlusion texture copied by a first step of offset 0).
    pub fn sat_parity(&self) -> u32 {
        self.sat_steps().max(1).saturating_sub(1) % 2
    }
}

/// What the technique reads from the scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OcclusionSettings {
    /// 4, 8 or 16.
    pub slices: u32,
    /// Edge of each occlusion texture, in texels (the scene's `map_size`).
    pub size: u32,
    pub prefilter: Prefilter,
    pub combine: Combine,
    /// §3.4.1: each slice also projected onto the next.
    pub leak_fix: bool,
    /// The light is a sun (§3.5): orthographic slices and the Gaussian pyramid in the
    /// occlusion textures' mipmap levels, whatever `prefilter` says.
    pub sun: bool,
}

impl OcclusionSettings {
    pub fn of(scene: &Scene) -> OcclusionSettings {
        let sun = scene.lights.first().and_then(|l| l.sun()).is_some();
        OcclusionSettings {
            slices: scene.shadow.slices,
            size: scene.shadow.map_size,
            // A sun's Gaussian pyramid is read as mipmaps are (trilinear at a lod).
            prefilter: if sun {
                Prefilter::Mipmap
            } else {
                scene.shadow.prefilter
            },
            combine: scene.shadow.combine,
            leak_fix: true,
            sun,
        }
    }

    /// RGBA textures of four slices each.
    pub fn textures(&self) -> u32 {
        self.slices.div_ceil(4)
    }
}

/// The light's frame, the slicing view and the slices (see the module note).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliceView {
    /// World → light frame.
    pub frame: Mat4,
    /// The light's half extents (a, b).
    pub light_half: Vec2,
    /// The window's half extents on the light's plane.
    pub half_window: Vec2,
    /// The centre of projection's distance behind the light's plane.
    pub cop: f32,
    /// The first slice's top depth and one slice's depth.
    pub near: f32,
    pub slice_depth: f32,
    /// A sun's tan(α/2), the disc's radius per unit of distance (`occlusion_sun`); `None`
    /// for a rectangle.
    pub sun_tan: Option<f32>,
}

/// The casters' world-space bounding-box corners.
pub fn caster_corners(scene: &Scene) -> Vec<Vec3> {
    scene
        .objects
        .iter()
        .filter(|o| o.casts)
        .filter_map(|o| o.world_mesh().bounds())
        .flat_map(|(lo, hi)| {
            (0..8).map(move |i| {
                Vec3::new(
                    if i & 1 == 0 { lo.x } else { hi.x },
                    if i & 2 == 0 { lo.y } else { hi.y },
                    if i & 4 == 0 { lo.z } else { hi.z },
                )
            })
        })
        .collect()
}

impl SliceView {
    pub fn of(scene: &Scene, area: &AreaRectangle, slices: u32) -> SliceView {
        let centre = area.centre();
        let (a, b) = (area.edge_u.length() * 0.5, area.edge_v.length() * 0.5);
        let u = area.edge_u.normalize_or_zero();
        let mut n = area.edge_u.cross(area.edge_v).normalize_or_zero();
        let corners = caster_corners(scene);
        let mean = corners.iter().copied().sum::<Vec3>() / corners.len().max(1) as f32;
        if n.dot(mean - centre) < 0.0 {
            n = -n;
        }
        let v = n.cross(u);
        let frame = Mat4::from_cols(
            Vec4::new(u.x, v.x, n.x, 0.0),
            Vec4::new(u.y, v.y, n.y, 0.0),
            Vec4::new(u.z, v.z, n.z, 0.0),
            Vec4::new(-u.dot(centre), -v.dot(centre), -n.dot(centre), 1.0),
        );
        let local: Vec<Vec3> = corners.iter().map(|&c| frame.transform_point3(c)).collect();
        let depth =
            |f: fn(f32, f32) -> f32, start: f32| local.iter().map(|c| c.z.max(0.0)).fold(start, f);
        let (near, far) = (depth(f32::min, f32::INFINITY), depth(f32::max, 0.0));
        let (near, far) = if near.is_finite() && far > near {
            (near, far)
        } else {
            (0.0, 1.0)
        };
        let cop = far.max(1e-3);
        let margin = local.iter().fold(1.0f32, |m, c| {
            let shrink = cop / (c.z.max(0.0) + cop);
            m.max(c.x.abs() / a.max(1e-6) * shrink)
                .max(c.y.abs() / b.max(1e-6) * shrink)
        });
        SliceView {
            frame,
            light_half: Vec2::new(a, b),
            half_window: Vec2::new(a, b) * margin,
            cop,
            near,
            slice_depth: (far - near) / slices as f32,
            sun_tan: None,
        }
    }

    /// The uniforms both programs share (`cop` only for a rectangle: the sun's view is
    /// orthographic).
    fn uniforms(&self) -> Vec<Command> {
        let mut commands = vec![
            uniform("half_window", UniformValue::Vec2(self.half_window)),
            uniform("slice_near", UniformValue::Float(self.near)),
            uniform("slice_depth", UniformValue::Float(self.slice_depth)),
        ];
        commands.push(match self.sun_tan {
            Some(tan) => uniform("sun_tan", UniformValue::Float(tan)),
            None => uniform("cop", UniformValue::Float(self.cop)),
        });
        commands
    }
}

pub(crate) fn uniform(name: &str, value: UniformValue) -> Command {
    Command::Uniform {
        name: Arc::from(name),
        value,
    }
}

pub(crate) fn shader(name: &str) -> &'static str {
    crate::shaders::find(name).map_or("", |s| s.source)
}

/// eisemann/slices with the slice count and the leak fix compiled in.
fn slice_program(settings: &OcclusionSettings) -> Arc<ShaderProgram> {
    let defines = [
        ("SLICES", settings.slices.to_string()),
        ("LEAK_FIX", u32::from(settings.leak_fix).to_string()),
        ("SUN", u32::from(settings.sun).to_string()),
    ];
    Arc::new(ShaderProgram {
        name: "eisemann/slices".into(),
        vertex: with_defines(shader("eisemann/slices.vert"), &defines),
        fragment: with_defines(shader("eisemann/slices.frag"), &defines),
        samplers: Vec::new(),
    })
}

/// eisemann/visibility in `look`, the occlusion texture k on unit k.
fn visibility_program(settings: &OcclusionSettings, look: Look) -> Arc<ShaderProgram> {
    let look_value = match look {
        Look::Shaded => 0,
        Look::Mask => 1,
    };
    let defines = [
        ("SLICES", settings.slices.to_string()),
        (
            "PREFILTER",
            prefilter_define(settings.prefilter).to_string(),
        ),
        ("COMBINE", settings.combine_define().to_string()),
        ("LEVELS", settings.levels().to_string()),
        ("LOOK", look_value.to_string()),
        ("SUN", u32::from(settings.sun).to_string()),
    ];
    Arc::new(ShaderProgram {
        name: "eisemann/visibility".into(),
        vertex: shader("eisemann/visibility.vert").into(),
        fragment: with_defines(shader("eisemann/visibility.frag"), &defines),
        samplers: sampled_textures(settings)
            .into_iter()
            .map(|(name, unit, _)| SamplerBinding { name, unit })
            .collect(),
    })
}

fn prefilter_define(p: Prefilter) -> u32 {
    match p {
        Prefilter::Mipmap => 0,
        Prefilter::Nbuffers => 1,
        Prefilter::Sat => 2,
    }
}

/// What the visibility program samples: (sampler, unit, texture name). Mipmaps: the
/// occlusion texture k on unit k. N-buffers: texture k's even levels on unit k, its odd
/// levels on unit 4 + k. Summed-area tables: texture k's table on unit k.
fn sampled_textures(settings: &OcclusionSettings) -> Vec<(String, u8, u32)> {
    let textures = settings.textures();
    match settings.prefilter {
        Prefilter::Mipmap => (0..textures)
            .map(|k| (format!("occlusion{k}"), k as u8, OCCLUSION_TEXTURE_BASE + k))
            .collect(),
        Prefilter::Sat => (0..textures)
            .map(|k| {
                (
                    format!("sat{k}"),
                    k as u8,
                    sat_texture(k, settings.sat_parity()),
                )
            })
            .collect(),
        Prefilter::Nbuffers => (0..textures)
            .flat_map(|k| {
                [
                    (format!("even{k}"), k as u8, nbuffer_texture(k, 0)),
                    (format!("odd{k}"), 4 + k as u8, nbuffer_texture(k, 1)),
                ]
            })
            .collect(),
    }
}

/// The texture holding occlusion texture k's N-buffer levels of parity `parity`.
pub fn nbuffer_texture(k: u32, parity: u32) -> u32 {
    NBUFFER_TEXTURE_BASE + 2 * k + parity
}

/// The summed-area-table texture of occlusion texture k written by the doubling steps of
/// parity `parity` (step i writes parity i mod 2, reading the other).
pub fn sat_texture(k: u32, parity: u32) -> u32 {
    SAT_TEXTURE_BASE + 2 * k + parity
}

/// The scene's rectangle or sun, or [`TechniqueError::NoAreaLight`] naming this technique.
fn soft_source(scene: &Scene) -> Result<SoftSource, TechniqueError> {
    SoftSource::of(scene).map_err(|e| match e {
        TechniqueError::NoAreaLight { found, .. } => TechniqueError::NoAreaLight {
            technique: ID,
            found,
        },
        other => other,
    })
}

pub fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, TechniqueError> {
    check_light_count(scene)?;
    let source = soft_source(scene)?;
    let settings = OcclusionSettings::of(scene);
    let view = match &source {
        SoftSource::Rectangle(area) => SliceView::of(scene, area, settings.slices),
        SoftSource::Sun(sun) => sun_view(scene, sun, settings.slices),
    };
    let mut setup = Vec::new();
    for k in 0..settings.textures() {
        setup.extend(texture_setup(k, &settings));
        if settings.sun {
            setup.extend(gauss_setup(k, &settings));
        }
        for parity in 0..2 {
            match settings.prefilter {
                Prefilter::Mipmap => {}
                Prefilter::Nbuffers => setup.extend(nbuffer_setup(k, parity, &settings)),
                Prefilter::Sat => setup.extend(sat_setup(k, parity, &settings)),
            }
        }
    }
    setup.push(Command::ActiveTexture(0));
    let filter = match settings.prefilter {
        Prefilter::Mipmap if settings.sun => gauss_pass(&settings),
        Prefilter::Mipmap => filter_pass(&settings),
        Prefilter::Nbuffers => nbuffer_pass(&settings),
        Prefilter::Sat => sat_pass(&settings),
    };
    let maps = vec![slice_pass(scene, prepared, &settings, &view), filter];
    let passes = eye_passes(scene, prepared, &settings, &view, Look::Shaded);
    let mask_passes = eye_passes(scene, prepared, &settings, &view, Look::Mask);
    Ok(Plan {
        setup,
        maps,
        passes,
        mask: visibility_mask(scene, mask_passes),
        framebuffer: FramebufferNeeds {
            width: scene.image.width,
            height: scene.image.height,
            depth: DepthBits::D24,
            stencil: false,
        },
        map_image: None,
        notes: vec![format!(
            "{} slices in {} RGBA textures of {}², {}, {:?} combination",
            settings.slices,
            settings.textures(),
            settings.size,
            match settings.sun {
                true => "a sun: orthographic slices, Gaussian pyramid (§3.5; `prefilter` is \
                         for rectangular lights)"
                    .to_string(),
                false => format!("{:?} prefilter", settings.prefilter),
            },
            settings.combine
        )],
    })
}

/// Occlusion texture k: RGBA8 of size², LINEAR_MIPMAP_LINEAR for the mipmap prefilter
/// (NEAREST when N-buffers or the summed-area table read it texel by texel: complete
/// without mipmaps, as texelFetch needs),
/// CLAMP_TO_BORDER with a border of 0 (no occluder outside the window).
fn texture_setup(k: u32, settings: &OcclusionSettings) -> Vec<Command> {
    let size = settings.size;
    let min_filter = match settings.prefilter {
        Prefilter::Mipmap => Filter::LinearMipmapLinear,
        Prefilter::Nbuffers | Prefilter::Sat => Filter::Nearest,
    };
    let param = |param| Command::TexParameter {
        target: TextureTarget::Texture2D,
        param,
    };
    vec![
        Command::ActiveTexture(k as u8),
        Command::BindTexture {
            target: TextureTarget::Texture2D,
            name: OCCLUSION_TEXTURE_BASE + k,
        },
        Command::TexImage(TexImage {
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::Rgba8,
            requested: None,
            width: size as i32,
            height: size as i32,
            depth: 1,
            border: 0,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            data: TexData::Null,
        }),
        param(TexParam::MinFilter(min_filter)),
        param(TexParam::MagFilter(Filter::Linear)),
        param(TexParam::WrapS(Wrap::ClampToBorder)),
        param(TexParam::WrapT(Wrap::ClampToBorder)),
        param(TexParam::BorderColor(Vec4::ZERO)),
    ]
}

/// The casters sliced into the occlusion textures, one draw of them per texture.
fn slice_pass(
    scene: &Scene,
    prepared: &Prepared,
    settings: &OcclusionSettings,
    view: &SliceView,
) -> Pass {
    let mut commands = vec![
        Command::BindFramebuffer {
            target: FramebufferTarget::Both,
            name: SLICE_FRAMEBUFFER,
        },
        Command::Viewport(Viewport {
            x: 0,
            y: 0,
            width: settings.size as i32,
            height: settings.size as i32,
        }),
        Command::Disable(Capability::DepthTest),
        Command::Disable(Capability::Lighting),
        Command::Enable(Capability::Blend),
        Command::BlendFunc {
            src: BlendFactor::One,
            dst: BlendFactor::One,
        },
        Command::ClearColor(Vec4::ZERO),
        Command::MatrixMode(crate::ff::MatrixMode::Modelview),
        Command::LoadMatrix(view.frame),
        Command::UseProgram(Some(slice_program(settings))),
    ];
    commands.extend(view.uniforms());
    for k in 0..settings.textures() {
        commands.extend([
            Command::FramebufferTexture {
                target: FramebufferTarget::Both,
                attachment: AttachmentPoint::Color(0),
                texture: Some((TextureTarget::Texture2D, OCCLUSION_TEXTURE_BASE + k)),
                level: 0,
                layer: 0,
            },
            Command::Clear(ClearMask {
                color: true,
                depth: false,
                stencil: false,
                accum: false,
            }),
            uniform("first_slice", UniformValue::Float((4 * k) as f32)),
        ]);
        commands.extend(objects(
            scene,
            prepared,
            |o| o.casts,
            Paint::Flat(Vec4::ONE),
        ));
    }
    commands.extend(back_to_the_window());
    commands.extend([
        Command::Disable(Capability::Blend),
        Command::Enable(Capability::DepthTest),
    ]);
    Pass {
        name: "slices",
        commands,
    }
}

/// The N-buffer levels of parity `parity` of occlusion texture k: RGBA8, `size` wide,
/// ⌈levels / 2⌉ · size high (level l at rows (l / 2) · size), LINEAR, CLAMP_TO_EDGE.
fn nbuffer_setup(k: u32, parity: u32, settings: &OcclusionSettings) -> Vec<Command> {
    let param = |param| Command::TexParameter {
        target: TextureTarget::Texture2D,
        param,
    };
    let rows = settings.levels().div_ceil(2) * settings.size;
    vec![
        Command::BindTexture {
            target: TextureTarget::Texture2D,
            name: nbuffer_texture(k, parity),
        },
        Command::TexImage(TexImage {
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::Rgba8,
            requested: None,
            width: settings.size as i32,
            height: rows as i32,
            depth: 1,
            border: 0,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            data: TexData::Null,
        }),
        param(TexParam::MinFilter(Filter::Linear)),
        param(TexParam::MagFilter(Filter::Linear)),
        param(TexParam::WrapS(Wrap::ClampToEdge)),
        param(TexParam::WrapT(Wrap::ClampToEdge)),
    ]
}

/// A quad covering the window in clip coordinates (for full-window program passes).
pub(crate) fn window_quad() -> Arc<crate::ff::Geometry> {
    let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
    Arc::new(crate::ff::Geometry::new(
        crate::ff::Primitive::Quads,
        corners
            .iter()
            .map(|&(x, y)| Vec4::new(x, y, 0.0, 1.0))
            .collect(),
    ))
}

/// The N-buffers of §3.2: level 0 the occlusion texture itself, level l from level l − 1
/// (eisemann/nbuffer), each level drawn into the rows of its parity's texture while the
/// other parity's texture is read — no texture is read and written in one draw.
fn nbuffer_pass(settings: &OcclusionSettings) -> Pass {
    let size = settings.size as i32;
    let quad = window_quad();
    let mut commands = vec![uniform("texels", UniformValue::Int(size))];
    for k in 0..settings.textures() {
        // Level 0: the occlusion texture copied (a box of one texel: half_box 0 reads the
        // same texel four times).
        for l in 0..settings.levels() {
            let (source, source_row, half_box) = match l {
                0 => (OCCLUSION_TEXTURE_BASE + k, 0, 0),
                _ => (
                    nbuffer_texture(k, (l - 1) % 2),
                    ((l - 1) / 2) as i32 * size,
                    1 << (l - 1),
                ),
            };
            let target_row = (l / 2) as i32 * size;
            commands.extend([
                Command::FramebufferTexture {
                    target: FramebufferTarget::Both,
                    attachment: AttachmentPoint::Color(0),
                    texture: Some((TextureTarget::Texture2D, nbuffer_texture(k, l % 2))),
                    level: 0,
                    layer: 0,
                },
                Command::BindTexture {
                    target: TextureTarget::Texture2D,
                    name: source,
                },
                Command::Viewport(Viewport {
                    x: 0,
                    y: target_row,
                    width: size,
                    height: size,
                }),
                uniform("source_row", UniformValue::Int(source_row)),
                uniform("target_row", UniformValue::Int(target_row)),
                uniform("half_box", UniformValue::Int(half_box)),
                Command::Draw(quad.clone()),
            ]);
        }
    }
    prefilter_pass("eisemann/nbuffer", commands)
}

/// Summed-area table k of parity `parity`: RGBA32F of size² (sums of up to size² binary
/// texels: integers, exact in a float up to 2^24, i.e. maps up to 4096²; larger ones round
/// the sums far from the origin), LINEAR (the look-up interpolates
/// the table between texel corners, see visibility.frag), CLAMP_TO_BORDER with a border of
/// 0 (the sum before the first texel).
pub fn sat_setup(k: u32, parity: u32, settings: &OcclusionSettings) -> Vec<Command> {
    let param = |param| Command::TexParameter {
        target: TextureTarget::Texture2D,
        param,
    };
    vec![
        Command::BindTexture {
            target: TextureTarget::Texture2D,
            name: sat_texture(k, parity),
        },
        Command::TexImage(TexImage {
            target: TextureTarget::Texture2D,
            level: 0,
            internal_format: TexFormat::Rgba32F,
            requested: None,
            width: settings.size as i32,
            height: settings.size as i32,
            depth: 1,
            border: 0,
            format: PixelFormat::Rgba,
            ty: PixelType::Float,
            data: TexData::Null,
        }),
        param(TexParam::MinFilter(Filter::Linear)),
        param(TexParam::MagFilter(Filter::Linear)),
        param(TexParam::WrapS(Wrap::ClampToBorder)),
        param(TexParam::WrapT(Wrap::ClampToBorder)),
        param(TexParam::BorderColor(Vec4::ZERO)),
    ]
}

/// The summed-area tables of §3.2 by recursive doubling (eisemann/sat): step i < ⌈log2 n⌉
/// adds the texel 2^i to the left, step ⌈log2 n⌉ + i the texel 2^i below; step 0 reads the
/// occlusion texture, step i the table of parity (i − 1) mod 2, and writes parity i mod 2.
pub fn sat_pass(settings: &OcclusionSettings) -> Pass {
    let size = settings.size as i32;
    let quad = window_quad();
    let per_axis = settings.sat_steps_per_axis();
    let mut commands = vec![Command::Viewport(Viewport {
        x: 0,
        y: 0,
        width: size,
        height: size,
    })];
    for k in 0..settings.textures() {
        for i in 0..settings.sat_steps().max(1) {
            let source = match i {
                0 => OCCLUSION_TEXTURE_BASE + k,
                _ => sat_texture(k, (i - 1) % 2),
            };
            // A one-texel table is the texel: one step of offset 0 would double it, so
            // that step adds nothing (the offset points past the texture).
            let (offset_x, offset_y) = match (settings.sat_steps(), i < per_axis) {
                (0, _) => (size, 0),
                (_, true) => (1 << i, 0),
                (_, false) => (0, 1 << (i - per_axis)),
            };
            commands.extend([
                Command::FramebufferTexture {
                    target: FramebufferTarget::Both,
                    attachment: AttachmentPoint::Color(0),
                    texture: Some((TextureTarget::Texture2D, sat_texture(k, i % 2))),
                    level: 0,
                    layer: 0,
                },
                Command::BindTexture {
                    target: TextureTarget::Texture2D,
                    name: source,
                },
                uniform("offset_x", UniformValue::Int(offset_x)),
                uniform("offset_y", UniformValue::Int(offset_y)),
                Command::Draw(quad.clone()),
            ]);
        }
    }
    prefilter_pass("eisemann/sat", commands)
}

/// A prefilter pass: the program `eisemann/window.vert` + `PROGRAM.frag` (its one sampler
/// `source` on unit 0) drawn by `draws` into the slice framebuffer with the depth test
/// and blending off; then fixed function and the window again, the depth test back on.
pub(crate) fn prefilter_pass(program: &str, draws: Vec<Command>) -> Pass {
    let program = Arc::new(ShaderProgram {
        name: program.into(),
        vertex: shader("eisemann/window.vert").into(),
        fragment: shader(&format!("{program}.frag")).into(),
        samplers: vec![SamplerBinding {
            name: "source".into(),
            unit: 0,
        }],
    });
    let mut commands = vec![
        Command::BindFramebuffer {
            target: FramebufferTarget::Both,
            name: SLICE_FRAMEBUFFER,
        },
        Command::Disable(Capability::DepthTest),
        Command::Disable(Capability::Blend),
        Command::UseProgram(Some(program)),
        Command::ActiveTexture(0),
    ];
    commands.extend(draws);
    commands.extend(back_to_the_window());
    commands.push(Command::Enable(Capability::DepthTest));
    Pass {
        name: "prefilter",
        commands,
    }
}

/// After a pass into the occlusion textures: fixed function again, colour attachment 0
/// detached and the window's framebuffer (0) bound.
pub(crate) fn back_to_the_window() -> [Command; 3] {
    [
        Command::UseProgram(None),
        Command::FramebufferTexture {
            target: FramebufferTarget::Both,
            attachment: AttachmentPoint::Color(0),
            texture: None,
            level: 0,
            layer: 0,
        },
        Command::BindFramebuffer {
            target: FramebufferTarget::Both,
            name: 0,
        },
    ]
}

/// The prefilter of §3.2 on each occlusion texture.
fn filter_pass(settings: &OcclusionSettings) -> Pass {
    let mut commands = Vec::new();
    for k in 0..settings.textures() {
        commands.extend([
            Command::ActiveTexture(k as u8),
            Command::BindTexture {
                target: TextureTarget::Texture2D,
                name: OCCLUSION_TEXTURE_BASE + k,
            },
            Command::GenerateMipmap(TextureTarget::Texture2D),
        ]);
    }
    commands.push(Command::ActiveTexture(0));
    Pass {
        name: "prefilter",
        commands,
    }
}

/// The visibility program's pass-wide uniforms: the slicing view, the light, the
/// texture size, and the eye → light frame matrix and the camera in the light's frame.
fn visibility_uniforms(
    scene: &Scene,
    settings: &OcclusionSettings,
    view: &SliceView,
) -> Vec<Command> {
    let camera = scene.camera.view();
    let eye_to_light = view.frame * camera.inverse();
    let mut commands = view.uniforms();
    commands.extend([
        uniform("light_half", UniformValue::Vec2(view.light_half)),
        uniform("texels", UniformValue::Float(settings.size as f32)),
        uniform("eye_to_light", UniformValue::Mat4(eye_to_light)),
        uniform(
            "camera_light",
            UniformValue::Vec4(eye_to_light * Vec4::new(0.0, 0.0, 0.0, 1.0)),
        ),
    ]);
    commands
}

/// Each object drawn with its `receives` uniform.
fn visibility_draws(scene: &Scene, prepared: &Prepared, paint: Paint) -> Vec<Command> {
    let mut commands = Vec::new();
    for receives in [true, false] {
        if !scene.objects.iter().any(|o| o.receives == receives) {
            continue;
        }
        commands.push(uniform(
            "receives",
            UniformValue::Float(if receives { 1.0 } else { 0.0 }),
        ));
        commands.extend(objects(scene, prepared, |o| o.receives == receives, paint));
    }
    commands
}

fn bind_occlusion(settings: &OcclusionSettings) -> Vec<Command> {
    let mut commands = Vec::new();
    for (_, unit, name) in sampled_textures(settings) {
        commands.extend([
            Command::ActiveTexture(unit),
            Command::BindTexture {
                target: TextureTarget::Texture2D,
                name,
            },
        ]);
    }
    commands.push(Command::ActiveTexture(0));
    commands
}

fn eye_passes(
    scene: &Scene,
    prepared: &Prepared,
    settings: &OcclusionSettings,
    view: &SliceView,
    look: Look,
) -> Vec<Pass> {
    let program = visibility_program(settings, look);
    match look {
        Look::Mask => {
            let mut commands = eye_start(scene, look, false);
            commands.push(Command::Disable(Capability::Lighting));
            commands.extend(bind_occlusion(settings));
            commands.push(Command::UseProgram(Some(program)));
            commands.extend(visibility_uniforms(scene, settings, view));
            commands.extend(visibility_draws(scene, prepared, Paint::Flat(Vec4::ONE)));
            commands.push(Command::UseProgram(None));
            commands.extend(reset(&[]));
            vec![Pass {
                name: "visibility",
                commands,
            }]
        }
        Look::Shaded => {
            let mut lit = vec![
                Command::DepthFunc(CompareFunc::Equal),
                Command::DepthMask(false),
                Command::Enable(Capability::Blend),
                Command::BlendFunc {
                    src: BlendFactor::One,
                    dst: BlendFactor::One,
                },
            ];
            // Light 0's position and colour, set under the camera, for the built-ins.
            lit.extend(lighting(scene, look, LightSet::ShadowingOnly));
            lit.extend(bind_occlusion(settings));
            lit.push(Command::UseProgram(Some(program)));
            lit.extend(visibility_uniforms(scene, settings, view));
            lit.extend(visibility_draws(scene, prepared, Paint::Material));
            lit.push(Command::UseProgram(None));
            lit.extend(reset(&[]));
            vec![
                dim_pass(scene, prepared, look, false),
                Pass {
                    name: "lit",
                    commands: lit,
                },
            ]
        }
    }
}

/// The mask pass, then glReadPixels of the image as RGBA/UNSIGNED_BYTE, decoded as a
/// visibility (red = the visible fraction in 255ths, background pure blue).
fn visibility_mask(scene: &Scene, passes: Vec<Pass>) -> MaskPlan {
    let plan = super::colour_mask(scene, passes);
    MaskPlan {
        commands: plan.commands,
        source: MaskSource::Visibility {
            slot: MASK_SLOT,
            width: scene.image.width,
            height: scene.image.height,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::LightKind;

    /// The default scene with its spot light made a 2 × 2 rectangle, as the truth's tests do.
    fn area_scene() -> Scene {
        let mut scene = Scene::default_scene();
        let light = &mut scene.lights[0];
        let centre = light.view.eye;
        light.kind = LightKind::Area {
            corner: centre - Vec3::new(1.0, 0.0, 1.0),
            edge_u: Vec3::new(2.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.0, 2.0),
        };
        scene.shadow.technique = ID;
        scene
    }

    #[test]
    fn every_caster_projects_inside_the_window_and_the_slices_span_the_casters() {
        let scene = area_scene();
        let SoftSource::Rectangle(area) = soft_source(&scene).unwrap() else {
            panic!("the scene's light is a rectangle");
        };
        let view = SliceView::of(&scene, &area, 16);
        assert!(view.half_window.x >= view.light_half.x - 1e-6);
        // The window keeps the light's aspect.
        let aspect = view.half_window / view.light_half;
        assert!((aspect.x - aspect.y).abs() < 1e-5);
        let mut deepest = 0.0f32;
        for o in scene.objects.iter().filter(|o| o.casts) {
            for p in o.world_mesh().positions {
                let q = view.frame.transform_point3(p);
                assert!(q.z >= view.near - 1e-3, "{q} above the first slice");
                deepest = deepest.max(q.z);
                // x·cop / (half_window · (z + cop)) within [−1, 1].
                let ndc = q.truncate() * view.cop / (view.half_window * (q.z + view.cop));
                assert!(ndc.abs().max_element() <= 1.0 + 1e-4, "{p} lands at {ndc}");
            }
        }
        let far = view.near + 16.0 * view.slice_depth;
        assert!((far - deepest).abs() < 1e-2 * far, "{far} vs {deepest}");
        // The light's centre is the frame's origin, its axis z.
        let c = view.frame.transform_point3(area.centre());
        assert!(c.length() < 1e-4, "{c}");
    }

    #[test]
    fn the_plan_slices_into_one_texture_per_four_slices_and_leaves_no_program_in_use() {
        for (slices, prefilter) in [
            (4, Prefilter::Mipmap),
            (8, Prefilter::Nbuffers),
            (16, Prefilter::Nbuffers),
        ] {
            let mut scene = area_scene();
            scene.shadow.slices = slices;
            scene.shadow.prefilter = prefilter;
            let prepared = Prepared::new(&scene);
            let plan = plan(&scene, &prepared).expect("plans");
            let slice_targets = plan.maps[0]
                .commands
                .iter()
                .filter(|c| {
                    matches!(
                        c,
                        Command::FramebufferTexture {
                            texture: Some(_),
                            ..
                        }
                    )
                })
                .count();
            assert_eq!(slice_targets as u32, slices / 4);
            for pass in plan.maps.iter().chain(&plan.passes).chain([&Pass {
                name: "mask",
                commands: plan.mask.commands.clone(),
            }]) {
                let last = pass
                    .commands
                    .iter()
                    .rev()
                    .find(|c| matches!(c, Command::UseProgram(_)));
                assert!(
                    last.is_none() || last == Some(&Command::UseProgram(None)),
                    "pass `{}` leaves a program in use",
                    pass.name
                );
            }
            assert!(matches!(plan.mask.source, MaskSource::Visibility { .. }));
        }
    }

    #[test]
    fn refusals_name_the_technique_and_what_to_change() {
        let mut scene = Scene::default_scene();
        scene.shadow.technique = ID;
        let prepared = Prepared::new(&scene);
        let err = plan(&scene, &prepared).unwrap_err().to_string();
        assert!(
            err.contains("occlusion-textures") && err.contains("a spot light"),
            "{err}"
        );
    }

    #[test]
    fn the_summed_area_table_takes_two_doubling_steps_per_power_of_two_and_ends_sampled() {
        // (map size, steps per axis): ⌈log2 n⌉, so that the last step reaches the row's end.
        for (size, per_axis) in [(1, 0), (2, 1), (256, 8), (300, 9), (512, 9)] {
            let mut scene = area_scene();
            scene.shadow.prefilter = Prefilter::Sat;
            scene.shadow.map_size = size;
            scene.shadow.slices = 8;
            let settings = OcclusionSettings::of(&scene);
            assert_eq!(settings.sat_steps_per_axis(), per_axis, "{size}");
            let prepared = Prepared::new(&scene);
            let plan = plan(&scene, &prepared).expect("plans");
            let draws = |pass: &Pass| {
                pass.commands
                    .iter()
                    .filter(|c| matches!(c, Command::Draw(_)))
                    .count() as u32
            };
            // Two textures of four slices, each its steps (one copy step for one texel).
            assert_eq!(draws(&plan.maps[1]), 2 * (2 * per_axis).max(1), "{size}");
            // The look-up samples the texture the last step wrote.
            let written: Vec<u32> = plan.maps[1]
                .commands
                .iter()
                .filter_map(|c| match c {
                    Command::FramebufferTexture {
                        texture: Some((_, name)),
                        ..
                    } => Some(*name),
                    _ => None,
                })
                .collect();
            let sampled: Vec<u32> = sampled_textures(&settings)
                .into_iter()
                .map(|(_, _, name)| name)
                .collect();
            let steps = written.len() / 2;
            assert_eq!(sampled, vec![written[steps - 1], written[2 * steps - 1]]);
        }
    }

    #[test]
    fn every_shader_variant_names_its_defines() {
        let scene = area_scene();
        let settings = OcclusionSettings::of(&scene);
        let p = visibility_program(&settings, Look::Mask);
        for define in ["#define SLICES 16", "#define LOOK 1", "#define COMBINE 0"] {
            assert!(p.fragment.contains(define), "{define}");
        }
        assert!(p.fragment.starts_with("#version 330 core\n"));
        assert_eq!(p.samplers.len(), 4);
    }
}
