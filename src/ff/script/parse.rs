//! Script text → Commands: statements are read generically (name, arguments), then each
//! call is converted by a small function per area; glBegin/glEnd pairs fold into one Draw.

use std::sync::Arc;

use super::lexer::{lex, Tok, Token};
use super::names::{ranked, Family, GlEnum};
use super::ScriptError;
use crate::ff::api::{CType, Entry, Form};
use crate::ff::args::{Args, PixelShape};
use crate::ff::client::{ArrayData, BytesOnly};
use crate::ff::front::Client;
use crate::ff::pixel_layout;
use crate::ff::pixel_store::Packing;
use crate::ff::*;
use crate::vocab::DepthRule;

type Res<T> = Result<T, ScriptError>;

/// One argument as written.
#[derive(Debug, Clone, PartialEq)]
enum Arg<'a> {
    /// `f(name)`: a client helper applied to a buffer (converted depth readbacks).
    Call { func: &'a str, arg: &'a str },
    /// A number literal, `INFINITY` or `NAN`, optionally negated; `int_cast` when a cast
    /// to an integer type applies (C converts by truncation towards zero).
    Num {
        neg: bool,
        text: &'a str,
        int_cast: bool,
    },
    /// An identifier, optionally `+ n`.
    Name { name: &'a str, offset: u32 },
    /// `A | B | …`
    Or(Vec<&'a str>),
    /// `(T[]){…}`
    Array {
        ty: &'a str,
        values: Vec<(bool, &'a str)>,
    },
    /// `(const void *[]){a, b, …}`: an array of pointers, each a compound literal, NULL or
    /// (into a bound buffer) an offset.
    Pointers(Vec<Arg<'a>>),
}

struct Stmt<'a> {
    line: usize,
    name: &'a str,
    args: Vec<Arg<'a>>,
}

struct Cursor<'t, 'a> {
    toks: &'t [Token<'a>],
    pos: usize,
}

impl<'a> Cursor<'_, 'a> {
    fn peek(&self) -> Option<Tok<'a>> {
        self.toks.get(self.pos).map(|t| t.tok)
    }
    fn line(&self) -> usize {
        self.toks
            .get(self.pos)
            .or(self.toks.last())
            .map_or(1, |t| t.line)
    }
    fn next(&mut self) -> Option<Tok<'a>> {
        let t = self.peek();
        self.pos += 1;
        t
    }
    fn error(&self, expected: &'static str) -> ScriptError {
        let found = self
            .peek()
            .map_or("end of input".to_string(), |t| describe(t));
        ScriptError::Syntax {
            line: self.line(),
            expected,
            found,
        }
    }
    fn eat(&mut self, tok: Tok<'a>, expected: &'static str) -> Res<()> {
        if self.peek() == Some(tok) {
            self.pos += 1;
            Ok(())
        } else {
            Err(self.error(expected))
        }
    }
    fn ident(&mut self, expected: &'static str) -> Res<&'a str> {
        match self.peek() {
            Some(Tok::Ident(s)) => {
                self.pos += 1;
                Ok(s)
            }
            _ => Err(self.error(expected)),
        }
    }
    fn number(&mut self, neg: bool) -> Res<(bool, &'a str)> {
        match self.next() {
            Some(Tok::Num(t)) => Ok((neg, t)),
            Some(Tok::Ident(t @ ("INFINITY" | "NAN"))) => Ok((neg, t)),
            Some(Tok::Minus) if !neg => self.number(true),
            _ => {
                self.pos -= 1;
                Err(self.error("a number"))
            }
        }
    }

    fn statement(&mut self) -> Res<Stmt<'a>> {
        let line = self.line();
        let name = self.ident("a GL call")?;
        self.eat(Tok::LParen, "'('")?;
        let mut args = Vec::new();
        if self.peek() != Some(Tok::RParen) {
            loop {
                args.push(self.arg()?);
                if self.peek() == Some(Tok::Comma) {
                    self.pos += 1;
                } else {
                    break;
                }
            }
        }
        self.eat(Tok::RParen, "',' or ')'")?;
        self.eat(Tok::Semi, "';'")?;
        Ok(Stmt { line, name, args })
    }

    fn arg(&mut self) -> Res<Arg<'a>> {
        match self.peek() {
            Some(Tok::LParen) => self.parenthesised(),
            Some(Tok::Num(_) | Tok::Minus | Tok::Ident("INFINITY" | "NAN")) => {
                let (neg, text) = self.number(false)?;
                Ok(Arg::Num {
                    neg,
                    text,
                    int_cast: false,
                })
            }
            Some(Tok::Ident(name)) => {
                self.pos += 1;
                match self.peek() {
                    Some(Tok::Pipe) => {
                        let mut names = vec![name];
                        while self.peek() == Some(Tok::Pipe) {
                            self.pos += 1;
                            names.push(self.ident("a GL token after '|'")?);
                        }
                        Ok(Arg::Or(names))
                    }
                    Some(Tok::Plus) => {
                        self.pos += 1;
                        let (_, text) = self.number(true)?;
                        let offset = int_literal(text)
                            .and_then(|v| u32::try_from(v).ok())
                            .ok_or_else(|| self.error("an index after '+'"))?;
                        Ok(Arg::Name { name, offset })
                    }
                    Some(Tok::LParen) => {
                        self.pos += 1;
                        let arg = self.ident("a buffer name")?;
                        self.eat(Tok::RParen, "')'")?;
                        Ok(Arg::Call { func: name, arg })
                    }
                    _ => Ok(Arg::Name { name, offset: 0 }),
                }
            }
            _ => Err(self.error("an argument")),
        }
    }

    /// After '(': a compound literal `(T[]){…}`, a cast `(T)x` or `(T *)x`, or redundant
    /// parentheses `(x)`. A cast to an integer type truncates a number towards zero, as C
    /// converts; every other cast leaves the value as it is (the dialect's values already
    /// have the parameter's type).
    fn parenthesised(&mut self) -> Res<Arg<'a>> {
        let at = |k: usize| self.toks.get(self.pos + k).map(|t| t.tok);
        let mut k = 1;
        while at(k) == Some(Tok::Ident("const")) {
            k += 1;
        }
        let ty = match at(k) {
            Some(Tok::Ident(t)) if is_c_type(t) => Some(t),
            _ => None,
        };
        let Some(ty) = ty else {
            self.eat(Tok::LParen, "'('")?;
            let inner = self.arg()?;
            self.eat(Tok::RParen, "')'")?;
            return Ok(inner);
        };
        if at(k + 1) == Some(Tok::LBracket) {
            return self.array();
        }
        let mut star = k + 1;
        while matches!(at(star), Some(Tok::Star | Tok::Ident("const"))) {
            star += 1;
        }
        if star > k + 1 && at(star) == Some(Tok::LBracket) {
            return self.pointer_array(star);
        }
        self.pos += k + 1;
        let mut pointer = false;
        while self.peek() == Some(Tok::Star) || self.peek() == Some(Tok::Ident("const")) {
            pointer |= self.peek() == Some(Tok::Star);
            self.pos += 1;
        }
        self.eat(Tok::RParen, "')' closing the cast")?;
        let inner = self.arg()?;
        Ok(match inner {
            // (void *)0 and (const GLvoid *)NULL are the null pointer.
            Arg::Num { text, .. } if pointer && int_literal(text) == Some(0) => Arg::Name {
                name: "NULL",
                offset: 0,
            },
            Arg::Num { neg, text, .. } if !pointer && INTEGER_TYPES.contains(&ty) => Arg::Num {
                neg,
                text,
                int_cast: true,
            },
            other => other,
        })
    }

    /// `(const void *[]){a, b}`, the type's tokens ending before `bracket`.
    fn pointer_array(&mut self, bracket: usize) -> Res<Arg<'a>> {
        self.pos += bracket + 1;
        if let Some(Tok::Num(_)) = self.peek() {
            self.pos += 1;
        }
        self.eat(Tok::RBracket, "']'")?;
        self.eat(Tok::RParen, "')'")?;
        self.eat(Tok::LBrace, "'{'")?;
        let mut items = Vec::new();
        while self.peek() != Some(Tok::RBrace) {
            items.push(self.arg()?);
            if self.peek() == Some(Tok::Comma) {
                self.pos += 1;
            } else {
                break;
            }
        }
        self.eat(Tok::RBrace, "',' or '}'")?;
        Ok(Arg::Pointers(items))
    }

    fn array(&mut self) -> Res<Arg<'a>> {
        self.eat(Tok::LParen, "'('")?;
        while self.peek() == Some(Tok::Ident("const")) {
            self.pos += 1;
        }
        let ty = self.ident("an array type such as GLfloat")?;
        self.eat(Tok::LBracket, "'['")?;
        // C99 allows the length: (GLint[4]){0}.
        if let Some(Tok::Num(_)) = self.peek() {
            self.pos += 1;
        }
        self.eat(Tok::RBracket, "']'")?;
        self.eat(Tok::RParen, "')'")?;
        self.eat(Tok::LBrace, "'{'")?;
        let mut values = Vec::new();
        while self.peek() != Some(Tok::RBrace) {
            // A GL token is its value, as in C: (GLint[]){GL_NEAREST}.
            if let Some(Tok::Ident(name)) = self.peek() {
                if crate::ff::glenum::value_of(name).is_some() {
                    self.pos += 1;
                    values.push((false, name));
                    if self.peek() == Some(Tok::Comma) {
                        self.pos += 1;
                        continue;
                    }
                    break;
                }
            }
            values.push(self.number(false)?);
            if self.peek() == Some(Tok::Comma) {
                self.pos += 1;
            } else {
                break;
            }
        }
        self.eat(Tok::RBrace, "',' or '}'")?;
        Ok(Arg::Array { ty, values })
    }
}

