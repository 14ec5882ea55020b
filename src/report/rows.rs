//! One flat, serialisable row per technique × pipeline, and the Pareto front.
//!
//! Pareto front over (time, error), both minimised: a row is on it when no other row is at
//! least as fast and at least as accurate and strictly better in one of the two. The time
//! is the typical frame (steady median; the cold frame when it is the only one).

use crate::vocab::{offset_text, OffsetSource, PipelineKind, TechniqueId};
use serde::Serialize;

use crate::gpu::Backend;
use crate::render::RenderOutcome;
use crate::scene::Scene;
use crate::study::{Row, RowResult};
use crate::techniques;

use super::objects::ObjectShare;

/// The figures of a measured row.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Measured {
    /// 100 · wrong / truth geometry pixels (the `render` line's error %).
    pub error_percent: f64,
    /// Truth lit, technique shadowed (acne, too little bias).
    pub false_shadow: u64,
    /// Truth shadowed, technique lit (peter-panning, too much bias).
    pub missed_shadow: u64,
    /// Technique background where the truth has geometry.
    pub coverage: u64,
    pub geometry_pixels: u64,
    /// Half-width of the edge band, pixels.
    pub band: u32,
    /// Error % outside the band around the truth's shadow edges.
    pub outside_band_error_percent: f64,
    pub outside_band_false_shadow: u64,
    pub outside_band_missed_shadow: u64,
    /// Against an area light's truth (`metrics::visibility_errors`; a hard mask counts as
    /// visibility 0 or 1): RMSE, maximum |error| and RMSE in the truth's penumbra. `None`
    /// for other lights (and the penumbra's when the truth has none).
    pub visibility_rmse: Option<f64>,
    pub visibility_max_abs: Option<f64>,
    pub penumbra_rmse: Option<f64>,
    /// Steady frames (2…N): median, min, max; `None` with one frame.
    pub ms_median: Option<f64>,
    pub ms_min: Option<f64>,
    pub ms_max: Option<f64>,
    pub steady_frames: usize,
    pub cold_ms: f64,
    /// The time plotted and ranked: the steady median, or the cold frame alone.
    pub typical_ms: f64,
    pub passes: usize,
    pub programs_compiled: u64,
    pub maps_made: u32,
    /// What the technique says about this scene.
    pub notes: Vec<String>,
    /// The polygon offset as `FACTOR,UNITS` or `none`, and where it came from; `None` for
    /// a technique that reads no offset.
    pub offset: Option<String>,
    pub offset_source: Option<OffsetSource>,
    /// glGetString(GL_RENDERER) and (GL_VERSION) of the context the row ran on.
    pub gl_renderer: String,
    pub gl_version: String,
    /// Each object's share of the error, in scene order; empty for a scene of one object
    /// (`super::objects`).
    pub objects: Vec<ObjectShare>,
}

impl Measured {
    /// `1,4 (technique default)`, or `—` for a technique that reads no offset.
    pub fn offset_cell(&self) -> String {
        match (&self.offset, self.offset_source) {
            (Some(o), Some(source)) => format!("{o} ({source})"),
            _ => "—".to_string(),
        }
    }
}

impl Measured {
    /// From a render outcome of `scene`, through the same `figures()` `render` prints
    /// (and the same per-object split; `scene` names its objects).
    pub fn of(outcome: &RenderOutcome, scene: &Scene) -> Measured {
        let fig = outcome.figures();
        let band = &outcome.metrics.outside_band;
        let steady = fig.timings.steady;
        Measured {
            error_percent: fig.wrong_percent,
            false_shadow: fig.false_shadow,
            missed_shadow: fig.missed_shadow,
            coverage: outcome.metrics.all.coverage,
            geometry_pixels: outcome.metrics.all.pixels,
            band: outcome.metrics.band,
            outside_band_error_percent: band.wrong_percent,
            outside_band_false_shadow: band.false_shadow,
            outside_band_missed_shadow: band.missed_shadow,
            visibility_rmse: fig.visibility_rmse,
            visibility_max_abs: outcome.visibility.as_ref().map(|v| v.errors.max_abs),
            penumbra_rmse: outcome
                .visibility
                .as_ref()
                .and_then(|v| v.errors.penumbra_rmse),
            ms_median: steady.map(|s| s.median),
            ms_min: steady.map(|s| s.min),
            ms_max: steady.map(|s| s.max),
            steady_frames: steady.map_or(0, |s| s.samples),
            cold_ms: fig.timings.cold_ms,
            typical_ms: fig.timings.typical_ms(),
            passes: fig.passes,
            programs_compiled: fig.programs,
            maps_made: fig.maps_made,
            notes: outcome.notes.clone(),
            offset: fig.offset.map(|(o, _)| offset_text(o)),
            offset_source: fig.offset.map(|(_, source)| source),
            gl_renderer: outcome.gl_renderer.clone(),
            gl_version: outcome.gl_version.clone(),
            objects: ObjectShare::all(scene, &outcome.objects),
        }
    }
}

/// One technique × pipeline of a comparison.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ResultRow {
    pub technique: TechniqueId,
    pub summary: &'static str,
    pub pipeline: PipelineKind,
    pub backend: Backend,
    /// On the Pareto front of time and error.
    pub pareto: bool,
    /// Why the combination did not run, when it did not.
    pub skipped: Option<String>,
    pub measured: Option<Measured>,
}

