//! The comparison as one HTML page: a headline (most accurate, fastest, the Pareto front),
//! the table with bars for error and time, the error by object (a scene of several
//! objects only), the plot beside the truth and the error colours,
//! a card per technique × pipeline (image, mask, error image, figures, why it is right or
//! wrong here, notes, the strip of its passes), the scene, and where the time went. Inline
//! CSS, no scripts, no network: pictures are referred to by bare file name and only when
//! [`Written`] lists them.
//!
//! **Why, in one sentence** ([`why`]): computed from the row's counts, never canned. Acne
//! is false shadow (lit in the truth, so on a surface facing the light, and shadowed by the
//! technique); peter-panning is missed shadow (shadowed in the truth, lit by the
//! technique: the shadow detached from its contact). Errors within the edge band are
//! aliasing. For the 8-bit maps the sentence gives one 8-bit step in scene units at the
//! receivers ([`map_step`]): `linear8`'s ramp spreads 256 steps evenly over the light's
//! range, (far − near)/256; `dual8`'s map holds ⌊255·z⌋ of perspective depth, whose step at
//! eye distance d from the light is d²·(far − near)/(far·near·255) — given over the
//! receivers' vertex distances (clamped to the light's range).

use std::fmt::Write as _;

use crate::ff::Command;
use crate::render::pipeline_name;
use crate::scene::Scene;
use crate::study::{Comparison, RowResult};
use crate::techniques::parts::ShadowLight;
use crate::vocab::{Named, TechniqueId};

use super::file_names::{
    RowFiles, CSV, JSON, OBJECTS_CSV, PLOT_PNG, PLOT_SVG, SHEET, TRUTH_MASK, VISIBILITY_PLOT_SVG,
};
use super::objects::{columns, share_of, Share};
use super::pass_pictures::StripPass;
use super::table::ms_cell;
use super::{ResultRow, Written, ERROR_COLOURS};

