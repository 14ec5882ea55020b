//! Techniques: each is a plan of passes written as fixed-function [`Command`]s, the calls a
//! program of the era would have made. A technique sets state and draws; it never touches
//! GL, so a plan can be printed, asserted on in pure tests, and executed by either pipeline.
//!
//! **One list of names.** The names live with [`TechniqueId`] in `vocab`, below the scene
//! reader that parses them; [`technique`] maps each id to its entry with an exhaustive
//! match. Adding a technique means adding its variant and name there and its arm here;
//! forgetting the arm does not compile.
//!
//! **Preparation once, plans once, frames many.** [`Prepared::new`] converts every object's
//! mesh into one shared `Arc<Geometry>`; [`Technique::plan`] builds the passes from the scene
//! and those geometries; the renderer then executes the same command lists every frame, so
//! nothing is converted or uploaded twice by this layer.
//!
//! **Passes only for what the scene asks for.** A plan enables a capability only when the
//! scene uses it: lighting only with lights, LIGHTi only for the scene's lights, NORMALIZE
//! only when a transform scales, no texture unit unless the technique samples a map.
//!
//! **The shadow mask.** After the last frame the renderer executes [`Plan::mask`]'s commands
//! and decodes their readback with [`MaskPlan::decode`] into a [`Mask`] (255 lit, 0
//! shadowed, 128 background, top row first) that `metrics` compares with the truth.

pub mod accumulate;
pub mod depth_compare;
pub mod dual8;
pub mod explain;
pub mod linear8;
pub mod map;
pub mod multidigit16;
pub mod multidigit16_combine;
pub mod none;
pub mod occluder_planes;
pub mod occluder_program;
pub mod occlusion_sun;
pub mod occlusion_textures;
pub mod parts;
pub mod planar;
pub mod plane;
pub mod projective;
pub mod setup;

use crate::vocab::{DepthBits, Named, TechniqueId};
use std::sync::Arc;

use crate::ff::{Command, Geometry, PixelFormat, PixelType, MAX_LIGHTS};
use crate::metrics::{Mask, VisibilityImage, BACKGROUND, LIT, SHADOWED};
use crate::pipeline::Readback;
use crate::scene::Scene;

/// Failures of the techniques layer.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TechniqueError {
    #[error("`{name}` is not a known technique; known techniques: {}", .known.join(", "))]
    Unknown {
        name: String,
        known: Vec<&'static str>,
    },
    #[error("the scene has {count} lights; the fixed-function pipeline has {max} (GL_MAX_LIGHTS)")]
    TooManyLights { count: usize, max: usize },
    #[error("`{technique}` needs a light to cast shadows; the scene has none (add a [[light]])")]
    NoLight { technique: TechniqueId },
    #[error("`{technique}` needs a stencil buffer; a {bits}-bit depth buffer has none (use depth_bits 24 or \"32f\")")]
    NeedsStencil { technique: TechniqueId, bits: u32 },
    #[error("`{technique}` numbers flat receivers in an 8-bit stencil buffer: at most {max} of them may face the light")]
    TooManyFlatReceivers { technique: TechniqueId, max: usize },
    #[error("`{technique}` with `projector = \"pseudo-depth\"` projects onto a flat receiver, and no flat receiver of this scene has the light strictly on one side of its plane (p·l ≠ 0); use `projector = \"perspective\"` or add a flat receiver")]
    NoProjectionPlane { technique: TechniqueId },
    #[error("`{technique}` needs a soft light to sample, and the scene's first light is {found}: make it `type = \"area\"` with `corner`, `edge_u` and `edge_v` (or `centre`, `size` and `at`), or a sun: `type = \"directional\"` with `angular_diameter`")]
    NoAreaLight {
        technique: TechniqueId,
        found: &'static str,
    },
    #[error("{samples} light samples asked for; `accumulate` takes 1 to {max}")]
    LightSamples { samples: u32, max: u32 },
    #[error("`{technique}` needs shadow planes, and no object that casts declares any: add `[[object.plane]]` tables (origin, normal, up, right, width, height, occluder) or use `shape = \"aircraft\", layout = \"f35\"`, which brings the thesis's three")]
    NoShadowPlanes { technique: TechniqueId },
    #[error("`occluder-planes` with `program = \"coleman\"` runs the thesis's shaders, which hard-code the F-35's three shadow planes under a directional light, and {why}: use `program = \"generic\"` (a program generated for any planes, directional or point light) or `\"fixed-function\"`")]
    ColemanDoesNotFit {
        why: occluder_program::ColemanMisfit,
    },
    #[error("the casters declare {count} shadow planes; one texture unit each, and the fixed-function pipeline has {max} (GL_MAX_TEXTURE_UNITS)")]
    TooManyShadowPlanes { count: usize, max: usize },
    #[error("the mask readback (slot {slot}) is missing: the pipeline did not execute ReadPixels")]
    MissingReadback { slot: u32 },
    #[error("the mask readback is {got_w}×{got_h} {format:?}/{ty:?}; expected {w}×{h} {expected_format:?}/{expected_ty:?}", got_w = .got.0, got_h = .got.1, w = .expected.0, h = .expected.1)]
    ReadbackShape {
        got: (u32, u32),
        expected: (u32, u32),
        format: PixelFormat,
        ty: PixelType,
        expected_format: PixelFormat,
        expected_ty: PixelType,
    },
}

