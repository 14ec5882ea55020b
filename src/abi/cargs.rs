//! A C call's arguments as the shared converters read them ([`Args`]): tokens arrive as
//! GLenum values, arrays as typed pointers, and a bad argument is the GL error the
//! specification gives (INVALID_ENUM for a token outside the set, INVALID_VALUE for a bad
//! number, bitfield or null array).
//!
//! Pointers are read only as far as the call's parameters say (four floats for
//! GL_AMBIENT, three for GL_SPOT_DIRECTION, width × height pixels laid out by the
//! unpack parameters), never further: what a C program passes is its own contract, as with any GL.

use std::borrow::Cow;
use std::cell::Cell;
use std::ffi::c_void;
use std::sync::Arc;

use crate::ff::api::{CType, Entry};
use crate::ff::args::{Args, PixelShape};
use crate::ff::client::{ArrayData, ClientMemory};
use crate::ff::float_token::FloatToken;
use crate::ff::glenum::{pname_of, value_of, Family, GlEnum};
use crate::ff::pixel_layout;
use crate::ff::pixel_store::Packing;
use crate::ff::upload_bounds::PixelAccess;
use crate::ff::{GlErrorKind, TexData};

/// The element type behind a pointer parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CElem {
    Byte,
    UByte,
    Short,
    UShort,
    Int,
    UInt,
    Float,
    Double,
    Void,
}

/// The element type of a pointer parameter's pointee.
pub trait CElement {
    const ELEM: CElem;
}

macro_rules! elements {
    ($($t:ty => $e:ident),*) => {
        $(impl CElement for $t {
            const ELEM: CElem = CElem::$e;
        })*
    };
}
elements!(i8 => Byte, u8 => UByte, i16 => Short, u16 => UShort, i32 => Int, u32 => UInt,
          f32 => Float, f64 => Double, c_void => Void, *mut c_void => Void,
          *const c_void => Void);

/// One argument of a C call.
#[derive(Clone, Copy, Debug)]
pub enum CArg {
    Int(i64),
    Float(f64),
    Ptr(*const c_void, CElem),
}

macro_rules! int_args {
    ($($t:ty),*) => {
        $(impl From<$t> for CArg {
            fn from(v: $t) -> Self {
                CArg::Int(v as i64)
            }
        })*
    };
}
int_args!(i8, u8, i16, u16, i32, u32, isize);

impl From<f32> for CArg {
    fn from(v: f32) -> Self {
        CArg::Float(f64::from(v))
    }
}

impl From<f64> for CArg {
    fn from(v: f64) -> Self {
        CArg::Float(v)
    }
}

impl<T: CElement> From<*const T> for CArg {
    fn from(p: *const T) -> Self {
        CArg::Ptr(p.cast(), T::ELEM)
    }
}

impl<T: CElement> From<*mut T> for CArg {
    fn from(p: *mut T) -> Self {
        CArg::Ptr(p.cast_const().cast(), T::ELEM)
    }
}

/// `out.len()` elements of type `elem` from `p`, each as its C type holds it.
///
/// # Safety
/// `p` points to at least `out.len()` elements of `elem`'s type.
pub(super) unsafe fn read_elements(p: *const c_void, elem: CElem, out: &mut [f64]) {
    unsafe fn each<T: Copy>(p: *const c_void, out: &mut [f64], f: impl Fn(T) -> f64) {
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = f(p.cast::<T>().add(k).read_unaligned());
        }
    }
    match elem {
        CElem::Byte => each(p, out, |x: i8| f64::from(x)),
        CElem::UByte | CElem::Void => each(p, out, |x: u8| f64::from(x)),
        CElem::Short => each(p, out, |x: i16| f64::from(x)),
        CElem::UShort => each(p, out, |x: u16| f64::from(x)),
        CElem::Int => each(p, out, |x: i32| f64::from(x)),
        CElem::UInt => each(p, out, |x: u32| f64::from(x)),
        CElem::Float => each(p, out, |x: f32| f64::from(x)),
        CElem::Double => each(p, out, |x: f64| x),
    }
}

/// The readback slot a C glReadPixels uses before its bytes are copied out.
pub const CALLER_SLOT: u32 = u32::MAX;

