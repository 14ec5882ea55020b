//! Pictures: the error image of a mask against the truth, and the contact sheet.
//!
//! Error image, per pixel (the truth's class, the technique's class):
//! lit/lit light grey, shadowed/shadowed dark grey, lit/shadowed false shadow (orange),
//! shadowed/lit missed shadow (blue), geometry/background missing coverage (magenta),
//! background/anything the page's dark background. Orange and blue stay apart for the
//! common colour-vision deficiencies.
//!
//! Contact sheet: a header line, then one line per measured row — its label above, then
//! image, mask and error image as tiles of at most [`TILE`] pixels; the first line holds
//! the truth mask and the error legend. Labels are drawn by plotters on the sheet's buffer.

use image::{imageops, Rgb, RgbImage, RgbaImage};
use plotters::prelude::*;

use crate::metrics::{Class, Mask};
use crate::render::pipeline_name;

use super::{font, ReportError, ResultRow};

/// The colours of an error image (RGB).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ErrorColours {
    pub lit: [u8; 3],
    pub shadowed: [u8; 3],
    pub false_shadow: [u8; 3],
    pub missed_shadow: [u8; 3],
    pub coverage: [u8; 3],
    pub background: [u8; 3],
}

/// The palette used by error images, the sheet's legend and the page's legend.
pub const ERROR_COLOURS: ErrorColours = ErrorColours {
    lit: [226, 226, 226],
    shadowed: [120, 120, 120],
    false_shadow: [240, 120, 0],
    missed_shadow: [0, 110, 255],
    coverage: [220, 0, 220],
    background: [36, 38, 48],
};

/// The error image of `mask` against `truth` (same size; a mismatch gives what overlaps).
pub fn error_image(mask: &Mask, truth: &Mask) -> RgbImage {
    let c = ERROR_COLOURS;
    RgbImage::from_fn(truth.width, truth.height, |x, y| {
        let t = truth.class(x, y);
        let m = if x < mask.width && y < mask.height {
            mask.class(x, y)
        } else {
            Class::Background
        };
        Rgb(match (t, m) {
            (Class::Background, _) => c.background,
            (_, Class::Background) => c.coverage,
            (Class::Lit, Class::Lit) => c.lit,
            (Class::Shadowed, Class::Shadowed) => c.shadowed,
            (Class::Lit, Class::Shadowed) => c.false_shadow,
            (Class::Shadowed, Class::Lit) => c.missed_shadow,
        })
    })
}

/// Largest tile edge on the sheet, pixels.
pub const TILE: u32 = 256;
const GAP: u32 = 10;
const LABEL: u32 = 26;
const HEADER: u32 = 34;

/// One line of the sheet: its label and up to three pictures (missing ones are blank).
pub struct SheetLine<'a> {
    pub label: String,
    pub tiles: [Option<&'a RgbImage>; 3],
}

/// The sheet's line for a measured row.
pub fn row_label(r: &ResultRow) -> String {
    match &r.measured {
        Some(m) => format!(
            "{} · {} — error {:.2}% (false {}, missed {}) · {:.2} ms{}",
            r.technique,
            pipeline_name(r.pipeline),
            m.error_percent,
            m.false_shadow,
            m.missed_shadow,
            m.typical_ms,
            if r.pareto { " · Pareto" } else { "" }
        ),
        None => format!("{} · {} — skipped", r.technique, pipeline_name(r.pipeline)),
    }
}

fn fit(img: &RgbImage, tile: (u32, u32)) -> RgbImage {
    if img.dimensions() == tile {
        img.clone()
    } else {
        imageops::resize(img, tile.0, tile.1, imageops::FilterType::Nearest)
    }
}

/// RGBA → RGB, alpha dropped (rendered images are opaque).
pub fn rgb(img: &RgbaImage) -> RgbImage {
    image::DynamicImage::ImageRgba8(img.clone()).to_rgb8()
}

/// Mask → RGB grey.
pub fn mask_rgb(mask: &Mask) -> RgbImage {
    image::DynamicImage::ImageLuma8(mask.to_image()).to_rgb8()
}

