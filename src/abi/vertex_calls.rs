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

use super::cargs::{read_elements, CArg};
use crate::ff::api::{Attrib, AttribCall, Entry};
use crate::ff::front::Client;
use crate::ff::glenum::Family;
use crate::ff::immediate::{component, DEFAULT_COMPONENTS};

/// A vertex-attribute call inside glBegin/glEnd, straight into `client`'s open pair;
/// `false` when the call takes the general path (`Client::call`): not an attribute call,
/// no pair open, a list being compiled (which keeps the call), or arguments [`read`] does
/// not take. Inside the pair an attribute or a vertex yields no command.
#[inline]
pub fn in_pair(client: &mut Client, entry: Entry, args: &[CArg]) -> bool {
    let Some(form) = entry.attrib_call() else {
        return false;
    };
    if !client.immediate.is_open() || client.lists.compiling().is_some() {
        return false;
    }
    match read(form, args) {
        Some((unit, c)) => client.immediate.in_pair(form.attrib, unit, c),
        None => false,
    }
}

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
        let mut v = [0.0; 4];
        // SAFETY: the program passed an array of at least the prototype's count of its
        // element type (GL's contract with the caller: glVertex3fv reads three floats).
        unsafe { read_elements(p, elem, &mut v[..len]) };
        for (slot, x) in c.iter_mut().zip(&v[..len]) {
            *slot = component(form, *x);
        }
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
