//! The arguments of one GL call, as the converters of [`calls`](super::calls) read them.
//!
//! A call reaches the layer through one of two front ends: a script (`ff::script`, where
//! tokens are names and arrays are compound literals) or the C library (`abi`, where tokens
//! are GLenum values and arrays are pointers). Each implements `Args`; the converters from a
//! call to its [`Command`](super::Command) are written once, against this trait, and each
//! front end says what a bad argument is: a script error with the line and the valid
//! alternatives, or the GL error the specification gives (INVALID_ENUM for a token outside
//! the set, INVALID_VALUE for a bad number or bitfield).

use std::sync::Arc;

use glam::{Mat4, Vec3, Vec4};

use super::api::{CType, Entry};
use super::client::ArrayData;
use super::command::TexData;
use super::error::GlErrorKind;
use super::glenum::{Family, GlEnum};
use super::texture::{PixelFormat, PixelType};

/// What a pixel pointer holds, so that a front end that receives only a pointer knows how
/// many bytes to read (GL 1.5 §3.6.4: width × height groups, or bits for a bitmap, laid
/// out by the unpack parameters: `pixel_layout`; GL 1.2 §3.8.1: depth images of them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelShape {
    pub width: i32,
    pub height: i32,
    /// `Some(depth)`: the images of a 3D call (glTexImage3D, glTexSubImage3D, glGetTexImage
    /// of a 3D level), which IMAGE_HEIGHT and SKIP_IMAGES lay out; `None`: one rectangle,
    /// which those parameters do not move.
    pub depth: Option<i32>,
    /// For a bitmap, LUMINANCE (unused).
    pub format: PixelFormat,
    /// For a bitmap, UNSIGNED_BYTE (unused).
    pub ty: PixelType,
    pub kind: ShapeKind,
}

/// Whether a shape is groups of components or a bitmap (one bit a pixel, GL's BITMAP type),
/// and for a COLOR_INDEX image, the run Mesa 22.3 reads instead of rows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShapeKind {
    Groups,
    Bitmap,
    /// COLOR_INDEX groups as Mesa 22.3 reads them: each image's width·height groups one
    /// run from its first group, the rows neither padded nor ROW_LENGTH apart (its
    /// `_mesa_unpack_color_index_to_rgba_float` extracts them in one span; measured,
    /// `tests/c/index_pixels.c`: 3 indices a row at alignment 4 read the padding byte).
    IndexRun,
    /// COLOR_INDEX in GL_BITMAP: each image's width·height bits one run, as
    /// [`ShapeKind::IndexRun`], bit 0 or 1 the index; LSB_FIRST as the call takes it.
    IndexBits(LsbFirst),
}

/// Whether a call reads UNPACK_LSB_FIRST for COLOR_INDEX bits: glTexImage does; Mesa
/// 22.3's glDrawPixels reads the most significant bit first whatever it says (measured).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LsbFirst {
    Honoured,
    Ignored,
}

impl PixelShape {
    /// `width × height` groups of `format` in `ty`.
    pub fn groups(width: i32, height: i32, format: PixelFormat, ty: PixelType) -> Self {
        Self {
            width,
            height,
            depth: None,
            format,
            ty,
            kind: ShapeKind::Groups,
        }
    }

    /// `depth` images of `width × height` groups of `format` in `ty` (GL 1.2's 3D calls).
    pub fn volume(width: i32, height: i32, depth: i32, format: PixelFormat, ty: PixelType) -> Self {
        Self {
            depth: Some(depth),
            ..Self::groups(width, height, format, ty)
        }
    }

    /// `width × height` bits (glBitmap, glPolygonStipple).
    pub fn bitmap(width: i32, height: i32) -> Self {
        Self {
            width,
            height,
            depth: None,
            format: PixelFormat::Luminance,
            ty: PixelType::UnsignedByte,
            kind: ShapeKind::Bitmap,
        }
    }

    /// Bytes of one group.
    pub fn group_bytes(&self) -> usize {
        self.ty.group_bytes(self.format)
    }

    /// Bytes of one element: what SWAP_BYTES reverses.
    pub fn element_bytes(&self) -> usize {
        self.ty.size()
    }
}

/// Typed readers of one call's arguments, by position.
pub trait Args {
    /// What a bad argument becomes.
    type Error;

    /// The entry point called.
    fn entry(&self) -> Entry;

    /// `Ok` when the call has `n` arguments (a C call always has its prototype's).
    fn count(&self, n: usize) -> Result<(), Self::Error>;

