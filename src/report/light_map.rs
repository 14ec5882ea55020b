//! Pictures of the light's map (`render --depth-map`), top row first: float depth and
//! 8-bit maps as one grey image (0 black, near; 1 or 255 white, far); a two-digit 16-bit
//! map as two images, as on Kilgard's slide of where the information is — the big digit
//! (high byte) grey, the little digit (low byte) pseudo-coloured so that neighbouring
//! values read as different colours. The pseudo-coloured picture carries its legend: a
//! band of [`LEGEND_BAND`] rows under the map, the colour ramp from 0 (left) to 255 (right)
//! with its ends labelled.

use image::{Rgba, RgbaImage};

use crate::render::{LightMap, MapTexels};

/// The map as labelled pictures: `depth`, or `big-digit` and `little-digit`.
pub fn light_map_pictures(map: &LightMap) -> Vec<(String, RgbaImage)> {
    let texel = map.texels.size();
    let texels: Vec<&[u8]> = map
        .rows_top_first()
        .flat_map(|row| row.chunks_exact(texel))
        .collect();
    let picture = |f: &dyn Fn(&[u8]) -> Rgba<u8>| {
        let mut img = RgbaImage::new(map.size, map.size);
        for (p, t) in img.pixels_mut().zip(&texels) {
            *p = f(t);
        }
        img
    };
    match map.texels {
        MapTexels::Depth => vec![(
            "depth".to_string(),
            picture(&|t| {
                let z = f32::from_ne_bytes([t[0], t[1], t[2], t[3]]);
                grey((z.clamp(0.0, 1.0) * 255.0).round() as u8)
            }),
        )],
        MapTexels::Byte => vec![("depth".to_string(), picture(&|t| grey(t[0])))],
        MapTexels::Digits => {
            let d = |t: &[u8]| u16::from_ne_bytes([t[0], t[1]]);
            vec![
                (
                    "big-digit".to_string(),
                    picture(&|t| grey((d(t) >> 8) as u8)),
                ),
                (
                    "little-digit".to_string(),
                    with_legend(&picture(&|t| pseudo_colour((d(t) & 0xff) as u8))),
                ),
            ]
        }
    }
}

/// Rows of the legend band under a pseudo-coloured map.
pub const LEGEND_BAND: u32 = 26;

/// `map` with the pseudo-colour legend under it: a ramp from 0 at the left to 255 at the
/// right, its ends labelled (the labels are left out when no font is found).
fn with_legend(map: &RgbaImage) -> RgbaImage {
    let (w, h) = map.dimensions();
    let mut out = RgbaImage::from_pixel(w, h + LEGEND_BAND, Rgba([24, 26, 32, 255]));
    image::imageops::replace(&mut out, map, 0, 0);
    for x in 0..w {
        let v = (u64::from(x) * 255 / u64::from(w.saturating_sub(1).max(1))) as u8;
        for y in h + 2..h + 12 {
            out.put_pixel(x, y, pseudo_colour(v));
        }
    }
    if super::font::ensure().is_ok() {
        use plotters::prelude::*;
        let mut rgb = image::DynamicImage::ImageRgba8(out.clone()).to_rgb8();
        let drawn = (|| -> Result<(), String> {
            let root =
                BitMapBackend::with_buffer(&mut rgb, (w, h + LEGEND_BAND)).into_drawing_area();
            let style = (super::font::FAMILY, 11)
                .into_font()
                .color(&RGBColor(235, 235, 235));
            let e = |x: &dyn std::fmt::Display| x.to_string();
            root.draw(&Text::new("0", (1, (h + 13) as i32), style.clone()))
                .map_err(|x| e(&x))?;
            let right = "255";
            let (tw, _) = root.estimate_text_size(right, &style).map_err(|x| e(&x))?;
            root.draw(&Text::new(
                right,
                (w as i32 - tw as i32 - 1, (h + 13) as i32),
                style,
            ))
            .map_err(|x| e(&x))?;
            root.present().map_err(|x| e(&x))
        })();
        if drawn.is_ok() {
            out = image::DynamicImage::ImageRgb8(rgb).to_rgba8();
        }
    }
    out
}

fn grey(v: u8) -> Rgba<u8> {
    Rgba([v, v, v, 255])
}

/// A hue ramp over 0..=255 (blue → cyan → green → yellow → red), so that neighbouring
/// little-digit values read as different colours, like the slide's pseudo-colour inset.
pub fn pseudo_colour(v: u8) -> Rgba<u8> {
    let x = f32::from(v) / 255.0 * 4.0;
    let (r, g, b) = match x as u32 {
        0 => (0.0, x, 1.0),
        1 => (0.0, 1.0, 2.0 - x),
        2 => (x - 2.0, 1.0, 0.0),
        _ => (1.0, (4.0 - x).max(0.0), 0.0),
    };
    let c = |f: f32| (f.clamp(0.0, 1.0) * 255.0).round() as u8;
    Rgba([c(r), c(g), c(b), 255])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn digits_split_into_two_pictures_top_row_first() {
        // 2×2, bottom row first: bottom (0x0102, 0x0304), top (0xff00, 0x00ff).
        let bytes = [0x0102u16, 0x0304, 0xff00, 0x00ff]
            .iter()
            .flat_map(|d| d.to_ne_bytes())
            .collect();
        let map = LightMap {
            texels: MapTexels::Digits,
            size: 2,
            bytes,
        };
        let pictures = light_map_pictures(&map);
        let labels: Vec<&str> = pictures.iter().map(|(l, _)| l.as_str()).collect();
        assert_eq!(labels, ["big-digit", "little-digit"]);
        let big = &pictures[0].1;
        assert_eq!(big.get_pixel(0, 0), &grey(0xff));
        assert_eq!(big.get_pixel(1, 1), &grey(0x03));
        assert_eq!(pictures[1].1.get_pixel(1, 0), &pseudo_colour(0xff));
        // The legend under the little digit: its ramp runs blue to red.
        let little = &pictures[1].1;
        assert_eq!(little.dimensions(), (2, 2 + LEGEND_BAND));
        assert_eq!(little.get_pixel(0, 2 + 5), &pseudo_colour(0));
        assert_eq!(little.get_pixel(1, 2 + 5), &pseudo_colour(255));
    }

    #[test]
    fn the_ramp_runs_blue_to_red() {
        assert_eq!(pseudo_colour(0), Rgba([0, 0, 255, 255]));
        assert_eq!(pseudo_colour(255), Rgba([255, 0, 0, 255]));
    }
}