/// The non-integer type names a cast or a compound literal may use (with
/// [`INTEGER_TYPES`], every type the dialect knows).
const OTHER_TYPES: &[&str] = &[
    "GLfloat", "GLdouble", "GLclampf", "GLclampd", "GLvoid", "void", "float", "double",
];

fn is_c_type(name: &str) -> bool {
    OTHER_TYPES.contains(&name) || INTEGER_TYPES.contains(&name)
}

/// The cast types that make a number an integer (truncated towards zero).
const INTEGER_TYPES: &[&str] = &[
    "GLint",
    "GLuint",
    "GLsizei",
    "GLenum",
    "GLboolean",
    "GLbitfield",
    "GLbyte",
    "GLubyte",
    "GLshort",
    "GLushort",
    "int",
    "unsigned",
    "short",
    "char",
    "long",
    "size_t",
];

fn describe(t: Tok<'_>) -> String {
    t.describe()
}

/// C integer literal: decimal or hex, optional u/U/l/L suffixes; a GL token in an array
/// is its value.
fn int_literal(text: &str) -> Option<i64> {
    if text.starts_with("GL_") {
        return crate::ff::glenum::value_of(text).map(i64::from);
    }
    let t = text.trim_end_matches(['u', 'U', 'l', 'L']);
    if let Some(hex) = t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
        i64::from_str_radix(hex, 16).ok()
    } else {
        t.parse().ok()
    }
}

