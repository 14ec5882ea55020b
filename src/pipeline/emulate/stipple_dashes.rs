//! The state a stippled line draw reads (`line_stipple`): the matrices, the viewport and
//! depth range, the enabled user clip planes and the stipple, gathered for one draw.

use super::line_stipple::{dashes, Dash, StippleInputs, WindowTransform};
use crate::ff::{FixedState, Geometry, LineStipple, Primitive};

/// True for the primitives drawn as lines (LINE_STIPPLE applies to them directly).
pub fn is_line(p: Primitive) -> bool {
    matches!(
        p,
        Primitive::Lines | Primitive::LineStrip | Primitive::LineLoop
    )
}

/// The dashes of the line draw `g` under `state` and `stipple`.
pub fn of_draw(state: &FixedState, stipple: LineStipple, g: &Geometry) -> Vec<Dash> {
    let planes: Vec<_> = state.clip_planes.iter().filter_map(|p| p.get()).collect();
    let inputs = StippleInputs {
        modelview: state.modelview_matrix(),
        projection: state.projection_matrix(),
        transform: WindowTransform::new(state.viewport, state.depth_range),
        clip_planes: &planes,
        stipple,
    };
    let order: Vec<u32> = match &g.indices {
        Some(i) => i.clone(),
        None => (0..g.positions.len() as u32).collect(),
    };
    dashes(g.primitive, &g.positions, &order, &inputs)
}
