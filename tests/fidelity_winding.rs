//! Indexed TRIANGLES under every front face and culled face: the emulated path gives
//! llvmpipe the faces a pass keeps counter-clockwise in its own pixel rows, swapping each
//! triangle's first two corners and the core front face where GL's are clockwise there
//! (`pipeline::emulate::draw::Winding`). The same faces must be kept, lit on the same side
//! and coloured from the same provoking vertex as on Mesa's native path: exact images.

mod fidelity;
mod support;

use fidelity::{compare, script_file, Frame};
use support::Tolerance;

/// The back material of `winding.c`, lit by the light behind the mesh: pinkish, red and
/// blue well above green.
fn is_back_material(p: [u8; 4]) -> bool {
    let [r, g, b, _] = p.map(u16::from);
    r > 2 * g && b > 2 * g
}

/// Each 64×64 cell keeps one of the two copies (the mirrored one winds the other way).
/// Cells, left to right: FrontFace CCW + CullFace BACK keeps the front faces; CW + FRONT
/// and CCW + FRONT keep the back faces, which show the back material; CW + BACK keeps the
/// front faces. The first two keep faces counter-clockwise in GL's window space, drawn
/// reversed. Smooth and flat rows alike; exact between paths.
#[test]
fn culled_triangles_keep_the_same_faces_as_mesa() {
    let pairs = compare(
        "winding",
        &script_file("winding"),
        Frame::new(256, 128),
        Tolerance::EXACT,
    );
    // Whether each cell, left to right, keeps back faces.
    let keeps_back = [false, true, true, false];
    for p in pairs {
        for (path, out) in [("emulate", &p.emulate), ("native", &p.native)] {
            for row in 0..2u32 {
                for (cell, back) in keeps_back.iter().enumerate() {
                    let (x0, y0) = (64 * cell as u32, 64 * (1 - row));
                    let drawn: Vec<[u8; 4]> = (0..64 * 64)
                        .map(|i| out.image.get_pixel(x0 + i % 64, y0 + i / 64).0)
                        .filter(|px| px[..3] != [26, 26, 26])
                        .collect();
                    assert!(
                        drawn.len() > 400,
                        "{} {path}: row {row} cell {cell} drew {} pixels",
                        p.backend,
                        drawn.len()
                    );
                    let pink = drawn.iter().filter(|px| is_back_material(**px)).count();
                    let share = pink as f64 / drawn.len() as f64;
                    assert!(
                        if *back { share > 0.9 } else { share < 0.1 },
                        "{} {path}: row {row} cell {cell}: {:.0}% back material",
                        p.backend,
                        share * 100.0
                    );
                }
            }
        }
    }
}
