//! What every pass of a frame leaves behind (`render --passes`, `compare`'s pass strip):
//! the colour, depth and stencil buffers after each pass, the light's map where a pass
//! leaves it only in a texture, and for passes with an alpha test the alpha before the
//! test and, for the 8-bit comparisons, the map minus the ramp in 8-bit steps.
//!
//! **Where it is read.** [`Session::pass_images`] renders one more frame with a [`Capture`]
//! set: after each pass (the light's map passes included — that frame makes its maps
//! again) the hook in `Session::frame` reads the buffers straight from the render target
//! (glReadPixels of RGBA, DEPTH_COMPONENT/FLOAT and STENCIL_INDEX: a framebuffer object
//! on both the core and the compatibility context), each cropped to the corner the pass
//! draws in — the map's `size`² for a map pass, the image for an eye pass — and turned
//! top row first. After the last map pass the plan's own depth-map read-out
//! ([`LightMap`], what `render --depth-map` shows) runs, so the texels are the uploaded
//! ones.
//!
//! **What a pass would have written without its alpha test** cannot be read after the
//! pass: the test threw it away. It is taken by *variants* of the pass, after the frame,
//! each in a replay of the eye passes — the passes before it as they are, the variant in
//! its place, the passes after it as they are (so every replay ends in the state a frame
//! ends in) — and the frame's eye passes are executed once more at the end, so that the
//! framebuffer again holds the frame's picture. Variants are command lists (the plan's
//! own, filtered), never GL behind the pipeline's back:
//! - *alpha before the test*: the pass without `Enable(ALPHA_TEST)`, `AlphaFunc`,
//!   `ColorMask` and `Enable(BLEND)`, with the test and blending disabled first (an earlier
//!   pass may have left them on) and after glClear of colour with all channels writable,
//!   once with alpha cleared to 0 and once to 1: a pixel the pass drew holds the same
//!   alpha both times; one that differs was not drawn.
//! - *map minus ramp*: the same, with the pass's texture environment (`TexEnv`, and
//!   register combiners, disabled) replaced by a measuring one — unit 0's texel alpha (the map: M/255
//!   for an 8-bit map, the big digit of a two-digit map) REPLACE, unit 1's texel alpha (the
//!   ramp: F/255) SUBTRACTed, later units passing PREVIOUS on. Rendered twice, as M − F
//!   and as F − M, each clamped to [0, 1] by GL, with alpha cleared to 1: the difference of
//!   the two bytes is M − F in 8-bit steps, exact (M/255 − F/255 is exact in both
//!   precisions and rounds back to the integer). Where both bytes are non-zero the pass did
//!   not compare there (not drawn, or drawn without textures: a receiver's M − F and F − M
//!   cannot both be positive). The technique's comparison is alpha = ½ + (M − F)/255,
//!   GREATER ½ (`dual8`): lit iff M − F > 0; 0, the tie, is shadowed.
//!
//! Variants exist for eye passes only (no map pass has an alpha test); the replays
//! compile the variants' programs on the emulated path, which is why `compare` captures in
//! a session of its own ([`capture`]) and its figures stay those of the measured session.

use glam::Vec4;
use image::RgbaImage;

use crate::ff::{
    Capability, ClearMask, ColorMask, CombineArg, CombineFunc, CombineOperand, CombineSource,
    Command, CompareFunc, TexEnvMode, TexEnvParam,
};
use crate::gpu::{GpuContext, RenderTarget};
use crate::pipeline::Pipeline;
use crate::scene::Scene;
use crate::techniques::{MapImagePlan, MapImageSource, Pass, Plan};
use crate::vocab::TechniqueId;

use super::{apply_overrides, run, LightMap, RenderError, RenderOptions, Session};

