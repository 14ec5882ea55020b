//! The vertex-attribute calls from C (glVertex…, glColor…, glNormal…, glTexCoord…,
//! glMultiTexCoord…) inside glBegin/glEnd, read straight into the open pair
//! (`Immediate::in_pair`): the path a call takes once per vertex, free of allocation and
//! of the general routing.
//!
//! A C argument already has its parameter's type (the compiler converted it at the call,
//! and an array's elements are of the prototype's type), so the values need none of the
//! conversions a script's literals get (`CType::convert` is the identity on them); each is
//! taken by the shared rule `immediate::component` (integer colours and normals
//! normalised), missing components from `DEFAULT_COMPONENTS`. Anything this reader
//! cannot take whole (a null array, a unit outside GL_TEXTURE0…, glRect) goes the general
//! way, which gives the error.

use super::cargs::{CArg, CElem};
use crate::ff::api::{Attrib, AttribCall};
use crate::ff::glenum::Family;
use crate::ff::immediate::{component, DEFAULT_COMPONENTS};

/// The call's unit (glMultiTexCoord; 0 otherwise) and components; `None` to take the
/// general path.
#[inline]
pub fn read(form: AttribCall, args: &[CArg]) -> Option<(u8, [f32; 4])> {
    let (unit, values) = match form.attrib {
        Attrib::MultiTexCoord => {
            let (target, rest) = args.split_first()?;
            let CArg::Int(t) = *target else {
                return None;
            };
            (Family::Texture.from_value(u32::try_from(t).ok()?)?, rest)
        }
        Attrib::Rect => return None,
        _ => (0, args),
    };
    let mut c = DEFAULT_COMPONENTS;
    let len = form.count.min(4);
    if form.vector {
        let CArg::Ptr(p, elem) = *values.first()? else {
            return None;
        };
        if p.is_null() {
            return None;
        }
        // SAFETY: the program passed an array of at least the prototype's count of its
        // element type (GL's contract with the caller: glVertex3fv reads three floats).
        unsafe { read_array(p, elem, form, &mut c[..len]) };
    } else {
        for (slot, arg) in c[..len].iter_mut().zip(values.get(..len)?) {
            *slot = match *arg {
                CArg::Float(x) => component(form, x),
                CArg::Int(x) => component(form, x as f64),
                CArg::Ptr(..) => return None,
            };
        }
    }
    Some((unit, c))
}

/// `out.len()` components from an array of `elem`; floats are taken as they are.
///
/// # Safety
/// `p` points to at least `out.len()` elements of `elem`'s type.
#[inline]
unsafe fn read_array(p: *const std::ffi::c_void, elem: CElem, form: AttribCall, out: &mut [f32]) {
    unsafe fn each<T: Copy>(p: *const std::ffi::c_void, out: &mut [f32], f: impl Fn(T) -> f32) {
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = f(p.cast::<T>().add(k).read_unaligned());
        }
    }
    let c = |x: f64| component(form, x);
    match elem {
        CElem::Float => each(p, out, |x: f32| x),
        CElem::Double => each(p, out, |x: f64| x as f32),
        CElem::Byte => each(p, out, |x: i8| c(f64::from(x))),
        CElem::UByte | CElem::Void => each(p, out, |x: u8| c(f64::from(x))),
        CElem::Short => each(p, out, |x: i16| c(f64::from(x))),
        CElem::UShort => each(p, out, |x: u16| c(f64::from(x))),
        CElem::Int => each(p, out, |x: i32| c(f64::from(x))),
        CElem::UInt => each(p, out, |x: u32| c(f64::from(x))),
    }
}
