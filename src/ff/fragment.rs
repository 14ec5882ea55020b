//! Per-fragment operations and rasterisation state: alpha, stencil and depth tests,
//! blending, masks, polygon offset, culling (GL 1.5 §3.5, §4.1).
//!
//! One [`CompareFunc`] serves the alpha, depth and stencil tests and the depth-texture compare.
//! Parameters are stored apart from their enables, as in GL (glAlphaFunc while the alpha test
//! is disabled still sets the function); [`Toggle::get`] gives the `Option` a pipeline keys on.

use glam::Vec4;

/// A state value with its GL enable. Disabling keeps the value (GL keeps it too).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Toggle<T> {
    pub enabled: bool,
    pub value: T,
}

impl<T: Copy> Toggle<T> {
    /// Disabled, holding `value` (every capability starts disabled except DITHER, a plain
    /// `bool` in `FixedState`, and MULTISAMPLE, not modelled).
    pub const fn off(value: T) -> Self {
        Self {
            enabled: false,
            value,
        }
    }

    /// `Some(value)` when enabled: what a shader key or a sync step needs.
    pub fn get(&self) -> Option<T> {
        self.enabled.then_some(self.value)
    }
}

/// NEVER … ALWAYS. `passes(incoming, reference)`:
/// alpha test `α_frag op ref`, depth test `z_frag op z_buf`, stencil `(ref & mask) op
/// (stencil & mask)`, texture compare `r op D_t` (ARB_shadow).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CompareFunc {
    Never,
    Less,
    Equal,
    Lequal,
    Greater,
    Notequal,
    Gequal,
    Always,
}

impl CompareFunc {
    /// `a op b`.
    pub fn passes<T: PartialOrd>(self, a: T, b: T) -> bool {
        match self {
            CompareFunc::Never => false,
            CompareFunc::Less => a < b,
            CompareFunc::Equal => a == b,
            CompareFunc::Lequal => a <= b,
            CompareFunc::Greater => a > b,
            CompareFunc::Notequal => a != b,
            CompareFunc::Gequal => a >= b,
            CompareFunc::Always => true,
        }
    }
}

/// glAlphaFunc. GL default: ALWAYS, ref 0. The reference is clamped to [0, 1] when set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AlphaTest {
    pub func: CompareFunc,
    pub reference: f32,
}

impl AlphaTest {
    pub const DEFAULT: Self = Self {
        func: CompareFunc::Always,
        reference: 0.0,
    };

    /// ALPHA_TEST_REF as glGet answers it: the reference, with a NaN (which the clamp at
    /// glAlphaFunc keeps) read back as 0, as Mesa 22.3 answers it through every getter
    /// (measured, `tests/c/float_params.c`). The test itself compares a NaN reference as
    /// Mesa's llvmpipe does (`pipeline::emulate::uniforms`).
    pub fn answered_reference(&self) -> f32 {
        if self.reference.is_nan() {
            0.0
        } else {
            self.reference
        }
    }
}

/// glDepthFunc + glDepthMask. GL default: LESS, mask TRUE. With the depth test disabled the
/// depth buffer is neither tested nor written (§4.1.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct DepthTest {
    pub func: CompareFunc,
    pub write: bool,
}

impl DepthTest {
    pub const LESS_WRITE: Self = Self {
        func: CompareFunc::Less,
        write: true,
    };
}

/// glStencilOp actions. INCR/DECR saturate at 0 and 2^s − 1; the WRAP forms (GL 1.4) wrap.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StencilOp {
    Keep,
    Zero,
    Replace,
    Incr,
    Decr,
    Invert,
    IncrWrap,
    DecrWrap,
}

impl StencilOp {
    /// The new stencil value for an s-bit buffer: `max = 2^s − 1`.
    pub fn apply(self, value: u32, reference: i32, max: u32) -> u32 {
        match self {
            StencilOp::Keep => value,
            StencilOp::Zero => 0,
            // The reference is clamped to [0, 2^s − 1] (§4.1.4).
            StencilOp::Replace => (reference.max(0) as u32).min(max),
            StencilOp::Incr => value.saturating_add(1).min(max),
            StencilOp::Decr => value.saturating_sub(1),
            StencilOp::Invert => !value & max,
            StencilOp::IncrWrap => value.wrapping_add(1) & max,
            StencilOp::DecrWrap => value.wrapping_sub(1) & max,
        }
    }
}

/// The stencil bits the model assumes: every target the pipelines make with a stencil buffer
/// has 8 (D24S8).
pub const STENCIL_BITS: u32 = 8;

