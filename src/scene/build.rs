//! Raw tables → validated scene. One function per table; each reports the first problem it
//! finds with the key's dotted path (`light[0].near`) and its line.
//!
//! Defaults: a missing `[camera]` or `[image]` is the default scene's; a missing `[shadow]`
//! is technique `none`, a 256² D24 map, the technique's default offset, float precision, the driver's depth readback, nearest filtering.
//! A missing `[truth]` is `TruthSettings::DEFAULT_SAMPLES` shadow rays per area-light pixel.
//! A directional light's `angular_diameter` (degrees, (0, 30]) makes it a sun (`SunDisc`);
//! without it the light is hard (0).
//! A light's `up` defaults to +y, or −z when the light looks along ±y (gluLookAt needs an
//! up that is not parallel to the view); an explicit `up` along the view is an error.

use super::check::{span_of, Ctx, Result};
use super::error::{Problem, SceneError, SceneWarning, WarningKind};
use super::limits::MAX_IMAGE_SIZE;
use super::raw::*;
use super::sun::MAX_SUN_DIAMETER_DEGREES;
use super::types::*;
use crate::mesh::{self, AircraftLayout};
use crate::vocab::{DepthBits, Named, OffsetSource, PolygonOffset, TechniqueId};
use glam::Vec3;
use std::ops::Range;
use toml::Spanned;

pub(super) fn scene(ctx: &mut Ctx, raw: RawScene) -> Result<Scene> {
    let defaults = Scene::default_scene();
    let camera = match &raw.camera {
        Some(c) => camera(ctx, c)?,
        None => defaults.camera,
    };
    let image = match &raw.image {
        Some(i) => image(ctx, i.get_ref(), defaults.image)?,
        None => defaults.image,
    };
    let lights = raw
        .light
        .iter()
        .enumerate()
        .map(|(i, l)| light(ctx, l, &format!("light[{i}].")))
        .collect::<Result<Vec<_>>>()?;
    // Shapes first: their triangles are counted from the parameters, and refused over
    // the budget, before the first mesh is built.
    let mut shapes = Vec::with_capacity(raw.object.len());
    let mut triangles = 0u64;
    for (i, o) in raw.object.iter().enumerate() {
        let shape = shape(ctx, o.get_ref(), o.span(), &format!("object[{i}]."))?;
        triangles = triangles.saturating_add(shape.0.triangle_estimate());
        ctx.within_budget(triangles, o.span(), &format!("object[{i}]"))?;
        shapes.push(shape);
    }
    let mut objects = Vec::with_capacity(raw.object.len());
    let mut planes = Vec::new();
    for (i, (o, shape)) in raw.object.iter().zip(shapes).enumerate() {
        let prefix = format!("object[{i}].");
        let object = object(ctx, o, shape, &prefix)?;
        let declared = super::planes::object_planes(ctx, o, &object, &prefix)?;
        if let Some(first) = o.get_ref().section.first().filter(|_| declared.is_empty()) {
            let what = "section (`[[object.section]]` cuts an object with shadow planes)";
            return Err(ctx.invalid(
                first.span(),
                &format!("{prefix}plane"),
                Problem::Missing { what: what.into() },
            ));
        }
        let sections = super::planes::object_sections(ctx, o, declared.len(), &prefix)?;
        if !declared.is_empty() {
            planes.push(ObjectPlanes {
                object: i,
                planes: declared,
                sections,
            });
        }
        if let Shape::Obj { .. } = object.shape {
            // An OBJ's count is known once it is read.
            triangles = triangles.saturating_add(object.mesh.triangle_count() as u64);
            ctx.within_budget(triangles, o.span(), &format!("object[{i}]"))?;
        }
        objects.push(object);
    }
    super::planes::within_units(ctx, &raw.object, &objects, &planes)?;
    let mut shadow = match &raw.shadow {
        Some(s) => shadow(ctx, s.get_ref())?,
        None => ShadowSettings::default(),
    };
    shadow.planes = planes;
    let truth = match &raw.truth {
        Some(t) => truth(ctx, t.get_ref())?,
        None => TruthSettings::default(),
    };
    Ok(Scene {
        camera,
        image,
        lights,
        objects,
        shadow,
        truth,
        warnings: std::mem::take(&mut ctx.warnings),
        limits: ctx.limits,
    })
}

