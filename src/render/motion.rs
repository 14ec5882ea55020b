//! Motion (`render --orbit`): the camera's or the light's eye turns about the vertical axis
//! through the point it looks at, a fixed angle per frame; frame 1 is the scene as written.
//! A moved scene shares the base scene's meshes (`Arc`), so a frame's motion copies no
//! vertex data: the session re-plans over the same prepared geometry, and its maps go stale
//! exactly when the map passes changed (a turning light), not when only the eye moved.
//!
//! A [`Turn`] (`render --turn light:AZ,EL`) places the camera or the light once, before
//! frame 1: the eye keeps its distance from the point it looks at, its elevation above the
//! horizontal plane through that point changes by EL degrees (kept within ±[`MAX_ELEVATION`],
//! where gluLookAt's up vector stays usable), then its azimuth about +Y by AZ degrees; a
//! directional light's direction turns with it. The viewer's mouse and arrow keys move
//! things this way, so the command line it prints reproduces what it shows.

use crate::scene::{LightKind, Scene};
use crate::vocab::Named;

/// A motion: the camera's or the light's eye turns about the vertical axis through the
/// point it looks at, by `degrees_per_frame` (frame 1 is the scene as written).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    pub target: OrbitTarget,
    pub degrees_per_frame: f32,
}

impl std::str::FromStr for Orbit {
    type Err = String;

    /// `camera:DEG` or `light:DEG` (degrees per frame, finite).
    fn from_str(text: &str) -> Result<Orbit, String> {
        let bad = || format!("`{text}`: expected camera:DEGREES or light:DEGREES (e.g. light:5)");
        let (what, deg) = text.split_once(':').ok_or_else(bad)?;
        let target = OrbitTarget::from_name(what).ok_or_else(bad)?;
        let degrees_per_frame: f32 = deg.trim().parse().map_err(|_| bad())?;
        if !degrees_per_frame.is_finite() {
            return Err(bad());
        }
        Ok(Orbit {
            target,
            degrees_per_frame,
        })
    }
}

/// What an [`Orbit`] moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum OrbitTarget {
    /// The eye: the maps stay valid.
    Camera,
    /// The shadowing light (the scene's first): the maps go stale every frame.
    Light,
}

impl Named for OrbitTarget {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("camera", OrbitTarget::Camera),
        ("light", OrbitTarget::Light),
    ];
}

impl Orbit {
    /// `scene` as it stands at frame `n` (1-based): the target's eye turned by
    /// (n − 1)·degrees about +Y through its `at`; a directional light's direction turns too.
    /// The objects, and so their meshes, are shared with `scene`.
    pub fn scene_at(&self, scene: &Scene, n: u32) -> Scene {
        let turn = glam::Mat3::from_rotation_y(
            (self.degrees_per_frame * n.saturating_sub(1) as f32).to_radians(),
        );
        let mut scene = scene.clone();
        match self.target {
            OrbitTarget::Camera => {
                let c = &mut scene.camera;
                c.eye = c.at + turn * (c.eye - c.at);
            }
            OrbitTarget::Light => {
                if let Some(light) = scene.lights.first_mut() {
                    let v = &mut light.view;
                    v.eye = v.at + turn * (v.eye - v.at);
                    if let LightKind::Directional { direction, .. } = &mut light.kind {
                        *direction = turn * *direction;
                    }
                }
            }
        }
        scene
    }
}

/// The largest elevation (degrees above or below the horizontal plane through the point
/// looked at) a [`Turn`] leaves an eye at.
pub const MAX_ELEVATION: f32 = 85.0;

/// The camera or the light placed once: elevation changed by `elevation` degrees (clamped
/// to ±[`MAX_ELEVATION`]), then azimuth by `azimuth` degrees about +Y.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Turn {
    pub target: OrbitTarget,
    pub azimuth: f32,
    pub elevation: f32,
}

impl std::str::FromStr for Turn {
    type Err = String;

    /// `camera:AZ[,EL]` or `light:AZ[,EL]` (degrees, finite).
    fn from_str(text: &str) -> Result<Turn, String> {
        let bad = || {
            format!("`{text}`: expected camera:AZIMUTH[,ELEVATION] or light:AZIMUTH[,ELEVATION] in degrees (e.g. light:30,-10)")
        };
        let (what, angles) = text.split_once(':').ok_or_else(bad)?;
        let target = OrbitTarget::from_name(what).ok_or_else(bad)?;
        let (az, el) = angles.split_once(',').unwrap_or((angles, "0"));
        let number = |t: &str| {
            t.trim()
                .parse::<f32>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(bad)
        };
        Ok(Turn {
            target,
            azimuth: number(az)?,
            elevation: number(el)?,
        })
    }
}

impl std::fmt::Display for Turn {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}:{},{}",
            self.target.name(),
            self.azimuth,
            self.elevation
        )
    }
}

