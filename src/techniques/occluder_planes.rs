//! `occluder-planes`: Coleman's occluder textures (thesis 003, §4), in the fixed-function
//! form. Each caster carries shadow planes (`[[object.plane]]`, or the `f35` layout's
//! three); each plane holds an occluder texture, black where the part of the object it
//! stands for blocks the light. A fragment is shadowed by a plane when the ray from it
//! towards the light meets the plane between it and the light, inside the black.
//!
//! ```text
//! setup  per plane k: glBindTexture(3D, 64 + k); LINEAR; S, T CLAMP_TO_BORDER (white),
//!                     R CLAMP_TO_EDGE;
//!                     glTexImage3D(LUMINANCE8, w, h, 2): slice 0 white, slice 1 the occluder
//! frame  dim:  the shadowing light off; draw everything (no light pass: no map at all)
//!        lit:  glDepthFunc(EQUAL); glBlendFunc(ONE, ONE); only the shadowing light
//!              unit k: the plane's texture, MODULATE, OBJECT_LINEAR S, T, R, Q
//!              per receiver: the planes' object planes (directional light), or the
//!              identity planes and the texture matrix (point light); draw it
//! ```
//!
//! **The plane's coordinates are affine (or projective) in the vertex.** With L the
//! direction towards a directional light, the ray p + s·L meets the plane (o, n) at
//! s_I = n·(o − p) / (n·L) (equation 6), affine in p, so the intersection q = p + s_I·L is
//! too, and so are s = right·(q − o) / width and t = up·(q − o) / height (equation 8 with
//! the appendix's sign): three rows of a 4×4 matrix, computed on the CPU from the light
//! and the object's transform, given to GL as OBJECT_LINEAR planes. For a point light at
//! S the ray is p + s·(S − p): with a = n·(o − p), b = n·(S − p) and c = n·(S − o),
//! q − o = (c·p + a·S − b·o) / b — projective, so Q = b and the matrix goes on the
//! texture matrix stack (texgen makes (x, y, z, 1)); GL divides by q.
//!
//! **"Behind the plane" is the third coordinate.** Coleman's fragment shader ignores an
//! occluder that is not between the point and the light (s_I ≤ 0, §4.1 "false shadow").
//! Here r = ½ + s_I / (4ε) (ε = 10⁻⁴ of the plane's larger side) looks up a 3D texture of
//! two slices: r ≤ ¼ reads the white slice (factor 1), r ≥ ¾ the occluder (CLAMP_TO_EDGE
//! clamps r, and LINEAR blends the two slices only for |s_I| < ε). Outside the plane's
//! rectangle S and T read the white border (CLAMP_TO_BORDER): nothing occludes there. The
//! fragment shader's `saturate` reads the edge texel instead, which is the same for the
//! thesis's textures (white at their edges) but not for an all-black one, which §5 wants
//! black only "if the texture coordinates were in the range [0, 1]". For a point light a
//! plane beyond the light (s_I > 1) still counts.
//!
//! **The factors multiply.** Unit 0 MODULATEs the lit fragment colour by its texel, unit k
//! the previous unit's result: the shadowing light's contribution × Π factor_k, added
//! over the dim pass, which keeps the ambient — Coleman's
//! `diffuse · shadowPercent + ambient`. Every receiver looks up every caster's planes, its
//! own included (self-shadowing), at most MAX_TEXTURE_UNITS in one draw.
//!
//! **Sections** (`[[object.section]]`, the thesis's teapot, §5: "any one section of the
//! teapot would only have to consider shadow planes for that section"): a receiver cut
//! into sections is drawn once per section in the lit pass, clipped to it by user clip
//! planes (section k: its cut and the other side of every earlier cut), looking up only
//! that section's own planes and the other casters'. A fragment on a cut itself is kept by
//! both sides (glClipPlane keeps a·p ≥ 0) and may be lit twice there.
//!
//! A plane parallel to the light (|n·L| < 10⁻⁶) casts nothing: its R is a constant 0.
//!
//! **Other forms.** `[shadow] program = "coleman"` runs the thesis's own shaders and
//! `"generic"` a program generated for the scene's planes (`occluder_program`); both keep
//! this mask (white × Π factors over the dim pass's black) and run on the emulated
//! pipeline only.