/// Every pass of one frame as it left the framebuffer.
#[derive(Debug, Clone, PartialEq)]
pub struct PassImages {
    pub technique: TechniqueId,
    /// Depth and stencil bits of the framebuffer the passes drew into.
    pub depth_bits: u32,
    pub stencil_bits: u32,
    /// Map passes first, then the eye passes, in the order executed.
    pub passes: Vec<PassImage>,
}

/// Which corner of the shared framebuffer a pass draws in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Corner {
    /// The light's map, `size`² texels in the lower-left corner.
    Map,
    /// The image, the scene's width × height in the lower-left corner.
    Image,
}

/// What one pass left, in its corner, top row first.
#[derive(Debug, Clone, PartialEq)]
pub struct PassImage {
    /// 1-based position in the frame.
    pub number: usize,
    /// The plan's name of the pass.
    pub name: &'static str,
    pub corner: Corner,
    pub width: u32,
    pub height: u32,
    /// The colour buffer, alpha as the passes left it.
    pub color: RgbaImage,
    /// Window-space depth in [0, 1] (the stored value read as FLOAT), `width·height`.
    pub depth: Vec<f32>,
    /// Stencil indices, when the framebuffer has a stencil buffer.
    pub stencil: Option<Vec<u8>>,
    /// For a pass that enables the alpha test: the alpha it computed before the test.
    pub alpha: Option<AlphaBeforeTest>,
    /// For the 8-bit comparisons ([`map_minus_ramp`]): M − F in 8-bit steps per pixel,
    /// `None` where the pass did not compare.
    pub map_minus_ramp: Option<Vec<Option<i16>>>,
    /// The light's map, after the last map pass (the texture it left it in).
    pub map: Option<LightMap>,
}

/// The alpha a pass computed, before its alpha test discarded any of it.
#[derive(Debug, Clone, PartialEq)]
pub struct AlphaBeforeTest {
    /// The test the pass enables (its last `AlphaFunc`); `None` when the pass enables the
    /// test without setting it (the function an earlier pass set applies).
    pub test: Option<(CompareFunc, f32)>,
    /// The alpha byte per pixel, `None` where the pass drew nothing.
    pub alpha: Vec<Option<u8>>,
}

/// What a technique's "map minus ramp" picture measures, or `None` for a technique whose
/// comparison is not an 8-bit map on unit 0 against a ramp on unit 1.
pub fn map_minus_ramp(technique: TechniqueId) -> Option<&'static str> {
    const BYTES: &str = "M − F: the map's byte (unit 0) minus the fragment's ramp byte \
                         (unit 1); the alpha test passes (lit) iff M − F > 0";
    match technique {
        TechniqueId::Dual8 | TechniqueId::Linear8 => Some(BYTES),
        TechniqueId::Multidigit16 => Some(
            "big(map) − big(fragment): the high 8-bit digits (unit 0's alpha minus unit 1's \
             ramp); > 0 lit by the big digits, 0 leaves the decision to the little digits",
        ),
        TechniqueId::None
        | TechniqueId::DepthCompare
        | TechniqueId::Accumulate
        | TechniqueId::Multidigit16Combine
        | TechniqueId::Planar
        | TechniqueId::Projective
        | TechniqueId::OccluderPlanes
        | TechniqueId::OcclusionTextures => None,
    }
}

/// The pass images of the last frame `options` ask for (with an orbit, the scene at its
/// last frame), rendered in a session of their own so that no other render's figures
/// count the capture.
pub fn capture(scene: &Scene, options: &RenderOptions) -> Result<PassImages, RenderError> {
    let frames = options.frames.max(1);
    let scene = apply_overrides(scene, options.size, options.technique);
    let scene = match options.orbit {
        Some(orbit) => orbit.scene_at(&scene, frames),
        None => scene,
    };
    let options = RenderOptions {
        frames: 1,
        orbit: None,
        pass_times: false,
        depth_map: false,
        ..options.clone()
    };
    Session::new(&scene, &options)?.pass_images()
}

