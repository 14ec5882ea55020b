//! Soft shadows judged as visibility: how much of an area light each pixel sees, against
//! the truth's stratified estimate (`truth::Truth::visibility`).
//!
//! A technique's visibility is a [`VisibilityImage`]: per pixel `None` (background — kept
//! apart, never a value that could be read as half a light) or `Some(k)`, k/255 of the
//! light seen. A soft technique reads it from its accumulated mask; a hard one has
//! [`VisibilityImage::from_mask`]: lit = 1, shadowed = 0. So every technique on an
//! area-light scene gets the same figures, over the truth's geometry pixels (truth mask ≠
//! 128), with d = v_tech − v_truth:
//! - RMSE = √(Σ d² / n);
//! - maximum |d|;
//! - penumbra RMSE: the same over the pixels whose truth visibility is strictly between 0
//!   and 1 (`None` when the truth has none: a point light, or nothing in half shadow).
//!
//! A truth geometry pixel where the technique drew background has no technique value: it is
//! left out of every figure and counted as `uncovered` (the renderer already refuses a
//! render whose geometry differs from the truth's beyond 1% of the pixels).

use image::GrayAlphaImage;
use serde::Serialize;

use super::{Mask, MetricsError, BACKGROUND, LIT};

/// Visibility per pixel, row-major, top row first: `None` on background, `Some(k)` = k/255
/// of the light seen.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct VisibilityImage {
    pub width: u32,
    pub height: u32,
    pub data: Vec<Option<u8>>,
}

impl VisibilityImage {
    /// A hard mask as a visibility: lit 255 (the whole light), shadowed 0, background none
    /// (a mask's values between read as the side they lean to, `Class`).
    pub fn from_mask(mask: &Mask) -> VisibilityImage {
        let data = mask
            .data
            .iter()
            .map(|&v| match super::Class::of(v) {
                super::Class::Background => None,
                super::Class::Lit => Some(LIT),
                super::Class::Shadowed => Some(0),
            })
            .collect();
        VisibilityImage {
            width: mask.width,
            height: mask.height,
            data,
        }
    }

    /// Grey = k (0 none of the light … 255 all of it), alpha 0 on background and 255
    /// elsewhere — the layout of the truth's `visibility_image`.
    pub fn to_image(&self) -> GrayAlphaImage {
        let data = self
            .data
            .iter()
            .flat_map(|v| match v {
                Some(k) => [*k, 255],
                None => [0, 0],
            })
            .collect();
        GrayAlphaImage::from_raw(self.width, self.height, data)
            .unwrap_or_else(|| GrayAlphaImage::new(self.width, self.height))
    }
}

/// A visibility scored against the truth's.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct VisibilityErrors {
    /// √(mean d²) over the truth's geometry pixels the technique covers.
    pub rmse: f64,
    /// max |d| over the same pixels (0 when there are none).
    pub max_abs: f64,
    /// √(mean d²) over those whose truth visibility is strictly between 0 and 1; `None`
    /// when there is no such pixel.
    pub penumbra_rmse: Option<f64>,
    /// Pixels in `rmse`.
    pub pixels: u64,
    /// Pixels in `penumbra_rmse`.
    pub penumbra_pixels: u64,
    /// Truth geometry pixels where the technique drew background (in no figure).
    pub uncovered: u64,
}