use glam::{Mat4, Vec3, Vec4};
use std::sync::Arc;

use crate::ff::{
    self, Capability, Command, Filter, MatrixMode, PixelFormat, PixelType, TexCoord, TexData,
    TexFormat, TexGenMode, TexGenParam, TexImage, TexParam, TextureTarget, Wrap, MAX_TEXTURE_UNITS,
};
use crate::mesh::occluder::{OccluderTexture, PlaneFrame, PASSES};
use crate::scene::{LightKind, OccluderPlane, OccluderProgram, Scene};
use crate::vocab::TechniqueId;

use super::occluder_program as program;
use super::parts::{
    dim_pass, does_not_receive, eye_start, lighting, objects, reset, LightSet, Look,
};
use super::{check_light_count, colour_mask, Pass, Plan, Prepared, Technique, TechniqueError};

pub const ID: TechniqueId = TechniqueId::OccluderPlanes;

pub const TECHNIQUE: Technique = Technique {
    summary:
        "Coleman's occluder planes: per-object planes with occluder textures, one eye pass, no map",
    plan,
};

/// The texture name of plane k: `OCCLUDER_TEXTURE_BASE + k`.
pub const OCCLUDER_TEXTURE_BASE: u32 = 64;

/// ε of the behind-the-plane ramp, relative to the plane's larger side.
pub const BEHIND_RAMP: f32 = 1e-4;

/// Below this |n·L| (unit vectors) a plane is taken as parallel to the light.
const PARALLEL: f32 = 1e-6;

/// Where the light is, in some object's space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LightAt {
    /// Towards a directional light (any length).
    Direction(Vec3),
    /// A point (point, spot or an area light's centre).
    Point(Vec3),
}

/// One plane of one caster, as the technique uses it.
#[derive(Debug, Clone, PartialEq)]
pub struct ScenePlane {
    /// Index of the caster in `scene.objects`.
    pub caster: usize,
    pub plane: OccluderPlane,
}

/// Every caster's planes, in scene order (object, then plane): plane k uses unit k.
pub fn scene_planes(scene: &Scene) -> Result<Vec<ScenePlane>, TechniqueError> {
    let planes: Vec<ScenePlane> = scene
        .shadow
        .planes
        .iter()
        .filter(|p| scene.objects.get(p.object).is_some_and(|o| o.casts))
        .flat_map(|p| {
            p.planes.iter().map(|plane| ScenePlane {
                caster: p.object,
                plane: plane.clone(),
            })
        })
        .collect();
    if planes.is_empty() {
        return Err(TechniqueError::NoShadowPlanes { technique: ID });
    }
    Ok(planes)
}

/// One draw of a receiver in the lit pass (`scene::plane_lookups`): the clip planes that
/// cut it to a section (object space) and the planes it looks up, as indices into
/// [`scene_planes`]' list; unit u reads `planes[u]`.
#[derive(Debug, Clone, PartialEq)]
pub struct ReceiverDraw {
    pub receiver: usize,
    pub clips: Vec<Vec4>,
    pub planes: Vec<usize>,
}

/// Every receiver's draws, refused when one looks up more planes than there are texture
/// units (a scene read from a file was refused already, at its line).
pub fn receiver_draws(
    scene: &Scene,
    planes: &[ScenePlane],
) -> Result<Vec<ReceiverDraw>, TechniqueError> {
    let first = |caster: usize| planes.iter().position(|p| p.caster == caster);
    crate::scene::plane_lookups(&scene.objects, &scene.shadow.planes)
        .into_iter()
        .map(|l| {
            let looked: Vec<usize> = l
                .planes
                .iter()
                .filter_map(|&(caster, k)| first(caster).map(|f| f + k))
                .collect();
            if looked.len() > MAX_TEXTURE_UNITS {
                return Err(TechniqueError::TooManyShadowPlanes {
                    count: looked.len(),
                    max: MAX_TEXTURE_UNITS,
                });
            }
            Ok(ReceiverDraw {
                receiver: l.receiver,
                clips: l.clips,
                planes: looked,
            })
        })
        .collect()
}

