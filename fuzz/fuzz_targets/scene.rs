//! Scene TOML: `Scene::parse` on any text. The property: no panic, no abort, no hang; an
//! error is an `Err` whose message is not empty and, when the error has a location, whose
//! Display names that file:line:col, the line one that exists in the text.
//!
//! The scene is read as if from `assets/`, so `mesh = "pyramid.obj"` loads the OBJ there;
//! texts naming the device and process file systems are skipped, since `/dev/zero` is a
//! file that never ends, not a parser input. The scene is held to a triangle budget of one
//! million (the default's 20 million is a 6 GiB scene, beyond the fuzzer's 2 GB per input):
//! what is over it must be refused by the count, before any mesh is built.

#![no_main]

use fixedfunc::scene::{Limits, Scene};
use libfuzzer_sys::fuzz_target;
use std::path::Path;

const ORIGIN: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../assets/fuzz.toml");

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if ["/dev", "/proc", "/sys"].iter().any(|p| text.contains(p)) {
        return;
    }
    let limits = Limits {
        max_triangles: 1_000_000,
        ..Limits::default()
    };
    match Scene::parse_with(&text, Path::new(ORIGIN), limits) {
        Ok(scene) => {
            for warning in &scene.warnings {
                assert!(!warning.to_string().is_empty());
            }
        }
        Err(e) => {
            let message = e.to_string();
            assert!(!message.trim().is_empty(), "empty message for {e:?}");
            if let Some(at) = e.location() {
                let place = format!("{ORIGIN}:{}:{}", at.line, at.col);
                assert!(
                    message.contains(&place),
                    "`{message}` does not name {place}"
                );
                let lines = text.matches('\n').count() + 1;
                assert!(
                    (1..=lines).contains(&at.line) && at.col >= 1,
                    "{place} is outside the {lines} lines of the text"
                );
            }
        }
    }
});
