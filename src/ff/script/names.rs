//! The script's side of GL token names: the indexed families (GL_LIGHTi, GL_TEXTUREi,
//! GL_COMBINERi_NV, GL_CLIP_PLANEi, with `GL_LIGHT0 + n` beyond the named tokens, as C allows) and the
//! ranking of names in errors. The enum tables are `ff::glenum`'s and the calls
//! `ff::api`'s, shared with both pipelines.

pub use crate::ff::glenum::GlEnum;

/// Indexed token families: `GL_LIGHT0`…, `GL_TEXTURE0`…, `GL_COMBINER0_NV`….
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    Light,
    Texture,
    Combiner,
    ClipPlane,
}

impl Family {
    /// (prefix, suffix, number of named tokens).
    fn parts(self) -> (&'static str, &'static str, u32) {
        match self {
            Family::Light => ("GL_LIGHT", "", 8),
            Family::Texture => ("GL_TEXTURE", "", 32),
            Family::Combiner => ("GL_COMBINER", "_NV", 8),
            Family::ClipPlane => ("GL_CLIP_PLANE", "", 6),
        }
    }

    /// `GL_TEXTURE3` (+ offset) → 3 (+ offset). Accepts the `_ARB` spelling of TEXTUREi.
    pub fn parse(self, name: &str, offset: u32) -> Option<u8> {
        let (prefix, suffix, count) = self.parts();
        let rest = name.strip_prefix(prefix)?;
        let digits = match self {
            Family::Texture => rest.strip_suffix("_ARB").unwrap_or(rest),
            _ => rest.strip_suffix(suffix)?,
        };
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        let i: u32 = digits.parse().ok().filter(|i| *i < count)?;
        u8::try_from(i.checked_add(offset)?).ok()
    }

    /// The token for index `i`: `GL_LIGHT2`, or `GL_LIGHT0 + 9` beyond the named ones.
    pub fn print(self, i: u8) -> String {
        let (prefix, suffix, count) = self.parts();
        if u32::from(i) < count {
            format!("{prefix}{i}{suffix}")
        } else {
            format!("{prefix}0{suffix} + {i}")
        }
    }

    pub fn example(self) -> &'static str {
        match self {
            Family::Light => "GL_LIGHT0..GL_LIGHT7",
            Family::Texture => "GL_TEXTURE0..GL_TEXTURE31",
            Family::Combiner => "GL_COMBINER0_NV..GL_COMBINER7_NV",
            Family::ClipPlane => "GL_CLIP_PLANE0..GL_CLIP_PLANE5",
        }
    }
}

/// Levenshtein distance, to list the closest names first in errors.
pub fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != *cb);
            cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}

/// `names`, closest to `found` first (stable for ties), without duplicates.
pub fn ranked(found: &str, names: &[&'static str]) -> Vec<&'static str> {
    // A name longer than any GL token ranks the same by its first 64 characters; the cap
    // keeps an error about a 10,000-character identifier as cheap as any other.
    let found: String = found.chars().take(64).collect();
    let mut seen = std::collections::HashSet::new();
    let mut v: Vec<&'static str> = names.iter().copied().filter(|n| seen.insert(*n)).collect();
    v.sort_by_cached_key(|n| distance(&found, n));
    v
}