/// Clip planes 0… set to `clips` (object space: specified under the receiver's model
/// matrix, which glClipPlane applies the inverse of) and enabled.
pub fn clip_commands(model: Mat4, clips: &[Vec4]) -> Vec<Command> {
    if clips.is_empty() {
        return Vec::new();
    }
    let mut commands = vec![Command::PushMatrix, Command::MultMatrix(model)];
    for (c, &equation) in clips.iter().enumerate() {
        commands.push(Command::ClipPlane {
            plane: c as u8,
            equation,
        });
    }
    commands.push(Command::PopMatrix);
    commands.extend((0..clips.len()).map(|c| Command::Enable(Capability::ClipPlane(c as u8))));
    commands
}

/// The dim pass with each sectioned receiver drawn section by section, clipped as the lit
/// pass draws it: clipping makes new vertices, whose interpolated depths need not equal
/// the whole triangle's, so both passes draw the same clipped triangles and the lit pass's
/// DepthFunc(EQUAL) finds the depths the dim pass wrote (GL's invariance holds only for
/// the same primitives, Appendix A).
pub fn sectioned_dim_pass(
    scene: &Scene,
    prepared: &Prepared,
    look: Look,
    draws: &[ReceiverDraw],
) -> Pass {
    let clipped: Vec<&ReceiverDraw> = draws.iter().filter(|d| !d.clips.is_empty()).collect();
    if clipped.is_empty() {
        return dim_pass(scene, prepared, look, false);
    }
    let mut commands = eye_start(scene, look, false);
    commands.extend(lighting(scene, look, LightSet::Dim));
    let paint = look.paint(false);
    let is_cut = |o: &crate::scene::Object| {
        clipped
            .iter()
            .any(|d| std::ptr::eq(&scene.objects[d.receiver], o))
    };
    commands.extend(objects(scene, prepared, |o| !is_cut(o), paint));
    for draw in clipped {
        let object = &scene.objects[draw.receiver];
        commands.extend(clip_commands(object.transform.matrix(), &draw.clips));
        commands.extend(objects(scene, prepared, |o| std::ptr::eq(o, object), paint));
        commands.extend(unclip_commands(&draw.clips));
    }
    Pass {
        name: "dim",
        commands,
    }
}

/// The clip planes `clip_commands` enabled, disabled.
pub fn unclip_commands(clips: &[Vec4]) -> Vec<Command> {
    (0..clips.len())
        .map(|c| Command::Disable(Capability::ClipPlane(c as u8)))
        .collect()
}

/// The shadowing light (the scene's first) in world space.
pub fn world_light(scene: &Scene) -> Result<LightAt, TechniqueError> {
    let light = scene
        .lights
        .first()
        .ok_or(TechniqueError::NoLight { technique: ID })?;
    Ok(match (light.kind, light.position()) {
        // `direction` is where the light travels; towards the light is its opposite.
        (LightKind::Directional { direction, .. }, _) => LightAt::Direction(-direction),
        (_, Some(p)) => LightAt::Point(p),
        (_, None) => LightAt::Direction(light.view.eye - light.view.at),
    })
}

/// The light in the space of an object with model matrix `model`: a direction by M₃⁻¹
/// (world d = M₃·d_object), a point by M⁻¹.
pub fn light_in(light: LightAt, model: Mat4) -> LightAt {
    let inverse = model.inverse();
    match light {
        LightAt::Direction(d) => LightAt::Direction(inverse.transform_vector3(d)),
        LightAt::Point(p) => LightAt::Point(inverse.transform_point3(p)),
    }
}