/// gluLookAt's inputs: the view direction must be non-zero and not parallel to up.
/// `eye_key` names what the eye was written as (`camera.eye`, `light[0].position`…).
fn look_at(
    ctx: &Ctx,
    (eye, eye_key): (Vec3, &str),
    at: Vec3,
    up: Vec3,
    spans: [Range<usize>; 2],
    prefix: &str,
) -> Result<Camera> {
    let view = at - eye;
    if view.length_squared() == 0.0 {
        return Err(ctx.invalid(
            spans[0].clone(),
            &format!("{prefix}at"),
            Problem::Coincides {
                other: eye_key.to_string(),
                point: eye,
            },
        ));
    }
    if up.length_squared() == 0.0 || view.normalize().cross(up.normalize()).length() < 1e-6 {
        return Err(ctx.invalid(
            spans[1].clone(),
            &format!("{prefix}up"),
            Problem::UpAlongView { view },
        ));
    }
    Ok(Camera {
        eye,
        at,
        up,
        projection: Projection::Perspective {
            fovy: 90.0,
            near: 1.0,
            far: 100.0,
        },
    })
}

/// gluPerspective's fovy ∈ (0, 180), 0 < near < far.
fn perspective(
    ctx: &Ctx,
    fovy: &Spanned<f32>,
    near: &Spanned<f32>,
    far: &Spanned<f32>,
    prefix: &str,
) -> Result<Projection> {
    let f = ctx.finite(fovy, &format!("{prefix}fovy"))?;
    if !(f > 0.0 && f < 180.0) {
        return Err(ctx.invalid(
            fovy.span(),
            &format!("{prefix}fovy"),
            Problem::FovyOutOfRange(f),
        ));
    }
    let n = ctx.positive(near, &format!("{prefix}near"))?;
    let (n, fa) = near_far(ctx, n, far, prefix)?;
    Ok(Projection::Perspective {
        fovy: f,
        near: n,
        far: fa,
    })
}

fn near_far(ctx: &Ctx, near: f32, far: &Spanned<f32>, prefix: &str) -> Result<(f32, f32)> {
    let fa = ctx.finite(far, &format!("{prefix}far"))?;
    if near >= fa {
        return Err(ctx.invalid(
            far.span(),
            &format!("{prefix}far"),
            Problem::NearNotBeforeFar { near, far: fa },
        ));
    }
    Ok((near, fa))
}

fn spanned<T: Copy>(v: &S<T>, default: T, at: Range<usize>) -> Spanned<T> {
    match v {
        Some(v) => v.clone_spanned(),
        None => Spanned::new(at, default),
    }
}

trait CloneSpanned<T> {
    fn clone_spanned(&self) -> Spanned<T>;
}

impl<T: Copy> CloneSpanned<T> for Spanned<T> {
    fn clone_spanned(&self) -> Spanned<T> {
        Spanned::new(self.span(), *self.get_ref())
    }
}

fn camera(ctx: &Ctx, table: &Spanned<RawCamera>) -> Result<Camera> {
    let (c, span, p) = (table.get_ref(), table.span(), "camera.");
    let eye = ctx.vec3(
        ctx.required(&c.eye, "camera.eye", "camera", span.clone())?,
        "camera.eye",
    )?;
    let at = ctx.required(&c.at, "camera.at", "camera", span.clone())?;
    let up_span = span_of(&c.up).unwrap_or(span.clone());
    let up = ctx.opt_vec3(&c.up, "camera.up", Vec3::Y)?;
    let mut cam = look_at(
        ctx,
        (eye, "camera.eye"),
        ctx.vec3(at, "camera.at")?,
        up,
        [at.span(), up_span],
        p,
    )?;
    let near = ctx.required(&c.near, "camera.near", "camera", span.clone())?;
    let far = ctx.required(&c.far, "camera.far", "camera", span.clone())?;
    cam.projection = match (&c.fovy, &c.ortho) {
        (Some(fovy), None) => perspective(ctx, fovy, near, far, p)?,
        (None, Some(o)) => {
            let b = o.get_ref();
            let l = ctx.finite(&b.left, "camera.ortho.left")?;
            let r = ctx.finite(&b.right, "camera.ortho.right")?;
            let bo = ctx.finite(&b.bottom, "camera.ortho.bottom")?;
            let t = ctx.finite(&b.top, "camera.ortho.top")?;
            for (low, high, s, low_key, high_key) in [
                (l, r, &b.right, "left", "right"),
                (bo, t, &b.top, "bottom", "top"),
            ] {
                if low >= high {
                    return Err(ctx.invalid(
                        s.span(),
                        &format!("camera.ortho.{high_key}"),
                        Problem::NotAbove {
                            low_key: format!("camera.ortho.{low_key}"),
                            low,
                            high,
                        },
                    ));
                }
            }
            let (n, f) = near_far(ctx, ctx.finite(near, "camera.near")?, far, p)?;
            Projection::Orthographic {
                left: l,
                right: r,
                bottom: bo,
                top: t,
                near: n,
                far: f,
            }
        }
        (Some(fovy), Some(_)) => {
            return Err(ctx.invalid(
                fovy.span(),
                "camera.fovy",
                Problem::Conflicts { other: "ortho" },
            ))
        }
        (None, None) => {
            return Err(ctx.invalid(
                span,
                "camera.fovy",
                Problem::Missing {
                    what: "camera without `ortho`".into(),
                },
            ))
        }
    };
    Ok(cam)
}

