//! The pieces the shadow techniques share: the shadowing light's view and texgen planes, the
//! light pass, the dim pass, lighting per pass, objects drawn in a pass's paint, and the
//! state reset that ends a frame. Each returns Commands; none touches GL.
//!
//! **Frames repeat.** A technique's frame ends with [`reset`], which puts back the state
//! every pass assumes at its start (GL's defaults for the depth, alpha, stencil, blend and
//! colour-mask state, and every texture unit the technique used disabled), so the next
//! frame — with or without its map passes — begins from the same state.
//!
//! **Looks.** Every eye pass exists in two looks: [`Look::Shaded`] is the picture (dim
//! pass with the shadowing light off, lit passes with it on); [`Look::Mask`] draws the same
//! geometry through the same tests with lighting off, dim in black, lit in white, over the
//! mask background — the mask the renderer decodes (`MaskSource::Colour`). The tests that
//! decide lit or shadowed (texture compare, alpha, stencil, depth EQUAL) are the same in
//! both looks, so the mask is the picture's shadow, not a second technique.
//!
//! **The light's texture matrix.** M = B · P_light · V_light with B the bias
//! `translate(½,½,½) · scale(½,½,½)`; its four rows are the eye-linear planes of S, T, R and
//! Q, set while the modelview holds the eye's view: GL multiplies a plane by the inverse
//! modelview when it is set (§2.10.4), so the generated (s, t, r, q) = M · world position —
//! Kilgard's "no need for the texture matrix". P_light is the matrix glFrustum/glOrtho build
//! from the light's volume (`ff::matrix`), the same numbers the light pass loads.

use crate::vocab::{PolygonOffset, TechniqueId};
use glam::{Mat4, Vec3, Vec4};

use crate::ff::{
    self, Capability, ClearMask, ColorMask, Command, CompareFunc, Face, LightModelParam,
    MaterialParam, TexCoord, TexGenMode, TexGenParam, TextureTarget, Viewport,
};
use crate::scene::{Light, Object, Scene};

use super::setup::{camera, light_commands, view_volume, GLOBAL_AMBIENT};
use super::{Pass, Prepared, TechniqueError, MASK_BACKGROUND};

/// Which picture a pass draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Look {
    /// The rendered image: materials and lights.
    Shaded,
    /// The shadow mask: lighting off, dim black, lit white, background [`MASK_BACKGROUND`].
    Mask,
}

/// How a pass colours the objects it draws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Paint {
    /// glMaterial from the scene (lighting on).
    Material,
    /// glColor (lighting off).
    Flat(Vec4),
    /// glColor of each object's own material colour (lighting off).
    OwnColour,
}

impl Look {
    /// The paint of a pass that draws dim (`lit` false) or lit surfaces.
    pub fn paint(self, lit: bool) -> Paint {
        match (self, lit) {
            (Look::Shaded, _) => Paint::Material,
            (Look::Mask, true) => Paint::Flat(Vec4::ONE),
            (Look::Mask, false) => Paint::Flat(Vec4::new(0.0, 0.0, 0.0, 1.0)),
        }
    }
}

/// The light whose shadows a technique draws (the scene's first light) and its view.
#[derive(Debug, Clone, PartialEq)]
pub struct ShadowLight {
    /// GL light index (0).
    pub index: u8,
    pub light: Light,
    /// glFrustum or glOrtho of the light's volume, aspect 1 (square maps).
    pub volume: Command,
    /// The matrix `volume` builds.
    pub projection: Mat4,
    /// gluLookAt of the light.
    pub view: Mat4,
    /// Near and far of the light's volume.
    pub near: f32,
    pub far: f32,
}

/// B = translate(½,½,½) · scale(½,½,½): clip space [−1, 1] to texture space [0, 1].
pub const BIAS: Mat4 = Mat4::from_cols(
    Vec4::new(0.5, 0.0, 0.0, 0.0),
    Vec4::new(0.0, 0.5, 0.0, 0.0),
    Vec4::new(0.0, 0.0, 0.5, 0.0),
    Vec4::new(0.5, 0.5, 0.5, 1.0),
);

