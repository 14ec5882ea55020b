//! glTexGen and glTexEnv of the active unit, as given in the command.
//!
//! An eye plane is passed in object coordinates while GL's modelview equals the model's;
//! GL multiplies it by the inverse modelview itself (GL 1.5 §2.11.4), ending with the eye
//! plane the model stored. Texenv goes through unchanged, COMBINE with its crossbar sources
//! (TEXTUREn) and DOT3 included; scales are sent as the floats 1, 2 or 4.

use crate::ff::{CombineArg, TexCoord, TexEnvParam, TexGenParam};

use super::bindings as gl;
use super::conv;

/// glTexGen for one coordinate of the active unit.
pub fn texgen(g: &gl::Gl, coord: TexCoord, param: TexGenParam) {
    let c = conv::value(coord);
    // SAFETY: plain GL calls; plane forms get four floats.
    unsafe {
        match param {
            TexGenParam::Mode(m) => g.TexGeni(c, gl::TEXTURE_GEN_MODE, conv::int(conv::value(m))),
            TexGenParam::ObjectPlane(p) => {
                let a = p.to_array();
                g.TexGenfv(c, gl::OBJECT_PLANE, a.as_ptr());
            }
            TexGenParam::EyePlane(p) => {
                let a = p.to_array();
                g.TexGenfv(c, gl::EYE_PLANE, a.as_ptr());
            }
        }
    }
}

/// glTexEnv(TEXTURE_ENV, …) of the active unit.
pub fn texenv(g: &gl::Gl, param: TexEnvParam) {
    let t = gl::TEXTURE_ENV;
    let int = |pname, value| {
        // SAFETY: plain GL call on the current context.
        unsafe { g.TexEnvi(t, pname, conv::int(value)) }
    };
    let arg = CombineArg::index;
    match param {
        TexEnvParam::Mode(m) => int(gl::TEXTURE_ENV_MODE, conv::value(m)),
        TexEnvParam::Color(c) => {
            let a = c.to_array();
            // SAFETY: four floats.
            unsafe { g.TexEnvfv(t, gl::TEXTURE_ENV_COLOR, a.as_ptr()) }
        }
        TexEnvParam::CombineRgb(f) => int(gl::COMBINE_RGB, conv::value(f)),
        TexEnvParam::CombineAlpha(f) => int(gl::COMBINE_ALPHA, conv::value(f)),
        TexEnvParam::SourceRgb(a, s) => int(conv::source_rgb(arg(a)), conv::combine_source(s)),
        TexEnvParam::SourceAlpha(a, s) => int(conv::source_alpha(arg(a)), conv::combine_source(s)),
        TexEnvParam::OperandRgb(a, o) => int(conv::operand_rgb(arg(a)), conv::value(o)),
        TexEnvParam::OperandAlpha(a, o) => int(conv::operand_alpha(arg(a)), conv::value(o)),
        // SAFETY (both): plain GL calls on the current context.
        TexEnvParam::RgbScale(s) => unsafe { g.TexEnvf(t, gl::RGB_SCALE, s) },
        TexEnvParam::AlphaScale(s) => unsafe { g.TexEnvf(t, gl::ALPHA_SCALE, s) },
        // SAFETY: a plain GL call on the current context.
        TexEnvParam::LodBias(b) => unsafe {
            g.TexEnvf(gl::TEXTURE_FILTER_CONTROL, gl::TEXTURE_LOD_BIAS, b)
        },
        // SAFETY: a plain GL call on the current context.
        TexEnvParam::CoordReplace(on) => unsafe {
            g.TexEnvi(gl::POINT_SPRITE, gl::COORD_REPLACE, i32::from(on))
        },
    }
}
