//! The error by object in a comparison's outputs: each measured row's per-object split
//! (`RenderOutcome::objects`, made by `render::object_split` against the comparison's one
//! truth, exactly as `render` prints it) with the objects' names, for `results.json` (each
//! row's `measured.objects`), `objects.csv` (one line per row × object), the page's
//! "Error by object" table and the terminal's table after the main one.
//!
//! Only a scene of several objects has a split (one object's would repeat the row's
//! figures): a one-object comparison writes `objects: []` and an `objects.csv` of its
//! header alone, and neither the page nor the terminal shows the table. A skipped row has
//! no split at all.
//!
//! Self-shadow = facing away + own occluder (`metrics::per_object`); a share's percent is
//! 100 · wrong / of, none when it has no pixels (0 % would claim a success there). Over a
//! row's objects the wrong counts add up to its false + missed shadow + coverage, and the
//! pixels to its geometry pixels.

use serde::Serialize;

use crate::metrics::per_object::Tally;
use crate::metrics::ObjectErrors;
use crate::render::{object_name, pipeline_name};
use crate::scene::Scene;

use super::csv::{line, opt};
use super::provenance::Provenance;
use super::table::{aligned, HeaderRule};
use super::ResultRow;

/// Pixels of one kind on one object, and how many of them the technique got wrong.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Share {
    pub wrong: u64,
    /// The truth's pixels of this kind on the object.
    pub of: u64,
    /// 100 · wrong / of; `None` without pixels.
    pub percent: Option<f64>,
}

impl From<Tally> for Share {
    fn from(t: Tally) -> Share {
        Share {
            wrong: t.wrong,
            of: t.pixels,
            percent: (t.pixels > 0).then(|| t.percent()),
        }
    }
}

impl Share {
    /// `3.11`, or `—` without pixels.
    pub fn cell(&self) -> String {
        self.percent.map_or("—".to_string(), |p| format!("{p:.2}"))
    }
}

/// One object's share of a row's error.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ObjectShare {
    /// Index into the scene's objects.
    pub object: usize,
    /// Its name, else `object I (shape)` (`render::object_name`).
    pub name: String,
    /// Attached and own-occluder shadow together.
    pub self_shadow: Share,
    /// Attached shadow: the surface faces away from the light.
    pub facing_away: Share,
    /// Facing the light, shadowed by the object's own geometry.
    pub own_occluder: Share,
    /// Facing the light, shadowed by other objects only.
    pub from_others: Share,
    /// Lit in the truth.
    pub lit: Share,
}

impl ObjectShare {
    /// A render's split (`RenderOutcome::objects`) with the names of `scene`'s objects.
    pub fn all(scene: &Scene, split: &[ObjectErrors]) -> Vec<ObjectShare> {
        split
            .iter()
            .map(|e| ObjectShare {
                object: e.object,
                name: object_name(scene, e.object),
                self_shadow: e.self_shadow().into(),
                facing_away: e.faces_away.into(),
                own_occluder: e.own_occluder.into(),
                from_others: e.other_occluder.into(),
                lit: e.lit.into(),
            })
            .collect()
    }

    /// Wrong pixels on the object: self-shadow, from others and lit together.
    pub fn wrong(&self) -> u64 {
        self.self_shadow.wrong + self.from_others.wrong + self.lit.wrong
    }
}

/// The objects any measured row has a split for, in scene order: (index, name).
pub fn columns(rows: &[ResultRow]) -> Vec<(usize, String)> {
    let mut out: Vec<(usize, String)> = Vec::new();
    for o in rows
        .iter()
        .filter_map(|r| r.measured.as_ref())
        .flat_map(|m| &m.objects)
    {
        if !out.iter().any(|(i, _)| *i == o.object) {
            out.push((o.object, o.name.clone()));
        }
    }
    out.sort_by_key(|(i, _)| *i);
    out
}

/// Row `r`'s share of object `index`, when it has one.
pub fn share_of(r: &ResultRow, index: usize) -> Option<&ObjectShare> {
    r.measured
        .as_ref()
        .and_then(|m| m.objects.iter().find(|o| o.object == index))
}

