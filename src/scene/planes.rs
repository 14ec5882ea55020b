//! `[[object.plane]]`: an object's shadow planes for `occluder-planes` (Coleman, thesis
//! 003 §4). Each plane is read in the object's own space — origin (the occluder texture's
//! corner s = t = 0), normal, up (t), right (s), width, height — and its occluder: the
//! recipe of a generated silhouette (the default), all black, or a PNG. The textures are
//! made here, once, so every reader of the scene sees the same texels.
//!
//! Refused, each at its line: a zero or non-finite vector, axes not perpendicular
//! (|a · b| > 1e-3 after normalising), a width or height ≤ 0, a texture size outside
//! 1..=`MAX_IMAGE_SIZE`, an unreadable PNG, and more planes in the scene than texture units
//! (`ff::MAX_TEXTURE_UNITS`: every receiver looks up every caster's planes in one pass, one
//! unit each).
//!
//! An `f35` aircraft that declares no plane gets the thesis's three (`shaders::F35_PLANES`)
//! with the recipes of [`F35_RECIPES`].

use super::check::{span_of, Ctx, Result};
use super::error::{Problem, SceneError};
use super::limits::MAX_IMAGE_SIZE;
use super::raw::{RawObject, RawOccluder, RawOccluderTable, RawPlane};
use super::types::{Object, ObjectPlanes, OccluderPlane, PlaneSection, Shape};
use crate::ff::{MAX_CLIP_PLANES, MAX_TEXTURE_UNITS};
use crate::mesh::occluder::{
    occluder_texture, silhouette, OccluderRecipe, OccluderSource, PlaneFrame,
};
use crate::mesh::AircraftLayout;
use crate::shaders::F35_PLANES;
use crate::vocab::Named;
use glam::Vec3;
use std::sync::Arc;
use toml::Spanned;

/// The recipes of the F-35's planes, in `F35_PLANES`' order. The z = 0 plane takes every
/// triangle within 1 m (fuselage, wings, stabilisers; the fins reach 2.2 m, so their
/// faces are left out, as the thesis removed them, §5). Each fin plane takes the triangles
/// within 5 cm (the fin, 3 cm either side) and extends its silhouette 16 texels (26 cm)
/// down into the fuselage, the thesis's "extend the shape of the tail fin downward".
/// No isotropic dilation: on `assets/f35.toml` one texel (6 cm on the z = 0 plane) put
/// false shadow along every wing edge — error 1.31% against the truth with `dilate = 1`,
/// 0.86% without (LINEAR filtering already reaches half a texel past the centres).
pub const F35_RECIPES: [OccluderRecipe; 3] = [
    OccluderRecipe {
        size: 256,
        depth: 1.0,
        dilate: 0,
        extend: 0,
    },
    OccluderRecipe {
        size: 256,
        depth: 0.05,
        dilate: 0,
        extend: 16,
    },
    OccluderRecipe {
        size: 256,
        depth: 0.05,
        dilate: 0,
        extend: 16,
    },
];

/// `[shadow] program`: which form of `occluder-planes` draws the eye pass. Read by serde
/// (an unknown value is refused at its line with the valid ones listed) and by the command
/// line (`--occluder-program`) through the same names ([`Named`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum OccluderProgram {
    /// Object-linear texgen per receiver, a 2-slice 3D texture per plane, MODULATE: runs on
    /// both pipelines.
    #[default]
    FixedFunction,
    /// The thesis's shaders (`shaders/coleman/`), unchanged: the F-35's three planes only,
    /// under a directional light. Emulated pipeline only.
    Coleman,
    /// One GLSL program generated for the scene's planes, directional or point light.
    /// Emulated pipeline only.
    Generic,
}

