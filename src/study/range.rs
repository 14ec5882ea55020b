//! One axis of a sweep, written `A..B[:steps]`: `steps` evenly spaced values from A to B
//! inclusive, value i = A + (B − A) · i / (steps − 1). Without `:steps` a range takes
//! [`DEFAULT_STEPS`] values; a bare number `A` (or `A..A`) is the single value A.
//!
//! Refused, with the reason: A > B, zero steps, more than [`MAX_STEPS`], NaN or infinite
//! ends, one step over A < B (which value would it be?), several steps over A = B (the
//! same value again), and anything that is not of that shape.

use std::fmt;
use std::str::FromStr;

/// Values taken by `A..B` when no step count is given.
pub const DEFAULT_STEPS: u32 = 5;
/// The most values one axis may take (a grid of 64 × 64 cells is already 4096 renders).
pub const MAX_STEPS: u32 = 64;

/// Why a range was refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RangeProblem {
    #[error("expected A..B[:steps] or a single number, e.g. 0..4:9")]
    Format,
    #[error("`{0}` is not a finite number")]
    NotFinite(String),
    #[error("the start {a} is greater than the end {b}")]
    Reversed { a: f32, b: f32 },
    #[error("the step count must be at least 1")]
    ZeroSteps,
    #[error("at most {MAX_STEPS} steps per axis")]
    TooManySteps,
    #[error("one step cannot span {a}..{b}: give A..A, or 2 steps or more")]
    OneStepOverSpan { a: f32, b: f32 },
    #[error("{steps} steps over {a}..{a} repeat one value: give {a} alone")]
    RepeatedValue { a: f32, steps: u32 },
}

/// An inclusive, evenly stepped range of values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepRange {
    pub start: f32,
    pub end: f32,
    pub steps: u32,
}

impl SweepRange {
    /// The single value `v`.
    pub fn single(v: f32) -> SweepRange {
        SweepRange {
            start: v,
            end: v,
            steps: 1,
        }
    }

    /// The values, from start to end inclusive.
    pub fn values(&self) -> Vec<f32> {
        if self.steps <= 1 {
            return vec![self.start];
        }
        let span = f64::from(self.end) - f64::from(self.start);
        let last = f64::from(self.steps - 1);
        (0..self.steps)
            .map(|i| (f64::from(self.start) + span * f64::from(i) / last) as f32)
            .collect()
    }

    /// The distance between neighbouring values (0 for a single value).
    pub fn spacing(&self) -> f64 {
        if self.steps <= 1 {
            0.0
        } else {
            (f64::from(self.end) - f64::from(self.start)) / f64::from(self.steps - 1)
        }
    }

    /// `steps` values `spacing` apart with `centre` at index ⌊(steps − 1)/2⌋ (the middle
    /// value, or the lower of the two middle ones), the whole range moved up when its
    /// start would fall below `lowest`: it then starts at `lowest` and `centre` lies nearer
    /// its low end (or between two of its values). `steps` ≥ 2 and `spacing` > 0.
    pub fn around(centre: f32, spacing: f64, steps: u32, lowest: f32) -> SweepRange {
        let below = f64::from((steps.max(2) - 1) / 2);
        let start = (f64::from(centre) - spacing * below).max(f64::from(lowest));
        let end = start + spacing * f64::from(steps.max(2) - 1);
        SweepRange {
            start: start as f32,
            end: end as f32,
            steps: steps.max(2),
        }
    }
}

fn number(text: &str) -> Result<f32, RangeProblem> {
    let t = text.trim();
    let v: f32 = t.parse().map_err(|_| RangeProblem::Format)?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(RangeProblem::NotFinite(t.to_string()))
    }
}

impl FromStr for SweepRange {
    type Err = RangeProblem;

    fn from_str(text: &str) -> Result<SweepRange, RangeProblem> {
        let text = text.trim();
        let Some((a, rest)) = text.split_once("..") else {
            return number(text).map(SweepRange::single);
        };
        if rest.starts_with('.') {
            return Err(RangeProblem::Format);
        }
        let (b, steps) = match rest.split_once(':') {
            Some((b, s)) => {
                let s = s.trim();
                if s.is_empty() || !s.bytes().all(|c| c.is_ascii_digit()) {
                    return Err(RangeProblem::Format);
                }
                let n: u32 = s.parse().map_err(|_| RangeProblem::TooManySteps)?;
                (b, Some(n))
            }
            None => (rest, None),
        };
        let (a, b) = (number(a)?, number(b)?);
        if a > b {
            return Err(RangeProblem::Reversed { a, b });
        }
        let steps = match steps {
            Some(0) => return Err(RangeProblem::ZeroSteps),
            Some(n) if n > MAX_STEPS => return Err(RangeProblem::TooManySteps),
            Some(1) if a < b => return Err(RangeProblem::OneStepOverSpan { a, b }),
            Some(n) if n > 1 && a == b => return Err(RangeProblem::RepeatedValue { a, steps: n }),
            Some(n) => n,
            None if a == b => 1,
            None => DEFAULT_STEPS,
        };
        Ok(SweepRange {
            start: a,
            end: b,
            steps,
        })
    }
}

