//! What a technique's frame means, for `fixedfunc explain`: the technique's own note, a
//! paragraph per pass, the figures that decide whether it succeeds, and the state each pass
//! draws with.
//!
//! **One source for words and code.** A technique's overview is its module's `//!` note,
//! read from the module's source when this crate is compiled (`include_str!`), so a page or
//! a program prints what the code's documentation says. Each pass's paragraph is in
//! [`pass_notes`], keyed by the names the plans give their passes, and retells the module
//! note's lines for that pass; a test plans every technique on the default scene and fails
//! on a pass without a paragraph or a paragraph for a pass no plan makes.
//!
//! **State as glGet answers it.** [`state_rows`] asks the state model every glGet pname,
//! capability, texture unit, light and texture object it answers (`ff::query`, the table
//! the C library answers glGet from) and keeps what differs from a fresh context's answer:
//! the state "as GL reports it", never a second list of fields that could drift from the
//! model. What is set per object (the modelview matrix, the material, the current normal
//! and texture coordinates) is left out: it changes at every draw.
//!
//! **The figures** ([`figures`]) are the quantisation of the map and of the fragment's depth
//! and the bias that separates them, in the steps that decide the comparison (8-bit steps of
//! 1/255 for `dual8`, ramp steps of 1/256 of the light's range for `linear8`, 16-bit steps
//! for the digit techniques), computed from the scene's `[shadow]` settings with the
//! offset rules of `vocab` (one polygon-offset unit is two LSBs of a 16- or 24-bit buffer
//! on llvmpipe, 2⁻²⁴ of a float one at depths in [0.5, 1)).

use crate::ff::glenum::{registry as r, Family, GlEnum};
use crate::ff::query::{self, QueryValue, PNAMES};
use crate::ff::{
    BlendEquation, BlendFactor, Capability, CombineFunc, CombineOperand, CombineSource, Command,
    CompareFunc, CompareMode, DepthTextureMode, Filter, FixedState, MatrixMode, ShadeModel,
    StencilOp, TexCoord, TexEnvMode, TexFormat, TexGenMode, TextureTarget, Wrap, MAX_LIGHTS,
};
use crate::scene::Scene;
use crate::vocab::{default_offset, DepthBits, DepthRule, ReadbackRule, TechniqueId};

use super::parts::ShadowLight;

/// The note printed before the setup commands of every technique that has some.
pub const SETUP_NOTE: &str = "Executed once, before the first frame: what never changes — \
    the parameters of the textures that the map passes copy or upload into (their filter, \
    and CLAMP_TO_BORDER with a white border, so that whatever lies outside the light's map \
    reads as lit), the compare mode of a depth texture, and the 1D ramps that turn a \
    texture coordinate into an 8-bit digit.";

/// The dim pass every shadow-map technique starts its frame with (`parts::dim_pass`).
const DIM: &str = "Everything drawn as if it were in shadow: the colour, depth (and \
    stencil) buffers cleared, the camera's projection and view, every light but the \
    shadowing one. The depth test writes the depths that the later DepthFunc(EQUAL) passes \
    match exactly: every pass sends the same vertices through the same matrices.";

/// Light pass of the depth-map techniques (`parts::light_pass`).
const LIGHT: &str = "From the light, into the framebuffer's lower-left map-sized corner: \
    glViewport(map), colour writes off, the depth cleared, the light's frustum and \
    gluLookAt, glPolygonOffset(factor, units) on filled polygons, and the casters drawn. \
    The depth buffer's corner is now the shadow map — the depth of the nearest caster per \
    texel — and the bias lives in these depths, where Kilgard puts it.";

const NONE: &[(&str, &str)] = &[(
    "eye",
    "The lit scene in one pass: the colour and depth buffers cleared, the camera's \
     projection and view, the scene's lights with a global ambient of 0.1, then every object \
     under its model matrix with its material. No texture unit is touched, NORMALIZE only \
     when a transform scales. The baseline every shadow technique is timed against, and the \
     eye pass they build on.",
)];

const DEPTH_COMPARE: &[(&str, &str)] = &[
    ("light", LIGHT),
    (
        "copy",
        "glCopyTexImage2D copies the corner's depth into the map texture as \
         DEPTH_COMPONENT16, 24 or 32F — the light pass's own precision, no readback. The \
         texture was set up with COMPARE_R_TO_TEXTURE, LEQUAL and DEPTH_TEXTURE_MODE \
         LUMINANCE, so its lookup is the comparison (SGIX_shadow, ARB_shadow).",
    ),
    ("dim", DIM),
    (
        "lit",
        "The shadowing light alone (no global ambient), added with glBlendFunc(ONE, ONE) \
         where DepthFunc(EQUAL) finds the dim pass's surface. Unit 0 projects the map with \
         eye-linear S, T, R, Q = the rows of B·P_light·V_light; the texel is the compare \
         result c of r/q ≤ the stored depth — 1 lit, 0 shadowed, in between with LINEAR \
         filtering (the era's hardware PCF) — and MODULATE scales the light's contribution \
         by it. Lit pixels equal `none`'s image, shadowed ones keep the ambient.",
    ),
];

const ACCUMULATE: &[(&str, &str)] = &[
    (
        "accum-clear",
        "glClear(GL_ACCUM_BUFFER_BIT) with the clear value glClearAccum(0, 0, 0, 0) set \
         once: the sum of the samples' pictures starts at 0 every frame.",
    ),
    ("light", LIGHT),
    (
        "copy",
        "glCopyTexImage2D copies the corner's depth into the one map texture, as \
         depth-compare's copy: each sample of the light re-makes it from its own point, \
         every frame.",
    ),
    ("dim", DIM),
    (
        "lit",
        "depth-compare's lit pass with the shadowing light a point at this sample's place \
         on the rectangle: its contribution added where the map's compare says lit.",
    ),
    (
        "accum",
        "glAccum(GL_ACCUM, 1/N): the colour buffer, weighted by 1/N, added to the \
         accumulation buffer (signed 16-bit per channel on Mesa: each add truncates).",
    ),
    (
        "return",
        "glAccum(GL_RETURN, 1): the sum — the average of the N hard-shadow pictures, a \
         penumbra where some points of the light are hidden — written back to the colour \
         buffer.",
    ),
];

const DUAL8: &[(&str, &str)] = &[
    ("light", LIGHT),
    (
        "readback",
        "glReadPixels(DEPTH_COMPONENT, UNSIGNED_BYTE) reads the corner's depths into client \
         memory as bytes: Mesa truncates, so the map holds M = ⌊255·z⌋ (the scene's \
         `readback` rule can impose truncation or rounding on any driver: the depths are \
         then read as FLOAT and converted by the program). On 8-bit consumer hardware (TNT, \
         GeForce 256) this round trip through the client was the way into a texture.",
    ),
    (
        "upload",
        "glTexImage2D puts the bytes into the map texture on unit 0 as INTENSITY8: every \
         channel, alpha included, reads M/255.",
    ),
    ("dim", DIM),
    (
        "lit",
        "The comparison, per fragment, in the texture environment. Unit 0 reads the map at \
         (s/q, t/q) (eye-linear S, T, Q = rows 0, 1, 3 of B·P·V) and passes alpha = M/255; \
         unit 1 reads the 256-texel ramp at r/q (eye-linear S = row 2, Q = row 3), the \
         fragment's own depth F = ⌊256·r/q⌋, and computes alpha = ADD_SIGNED(M/255, \
         1 − F/255) = M/255 + (1 − F/255) − ½. glAlphaFunc(GREATER, 0.5) keeps a fragment \
         iff M > F, and DepthFunc(EQUAL) with every light on draws the lit receivers over \
         the dim pass. Equality is shadowed (the ADD_SIGNED tie) and F − M is 0 or 1 for \
         the same depth, so without two 8-bit steps of bias a surface shadows itself.",
    ),
];

