//! The native path's GL values: the model's enums through `ff::glenum`'s one table (values
//! from the Khronos registry), plus the few conversions that are not one table lookup —
//! capabilities (GL_LIGHTi; REGISTER_COMBINERS_NV, which Mesa lacks) and combine sources
//! (GL_TEXTUREi, the crossbar). On a compatibility context every legacy format exists, so
//! the table's value is the one sent, with no substitution.

use crate::ff::glenum::{clip_plane, gl, light, registry, texture_unit as unit};
use crate::ff::{Capability, CombineSource};

use super::bindings::types::GLenum;

pub use crate::ff::glenum::gl as value;

/// A `GLint` view of an enum, for the `…i` entry points (every GL enum fits in 31 bits).
pub fn int(e: GLenum) -> i32 {
    e as i32
}

/// GL_TEXTUREi.
pub fn texture_unit(i: u8) -> GLenum {
    unit(i)
}

/// The glEnable name of a capability; `None` for REGISTER_COMBINERS_NV, which Mesa lacks
/// (the model records it; a draw with it enabled is refused).
pub fn capability(c: Capability) -> Option<GLenum> {
    match c {
        Capability::Light(i) => Some(light(i)),
        Capability::ClipPlane(i) => Some(clip_plane(i)),
        Capability::RegisterCombiners => None,
        other => Some(gl(other)),
    }
}

/// GL_CLIP_PLANEi.
pub fn clip_plane_name(i: u8) -> GLenum {
    clip_plane(i)
}

/// A combine source; TEXTUREn is the crossbar (ARB_texture_env_crossbar, GL 1.4).
pub fn combine_source(s: CombineSource) -> GLenum {
    match s {
        CombineSource::TextureUnit(n) => unit(n),
        other => gl(other),
    }
}

/// SRCn_RGB for argument index 0..2.
pub fn source_rgb(arg: usize) -> GLenum {
    registry::SRC0_RGB + arg as GLenum
}

/// SRCn_ALPHA for argument index 0..2.
pub fn source_alpha(arg: usize) -> GLenum {
    registry::SRC0_ALPHA + arg as GLenum
}

/// OPERANDn_RGB for argument index 0..2.
pub fn operand_rgb(arg: usize) -> GLenum {
    registry::OPERAND0_RGB + arg as GLenum
}

/// OPERANDn_ALPHA for argument index 0..2.
pub fn operand_alpha(arg: usize) -> GLenum {
    registry::OPERAND0_ALPHA + arg as GLenum
}

/// glCopyPixels' type (§4.3.3).
pub fn copy_kind(k: crate::ff::CopyKind) -> GLenum {
    match k {
        crate::ff::CopyKind::Color => registry::COLOR,
        crate::ff::CopyKind::Depth => registry::DEPTH,
        crate::ff::CopyKind::Stencil => registry::STENCIL,
    }
}

/// A pixel map's GLenum.
pub fn pixel_map(m: crate::ff::pixel_map::PixelMapName) -> GLenum {
    gl(m)
}

/// glPixelTransfer's pname and value (the integer ones as floats, which glPixelTransferf
/// reads as Mesa's glPixelTransferi passes them).
pub fn pixel_transfer(p: crate::ff::PixelTransferParam) -> (GLenum, f32) {
    use crate::ff::PixelTransferParam as P;
    const SCALE: [GLenum; 4] = [
        registry::RED_SCALE,
        registry::GREEN_SCALE,
        registry::BLUE_SCALE,
        registry::ALPHA_SCALE,
    ];
    const BIAS: [GLenum; 4] = [
        registry::RED_BIAS,
        registry::GREEN_BIAS,
        registry::BLUE_BIAS,
        registry::ALPHA_BIAS,
    ];
    match p {
        P::Scale(i, v) => (SCALE[usize::from(i.min(3))], v),
        P::Bias(i, v) => (BIAS[usize::from(i.min(3))], v),
        P::DepthScale(v) => (registry::DEPTH_SCALE, v),
        P::DepthBias(v) => (registry::DEPTH_BIAS, v),
        P::IndexShift(v) => (registry::INDEX_SHIFT, v as f32),
        P::IndexOffset(v) => (registry::INDEX_OFFSET, v as f32),
        P::MapColor(b) => (registry::MAP_COLOR, f32::from(u8::from(b))),
        P::MapStencil(b) => (registry::MAP_STENCIL, f32::from(u8::from(b))),
    }
}
