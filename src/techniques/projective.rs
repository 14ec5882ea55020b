//! `projective`: the slide projector — the casters drawn black on white from the light into
//! a texture, projected onto the receivers with eye-linear texgen (lecture notes 004,
//! "shadow textures"; thesis 003 §2.3; Kilgard's projective texturing).
//!
//! ```text
//! maps   silhouette: glViewport(map); glDisable(LIGHTING); glClearColor(1,1,1,1); glClear(COLOR|DEPTH)
//!                    the projector's projection and modelview; glColor3f(0,0,0); draw the casters
//!        copy:       glBindTexture(2D, map); glCopyTexImage2D(RGB8, 0, 0, map, map)
//! frame  dim:        the shadowing light off; draw everything
//!        lit:        glDepthFunc(EQUAL); glBlendFunc(ONE, ONE); only the shadowing light
//!                    unit 0: the silhouette, MODULATE; eye-linear S, T, R, Q = rows of B·C
//!                    draw receivers (others without the texture)
//! ```
//! C is the projector's world → clip matrix and B the [−1, 1] → [0, 1] bias, so the
//! generated (s/q, t/q) is where the light sees the fragment in the silhouette: white adds
//! the shadowing light, black adds nothing. Outside the silhouette the white border
//! (CLAMP_TO_BORDER) keeps fragments lit.
//!
//! **Two projectors** (`[shadow] projector`):
//! - `perspective`: C = P_light·V_light, the light's own frustum. Casters anywhere in it
//!   print their silhouette, including those below the receivers' plane.
//! - `pseudo-depth` (the lecture notes): the casters are flattened onto the largest flat
//!   receiver p (oriented so that d_L = p·l > 0) by the shadow matrix, viewed head-on by a
//!   glOrtho of the plane's region, with the third coordinate replaced by the pseudo-depth
//!   s = Z/W: W = (p·l)·x_w − l_w·(p·x) is the shadow matrix's w, and Z = d_L for a point
//!   light (s = d_L / (d_L − d(x))), Z = (p·l)·(1 + d(x)/D) for a directional one (D = 2R,
//!   the scene's diameter). s ≥ 1 between the plane and the light, s < 1 below the plane,
//!   and W < 0 beyond the light, where GL's clip volume −w ≤ z ≤ w is empty. So a glOrtho
//!   with near 1 clips every false shadow. The near plane sits at d(x) = δ (δ = 10⁻³·R)
//!   rather than 0, so the receiver lying in p — and anything touching it for less than δ —
//!   casts nothing instead of flickering on the clip boundary. The far plane is 64, not ∞:
//!   the near test z_c + w_c = 2(Z − n·W)/(f − n) shrinks as f grows until rounding of
//!   z_c and w_c decides it; 64 keeps the margin ≥ 30× the rounding and only drops casters
//!   within 1/64 of the light's height below it.
//!
//! **Casters kept apart from receivers.** A silhouette says that *something* stands between
//! the light and the fragment, not whether it is nearer the light: an object projected
//! through its own silhouette is dark wherever it covers it — its lit side included. The
//! era's projective shadows therefore never let an object receive its own silhouette:
//! each receiver gets the silhouette of the *other* casters ([`Silhouettes`]: one texture
//! per distinct set — every caster for a receiver that casts nothing, every caster but
//! itself for one that does; the set of all casters is [`MAP_TEXTURE`], the others
//! [`SILHOUETTE_TEXTURE_BASE`] + k). The price is one silhouette and copy per set, and no
//! self-shadowing at all — exactly the gap occluder textures fill; the plan's notes name
//! the objects concerned. Another caster behind a receiver (farther from the light) still
//! shadows it: the silhouette has no depth. Fragments behind the projector (q ≤ 0) read
//! the silhouette mirrored; the notes name receivers reaching there.

use crate::vocab::{Projector, TechniqueId};
use glam::{Mat4, Vec3, Vec4};

use crate::ff::{Command, CopyTexImage, PixelFormat, PixelType, TexFormat, ViewVolume};
use crate::scene::Scene;

use super::map::{map_parameters, read_corner, MapSettings, MAP_IMAGE_SLOT, MAP_TEXTURE};
use super::parts::{map_pass_start, objects, Look, Paint, ShadowLight, BIAS};
use super::planar::{list, object_name};
use super::plane::{area, flat_plane, light_vector, scene_radius};
use super::{
    check_light_count, colour_mask, MapImagePlan, MapImageSource, Pass, Plan, Prepared, Technique,
    TechniqueError,
};

