//! glLight, glLightModel and glMaterial as given in the command. Positions and spot
//! directions are passed in object coordinates while GL's modelview equals the model's, so
//! GL transforms them itself (GL 1.5 §2.14.1) and ends with the eye-space values the model
//! stored.

use glam::Vec4;

use crate::ff::{Face, LightModelParam, LightParam, MaterialParam};

use super::bindings as gl;
use super::bindings::types::GLenum;
use super::conv;

fn fv(g: &gl::Gl, light: GLenum, pname: GLenum, v: Vec4) {
    let a = v.to_array();
    // SAFETY: four floats, enough for every vector parameter of glLightfv.
    unsafe { g.Lightfv(light, pname, a.as_ptr()) }
}

fn f(g: &gl::Gl, light: GLenum, pname: GLenum, v: f32) {
    // SAFETY: plain GL call on the current context.
    unsafe { g.Lightf(light, pname, v) }
}

/// glLight for LIGHT0 + `index`.
pub fn light(g: &gl::Gl, index: u8, param: LightParam) {
    let l = gl::LIGHT0 + GLenum::from(index);
    match param {
        LightParam::Ambient(c) => fv(g, l, gl::AMBIENT, c),
        LightParam::Diffuse(c) => fv(g, l, gl::DIFFUSE, c),
        LightParam::Specular(c) => fv(g, l, gl::SPECULAR, c),
        LightParam::Position(p) => fv(g, l, gl::POSITION, p),
        // A 3-vector: the fourth float is ignored by GL.
        LightParam::SpotDirection(d) => fv(g, l, gl::SPOT_DIRECTION, d.extend(0.0)),
        LightParam::SpotExponent(e) => f(g, l, gl::SPOT_EXPONENT, e),
        LightParam::SpotCutoff(c) => f(g, l, gl::SPOT_CUTOFF, c),
        LightParam::ConstantAttenuation(k) => f(g, l, gl::CONSTANT_ATTENUATION, k),
        LightParam::LinearAttenuation(k) => f(g, l, gl::LINEAR_ATTENUATION, k),
        LightParam::QuadraticAttenuation(k) => f(g, l, gl::QUADRATIC_ATTENUATION, k),
    }
}

/// glLightModel.
pub fn light_model(g: &gl::Gl, param: LightModelParam) {
    // SAFETY: plain GL calls; the vector form gets four floats.
    unsafe {
        match param {
            LightModelParam::Ambient(c) => {
                let a = c.to_array();
                g.LightModelfv(gl::LIGHT_MODEL_AMBIENT, a.as_ptr());
            }
            LightModelParam::LocalViewer(b) => {
                g.LightModeli(gl::LIGHT_MODEL_LOCAL_VIEWER, i32::from(b))
            }
            LightModelParam::TwoSide(b) => g.LightModeli(gl::LIGHT_MODEL_TWO_SIDE, i32::from(b)),
            LightModelParam::ColorControl(c) => {
                g.LightModeli(gl::LIGHT_MODEL_COLOR_CONTROL, conv::int(conv::value(c)))
            }
        }
    }
}

/// glMaterial.
pub fn material(g: &gl::Gl, face: Face, param: MaterialParam) {
    let face = conv::value(face);
    let (pname, v) = match param {
        MaterialParam::Ambient(c) => (gl::AMBIENT, c),
        MaterialParam::Diffuse(c) => (gl::DIFFUSE, c),
        MaterialParam::AmbientAndDiffuse(c) => (gl::AMBIENT_AND_DIFFUSE, c),
        MaterialParam::Specular(c) => (gl::SPECULAR, c),
        MaterialParam::Emission(c) => (gl::EMISSION, c),
        MaterialParam::Shininess(s) => {
            // SAFETY: plain GL call on the current context.
            unsafe { g.Materialf(face, gl::SHININESS, s) };
            return;
        }
        MaterialParam::ColorIndexes(i) => {
            let a = i.to_array();
            // SAFETY: three floats, as COLOR_INDEXES reads.
            unsafe { g.Materialfv(face, gl::COLOR_INDEXES, a.as_ptr()) };
            return;
        }
    };
    let a = v.to_array();
    // SAFETY: four floats.
    unsafe { g.Materialfv(face, pname, a.as_ptr()) }
}
