//! What one run of `abi_bench.c` printed, read back: one record per line, `key value…`
//! (the format is written at the top of the C source). A run counts only when every record
//! is there and the last one, `errors 0`, says the program checked its GL error flag and
//! its image after the frames; anything else is an error naming the line.

use super::{AbiError, AbiMode};
use crate::vocab::Named;

/// One run's records.
#[derive(Clone, Debug, PartialEq)]
pub struct RunOutput {
    /// `glGetString(GL_VENDOR)`: `fixedfunc` on the layer's library.
    pub vendor: String,
    pub renderer: String,
    pub mode: AbiMode,
    /// Vertices submitted per frame (indices for indexed draws).
    pub vertices: u64,
    /// Draw calls per frame (glEnd, glDrawElements or glCallList).
    pub draws: u64,
    /// Each frame's time in ms, first frame first (clear … glFinish).
    pub frame_ms: Vec<f64>,
    /// Pixels of the last frame not of the clear colour.
    pub drawn: u64,
    /// Drawn pixels under 16 in every channel (in shadow).
    pub dark: u64,
    /// Drawn pixels over 96 in some channel.
    pub lit: u64,
    /// Mean R, G, B of the last frame, 0…255.
    pub mean: [f64; 3],
}

/// Reads a run's standard output.
pub fn parse(text: &str) -> Result<RunOutput, AbiError> {
    let mut fields = Fields::default();
    let mut complete = false;
    for (i, line) in text.lines().enumerate() {
        let bad = |reason: &str| AbiError::Output {
            line: i + 1,
            text: line.to_string(),
            reason: reason.to_string(),
        };
        let (key, rest) = line.split_once(' ').unwrap_or((line, ""));
        match key {
            "vendor" => fields.vendor = Some(rest.to_string()),
            "renderer" => fields.renderer = Some(rest.to_string()),
            "mode" => {
                fields.mode = Some(AbiMode::from_name(rest).ok_or_else(|| {
                    bad(&format!(
                        "not a mode; the modes are {}",
                        AbiMode::names().join(", ")
                    ))
                })?)
            }
            "vertices" => fields.vertices = Some(number(rest).ok_or_else(|| bad("not a count"))?),
            "draws" => fields.draws = Some(number(rest).ok_or_else(|| bad("not a count"))?),
            "drawn" => fields.drawn = Some(number(rest).ok_or_else(|| bad("not a count"))?),
            "dark" => fields.dark = Some(number(rest).ok_or_else(|| bad("not a count"))?),
            "lit" => fields.lit = Some(number(rest).ok_or_else(|| bad("not a count"))?),
            "frame" => {
                let (index, ms) = frame(rest).ok_or_else(|| bad("not `frame INDEX MS`"))?;
                if index != fields.frame_ms.len() {
                    return Err(bad(&format!(
                        "frame {} was expected",
                        fields.frame_ms.len()
                    )));
                }
                fields.frame_ms.push(ms);
            }
            "mean" => fields.mean = Some(mean(rest).ok_or_else(|| bad("not three means"))?),
            "errors" if rest == "0" => complete = true,
            _ => return Err(bad("not a record the program writes")),
        }
    }
    let missing = |what: &'static str| AbiError::Incomplete { missing: what };
    if !complete {
        return Err(missing("errors 0"));
    }
    if fields.frame_ms.is_empty() {
        return Err(missing("frame"));
    }
    Ok(RunOutput {
        vendor: fields.vendor.ok_or(missing("vendor"))?,
        renderer: fields.renderer.ok_or(missing("renderer"))?,
        mode: fields.mode.ok_or(missing("mode"))?,
        vertices: fields.vertices.ok_or(missing("vertices"))?,
        draws: fields.draws.ok_or(missing("draws"))?,
        frame_ms: fields.frame_ms,
        drawn: fields.drawn.ok_or(missing("drawn"))?,
        dark: fields.dark.ok_or(missing("dark"))?,
        lit: fields.lit.ok_or(missing("lit"))?,
        mean: fields.mean.ok_or(missing("mean"))?,
    })
}

#[derive(Default)]
struct Fields {
    vendor: Option<String>,
    renderer: Option<String>,
    mode: Option<AbiMode>,
    vertices: Option<u64>,
    draws: Option<u64>,
    frame_ms: Vec<f64>,
    drawn: Option<u64>,
    dark: Option<u64>,
    lit: Option<u64>,
    mean: Option<[f64; 3]>,
}

fn number(text: &str) -> Option<u64> {
    text.parse().ok()
}

/// A time or a mean: finite and not negative.
fn measure(text: &str) -> Option<f64> {
    text.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite() && *v >= 0.0)
}

fn frame(text: &str) -> Option<(usize, f64)> {
    let (index, ms) = text.split_once(' ')?;
    Some((index.parse().ok()?, measure(ms)?))
}

fn mean(text: &str) -> Option<[f64; 3]> {
    let mut parts = text.split(' ').map(measure);
    let means = [parts.next()??, parts.next()??, parts.next()??];
    parts.next().is_none().then_some(means)
}

#[cfg(test)]
mod tests {
    use super::*;

    const GOOD: &str = "vendor Mesa/X.org\nrenderer llvmpipe (LLVM 15.0.6, 256 bits)\n\
        mode arrays\nvertices 110592\ndraws 16\nframe 0 9.5\nframe 1 3.25\ndrawn 41252\n\
        dark 0\nlit 31871\nmean 124.389 111.519 91.143\nerrors 0\n";

    #[test]
    fn a_complete_run_is_read() {
        let run = parse(GOOD).expect("parses");
        assert_eq!(run.vendor, "Mesa/X.org");
        assert_eq!(run.renderer, "llvmpipe (LLVM 15.0.6, 256 bits)");
        assert_eq!(run.mode, AbiMode::Arrays);
        assert_eq!((run.vertices, run.draws), (110_592, 16));
        assert_eq!(run.frame_ms, vec![9.5, 3.25]);
        assert_eq!((run.drawn, run.dark, run.lit), (41_252, 0, 31_871));
        assert_eq!(run.mean, [124.389, 111.519, 91.143]);
    }

    /// Each broken output is refused, at its line where it has one.
    #[test]
    fn broken_outputs_are_refused() {
        let cases: &[(&str, &str)] = &[
            // Stopped before its checks: no `errors 0`.
            (GOOD.trim_end_matches("errors 0\n"), "errors 0"),
            (&GOOD.replace("mode arrays", "mode spheres"), "line 3"),
            (&GOOD.replace("frame 1 3.25", "frame 1 fast"), "line 7"),
            (&GOOD.replace("frame 1 3.25", "frame 1 -3"), "line 7"),
            (
                &GOOD.replace("frame 1 3.25", "frame 2 3.25"),
                "frame 1 was expected",
            ),
            (&GOOD.replace("vertices 110592", "vertices many"), "line 4"),
            (
                &GOOD.replace("mean 124.389 111.519 91.143", "mean 1 2"),
                "line 11",
            ),
            (&GOOD.replace("dark 0\n", ""), "dark"),
            (&GOOD.replace("errors 0", "errors 1"), "line 12"),
            (&GOOD.replace("draws 16", "triangles 16"), "line 5"),
            ("", "errors 0"),
        ];
        for (text, expected) in cases {
            let error = parse(text).expect_err(text).to_string();
            assert!(error.contains(expected), "{error:?} lacks {expected:?}");
        }
    }
}