/// A technique's entry in the registry (its name is its [`TechniqueId`]'s).
#[derive(Clone, Copy)]
pub struct Technique {
    /// One line for `--help` and reports.
    pub summary: &'static str,
    /// Builds the passes and the mask plan for a scene and its prepared geometry.
    pub plan: fn(&Scene, &Prepared) -> Result<Plan, TechniqueError>,
}

impl std::fmt::Debug for Technique {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.summary)
    }
}

/// The technique behind an id.
pub fn technique(id: TechniqueId) -> &'static Technique {
    match id {
        TechniqueId::None => &none::TECHNIQUE,
        TechniqueId::DepthCompare => &depth_compare::TECHNIQUE,
        TechniqueId::Accumulate => &accumulate::TECHNIQUE,
        TechniqueId::Dual8 => &dual8::TECHNIQUE,
        TechniqueId::Linear8 => &linear8::TECHNIQUE,
        TechniqueId::Multidigit16 => &multidigit16::TECHNIQUE,
        TechniqueId::Multidigit16Combine => &multidigit16_combine::TECHNIQUE,
        TechniqueId::Planar => &planar::TECHNIQUE,
        TechniqueId::Projective => &projective::TECHNIQUE,
        TechniqueId::OccluderPlanes => &occluder_planes::TECHNIQUE,
        TechniqueId::OcclusionTextures => &occlusion_textures::TECHNIQUE,
    }
}

/// The id a technique name means, or [`TechniqueError::Unknown`] listing every name.
pub fn parse_name(name: &str) -> Result<TechniqueId, TechniqueError> {
    TechniqueId::from_name(name).ok_or_else(|| TechniqueError::Unknown {
        name: name.to_string(),
        known: TechniqueId::names(),
    })
}

/// The technique called `name`.
pub fn lookup(name: &str) -> Result<&'static Technique, TechniqueError> {
    parse_name(name).map(technique)
}

/// The scene's meshes as draw-ready geometry, made once per scene and shared (Arc) by every
/// pass and frame that draws them. `objects[i]` belongs to `scene.objects[i]`.
#[derive(Debug, Clone)]
pub struct Prepared {
    pub objects: Vec<Arc<Geometry>>,
}

impl Prepared {
    pub fn new(scene: &Scene) -> Prepared {
        Prepared {
            objects: scene
                .objects
                .iter()
                .map(|o| Arc::new(o.mesh.to_geometry()))
                .collect(),
        }
    }
}

/// One pass: the commands of one trip through the scene (or one full-screen step).
#[derive(Debug, Clone, PartialEq)]
pub struct Pass {
    /// What the pass is for, e.g. "eye".
    pub name: &'static str,
    pub commands: Vec<Command>,
}

