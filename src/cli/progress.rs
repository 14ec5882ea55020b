//! The progress of the study commands, on stderr, also when stderr is not a terminal.
//!
//! On a terminal an indicatif bar follows the study's [`Progress`]. Anywhere else — a CI
//! log, a pipe, a file — indicatif draws nothing, so plain lines take its place, one at the
//! first report and then at most one every [`INTERVAL_MS`] ms (default 5 s):
//!
//! ```text
//! sweep-bias: 812/4096 cells, 1m05s elapsed, ~4m20s left
//! ```
//!
//! A study whose units are alike (a sweep's cells) also gets an estimate of the whole,
//! printed once two units are done, from the second (the first also creates the context
//! and compiles the programs): `sweep-bias: 4096 cells × ~28 ms ≈ 1m55s`.

use std::io::IsTerminal;
use std::time::{Duration, Instant};

use fixedfunc::study::Progress;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// The environment variable that sets the time between progress lines, in milliseconds
/// (0: a line at every report).
pub const INTERVAL_MS: &str = "FIXEDFUNC_PROGRESS_INTERVAL_MS";
const DEFAULT_INTERVAL: Duration = Duration::from_secs(5);

/// Whether a study's units are alike enough to estimate the whole from one of them.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Estimate {
    /// Print `N units × ~T ≈ total` once two units are done.
    FromSecondUnit,
    Never,
}

/// Follows a study's [`Progress`] reports: a bar on a terminal, lines elsewhere.
pub struct StudyBar {
    command: &'static str,
    bar: Option<ProgressBar>,
    interval: Duration,
    estimate: Estimate,
    start: Instant,
    /// When the first report came (the work in units starts there) and its count.
    first: Option<(Instant, u64)>,
    /// The previous report, for the estimate.
    previous: Option<(Instant, u64)>,
    last_line: Option<Instant>,
    estimated: bool,
}

/// The interval between progress lines, from [`INTERVAL_MS`].
fn interval() -> Duration {
    match std::env::var(INTERVAL_MS) {
        Err(_) => DEFAULT_INTERVAL,
        Ok(text) => match text.trim().parse::<u64>() {
            Ok(ms) => Duration::from_millis(ms),
            Err(_) => {
                eprintln!(
                    "warning: {INTERVAL_MS}={text:?} is not a number of milliseconds; \
                     progress lines every {} s",
                    DEFAULT_INTERVAL.as_secs()
                );
                DEFAULT_INTERVAL
            }
        },
    }
}

/// A duration as a person reads it: `0.4s`, `42s`, `4m20s`, `2h03m`.
pub fn span(d: Duration) -> String {
    let s = d.as_secs_f64();
    if s < 10.0 {
        format!("{s:.1}s")
    } else if s < 60.0 {
        format!("{s:.0}s")
    } else if s < 3600.0 {
        let s = s.round() as u64;
        format!("{}m{:02}s", s / 60, s % 60)
    } else {
        let m = (s / 60.0).round() as u64;
        format!("{}h{:02}m", m / 60, m % 60)
    }
}

/// The time of one unit: `~28 ms`, `~1.2 s`.
fn per_unit(d: Duration) -> String {
    let ms = d.as_secs_f64() * 1e3;
    if ms < 1000.0 {
        format!("~{ms:.0} ms")
    } else {
        format!("~{:.1} s", ms / 1e3)
    }
}

impl StudyBar {
    /// `command` names the lines (`sweep-bias`).
    pub fn new(command: &'static str, estimate: Estimate) -> StudyBar {
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = ProgressBar::with_draw_target(Some(1), ProgressDrawTarget::stderr());
            bar.set_style(
                ProgressStyle::with_template("[{bar:32}] {pos}/{len} {elapsed_precise} {msg}")
                    .unwrap_or_else(|_| ProgressStyle::default_bar())
                    .progress_chars("=> "),
            );
            bar
        });
        StudyBar {
            command,
            bar,
            interval: interval(),
            estimate,
            start: Instant::now(),
            first: None,
            previous: None,
            last_line: None,
            estimated: false,
        }
    }

    /// A line above the bar, or on its own line without one.
    fn say(&self, line: &str) {
        match &self.bar {
            Some(bar) => bar.println(line),
            None => eprintln!("{line}"),
        }
    }

    pub fn update(&mut self, p: Progress) {
        let now = Instant::now();
        let first = *self.first.get_or_insert((now, p.done));
        if let Some(bar) = &self.bar {
            bar.set_length(p.total);
            bar.set_position(p.done);
            bar.set_message(p.what.clone());
        }
        self.estimate(now, &p);
        self.previous = Some((now, p.done));
        let due = self
            .last_line
            .is_none_or(|last| now.duration_since(last) >= self.interval);
        if self.bar.is_none() && due && p.done < p.total {
            let mut line = format!(
                "{}: {}/{} {}, {} elapsed",
                self.command,
                p.done,
                p.total,
                p.unit,
                span(now.duration_since(self.start))
            );
            let (t0, done0) = first;
            if p.done > done0 {
                let rate = now.duration_since(t0).as_secs_f64() / (p.done - done0) as f64;
                let left = Duration::from_secs_f64(rate * (p.total - p.done) as f64);
                line.push_str(&format!(", ~{} left", span(left)));
            }
            self.say(&line);
            self.last_line = Some(now);
        }
    }

    /// Prints the estimate once the second unit is done (see the module note).
    fn estimate(&mut self, now: Instant, p: &Progress) {
        if self.estimate == Estimate::Never || self.estimated || p.total <= 2 {
            return;
        }
        let Some((then, before)) = self.previous else {
            return;
        };
        if before == 0 || p.done <= before {
            return;
        }
        let unit = now.duration_since(then).div_f64((p.done - before) as f64);
        self.estimated = true;
        self.say(&format!(
            "{}: {} {} × {} ≈ {}",
            self.command,
            p.total,
            p.unit,
            per_unit(unit),
            span(Duration::from_secs_f64(unit.as_secs_f64() * p.total as f64))
        ));
    }

    pub fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

/// Counted steps of work that is not a study (`bench`'s groups), reported as a study's
/// are: a bar on a terminal, lines with the time left elsewhere.
pub struct CountBar {
    bar: StudyBar,
    done: u64,
    total: u64,
    unit: &'static str,
    what: String,
}

impl CountBar {
    pub fn new(command: &'static str, total: u64, unit: &'static str) -> CountBar {
        CountBar {
            bar: StudyBar::new(command, Estimate::FromSecondUnit),
            done: 0,
            total,
            unit,
            what: String::new(),
        }
    }

    /// What the next steps are of (shown on the bar).
    pub fn set_what(&mut self, what: String) {
        self.what = what;
    }

    /// One more step done.
    pub fn inc(&mut self) {
        self.done += 1;
        self.bar.update(Progress {
            done: self.done,
            total: self.total,
            unit: self.unit,
            what: self.what.clone(),
        });
    }

    /// A line above the bar, or on its own line without one.
    pub fn println(&self, line: &str) {
        self.bar.say(line);
    }

    pub fn finish(&self) {
        self.bar.finish();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_read_as_a_person_reads_them() {
        assert_eq!(span(Duration::from_millis(420)), "0.4s");
        assert_eq!(span(Duration::from_secs(42)), "42s");
        assert_eq!(span(Duration::from_secs(260)), "4m20s");
        assert_eq!(span(Duration::from_secs(2 * 3600 + 3 * 60)), "2h03m");
        assert_eq!(per_unit(Duration::from_millis(28)), "~28 ms");
        assert_eq!(per_unit(Duration::from_millis(1200)), "~1.2 s");
    }
}
