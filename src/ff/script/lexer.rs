//! Tokens of the script's C subset: identifiers, numbers, punctuation; `//` and `/* */`
//! comments and whitespace skipped; every token carries its line (1-based).

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
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Token<'a> {
    pub tok: Tok<'a>,
    pub line: usize,
}

pub fn lex(src: &str) -> Result<Vec<Token<'_>>, ScriptError> {
    let bytes = src.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    let mut line = 1;
    while i < bytes.len() {
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
            _ => None,
        };
        if let Some(tok) = punct {
            out.push(Token { tok, line });
            i += 1;
        } else if c == b'\n' {
            line += 1;
            i += 1;
        } else if c.is_ascii_whitespace() {
            i += 1;
        } else if src[i..].starts_with("//") {
            while i < bytes.len() && bytes[i] != b'\n' {
                i += 1;
            }
        } else if src[i..].starts_with("/*") {
            let open = line;
            let end = src[i + 2..]
                .find("*/")
                .ok_or(ScriptError::UnterminatedComment { line: open })?;
            line += src[i..i + 2 + end].matches('\n').count();
            i += end + 4;
        } else if c.is_ascii_alphabetic() || c == b'_' {
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            out.push(Token {
                tok: Tok::Ident(&src[start..i]),
                line,
            });
        } else if c.is_ascii_digit() || c == b'.' {
            let hex = src[i..].starts_with("0x") || src[i..].starts_with("0X");
            while i < bytes.len() {
                let b = bytes[i];
                let exp_sign = !hex
                    && (b == b'+' || b == b'-')
                    && matches!(bytes.get(i.wrapping_sub(1)), Some(b'e' | b'E'));
                if b.is_ascii_alphanumeric() || b == b'.' || exp_sign {
                    i += 1;
                } else {
                    break;
                }
            }
            out.push(Token {
                tok: Tok::Num(&src[start..i]),
                line,
            });
        } else {
            let ch = src[i..].chars().next().unwrap_or('?');
            return Err(ScriptError::UnexpectedChar { line, ch });
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_comments_and_numbers() {
        let toks = lex("a(1.5e-3f, 0xFF); // x\n/* two\nlines */ b(-.5);").unwrap();
        let kinds: Vec<_> = toks.iter().map(|t| (t.tok, t.line)).collect();
        assert_eq!(kinds[0], (Tok::Ident("a"), 1));
        assert_eq!(kinds[2], (Tok::Num("1.5e-3f"), 1));
        assert_eq!(kinds[4], (Tok::Num("0xFF"), 1));
        assert_eq!(kinds[7], (Tok::Ident("b"), 3));
        assert_eq!(kinds[9], (Tok::Minus, 3));
        assert_eq!(kinds[10], (Tok::Num(".5"), 3));
        assert!(matches!(
            lex("/* open"),
            Err(ScriptError::UnterminatedComment { line: 1 })
        ));
        assert!(matches!(
            lex("\n@"),
            Err(ScriptError::UnexpectedChar { line: 2, ch: '@' })
        ));
    }
}