/// The capture of one frame in progress (see the module note).
pub(super) struct Capture {
    image: (u32, u32),
    map_size: u32,
    maps: usize,
    map_image: Option<MapImagePlan>,
    technique: TechniqueId,
    taken: Vec<PassImage>,
}

impl Capture {
    pub(super) fn new(plan: &Plan, scene: &Scene) -> Capture {
        let map_size = plan
            .map_image
            .as_ref()
            .map_or(scene.shadow.map_size, |m| match m.source {
                MapImageSource::DepthFloat { size, .. }
                | MapImageSource::Bytes { size, .. }
                | MapImageSource::Digits { size, .. } => size,
            });
        Capture {
            image: (scene.image.width, scene.image.height),
            map_size,
            maps: plan.maps.len(),
            map_image: plan.map_image.clone(),
            technique: scene.shadow.technique,
            taken: Vec::new(),
        }
    }

    /// Reads what pass `index` of frame `frame` left (the hook in `Session::frame`).
    pub(super) fn after_pass(
        &mut self,
        pipeline: &mut dyn Pipeline,
        ctx: &GpuContext,
        target: Option<&RenderTarget>,
        index: usize,
        pass: &Pass,
        frame: u32,
    ) -> Result<(), RenderError> {
        let target = target.ok_or(RenderError::Released)?;
        let corner = if index < self.maps {
            Corner::Map
        } else {
            Corner::Image
        };
        let (width, height) = match corner {
            Corner::Map => (self.map_size, self.map_size),
            Corner::Image => self.image,
        };
        let color = read_color(ctx, target, width, height)?;
        let (width, height) = (width.min(target.width()), height.min(target.height()));
        let stride = target.width();
        let depth = lower_left(&target.read_depth_f32(ctx)?, stride, width, height);
        let stencil = if target.stencil_bits() > 0 {
            Some(lower_left(
                &target.read_stencil(ctx)?,
                stride,
                width,
                height,
            ))
        } else {
            None
        };
        let map = match &self.map_image {
            Some(m) if index + 1 == self.maps => {
                run(pipeline, ctx, "depth-map", frame, &m.commands)?;
                Some(LightMap::read(m.source, |slot| pipeline.readback(slot))?)
            }
            _ => None,
        };
        self.taken.push(PassImage {
            number: index + 1,
            name: pass.name,
            corner,
            width,
            height,
            color,
            depth,
            stencil,
            alpha: None,
            map_minus_ramp: None,
            map,
        });
        Ok(())
    }

    /// Runs the variants of the frame's alpha-tested eye passes, then the eye passes once
    /// more, and returns every pass's images.
    pub(super) fn finish(
        mut self,
        pipeline: &mut dyn Pipeline,
        ctx: &GpuContext,
        target: &RenderTarget,
        plan: &Plan,
        frame: u32,
    ) -> Result<PassImages, RenderError> {
        let replay = Replay {
            passes: &plan.passes,
            ctx,
            target,
            image: self.image,
            frame,
        };
        let measures = map_minus_ramp(self.technique).is_some();
        for (j, pass) in plan.passes.iter().enumerate() {
            let Some(test) = alpha_test(pass) else {
                continue;
            };
            let low = replay.alpha(pipeline, j, &without_alpha_test(pass, 0.0))?;
            let high = replay.alpha(pipeline, j, &without_alpha_test(pass, 1.0))?;
            let alpha = low
                .iter()
                .zip(&high)
                .map(|(&l, &h)| (l == h).then_some(l))
                .collect();
            let steps = if measures {
                let plus = replay.alpha(pipeline, j, &measuring(pass, Order::MapMinusRamp))?;
                let minus = replay.alpha(pipeline, j, &measuring(pass, Order::RampMinusMap))?;
                Some(
                    plus.iter()
                        .zip(&minus)
                        .map(|(&p, &m)| steps(p, m))
                        .collect(),
                )
            } else {
                None
            };
            if let Some(image) = self.taken.get_mut(self.maps + j) {
                image.alpha = Some(AlphaBeforeTest { test, alpha });
                image.map_minus_ramp = steps;
            }
        }
        for pass in &plan.passes {
            run(pipeline, ctx, pass.name, frame, &pass.commands)?;
        }
        Ok(PassImages {
            technique: self.technique,
            depth_bits: target.depth_bits(),
            stencil_bits: target.stencil_bits(),
            passes: self.taken,
        })
    }
}

