//! The comparison as one HTML page: a headline (most accurate, fastest, the Pareto front),
//! the table with bars for error and time, the plot beside the truth and the error colours,
//! a card per technique × pipeline (image, mask, error image, figures, notes), the scene,
//! and where the time went. Inline CSS, no scripts, no network: pictures are referred to
//! by bare file name and only when [`Written`] lists them.

use std::fmt::Write as _;

use crate::render::pipeline_name;
use crate::study::{Comparison, RowResult};
use crate::vocab::Named;

use super::file_names::{RowFiles, CSV, JSON, PLOT_PNG, PLOT_SVG, SHEET, TRUTH_MASK};
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

const STYLE: &str = "
body{font-family:system-ui,'DejaVu Sans',sans-serif;margin:0 auto;max-width:1360px;padding:24px 28px;color:#1d1f24;background:#fafafa}
h1{font-size:28px;margin:0 0 6px}h2{font-size:21px;margin:28px 0 10px;border-bottom:2px solid #e2e4ea;padding-bottom:4px}
h3{font-size:16px;margin:0 0 8px}.lead{font-size:17px;line-height:1.5;margin:6px 0}
.lead b{color:#0a4fa8}.muted{color:#5b6070;font-size:14px}
table{border-collapse:collapse;font-size:13.5px;width:100%;background:#fff}
th,td{padding:5px 7px;border-bottom:1px solid #e6e8ee;text-align:right;white-space:nowrap}
th{background:#eef0f5;font-weight:600;white-space:normal;vertical-align:bottom}td.name,th.name{text-align:left}
tr.front td{background-color:#eefaf2}tr.skip td{color:#80859a;font-style:italic}
.bar{background-repeat:no-repeat;background-size:var(--w) 70%;background-position:left center}
.err{background-image:linear-gradient(#f7c9a6,#f7c9a6)}.time{background-image:linear-gradient(#bcd4f5,#bcd4f5)}
.two{display:grid;grid-template-columns:3fr 2fr;gap:24px;align-items:start}
.two img{width:100%;border:1px solid #dde0e8;background:#fff}
.legend{list-style:none;padding:0;margin:10px 0;font-size:14px;columns:2}
.legend li{margin:4px 0}.sw{display:inline-block;width:14px;height:14px;vertical-align:-2px;margin-right:6px;border:1px solid #999}
.cards{display:grid;grid-template-columns:repeat(2,1fr);gap:18px}
.card{background:#fff;border:1px solid #dde0e8;border-radius:6px;padding:12px}
.card.front{border-color:#3aa76d;box-shadow:0 0 0 1px #3aa76d}
.pics{display:grid;grid-template-columns:repeat(3,1fr);gap:6px}
.pics figure{margin:0}.pics img{width:100%;image-rendering:pixelated;display:block}
.pics figcaption{font-size:12px;color:#5b6070;text-align:center}
.fig{font-size:14px;margin:8px 0 0}.note{font-size:13px;color:#8a4b00;margin:4px 0 0}
dl{display:grid;grid-template-columns:max-content 1fr;gap:4px 16px;font-size:14px}dt{font-weight:600}dd{margin:0}
.tag{display:inline-block;font-size:11px;padding:1px 6px;border-radius:8px;background:#3aa76d;color:#fff;margin-left:6px;vertical-align:2px}
";

/// The page. `facts` describe the scene; `written` lists the files next to the page.
pub fn page(
    c: &Comparison,
    rows: &[ResultRow],
    scene: &str,
    facts: &[(String, String)],
    written: &Written,
) -> String {
    let mut h = String::new();
    let _ = write!(
        h,
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <meta name=\"viewport\" content=\"width=device-width\">\
         <title>fixedfunc compare — {}</title><style>{STYLE}</style></head><body>\n",
        escape(scene)
    );
    headline(&mut h, c, rows, scene);
    table(&mut h, rows);
    plot_and_truth(&mut h, written);
    cards(&mut h, c, rows, written);
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
        "<h2>Results</h2><table><tr><th class=\"name\">technique</th><th class=\"name\">pipeline</th>\
         <th class=\"name\">polygon offset</th><th>error %</th><th>false shadow</th><th>missed shadow</th><th>error % outside edge band</th>\
         <th>ms per frame: median [min–max]</th><th>cold frame ms</th><th>passes</th>\
         <th>programs</th><th>maps made</th></tr>\n",
    );
    for r in rows {
        let name = format!(
            "<td class=\"name\" title=\"{}\">{}{}</td><td class=\"name\">{}</td>",
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
                    "<tr{}>{name}<td class=\"name\">{}</td><td class=\"bar err\" style=\"--w:{:.0}%\">{:.2}</td><td>{}</td><td>{}</td>\
                     <td>{:.2}</td><td class=\"bar time\" style=\"--w:{:.0}%\">{}</td><td>{:.1}</td>\
                     <td>{}</td><td>{}</td><td>{}</td></tr>",
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
                    "<tr class=\"skip\">{name}<td class=\"name\" colspan=\"10\">skipped: {}</td></tr>",
                    escape(reason.as_deref().unwrap_or("not run"))
                );
            }
        }
    }
    h.push_str(
        "</table><p class=\"muted\">Green rows are on the Pareto front: no other run is faster \
         beyond doubt (all its frames quicker) and as accurate, or as fast within the frames' \
         spread (their time ranges overlap) and more accurate. False shadow: lit in the truth, shadowed by the technique \
         (acne). Missed shadow: shadowed in the truth, lit by the technique (peter-panning). \
         The edge band excludes pixels next to the truth's shadow edges, where one pixel of \
         aliasing is expected.</p>\n",
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
    let c = ERROR_COLOURS;
    let _ = writeln!(
        h,
        "<section class=\"two\"><div><h2>Error against time</h2>{}\
         <p class=\"muted\">One point per run; the green staircase is the Pareto front. \
         Lower is more accurate (the error axis is logarithmic), further left is faster; filled circles ran on the emulated pipeline, hollow squares on the native one.</p></div>\
         <div><h2>Ground truth and error colours</h2>{}<ul class=\"legend\">{}{}{}{}{}{}</ul>\
         <p class=\"muted\">The truth mask: white lit, black shadowed (surfaces facing away \
         from the light included), grey background.</p></div></section>",
        img(PLOT_SVG, "error against time per frame", written),
        img(TRUTH_MASK, "ground-truth shadow mask", written),
        swatch(c.lit, "lit, correct"),
        swatch(c.shadowed, "shadowed, correct"),
        swatch(c.false_shadow, "false shadow (acne)"),
        swatch(c.missed_shadow, "missed shadow (peter-panning)"),
        swatch(c.coverage, "geometry missing"),
        swatch(c.background, "background"),
    );
}

fn cards(h: &mut String, c: &Comparison, rows: &[ResultRow], written: &Written) {
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
        for note in &m.notes {
            let _ = write!(h, "<p class=\"note\">note: {}</p>", escape(note));
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
    for name in [CSV, JSON, PLOT_PNG, SHEET] {
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
    use super::escape;

    #[test]
    fn escaping_covers_markup_and_quotes() {
        assert_eq!(escape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
        assert_eq!(escape("plain"), "plain");
    }
}