/// Scores `technique` against the truth's visibility `truth` (in [0, 1], row-major, top
/// row first) over the geometry of `truth_mask`.
pub fn visibility_errors(
    technique: &VisibilityImage,
    truth: &[f32],
    truth_mask: &Mask,
) -> Result<VisibilityErrors, MetricsError> {
    if (technique.width, technique.height) != (truth_mask.width, truth_mask.height) {
        return Err(MetricsError::SizeMismatch {
            technique: (technique.width, technique.height),
            truth: (truth_mask.width, truth_mask.height),
        });
    }
    let n = truth_mask.data.len();
    for got in [technique.data.len(), truth.len()] {
        if got != n {
            return Err(MetricsError::VisibilityLength {
                got,
                width: truth_mask.width,
                height: truth_mask.height,
            });
        }
    }
    let (mut sum, mut pixels, mut max_abs) = (0.0f64, 0u64, 0.0f64);
    let (mut penumbra_sum, mut penumbra_pixels, mut uncovered) = (0.0f64, 0u64, 0u64);
    for ((v, &t), &m) in technique.data.iter().zip(truth).zip(&truth_mask.data) {
        if m == BACKGROUND {
            continue;
        }
        let Some(k) = v else {
            uncovered += 1;
            continue;
        };
        let t = f64::from(t.clamp(0.0, 1.0));
        let d = f64::from(*k) / 255.0 - t;
        sum += d * d;
        pixels += 1;
        max_abs = max_abs.max(d.abs());
        if t > 0.0 && t < 1.0 {
            penumbra_sum += d * d;
            penumbra_pixels += 1;
        }
    }
    let root = |s: f64, n: u64| if n == 0 { 0.0 } else { (s / n as f64).sqrt() };
    Ok(VisibilityErrors {
        rmse: root(sum, pixels),
        max_abs,
        penumbra_rmse: (penumbra_pixels > 0).then(|| root(penumbra_sum, penumbra_pixels)),
        pixels,
        penumbra_pixels,
        uncovered,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::SHADOWED;

    /// 2 × 3: truth background at 0, the rest geometry.
    fn truth_mask() -> Mask {
        Mask {
            width: 3,
            height: 2,
            data: vec![BACKGROUND, LIT, LIT, SHADOWED, SHADOWED, LIT],
        }
    }

    fn image(data: Vec<Option<u8>>) -> VisibilityImage {
        VisibilityImage {
            width: 3,
            height: 2,
            data,
        }
    }

    #[test]
    fn background_is_excluded_and_the_penumbra_is_strictly_between_0_and_1() {
        let truth = [0.3, 1.0, 0.5, 0.0, 0.25, 1.0];
        // Pixel 0 is the truth's background: whatever the technique says there is ignored.
        let tech = image(vec![
            Some(0),
            Some(255),
            Some(255),
            Some(0),
            Some(0),
            Some(255),
        ]);
        let e = visibility_errors(&tech, &truth, &truth_mask()).unwrap();
        assert_eq!(e.pixels, 5);
        // Penumbra: pixels 2 (0.5) and 4 (0.25) only — 0 and 1 are not in it.
        assert_eq!(e.penumbra_pixels, 2);
        let penumbra = ((0.25f64 + 0.0625) / 2.0).sqrt();
        assert!((e.penumbra_rmse.unwrap() - penumbra).abs() < 1e-12, "{e:?}");
        assert!((e.rmse - ((0.25f64 + 0.0625) / 5.0).sqrt()).abs() < 1e-12);
        assert_eq!(e.max_abs, 0.5);
        assert_eq!(e.uncovered, 0);
    }

    #[test]
    fn max_abs_is_the_largest_difference_and_uncovered_pixels_are_counted_apart() {
        let truth = [0.0, 1.0, 0.9, 0.0, 0.0, 1.0];
        let tech = image(vec![None, Some(0), None, Some(51), Some(0), Some(255)]);
        let e = visibility_errors(&tech, &truth, &truth_mask()).unwrap();
        assert_eq!(e.max_abs, 1.0);
        assert_eq!(e.uncovered, 1);
        assert_eq!(e.pixels, 4);
        assert_eq!(
            e.penumbra_rmse, None,
            "0.9 was not covered: no penumbra pixel left"
        );
    }

    #[test]
    fn a_hard_mask_is_visibility_0_or_1_and_keeps_its_background_apart() {
        let mask = Mask {
            width: 4,
            height: 1,
            data: vec![BACKGROUND, LIT, SHADOWED, 200],
        };
        let v = VisibilityImage::from_mask(&mask);
        assert_eq!(v.data, vec![None, Some(255), Some(0), Some(255)]);
        let picture = v.to_image();
        assert_eq!(picture.get_pixel(0, 0).0, [0, 0]);
        assert_eq!(picture.get_pixel(1, 0).0, [255, 255]);
        assert_eq!(picture.get_pixel(2, 0).0, [0, 255]);
    }

    #[test]
    fn sizes_must_agree() {
        let truth = [0.0; 6];
        let small = VisibilityImage {
            width: 1,
            height: 1,
            data: vec![Some(0)],
        };
        assert!(visibility_errors(&small, &truth, &truth_mask()).is_err());
        let tech = image(vec![Some(0); 6]);
        assert!(visibility_errors(&tech, &truth[..5], &truth_mask()).is_err());
    }
}
