//! The polygon-offset grid of one technique: factor × units, per depth format and pipeline.
//!
//! A cell is scored by `metrics::compare` against the truth, so it splits into false
//! shadow (truth lit, technique shadowed: acne, the bias too small) and missed shadow
//! (truth shadowed, technique lit: peter-panning, the bias too large). The best cell of a
//! surface is the one with the fewest wrong pixels; ties go to fewer wrong pixels outside
//! the edge band, then to the later round (its grid is the finer one around the cell),
//! then to the first in grid order (units-major, as the heatmap's rows).
//!
//! **Rounds.** Without `--refine` a surface is one round: the grid as given. With it
//! ([`Refine`]), each round is judged by the best cell so far ([`Verdict`]) and, unless it
//! is settled, followed by another grid around that cell, on the same session (the
//! context and programs are made once per surface, not once per round). Every cell keeps
//! the number of its round.

use crate::vocab::{DepthBits, PipelineKind, PolygonOffset, TechniqueId};
use std::ops::Range;
use std::time::Instant;

use image::RgbaImage;
use serde::Serialize;

use crate::gpu::Backend;
use crate::metrics::{Mask, Metrics};
use crate::render::{self, pipeline_name, ImageSize, RenderError, RenderOptions, Session};
use crate::scene::{OffsetSetting, Scene, ShadowSettings};
use crate::truth::{self, Truth};

use super::{ms_since, not_applicable, Progress, StudyError, SweepRange};

/// What to sweep.
#[derive(Debug, Clone)]
pub struct SweepSpec {
    pub technique: TechniqueId,
    pub factor: SweepRange,
    pub units: SweepRange,
    pub depths: Vec<DepthBits>,
    pub pipelines: Vec<PipelineKind>,
    pub backend: Backend,
    pub size: Option<ImageSize>,
    /// Repeat each surface's grid around its best cell (`--refine`); `None`: one round.
    pub refine: Option<Refine>,
}

/// The finest factor spacing refinement goes to. The factor scales the polygon's depth
/// slope (its largest depth change per pixel), and the map is sampled at texel centres,
/// so a lookup's depth is already off by up to half a texel's slope: factors 1/8 apart
/// move the offset by less than a quarter of that error.
pub const FACTOR_FLOOR: f64 = 0.125;
/// The finest units spacing refinement goes to: half a unit, one LSB of a 16- or 24-bit
/// depth buffer (one unit is two, `DepthBits::offset_units_in_steps`). A finer step
/// changes the offset by less than the buffer can hold. (A float buffer's step at depths
/// in [0.5, 1) is one unit, so half a unit is finer than it needs, never coarser.)
pub const UNITS_FLOOR: f64 = 0.5;
/// The most rounds `--refine` may be given.
pub const MAX_ROUNDS: u32 = 8;

/// How `--refine` repeats a surface's grid. After each round the best cell so far is
/// placed on the round's grid, axis by axis (an axis of one value is fixed and stays):
///
/// - on a side past which lower or higher values may be tried (an *open* edge): the next
///   grid keeps the spacing and is centred on the best, so it moves half its span past
///   that side;
/// - inside, or on the low side at the *lowest* value tried: the next grid is centred on
///   the best with the spacing halved, but never below the axis's floor
///   ([`FACTOR_FLOOR`], [`UNITS_FLOOR`]); a spacing already at or under the floor stays.
///
/// The lowest value tried is 0, or the given start when the user gave a negative one: a
/// negative offset pulls the map towards the light and only adds acne. A grid that would
/// start below it is moved up to start there. Each refined grid has as many values per
/// axis as the given one, but at least 3 (two values have no inside).
///
/// A surface is *settled* when its best lies inside (or at the lowest value) on every
/// axis and every spacing is at or under its floor; refinement stops there, or after
/// `max_rounds` rounds in all (the given grid counted), and then says what was unsettled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Refine {
    /// Rounds in all, the given grid included (2 to [`MAX_ROUNDS`]).
    pub max_rounds: u32,
}

