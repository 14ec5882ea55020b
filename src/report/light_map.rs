//! Pictures of the light's map (`render --depth-map`), top row first: float depth and
//! 8-bit maps as one grey image (0 black, near; 1 or 255 white, far); a two-digit 16-bit
//! map as two images, as on Kilgard's slide of where the information is — the big digit
//! (high byte) grey, the little digit (low byte) pseudo-coloured so that neighbouring
//! values read as different colours.

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
                    picture(&|t| pseudo_colour((d(t) & 0xff) as u8)),
                ),
            ]
        }
    }
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
    }

    #[test]
    fn the_ramp_runs_blue_to_red() {
        assert_eq!(pseudo_colour(0), Rgba([0, 0, 255, 255]));
        assert_eq!(pseudo_colour(255), Rgba([255, 0, 0, 255]));
    }
}
