//! The converter of the raster calls added with GL 1.0–1.4 fog, scissor, clip planes, logic
//! op and blending, and glHint; `Ok(None)` for calls of other areas.

use super::api::{CType, Entry};
use super::args::Args;
use super::glenum::{Family, GlEnum};
use super::*;

const FOG_PNAMES: &[&str] = &[
    "GL_FOG_COLOR",
    "GL_FOG_DENSITY",
    "GL_FOG_START",
    "GL_FOG_END",
    "GL_FOG_INDEX",
    "GL_FOG_MODE",
    "GL_FOG_COORD_SRC",
];

/// The token a vector form's one value names (INVALID_ENUM for a value of no token of `T`).
fn token_value<A: Args, T: GlEnum>(c: &A) -> Result<T, A::Error> {
    let v = c.floats::<1>(1)?[0];
    super::float_token::FloatToken::of(c.entry())
        .token(f64::from(v))
        .and_then(T::from_gl_value)
        .ok_or_else(|| c.unknown(1, T::names()))
}

/// A scalar fog parameter of `value`.
fn fog_scalar(pname: &str, value: f32) -> FogParam {
    match pname {
        "GL_FOG_DENSITY" => FogParam::Density(value),
        "GL_FOG_START" => FogParam::Start(value),
        "GL_FOG_END" => FogParam::End(value),
        _ => FogParam::Index(value),
    }
}

/// glFog{f,i}(pname, param) and glFog{f,i}v(pname, params). FOG_MODE and FOG_COORD_SRC
/// take a token (in the vector forms its value, as a C program passes it; a script writes
/// them with glFogi). glFogiv's colour is mapped as signed integers are (GL 1.5 Table 2.9:
/// (2c + 1)/(2³² − 1)).
fn fog<A: Args>(c: &A) -> Result<FogParam, A::Error> {
    c.count(2)?;
    Ok(match c.entry() {
        Entry::Fogf | Entry::Fogi => match c.pname(0, FOG_PNAMES)? {
            "GL_FOG_MODE" => FogParam::Mode(c.enm(1)?),
            "GL_FOG_COORD_SRC" => FogParam::CoordSource(c.enm(1)?),
            // FOG_COLOR is (param, 0, 0, 0) (`calls::first_of_four`), glFogi's integer taken
            // as a number, as Mesa takes it (measured).
            "GL_FOG_COLOR" => FogParam::Color(super::calls::first_of_four(c.f32(1)?)),
            p => fog_scalar(p, c.f32(1)?),
        },
        _ => {
            let int = c.entry() == Entry::Fogiv;
            match c.pname(0, FOG_PNAMES)? {
                "GL_FOG_COLOR" => {
                    let v = c.floats::<4>(1)?;
                    FogParam::Color(glam::Vec4::from_array(v.map(|x| {
                        if int {
                            CType::Int.normalized(f64::from(x))
                        } else {
                            x
                        }
                    })))
                }
                "GL_FOG_MODE" => FogParam::Mode(token_value(c)?),
                "GL_FOG_COORD_SRC" => FogParam::CoordSource(token_value(c)?),
                p => fog_scalar(p, c.floats::<1>(1)?[0]),
            }
        }
    })
}

const POINT_PNAMES: &[&str] = &[
    "GL_POINT_SIZE_MIN",
    "GL_POINT_SIZE_MAX",
    "GL_POINT_FADE_THRESHOLD_SIZE",
    "GL_POINT_SPRITE_COORD_ORIGIN",
    "GL_POINT_DISTANCE_ATTENUATION",
];

/// glPointParameter{f,i}(pname, param) and glPointParameter{f,i}v(pname, params), with
/// their ARB and EXT names. Integers are taken as numbers (GL 1.5 §3.3). The scalar forms
/// take POINT_DISTANCE_ATTENUATION as (param, 0, 0), as Mesa does (measured; GL 1.4 §3.3
/// gives it three values).
fn point_parameter<A: Args>(c: &A) -> Result<PointParam, A::Error> {
    c.count(2)?;
    let scalar = matches!(
        c.entry(),
        Entry::PointParameterf
            | Entry::PointParameteri
            | Entry::PointParameterfARB
            | Entry::PointParameterfEXT
    );
    let pname = c.pname(0, POINT_PNAMES)?;
    let value = |c: &A| -> Result<f32, A::Error> {
        if scalar {
            c.f32(1)
        } else {
            Ok(c.floats::<1>(1)?[0])
        }
    };
    Ok(match pname {
        "GL_POINT_SIZE_MIN" => PointParam::SizeMin(value(c)?),
        "GL_POINT_SIZE_MAX" => PointParam::SizeMax(value(c)?),
        "GL_POINT_FADE_THRESHOLD_SIZE" => PointParam::FadeThreshold(value(c)?),
        // A token (a script's GL_LOWER_LEFT) or its value as a number (a C program's).
        "GL_POINT_SPRITE_COORD_ORIGIN" => PointParam::SpriteCoordOrigin(match c.token(1) {
            Ok(t) => t,
            Err(_) => value(c)? as u32,
        }),
        _ if scalar => PointParam::DistanceAttenuation([value(c)?, 0.0, 0.0]),
        _ => PointParam::DistanceAttenuation(c.floats::<3>(1)?),
    })
}

/// Fog, scissor, clip planes, logic op and blending.
pub fn raster<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    Ok(Some(match c.entry() {
        Entry::Fogf | Entry::Fogi | Entry::Fogfv | Entry::Fogiv => Command::Fog(fog(c)?),
        Entry::PointParameterf
        | Entry::PointParameterfv
        | Entry::PointParameteri
        | Entry::PointParameteriv
        | Entry::PointParameterfARB
        | Entry::PointParameterfEXT
        | Entry::PointParameterfvARB
        | Entry::PointParameterfvEXT => Command::PointParameter(point_parameter(c)?),
        Entry::ClipPlane => {
            c.count(2)?;
            Command::ClipPlane {
                plane: c.family(0, Family::ClipPlane)?,
                equation: c.vec4_array(1)?,
            }
        }
        Entry::BlendColor => c.count(4).and(c.vec4_args(0)).map(Command::BlendColor)?,
        Entry::BlendEquation => c.count(1).and(c.enm(0)).map(Command::BlendEquation)?,
        Entry::BlendFuncSeparate => {
            c.count(4)?;
            Command::BlendFuncSeparate {
                src_rgb: c.enm(0)?,
                dst_rgb: c.enm(1)?,
                src_alpha: c.enm(2)?,
                dst_alpha: c.enm(3)?,
            }
        }
        Entry::Hint => {
            c.count(2)?;
            Command::Hint {
                target: c.enm(0)?,
                mode: c.enm(1)?,
            }
        }
        Entry::LogicOp => c.count(1).and(c.enm(0)).map(Command::LogicOp)?,
        Entry::Scissor => {
            c.count(4)?;
            Command::Scissor(ScissorBox {
                x: c.i32(0)?,
                y: c.i32(1)?,
                width: c.i32(2)?,
                height: c.i32(3)?,
            })
        }
        _ => return Ok(None),
    }))
}
