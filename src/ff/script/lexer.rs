//! Tokens of the script's C subset: identifiers, numbers, punctuation; `//` and `/* */`
//! comments and whitespace skipped; every token carries its line (1-based).
//!
//! The preprocessor lines a C compiler would accept are read here, as far as the dialect
//! needs them (`preprocess`): a UTF-8 byte-order mark is skipped; `#include`, `#pragma`,
//! `#line` and `#error`-free files pass; `#define NAME tokens` defines an object-like macro
//! that later identifiers expand to (nested expansion, no recursion: C's rule that a macro
//! is not expanded inside its own expansion); `#undef` forgets one; `#if`, `#ifdef`,
//! `#ifndef`, `#elif`, `#else`, `#endif` keep or drop lines, with `#if` reading an integer,
//! `defined NAME`/`defined(NAME)`, `!` of those, or a macro naming an integer. Function-like
//! macros and other directives are refused with the line, not ignored.

use std::collections::HashMap;

use super::ScriptError;

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tok<'a> {
    Ident(&'a str),
    /// The literal as written (digits, '.', exponent, hex, suffixes).
    Num(&'a str),
    LParen,
    RParen,
    LBrace,
    RBrace,
    LBracket,
    RBracket,
    Comma,
    Semi,
    Pipe,
    Plus,
    Minus,
    Star,
}

impl Tok<'_> {
    /// The token as a C programmer would name it in an error.
    pub fn describe(self) -> String {
        let p = |s: &str| format!("'{s}'");
        match self {
            Tok::Ident(s) | Tok::Num(s) => s.to_string(),
            Tok::LParen => p("("),
            Tok::RParen => p(")"),
            Tok::LBrace => p("{"),
            Tok::RBrace => p("}"),
            Tok::LBracket => p("["),
            Tok::RBracket => p("]"),
            Tok::Comma => p(","),
            Tok::Semi => p(";"),
            Tok::Pipe => p("|"),
            Tok::Plus => p("+"),
            Tok::Minus => p("-"),
            Tok::Star => p("*"),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Token<'a> {
    pub tok: Tok<'a>,
    pub line: usize,
}

/// Macro expansions nest at most this deep (a C compiler stops self-reference instead;
/// mutual references end here with an error rather than loop).
const MAX_EXPANSION_DEPTH: usize = 32;

/// All macro expansions of a script together produce at most this many tokens: a macro
/// whose body names the previous one twice doubles at each level, so 30 such lines would
/// otherwise expand to 2³⁰ tokens. Each expansion is charged its body's length.
const MAX_EXPANDED_TOKENS: usize = 1 << 20;

/// The tokens of `src`, preprocessed.
pub fn lex(src: &str) -> Result<Vec<Token<'_>>, ScriptError> {
    let src = src.strip_prefix('\u{FEFF}').unwrap_or(src);
    let mut pp = Preprocessor::default();
    let mut out = Vec::new();
    let mut budget = MAX_EXPANDED_TOKENS;
    let mut line = 1;
    let mut rest = src;
    while !rest.is_empty() {
        // One logical line at a time: directives are whole lines (with '\' continuations).
        let (text, consumed, newlines) = logical_line(rest);
        let first_line = line;
        line += newlines;
        rest = &rest[consumed..];
        let trimmed = text.trim_start();
        if let Some(directive) = trimmed.strip_prefix('#').filter(|_| pp.comment.is_none()) {
            pp.directive(directive, first_line)?;
            continue;
        }
        if !pp.active() {
            continue;
        }
        // Expanded with the macros defined so far, as a C preprocessor reads top to bottom.
        let mut line_tokens = Vec::new();
        tokens(text, first_line, &mut pp.comment, &mut line_tokens)?;
        out.extend(pp.expand(line_tokens, &mut budget)?);
    }
    if let Some(open) = pp.comment {
        return Err(ScriptError::UnterminatedComment { line: open });
    }
    if let Some(&(_, _, open)) = pp.conditions.last() {
        return Err(ScriptError::Preprocessor {
            line: open,
            problem: "#if without #endif".to_string(),
        });
    }
    Ok(out)
}

/// The next logical line: its text (without the newline), the bytes consumed, and the
/// newlines crossed. A backslash before a newline joins lines; a `/*` comment that spans
/// lines is left to the tokeniser (it keeps its own state across lines).
fn logical_line(s: &str) -> (&str, usize, usize) {
    let bytes = s.as_bytes();
    let mut i = 0;
    let mut newlines = 0;
    while i < bytes.len() {
        if bytes[i] == b'\n' {
            newlines += 1;
            if i > 0 && bytes[i - 1] == b'\\' {
                i += 1;
                continue;
            }
            return (&s[..i], i + 1, newlines);
        }
        i += 1;
    }
    (s, s.len(), newlines)
}

/// Tokenises one logical line starting at `line`; `comment` is the line a still-open
/// `/*` began on.
fn tokens<'a>(
    text: &'a str,
    mut line: usize,
    comment: &mut Option<usize>,
    out: &mut Vec<Token<'a>>,
) -> Result<(), ScriptError> {
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        if comment.is_some() {
            match text[i..].find("*/") {
                Some(end) => {
                    line += text[i..i + end].matches('\n').count();
                    i += end + 2;
                    *comment = None;
                    continue;
                }
                None => return Ok(()),
            }
        }
        let c = bytes[i];
        let start = i;
        let punct = match c {
            b'(' => Some(Tok::LParen),
            b')' => Some(Tok::RParen),
            b'{' => Some(Tok::LBrace),
            b'}' => Some(Tok::RBrace),
            b'[' => Some(Tok::LBracket),
            b']' => Some(Tok::RBracket),
            b',' => Some(Tok::Comma),
            b';' => Some(Tok::Semi),
            b'|' => Some(Tok::Pipe),
            b'+' => Some(Tok::Plus),
            b'-' => Some(Tok::Minus),
            b'*' => Some(Tok::Star),
            _ => None,
        };
        if text[i..].starts_with("//") {
            return Ok(());
        } else if text[i..].starts_with("/*") {
            *comment = Some(line);
            i += 2;
        } else if let Some(tok) = punct {
            out.push(Token { tok, line });
            i += 1;
        } else if c == b'\n' {
            // A continued line inside a directive-free logical line.
            line += 1;
            i += 1;
        } else if c.is_ascii_whitespace() || (c == b'\\' && bytes.get(i + 1) == Some(&b'\n')) {
            // Whitespace, or the backslash of a spliced line.
            i += 1;
        } else if c.is_ascii_alphabetic() || c == b'_' {
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            out.push(Token {
                tok: Tok::Ident(&text[start..i]),
                line,
            });
        } else if c.is_ascii_digit() || c == b'.' {
            let hex = text[i..].starts_with("0x") || text[i..].starts_with("0X");
            while i < bytes.len() {
                let b = bytes[i];
                // A sign belongs to the literal after a decimal exponent (e, E) or a hex
                // float's binary exponent (p, P).
                let exp = if hex { [b'p', b'P'] } else { [b'e', b'E'] };
                let exp_sign = (b == b'+' || b == b'-')
                    && bytes
                        .get(i.wrapping_sub(1))
                        .is_some_and(|p| exp.contains(p));
                if b.is_ascii_alphanumeric() || b == b'.' || exp_sign {
                    i += 1;
                } else {
                    break;
                }
            }
            out.push(Token {
                tok: Tok::Num(&text[start..i]),
                line,
            });
        } else {
            let ch = text[i..].chars().next().unwrap_or('?');
            return Err(ScriptError::UnexpectedChar { line, ch });
        }
    }
    Ok(())
}

