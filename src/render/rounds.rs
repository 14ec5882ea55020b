//! Round-robin frames over several open sessions: frame k of every live session before
//! frame k + 1 of any, so that machine noise — another build, a frequency step — hits all
//! of them alike instead of whichever happened to run during it.
//!
//! `study::compare` and `bench::techniques` both drive their sessions through [`run`]. What
//! differs between them is written as [`Rules`]: what a failed frame means (the session
//! leaves the rounds and its row says why, or the whole run stops) and what is counted
//! after each turn and each round (progress steps, frame times, a progress tick).

use super::{RenderError, Session};

/// One session in the rounds and what its caller keeps beside it.
pub struct Lane<T> {
    pub tag: T,
    /// The open session, or why it is out of the rounds (its setup or a frame failed).
    pub session: Result<Session, RenderError>,
}

/// What becomes of a lane whose frame failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// It leaves the rounds (its session is released at once); the others go on.
    Retire,
    /// The rounds stop: [`run`] returns [`Stopped`].
    Stop,
}

/// The rounds stopped on a failed frame.
#[derive(Debug)]
pub struct Stopped {
    /// Index of the lane whose frame failed.
    pub lane: usize,
    pub error: RenderError,
}

/// What a caller of [`run`] decides and counts.
pub trait Rules<T> {
    /// `tag`'s frame failed with `error`.
    fn failed(&mut self, tag: &T, error: &RenderError) -> Verdict;

    /// `tag`'s turn in `round` (1-based) is over: `ms` is its frame's time, `None` when
    /// the lane is out of the rounds (from this turn or an earlier one).
    fn turn(&mut self, _round: u32, _tag: &mut T, _ms: Option<f64>) {}

    /// Every lane had its turn in `round`.
    fn round_done(&mut self, _round: u32) {}
}

/// `rounds` rounds of one frame per live lane, in lane order.
pub fn run<T>(
    lanes: &mut [Lane<T>],
    rounds: u32,
    rules: &mut impl Rules<T>,
) -> Result<(), Stopped> {
    for round in 1..=rounds {
        for (i, lane) in lanes.iter_mut().enumerate() {
            let mut ms = None;
            if let Ok(session) = &mut lane.session {
                match session.frame() {
                    Ok(t) => ms = Some(t),
                    Err(error) => {
                        if rules.failed(&lane.tag, &error) == Verdict::Stop {
                            return Err(Stopped { lane: i, error });
                        }
                        // Dropping the session releases its context now.
                        lane.session = Err(error);
                    }
                }
            }
            rules.turn(round, &mut lane.tag, ms);
        }
        rules.round_done(round);
    }
    Ok(())
}
