//! glLogicOp (GL 1.5 §4.1.10): the 16 operations of Table 4.4, emulated (core GL's own
//! glLogicOp) against native on both headless backends, exact, and each pixel against the
//! table on bytes (`LogicOp::apply`). BLEND is on with (ZERO, ONE) throughout: GL turns
//! blending off while COLOR_LOGIC_OP is on, so a path that blended would keep the
//! destination (COPY would read d, not s) and fail; a wrong opcode fails its column.
//! INDEX_LOGIC_OP is enabled too and changes nothing in RGBA.

mod fidelity;
mod support;

use fidelity::{compare, ortho, probe_gl, Frame};
use fixedfunc::ff::glenum::GlEnum;
use fixedfunc::ff::LogicOp;
use support::Tolerance;

const OPS: [LogicOp; 16] = [
    LogicOp::Clear,
    LogicOp::And,
    LogicOp::AndReverse,
    LogicOp::Copy,
    LogicOp::AndInverted,
    LogicOp::Noop,
    LogicOp::Xor,
    LogicOp::Or,
    LogicOp::Nor,
    LogicOp::Equiv,
    LogicOp::Invert,
    LogicOp::OrReverse,
    LogicOp::CopyInverted,
    LogicOp::OrInverted,
    LogicOp::Nand,
    LogicOp::Set,
];

/// The fragment colour s and the cleared destination d, as bytes.
const S: [u8; 4] = [0x5A, 0xC3, 0x0F, 0xF0];
const D: [u8; 4] = [0x3C, 0x96, 0xFF, 0x81];

fn unit(b: [u8; 4]) -> String {
    b.map(|v| format!("{:?}", f32::from(v) / 255.0)).join(", ")
}

#[test]
fn the_sixteen_logic_ops_replace_blending() {
    let mut src = format!(
        "glViewport(0, 0, 16, 1);\n{}glClearColor({});\nglClear(GL_COLOR_BUFFER_BIT);\n\
         glEnable(GL_BLEND);\nglBlendFunc(GL_ZERO, GL_ONE);\nglEnable(GL_INDEX_LOGIC_OP);\n\
         glEnable(GL_COLOR_LOGIC_OP);\nglColor4f({});\n",
        ortho(16, 1),
        unit(D),
        unit(S)
    );
    for (i, op) in OPS.iter().enumerate() {
        src += &format!(
            "glLogicOp({});\nglRectf({i}, 0, {}, 1);\n",
            op.gl_name().unwrap_or("GL_NONE"),
            i + 1
        );
    }
    for p in compare("logic-op", &src, Frame::new(16, 1), Tolerance::EXACT) {
        for out in [&p.emulate, &p.native] {
            for (i, op) in OPS.iter().enumerate() {
                let want: [u8; 4] = std::array::from_fn(|c| op.apply(S[c], D[c]));
                probe_gl(&out.image, i as u32, 0, want, 0);
            }
        }
    }
}