pub const ID: TechniqueId = TechniqueId::Projective;

pub const TECHNIQUE: Technique = Technique {
    summary: "slide projector: the casters' silhouette from the light, projected by texgen",
    plan,
};

/// δ of the pseudo-depth near plane, relative to the scene's radius.
pub const NEAR_OFFSET: f32 = 1e-3;
/// The pseudo-depth far plane (see the module note).
pub const FAR: f32 = 64.0;

/// The first texture name of the silhouettes other than the one of all casters.
pub const SILHOUETTE_TEXTURE_BASE: u32 = 16;

/// The silhouettes a frame needs: each distinct set of casters some receiver is shadowed
/// by (every caster but the receiver itself), and which set each receiver uses.
#[derive(Debug, Clone, PartialEq)]
pub struct Silhouettes {
    /// Object indices of the casters of each set; the set of all casters, when a receiver
    /// uses it, comes first.
    pub sets: Vec<Vec<usize>>,
    /// Per object: the set it receives, `None` for an object that receives nothing.
    pub of_object: Vec<Option<usize>>,
}

impl Silhouettes {
    pub fn of(scene: &Scene) -> Silhouettes {
        let casters: Vec<usize> = (0..scene.objects.len())
            .filter(|&i| scene.objects[i].casts)
            .collect();
        let mut sets: Vec<Vec<usize>> = Vec::new();
        let mut of_object = vec![None; scene.objects.len()];
        let index_of =
            |set: Vec<usize>, sets: &mut Vec<Vec<usize>>| match sets.iter().position(|s| *s == set)
            {
                Some(k) => k,
                None => {
                    sets.push(set);
                    sets.len() - 1
                }
            };
        // The set of all casters first, so that it takes MAP_TEXTURE.
        if scene.objects.iter().any(|o| o.receives && !o.casts) {
            index_of(casters.clone(), &mut sets);
        }
        for (i, o) in scene.objects.iter().enumerate() {
            if o.receives {
                let others: Vec<usize> = casters.iter().copied().filter(|&c| c != i).collect();
                of_object[i] = Some(index_of(others, &mut sets));
            }
        }
        Silhouettes { sets, of_object }
    }

    /// The texture name of set `k`.
    pub fn texture(&self, k: usize) -> u32 {
        if k == 0 {
            MAP_TEXTURE
        } else {
            SILHOUETTE_TEXTURE_BASE + k as u32
        }
    }
}

/// The projector: how the silhouette pass views the casters.
#[derive(Debug, Clone, PartialEq)]
pub struct Projection {
    /// glFrustum (perspective) or glOrtho (pseudo-depth) on the projection stack.
    pub volume: ViewVolume,
    pub volume_command: Command,
    /// The modelview of the silhouette pass: V_light, or the pseudo-depth shadow matrix.
    pub modelview: Mat4,
    /// C = projection · modelview: world → clip.
    pub world_to_clip: Mat4,
    /// The flat receiver the pseudo-depth projector flattens onto.
    pub plane_object: Option<usize>,
}

impl Projection {
    /// Row `i` of B·C: the eye plane of S (0), T (1), R (2) or Q (3).
    pub fn plane(&self, i: usize) -> Vec4 {
        (BIAS * self.world_to_clip).row(i)
    }
}

/// The scene's projector.
pub fn projection(scene: &Scene) -> Result<Projection, TechniqueError> {
    let light = ShadowLight::of(scene, ID)?;
    match scene.shadow.projector {
        Projector::Perspective => {
            let volume = match light.volume {
                Command::Frustum(v) | Command::Ortho(v) => v,
                _ => unreachable!("ShadowLight::volume is glFrustum or glOrtho"),
            };
            Ok(Projection {
                volume,
                volume_command: light.volume.clone(),
                modelview: light.view,
                world_to_clip: light.projection * light.view,
                plane_object: None,
            })
        }
        Projector::PseudoDepth => pseudo_depth(scene, &light),
    }
}