/// The matrix whose rows are S, T, R, Q of `frame` under `light` (both in the same object
/// space): (s/q, t/q) is where the ray towards the light meets the plane, in the occluder
/// texture's [0, 1]², and r/q = ½ + s_I / (4ε) (module note).
pub fn plane_matrix(frame: &PlaneFrame, light: LightAt) -> Mat4 {
    let PlaneFrame {
        origin: o,
        normal: n,
        up,
        right,
        width,
        height,
    } = *frame;
    let gain = 1.0 / (4.0 * BEHIND_RAMP * width.max(height));
    // a(p) = n·(o − p) as a row: (−n, n·o).
    let a = (-n).extend(n.dot(o));
    let rows = match light {
        LightAt::Direction(l) => {
            let k = n.dot(l);
            if k.abs() < PARALLEL * l.length() {
                return parallel();
            }
            // axis·(q − o) = axis·(p − o) + (axis·L / k)·a(p).
            let along = |axis: Vec3, size: f32| {
                ((axis).extend(-axis.dot(o)) + a * (axis.dot(l) / k)) / size
            };
            [
                along(right, width),
                along(up, height),
                Vec4::new(0.0, 0.0, 0.0, 0.5) + a * (gain / k),
                Vec4::W,
            ]
        }
        LightAt::Point(s) => {
            let c = n.dot(s - o);
            // b(p) = n·(S − p): (−n, n·S).
            let b = (-n).extend(n.dot(s));
            if c.abs() < PARALLEL * (s - o).length().max(1.0) {
                // The light in the plane: every ray meets it at the light.
                return parallel();
            }
            // axis·(c·p + a·S − b·o), over the size.
            let along = |axis: Vec3, size: f32| {
                (axis.extend(0.0) * c + a * axis.dot(s) - b * axis.dot(o)) / size
            };
            [
                along(right, width),
                along(up, height),
                b * 0.5 + a * gain,
                b,
            ]
        }
    };
    Mat4::from_cols(rows[0], rows[1], rows[2], rows[3]).transpose()
}

/// The matrix of a plane the light runs along: r = 0 everywhere (the white slice).
fn parallel() -> Mat4 {
    Mat4::from_cols(Vec4::ZERO, Vec4::ZERO, Vec4::ZERO, Vec4::W).transpose()
}

/// The matrix of plane `p` for receiver `receiver` (object index): the plane's rows in the
/// caster's space, times M_caster⁻¹ · M_receiver, so it takes the receiver's object
/// coordinates.
pub fn receiver_matrix(scene: &Scene, light: LightAt, p: &ScenePlane, receiver: usize) -> Mat4 {
    let caster = scene.objects[p.caster].transform.matrix();
    let model = scene.objects[receiver].transform.matrix();
    plane_matrix(&p.plane.frame, light_in(light, caster)) * caster.inverse() * model
}

/// The factor plane `p` puts on the light at world point `x` (CPU model, NEAREST look-up):
/// 1 when the plane is not between `x` and the light, else the occluder's texel / 255 at
/// (s/q, t/q) (white outside [0, 1]²).
pub fn factor_at(scene: &Scene, light: LightAt, p: &ScenePlane, x: Vec3) -> f32 {
    let caster = scene.objects[p.caster].transform.matrix();
    let stq =
        plane_matrix(&p.plane.frame, light_in(light, caster)) * caster.inverse() * x.extend(1.0);
    let (s, t, r) = (stq.x / stq.w, stq.y / stq.w, stq.z / stq.w);
    if r <= 0.5 {
        return 1.0;
    }
    f32::from(p.plane.texture.nearest(glam::Vec2::new(s, t))) / 255.0
}

