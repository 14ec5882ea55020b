//! The accumulation buffer (GL 1.5 §4.2.4) as Mesa keeps it: four signed 16-bit values per
//! pixel, 1.0 stored as 32767. The spec leaves the representation to the implementation;
//! these are the rules measured on Mesa 22.3's OSMesa (16 accumulation bits per channel
//! whatever OSMesaCreateContextExt asks for beyond 0), with worked examples:
//!
//! - `q(x)` = x truncated toward zero to an integer, then wrapped to 16 bits (C's
//!   `(GLshort)x` on x86: the low 16 bits of the 32-bit truncation; 0 beyond ±2³¹).
//! - colours are read as c = k/255 from the unorm8 colour buffer.
//! - CLEAR (glClearAccum clamps to [−1, 1]): a = q((v·65535 − 1)/2), the signed-short
//!   mapping of §2.14 (Table 2.9). 0.1 → q(3276.25) = 3276; 1 → 32767; −0.5 → −16384 (not
//!   −16383: RETURN −1 then writes 128, not 127); −1 → −32768.
//! - ACCUM v: a = wrap(a + q(c·(v·32767))). (1, ½, ¼) ×0.5 then (0, 1, 0) ×0.5:
//!   R 16383 + 0, G q(128/255·16383.5) = 8223 + 16383 = 24606, B q(64/255·16383.5) = 4111.
//!   The sum wraps: 26213 (0.8) + 16383 = 42596 → −22940, which RETURN writes as 0.
//! - LOAD v: a = q(c·(v·32767)). LOAD 2 of c = 1 gives q(65534) = −2.
//! - ADD v: a = wrap(a + q(v·32767)). ADD 1.5 adds q(49150.5) = −16386.
//! - MULT v: a = q(a·v). 16383 × 0.5 → 8191; 16383 × 3 → q(49149) = −16387.
//! - RETURN v: c = a·(v/32767) clamped to [0, 1], stored as unorm8 rounding half to even:
//!   24606 × 1 → 191.49 → 191; 8191 → 63.74 → 64; a negative value writes 0.
//!
//! The scissor box limits the clear and every operation; RETURN writes through the colour
//! mask and no other per-fragment operation (§4.2.4).

use glam::Vec4;

/// glAccum's op. GL has no default.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AccumOp {
    Accum,
    Load,
    Return,
    Mult,
    Add,
}

/// The value that stands for 1.0.
pub const ACCUM_ONE: f32 = 32767.0;

/// Accumulation bits per channel of a window made with any accumulation bits (Mesa's
/// OSMesa: 8, 16 and 32 asked all give 16).
pub const ACCUM_BITS: u8 = 16;

/// `(GLshort)x` as Mesa's build computes it on x86: truncation toward zero to 32 bits
/// (0x8000_0000 when out of range or NaN), then the low 16 bits.
pub fn q(x: f32) -> i16 {
    let t = if x.is_finite() && x.abs() < 2_147_483_648.0 {
        x as i32
    } else {
        i32::MIN
    };
    t as i16
}

/// A sum stored back into a 16-bit value: wrapped.
fn wrap(a: i16, b: i16) -> i16 {
    a.wrapping_add(b)
}

/// unorm8 of a float clamped to [0, 1], rounding half to even (Mesa's `_mesa_float_to_unorm`).
pub fn unorm8(c: f32) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0).round_ties_even() as u8
}

/// A rectangle of the buffer, in window coordinates: the scissor box clipped to the buffer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Region {
    pub x: usize,
    pub y: usize,
    pub width: usize,
    pub height: usize,
}

/// The accumulation buffer of one window: RGBA i16 per pixel, bottom row first.
#[derive(Debug, Clone, PartialEq)]
pub struct AccumBuffer {
    width: usize,
    height: usize,
    values: Vec<[i16; 4]>,
}

impl AccumBuffer {
    /// A buffer of `width` × `height` pixels holding 0 (GL leaves a new buffer undefined).
    pub fn new(width: usize, height: usize) -> Self {
        Self {
            width,
            height,
            values: vec![[0; 4]; width * height],
        }
    }

    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// The stored values of pixel (x, y).
    pub fn at(&self, x: usize, y: usize) -> [i16; 4] {
        self.values[y * self.width + x]
    }

    /// `region` clipped to the buffer.
    pub fn clip(&self, r: Region) -> Region {
        let x = r.x.min(self.width);
        let y = r.y.min(self.height);
        Region {
            x,
            y,
            width: r.width.min(self.width - x),
            height: r.height.min(self.height - y),
        }
    }