const LINEAR8: &[(&str, &str)] = &[
    (
        "light",
        "The distance pass: colour on, cleared to white (the far distance); unit 0's ramp \
         at eye-linear S = the light's linear distance plane plus the bias b = units/256, \
         REPLACE; the casters drawn with the depth test on. The nearest caster's distance \
         s = (d − near)/(far − near) ends in colour alpha as M = ⌊256·(s + b)⌋: the 8 bits \
         are spread evenly over the light's range instead of crowding near its near plane.",
    ),
    (
        "readback",
        "glReadPixels(ALPHA, UNSIGNED_BYTE): the map is colour, not depth — the ramp already \
         made the bytes, exactly (i/255 is exact in RGBA8), whatever the scene's depth \
         readback rule says.",
    ),
    (
        "upload",
        "glTexImage2D puts the bytes into the map texture on unit 0 as INTENSITY8: every \
         channel, alpha included, reads M/255.",
    ),
    ("dim", DIM),
    (
        "lit",
        "As `dual8`'s, with unit 1's S = the same linear distance plane (q = 1): the \
         fragment's F = ⌊256·s⌋ against the map's M, lit iff M > F. Polygon offset moves \
         depths, not the colour this map is made of, so the bias was added to the map's \
         distance plane instead; without it M = F wherever a surface sees the light, and the \
         ADD_SIGNED tie shadows it.",
    ),
];

const DIGIT_MAPS: [(&str, &str); 3] = [
    (
        "light",
        "Depth only, from the light, with glPolygonOffset(factor, units), into the \
         map-sized corner: the depths the two 8-bit digits are cut from.",
    ),
    (
        "readback",
        "glReadPixels(DEPTH_COMPONENT, UNSIGNED_SHORT): the map as D = round(65535·z), Mesa's \
         rule for shorts (the scene's `readback` rule can impose truncation or rounding).",
    ),
    (
        "upload",
        "glTexImage2D of the shorts as LUMINANCE_ALPHA bytes into LUMINANCE8_ALPHA8: on a \
         little-endian machine each short's low byte, the little digit D & 255, lands in \
         luminance and its high byte, the big digit D >> 8, in alpha.",
    ),
];

const DIGIT_DIM: &str = "Everything drawn as if it were in shadow, with the stencil \
    cleared to 0 for the digit passes' tags: the shadowing light off, the depth test writing \
    the depths that the later DepthFunc(EQUAL) passes match exactly.";

const MULTIDIGIT16: &[(&str, &str)] = &[
    DIGIT_MAPS[0],
    DIGIT_MAPS[1],
    DIGIT_MAPS[2],
    ("dim", DIGIT_DIM),
    (
        "big",
        "The big digits. DepthFunc(EQUAL); unit 0 the map, unit 1 the CLAMP_TO_EDGE ramp at \
         r/q (the fragment's big digit ⌊256·r/q⌋); one register-combiner stage computes \
         alpha = big(map) − big(fragment), clamped to [0, 1]; glAlphaFunc(GREATER, 0) \
         passes where the map's big digit is the greater, and those receivers are drawn lit \
         and tagged with stencil 1 (ALWAYS, REPLACE).",
    ),
    (
        "little",
        "The little digits, where the big ones tie. Unit 2 reads the REPEAT ramp at \
         256·r/q (the fragment's little digit ⌊65536·r/q⌋ mod 256); two combiner stages give \
         little(map) − little(fragment) where big(map) + ½ − big(fragment) ≥ ½ (a MUX) and 0 \
         elsewhere; AlphaFunc(GREATER, 0) and stencil NOTEQUAL 1 draw the rest of the lit \
         receivers. Lit iff the map's 16-bit number is the greater.",
    ),
];

const MULTIDIGIT16_COMBINE: &[(&str, &str)] = &[
    DIGIT_MAPS[0],
    DIGIT_MAPS[1],
    DIGIT_MAPS[2],
    ("dim", DIGIT_DIM),
    (
        "big-lit",
        "Colour writes off: this pass and the next two write stencil tags only. Unit 0 \
         passes the map's alpha (its big digit), unit 1 subtracts the fragment's big digit \
         read from the ramp at r/q: alpha = SUBTRACT(PREVIOUS, TEXTURE) = big(map) − \
         big(fragment). AlphaFunc(GREATER, 0) with stencil ALWAYS, REPLACE 1 tags the pixels \
         whose map's big digit is the greater: lit.",
    ),
    (
        "big-shadowed",
        "The reverse difference, big(fragment) − big(map) > 0, where the stencil still \
         holds 0: tagged 2, shadowed. What is left at 0 has equal big digits.",
    ),
    (
        "little-lit",
        "Where the stencil holds 0 (equal big digits): unit 0 passes little(map) in RGB, \
         unit 1 computes ADD_SIGNED(PREVIOUS, 1 − TEXTURE) = ½ + little(map) − \
         little(fragment), unit 2 DOT3_RGBA with the constant (1, 1, 1, 1) moves 6·d into \
         alpha — combine's alpha operands read only alpha, and DOT3 is the one function that \
         moves an RGB result there. AlphaFunc(GREATER, 0) tags 1 where the map's little \
         digit is the greater.",
    ),
    (
        "lit",
        "Colour on: stencil EQUAL 1, every light on, no textures — the lit colour drawn \
         where the tags say lit, over the dim pass.",
    ),
];

const PLANAR: &[(&str, &str)] = &[
    (
        "eye",
        "The scene, lit, with the stencil numbering the flat lit receivers: receiver k is \
         drawn with glStencilFunc(ALWAYS, k, ~0) and glStencilOp(KEEP, KEEP, REPLACE), so \
         the stencil holds k where it is the visible surface; other objects leave the \
         stencil alone (offset mode) or write 0 (stencil mode).",
    ),
    (
        "shadow",
        "The casters again, lighting off, through each receiver's shadow matrix \
         M_k = (p_k·l)·I − l·p_kᵀ, flattened onto its plane (their triangles clipped on the \
         CPU to the slab between the plane and the light): black at half alpha, blended \
         (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) where the stencil holds k. The first fragment \
         that passes sets the stencil to 0, so every shadowed pixel is darkened exactly \
         once. Z-fighting with the receiver is avoided by glPolygonOffset(−2, −9) with depth \
         writes off (offset mode, dinoshade) or by the depth test off (stencil mode).",
    ),
];

