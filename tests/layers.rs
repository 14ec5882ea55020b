//! The layer order of `src/lib.rs`, checked on the sources: no module names a module above
//! it (`crate::X` or `fixedfunc::X` in code, comments excluded). Modules on one rung (`bench`
//! and `study`; `vocab` and `stats`) may not use each other either.

use std::fs;
use std::path::{Path, PathBuf};

/// Lowest first; modules on one rung share a number.
const LAYERS: &[(&str, u32)] = &[
    ("vocab", 0),
    ("stats", 0),
    ("shaders", 0),
    ("gpu", 1),
    ("ff", 2),
    ("mesh", 3),
    ("scene", 4),
    ("metrics", 5),
    ("truth", 6),
    ("pipeline", 7),
    ("abi", 8),
    ("techniques", 8),
    ("render", 9),
    ("bench", 10),
    ("study", 10),
    ("report", 11),
    ("view", 12),
    ("cli", 13),
];

fn rank(module: &str) -> Option<u32> {
    LAYERS.iter().find(|(m, _)| *m == module).map(|(_, r)| *r)
}

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).expect("src is readable").flatten() {
        let path = entry.path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The modules `code` names as `crate::X` or `fixedfunc::X`.
fn named_modules(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    for line in code.lines() {
        let line = line.split("//").next().unwrap_or("");
        for prefix in ["crate::", "fixedfunc::"] {
            let mut rest = line;
            while let Some(i) = rest.find(prefix) {
                let after = &rest[i + prefix.len()..];
                let name: String = after
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                // `fixedfunc::` also names the binary; only module paths count.
                let boundary = i == 0 || !rest.as_bytes()[i - 1].is_ascii_alphanumeric();
                if boundary && !name.is_empty() {
                    out.push(name);
                }
                rest = after;
            }
        }
    }
    out
}

#[test]
fn no_import_runs_up_the_layer_order() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    let mut upward = Vec::new();
    for file in &files {
        let rel = file.strip_prefix(&src).expect("under src");
        let first = rel
            .components()
            .next()
            .and_then(|c| c.as_os_str().to_str())
            .unwrap_or("");
        let module = first.trim_end_matches(".rs");
        let Some(own) = rank(module) else {
            continue; // lib.rs, main.rs
        };
        let code = fs::read_to_string(file).expect("source is readable");
        for named in named_modules(&code) {
            if let Some(other) = rank(&named) {
                if named != module && other >= own {
                    upward.push(format!("{} uses {named}", rel.display()));
                }
            }
        }
    }
    upward.sort();
    upward.dedup();
    assert!(
        upward.is_empty(),
        "imports up (or across) the layer order:\n{}",
        upward.join("\n")
    );
}

#[test]
fn every_module_has_a_layer() {
    let lib = fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("src/lib.rs"))
        .expect("lib.rs");
    for line in lib.lines() {
        if let Some(name) = line.strip_prefix("pub mod ") {
            let name = name.trim_end_matches(';');
            assert!(rank(name).is_some(), "module {name} is missing from LAYERS");
        }
    }
}