    fn each(&mut self, r: Region, mut f: impl FnMut(usize, &mut [i16; 4])) {
        let r = self.clip(r);
        for y in r.y..r.y + r.height {
            for x in r.x..r.x + r.width {
                let i = y * self.width + x;
                f(i, &mut self.values[i]);
            }
        }
    }

    /// glClear(ACCUM_BUFFER_BIT) with the clear value `v` (already clamped to [−1, 1]).
    pub fn clear(&mut self, r: Region, v: Vec4) {
        let a = v.to_array().map(|c| q((c * 65535.0 - 1.0) / 2.0));
        self.each(r, |_, p| *p = a);
    }

    /// ACCUM, LOAD, ADD or MULT with `value`; `colour` is the read buffer's RGBA8 bytes,
    /// the whole buffer bottom row first (ADD and MULT do not read it). RETURN is
    /// [`AccumBuffer::returned`].
    pub fn apply(&mut self, op: AccumOp, value: f32, r: Region, colour: &[u8]) {
        let scale = value * ACCUM_ONE;
        let c = |i: usize, k: usize| f32::from(colour[4 * i + k]) / 255.0;
        match op {
            AccumOp::Accum => self.each(r, |i, p| {
                for (k, v) in p.iter_mut().enumerate() {
                    *v = wrap(*v, q(c(i, k) * scale));
                }
            }),
            AccumOp::Load => self.each(r, |i, p| {
                for (k, v) in p.iter_mut().enumerate() {
                    *v = q(c(i, k) * scale);
                }
            }),
            AccumOp::Add => {
                let d = q(scale);
                self.each(r, |_, p| *p = p.map(|v| wrap(v, d)));
            }
            AccumOp::Mult => self.each(r, |_, p| *p = p.map(|v| q(f32::from(v) * value))),
            AccumOp::Return => {}
        }
    }