const PROJECTIVE: &[(&str, &str)] = &[
    (
        "silhouette",
        "The projector's view of one set of casters, black on a white clear with lighting \
         off, into the map-sized corner: a silhouette. With the pseudo-depth projector the \
         casters are flattened onto the largest flat receiver first, and a glOrtho with near \
         1 clips every false shadow (below the plane, beyond the light).",
    ),
    (
        "copy",
        "glCopyTexImage2D of the corner into the set's texture as RGB8. There is one \
         silhouette and one copy per distinct set of casters: a receiver is never shown its \
         own silhouette, which would darken its lit side.",
    ),
    ("dim", DIM),
    (
        "lit",
        "The shadowing light alone, added (ONE, ONE) where DepthFunc(EQUAL) finds the dim \
         pass's surface, MODULATEd by the silhouette projected with eye-linear S, T, R, Q = \
         the rows of B·C: white adds the light, black adds nothing. Each receiver is drawn \
         with the silhouette of the other casters; outside it the white border keeps \
         fragments lit.",
    ),
];

const OCCLUDER_PLANES: &[(&str, &str)] = &[
    ("dim", DIM),
    (
        "lit",
        "The shadowing light alone, added (ONE, ONE) where DepthFunc(EQUAL) finds the dim \
         pass's surface. Unit k holds plane k's occluder as a two-slice 3D texture and \
         MODULATEs: OBJECT_LINEAR S, T, R, Q are the plane's rows for the receiver being \
         drawn (with a point light, on the texture matrix), so (s, t) is where the ray \
         towards the light meets the plane and r picks the white slice when the plane is \
         not between the fragment and the light. The light arrives times the product of \
         the factors.",
    ),
];

const OCCLUSION_TEXTURES: &[(&str, &str)] = &[
    (
        "slices",
        "The casters from behind the area light (the centre of projection offset on its axis, \
         the near window fitted around the light) into a framebuffer object, once per RGBA \
         occlusion texture, with Eisemann & Décoret's slicing program: each fragment writes 1 \
         into the channel of its depth slice (and of the next slice: the light-leak fix), \
         blended ONE, ONE so that a channel holds the union of its slice's occluders.",
    ),
    (
        "prefilter",
        "`prefilter = \"mipmap\"`: glGenerateMipmap of each occlusion texture, a box of 2^l \
         texels read at level l, trilinearly. `\"nbuffers\"`: full-window program passes into \
         a framebuffer object build level l (the mean of 2^l × 2^l texels) from four texels \
         of level l − 1, even and odd levels in two textures so none is read while written.",
    ),
    ("dim", DIM),
    (
        "lit",
        "The shadowing light's diffuse term added (ONE, ONE) where DepthFunc(EQUAL) finds the \
         dim pass's surface, times the visibility the program computes: for every slice \
         between the fragment and the light, the blocked fraction read with a box of the \
         light's size scaled by d(P, slice)/d(P, light), combined as Π(1 − I_k).",
    ),
];

/// Pass name → paragraph, for every pass `id`'s plans make.
pub fn pass_notes(id: TechniqueId) -> &'static [(&'static str, &'static str)] {
    match id {
        TechniqueId::None => NONE,
        TechniqueId::DepthCompare => DEPTH_COMPARE,
        TechniqueId::Accumulate => ACCUMULATE,
        TechniqueId::Dual8 => DUAL8,
        TechniqueId::Linear8 => LINEAR8,
        TechniqueId::Multidigit16 => MULTIDIGIT16,
        TechniqueId::Multidigit16Combine => MULTIDIGIT16_COMBINE,
        TechniqueId::Planar => PLANAR,
        TechniqueId::Projective => PROJECTIVE,
        TechniqueId::OccluderPlanes => OCCLUDER_PLANES,
        TechniqueId::OcclusionTextures => OCCLUSION_TEXTURES,
    }
}

/// The paragraph of pass `pass` of technique `id`.
pub fn pass_note(id: TechniqueId, pass: &str) -> Option<&'static str> {
    pass_notes(id)
        .iter()
        .find(|(name, _)| *name == pass)
        .map(|(_, note)| *note)
}

/// The technique module's source, whose `//!` note is its overview.
fn module_source(id: TechniqueId) -> &'static str {
    match id {
        TechniqueId::None => include_str!("none.rs"),
        TechniqueId::DepthCompare => include_str!("depth_compare.rs"),
        TechniqueId::Accumulate => include_str!("accumulate.rs"),
        TechniqueId::Dual8 => include_str!("dual8.rs"),
        TechniqueId::Linear8 => include_str!("linear8.rs"),
        TechniqueId::Multidigit16 => include_str!("multidigit16.rs"),
        TechniqueId::Multidigit16Combine => include_str!("multidigit16_combine.rs"),
        TechniqueId::Planar => include_str!("planar.rs"),
        TechniqueId::Projective => include_str!("projective.rs"),
        TechniqueId::OccluderPlanes => include_str!("occluder_planes.rs"),
        TechniqueId::OcclusionTextures => include_str!("occlusion_textures.rs"),
    }
}

/// The technique module's `//!` note as markdown: rustdoc links become their code text.
pub fn overview(id: TechniqueId) -> String {
    let mut text = String::new();
    for line in module_source(id).lines() {
        let Some(rest) = line.strip_prefix("//!") else {
            break;
        };
        text.push_str(&unlink(rest.strip_prefix(' ').unwrap_or(rest)));
        text.push('\n');
    }
    text
}

/// `` [`a::b`] `` and `` [`a`](b) `` → `` `a::b` ``, `` `a` ``.
fn unlink(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut rest = line;
    while let Some(start) = rest.find("[`") {
        let Some(len) = rest[start + 2..].find("`]") else {
            break;
        };
        out.push_str(&rest[..start]);
        out.push('`');
        out.push_str(&rest[start + 2..start + 2 + len]);
        out.push('`');
        rest = &rest[start + 2 + len + 2..];
        if rest.starts_with('(') {
            if let Some(close) = rest.find(')') {
                rest = &rest[close + 1..];
            }
        }
    }
    out.push_str(rest);
    out
}

/// One figure of a frame: what it is and its value, in words.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Figure {
    pub name: String,
    pub value: String,
}

fn figure(name: &str, value: String) -> Figure {
    Figure {
        name: name.to_string(),
        value,
    }
}

/// How far glPolygonOffset's `units` move a depth z ∈ [0, 1] on llvmpipe (`vocab`'s rule:
/// two LSBs of a 16- or 24-bit buffer per unit, 2⁻²⁴ of a float one at depths in [0.5, 1)).
pub fn offset_units_in_z(depth: DepthBits, units: f32) -> f64 {
    let units = f64::from(units);
    match depth {
        DepthBits::D16 => 2.0 * units / 65_535.0,
        DepthBits::D24 => 2.0 * units / 16_777_215.0,
        DepthBits::D32F => units / 16_777_216.0,
    }
}