/// What a technique runs, when, and how its shadow mask is obtained afterwards.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    /// Executed once, before the first frame: what never changes (ramps, parameters of
    /// textures that are only ever re-specified).
    pub setup: Vec<Command>,
    /// The passes that make the technique's maps (light pass, readback, upload): executed
    /// on the first frame and again only when the maps are stale (see `render::RemakeMaps`).
    pub maps: Vec<Pass>,
    /// Executed in order, every frame, after the maps when they are made.
    pub passes: Vec<Pass>,
    pub mask: MaskPlan,
    /// The framebuffer the passes draw into.
    pub framebuffer: FramebufferNeeds,
    /// How to show the light's map as images (`render --depth-map`); `None` without maps.
    pub map_image: Option<MapImagePlan>,
    /// What the render line should say about this scene and technique (e.g. a known
    /// failure mode the scene triggers).
    pub notes: Vec<String>,
}

impl Plan {
    /// A plan of every-frame passes only, drawn into a framebuffer of the image's size.
    pub fn single(passes: Vec<Pass>, mask: MaskPlan, framebuffer: FramebufferNeeds) -> Plan {
        Plan {
            setup: Vec::new(),
            maps: Vec::new(),
            passes,
            mask,
            framebuffer,
            map_image: None,
            notes: Vec::new(),
        }
    }

    /// Every command of one frame that makes its maps, in order (setup excluded).
    pub fn frame_commands(&self) -> impl Iterator<Item = &Command> {
        self.maps
            .iter()
            .chain(&self.passes)
            .flat_map(|p| p.commands.iter())
    }

    /// Passes in a frame that makes its maps.
    pub fn pass_count(&self) -> usize {
        self.maps.len() + self.passes.len()
    }

    /// Whether any command of the plan uses the accumulation buffer (glAccum, or a clear
    /// of ACCUM_BUFFER_BIT): the renderer then gives the framebuffer one (`render::Session`).
    pub fn needs_accumulation(&self) -> bool {
        let uses = |c: &Command| match c {
            Command::Accum { .. } => true,
            Command::Clear(mask) => mask.accum,
            _ => false,
        };
        self.setup
            .iter()
            .chain(self.frame_commands())
            .chain(&self.mask.commands)
            .any(uses)
    }
}

/// The framebuffer a plan needs: at least the image and the light's map (they share one
/// framebuffer, as on the era's hardware: the light pass draws in its lower-left corner).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FramebufferNeeds {
    pub width: u32,
    pub height: u32,
    pub depth: DepthBits,
    pub stencil: bool,
}

/// Commands that read the light's map after the frames, and how to turn the bytes into
/// pictures.
#[derive(Debug, Clone, PartialEq)]
pub struct MapImagePlan {
    /// Executed after the map passes are executed once more (empty when the map passes
    /// already leave the readback behind).
    pub commands: Vec<Command>,
    pub source: MapImageSource,
}

/// Which readback holds the map, and in what form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MapImageSource {
    /// Depth as FLOAT: one grey image, 0 black (near) to 1 white (far).
    DepthFloat { slot: u32, size: u32 },
    /// One byte per texel (an 8-bit map): one grey image. With `from_float`, the slot
    /// holds FLOAT depth that the program converts by that rule.
    Bytes {
        slot: u32,
        size: u32,
        from_float: Option<crate::vocab::DepthRule>,
    },
    /// Depth as UNSIGNED_SHORT: the big digit (high byte) grey, the little digit (low byte)
    /// pseudo-coloured, as on Kilgard's slide of where the information is. With
    /// `from_float`, as for `Bytes`.
    Digits {
        slot: u32,
        size: u32,
        from_float: Option<crate::vocab::DepthRule>,
    },
}

/// Commands executed once after the last frame, and how their readback becomes a mask.
#[derive(Debug, Clone, PartialEq)]
pub struct MaskPlan {
    pub commands: Vec<Command>,
    pub source: MaskSource,
}

/// The readback slot mask plans use.
pub const MASK_SLOT: u32 = 0;

