//! CSV as RFC 4180 writes it: comma-separated, a header line, fields quoted (with inner
//! quotes doubled) only when they hold a comma, quote or line break. Written by hand: the
//! files are a few dozen lines of numbers and names, and nothing here is ever parsed.

/// One CSV line (with its `\n`) from fields.
pub fn line<S: AsRef<str>>(fields: &[S]) -> String {
    let mut out = fields
        .iter()
        .map(|f| field(f.as_ref()))
        .collect::<Vec<_>>()
        .join(",");
    out.push('\n');
    out
}

fn field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// A number, or an empty field for none.
pub fn opt<T: ToString>(v: Option<T>) -> String {
    v.map_or(String::new(), |v| v.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_quoted_only_when_needed() {
        assert_eq!(line(&["a", "1.5", ""]), "a,1.5,\n");
        assert_eq!(
            line(&["x,y", "say \"hi\"", "two\nlines"]),
            "\"x,y\",\"say \"\"hi\"\"\",\"two\nlines\"\n"
        );
        assert_eq!(opt(Some(3)), "3");
        assert_eq!(opt::<u32>(None), "");
    }
}
