//! `planar`: projection shadows on flat receivers — the casters drawn a second time
//! through the shadow matrix, dark and blended, once per pixel, clipped to the receiver
//! with the stencil buffer (Blinn 1988; Kilgard's dinoshade; lecture notes 004, thesis 003
//! §2.1).
//!
//! ```text
//! frame  eye:    clear colour, depth, stencil; every light on; per object:
//!                  flat lit receiver k:  glStencilFunc(ALWAYS, k, ~0); glStencilOp(KEEP, KEEP, REPLACE)
//!                  any other object:     offset mode: stencil off; stencil mode: ALWAYS, 0, REPLACE
//!                  draw it
//!        shadow: glDisable(LIGHTING); glStencilOp(KEEP, KEEP, ZERO)
//!                offset mode: glEnable(POLYGON_OFFSET_FILL); glPolygonOffset(−2, −9); glDepthMask(F)
//!                stencil mode: glDisable(DEPTH_TEST)
//!                glEnable(BLEND); glBlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA); glColor4f(0, 0, 0, ½)
//!                per receiver k: glStencilFunc(EQUAL, k, ~0); glPushMatrix(); glMultMatrixf(M_k);
//!                                draw the casters' slab parts; glPopMatrix()
//! ```
//! M_k = (p_k·l)·I − l·p_kᵀ (see [`super::plane`]). The modelview is V_eye·M_k and the
//! casters' triangles are sent in world coordinates, already clipped on the CPU to the slab
//! that can cast onto p_k (false-shadow rejection: nothing below the plane, nothing beyond
//! the light; the receiver itself lies in its plane and casts nothing).
//!
//! **Once per pixel.** A caster's projection covers most shadow pixels two or more times
//! (front and back faces, overlapping triangles). The first shadow fragment that passes
//! EQUAL k sets the stencil to 0 (ZERO on depth pass), so no later fragment there passes:
//! every shadowed pixel is blended exactly once, v → v·(1 − ½) — dinoshade's trick
//! (LESS 2 / REPLACE 2 over a floor marked 3) with one number per receiver.
//!
//! **Clipped to the receiver.** The shadow is drawn only where the stencil holds k, i.e.
//! where receiver k was drawn and passed the depth test: nothing falls off its edge, and a
//! floor's shadow never lands on a wall (each flat receiver has its own number, 1…255).
//!
//! **Z-fighting, two ways** (`[shadow] planar_mode`):
//! - `offset` (dinoshade): the shadow is depth-tested against the scene with
//!   glPolygonOffset(−2, −9) pulling it towards the eye — on llvmpipe about −18 LSB of a
//!   24-bit buffer plus twice the slope (notes H7, H8) — so it wins against the coplanar
//!   receiver and loses against objects standing in front of it. Too little offset drops
//!   shadow pixels, too much lets the shadow climb onto an object touching the receiver.
//! - `stencil`: every object writes its number (0 unless it is a flat lit receiver) where it
//!   is visible, so the stencil holds k exactly where receiver k is the visible surface; the
//!   shadow lies in that surface's plane, so the depth test is not needed and is off.
//!
//! **Which receivers.** Objects with `receives`, when their world mesh is flat (every
//! vertex within 10⁻⁵ of the bounding diagonal of its largest triangle's plane). A curved
//! receiver gets no planar shadow; a flat one whose visible side the light does not
//! strictly face (light in the plane, a directional light parallel to it, light behind it)
//! is unlit all over — both are named in [`Plan::notes`].
//!
//! **Mask.** The same two passes with lighting off: every object white except unlit flat
//! receivers (black), the shadow opaque black through the same stencil and depth tests.
//! Curved objects are never shadowed by this technique, so it should be judged on its flat
//! receivers' pixels.

use crate::vocab::{PlanarMode, TechniqueId};
use std::sync::Arc;

use glam::{Mat4, Vec4};

use crate::ff::{BlendFactor, Capability, Command, CompareFunc, Geometry, Primitive, StencilOp};
use crate::scene::Scene;

use super::map::MapSettings;
use super::parts::{eye_start, lighting, objects, reset, LightSet, Look, Paint, ShadowLight};
use super::plane::{
    clip_to_slab, facing, flat_plane, light_vector, scene_radius, shadow_matrix, Facing, Slab,
    OFFSET,
};
use super::{
    check_light_count, colour_mask, FramebufferNeeds, Pass, Plan, Prepared, Technique,
    TechniqueError,
};

pub const ID: TechniqueId = TechniqueId::Planar;

pub const TECHNIQUE: Technique = Technique {
    summary:
        "projection shadows: casters through (p·l)I − l·pᵀ onto flat receivers, stencil, blend",
    plan,
};

/// Dinoshade's glPolygonOffset(factor, units) for the shadow in `offset` mode.
pub const SHADOW_OFFSET: (f32, f32) = (-2.0, -9.0);

/// The shadow's colour in the picture: black at half coverage, blended
/// SRC_ALPHA / ONE_MINUS_SRC_ALPHA, so a shadowed pixel v becomes ½·v.
pub const SHADOW_COLOUR: Vec4 = Vec4::new(0.0, 0.0, 0.0, 0.5);