pub fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, TechniqueError> {
    check_light_count(scene)?;
    let planes = scene_planes(scene)?;
    let draws = receiver_draws(scene, &planes)?;
    let light = world_light(scene)?;
    let (setup, passes, mask) = match scene.shadow.occluder_program {
        OccluderProgram::FixedFunction => {
            let mut setup = Vec::new();
            for (k, p) in planes.iter().enumerate() {
                setup.extend(texture_commands(texture_name(k), &p.plane.texture));
            }
            let look = |look| eye_passes(scene, prepared, &planes, &draws, light, look);
            (setup, look(Look::Shaded), look(Look::Mask))
        }
        OccluderProgram::Generic => {
            let look =
                |look| program::generic_passes(scene, prepared, &planes, &draws, light, look);
            (
                program::setup(&planes),
                look(Look::Shaded),
                look(Look::Mask),
            )
        }
        OccluderProgram::Coleman => {
            let fit = program::coleman_fit(scene, &planes, light)
                .map_err(|why| TechniqueError::ColemanDoesNotFit { why })?;
            let look = |look| program::coleman_passes(scene, prepared, &fit, look);
            (
                program::setup(&planes),
                look(Look::Shaded),
                look(Look::Mask),
            )
        }
    };
    let mask = colour_mask(scene, mask);
    let (width, height) = (scene.image.width, scene.image.height);
    let mut plan = Plan::single(
        passes,
        mask,
        super::FramebufferNeeds {
            width,
            height,
            depth: scene.shadow.depth,
            stencil: false,
        },
    );
    plan.setup = setup;
    if scene.shadow.occluder_program == OccluderProgram::Coleman && scene.lights.len() > 1 {
        plan.notes.push(format!(
            "program = \"coleman\" lights the receivers with the first light only (the \
             appendix's glstate.light[0]); the other {} are left out of them",
            scene.lights.len() - 1
        ));
    }
    Ok(plan)
}

/// The texture name of plane `k`.
pub fn texture_name(k: usize) -> u32 {
    OCCLUDER_TEXTURE_BASE + k as u32
}

/// The 3D texture of an occluder: slice 0 (r = ¼) white, slice 1 (r = ¾) the occluder;
/// LINEAR; S and T CLAMP_TO_BORDER with a white border (outside the plane's rectangle
/// nothing occludes), R CLAMP_TO_EDGE (the behind-the-plane ramp saturates).
pub fn texture_commands(name: u32, texture: &OccluderTexture) -> Vec<Command> {
    let mut texels = vec![PASSES; texture.texels.len()];
    texels.extend_from_slice(&texture.texels);
    luminance_texture(TextureTarget::Texture3D, name, texture, 2, texels)
}

/// A LUMINANCE8 occluder texture of `depth` slices of `texture`'s size: LINEAR, S and T
/// CLAMP_TO_BORDER with a white border, R (3D only) CLAMP_TO_EDGE.
pub fn luminance_texture(
    target: TextureTarget,
    name: u32,
    texture: &OccluderTexture,
    depth: i32,
    texels: Vec<u8>,
) -> Vec<Command> {
    let param = |param| Command::TexParameter { target, param };
    let mut commands = vec![
        Command::BindTexture { target, name },
        param(TexParam::MinFilter(Filter::Linear)),
        param(TexParam::MagFilter(Filter::Linear)),
        param(TexParam::WrapS(Wrap::ClampToBorder)),
        param(TexParam::WrapT(Wrap::ClampToBorder)),
        param(TexParam::BorderColor(Vec4::ONE)),
    ];
    if target == TextureTarget::Texture3D {
        commands.push(param(TexParam::WrapR(Wrap::ClampToEdge)));
    }
    commands.push(Command::TexImage(TexImage {
        target,
        level: 0,
        internal_format: TexFormat::Luminance8,
        requested: None,
        width: texture.width as i32,
        height: texture.height as i32,
        depth,
        border: 0,
        format: PixelFormat::Luminance,
        ty: PixelType::UnsignedByte,
        data: TexData::Bytes(Arc::from(texels)),
    }));
    commands
}

