//! The raster state that stays GL state on the core path (depth, stencil, blend with its
//! equation and constant colour, logic op, masks, polygon offset, culling, polygon mode,
//! line width, viewport, scissor, the CLIP_DISTANCE enables of the user clip planes, depth
//! range), synced before each draw through a shadow copy of what was last sent: an
//! unchanged value is not sent again, and both outcomes are counted.

use crate::vocab::PolygonOffset;
use glam::Vec4;
use glow::HasContext;

use super::conv;
use super::draw::Winding;
use super::key::{PointKey, PositionSource};
use super::polygon::PolygonPass;
use super::shadergen::{uniform_point_size, WINDOW_SPAN};
use crate::ff::{
    Blend, ColorMask, DepthRange, DepthTest, Face, FixedState, FrontFace, LogicOp, OffsetEnables,
    PolygonMode, ScissorBox, StencilTest, Toggle, Viewport, MAX_CLIP_PLANES,
};

/// A core GL call of one argument that glow 0.16 does not wrap (glLogicOp, glPointSize),
/// looked up once when the pipeline is made (`None`: the driver has none, and the call
/// does nothing).
pub struct CoreCall<A>(Option<unsafe extern "system" fn(A)>);

impl<A> Clone for CoreCall<A> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<A> Copy for CoreCall<A> {}

impl<A> Default for CoreCall<A> {
    fn default() -> Self {
        CoreCall(None)
    }
}

impl<A> CoreCall<A> {
    /// `name`, whose C type must be void (A).
    fn load(ctx: &crate::gpu::GpuContext, name: &str) -> CoreCall<A> {
        let p = ctx.proc_address(name);
        // SAFETY: a non-null address from the context's loader is `name`, of C type
        // void (A) for each use below; `Option<fn>` has the same layout as a nullable
        // pointer.
        CoreCall(unsafe {
            std::mem::transmute::<*const std::ffi::c_void, Option<unsafe extern "system" fn(A)>>(p)
        })
    }

    fn call(self, a: A) {
        if let Some(f) = self.0 {
            // SAFETY: the call on the current context.
            unsafe { f(a) }
        }
    }
}

/// The core calls the sync makes that glow lacks: glLogicOp (COLOR_LOGIC_OP is still
/// toggled without it, with the driver's opcode) and glPointSize.
#[derive(Clone, Copy, Default)]
pub struct CoreCalls {
    logic_op: CoreCall<u32>,
    point_size: CoreCall<f32>,
}

impl CoreCalls {
    pub fn load(ctx: &crate::gpu::GpuContext) -> CoreCalls {
        CoreCalls {
            logic_op: CoreCall::load(ctx, "glLogicOp"),
            point_size: CoreCall::load(ctx, "glPointSize"),
        }
    }
}

/// The viewport of a `PositionSource::Window` pass: scale S, translation 0.
const WINDOW_VIEWPORT: Viewport = Viewport {
    x: -WINDOW_SPAN,
    y: -WINDOW_SPAN,
    width: 2 * WINDOW_SPAN,
    height: 2 * WINDOW_SPAN,
};

/// One piece of state as last sent (`None` = never sent).
struct Sent<T>(Option<T>);

impl<T: PartialEq + Copy> Sent<T> {
    fn sync(&mut self, value: T, counts: &mut (u64, u64), send: impl FnOnce(T)) {
        if self.0 == Some(value) {
            counts.1 += 1;
        } else {
            send(value);
            self.0 = Some(value);
            counts.0 += 1;
        }
    }
}

impl<T> Default for Sent<T> {
    fn default() -> Self {
        Sent(None)
    }
}