/// Stencil numbers are 8 bits; 0 means "no flat lit receiver here".
pub const MAX_RECEIVERS: usize = 255;

/// What `planar` does with one object that has `receives`.
#[derive(Debug, Clone, PartialEq)]
pub enum Receiver {
    /// Flat and lit: marked with stencil `id`, darkened by every caster through `matrix`.
    Shadowed {
        object: usize,
        id: u8,
        /// Unit normal, oriented towards the eye and the light.
        plane: Vec4,
        matrix: Mat4,
        /// The casters' slab parts, world coordinates (one geometry per caster that has any).
        casters: Vec<Arc<Geometry>>,
    },
    /// Flat, but its visible side does not strictly face the light: unlit all over.
    Unlit { object: usize },
    /// Not flat: no planar shadow.
    Curved { object: usize },
    /// Flat and in the eye's plane: covers no pixel.
    EdgeOn { object: usize },
}

impl Receiver {
    pub fn object(&self) -> usize {
        match *self {
            Receiver::Shadowed { object, .. }
            | Receiver::Unlit { object }
            | Receiver::Curved { object }
            | Receiver::EdgeOn { object } => object,
        }
    }
}

/// Every receiving object, classified, in scene order.
pub fn receivers(scene: &Scene) -> Result<Vec<Receiver>, TechniqueError> {
    let light = ShadowLight::of(scene, ID)?;
    let l = light_vector(&light.light);
    let delta = OFFSET * scene_radius(scene);
    let worlds: Vec<_> = scene.objects.iter().map(|o| o.world_mesh()).collect();
    let mut out = Vec::new();
    let mut next_id = 1usize;
    for (i, object) in scene.objects.iter().enumerate() {
        if !object.receives {
            continue;
        }
        let Some(plane) = flat_plane(&worlds[i]) else {
            out.push(Receiver::Curved { object: i });
            continue;
        };
        let plane = match facing(plane, scene.camera.eye, l) {
            Facing::Lit { plane } => plane,
            Facing::Unlit => {
                out.push(Receiver::Unlit { object: i });
                continue;
            }
            Facing::EdgeOnToEye => {
                out.push(Receiver::EdgeOn { object: i });
                continue;
            }
        };
        if next_id > MAX_RECEIVERS {
            return Err(TechniqueError::TooManyFlatReceivers {
                technique: ID,
                max: MAX_RECEIVERS,
            });
        }
        let slab = Slab::new(plane, l, delta);
        let casters = scene
            .objects
            .iter()
            .zip(&worlds)
            .filter(|(o, _)| o.casts)
            .map(|(_, mesh)| clip_to_slab(mesh, plane, slab))
            .filter(|tris| !tris.is_empty())
            .map(|tris| {
                let positions = tris.iter().map(|p| p.extend(1.0)).collect();
                Arc::new(Geometry::new(Primitive::Triangles, positions))
            })
            .collect();
        out.push(Receiver::Shadowed {
            object: i,
            id: next_id as u8,
            plane,
            matrix: shadow_matrix(plane, l),
            casters,
        });
        next_id += 1;
    }
    Ok(out)
}

pub fn plan(scene: &Scene, prepared: &Prepared) -> Result<Plan, TechniqueError> {
    check_light_count(scene)?;
    let settings = MapSettings::of(scene);
    settings.check_stencil(ID)?;
    let receivers = receivers(scene)?;
    let mode = scene.shadow.planar_mode;
    let eye = |look| {
        vec![
            scene_pass(scene, prepared, &receivers, mode, look),
            shadow_pass(&receivers, mode, look),
        ]
    };
    Ok(Plan {
        notes: notes(scene, &receivers),
        ..Plan::single(
            eye(Look::Shaded),
            colour_mask(scene, eye(Look::Mask)),
            FramebufferNeeds {
                width: scene.image.width,
                height: scene.image.height,
                depth: settings.depth,
                stencil: true,
            },
        )
    })
}

/// How the eye pass treats one object.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mark {
    /// A flat lit receiver: stencil number `id`.
    Receiver(u8),
    /// A flat receiver the light does not reach: dim in the mask.
    Unlit,
    /// Anything else.
    Plain,
}

fn marks(scene: &Scene, receivers: &[Receiver]) -> Vec<Mark> {
    let mut marks = vec![Mark::Plain; scene.objects.len()];
    for r in receivers {
        match *r {
            Receiver::Shadowed { object, id, .. } => marks[object] = Mark::Receiver(id),
            Receiver::Unlit { object } => marks[object] = Mark::Unlit,
            Receiver::Curved { .. } | Receiver::EdgeOn { .. } => {}
        }
    }
    marks
}