impl Refine {
    /// Rounds in all when `--refine` gives no number.
    pub const DEFAULT_ROUNDS: u32 = 4;
}

/// One axis of the grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Axis {
    Factor,
    Units,
}

impl Axis {
    /// The finest spacing refinement goes to on this axis.
    pub fn floor(self) -> f64 {
        match self {
            Axis::Factor => FACTOR_FLOOR,
            Axis::Units => UNITS_FLOOR,
        }
    }

    /// The axis's low and high sides.
    fn sides(self) -> (Edge, Edge) {
        match self {
            Axis::Factor => (Edge::LowestFactor, Edge::HighestFactor),
            Axis::Units => (Edge::LowestUnits, Edge::HighestUnits),
        }
    }
}

impl std::fmt::Display for Axis {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Axis::Factor => "factor",
            Axis::Units => "units",
        })
    }
}

/// One cell of the grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    pub factor: f32,
    pub units: f32,
    /// The round the cell was measured in (1: the grid as given).
    pub round: u32,
    pub metrics: Metrics,
    /// Restage, frame, mask passes and scoring (ms); reading the colour image for the
    /// pictures is not counted.
    pub ms: f64,
}

impl Cell {
    /// The order the best cell is chosen by (smaller is better).
    pub fn score(&self) -> (u64, u64) {
        (self.metrics.all.wrong, self.metrics.outside_band.wrong)
    }
}

/// The grids of one depth format on one pipeline.
#[derive(Debug, Clone)]
pub struct Surface {
    pub depth: DepthBits,
    pub pipeline: PipelineKind,
    pub result: SurfaceResult,
}

/// Measured grids, or why there are none.
#[derive(Debug, Clone)]
pub enum SurfaceResult {
    Measured {
        /// Every round's cells, round after round; within a round row-major:
        /// `cells[r.cells.start + u * r.factor.steps + f]` has the round's `units[u]`,
        /// `factors[f]`.
        cells: Vec<Cell>,
        /// The rounds, in order (one without `--refine`).
        rounds: Vec<Round>,
        /// Index of the best cell over all rounds.
        best: usize,
        /// `Session::new` (ms).
        setup_ms: f64,
    },
    Skipped {
        reason: String,
    },
}

/// One grid of a surface.
#[derive(Debug, Clone, PartialEq)]
pub struct Round {
    /// 1 for the grid as given.
    pub number: u32,
    pub factor: SweepRange,
    pub units: SweepRange,
    /// Its cells' indices in the surface's `cells`.
    pub cells: Range<usize>,
    /// The round's own best cell (an index into the surface's `cells`).
    pub best: usize,
    /// With `--refine`: where the best cell so far lies on this round's grid.
    pub verdict: Option<Verdict>,
}

impl Round {
    /// The sides of this round's grid its own best cell lies on ([`edges`]).
    pub fn edges(&self) -> Vec<Edge> {
        edges(
            self.best - self.cells.start,
            self.factor.steps as usize,
            self.units.steps as usize,
        )
    }
}

/// Where the best cell so far lies on a round's grid, under `--refine` (see [`Refine`]).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Verdict {
    /// Its index in the surface's `cells` (this round's or an earlier one's).
    pub best: usize,
    /// Sides it lies on past which a better offset may lie: the next grid moves.
    pub open: Vec<Edge>,
    /// Low sides it lies on at the lowest value tried: nothing lies past them.
    pub at_lowest: Vec<Edge>,
    /// Axes it lies inside (or at the lowest value) with a spacing above the floor: the
    /// next grid halves it.
    pub coarse: Vec<Axis>,
}

impl Verdict {
    /// Inside or at the lowest value on every axis, every spacing at or under its floor.
    pub fn settled(&self) -> bool {
        self.open.is_empty() && self.coarse.is_empty()
    }
}

