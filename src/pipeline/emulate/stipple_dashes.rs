//! The state a stippled line draw reads (`line_stipple`): the matrices, the viewport and
//! depth range, the enabled user clip planes and the stipple, gathered for one draw.

use super::line_stipple::{
    dashes_of_segments, segments, Dash, LineLength, Segment, StippleInputs, WindowTransform,
};
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
    let order: Vec<u32> = match &g.indices {
        Some(i) => i.clone(),
        None => (0..g.positions.len() as u32).collect(),
    };
    of_segments(state, stipple, g, &segments(g.primitive, &order))
}

/// The dashes of `segments` between the vertices of `g` (a polygon draw's outline).
pub fn of_segments(
    state: &FixedState,
    stipple: LineStipple,
    g: &Geometry,
    segments: &[Segment],
) -> Vec<Dash> {
    let planes: Vec<_> = state.clip_planes.iter().filter_map(|p| p.get()).collect();
    let inputs = StippleInputs {
        modelview: state.modelview_matrix(),
        projection: state.projection_matrix(),
        transform: WindowTransform::new(state.viewport, state.depth_range),
        clip_planes: &planes,
        stipple,
        length: if state.smooth.line {
            LineLength::Euclidean
        } else {
            LineLength::MajorAxis
        },
    };
    dashes_of_segments(segments, &g.positions, &inputs)
}