/// Text made safe for HTML content and attribute values.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for ch in text.chars() {
        match ch {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// The rules both pages (compare and sweep-bias) share: page, headings, tables, legends.
pub(super) const BASE_STYLE: &str = "
body{font-family:system-ui,'DejaVu Sans',sans-serif;margin:0 auto;max-width:1360px;padding:24px 28px;color:#1d1f24;background:#fafafa}
@media (max-width:960px){body{padding:12px}}
h1{font-size:28px;margin:0 0 6px}h2{font-size:21px;margin:28px 0 10px;border-bottom:2px solid #e2e4ea;padding-bottom:4px}
.lead{font-size:17px;line-height:1.5;margin:6px 0}.lead b{color:#0a4fa8}.muted{color:#5b6070;font-size:14px}
table{border-collapse:collapse;font-size:13.5px;background:#fff}
th,td{padding:5px 6px;border-bottom:1px solid #e6e8ee;text-align:right;white-space:nowrap}
th{background:#eef0f5;font-weight:600;vertical-align:bottom}td.name,th.name{text-align:left}
tr.skip td{color:#80859a;font-style:italic}
.legend{list-style:none;padding:0;margin:10px 0;font-size:14px;columns:2}
.legend li{margin:4px 0}.sw{display:inline-block;width:14px;height:14px;vertical-align:-2px;margin-right:6px;border:1px solid #999}
.wide{overflow-x:auto}
";

/// The compare page's own rules. Its results table fits a 900 px window: header cells and
/// the technique and offset cells wrap, the three counts share one column, and a wrapper
/// scrolls it rather than the page should a window be narrower still.
const STYLE: &str = "
h3{font-size:16px;margin:0 0 8px}
table{width:100%}th{white-space:normal}td.wrap{white-space:normal}
tr.front td{background-color:#eefaf2}
.bar{background-repeat:no-repeat;background-size:var(--w) 70%;background-position:left center}
.err{background-image:linear-gradient(#f7c9a6,#f7c9a6)}.time{background-image:linear-gradient(#bcd4f5,#bcd4f5)}
.two{display:grid;grid-template-columns:3fr 2fr;gap:24px;align-items:start}
.two img{width:100%;border:1px solid #dde0e8;background:#fff}
.cards{display:grid;grid-template-columns:repeat(2,1fr);gap:18px}
@media (max-width:960px){.cards,.two{grid-template-columns:1fr}}
.card{background:#fff;border:1px solid #dde0e8;border-radius:6px;padding:12px}
.card.front{border-color:#3aa76d;box-shadow:0 0 0 1px #3aa76d}
.pics{display:grid;grid-template-columns:repeat(3,1fr);gap:6px}
.pics figure{margin:0}.pics img{width:100%;image-rendering:pixelated;display:block}
.pics figcaption{font-size:12px;color:#5b6070;text-align:center}
.fig{font-size:14px;margin:8px 0 0}.note{font-size:13px;color:#8a4b00;margin:4px 0 0}
dl{display:grid;grid-template-columns:max-content 1fr;gap:4px 16px;font-size:14px}dt{font-weight:600}dd{margin:0}
.why{font-size:14px;margin:6px 0 0}.strip{display:flex;gap:6px;overflow-x:auto;margin:8px 0 0}
.strip figure{margin:0;flex:none;width:96px}.strip img{width:96px;image-rendering:pixelated;display:block;border:1px solid #dde0e8}
.strip figcaption{font-size:11px;color:#5b6070;line-height:1.3}.strip figcaption a{color:#0a4fa8}
.tag{display:inline-block;font-size:11px;padding:1px 6px;border-radius:8px;background:#3aa76d;color:#fff;margin-left:6px;vertical-align:2px}
";

/// A row's pass strip: its files' stem, its passes, the legend file's name.
#[derive(Debug, Clone, PartialEq)]
pub struct PassStrip {
    pub slug: String,
    pub passes: Vec<StripPass>,
    pub legend: String,
}

/// The page. `facts` describe the scene; `written` lists the files next to the page;
/// `strips` the rows' pass pictures.
pub fn page(
    c: &Comparison,
    rows: &[ResultRow],
    scene: &str,
    facts: &[(String, String)],
    written: &Written,
    strips: &[PassStrip],
) -> String {
    let mut h = String::new();
    let _ = write!(
        h,
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <meta name=\"viewport\" content=\"width=device-width\">\
         <title>fixedfunc compare — {}</title><style>{BASE_STYLE}{STYLE}</style></head><body>\n",
        escape(scene)
    );
    headline(&mut h, c, rows, scene);
    table(&mut h, rows);
    objects_table(&mut h, rows);
    plot_and_truth(&mut h, written);
    cards(&mut h, c, rows, written, strips);
    scene_section(&mut h, facts, c);
    footer(&mut h, c, written);
    h.push_str("</body></html>\n");
    h
}

fn label(r: &ResultRow) -> String {
    format!("{} ({})", r.technique, pipeline_name(r.pipeline))
}

fn headline(h: &mut String, c: &Comparison, rows: &[ResultRow], scene: &str) {
    let measured: Vec<(&ResultRow, &super::Measured)> = rows
        .iter()
        .filter_map(|r| r.measured.as_ref().map(|m| (r, m)))
        .collect();
    let best = measured
        .iter()
        .min_by(|a, b| a.1.error_percent.total_cmp(&b.1.error_percent));
    let fastest = measured
        .iter()
        .min_by(|a, b| a.1.typical_ms.total_cmp(&b.1.typical_ms));
    let mut front: Vec<&(&ResultRow, &super::Measured)> =
        measured.iter().filter(|(r, _)| r.pareto).collect();
    front.sort_by(|a, b| a.1.typical_ms.total_cmp(&b.1.typical_ms));
    let skipped = rows.len() - measured.len();
    let _ = write!(
        h,
        "<header><h1>Shadow techniques compared: accuracy against time</h1>\
         <p class=\"lead\">{} — {} runs measured{} on the {} backend, {}×{} pixels, \
         {} frames each with the frames of all runs interleaved; shadow map {}. Error is the \
         share of geometry pixels whose shadow differs from a ray-cast ground truth.</p>",
        escape(scene),
        measured.len(),
        if skipped > 0 {
            format!(", {skipped} skipped")
        } else {
            String::new()
        },
        rows.first().map_or("egl", |r| r.backend.name()),
        c.scene.image.width,
        c.scene.image.height,
        c.frames,
        escape(&shadow_brief(&c.scene.shadow))
    );
    h.push_str("<p class=\"lead\">");
    if let Some((r, m)) = best {
        let _ = write!(
            h,
            "Most accurate: <b>{}</b>, {:.2}% wrong. ",
            escape(&label(r)),
            m.error_percent
        );
    }
    if let Some((r, m)) = fastest {
        let _ = write!(
            h,
            "Fastest: <b>{}</b>, {:.2} ms per frame. ",
            escape(&label(r)),
            m.typical_ms
        );
    }
    if !front.is_empty() {
        let names: Vec<String> = front.iter().map(|(r, _)| escape(&label(r))).collect();
        let _ = write!(
            h,
            "Best trade-offs (Pareto front, fastest first): <b>{}</b>.",
            names.join("</b> → <b>")
        );
    }
    h.push_str("</p></header>\n");
}

/// `256² texels, 24-bit depth, no polygon offset`.
fn shadow_brief(s: &crate::scene::ShadowSettings) -> String {
    format!(
        "{}² texels, {} depth, {}",
        s.map_size,
        super::heatmap::depth_label(s.depth),
        super::offset_brief(s)
    )
}

fn table(h: &mut String, rows: &[ResultRow]) {
    let max = |f: fn(&super::Measured) -> f64| {
        rows.iter()
            .filter_map(|r| r.measured.as_ref().map(f))
            .fold(0.0, f64::max)
            .max(1e-9)
    };
    let (max_err, max_ms) = (max(|m| m.error_percent), max(|m| m.typical_ms));
    h.push_str(
        "<h2>Results</h2><div class=\"wide\"><table><tr><th class=\"name\">technique</th><th class=\"name\">pipeline</th>\
         <th class=\"name\">polygon offset</th><th>error %</th><th>false shadow</th><th>missed shadow</th><th>error % outside edge band</th>\
         <th>ms per frame: median [min–max]</th><th>cold frame ms</th><th>passes · programs · maps made</th></tr>\n",
    );
    for r in rows {
        let name = format!(
            "<td class=\"name wrap\" title=\"{}\">{}{}</td><td class=\"name\">{}</td>",
            escape(r.summary),
            escape(r.technique.name()),
            if r.pareto {
                "<span class=\"tag\">Pareto</span>"
            } else {
                ""
            },
            pipeline_name(r.pipeline)
        );
        match (&r.measured, &r.skipped) {
            (Some(m), _) => {
                let _ = writeln!(
                    h,
                    "<tr{}>{name}<td class=\"name wrap\">{}</td><td class=\"bar err\" style=\"--w:{:.0}%\">{:.2}</td><td>{}</td><td>{}</td>\
                     <td>{:.2}</td><td class=\"bar time wrap\" style=\"--w:{:.0}%\">{}</td><td>{:.1}</td>\
                     <td>{} · {} · {}</td></tr>",
                    if r.pareto { " class=\"front\"" } else { "" },
                    escape(&m.offset_cell()),
                    100.0 * m.error_percent / max_err,
                    m.error_percent,
                    m.false_shadow,
                    m.missed_shadow,
                    m.outside_band_error_percent,
                    100.0 * m.typical_ms / max_ms,
                    ms_cell(m),
                    m.cold_ms,
                    m.passes,
                    m.programs_compiled,
                    m.maps_made
                );
            }
            (None, reason) => {
                let _ = writeln!(
                    h,
                    "<tr class=\"skip\">{name}<td class=\"name\" colspan=\"8\">skipped: {}</td></tr>",
                    escape(reason.as_deref().unwrap_or("not run"))
                );
            }
        }
    }
    h.push_str(
        "</table></div><p class=\"muted\">Green rows are on the Pareto front: no other run is faster \
         beyond doubt (all its frames quicker) and as accurate, or as fast within the frames' \
         spread (their time ranges overlap) and more accurate. False shadow: lit in the truth, shadowed by the technique \
         (acne). Missed shadow: shadowed in the truth, lit by the technique (peter-panning). \
         The edge band excludes pixels next to the truth's shadow edges, where one pixel of \
         aliasing is expected.</p>\n",
    );
}

/// "Error by object": one row per run, three columns per object (self-shadow, from
/// others, lit: wrong % of the truth's pixels of that kind, the counts in the cell's
/// title). Only for a scene of several objects: no row has a split otherwise.
fn objects_table(h: &mut String, rows: &[ResultRow]) {
    let columns = columns(rows);
    if columns.is_empty() {
        return;
    }
    h.push_str(
        "<h2>Error by object</h2><div class=\"wide\"><table><tr><th class=\"name\" rowspan=\"2\">technique</th>\
         <th class=\"name\" rowspan=\"2\">pipeline</th>",
    );
    for (_, name) in &columns {
        let _ = write!(h, "<th colspan=\"3\">{}</th>", escape(name));
    }
    h.push_str("</tr>\n<tr>");
    for _ in &columns {
        h.push_str("<th>self-shadow %</th><th>from others %</th><th>lit %</th>");
    }
    h.push_str("</tr>\n");
    let cell = |s: &Share| format!("<td title=\"{} of {} px\">{}</td>", s.wrong, s.of, s.cell());
    for r in rows {
        let name = format!(
            "<td class=\"name\">{}</td><td class=\"name\">{}</td>",
            escape(r.technique.name()),
            pipeline_name(r.pipeline)
        );
        if r.measured.is_none() {
            let _ = writeln!(
                h,
                "<tr class=\"skip\">{name}<td class=\"name\" colspan=\"{}\">skipped: {}</td></tr>",
                3 * columns.len(),
                escape(r.skipped.as_deref().unwrap_or("not run"))
            );
            continue;
        }
        let _ = write!(h, "<tr>{name}");
        for (i, _) in &columns {
            match share_of(r, *i) {
                Some(o) => {
                    let _ = write!(
                        h,
                        "{}{}{}",
                        cell(&o.self_shadow),
                        cell(&o.from_others),
                        cell(&o.lit)
                    );
                }
                None => h.push_str("<td>—</td><td>—</td><td>—</td>"),
            }
        }
        h.push_str("</tr>\n");
    }
    h.push_str(
        "</table></div><p class=\"muted\">Wrong % of the truth's pixels of each kind on each \
         object (hover for the counts; — where the object has none). Self-shadow: the surface \
         faces away from the light, or the object's own geometry blocks it. From others: \
         only other objects block it. Lit: the truth lights it, and the technique shadowed it \
         or drew background. Over the objects the counts add up to the row's wrong pixels \
         (false shadow, missed shadow, background where the truth has geometry); \
         <code>objects.csv</code> has them all.</p>\n",
    );
}

/// A picture the page shows, linked to the file itself (a click opens it full size).
fn img(name: &str, alt: &str, written: &Written) -> String {
    if written.contains(name) {
        format!(
            "<a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\" loading=\"lazy\"></a>",
            escape(name),
            escape(alt)
        )
    } else {
        String::new()
    }
}

/// The error image's colours as a list (`ERROR_COLOURS`).
pub(super) fn error_legend() -> String {
    let c = ERROR_COLOURS;
    format!(
        "<ul class=\"legend\">{}{}{}{}{}{}</ul>",
        swatch(c.lit, "lit, correct"),
        swatch(c.shadowed, "shadowed, correct"),
        swatch(c.false_shadow, "false shadow (acne)"),
        swatch(c.missed_shadow, "missed shadow (peter-panning)"),
        swatch(c.coverage, "geometry missing"),
        swatch(c.background, "background"),
    )
}

fn swatch(rgb: [u8; 3], text: &str) -> String {
    format!(
        "<li><span class=\"sw\" style=\"background:rgb({},{},{})\"></span>{}</li>",
        rgb[0],
        rgb[1],
        rgb[2],
        escape(text)
    )
}

fn plot_and_truth(h: &mut String, written: &Written) {
    let _ = writeln!(
        h,
        "<section class=\"two\"><div><h2>Error against time</h2>{}\
         <p class=\"muted\">One point per run; the green staircase is the Pareto front. \
         Lower is more accurate (the error axis is logarithmic), further left is faster; filled circles ran on the emulated pipeline, hollow squares on the native one.</p></div>\
         <div><h2>Ground truth and error colours</h2>{}{}\
         <p class=\"muted\">The truth mask: white lit, black shadowed (surfaces facing away \
         from the light included), grey background.</p></div></section>",
        img(PLOT_SVG, "error against time per frame", written),
        img(TRUTH_MASK, "ground-truth shadow mask", written),
        error_legend(),
    );
    if written.contains(VISIBILITY_PLOT_SVG) {
        let _ = writeln!(
            h,
            "<section><h2>Visibility error against time</h2>{}\
             <p class=\"muted\">The scene's light is soft (an area light or a sun): each run's visibility \
             (the fraction of the light each pixel sees; a hard shadow counts as 0 or 1) \
             against the truth's, as an RMSE over the geometry pixels. Soft and hard \
             techniques on one plot; the green staircase is its Pareto front.</p></section>",
            img(
                VISIBILITY_PLOT_SVG,
                "visibility RMSE against time per frame",
                written
            ),
        );
    }
}

fn cards(
    h: &mut String,
    c: &Comparison,
    rows: &[ResultRow],
    written: &Written,
    strips: &[PassStrip],
) {
    h.push_str("<h2>Each technique: image, shadow mask, error</h2><div class=\"cards\">\n");
    for (r, row) in rows.iter().zip(&c.rows) {
        let Some(m) = &r.measured else {
            continue;
        };
        let files = RowFiles::of(&row.slug());
        let pic = |name: &str, caption: &str| {
            format!(
                "<figure>{}<figcaption>{caption}</figcaption></figure>",
                img(name, &format!("{} {caption}", label(r)), written)
            )
        };
        let _ = write!(
            h,
            "<div class=\"card{}\"><h3>{}{}</h3><p class=\"muted\">{}</p><div class=\"pics\">{}{}{}</div>\
             <p class=\"fig\">error <b>{:.2}%</b> (false shadow {}, missed shadow {}) · \
             <b>{}</b> ms per frame · cold {:.1} ms · {} pass{} · {} program{}</p>",
            if r.pareto { " front" } else { "" },
            escape(&label(r)),
            if r.pareto {
                "<span class=\"tag\">Pareto</span>"
            } else {
                ""
            },
            escape(r.summary),
            pic(&files.image, "image"),
            pic(&files.mask, "shadow mask"),
            pic(&files.error, "error"),
            m.error_percent,
            m.false_shadow,
            m.missed_shadow,
            ms_cell(m),
            m.cold_ms,
            m.passes,
            if m.passes == 1 { "" } else { "es" },
            m.programs_compiled,
            if m.programs_compiled == 1 { "" } else { "s" }
        );
        let figures = Why::of(m, map_step(&c.scene, r.technique));
        let _ = write!(h, "<p class=\"why\">{}</p>", escape(&why(&figures)));
        for note in &m.notes {
            let _ = write!(h, "<p class=\"note\">note: {}</p>", escape(note));
        }
        if let Some(strip) = strips.iter().find(|s| s.slug == row.slug()) {
            pass_strip(h, strip, written);
        }
        h.push_str("</div>\n");
    }
    h.push_str("</div>\n");
    let skipped: Vec<&ResultRow> = rows.iter().filter(|r| r.measured.is_none()).collect();
    if !skipped.is_empty() {
        h.push_str("<p class=\"muted\">Not run: ");
        let list: Vec<String> = skipped
            .iter()
            .map(|r| {
                format!(
                    "{} — {}",
                    escape(&label(r)),
                    escape(r.skipped.as_deref().unwrap_or("not run"))
                )
            })
            .collect();
        h.push_str(&list.join("; "));
        h.push_str(".</p>\n");
    }
}

/// One thumbnail per pass, linked to its full-size picture, and the pass's other pictures
/// as links.
fn pass_strip(h: &mut String, strip: &PassStrip, written: &Written) {
    h.push_str("<div class=\"strip\">");
    for pass in &strip.passes {
        let caption = format!("{:02} {}", pass.number, pass.name);
        let links: Vec<String> = pass
            .files
            .iter()
            .filter(|(_, file)| written.contains(file))
            .map(|(kind, file)| format!("<a href=\"{}\">{}</a>", escape(file), escape(kind)))
            .collect();
        let _ = write!(
            h,
            "<figure>{}<figcaption>{}<br>{}</figcaption></figure>",
            img(&pass.thumbnail, &caption, written),
            escape(&caption),
            links.join(" · ")
        );
    }
    h.push_str("</div>");
    if written.contains(&strip.legend) {
        let _ = write!(
            h,
            "<p class=\"muted\">Each pass of the last frame as it left the buffers; \
             <a href=\"{0}\">{0}</a> says how each picture is made.</p>",
            escape(&strip.legend)
        );
    }
}

/// The figures [`why`] reads: a row's counts, and its map's step when it has an 8-bit map.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Why {
    /// Truth geometry pixels.
    pixels: u64,
    false_shadow: u64,
    missed_shadow: u64,
    outside_false: u64,
    outside_missed: u64,
    band: u32,
    step: Option<MapStep>,
}

impl Why {
    fn of(m: &super::Measured, step: Option<MapStep>) -> Why {
        Why {
            pixels: m.geometry_pixels,
            false_shadow: m.false_shadow,
            missed_shadow: m.missed_shadow,
            outside_false: m.outside_band_false_shadow,
            outside_missed: m.outside_band_missed_shadow,
            band: m.band,
            step,
        }
    }
}

/// One 8-bit step of a light's map in scene units at the receivers.
#[derive(Debug, Clone, Copy, PartialEq)]
enum MapStep {
    /// The same everywhere: (far − near)/`divisor`.
    Even { units: f64, divisor: u32 },
    /// Perspective depth /255: from `near` (the receivers' nearest to the light) to `far`.
    Perspective { near: f64, far: f64 },
}

/// Why the row is right or wrong here, in one sentence (the module note's rules).
fn why(w: &Why) -> String {
    let wrong = w.false_shadow + w.missed_shadow;
    let outside = w.outside_false + w.outside_missed;
    let pct = |n: u64| 100.0 * n as f64 / w.pixels.max(1) as f64;
    let mut s = if wrong == 0 {
        "Right here: no geometry pixel's shadow differs from the truth".to_string()
    } else if outside == 0 {
        format!(
            "Right but for aliasing: all {wrong} wrong pixels lie within {} px of a shadow edge",
            w.band
        )
    } else if outside * 1000 <= w.pixels {
        format!(
            "Right but for {outside} scattered pixels ({:.2}%) away from shadow edges \
             ({} false, {} missed) and {} at edges",
            pct(outside),
            w.outside_false,
            w.outside_missed,
            wrong - outside
        )
    } else if w.outside_false >= w.outside_missed {
        let mut s = format!(
            "Wrong by acne: {} pixels ({:.2}%) away from shadow edges are lit surfaces facing \
             the light that it shadows (false shadow)",
            w.outside_false,
            pct(w.outside_false)
        );
        if w.outside_missed > 0 {
            let _ = write!(s, ", and it lights {} in shadow", w.outside_missed);
        }
        s
    } else {
        let mut s = format!(
            "Wrong by peter-panning: {} pixels ({:.2}%) away from shadow edges are in shadow \
             in the truth but lit — the shadow is missed where it should start at contact",
            w.outside_missed,
            pct(w.outside_missed)
        );
        if w.outside_false > 0 {
            let _ = write!(s, ", and it shadows {} lit (acne)", w.outside_false);
        }
        s
    };
    match w.step {
        Some(MapStep::Even { units, divisor }) => {
            let _ = write!(
                s,
                "; one 8-bit step of its map is {units:.4} scene units at every receiver \
                 (the light's depth range / {divisor})"
            );
        }
        Some(MapStep::Perspective { near, far }) => {
            let _ = write!(
                s,
                "; one 8-bit step of its map is {near:.4}–{far:.4} scene units at the \
                 receivers (perspective depth / 255: d²·(far − near)/(far·near·255) at \
                 distance d from the light)"
            );
        }
        None => {}
    }
    s.push('.');
    s
}

/// One 8-bit step of `technique`'s map at the scene's receivers (module note), or `None`
/// for a technique without an 8-bit map.
fn map_step(scene: &Scene, technique: TechniqueId) -> Option<MapStep> {
    let light = ShadowLight::of(scene, technique).ok()?;
    let (n, f) = (f64::from(light.near), f64::from(light.far));
    match technique {
        TechniqueId::Linear8 => Some(MapStep::Even {
            units: (f - n) / 256.0,
            divisor: 256,
        }),
        TechniqueId::Dual8 if !matches!(light.volume, Command::Frustum(_)) => Some(MapStep::Even {
            units: (f - n) / 255.0,
            divisor: 255,
        }),
        TechniqueId::Dual8 => {
            let (lo, hi) = receiver_distances(scene, &light)?;
            let step = |d: f64| d * d * (f - n) / (f * n * 255.0);
            Some(MapStep::Perspective {
                near: step(lo),
                far: step(hi),
            })
        }
        TechniqueId::None
        | TechniqueId::DepthCompare
        | TechniqueId::Accumulate
        | TechniqueId::Multidigit16
        | TechniqueId::Multidigit16Combine
        | TechniqueId::Planar
        | TechniqueId::Projective
        | TechniqueId::OccluderPlanes
        | TechniqueId::OcclusionTextures => None,
    }
}

/// The smallest and largest eye distance from the light of the receivers' vertices,
/// clamped to its near and far planes.
fn receiver_distances(scene: &Scene, light: &ShadowLight) -> Option<(f64, f64)> {
    let (n, f) = (light.near, light.far);
    scene
        .objects
        .iter()
        .filter(|o| o.receives)
        .flat_map(|o| {
            let m = light.view * o.transform.matrix();
            o.mesh
                .positions
                .iter()
                .map(move |p| (-m.transform_point3(*p).z).clamp(n, f))
        })
        .fold(None, |r, d| match r {
            None => Some((d, d)),
            Some((lo, hi)) => Some((f32::min(lo, d), f32::max(hi, d))),
        })
        .map(|(lo, hi)| (f64::from(lo), f64::from(hi)))
}

fn scene_section(h: &mut String, facts: &[(String, String)], c: &Comparison) {
    h.push_str("<h2>Scene</h2><dl>");
    for (k, v) in facts {
        let _ = write!(h, "<dt>{}</dt><dd>{}</dd>", escape(k), escape(v));
    }
    let _ = writeln!(
        h,
        "<dt>ground truth</dt><dd>{} triangles, {} primary and {} shadow rays</dd></dl>",
        c.truth.triangles, c.truth.primary_rays, c.truth.shadow_rays
    );
}

fn footer(h: &mut String, c: &Comparison, written: &Written) {
    let mut links = Vec::new();
    for name in [CSV, OBJECTS_CSV, JSON, PLOT_PNG, SHEET] {
        if written.contains(name) {
            links.push(format!("<a href=\"{0}\">{0}</a>", escape(name)));
        }
    }
    let _ = write!(
        h,
        "<h2>Files and time</h2><p class=\"muted\">Also in this folder: {}. \
         The whole comparison took {:.1} s: ground truth {:.0} ms",
        links.join(", "),
        c.total_ms / 1e3,
        c.truth_ms
    );
    for row in &c.rows {
        if let RowResult::Measured { cost, .. } = &row.result {
            let _ = write!(
                h,
                "; {} ({}) {:.0} ms",
                escape(row.technique.name()),
                pipeline_name(row.pipeline),
                cost.total_ms()
            );
        }
    }
    h.push_str(".</p>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    fn counts(false_shadow: u64, missed_shadow: u64, outside: (u64, u64)) -> Why {
        Why {
            pixels: 10_000,
            false_shadow,
            missed_shadow,
            outside_false: outside.0,
            outside_missed: outside.1,
            band: 1,
            step: None,
        }
    }

    #[test]
    fn the_sentence_names_what_the_counts_show() {
        assert!(why(&counts(0, 0, (0, 0))).starts_with("Right here"));
        let edges = why(&counts(12, 3, (0, 0)));
        assert!(
            edges.contains("all 15 wrong pixels lie within 1 px"),
            "{edges}"
        );
        let scattered = why(&counts(12, 3, (5, 0)));
        assert!(
            scattered.starts_with("Right but for 5 scattered pixels (0.05%)"),
            "{scattered}"
        );
        let acne = why(&counts(900, 40, (800, 20)));
        assert!(
            acne.starts_with("Wrong by acne: 800 pixels (8.00%)"),
            "{acne}"
        );
        assert!(acne.contains("facing the light") && acne.contains("lights 20 in shadow"));
        let panning = why(&counts(10, 500, (5, 450)));
        assert!(
            panning.starts_with("Wrong by peter-panning: 450 pixels (4.50%)"),
            "{panning}"
        );
        assert!(panning.contains("contact") && panning.contains("shadows 5 lit (acne)"));
        for s in [acne, panning] {
            assert!(!s.contains(". ") && s.ends_with('.'), "one sentence: {s}");
        }
    }

    #[test]
    fn the_sentence_gives_the_map_step_and_its_rule() {
        let mut w = counts(900, 0, (800, 0));
        w.step = Some(MapStep::Even {
            units: 0.0390625,
            divisor: 256,
        });
        assert!(why(&w)
            .contains("0.0391 scene units at every receiver (the light's depth range / 256)"));
        w.step = Some(MapStep::Perspective {
            near: 0.01,
            far: 0.2,
        });
        assert!(
            why(&w).contains("0.0100–0.2000 scene units at the receivers (perspective depth / 255")
        );
    }

    #[test]
    fn map_steps_follow_each_8_bit_map_rule() {
        let scene = Scene::default_scene();
        let light = ShadowLight::of(&scene, TechniqueId::Linear8).expect("a light");
        let range = f64::from(light.far - light.near);
        assert_eq!(
            map_step(&scene, TechniqueId::Linear8),
            Some(MapStep::Even {
                units: range / 256.0,
                divisor: 256
            })
        );
        match map_step(&scene, TechniqueId::Dual8) {
            Some(MapStep::Perspective { near, far }) => {
                // Perspective steps grow with distance, and at the near plane are
                // (far − near)·near/(far·255).
                assert!(0.0 < near && near <= far, "{near} {far}");
                let n = f64::from(light.near);
                let f = f64::from(light.far);
                assert!(near >= n * (f - n) / (f * 255.0) - 1e-9);
            }
            other => panic!("dual8 on the default scene: {other:?}"),
        }
        assert_eq!(map_step(&scene, TechniqueId::DepthCompare), None);
        assert_eq!(map_step(&scene, TechniqueId::Multidigit16), None);
    }

    #[test]
    fn escaping_covers_markup_and_quotes() {
        assert_eq!(escape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
        assert_eq!(escape("plain"), "plain");
    }

    /// The results table's width at 13.5 px: each column's widest cell (the header wraps
    /// to its longest word), 6 px padding a side — under 900 px less the narrow-window
    /// body padding, with every technique's longest cells.
    #[test]
    fn the_results_table_fits_a_900_px_window() {
        let mut h = String::new();
        table(&mut h, &[]);
        let headers = h.matches("<th").count();
        assert_eq!(headers, 10, "{h}");
        assert!(h.contains("<div class=\"wide\">"));
        // Widest cells in characters (wrapping cells by their longest line): technique
        // name with the Pareto tag on its own line, pipeline, offset "1,98689.5
        // (technique default)" wrapped at its spaces, error, counts, band error, ms
        // "12.34 [10.00–15.00]" wrapped at its space, cold, "5 · 12 · 1".
        let widest = [20, 7, 10, 6, 7, 7, 8, 13, 8, 10];
        let px: f64 = widest.iter().map(|&c| f64::from(c) * 7.4 + 12.0).sum();
        assert!(px + 2.0 * 12.0 < 900.0, "{px:.0} px");
    }
}