impl ShadowLight {
    /// The scene's first light, or [`TechniqueError::NoLight`].
    pub fn of(scene: &Scene, technique: TechniqueId) -> Result<ShadowLight, TechniqueError> {
        let light = *scene
            .lights
            .first()
            .ok_or(TechniqueError::NoLight { technique })?;
        // Square maps: aspect 1. The matrix is the one GL builds from the same volume.
        let volume = view_volume(light.view.projection, 1.0);
        let (projection, near, far) = match &volume {
            Command::Frustum(v) => (ff::matrix::frustum(*v), v.near, v.far),
            Command::Ortho(v) => (ff::matrix::ortho(*v), v.near, v.far),
            _ => unreachable!("view_volume returns Frustum or Ortho"),
        };
        let projection = projection.unwrap_or(Mat4::IDENTITY);
        Ok(ShadowLight {
            index: 0,
            light,
            volume,
            projection,
            view: light.view.view(),
            near,
            far,
        })
    }

    /// M = B · P_light · V_light: world position → (s, t, r, q) of the light's map.
    pub fn texture_matrix(&self) -> Mat4 {
        BIAS * self.projection * self.view
    }

    /// Row `i` of M: the eye plane of S (0), T (1), R (2) or Q (3).
    pub fn plane(&self, i: usize) -> Vec4 {
        self.texture_matrix().row(i)
    }

    /// The plane of the eye-planar distance from the light scaled to the volume:
    /// s = (d − near) / (far − near), d = −z of the position in the light's view — 0 on the
    /// near plane, 1 on the far one, linear in between (Heidrich's linear depth).
    pub fn linear_distance_plane(&self) -> Vec4 {
        let range = self.far - self.near;
        (-self.view.row(2) - Vec4::new(0.0, 0.0, 0.0, self.near)) / range
    }

    /// The light's projection and view, the modelview left current.
    pub fn view_commands(&self) -> Vec<Command> {
        vec![
            Command::MatrixMode(ff::MatrixMode::Projection),
            Command::LoadIdentity,
            self.volume.clone(),
            Command::MatrixMode(ff::MatrixMode::Modelview),
            Command::LoadMatrix(self.view),
        ]
    }
}

/// Eye-linear texgen on the active unit: for each (coordinate, plane), the mode, the plane
/// (set now, so it is multiplied by the current inverse modelview) and the enable.
pub fn eye_linear(planes: &[(TexCoord, Vec4)]) -> Vec<Command> {
    let mut commands = Vec::with_capacity(planes.len() * 3);
    for &(coord, plane) in planes {
        commands.extend([
            Command::TexGen {
                coord,
                param: TexGenParam::Mode(TexGenMode::EyeLinear),
            },
            Command::TexGen {
                coord,
                param: TexGenParam::EyePlane(plane),
            },
            Command::Enable(Capability::TextureGen(coord)),
        ]);
    }
    commands
}

/// The objects `which` selects, each under its model matrix, in `paint`. The same
/// Push/MultMatrix/Pop sequence in every pass, so every pass computes bit-identical depths
/// and DepthFunc(EQUAL) passes match (hard case H18).
pub fn objects(
    scene: &Scene,
    prepared: &Prepared,
    which: impl Fn(&Object) -> bool,
    paint: Paint,
) -> Vec<Command> {
    let mut commands = Vec::new();
    for (object, geometry) in scene.objects.iter().zip(&prepared.objects) {
        if !which(object) {
            continue;
        }
        commands.push(Command::PushMatrix);
        commands.push(Command::MultMatrix(object.transform.matrix()));
        match paint {
            Paint::Material => {
                let m = &object.material;
                let material = |param| Command::Material {
                    face: Face::FrontAndBack,
                    param,
                };
                commands.extend([
                    material(MaterialParam::AmbientAndDiffuse(m.colour.extend(1.0))),
                    material(MaterialParam::Specular(m.specular.extend(1.0))),
                    material(MaterialParam::Shininess(m.shininess)),
                ]);
            }
            Paint::Flat(c) => commands.push(Command::Color(c)),
            Paint::OwnColour => commands.push(Command::Color(object.material.colour.extend(1.0))),
        }
        commands.push(Command::Draw(geometry.clone()));
        commands.push(Command::PopMatrix);
    }
    commands
}