/// The preprocessor's state: macros, the stack of open conditionals, and an open comment.
#[derive(Default)]
struct Preprocessor<'a> {
    macros: HashMap<&'a str, Vec<Tok<'a>>>,
    /// (this branch is kept, some branch of this #if was kept, line of the #if).
    conditions: Vec<(bool, bool, usize)>,
    comment: Option<usize>,
}

impl<'a> Preprocessor<'a> {
    fn active(&self) -> bool {
        self.conditions.iter().all(|(keep, _, _)| *keep)
    }

    fn directive(&mut self, text: &'a str, line: usize) -> Result<(), ScriptError> {
        let text = text.trim();
        let (name, rest) = text
            .split_once(|c: char| c.is_whitespace() || c == '(' || c == '"' || c == '<')
            .map_or((text, ""), |(n, _)| (n, text[n.len()..].trim()));
        let fail = |problem: String| Err(ScriptError::Preprocessor { line, problem });
        let outer = self.active();
        match name {
            "if" | "ifdef" | "ifndef" => {
                let keep = outer && self.condition(name, rest, line)?;
                self.conditions.push((keep, keep, line));
            }
            "elif" => {
                let Some(&(_, taken, open)) = self.conditions.last() else {
                    return fail("#elif without #if".into());
                };
                self.conditions.pop();
                let outer = self.active();
                let keep = outer && !taken && self.condition("if", rest, line)?;
                self.conditions.push((keep, taken || keep, open));
            }
            "else" => {
                let Some((_, taken, open)) = self.conditions.pop() else {
                    return fail("#else without #if".into());
                };
                let keep = self.active() && !taken;
                self.conditions.push((keep, true, open));
            }
            "endif" => {
                if self.conditions.pop().is_none() {
                    return fail("#endif without #if".into());
                }
            }
            _ if !outer => {}
            // Headers declare what the dialect already knows; nothing else they hold is
            // meaningful to a list of calls.
            "include" | "pragma" | "line" | "" => {}
            "define" => {
                let (macro_name, body) = rest
                    .split_once(|c: char| c.is_whitespace())
                    .unwrap_or((rest, ""));
                let (macro_name, function_like) = match macro_name.split_once('(') {
                    Some((n, _)) => (n, true),
                    None => (macro_name, false),
                };
                if function_like {
                    return fail(format!(
                        "#define {macro_name}(…): function-like macros are not supported; define a constant"
                    ));
                }
                if !is_identifier(macro_name) {
                    return fail(format!("#define needs a macro name, found {macro_name:?}"));
                }
                let mut toks = Vec::new();
                let mut comment = None;
                tokens(body, line, &mut comment, &mut toks)?;
                self.macros
                    .insert(macro_name, toks.into_iter().map(|t| t.tok).collect());
            }
            "undef" => {
                self.macros.remove(rest);
            }
            "error" => return fail(format!("#error {rest}")),
            other => {
                return fail(format!(
                    "#{other} is not supported (known: include, define, undef, if, ifdef, ifndef, elif, else, endif, pragma)"
                ))
            }
        }
        Ok(())
    }

