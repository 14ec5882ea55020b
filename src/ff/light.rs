//! Lighting state (GL 1.5 §2.14): eight lights, the light model, front and back materials,
//! colour material.
//!
//! Light positions are stored in eye coordinates: multiplied by the modelview current when
//! glLight(POSITION) is called; spot directions by its upper-left 3×3 (§2.14.1). Later
//! modelview changes do not move a light.

use glam::{Mat4, Vec3, Vec4};

use super::error::{GlError, GlResult};
use super::fragment::Face;
use super::geometry::{MaterialColor, MaterialSide, MaterialSlot};

/// GL_MAX_LIGHTS.
pub const MAX_LIGHTS: usize = 8;

/// One glLight parameter with its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LightParam {
    Ambient(Vec4),
    Diffuse(Vec4),
    Specular(Vec4),
    /// Object coordinates; w = 0 is a directional light.
    Position(Vec4),
    /// Object coordinates.
    SpotDirection(Vec3),
    /// [0, 128], else INVALID_VALUE.
    SpotExponent(f32),
    /// [0, 90] or 180, else INVALID_VALUE.
    SpotCutoff(f32),
    /// ≥ 0, else INVALID_VALUE (all three attenuations).
    ConstantAttenuation(f32),
    LinearAttenuation(f32),
    QuadraticAttenuation(f32),
}

/// One light source. Defaults per GL 1.5 Table 6.10.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Light {
    /// GL default: (0, 0, 0, 1).
    pub ambient: Vec4,
    /// GL default: (1, 1, 1, 1) for light 0, (0, 0, 0, 1) for the others.
    pub diffuse: Vec4,
    /// GL default: (1, 1, 1, 1) for light 0, (0, 0, 0, 1) for the others.
    pub specular: Vec4,
    /// Eye coordinates. GL default: (0, 0, 1, 0), a directional light along −z.
    pub position: Vec4,
    /// Eye coordinates. GL default: (0, 0, −1).
    pub spot_direction: Vec3,
    /// GL default: 0.
    pub spot_exponent: f32,
    /// Degrees; 180 means no spot. GL default: 180.
    pub spot_cutoff: f32,
    /// Attenuation 1/(k0 + k1·d + k2·d²). GL default: k0 = 1, k1 = 0, k2 = 0.
    pub constant_attenuation: f32,
    pub linear_attenuation: f32,
    pub quadratic_attenuation: f32,
}

impl Light {
    /// The GL default for light `index`.
    pub fn default_for(index: usize) -> Self {
        let bright = if index == 0 { Vec4::ONE } else { Vec4::W };
        Self {
            ambient: Vec4::W,
            diffuse: bright,
            specular: bright,
            position: Vec4::Z,
            spot_direction: Vec3::NEG_Z,
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            constant_attenuation: 1.0,
            linear_attenuation: 0.0,
            quadratic_attenuation: 0.0,
        }
    }

    /// cos(cutoff) as Mesa keeps it (`_CosCutoff`): `cosf` of the angle converted to
    /// radians in double precision, raised to 0 when below it (a cutoff of 90° gives 0,
    /// where the single-precision cosine gives −4.4·10⁻⁸); a NaN cutoff keeps a NaN cosine,
    /// which no spot factor passes on the vertex path (measured, `tests/c/float_params.c`).
    pub fn cos_cutoff(&self) -> f32 {
        let cos = ((f64::from(self.spot_cutoff) * std::f64::consts::PI / 180.0) as f32).cos();
        if cos < 0.0 {
            0.0
        } else {
            cos
        }
    }