/// Which lights a pass turns on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LightSet {
    /// Every light but the shadowing one, and the global ambient: the shadowed look.
    Dim,
    /// Every light and the global ambient: the lit look of `none`.
    All,
    /// The shadowing light alone, no global ambient: what an additive pass adds to Dim.
    ShadowingOnly,
}

/// Lighting for a pass in `look`: in the mask look lighting is off (paint is flat).
/// Lights are specified with the modelview holding the eye's view (call after the camera).
pub fn lighting(scene: &Scene, look: Look, set: LightSet) -> Vec<Command> {
    if look == Look::Mask || scene.lights.is_empty() {
        return vec![Command::Disable(Capability::Lighting)];
    }
    let ambient = match set {
        LightSet::ShadowingOnly => 0.0,
        LightSet::Dim | LightSet::All => GLOBAL_AMBIENT,
    };
    let mut commands = vec![
        Command::Enable(Capability::Lighting),
        Command::LightModel(LightModelParam::Ambient(Vec3::splat(ambient).extend(1.0))),
    ];
    for (i, light) in scene.lights.iter().enumerate() {
        let i = i as u8;
        let on = match set {
            LightSet::Dim => i != 0,
            LightSet::All => true,
            LightSet::ShadowingOnly => i == 0,
        };
        if on {
            commands.extend(light_commands(i, light));
        } else {
            commands.push(Command::Disable(Capability::Light(i)));
        }
    }
    commands
}

/// Viewport of the image, clear (colour to the background or the mask background, depth,
/// and stencil when the technique uses it), depth test on, NORMALIZE when a transform
/// scales, and the eye's camera.
pub fn eye_start(scene: &Scene, look: Look, stencil: bool) -> Vec<Command> {
    let (w, h) = (scene.image.width, scene.image.height);
    let clear = match look {
        Look::Shaded => scene.image.background.extend(1.0),
        Look::Mask => Vec4::from_array(MASK_BACKGROUND.map(|b| f32::from(b) / 255.0)),
    };
    let mut commands = vec![
        Command::Viewport(Viewport {
            x: 0,
            y: 0,
            width: w as i32,
            height: h as i32,
        }),
        Command::ClearColor(clear),
        Command::Clear(ClearMask {
            color: true,
            depth: true,
            stencil,
            accum: false,
        }),
        Command::Enable(Capability::DepthTest),
    ];
    if scene.objects.iter().any(|o| o.transform.scale != Vec3::ONE) {
        commands.push(Command::Enable(Capability::Normalize));
    }
    commands.extend(camera(&scene.camera, w, h));
    commands
}

/// The first eye pass of every shadow technique: everything drawn as if shadowed (the
/// shadowing light off; black in the mask look), with the depth test writing the depths
/// the later DepthFunc(EQUAL) passes match.
pub fn dim_pass(scene: &Scene, prepared: &Prepared, look: Look, stencil: bool) -> Pass {
    let mut commands = eye_start(scene, look, stencil);
    commands.extend(lighting(scene, look, LightSet::Dim));
    commands.extend(objects(scene, prepared, |_| true, look.paint(false)));
    Pass {
        name: "dim",
        commands,
    }
}

