//! Which shadow technique: the names scene files and `--technique` use. The scene reader
//! parses `[shadow] technique` into a [`TechniqueId`], and `techniques::technique` maps each
//! id to its plan with an exhaustive match, so a new technique is one variant here, one
//! name below and one arm there — the compiler finds a missing arm.

use super::Named;

/// A shadow technique (its plan: `techniques::technique`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum TechniqueId {
    None,
    DepthCompare,
    Dual8,
    Linear8,
    Multidigit16,
    Multidigit16Combine,
    Planar,
    Projective,
    Accumulate,
    OccluderPlanes,
    OcclusionTextures,
}

impl Named for TechniqueId {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("none", TechniqueId::None),
        ("depth-compare", TechniqueId::DepthCompare),
        ("dual8", TechniqueId::Dual8),
        ("linear8", TechniqueId::Linear8),
        ("multidigit16", TechniqueId::Multidigit16),
        ("multidigit16-combine", TechniqueId::Multidigit16Combine),
        ("planar", TechniqueId::Planar),
        ("projective", TechniqueId::Projective),
        ("accumulate", TechniqueId::Accumulate),
        ("occluder-planes", TechniqueId::OccluderPlanes),
        ("occlusion-textures", TechniqueId::OcclusionTextures),
    ];
}

impl TechniqueId {
    /// Whether the light pass of the technique reads the polygon offset (the shadow-map
    /// techniques; `planar` keeps its shadow off the receiver by its own means).
    pub fn uses_offset(self) -> bool {
        matches!(
            self,
            TechniqueId::DepthCompare
                | TechniqueId::Accumulate
                | TechniqueId::Dual8
                | TechniqueId::Linear8
                | TechniqueId::Multidigit16
                | TechniqueId::Multidigit16Combine
        )
    }
}

impl std::fmt::Display for TechniqueId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // `pad`, so that widths and alignment (`{:<22}`) apply as they do to the name.
        f.pad(self.name())
    }
}

/// Serialised as its name (`"depth-compare"`), as tables and JSON print it.
impl serde::Serialize for TechniqueId {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.name())
    }
}