impl Named for OccluderProgram {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("fixed-function", OccluderProgram::FixedFunction),
        ("coleman", OccluderProgram::Coleman),
        ("generic", OccluderProgram::Generic),
    ];

    fn help(self) -> &'static str {
        match self {
            OccluderProgram::FixedFunction => "texgen and 3D textures, both pipelines",
            OccluderProgram::Coleman => "the thesis's F-35 shaders (shaders/coleman/)",
            OccluderProgram::Generic => "one generated program for any planes",
        }
    }
}

/// The edge of an all-black occluder, texels: the white border blends in over half a
/// texel, 1/32 of the rectangle.
const BLACK_SIZE: u32 = 16;

/// The planes of `object` (read from `table`): declared, or its shape's defaults.
pub(super) fn object_planes(
    ctx: &Ctx,
    table: &Spanned<RawObject>,
    object: &Object,
    prefix: &str,
) -> Result<Vec<OccluderPlane>> {
    let raw = &table.get_ref().plane;
    if raw.is_empty() {
        return Ok(match object.shape {
            Shape::Aircraft {
                layout: AircraftLayout::F35,
            } => F35_PLANES
                .iter()
                .zip(F35_RECIPES)
                .map(|(p, recipe)| {
                    let frame = PlaneFrame {
                        origin: p.origin,
                        normal: p.normal,
                        up: p.up,
                        right: p.right,
                        width: p.width,
                        height: p.height,
                    };
                    // A silhouette is rasterised from the mesh: nothing to fail.
                    let texture = silhouette(&object.mesh, &frame, &recipe);
                    let source = OccluderSource::Silhouette(recipe);
                    OccluderPlane {
                        frame,
                        source,
                        texture: Arc::new(texture),
                    }
                })
                .collect(),
            _ => Vec::new(),
        });
    }
    raw.iter()
        .enumerate()
        .map(|(k, p)| plane(ctx, p, object, &format!("{prefix}plane[{k}].")))
        .collect()
}

/// `[[object.section]]` of an object with `plane_count` planes: every section but the last
/// has a `cut` (finite, not all zero in a, b, c), the last none; plane indices exist; at
/// most `MAX_CLIP_PLANES` + 1 sections (the last is drawn with one clip plane per earlier
/// cut).
pub(super) fn object_sections(
    ctx: &Ctx,
    table: &Spanned<RawObject>,
    plane_count: usize,
    prefix: &str,
) -> Result<Vec<PlaneSection>> {
    let raw = &table.get_ref().section;
    if raw.len() > MAX_CLIP_PLANES + 1 {
        return Err(ctx.invalid(
            raw[MAX_CLIP_PLANES + 1].span(),
            &format!("{prefix}section"),
            Problem::TooManySections {
                count: raw.len(),
                max: MAX_CLIP_PLANES,
            },
        ));
    }
    let last = raw.len().saturating_sub(1);
    let mut sections = Vec::with_capacity(raw.len());
    for (k, section) in raw.iter().enumerate() {
        let (r, span) = (section.get_ref(), section.span());
        let key = |k2: &str| format!("{prefix}section[{k}].{k2}");
        let cut = match (&r.cut, k == last) {
            (Some(c), true) => {
                return Err(ctx.invalid(c.span(), &key("cut"), Problem::CutOnLastSection))
            }
            (None, true) => None,
            (c, false) => {
                let c =
                    ctx.required(c, &key("cut"), "section that is not the last", span.clone())?;
                let v = glam::Vec4::from_array(c.get_ref().0);
                if !v.is_finite() {
                    return Err(ctx.invalid(c.span(), &key("cut"), Problem::NotFinite));
                }
                if v.truncate().length_squared() == 0.0 {
                    return Err(ctx.invalid(c.span(), &key("cut"), Problem::ZeroVector));
                }
                Some(v)
            }
        };
        let listed = ctx.required(&r.planes, &key("planes"), "section", span.clone())?;
        let mut planes = Vec::with_capacity(listed.get_ref().len());
        for index in listed.get_ref() {
            let i = *index.get_ref();
            if i as usize >= plane_count {
                return Err(ctx.invalid(
                    index.span(),
                    &key("planes"),
                    Problem::NoSuchPlane {
                        index: i,
                        count: plane_count,
                    },
                ));
            }
            planes.push(i as usize);
        }
        sections.push(PlaneSection { cut, planes });
    }
    Ok(sections)
}