#[derive(Default)]
pub struct RasterSync {
    /// The whole toggle, not its `get()`: glClear honours glDepthMask and glStencilMask
    /// whether or not the tests are enabled (GL 1.5 §4.2.3), so a mask changed while its
    /// test is off must still be sent.
    depth: Sent<Toggle<DepthTest>>,
    stencil: Sent<Toggle<StencilTest>>,
    /// BLEND with its factors and equation, and the constant colour.
    blend: Sent<(Option<Blend>, Vec4)>,
    color_mask: Sent<ColorMask>,
    offset: Sent<(OffsetEnables, PolygonOffset)>,
    cull: Sent<(Option<Face>, FrontFace)>,
    polygon_mode: Sent<PolygonMode>,
    /// glLineWidth.
    line_width: Sent<f32>,
    /// PROGRAM_POINT_SIZE: on only for a points pass whose sizes are attenuated by
    /// distance (the program's gl_PointSize); otherwise glPointSize carries the size
    /// (`point_size`), as in Mesa's rasteriser state (`uniform_point_size`).
    program_point_size: Sent<bool>,
    point_size: Sent<f32>,
    /// LINE_SMOOTH: core GL keeps it, and llvmpipe draws it with the same aaline stage as
    /// Mesa's compatibility context (round points are the program's, `PointShape::Round`).
    line_smooth: Sent<bool>,
    viewport: Sent<Viewport>,
    /// COLOR_LOGIC_OP with its opcode (core GL has glLogicOp and, like GL 1.x, blends
    /// nothing while it is on).
    logic_op: Sent<Option<LogicOp>>,
    calls: CoreCalls,
    /// The enabled user clip planes as bits: CLIP_DISTANCEi for plane i, which the
    /// program writes (the key lists the same planes).
    clip_planes: Sent<u8>,
    /// The scissor box in force (`None`: test off, or never set = the whole target).
    scissor: Sent<Option<ScissorBox>>,
    depth_range: Sent<DepthRange>,
    /// (sent, skipped)
    counts: (u64, u64),
}

fn toggle(gl: &glow::Context, cap: u32, on: bool) {
    unsafe {
        if on {
            gl.enable(cap)
        } else {
            gl.disable(cap)
        }
    }
}

impl RasterSync {
    /// A sync that makes the calls glow lacks through `calls`.
    pub fn new(calls: CoreCalls) -> RasterSync {
        RasterSync {
            calls,
            ..RasterSync::default()
        }
    }

    /// Calls sent and skipped so far.
    pub fn counts(&self) -> (u64, u64) {
        self.counts
    }

    /// Brings the GL raster state in line with the model before a draw or a clear; a draw
    /// pass brings its own core polygon mode and cull face (`polygon`), a clear uses the
    /// state's front mode and cull face (neither affects it).
    /// Core GL's front face is the model's, or its opposite for a draw whose corners are
    /// reversed (`draw::Winding`).
    pub fn sync(
        &mut self,
        gl: &glow::Context,
        s: &FixedState,
        pass: Option<&PolygonPass>,
        winding: Winding,
    ) {
        let c = &mut self.counts;
        let window = pass.is_some_and(|p| p.positions == PositionSource::Window);
        let (viewport, depth_range) = if window {
            (WINDOW_VIEWPORT, DepthRange::DEFAULT)
        } else {
            (s.viewport, s.depth_range)
        };
        self.viewport.sync(viewport, c, |v| unsafe {
            gl.viewport(v.x, v.y, v.width, v.height)
        });
        let planes = s
            .clip_planes
            .iter()
            .enumerate()
            .filter(|(_, p)| p.enabled)
            .fold(0u8, |bits, (i, _)| bits | (1 << i));
        self.clip_planes.sync(planes, c, |bits| {
            for i in 0..MAX_CLIP_PLANES {
                toggle(gl, glow::CLIP_DISTANCE0 + i as u32, bits & (1 << i) != 0);
            }
        });
        // Also before a clear: glClear obeys the scissor (GL 1.5 §4.2.3).
        self.scissor.sync(s.scissor_box(), c, |b| unsafe {
            toggle(gl, glow::SCISSOR_TEST, b.is_some());
            if let Some(b) = b {
                gl.scissor(b.x, b.y, b.width, b.height);
            }
        });
        self.depth_range.sync(depth_range, c, |r| unsafe {
            gl.depth_range_f64(f64::from(r.near), f64::from(r.far))
        });
        self.color_mask.sync(s.color_mask, c, |m| unsafe {
            gl.color_mask(m.r, m.g, m.b, m.a)
        });
        self.line_width
            .sync(s.line_width, c, |w| unsafe { gl.line_width(w) });
        let draws_points = pass.is_some_and(|p| p.draws_points());
        let points = PointKey::of(s);
        self.program_point_size
            .sync(draws_points && points.attenuated, c, |on| {
                toggle(gl, glow::PROGRAM_POINT_SIZE, on)
            });
        if draws_points && !points.attenuated {
            let limits = (s.point_params.size_min, s.point_params.size_max);
            let size = uniform_point_size(s.point_size, limits, points.shape);
            self.point_size
                .sync(size, c, |v| self.calls.point_size.call(v));
        }
        self.line_smooth
            .sync(s.smooth.line, c, |on| toggle(gl, glow::LINE_SMOOTH, on));
        self.sync_tests(gl, s, pass);
        let (mode, cull) = match pass {
            Some(p) => (p.mode, p.cull),
            None => (s.polygon_mode.front, s.cull_face.get()),
        };
        self.sync_faces(gl, mode, cull, winding.front_face(s.front_face));
    }