/// A finished sweep.
#[derive(Debug, Clone)]
pub struct Sweep {
    pub technique: TechniqueId,
    /// The grid as given (round 1).
    pub factors: Vec<f32>,
    pub units: Vec<f32>,
    pub surfaces: Vec<Surface>,
    pub truth: Truth,
    pub truth_ms: f64,
    pub total_ms: f64,
    pub refine: Option<Refine>,
}

/// A side of the grid a cell lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Edge {
    LowestFactor,
    HighestFactor,
    LowestUnits,
    HighestUnits,
}

impl std::fmt::Display for Edge {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Edge::LowestFactor => "the lowest factor",
            Edge::HighestFactor => "the highest factor",
            Edge::LowestUnits => "the lowest units",
            Edge::HighestUnits => "the highest units",
        })
    }
}

/// The edges of a `factors` × `units` grid that cell `index` (row-major, see
/// [`SurfaceResult::Measured`]) lies on. An axis of one value has no edge: the user fixed
/// it. A best cell on an edge says the best offset may lie beyond the grid.
pub fn edges(index: usize, factors: usize, units: usize) -> Vec<Edge> {
    if factors == 0 {
        return Vec::new();
    }
    let (u, f) = (index / factors, index % factors);
    let mut out = Vec::new();
    if factors > 1 {
        if f == 0 {
            out.push(Edge::LowestFactor);
        }
        if f + 1 == factors {
            out.push(Edge::HighestFactor);
        }
    }
    if units > 1 {
        if u == 0 {
            out.push(Edge::LowestUnits);
        }
        if u + 1 == units {
            out.push(Edge::HighestUnits);
        }
    }
    out
}

/// Index of the best cell (see the module note); `None` for no cells.
pub fn best(cells: &[Cell]) -> Option<usize> {
    (0..cells.len()).min_by_key(|&i| {
        let (wrong, outside) = cells[i].score();
        (wrong, outside, std::cmp::Reverse(cells[i].round), i)
    })
}

/// The values a refined axis holds: as many as the given one, at least 3; a fixed axis 1.
fn refined_steps(range: SweepRange) -> u32 {
    if range.steps <= 1 {
        1
    } else {
        range.steps.max(3)
    }
}

/// Places `best` on one axis of a round (recorded in `verdict`) and returns that axis's
/// next range, by the rule of [`Refine`].
fn refine_axis(
    axis: Axis,
    range: SweepRange,
    best: f32,
    lowest: f32,
    verdict: &mut Verdict,
) -> SweepRange {
    if range.steps <= 1 {
        return range;
    }
    let h = range.spacing();
    let eps = h * 1e-3;
    let b = f64::from(best);
    let low = b <= f64::from(range.start) + eps;
    let high = b >= f64::from(range.end) - eps;
    let at_lowest = low && b <= f64::from(lowest) + eps;
    let (low_side, high_side) = axis.sides();
    let spacing = if high || (low && !at_lowest) {
        verdict.open.push(if high { high_side } else { low_side });
        h
    } else {
        if at_lowest {
            verdict.at_lowest.push(low_side);
        }
        // Within 0.1% of the floor is at it: the ends are f32, so a spacing set to the
        // floor comes back a few ULPs off it.
        if h > axis.floor() * (1.0 + 1e-3) {
            verdict.coarse.push(axis);
            (h / 2.0).max(axis.floor())
        } else {
            h
        }
    };
    SweepRange::around(best, spacing, refined_steps(range), lowest)
}

/// The verdict on a round's grid given the best cell so far (index `best` in `cells`),
/// and the next round's factor and units ranges. `lowest` is the lowest (factor, units)
/// refinement tries.
pub fn refine_round(
    factor: SweepRange,
    units: SweepRange,
    cells: &[Cell],
    best: usize,
    lowest: (f32, f32),
) -> (Verdict, SweepRange, SweepRange) {
    let mut verdict = Verdict {
        best,
        ..Verdict::default()
    };
    let b = cells[best];
    let factor = refine_axis(Axis::Factor, factor, b.factor, lowest.0, &mut verdict);
    let units = refine_axis(Axis::Units, units, b.units, lowest.1, &mut verdict);
    (verdict, factor, units)
}

