//! `generate(&ShaderKey)`: the GLSL 330 source of one fixed-function program. It sees only
//! the key (never the state), and emits only the stages the key enables: a key with one
//! texture unit has no code for any other unit, a key without lighting has no lighting code.
//!
//! Attribute locations are fixed, sixteen in all (llvmpipe's MAX_VERTEX_ATTRIBS): 0
//! position (vec4), 1 normal, 2 colour, 3 + u texture coordinate of unit u, then the edge
//! attribute of split polygons — which the window position of a line stipple's dash ends
//! shares, the two never being drawn together —, then the shade position and normal (the
//! provoking vertex's, which flat shading lights), the secondary colour and the fog
//! coordinate (GL 1.4). Under flat shading the colours are read only at the provoking
//! vertex, so a split polygon's colour arrays are bound to copies holding each corner's
//! provoking value (`draw`), and the colours need no shade locations. A vertex array that a
//! draw lacks is disabled and its current value is set as a constant attribute, so "per
//! vertex or per draw" never changes the key.

mod combiners;
mod fragment;
mod pixels;
mod vertex;

pub use vertex::uniform_point_size;

use super::key::ShaderKey;
use super::uniforms::UniformSource;

pub const ATTRIB_POSITION: u32 = 0;
pub const ATTRIB_NORMAL: u32 = 1;
pub const ATTRIB_COLOR: u32 = 2;
pub const ATTRIB_TEXCOORD0: u32 = 3;
/// The edge attribute of split polygons (`polygon`), after the last texture unit's.
pub const ATTRIB_EDGE: u32 = ATTRIB_TEXCOORD0 + crate::ff::MAX_TEXTURE_UNITS as u32;
/// Window coordinates computed on the CPU (`key::PositionSource::Window`): the dashes of
/// stippled lines, which have no polygon edges.
pub const ATTRIB_WINDOW: u32 = ATTRIB_EDGE;
/// The shade attributes: the position and normal of the provoking vertex of the primitive
/// a vertex belongs to (`assembly`), what flat shading lights.
pub const ATTRIB_SHADE_POSITION: u32 = ATTRIB_EDGE + 1;
pub const ATTRIB_SHADE_NORMAL: u32 = ATTRIB_EDGE + 2;
/// The secondary colour (GL 1.4).
pub const ATTRIB_SECONDARY: u32 = ATTRIB_EDGE + 3;
/// The fog coordinate (GL 1.4), read under FOG_COORD_SRC = FOG_COORD.
pub const ATTRIB_FOG_COORD: u32 = ATTRIB_EDGE + 4;
/// One past the last location: at most MAX_VERTEX_ATTRIBS = 16 on llvmpipe.
pub const ATTRIB_COUNT: u32 = ATTRIB_EDGE + 5;
/// Where the per-vertex material values of a draw with glMaterial inside glBegin/glEnd go:
/// core GL gives 16 attributes and the layer uses them all, so the values take the
/// locations of the last texture units' coordinates, the first slot present (in
/// `MaterialSlot::bit` order of `mask`) unit 7's, the next unit 6's. The draw checks that
/// no unit it reads is among them (`Emulate::draw`).
pub fn material_location(mask: u16, bit: usize) -> u32 {
    let rank = (mask & ((1u16 << bit) - 1)).count_ones();
    ATTRIB_TEXCOORD0 + crate::ff::MAX_TEXTURE_UNITS as u32 - 1 - rank
}

/// Half the side of the viewport a `PositionSource::Window` pass draws with: the viewport
/// (−S, −S, 2S, 2S) has scale S and translation 0, so x_w = (x_w / S) · S exactly for a
/// power of two S. 2S is llvmpipe's MAX_VIEWPORT_DIMS; windows beyond S pixels are clipped.
pub const WINDOW_SPAN: i32 = 8192;

/// A generated program: both sources and the uniforms each declared.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GeneratedProgram {
    pub vertex: String,
    pub fragment: String,
    pub uniforms: Vec<UniformSource>,
}

pub fn generate(key: &ShaderKey) -> GeneratedProgram {
    let vs = vertex::generate(&key.vertex, &key.fragment);
    let fs = fragment::generate(&key.fragment);
    let mut uniforms = vs.uniforms().to_vec();
    for u in fs.uniforms() {
        if !uniforms.contains(u) {
            uniforms.push(*u);
        }
    }
    GeneratedProgram {
        vertex: vs.finish(),
        fragment: fs.finish(),
        uniforms,
    }
}
