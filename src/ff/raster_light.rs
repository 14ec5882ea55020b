//! Lighting of one point on the CPU, for the raster colour (GL 1.5 §2.13: the raster
//! position's colour is computed as a vertex's would be, §2.14.1). The formulas are the
//! emulated vertex stage's (`pipeline::emulate::shadergen::vertex`), term for term, so a
//! point drawn and a raster position lit in the same state get the same colour:
//!
//! c = e_m + a_m·a_cs + Σ att·spot·(a_m·a_l + max(n·L, 0)·d_m·d_l + f·max(n·ĥ, 0)^s·s_m·s_l),
//! alpha = d_m.a, clamped to [0, 1]; f = 1 where n·L > 0, else 0; ĥ = L + (0, 0, 1), or
//! L − P_e/|P_e| with LOCAL_VIEWER. The front face's material is used (the raster position
//! has no facing). With SEPARATE_SPECULAR_COLOR the specular sum is the secondary colour,
//! which the raster colour does not hold.
//! Colour material needs nothing here: the model keeps the tracked material colours
//! current (`FixedState::set_color`).

use glam::{Vec3, Vec4};

use super::light::ColorControl;
use super::state::FixedState;

/// The lit front colour of a point at `eye` with eye-space normal `n`.
pub fn lit_color(s: &FixedState, eye: Vec4, n: Vec3) -> Vec4 {
    let m = &s.materials.front;
    let view = if s.light_model.local_viewer {
        (-eye.truncate()).normalize_or_zero()
    } else {
        Vec3::Z
    };
    let separate = s.light_model.color_control == ColorControl::SeparateSpecularColor;
    let mut c = m.emission.truncate() + m.ambient.truncate() * s.light_model.ambient.truncate();
    for light in s.lights.iter().filter_map(|l| l.get()) {
        let p = light.position;
        let (dir, mut att) = if p.w == 0.0 {
            (p.truncate().normalize_or_zero(), 1.0)
        } else {
            let d = p.truncate() / p.w - eye.truncate() / eye.w;
            let dist = d.length();
            let k = Vec3::new(
                light.constant_attenuation,
                light.linear_attenuation,
                light.quadratic_attenuation,
            );
            // (1, 0, 0) is exactly 1, whatever the distance (as the vertex stage).
            let att = if k == Vec3::X {
                1.0
            } else {
                1.0 / (k.x + k.y * dist + k.z * dist * dist)
            };
            (d / dist.max(1e-30), att)
        };
        if light.spot_cutoff != 180.0 {
            // spot = (−L·ŝ)^e when −L·ŝ ≥ cos(cutoff), else 0; x^0 = 1. Mesa's raster
            // position tests ≥ with its cosine (`Light::cos_cutoff`), where its vertex
            // program tests > (`shadergen::vertex`): a zero spot direction lights a raster
            // position by (0)^e.
            let sd = (-dir).dot(light.spot_direction.normalize_or_zero());
            let cos = light.cos_cutoff();
            att *= if sd < cos {
                0.0
            } else if light.spot_exponent == 0.0 {
                1.0
            } else {
                sd.max(0.0).powf(light.spot_exponent)
            };
        }
        let mut ndl = n.dot(dir);
        if ndl.is_nan() {
            ndl = 0.0;
        }
        let mut term = m.ambient.truncate() * light.ambient.truncate()
            + ndl.max(0.0) * m.diffuse.truncate() * light.diffuse.truncate();
        if ndl > 0.0 && !separate {
            let ndh = n.dot((dir + view).normalize_or_zero()).max(0.0);
            let f = if m.shininess == 0.0 {
                1.0
            } else {
                ndh.powf(m.shininess)
            };
            term += f * m.specular.truncate() * light.specular.truncate();
        }
        c += att * term;
    }
    // The lit clamp: NaN → 1, as the vertex stage's saturate_lit.
    let sat = |v: f32| if v.is_nan() { 1.0 } else { v.clamp(0.0, 1.0) };
    Vec4::new(sat(c.x), sat(c.y), sat(c.z), sat(m.diffuse.w))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::{Capability, Command, LightParam, MaterialParam};

    #[test]
    fn default_light_on_a_facing_normal_gives_ambient_plus_diffuse() {
        let mut s = FixedState::new();
        s.apply(&Command::Enable(Capability::Light(0))).unwrap();
        // Scene ambient 0.2·0.2 + diffuse 0.8·1 (n·L = 1); no specular (s_m = 0).
        let c = lit_color(&s, Vec4::new(0.0, 0.0, -1.0, 1.0), Vec3::Z);
        assert!((c - Vec4::new(0.84, 0.84, 0.84, 1.0)).abs().max_element() < 1e-6);
        // Facing away: only the ambient terms.
        let c = lit_color(&s, Vec4::new(0.0, 0.0, -1.0, 1.0), Vec3::NEG_Z);
        assert!((c.x - 0.04).abs() < 1e-6);
    }

    #[test]
    fn attenuation_and_clamping() {
        let mut s = FixedState::new();
        s.apply(&Command::Enable(Capability::Light(0))).unwrap();
        s.apply(&Command::Light {
            light: 0,
            param: LightParam::Position(Vec4::new(0.0, 0.0, 1.0, 1.0)),
        })
        .unwrap();
        s.apply(&Command::Light {
            light: 0,
            param: LightParam::QuadraticAttenuation(1.0),
        })
        .unwrap();
        // Distance 2 from (0,0,−1): att = 1/(1 + 4) on ambient 0 + diffuse 0.8.
        let c = lit_color(&s, Vec4::new(0.0, 0.0, -1.0, 1.0), Vec3::Z);
        assert!((c.x - (0.04 + 0.8 / 5.0)).abs() < 1e-6);
        s.apply(&Command::Material {
            face: crate::ff::Face::Front,
            param: MaterialParam::Emission(Vec4::splat(3.0)),
        })
        .unwrap();
        let c = lit_color(&s, Vec4::new(0.0, 0.0, -1.0, 1.0), Vec3::Z);
        assert_eq!(c.truncate(), Vec3::ONE);
    }
}