    /// RETURN `value`: the colours a·(v/32767) as unorm8 RGBA, the whole buffer bottom row
    /// first (the caller writes the region's pixels through the colour mask).
    pub fn returned(&self, value: f32) -> Vec<u8> {
        let scale = value / ACCUM_ONE;
        self.values
            .iter()
            .flat_map(|p| p.map(|v| unorm8(f32::from(v) * scale)))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ALL: Region = Region {
        x: 0,
        y: 0,
        width: 1,
        height: 1,
    };

    fn one(colour: [u8; 4], ops: &[(AccumOp, f32)], start: Vec4) -> [u8; 4] {
        let mut b = AccumBuffer::new(1, 1);
        b.clear(ALL, start);
        for (op, v) in ops {
            b.apply(*op, *v, ALL, &colour);
        }
        let ret = ops
            .iter()
            .rev()
            .find(|(op, _)| *op == AccumOp::Return)
            .map_or(1.0, |(_, v)| *v);
        b.returned(ret).try_into().unwrap()
    }

    #[test]
    fn clear_values_map_as_signed_shorts() {
        let mut b = AccumBuffer::new(1, 1);
        b.clear(ALL, Vec4::new(0.1, -0.5, 1.0, -1.0));
        assert_eq!(b.at(0, 0), [3276, -16384, 32767, -32768]);
        b.clear(ALL, Vec4::new(0.3, 0.5, 0.8, 0.0));
        assert_eq!(b.at(0, 0), [9829, 16383, 26213, 0]);
    }

    #[test]
    fn q_truncates_and_wraps_like_a_c_short_cast() {
        assert_eq!(q(3276.7), 3276);
        assert_eq!(q(-3276.7), -3276);
        assert_eq!(q(49150.5), -16386);
        assert_eq!(q(65534.0), -2);
        assert_eq!(q(-98301.0), -32765);
        assert_eq!(q(f32::NAN), 0);
        assert_eq!(q(1e10), 0);
    }

    /// The measured example: (1, ½, ¼) and (0, 1, 0) accumulated at 0.5, returned at 1.
    #[test]
    fn two_accumulated_frames_return_as_mesa_writes_them() {
        let mut b = AccumBuffer::new(1, 1);
        b.clear(ALL, Vec4::ZERO);
        b.apply(AccumOp::Accum, 0.5, ALL, &[255, 128, 64, 255]);
        b.apply(AccumOp::Accum, 0.5, ALL, &[0, 255, 0, 0]);
        assert_eq!(b.at(0, 0), [16383, 24606, 4111, 16383]);
        assert_eq!(b.returned(1.0), vec![127, 191, 32, 127]);
    }

    /// Each ACCUM of k/255 at v, returned at 1 (measured on Mesa's OSMesa).
    #[test]
    fn accum_of_one_frame_matches_mesa() {
        let cases: [(f32, u8, u8); 10] = [
            (0.5, 51, 25),
            (0.5, 153, 76),
            (0.3, 51, 15),
            (0.3, 255, 76),
            (0.7, 204, 143),
            (0.1, 255, 25),
            (2.0, 102, 204),
            // 0.6·2·32767 = 39320 wraps to −26216: RETURN writes 0.
            (2.0, 153, 0),
            (2.0, 255, 0),
            (-1.0, 255, 0),
        ];
        for (v, k, want) in cases {
            let got = one([k; 4], &[(AccumOp::Accum, v)], Vec4::ZERO);
            assert_eq!(got, [want; 4], "ACCUM {v} of {k}");
        }
    }

    #[test]
    fn load_add_mult_and_return_match_mesa() {
        let v = |x: f32| Vec4::splat(x);
        let c = [153, 51, 102, 255];
        assert_eq!(
            one(c, &[(AccumOp::Load, 0.5), (AccumOp::Return, 2.0)], v(0.0)),
            [153, 51, 102, 255]
        );
        assert_eq!(
            one(c, &[(AccumOp::Load, 0.5), (AccumOp::Return, 1.0)], v(0.0)),
            [76, 25, 51, 127]
        );
        let start = Vec4::new(0.1, 0.2, 0.3, 0.4);
        assert_eq!(one(c, &[(AccumOp::Return, 1.0)], start), [25, 51, 76, 102]);
        assert_eq!(one(c, &[(AccumOp::Add, 0.25)], start), [89, 115, 140, 166]);
        // ADD 1.5 adds q(49150.5) = −16386.
        let add = [(AccumOp::Add, 0.25), (AccumOp::Add, 1.5)];
        assert_eq!(one(c, &add, start), [0, 0, 13, 38]);
        let add3 = [
            (AccumOp::Add, 0.25),
            (AccumOp::Add, 1.5),
            (AccumOp::Add, -3.0),
        ];
        assert_eq!(one(c, &add3, start), [217, 242, 0, 0]);
        let neg = Vec4::new(-0.5, 0.5, 0.2, 0.8);
        assert_eq!(one(c, &[(AccumOp::Return, -1.0)], neg), [128, 0, 0, 0]);
        assert_eq!(one(c, &[(AccumOp::Mult, 0.5)], v(0.5)), [64; 4]);
        let m3 = [(AccumOp::Mult, 0.5), (AccumOp::Mult, 3.0)];
        assert_eq!(one(c, &m3, v(0.5)), [191; 4]);
        let m = [
            (AccumOp::Mult, 0.5),
            (AccumOp::Mult, 3.0),
            (AccumOp::Mult, -1.0),
            (AccumOp::Return, -1.0),
        ];
        assert_eq!(one(c, &m, v(0.5)), [191; 4]);
    }

    #[test]
    fn sums_beyond_one_wrap_and_loads_beyond_one_wrap() {
        let w = [255; 4];
        let acc = [(AccumOp::Accum, 0.5), (AccumOp::Return, 0.5)];
        assert_eq!(one(w, &acc, Vec4::splat(0.8)), [0; 4]);
        let load = [(AccumOp::Load, 2.0), (AccumOp::Return, 0.25)];
        assert_eq!(one(w, &load, Vec4::ZERO), [0; 4]);
        let load = [(AccumOp::Load, -2.0), (AccumOp::Return, -0.25)];
        assert_eq!(one(w, &load, Vec4::ZERO), [0; 4]);
    }

    #[test]
    fn return_scales_clamp_at_one() {
        let start = Vec4::new(0.5, 0.25, 0.1, 0.9);
        let cases = [
            (0.3, [38, 19, 8, 69]),
            (0.7, [89, 45, 18, 161]),
            (1.1, [140, 70, 28, 252]),
            (1.5, [191, 96, 38, 255]),
            (1.9, [242, 121, 48, 255]),
        ];
        for (v, want) in cases {
            assert_eq!(one([0; 4], &[(AccumOp::Return, v)], start), want, "{v}");
        }
    }

    #[test]
    fn the_region_limits_clear_and_operations() {
        let mut b = AccumBuffer::new(2, 1);
        let left = Region {
            x: 0,
            y: 0,
            width: 1,
            height: 1,
        };
        b.clear(left, Vec4::ONE);
        assert_eq!(b.at(0, 0), [32767; 4]);
        assert_eq!(b.at(1, 0), [0; 4]);
        let wide = Region {
            x: 1,
            y: 0,
            width: 100,
            height: 100,
        };
        b.apply(AccumOp::Add, 0.5, wide, &[]);
        assert_eq!(b.at(0, 0), [32767; 4]);
        assert_eq!(b.at(1, 0), [16383; 4]);
    }
}

/// The model's rules for the calls: the clamp, the errors, the queries and the attribute
/// group; the script dialect reads and prints them back.
#[cfg(test)]
mod model_tests {
    use glam::Vec4;

