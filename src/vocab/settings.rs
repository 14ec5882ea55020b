//! The settings a render is made with: which path runs the commands, in which precision,
//! the light pass's polygon offset, how a map is filtered, and the projection techniques'
//! choices. Scene files (serde) and the command line (through [`Named`]) read the same
//! names; a test in `vocab` checks that they agree.

use serde::{Deserialize, Serialize};

use super::Named;

/// Which path executes the Commands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum PipelineKind {
    /// Generated GLSL on a core 3.3 context.
    Emulate,
    /// Mesa's own fixed-function path on a compatibility context.
    Native,
}

impl Named for PipelineKind {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("emulate", PipelineKind::Emulate),
        ("native", PipelineKind::Native),
    ];

    fn help(self) -> &'static str {
        match self {
            PipelineKind::Emulate => "generated GLSL on a core 3.3 context",
            PipelineKind::Native => "Mesa's own fixed-function path on a compatibility context",
        }
    }
}

/// How the texture and combiner stages compute.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Precision {
    /// fp32, as Mesa's native fixed-function path does on llvmpipe.
    #[default]
    Float,
    /// 8-bit integer stages, 9-bit signed register combiners.
    Fixed8,
}

impl Named for Precision {
    const NAMES: &'static [(&'static str, Self)] =
        &[("float", Precision::Float), ("fixed8", Precision::Fixed8)];

    fn help(self) -> &'static str {
        match self {
            Precision::Float => "fp32, as Mesa's native fixed-function path does on llvmpipe",
            Precision::Fixed8 => "8-bit integer stages, 9-bit signed register combiners",
        }
    }
}

/// glPolygonOffset: o = m·factor + r·units, m = max(|∂z/∂x|, |∂z/∂y|) on llvmpipe (the spec
/// allows up to the Euclidean norm), r the minimum resolvable difference. GL default: 0, 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PolygonOffset {
    pub factor: f32,
    pub units: f32,
}

/// A polygon offset as the command line writes it (`--offset`): `FACTOR,UNITS`, two finite
/// numbers, or `none` (any case) for no offset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OffsetArg {
    None,
    Offset(PolygonOffset),
}

/// Text that is neither `FACTOR,UNITS` nor `none`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("`{text}`: expected FACTOR,UNITS (two finite numbers, e.g. 1,4) or none")]
pub struct BadOffset {
    pub text: String,
}

impl std::str::FromStr for OffsetArg {
    type Err = BadOffset;

    fn from_str(text: &str) -> Result<OffsetArg, BadOffset> {
        if text.eq_ignore_ascii_case("none") {
            return Ok(OffsetArg::None);
        }
        let bad = || BadOffset {
            text: text.to_string(),
        };
        let (f, u) = text.split_once(',').ok_or_else(bad)?;
        let factor: f32 = f.trim().parse().map_err(|_| bad())?;
        let units: f32 = u.trim().parse().map_err(|_| bad())?;
        if !(factor.is_finite() && units.is_finite()) {
            return Err(bad());
        }
        Ok(OffsetArg::Offset(PolygonOffset { factor, units }))
    }
}

/// How a shadow map is sampled (GL_TEXTURE_MIN/MAG_FILTER of the map).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum MapFilter {
    /// One texel per lookup: hard, blocky edges.
    #[default]
    Nearest,
    /// LINEAR: on a depth texture with compare on, the era's hardware percentage-closer
    /// filter (four compares blended bilinearly); on an 8-bit map, interpolated depths.
    Linear,
}

impl Named for MapFilter {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("nearest", MapFilter::Nearest),
        ("linear", MapFilter::Linear),
    ];

    fn help(self) -> &'static str {
        match self {
            MapFilter::Nearest => "one texel per lookup: hard, blocky edges",
            MapFilter::Linear => "percentage-closer filtering on a compared depth texture",
        }
    }
}

/// How planar projection shadows keep off the receiver's depth (`[shadow] planar_mode`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum PlanarMode {
    /// Dinoshade's way: the projected shadow is depth-tested, pulled towards the eye by
    /// glPolygonOffset so it wins against the coplanar receiver; the stencil marks
    /// receivers and stops a second blend.
    #[default]
    Offset,
    /// Stencil alone: every object writes its receiver number (0 for the rest) where it is
    /// visible, and the shadow is drawn with the depth test off where the number matches —
    /// the shadow lies in the receiver's plane, so the visible receiver is the right depth.
    Stencil,
}

impl Named for PlanarMode {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("offset", PlanarMode::Offset),
        ("stencil", PlanarMode::Stencil),
    ];

    fn help(self) -> &'static str {
        match self {
            PlanarMode::Offset => "depth-tested shadow pulled forward by polygon offset",
            PlanarMode::Stencil => "receiver numbers in the stencil, shadow without depth test",
        }
    }
}

/// What the slide projector projects from (`[shadow] projector`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Deserialize, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Projector {
    /// The light's own frustum (its `fovy`, `near`, `far`): casters below the receivers'
    /// plane still cast.
    Perspective,
    /// The lecture notes' construction: the casters flattened onto the largest flat
    /// receiver by the shadow matrix, with the pseudo-depth s = (p·l)/(p·l − p·x) kept in
    /// [1, ∞) by an orthographic near 1, far "at infinity": casters below that plane or
    /// beyond the light are clipped away.
    #[default]
    PseudoDepth,
}

impl Named for Projector {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("perspective", Projector::Perspective),
        ("pseudo-depth", Projector::PseudoDepth),
    ];

    fn help(self) -> &'static str {
        match self {
            Projector::Perspective => "the light's own frustum",
            Projector::PseudoDepth => "the shadow matrix's pseudo-depth, clipping false shadows",
        }
    }
}
