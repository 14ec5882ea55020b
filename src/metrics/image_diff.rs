//! Two colour images compared pixel by pixel, for `--expect` and `replay --pipeline both`.
//!
//! A pixel's difference is its largest channel difference, max over R, G, B, A of |a − b|
//! in 8-bit steps. A [`Tolerance`] `(d, f)` passes when the pixels whose difference exceeds
//! d are at most a fraction f of the image — the form the project's image tests state
//! (3/255 on 99% of pixels is `3,1%`). Images of different sizes do not compare.
//!
//! The difference picture shows where: a pixel equal in both is the reference at a quarter
//! of its brightness (so the scene stays recognisable), a pixel within d is yellow, one
//! beyond d red, brighter the larger its difference.

use std::fmt;
use std::str::FromStr;

use image::{Rgba, RgbaImage};
use serde::Serialize;

use super::MetricsError;

/// How far two images may differ: `per_channel` steps, on all but `fraction` of pixels.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Tolerance {
    pub per_channel: u8,
    /// In [0, 1].
    pub fraction: f64,
}

impl Tolerance {
    /// 3/255 on 99% of pixels.
    pub const DEFAULT: Tolerance = Tolerance {
        per_channel: 3,
        fraction: 0.01,
    };
}

impl fmt::Display for Tolerance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{},{}%", self.per_channel, self.fraction * 100.0)
    }
}

/// `D,F%` or `D,F` (F a fraction): D in 0..=255 steps, F in [0, 100]% of pixels.
impl FromStr for Tolerance {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        let usage = || {
            format!(
                "`{s}` is not a tolerance: give STEPS,PERCENT% (e.g. 3,1% = at most 1% of \
                 pixels differ by more than 3/255) or STEPS,FRACTION (3,0.01)"
            )
        };
        let (steps, share) = s.split_once(',').ok_or_else(usage)?;
        let per_channel: u8 = steps.trim().parse().map_err(|_| {
            format!("`{steps}`: the per-channel difference is 0 to 255 steps of 1/255")
        })?;
        let share = share.trim();
        let fraction = match share.strip_suffix('%') {
            Some(p) => p.trim().parse::<f64>().map(|p| p / 100.0),
            None => share.parse::<f64>(),
        }
        .map_err(|_| usage())?;
        if !(0.0..=1.0).contains(&fraction) {
            return Err(format!(
                "`{share}`: the share of pixels allowed to differ is 0 to 100% (0 to 1)"
            ));
        }
        Ok(Tolerance {
            per_channel,
            fraction,
        })
    }
}

/// What differs between two images of one size.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ImageDiff {
    pub width: u32,
    pub height: u32,
    /// The largest difference of any pixel, in steps of 1/255.
    pub largest: u8,
    /// The first pixel (row by row, top first) with the largest difference.
    pub at: (u32, u32),
    /// Pixels that differ at all.
    pub differing: u64,
}

impl ImageDiff {
    /// Compares `image` with `reference`.
    pub fn of(image: &RgbaImage, reference: &RgbaImage) -> Result<ImageDiff, MetricsError> {
        if image.dimensions() != reference.dimensions() {
            return Err(MetricsError::ImageSizes {
                image: image.dimensions(),
                reference: reference.dimensions(),
            });
        }
        let mut diff = ImageDiff {
            width: image.width(),
            height: image.height(),
            largest: 0,
            at: (0, 0),
            differing: 0,
        };
        for (x, y, p) in image.enumerate_pixels() {
            let d = difference(p, reference.get_pixel(x, y));
            if d > 0 {
                diff.differing += 1;
            }
            if d > diff.largest {
                diff.largest = d;
                diff.at = (x, y);
            }
        }
        Ok(diff)
    }

    /// Pixels whose difference exceeds `per_channel`.
    pub fn beyond(image: &RgbaImage, reference: &RgbaImage, per_channel: u8) -> u64 {
        image
            .pixels()
            .zip(reference.pixels())
            .filter(|(a, b)| difference(a, b) > per_channel)
            .count() as u64
    }

    pub fn pixels(&self) -> u64 {
        u64::from(self.width) * u64::from(self.height)
    }
}

/// The verdict of a comparison under a tolerance.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Verdict {
    pub diff: ImageDiff,
    pub tolerance: Tolerance,
    /// Pixels whose difference exceeds the tolerance's per-channel steps.
    pub beyond: u64,
}

impl Verdict {
    /// Compares `image` with `reference` under `tolerance`.
    pub fn of(
        image: &RgbaImage,
        reference: &RgbaImage,
        tolerance: Tolerance,
    ) -> Result<Verdict, MetricsError> {
        let diff = ImageDiff::of(image, reference)?;
        Ok(Verdict {
            diff,
            tolerance,
            beyond: ImageDiff::beyond(image, reference, tolerance.per_channel),
        })
    }