    /// Sets one parameter; positions and directions go to eye space through `modelview`.
    pub fn set(&mut self, param: LightParam, modelview: Mat4) -> GlResult {
        match param {
            LightParam::Ambient(c) => self.ambient = c,
            LightParam::Diffuse(c) => self.diffuse = c,
            LightParam::Specular(c) => self.specular = c,
            // P_eye = M·P (§2.14.1).
            LightParam::Position(p) => self.position = modelview * p,
            // d_eye = M₃ₓ₃·d: the direction is transformed as a vector (w = 0).
            LightParam::SpotDirection(d) => {
                self.spot_direction = (modelview * d.extend(0.0)).truncate()
            }
            LightParam::SpotExponent(e) => {
                if outside(e, 0.0, 128.0) {
                    return Err(GlError::invalid_value("SPOT_EXPONENT must be in [0, 128]"));
                }
                self.spot_exponent = e;
            }
            LightParam::SpotCutoff(c) => {
                if outside(c, 0.0, 90.0) && c != 180.0 {
                    return Err(GlError::invalid_value(
                        "SPOT_CUTOFF must be in [0, 90] or 180",
                    ));
                }
                self.spot_cutoff = c;
            }
            LightParam::ConstantAttenuation(k) => self.constant_attenuation = non_negative(k)?,
            LightParam::LinearAttenuation(k) => self.linear_attenuation = non_negative(k)?,
            LightParam::QuadraticAttenuation(k) => self.quadratic_attenuation = non_negative(k)?,
        }
        Ok(())
    }
}

fn non_negative(k: f32) -> GlResult<f32> {
    if k < 0.0 {
        Err(GlError::invalid_value("attenuation factors must be ≥ 0"))
    } else {
        Ok(k)
    }
}

/// Whether `v` lies outside [lo, hi] as Mesa 22.3 tests a light or material parameter
/// (`v < lo || v > hi`): a NaN is not outside, so it is kept without an error, and reads
/// back NaN (measured: SPOT_EXPONENT, SPOT_CUTOFF, the attenuations and SHININESS;
/// `tests/c/float_params.c`). ±∞ beyond the range are refused.
pub fn outside(v: f32, lo: f32, hi: f32) -> bool {
    v < lo || v > hi
}

/// Whether glMaterial refuses a shininess (INVALID_VALUE): outside [0, 128] as
/// [`outside`] tests it, wherever the call is made (alone, inside glBegin/glEnd, in a list).
pub fn shininess_refused(s: f32) -> bool {
    outside(s, 0.0, 128.0)
}

/// LIGHT_MODEL_COLOR_CONTROL (GL 1.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ColorControl {
    SingleColor,
    SeparateSpecularColor,
}

/// One glLightModel parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LightModelParam {
    Ambient(Vec4),
    LocalViewer(bool),
    TwoSide(bool),
    ColorControl(ColorControl),
}

/// glLightModel state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LightModel {
    /// GL default: (0.2, 0.2, 0.2, 1).
    pub ambient: Vec4,
    /// GL default: FALSE (the viewer at (0, 0, ∞) for specular).
    pub local_viewer: bool,
    /// GL default: FALSE.
    pub two_side: bool,
    /// GL default: SINGLE_COLOR.
    pub color_control: ColorControl,
}

impl LightModel {
    pub const DEFAULT: Self = Self {
        ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
        local_viewer: false,
        two_side: false,
        color_control: ColorControl::SingleColor,
    };

    pub fn set(&mut self, param: LightModelParam) {
        match param {
            LightModelParam::Ambient(c) => self.ambient = c,
            LightModelParam::LocalViewer(b) => self.local_viewer = b,
            LightModelParam::TwoSide(b) => self.two_side = b,
            LightModelParam::ColorControl(c) => self.color_control = c,
        }
    }
}

/// One glMaterial parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MaterialParam {
    Ambient(Vec4),
    Diffuse(Vec4),
    AmbientAndDiffuse(Vec4),
    Specular(Vec4),
    Emission(Vec4),
    /// [0, 128], else INVALID_VALUE.
    Shininess(f32),
    /// COLOR_INDEXES (a, d, s): the ambient, diffuse and specular indices of colour-index
    /// lighting (GL 1.5 §2.14.5). Kept and answered as Mesa keeps them in an RGBA
    /// context; no RGBA lighting reads them.
    ColorIndexes(Vec3),
}

