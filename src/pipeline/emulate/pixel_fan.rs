//! The fan glDrawPixels and glCopyPixels are drawn as, corner for corner Mesa's
//! (`st_cb_drawpixels.c`, `draw_textured_quad` and `st_draw_quad`): one triangle fan over
//! the zoomed rectangle whose corners carry normalised texture coordinates, the image read
//! with NEAREST. A fragment gets the image's pixel (⌊s·w⌋, ⌊t·h⌋) of the coordinates the
//! rasteriser interpolates at its centre, so which group a centre on a group boundary
//! joins (zoom 0.5, 1.5, 0.3, …) follows llvmpipe's float rounding — not a rule of the
//! specification — and only the same fan through the same rasteriser gives the same
//! pixels (measured against Mesa's OSMesa: `tests/c/pixel_zoom.c`).
//!
//! For the rectangle's corner (x, y) (integers: the raster position rounded), size w × h,
//! zoom (z_x, z_y) and the draw framebuffer's size W × H, Mesa's corners are, in fan order,
//! (x₀, y₁), (x₁, y₁), (x₁, y₀), (x₀, y₀) with s = 0, 1, 1, 0, where x₀ = x,
//! x₁ = x + w·z_x and the clip coordinate of a window x is x/W·2 − 1 (the same for y with
//! H), evaluated in that order in f32. Mesa draws them under a viewport that flips y:
//! - into a window-system framebuffer (stored top row first, its own viewport flipped
//!   too): y₀ = y, y₁ = y + h·z_y, and the clip y as computed;
//! - into a framebuffer object (bottom row first, its viewport not flipped): y₀ = y′,
//!   y₁ = y′ + h·z_y with y′ = H − trunc(y + h·z_y), and the clip y negated here so that
//!   the rasteriser sees Mesa's window coordinates.
//!
//! The t of the first two corners is 1 and of the last two 0, swapped when exactly one of
//! "the draw framebuffer is an object" and "the image's first row is its top" holds (the
//! latter for glCopyPixels from a window-system framebuffer, whose rows Mesa copies as
//! stored).

use glam::{Vec2, Vec4};

use crate::ff::PixelZoom;

/// How a framebuffer stores its rows: Mesa keeps a window-system framebuffer top row
/// first and a framebuffer object bottom row first (GL's order).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RowOrder {
    TopFirst,
    BottomFirst,
}

/// The t the fan's first two corners carry (the last two carry the other).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelFan {
    /// t = 1 at the first two corners, 0 at the last two.
    FirstCornersT1,
    /// t = 0 at the first two corners, 1 at the last two.
    FirstCornersT0,
}

impl PixelFan {
    /// The t of the first two corners and of the last two.
    pub fn corner_t(self) -> (f32, f32) {
        match self {
            PixelFan::FirstCornersT1 => (1.0, 0.0),
            PixelFan::FirstCornersT0 => (0.0, 1.0),
        }
    }
}

/// A rectangle's fan: its four corners in clip coordinates (z 0, w 1) and their t.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fan {
    pub corners: [Vec4; 4],
    pub t: PixelFan,
}