/// glStencilFunc + glStencilOp + glStencilMask. GL default: ALWAYS, ref 0, masks all ones
/// of the STENCIL_BITS (0xFF: Mesa's initial masks, which glGetIntegerv reports as 255),
/// KEEP/KEEP/KEEP.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct StencilTest {
    pub func: CompareFunc,
    pub reference: i32,
    pub value_mask: u32,
    pub write_mask: u32,
    /// Stencil test fails.
    pub fail: StencilOp,
    /// Stencil passes, depth fails.
    pub depth_fail: StencilOp,
    /// Both pass (or no depth test).
    pub depth_pass: StencilOp,
}

impl StencilTest {
    pub const DEFAULT: Self = Self {
        func: CompareFunc::Always,
        reference: 0,
        value_mask: (1 << STENCIL_BITS) - 1,
        write_mask: (1 << STENCIL_BITS) - 1,
        fail: StencilOp::Keep,
        depth_fail: StencilOp::Keep,
        depth_pass: StencilOp::Keep,
    };
}

/// glBlendFunc / glBlendFuncSeparate factors (GL 1.5 Table 4.2), c the constant colour of
/// glBlendColor.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BlendFactor {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    DstColor,
    OneMinusDstColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstAlpha,
    OneMinusDstAlpha,
    /// Source factor only: (f, f, f, 1) with f = min(As, 1 − Ad).
    SrcAlphaSaturate,
    /// (Rc, Gc, Bc, Ac)
    ConstantColor,
    /// (1, 1, 1, 1) − (Rc, Gc, Bc, Ac)
    OneMinusConstantColor,
    /// (Ac, Ac, Ac, Ac)
    ConstantAlpha,
    /// 1 − Ac on every component
    OneMinusConstantAlpha,
}

/// glBlendEquation (GL 1.5 §4.1.7): s, d the source and destination colours, S, D their
/// factors. GL default: FUNC_ADD. MIN and MAX ignore the factors.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BlendEquation {
    /// s·S + d·D
    FuncAdd,
    /// s·S − d·D
    FuncSubtract,
    /// d·D − s·S
    FuncReverseSubtract,
    /// min(s, d)
    Min,
    /// max(s, d)
    Max,
}

/// glBlendFuncSeparate (glBlendFunc sets the RGB and alpha factors alike) and
/// glBlendEquation. GL default: ONE, ZERO for both, FUNC_ADD. The constant colour is
/// `FixedState::blend_color`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Blend {
    pub src_rgb: BlendFactor,
    pub dst_rgb: BlendFactor,
    pub src_alpha: BlendFactor,
    pub dst_alpha: BlendFactor,
    pub equation: BlendEquation,
}

impl Blend {
    pub const ONE_ZERO: Self = Self {
        src_rgb: BlendFactor::One,
        dst_rgb: BlendFactor::Zero,
        src_alpha: BlendFactor::One,
        dst_alpha: BlendFactor::Zero,
        equation: BlendEquation::FuncAdd,
    };
}

/// glLogicOp (GL 1.5 §4.1.10, Table 4.4): the colour written is op(s, d) bit by bit, s the
/// fragment's colour and d the framebuffer's, as unsigned integers of the buffer's bits.
/// GL default: COPY. While COLOR_LOGIC_OP is on, blending is off (§4.1.10).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LogicOp {
    /// 0
    Clear,
    /// s ∧ d
    And,
    /// s ∧ ¬d
    AndReverse,
    /// s
    Copy,
    /// ¬s ∧ d
    AndInverted,
    /// d
    Noop,
    /// s ⊕ d
    Xor,
    /// s ∨ d
    Or,
    /// ¬(s ∨ d)
    Nor,
    /// ¬(s ⊕ d)
    Equiv,
    /// ¬d
    Invert,
    /// s ∨ ¬d
    OrReverse,
    /// ¬s
    CopyInverted,
    /// ¬s ∨ d
    OrInverted,
    /// ¬(s ∧ d)
    Nand,
    /// all 1
    Set,
}

impl LogicOp {
    /// Table 4.4 on one 8-bit component.
    pub fn apply(self, s: u8, d: u8) -> u8 {
        match self {
            LogicOp::Clear => 0,
            LogicOp::And => s & d,
            LogicOp::AndReverse => s & !d,
            LogicOp::Copy => s,
            LogicOp::AndInverted => !s & d,
            LogicOp::Noop => d,
            LogicOp::Xor => s ^ d,
            LogicOp::Or => s | d,
            LogicOp::Nor => !(s | d),
            LogicOp::Equiv => !(s ^ d),
            LogicOp::Invert => !d,
            LogicOp::OrReverse => s | !d,
            LogicOp::CopyInverted => !s,
            LogicOp::OrInverted => !s | d,
            LogicOp::Nand => !(s & d),
            LogicOp::Set => 0xff,
        }
    }
}