/// The figures that decide the scene's technique (its `[shadow] technique`).
pub fn figures(scene: &Scene) -> Vec<Figure> {
    let s = &scene.shadow;
    let id = s.technique;
    let mut out = vec![figure(
        "image, framebuffer",
        format!(
            "{}×{} image; the map is {}×{} and shares the framebuffer (its lower-left corner)",
            scene.image.width, scene.image.height, s.map_size, s.map_size
        ),
    )];
    if id.uses_offset() {
        out.push(offset_figure(scene));
    }
    match id {
        TechniqueId::None => {}
        TechniqueId::DepthCompare => out.extend(depth_compare_figures(scene)),
        TechniqueId::Accumulate => {
            out.extend(depth_compare_figures(scene));
            let n = s.light_samples;
            out.push(figure(
                "light samples",
                format!(
                    "{n} hard-shadow renders a frame from stratified points of the area light, \
                     each added with glAccum(GL_ACCUM, 1/{n}); one render weighs \
                     q(32767/{n}) = {} of 32767, so the returned visibility is exact to \
                     {n}/32767 of the light",
                    crate::ff::accum::q(32767.0 / n.max(1) as f32)
                ),
            ));
        }
        TechniqueId::Dual8 => out.extend(dual8_figures(scene)),
        TechniqueId::Linear8 => out.extend(linear8_figures(scene)),
        TechniqueId::Multidigit16 | TechniqueId::Multidigit16Combine => {
            out.extend(digit_figures(scene))
        }
        TechniqueId::Planar => out.push(figure(
            "shadow bias",
            format!(
                "`planar_mode = \"{}\"`: offset mode draws the shadow with \
                 glPolygonOffset({}, {}) towards the eye ({} plus twice the slope), depth \
                 writes off; stencil mode turns the depth test off instead",
                crate::vocab::Named::name(s.planar_mode),
                super::planar::SHADOW_OFFSET.0,
                super::planar::SHADOW_OFFSET.1,
                DepthBits::D24.offset_units_in_steps(super::planar::SHADOW_OFFSET.1),
            ),
        )),
        TechniqueId::Projective => out.push(figure(
            "silhouette",
            format!(
                "RGB8, {}×{}, `projector = \"{}\"`; no depth is compared, so no bias",
                s.map_size,
                s.map_size,
                crate::vocab::Named::name(s.projector)
            ),
        )),
        TechniqueId::OccluderPlanes => out.push(figure(
            "shadow planes",
            format!(
                "{} planes, one texture unit each (of {}); no map, no depth compare, so no bias",
                s.planes.iter().map(|p| p.planes.len()).sum::<usize>(),
                crate::ff::MAX_TEXTURE_UNITS
            ),
        )),
        TechniqueId::OcclusionTextures => {
            let o = super::occlusion_textures::OcclusionSettings::of(scene);
            out.push(figure(
                "occlusion textures",
                format!(
                    "{} slices in {} RGBA textures of {}² ({:?} prefilter, {:?} combination); \
                     shader programs, so the emulate pipeline only",
                    o.slices,
                    o.slices.div_ceil(4),
                    o.size,
                    o.prefilter,
                    o.combine
                ),
            ));
        }
    }
    out
}

/// The light pass's offset, where it came from, and what its units are in depth LSBs.
fn offset_figure(scene: &Scene) -> Figure {
    let s = &scene.shadow;
    let value = match s.offset() {
        None => format!("none ({})", s.offset_source()),
        Some(o) => format!(
            "glPolygonOffset({}, {}) ({}): the units are {}, plus {} × the depth slope",
            o.factor,
            o.units,
            s.offset_source(),
            s.depth.offset_units_in_steps(o.units),
            o.factor
        ),
    };
    figure("light pass offset", value)
}

/// The given offset's units in steps of 1/`levels`, and the technique's default's.
fn bias_in_steps(scene: &Scene, levels: f64) -> (f64, f64) {
    let s = &scene.shadow;
    let steps = |units: Option<f32>| units.map_or(0.0, |u| offset_units_in_z(s.depth, u) * levels);
    (
        steps(s.offset().map(|o| o.units)),
        steps(default_offset(s.technique, s.depth).map(|o| o.units)),
    )
}

/// "enough" or "not enough" against the steps the comparison needs.
fn verdict(given: f64, needed: f64) -> &'static str {
    if given >= needed {
        "enough"
    } else {
        "not enough: surfaces facing the light shadow themselves (acne)"
    }
}

fn depth_compare_figures(scene: &Scene) -> Vec<Figure> {
    let s = &scene.shadow;
    let bits = s.depth.bits();
    let step = match s.depth {
        DepthBits::D16 => "1/65535".to_string(),
        DepthBits::D24 => "1/16777215".to_string(),
        DepthBits::D32F => "2⁻²⁴ at depths in [0.5, 1)".to_string(),
    };
    let (given, default) = bias_in_steps(
        scene,
        match s.depth {
            DepthBits::D16 => 65_535.0,
            DepthBits::D24 => 16_777_215.0,
            DepthBits::D32F => 16_777_216.0,
        },
    );
    vec![
        figure(
            "map",
            format!(
                "the light pass's depth copied as DEPTH_COMPONENT{}: a step of {step}",
                if bits == 32 {
                    "32F".into()
                } else {
                    bits.to_string()
                }
            ),
        ),
        figure(
            "fragment",
            "r/q of the eye-linear R and Q, clamped to [0, 1], compared LEQUAL in the \
             texture unit at the map's precision"
                .to_string(),
        ),
        figure(
            "bias",
            format!(
                "{} steps of the map's format from the units (the default gives {}; \
                 Kilgard's \"usually works\" (1, 4)); the factor covers slopes",
                crate::vocab::short(given),
                crate::vocab::short(default)
            ),
        ),
    ]
}

fn dual8_figures(scene: &Scene) -> Vec<Figure> {
    let s = &scene.shadow;
    let map = match s.readback {
        ReadbackRule::Driver => "M = ⌊255·z⌋ (glReadPixels UNSIGNED_BYTE: Mesa truncates)",
        ReadbackRule::Cpu(DepthRule::Truncate) => "M = ⌊255·z⌋ (FLOAT read, truncated)",
        ReadbackRule::Cpu(DepthRule::Round) => "M = ⌊255·z + ½⌋ (FLOAT read, rounded)",
    };
    let (given, default) = bias_in_steps(scene, 255.0);
    vec![
        figure(
            "map quantisation",
            format!("{map}: 256 levels, a step of 1/255 = 0.003922 of the depth range"),
        ),
        figure(
            "ramp quantisation",
            "F = ⌊256·r/q⌋ clamped to 255 (the 256-texel ramp, NEAREST): a step of 1/256 = \
             0.003906"
                .to_string(),
        ),
        figure(
            "comparison",
            "alpha = M/255 + (1 − F/255) − ½ > ½ iff M > F: a tie is shadowed, and F − M is 0 \
             or 1 for the same depth"
                .to_string(),
        ),
        figure(
            "bias needed",
            "at least 2 steps of 1/255 (8-bit steps) lifted into the map by the light pass's \
             offset"
                .to_string(),
        ),
        figure(
            "bias given",
            format!(
                "{} 8-bit steps from the units, {} (the technique's default gives {}; the \
                 slide's \"(1.0, 4.0)\" gives {})",
                crate::vocab::short(given),
                verdict(given, 2.0),
                crate::vocab::short(default),
                crate::vocab::short(offset_units_in_z(DepthBits::D24, 4.0) * 255.0)
            ),
        ),
    ]
}