fn image(ctx: &Ctx, i: &RawImage, default: ImageSpec) -> Result<ImageSpec> {
    ctx.at_most(&i.width, "image.width", MAX_IMAGE_SIZE)?;
    ctx.at_most(&i.height, "image.height", MAX_IMAGE_SIZE)?;
    Ok(ImageSpec {
        width: ctx.count(&i.width, "image.width", default.width, 1)?,
        height: ctx.count(&i.height, "image.height", default.height, 1)?,
        background: ctx.opt_vec3(&i.background, "image.background", default.background)?,
    })
}

/// The up vector of a light's view: explicit, or +y unless the view is along ±y, then −z.
fn light_up(ctx: &Ctx, l: &RawLight, view: Vec3, prefix: &str) -> Result<Vec3> {
    match &l.up {
        Some(up) => ctx.vec3(up, &format!("{prefix}up")),
        None if view.normalize_or_zero().cross(Vec3::Y).length() < 1e-6 => Ok(-Vec3::Z),
        None => Ok(Vec3::Y),
    }
}

fn light(ctx: &Ctx, table: &Spanned<RawLight>, prefix: &str) -> Result<Light> {
    let (l, span) = (table.get_ref(), table.span());
    let kind = *l.kind.get_ref();
    let given = [
        ("position", span_of(&l.position)),
        ("at", span_of(&l.at)),
        ("up", span_of(&l.up)),
        ("fovy", span_of(&l.fovy)),
        ("near", span_of(&l.near)),
        ("far", span_of(&l.far)),
        ("cutoff", span_of(&l.cutoff)),
        ("exponent", span_of(&l.exponent)),
        ("direction", span_of(&l.direction)),
        ("angular_diameter", span_of(&l.angular_diameter)),
        ("extent", span_of(&l.extent)),
        ("distance", span_of(&l.distance)),
        ("corner", span_of(&l.corner)),
        ("edge_u", span_of(&l.edge_u)),
        ("edge_v", span_of(&l.edge_v)),
        ("centre", span_of(&l.centre)),
        ("size", span_of(&l.size)),
    ];
    const COMMON: [&str; 3] = ["type", "colour", "intensity"];
    let (what, valid): (&str, Vec<&'static str>) = match kind {
        LightType::Point => (
            "point light",
            vec!["position", "at", "up", "fovy", "near", "far"],
        ),
        LightType::Spot => (
            "spot light",
            vec![
                "position", "at", "up", "fovy", "near", "far", "cutoff", "exponent",
            ],
        ),
        LightType::Directional => (
            "directional light",
            vec![
                "direction",
                "angular_diameter",
                "at",
                "up",
                "extent",
                "distance",
                "near",
                "far",
            ],
        ),
        LightType::Area => (
            "area light",
            vec![
                "corner", "edge_u", "edge_v", "centre", "size", "at", "up", "fovy", "near", "far",
            ],
        ),
    };
    let valid: Vec<&'static str> = COMMON.iter().copied().chain(valid).collect();
    ctx.only(&given, &valid, what, prefix)?;
    let key = |k: &str| format!("{prefix}{k}");
    let colour = ctx.opt_vec3(&l.colour, &key("colour"), Vec3::ONE)?;
    let intensity = ctx.size(&l.intensity, &key("intensity"), 1.0)?;
    let frustum = |ctx: &Ctx| {
        perspective(
            ctx,
            &spanned(&l.fovy, 90.0, span.clone()),
            &spanned(&l.near, 1.0, span.clone()),
            &spanned(&l.far, 100.0, span.clone()),
            prefix,
        )
    };
    let up_span = span_of(&l.up).unwrap_or(span.clone());
    let (kind, view) = match kind {
        LightType::Point | LightType::Spot => {
            let position = ctx.required(&l.position, &key("position"), what, span.clone())?;
            let position = ctx.vec3(position, &key("position"))?;
            let at = ctx.required(&l.at, &key("at"), what, span.clone())?;
            let at_v = ctx.vec3(at, &key("at"))?;
            let up = light_up(ctx, l, at_v - position, prefix)?;
            let eye = (position, key("position"));
            let mut view = look_at(ctx, (eye.0, &eye.1), at_v, up, [at.span(), up_span], prefix)?;
            view.projection = frustum(ctx)?;
            let kind = if kind == LightType::Point {
                LightKind::Point
            } else {
                let half = match view.projection {
                    Projection::Perspective { fovy, .. } => fovy / 2.0,
                    Projection::Orthographic { .. } => 45.0,
                };
                let cutoff = ctx.number(&l.cutoff, &key("cutoff"), half)?;
                if !(0.0..=90.0).contains(&cutoff) {
                    let s = span_of(&l.cutoff).unwrap_or(span.clone());
                    return Err(ctx.invalid(
                        s,
                        &key("cutoff"),
                        Problem::OutOfRange {
                            low: 0.0,
                            high: 90.0,
                            value: cutoff,
                        },
                    ));
                }
                let exponent = ctx.number(&l.exponent, &key("exponent"), 0.0)?;
                if !(0.0..=128.0).contains(&exponent) {
                    let s = span_of(&l.exponent).unwrap_or(span.clone());
                    return Err(ctx.invalid(
                        s,
                        &key("exponent"),
                        Problem::OutOfRange {
                            low: 0.0,
                            high: 128.0,
                            value: exponent,
                        },
                    ));
                }
                LightKind::Spot { cutoff, exponent }
            };
            (kind, view)
        }
        LightType::Directional => {
            let direction = ctx.required(&l.direction, &key("direction"), what, span.clone())?;
            let d = ctx.direction(direction, &key("direction"))?;
            let at = ctx.opt_vec3(&l.at, &key("at"), Vec3::ZERO)?;
            let extent = ctx.size(&l.extent, &key("extent"), 10.0)?;
            let distance = ctx.size(&l.distance, &key("distance"), 20.0)?;
            let near = ctx.number(&l.near, &key("near"), 1.0)?;
            let (near, far) = near_far(
                ctx,
                near,
                &spanned(&l.far, 2.0 * distance, span.clone()),
                prefix,
            )?;
            let eye = at - d.normalize() * distance;
            let up = light_up(ctx, l, d, prefix)?;
            let eye = (eye, key("direction"));
            let spans = [direction.span(), up_span];
            let mut view = look_at(ctx, (eye.0, &eye.1), at, up, spans, prefix)?;
            view.projection = Projection::Orthographic {
                left: -extent,
                right: extent,
                bottom: -extent,
                top: extent,
                near,
                far,
            };
            let angular_diameter =
                angular_diameter(ctx, &l.angular_diameter, &key("angular_diameter"))?;
            (
                LightKind::Directional {
                    direction: d,
                    angular_diameter,
                },
                view,
            )
        }
        LightType::Area => area_light(ctx, l, span.clone(), prefix, up_span, &frustum)?,
    };
    Ok(Light {
        kind,
        view,
        colour,
        intensity,
    })
}

