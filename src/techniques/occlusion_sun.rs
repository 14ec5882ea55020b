//! `occlusion-textures` under a sun: Eisemann & Décoret's §3.5 variant, "sunlight-like
//! shadows (see Figure 8). We suppose that the source is at infinity and consider a
//! constant frustum from each scene point. To capture the spherical shape we use a
//! Gaussian instead of a box-filter."
//!
//! ```text
//! maps   slices:  as for a rectangle, through an orthographic slicing view along the sun
//!        filter:  per RGBA texture k, per level l ≥ 1: two program passes (eisemann/gauss)
//!                 level l − 1 → the row pass into GAUSS_TEMP_TEXTURE → level l
//! frame  as for a rectangle; eisemann/visibility compiled with SUN 1
//! ```
//!
//! **The slicing view.** The frame's z runs along the sun's light (its `direction`), x and
//! y across it; z = 0 is the casters' nearest bounding-box depth, so every caster lies in
//! z ∈ [0, far], cut into uniform slices. The window is the square (the occlusion texture's
//! texels stay square, so one Gaussian width serves both axes) around the casters' corners
//! projected along z. Rays towards the sun's centre are parallel: P's slice look-ups are all
//! at P's own (x, y).
//!
//! **The kernel.** Seen from P, the sun is the cone of half-angle θ = α/2 around −z; at a
//! slice plane Δz = z_P − z_s closer to the sun the cone is a disc of radius
//! R = Δz · tan θ (the paper's "constant frustum"). A uniform disc of radius R has
//! standard deviation R/2 along each axis; that Gaussian is read from a Gaussian pyramid.
//!
//! **The Gaussian pyramid** (Burt & Adelson 1983) lives in the occlusion texture's mipmap
//! levels: level l is level l − 1 convolved with the binomial kernel
//! [1 5 10 10 5 1]/32 along each axis (variance 5/4 texel² of that level) and decimated by
//! two, its taps centred on the two level-(l − 1) texels under a level-l texel. The
//! variances add up to σ_l² = 5/4 · (4^l − 1)/3 ≈ (0.645 · 2^l)² level-0 texels², so a
//! deviation σ = R/2 is read at lod = log2(σ / 0.645) = log2(0.775 · R) (R in texels),
//! trilinearly between levels (visibility.frag with SUN 1). Levels hold 8 bits, as the rest of the
//! occlusion texture; taps beyond the texture read 0 (no occluder outside the window).

use glam::{Mat4, Vec2, Vec3, Vec4};

use crate::ff::framebuffer::{AttachmentPoint, FramebufferTarget};
use crate::ff::{
    Command, Filter, PixelFormat, PixelType, TexData, TexFormat, TexImage, TexParam, TextureTarget,
    UniformValue, Viewport, Wrap,
};
use crate::scene::{Scene, SunDisc};

use super::occlusion_textures::{
    caster_corners, prefilter_pass, uniform, window_quad, OcclusionSettings, SliceView,
    OCCLUSION_TEXTURE_BASE,
};
use super::Pass;

/// The texture the Gaussian pyramid's row passes write (RGBA8, the map's size).
pub const GAUSS_TEMP_TEXTURE: u32 = 130;

/// The edge of mipmap level l of a texture `size` texels wide: max(1, ⌊size / 2^l⌋).
pub fn level_size(size: u32, level: u32) -> u32 {
    (size >> level.min(31)).max(1)
}

/// The orthographic slicing view along the sun (see the module note).
pub fn sun_view(scene: &Scene, sun: &SunDisc, slices: u32) -> SliceView {
    let z = -sun.towards;
    let (x, y) = z.any_orthonormal_pair();
    let corners = caster_corners(scene);
    let along = |axis: Vec3, f: fn(f32, f32) -> f32, start: f32| {
        corners.iter().map(|&c| axis.dot(c)).fold(start, f)
    };
    let (near, far) = (
        along(z, f32::min, f32::INFINITY),
        along(z, f32::max, f32::NEG_INFINITY),
    );
    let (near, far) = if near.is_finite() && far > near {
        (near, far)
    } else {
        (0.0, 1.0)
    };
    let centre = Vec2::new(
        0.5 * (along(x, f32::min, f32::INFINITY) + along(x, f32::max, f32::NEG_INFINITY)),
        0.5 * (along(y, f32::min, f32::INFINITY) + along(y, f32::max, f32::NEG_INFINITY)),
    );
    let centre = if centre.is_finite() {
        centre
    } else {
        Vec2::ZERO
    };
    let half = corners
        .iter()
        .map(|&c| {
            let p = Vec2::new(x.dot(c), y.dot(c)) - centre;
            p.x.abs().max(p.y.abs())
        })
        .fold(1e-3f32, f32::max);
    // Rows x, y, z; the translation puts the window's centre on the axis and the nearest
    // caster at z = 0.
    let frame = Mat4::from_cols(
        Vec4::new(x.x, y.x, z.x, 0.0),
        Vec4::new(x.y, y.y, z.y, 0.0),
        Vec4::new(x.z, y.z, z.z, 0.0),
        Vec4::new(-centre.x, -centre.y, -near, 1.0),
    );
    SliceView {
        frame,
        light_half: Vec2::ZERO,
        half_window: Vec2::splat(half),
        cop: 0.0,
        near: 0.0,
        slice_depth: (far - near) / slices as f32,
        sun_tan: Some(sun.half_angle().tan()),
    }
}