/// Shadow planes a scene may declare in all: each has its own texture name
/// (`occluder-planes` numbers them from 64 for the fixed-function form, from 80 for the
/// programs).
pub const MAX_SCENE_PLANES: usize = 15;

/// One draw of a receiver in `occluder-planes`' lit pass: the receiver cut to one section
/// (glClipPlane equations in its object space; none for a whole object) and the planes it
/// looks up, one texture unit each, as (caster object, index among its planes).
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneLookup {
    pub receiver: usize,
    pub clips: Vec<glam::Vec4>,
    pub planes: Vec<(usize, usize)>,
}

/// Every receiver's draws: a receiver with sections once per section (section k keeps its
/// cut and the negation of every earlier cut; it looks up its own listed planes), any
/// other once (its own planes, if it casts, all of them); each also looks up every other
/// caster's planes. Casters that do not cast shadows contribute none.
pub fn plane_lookups(objects: &[Object], planes: &[ObjectPlanes]) -> Vec<PlaneLookup> {
    let casting: Vec<&ObjectPlanes> = planes
        .iter()
        .filter(|p| objects.get(p.object).is_some_and(|o| o.casts))
        .collect();
    let others = |receiver: usize| -> Vec<(usize, usize)> {
        casting
            .iter()
            .filter(|p| p.object != receiver)
            .flat_map(|p| (0..p.planes.len()).map(move |k| (p.object, k)))
            .collect()
    };
    let mut lookups = Vec::new();
    for (r, object) in objects.iter().enumerate() {
        if !object.receives {
            continue;
        }
        let own = casting.iter().find(|p| p.object == r);
        match own {
            Some(p) if !p.sections.is_empty() => {
                for (k, section) in p.sections.iter().enumerate() {
                    let mut clips: Vec<glam::Vec4> = p.sections[..k]
                        .iter()
                        .filter_map(|s| s.cut.map(|c| -c))
                        .collect();
                    clips.extend(section.cut);
                    let mut looked: Vec<(usize, usize)> =
                        section.planes.iter().map(|&i| (r, i)).collect();
                    looked.extend(others(r));
                    lookups.push(PlaneLookup {
                        receiver: r,
                        clips,
                        planes: looked,
                    });
                }
            }
            _ => {
                let mut looked: Vec<(usize, usize)> = own
                    .map(|p| (0..p.planes.len()).map(|k| (r, k)).collect())
                    .unwrap_or_default();
                looked.extend(others(r));
                looked.sort_unstable();
                lookups.push(PlaneLookup {
                    receiver: r,
                    clips: Vec::new(),
                    planes: looked,
                });
            }
        }
    }
    lookups
}

/// Refuses a scene in which some receiver's draw would look up more planes than there are
/// texture units, at the last object that declares planes.
pub(super) fn within_units(
    ctx: &Ctx,
    tables: &[Spanned<RawObject>],
    objects: &[Object],
    planes: &[ObjectPlanes],
) -> Result<()> {
    let total: usize = planes.iter().map(|p| p.planes.len()).sum();
    if let Some(last) = planes.last().filter(|_| total > MAX_SCENE_PLANES) {
        let table = &tables[last.object];
        return Err(ctx.invalid(
            table
                .get_ref()
                .plane
                .last()
                .map_or(table.span(), Spanned::span),
            &format!("object[{}].plane", last.object),
            Problem::TooManyScenePlanes {
                count: total,
                max: MAX_SCENE_PLANES,
            },
        ));
    }
    let Some(worst) = plane_lookups(objects, planes)
        .into_iter()
        .max_by_key(|l| l.planes.len())
        .filter(|l| l.planes.len() > MAX_TEXTURE_UNITS)
    else {
        return Ok(());
    };
    let Some(last) = planes.last() else {
        return Ok(());
    };
    let table = &tables[last.object];
    let span = table
        .get_ref()
        .plane
        .last()
        .map_or(table.span(), Spanned::span);
    let receiver = objects[worst.receiver]
        .name
        .clone()
        .unwrap_or_else(|| format!("object[{}]", worst.receiver));
    let receiver = if worst.clips.is_empty() {
        receiver
    } else {
        format!("a section of {receiver}")
    };
    Err(ctx.invalid(
        span,
        &format!("object[{}].plane", last.object),
        Problem::TooManyPlanes {
            count: worst.planes.len(),
            max: MAX_TEXTURE_UNITS,
            receiver,
        },
    ))
}

