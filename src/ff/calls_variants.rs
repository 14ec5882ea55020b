//! The integer and transposed variants of GL 1.0–1.5 calls whose float forms `calls`
//! converts: glLightiv, glLightModeliv, glMateriali/iv, glTexEnviv, glTexParameteriv, the
//! vector forms glTexEnvfv, glTexParameterfv, glLightModelfv and glTexGen{i,f,d}v of scalar
//! parameters, and
//! glLoadTransposeMatrix / glMultTransposeMatrix (GL 1.3, and their ARB names).
//!
//! Integer colours are mapped as GL 1.5 Table 2.9 maps a signed integer, (2c + 1)/(2³² − 1)
//! (glLightiv's and glMaterialiv's AMBIENT, DIFFUSE, SPECULAR and EMISSION, the light
//! model's ambient, TEXTURE_ENV_COLOR, TEXTURE_BORDER_COLOR); every other integer is taken
//! as it is (positions, directions, exponents, cutoffs, attenuations, shininess, and the
//! tokens of scalar parameters, which a vector form passes as `params[0]`). A transposed
//! matrix is the row-major form of the column-major one (§2.11.2): M = transpose(m).

use super::api::{CType, Entry};
use super::args::{Args, PixelShape};
use super::calls::{
    env_scalar, first_of_four, light_scalar, material_vector, tex_param, LIGHT_PNAMES,
    MATERIAL_PNAMES,
};
use super::client::ArrayData;
use super::command::TexData;
use super::error::GlErrorKind;
use super::float_token::FloatToken;
use super::glenum::{pname_of, value_of, Family, GlEnum};
use super::*;

/// A colour of four signed integers (Table 2.9).
fn int_color<A: Args>(c: &A, i: usize) -> Result<glam::Vec4, A::Error> {
    let v = c.array_f64(i, 4)?;
    Ok(glam::Vec4::from_array(
        [0, 1, 2, 3].map(|k| CType::Int.normalized(v[k])),
    ))
}

/// The variants' Commands (`Ok(None)` for other calls).
pub fn variants<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    let pname_is = |i: usize, name: &str| c.token(i).ok() == value_of(name);
    Ok(Some(match c.entry() {
        Entry::LoadTransposeMatrixf
        | Entry::LoadTransposeMatrixd
        | Entry::LoadTransposeMatrixfARB
        | Entry::LoadTransposeMatrixdARB => {
            c.count(1)?;
            Command::LoadMatrix(c.mat4(0)?.transpose())
        }
        Entry::MultTransposeMatrixf
        | Entry::MultTransposeMatrixd
        | Entry::MultTransposeMatrixfARB
        | Entry::MultTransposeMatrixdARB => {
            c.count(1)?;
            Command::MultMatrix(c.mat4(0)?.transpose())
        }
        Entry::Lightiv => {
            c.count(3)?;
            let light = c.family(0, Family::Light)?;
            let param = match c.pname(1, LIGHT_PNAMES)? {
                "GL_AMBIENT" => LightParam::Ambient(int_color(c, 2)?),
                "GL_DIFFUSE" => LightParam::Diffuse(int_color(c, 2)?),
                "GL_SPECULAR" => LightParam::Specular(int_color(c, 2)?),
                "GL_POSITION" => LightParam::Position(c.vec4_array(2)?),
                "GL_SPOT_DIRECTION" => LightParam::SpotDirection(c.vec3_array(2)?),
                p => light_scalar(p, c.array_f64(2, 1)?[0] as f32),
            };
            Command::Light { light, param }
        }
        // The vector forms of the scalar light-model parameters read params[0] as
        // glLightModelf reads its value (Mesa 22.3 takes them; GL 1.5 §2.14.2 allows them).
        Entry::LightModelfv if !pname_is(0, "GL_LIGHT_MODEL_AMBIENT") => {
            c.count(2)?;
            let scalar = ScalarAt {
                entry: Entry::LightModelf,
                ..ScalarAt::new(c, 1)?
            };
            super::calls::lighting(&scalar)?.ok_or_else(|| c.unsupported())?
        }
        // glTexGen{i,f,d}v(coord, TEXTURE_GEN_MODE, params): the mode is params[0] (GL 1.5
        // §2.11.4), truncated from a float as Mesa converts it.
        Entry::TexGenfv | Entry::TexGendv | Entry::TexGeniv
            if pname_is(1, "GL_TEXTURE_GEN_MODE") =>
        {
            c.count(3)?;
            Command::TexGen {
                coord: c.enm(0)?,
                param: TexGenParam::Mode(ScalarAt::new(c, 2)?.enm(2)?),
            }
        }
        Entry::LightModeliv => {
            c.count(2)?;
            if pname_is(0, "GL_LIGHT_MODEL_AMBIENT") {
                Command::LightModel(LightModelParam::Ambient(int_color(c, 1)?))
            } else {
                let scalar = ScalarAt {
                    entry: Entry::LightModeli,
                    ..ScalarAt::new(c, 1)?
                };
                super::calls::lighting(&scalar)?.ok_or_else(|| c.unsupported())?
            }
        }
        // GL 1.5 Table 2.10 gives the scalar forms SHININESS only (else INVALID_ENUM);
        // Mesa takes a colour pname without an error, reading the other components from
        // beyond the argument (tests/c/calls.c pins the missing error). Followed: Mesa's
        // acceptance, with the colour (param, 0, 0, 0).
        Entry::Materiali | Entry::Materialf => {
            c.count(3)?;
            let face = c.enm(0)?;
            let v = c.f32(2)?;
            let param = match c.pname(1, MATERIAL_PNAMES)? {
                "GL_SHININESS" => MaterialParam::Shininess(v),
                "GL_COLOR_INDEXES" => MaterialParam::ColorIndexes(first_of_four(v).truncate()),
                p => material_vector(p, first_of_four(v)),
            };
            Command::Material { face, param }
        }
        Entry::Materialiv => {
            c.count(3)?;
            let face = c.enm(0)?;
            let param = match c.pname(1, MATERIAL_PNAMES)? {
                "GL_SHININESS" => MaterialParam::Shininess(c.array_f64(2, 1)?[0] as f32),
                // Indices, not colours: the integers themselves (Mesa measured).
                "GL_COLOR_INDEXES" => {
                    let v = c.array_f64(2, 3)?;
                    MaterialParam::ColorIndexes(glam::Vec3::new(
                        v[0] as f32,
                        v[1] as f32,
                        v[2] as f32,
                    ))
                }
                p => material_vector(p, int_color(c, 2)?),
            };
            Command::Material { face, param }
        }
        Entry::TexEnviv | Entry::TexEnvfv => {
            c.count(3)?;
            let color = pname_is(1, "GL_TEXTURE_ENV_COLOR");
            match (c.entry(), color) {
                // glTexEnvfv(GL_TEXTURE_ENV_COLOR) is `calls`' own.
                (Entry::TexEnvfv, true) => return Ok(None),
                (_, true) => {
                    c.pname(0, &["GL_TEXTURE_ENV"])?;
                    Command::TexEnv(TexEnvParam::Color(int_color(c, 2)?))
                }
                _ => Command::TexEnv(env_scalar(&ScalarAt::new(c, 2)?)?),
            }
        }
        Entry::TexParameteriv | Entry::TexParameterfv => {
            c.count(3)?;
            let border = pname_is(1, "GL_TEXTURE_BORDER_COLOR");
            match (c.entry(), border) {
                (Entry::TexParameterfv, true) => return Ok(None),
                (_, true) => Command::TexParameter {
                    target: c.enm(0)?,
                    param: TexParam::BorderColor(int_color(c, 2)?),
                },
                _ => Command::TexParameter {
                    target: c.enm(0)?,
                    param: tex_param(&ScalarAt::new(c, 2)?)?,
                },
            }
        }
        _ => return Ok(None),
    }))
}