impl Turn {
    /// The rotation that takes the eye offset `v` (eye − at) to its turned place.
    pub fn rotation(&self, v: glam::Vec3) -> glam::Mat3 {
        let horizontal = glam::Vec3::new(v.x, 0.0, v.z);
        let now = v.y.atan2(horizontal.length()).to_degrees();
        let wanted = (now + self.elevation).clamp(-MAX_ELEVATION, MAX_ELEVATION);
        // Elevation: about the horizontal axis perpendicular to v (none for a vertical v,
        // whose azimuth is undefined: it is left where it is).
        let axis = glam::Vec3::Y.cross(v);
        let lift = if axis.length_squared() > 1e-12 {
            glam::Mat3::from_axis_angle(axis.normalize(), -(wanted - now).to_radians())
        } else {
            glam::Mat3::IDENTITY
        };
        glam::Mat3::from_rotation_y(self.azimuth.to_radians()) * lift
    }

    /// `scene` with the target turned; the objects, and so their meshes, are shared.
    pub fn apply(&self, scene: &Scene) -> Scene {
        let mut scene = scene.clone();
        if self.azimuth == 0.0 && self.elevation == 0.0 {
            return scene;
        }
        match self.target {
            OrbitTarget::Camera => {
                let c = &mut scene.camera;
                c.eye = c.at + self.rotation(c.eye - c.at) * (c.eye - c.at);
            }
            OrbitTarget::Light => {
                if let Some(light) = scene.lights.first_mut() {
                    let v = &mut light.view;
                    let turn = self.rotation(v.eye - v.at);
                    v.eye = v.at + turn * (v.eye - v.at);
                    if let LightKind::Directional { direction, .. } = &mut light.kind {
                        *direction = turn * *direction;
                    }
                }
            }
        }
        scene
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn turns_parse_print_and_keep_distance_and_elevation_limits() {
        let t: Turn = "light:30,-10".parse().unwrap();
        assert_eq!(
            (t.target, t.azimuth, t.elevation),
            (OrbitTarget::Light, 30.0, -10.0)
        );
        assert_eq!(t.to_string().parse::<Turn>(), Ok(t));
        let az: Turn = "camera:15".parse().unwrap();
        assert_eq!(az.elevation, 0.0);
        for bad in ["light", "sun:5", "camera:x", "camera:1,inf", "light:1,2,3"] {
            let e = bad.parse::<Turn>().unwrap_err();
            assert!(e.contains("AZIMUTH"), "{bad}: {e}");
        }
        let base = Scene::default_scene();
        let up: Turn = "camera:0,200".parse().unwrap();
        let moved = up.apply(&base);
        let (v0, v1) = (
            base.camera.eye - base.camera.at,
            moved.camera.eye - moved.camera.at,
        );
        assert!((v0.length() - v1.length()).abs() < 1e-3 * v0.length());
        let elevation = v1.y.atan2((v1.x * v1.x + v1.z * v1.z).sqrt()).to_degrees();
        assert!((elevation - MAX_ELEVATION).abs() < 1e-2, "{elevation}");
        // An azimuth alone is the orbit's turn.
        let orbit = Orbit {
            target: OrbitTarget::Light,
            degrees_per_frame: 40.0,
        };
        let turned = Turn {
            target: OrbitTarget::Light,
            azimuth: 40.0,
            elevation: 0.0,
        }
        .apply(&base);
        let orbited = orbit.scene_at(&base, 2);
        let d = turned.lights[0].view.eye - orbited.lights[0].view.eye;
        assert!(d.length() < 1e-4, "{d}");
        assert_eq!(
            Turn {
                azimuth: 0.0,
                ..turned_light()
            }
            .apply(&base),
            base
        );
    }

    fn turned_light() -> Turn {
        Turn {
            target: OrbitTarget::Light,
            azimuth: 0.0,
            elevation: 0.0,
        }
    }

    #[test]
    fn orbits_parse_or_say_what_is_expected() {
        let o: Orbit = "light:5".parse().unwrap();
        assert_eq!((o.target, o.degrees_per_frame), (OrbitTarget::Light, 5.0));
        for bad in ["light", "sun:5", "camera:x", "camera:inf"] {
            let e = bad.parse::<Orbit>().unwrap_err();
            assert!(e.contains("camera:DEGREES"), "{bad}: {e}");
        }
    }

    #[test]
    fn a_moved_scene_shares_the_meshes_and_moves_only_its_target() {
        let base = Scene::default_scene();
        let orbit = Orbit {
            target: OrbitTarget::Camera,
            degrees_per_frame: 90.0,
        };
        let moved = orbit.scene_at(&base, 2);
        for (a, b) in base.objects.iter().zip(&moved.objects) {
            assert!(std::sync::Arc::ptr_eq(&a.mesh, &b.mesh));
        }
        assert_eq!(moved.lights, base.lights);
        assert_ne!(moved.camera.eye, base.camera.eye);
        assert_eq!(orbit.scene_at(&base, 1), base);
    }
}