/// One face's material. Defaults per GL 1.5 Table 6.9.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// GL default: (0.2, 0.2, 0.2, 1).
    pub ambient: Vec4,
    /// GL default: (0.8, 0.8, 0.8, 1).
    pub diffuse: Vec4,
    /// GL default: (0, 0, 0, 1).
    pub specular: Vec4,
    /// GL default: (0, 0, 0, 1).
    pub emission: Vec4,
    /// GL default: 0.
    pub shininess: f32,
    /// COLOR_INDEXES. GL default: (0, 1, 1).
    pub color_indexes: Vec3,
}

impl Material {
    pub const DEFAULT: Self = Self {
        ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
        diffuse: Vec4::new(0.8, 0.8, 0.8, 1.0),
        specular: Vec4::W,
        emission: Vec4::W,
        shininess: 0.0,
        color_indexes: Vec3::new(0.0, 1.0, 1.0),
    };

    /// The specular exponent a vertex is lit with: the shininess, a NaN one as 128. Mesa's
    /// vertex program takes the exponent through LIT, which clamps it to [−128, 128] with a
    /// min and max that drop a NaN (measured: a NaN shininess lights as 128 would,
    /// `tests/c/float_params.c`). The raster position, lit on the CPU, keeps the NaN.
    pub fn lit_exponent(&self) -> f32 {
        if self.shininess.is_nan() {
            128.0
        } else {
            self.shininess
        }
    }

    fn set(&mut self, param: MaterialParam) {
        match param {
            MaterialParam::Ambient(c) => self.ambient = c,
            MaterialParam::Diffuse(c) => self.diffuse = c,
            MaterialParam::AmbientAndDiffuse(c) => {
                self.ambient = c;
                self.diffuse = c;
            }
            MaterialParam::Specular(c) => self.specular = c,
            MaterialParam::Emission(c) => self.emission = c,
            MaterialParam::Shininess(s) => self.shininess = s,
            MaterialParam::ColorIndexes(i) => self.color_indexes = i,
        }
    }
}

/// Front and back materials.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Materials {
    pub front: Material,
    pub back: Material,
}

impl Materials {
    pub const DEFAULT: Self = Self {
        front: Material::DEFAULT,
        back: Material::DEFAULT,
    };

    /// glMaterial: validates, then sets the face(s).
    pub fn set(&mut self, face: Face, param: MaterialParam) -> GlResult {
        if let MaterialParam::Shininess(s) = param {
            if shininess_refused(s) {
                return Err(GlError::invalid_value("SHININESS must be in [0, 128]"));
            }
        }
        if matches!(face, Face::Front | Face::FrontAndBack) {
            self.front.set(param);
        }
        if matches!(face, Face::Back | Face::FrontAndBack) {
            self.back.set(param);
        }
        Ok(())
    }

    /// glMaterial while COLOR_MATERIAL is enabled with `tracking`: the colours it tracks
    /// keep the current colour (GL 1.5 §2.14.3: they "always have the value of the current
    /// color"), so only the others are set — Mesa's `_mesa_Materialfv` masks them out the
    /// same way, per face, and glGetMaterial answers the tracked colour.
    pub fn set_untracked(
        &mut self,
        face: Face,
        param: MaterialParam,
        tracking: ColorMaterial,
    ) -> GlResult {
        let before = *self;
        self.set(face, param)?;
        for slot in MaterialSlot::ALL
            .into_iter()
            .filter(|s| tracking.tracks(*s))
        {
            self.copy_slot(slot, &before);
        }
        Ok(())
    }