/// The fan of a `width` × `height` image at window `corner` under `zoom`, drawn into a
/// framebuffer of `size` stored in `draw` order, the image's rows in `image` order.
pub fn fan(
    corner: Vec2,
    (width, height): (i32, i32),
    zoom: PixelZoom,
    size: (i32, i32),
    draw: RowOrder,
    image: RowOrder,
) -> Fan {
    let (fb_w, fb_h) = (size.0.max(1) as f32, size.1.max(1) as f32);
    let clip = |v: f32, extent: f32| v / extent * 2.0 - 1.0;
    let x0 = corner.x;
    let x1 = corner.x + width as f32 * zoom.x;
    let (y0, y_sign) = match draw {
        RowOrder::TopFirst => (corner.y, 1.0),
        // trunc, as C's (int) conversion; saturating where C's is undefined.
        RowOrder::BottomFirst => (
            (size.1 - (corner.y + height as f32 * zoom.y) as i32) as f32,
            -1.0,
        ),
    };
    let y1 = y0 + height as f32 * zoom.y;
    let (cx0, cx1) = (clip(x0, fb_w), clip(x1, fb_w));
    let (cy0, cy1) = (y_sign * clip(y0, fb_h), y_sign * clip(y1, fb_h));
    let at = |x: f32, y: f32| Vec4::new(x, y, 0.0, 1.0);
    let t = match (draw == RowOrder::BottomFirst) != (image == RowOrder::TopFirst) {
        false => PixelFan::FirstCornersT1,
        true => PixelFan::FirstCornersT0,
    };
    Fan {
        corners: [at(cx0, cy1), at(cx1, cy1), at(cx1, cy0), at(cx0, cy0)],
        t,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ZOOM_HALF: PixelZoom = PixelZoom { x: 0.5, y: 0.5 };

    /// Into a window-system framebuffer the corners are the window rectangle's.
    #[test]
    fn a_window_fan_covers_the_zoomed_rectangle() {
        let f = fan(
            Vec2::new(16.0, 8.0),
            (32, 16),
            ZOOM_HALF,
            (64, 32),
            RowOrder::TopFirst,
            RowOrder::BottomFirst,
        );
        // x: 16 → −0.5, 32 → 0; y: 8 → −0.5, 16 → 0.
        assert_eq!(f.corners[0], Vec4::new(-0.5, 0.0, 0.0, 1.0));
        assert_eq!(f.corners[1], Vec4::new(0.0, 0.0, 0.0, 1.0));
        assert_eq!(f.corners[2], Vec4::new(0.0, -0.5, 0.0, 1.0));
        assert_eq!(f.corners[3], Vec4::new(-0.5, -0.5, 0.0, 1.0));
        assert_eq!(f.t, PixelFan::FirstCornersT1);
    }

    /// Into a framebuffer object the top edge is truncated to an integer and the bottom
    /// follows it: 8 + 5·1.5 = 15.5 → 15, so the rectangle spans 7.5 to 15.
    #[test]
    fn an_object_fan_truncates_its_top_edge() {
        let f = fan(
            Vec2::new(0.0, 8.0),
            (4, 5),
            PixelZoom { x: 1.0, y: 1.5 },
            (64, 32),
            RowOrder::BottomFirst,
            RowOrder::BottomFirst,
        );
        // y′ = 32 − 15 = 17, y₁ = 24.5; negated clip: 17 → −(1/16), 24.5 → −(17/32).
        assert_eq!(f.corners[0].y, -(24.5 / 32.0 * 2.0 - 1.0));
        assert_eq!(f.corners[3].y, -(17.0 / 32.0 * 2.0 - 1.0));
        // In window terms (y = (1 + clip)·H/2): the fan spans 7.5 … 15.
        assert_eq!((1.0 + f.corners[0].y) * 16.0, 7.5);
        assert_eq!((1.0 + f.corners[3].y) * 16.0, 15.0);
        assert_eq!(f.t, PixelFan::FirstCornersT0);
    }

    /// The t swaps with either order and returns with both.
    #[test]
    fn t_follows_both_row_orders() {
        let t = |draw, image| fan(Vec2::ZERO, (2, 2), ZOOM_HALF, (8, 8), draw, image).t;
        use RowOrder::*;
        assert_eq!(t(TopFirst, BottomFirst), PixelFan::FirstCornersT1);
        assert_eq!(t(BottomFirst, BottomFirst), PixelFan::FirstCornersT0);
        assert_eq!(t(TopFirst, TopFirst), PixelFan::FirstCornersT0);
        assert_eq!(t(BottomFirst, TopFirst), PixelFan::FirstCornersT1);
    }
}