/// The offsets of a grid, units-major (as the cells are stored).
fn offsets(factor: SweepRange, units: SweepRange) -> Vec<PolygonOffset> {
    let factors = factor.values();
    units
        .values()
        .into_iter()
        .flat_map(|u| {
            factors.iter().map(move |&f| PolygonOffset {
                factor: f,
                units: u,
            })
        })
        .collect()
}

/// The most cells one surface can take: the given grid, and with `--refine` every later
/// round at its refined size.
fn planned_cells(spec: &SweepSpec) -> u64 {
    let given = u64::from(spec.factor.steps) * u64::from(spec.units.steps);
    let refined = u64::from(refined_steps(spec.factor)) * u64::from(refined_steps(spec.units));
    let later = spec
        .refine
        .map_or(0, |r| u64::from(r.max_rounds.max(1) - 1));
    given + later * refined
}

/// A measured cell with its pictures, handed out as the sweep goes (the pictures are not
/// kept: a sweep of thousands of cells would hold gigabytes).
pub struct Shot<'a> {
    pub depth: DepthBits,
    pub pipeline: PipelineKind,
    pub cell: &'a Cell,
    /// The colour image of the cell's frame.
    pub image: &'a RgbaImage,
    /// The technique's shadow mask.
    pub mask: &'a Mask,
    /// The truth's mask it was judged against.
    pub truth: &'a Mask,
}

/// Runs the grid; `progress` is called after each step.
pub fn sweep(
    scene: &Scene,
    spec: &SweepSpec,
    progress: impl FnMut(Progress),
) -> Result<Sweep, StudyError> {
    run_sweep(scene, spec, progress, None)
}