/// A directional light's `angular_diameter`: absent, 0 (a hard light); given, degrees in
/// (0, `MAX_SUN_DIAMETER_DEGREES`], returned in radians.
fn angular_diameter(ctx: &Ctx, v: &S<f32>, key: &str) -> Result<f32> {
    let Some(v) = v else {
        return Ok(0.0);
    };
    let degrees = ctx.finite(v, key)?;
    if degrees > 0.0 && degrees <= MAX_SUN_DIAMETER_DEGREES {
        Ok(degrees.to_radians())
    } else {
        Err(ctx.invalid(
            v.span(),
            key,
            Problem::DegreesOutOfRange {
                max: MAX_SUN_DIAMETER_DEGREES,
                value: degrees,
            },
        ))
    }
}

fn area_light(
    ctx: &Ctx,
    l: &RawLight,
    span: Range<usize>,
    prefix: &str,
    up_span: Range<usize>,
    frustum: &dyn Fn(&Ctx) -> Result<Projection>,
) -> Result<(LightKind, Camera)> {
    let key = |k: &str| format!("{prefix}{k}");
    let what = "area light (corner + edge_u + edge_v, or centre + size + at)";
    let (corner, edge_u, edge_v, at) = match (&l.corner, &l.centre) {
        (Some(corner), None) => {
            let corner = ctx.vec3(corner, &key("corner"))?;
            let eu = ctx.direction(
                ctx.required(&l.edge_u, &key("edge_u"), what, span.clone())?,
                &key("edge_u"),
            )?;
            let ev_raw = ctx.required(&l.edge_v, &key("edge_v"), what, span.clone())?;
            let ev = ctx.direction(ev_raw, &key("edge_v"))?;
            let normal = eu.cross(ev);
            if normal.length_squared() == 0.0 {
                return Err(ctx.invalid(
                    ev_raw.span(),
                    &key("edge_v"),
                    Problem::ParallelEdges {
                        other: key("edge_u"),
                        edge: eu,
                    },
                ));
            }
            let centre = corner + 0.5 * (eu + ev);
            let at = ctx.opt_vec3(&l.at, &key("at"), centre + normal.normalize())?;
            (corner, eu, ev, at)
        }
        (None, Some(centre)) => {
            let centre = ctx.vec3(centre, &key("centre"))?;
            let size = ctx.required(&l.size, &key("size"), what, span.clone())?;
            let [w, h] = size.get_ref().0;
            for v in [w, h] {
                if !(v.is_finite() && v > 0.0) {
                    return Err(ctx.invalid(size.span(), &key("size"), Problem::NotPositive(v)));
                }
            }
            let at_raw = ctx.required(&l.at, &key("at"), what, span.clone())?;
            let at = ctx.vec3(at_raw, &key("at"))?;
            let n = (at - centre).normalize_or_zero();
            if n == Vec3::ZERO {
                return Err(ctx.invalid(
                    at_raw.span(),
                    &key("at"),
                    Problem::Coincides {
                        other: key("centre"),
                        point: centre,
                    },
                ));
            }
            // An orthonormal frame (u, v, n): u ⟂ the hint (y, or z when n ∥ y).
            let hint = if n.cross(Vec3::Y).length() < 1e-6 {
                Vec3::Z
            } else {
                Vec3::Y
            };
            let u = hint.cross(n).normalize();
            let v = n.cross(u);
            let (eu, ev) = (u * w, v * h);
            (centre - 0.5 * (eu + ev), eu, ev, at)
        }
        (Some(_), Some(c)) => {
            return Err(ctx.invalid(
                c.span(),
                &key("centre"),
                Problem::Conflicts { other: "corner" },
            ))
        }
        (None, None) => {
            return Err(ctx.invalid(span, &key("corner"), Problem::Missing { what: what.into() }))
        }
    };
    let centre = corner + 0.5 * (edge_u + edge_v);
    let up = light_up(ctx, l, at - centre, prefix)?;
    let at_span = span_of(&l.at).unwrap_or(span.clone());
    // The light's view starts at the rectangle's centre.
    let eye_key = match l.centre {
        Some(_) => key("centre"),
        None => format!("{prefix}corner + (edge_u + edge_v) / 2"),
    };
    let mut view = look_at(ctx, (centre, &eye_key), at, up, [at_span, up_span], prefix)?;
    view.projection = frustum(ctx)?;
    Ok((
        LightKind::Area {
            corner,
            edge_u,
            edge_v,
        },
        view,
    ))
}