fn linear8_figures(scene: &Scene) -> Vec<Figure> {
    let units = scene.shadow.offset().map_or(0.0, |o| o.units);
    let range = ShadowLight::of(scene, TechniqueId::Linear8)
        .ok()
        .map(|l| (l.near, l.far));
    let step = range.map_or(String::new(), |(near, far)| {
        format!(
            "; the light's range {near}…{far} makes one step {} scene units",
            crate::vocab::short(f64::from(far - near) / 256.0)
        )
    });
    vec![
        figure(
            "map quantisation",
            format!(
                "M = ⌊256·(s + b)⌋ of the linear distance s = (d − near)/(far − near), stored \
                 exactly in alpha: a step of 1/256 of the light's range{step}"
            ),
        ),
        figure(
            "ramp quantisation",
            "F = ⌊256·s⌋ of the same plane, clamped to 255".to_string(),
        ),
        figure(
            "comparison",
            "lit iff M > F; a tie is shadowed (ADD_SIGNED, GREATER ½)".to_string(),
        ),
        figure(
            "bias",
            format!(
                "b = units/256: {} ramp steps, {} (at least 1 step is needed; polygon offset \
                 cannot move this map, which is colour, and the factor is ignored)",
                crate::vocab::short(f64::from(units)),
                verdict(f64::from(units), 1.0)
            ),
        ),
    ]
}

fn digit_figures(scene: &Scene) -> Vec<Figure> {
    let s = &scene.shadow;
    let map = match s.readback {
        ReadbackRule::Driver => "D = round(65535·z) (glReadPixels UNSIGNED_SHORT: Mesa rounds)",
        ReadbackRule::Cpu(DepthRule::Truncate) => "D = ⌊65535·z⌋ (FLOAT read, truncated)",
        ReadbackRule::Cpu(DepthRule::Round) => "D = ⌊65535·z + ½⌋ (FLOAT read, rounded)",
    };
    let (given, default) = bias_in_steps(scene, 65_535.0);
    vec![
        figure(
            "map quantisation",
            format!(
                "{map}, kept as two digits: big = D >> 8 (alpha), little = D & 255 \
                 (luminance); a step of 1/65535"
            ),
        ),
        figure(
            "ramp quantisation",
            "big(fragment) = ⌊256·r/q⌋ (CLAMP_TO_EDGE ramp), little(fragment) = \
             ⌊65536·r/q⌋ mod 256 (REPEAT ramp at 256·r/q): F = ⌊65536·r/q⌋, a step of 1/65536"
                .to_string(),
        ),
        figure(
            "comparison",
            "lit iff big(map) > big(fragment), or the big digits tie and little(map) > \
             little(fragment): D > F, a tie shadowed"
                .to_string(),
        ),
        figure(
            "bias",
            format!(
                "{} 16-bit steps from the units, {} (at least 2 are needed: F − D is up to 1 \
                 for the same depth; the default gives {})",
                crate::vocab::short(given),
                verdict(given, 2.0),
                crate::vocab::short(default)
            ),
        ),
    ]
}

/// One row of a state table: where the state lives (`""` for the context, `unit 1`,
/// `GL_LIGHT0`, `texture 1`), its glGet name, and its value as glGet answers it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StateRow {
    pub group: String,
    pub name: String,
    pub value: String,
}

/// The state of a pass's draws: the draws (numbered in the pass from 0) that share these
/// rows, or none for a pass that draws nothing (its rows are then the state it leaves).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PassState {
    pub draws: Option<(usize, usize)>,
    pub rows: Vec<StateRow>,
}

/// Pnames left out of the tables: set per object, duplicates of another row (the GL 1.4
/// names of the blend factors; the transposed matrices), or per texture unit (asked per
/// unit instead).
const LEFT_OUT: [u32; 18] = [
    r::MODELVIEW_MATRIX,
    r::MODELVIEW_STACK_DEPTH,
    r::TRANSPOSE_MODELVIEW_MATRIX,
    r::TRANSPOSE_PROJECTION_MATRIX,
    r::TRANSPOSE_TEXTURE_MATRIX,
    r::CURRENT_NORMAL,
    r::CURRENT_TEXTURE_COORDS,
    r::CURRENT_RASTER_TEXTURE_COORDS,
    r::BLEND_SRC_RGB,
    r::BLEND_DST_RGB,
    r::BLEND_SRC_ALPHA,
    r::BLEND_DST_ALPHA,
    r::BLEND_EQUATION_ALPHA,
    r::TEXTURE_MATRIX,
    r::TEXTURE_STACK_DEPTH,
    r::TEXTURE_BINDING_1D,
    r::TEXTURE_BINDING_2D,
    r::TEXTURE_BINDING_3D,
];

/// The pnames asked per texture unit (with that unit active).
const UNIT_PNAMES: [(&str, u32); 4] = [
    ("GL_TEXTURE_BINDING_1D", r::TEXTURE_BINDING_1D),
    ("GL_TEXTURE_BINDING_2D", r::TEXTURE_BINDING_2D),
    ("GL_TEXTURE_BINDING_3D", r::TEXTURE_BINDING_3D),
    ("GL_TEXTURE_MATRIX", r::TEXTURE_MATRIX),
];

/// glGetTexEnv's pnames.
const ENV_PNAMES: [(&str, u32); 18] = [
    ("GL_TEXTURE_ENV_MODE", r::TEXTURE_ENV_MODE),
    ("GL_TEXTURE_ENV_COLOR", r::TEXTURE_ENV_COLOR),
    ("GL_COMBINE_RGB", r::COMBINE_RGB),
    ("GL_COMBINE_ALPHA", r::COMBINE_ALPHA),
    ("GL_SOURCE0_RGB", r::SOURCE0_RGB),
    ("GL_SOURCE1_RGB", r::SOURCE1_RGB),
    ("GL_SOURCE2_RGB", r::SOURCE2_RGB),
    ("GL_SOURCE0_ALPHA", r::SOURCE0_ALPHA),
    ("GL_SOURCE1_ALPHA", r::SOURCE1_ALPHA),
    ("GL_SOURCE2_ALPHA", r::SOURCE2_ALPHA),
    ("GL_OPERAND0_RGB", r::OPERAND0_RGB),
    ("GL_OPERAND1_RGB", r::OPERAND1_RGB),
    ("GL_OPERAND2_RGB", r::OPERAND2_RGB),
    ("GL_OPERAND0_ALPHA", r::OPERAND0_ALPHA),
    ("GL_OPERAND1_ALPHA", r::OPERAND1_ALPHA),
    ("GL_OPERAND2_ALPHA", r::OPERAND2_ALPHA),
    ("GL_RGB_SCALE", r::RGB_SCALE),
    ("GL_ALPHA_SCALE", r::ALPHA_SCALE),
];

/// glGetTexGen's pnames.
const TEXGEN_PNAMES: [(&str, u32); 3] = [
    ("GL_TEXTURE_GEN_MODE", r::TEXTURE_GEN_MODE),
    ("GL_EYE_PLANE", r::EYE_PLANE),
    ("GL_OBJECT_PLANE", r::OBJECT_PLANE),
];

