//! Commands as text, in the era's own syntax: one GL call per line, valid C99.
//!
//! A script is the body of a C function (compiled with <GL/gl.h>, <GL/glext.h> under
//! GL_GLEXT_PROTOTYPES, <math.h> and <stddef.h>): `glTexGenfv(GL_S, GL_EYE_PLANE,
//! (GLfloat[]){1, 0, 0, 0});`. Arrays are compound literals: `(GLfloat[])` for vectors and
//! matrices; pixel data is a `GLubyte`, `GLushort`, `GLuint` or `GLfloat` array whose element type
//! fixes how its values become bytes (little-endian), or `NULL`. `glBegin … glEnd` with
//! glVertex/glColor/glNormal/glTexCoord/glMultiTexCoord folds into one `Command::Draw`; an
//! attribute called inside the pair becomes a per-vertex array (vertices before its first call
//! take the value current at glBegin). `glReadPixels` writes to `readback_<n>`, a name the
//! harness declares by convention (`static unsigned char readback_0[…];`), which is
//! `ReadPixels::slot = n`. Indices beyond the named tokens print as `GL_LIGHT0 + 9`.
//!
//! [`print`] is the inverse of [`parse`]: `parse(&print(cmds)) == cmds` for every command list
//! (indexed geometry prints as client arrays and glDrawElements; vertices no index names
//! are dropped).

mod lexer;
pub mod names;
mod parse;
mod print;
mod print_pixels;

pub use parse::{parse, parse_lines};
pub use print::{print, print_aligned};

/// A script error, with the line and the valid alternatives where there are any.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ScriptError {
    #[error("line {line}: unexpected character {ch:?}")]
    UnexpectedChar { line: usize, ch: char },
    #[error("line {line}: unterminated /* comment")]
    UnterminatedComment { line: usize },
    #[error("line {line}: {problem}")]
    Preprocessor { line: usize, problem: String },
    #[error("line {line}: expected {expected}, found {found}")]
    Syntax {
        line: usize,
        expected: &'static str,
        found: String,
    },
    #[error(
        "line {line}: unknown call {name}; closest known: {}",
        closest(expected)
    )]
    UnknownCall {
        line: usize,
        name: String,
        expected: Vec<&'static str>,
    },
    #[error("line {line}: {call} argument {arg}: {name} is not valid here; expected one of: {}", expected.join(", "))]
    UnknownEnum {
        line: usize,
        call: &'static str,
        arg: usize,
        name: String,
        expected: Vec<&'static str>,
    },
    /// A call of the table the layer leaves out (selection, feedback, evaluators…): the
    /// C library exports it and records GL_INVALID_OPERATION; a script stops here.
    #[error("line {line}: {call} is not implemented by fixedfunc (the C library records GL_INVALID_OPERATION for it)")]
    NotImplemented { line: usize, call: &'static str },
    #[error("line {line}: {call} takes {expected} arguments, found {found}")]
    ArgCount {
        line: usize,
        call: &'static str,
        expected: usize,
        found: usize,
    },
    #[error("line {line}: {call} argument {arg}: expected {expected}, found {found}")]
    BadArgument {
        line: usize,
        call: &'static str,
        arg: usize,
        expected: &'static str,
        found: String,
    },
    #[error("line {line}: {call}: array of {expected} values expected, found {found}")]
    ArrayLength {
        line: usize,
        call: &'static str,
        expected: usize,
        found: usize,
    },
    #[error("line {line}: {call}: {rule}")]
    Immediate {
        line: usize,
        call: String,
        rule: &'static str,
    },
}

fn closest(names: &[&str]) -> String {
    names.iter().take(5).copied().collect::<Vec<_>>().join(", ")
}

/// The geometry of each draw a script makes (unit tests of the layers that make draws).
#[cfg(test)]
pub(crate) fn draws(src: &str) -> Vec<std::sync::Arc<crate::ff::Geometry>> {
    parse(src)
        .expect("the script parses")
        .into_iter()
        .filter_map(|c| match c {
            crate::ff::Command::Draw(g) => Some(g),
            _ => None,
        })
        .collect()
}

#[cfg(test)]
mod every_row_tests;
#[cfg(test)]
mod secondary_tests;
#[cfg(test)]
mod tests;

#[cfg(test)]
mod pixels_tests;
#[cfg(test)]
mod stipple_tests;