    /// Puts `slot` back to its value in `from`.
    fn copy_slot(&mut self, slot: MaterialSlot, from: &Materials) {
        let (to, from) = match slot {
            MaterialSlot::Color(MaterialSide::Front, _)
            | MaterialSlot::Shininess(MaterialSide::Front) => (&mut self.front, &from.front),
            MaterialSlot::Color(MaterialSide::Back, _)
            | MaterialSlot::Shininess(MaterialSide::Back) => (&mut self.back, &from.back),
        };
        match slot {
            MaterialSlot::Color(_, MaterialColor::Ambient) => to.ambient = from.ambient,
            MaterialSlot::Color(_, MaterialColor::Diffuse) => to.diffuse = from.diffuse,
            MaterialSlot::Color(_, MaterialColor::Specular) => to.specular = from.specular,
            MaterialSlot::Color(_, MaterialColor::Emission) => to.emission = from.emission,
            MaterialSlot::Shininess(_) => to.shininess = from.shininess,
        }
    }
}

impl Materials {
    /// The value of a material slot, as a per-vertex array holds it (shininess as
    /// (s, 0, 0, 1)).
    pub fn value(&self, slot: MaterialSlot) -> Vec4 {
        let face = |s: MaterialSide| match s {
            MaterialSide::Front => &self.front,
            MaterialSide::Back => &self.back,
        };
        match slot {
            MaterialSlot::Color(s, MaterialColor::Ambient) => face(s).ambient,
            MaterialSlot::Color(s, MaterialColor::Diffuse) => face(s).diffuse,
            MaterialSlot::Color(s, MaterialColor::Specular) => face(s).specular,
            MaterialSlot::Color(s, MaterialColor::Emission) => face(s).emission,
            MaterialSlot::Shininess(s) => Vec4::new(face(s).shininess, 0.0, 0.0, 1.0),
        }
    }
}

impl MaterialSlot {
    /// Whether glMaterial(face, param) sets this slot (FRONT_AND_BACK both sides,
    /// AMBIENT_AND_DIFFUSE both colours).
    pub fn set_by(self, face: Face, param: MaterialParam) -> bool {
        let side = match self {
            MaterialSlot::Color(s, _) | MaterialSlot::Shininess(s) => s,
        };
        let on_side = match face {
            Face::Front => side == MaterialSide::Front,
            Face::Back => side == MaterialSide::Back,
            Face::FrontAndBack => true,
        };
        on_side
            && matches!(
                (self, param),
                (
                    MaterialSlot::Color(_, MaterialColor::Ambient),
                    MaterialParam::Ambient(_)
                ) | (
                    MaterialSlot::Color(_, MaterialColor::Diffuse),
                    MaterialParam::Diffuse(_)
                ) | (
                    MaterialSlot::Color(_, MaterialColor::Ambient | MaterialColor::Diffuse),
                    MaterialParam::AmbientAndDiffuse(_)
                ) | (
                    MaterialSlot::Color(_, MaterialColor::Specular),
                    MaterialParam::Specular(_)
                ) | (
                    MaterialSlot::Color(_, MaterialColor::Emission),
                    MaterialParam::Emission(_)
                ) | (MaterialSlot::Shininess(_), MaterialParam::Shininess(_))
            )
    }

    /// The glMaterial face and parameter names that set this slot alone.
    pub fn names(self) -> (&'static str, &'static str) {
        let face = |s: MaterialSide| match s {
            MaterialSide::Front => "GL_FRONT",
            MaterialSide::Back => "GL_BACK",
        };
        match self {
            MaterialSlot::Color(s, MaterialColor::Ambient) => (face(s), "GL_AMBIENT"),
            MaterialSlot::Color(s, MaterialColor::Diffuse) => (face(s), "GL_DIFFUSE"),
            MaterialSlot::Color(s, MaterialColor::Specular) => (face(s), "GL_SPECULAR"),
            MaterialSlot::Color(s, MaterialColor::Emission) => (face(s), "GL_EMISSION"),
            MaterialSlot::Shininess(s) => (face(s), "GL_SHININESS"),
        }
    }
}

/// Which material colour tracks the current colour under COLOR_MATERIAL.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ColorMaterialMode {
    Ambient,
    Diffuse,
    Specular,
    Emission,
    AmbientAndDiffuse,
}

