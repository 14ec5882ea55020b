//! Programs cached by key. The cache stores the `Result`, so a key whose program fails to
//! compile fails once and is never rebuilt; the number of compiles is a figure the renders
//! and benchmarks report ("zero compiles after the first frame"). The last key asked for
//! is kept beside its entry: consecutive draws of one state compare keys instead of
//! hashing one (SipHash of a `ShaderKey` is ~2,000 instructions a draw, its comparison a
//! few hundred).

use std::collections::HashMap;
use std::hash::Hash;
use std::rc::Rc;

use super::super::error::ShaderError;

/// Programs by key, with a count of builds.
pub struct ProgramCache<K, P> {
    entries: HashMap<K, Result<Rc<P>, ShaderError>>,
    last: Option<(K, Result<Rc<P>, ShaderError>)>,
    compiles: usize,
}

impl<K: Hash + Eq + Clone, P> Default for ProgramCache<K, P> {
    fn default() -> Self {
        ProgramCache {
            entries: HashMap::new(),
            last: None,
            compiles: 0,
        }
    }
}

impl<K: Hash + Eq + Clone, P> ProgramCache<K, P> {
    /// The program for `key`, built by `build` the first time the key is seen.
    pub fn get_or_build(
        &mut self,
        key: &K,
        build: impl FnOnce(&K) -> Result<P, ShaderError>,
    ) -> Result<Rc<P>, ShaderError> {
        if let Some((last, entry)) = &self.last {
            if last == key {
                return entry.clone();
            }
        }
        let entry = match self.entries.get(key) {
            Some(entry) => entry.clone(),
            None => {
                self.compiles += 1;
                let entry = build(key).map(Rc::new);
                self.entries.insert(key.clone(), entry.clone());
                entry
            }
        };
        self.last = Some((key.clone(), entry.clone()));
        entry
    }

    /// How many programs were built (successfully or not).
    pub fn compiles(&self) -> usize {
        self.compiles
    }

    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// Every successfully built program, for deletion.
    pub fn drain(&mut self) -> impl Iterator<Item = Rc<P>> + '_ {
        self.last = None;
        self.entries.drain().filter_map(|(_, v)| v.ok())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::error::ShaderStage;

    #[test]
    fn builds_once_per_key_and_remembers_failures() {
        let mut cache: ProgramCache<u32, String> = ProgramCache::default();
        let mut builds = 0;
        for _ in 0..3 {
            let p = cache.get_or_build(&1, |k| {
                builds += 1;
                Ok(format!("program {k}"))
            });
            assert_eq!(p.as_deref().map(String::as_str), Ok("program 1"));
        }
        for _ in 0..2 {
            let e = cache.get_or_build(&2, |_| {
                Err(ShaderError {
                    stage: ShaderStage::Fragment,
                    key: "2".into(),
                    glsl: String::new(),
                    log: "bad".into(),
                })
            });
            assert!(e.is_err());
        }
        assert_eq!(builds, 1);
        assert_eq!(cache.compiles(), 2);
        assert_eq!(cache.len(), 2);
    }
}