/// One C call: its entry point, its arguments, and the client state reading needs.
pub struct CCall<'a> {
    pub entry: Entry,
    pub args: &'a [CArg],
    /// The unpack parameters of glPixelStore.
    pub unpack: Packing,
    /// Whether the call's pixel pointer may be read (`ff::upload_bounds`): a call whose
    /// sizes GL refuses takes it as NULL.
    pub access: PixelAccess,
    /// Set when no converter knew the call.
    pub unsupported: Cell<bool>,
}

impl<'a> CCall<'a> {
    /// A call with `args`, unpacking client pixels by `unpack`, its pointer readable (the
    /// general path narrows `access` for sizes GL refuses).
    pub fn new(entry: Entry, args: &'a [CArg], unpack: Packing) -> CCall<'a> {
        CCall {
            entry,
            args,
            unpack,
            access: PixelAccess::Read,
            unsupported: Cell::new(false),
        }
    }

    /// Whether the call failed because the layer has no converter for it.
    pub fn was_unsupported(&self) -> bool {
        self.unsupported.get()
    }

    fn value(&self, i: usize) -> Option<f64> {
        match self.args.get(i)? {
            CArg::Int(v) => Some(*v as f64),
            CArg::Float(v) => Some(*v),
            CArg::Ptr(..) => None,
        }
    }

    /// A token: an integer argument, or a float holding one (`glTexParameterf(…,
    /// GL_LINEAR)`), converted as the call converts it ([`FloatToken`]).
    fn token(&self, i: usize) -> Option<u32> {
        match self.args.get(i)? {
            CArg::Int(v) => u32::try_from(*v).ok(),
            CArg::Float(v) => FloatToken::of(self.entry).token(*v),
            CArg::Ptr(..) => None,
        }
    }

    fn pointer(&self, i: usize) -> Result<(*const c_void, CElem), GlErrorKind> {
        match self.args.get(i) {
            Some(CArg::Ptr(p, e)) if !p.is_null() => Ok((*p, *e)),
            _ => Err(GlErrorKind::InvalidValue),
        }
    }

    /// `n` values from pointer argument `i`, each as its C element type holds it.
    fn read(&self, i: usize, n: usize) -> Result<Vec<f64>, GlErrorKind> {
        let mut v = vec![0.0; n];
        self.read_into(i, &mut v)?;
        Ok(v)
    }

    /// `out.len()` values from pointer argument `i` into `out`.
    /// No value read is no pointer used: n = 0 with a NULL array is no error (glDeleteTextures(0,
    /// NULL) and the like, as on Mesa).
    fn read_into(&self, i: usize, out: &mut [f64]) -> Result<(), GlErrorKind> {
        if out.is_empty() {
            return Ok(());
        }
        let (p, elem) = self.pointer(i)?;
        // SAFETY: the caller passed a pointer to at least `out.len()` elements of this type,
        // as the GL prototype and the parameter name require (GL's contract with the
        // program).
        unsafe { read_elements(p, elem, out) };
        Ok(())
    }

    /// The pixels of `shape` from pointer `i`, unpacked with the unpack parameters
    /// (GL 1.5 §3.6.4, `pixel_layout`) into the tightly packed rows the model holds.
    fn unpack(&self, i: usize, shape: PixelShape) -> Result<Option<Arc<[u8]>>, GlErrorKind> {
        let p = match self.args.get(i) {
            Some(CArg::Ptr(..)) if self.access == PixelAccess::Skip => return Ok(None),
            Some(CArg::Ptr(p, _)) if p.is_null() => return Ok(None),
            Some(CArg::Ptr(p, _)) => *p,
            _ => return Err(GlErrorKind::InvalidValue),
        };
        let extent = pixel_layout::layout(shape, &self.unpack).extent;
        // SAFETY: the program's buffer holds the rows the unpack parameters place (up to
        // the last row's last byte), as GL requires of the data a pixel call reads.
        let src = unsafe { std::slice::from_raw_parts(p.cast::<u8>(), extent) };
        pixel_layout::unpack(src, shape, &self.unpack)
            .map(|v| Some(Arc::from(v)))
            .ok_or(GlErrorKind::InvalidValue)
    }
}

impl Args for CCall<'_> {
    type Error = GlErrorKind;