/// How a readback becomes a shadow mask.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MaskSource {
    /// The frame's own depth buffer read as FLOAT (no extra pass): a pixel is geometry iff
    /// z < 1 (the cleared far value), and every geometry pixel is lit — a technique without
    /// shadows. 255 where z < 1, 128 elsewhere.
    DepthCoverage { slot: u32, width: u32, height: u32 },
    /// The technique's passes drawn again in mask colours — cleared to pure blue
    /// [`MASK_BACKGROUND`], everything that would be dim in black, everything lit in white
    /// — read as RGBA/UNSIGNED_BYTE. Background iff the pixel is (0, 0, 255); otherwise lit
    /// iff red ≥ 128 (a filtered compare that is at least half lit counts as lit),
    /// shadowed below.
    Colour { slot: u32, width: u32, height: u32 },
    /// Mask passes accumulated over the light's samples (`accumulate`), read as
    /// RGBA/UNSIGNED_BYTE: each geometry pixel grey, its red the fraction of the samples
    /// that saw the light (0–255); the background (0, 0, ≈255) — blue ahead of red by at
    /// least 128. The mask is lit iff red ≥ 128, as for `Colour`;
    /// [`MaskPlan::decode_visibility`] gives the fraction itself.
    Visibility { slot: u32, width: u32, height: u32 },
}

/// The mask plan of a technique whose `passes` were built in the mask look: the passes,
/// then glReadPixels of the image as RGBA/UNSIGNED_BYTE into [`MASK_SLOT`].
pub fn colour_mask(scene: &Scene, passes: Vec<Pass>) -> MaskPlan {
    let (width, height) = (scene.image.width, scene.image.height);
    let mut commands: Vec<Command> = passes.into_iter().flat_map(|p| p.commands).collect();
    commands.push(Command::ReadPixels(crate::ff::ReadPixels {
        x: 0,
        y: 0,
        width: width as i32,
        height: height as i32,
        format: PixelFormat::Rgba,
        ty: PixelType::UnsignedByte,
        slot: MASK_SLOT,
    }));
    MaskPlan {
        commands,
        source: MaskSource::Colour {
            slot: MASK_SLOT,
            width,
            height,
        },
    }
}

/// The clear colour of mask passes (pure blue: no lit or shadowed pixel can be it).
pub const MASK_BACKGROUND: [u8; 4] = [0, 0, 255, 255];

impl MaskPlan {
    /// Decodes the readback of `self.source`'s slot (bottom row first, as GL returns it)
    /// into a mask (top row first).
    pub fn decode<'r>(
        &self,
        readback: impl Fn(u32) -> Option<&'r Readback>,
    ) -> Result<Mask, TechniqueError> {
        let (slot, width, height, expected) = match self.source {
            MaskSource::DepthCoverage {
                slot,
                width,
                height,
            } => (
                slot,
                width,
                height,
                (PixelFormat::DepthComponent, PixelType::Float),
            ),
            MaskSource::Colour {
                slot,
                width,
                height,
            }
            | MaskSource::Visibility {
                slot,
                width,
                height,
            } => (
                slot,
                width,
                height,
                (PixelFormat::Rgba, PixelType::UnsignedByte),
            ),
        };
        let r = readback(slot).ok_or(TechniqueError::MissingReadback { slot })?;
        let n = width as usize * height as usize;
        if (r.width, r.height) != (width, height)
            || (r.format, r.ty) != expected
            || r.bytes.len() != n * 4
        {
            return Err(TechniqueError::ReadbackShape {
                got: (r.width, r.height),
                expected: (width, height),
                format: r.format,
                ty: r.ty,
                expected_format: expected.0,
                expected_ty: expected.1,
            });
        }
        // Four bytes a pixel either way; rows flipped to top first.
        let row = width as usize * 4;
        let pixels = r
            .bytes
            .chunks_exact(row.max(1))
            .rev()
            .flat_map(|line| line.chunks_exact(4));
        let data = match self.source {
            MaskSource::DepthCoverage { .. } => pixels
                .map(|b| {
                    let z = f32::from_ne_bytes([b[0], b[1], b[2], b[3]]);
                    if z < 1.0 {
                        LIT
                    } else {
                        BACKGROUND
                    }
                })
                .collect(),
            MaskSource::Colour { .. } => pixels
                .map(|p| {
                    if p[..3] == MASK_BACKGROUND[..3] {
                        BACKGROUND
                    } else if p[0] >= 128 {
                        LIT
                    } else {
                        SHADOWED
                    }
                })
                .collect(),
            MaskSource::Visibility { .. } => pixels
                .map(|p| match accumulated_visibility(p) {
                    None => BACKGROUND,
                    Some(v) if v >= 128 => LIT,
                    Some(_) => SHADOWED,
                })
                .collect(),
        };
        Ok(Mask {
            width,
            height,
            data,
        })
    }

    /// The visibility a [`MaskSource::Visibility`] readback holds (`None` for any other
    /// source): per pixel, top row first, `None` on background, else the red channel —
    /// the fraction of the light's samples that saw the pixel, in 255ths.
    pub fn decode_visibility<'r>(
        &self,
        readback: impl Fn(u32) -> Option<&'r Readback>,
    ) -> Result<Option<VisibilityImage>, TechniqueError> {
        let MaskSource::Visibility {
            slot,
            width,
            height,
        } = self.source
        else {
            return Ok(None);
        };
        // The shape was checked by `decode` on the same readback; checked again here.
        let r = readback(slot).ok_or(TechniqueError::MissingReadback { slot })?;
        let n = width as usize * height as usize;
        if (r.width, r.height) != (width, height) || r.bytes.len() != n * 4 {
            return Err(TechniqueError::ReadbackShape {
                got: (r.width, r.height),
                expected: (width, height),
                format: r.format,
                ty: r.ty,
                expected_format: PixelFormat::Rgba,
                expected_ty: PixelType::UnsignedByte,
            });
        }
        let row = width as usize * 4;
        let data = r
            .bytes
            .chunks_exact(row.max(1))
            .rev()
            .flat_map(|line| line.chunks_exact(4))
            .map(accumulated_visibility)
            .collect();
        Ok(Some(VisibilityImage {
            width,
            height,
            data,
        }))
    }
}