    /// An #if/#ifdef/#ifndef condition.
    fn condition(&self, kind: &str, rest: &str, line: usize) -> Result<bool, ScriptError> {
        let defined = |n: &str| self.macros.contains_key(n.trim());
        match kind {
            "ifdef" => return Ok(defined(rest)),
            "ifndef" => return Ok(!defined(rest)),
            _ => {}
        }
        let (negate, expr) = match rest.strip_prefix('!') {
            Some(e) => (true, e.trim()),
            None => (false, rest),
        };
        let value = if let Some(arg) = expr.strip_prefix("defined") {
            let arg = arg.trim().trim_start_matches('(').trim_end_matches(')');
            Some(defined(arg))
        } else {
            let text = match self.macros.get(expr).map(Vec::as_slice) {
                Some([Tok::Num(n)]) => *n,
                _ => expr,
            };
            let digits = text.trim_end_matches(['u', 'U', 'l', 'L']);
            digits.parse::<i64>().ok().map(|v| v != 0)
        };
        match value {
            Some(v) => Ok(v != negate),
            None => Err(ScriptError::Preprocessor {
                line,
                problem: format!(
                    "#if {rest}: only an integer, defined NAME or a macro naming an integer is understood"
                ),
            }),
        }
    }

    /// The tokens with every macro name replaced by its expansion (at the use's line).
    /// `toks` with every macro expanded, each expansion charged to `budget`.
    fn expand(
        &self,
        toks: Vec<Token<'a>>,
        budget: &mut usize,
    ) -> Result<Vec<Token<'a>>, ScriptError> {
        if self.macros.is_empty() {
            return Ok(toks);
        }
        let mut out = Vec::with_capacity(toks.len());
        for t in toks {
            self.expand_one(t.tok, t.line, &mut Vec::new(), budget, &mut out)?;
        }
        Ok(out)
    }

    fn expand_one(
        &self,
        tok: Tok<'a>,
        line: usize,
        within: &mut Vec<&'a str>,
        budget: &mut usize,
        out: &mut Vec<Token<'a>>,
    ) -> Result<(), ScriptError> {
        let Tok::Ident(name) = tok else {
            out.push(Token { tok, line });
            return Ok(());
        };
        let Some(body) = self.macros.get(name).filter(|_| !within.contains(&name)) else {
            out.push(Token { tok, line });
            return Ok(());
        };
        if within.len() >= MAX_EXPANSION_DEPTH {
            return Err(ScriptError::Preprocessor {
                line,
                problem: format!(
                    "macro {name} expands more than {MAX_EXPANSION_DEPTH} levels deep"
                ),
            });
        }
        *budget = budget
            .checked_sub(body.len())
            .ok_or_else(|| ScriptError::Preprocessor {
                line,
                problem: format!(
                    "macro {name}: the script's macros expand to more than {MAX_EXPANDED_TOKENS} tokens"
                ),
            })?;
        within.push(name);
        for t in body {
            self.expand_one(*t, line, within, budget, out)?;
        }
        within.pop();
        Ok(())
    }
}

fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(src: &str) -> Vec<(Tok<'_>, usize)> {
        lex(src).unwrap().iter().map(|t| (t.tok, t.line)).collect()
    }

    #[test]
    fn lines_comments_and_numbers() {
        let toks = kinds("a(1.5e-3f, 0xFF); // x\n/* two\nlines */ b(-.5);");
        assert_eq!(toks[0], (Tok::Ident("a"), 1));
        assert_eq!(toks[2], (Tok::Num("1.5e-3f"), 1));
        assert_eq!(toks[4], (Tok::Num("0xFF"), 1));
        assert_eq!(toks[7], (Tok::Ident("b"), 3));
        assert_eq!(toks[9], (Tok::Minus, 3));
        assert_eq!(toks[10], (Tok::Num(".5"), 3));
        assert!(matches!(
            lex("/* open"),
            Err(ScriptError::UnterminatedComment { line: 1 })
        ));
        assert!(matches!(
            lex("\n@"),
            Err(ScriptError::UnexpectedChar { line: 2, ch: '@' })
        ));
    }

    #[test]
    fn hex_floats_keep_their_binary_exponent_sign() {
        let toks = kinds("f(0x1.8p-3f, 0X1P+4);");
        assert_eq!(toks[2], (Tok::Num("0x1.8p-3f"), 1));
        assert_eq!(toks[4], (Tok::Num("0X1P+4"), 1));
    }

    #[test]
    fn a_byte_order_mark_is_skipped() {
        assert_eq!(kinds("\u{FEFF}f();")[0], (Tok::Ident("f"), 1));
    }

    #[test]
    fn includes_are_skipped_and_defines_expand() {
        let src = "#include <GL/gl.h>\n#include \"x.h\"\n#define SIZE 64\n#define W SIZE\nf(W, SIZE);\n#undef SIZE\ng(SIZE);";
        let toks = kinds(src);
        assert_eq!(toks[2], (Tok::Num("64"), 5));
        assert_eq!(toks[4], (Tok::Num("64"), 5));
        assert_eq!(toks[9], (Tok::Ident("SIZE"), 7));
    }

    #[test]
    fn conditionals_keep_one_branch() {
        let src = "#define A 1\n#if 0\nx();\n#elif defined(A)\ny();\n#else\nz();\n#endif\n#ifndef A\nw();\n#endif";
        let names: Vec<_> = kinds(src)
            .into_iter()
            .filter_map(|(t, _)| match t {
                Tok::Ident(n) => Some(n),
                _ => None,
            })
            .collect();
        assert_eq!(names, vec!["y"]);
    }

    #[test]
    fn unsupported_directives_name_the_line() {
        assert!(matches!(
            lex("f();\n#define SQ(x) ((x)*(x))"),
            Err(ScriptError::Preprocessor { line: 2, .. })
        ));
        assert!(matches!(
            lex("#if 1\nf();"),
            Err(ScriptError::Preprocessor { line: 1, .. })
        ));
        assert!(lex("#define A B\n#define B A\nA").is_ok());
    }

    /// A timeout of the script fuzz target (`fuzz/run.sh script`, 5 s per input): 24 macros,
    /// each naming the next twice, made 2²⁴ tokens from 500 bytes; now the expansion budget
    /// refuses it at the line that used it.
    #[test]
    fn doubling_macros_are_refused_not_expanded() {
        let mut src: String = (0..24)
            .map(|i| format!("#define M{i} M{j} M{j}\n", j = i + 1))
            .collect();
        src.push_str("glBegin(M0);\n");
        let started = std::time::Instant::now();
        match lex(&src) {
            Err(ScriptError::Preprocessor { line: 25, problem }) => {
                assert!(problem.contains("expand to more than"), "{problem}")
            }
            other => panic!("expected a preprocessor error at line 25, got {other:?}"),
        }
        assert!(started.elapsed().as_secs() < 5);
        // Within the budget, a doubling chain still expands in full.
        let mut src: String = (0..10)
            .map(|i| format!("#define M{i} M{j} M{j}\n", j = i + 1))
            .collect();
        src.push_str("M0");
        assert_eq!(lex(&src).map(|t| t.len()), Ok(1024));
    }

    #[test]
    fn tokens_are_named_as_in_c() {
        assert_eq!(Tok::Semi.describe(), "';'");
        assert_eq!(Tok::RParen.describe(), "')'");
    }
}