/// The lecture notes' projector (module note).
fn pseudo_depth(scene: &Scene, light: &ShadowLight) -> Result<Projection, TechniqueError> {
    let l = light_vector(&light.light);
    let radius = scene_radius(scene);
    let delta = NEAR_OFFSET * radius;
    let worlds: Vec<_> = scene.objects.iter().map(|o| o.world_mesh()).collect();
    // The largest flat receiver with the light strictly on one side (by 2δ for a point).
    let (object, plane) = scene
        .objects
        .iter()
        .enumerate()
        .filter(|(_, o)| o.receives)
        .filter_map(|(i, _)| {
            let p = flat_plane(&worlds[i])?;
            // Oriented towards the light; a light in the plane (or parallel to it) has no side.
            let p = match p.dot(l) {
                side if side > 0.0 => p,
                side if side < 0.0 => -p,
                _ => return None,
            };
            let clear = l.w == 0.0 || p.dot(l) > 2.0 * delta;
            clear.then_some((i, p))
        })
        .max_by(|a, b| area(&worlds[a.0]).total_cmp(&area(&worlds[b.0])))
        .ok_or(TechniqueError::NoProjectionPlane { technique: ID })?;
    let k = plane.dot(l);
    let w_row = Vec4::new(0.0, 0.0, 0.0, k) - l.w * plane;
    let (z_row, near) = if l.w != 0.0 {
        // s = d_L / (d_L − d): near where d = δ.
        (Vec4::new(0.0, 0.0, 0.0, k), k / (k - delta))
    } else {
        // s = 1 + d / D.
        let diameter = 2.0 * radius;
        (k * (Vec4::W + plane / diameter), 1.0 + delta / diameter)
    };
    // Plane coordinates: origin o (the plane's point nearest the world origin), axes e_u, e_v.
    let n = plane.truncate();
    let origin = -plane.w * n;
    let (e_u, e_v) = n.any_orthonormal_pair();
    // u·W = e_u·(M·x)_xyz − (e_u·o)·W, with (M·x)_xyz rows (p·l)·e_j − l_j·p.
    let axis_row =
        |e: Vec3| k * e.extend(0.0) - e.dot(l.truncate()) * plane - e.dot(origin) * w_row;
    let (u_row, v_row) = (axis_row(e_u), axis_row(e_v));
    // Eye coordinates (u·W, v·W, −Z, W): glOrtho then sees −z_e / w_e = s.
    let modelview = Mat4::from_cols(u_row, v_row, -z_row, w_row).transpose();
    let (lo, hi) = region(scene, &worlds, modelview, k);
    let volume = ViewVolume {
        left: lo.x,
        right: hi.x,
        bottom: lo.y,
        top: hi.y,
        near,
        far: FAR,
    };
    let ortho = crate::ff::matrix::ortho(volume).unwrap_or(Mat4::IDENTITY);
    Ok(Projection {
        volume,
        volume_command: Command::Ortho(volume),
        modelview,
        world_to_clip: ortho * modelview,
        plane_object: Some(object),
    })
}

/// The (u, v) rectangle the silhouette covers: the projections of every receiver vertex
/// with W ≥ (p·l)/8 (nearer the plane than 7/8 of the light's height), padded by 1/64 of
/// its size so edge texels are not the border.
fn region(scene: &Scene, worlds: &[crate::mesh::Mesh], modelview: Mat4, k: f32) -> (Vec3, Vec3) {
    let mut lo = Vec3::splat(f32::INFINITY);
    let mut hi = Vec3::splat(f32::NEG_INFINITY);
    for (o, mesh) in scene.objects.iter().zip(worlds) {
        if !o.receives {
            continue;
        }
        for &p in &mesh.positions {
            let e = modelview * p.extend(1.0);
            if e.w >= k / 8.0 {
                let uv = Vec3::new(e.x / e.w, e.y / e.w, 0.0);
                lo = lo.min(uv);
                hi = hi.max(uv);
            }
        }
    }
    let pad = ((hi - lo) / 64.0).max(Vec3::splat(1e-3));
    (lo - pad, hi + pad)
}