/// glGetLight's pnames.
const LIGHT_PNAMES: [(&str, u32); 10] = [
    ("GL_AMBIENT", r::AMBIENT),
    ("GL_DIFFUSE", r::DIFFUSE),
    ("GL_SPECULAR", r::SPECULAR),
    ("GL_POSITION", r::POSITION),
    ("GL_SPOT_DIRECTION", r::SPOT_DIRECTION),
    ("GL_SPOT_EXPONENT", r::SPOT_EXPONENT),
    ("GL_SPOT_CUTOFF", r::SPOT_CUTOFF),
    ("GL_CONSTANT_ATTENUATION", r::CONSTANT_ATTENUATION),
    ("GL_LINEAR_ATTENUATION", r::LINEAR_ATTENUATION),
    ("GL_QUADRATIC_ATTENUATION", r::QUADRATIC_ATTENUATION),
];

/// glGetTexParameter's pnames the techniques set.
const TEXTURE_PNAMES: [(&str, u32); 10] = [
    ("GL_TEXTURE_MIN_FILTER", r::TEXTURE_MIN_FILTER),
    ("GL_TEXTURE_MAG_FILTER", r::TEXTURE_MAG_FILTER),
    ("GL_TEXTURE_WRAP_S", r::TEXTURE_WRAP_S),
    ("GL_TEXTURE_WRAP_T", r::TEXTURE_WRAP_T),
    ("GL_TEXTURE_WRAP_R", r::TEXTURE_WRAP_R),
    ("GL_TEXTURE_BORDER_COLOR", r::TEXTURE_BORDER_COLOR),
    ("GL_TEXTURE_COMPARE_MODE", r::TEXTURE_COMPARE_MODE),
    ("GL_TEXTURE_COMPARE_FUNC", r::TEXTURE_COMPARE_FUNC),
    ("GL_DEPTH_TEXTURE_MODE", r::DEPTH_TEXTURE_MODE),
    ("GL_GENERATE_MIPMAP", r::GENERATE_MIPMAP),
];

/// The per-unit capabilities (asked with the unit active).
const UNIT_CAPABILITIES: [Capability; 7] = [
    Capability::Texture1D,
    Capability::Texture2D,
    Capability::Texture3D,
    Capability::TextureGen(TexCoord::S),
    Capability::TextureGen(TexCoord::T),
    Capability::TextureGen(TexCoord::R),
    Capability::TextureGen(TexCoord::Q),
];

/// Everything about `state` that glGet answers differently from a fresh context, but what
/// is set per object (see the module note), in the order of GL's state tables: the
/// context's pnames and capabilities, each texture unit, each light, each texture object.
pub fn state_rows(state: &FixedState) -> Vec<StateRow> {
    let fresh = FixedState::new();
    let mut rows = Vec::new();
    let mut row = |group: &str, name: &str, value: String| {
        rows.push(StateRow {
            group: group.to_string(),
            name: name.to_string(),
            value,
        })
    };
    for p in PNAMES.iter().filter(|p| !LEFT_OUT.contains(&p.value)) {
        if let (Ok(now), Ok(then)) = (state.get(p.value), fresh.get(p.value)) {
            if now != then {
                row("", p.name, values(&now, p.value));
            }
        }
    }
    for cap in query::capabilities() {
        let Some(c) = query::capability(cap) else {
            continue;
        };
        if UNIT_CAPABILITIES.contains(&c) {
            continue;
        }
        if let (Ok(now), Ok(then)) = (state.is_enabled(cap), fresh.is_enabled(cap)) {
            if now != then {
                row("", &capability_name(c), bool_name(now).to_string());
            }
        }
    }
    for unit in 0..crate::ff::MAX_TEXTURE_UNITS {
        for (name, value) in unit_differences(state, &fresh, unit) {
            row(&format!("unit {unit}"), &name, value);
        }
    }
    for light in 0..MAX_LIGHTS as u32 {
        let l = r::LIGHT0 + light;
        for (name, pname) in LIGHT_PNAMES {
            if let (Ok(now), Ok(then)) = (state.get_light(l, pname), fresh.get_light(l, pname)) {
                if now != then {
                    row(&Family::Light.print(light as u8), name, values(&now, pname));
                }
            }
        }
    }
    for (&name, object) in &state.textures {
        for (what, value) in texture_differences(state, &fresh, name, object.target) {
            row(&format!("texture {name}"), &what, value);
        }
    }
    rows
}

/// `state` and `fresh` with texture unit `unit` active.
fn with_unit(state: &FixedState, unit: usize) -> FixedState {
    let mut s = state.clone();
    s.active_texture = unit;
    s
}

/// What texture unit `unit` answers differently from a fresh context.
fn unit_differences(state: &FixedState, fresh: &FixedState, unit: usize) -> Vec<(String, String)> {
    let (now, then) = (with_unit(state, unit), with_unit(fresh, unit));
    let mut out = Vec::new();
    for c in UNIT_CAPABILITIES {
        let cap = c.gl_value().unwrap_or(0);
        if let (Ok(a), Ok(b)) = (now.is_enabled(cap), then.is_enabled(cap)) {
            if a != b {
                out.push((capability_name(c), bool_name(a).to_string()));
            }
        }
    }
    for (name, pname) in UNIT_PNAMES {
        if let (Ok(a), Ok(b)) = (now.get(pname), then.get(pname)) {
            if a != b {
                out.push((name.to_string(), values(&a, pname)));
            }
        }
    }
    for (name, pname) in ENV_PNAMES {
        if let (Ok(a), Ok(b)) = (
            now.get_tex_env(r::TEXTURE_ENV, pname),
            then.get_tex_env(r::TEXTURE_ENV, pname),
        ) {
            if a != b {
                out.push((name.to_string(), values(&a, pname)));
            }
        }
    }
    for coord in TexCoord::ALL {
        let c = coord.gl_value().unwrap_or(0);
        for (name, pname) in TEXGEN_PNAMES {
            if let (Ok(a), Ok(b)) = (now.get_tex_gen(c, pname), then.get_tex_gen(c, pname)) {
                if a != b {
                    let coord_name = coord.gl_name().unwrap_or("GL_S");
                    out.push((format!("{name} ({coord_name})"), values(&a, pname)));
                }
            }
        }
    }
    out
}

