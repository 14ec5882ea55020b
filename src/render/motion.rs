//! Motion (`render --orbit`): the camera's or the light's eye turns about the vertical axis
//! through the point it looks at, a fixed angle per frame; frame 1 is the scene as written.
//! A moved scene shares the base scene's meshes (`Arc`), so a frame's motion copies no
//! vertex data: the session re-plans over the same prepared geometry, and its maps go stale
//! exactly when the map passes changed (a turning light), not when only the eye moved.

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
                    if let LightKind::Directional { direction } = &mut light.kind {
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