/// An accumulated mask pixel: background when blue leads red by 128 or more (the mask
/// background (0, 0, 255) averaged with itself), else its red, the lit fraction in 255ths.
fn accumulated_visibility(p: &[u8]) -> Option<u8> {
    if i32::from(p[2]) - i32::from(p[0]) >= 128 {
        None
    } else {
        Some(p[0])
    }
}

/// Fails when the scene has more lights than GL_MAX_LIGHTS.
pub(crate) fn check_light_count(scene: &Scene) -> Result<(), TechniqueError> {
    if scene.lights.len() > MAX_LIGHTS {
        return Err(TechniqueError::TooManyLights {
            count: scene.lights.len(),
            max: MAX_LIGHTS,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_has_a_technique() {
        for id in TechniqueId::all() {
            assert_eq!(parse_name(id.name()), Ok(id));
            // By summary, not address: a promoted `&CONST` may live at a different address
            // in each codegen unit (measured: `none` failed ptr::eq in a release build).
            assert_eq!(lookup(id.name()).unwrap().summary, technique(id).summary);
        }
        let err = lookup("shadow-volumes").unwrap_err();
        assert!(err.to_string().contains("known techniques: none"), "{err}");
    }

    #[test]
    fn depth_coverage_flips_rows_and_splits_at_the_far_value() {
        // 2×2, bottom row first: bottom (1.0, 0.5), top (0.25, 1.0).
        let bytes: Vec<u8> = [1.0f32, 0.5, 0.25, 1.0]
            .iter()
            .flat_map(|z| z.to_ne_bytes())
            .collect();
        let plan = MaskPlan {
            commands: Vec::new(),
            source: MaskSource::DepthCoverage {
                slot: 3,
                width: 2,
                height: 2,
            },
        };
        let stored = Readback {
            width: 2,
            height: 2,
            depth: None,
            format: PixelFormat::DepthComponent,
            ty: PixelType::Float,
            bytes,
        };
        let readback = |slot| (slot == 3).then_some(&stored);
        let mask = plan.decode(readback).unwrap();
        assert_eq!(mask.data, vec![LIT, BACKGROUND, BACKGROUND, LIT]);
        assert_eq!(
            plan.decode(|_| None),
            Err(TechniqueError::MissingReadback { slot: 3 })
        );
    }
}
