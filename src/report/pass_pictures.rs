//! Pictures of what each pass left (`render::PassImages`): files named
//! `PREFIX` + `NN-PASS-KIND.png` — NN the pass's 1-based place in the frame (map passes
//! first), PASS the plan's name of the pass, KIND one of the list below — and a text legend
//! `PREFIX` + `legend.txt` with the rules and every picture's own numbers.
//!
//! - `color`: the colour buffer, opaque (its alpha is pictured by `alpha` where it
//!   matters); the last pass's is the frame's image.
//! - `depth`: the depth buffer normalised per picture: the depths below 1 (the clear value
//!   every pass clears to) stretched from their minimum (black) to their maximum (white);
//!   depth 1 — cleared, or geometry exactly at the far plane — pale blue ([`CLEARED`]);
//!   a picture whose depths are all equal is black. No legend is drawn (the picture stays
//!   the buffer's size); each picture's range is listed in the legend file.
//! - `stencil`: each stencil value its own colour ([`stencil_colour`]), the values present
//!   listed beside the picture.
//! - `alpha` (passes with an alpha test): the alpha the pass computed before its test, grey
//!   0 black … 255 white, [`NOT_DRAWN`] where the pass drew nothing; the test beside it.
//! - `map-minus-ramp` (dual8, linear8, multidigit16): M − F in 8-bit steps
//!   ([`step_colour`]): lit side (> 0) blue, darker with more steps; the tie (0) magenta —
//!   shadowed, GREATER fails on equality; shadowed side (< 0) orange, darker with more
//!   steps; beyond ±8 steps the colour of ±8; [`NOT_COMPARED`] where the pass did not
//!   compare. The values present are listed beside the picture.
//! - `map-depth`, `map-big-digit`, `map-little-digit` (after the last map pass): the light's
//!   map as the texture holds it (`light_map_pictures`, as `render --depth-map`).
//!
//! The false-colour legends are drawn beside the picture (the pass's pixels stay at the
//! top-left, one to one) with the report's font, like the contact sheet's.
//!
//! [`strip`] groups the files by pass for `compare`'s page: one thumbnail per pass (the
//! colour picture of an eye pass; of a map pass, the light's map where it leaves one, else
//! its depth) and the pass's other pictures as links.

use std::fmt::Write as _;
use std::path::Path;

use image::{imageops, Rgb, RgbImage};
use plotters::prelude::*;

use crate::render::{Corner, PassImage, PassImages};
use crate::vocab::Named;

use super::{ensure_dir, font, light_map_pictures, write_png, write_text, ReportError, Written};

/// Depth 1: cleared (pale blue).
pub const CLEARED: [u8; 3] = [170, 205, 255];
/// Alpha picture: a pixel the pass did not draw.
pub const NOT_DRAWN: [u8; 3] = [0, 120, 110];
/// Map-minus-ramp picture: a pixel the pass did not compare.
pub const NOT_COMPARED: [u8; 3] = [48, 48, 58];
/// Steps beyond which the map-minus-ramp colours saturate.
pub const STEP_RANGE: i16 = 8;

/// One picture of one pass, and the file it goes to.
#[derive(Debug, Clone)]
pub struct PassPicture {
    /// The pass's 1-based place in the frame.
    pub number: usize,
    pub pass: &'static str,
    /// Drawn in the light's map corner (a map pass).
    pub map_pass: bool,
    /// `color`, `depth`, `stencil`, `alpha`, `map-minus-ramp`, `map-…`.
    pub kind: String,
    pub file: String,
    pub image: RgbImage,
}

/// One pass in a strip: its thumbnail and every picture as (kind, file).
#[derive(Debug, Clone, PartialEq)]
pub struct StripPass {
    pub number: usize,
    pub name: &'static str,
    pub thumbnail: String,
    pub files: Vec<(String, String)>,
}

/// The pictures grouped by pass, in order, with the thumbnail the module note chooses.
pub fn strip(pictures: &[PassPicture]) -> Vec<StripPass> {
    let mut out: Vec<StripPass> = Vec::new();
    for p in pictures {
        match out.last_mut() {
            Some(s) if s.number == p.number => s.files.push((p.kind.clone(), p.file.clone())),
            _ => out.push(StripPass {
                number: p.number,
                name: p.pass,
                thumbnail: String::new(),
                files: vec![(p.kind.clone(), p.file.clone())],
            }),
        }
    }
    for s in &mut out {
        let find = |pick: &dyn Fn(&str) -> bool| {
            s.files
                .iter()
                .find(|(kind, _)| pick(kind))
                .map(|(_, f)| f.clone())
        };
        let map_pass = pictures.iter().any(|p| p.number == s.number && p.map_pass);
        s.thumbnail = if map_pass {
            find(&|k| k.starts_with("map-")).or_else(|| find(&|k| k == "depth"))
        } else {
            find(&|k| k == "color")
        }
        .unwrap_or_default();
    }
    out
}