/// Runs the grid as [`sweep`] does and hands each cell's pictures to `shot` (the colour
/// image is read back before the mask passes, which may draw over it).
pub fn sweep_with_pictures(
    scene: &Scene,
    spec: &SweepSpec,
    progress: impl FnMut(Progress),
    mut shot: impl FnMut(Shot<'_>),
) -> Result<Sweep, StudyError> {
    run_sweep(scene, spec, progress, Some(&mut shot))
}

impl SweepSpec {
    /// Whether there is something to sweep: a depth format, a pipeline, and a technique
    /// that reads the polygon offset (`TechniqueId::uses_offset`; the others would score
    /// one mask in every cell).
    pub fn check(&self) -> Result<(), StudyError> {
        if self.depths.is_empty() || self.pipelines.is_empty() {
            return Err(StudyError::Empty);
        }
        if !self.technique.uses_offset() {
            return Err(StudyError::NoOffset {
                technique: self.technique,
            });
        }
        Ok(())
    }
}

fn run_sweep(
    scene: &Scene,
    spec: &SweepSpec,
    mut progress: impl FnMut(Progress),
    mut shot: Option<&mut dyn FnMut(Shot<'_>)>,
) -> Result<Sweep, StudyError> {
    spec.check()?;
    let start = Instant::now();
    let first_offset = offsets(spec.factor, spec.units).first().copied();
    // The work is counted in cells: the truth before them is reported as cell 0 done, and
    // a surface's set-up is part of its first cell. With `--refine` every surface is
    // counted at its most rounds; the cells of rounds it does not need are counted done
    // when it settles, so the bar still ends full.
    let per_surface = planned_cells(spec);
    let surfaces_n = (spec.depths.len() * spec.pipelines.len()) as u64;
    let total = surfaces_n * per_surface;
    let mut done = 0;
    let mut step = |cells: u64, what: String| {
        done += cells;
        progress(Progress {
            done,
            total,
            unit: "cells",
            what,
        });
    };

    let mut scene = render::apply_overrides(scene, spec.size, Some(spec.technique));
    let base = RenderOptions {
        backend: spec.backend,
        size: spec.size,
        frames: 1,
        ..RenderOptions::default()
    };
    // One session at a time: each surface's is released before the next is made.
    render::Footprint::of(&scene, 1).check(&scene.limits)?;
    let truth_start = Instant::now();
    let truth = truth::truth(&scene, &base.truth)?;
    let truth_ms = ms_since(truth_start);
    step(0, "ground truth".to_string());

    let mut surfaces = Vec::new();
    for &depth in &spec.depths {
        for &pipeline in &spec.pipelines {
            scene.shadow.depth = depth;
            scene.shadow.polygon_offset = OffsetSetting::command_line(first_offset);
            let options = RenderOptions {
                pipeline,
                ..base.clone()
            };
            let result = one_surface(
                &scene,
                &options,
                spec,
                &truth,
                per_surface,
                &mut step,
                shot.as_deref_mut(),
            )?;
            surfaces.push(Surface {
                depth,
                pipeline,
                result,
            });
        }
    }
    Ok(Sweep {
        technique: spec.technique,
        factors: spec.factor.values(),
        units: spec.units.values(),
        surfaces,
        truth,
        truth_ms,
        total_ms: ms_since(start),
        refine: spec.refine,
    })
}

/// Measures the surface of `scene`'s depth format on `options`' pipeline (or says why it
/// does not apply), reporting each cell to `step` and counting the `per_surface` cells it
/// did not run as done at the end; hands each cell's pictures to `shot` when given.
fn one_surface(
    scene: &Scene,
    options: &RenderOptions,
    spec: &SweepSpec,
    truth: &Truth,
    per_surface: u64,
    step: &mut dyn FnMut(u64, String),
    mut shot: Option<&mut (dyn FnMut(Shot<'_>) + '_)>,
) -> Result<SurfaceResult, StudyError> {
    let (depth, pipeline) = (scene.shadow.depth, options.pipeline);
    let label = format!("{} bits ({})", depth.bits(), pipeline_name(pipeline));
    let mut ran = 0;
    let mut on_cell = |round: u32, i: usize, of: usize| {
        ran += 1;
        step(1, format!("round {round}, cell {}/{of} at {label}", i + 1));
    };
    let mut pictures = shot.as_mut().map(|f| {
        move |image: &RgbaImage, mask: &Mask, cell: &Cell| {
            f(Shot {
                depth,
                pipeline,
                cell,
                image,
                mask,
                truth: &truth.mask,
            })
        }
    });
    let grids = Grids {
        factor: spec.factor,
        units: spec.units,
        refine: spec.refine,
    };
    let result = match surface(
        scene,
        options,
        &grids,
        truth,
        &mut on_cell,
        pictures.as_mut().map(|p| p as PictureSink<'_>),
    ) {
        Ok(r) => r,
        Err(e) => match not_applicable(&e) {
            Some(reason) => SurfaceResult::Skipped { reason },
            None => {
                return Err(StudyError::Render {
                    technique: spec.technique,
                    pipeline: pipeline_name(pipeline),
                    source: Box::new(e),
                })
            }
        },
    };
    // Count the cells that will not run (a skipped surface, rounds a settled surface does
    // not need), so the bar still ends full.
    let left = per_surface.saturating_sub(ran);
    if left > 0 {
        let what = match result {
            SurfaceResult::Skipped { .. } => format!("skipped {label}"),
            SurfaceResult::Measured { .. } => format!("settled {label}"),
        };
        step(left, what);
    }
    Ok(result)
}

/// The given grid and how to refine it.
struct Grids {
    factor: SweepRange,
    units: SweepRange,
    refine: Option<Refine>,
}

/// Where a surface's cells' pictures go: (image, mask, cell).
type PictureSink<'a> = &'a mut dyn FnMut(&RgbaImage, &Mask, &Cell);

/// One session over every round of one surface; `cell_done(round, i, cells in round)`
/// after each cell, `pictures(image, mask, cell)` when given.
fn surface(
    scene: &Scene,
    options: &RenderOptions,
    grids: &Grids,
    truth: &Truth,
    cell_done: &mut dyn FnMut(u32, usize, usize),
    mut pictures: Option<PictureSink<'_>>,
) -> Result<SurfaceResult, RenderError> {
    let t0 = Instant::now();
    let mut session = Session::new(scene, options)?;
    let setup_ms = ms_since(t0);
    let lowest = (grids.factor.start.min(0.0), grids.units.start.min(0.0));
    let (mut factor, mut units) = (grids.factor, grids.units);
    let mut cells: Vec<Cell> = Vec::new();
    let mut rounds = Vec::new();
    loop {
        let number = rounds.len() as u32 + 1;
        let first = cells.len();
        let grid = offsets(factor, units);
        for (i, &offset) in grid.iter().enumerate() {
            let t = Instant::now();
            if !cells.is_empty() {
                session.restage(&ShadowSettings {
                    polygon_offset: OffsetSetting::command_line(Some(offset)),
                    ..session.scene().shadow.clone()
                })?;
            }
            session.frame()?;
            let mut ms = ms_since(t);
            // The picture first: mask plans may draw over it. Not part of the cell's time.
            let image = match pictures {
                Some(_) => Some(session.image()?),
                None => None,
            };
            let t = Instant::now();
            let mask = session.mask()?;
            let metrics = render::judge(&mask, truth, options.band)?;
            ms += ms_since(t);
            let cell = Cell {
                factor: offset.factor,
                units: offset.units,
                round: number,
                metrics,
                ms,
            };
            if let (Some(p), Some(image)) = (pictures.as_mut(), &image) {
                p(image, &mask, &cell);
            }
            cells.push(cell);
            cell_done(number, i, grid.len());
        }
        let own_best = first + best(&cells[first..]).unwrap_or(0);
        let mut round = Round {
            number,
            factor,
            units,
            cells: first..cells.len(),
            best: own_best,
            verdict: None,
        };
        let Some(refine) = grids.refine else {
            rounds.push(round);
            break;
        };
        let so_far = best(&cells).unwrap_or(0);
        let (verdict, next_factor, next_units) =
            refine_round(factor, units, &cells, so_far, lowest);
        let more = !verdict.settled() && number < refine.max_rounds;
        round.verdict = Some(verdict);
        rounds.push(round);
        if !more {
            break;
        }
        (factor, units) = (next_factor, next_units);
    }
    let best = best(&cells).unwrap_or(0);
    Ok(SurfaceResult::Measured {
        cells,
        rounds,
        best,
        setup_ms,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::Counts;

    fn cell(wrong: u64, outside: u64) -> Cell {
        let counts = |w| Counts {
            wrong: w,
            ..Counts::default()
        };
        Cell {
            factor: 0.0,
            units: 0.0,
            round: 1,
            metrics: Metrics {
                all: counts(wrong),
                outside_band: counts(outside),
                band: 1,
                extra_coverage: 0,
                visibility_rmse: None,
            },
            ms: 0.0,
        }
    }

    #[test]
    fn a_cell_on_a_side_of_the_grid_names_it_and_a_fixed_axis_has_no_side() {
        // 3 factors × 2 units: index 0 is (lowest factor, lowest units), 4 the middle
        // factor of the highest units.
        assert_eq!(edges(0, 3, 2), [Edge::LowestFactor, Edge::LowestUnits]);
        assert_eq!(edges(4, 3, 2), [Edge::HighestUnits]);
        assert_eq!(edges(5, 3, 2), [Edge::HighestFactor, Edge::HighestUnits]);
        // 3 × 3: the centre is inside.
        assert_eq!(edges(4, 3, 3), []);
        // One factor (fixed): only the units' sides count.
        assert_eq!(edges(1, 1, 3), []);
        assert_eq!(edges(2, 1, 3), [Edge::HighestUnits]);
    }

    #[test]
    fn best_is_fewest_wrong_then_fewest_outside_the_band_then_latest_round_then_first() {
        assert_eq!(best(&[]), None);
        assert_eq!(best(&[cell(5, 1), cell(3, 3), cell(4, 0)]), Some(1));
        assert_eq!(best(&[cell(3, 3), cell(3, 2), cell(3, 2)]), Some(1));
        assert_eq!(best(&[cell(0, 0), cell(0, 0)]), Some(0));
        let later = Cell {
            round: 2,
            ..cell(3, 2)
        };
        assert_eq!(best(&[cell(3, 2), later, later]), Some(1));
        assert_eq!(best(&[cell(2, 2), later]), Some(0));
    }

    /// A cell at (factor, units).
    fn at(factor: f32, units: f32) -> Cell {
        Cell {
            factor,
            units,
            ..cell(0, 0)
        }
    }

    fn range(s: &str) -> SweepRange {
        s.parse().expect("a range")
    }

    #[test]
    fn a_best_on_an_open_side_moves_the_grid_with_the_same_spacing() {
        let (v, f, u) = refine_round(
            range("0..1:3"),
            range("0..2:3"),
            &[at(1.0, 2.0)],
            0,
            (0.0, 0.0),
        );
        assert_eq!(v.open, [Edge::HighestFactor, Edge::HighestUnits]);
        assert!(v.coarse.is_empty() && !v.settled());
        assert_eq!(f.values(), [0.5, 1.0, 1.5]);
        assert_eq!(u.values(), [1.0, 2.0, 3.0]);
        // A given negative start is the lowest tried; below it nothing is.
        let (v, f, _) = refine_round(
            range("-2..2:3"),
            range("1"),
            &[at(-2.0, 1.0)],
            0,
            (-2.0, 0.0),
        );
        assert_eq!(
            (v.open.len(), v.at_lowest.clone()),
            (0, vec![Edge::LowestFactor])
        );
        assert_eq!(f.values(), [-2.0, -1.0, 0.0]);
    }

    #[test]
    fn a_best_inside_or_at_zero_halves_the_spacing_down_to_the_floor_then_settles() {
        // Inside on factor, at 0 on units (nothing below): both zoom.
        let (v, f, u) = refine_round(
            range("0..1:5"),
            range("0..4:3"),
            &[at(0.5, 0.0)],
            0,
            (0.0, 0.0),
        );
        assert_eq!(v.open, []);
        assert_eq!(v.at_lowest, [Edge::LowestUnits]);
        assert_eq!(v.coarse, [Axis::Factor, Axis::Units]);
        assert_eq!(f.values(), [0.25, 0.375, 0.5, 0.625, 0.75]);
        assert_eq!(u.values(), [0.0, 1.0, 2.0]);
        // Halving 0.2 would give 0.1, under the floor: the floor it is.
        let (_, f, _) = refine_round(
            range("0..0.4:3"),
            range("2"),
            &[at(0.2, 2.0)],
            0,
            (0.0, 0.0),
        );
        assert!((f.spacing() - FACTOR_FLOOR).abs() < 1e-6, "{f:?}");
        // Far from 0 the f32 ends leave the spacing some ULPs off the floor: still settled.
        let (v, ..) = refine_round(
            range("99.875..100.125:3"),
            range("2"),
            &[at(100.0, 2.0)],
            0,
            (0.0, 0.0),
        );
        assert!(v.settled(), "{v:?}");
        // Spacings at the floors and the best inside: settled, grid kept.
        let (v, f, u) = refine_round(
            range("0..0.25:3"),
            range("1..2:3"),
            &[at(0.125, 1.5)],
            0,
            (0.0, 0.0),
        );
        assert!(v.settled(), "{v:?}");
        assert_eq!(
            (f.values(), u.values()),
            (range("0..0.25:3").values(), range("1..2:3").values())
        );
        // A fixed axis stays fixed and two values become three (two have no inside).
        let (v, f, u) = refine_round(range("1"), range("0..4:2"), &[at(1.0, 4.0)], 0, (0.0, 0.0));
        assert_eq!(v.open, [Edge::HighestUnits]);
        assert_eq!((f.values(), u.values()), (vec![1.0], vec![0.0, 4.0, 8.0]));
    }
}
