//! The polygon-offset grid of one technique: factor × units, per depth format and pipeline.
//!
//! A cell is scored by `metrics::compare` against the truth, so it splits into false
//! shadow (truth lit, technique shadowed: acne, the bias too small) and missed shadow
//! (truth shadowed, technique lit: peter-panning, the bias too large). The best cell of a
//! surface is the one with the fewest wrong pixels; ties go to fewer wrong pixels outside
//! the edge band, then to the first in grid order (units-major, as the heatmap's rows).

use crate::vocab::{DepthBits, PipelineKind, PolygonOffset, TechniqueId};
use std::time::Instant;

use crate::gpu::Backend;
use crate::metrics::Metrics;
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
}

/// One cell of the grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    pub factor: f32,
    pub units: f32,
    pub metrics: Metrics,
    /// Restage, frame, mask passes and scoring (ms).
    pub ms: f64,
}

impl Cell {
    /// The order the best cell is chosen by (smaller is better).
    pub fn score(&self) -> (u64, u64) {
        (self.metrics.all.wrong, self.metrics.outside_band.wrong)
    }
}

/// The grid of one depth format on one pipeline.
#[derive(Debug, Clone)]
pub struct Surface {
    pub depth: DepthBits,
    pub pipeline: PipelineKind,
    pub result: SurfaceResult,
}

/// A measured grid, or why there is none.
#[derive(Debug, Clone)]
pub enum SurfaceResult {
    Measured {
        /// Row-major: `cells[u * factors.len() + f]` has `units[u]`, `factors[f]`.
        cells: Vec<Cell>,
        /// Index of the best cell.
        best: usize,
        /// `Session::new` (ms).
        setup_ms: f64,
    },
    Skipped {
        reason: String,
    },
}

/// A finished sweep.
#[derive(Debug, Clone)]
pub struct Sweep {
    pub technique: TechniqueId,
    pub factors: Vec<f32>,
    pub units: Vec<f32>,
    pub surfaces: Vec<Surface>,
    pub truth: Truth,
    pub truth_ms: f64,
    pub total_ms: f64,
}

/// A side of the grid a cell lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
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
    (0..cells.len()).min_by_key(|&i| cells[i].score())
}

/// Runs the grid; `progress` is called after each step.
pub fn sweep(
    scene: &Scene,
    spec: &SweepSpec,
    mut progress: impl FnMut(Progress),
) -> Result<Sweep, StudyError> {
    if spec.depths.is_empty() || spec.pipelines.is_empty() {
        return Err(StudyError::Empty);
    }
    let start = Instant::now();
    let (factors, units) = (spec.factor.values(), spec.units.values());
    let offsets: Vec<PolygonOffset> = units
        .iter()
        .flat_map(|&u| {
            factors.iter().map(move |&f| PolygonOffset {
                factor: f,
                units: u,
            })
        })
        .collect();
    // The work is counted in cells: the truth before them is reported as cell 0 done, and
    // a surface's set-up is part of its first cell.
    let surfaces_n = (spec.depths.len() * spec.pipelines.len()) as u64;
    let total = surfaces_n * offsets.len() as u64;
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
            scene.shadow.polygon_offset = OffsetSetting::command_line(offsets.first().copied());
            let options = RenderOptions {
                pipeline,
                ..base.clone()
            };
            let label = format!("{} bits ({})", depth.bits(), pipeline_name(pipeline));
            let mut ran = 0;
            let result = match grid(&scene, &options, &offsets, &truth, |i| {
                ran = i + 1;
                step(1, format!("cell {}/{} at {label}", i + 1, offsets.len()));
            }) {
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
            if let SurfaceResult::Skipped { .. } = result {
                // Count the cells that will not run, so the bar still ends full.
                step((offsets.len() - ran) as u64, format!("skipped {label}"));
            }
            surfaces.push(Surface {
                depth,
                pipeline,
                result,
            });
        }
    }
    Ok(Sweep {
        technique: spec.technique,
        factors,
        units,
        surfaces,
        truth,
        truth_ms,
        total_ms: ms_since(start),
    })
}

/// One session over every offset; `cell_done(i)` after cell i.
fn grid(
    scene: &Scene,
    options: &RenderOptions,
    offsets: &[PolygonOffset],
    truth: &Truth,
    mut cell_done: impl FnMut(usize),
) -> Result<SurfaceResult, RenderError> {
    let t0 = Instant::now();
    let mut session = Session::new(scene, options)?;
    let setup_ms = ms_since(t0);
    let mut cells = Vec::with_capacity(offsets.len());
    for (i, &offset) in offsets.iter().enumerate() {
        let t = Instant::now();
        if i > 0 {
            session.restage(&ShadowSettings {
                polygon_offset: OffsetSetting::command_line(Some(offset)),
                ..session.scene().shadow.clone()
            })?;
        }
        session.frame()?;
        let mask = session.mask()?;
        let metrics = render::judge(&mask, truth, options.band)?;
        cells.push(Cell {
            factor: offset.factor,
            units: offset.units,
            metrics,
            ms: ms_since(t),
        });
        cell_done(i);
    }
    let best = best(&cells).unwrap_or(0);
    Ok(SurfaceResult::Measured {
        cells,
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
    fn best_is_fewest_wrong_then_fewest_outside_the_band_then_first() {
        assert_eq!(best(&[]), None);
        assert_eq!(best(&[cell(5, 1), cell(3, 3), cell(4, 0)]), Some(1));
        assert_eq!(best(&[cell(3, 3), cell(3, 2), cell(3, 2)]), Some(1));
        assert_eq!(best(&[cell(0, 0), cell(0, 0)]), Some(0));
    }
}