fn plane(
    ctx: &Ctx,
    table: &Spanned<RawPlane>,
    object: &Object,
    prefix: &str,
) -> Result<OccluderPlane> {
    let (p, span) = (table.get_ref(), table.span());
    let key = |k: &str| format!("{prefix}{k}");
    let what = "shadow plane (origin, normal, up, right, width, height)";
    let vector = |v, k: &str| -> Result<Vec3> {
        ctx.direction(ctx.required(v, &key(k), what, span.clone())?, &key(k))
    };
    let origin = ctx.vec3(
        ctx.required(&p.origin, &key("origin"), what, span.clone())?,
        &key("origin"),
    )?;
    let frame = PlaneFrame {
        origin,
        normal: vector(&p.normal, "normal")?,
        up: vector(&p.up, "up")?,
        right: vector(&p.right, "right")?,
        width: ctx.positive(
            ctx.required(&p.width, &key("width"), what, span.clone())?,
            &key("width"),
        )?,
        height: ctx.positive(
            ctx.required(&p.height, &key("height"), what, span.clone())?,
            &key("height"),
        )?,
    };
    let frame = frame.normalised().map_err(|(axis, problem)| {
        let at = match axis {
            crate::mesh::occluder::FrameAxis::Normal => span_of(&p.normal),
            crate::mesh::occluder::FrameAxis::Up => span_of(&p.up),
            crate::mesh::occluder::FrameAxis::Right => span_of(&p.right),
        };
        ctx.invalid(
            at.unwrap_or(span.clone()),
            &key(&axis.to_string()),
            Problem::Frame(problem),
        )
    })?;
    let occluder_span = span_of(&p.occluder).unwrap_or(span.clone());
    let source = match &p.occluder {
        None => OccluderSource::Silhouette(OccluderRecipe::default()),
        Some(o) => occluder(ctx, o, &key("occluder"))?,
    };
    let size = match source {
        OccluderSource::Silhouette(r) => r.size,
        OccluderSource::Black | OccluderSource::Png(_) => BLACK_SIZE,
    };
    let texture = occluder_texture(&object.mesh, &frame, &source, size).map_err(|source| {
        SceneError::Occluder {
            at: ctx.at(occluder_span),
            key: key("occluder"),
            source,
        }
    })?;
    Ok(OccluderPlane {
        frame,
        source,
        texture: Arc::new(texture),
    })
}

fn occluder(ctx: &Ctx, o: &Spanned<RawOccluder>, key: &str) -> Result<OccluderSource> {
    match o.get_ref() {
        RawOccluder::Named(name) => match name.as_str() {
            "silhouette" => Ok(OccluderSource::Silhouette(OccluderRecipe::default())),
            "black" => Ok(OccluderSource::Black),
            _ => Err(ctx.invalid(
                o.span(),
                key,
                Problem::NotOneOf {
                    value: format!("\"{name}\""),
                    expected: vec![
                        "\"silhouette\"",
                        "\"black\"",
                        "{ png = \"file.png\" }",
                        "{ size, depth, dilate, extend }",
                    ],
                },
            )),
        },
        RawOccluder::Table(t) => table(ctx, t, o.span(), key),
    }
}

