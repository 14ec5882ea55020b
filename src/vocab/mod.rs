//! The project's shared vocabulary: the small named values every layer speaks of — which
//! technique, which pipeline, how many depth bits, how a depth readback becomes integers,
//! the polygon offset — defined once, here, at the bottom of the layer order. It depends
//! on nothing of the crate and on no front end: the command line's value parsers and the
//! scene reader both read the names through [`Named`], so the spelling a user types lives
//! next to the value it means and nowhere else.

mod bias;
mod depth;
mod settings;
mod submission;
mod technique;

pub use bias::{default_offset, offset_text, OffsetSource};
pub use depth::{short, DepthBits, DepthRule, ReadbackRule};
pub use settings::{
    BadOffset, MapFilter, OffsetArg, PipelineKind, PlanarMode, PolygonOffset, Precision, Projector,
};
pub use submission::Submission;
pub use technique::TechniqueId;

/// A value with user-facing names: the first name of a value is the one printed, later
/// ones are accepted aliases.
pub trait Named: Copy + PartialEq + Sized + 'static {
    /// Every value with its name, in the order help texts list them.
    const NAMES: &'static [(&'static str, Self)];

    /// One line on what the value means, for help texts.
    fn help(self) -> &'static str {
        ""
    }

    /// The printed name. Cannot fail for a value of the type: each `Named` impl lists every
    /// variant of its enum in NAMES beside the enum (no input builds a value, only code).
    fn name(self) -> &'static str {
        Self::NAMES
            .iter()
            .find(|(_, v)| *v == self)
            .map(|(n, _)| *n)
            .expect("every value of a Named type has a name")
    }

    /// The value a name means, if any.
    fn from_name(name: &str) -> Option<Self> {
        Self::NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, v)| *v)
    }

    /// Every value once, in order (aliases skipped).
    fn all() -> Vec<Self> {
        let mut out: Vec<Self> = Vec::new();
        for (_, v) in Self::NAMES {
            if !out.contains(v) {
                out.push(*v);
            }
        }
        out
    }

    /// The printed names, in order.
    fn names() -> Vec<&'static str> {
        Self::all().into_iter().map(Self::name).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each spelling a scene file reads (serde) is the name the command line reads (Named).
    fn serde_agrees<T: Named + serde::de::DeserializeOwned + std::fmt::Debug>() {
        for v in T::all() {
            let parsed: T = serde_json::from_str(&format!("\"{}\"", v.name()))
                .unwrap_or_else(|e| panic!("{} does not deserialize: {e}", v.name()));
            assert_eq!(parsed, v);
        }
    }

    #[test]
    fn scene_spellings_are_the_named_ones() {
        serde_agrees::<Precision>();
        serde_agrees::<MapFilter>();
        serde_agrees::<PlanarMode>();
        serde_agrees::<Projector>();
        serde_agrees::<ReadbackRule>();
        serde_agrees::<Submission>();
    }

    #[test]
    fn names_round_trip() {
        fn check<T: Named + std::fmt::Debug>() {
            for v in T::all() {
                assert_eq!(T::from_name(v.name()), Some(v));
            }
        }
        check::<TechniqueId>();
        check::<PipelineKind>();
        check::<DepthBits>();
        check::<ReadbackRule>();
        check::<Precision>();
        check::<MapFilter>();
        check::<PlanarMode>();
        check::<Projector>();
        check::<Submission>();
        assert_eq!(DepthBits::from_name("32f"), Some(DepthBits::D32F));
        assert_eq!(TechniqueId::from_name("dual9"), None);
    }
}
