//! How a program hands its objects' vertices to GL — the three doors of GL 1.5: immediate
//! mode (§2.6: glBegin, one call per attribute per vertex, glEnd), display lists (§5.4: the
//! same calls compiled once, replayed by glCallList) and buffer objects (§2.9: the arrays
//! stored once on the server). `render` submits a session's object draws by one of them
//! (`RenderOptions::submission`); `bench --only coleman` times the three.

use serde::{Deserialize, Serialize};

use super::Named;

/// Which door a session's object draws go through.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Deserialize, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Submission {
    /// glBegin, the vertex-attribute calls of every vertex, glEnd, every draw of every
    /// frame: the vertices cross the API one call at a time and are uploaded again.
    Immediate,
    /// Each object's immediate-mode calls compiled once into a display list (glNewList
    /// … GL_COMPILE … glEndList); each draw is one glCallList.
    DisplayList,
    /// The arrays uploaded once into buffers and drawn from there (the layer's own draws).
    #[default]
    Buffers,
}

impl Named for Submission {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("immediate", Submission::Immediate),
        ("display-list", Submission::DisplayList),
        ("buffers", Submission::Buffers),
        ("lists", Submission::DisplayList),
    ];

    fn help(self) -> &'static str {
        match self {
            Submission::Immediate => "glBegin, a call per attribute per vertex, glEnd, every draw",
            Submission::DisplayList => "a display list compiled once, glCallList each draw",
            Submission::Buffers => "arrays uploaded once into buffers, drawn from there",
        }
    }
}

impl std::fmt::Display for Submission {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}