fn table(
    ctx: &Ctx,
    t: &RawOccluderTable,
    span: std::ops::Range<usize>,
    key: &str,
) -> Result<OccluderSource> {
    let recipe_given = t.size.is_some() || t.depth.is_some() || t.dilate.is_some();
    if let Some(png) = &t.png {
        if recipe_given || t.extend.is_some() {
            return Err(ctx.invalid(
                span,
                &format!("{key}.png"),
                Problem::Conflicts {
                    other: "size, depth, dilate, extend (a picture is used as it is)",
                },
            ));
        }
        return Ok(OccluderSource::Png(ctx.base_dir.join(png)));
    }
    let defaults = OccluderRecipe::default();
    let size = t.size.unwrap_or(defaults.size);
    if !(1..=MAX_IMAGE_SIZE).contains(&size) {
        return Err(ctx.invalid(
            span,
            &format!("{key}.size"),
            Problem::OutOfRange {
                low: 1.0,
                high: MAX_IMAGE_SIZE as f32,
                value: size as f32,
            },
        ));
    }
    let depth = t.depth.unwrap_or(defaults.depth);
    if !(depth.is_finite() && depth > 0.0) {
        return Err(ctx.invalid(span, &format!("{key}.depth"), Problem::NotPositive(depth)));
    }
    Ok(OccluderSource::Silhouette(OccluderRecipe {
        size,
        depth,
        dilate: t.dilate.unwrap_or(defaults.dilate),
        extend: t.extend.unwrap_or(defaults.extend),
    }))
}

#[cfg(test)]
mod tests {
    use crate::mesh::occluder::{OccluderSource, OCCLUDES};
    use crate::scene::{Scene, SceneError};
    use std::path::Path;

    fn parse(text: &str) -> Result<Scene, SceneError> {
        Scene::parse(text, Path::new("planes.toml"))
    }

    const F35: &str = "[[object]]\nshape = \"aircraft\"\nlayout = \"f35\"\n";

    fn with_plane(fields: &str) -> String {
        format!("[[object]]\nshape = \"box\"\n[[object.plane]]\n{fields}\n")
    }

    const GOOD: &str = "origin = [-1, -1, 0]\nnormal = [0, 0, 2]\nup = [0, 1, 0]\nright = [1, 0, 0]\nwidth = 2\nheight = 2";