/// C floating literal (or integer), optional f/F suffix; INFINITY and NAN from <math.h>.
fn float_literal(text: &str) -> Option<f32> {
    match text {
        "INFINITY" => Some(f32::INFINITY),
        "NAN" => Some(f32::NAN),
        _ if text.starts_with("0x") || text.starts_with("0X") => {
            hex_float(&text[2..]).or_else(|| int_literal(text).map(|v| v as f32))
        }
        _ => {
            let t = text.strip_suffix(['f', 'F']).unwrap_or(text);
            t.parse()
                .ok()
                .or_else(|| int_literal(text).map(|v| v as f32))
        }
    }
}

/// A C literal's value: `f`-suffixed literals are floats (rounded to f32), other floating
/// literals doubles, integer literals exact; INFINITY and NAN from <math.h>.
fn c_number(text: &str) -> Option<f64> {
    let is_hex = text.starts_with("0x") || text.starts_with("0X");
    let float_suffix = !is_hex && text.ends_with(['f', 'F'])
        || is_hex && text.contains(['p', 'P']) && text.ends_with(['f', 'F']);
    if float_suffix || matches!(text, "INFINITY" | "NAN") {
        return float_literal(text).map(f64::from);
    }
    if let Some(v) = int_literal(text) {
        return Some(v as f64);
    }
    if is_hex {
        return hex_float_f64(&text[2..]);
    }
    text.trim_end_matches(['l', 'L']).parse().ok()
}