/// The legend's file name under `prefix`.
pub fn legend_name(prefix: &str) -> String {
    format!("{prefix}legend.txt")
}

/// Every pass's pictures, in pass order, named under `prefix`.
pub fn pass_pictures(images: &PassImages, prefix: &str) -> Result<Vec<PassPicture>, ReportError> {
    let mut out = Vec::new();
    for pass in &images.passes {
        let mut add = |kind: &str, image: RgbImage| {
            out.push(PassPicture {
                number: pass.number,
                pass: pass.name,
                map_pass: pass.corner == Corner::Map,
                kind: kind.to_string(),
                file: format!("{prefix}{:02}-{}-{kind}.png", pass.number, pass.name),
                image,
            });
        };
        add("color", color(pass));
        add("depth", depth_picture(pass));
        if pass.stencil.is_some() {
            add("stencil", stencil_picture(pass)?);
        }
        if pass.alpha.is_some() {
            add("alpha", alpha_picture(pass)?);
        }
        if pass.map_minus_ramp.is_some() {
            add("map-minus-ramp", steps_picture(pass)?);
        }
        if let Some(map) = &pass.map {
            for (label, picture) in light_map_pictures(map) {
                add(
                    &format!("map-{label}"),
                    image::DynamicImage::from(picture).to_rgb8(),
                );
            }
        }
    }
    Ok(out)
}

/// Writes every picture and the legend into `dir` (created when missing); each file is
/// complete or absent (`files`).
pub fn write_pass_images(
    images: &PassImages,
    dir: &Path,
    prefix: &str,
) -> Result<(Vec<PassPicture>, Written), ReportError> {
    ensure_dir(dir)?;
    let pictures = pass_pictures(images, prefix)?;
    let mut written = Written::default();
    for p in &pictures {
        write_png(dir, &p.file, &p.image, &mut written)?;
    }
    write_text(
        dir,
        &legend_name(prefix),
        &legend(images, &pictures),
        &mut written,
    )?;
    Ok((pictures, written))
}

fn rgb(c: [u8; 3]) -> Rgb<u8> {
    Rgb(c)
}

fn color(pass: &PassImage) -> RgbImage {
    image::DynamicImage::from(pass.color.clone()).to_rgb8()
}

/// The smallest and largest depth below 1, if any.
fn depth_range(depth: &[f32]) -> Option<(f32, f32)> {
    depth
        .iter()
        .filter(|&&z| z < 1.0)
        .fold(None, |r, &z| match r {
            None => Some((z, z)),
            Some((lo, hi)) => Some((lo.min(z), hi.max(z))),
        })
}

/// The module note's depth rule for one value.
fn depth_colour(z: f32, range: Option<(f32, f32)>) -> [u8; 3] {
    match range {
        _ if z >= 1.0 => CLEARED,
        Some((lo, hi)) if hi > lo => {
            let v = ((z - lo) / (hi - lo) * 255.0).round().clamp(0.0, 255.0) as u8;
            [v; 3]
        }
        _ => [0; 3],
    }
}

fn depth_picture(pass: &PassImage) -> RgbImage {
    let range = depth_range(&pass.depth);
    RgbImage::from_fn(pass.width, pass.height, |x, y| {
        rgb(depth_colour(
            pass.depth[(y * pass.width + x) as usize],
            range,
        ))
    })
}

/// A colour per stencil value, each its own: 0 black, 1…15 from a hand-picked table of
/// distinguishable colours, 16…255 spread over hue, saturation and value.
pub fn stencil_colour(v: u8) -> [u8; 3] {
    const TABLE: [[u8; 3]; 16] = [
        [0, 0, 0],
        [230, 159, 0],
        [86, 180, 233],
        [0, 158, 115],
        [240, 228, 66],
        [0, 114, 178],
        [213, 94, 0],
        [204, 121, 167],
        [255, 255, 255],
        [128, 128, 128],
        [128, 0, 0],
        [0, 128, 128],
        [128, 128, 0],
        [255, 0, 255],
        [0, 255, 0],
        [90, 60, 160],
    ];
    if let Some(c) = TABLE.get(usize::from(v)) {
        return *c;
    }
    // 240 values: 40 hues × 3 values × 2 saturations.
    let i = u32::from(v) - 16;
    // Half a step off the primaries, which the table holds.
    let hue = ((i % 40) as f32 + 0.5) / 40.0;
    let value = [1.0, 0.75, 0.5][((i / 40) % 3) as usize];
    let saturation = [1.0, 0.55][(i / 120) as usize % 2];
    hsv(hue, saturation, value)
}

