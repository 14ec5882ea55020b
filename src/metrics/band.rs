//! The band around the truth's shadow edges, where a one-pixel shift of an edge (aliasing,
//! map resolution) is expected: errors outside it are real errors.
//!
//! An edge pixel is a geometry pixel with a 4-neighbour of the other class (lit next to
//! shadowed; silhouettes against the background are not shadow edges). The band of width
//! k holds every pixel within Chebyshev distance k of an edge pixel: max(|dx|, |dy|) ≤ k,
//! computed as a separable max filter (rows, then columns).

use super::mask::{Class, Mask};

/// `true` for pixels in the k-band around the shadow edges of `truth`.
pub fn edge_band(truth: &Mask, k: u32) -> Vec<bool> {
    let (w, h) = (truth.width as usize, truth.height as usize);
    let mut edge = vec![false; w * h];
    for y in 0..h {
        for x in 0..w {
            let c = Class::of(truth.data[y * w + x]);
            if c == Class::Background {
                continue;
            }
            let other = |nx: usize, ny: usize| {
                let n = Class::of(truth.data[ny * w + nx]);
                n != Class::Background && n != c
            };
            edge[y * w + x] = (x > 0 && other(x - 1, y))
                || (x + 1 < w && other(x + 1, y))
                || (y > 0 && other(x, y - 1))
                || (y + 1 < h && other(x, y + 1));
        }
    }
    let k = k as usize;
    let mut rows = vec![false; w * h];
    for y in 0..h {
        for x in 0..w {
            let (lo, hi) = (x.saturating_sub(k), (x + k).min(w.saturating_sub(1)));
            rows[y * w + x] = (lo..=hi).any(|i| edge[y * w + i]);
        }
    }
    let mut band = vec![false; w * h];
    for y in 0..h {
        let (lo, hi) = (y.saturating_sub(k), (y + k).min(h.saturating_sub(1)));
        for x in 0..w {
            band[y * w + x] = (lo..=hi).any(|j| rows[j * w + x]);
        }
    }
    band
}