/// M − F from the bytes of the two measuring variants (M − F and F − M, each clamped at
/// 0); `None` where both are non-zero: the pass did not compare there.
fn steps(map_minus_ramp: u8, ramp_minus_map: u8) -> Option<i16> {
    if map_minus_ramp > 0 && ramp_minus_map > 0 {
        None
    } else {
        Some(i16::from(map_minus_ramp) - i16::from(ramp_minus_map))
    }
}

/// The eye passes, replayed with one of them replaced.
struct Replay<'a> {
    passes: &'a [Pass],
    ctx: &'a GpuContext,
    target: &'a RenderTarget,
    image: (u32, u32),
    frame: u32,
}

impl Replay<'_> {
    /// The alpha bytes (image corner, top row first) `variant` leaves in place of pass
    /// `j`; the replay then runs the passes after it, ending as a frame ends.
    fn alpha(
        &self,
        pipeline: &mut dyn Pipeline,
        j: usize,
        variant: &[Command],
    ) -> Result<Vec<u8>, RenderError> {
        let (ctx, frame) = (self.ctx, self.frame);
        for pass in &self.passes[..j] {
            run(pipeline, ctx, pass.name, frame, &pass.commands)?;
        }
        run(pipeline, ctx, self.passes[j].name, frame, variant)?;
        let color = read_color(ctx, self.target, self.image.0, self.image.1)?;
        for pass in &self.passes[j + 1..] {
            run(pipeline, ctx, pass.name, frame, &pass.commands)?;
        }
        Ok(color.pixels().map(|p| p.0[3]).collect())
    }
}

/// The alpha test a pass enables: `Some(test)` when it has `Enable(ALPHA_TEST)`, `test`
/// being its last `AlphaFunc` if it sets one.
fn alpha_test(pass: &Pass) -> Option<Option<(CompareFunc, f32)>> {
    let enables = pass
        .commands
        .iter()
        .any(|c| matches!(c, Command::Enable(Capability::AlphaTest)));
    enables.then(|| {
        pass.commands.iter().rev().find_map(|c| match c {
            Command::AlphaFunc { func, reference } => Some((*func, *reference)),
            _ => None,
        })
    })
}

/// Commands the alpha variants drop: the test itself, and what would keep its alpha out
/// of the colour buffer (write masks, blending).
fn hides_alpha(c: &Command) -> bool {
    matches!(
        c,
        Command::Enable(Capability::AlphaTest | Capability::Blend)
            | Command::AlphaFunc { .. }
            | Command::ColorMask(_)
    )
}

/// The alpha test and blending off (an earlier pass may have left them on), all channels
/// writable; glClearColor(0, 0, 0, alpha); glClear(COLOR).
fn clear_alpha(alpha: f32) -> Vec<Command> {
    vec![
        Command::Disable(Capability::AlphaTest),
        Command::Disable(Capability::Blend),
        Command::ColorMask(ColorMask::ALL),
        Command::ClearColor(Vec4::new(0.0, 0.0, 0.0, alpha)),
        Command::Clear(ClearMask {
            color: true,
            depth: false,
            stencil: false,
            accum: false,
        }),
    ]
}

/// The pass drawing every fragment's colour: no alpha test, no masks, no blending, into a
/// colour buffer cleared to alpha `clear`.
fn without_alpha_test(pass: &Pass, clear: f32) -> Vec<Command> {
    let mut c = clear_alpha(clear);
    c.extend(pass.commands.iter().filter(|c| !hides_alpha(c)).cloned());
    c
}