/// What texture object `name` answers differently from a fresh default texture of its
/// target: level 0's size and internal format, then its parameters.
fn texture_differences(
    state: &FixedState,
    fresh: &FixedState,
    name: u32,
    target: TextureTarget,
) -> Vec<(String, String)> {
    let t = target.gl_value().unwrap_or(0);
    let mut now = state.clone();
    now.active_texture = 0;
    let unit = &mut now.units[0];
    match target {
        TextureTarget::Texture1D => unit.bound_1d = name,
        TextureTarget::Texture2D => unit.bound_2d = name,
        TextureTarget::Texture3D => unit.bound_3d = name,
        TextureTarget::CubeMap | TextureTarget::CubeFace(_) => unit.bound_cube_map = name,
    }
    // The fresh context answers for its default texture of the target (name 0).
    let then = with_unit(fresh, 0);
    let mut out = vec![(
        "GL_TEXTURE_TARGET".to_string(),
        target.gl_name().unwrap_or("GL_TEXTURE_2D").to_string(),
    )];
    let level = |pname| now.get_tex_level_parameter(t, 0, pname).ok();
    if let (Some(w), Some(h), Some(f)) = (
        level(r::TEXTURE_WIDTH),
        level(r::TEXTURE_HEIGHT),
        level(r::TEXTURE_INTERNAL_FORMAT),
    ) {
        let size = match target {
            TextureTarget::Texture1D => values(&w, r::TEXTURE_WIDTH),
            _ => format!(
                "{}×{}",
                values(&w, r::TEXTURE_WIDTH),
                values(&h, r::TEXTURE_HEIGHT)
            ),
        };
        if size != "0" && size != "0×0" {
            out.push((
                "level 0".to_string(),
                format!("{size} {}", values(&f, r::TEXTURE_INTERNAL_FORMAT)),
            ));
        }
    }
    for (pname_name, pname) in TEXTURE_PNAMES {
        if let (Ok(a), Ok(b)) = (
            now.get_tex_parameter(t, pname),
            then.get_tex_parameter(t, pname),
        ) {
            if a != b {
                out.push((pname_name.to_string(), values(&a, pname)));
            }
        }
    }
    out
}

/// `GL_DEPTH_TEST`, `GL_LIGHT0`, `GL_CLIP_PLANE2`.
fn capability_name(c: Capability) -> String {
    match c {
        Capability::Light(i) => Family::Light.print(i),
        Capability::ClipPlane(i) => Family::ClipPlane.print(i),
        other => other.gl_name().unwrap_or("GL_NONE").to_string(),
    }
}

fn bool_name(b: bool) -> &'static str {
    if b {
        "GL_TRUE"
    } else {
        "GL_FALSE"
    }
}

/// A query's values as text: one value alone, a matrix as four rows, others in parentheses.
fn values(v: &[QueryValue], pname: u32) -> String {
    let texts: Vec<String> = v.iter().map(|x| value(*x, pname)).collect();
    match texts.len() {
        1 => texts[0].clone(),
        16 => {
            // Column-major, as glGet writes matrices: print the rows.
            let rows: Vec<String> = (0..4)
                .map(|i| {
                    (0..4)
                        .map(|j| texts[j * 4 + i].clone())
                        .collect::<Vec<_>>()
                        .join(" ")
                })
                .collect();
            format!("[{}]", rows.join("; "))
        }
        _ => format!("({})", texts.join(", ")),
    }
}

fn value(v: QueryValue, pname: u32) -> String {
    match v {
        QueryValue::Bool(b) => bool_name(b).to_string(),
        QueryValue::Int(i) => i.to_string(),
        QueryValue::UInt(u) if u > 0xFFFF => format!("{u:#X}"),
        QueryValue::UInt(u) => u.to_string(),
        QueryValue::Enum(e) => enum_name(e, pname),
        QueryValue::Float(f)
        | QueryValue::Normalized(f)
        | QueryValue::Truncated(f)
        | QueryValue::Saturated(f) => number(f64::from(f)),
        QueryValue::NormalizedDouble(d) => number(d),
    }
}

/// A float in at most 4 significant decimals (scientific below 10⁻³).
fn number(x: f64) -> String {
    if x != 0.0 && x.abs() < 1e-3 {
        format!("{x:.3e}")
    } else {
        crate::vocab::short(x)
    }
}

/// The token of an enum a query answered. Values are shared between tokens (0 is ZERO,
/// NONE and FALSE; 1 is ONE), so the model's own tables decide first — the enums whose
/// values glGet answers with — then the registry's name without an extension suffix.
fn enum_name(value: u32, pname: u32) -> String {
    if pname == r::DRAW_BUFFER || pname == r::READ_BUFFER {
        if let Some(n) =
            crate::ff::framebuffer::ColorBuffer::from_gl_value(value).and_then(GlEnum::gl_name)
        {
            return n.to_string();
        }
    }
    if let Some(i) = Family::Texture.from_value(value) {
        return Family::Texture.print(i);
    }
    let model = [
        name_in::<BlendFactor>(value),
        name_in::<StencilOp>(value),
        name_in::<CompareFunc>(value),
        name_in::<BlendEquation>(value),
        name_in::<TexEnvMode>(value),
        name_in::<CombineFunc>(value),
        name_in::<CombineSource>(value),
        name_in::<CombineOperand>(value),
        name_in::<TexGenMode>(value),
        name_in::<Filter>(value),
        name_in::<Wrap>(value),
        name_in::<CompareMode>(value),
        name_in::<DepthTextureMode>(value),
        name_in::<TexFormat>(value),
        name_in::<MatrixMode>(value),
        name_in::<ShadeModel>(value),
    ];
    if let Some(n) = model.into_iter().flatten().next() {
        return n.to_string();
    }
    let names = r::BY_NAME
        .iter()
        .filter(|(_, v)| *v == value)
        .map(|(n, _)| *n);
    let suffixed = |n: &&str| {
        ["_ARB", "_EXT", "_NV", "_SGIX", "_SGIS", "_OES"]
            .iter()
            .any(|s| n.ends_with(s))
    };
    let mut all: Vec<&str> = names.collect();
    all.sort_by_key(|n| (suffixed(n), n.len()));
    all.first()
        .map_or_else(|| format!("{value:#06X}"), |n| (*n).to_string())
}

fn name_in<T: GlEnum>(value: u32) -> Option<&'static str> {
    T::from_gl_value(value).and_then(GlEnum::gl_name)
}