impl ResultRow {
    /// The study's row of `scene`, not yet placed on the front.
    pub fn of(row: &Row, scene: &Scene) -> ResultRow {
        let (skipped, measured) = match &row.result {
            RowResult::Measured { outcome, .. } => (None, Some(Measured::of(outcome, scene))),
            RowResult::Skipped { reason } => (Some(reason.clone()), None),
        };
        ResultRow {
            technique: row.technique,
            summary: techniques::technique(row.technique).summary,
            pipeline: row.pipeline,
            backend: row.backend,
            pareto: false,
            skipped,
            measured,
        }
    }

    /// Every row of a study of `scene`, with the Pareto front marked.
    pub fn all(rows: &[Row], scene: &Scene) -> Vec<ResultRow> {
        let mut out: Vec<ResultRow> = rows.iter().map(|r| ResultRow::of(r, scene)).collect();
        let points: Vec<Option<FrontPoint>> = out
            .iter()
            .map(|r| r.measured.as_ref().map(FrontPoint::of))
            .collect();
        for i in pareto_front(&points) {
            out[i].pareto = true;
        }
        out
    }
}

/// A row as the Pareto front weighs it: its time as a range (the steady frames' min and
/// max; the one cold frame when there are no others) and its error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrontPoint {
    /// The time plotted and ranked (ms).
    pub ms: f64,
    pub ms_min: f64,
    pub ms_max: f64,
    pub error: f64,
}

impl FrontPoint {
    pub fn of(m: &Measured) -> FrontPoint {
        FrontPoint {
            ms: m.typical_ms,
            ms_min: m.ms_min.unwrap_or(m.typical_ms),
            ms_max: m.ms_max.unwrap_or(m.typical_ms),
            error: m.error_percent,
        }
    }

    /// Faster beyond doubt: every frame of `self` took less than every frame of `other`.
    fn faster_than(&self, other: &FrontPoint) -> bool {
        self.ms_max < other.ms_min
    }

    /// Whether `self` dominates `other`. Two rows whose time ranges overlap tie in time
    /// (which is faster flips from run to run on a shared machine), so between them only
    /// the error decides; otherwise `self` must be faster and no more wrong, or as fast
    /// and less wrong.
    fn dominates(&self, other: &FrontPoint) -> bool {
        let tie = !self.faster_than(other) && !other.faster_than(self);
        match (self.faster_than(other), tie) {
            (true, _) => self.error <= other.error,
            (false, true) => self.error < other.error,
            (false, false) => false,
        }
    }
}

/// Indices of the points no other point dominates ([`FrontPoint::dominates`]), ordered by
/// time (then error); `None` points take no part.
pub fn pareto_front(points: &[Option<FrontPoint>]) -> Vec<usize> {
    let mut front: Vec<usize> = (0..points.len())
        .filter(|&i| {
            points[i].is_some_and(|p| !points.iter().any(|q| q.is_some_and(|q| q.dominates(&p))))
        })
        .collect();
    let key = |i: usize| points[i].map_or((0.0, 0.0), |p| (p.ms, p.error));
    front.sort_by(|&a, &b| {
        let (pa, pb) = (key(a), key(b));
        pa.0.total_cmp(&pb.0).then(pa.1.total_cmp(&pb.1))
    });
    front
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_front_keeps_only_undominated_points() {
        // Times without spread: no two overlap unless equal.
        let p = |t: f64, e: f64| {
            Some(FrontPoint {
                ms: t,
                ms_min: t,
                ms_max: t,
                error: e,
            })
        };
        // 0 fast and wrong, 1 slow and right, 2 dominated by 0 and 1, 3 equal to 0 (kept:
        // equal points do not dominate each other), 4 skipped.
        let pts = [
            p(1.0, 10.0),
            p(5.0, 0.5),
            p(6.0, 12.0),
            p(1.0, 10.0),
            None,
            p(3.0, 2.0),
        ];
        assert_eq!(pareto_front(&pts), vec![0, 3, 5, 1]);
        assert_eq!(pareto_front(&[None, None]), Vec::<usize>::new());
        assert_eq!(pareto_front(&[p(2.0, 2.0), p(2.0, 1.0)]), vec![1]);
    }

    #[test]
    fn rows_whose_time_ranges_overlap_tie_in_time_and_the_error_decides() {
        let r = |ms: f64, lo: f64, hi: f64, error: f64| {
            Some(FrontPoint {
                ms,
                ms_min: lo,
                ms_max: hi,
                error,
            })
        };
        // 0 is a little faster by its median but its frames overlap 1's: a tie in time,
        // and 1 is less wrong, so 1 dominates 0. 2 is faster beyond doubt than both: it
        // stays, however wrong.
        let pts = [
            r(2.0, 1.8, 2.6, 5.0),
            r(2.2, 1.9, 2.5, 1.0),
            r(1.0, 0.9, 1.1, 9.0),
        ];
        assert_eq!(pareto_front(&pts), vec![2, 1]);
        // With the same error the tie keeps both.
        let same = [r(2.0, 1.8, 2.6, 1.0), r(2.2, 1.9, 2.5, 1.0)];
        assert_eq!(pareto_front(&same), vec![0, 1]);
        // Apart in time, the faster one is not dominated by a less wrong slower one.
        let apart = [r(2.0, 1.8, 2.1, 5.0), r(3.0, 2.9, 3.1, 1.0)];
        assert_eq!(pareto_front(&apart), vec![0, 1]);
    }
}