/// A C99 hexadecimal floating literal after its `0x`: hex digits with an optional point,
/// then a binary exponent `p±n` (required: without it the literal is an integer), then an
/// optional `f`/`l` suffix. The value is mantissa·2ⁿ, computed in f64 and rounded once to
/// f32 (exact for every mantissa of up to 53 bits).
fn hex_float(text: &str) -> Option<f32> {
    hex_float_f64(text).map(|v| v as f32)
}

/// [`hex_float`] in f64.
fn hex_float_f64(text: &str) -> Option<f64> {
    let (mantissa, exponent) = text.split_once(['p', 'P'])?;
    let exponent = exponent.trim_end_matches(['f', 'F', 'l', 'L']);
    let exponent: i32 = exponent.parse().ok()?;
    let (whole, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    if whole.is_empty() && frac.is_empty() {
        return None;
    }
    let mut value = 0.0f64;
    for c in whole.chars().chain(frac.chars()) {
        value = value * 16.0 + f64::from(c.to_digit(16)?);
    }
    let scale = exponent.checked_sub(4 * i32::try_from(frac.len()).ok()?)?;
    Some(value * 2f64.powi(scale))
}

/// A statement with its call name resolved, and typed argument readers.
pub(super) struct Call<'s, 'a> {
    pub(super) line: usize,
    pub(super) name: &'static str,
    pub(super) entry: Entry,
    args: &'s [Arg<'a>],
    /// The unpack parameters when the call is read: pixel arrays are laid out by them.
    unpack: Packing,
}

impl Call<'_, '_> {
    fn num(&self, i: usize) -> Option<(bool, &str)> {
        match self.args.get(i) {
            Some(Arg::Num { neg, text, .. }) => Some((*neg, text)),
            _ => None,
        }
    }

    fn int_cast(&self, i: usize) -> bool {
        matches!(self.args.get(i), Some(Arg::Num { int_cast: true, .. }))
    }

    fn name(&self, i: usize) -> Option<(&str, u32)> {
        match self.args.get(i) {
            Some(Arg::Name { name, offset }) => Some((name, *offset)),
            _ => None,
        }
    }

    fn array(&self, i: usize) -> Option<(&str, &[(bool, &str)])> {
        match self.args.get(i) {
            Some(Arg::Array { ty, values }) => Some((ty, values)),
            _ => None,
        }
    }

    /// The numbers of a compound literal, as [`Call::f64`] reads each.
    fn array_all(&self, i: usize) -> Res<Vec<f64>> {
        let (_, values) = self
            .array(i)
            .ok_or_else(|| self.bad(i, "a compound-literal array such as (GLfloat[]){…}"))?;
        values
            .iter()
            .map(|(neg, text)| {
                let v = c_number(text).ok_or_else(|| self.bad(i, "numbers in the array"))?;
                Ok(if *neg { -v } else { v })
            })
            .collect()
    }
    fn or_names(&self, i: usize) -> Option<Vec<&str>> {
        match self.args.get(i) {
            Some(Arg::Or(v)) => Some(v.clone()),
            Some(Arg::Name { name, offset: 0 }) => Some(vec![name]),
            Some(Arg::Num {
                neg: false,
                text: "0",
                ..
            }) => Some(vec![]),
            _ => None,
        }
    }
}

impl Args for Call<'_, '_> {
    type Error = ScriptError;

