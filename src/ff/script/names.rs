//! The script's side of GL token names: the ranking of names in errors. The indexed
//! families (GL_LIGHTi, GL_TEXTUREi, GL_COMBINERi_NV) are `ff::glenum::Family`. The enum tables are `ff::glenum`'s and the calls
//! `ff::api`'s, shared with both pipelines.

pub use crate::ff::glenum::{Family, GlEnum};

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