/// The dim pass, then the shadowing light added, receiver draw by receiver draw, through
/// the units of the planes each looks up.
fn eye_passes(
    scene: &Scene,
    prepared: &Prepared,
    planes: &[ScenePlane],
    draws: &[ReceiverDraw],
    light: LightAt,
    look: Look,
) -> Vec<Pass> {
    let projective = matches!(light, LightAt::Point(_));
    let mut lit = vec![
        Command::DepthFunc(ff::CompareFunc::Equal),
        Command::DepthMask(false),
        Command::Enable(Capability::Blend),
        Command::BlendFunc {
            src: ff::BlendFactor::One,
            dst: ff::BlendFactor::One,
        },
    ];
    lit.extend(lighting(scene, look, LightSet::ShadowingOnly));
    let used = draws.iter().map(|d| d.planes.len()).max().unwrap_or(0);
    for u in 0..used {
        lit.extend(unit_commands(u as u8, projective));
    }
    let paint = look.paint(true);
    for draw in draws {
        let object = &scene.objects[draw.receiver];
        for (u, &k) in draw.planes.iter().enumerate() {
            lit.extend([
                Command::ActiveTexture(u as u8),
                Command::BindTexture {
                    target: TextureTarget::Texture3D,
                    name: texture_name(k),
                },
                Command::Enable(Capability::Texture3D),
            ]);
            lit.extend(plane_commands(
                receiver_matrix(scene, light, &planes[k], draw.receiver),
                projective,
            ));
        }
        for u in draw.planes.len()..used {
            lit.extend([
                Command::ActiveTexture(u as u8),
                Command::Disable(Capability::Texture3D),
            ]);
        }
        lit.push(Command::ActiveTexture(0));
        lit.extend(clip_commands(object.transform.matrix(), &draw.clips));
        lit.extend(objects(scene, prepared, |o| std::ptr::eq(o, object), paint));
        lit.extend(unclip_commands(&draw.clips));
    }
    let units: Vec<u8> = (0..used as u8).collect();
    for &u in &units {
        lit.push(Command::ActiveTexture(u));
        lit.push(Command::Disable(Capability::Texture3D));
        if projective {
            lit.extend([
                Command::MatrixMode(MatrixMode::Texture),
                Command::LoadIdentity,
                Command::MatrixMode(MatrixMode::Modelview),
            ]);
        }
    }
    lit.extend(reset(&units));
    lit.extend(objects(scene, prepared, does_not_receive, paint));
    vec![
        sectioned_dim_pass(scene, prepared, look, draws),
        Pass {
            name: "lit",
            commands: lit,
        },
    ]
}

/// Unit `unit`: MODULATE, OBJECT_LINEAR on S, T, R, Q; with a point light the planes are
/// the identity's rows (x, y, z, 1), set once here. Each draw binds and enables its
/// plane's 3D texture.
fn unit_commands(unit: u8, projective: bool) -> Vec<Command> {
    let mut commands = vec![
        Command::ActiveTexture(unit),
        Command::TexEnv(ff::TexEnvParam::Mode(ff::TexEnvMode::Modulate)),
    ];
    for coord in TexCoord::ALL {
        commands.extend([
            Command::TexGen {
                coord,
                param: TexGenParam::Mode(TexGenMode::ObjectLinear),
            },
            Command::Enable(Capability::TextureGen(coord)),
        ]);
    }
    if projective {
        commands.extend(object_planes(Mat4::IDENTITY));
    }
    commands
}

/// The active unit's S, T, R, Q for one receiver: the rows of `m` as object planes
/// (directional light), or `m` on the texture matrix stack (point light).
fn plane_commands(m: Mat4, projective: bool) -> Vec<Command> {
    if projective {
        vec![
            Command::MatrixMode(MatrixMode::Texture),
            Command::LoadMatrix(m),
            Command::MatrixMode(MatrixMode::Modelview),
        ]
    } else {
        object_planes(m)
    }
}

