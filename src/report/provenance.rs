//! What produced a report: the fixedfunc version, the command line, and the GL renderer
//! and version strings of each context the rows ran on — so that a `results.json`, a
//! `results.csv` or a page read later says where its numbers came from.

use serde::Serialize;

use crate::render::pipeline_name;

use super::ResultRow;

/// The program and command behind a report.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Provenance {
    /// This crate's version (Cargo.toml).
    pub fixedfunc_version: &'static str,
    /// The command line as the shell would take it back (arguments with spaces or quotes
    /// in single quotes).
    pub command_line: String,
}

impl Provenance {
    /// This process's version and command line.
    pub fn of_this_process() -> Provenance {
        Provenance {
            fixedfunc_version: env!("CARGO_PKG_VERSION"),
            command_line: std::env::args()
                .map(|a| shell_word(&a))
                .collect::<Vec<_>>()
                .join(" "),
        }
    }
}

/// `a` as one shell word: as it is when it holds only safe characters, else in single
/// quotes (a quote inside written '\'').
pub fn shell_word(a: &str) -> String {
    let safe = |c: char| c.is_ascii_alphanumeric() || "-_./,:=+%@".contains(c);
    if !a.is_empty() && a.chars().all(safe) {
        a.to_string()
    } else {
        format!("'{}'", a.replace('\'', r"'\''"))
    }
}

/// One context the rows ran on.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct ContextStrings {
    pub backend: &'static str,
    pub pipeline: &'static str,
    pub renderer: String,
    pub version: String,
}

/// The distinct contexts of the measured rows, in row order.
pub fn contexts(rows: &[ResultRow]) -> Vec<ContextStrings> {
    let mut out: Vec<ContextStrings> = Vec::new();
    for r in rows {
        let Some(m) = &r.measured else { continue };
        let c = ContextStrings {
            backend: r.backend.name(),
            pipeline: pipeline_name(r.pipeline),
            renderer: m.gl_renderer.clone(),
            version: m.gl_version.clone(),
        };
        if !out.contains(&c) {
            out.push(c);
        }
    }
    out
}

/// The page's lines on what produced it, as (what, value).
pub fn facts(p: &Provenance, contexts: &[ContextStrings]) -> Vec<(String, String)> {
    let mut facts = vec![(
        "produced by".to_string(),
        format!("fixedfunc {}: {}", p.fixedfunc_version, p.command_line),
    )];
    for c in contexts {
        facts.push((
            format!("GL ({}, {})", c.backend, c.pipeline),
            format!("{} · {}", c.renderer, c.version),
        ));
    }
    facts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_with_spaces_or_quotes_are_quoted_as_a_shell_takes_them_back() {
        assert_eq!(shell_word("--offset"), "--offset");
        assert_eq!(shell_word("1,4"), "1,4");
        assert_eq!(shell_word("my scene.toml"), "'my scene.toml'");
        assert_eq!(shell_word("it's"), r"'it'\''s'");
        assert_eq!(shell_word(""), "''");
    }
}