/// Which way round a measuring variant subtracts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Order {
    /// alpha = unit 0's texel − unit 1's texel: M − F.
    MapMinusRamp,
    /// alpha = unit 1's texel − unit 0's texel: F − M.
    RampMinusMap,
}

/// The measuring texture environment: unit 0 REPLACE(TEXTURE) alpha; unit 1
/// SUBTRACT(PREVIOUS, TEXTURE) or SUBTRACT(TEXTURE, PREVIOUS) alpha; unit 2 passes
/// PREVIOUS on; RGB the primary colour throughout; scales 1.
fn measuring_env(order: Order) -> Vec<Command> {
    use TexEnvParam as P;
    let env = |p: P| Command::TexEnv(p);
    let pass_on = |source: CombineSource| {
        [
            env(P::Mode(TexEnvMode::Combine)),
            env(P::CombineRgb(CombineFunc::Replace)),
            env(P::SourceRgb(CombineArg::Arg0, source)),
            env(P::OperandRgb(CombineArg::Arg0, CombineOperand::SrcColor)),
            env(P::RgbScale(1.0)),
            env(P::AlphaScale(1.0)),
            env(P::OperandAlpha(CombineArg::Arg0, CombineOperand::SrcAlpha)),
            env(P::OperandAlpha(CombineArg::Arg1, CombineOperand::SrcAlpha)),
        ]
    };
    let (first, second) = match order {
        Order::MapMinusRamp => (CombineSource::Previous, CombineSource::Texture),
        Order::RampMinusMap => (CombineSource::Texture, CombineSource::Previous),
    };
    let mut c = vec![Command::ActiveTexture(0)];
    c.extend(pass_on(CombineSource::PrimaryColor));
    c.extend([
        env(P::CombineAlpha(CombineFunc::Replace)),
        env(P::SourceAlpha(CombineArg::Arg0, CombineSource::Texture)),
        Command::ActiveTexture(1),
    ]);
    c.extend(pass_on(CombineSource::Previous));
    c.extend([
        env(P::CombineAlpha(CombineFunc::Subtract)),
        env(P::SourceAlpha(CombineArg::Arg0, first)),
        env(P::SourceAlpha(CombineArg::Arg1, second)),
        Command::ActiveTexture(2),
    ]);
    c.extend(pass_on(CombineSource::Previous));
    c.extend([
        env(P::CombineAlpha(CombineFunc::Replace)),
        env(P::SourceAlpha(CombineArg::Arg0, CombineSource::Previous)),
        Command::ActiveTexture(0),
    ]);
    c
}

/// The pass with its texture environment replaced by [`measuring_env`]: its own `TexEnv`
/// commands and register combiners dropped, as well as what [`hides_alpha`] drops, into a
/// colour buffer cleared to alpha 1.
fn measuring(pass: &Pass, order: Order) -> Vec<Command> {
    let mut c = clear_alpha(1.0);
    c.push(Command::Disable(Capability::RegisterCombiners));
    c.extend(measuring_env(order));
    c.extend(
        pass.commands
            .iter()
            .filter(|c| {
                !hides_alpha(c)
                    && !matches!(
                        c,
                        Command::TexEnv(_) | Command::Enable(Capability::RegisterCombiners)
                    )
            })
            .cloned(),
    );
    c
}

/// The lower-left `width × height` of the colour buffer, top row first.
fn read_color(
    ctx: &GpuContext,
    target: &RenderTarget,
    width: u32,
    height: u32,
) -> Result<RgbaImage, RenderError> {
    let full = target.read_color(ctx)?;
    let (width, height) = (width.min(full.width()), height.min(full.height()));
    Ok(image::imageops::crop_imm(&full, 0, full.height() - height, width, height).to_image())
}

