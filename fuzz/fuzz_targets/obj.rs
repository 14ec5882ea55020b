//! OBJ meshes: `load_obj_str` on any text. The property: no panic, no abort, no hang; an
//! error is an `Err` with a message; a mesh that loads is well formed — one unit (or zero)
//! normal per position, every index in range, at least one triangle.

#![no_main]

use fixedfunc::mesh::load_obj_str;
use libfuzzer_sys::fuzz_target;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    match load_obj_str(&text, Path::new("fuzz.obj")) {
        Ok(loaded) => {
            let mesh = &loaded.mesh;
            assert_eq!(mesh.normals.len(), mesh.positions.len());
            assert!(!mesh.triangles.is_empty());
            let n = mesh.positions.len();
            for t in &mesh.triangles {
                assert!(
                    t.iter().all(|&i| (i as usize) < n),
                    "index out of range: {t:?} of {n}"
                );
            }
        }
        Err(e) => assert!(!e.to_string().trim().is_empty(), "empty message for {e:?}"),
    }
});