    fn entry(&self) -> Entry {
        self.entry
    }
    fn unsupported(&self) -> ScriptError {
        ScriptError::UnknownCall {
            line: self.line,
            name: self.name.to_string(),
            expected: ranked(self.name, &Entry::script_names()),
        }
    }
    fn immediate(&self, rule: &'static str) -> ScriptError {
        ScriptError::Immediate {
            line: self.line,
            call: self.name.to_string(),
            rule,
        }
    }
    fn array_length(&self, expected: usize, found: usize) -> ScriptError {
        ScriptError::ArrayLength {
            line: self.line,
            call: self.name,
            expected,
            found,
        }
    }
    fn also_expected(&self, err: ScriptError, alternative: &'static str) -> ScriptError {
        match err {
            ScriptError::UnknownEnum {
                line,
                call,
                arg,
                name,
                mut expected,
            } => {
                expected.push(alternative);
                ScriptError::UnknownEnum {
                    line,
                    call,
                    arg,
                    name,
                    expected,
                }
            }
            other => other,
        }
    }
    fn bits(&self, i: usize, names: &[&'static str]) -> Res<Vec<&'static str>> {
        let found = self
            .or_names(i)
            .ok_or_else(|| self.bad(i, "bits joined by '|', or 0"))?;
        found
            .into_iter()
            .map(|n| {
                names
                    .iter()
                    .find(|b| **b == n)
                    .copied()
                    .ok_or_else(|| ScriptError::UnknownEnum {
                        line: self.line,
                        call: self.name,
                        arg: i + 1,
                        name: n.to_string(),
                        expected: names.to_vec(),
                    })
            })
            .collect()
    }
    fn array_f64(&self, i: usize, n: usize) -> Res<Vec<f64>> {
        let mut values = self.array_all(i)?;
        if values.len() < n {
            return Err(self.array_length(n, values.len()));
        }
        values.truncate(n);
        Ok(values)
    }

    fn count(&self, n: usize) -> Res<()> {
        if self.args.len() == n {
            Ok(())
        } else {
            Err(ScriptError::ArgCount {
                line: self.line,
                call: self.name,
                expected: n,
                found: self.args.len(),
            })
        }
    }

    fn bad(&self, i: usize, expected: &'static str) -> ScriptError {
        let found = self.args.get(i).map_or("nothing".to_string(), |a| match a {
            Arg::Num { neg, text, .. } => format!("{}{text}", if *neg { "-" } else { "" }),
            Arg::Name { name, offset: 0 } => name.to_string(),
            Arg::Name { name, offset } => format!("{name} + {offset}"),
            Arg::Or(names) => names.join(" | "),
            Arg::Array { ty, .. } => format!("a ({ty}[]) array"),
            Arg::Pointers(items) => format!("an array of {} pointers", items.len()),
            Arg::Call { func, arg } => format!("{func}({arg})"),
        });
        ScriptError::BadArgument {
            line: self.line,
            call: self.name,
            arg: i + 1,
            expected,
            found,
        }
    }

    /// A number as C passes it before the parameter's conversion: a literal with an `f`
    /// suffix is a float, any other floating literal a double, an integer literal exact.
    fn f64(&self, i: usize) -> Res<f64> {
        let (neg, text) = self.num(i).ok_or_else(|| self.bad(i, "a number"))?;
        let v = c_number(text).ok_or_else(|| self.bad(i, "a number"))?;
        let v = if self.int_cast(i) { v.trunc() } else { v };
        Ok(if neg { -v } else { v })
    }

    fn f32(&self, i: usize) -> Res<f32> {
        let (neg, text) = self.num(i).ok_or_else(|| self.bad(i, "a number"))?;
        let v = float_literal(text).ok_or_else(|| self.bad(i, "a number"))?;
        let v = if self.int_cast(i) { v.trunc() } else { v };
        Ok(if neg { -v } else { v })
    }

    fn int(&self, i: usize) -> Res<i64> {
        let (neg, text) = self.num(i).ok_or_else(|| self.bad(i, "an integer"))?;
        let v = int_literal(text)
            .or_else(|| {
                // (GLint)2.7 is 2: a cast to an integer type truncates towards zero.
                float_literal(text)
                    .filter(|f| self.int_cast(i) && f.is_finite() && f.abs() < 9.0e18)
                    .map(|f| f.trunc() as i64)
            })
            .ok_or_else(|| self.bad(i, "an integer"))?;
        Ok(if neg { -v } else { v })
    }

    fn unknown(&self, i: usize, expected: Vec<&'static str>) -> ScriptError {
        let found = match self.args.get(i) {
            Some(Arg::Name { name, offset: 0 }) => name.to_string(),
            _ => return self.bad(i, "a GL token"),
        };
        let expected = ranked(&found, &expected);
        ScriptError::UnknownEnum {
            line: self.line,
            call: self.name,
            arg: i + 1,
            name: found,
            expected,
        }
    }

    fn enm<T: GlEnum>(&self, i: usize) -> Res<T> {
        self.name(i)
            .filter(|(_, off)| *off == 0)
            .and_then(|(n, _)| T::from_gl_name(n))
            .ok_or_else(|| self.unknown(i, T::names()))
    }

    fn token(&self, i: usize) -> Res<u32> {
        self.name(i)
            .and_then(|(n, off)| crate::ff::glenum::value_of(n)?.checked_add(off))
            .ok_or_else(|| self.bad(i, "a GL token"))
    }

    /// A GL token naming one of `pnames` (a parameter name).
    /// One of `pnames`, or a name of the same value (an alias: GL_FOG_COORDINATE_SOURCE
    /// for GL_FOG_COORD_SRC, an `_EXT` name), as the C front end compares values.
    fn pname(&self, i: usize, pnames: &[&'static str]) -> Res<&'static str> {
        self.name(i)
            .filter(|(_, off)| *off == 0)
            .and_then(|(n, _)| {
                let value = crate::ff::glenum::value_of(n);
                pnames
                    .iter()
                    .find(|p| {
                        **p == n || (value.is_some() && crate::ff::glenum::value_of(p) == value)
                    })
                    .copied()
            })
            .ok_or_else(|| self.unknown(i, pnames.to_vec()))
    }

    fn family(&self, i: usize, f: Family) -> Res<u8> {
        self.name(i)
            .and_then(|(n, off)| f.parse(n, off))
            .ok_or_else(|| self.unknown(i, vec![f.example()]))
    }

    fn boolean(&self, i: usize) -> Res<bool> {
        match self.num(i) {
            Some((false, "0")) => Ok(false),
            Some((false, "1")) => Ok(true),
            _ => self.enm::<bool>(i),
        }
    }

    fn floats<const N: usize>(&self, i: usize) -> Res<[f32; N]> {
        let (_, values) = self
            .array(i)
            .ok_or_else(|| self.bad(i, "a (GLfloat[]){…} array"))?;
        if values.len() != N {
            return Err(ScriptError::ArrayLength {
                line: self.line,
                call: self.name,
                expected: N,
                found: values.len(),
            });
        }
        let mut out = [0.0; N];
        for (o, (neg, text)) in out.iter_mut().zip(values) {
            let v = float_literal(text).ok_or_else(|| self.bad(i, "numbers in the array"))?;
            *o = if *neg { -v } else { v };
        }
        Ok(out)
    }

    /// glTexImage's data: NULL, a readback buffer `readback_<n>`, a converted depth
    /// readback `fixedfunc_depth_<ubyte|ushort>_<truncate|round>(readback_<n>)`, or a pixel
    /// array.
    fn tex_data(&self, i: usize, shape: PixelShape) -> Res<TexData> {
        if let Some(Arg::Call { func, arg }) = self.args.get(i) {
            let (ty, rule) = depth_helper(func).ok_or_else(|| {
                self.bad(i, "a depth helper: fixedfunc_depth_ubyte_truncate, fixedfunc_depth_ubyte_round, fixedfunc_depth_ushort_truncate or fixedfunc_depth_ushort_round")
            })?;
            let slot = arg
                .strip_prefix("readback_")
                .filter(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
                .and_then(|d| d.parse().ok())
                .ok_or_else(|| self.bad(i, "a readback slot readback_<n> inside the helper"))?;
            return Ok(TexData::ConvertedDepth { slot, ty, rule });
        }
        match self.name(i) {
            Some((n, 0)) if n.starts_with("readback_") => self.slot(i).map(TexData::Readback),
            _ => Ok(self.pixels(i, shape)?.map_or(TexData::Null, TexData::Bytes)),
        }
    }

    /// Pixel data: NULL, or a compound literal whose element type gives the byte encoding,
    /// laid out by the unpack parameters as a C program's is (GL 1.5 §3.6.4,
    /// `pixel_layout`). With only an alignment set, a literal of tight rows (one row, or
    /// rows the alignment does not pad) is taken as it is — rows that the alignment does
    /// not pad only if the literal holds every one (`extent`, as for the other layouts),
    /// since the printer writes them back padded to the default alignment.
    fn pixels(&self, i: usize, shape: PixelShape) -> Res<Option<Arc<[u8]>>> {
        let Some(bytes) = self.literal_bytes(i)? else {
            return Ok(None);
        };
        let lay = pixel_layout::layout(shape, &self.unpack);
        let plain = self.unpack == Packing::aligned(self.unpack.alignment);
        let holds_every_row = bytes.len() >= lay.extent;
        let rows = lay.rows * lay.images;
        if plain && (rows < 2 || (lay.stride == lay.tight_row && holds_every_row)) {
            return Ok(Some(Arc::from(bytes)));
        }
        pixel_layout::unpack(&bytes, shape, &self.unpack)
            .map(|v| Some(Arc::from(v)))
            .ok_or_else(|| {
                self.bad(
                    i,
                    "pixel rows as the unpack parameters lay them out (glPixelStorei sets them; rows padded to GL_UNPACK_ALIGNMENT, 4 by default)",
                )
            })
    }
    fn array_as(&self, i: usize, n: usize, _ty: CType) -> Res<Vec<f64>> {
        self.array_f64(i, n)
    }
    fn deferred(&self, _err: &ScriptError) -> Option<GlErrorKind> {
        None
    }
    fn array_data(&self, i: usize) -> Res<ArrayData> {
        Ok(self
            .literal_bytes(i)?
            .map_or(ArrayData::Null, |b| ArrayData::Bytes(Arc::from(b))))
    }
    fn pointers(&self, i: usize, n: usize, bound: u32) -> Res<Vec<ArrayData>> {
        let items = match self.args.get(i) {
            Some(Arg::Pointers(items)) => items.as_slice(),
            _ if n == 0 => &[],
            _ => {
                return Err(self.bad(
                    i,
                    "an array of pointers such as (const void *[]){(GLushort[]){0, 1, 2}}",
                ))
            }
        };
        if items.len() < n {
            return Err(self.array_length(n, items.len()));
        }
        items[..n]
            .iter()
            .map(|item| {
                // Each pointer read as a pointer argument of its own.
                let one = Call {
                    args: std::slice::from_ref(item),
                    ..*self
                };
                crate::ff::buffers::Buffers::source(&one, 0, bound)
            })
            .collect()
    }
    fn offset(&self, i: usize) -> Res<usize> {
        if let Some(("NULL", 0)) = self.name(i) {
            return Ok(0);
        }
        usize::try_from(self.int(i)?).map_err(|_| self.bad(i, "a byte offset of 0 or more"))
    }
    fn slot(&self, i: usize) -> Res<u32> {
        self.name(i)
            .filter(|(_, off)| *off == 0)
            .and_then(|(n, _)| n.strip_prefix("readback_"))
            .filter(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
            .and_then(|d| d.parse().ok())
            .ok_or_else(|| self.bad(i, "a readback slot readback_<n>"))
    }
}

impl Call<'_, '_> {
    /// The bytes of a compound literal (its element type gives the encoding), or `None`
    /// for NULL.
    fn literal_bytes(&self, i: usize) -> Res<Option<Vec<u8>>> {
        if let Some(("NULL", 0)) = self.name(i) {
            return Ok(None);
        }
        // A null pointer constant: the integer literal 0 (C99 6.3.2.3).
        if let Some((false, text)) = self.num(i) {
            if int_literal(text) == Some(0) {
                return Ok(None);
            }
        }
        let (ty, values) = self
            .array(i)
            .ok_or_else(|| self.bad(i, "NULL or a pixel array"))?;
        let mut bytes = Vec::new();
        for (neg, text) in values {
            let int = || int_literal(text).map(|v| if *neg { -v } else { v });
            let ok = match ty {
                "GLubyte" | "GLboolean" => int()
                    .and_then(|v| u8::try_from(v).ok())
                    .map(|v| bytes.push(v)),
                "GLushort" => int()
                    .and_then(|v| u16::try_from(v).ok())
                    .map(|v| bytes.extend(v.to_le_bytes())),
                "GLuint" => int()
                    .and_then(|v| u32::try_from(v).ok())
                    .map(|v| bytes.extend(v.to_le_bytes())),
                "GLfloat" => float_literal(text)
                    .map(|v| bytes.extend((if *neg { -v } else { v }).to_le_bytes())),
                "GLbyte" => int()
                    .and_then(|v| i8::try_from(v).ok())
                    .map(|v| bytes.extend(v.to_le_bytes())),
                "GLshort" => int()
                    .and_then(|v| i16::try_from(v).ok())
                    .map(|v| bytes.extend(v.to_le_bytes())),
                "GLint" => int()
                    .and_then(|v| i32::try_from(v).ok())
                    .map(|v| bytes.extend(v.to_le_bytes())),
                "GLdouble" => c_number(text)
                    .map(|v| bytes.extend((if *neg { -v } else { v }).to_le_bytes())),
                _ => {
                    return Err(self.bad(
                        i,
                        "a GLubyte, GLboolean, GLbyte, GLushort, GLshort, GLuint, GLint, GLfloat or GLdouble array",
                    ))
                }
            };
            ok.ok_or_else(|| self.bad(i, "array values that fit the element type"))?;
        }
        Ok(Some(bytes))
    }
}

/// Parses a script into Commands.
pub fn parse(src: &str) -> Result<Vec<Command>, ScriptError> {
    parse_lines(src).map(|cmds| cmds.into_iter().map(|(_, c)| c).collect())
}

/// Parses a script into Commands, each with the script line that made it (a Draw: its
/// glEnd), so that a GL error met while executing can name the line.
pub fn parse_lines(src: &str) -> Result<Vec<(usize, Command)>, ScriptError> {
    let toks = lex(src)?;
    let mut cur = Cursor {
        toks: &toks,
        pos: 0,
    };
    // The model follows the script, so that glBegin reads the current values any earlier
    // command left (glColor, a glEnd's last vertex, glPopAttrib).
    let mut state = FixedState::default();
    let mut client = Client::default();
    let mut out = Vec::new();
    let mut made = Vec::new();
    let mut open_line = 0;
    while cur.peek().is_some() {
        // An empty statement is valid C and does nothing.
        if cur.peek() == Some(Tok::Semi) {
            cur.pos += 1;
            continue;
        }
        let stmt = cur.statement()?;
        let entry = Entry::from_name(stmt.name).ok_or_else(|| ScriptError::UnknownCall {
            line: stmt.line,
            name: stmt.name.to_string(),
            expected: ranked(stmt.name, &Entry::script_names()),
        })?;
        if entry.form() == Form::Left {
            return Err(ScriptError::NotImplemented {
                line: stmt.line,
                call: entry.name(),
            });
        }
        let call = Call {
            line: stmt.line,
            name: entry.name(),
            entry,
            args: &stmt.args,
            unpack: client.pixel_store.unpack,
        };
        if entry == Entry::Begin {
            open_line = stmt.line;
        }
        client.call(&call, &state, &BytesOnly, &mut made)?;
        for cmd in made.drain(..) {
            // Errors are the executing pipeline's to report; here only the values count.
            let _ = state.apply(&cmd);
            out.push((stmt.line, cmd));
        }
    }
    if client.immediate.is_open() {
        return Err(ScriptError::Immediate {
            line: open_line,
            call: "glBegin".into(),
            rule: "glBegin without glEnd",
        });
    }
    Ok(out)
}

/// The client helpers a script may apply to a depth readback, by name.
pub(super) const DEPTH_HELPERS: [(&str, PixelType, DepthRule); 4] = [
    (
        "fixedfunc_depth_ubyte_truncate",
        PixelType::UnsignedByte,
        DepthRule::Truncate,
    ),
    (
        "fixedfunc_depth_ubyte_round",
        PixelType::UnsignedByte,
        DepthRule::Round,
    ),
    (
        "fixedfunc_depth_ushort_truncate",
        PixelType::UnsignedShort,
        DepthRule::Truncate,
    ),
    (
        "fixedfunc_depth_ushort_round",
        PixelType::UnsignedShort,
        DepthRule::Round,
    ),
];

fn depth_helper(name: &str) -> Option<(PixelType, DepthRule)> {
    DEPTH_HELPERS
        .iter()
        .find(|(n, _, _)| *n == name)
        .map(|&(_, ty, rule)| (ty, rule))
}