/// Applies a pass's commands to `state`, and returns the state its draws see, consecutive
/// draws with the same rows as one entry (or, for a pass without draws, the state it
/// leaves). `at_draw` sees the state at every draw (for the shader keys).
pub fn pass_states(
    state: &mut FixedState,
    commands: &[Command],
    at_draw: &mut dyn FnMut(&FixedState),
) -> Vec<PassState> {
    let mut out: Vec<PassState> = Vec::new();
    let mut draw = 0;
    for cmd in commands {
        // A command GL refuses changes nothing; the plans raise none.
        let _ = state.apply(cmd);
        if !matches!(cmd, Command::Draw(_)) {
            continue;
        }
        at_draw(state);
        let rows = state_rows(state);
        match out.last_mut() {
            Some(PassState {
                draws: Some((_, last)),
                rows: previous,
            }) if *previous == rows => *last = draw,
            _ => out.push(PassState {
                draws: Some((draw, draw)),
                rows,
            }),
        }
        draw += 1;
    }
    if out.is_empty() {
        out.push(PassState {
            draws: None,
            rows: state_rows(state),
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::techniques::{technique, Prepared};
    use crate::vocab::{Named, PlanarMode, Projector};

    /// The default scene with `id` and each of its variants that changes the plan's shape.
    fn scenes(id: TechniqueId) -> Vec<Scene> {
        // Occluder planes need an object that declares planes: the F-35 scene.
        let mut base = match id {
            TechniqueId::OccluderPlanes => {
                let path = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/f35.toml");
                Scene::load(std::path::Path::new(path)).expect("assets/f35.toml loads")
            }
            _ => Scene::default_scene(),
        };
        base.image.width = 64;
        base.image.height = 64;
        base.shadow.map_size = 64;
        base.shadow.technique = id;
        if matches!(id, TechniqueId::Accumulate | TechniqueId::OcclusionTextures) {
            // Its light is a rectangle: the spot light's place, 2 × 2.
            let light = &mut base.lights[0];
            light.kind = crate::scene::LightKind::Area {
                corner: light.view.eye - glam::Vec3::new(1.0, 0.0, 1.0),
                edge_u: glam::Vec3::X * 2.0,
                edge_v: glam::Vec3::Z * 2.0,
            };
            base.shadow.light_samples = 2;
        }
        let mut stencil = base.clone();
        stencil.shadow.planar_mode = PlanarMode::Stencil;
        let mut perspective = base.clone();
        perspective.shadow.projector = Projector::Perspective;
        vec![base, stencil, perspective]
    }

    /// Every pass every technique's plan makes has a paragraph, and every paragraph belongs
    /// to a pass some plan makes: a new pass cannot go unexplained.
    #[test]
    fn every_pass_of_every_plan_has_a_note_and_every_note_a_pass() {
        for id in TechniqueId::all() {
            let mut made: Vec<&str> = Vec::new();
            for scene in scenes(id) {
                let prepared = Prepared::new(&scene);
                let plan = (technique(id).plan)(&scene, &prepared)
                    .unwrap_or_else(|e| panic!("{}: {e}", id.name()));
                for pass in plan.maps.iter().chain(&plan.passes) {
                    assert!(
                        pass_note(id, pass.name).is_some(),
                        "{}: pass `{}` has no note in techniques::explain",
                        id.name(),
                        pass.name
                    );
                    made.push(pass.name);
                }
            }
            for (name, note) in pass_notes(id) {
                assert!(
                    made.contains(name),
                    "{}: a note for `{name}`, a pass no plan makes",
                    id.name()
                );
                assert!(note.len() > 80, "{}: `{name}`'s note is a stub", id.name());
            }
            assert!(
                overview(id).contains(&format!("`{}`", id.name())),
                "{}'s overview is not its module note:\n{}",
                id.name(),
                overview(id)
            );
        }
    }

    #[test]
    fn links_become_code() {
        assert_eq!(
            unlink("see [`super::plane`] and [`Plan::notes`](x) and [a]."),
            "see `super::plane` and `Plan::notes` and [a]."
        );
    }

    /// A fresh state has no rows; each change is one row in GL's names, with GL's values.
    #[test]
    fn rows_are_what_differs_from_a_fresh_context() {
        let mut s = FixedState::new();
        assert_eq!(state_rows(&s), Vec::new());
        for c in [
            Command::DepthFunc(CompareFunc::Equal),
            Command::Enable(Capability::AlphaTest),
            Command::AlphaFunc {
                func: CompareFunc::Greater,
                reference: 0.5,
            },
            Command::BlendFunc {
                src: BlendFactor::One,
                dst: BlendFactor::One,
            },
            Command::ActiveTexture(1),
            Command::Enable(Capability::Texture1D),
            Command::TexEnv(crate::ff::TexEnvParam::Mode(TexEnvMode::Combine)),
            Command::TexEnv(crate::ff::TexEnvParam::CombineAlpha(CombineFunc::AddSigned)),
            Command::Enable(Capability::Light(0)),
        ] {
            s.apply(&c).unwrap();
        }
        let rows = state_rows(&s);
        let find = |group: &str, name: &str| {
            rows.iter()
                .find(|r| r.group == group && r.name == name)
                .map(|r| r.value.as_str())
        };
        assert_eq!(find("", "GL_DEPTH_FUNC"), Some("GL_EQUAL"));
        assert_eq!(find("", "GL_ALPHA_TEST"), Some("GL_TRUE"));
        assert_eq!(find("", "GL_ALPHA_TEST_FUNC"), Some("GL_GREATER"));
        assert_eq!(find("", "GL_ALPHA_TEST_REF"), Some("0.5"));
        assert_eq!(find("", "GL_BLEND_DST"), Some("GL_ONE"));
        assert_eq!(find("", "GL_ACTIVE_TEXTURE"), Some("GL_TEXTURE1"));
        assert_eq!(find("", "GL_LIGHT0"), Some("GL_TRUE"));
        assert_eq!(find("unit 1", "GL_TEXTURE_1D"), Some("GL_TRUE"));
        assert_eq!(find("unit 1", "GL_TEXTURE_ENV_MODE"), Some("GL_COMBINE"));
        assert_eq!(find("unit 1", "GL_COMBINE_ALPHA"), Some("GL_ADD_SIGNED"));
        // Unchanged state and other units: no rows.
        assert_eq!(find("", "GL_BLEND_SRC"), None);
        assert_eq!(find("unit 0", "GL_TEXTURE_1D"), None);
        assert_eq!(rows.len(), 10, "{rows:#?}");
    }

    /// dual8's figures on the default scene: its quantisation and its default bias of
    /// three 8-bit steps, which is enough; `--offset 1,4` is not.
    #[test]
    fn dual8_figures_give_the_steps() {
        let mut scene = Scene::default_scene();
        scene.shadow.technique = TechniqueId::Dual8;
        let text = |scene: &Scene| {
            figures(scene)
                .iter()
                .map(|f| format!("{}: {}\n", f.name, f.value))
                .collect::<String>()
        };
        let given = text(&scene);
        assert!(
            given.contains("M = ⌊255·z⌋") && given.contains("F = ⌊256·r/q⌋"),
            "{given}"
        );
        assert!(
            given.contains("3 8-bit steps from the units, enough"),
            "{given}"
        );
        scene.shadow.polygon_offset =
            crate::scene::OffsetSetting::command_line(Some(crate::vocab::PolygonOffset {
                factor: 1.0,
                units: 4.0,
            }));
        let slide = text(&scene);
        assert!(
            slide.contains("0.0001 8-bit steps from the units, not enough"),
            "{slide}"
        );
    }

    /// A pass's draws with the same state are one entry; a pass without draws reports the
    /// state it leaves.
    #[test]
    fn draws_with_the_same_state_share_an_entry() {
        let g = std::sync::Arc::new(crate::ff::Geometry::new(
            crate::ff::Primitive::Triangles,
            vec![glam::Vec4::W; 3],
        ));
        let commands = [
            Command::Draw(g.clone()),
            Command::Translate(glam::Vec3::X),
            Command::Draw(g.clone()),
            Command::Enable(Capability::Blend),
            Command::Draw(g),
        ];
        let mut s = FixedState::new();
        let mut seen = 0;
        let states = pass_states(&mut s, &commands, &mut |_| seen += 1);
        assert_eq!(seen, 3);
        assert_eq!(states.len(), 2, "{states:#?}");
        assert_eq!(states[0].draws, Some((0, 1)));
        assert_eq!(states[1].draws, Some((2, 2)));
        let none = pass_states(&mut s, &[Command::Disable(Capability::Blend)], &mut |_| {});
        assert_eq!(none[0].draws, None);
    }
}