    fn sync_tests(&mut self, gl: &glow::Context, s: &FixedState, pass: Option<&PolygonPass>) {
        let c = &mut self.counts;
        // With the depth test off GL writes no depth either (§4.1.5), so for a draw the mask
        // only matters while it is on; a clear obeys it regardless (§4.2.3).
        self.depth.sync(s.depth_test, c, |d| unsafe {
            toggle(gl, glow::DEPTH_TEST, d.enabled);
            gl.depth_func(conv::value(d.value.func));
            gl.depth_mask(d.value.write);
        });
        self.stencil.sync(s.stencil_test, c, |t| unsafe {
            toggle(gl, glow::STENCIL_TEST, t.enabled);
            let t = t.value;
            gl.stencil_func(conv::value(t.func), t.reference, t.value_mask);
            gl.stencil_op(
                conv::value(t.fail),
                conv::value(t.depth_fail),
                conv::value(t.depth_pass),
            );
            gl.stencil_mask(t.write_mask);
        });
        self.blend
            .sync((s.blend.get(), s.blend_color), c, |(b, k)| unsafe {
                toggle(gl, glow::BLEND, b.is_some());
                if let Some(b) = b {
                    gl.blend_func_separate(
                        conv::value(b.src_rgb),
                        conv::value(b.dst_rgb),
                        conv::value(b.src_alpha),
                        conv::value(b.dst_alpha),
                    );
                    gl.blend_equation(conv::value(b.equation));
                    gl.blend_color(k.x, k.y, k.z, k.w);
                }
            });
        let call = self.calls.logic_op;
        self.logic_op.sync(s.logic_op.get(), c, |op| {
            toggle(gl, glow::COLOR_LOGIC_OP, op.is_some());
            if let Some(op) = op {
                call.call(conv::value(op));
            }
        });
        // A pass offsets in its own mode only (`polygon`); a clear sends the state's enables.
        let enables = match pass {
            Some(p) => OffsetEnables {
                fill: p.offset,
                line: p.offset,
                point: p.offset,
            },
            None => s.offset_enables,
        };
        self.offset
            .sync((enables, s.polygon_offset), c, |(e, o)| unsafe {
                toggle(gl, glow::POLYGON_OFFSET_FILL, e.fill);
                toggle(gl, glow::POLYGON_OFFSET_LINE, e.line);
                toggle(gl, glow::POLYGON_OFFSET_POINT, e.point);
                gl.polygon_offset(o.factor, o.units);
            });
    }

    /// Core GL has one polygon mode for both faces: the pass says which, and which face
    /// to cull so that mode reaches only its own faces.
    fn sync_faces(
        &mut self,
        gl: &glow::Context,
        mode: PolygonMode,
        cull: Option<Face>,
        front_face: FrontFace,
    ) {
        let c = &mut self.counts;
        self.cull.sync((cull, front_face), c, |(f, ff)| unsafe {
            toggle(gl, glow::CULL_FACE, f.is_some());
            if let Some(f) = f {
                gl.cull_face(conv::value(f));
            }
            gl.front_face(conv::value(ff));
        });
        self.polygon_mode.sync(mode, c, |m| unsafe {
            gl.polygon_mode(glow::FRONT_AND_BACK, conv::value(m))
        });
    }

    /// Forget what was sent (after something else touched GL state).
    pub fn invalidate(&mut self) {
        let counts = self.counts;
        *self = RasterSync::new(self.calls);
        self.counts = counts;
    }
}