/// Lays the sheet out and labels it. `size` is the rendered images' size.
pub fn contact_sheet(
    title: &str,
    size: (u32, u32),
    lines: &[SheetLine<'_>],
    path: &std::path::Path,
) -> Result<RgbImage, ReportError> {
    font::ensure()?;
    let scale = f64::from(TILE) / f64::from(size.0.max(size.1).max(1));
    let scale = scale.min(1.0);
    let tile = (
        ((f64::from(size.0) * scale).round() as u32).max(1),
        ((f64::from(size.1) * scale).round() as u32).max(1),
    );
    let width = (3 * tile.0 + 4 * GAP).max(620);
    let line_h = LABEL + tile.1 + GAP;
    let height = HEADER + GAP + line_h * lines.len() as u32;
    let bg = Rgb([250, 250, 250]);
    let mut sheet = RgbImage::from_pixel(width, height, bg);
    for (i, line) in lines.iter().enumerate() {
        let y = HEADER + GAP + i as u32 * line_h + LABEL;
        for (k, img) in line.tiles.iter().enumerate() {
            if let Some(img) = img {
                let x = GAP + k as u32 * (tile.0 + GAP);
                imageops::replace(&mut sheet, &fit(img, tile), i64::from(x), i64::from(y));
            }
        }
    }
    draw_labels(&mut sheet, title, tile, lines, path)?;
    Ok(sheet)
}

fn draw_labels(
    sheet: &mut RgbImage,
    title: &str,
    tile: (u32, u32),
    lines: &[SheetLine<'_>],
    path: &std::path::Path,
) -> Result<(), ReportError> {
    let (w, h) = sheet.dimensions();
    let err = super::plot_error(path);
    let root = BitMapBackend::with_buffer(sheet, (w, h)).into_drawing_area();
    let text = |s: &str, x: u32, y: u32, px: u32| {
        Text::new(
            s.to_string(),
            (x as i32, y as i32),
            (font::FAMILY, px).into_font().color(&BLACK),
        )
    };
    root.draw(&text(title, GAP, 8, 20)).map_err(|e| err(&e))?;
    let line_h = LABEL + tile.1 + GAP;
    for (i, line) in lines.iter().enumerate() {
        let y = HEADER + GAP + i as u32 * line_h;
        root.draw(&text(&line.label, GAP, y + 4, 15))
            .map_err(|e| err(&e))?;
    }
    // The legend sits in the first line's empty third tile when the first line has one.
    if lines.first().is_some_and(|l| l.tiles[2].is_none()) {
        let x0 = GAP + 2 * (tile.0 + GAP);
        let y0 = HEADER + GAP + LABEL;
        let c = ERROR_COLOURS;
        let entries = [
            (c.lit, "lit, correct"),
            (c.shadowed, "shadowed, correct"),
            (c.false_shadow, "false shadow (acne)"),
            (c.missed_shadow, "missed shadow (peter-panning)"),
            (c.coverage, "missing geometry"),
            (c.background, "background"),
        ];
        for (k, (rgb, name)) in entries.iter().enumerate() {
            let y = (y0 + 4 + k as u32 * 22) as i32;
            let colour = RGBColor(rgb[0], rgb[1], rgb[2]);
            root.draw(&Rectangle::new(
                [(x0 as i32, y), (x0 as i32 + 16, y + 16)],
                colour.filled(),
            ))
            .map_err(|e| err(&e))?;
            root.draw(&text(name, x0 + 22, y as u32 + 1, 14))
                .map_err(|e| err(&e))?;
        }
    }
    root.present().map_err(|e| err(&e))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::{BACKGROUND, LIT, SHADOWED};

    #[test]
    fn error_image_colours_each_kind_of_pixel() {
        let truth = Mask {
            width: 6,
            height: 1,
            data: vec![LIT, SHADOWED, LIT, SHADOWED, LIT, BACKGROUND],
        };
        let mask = Mask {
            width: 6,
            height: 1,
            data: vec![LIT, SHADOWED, SHADOWED, LIT, BACKGROUND, LIT],
        };
        let img = error_image(&mask, &truth);
        let c = ERROR_COLOURS;
        let got: Vec<[u8; 3]> = img.pixels().map(|p| p.0).collect();
        assert_eq!(
            got,
            vec![
                c.lit,
                c.shadowed,
                c.false_shadow,
                c.missed_shadow,
                c.coverage,
                c.background
            ]
        );
    }
}