    #[test]
    fn an_f35_brings_three_planes_whose_occluders_hold_its_parts() {
        let scene = parse(F35).unwrap();
        let [planes] = &scene.shadow.planes[..] else {
            panic!("one object with planes")
        };
        assert_eq!((planes.object, planes.planes.len()), (0, 3));
        for p in &planes.planes {
            assert_eq!((p.texture.width, p.texture.height), (256, 256));
            assert!(p.texture.black_count() > 500, "{:?}", p.frame);
            assert!(matches!(p.source, OccluderSource::Silhouette(_)));
        }
        // The wings reach x = ±5.3 m: s = (5.3 − (−7.5)) / 15 ≈ 0.85 at the wing's
        // y ≈ −1.5 m (t ≈ 0.254) is black; the wing tip's outside (s ≈ 0.9) is white.
        let z = &planes.planes[0].texture;
        assert_eq!(z.nearest(glam::Vec2::new(0.84, 0.254)), OCCLUDES);
        assert_ne!(z.nearest(glam::Vec2::new(0.9, 0.254)), OCCLUDES);
        // The fighter layout has none; `length` is not the f35's.
        assert!(parse("[[object]]\nshape = \"aircraft\"\n")
            .unwrap()
            .shadow
            .planes
            .is_empty());
        let err = parse(&format!("{F35}length = 3\n"))
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("planes.toml:4") && err.contains("object[0].length"),
            "{err}"
        );
    }

    #[test]
    fn a_declared_plane_is_normalised_and_its_silhouette_made() {
        let scene = parse(&with_plane(GOOD)).unwrap();
        let p = &scene.shadow.planes[0].planes[0];
        assert_eq!(p.frame.normal, glam::Vec3::Z);
        // The unit box's top and bottom faces are 0.5 from z = 0: beyond the default
        // depth 0.1, and its sides project to lines; nothing is black.
        assert_eq!(p.texture.black_count(), 0);
        let deep = with_plane(&format!(
            "{GOOD}\noccluder = {{ depth = 1, size = 16, dilate = 0 }}"
        ));
        let p = &parse(&deep).unwrap().shadow.planes[0].planes[0];
        // [−0.5, 0.5]² of [−1, 1]²: the middle half of 16 texels each way.
        assert_eq!(p.texture.black_count(), 64);
        let black = with_plane(&format!("{GOOD}\noccluder = \"black\""));
        let p = &parse(&black).unwrap().shadow.planes[0].planes[0];
        assert_eq!(p.texture.black_count(), 256);
    }

    #[test]
    fn bad_planes_are_refused_at_their_line_with_what_is_wrong() {
        let cases = [
            (
                GOOD.replace("right = [1, 0, 0]", "right = [0, 0, 0]"),
                "plane[0].right",
                "zero vector",
            ),
            (
                GOOD.replace("up = [0, 1, 0]", "up = [0, 1, 1]"),
                "plane[0].up",
                "not perpendicular to `normal`",
            ),
            (
                GOOD.replace("width = 2", "width = 0"),
                "plane[0].width",
                "greater than zero",
            ),
            (
                GOOD.replace("height = 2", ""),
                "plane[0].height",
                "required",
            ),
            (
                format!("{GOOD}\noccluder = \"grey\""),
                "plane[0].occluder",
                "\"silhouette\", \"black\"",
            ),
            (
                format!("{GOOD}\noccluder = {{ png = \"a.png\", size = 4 }}"),
                "occluder.png",
                "cannot be combined",
            ),
            (
                format!("{GOOD}\noccluder = {{ png = \"missing.png\" }}"),
                "plane[0].occluder",
                "cannot read occluder picture",
            ),
            (
                format!("{GOOD}\noccluder = {{ size = 0 }}"),
                "occluder.size",
                "must be in",
            ),
        ];
        for (fields, key, says) in cases {
            let err = parse(&with_plane(&fields)).unwrap_err().to_string();
            assert!(
                err.contains("planes.toml:") && err.contains(key) && err.contains(says),
                "{fields}\n→ {err}"
            );
        }
    }

    #[test]
    fn more_planes_than_texture_units_are_refused() {
        let many = format!("{F35}{F35}{F35}");
        let err = parse(&many).unwrap_err().to_string();
        assert!(
            err.contains("object[2].plane")
                && err.contains("9 shadow planes")
                && err.contains("8 texture units"),
            "{err}"
        );
    }

    /// A box with two planes and `sections`.
    fn with_sections(sections: &str) -> String {
        format!("{}[[object.plane]]\n{GOOD}\n{sections}", with_plane(GOOD))
    }

    #[test]
    fn sections_keep_their_cuts_and_planes() {
        let scene = parse(&with_sections(
            "[[object.section]]\ncut = [0, 1, 0, -0.25]\nplanes = [1]\n\
             [[object.section]]\nplanes = [0, 1]\n",
        ))
        .unwrap();
        let sections = &scene.shadow.planes[0].sections;
        assert_eq!(sections.len(), 2);
        assert_eq!(sections[0].cut, Some(glam::Vec4::new(0.0, 1.0, 0.0, -0.25)));
        assert_eq!(
            (sections[1].cut, &sections[1].planes[..]),
            (None, &[0, 1][..])
        );
        // The second section is drawn on the other side of the first's cut.
        let lookups = super::plane_lookups(&scene.objects, &scene.shadow.planes);
        assert_eq!(
            lookups[1].clips,
            vec![glam::Vec4::new(0.0, -1.0, 0.0, 0.25)]
        );
    }

    #[test]
    fn bad_sections_are_refused_at_their_line_with_what_is_wrong() {
        // Lines 1–2 the box, 3–9 plane 0, 10–16 plane 1: sections start on line 18.
        let cases = [
            (
                "[[object.section]]\nplanes = [0]\n[[object.section]]\nplanes = [1]\n",
                ":17",
                "section[0].cut",
                "required",
            ),
            (
                "[[object.section]]\ncut = [0, 1, 0, 0]\nplanes = [0]\n",
                ":18",
                "section[0].cut",
                "last section",
            ),
            (
                "[[object.section]]\ncut = [0, 0, 0, 1]\nplanes = [0]\n\
                 [[object.section]]\nplanes = [1]\n",
                ":18",
                "section[0].cut",
                "zero vector",
            ),
            (
                "[[object.section]]\ncut = [0, 1, 0, nan]\nplanes = [0]\n\
                 [[object.section]]\nplanes = [1]\n",
                ":18",
                "section[0].cut",
                "finite",
            ),
            (
                "[[object.section]]\ncut = [0, 1, 0, 0]\nplanes = [0]\n\
                 [[object.section]]\nplanes = [1, 2]\n",
                ":21",
                "section[1].planes",
                "names plane 2, and the object has 2",
            ),
            (
                "[[object.section]]\ncut = [0, 1, 0, 0]\n[[object.section]]\nplanes = [1]\n",
                ":17",
                "section[0].planes",
                "required",
            ),
        ];
        for (sections, line, key, says) in cases {
            let err = parse(&with_sections(sections)).unwrap_err().to_string();
            assert!(
                err.contains(&format!("planes.toml{line}"))
                    && err.contains(key)
                    && err.contains(says),
                "{sections}\n→ {err}"
            );
        }
        let ten: String = (0..10)
            .map(|_| "[[object.section]]\ncut = [0, 1, 0, 0]\nplanes = [0]\n")
            .collect();
        let err = parse(&with_sections(&ten)).unwrap_err().to_string();
        assert!(
            err.contains("10 sections") && err.contains("GL_MAX_CLIP_PLANES is 8"),
            "{err}"
        );
        let bare = "[[object]]\nshape = \"box\"\n[[object.section]]\nplanes = [0]\n";
        let err = parse(bare).unwrap_err().to_string();
        assert!(
            err.contains("planes.toml:3") && err.contains("object[0].plane"),
            "{err}"
        );
    }

    #[test]
    fn the_program_key_reads_its_three_names_and_refuses_others_at_their_line() {
        use super::OccluderProgram;
        use crate::vocab::Named;
        assert_eq!(
            parse(F35).unwrap().shadow.occluder_program,
            OccluderProgram::FixedFunction
        );
        for v in OccluderProgram::all() {
            let scene = parse(&format!("{F35}[shadow]\nprogram = \"{}\"\n", v.name())).unwrap();
            assert_eq!(scene.shadow.occluder_program, v);
        }
        let err = parse(&format!("{F35}[shadow]\nprogram = \"cg\"\n"))
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("planes.toml:5")
                && ["fixed-function", "coleman", "generic"]
                    .iter()
                    .all(|n| err.contains(n)),
            "{err}"
        );
    }

    #[test]
    fn layout_names_its_values() {
        let err = parse("[[object]]\nshape = \"aircraft\"\nlayout = \"f16\"\n")
            .unwrap_err()
            .to_string();
        assert!(err.contains("fighter") && err.contains("f35"), "{err}");
        let err = parse("[[object]]\nshape = \"box\"\nlayout = \"f35\"\n")
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("object[0].layout") && err.contains("not used by a box"),
            "{err}"
        );
    }
}