    /// Argument `i` is not what the call takes.
    fn bad(&self, i: usize, expected: &'static str) -> Self::Error;

    /// Argument `i` is a token outside `expected`.
    fn unknown(&self, i: usize, expected: Vec<&'static str>) -> Self::Error;

    /// `err` (an `unknown` error) with one more valid alternative named.
    fn also_expected(&self, err: Self::Error, _alternative: &'static str) -> Self::Error {
        err
    }

    /// A call the layer has no converter for.
    fn unsupported(&self) -> Self::Error;

    /// A call not allowed between glBegin and glEnd, or immediate mode misused.
    fn immediate(&self, rule: &'static str) -> Self::Error;

    /// An array of `found` values where `expected` are needed.
    fn array_length(&self, expected: usize, found: usize) -> Self::Error;

    /// A number as the caller passed it, before the parameter's own conversion.
    fn f64(&self, i: usize) -> Result<f64, Self::Error>;

    /// A number as a GLfloat.
    fn f32(&self, i: usize) -> Result<f32, Self::Error>;

    /// An integer.
    fn int(&self, i: usize) -> Result<i64, Self::Error>;

    fn i32(&self, i: usize) -> Result<i32, Self::Error> {
        i32::try_from(self.int(i)?).map_err(|_| self.bad(i, "a 32-bit integer"))
    }

    fn u32(&self, i: usize) -> Result<u32, Self::Error> {
        u32::try_from(self.int(i)?).map_err(|_| self.bad(i, "an unsigned 32-bit integer"))
    }

    /// A token of the model enum `T`.
    fn enm<T: GlEnum>(&self, i: usize) -> Result<T, Self::Error>;

    /// A token as its GL value, whatever it names (the queries check it against the
    /// model: a token of the wrong set is then GL's INVALID_ENUM in either front end).
    fn token(&self, i: usize) -> Result<u32, Self::Error>;

    /// A token naming one of `pnames` (a parameter name).
    fn pname(&self, i: usize, pnames: &[&'static str]) -> Result<&'static str, Self::Error>;

    /// An indexed token: GL_LIGHTi, GL_TEXTUREi, GL_COMBINERi_NV.
    fn family(&self, i: usize, f: Family) -> Result<u8, Self::Error>;

    /// A GLboolean.
    fn boolean(&self, i: usize) -> Result<bool, Self::Error>;

    /// The bits of a bitfield argument, by name, each one of `names` (0 is no bits).
    fn bits(&self, i: usize, names: &[&'static str]) -> Result<Vec<&'static str>, Self::Error>;

    /// Exactly `N` floats from an array argument.
    fn floats<const N: usize>(&self, i: usize) -> Result<[f32; N], Self::Error>;

    /// The first `n` numbers of an array argument (at least `n` must be there), each as
    /// the caller's element type holds it.
    fn array_f64(&self, i: usize, n: usize) -> Result<Vec<f64>, Self::Error>;

    /// The first `out.len()` numbers of an array argument into `out`, as [`array_f64`]
    /// reads them; a front end that can read in place (the C library, once per glVertex3fv)
    /// does so without allocating.
    ///
    /// [`array_f64`]: Args::array_f64
    fn array_f64_into(&self, i: usize, out: &mut [f64]) -> Result<(), Self::Error> {
        let v = self.array_f64(i, out.len())?;
        out.copy_from_slice(&v[..out.len()]);
        Ok(())
    }

    /// The first `n` values of an untyped array argument (`const void *`) read as `ty`
    /// (a script's compound literal carries its own element type and is read as written).
    fn array_as(&self, i: usize, n: usize, ty: CType) -> Result<Vec<f64>, Self::Error>;

    /// The GL error to keep in a display list when a compiled call's arguments are bad
    /// (GL raises it when the list runs), or `None` when the front end stops at once (a
    /// script reports the line).
    fn deferred(&self, err: &Self::Error) -> Option<GlErrorKind>;

    /// glTexImage's data: NULL, bytes, or (scripts) a readback slot.
    fn tex_data(&self, i: usize, shape: PixelShape) -> Result<TexData, Self::Error>;

    /// Pixel data: NULL, or bytes.
    fn pixels(&self, i: usize, shape: PixelShape) -> Result<Option<Arc<[u8]>>, Self::Error>;

    /// The memory a client-array pointer names: NULL, bytes given with the call (a
    /// script), or an address in the program (C).
    fn array_data(&self, i: usize) -> Result<ArrayData, Self::Error>;

    /// The first `n` pointers of a pointer-array argument (`const void *const *`,
    /// glMultiDrawElements' index lists), each read as a pointer argument is: with
    /// `bound` a buffer object (not 0), a byte offset into it (GL 1.5 §2.9.5); without,
    /// the memory it names (C: an address; a script: a compound literal of compound
    /// literals, `(const void *[]){(GLushort[]){0, 1, 2}, NULL}`, or of offsets).
    fn pointers(&self, i: usize, n: usize, bound: u32) -> Result<Vec<ArrayData>, Self::Error>;

    /// A pointer argument read as a byte offset into a bound buffer object (C: the
    /// pointer's value, `(void *)12`; a script: an integer literal or NULL).
    fn offset(&self, i: usize) -> Result<usize, Self::Error>;

    /// The readback slot glReadPixels writes to.
    fn slot(&self, i: usize) -> Result<u32, Self::Error>;

    fn vec4_array(&self, i: usize) -> Result<Vec4, Self::Error> {
        self.floats::<4>(i).map(Vec4::from_array)
    }

    fn vec3_array(&self, i: usize) -> Result<Vec3, Self::Error> {
        self.floats::<3>(i).map(Vec3::from_array)
    }

    fn mat4(&self, i: usize) -> Result<Mat4, Self::Error> {
        self.floats::<16>(i).map(|a| Mat4::from_cols_array(&a))
    }

    fn vec3_args(&self, from: usize) -> Result<Vec3, Self::Error> {
        Ok(Vec3::new(
            self.f32(from)?,
            self.f32(from + 1)?,
            self.f32(from + 2)?,
        ))
    }

    fn vec4_args(&self, from: usize) -> Result<Vec4, Self::Error> {
        Ok(Vec4::new(
            self.f32(from)?,
            self.f32(from + 1)?,
            self.f32(from + 2)?,
            self.f32(from + 3)?,
        ))
    }
}
