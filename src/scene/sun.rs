//! A sun: a directional light whose source is a disc of apparent (full) diameter α, the
//! light at infinity of Eisemann & Décoret's §3.5. Seen from any point, it fills the cone
//! of half-angle θ_max = α/2 around w = −direction (rays towards the light go along −d).
//!
//! **Sampling.** A point (s, t) of the unit square becomes a direction of the cone in two
//! area-preserving steps, so a stratified grid of the square stays stratified, cell for
//! cell, on the sun:
//! 1. Shirley & Chiu's concentric map (1997) onto the unit disc: with a = 2s − 1,
//!    b = 2t − 1, (r, φ) = (a, π/4 · b/a) when |a| > |b|, else (b, π/2 − π/4 · a/b); the
//!    point is r (cos φ, sin φ). Squares about the centre go to rings, so cells stay compact
//!    (a polar map would make slivers at the centre).
//! 2. The disc onto the spherical cap, uniform in solid angle (the sun's radiance is taken
//!    uniform over its disc): the cap to θ has solid angle 2π(1 − cos θ), proportional to
//!    r², so 1 − cos θ = r² (1 − cos θ_max), and the direction is
//!    cos θ · w + sin θ · (x · e₁ + y · e₂) / r, (e₁, e₂) an orthonormal pair ⟂ w.
//!    1 − cos θ_max is computed as 2 sin²(θ_max/2), and sin θ / r as √(k (2 − h)),
//!    k = 1 − cos θ_max, h = 1 − cos θ = r² k, so that small suns keep their precision in
//!    f32.
//!
//! The truth samples suns this way per pixel, and `accumulate` picks its N directions this
//! way too.

use glam::{Vec2, Vec3};
use std::f32::consts::FRAC_PI_4;

/// The largest angular diameter a scene may give, in degrees (the real sun's is 0.53°).
pub const MAX_SUN_DIAMETER_DEGREES: f32 = 30.0;

/// The cone of directions towards a sun, and the map of the unit square onto it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SunDisc {
    /// w: the unit direction towards the sun's centre (−direction).
    pub towards: Vec3,
    /// e₁, e₂: an orthonormal pair perpendicular to `towards`.
    e1: Vec3,
    e2: Vec3,
    /// 1 − cos θ_max.
    one_minus_cos: f32,
    /// The full apparent diameter α = 2 θ_max, radians.
    pub angular_diameter: f32,
}

impl SunDisc {
    /// The sun of a light travelling along `direction` (any length but zero) with full
    /// apparent diameter `angular_diameter` radians.
    pub fn new(direction: Vec3, angular_diameter: f32) -> SunDisc {
        let towards = -direction.normalize_or_zero();
        let (e1, e2) = towards.any_orthonormal_pair();
        // 1 − cos θ_max = 2 sin²(θ_max / 2), θ_max = α / 2.
        let half = (0.25 * angular_diameter).sin();
        SunDisc {
            towards,
            e1,
            e2,
            one_minus_cos: 2.0 * half * half,
            angular_diameter,
        }
    }

    /// The half-angle θ_max of the cone, radians.
    pub fn half_angle(&self) -> f32 {
        0.5 * self.angular_diameter
    }

    /// The direction towards the sun of the point (s, t) ∈ [0, 1]² (module note): the
    /// concentric map onto the disc, then the disc onto the cap uniformly in solid angle.
    /// (½, ½) is the centre, `towards`.
    pub fn direction(&self, s: f32, t: f32) -> Vec3 {
        let p = concentric(s, t);
        // h = 1 − cos θ = r² k, k = 1 − cos θ_max; sin θ = √(h (2 − h)), so the disc
        // point's coefficient sin θ / r = √(k (2 − h)): one root, and none at r = 0.
        let h = p.length_squared() * self.one_minus_cos;
        let scale = (self.one_minus_cos * (2.0 - h)).max(0.0).sqrt();
        (1.0 - h) * self.towards + scale * (p.x * self.e1 + p.y * self.e2)
    }
}

/// Shirley & Chiu's concentric map of the unit square onto the unit disc (module note):
/// area-preserving, (½, ½) ↦ (0, 0), the square's edges onto the circle.
///
/// φ = π/4 · b/a, or π/2 − ψ with ψ = π/4 · a/b, whose cosine and sine are sin ψ and
/// cos ψ.
pub fn concentric(s: f32, t: f32) -> Vec2 {
    let (a, b) = (2.0 * s - 1.0, 2.0 * t - 1.0);
    if a == 0.0 && b == 0.0 {
        return Vec2::ZERO;
    }
    if a.abs() > b.abs() {
        let (sin, cos) = (FRAC_PI_4 * (b / a)).sin_cos();
        a * Vec2::new(cos, sin)
    } else {
        let (sin, cos) = (FRAC_PI_4 * (a / b)).sin_cos();
        b * Vec2::new(sin, cos)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_concentric_map_keeps_area_and_fills_the_disc() {
        assert_eq!(concentric(0.5, 0.5), Vec2::ZERO);
        // Corners and edge midpoints land on the unit circle.
        for (s, t) in [(0.0, 0.0), (1.0, 0.5), (0.5, 1.0), (1.0, 1.0), (0.0, 0.3)] {
            assert!((concentric(s, t).length() - 1.0).abs() < 1e-6, "{s} {t}");
        }
        // The square of half-side h about the centre goes to the disc of radius h: its
        // area fraction h² is kept. Count a fine grid's points inside radius 0.5.
        let n = 400;
        let inside = (0..n * n)
            .filter(|k| {
                let (s, t) = ((k % n) as f32 + 0.5, (k / n) as f32 + 0.5);
                concentric(s / n as f32, t / n as f32).length() < 0.5
            })
            .count();
        let fraction = inside as f32 / (n * n) as f32;
        assert!((fraction - 0.25).abs() < 0.01, "{fraction}");
    }

    #[test]
    fn sun_directions_stay_in_the_cone_and_reach_its_rim() {
        let alpha = 4f32.to_radians();
        let sun = SunDisc::new(Vec3::new(1.0, -2.0, 0.5), alpha);
        assert!((sun.towards - Vec3::new(-1.0, 2.0, -0.5).normalize()).length() < 1e-6);
        assert_eq!(sun.direction(0.5, 0.5), sun.towards);
        let mut widest = 0.0f32;
        for k in 0..=20 {
            for j in 0..=20 {
                let d = sun.direction(k as f32 / 20.0, j as f32 / 20.0);
                assert!((d.length() - 1.0).abs() < 1e-5);
                let angle = d.dot(sun.towards).clamp(-1.0, 1.0).acos();
                assert!(angle <= 0.5 * alpha + 1e-4, "{angle}");
                widest = widest.max(angle);
            }
        }
        assert!((widest - 0.5 * alpha).abs() < 2e-4, "{widest}");
        // Uniform in solid angle: half the samples within the cap of half the solid
        // angle, 1 − cos θ = (1 − cos θ_max) / 2.
        let half_cap = 1.0 - 0.5 * (1.0 - (0.5 * alpha).cos() as f64);
        let n = 200;
        let within = (0..n * n)
            .filter(|k| {
                let (s, t) = ((k % n) as f32 + 0.5, (k / n) as f32 + 0.5);
                let d = sun.direction(s / n as f32, t / n as f32);
                f64::from(d.dot(sun.towards)) >= half_cap
            })
            .count();
        let fraction = within as f64 / (n * n) as f64;
        assert!((fraction - 0.5).abs() < 0.02, "{fraction}");
    }
}