/// Mipmap levels 1 … of occlusion texture k, allocated (RGBA8, no data) for the pyramid,
/// and the row passes' texture.
pub fn gauss_setup(k: u32, settings: &OcclusionSettings) -> Vec<Command> {
    let image = |level: u32, width: u32, height: u32| {
        Command::TexImage(TexImage {
            target: TextureTarget::Texture2D,
            level: level as i32,
            internal_format: TexFormat::Rgba8,
            requested: None,
            width: width as i32,
            height: height as i32,
            depth: 1,
            border: 0,
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            data: TexData::Null,
        })
    };
    let mut commands = vec![Command::BindTexture {
        target: TextureTarget::Texture2D,
        name: OCCLUSION_TEXTURE_BASE + k,
    }];
    for l in 1..settings.levels() {
        let edge = level_size(settings.size, l);
        commands.push(image(l, edge, edge));
    }
    if k == 0 {
        let param = |param| Command::TexParameter {
            target: TextureTarget::Texture2D,
            param,
        };
        commands.extend([
            Command::BindTexture {
                target: TextureTarget::Texture2D,
                name: GAUSS_TEMP_TEXTURE,
            },
            image(0, settings.size, settings.size),
            param(TexParam::MinFilter(Filter::Nearest)),
            param(TexParam::MagFilter(Filter::Nearest)),
            param(TexParam::WrapS(Wrap::ClampToEdge)),
            param(TexParam::WrapT(Wrap::ClampToEdge)),
        ]);
    }
    commands
}

/// The Gaussian pyramid of every occlusion texture (see the module note): for level l,
/// the row pass reads level l − 1 and writes ⌊w / 2⌋ × h texels of the row texture, the
/// column pass reads those and writes level l. The texture a pass writes is never the one
/// its program samples (unit 0).
pub fn gauss_pass(settings: &OcclusionSettings) -> Pass {
    let quad = window_quad();
    let mut commands = Vec::new();
    for k in 0..settings.textures() {
        let texture = OCCLUSION_TEXTURE_BASE + k;
        for l in 1..settings.levels() {
            let (above, here) = (
                level_size(settings.size, l - 1) as i32,
                level_size(settings.size, l) as i32,
            );
            // (written texture, its level, read texture, its level, viewport w × h, axis)
            let steps = [
                (GAUSS_TEMP_TEXTURE, 0, texture, l - 1, (here, above), (1, 0)),
                (texture, l, GAUSS_TEMP_TEXTURE, 0, (here, here), (0, 1)),
            ];
            for (target, level, source, source_level, (w, h), (ax, ay)) in steps {
                let source_size = if source == GAUSS_TEMP_TEXTURE {
                    (here, above)
                } else {
                    (above, above)
                };
                commands.extend([
                    Command::FramebufferTexture {
                        target: FramebufferTarget::Both,
                        attachment: AttachmentPoint::Color(0),
                        texture: Some((TextureTarget::Texture2D, target)),
                        level: level as i32,
                        layer: 0,
                    },
                    Command::BindTexture {
                        target: TextureTarget::Texture2D,
                        name: source,
                    },
                    Command::Viewport(Viewport {
                        x: 0,
                        y: 0,
                        width: w,
                        height: h,
                    }),
                    uniform("source_level", UniformValue::Int(source_level as i32)),
                    uniform("source_width", UniformValue::Int(source_size.0)),
                    uniform("source_height", UniformValue::Int(source_size.1)),
                    uniform("axis_x", UniformValue::Int(ax)),
                    uniform("axis_y", UniformValue::Int(ay)),
                    Command::Draw(quad.clone()),
                ]);
            }
        }
    }
    prefilter_pass("eisemann/gauss", commands)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Light, LightKind};

    fn sun_scene(degrees: f32) -> (Scene, SunDisc) {
        let mut scene = Scene::default_scene();
        let direction = Vec3::new(0.3, -1.0, 0.2);
        scene.lights[0].kind = LightKind::Directional {
            direction,
            angular_diameter: degrees.to_radians(),
        };
        let sun = Light::sun(&scene.lights[0]).expect("a sun");
        (scene, sun)
    }

    #[test]
    fn the_sun_view_puts_every_caster_in_the_window_and_the_slices() {
        let (scene, sun) = sun_scene(3.0);
        let view = sun_view(&scene, &sun, 8);
        assert_eq!(view.half_window.x, view.half_window.y);
        let far = view.near + 8.0 * view.slice_depth;
        for o in scene.objects.iter().filter(|o| o.casts) {
            for p in o.world_mesh().positions {
                let q = view.frame.transform_point3(p);
                assert!(q.z >= -1e-3 && q.z <= far + 1e-3, "{q}");
                assert!(q.x.abs().max(q.y.abs()) <= view.half_window.x + 1e-3, "{q}");
            }
        }
        // z runs along the light: a point further along `direction` is deeper.
        let a = view.frame.transform_point3(Vec3::ZERO);
        let b = view.frame.transform_point3(-sun.towards);
        assert!((b.z - a.z - 1.0).abs() < 1e-5);
        assert!((b.truncate() - a.truncate()).length() < 1e-5);
        let tan = view.sun_tan.expect("a sun view");
        assert!((tan - 1.5f32.to_radians().tan()).abs() < 1e-7);
    }

    #[test]
    fn levels_halve_down_to_one_texel() {
        assert_eq!(level_size(256, 0), 256);
        assert_eq!(level_size(256, 3), 32);
        assert_eq!(level_size(300, 1), 150);
        assert_eq!(level_size(300, 8), 1);
        assert_eq!(level_size(4, 40), 1);
    }
}