/// The light pass: the casters from the light into the lower-left `size`² of the
/// framebuffer, depth only (colour masked off unless `colour`), lighting off, with
/// glPolygonOffset(factor, units) on filled polygons when the scene asks for it — the bias
/// lives in the map's depth values, where Kilgard puts it.
pub fn light_pass(
    scene: &Scene,
    prepared: &Prepared,
    light: &ShadowLight,
    size: u32,
    offset: Option<PolygonOffset>,
    colour: bool,
) -> Pass {
    let mut commands = map_pass_start(size, colour);
    commands.extend(light.view_commands());
    if let Some(o) = offset {
        commands.extend([
            Command::Enable(Capability::PolygonOffsetFill),
            Command::PolygonOffset {
                factor: o.factor,
                units: o.units,
            },
        ]);
    }
    commands.extend(objects(
        scene,
        prepared,
        |o| o.casts,
        Paint::Flat(Vec4::ONE),
    ));
    if offset.is_some() {
        commands.push(Command::Disable(Capability::PolygonOffsetFill));
    }
    if !colour {
        commands.push(Command::ColorMask(ColorMask::ALL));
    }
    Pass {
        name: "light",
        commands,
    }
}

/// The dim pass, then the shadowing light *added* (glBlendFunc(ONE, ONE), DepthFunc(EQUAL))
/// on receivers through the map bound as [`super::map::MAP_TEXTURE`] on unit 0, projected
/// by eye-linear S, T, R, Q = `planes` and applied with MODULATE: where the texel is 1 the
/// light's contribution is added in full, where it is 0 nothing is — the picture of `none`
/// in lit places, the ambient in shadow. Non-receivers get the light without the texture.
pub fn dim_then_added_light(
    scene: &Scene,
    prepared: &Prepared,
    planes: [Vec4; 4],
    look: Look,
) -> Vec<Pass> {
    dim_then_added_light_per_receiver(scene, prepared, planes, look, &|_| super::map::MAP_TEXTURE)
}

/// [`dim_then_added_light`] with each receiver (by object index) projected through its own
/// texture name: `texture_of(i)` is bound before receiver i is drawn.
pub fn dim_then_added_light_per_receiver(
    scene: &Scene,
    prepared: &Prepared,
    planes: [Vec4; 4],
    look: Look,
    texture_of: &dyn Fn(usize) -> u32,
) -> Vec<Pass> {
    let mut lit = vec![
        Command::DepthFunc(CompareFunc::Equal),
        Command::DepthMask(false),
        Command::Enable(Capability::Blend),
        Command::BlendFunc {
            src: ff::BlendFactor::One,
            dst: ff::BlendFactor::One,
        },
    ];
    lit.extend(lighting(scene, look, LightSet::ShadowingOnly));
    lit.extend([
        Command::ActiveTexture(0),
        Command::Enable(Capability::Texture2D),
        Command::TexEnv(ff::TexEnvParam::Mode(ff::TexEnvMode::Modulate)),
    ]);
    lit.extend(eye_linear(&[
        (TexCoord::S, planes[0]),
        (TexCoord::T, planes[1]),
        (TexCoord::R, planes[2]),
        (TexCoord::Q, planes[3]),
    ]));
    let paint = look.paint(true);
    // Receivers grouped by texture, in the order of their first receiver: one bind each.
    let mut names: Vec<u32> = Vec::new();
    for (i, o) in scene.objects.iter().enumerate() {
        if o.receives && !names.contains(&texture_of(i)) {
            names.push(texture_of(i));
        }
    }
    for name in names {
        lit.push(Command::BindTexture {
            target: TextureTarget::Texture2D,
            name,
        });
        let index = |o: &Object| scene.objects.iter().position(|p| std::ptr::eq(p, o));
        lit.extend(objects(
            scene,
            prepared,
            |o| o.receives && index(o).is_some_and(|i| texture_of(i) == name),
            paint,
        ));
    }
    lit.push(Command::Disable(Capability::Texture2D));
    lit.extend(objects(scene, prepared, does_not_receive, paint));
    lit.extend(reset(&[0]));
    vec![
        dim_pass(scene, prepared, look, false),
        Pass {
            name: "lit",
            commands: lit,
        },
    ]
}