fn hsv(h: f32, s: f32, v: f32) -> [u8; 3] {
    let h6 = h * 6.0;
    let f = h6 - h6.floor();
    let (p, q, t) = (v * (1.0 - s), v * (1.0 - s * f), v * (1.0 - s * (1.0 - f)));
    let (r, g, b) = match h6 as u32 % 6 {
        0 => (v, t, p),
        1 => (q, v, p),
        2 => (p, v, t),
        3 => (p, q, v),
        4 => (t, p, v),
        _ => (v, p, q),
    };
    let c = |x: f32| (x * 255.0).round() as u8;
    [c(r), c(g), c(b)]
}

/// Legend lines beyond which the remaining values are summed up in one line.
const MAX_ENTRIES: usize = 20;

fn stencil_picture(pass: &PassImage) -> Result<RgbImage, ReportError> {
    let stencil = pass.stencil.as_deref().unwrap_or(&[]);
    let img = RgbImage::from_fn(pass.width, pass.height, |x, y| {
        rgb(stencil_colour(stencil[(y * pass.width + x) as usize]))
    });
    let mut counts = [0u64; 256];
    for &s in stencil {
        counts[usize::from(s)] += 1;
    }
    let present: Vec<(u8, u64)> = (0..=255u8).zip(counts).filter(|&(_, n)| n > 0).collect();
    let mut entries: Vec<(Option<[u8; 3]>, String)> = present
        .iter()
        .take(MAX_ENTRIES)
        .map(|&(v, n)| (Some(stencil_colour(v)), format!("{v}: {n} px")))
        .collect();
    if present.len() > MAX_ENTRIES {
        entries.push((
            None,
            format!("… {} more values", present.len() - MAX_ENTRIES),
        ));
    }
    with_legend(&img, "stencil", &entries)
}

fn alpha_picture(pass: &PassImage) -> Result<RgbImage, ReportError> {
    let Some(alpha) = &pass.alpha else {
        return Ok(RgbImage::new(pass.width, pass.height));
    };
    let img = RgbImage::from_fn(pass.width, pass.height, |x, y| {
        match alpha.alpha[(y * pass.width + x) as usize] {
            Some(a) => Rgb([a; 3]),
            None => rgb(NOT_DRAWN),
        }
    });
    let entries = vec![
        (Some([0; 3]), "alpha 0".to_string()),
        (Some([255; 3]), "alpha 255".to_string()),
        (Some(NOT_DRAWN), "not drawn".to_string()),
        (None, alpha_test_text(alpha.test)),
    ];
    with_legend(&img, "alpha before the test", &entries)
}

fn alpha_test_text(test: Option<(crate::ff::CompareFunc, f32)>) -> String {
    match test {
        Some((func, reference)) => format!(
            "test {} {reference:.3} ({:.1}/255)",
            format!("{func:?}").to_uppercase(),
            reference * 255.0
        ),
        None => "test: as set before".to_string(),
    }
}

/// The module note's colour for M − F = `d` steps (`None`: not compared).
pub fn step_colour(d: Option<i16>) -> [u8; 3] {
    let lerp = |a: [u8; 3], b: [u8; 3], t: f32| {
        [0, 1, 2].map(|i| (f32::from(a[i]) + (f32::from(b[i]) - f32::from(a[i])) * t).round() as u8)
    };
    let k = |d: i16| f32::from(d.abs().min(STEP_RANGE) - 1) / f32::from(STEP_RANGE - 1);
    match d {
        None => NOT_COMPARED,
        Some(0) => [230, 0, 180],
        Some(d) if d > 0 => lerp([170, 215, 255], [10, 60, 170], k(d)),
        Some(d) => lerp([255, 205, 140], [150, 40, 0], k(d)),
    }
}

/// `+3 lit`, `0 tie: shadowed`, `≤ −8 shadowed`.
fn step_label(d: i16) -> String {
    let side = match d {
        0 => "tie: shadowed",
        d if d > 0 => "lit",
        _ => "shadowed",
    };
    match d {
        d if d >= STEP_RANGE => format!("≥ +{STEP_RANGE} {side}"),
        d if d <= -STEP_RANGE => format!("≤ −{STEP_RANGE} {side}"),
        d if d > 0 => format!("+{d} {side}"),
        d if d < 0 => format!("−{} {side}", -d),
        _ => format!("0 {side}"),
    }
}

