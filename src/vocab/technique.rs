//! Which shadow technique: the names scene files and `--technique` use.

use super::Named;

/// A shadow technique of `techniques::REGISTRY`.
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
    ];
}

impl std::fmt::Display for TechniqueId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}