/// glTexGen(coord, OBJECT_PLANE, row) for the four rows of `m`.
fn object_planes(m: Mat4) -> Vec<Command> {
    TexCoord::ALL
        .iter()
        .enumerate()
        .map(|(i, &coord)| Command::TexGen {
            coord,
            param: TexGenParam::ObjectPlane(m.row(i)),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shaders::F35_PLANES;

    fn frame(i: usize) -> PlaneFrame {
        let p = F35_PLANES[i];
        PlaneFrame {
            origin: p.origin,
            normal: p.normal,
            up: p.up,
            right: p.right,
            width: p.width,
            height: p.height,
        }
    }

    /// The matrix's (s, t) and the sign of r − ½ are the thesis's shadow coordinate and
    /// s_I (`ShadowPlane::shadow_coord`) for every F-35 plane, directional light.
    #[test]
    fn directional_rows_are_the_shadow_coordinate_of_the_appendix() {
        let light = Vec3::new(0.3, -0.2, 0.9).normalize();
        for (i, plane) in F35_PLANES.iter().enumerate() {
            let m = plane_matrix(&frame(i), LightAt::Direction(light * 3.0));
            for p in [
                Vec3::new(0.5, -2.0, -0.4),
                Vec3::new(1.3, -3.0, 0.7),
                Vec3::new(-4.0, 1.0, -0.05),
                Vec3::new(0.0, 6.0, 2.0),
            ] {
                let expected = plane.shadow_coord(p, light);
                let got = m * p.extend(1.0);
                assert!((got.w - 1.0).abs() < 1e-6);
                let st = glam::Vec2::new(got.x, got.y);
                assert!(
                    (st - expected.st).abs().max_element() < 1e-4,
                    "{i} {p}: {st} {expected:?}"
                );
                assert_eq!(got.z > 0.5, expected.plane_between(), "{i} {p}");
            }
        }
    }

    /// A point light far away along L gives the directional light's coordinates.
    #[test]
    fn a_far_point_light_tends_to_the_directional_one() {
        let light = Vec3::new(-0.4, 0.1, 0.8).normalize();
        for i in 0..3 {
            let far = plane_matrix(&frame(i), LightAt::Point(light * 1e5));
            let along = plane_matrix(&frame(i), LightAt::Direction(light));
            let p = Vec3::new(0.7, -2.5, -0.3);
            let a = far * p.extend(1.0);
            let b = along * p.extend(1.0);
            assert!(
                (a.x / a.w - b.x).abs() < 1e-3 && (a.y / a.w - b.y).abs() < 1e-3,
                "{i}"
            );
            assert_eq!(a.z / a.w > 0.5, b.z > 0.5, "{i}");
        }
    }

    #[test]
    fn a_point_light_ray_meets_the_plane_where_the_matrix_says() {
        let f = frame(0);
        let s = Vec3::new(1.0, 2.0, 6.0);
        let m = plane_matrix(&f, LightAt::Point(s));
        let p = Vec3::new(0.5, 0.5, -1.0);
        // The ray p + u (S − p) meets z = 0 at u = 1/7.
        let q = p + (s - p) / 7.0;
        let h = m * p.extend(1.0);
        let st = glam::Vec2::new(h.x / h.w, h.y / h.w);
        let expected = glam::Vec2::new((q.x - f.origin.x) / 15.0, (q.y - f.origin.y) / 15.0);
        assert!(
            (st - expected).abs().max_element() < 1e-5,
            "{st} {expected}"
        );
        assert!(h.z / h.w > 0.5, "between");
        // Above the plane, on the light's side: not between.
        let above = m * Vec3::new(0.5, 0.5, 1.0).extend(1.0);
        assert!(above.z / above.w < 0.5);
    }

    #[test]
    fn a_plane_along_the_light_casts_nothing() {
        let m = plane_matrix(&frame(0), LightAt::Direction(Vec3::X));
        let h = m * Vec3::new(1.0, 2.0, -3.0).extend(1.0);
        assert!(h.z / h.w < 0.5);
    }
}