    use super::{AccumOp, ACCUM_BITS};
    use crate::ff::framebuffer::FramebufferTarget;
    use crate::ff::glenum::registry as r;
    use crate::ff::script::{parse, print};
    use crate::ff::{AttribMask, Command, FixedState, GlErrorKind};

    const RETURN: Command = Command::Accum {
        op: AccumOp::Return,
        value: 1.0,
    };

    #[test]
    fn glaccum_needs_the_windows_accumulation_buffer() {
        let mut s = FixedState::default();
        let kind = |s: &mut FixedState, c: &Command| s.apply(c).map_err(|e| e.kind);
        assert_eq!(kind(&mut s, &RETURN), Err(GlErrorKind::InvalidOperation));
        assert_eq!(s.get_integerv(r::ACCUM_ALPHA_BITS), Ok(vec![0]));
        s.framebuffers.window_accum_bits = ACCUM_BITS;
        assert_eq!(kind(&mut s, &RETURN), Ok(()));
        assert_eq!(s.get_integerv(r::ACCUM_GREEN_BITS), Ok(vec![16]));
        // A framebuffer object has none (GL 3.0; Mesa measured: 0 bits, INVALID_OPERATION).
        let bind = Command::BindFramebuffer {
            target: FramebufferTarget::Both,
            name: 3,
        };
        assert_eq!(kind(&mut s, &bind), Ok(()));
        assert_eq!(kind(&mut s, &RETURN), Err(GlErrorKind::InvalidOperation));
        assert_eq!(s.get_integerv(r::ACCUM_RED_BITS), Ok(vec![0]));
    }

    #[test]
    fn the_clear_value_is_clamped_queried_and_saved_by_accum_buffer_bit() {
        let mut s = FixedState::default();
        s.apply(&Command::ClearAccum(Vec4::new(2.0, -3.0, 0.5, -0.25)))
            .unwrap();
        assert_eq!(
            s.get_floatv(r::ACCUM_CLEAR_VALUE),
            Ok(vec![1.0, -1.0, 0.5, -0.25])
        );
        s.apply(&Command::ClearAccum(Vec4::splat(0.3))).unwrap();
        // Mesa measured: 0.3 as an integer is 644245119 = ⌊0.3·(2³¹ − 1)⌋.
        assert_eq!(s.get_integerv(r::ACCUM_CLEAR_VALUE), Ok(vec![644245119; 4]));
        s.apply(&Command::PushAttrib(AttribMask(r::ACCUM_BUFFER_BIT)))
            .unwrap();
        s.apply(&Command::ClearAccum(Vec4::ZERO)).unwrap();
        s.apply(&Command::PushAttrib(AttribMask(r::COLOR_BUFFER_BIT)))
            .unwrap();
        s.apply(&Command::PopAttrib).unwrap();
        assert_eq!(s.clear.accum, Vec4::ZERO, "COLOR_BUFFER_BIT leaves it");
        s.apply(&Command::PopAttrib).unwrap();
        assert_eq!(s.clear.accum, Vec4::splat(0.3));
    }

    #[test]
    fn the_calls_parse_and_print_back() {
        let src = "glClearAccum(1, -1, 0.5, 0.25);\nglClear(GL_ACCUM_BUFFER_BIT);\n\
                   glAccum(GL_ACCUM, 0.125);\nglAccum(GL_LOAD, 2);\nglAccum(GL_RETURN, 1);\n\
                   glAccum(GL_MULT, -0.5);\nglAccum(GL_ADD, 0.25);\n";
        let cmds = parse(src).expect("parses");
        assert_eq!(cmds.len(), 7);
        assert_eq!(
            cmds[2],
            Command::Accum {
                op: AccumOp::Accum,
                value: 0.125
            }
        );
        assert_eq!(parse(&print(&cmds)).expect("reparses"), cmds);
        assert!(parse("glAccum(GL_ZERO, 1);").is_err());
    }
}
