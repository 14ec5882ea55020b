//! Generates the bindings of the native (compatibility-profile) pipeline: every OpenGL 2.1
//! entry point, fixed function included, as a struct of function pointers loaded at run time
//! (gl_generator's StructGenerator), so that the legacy calls are never declared by hand.

use std::env;
use std::fs::File;
use std::path::Path;

use gl_generator::{Api, Fallbacks, Profile, Registry, StructGenerator};

fn main() {
    let out = env::var("OUT_DIR").expect("cargo sets OUT_DIR for build scripts");
    let path = Path::new(&out).join("gl_compat.rs");
    let mut file = File::create(&path).expect("OUT_DIR is writable");
    Registry::new(
        Api::Gl,
        (2, 1),
        Profile::Compatibility,
        Fallbacks::All,
        ["GL_ARB_framebuffer_object", "GL_EXT_stencil_wrap"],
    )
    .write_bindings(StructGenerator, &mut file)
    .expect("the GL registry writes");
    println!("cargo:rerun-if-changed=build.rs");
}