fn steps_picture(pass: &PassImage) -> Result<RgbImage, ReportError> {
    let steps = pass.map_minus_ramp.as_deref().unwrap_or(&[]);
    let img = RgbImage::from_fn(pass.width, pass.height, |x, y| {
        rgb(step_colour(steps[(y * pass.width + x) as usize]))
    });
    let mut present = std::collections::BTreeMap::new();
    for d in steps {
        let key = d.map(|d| d.clamp(-STEP_RANGE, STEP_RANGE));
        *present.entry(key).or_insert(0u64) += 1;
    }
    let mut entries: Vec<(Option<[u8; 3]>, String)> = present
        .iter()
        .rev()
        .map(|(&d, n)| {
            let text = d.map_or("not compared".to_string(), step_label);
            (Some(step_colour(d)), format!("{text}: {n} px"))
        })
        .collect();
    entries.truncate(MAX_ENTRIES);
    with_legend(&img, "map − ramp, 8-bit steps", &entries)
}

const PANEL: u32 = 210;
const LINE: u32 = 16;

/// `picture` at the top-left, a legend panel beside it: `title`, then per entry a swatch
/// (when it has a colour) and a text.
fn with_legend(
    picture: &RgbImage,
    title: &str,
    entries: &[(Option<[u8; 3]>, String)],
) -> Result<RgbImage, ReportError> {
    font::ensure()?;
    let (w, h) = picture.dimensions();
    let width = w + PANEL;
    let height = h.max(LINE * (entries.len() as u32 + 1) + 8);
    let mut canvas = RgbImage::from_pixel(width, height, Rgb([250, 250, 250]));
    imageops::replace(&mut canvas, picture, 0, 0);
    let err = super::plot_error(Path::new(title));
    {
        let root = BitMapBackend::with_buffer(&mut canvas, (width, height)).into_drawing_area();
        let x0 = (w + 8) as i32;
        let style = (font::FAMILY, 12).into_font().color(&BLACK);
        root.draw(&Text::new(title.to_string(), (x0, 4), style.clone()))
            .map_err(|e| err(&e))?;
        for (k, (c, text)) in entries.iter().enumerate() {
            let y = (4 + LINE * (k as u32 + 1)) as i32;
            if let Some(c) = c {
                let square = [(x0, y), (x0 + 12, y + 12)];
                root.draw(&Rectangle::new(square, RGBColor(c[0], c[1], c[2]).filled()))
                    .map_err(|e| err(&e))?;
                root.draw(&Rectangle::new(square, BLACK))
                    .map_err(|e| err(&e))?;
            }
            root.draw(&Text::new(text.clone(), (x0 + 18, y), style.clone()))
                .map_err(|e| err(&e))?;
        }
        root.present().map_err(|e| err(&e))?;
    }
    Ok(canvas)
}

/// The legend file: the rules of the module note, then each picture's numbers.
pub fn legend(images: &PassImages, pictures: &[PassPicture]) -> String {
    let mut t = String::new();
    let _ = writeln!(
        t,
        "Pass images of `{}`: what each pass of one frame left in the framebuffer ({}-bit \
         depth, {} stencil bits), map passes first (in the light's map corner), then the \
         eye passes (in the image's corner). Files: NN-PASS-KIND.png.\n",
        images.technique.name(),
        images.depth_bits,
        images.stencil_bits
    );
    t.push_str(RULES);
    if let Some(what) = crate::render::pass_images::map_minus_ramp(images.technique) {
        let _ = writeln!(t, "map-minus-ramp here measures {what}.");
    }
    t.push('\n');
    for pass in &images.passes {
        let _ = writeln!(
            t,
            "{:02} {} ({}×{}, {} corner)",
            pass.number,
            pass.name,
            pass.width,
            pass.height,
            match pass.corner {
                Corner::Map => "map",
                Corner::Image => "image",
            }
        );
        for p in pictures.iter().filter(|p| p.number == pass.number) {
            let facts = picture_facts(pass, &p.kind).map_or(String::new(), |f| format!(": {f}"));
            let _ = writeln!(t, "  {}{facts}", p.file);
        }
    }
    t
}