impl fmt::Display for SweepRange {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.steps == 1 {
            write!(f, "{}", self.start)
        } else {
            write!(f, "{}..{}:{}", self.start, self.end, self.steps)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ok(s: &str) -> Vec<f32> {
        s.parse::<SweepRange>()
            .unwrap_or_else(|e| panic!("{s}: {e}"))
            .values()
    }

    fn problem(s: &str) -> RangeProblem {
        s.parse::<SweepRange>().expect_err(s)
    }

    #[test]
    fn ranges_give_evenly_spaced_inclusive_values() {
        assert_eq!(ok("0..4:5"), vec![0.0, 1.0, 2.0, 3.0, 4.0]);
        assert_eq!(ok("-1..1:3"), vec![-1.0, 0.0, 1.0]);
        assert_eq!(ok("0..8"), vec![0.0, 2.0, 4.0, 6.0, 8.0]);
        assert_eq!(ok("2.5"), vec![2.5]);
        assert_eq!(ok("1..1"), vec![1.0]);
        assert_eq!(ok(" 1 .. 1 :1 "), vec![1.0]);
        let v = ok("0..1:11");
        assert_eq!((v.len(), v[0], v[10]), (11, 0.0, 1.0));
        assert_eq!(
            "0..4:5".parse::<SweepRange>().map(|r| r.to_string()),
            Ok("0..4:5".into())
        );
    }

    #[test]
    fn a_range_around_a_value_centres_it_and_stops_at_the_lowest() {
        let r = SweepRange::around(1.0, 0.5, 3, 0.0);
        assert_eq!((r.values(), r.spacing()), (vec![0.5, 1.0, 1.5], 0.5));
        // Four values: the centre is the lower of the two middle ones.
        assert_eq!(
            SweepRange::around(2.0, 1.0, 4, 0.0).values(),
            [1.0, 2.0, 3.0, 4.0]
        );
        // It would start at −0.25: moved up to start at 0.
        assert_eq!(
            SweepRange::around(0.25, 0.5, 3, 0.0).values(),
            [0.0, 0.5, 1.0]
        );
        assert_eq!(
            SweepRange::around(-1.0, 1.0, 3, -4.0).values(),
            [-2.0, -1.0, 0.0]
        );
        assert_eq!(SweepRange::single(3.0).spacing(), 0.0);
        assert_eq!(ok_range("0..4:5").spacing(), 1.0);
    }

    fn ok_range(s: &str) -> SweepRange {
        s.parse().unwrap_or_else(|e| panic!("{s}: {e}"))
    }

    #[test]
    fn bad_ranges_say_why() {
        assert_eq!(problem("4..1"), RangeProblem::Reversed { a: 4.0, b: 1.0 });
        assert_eq!(problem("0..4:0"), RangeProblem::ZeroSteps);
        assert_eq!(problem("0..4:65"), RangeProblem::TooManySteps);
        assert_eq!(problem("0..4:99999999999"), RangeProblem::TooManySteps);
        assert_eq!(problem("NaN..4"), RangeProblem::NotFinite("NaN".into()));
        assert_eq!(problem("0..inf:3"), RangeProblem::NotFinite("inf".into()));
        assert_eq!(
            problem("0..4:1"),
            RangeProblem::OneStepOverSpan { a: 0.0, b: 4.0 }
        );
        assert_eq!(
            problem("2..2:3"),
            RangeProblem::RepeatedValue { a: 2.0, steps: 3 }
        );
        for s in [
            "", "a..b", "0..", "..4", "0..4:", "0..4:x", "0..4:-2", "0..4:2.5", "1,4", "0...4",
        ] {
            assert_eq!(problem(s), RangeProblem::Format, "{s:?}");
        }
        for p in [problem("4..1"), problem("0..4:0"), problem("x")] {
            assert!(!p.to_string().is_empty());
        }
    }
}