impl ColorMaterialMode {
    /// The glMaterial call that colour material stands for.
    pub fn param(self, c: Vec4) -> MaterialParam {
        match self {
            ColorMaterialMode::Ambient => MaterialParam::Ambient(c),
            ColorMaterialMode::Diffuse => MaterialParam::Diffuse(c),
            ColorMaterialMode::Specular => MaterialParam::Specular(c),
            ColorMaterialMode::Emission => MaterialParam::Emission(c),
            ColorMaterialMode::AmbientAndDiffuse => MaterialParam::AmbientAndDiffuse(c),
        }
    }
}

/// glColorMaterial. GL default: FRONT_AND_BACK, AMBIENT_AND_DIFFUSE. While COLOR_MATERIAL is
/// enabled the selected material colours follow the current colour (§2.14.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ColorMaterial {
    pub face: Face,
    pub mode: ColorMaterialMode,
}

impl ColorMaterial {
    pub const DEFAULT: Self = Self {
        face: Face::FrontAndBack,
        mode: ColorMaterialMode::AmbientAndDiffuse,
    };

    /// Whether `slot` follows the current colour (when COLOR_MATERIAL is enabled).
    pub fn tracks(self, slot: MaterialSlot) -> bool {
        slot.set_by(self.face, self.mode.param(Vec4::ZERO))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_follow_table_6_10() {
        assert_eq!(Light::default_for(0).diffuse, Vec4::ONE);
        assert_eq!(Light::default_for(3).diffuse, Vec4::new(0.0, 0.0, 0.0, 1.0));
        assert_eq!(
            Light::default_for(3).position,
            Vec4::new(0.0, 0.0, 1.0, 0.0)
        );
    }

    #[test]
    fn material_calls_leave_the_tracked_colours_alone() {
        let mut m = Materials::DEFAULT;
        let tracking = ColorMaterial {
            face: Face::Front,
            mode: ColorMaterialMode::Diffuse,
        };
        let blue = Vec4::new(0.0, 0.0, 1.0, 1.0);
        m.set_untracked(
            Face::FrontAndBack,
            MaterialParam::AmbientAndDiffuse(blue),
            tracking,
        )
        .unwrap();
        assert_eq!(m.front.diffuse, Material::DEFAULT.diffuse, "tracked");
        assert_eq!(m.front.ambient, blue);
        assert_eq!(m.back.diffuse, blue, "the other face is not tracked");
        assert!(m
            .set_untracked(Face::Front, MaterialParam::Shininess(200.0), tracking)
            .is_err());
    }

    #[test]
    fn position_and_direction_use_the_modelview_at_set_time() {
        let mv = Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0));
        let mut l = Light::default_for(0);
        l.set(LightParam::Position(Vec4::new(0.0, 0.0, 0.0, 1.0)), mv)
            .unwrap();
        assert_eq!(l.position, Vec4::new(1.0, 2.0, 3.0, 1.0));
        l.set(LightParam::SpotDirection(Vec3::NEG_Z), mv).unwrap();
        assert_eq!(
            l.spot_direction,
            Vec3::NEG_Z,
            "translation does not move a direction"
        );
    }

    #[test]
    fn out_of_range_values_keep_the_state() {
        let mut l = Light::default_for(1);
        let before = l;
        for p in [
            LightParam::SpotCutoff(91.0),
            LightParam::SpotCutoff(-1.0),
            LightParam::SpotExponent(129.0),
            LightParam::LinearAttenuation(-0.5),
        ] {
            assert!(l.set(p, Mat4::IDENTITY).is_err(), "{p:?}");
        }
        assert_eq!(l, before);
        assert!(l.set(LightParam::SpotCutoff(180.0), Mat4::IDENTITY).is_ok());
        let mut m = Materials::DEFAULT;
        assert!(m.set(Face::Front, MaterialParam::Shininess(200.0)).is_err());
        assert_eq!(m, Materials::DEFAULT);
    }
}