/// The lower-left `width × height` of a bottom-row-first readback `stride` values wide,
/// top row first.
fn lower_left<T: Copy>(data: &[T], stride: u32, width: u32, height: u32) -> Vec<T> {
    let (stride, w) = (stride as usize, width as usize);
    (0..height as usize)
        .rev()
        .flat_map(|row| data[row * stride..row * stride + w].iter().copied())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::techniques::{self, Prepared};
    use crate::vocab::Named;

    fn plan(id: TechniqueId) -> Plan {
        let mut scene = Scene::default_scene();
        scene.shadow.technique = id;
        let prepared = Prepared::new(&scene);
        (techniques::technique(id).plan)(&scene, &prepared).expect("plan")
    }

    #[test]
    fn the_alpha_variant_keeps_everything_but_the_test_masks_and_blending() {
        let plan = plan(TechniqueId::Dual8);
        let lit = plan
            .passes
            .iter()
            .find(|p| p.name == "lit")
            .expect("lit pass");
        assert_eq!(alpha_test(lit), Some(Some((CompareFunc::Greater, 0.5))));
        let variant = without_alpha_test(lit, 0.0);
        // An earlier pass may leave the test on: the variant turns it off first.
        assert_eq!(variant[0], Command::Disable(Capability::AlphaTest));
        assert!(!variant.iter().skip(5).any(hides_alpha));
        let kept = lit.commands.iter().filter(|c| !hides_alpha(c)).count();
        assert_eq!(variant.len(), kept + 5);
        assert!(matches!(variant[4], Command::Clear(m) if m.color && !m.depth && !m.stencil));
    }

    #[test]
    fn the_measuring_variant_subtracts_the_ramp_from_the_map_both_ways() {
        let plan = plan(TechniqueId::Dual8);
        let lit = plan
            .passes
            .iter()
            .find(|p| p.name == "lit")
            .expect("lit pass");
        for (order, first) in [
            (Order::MapMinusRamp, CombineSource::Previous),
            (Order::RampMinusMap, CombineSource::Texture),
        ] {
            let c = measuring(lit, order);
            let add_signed = Command::TexEnv(TexEnvParam::CombineAlpha(CombineFunc::AddSigned));
            assert!(!c.contains(&add_signed));
            let subtract = Command::TexEnv(TexEnvParam::CombineAlpha(CombineFunc::Subtract));
            let at = c.iter().position(|x| *x == subtract).expect("SUBTRACT");
            assert_eq!(
                c[at + 1],
                Command::TexEnv(TexEnvParam::SourceAlpha(CombineArg::Arg0, first))
            );
            // Only the measuring environment's TexEnv commands remain.
            let envs = c.iter().filter(|x| matches!(x, Command::TexEnv(_))).count();
            assert_eq!(envs, measuring_env(order).len() - 4);
        }
    }

    #[test]
    fn steps_are_signed_and_unknown_where_both_sides_are_positive() {
        assert_eq!(steps(3, 0), Some(3));
        assert_eq!(steps(0, 2), Some(-2));
        assert_eq!(steps(0, 0), Some(0));
        assert_eq!(steps(255, 255), None);
        assert_eq!(steps(1, 1), None);
    }

    #[test]
    fn only_the_8_bit_comparisons_have_a_map_minus_ramp() {
        let with: Vec<TechniqueId> = TechniqueId::all()
            .into_iter()
            .filter(|t| map_minus_ramp(*t).is_some())
            .collect();
        assert_eq!(
            with,
            [
                TechniqueId::Dual8,
                TechniqueId::Linear8,
                TechniqueId::Multidigit16
            ]
        );
    }

    #[test]
    fn a_corner_is_cropped_and_turned_top_row_first() {
        // A 3×3 readback, bottom row first: [0 1 2] / [3 4 5] / [6 7 8]; its lower-left 2×2.
        let data = [0u8, 1, 2, 3, 4, 5, 6, 7, 8];
        assert_eq!(lower_left(&data, 3, 2, 2), [3, 4, 0, 1]);
    }
}