/// A vector form's call read as its scalar form: argument `at` is `params[0]`, and the
/// call is `entry` (glLightModeliv is read as glLightModeli).
struct ScalarAt<'a, A> {
    inner: &'a A,
    entry: Entry,
    at: usize,
    value: f64,
}

impl<'a, A: Args> ScalarAt<'a, A> {
    fn new(inner: &'a A, at: usize) -> Result<Self, A::Error> {
        Ok(ScalarAt {
            inner,
            entry: inner.entry(),
            at,
            value: inner.array_f64(at, 1)?[0],
        })
    }

    fn token_value(&self) -> Option<u32> {
        FloatToken::of(self.entry).token(self.value)
    }
}

impl<A: Args> Args for ScalarAt<'_, A> {
    type Error = A::Error;
    fn entry(&self) -> Entry {
        self.entry
    }
    fn count(&self, _n: usize) -> Result<(), A::Error> {
        Ok(())
    }
    fn bad(&self, i: usize, expected: &'static str) -> A::Error {
        self.inner.bad(i, expected)
    }
    fn unknown(&self, i: usize, expected: Vec<&'static str>) -> A::Error {
        self.inner.unknown(i, expected)
    }
    fn also_expected(&self, err: A::Error, alternative: &'static str) -> A::Error {
        self.inner.also_expected(err, alternative)
    }
    fn unsupported(&self) -> A::Error {
        self.inner.unsupported()
    }
    fn immediate(&self, rule: &'static str) -> A::Error {
        self.inner.immediate(rule)
    }
    fn array_length(&self, expected: usize, found: usize) -> A::Error {
        self.inner.array_length(expected, found)
    }
    fn f64(&self, i: usize) -> Result<f64, A::Error> {
        if i == self.at {
            Ok(self.value)
        } else {
            self.inner.f64(i)
        }
    }
    fn f32(&self, i: usize) -> Result<f32, A::Error> {
        self.f64(i).map(|v| v as f32)
    }
    fn int(&self, i: usize) -> Result<i64, A::Error> {
        if i == self.at {
            Ok(self.value as i64)
        } else {
            self.inner.int(i)
        }
    }
    fn enm<T: GlEnum>(&self, i: usize) -> Result<T, A::Error> {
        if i != self.at {
            return self.inner.enm(i);
        }
        self.token_value()
            .and_then(T::from_gl_value)
            .ok_or_else(|| self.inner.unknown(i, T::names()))
    }
    fn token(&self, i: usize) -> Result<u32, A::Error> {
        if i != self.at {
            return self.inner.token(i);
        }
        self.token_value()
            .ok_or_else(|| self.inner.bad(i, "a GL token"))
    }
    fn pname(&self, i: usize, pnames: &[&'static str]) -> Result<&'static str, A::Error> {
        if i != self.at {
            return self.inner.pname(i, pnames);
        }
        self.token_value()
            .and_then(|v| pname_of(v, pnames))
            .ok_or_else(|| self.inner.unknown(i, pnames.to_vec()))
    }
    fn family(&self, i: usize, f: Family) -> Result<u8, A::Error> {
        if i != self.at {
            return self.inner.family(i, f);
        }
        self.token_value()
            .and_then(|v| f.from_value(v))
            .ok_or_else(|| self.inner.unknown(i, vec![f.example()]))
    }
    fn boolean(&self, i: usize) -> Result<bool, A::Error> {
        if i == self.at {
            Ok(self.value != 0.0)
        } else {
            self.inner.boolean(i)
        }
    }
    fn bits(&self, i: usize, names: &[&'static str]) -> Result<Vec<&'static str>, A::Error> {
        self.inner.bits(i, names)
    }
    fn floats<const N: usize>(&self, i: usize) -> Result<[f32; N], A::Error> {
        self.inner.floats(i)
    }
    fn array_f64(&self, i: usize, n: usize) -> Result<Vec<f64>, A::Error> {
        self.inner.array_f64(i, n)
    }
    fn array_as(&self, i: usize, n: usize, ty: CType) -> Result<Vec<f64>, A::Error> {
        self.inner.array_as(i, n, ty)
    }
    fn deferred(&self, err: &A::Error) -> Option<GlErrorKind> {
        self.inner.deferred(err)
    }
    fn tex_data(&self, i: usize, shape: PixelShape) -> Result<TexData, A::Error> {
        self.inner.tex_data(i, shape)
    }
    fn pixels(
        &self,
        i: usize,
        shape: PixelShape,
    ) -> Result<Option<std::sync::Arc<[u8]>>, A::Error> {
        self.inner.pixels(i, shape)
    }
    fn array_data(&self, i: usize) -> Result<ArrayData, A::Error> {
        self.inner.array_data(i)
    }
    fn pointers(&self, i: usize, n: usize, bound: u32) -> Result<Vec<ArrayData>, A::Error> {
        self.inner.pointers(i, n, bound)
    }
    fn offset(&self, i: usize) -> Result<usize, A::Error> {
        self.inner.offset(i)
    }
    fn slot(&self, i: usize) -> Result<u32, A::Error> {
        self.inner.slot(i)
    }
}

#[cfg(test)]
mod tests {
    use crate::ff::script::parse;
    use crate::ff::{Command, LightParam, MaterialParam};
    use glam::{Mat4, Vec4};

    #[test]
    fn mesa_scalar_material_sets_a_vector_pname_as_v000() {
        let cmds = parse("glMateriali(GL_FRONT, GL_DIFFUSE, 3);").unwrap();
        assert!(matches!(
            cmds[0],
            Command::Material { param: MaterialParam::Diffuse(v), .. } if v == Vec4::new(3.0, 0.0, 0.0, 0.0)
        ));
    }

    #[test]
    fn integer_colours_are_normalised_and_positions_kept() {
        let cmds = parse(
            "glLightiv(GL_LIGHT0, GL_DIFFUSE, (GLint[]){2147483647, 0, -2147483647, 0});\n\
             glLightiv(GL_LIGHT0, GL_POSITION, (GLint[]){1, 2, 3, 0});\n\
             glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint[]){0x2600});",
        )
        .unwrap();
        match (&cmds[0], &cmds[1]) {
            (
                Command::Light {
                    param: LightParam::Diffuse(d),
                    ..
                },
                Command::Light {
                    param: LightParam::Position(p),
                    ..
                },
            ) => {
                assert_eq!(
                    *d,
                    Vec4::new(
                        1.0,
                        (1.0 / 4294967295.0) as f32,
                        -1.0,
                        (1.0 / 4294967295.0) as f32
                    )
                );
                assert_eq!(*p, Vec4::new(1.0, 2.0, 3.0, 0.0));
            }
            other => panic!("{other:?}"),
        }
        assert!(matches!(cmds[2], Command::TexParameter { .. }));
    }

    #[test]
    fn transposed_matrices_load_their_rows_as_columns() {
        let cmds = parse(
            "glLoadTransposeMatrixf((GLfloat[]){1, 0, 0, 5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1});",
        )
        .unwrap();
        let want = Mat4::from_translation(glam::Vec3::new(5.0, 6.0, 7.0));
        assert_eq!(cmds, vec![Command::LoadMatrix(want)]);
    }
}