pub fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, TechniqueError> {
    check_light_count(scene)?;
    let map = MapSettings::of(scene);
    let projector = projection(scene)?;
    let silhouettes = Silhouettes::of(scene);
    let bind = |k: usize| Command::BindTexture {
        target: crate::ff::TextureTarget::Texture2D,
        name: silhouettes.texture(k),
    };
    let mut setup = vec![Command::ActiveTexture(0)];
    for k in 0..silhouettes.sets.len().max(1) {
        setup.push(bind(k));
        setup.extend(map_parameters(map.gl_filter()));
    }
    let mut maps = Vec::new();
    for (k, set) in silhouettes.sets.iter().enumerate() {
        maps.push(silhouette_pass(scene, prepared, &projector, map.size, set));
        maps.push(Pass {
            name: "copy",
            commands: vec![
                Command::ActiveTexture(0),
                bind(k),
                Command::CopyTexImage2D(CopyTexImage {
                    face: None,
                    requested: None,
                    level: 0,
                    internal_format: TexFormat::Rgb8,
                    x: 0,
                    y: 0,
                    width: map.size as i32,
                    height: map.size as i32,
                    border: 0,
                }),
            ],
        });
    }
    // `--depth-map` shows the silhouette of every caster, drawn again for the read.
    let all: Vec<usize> = (0..scene.objects.len())
        .filter(|&i| scene.objects[i].casts)
        .collect();
    let mut map_commands = silhouette_pass(scene, prepared, &projector, map.size, &all).commands;
    map_commands.push(read_corner(
        map.size,
        PixelFormat::Luminance,
        PixelType::UnsignedByte,
        MAP_IMAGE_SLOT,
    ));
    let eye = |look| eye_passes(scene, prepared, &projector, &silhouettes, look);
    Ok(Plan {
        setup,
        maps,
        passes: eye(Look::Shaded),
        mask: colour_mask(scene, eye(Look::Mask)),
        framebuffer: map.framebuffer(scene, false),
        map_image: Some(MapImagePlan {
            commands: map_commands,
            source: MapImageSource::Bytes {
                slot: MAP_IMAGE_SLOT,
                size: map.size,
                from_float: None,
            },
        }),
        notes: notes(scene, &projector),
    })
}

/// The casters of `set` (object indices), black on white, from the projector into the
/// map's corner.
fn silhouette_pass(
    scene: &Scene,
    prepared: &Prepared,
    p: &Projection,
    size: u32,
    set: &[usize],
) -> Pass {
    let mut c = map_pass_start(size, true);
    c.extend([
        Command::MatrixMode(crate::ff::MatrixMode::Projection),
        Command::LoadIdentity,
        p.volume_command.clone(),
        Command::MatrixMode(crate::ff::MatrixMode::Modelview),
        Command::LoadMatrix(p.modelview),
    ]);
    let black = Paint::Flat(Vec4::new(0.0, 0.0, 0.0, 1.0));
    let in_set = |o: &crate::scene::Object| set.iter().any(|&i| std::ptr::eq(&scene.objects[i], o));
    c.extend(objects(scene, prepared, in_set, black));
    // Leave an affine modelview behind. Measured on Mesa 22.3 llvmpipe (native path): after
    // draws under the projective pseudo-depth modelview, the eye pass's EYE_LINEAR planes —
    // set later under a freshly loaded camera view — generate wrong coordinates; a
    // glLoadIdentity here avoids it (`tests/technique_projective.rs` pins the bug).
    c.push(Command::LoadIdentity);
    Pass {
        name: "silhouette",
        commands: c,
    }
}

/// Dim pass, then the shadowing light added on each receiver through the silhouette of
/// the casters other than itself.
fn eye_passes(
    scene: &Scene,
    prepared: &Prepared,
    p: &Projection,
    silhouettes: &Silhouettes,
    look: Look,
) -> Vec<Pass> {
    super::parts::dim_then_added_light_per_receiver(
        scene,
        prepared,
        [0, 1, 2, 3].map(|i| p.plane(i)),
        look,
        &|i| silhouettes.texture(silhouettes.of_object[i].unwrap_or(0)),
    )
}

fn notes(scene: &Scene, p: &Projection) -> Vec<String> {
    let mut notes = Vec::new();
    let both: Vec<String> = (0..scene.objects.len())
        .filter(|&i| scene.objects[i].casts && scene.objects[i].receives)
        .filter(|&i| Some(i) != p.plane_object)
        .map(|i| object_name(scene, i))
        .collect();
    if !both.is_empty() {
        notes.push(format!(
            "projective: {} both caster and receiver: each receives only the other casters' silhouette, so none shadows itself (no self-shadowing)",
            list(&both)
        ));
    }
    let behind: Vec<String> = (0..scene.objects.len())
        .filter(|&i| scene.objects[i].receives)
        .filter(|&i| {
            let m = p.world_to_clip * scene.objects[i].transform.matrix();
            scene.objects[i]
                .mesh
                .positions
                .iter()
                .any(|x| (m * x.extend(1.0)).w <= 0.0)
        })
        .map(|i| object_name(scene, i))
        .collect();
    if !behind.is_empty() {
        notes.push(format!(
            "projective: {} partly behind the projector (q ≤ 0): the silhouette falls there mirrored",
            list(&behind)
        ));
    }
    if let Some(i) = p.plane_object {
        notes.push(format!(
            "projective: pseudo-depth projector on the plane of {} (ortho near {:.4}, far {FAR}): casters below it or beyond the light cast nothing",
            object_name(scene, i),
            p.volume.near
        ));
    }
    notes
}