/// glHint targets (GL 1.5 §5.6, Table 5.7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum HintTarget {
    PerspectiveCorrection,
    PointSmooth,
    LineSmooth,
    PolygonSmooth,
    Fog,
    /// GL 1.3's TEXTURE_COMPRESSION_HINT.
    TextureCompression,
    /// GL 1.4's GENERATE_MIPMAP_HINT.
    GenerateMipmap,
}

/// glHint modes. GL default: DONT_CARE for every target.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum HintMode {
    Fastest,
    Nicest,
    DontCare,
}

/// The hints: how an implementation may trade quality for speed. State only: neither
/// path changes its arithmetic for them (Mesa's llvmpipe ignores them too).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Hints {
    pub perspective_correction: HintMode,
    pub point_smooth: HintMode,
    pub line_smooth: HintMode,
    pub polygon_smooth: HintMode,
    pub fog: HintMode,
    pub texture_compression: HintMode,
    pub generate_mipmap: HintMode,
}

impl Hints {
    pub const DEFAULT: Self = Self {
        perspective_correction: HintMode::DontCare,
        point_smooth: HintMode::DontCare,
        line_smooth: HintMode::DontCare,
        polygon_smooth: HintMode::DontCare,
        fog: HintMode::DontCare,
        texture_compression: HintMode::DontCare,
        generate_mipmap: HintMode::DontCare,
    };

    /// glHint(target, mode).
    pub fn set(&mut self, target: HintTarget, mode: HintMode) {
        let slot = match target {
            HintTarget::PerspectiveCorrection => &mut self.perspective_correction,
            HintTarget::PointSmooth => &mut self.point_smooth,
            HintTarget::LineSmooth => &mut self.line_smooth,
            HintTarget::PolygonSmooth => &mut self.polygon_smooth,
            HintTarget::Fog => &mut self.fog,
            HintTarget::TextureCompression => &mut self.texture_compression,
            HintTarget::GenerateMipmap => &mut self.generate_mipmap,
        };
        *slot = mode;
    }

    /// Every target with its mode.
    pub fn all(&self) -> [(HintTarget, HintMode); 7] {
        [
            (
                HintTarget::PerspectiveCorrection,
                self.perspective_correction,
            ),
            (HintTarget::PointSmooth, self.point_smooth),
            (HintTarget::LineSmooth, self.line_smooth),
            (HintTarget::PolygonSmooth, self.polygon_smooth),
            (HintTarget::Fog, self.fog),
            (HintTarget::TextureCompression, self.texture_compression),
            (HintTarget::GenerateMipmap, self.generate_mipmap),
        ]
    }
}

/// glColorMask. GL default: all TRUE.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ColorMask {
    pub r: bool,
    pub g: bool,
    pub b: bool,
    pub a: bool,
}

impl ColorMask {
    pub const ALL: Self = Self {
        r: true,
        g: true,
        b: true,
        a: true,
    };
    /// Every channel write-protected (a depth- or stencil-only pass).
    pub const NONE: Self = Self {
        r: false,
        g: false,
        b: false,
        a: false,
    };
}

/// Which rasterisation modes get the offset (POLYGON_OFFSET_FILL/LINE/POINT). GL default: none.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct OffsetEnables {
    pub fill: bool,
    pub line: bool,
    pub point: bool,
}

/// glPolygonMode modes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PolygonMode {
    Point,
    Line,
    Fill,
}

/// Front, back or both: glCullFace, glPolygonMode, glMaterial, glColorMaterial.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Face {
    Front,
    Back,
    FrontAndBack,
}

/// glFrontFace. GL default: CCW.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FrontFace {
    Cw,
    Ccw,
}

/// glShadeModel. GL default: SMOOTH.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ShadeModel {
    Flat,
    Smooth,
}

/// glClear's mask (COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct ClearMask {
    pub color: bool,
    pub depth: bool,
    pub stencil: bool,
    /// ACCUM_BUFFER_BIT: the accumulation buffer (`ff::accum`); nothing without one.
    pub accum: bool,
}