/// The start of every pass that draws into the map's `size`² corner: that viewport,
/// lighting off, the depth test on, and the clear — depth only with colour writes off, or
/// colour (to white, the far distance and the unshadowed texel) and depth with every
/// channel written.
pub fn map_pass_start(size: u32, colour: bool) -> Vec<Command> {
    let mut commands = vec![
        Command::Viewport(Viewport {
            x: 0,
            y: 0,
            width: size as i32,
            height: size as i32,
        }),
        Command::Disable(Capability::Lighting),
        Command::Enable(Capability::DepthTest),
    ];
    if colour {
        commands.extend([
            Command::ColorMask(ColorMask::ALL),
            Command::ClearColor(Vec4::ONE),
        ]);
    } else {
        commands.push(Command::ColorMask(ColorMask::NONE));
    }
    commands.push(Command::Clear(ClearMask {
        color: colour,
        depth: true,
        stencil: false,
        accum: false,
    }));
    commands
}

/// Back to the state every pass assumes at its start: depth LESS with writes, no alpha,
/// stencil, blend or combiners, all colour channels, and `units` with texturing and
/// texgen off (unit 0 left active).
pub fn reset(units: &[u8]) -> Vec<Command> {
    let mut commands = vec![
        Command::DepthFunc(CompareFunc::Less),
        Command::DepthMask(true),
        Command::Disable(Capability::AlphaTest),
        Command::Disable(Capability::StencilTest),
        Command::Disable(Capability::Blend),
        Command::Disable(Capability::RegisterCombiners),
        Command::ColorMask(ColorMask::ALL),
    ];
    for &unit in units {
        commands.push(Command::ActiveTexture(unit));
        commands.extend(texturing_off());
    }
    commands.push(Command::ActiveTexture(0));
    commands
}

/// The active unit's 1D and 2D texturing and its four texgen coordinates disabled.
pub fn texturing_off() -> Vec<Command> {
    let mut commands = vec![
        Command::Disable(Capability::Texture1D),
        Command::Disable(Capability::Texture2D),
    ];
    commands.extend(
        TexCoord::ALL
            .iter()
            .map(|&c| Command::Disable(Capability::TextureGen(c))),
    );
    commands
}

/// Whether an object takes the shadow test (receivers) — others are drawn lit.
pub fn receives(o: &Object) -> bool {
    o.receives
}

/// The complement of [`receives`].
pub fn does_not_receive(o: &Object) -> bool {
    !o.receives
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_texture_matrix_maps_the_light_volume_into_the_unit_cube() {
        let scene = Scene::default_scene();
        let light = ShadowLight::of(&scene, TechniqueId::None).unwrap();
        let m = light.texture_matrix();
        // The point the light looks at, on its axis: s = t = ½.
        let at = m * light.light.view.at.extend(1.0);
        assert!((at.x / at.w - 0.5).abs() < 1e-5 && (at.y / at.w - 0.5).abs() < 1e-5);
        // A point on the near plane has r/q = 0, on the far plane r/q = 1.
        let eye = light.light.view.eye;
        let dir = (light.light.view.at - eye).normalize();
        for (d, r) in [(light.near, 0.0), (light.far, 1.0)] {
            let p = m * (eye + d * dir).extend(1.0);
            assert!((p.z / p.w - r).abs() < 1e-4, "r/q at {d}: {}", p.z / p.w);
            // The linear plane agrees at both ends.
            let s = light
                .linear_distance_plane()
                .dot((eye + d * dir).extend(1.0));
            assert!((s - r).abs() < 1e-5, "linear s at {d}: {s}");
        }
    }

    #[test]
    fn no_light_is_a_clear_error() {
        let mut scene = Scene::default_scene();
        scene.lights.clear();
        let err = ShadowLight::of(&scene, TechniqueId::Dual8).unwrap_err();
        assert!(err.to_string().contains("needs a light"), "{err}");
    }
}