    /// Whether at most the tolerance's share of pixels lies beyond its steps.
    pub fn passes(&self) -> bool {
        self.beyond as f64 <= self.tolerance.fraction * self.diff.pixels() as f64
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let d = &self.diff;
        write!(
            f,
            "{} of {} pixels ({:.2}%) differ by more than {}/255 (allowed: {}%); largest \
             difference {}/255 at ({}, {}); {} pixels differ at all",
            self.beyond,
            d.pixels(),
            100.0 * self.beyond as f64 / d.pixels().max(1) as f64,
            self.tolerance.per_channel,
            self.tolerance.fraction * 100.0,
            d.largest,
            d.at.0,
            d.at.1,
            d.differing
        )
    }
}

/// max over the channels of |a − b|.
fn difference(a: &Rgba<u8>, b: &Rgba<u8>) -> u8 {
    a.0.iter()
        .zip(b.0)
        .map(|(&x, y)| x.abs_diff(y))
        .max()
        .unwrap_or(0)
}

/// The difference picture of `image` against `reference` (same size; see the module note).
pub fn picture(image: &RgbaImage, reference: &RgbaImage, per_channel: u8) -> RgbaImage {
    RgbaImage::from_fn(reference.width(), reference.height(), |x, y| {
        let r = reference.get_pixel(x, y);
        let d = image
            .get_pixel_checked(x, y)
            .map_or(u8::MAX, |p| difference(p, r));
        // Brighter with the difference: 128 at the smallest, 255 from 32 steps on.
        let bright = |d: u8| 128u8.saturating_add(d.saturating_mul(4));
        match d {
            0 => Rgba([r[0] / 4, r[1] / 4, r[2] / 4, 255]),
            d if d <= per_channel => Rgba([bright(d), bright(d), 0, 255]),
            d => Rgba([bright(d), 0, 0, 255]),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grey(w: u32, h: u32, v: u8) -> RgbaImage {
        RgbaImage::from_pixel(w, h, Rgba([v, v, v, 255]))
    }

    #[test]
    fn tolerances_parse_as_steps_and_a_percentage_or_a_fraction() {
        let t: Tolerance = "3,1%".parse().expect("3,1%");
        assert_eq!((t.per_channel, t.fraction), (3, 0.01));
        let t: Tolerance = "0, 0.5".parse().expect("0,0.5");
        assert_eq!((t.per_channel, t.fraction), (0, 0.5));
        // Each refusal quotes what is wrong.
        for (bad, quoted) in [
            ("3", "`3`"),
            ("256,1%", "`256`"),
            ("3,101%", "`101%`"),
            ("3,-1", "`-1`"),
            ("x,1%", "`x`"),
            ("3,abc", "`3,abc`"),
        ] {
            let e = bad.parse::<Tolerance>().expect_err(bad);
            assert!(e.contains(quoted), "{bad}: {e}");
        }
    }

    #[test]
    fn the_largest_difference_its_pixel_and_the_share_beyond_the_steps_decide() {
        let reference = grey(10, 10, 100);
        let mut image = reference.clone();
        image.put_pixel(2, 1, Rgba([100, 104, 100, 255])); // 4 steps, in green
        image.put_pixel(7, 3, Rgba([100, 100, 100, 90])); // 165 steps, in alpha
        image.put_pixel(0, 9, Rgba([103, 100, 100, 255])); // 3 steps: within
        let v = Verdict::of(&image, &reference, Tolerance::DEFAULT).expect("same size");
        assert_eq!(v.diff.largest, 165);
        assert_eq!(v.diff.at, (7, 3));
        assert_eq!(v.diff.differing, 3);
        assert_eq!(v.beyond, 2);
        // 2 of 100 pixels beyond 3/255: over 1%, within 2%.
        assert!(!v.passes());
        let two = Tolerance {
            fraction: 0.02,
            ..Tolerance::DEFAULT
        };
        assert!(Verdict::of(&image, &reference, two)
            .expect("same size")
            .passes());
        let t = "4,1%".parse().expect("4,1%");
        assert!(Verdict::of(&image, &reference, t)
            .expect("same size")
            .passes());
    }

    #[test]
    fn images_of_different_sizes_do_not_compare() {
        let e = ImageDiff::of(&grey(4, 4, 0), &grey(4, 5, 0)).expect_err("sizes");
        assert_eq!(
            e,
            MetricsError::ImageSizes {
                image: (4, 4),
                reference: (4, 5)
            }
        );
    }

    #[test]
    fn the_picture_dims_equal_pixels_and_marks_the_others_by_their_difference() {
        let reference = grey(3, 1, 200);
        let mut image = reference.clone();
        image.put_pixel(1, 0, Rgba([202, 200, 200, 255]));
        image.put_pixel(2, 0, Rgba([0, 200, 200, 255]));
        let p = picture(&image, &reference, 3);
        assert_eq!(p.get_pixel(0, 0).0, [50, 50, 50, 255]);
        assert_eq!(p.get_pixel(1, 0).0, [136, 136, 0, 255]);
        assert_eq!(p.get_pixel(2, 0).0, [255, 0, 0, 255]);
    }
}