fn extent(ctx: &Ctx, v: &Spanned<Extent>, key: &str) -> Result<Vec3> {
    let e = match *v.get_ref() {
        Extent::Uniform(x) => Vec3::splat(x),
        Extent::PerAxis(a) => Vec3::from_array(a.0),
    };
    if !e.is_finite() {
        return Err(ctx.invalid(v.span(), key, Problem::NotFinite));
    }
    match e.to_array().into_iter().find(|x| *x <= 0.0) {
        Some(x) => Err(ctx.invalid(v.span(), key, Problem::NotPositive(x))),
        None => Ok(e),
    }
}

fn uniform(ctx: &Ctx, v: &S<Extent>, key: &str, default: f32) -> Result<f32> {
    match v {
        None => Ok(default),
        Some(s) => match *s.get_ref() {
            Extent::Uniform(_) => Ok(extent(ctx, s, key)?.x),
            Extent::PerAxis(_) => Err(ctx.invalid(
                s.span(),
                key,
                Problem::NotOneOf {
                    value: "an array".into(),
                    expected: vec!["a single number"],
                },
            )),
        },
    }
}

fn shape(
    ctx: &mut Ctx,
    o: &RawObject,
    span: Range<usize>,
    prefix: &str,
) -> Result<(Shape, Option<Range<usize>>)> {
    let key = |k: &str| format!("{prefix}{k}");
    let given = [
        ("size", span_of(&o.size)),
        ("tessellation", span_of(&o.tessellation)),
        ("radius", span_of(&o.radius)),
        ("slices", span_of(&o.slices)),
        ("stacks", span_of(&o.stacks)),
        ("major_radius", span_of(&o.major_radius)),
        ("minor_radius", span_of(&o.minor_radius)),
        ("rings", span_of(&o.rings)),
        ("sides", span_of(&o.sides)),
        ("length", span_of(&o.length)),
        ("layout", span_of(&o.layout)),
    ];
    let (kind, valid): (&str, &[&'static str]) = match (&o.shape, &o.mesh) {
        (Some(_), Some(m)) => return Err(ctx.invalid(m.span(), &key("mesh"), Problem::Conflicts { other: "shape" })),
        (None, None) => {
            return Err(ctx.invalid(span, &key("shape"), Problem::Missing {
                what: "object (`shape = \"plane\" | \"box\" | \"sphere\" | \"torus\" | \"teapot\" | \"aircraft\"` or `mesh = \"file.obj\"`)".into(),
            }))
        }
        (None, Some(m)) => {
            ctx.only(&given, &[], "mesh object", prefix)?;
            let path = ctx.base_dir.join(m.get_ref());
            return Ok((Shape::Obj { path }, Some(m.span())));
        }
        (Some(s), None) => match s.get_ref() {
            ShapeType::Plane => ("plane", &["size", "tessellation"]),
            ShapeType::Box => ("box", &["size"]),
            ShapeType::Sphere => ("sphere", &["radius", "slices", "stacks"]),
            ShapeType::Torus => ("torus", &["major_radius", "minor_radius", "rings", "sides"]),
            ShapeType::Teapot => ("teapot", &["size", "tessellation"]),
            ShapeType::Aircraft => match o.layout.as_ref().map(|l| *l.get_ref()) {
                Some(AircraftLayoutName::F35) => ("f35 aircraft (its size is the thesis's, in metres; scale it with `scale`)", &["layout"]),
                Some(AircraftLayoutName::Fighter) | None => ("aircraft", &["length", "layout"]),
            },
        },
    };
    ctx.only(&given, valid, kind, prefix)?;
    let shape = match o.shape.as_ref().map(|s| *s.get_ref()) {
        Some(ShapeType::Plane) => Shape::Plane {
            size: uniform(ctx, &o.size, &key("size"), 10.0)?,
            tessellation: ctx.count(&o.tessellation, &key("tessellation"), 16, 1)?,
        },
        Some(ShapeType::Box) => Shape::Box {
            size: o
                .size
                .as_ref()
                .map_or(Ok(Vec3::ONE), |s| extent(ctx, s, &key("size")))?,
        },
        Some(ShapeType::Sphere) => Shape::Sphere {
            radius: ctx.size(&o.radius, &key("radius"), 1.0)?,
            slices: ctx.count(&o.slices, &key("slices"), 32, 3)?,
            stacks: ctx.count(&o.stacks, &key("stacks"), 16, 2)?,
        },
        Some(ShapeType::Torus) => Shape::Torus {
            major_radius: ctx.size(&o.major_radius, &key("major_radius"), 1.0)?,
            minor_radius: ctx.size(&o.minor_radius, &key("minor_radius"), 0.25)?,
            rings: ctx.count(&o.rings, &key("rings"), 32, 3)?,
            sides: ctx.count(&o.sides, &key("sides"), 16, 3)?,
        },
        Some(ShapeType::Teapot) => Shape::Teapot {
            size: uniform(ctx, &o.size, &key("size"), 1.0)?,
            tessellation: ctx.count(&o.tessellation, &key("tessellation"), 8, 1)?,
        },
        Some(ShapeType::Aircraft) | None => Shape::Aircraft {
            layout: match o.layout.as_ref().map(|l| *l.get_ref()) {
                Some(AircraftLayoutName::F35) => AircraftLayout::F35,
                Some(AircraftLayoutName::Fighter) | None => AircraftLayout::Fighter {
                    length: ctx.size(&o.length, &key("length"), 4.0)?,
                },
            },
        },
    };
    Ok((shape, None))
}

/// The object of `table`, whose `shape` (and the OBJ path's span) is already read.
fn object(
    ctx: &mut Ctx,
    table: &Spanned<RawObject>,
    (shape, mesh_span): (Shape, Option<Range<usize>>),
    prefix: &str,
) -> Result<Object> {
    let (o, span) = (table.get_ref(), table.span());
    let key = |k: &str| format!("{prefix}{k}");
    let mesh = match (&shape, shape.procedural_mesh()) {
        (_, Some(m)) => m,
        (Shape::Obj { path }, None) => {
            let at = ctx.at(mesh_span.unwrap_or(span.clone()));
            let loaded = mesh::load_obj(path).map_err(|source| SceneError::Mesh {
                at: at.clone(),
                key: key("mesh"),
                source,
            })?;
            if loaded.degenerate > 0 {
                ctx.warnings.push(SceneWarning {
                    at,
                    key: key("mesh"),
                    kind: WarningKind::DegenerateFaces {
                        count: loaded.degenerate,
                    },
                });
            }
            loaded.mesh
        }
        (_, None) => mesh::Mesh::default(),
    };
    let rotate = match &o.rotate {
        None => Vec::new(),
        Some(r) => {
            let list = match r.get_ref() {
                Rotations::One(one) => vec![*one],
                Rotations::Many(many) => many.clone(),
            };
            let mut out = Vec::with_capacity(list.len());
            for raw in list {
                let axis = Vec3::from_array(raw.axis.0);
                if !axis.is_finite() || !raw.degrees.is_finite() {
                    return Err(ctx.invalid(r.span(), &key("rotate"), Problem::NotFinite));
                }
                if axis.length_squared() == 0.0 {
                    return Err(ctx.invalid(r.span(), &key("rotate"), Problem::ZeroVector));
                }
                out.push(Rotation {
                    axis: axis.normalize(),
                    degrees: raw.degrees,
                });
            }
            out
        }
    };
    let transform = Transform {
        translate: ctx.opt_vec3(&o.translate, &key("translate"), Vec3::ZERO)?,
        rotate,
        scale: o
            .scale
            .as_ref()
            .map_or(Ok(Vec3::ONE), |s| extent(ctx, s, &key("scale")))?,
    };
    let defaults = Material::default();
    let shininess = ctx.number(&o.shininess, &key("shininess"), defaults.shininess)?;
    if !(0.0..=128.0).contains(&shininess) {
        let s = span_of(&o.shininess).unwrap_or(span);
        return Err(ctx.invalid(
            s,
            &key("shininess"),
            Problem::OutOfRange {
                low: 0.0,
                high: 128.0,
                value: shininess,
            },
        ));
    }
    Ok(Object {
        name: o.name.clone(),
        shape,
        mesh: std::sync::Arc::new(mesh),
        transform,
        material: Material {
            colour: ctx.opt_vec3(&o.colour, &key("colour"), defaults.colour)?,
            specular: ctx.opt_vec3(&o.specular, &key("specular"), defaults.specular)?,
            shininess,
        },
        casts: o.casts.unwrap_or(true),
        receives: o.receives.unwrap_or(true),
    })
}

fn shadow(ctx: &Ctx, s: &RawShadow) -> Result<ShadowSettings> {
    let defaults = ShadowSettings::default();
    let technique = match &s.technique {
        None => defaults.technique,
        Some(t) => TechniqueId::from_name(t.get_ref()).ok_or_else(|| {
            ctx.invalid(
                t.span(),
                "shadow.technique",
                Problem::UnknownTechnique {
                    name: t.get_ref().clone(),
                    known: TechniqueId::names(),
                },
            )
        })?,
    };
    let depth = match &s.depth_bits {
        None => defaults.depth,
        Some(d) => match d.get_ref() {
            DepthBitsValue::Int(16) => DepthBits::D16,
            DepthBitsValue::Int(24) => DepthBits::D24,
            DepthBitsValue::Text(t) if t == "16" => DepthBits::D16,
            DepthBitsValue::Text(t) if t == "24" => DepthBits::D24,
            DepthBitsValue::Text(t) if t.eq_ignore_ascii_case("32f") => DepthBits::D32F,
            other => {
                let value = match other {
                    DepthBitsValue::Int(i) => i.to_string(),
                    DepthBitsValue::Text(t) => format!("\"{t}\""),
                };
                return Err(ctx.invalid(
                    d.span(),
                    "shadow.depth_bits",
                    Problem::NotOneOf {
                        value,
                        expected: vec!["16", "24", "\"32f\""],
                    },
                ));
            }
        },
    };
    let polygon_offset = match &s.polygon_offset {
        None => OffsetSetting::TechniqueDefault,
        Some(o) => {
            let RawOffset { factor, units } = *o.get_ref();
            if !(factor.is_finite() && units.is_finite()) {
                return Err(ctx.invalid(o.span(), "shadow.polygon_offset", Problem::NotFinite));
            }
            OffsetSetting::Given {
                offset: Some(PolygonOffset { factor, units }),
                by: OffsetSource::Scene,
            }
        }
    };
    Ok(ShadowSettings {
        technique,
        map_size: {
            ctx.at_most(&s.map_size, "shadow.map_size", MAX_IMAGE_SIZE)?;
            ctx.count(&s.map_size, "shadow.map_size", defaults.map_size, 1)?
        },
        depth,
        polygon_offset,
        precision: s.precision.unwrap_or(defaults.precision),
        readback: s.readback.unwrap_or(defaults.readback),
        filter: s.filter.unwrap_or(defaults.filter),
        planar_mode: s.planar_mode.unwrap_or(defaults.planar_mode),
        projector: s.projector.unwrap_or(defaults.projector),
        light_samples: light_samples(ctx, &s.light_samples)?,
        // Gathered from the objects by `scene`.
        planes: Vec::new(),
        slices: slices(ctx, &s.slices)?,
        prefilter: s.prefilter.unwrap_or(defaults.prefilter),
        combine: s.combine.unwrap_or(defaults.combine),
        occluder_program: s.program.unwrap_or(defaults.occluder_program),
    })
}

/// `[shadow] slices`: one of `SLICE_COUNTS`, named when refused.
fn slices(ctx: &Ctx, v: &S<u32>) -> Result<u32> {
    match v {
        None => Ok(ShadowSettings::default().slices),
        Some(n) if super::SLICE_COUNTS.contains(n.get_ref()) => Ok(*n.get_ref()),
        Some(n) => Err(ctx.invalid(
            n.span(),
            "shadow.slices",
            Problem::NotOneOf {
                value: n.get_ref().to_string(),
                expected: vec!["4", "8", "16"],
            },
        )),
    }
}

/// `[shadow] light_samples`: 1 to `ShadowSettings::MAX_LIGHT_SAMPLES`, the whole range
/// named when refused.
fn light_samples(ctx: &Ctx, v: &S<u32>) -> Result<u32> {
    let max = ShadowSettings::MAX_LIGHT_SAMPLES;
    match v {
        None => Ok(ShadowSettings::DEFAULT_LIGHT_SAMPLES),
        Some(n) if (1..=max).contains(n.get_ref()) => Ok(*n.get_ref()),
        Some(n) => Err(ctx.invalid(
            n.span(),
            "shadow.light_samples",
            Problem::OutOfRange {
                low: 1.0,
                high: max as f32,
                value: *n.get_ref() as f32,
            },
        )),
    }
}

/// `[truth] samples`: 1 to `TruthSettings::MAX_SAMPLES`, the whole range named when refused.
fn truth(ctx: &Ctx, t: &RawTruth) -> Result<TruthSettings> {
    let samples = match &t.samples {
        None => TruthSettings::DEFAULT_SAMPLES,
        Some(n) if (1..=TruthSettings::MAX_SAMPLES).contains(n.get_ref()) => *n.get_ref(),
        Some(n) => {
            return Err(ctx.invalid(
                n.span(),
                "truth.samples",
                Problem::OutOfRange {
                    low: 1.0,
                    high: TruthSettings::MAX_SAMPLES as f32,
                    value: *n.get_ref() as f32,
                },
            ))
        }
    };
    Ok(TruthSettings { samples })
}