const RULES: &str = "\
color: the colour buffer, opaque; the last pass's is the frame's image.
depth: depths below 1 stretched from their minimum (black) to their maximum (white), \
depth 1 (cleared) pale blue; all equal: black. Each picture's own range is listed below.
stencil: each stencil value its own colour; the values present are listed beside it.
alpha: the alpha the pass computed before its alpha test (the pass replayed without the \
test, masks and blending), grey 0 black … 255 white; teal where the pass drew nothing.
map-minus-ramp: M − F in 8-bit steps, measured exactly by replaying the pass with \
SUBTRACT in place of its comparison: > 0 lit side (blue, darker with more steps), 0 the \
tie (magenta, shadowed: GREATER fails on equality), < 0 shadowed side (orange, darker \
with more steps), saturating at ±8; dark grey where the pass did not compare.
map-*: the light's map as its texture holds it (as render --depth-map writes it).
";

/// A picture's own numbers for the legend file, where it has some.
fn picture_facts(pass: &PassImage, kind: &str) -> Option<String> {
    Some(match kind {
        "depth" => match depth_range(&pass.depth) {
            Some((lo, hi)) => format!("z {lo:.6} (black) … {hi:.6} (white)"),
            None => "every depth is 1 (cleared)".to_string(),
        },
        "stencil" => {
            let mut values: Vec<u8> = pass.stencil.iter().flatten().copied().collect();
            values.sort_unstable();
            values.dedup();
            format!("values {values:?}")
        }
        "alpha" => alpha_test_text(pass.alpha.as_ref()?.test),
        "map-minus-ramp" => {
            let steps: Vec<i16> = pass
                .map_minus_ramp
                .iter()
                .flatten()
                .flatten()
                .copied()
                .collect();
            match (steps.iter().min(), steps.iter().max()) {
                (Some(lo), Some(hi)) => format!(
                    "steps {lo} … {hi}; {} compared pixels, {} of them ≤ 0 (shadowed)",
                    steps.len(),
                    steps.iter().filter(|&&d| d <= 0).count()
                ),
                _ => "no pixel compared".to_string(),
            }
        }
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn picture(number: usize, pass: &'static str, map_pass: bool, kind: &str) -> PassPicture {
        PassPicture {
            number,
            pass,
            map_pass,
            kind: kind.to_string(),
            file: format!("{number:02}-{pass}-{kind}.png"),
            image: RgbImage::new(1, 1),
        }
    }

    #[test]
    fn a_strip_shows_each_pass_by_its_most_telling_picture() {
        let pictures = [
            picture(1, "light", true, "color"),
            picture(1, "light", true, "depth"),
            picture(2, "upload", true, "depth"),
            picture(2, "upload", true, "map-depth"),
            picture(3, "lit", false, "color"),
            picture(3, "lit", false, "alpha"),
        ];
        let strip = strip(&pictures);
        let thumbnails: Vec<&str> = strip.iter().map(|s| s.thumbnail.as_str()).collect();
        assert_eq!(
            thumbnails,
            [
                "01-light-depth.png",
                "02-upload-map-depth.png",
                "03-lit-color.png"
            ]
        );
        assert_eq!(strip[2].files.len(), 2);
        assert_eq!(strip[2].name, "lit");
    }

    #[test]
    fn every_stencil_value_has_its_own_colour() {
        let mut colours: Vec<[u8; 3]> = (0..=255u8).map(stencil_colour).collect();
        colours.sort_unstable();
        colours.dedup();
        assert_eq!(colours.len(), 256);
    }

    #[test]
    fn depth_is_stretched_and_cleared_depth_stands_apart() {
        let range = depth_range(&[0.5, 0.75, 1.0]);
        assert_eq!(range, Some((0.5, 0.75)));
        assert_eq!(depth_colour(0.5, range), [0; 3]);
        assert_eq!(depth_colour(0.75, range), [255; 3]);
        assert_eq!(depth_colour(0.625, range), [128; 3]);
        assert_eq!(depth_colour(1.0, range), CLEARED);
        assert_eq!(depth_colour(0.3, Some((0.3, 0.3))), [0; 3]);
        assert_eq!(depth_range(&[1.0]), None);
    }

    #[test]
    fn steps_have_a_side_and_saturate() {
        assert_eq!(step_colour(Some(0)), [230, 0, 180]);
        assert_eq!(step_colour(Some(8)), step_colour(Some(100)));
        assert_eq!(step_colour(Some(-8)), step_colour(Some(-100)));
        assert_ne!(step_colour(Some(1)), step_colour(Some(2)));
        assert_ne!(step_colour(Some(-1)), step_colour(Some(1)));
        assert_eq!(step_colour(None), NOT_COMPARED);
        assert_eq!(step_label(-9), "≤ −8 shadowed");
        assert_eq!(step_label(3), "+3 lit");
        assert_eq!(step_label(0), "0 tie: shadowed");
    }
}