impl ClearMask {
    pub const ALL: Self = Self {
        color: true,
        depth: true,
        stencil: true,
        accum: false,
    };
}

/// glClearColor / glClearDepth / glClearStencil / glClearAccum. GL default: (0,0,0,0), 1, 0,
/// (0,0,0,0). Colour and depth are clamped to [0, 1] when set, the accumulation value to
/// [−1, 1] (GL 1.5 §4.2.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClearValues {
    pub color: Vec4,
    /// A double, as glClearDepth takes it and Mesa keeps it: 0.3 clears a 24-bit buffer
    /// to ⌊0.3·(2²⁴−1) + ½⌋ = 0x4CCCCC, where 0.3 rounded to a float first gives 0x4CCCCD.
    pub depth: f64,
    pub stencil: i32,
    pub accum: Vec4,
}

impl ClearValues {
    pub const DEFAULT: Self = Self {
        color: Vec4::ZERO,
        depth: 1.0,
        stencil: 0,
        accum: Vec4::ZERO,
    };
}

/// glViewport. GL default: (0, 0, window width, window height); here (0, 0, 0, 0) until the
/// pipeline sets the target size.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Viewport {
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
}

/// glScissor's box in window coordinates (GL 1.5 §4.1.2): a fragment at (x_w, y_w) passes
/// when x ≤ x_w < x + width and y ≤ y_w < y + height; glClear obeys it too (§4.2.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct ScissorBox {
    pub x: i32,
    pub y: i32,
    /// ≥ 0, else INVALID_VALUE.
    pub width: i32,
    /// ≥ 0, else INVALID_VALUE.
    pub height: i32,
}

/// glDepthRange, clamped to [0, 1] when set: z_w = z_ndc·(f − n)/2 + (n + f)/2.
/// GL default: 0, 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DepthRange {
    pub near: f32,
    pub far: f32,
}

impl DepthRange {
    pub const DEFAULT: Self = Self {
        near: 0.0,
        far: 1.0,
    };

    /// Window z of an NDC z.
    pub fn window_z(&self, z_ndc: f32) -> f32 {
        z_ndc * (self.far - self.near) * 0.5 + (self.near + self.far) * 0.5
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compare_funcs() {
        use CompareFunc::*;
        let table = [
            (Never, 1, 2, false),
            (Less, 1, 2, true),
            (Less, 2, 2, false),
            (Equal, 2, 2, true),
            (Lequal, 2, 2, true),
            (Greater, 3, 2, true),
            (Notequal, 2, 2, false),
            (Gequal, 2, 2, true),
            (Always, 0, 9, true),
        ];
        for (f, a, b, want) in table {
            assert_eq!(f.passes(a, b), want, "{f:?} {a} {b}");
        }
    }

    /// Table 4.4 on the patterns s = 1100, d = 1010: each opcode's truth table.
    #[test]
    fn logic_ops_follow_table_4_4() {
        use LogicOp::*;
        let (s, d) = (0b1100, 0b1010);
        let table = [
            (Clear, 0b0000),
            (And, 0b1000),
            (AndReverse, 0b0100),
            (Copy, 0b1100),
            (AndInverted, 0b0010),
            (Noop, 0b1010),
            (Xor, 0b0110),
            (Or, 0b1110),
            (Nor, 0b0001),
            (Equiv, 0b1001),
            (Invert, 0b0101),
            (OrReverse, 0b1101),
            (CopyInverted, 0b0011),
            (OrInverted, 0b1011),
            (Nand, 0b0111),
            (Set, 0b1111),
        ];
        for (op, want) in table {
            assert_eq!(op.apply(s, d) & 0b1111, want, "{op:?}");
        }
    }

    #[test]
    fn stencil_wrap_and_saturate_like_piglit_stencil_wrap() {
        let max = 255;
        let mut v = 0;
        for _ in 0..max + 5 {
            v = StencilOp::Incr.apply(v, 0, max);
        }
        assert_eq!(v, max);
        let mut v = 0;
        for _ in 0..max + 5 {
            v = StencilOp::IncrWrap.apply(v, 0, max);
        }
        assert_eq!(v, 4);
        assert_eq!(StencilOp::Decr.apply(0, 0, max), 0);
        let mut v = 0;
        for _ in 0..5 {
            v = StencilOp::DecrWrap.apply(v, 0, max);
        }
        assert_eq!(v, 251);
        assert_eq!(StencilOp::Replace.apply(0, 300, max), 255);
        assert_eq!(StencilOp::Invert.apply(0x0f, 0, max), 0xf0);
    }
}
