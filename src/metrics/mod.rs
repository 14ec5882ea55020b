//! Scoring a technique's shadow mask against the ground truth (pure; no GL).
//!
//! Over the truth's geometry pixels (value ≠ 128):
//! - false shadow: truth lit, technique shadowed;
//! - missed shadow: truth shadowed, technique lit;
//! - coverage: the technique saw background where the truth has geometry;
//! - wrong = false + missed + coverage, and wrong % = 100 · wrong / geometry pixels.
//!
//! The same counts are repeated outside a k-pixel band around the truth's shadow edges
//! (see `band`), separating edge aliasing from real errors. Soft shadows are scored by the
//! RMSE of visibility, √(Σ (v_tech − v_truth)² / n), over the same geometry pixels.

mod band;
pub mod image_diff;
mod mask;
pub mod per_object;
#[cfg(test)]
mod tests;
mod visibility;

pub use band::edge_band;
pub use mask::{Class, Mask, BACKGROUND, LIT, SHADOWED};
pub use per_object::{per_object, Cause, ObjectErrors, ShadowCauses};
pub use visibility::{visibility_errors, VisibilityErrors, VisibilityImage};

use serde::Serialize;

/// Failures of the metrics layer.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MetricsError {
    #[error("image sizes differ: technique {technique:?}, truth {truth:?}")]
    SizeMismatch {
        technique: (u32, u32),
        truth: (u32, u32),
    },
    #[error(
        "the images differ in size: {}×{} against the reference's {}×{}",
        .image.0, .image.1, .reference.0, .reference.1
    )]
    ImageSizes {
        image: (u32, u32),
        reference: (u32, u32),
    },
    #[error("visibility has {got} values, the {width}×{height} mask needs {}", .width * .height)]
    VisibilityLength { got: usize, width: u32, height: u32 },
}

/// Error counts over a set of the truth's geometry pixels.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct Counts {
    /// Truth geometry pixels considered.
    pub pixels: u64,
    pub false_shadow: u64,
    pub missed_shadow: u64,
    /// Technique background where the truth has geometry.
    pub coverage: u64,
    pub wrong: u64,
    /// 100 · wrong / pixels (0 when there are no pixels).
    pub wrong_percent: f64,
}

impl Counts {
    fn add(&mut self, truth: Class, technique: Class) {
        self.pixels += 1;
        match (truth, technique) {
            (Class::Lit, Class::Shadowed) => self.false_shadow += 1,
            (Class::Shadowed, Class::Lit) => self.missed_shadow += 1,
            (_, Class::Background) => self.coverage += 1,
            _ => {}
        }
    }

    fn finish(mut self) -> Counts {
        self.wrong = self.false_shadow + self.missed_shadow + self.coverage;
        self.wrong_percent = if self.pixels == 0 {
            0.0
        } else {
            100.0 * self.wrong as f64 / self.pixels as f64
        };
        self
    }
}

/// A technique's mask scored against the truth.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Metrics {
    /// Over every truth geometry pixel.
    pub all: Counts,
    /// Over the truth geometry pixels outside the edge band.
    pub outside_band: Counts,
    /// The band's half-width k in pixels.
    pub band: u32,
    /// Truth background where the technique drew geometry (not counted in `wrong`).
    pub extra_coverage: u64,
    /// RMSE of visibility, when soft-shadow visibilities were compared.
    pub visibility_rmse: Option<f64>,
}

/// Scores `technique` against `truth` with an edge band of half-width `band`.
pub fn compare(technique: &Mask, truth: &Mask, band: u32) -> Result<Metrics, MetricsError> {
    if (technique.width, technique.height) != (truth.width, truth.height) {
        return Err(MetricsError::SizeMismatch {
            technique: (technique.width, technique.height),
            truth: (truth.width, truth.height),
        });
    }
    let in_band = edge_band(truth, band);
    let (mut all, mut outside) = (Counts::default(), Counts::default());
    let mut extra_coverage = 0;
    for ((&t, &m), &b) in truth.data.iter().zip(&technique.data).zip(&in_band) {
        let (t, m) = (Class::of(t), Class::of(m));
        if t == Class::Background {
            extra_coverage += u64::from(m != Class::Background);
            continue;
        }
        all.add(t, m);
        if !b {
            outside.add(t, m);
        }
    }
    Ok(Metrics {
        all: all.finish(),
        outside_band: outside.finish(),
        band,
        extra_coverage,
        visibility_rmse: None,
    })
}

/// √(mean (v_tech − v_truth)²) over the truth's geometry pixels; visibilities in [0, 1],
/// row-major, top row first. 0 when the truth has no geometry.
pub fn visibility_rmse(
    technique: &[f32],
    truth: &[f32],
    truth_mask: &Mask,
) -> Result<f64, MetricsError> {
    let n = truth_mask.data.len();
    for got in [technique.len(), truth.len()] {
        if got != n {
            return Err(MetricsError::VisibilityLength {
                got,
                width: truth_mask.width,
                height: truth_mask.height,
            });
        }
    }
    let (mut sum, mut count) = (0.0f64, 0u64);
    for ((&a, &b), &m) in technique.iter().zip(truth).zip(&truth_mask.data) {
        if m != BACKGROUND {
            let d = f64::from(a) - f64::from(b);
            sum += d * d;
            count += 1;
        }
    }
    Ok(if count == 0 {
        0.0
    } else {
        (sum / count as f64).sqrt()
    })
}