const CSV_HEADER: [&str; 21] = [
    "technique",
    "pipeline",
    "object",
    "object_index",
    "self_shadow_wrong",
    "self_shadow_pixels",
    "self_shadow_percent",
    "facing_away_wrong",
    "facing_away_pixels",
    "own_occluder_wrong",
    "own_occluder_pixels",
    "from_others_wrong",
    "from_others_pixels",
    "from_others_percent",
    "lit_wrong",
    "lit_pixels",
    "lit_percent",
    "wrong",
    "pixels",
    "fixedfunc_version",
    "command_line",
];

/// `objects.csv`: one line per measured row × object; percents at full precision, empty
/// for a share without pixels.
pub fn objects_csv(rows: &[ResultRow], produced: &Provenance) -> String {
    let mut out = line(&CSV_HEADER);
    for r in rows {
        let Some(m) = &r.measured else { continue };
        for o in &m.objects {
            out.push_str(&line(&[
                r.technique.to_string(),
                pipeline_name(r.pipeline).to_string(),
                o.name.clone(),
                o.object.to_string(),
                o.self_shadow.wrong.to_string(),
                o.self_shadow.of.to_string(),
                opt(o.self_shadow.percent),
                o.facing_away.wrong.to_string(),
                o.facing_away.of.to_string(),
                o.own_occluder.wrong.to_string(),
                o.own_occluder.of.to_string(),
                o.from_others.wrong.to_string(),
                o.from_others.of.to_string(),
                opt(o.from_others.percent),
                o.lit.wrong.to_string(),
                o.lit.of.to_string(),
                opt(o.lit.percent),
                o.wrong().to_string(),
                (o.self_shadow.of + o.from_others.of + o.lit.of).to_string(),
                produced.fixedfunc_version.to_string(),
                produced.command_line.clone(),
            ]));
        }
    }
    out
}

/// The terminal's table of the error by object, one line per measured row, one column per
/// object (`self-shadow / from others / lit`, wrong %); empty when no row has a split.
pub fn objects_table(rows: &[ResultRow]) -> String {
    let columns = columns(rows);
    if columns.is_empty() {
        return String::new();
    }
    let mut lines: Vec<Vec<String>> = vec![["technique", "pipeline"]
        .iter()
        .map(|s| s.to_string())
        .chain(columns.iter().map(|(_, name)| name.clone()))
        .collect()];
    for r in rows.iter().filter(|r| r.measured.is_some()) {
        let mut l = vec![
            r.technique.to_string(),
            pipeline_name(r.pipeline).to_string(),
        ];
        l.extend(columns.iter().map(|(i, _)| {
            share_of(r, *i).map_or("—".to_string(), |o| {
                format!(
                    "{} / {} / {}",
                    o.self_shadow.cell(),
                    o.from_others.cell(),
                    o.lit.cell()
                )
            })
        }));
        lines.push(l);
    }
    let mut out = "error by object, wrong %: self-shadow / from others / lit (— no such pixels)\n"
        .to_string();
    // Names left, figures right.
    out.push_str(&aligned(&lines, 2, HeaderRule::None));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tally(wrong: u64, pixels: u64) -> Tally {
        Tally { pixels, wrong }
    }

    #[test]
    fn shares_keep_the_split_and_a_share_of_no_pixels_has_no_percent() {
        let scene = Scene::default_scene();
        let e = ObjectErrors {
            object: 1,
            lit: tally(3, 300),
            faces_away: tally(1, 10),
            own_occluder: tally(4, 40),
            other_occluder: tally(0, 0),
        };
        let [o] = ObjectShare::all(&scene, &[e])
            .try_into()
            .unwrap_or_else(|v: Vec<_>| panic!("{v:?}"));
        assert_eq!(o.name, object_name(&scene, 1));
        assert_eq!((o.self_shadow.wrong, o.self_shadow.of), (5, 50));
        assert_eq!(o.self_shadow.percent, Some(10.0));
        assert_eq!(o.from_others.percent, None);
        assert_eq!(o.from_others.cell(), "—");
        assert_eq!(o.lit.cell(), "1.00");
        assert_eq!(o.wrong(), 8);
    }
}
