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
use super::types::{Object, OccluderPlane, Shape};
use crate::ff::MAX_TEXTURE_UNITS;
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

/// Refuses a running total of planes above the texture units.
pub(super) fn within_units(
    ctx: &Ctx,
    table: &Spanned<RawObject>,
    count: usize,
    prefix: &str,
) -> Result<()> {
    if count <= MAX_TEXTURE_UNITS {
        return Ok(());
    }
    let span = table
        .get_ref()
        .plane
        .last()
        .map_or(table.span(), Spanned::span);
    Err(ctx.invalid(
        span,
        &format!("{prefix}plane"),
        Problem::TooManyPlanes {
            count,
            max: MAX_TEXTURE_UNITS,
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
