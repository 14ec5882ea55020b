//! One C function per row of the entry-point table, expanded from the table itself
//! (`ff::api::gl_entry_table`): the name, parameters and return type are the row's, the
//! body hands the arguments to [`dispatch`](super::dispatch). [`proc_address`] finds any
//! of them by name, for OSMesaGetProcAddress.
//!
//! The functions are `unsafe extern "C"`: their pointer arguments are read as GL reads
//! them (the program's contract), which Rust cannot check.
#![allow(clippy::missing_safety_doc, clippy::too_many_arguments, non_snake_case)]

use std::collections::HashMap;
use std::ffi::c_void;
use std::sync::OnceLock;

use super::cargs::CArg;
use super::context::Ret;
use crate::ff::api::ctypes::*;
use crate::ff::api::{gl_entry_table, Entry};

/// A C return value from what the call gave back.
pub trait FromRet {
    fn from_ret(r: Ret) -> Self;
}

impl FromRet for () {
    fn from_ret(_: Ret) -> Self {}
}

impl FromRet for GLenum {
    fn from_ret(r: Ret) -> Self {
        match r {
            Ret::Enum(v) => v,
            _ => 0,
        }
    }
}

impl FromRet for GLint {
    fn from_ret(r: Ret) -> Self {
        match r {
            Ret::Enum(v) => v as GLint,
            _ => 0,
        }
    }
}

impl FromRet for GLboolean {
    fn from_ret(r: Ret) -> Self {
        match r {
            Ret::Enum(v) => u8::from(v != 0),
            _ => 0,
        }
    }
}

impl FromRet for *const GLubyte {
    fn from_ret(r: Ret) -> Self {
        match r {
            Ret::Ptr(p) => p,
            _ => std::ptr::null(),
        }
    }
}

impl FromRet for *mut c_void {
    fn from_ret(r: Ret) -> Self {
        match r {
            Ret::Ptr(p) => p.cast_mut().cast(),
            _ => std::ptr::null_mut(),
        }
    }
}

macro_rules! ret_type {
    () => {
        ()
    };
    ($t:ty) => {
        $t
    };
}

macro_rules! define_exports {
    ($($variant:ident = $name:ident($form:ident; $($arg:ident: $ty:ty),*) $(-> $ret:ty)?;)*) => {
        $(
            #[no_mangle]
            pub unsafe extern "C" fn $name($($arg: $ty),*) $(-> $ret)? {
                let r = super::dispatch(Entry::$variant, &[$(CArg::from($arg)),*]);
                <ret_type!($($ret)?) as FromRet>::from_ret(r)
            }
        )*

        /// Every exported GL function by C name.
        fn gl_functions() -> HashMap<&'static str, usize> {
            HashMap::from([$((stringify!($name), $name as *const () as usize)),*])
        }
    };
}

gl_entry_table!(define_exports);

/// The address of an exported function (GL or OSMesa) by C name, or of the command the
/// registry names it an alias of (glBlendEquationEXT: glBlendEquation's), as Mesa's
/// OSMesaGetProcAddress answers it; null when there is none.
pub fn proc_address(name: &str) -> *const c_void {
    static TABLE: OnceLock<HashMap<&'static str, usize>> = OnceLock::new();
    let table = TABLE.get_or_init(|| {
        let mut t = gl_functions();
        t.extend(super::osmesa::functions());
        t
    });
    table
        .get(name)
        .or_else(|| table.get(crate::ff::glenum::registry_alias(name)?))
        .map_or(std::ptr::null(), |a| *a as *const c_void)
}