    fn entry(&self) -> Entry {
        self.entry
    }
    fn count(&self, _n: usize) -> Result<(), GlErrorKind> {
        // A C call has its prototype's arguments.
        Ok(())
    }
    fn bad(&self, _i: usize, _expected: &'static str) -> GlErrorKind {
        GlErrorKind::InvalidValue
    }
    fn unknown(&self, _i: usize, _expected: Vec<&'static str>) -> GlErrorKind {
        GlErrorKind::InvalidEnum
    }
    fn unsupported(&self) -> GlErrorKind {
        self.unsupported.set(true);
        GlErrorKind::InvalidOperation
    }
    fn immediate(&self, _rule: &'static str) -> GlErrorKind {
        GlErrorKind::InvalidOperation
    }
    fn array_length(&self, _expected: usize, _found: usize) -> GlErrorKind {
        GlErrorKind::InvalidValue
    }
    fn f64(&self, i: usize) -> Result<f64, GlErrorKind> {
        self.value(i).ok_or(GlErrorKind::InvalidValue)
    }
    fn f32(&self, i: usize) -> Result<f32, GlErrorKind> {
        self.f64(i).map(|v| v as f32)
    }
    fn int(&self, i: usize) -> Result<i64, GlErrorKind> {
        match self.args.get(i) {
            Some(CArg::Int(v)) => Ok(*v),
            // A float given where GL keeps an integer: GL 1.5 §2.3, rounded to nearest.
            Some(CArg::Float(v)) if v.is_finite() => Ok(v.round() as i64),
            _ => Err(GlErrorKind::InvalidValue),
        }
    }
    fn enm<T: GlEnum>(&self, i: usize) -> Result<T, GlErrorKind> {
        self.token(i)
            .and_then(T::from_gl_value)
            .ok_or(GlErrorKind::InvalidEnum)
    }
    fn token(&self, i: usize) -> Result<u32, GlErrorKind> {
        CCall::token(self, i).ok_or(GlErrorKind::InvalidEnum)
    }
    fn pname(&self, i: usize, pnames: &[&'static str]) -> Result<&'static str, GlErrorKind> {
        let v = self.token(i).ok_or(GlErrorKind::InvalidEnum)?;
        pname_of(v, pnames).ok_or(GlErrorKind::InvalidEnum)
    }
    fn family(&self, i: usize, f: Family) -> Result<u8, GlErrorKind> {
        self.token(i)
            .and_then(|v| f.from_value(v))
            .ok_or(GlErrorKind::InvalidEnum)
    }
    fn boolean(&self, i: usize) -> Result<bool, GlErrorKind> {
        self.value(i)
            .map(|v| v != 0.0)
            .ok_or(GlErrorKind::InvalidValue)
    }
    fn bits(&self, i: usize, names: &[&'static str]) -> Result<Vec<&'static str>, GlErrorKind> {
        let v = self.token(i).ok_or(GlErrorKind::InvalidValue)?;
        let mut rest = v;
        let mut out = Vec::new();
        for n in names {
            // A name matches when every bit of its value is set: a composite such as
            // GL_ALL_ATTRIB_BITS names all the groups, not any one of them (GL 1.5 §6.1.14).
            let bit = value_of(n).unwrap_or(0);
            if bit != 0 && v & bit == bit {
                out.push(*n);
                rest &= !bit;
            }
        }
        // A bit outside the set: INVALID_VALUE (GL 1.5 §4.2.3 for glClear).
        if rest == 0 {
            Ok(out)
        } else {
            Err(GlErrorKind::InvalidValue)
        }
    }
    fn floats<const N: usize>(&self, i: usize) -> Result<[f32; N], GlErrorKind> {
        let v = self.read(i, N)?;
        let mut out = [0.0; N];
        for (o, x) in out.iter_mut().zip(v) {
            *o = x as f32;
        }
        Ok(out)
    }
    fn array_f64(&self, i: usize, n: usize) -> Result<Vec<f64>, GlErrorKind> {
        self.read(i, n)
    }
    fn array_f64_into(&self, i: usize, out: &mut [f64]) -> Result<(), GlErrorKind> {
        self.read_into(i, out)
    }
    fn tex_data(&self, i: usize, shape: PixelShape) -> Result<TexData, GlErrorKind> {
        Ok(self.unpack(i, shape)?.map_or(TexData::Null, TexData::Bytes))
    }
    fn pixels(&self, i: usize, shape: PixelShape) -> Result<Option<Arc<[u8]>>, GlErrorKind> {
        self.unpack(i, shape)
    }
    fn array_as(&self, i: usize, n: usize, ty: CType) -> Result<Vec<f64>, GlErrorKind> {
        let elem = match ty {
            CType::Byte => CElem::Byte,
            CType::UByte => CElem::UByte,
            CType::Short => CElem::Short,
            CType::UShort => CElem::UShort,
            CType::Int => CElem::Int,
            CType::UInt => CElem::UInt,
            CType::Float => CElem::Float,
            CType::Double => CElem::Double,
        };
        if n == 0 {
            return Ok(Vec::new());
        }
        let (p, _) = self.pointer(i)?;
        let typed = CCall {
            entry: self.entry,
            args: &[CArg::Ptr(p, elem)],
            unpack: self.unpack,
            access: self.access,
            unsupported: Cell::new(false),
        };
        typed.read(0, n)
    }
    fn deferred(&self, err: &GlErrorKind) -> Option<GlErrorKind> {
        Some(*err)
    }
    fn array_data(&self, i: usize) -> Result<ArrayData, GlErrorKind> {
        match self.args.get(i) {
            // A compressed sub-image's blocks, of a region GL refuses.
            Some(CArg::Ptr(..)) if self.access == PixelAccess::Skip => Ok(ArrayData::Null),
            Some(CArg::Ptr(p, _)) if p.is_null() => Ok(ArrayData::Null),
            Some(CArg::Ptr(p, _)) => Ok(ArrayData::Address(*p as usize)),
            // An integer where a pointer goes: an offset into no buffer object.
            _ => Err(GlErrorKind::InvalidValue),
        }
    }
    fn pointers(&self, i: usize, n: usize, bound: u32) -> Result<Vec<ArrayData>, GlErrorKind> {
        let Some(CArg::Ptr(p, _)) = self.args.get(i) else {
            return Err(GlErrorKind::InvalidValue);
        };
        if n == 0 {
            return Ok(Vec::new());
        }
        if p.is_null() {
            return Err(GlErrorKind::InvalidValue);
        }
        let list = p.cast::<*const c_void>();
        Ok((0..n)
            .map(|k| {
                // SAFETY: the program's array holds the `drawcount` pointers the call names
                // (glMultiDrawElements' contract).
                let q = unsafe { list.add(k).read_unaligned() };
                match (bound, q.is_null()) {
                    (0, true) => ArrayData::Null,
                    (0, false) => ArrayData::Address(q as usize),
                    (name, _) => ArrayData::Buffer {
                        name,
                        offset: q as usize,
                    },
                }
            })
            .collect())
    }
    fn offset(&self, i: usize) -> Result<usize, GlErrorKind> {
        match self.args.get(i) {
            Some(CArg::Ptr(p, _)) => Ok(*p as usize),
            Some(CArg::Int(v)) => usize::try_from(*v).map_err(|_| GlErrorKind::InvalidValue),
            _ => Err(GlErrorKind::InvalidValue),
        }
    }
    fn slot(&self, _i: usize) -> Result<u32, GlErrorKind> {
        Ok(CALLER_SLOT)
    }
}

/// The calling program's memory, read where a client array points (GL's contract: the
/// program keeps the arrays valid while a draw reads them).
pub struct ProgramMemory;

impl ClientMemory for ProgramMemory {
    fn read<'d>(&self, data: &'d ArrayData, offset: usize, len: usize) -> Option<Cow<'d, [u8]>> {
        match data {
            ArrayData::Address(a) => {
                let start = a.checked_add(offset)?;
                // SAFETY: the program's array holds the elements the draw names.
                let bytes = unsafe { std::slice::from_raw_parts(start as *const u8, len) };
                Some(Cow::Borrowed(bytes))
            }
            ArrayData::Bytes(b) => b.get(offset..offset.checked_add(len)?).map(Cow::Borrowed),
            ArrayData::Null | ArrayData::Buffer { .. } | ArrayData::Orphaned(_) => None,
        }
    }
}