/// The lit scene, each object writing its stencil number (see the module note).
fn scene_pass(
    scene: &Scene,
    prepared: &Prepared,
    receivers: &[Receiver],
    mode: PlanarMode,
    look: Look,
) -> Pass {
    let mut c = eye_start(scene, look, true);
    c.extend(lighting(scene, look, LightSet::All));
    c.push(Command::StencilOp {
        fail: StencilOp::Keep,
        depth_fail: StencilOp::Keep,
        depth_pass: StencilOp::Replace,
    });
    if mode == PlanarMode::Stencil {
        c.push(Command::Enable(Capability::StencilTest));
    }
    let always = |reference| Command::StencilFunc {
        func: CompareFunc::Always,
        reference,
        mask: !0,
    };
    for (i, mark) in marks(scene, receivers).into_iter().enumerate() {
        match (mark, mode) {
            (Mark::Receiver(id), PlanarMode::Offset) => {
                c.extend([Command::Enable(Capability::StencilTest), always(id.into())]);
            }
            (Mark::Receiver(id), PlanarMode::Stencil) => c.push(always(id.into())),
            (_, PlanarMode::Offset) => c.push(Command::Disable(Capability::StencilTest)),
            (_, PlanarMode::Stencil) => c.push(always(0)),
        }
        let paint = match (look, mark) {
            (Look::Shaded, _) => Paint::Material,
            (Look::Mask, Mark::Unlit) => look.paint(false),
            (Look::Mask, _) => look.paint(true),
        };
        let this = &scene.objects[i];
        c.extend(objects(scene, prepared, |o| std::ptr::eq(o, this), paint));
    }
    Pass {
        name: "eye",
        commands: c,
    }
}

/// The casters through each receiver's shadow matrix, once per pixel (module note).
fn shadow_pass(receivers: &[Receiver], mode: PlanarMode, look: Look) -> Pass {
    let mut c = vec![
        Command::Disable(Capability::Lighting),
        Command::Enable(Capability::StencilTest),
        Command::StencilOp {
            fail: StencilOp::Keep,
            depth_fail: StencilOp::Keep,
            depth_pass: StencilOp::Zero,
        },
    ];
    match mode {
        PlanarMode::Offset => c.extend([
            Command::Enable(Capability::PolygonOffsetFill),
            Command::PolygonOffset {
                factor: SHADOW_OFFSET.0,
                units: SHADOW_OFFSET.1,
            },
            Command::DepthMask(false),
        ]),
        PlanarMode::Stencil => c.push(Command::Disable(Capability::DepthTest)),
    }
    match look {
        Look::Shaded => c.extend([
            Command::Enable(Capability::Blend),
            Command::BlendFunc {
                src: BlendFactor::SrcAlpha,
                dst: BlendFactor::OneMinusSrcAlpha,
            },
            Command::Color(SHADOW_COLOUR),
        ]),
        // The mask needs no blend: one opaque black write per shadowed pixel.
        Look::Mask => c.push(Command::Color(Vec4::new(0.0, 0.0, 0.0, 1.0))),
    }
    for r in receivers {
        let Receiver::Shadowed {
            id,
            matrix,
            casters,
            ..
        } = r
        else {
            continue;
        };
        c.extend([
            Command::StencilFunc {
                func: CompareFunc::Equal,
                reference: (*id).into(),
                mask: !0,
            },
            Command::PushMatrix,
            Command::MultMatrix(*matrix),
        ]);
        c.extend(casters.iter().map(|g| Command::Draw(g.clone())));
        c.push(Command::PopMatrix);
    }
    match mode {
        PlanarMode::Offset => c.push(Command::Disable(Capability::PolygonOffsetFill)),
        PlanarMode::Stencil => c.push(Command::Enable(Capability::DepthTest)),
    }
    c.extend(reset(&[]));
    Pass {
        name: "shadow",
        commands: c,
    }
}

/// `ground`, or `object 3` for an unnamed one.
pub(crate) fn object_name(scene: &Scene, i: usize) -> String {
    match &scene.objects[i].name {
        Some(n) => format!("`{n}`"),
        None => format!("object {i}"),
    }
}

fn notes(scene: &Scene, receivers: &[Receiver]) -> Vec<String> {
    let names = |pick: fn(&Receiver) -> bool| {
        receivers
            .iter()
            .filter(|r| pick(r))
            .map(|r| object_name(scene, r.object()))
            .collect::<Vec<_>>()
    };
    let mut notes = Vec::new();
    let curved = names(|r| matches!(r, Receiver::Curved { .. }));
    if !curved.is_empty() {
        notes.push(format!(
            "planar: {} not flat: no planar shadow falls there (judge planar on flat receivers)",
            list(&curved)
        ));
    }
    let unlit = names(|r| matches!(r, Receiver::Unlit { .. }));
    if !unlit.is_empty() {
        notes.push(format!(
            "planar: the light is in the plane of {} or behind the side the eye sees (p·l ≤ 0): unlit, no projected shadow",
            list(&unlit)
        ));
    }
    if !receivers
        .iter()
        .any(|r| matches!(r, Receiver::Shadowed { .. }))
    {
        notes.push("planar: no flat receiver faces the light: nothing is projected".into());
    }
    notes
}

/// "`a` is" / "`a`, `b` are".
pub(crate) fn list(names: &[String]) -> String {
    let verb = if names.len() == 1 { "is" } else { "are" };
    format!("{} {verb}", names.join(", "))
}
