//! The picture the window shows: the view ([`Show`]) on top, a status bar of text below.
//!
//! The top is exactly the scene's image size (side by side: three of them in a row), so the
//! window's top rows are the render's own pixels and a screenshot compares with `render`'s
//! image directly; the status bar ([`STATUS_LINE`] pixels a line) sits under it, never over
//! it. With help on, the key list is drawn over the top on a darkened copy.
//!
//! Views: the image; the mask (white lit, black shadowed, grey background); the error image
//! of the mask against the truth (`report::error_image`: false shadow orange, missed blue),
//! the mask until the truth arrives; the light's map (`report::light_map_pictures`, its first
//! picture), scaled to the image's height with nearest texels; side by side: image, error
//! and map.

use image::{imageops, Rgb, RgbImage, RgbaImage};
use plotters::prelude::*;

use crate::metrics::Mask;
use crate::render::LightMap;
use crate::report::{self, font, ReportError};

use super::settings::Show;

/// Pixels per line of status text.
pub const STATUS_LINE: u32 = 16;
/// The status bar's width at least, so that its text reads on small images.
pub const MIN_WIDTH: u32 = 480;

const BAR: Rgb<u8> = Rgb([24, 26, 32]);
const TEXT: RGBColor = RGBColor(235, 235, 235);

/// What one frame left to show.
pub struct FrameParts<'a> {
    pub image: &'a RgbaImage,
    pub mask: &'a Mask,
    /// The truth's mask, once it has arrived for this view.
    pub truth: Option<&'a Mask>,
    pub map: Option<&'a LightMap>,
}

/// The top part of the picture: `show` of `parts`.
pub fn top(show: Show, parts: &FrameParts<'_>) -> RgbImage {
    let image = report::rgb(parts.image);
    let (w, h) = image.dimensions();
    let mask = || report::mask_rgb(parts.mask);
    let error = || match parts.truth {
        Some(t) if (t.width, t.height) == (parts.mask.width, parts.mask.height) => {
            report::error_image(parts.mask, t)
        }
        _ => mask(),
    };
    let map = || match parts
        .map
        .and_then(|m| report::light_map_pictures(m).into_iter().next())
    {
        Some((_, picture)) => {
            let side = h.max(1);
            imageops::resize(
                &report::rgb(&picture),
                side,
                side,
                imageops::FilterType::Nearest,
            )
        }
        None => RgbImage::from_pixel(h.max(1), h.max(1), BAR),
    };
    match show {
        Show::Image => image,
        Show::Mask => mask(),
        Show::Error => error(),
        Show::Map => map(),
        Show::SideBySide => {
            let (e, m) = (error(), map());
            let mut row = RgbImage::from_pixel(2 * w + m.width(), h, BAR);
            imageops::replace(&mut row, &image, 0, 0);
            imageops::replace(&mut row, &e, i64::from(w), 0);
            imageops::replace(&mut row, &m, i64::from(2 * w), 0);
            row
        }
    }
}

/// `top` with the status bar of `status` lines under it and, when given, the help drawn
/// over the top; opaque RGBA, top row first.
pub fn picture(
    top: &RgbImage,
    status: &[String],
    help: Option<&[String]>,
) -> Result<RgbaImage, ReportError> {
    font::ensure()?;
    let (w, h) = top.dimensions();
    let width = w.max(MIN_WIDTH);
    let bar = STATUS_LINE * status.len() as u32 + 6;
    let mut canvas = RgbImage::from_pixel(width, h + bar, BAR);
    imageops::replace(&mut canvas, top, 0, 0);
    if help.is_some() {
        for y in 0..h {
            for x in 0..w {
                let p = canvas.get_pixel_mut(x, y);
                p.0 = p.0.map(|c| c / 4);
            }
        }
    }
    let err = |e: &dyn std::fmt::Display| ReportError::Plot {
        path: "the viewer's window".into(),
        message: e.to_string(),
    };
    {
        let root = BitMapBackend::with_buffer(&mut canvas, (width, h + bar)).into_drawing_area();
        let style = (font::FAMILY, 13).into_font().color(&TEXT);
        for (i, line) in status.iter().enumerate() {
            let y = h + 4 + i as u32 * STATUS_LINE;
            root.draw(&Text::new(line.clone(), (6, y as i32), style.clone()))
                .map_err(|e| err(&e))?;
        }
        for (i, line) in help.unwrap_or(&[]).iter().enumerate() {
            let y = 4 + i as u32 * 14;
            if y + 14 > h {
                break;
            }
            root.draw(&Text::new(
                line.clone(),
                (6, y as i32),
                (font::FAMILY, 12).into_font().color(&TEXT),
            ))
            .map_err(|e| err(&e))?;
        }
        root.present().map_err(|e| err(&e))?;
    }
    Ok(image::DynamicImage::ImageRgb8(canvas).to_rgba8())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::{BACKGROUND, LIT, SHADOWED};

    #[test]
    fn the_top_rows_are_the_view_and_the_bar_sits_under_them() {
        let image = RgbaImage::from_fn(8, 4, |x, y| image::Rgba([x as u8 * 10, y as u8, 7, 255]));
        let mut mask = Mask::filled(8, 4, LIT);
        mask.data[0] = SHADOWED;
        let truth = Mask::filled(8, 4, LIT);
        let parts = FrameParts {
            image: &image,
            mask: &mask,
            truth: Some(&truth),
            map: None,
        };
        let shown = picture(&top(Show::Image, &parts), &["a".into(), "b".into()], None).unwrap();
        assert_eq!(shown.dimensions(), (MIN_WIDTH, 4 + 2 * STATUS_LINE + 6));
        for y in 0..4 {
            for x in 0..8 {
                assert_eq!(shown.get_pixel(x, y), image.get_pixel(x, y));
            }
        }
        let error = top(Show::Error, &parts);
        assert_eq!(error.get_pixel(0, 0).0, report::ERROR_COLOURS.false_shadow);
        assert_eq!(error.get_pixel(1, 0).0, report::ERROR_COLOURS.lit);
        let waiting = top(
            Show::Error,
            &FrameParts {
                truth: None,
                ..parts
            },
        );
        assert_eq!(
            waiting,
            report::mask_rgb(&mask),
            "the mask until the truth arrives"
        );
        let side = top(Show::SideBySide, &parts);
        assert_eq!(side.dimensions(), (2 * 8 + 4, 4));
        let _ = BACKGROUND;
    }
}
