//! GL 1.0's signed pixel types (BYTE, SHORT, INT), GL 1.2's packed types (Table 3.8) and
//! its BGR and BGRA formats (Table 3.5), on the way in and on the way out.
//!
//! **In** (glTexImage*, glTexSubImage*, glDrawPixels): client data in one of them is
//! rewritten into the model's own forms where it enters the layer, before a display list,
//! the trace, the script printer or either pipeline sees it ([`to_model`]):
//! - BGR and BGRA in a component type become RGB and RGBA in that type: the components
//!   move, none is converted, so nothing is lost;
//! - a signed type becomes FLOAT, a packed type UNSIGNED_BYTE (RGB for 3_3_2, 5_6_5 and
//!   their REV, RGBA for the others), each component converted by the rules below;
//! - STENCIL_INDEX in a signed type becomes UNSIGNED_INT: the index's two's-complement bits,
//!   of which the stencil path keeps the low ones;
//! - COLOR_INDEX stays in its type (Mesa draws a BYTE image otherwise than an INT one,
//!   `index_pixels`); GL_BITMAP becomes UNSIGNED_BYTE indices 0 and 1.
//!
//! **Out** (glReadPixels, glGetTexImage): the command keeps the format and type asked for;
//! the native path asks GL, the emulated path reads the read form ([`read_form`]) and
//! packs it on the CPU ([`from_model`]).
//!
//! Conversions, as Mesa 22.3 makes them (measured with OSMesa, `tests/c/pixel_types.c`):
//! - signed to float: c / (2ⁿ⁻¹ − 1), at least −1 (Mesa's `_mesa_snorm_to_float`, the
//!   normalisation of GL 4.2, not GL 1.5 Table 2.9's (2c + 1) / (2ⁿ − 1)); a negative
//!   colour is then clamped to 0 where the model clamps colour (1 → 2/255, 64 → 129/255);
//! - a packed field of b bits to 8 bits: its bits repeated for b ≤ 8, rounded for 10
//!   ([`field_to_unorm8`]), which is what an 8-bit texture or colour buffer keeps: Mesa
//!   unpacks to 8 bits too, so the model's form loses nothing an 8-bit target keeps;
//! - 8- and 16-bit storage to a signed or packed type: Mesa's integer rules
//!   ([`ReadFrom::Unorm8`], [`ReadFrom::Unorm16`]); float storage (and packed storage such
//!   as RGB5, which Mesa unpacks to floats): round(clamp(f, −1, 1) · (2ⁿ⁻¹ − 1)) and
//!   round(clamp(f, 0, 1) · (2ᵇ − 1)), half away from zero — INT as Mesa's
//!   `_mesa_float_to_snorm`, whose float constant is 2³¹ (1.0 wraps to INT_MIN).

use std::sync::Arc;

use super::args::{Args, PixelShape, ShapeKind};
use super::command::{Command, TexData};
use super::error::GlErrorKind;
use super::index_pixels;
use super::texture::{PixelFormat, PixelType};

/// The call's Command when `format` and `ty` do not go together: the GL error it raises
/// ([`refused`]), which a display list keeps for its execution as Mesa does.
pub fn refusal<A: Args>(c: &A, format: PixelFormat, ty: PixelType) -> Option<Command> {
    refused(format, ty).map(|error| Command::Raise {
        error,
        call: c.entry(),
    })
}

/// Client pixels in the model's form: format, type and bytes (NULL as `None`).
pub type ModelPixels = (PixelFormat, PixelType, Option<Arc<[u8]>>);

/// The pixels of argument `i` (of `shape`) in the model's form.
pub fn model_pixels<A: Args>(c: &A, i: usize, shape: PixelShape) -> Result<ModelPixels, A::Error> {
    let (format, ty) = model_form(shape.format, shape.ty);
    let data = c.pixels(i, shape)?.map(|d| shape_to_model(shape, d));
    Ok((format, ty, data))
}

/// Tight data of `shape` in the model's form: COLOR_INDEX bits as one index a byte,
/// anything else by [`to_model`].
fn shape_to_model(shape: PixelShape, data: Arc<[u8]>) -> Arc<[u8]> {
    match shape.kind {
        ShapeKind::IndexBits(_) => index_pixels::bits_as_indices(&data, shape).into(),
        ShapeKind::Groups | ShapeKind::Bitmap | ShapeKind::IndexRun => {
            to_model(shape.format, shape.ty, data)
        }
    }
}

/// The component RED, GREEN or BLUE data holds (0, 1, 2); `None` for other formats.
fn single_component(format: PixelFormat) -> Option<usize> {
    match format {
        PixelFormat::Red => Some(0),
        PixelFormat::Green => Some(1),
        PixelFormat::Blue => Some(2),
        _ => None,
    }
}

/// The format and type the model keeps texture data of `format` in `ty` in: the model's
/// form ([`model_form`]), but RGBA for RED, GREEN and BLUE, which a texture image stores
/// converted to RGBA (GL 1.5 §3.6.4: the missing colour components 0, alpha 1).
pub fn texel_form(format: PixelFormat, ty: PixelType) -> (PixelFormat, PixelType) {
    match (single_component(format), model_form(format, ty)) {
        (Some(_), (_, model_ty)) => (PixelFormat::Rgba, model_ty),
        (None, form) => form,
    }
}

/// Data of one component `k` a group, in `model_ty`, as RGBA groups: the others 0, alpha
/// the type's 1 (its largest value for an unsigned type, which the model keeps as the
/// bytes hold them; 1.0 as FLOAT).
fn single_to_rgba(k: usize, model_ty: PixelType, data: &[u8]) -> Arc<[u8]> {
    let size = model_ty.size();
    let one: Vec<u8> = match model_ty {
        PixelType::UnsignedByte => vec![u8::MAX],
        PixelType::UnsignedShort => u16::MAX.to_ne_bytes().to_vec(),
        PixelType::UnsignedInt => u32::MAX.to_ne_bytes().to_vec(),
        _ => 1f32.to_ne_bytes().to_vec(),
    };
    let mut out = Vec::with_capacity(data.len() * 4);
    for v in data.chunks_exact(size) {
        for c in 0..4 {
            match c {
                _ if c == k => out.extend_from_slice(v),
                3 => out.extend_from_slice(&one),
                _ => out.extend(std::iter::repeat_n(0u8, size)),
            }
        }
    }
    out.into()
}

/// Texture data of `shape` in the texel form ([`texel_form`]).
fn shape_to_texels(shape: PixelShape, data: Arc<[u8]>) -> Arc<[u8]> {
    let model = shape_to_model(shape, data);
    match single_component(shape.format) {
        Some(k) => single_to_rgba(k, model_form(shape.format, shape.ty).1, &model),
        None => model,
    }
}

/// glTexSubImage's pixels of argument `i` (of `shape`) in the texel form.
pub fn model_sub_texels<A: Args>(
    c: &A,
    i: usize,
    shape: PixelShape,
) -> Result<ModelPixels, A::Error> {
    let (format, ty) = texel_form(shape.format, shape.ty);
    let data = c.pixels(i, shape)?.map(|d| shape_to_texels(shape, d));
    Ok((format, ty, data))
}

/// glTexImage's data of argument `i` (of `shape`) in the texel form ([`texel_form`]). A
/// script's readback slot is read as the slot holds it, so it takes only the model's own
/// forms.
pub fn model_tex_data<A: Args>(
    c: &A,
    i: usize,
    shape: PixelShape,
) -> Result<(PixelFormat, PixelType, TexData), A::Error> {
    let (format, ty) = texel_form(shape.format, shape.ty);
    let data = match c.tex_data(i, shape)? {
        TexData::Bytes(d) => TexData::Bytes(shape_to_texels(shape, d)),
        TexData::Null => TexData::Null,
        slot if is_model_form(shape.format, shape.ty)
            && single_component(shape.format).is_none()
            && matches!(shape.kind, ShapeKind::Groups | ShapeKind::Bitmap) =>
        {
            slot
        }
        _ => {
            return Err(c.bad(
                i,
                "bytes or NULL: a readback slot is read in RGB(A), LUMINANCE(_ALPHA), ALPHA, \
                 DEPTH_COMPONENT or STENCIL_INDEX of an unsigned type or FLOAT",
            ))
        }
    };
    Ok((format, ty, data))
}

/// GL 1.2's packed pixel types (Table 3.8). A group is one element of 1, 2 or 4 bytes;
/// its fields are the format's components in the format's order, the first in the
/// element's highest bits, or (`…Rev`) its lowest (Tables 3.11–3.13).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PackedType {
    UnsignedByte332,
    UnsignedByte233Rev,
    UnsignedShort565,
    UnsignedShort565Rev,
    UnsignedShort4444,
    UnsignedShort4444Rev,
    UnsignedShort5551,
    UnsignedShort1555Rev,
    UnsignedInt8888,
    UnsignedInt8888Rev,
    UnsignedInt1010102,
    UnsignedInt2101010Rev,
}

impl PackedType {
    /// Bytes of one element (one group).
    pub fn bytes(self) -> usize {
        match self {
            PackedType::UnsignedByte332 | PackedType::UnsignedByte233Rev => 1,
            PackedType::UnsignedShort565
            | PackedType::UnsignedShort565Rev
            | PackedType::UnsignedShort4444
            | PackedType::UnsignedShort4444Rev
            | PackedType::UnsignedShort5551
            | PackedType::UnsignedShort1555Rev => 2,
            PackedType::UnsignedInt8888
            | PackedType::UnsignedInt8888Rev
            | PackedType::UnsignedInt1010102
            | PackedType::UnsignedInt2101010Rev => 4,
        }
    }

    /// The field widths as the type's name gives them, highest bits first, and whether
    /// the components run from the lowest bits (REV).
    fn layout(self) -> (&'static [u32], bool) {
        match self {
            PackedType::UnsignedByte332 => (&[3, 3, 2], false),
            PackedType::UnsignedByte233Rev => (&[2, 3, 3], true),
            PackedType::UnsignedShort565 => (&[5, 6, 5], false),
            PackedType::UnsignedShort565Rev => (&[5, 6, 5], true),
            PackedType::UnsignedShort4444 => (&[4, 4, 4, 4], false),
            PackedType::UnsignedShort4444Rev => (&[4, 4, 4, 4], true),
            PackedType::UnsignedShort5551 => (&[5, 5, 5, 1], false),
            PackedType::UnsignedShort1555Rev => (&[1, 5, 5, 5], true),
            PackedType::UnsignedInt8888 => (&[8, 8, 8, 8], false),
            PackedType::UnsignedInt8888Rev => (&[8, 8, 8, 8], true),
            PackedType::UnsignedInt1010102 => (&[10, 10, 10, 2], false),
            PackedType::UnsignedInt2101010Rev => (&[2, 10, 10, 10], true),
        }
    }

    /// Components of a group: 3 or 4.
    pub fn components(self) -> usize {
        self.layout().0.len()
    }

    /// (shift, bits) of each component, in the format's order.
    pub fn fields(self) -> Vec<(u32, u32)> {
        let (widths, rev) = self.layout();
        let total: u32 = widths.iter().sum();
        let mut out = Vec::with_capacity(widths.len());
        if rev {
            // The first component in the lowest bits; the widths, read from the low end,
            // are the name's read backwards.
            let mut shift = 0;
            for &bits in widths.iter().rev() {
                out.push((shift, bits));
                shift += bits;
            }
        } else {
            let mut top = total;
            for &bits in widths {
                top -= bits;
                out.push((top, bits));
            }
        }
        out
    }
}

/// The error GL gives a format and type that do not go together, if any: a packed type
/// whose group has another number of components than the format (GL 1.2 §3.6.4:
/// INVALID_OPERATION; Mesa also refuses BGR with 3_3_2 and 5_6_5), or a packed type with a
/// format that is no colour.
pub fn refused(format: PixelFormat, ty: PixelType) -> Option<GlErrorKind> {
    let PixelType::Packed(p) = ty else {
        return None;
    };
    let fits = match p.components() {
        3 => format == PixelFormat::Rgb,
        _ => matches!(
            format,
            PixelFormat::Rgba | PixelFormat::Bgra | PixelFormat::Abgr
        ),
    };
    (!fits).then_some(GlErrorKind::InvalidOperation)
}

/// The format and type the model keeps for client data of `format` in `ty`.
pub fn model_form(format: PixelFormat, ty: PixelType) -> (PixelFormat, PixelType) {
    let format = match format {
        PixelFormat::Bgr => PixelFormat::Rgb,
        PixelFormat::Bgra | PixelFormat::Abgr => PixelFormat::Rgba,
        f => f,
    };
    let ty = match (format, ty) {
        (PixelFormat::ColorIndex, t) => t,
        (PixelFormat::StencilIndex, PixelType::Byte | PixelType::Short | PixelType::Int) => {
            PixelType::UnsignedInt
        }
        (_, PixelType::Byte | PixelType::Short | PixelType::Int) => PixelType::Float,
        (_, PixelType::Packed(_)) => PixelType::UnsignedByte,
        (_, t) => t,
    };
    (format, ty)
}

/// The format and type a pipeline reads for glReadPixels or glGetTexImage in `format` and
/// `ty`, before [`from_model`] gives them as asked: the model's form, but FLOAT for a
/// packed type (its fields are packed from the values read).
pub fn read_form(format: PixelFormat, ty: PixelType) -> (PixelFormat, PixelType) {
    match model_form(format, ty) {
        (f, _) if matches!(ty, PixelType::Packed(_)) => (f, PixelType::Float),
        // Mesa packs luminance as UNSIGNED_INT from floats ([`luminance_uint`]).
        (f, PixelType::UnsignedInt) if is_luminance(f) => (f, PixelType::Float),
        form => form,
    }
}

/// LUMINANCE or LUMINANCE_ALPHA, which Mesa packs into the 32-bit types through floats.
fn is_luminance(format: PixelFormat) -> bool {
    matches!(format, PixelFormat::Luminance | PixelFormat::LuminanceAlpha)
}

/// The call a readback answers: Mesa packs luminance as INT differently in each.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Packer {
    ReadPixels,
    GetTexImage,
}

/// Whether `format` in `ty` is already the model's own form.
pub fn is_model_form(format: PixelFormat, ty: PixelType) -> bool {
    model_form(format, ty) == (format, ty)
}

/// For BGR, BGRA and ABGR, the element of the model's group each element of the client's
/// group comes from (red and blue swap places; ABGR reverses all four); `None` for every
/// other format.
fn swizzle(format: PixelFormat) -> Option<&'static [usize]> {
    match format {
        PixelFormat::Bgr => Some(&[2, 1, 0]),
        PixelFormat::Bgra => Some(&[2, 1, 0, 3]),
        PixelFormat::Abgr => Some(&[3, 2, 1, 0]),
        _ => None,
    }
}

/// Tight client data of `format` in `ty` (SWAP_BYTES already applied) in the model's form
/// ([`model_form`]); the data itself when it is that form already. A trailing partial group
/// is dropped.
pub fn to_model(format: PixelFormat, ty: PixelType, data: Arc<[u8]>) -> Arc<[u8]> {
    if is_model_form(format, ty) {
        return data;
    }
    let (_, model_ty) = model_form(format, ty);
    let group = ty.group_bytes(format);
    let order = client_order(format);
    let mut out = Vec::with_capacity(data.len() / group.max(1) * 16);
    if model_ty == ty {
        // BGR(A) in a component type: the elements move, their bytes unchanged.
        let size = ty.size();
        for g in data.chunks_exact(group) {
            for &i in &order {
                out.extend_from_slice(&g[i * size..(i + 1) * size]);
            }
        }
        return out.into();
    }
    let fields = match ty {
        PixelType::Packed(p) => p.fields(),
        _ => Vec::new(),
    };
    let mut values = Vec::with_capacity(4);
    for g in data.chunks_exact(group) {
        group_values(&mut values, g, format, ty, &fields);
        put_group(&mut out, &values, &order, model_ty);
    }
    out.into()
}

/// The order in which the model's group takes the client's elements: BGR(A)'s or ABGR's
/// swizzle,
/// or the elements as they come.
fn client_order(format: PixelFormat) -> Vec<usize> {
    match swizzle(format) {
        Some(s) => s.to_vec(),
        None => (0..format.components()).collect(),
    }
}

/// A packed field `v` of `bits` bits as 8 bits, as Mesa unpacks it: up to 8 bits by
/// repeating the bits (EXTEND_NORMALIZED_INT: v·⌊255/(2ᵇ − 1)⌋ + (v >> (b − 8 mod b));
/// 5 bits: 8v + (v >> 2), so 3 → 24 where round(3·255/31) is 25), 10 bits rounded,
/// ⌊(255v + 511) / 1023⌋ (measured, `tests/c/pixel_types.c`).
pub fn field_to_unorm8(v: u32, bits: u32) -> u8 {
    let max = (1u32 << bits) - 1;
    let v = v.min(max);
    let u = if bits > 8 {
        (255 * v + max / 2) / max
    } else {
        let rest = 8 % bits;
        v * (255 / max) + if rest == 0 { 0 } else { v >> (bits - rest) }
    };
    u as u8
}

/// One client group as numbers in the client's component order: signed types as
/// normalised floats (a stencil index as the integer), packed fields as 8-bit integers
/// ([`field_to_unorm8`]), unsigned and FLOAT elements as the bytes hold them.
/// `fields` are the packed type's ([`PackedType::fields`], taken once by the caller).
fn group_values(
    out: &mut Vec<f64>,
    g: &[u8],
    format: PixelFormat,
    ty: PixelType,
    fields: &[(u32, u32)],
) {
    let stencil = format == PixelFormat::StencilIndex;
    let n = format.components();
    out.clear();
    match ty {
        PixelType::Packed(p) => {
            // One element in the machine's byte order, as GL reads it.
            let word = match p.bytes() {
                1 => u32::from(g[0]),
                2 => u32::from(u16::from_ne_bytes([g[0], g[1]])),
                _ => u32::from_ne_bytes([g[0], g[1], g[2], g[3]]),
            };
            out.extend(fields.iter().map(|&(shift, bits)| {
                let max = (1u32 << bits) - 1;
                f64::from(field_to_unorm8((word >> shift) & max, bits))
            }));
        }
        _ => {
            let s = ty.size();
            out.extend((0..n).map(|i| element(&g[i * s..(i + 1) * s], ty, stencil)));
        }
    }
}

/// One element: a signed type normalised (or, for a stencil index, as the integer), an
/// unsigned type and FLOAT as the bytes hold them (unnormalised: they are copied, not
/// converted).
pub fn element(e: &[u8], ty: PixelType, stencil: bool) -> f64 {
    let signed = |v: i64, bits: u32| -> f64 {
        if stencil {
            v as f64
        } else {
            snorm_to_float(v, bits)
        }
    };
    match ty {
        PixelType::Byte => signed(i64::from(e[0] as i8), 8),
        PixelType::Short => signed(i64::from(i16::from_ne_bytes([e[0], e[1]])), 16),
        PixelType::Int => signed(i64::from(i32::from_ne_bytes([e[0], e[1], e[2], e[3]])), 32),
        PixelType::UnsignedByte => f64::from(e[0]),
        PixelType::UnsignedShort => f64::from(u16::from_ne_bytes([e[0], e[1]])),
        PixelType::UnsignedInt => f64::from(u32::from_ne_bytes([e[0], e[1], e[2], e[3]])),
        PixelType::Float => f64::from(f32::from_ne_bytes([e[0], e[1], e[2], e[3]])),
        PixelType::Packed(_) => 0.0,
    }
}

/// A group of `values` (client order) appended in the model's order (`order`,
/// [`client_order`]) and type `model_ty`.
fn put_group(out: &mut Vec<u8>, values: &[f64], order: &[usize], model_ty: PixelType) {
    for &i in order {
        let v = values.get(i).copied().unwrap_or(0.0);
        match model_ty {
            PixelType::UnsignedByte => out.push(v as u8),
            PixelType::UnsignedShort => out.extend((v as u16).to_ne_bytes()),
            // A stencil index from a signed type: its two's-complement bits.
            PixelType::UnsignedInt => out.extend((v as i64 as u32).to_ne_bytes()),
            _ => out.extend((v as f32).to_ne_bytes()),
        }
    }
}

/// What the values a pipeline reads were stored in: Mesa converts from 8-bit storage
/// with integer arithmetic, from anything else through floats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ReadFrom {
    /// An 8-bit colour buffer or texture: each value read is u / 255 for an integer u.
    Unorm8,
    /// A texture of 16 bits a component (RGB16, RGBA12, LUMINANCE16 …): each value read
    /// is u / 65535 for an integer u.
    Unorm16,
    /// Float, 16-bit or depth storage.
    Float,
}

/// Tight data the pipeline read in the read form of (`format`, `ty`) ([`read_form`])
/// as glReadPixels and glGetTexImage (`packer`) give it in `format` and `ty`: BGR(A)
/// reordered, signed and packed types converted from the FLOAT read, from `from`'s
/// storage; luminance in the 32-bit types by Mesa's float packing ([`luminance_uint`],
/// [`luminance_int`]).
pub fn from_model(
    read: &[u8],
    format: PixelFormat,
    ty: PixelType,
    from: ReadFrom,
    packer: Packer,
) -> Vec<u8> {
    let each_float = |pack: fn(f32) -> [u8; 4]| -> Vec<u8> {
        read.chunks_exact(4)
            .flat_map(|e| pack(read_f32(e)))
            .collect()
    };
    match ty {
        PixelType::UnsignedInt if is_luminance(format) => {
            return each_float(|x| luminance_uint(x).to_ne_bytes())
        }
        PixelType::Int if is_luminance(format) && packer == Packer::ReadPixels => {
            return each_float(|x| luminance_int(x).to_ne_bytes())
        }
        _ => {}
    }
    if is_model_form(format, ty) {
        return read.to_vec();
    }
    let (model_format, model_ty) = read_form(format, ty);
    let n = model_format.components();
    let elem = model_ty.size();
    // The model's group in the client's order.
    let order = client_order(format);
    let fields = match ty {
        PixelType::Packed(p) => p.fields(),
        _ => Vec::new(),
    };
    let mut out = Vec::with_capacity(read.len());
    for g in read.chunks_exact(n * elem) {
        let raw = |i: usize| &g[i * elem..(i + 1) * elem];
        let value = |i: usize| Stored::of(read_f32(raw(i)), from);
        match ty {
            PixelType::Packed(p) => {
                let mut word = 0u32;
                for (&(shift, bits), &i) in fields.iter().zip(&order) {
                    word |= value(i).unorm(bits) << shift;
                }
                match p.bytes() {
                    1 => out.push(word as u8),
                    2 => out.extend((word as u16).to_ne_bytes()),
                    _ => out.extend(word.to_ne_bytes()),
                }
            }
            PixelType::Byte | PixelType::Short | PixelType::Int
                if format == PixelFormat::DepthComponent =>
            {
                out.extend(depth_signed(read_f32(raw(0)), ty));
            }
            PixelType::Byte | PixelType::Short | PixelType::Int
                if format == PixelFormat::StencilIndex =>
            {
                let v = u32::from_ne_bytes([g[0], g[1], g[2], g[3]]);
                match ty {
                    // Mesa's `_mesa_pack_stencil_span`: the value's low 7 bits.
                    PixelType::Byte => out.push((v & 0x7f) as u8),
                    PixelType::Short => out.extend((v as u16).to_ne_bytes()),
                    _ => out.extend(v.to_ne_bytes()),
                }
            }
            PixelType::Byte => {
                for &i in &order {
                    out.push(value(i).snorm(8) as i8 as u8);
                }
            }
            PixelType::Short => {
                for &i in &order {
                    out.extend((value(i).snorm(16) as i16).to_ne_bytes());
                }
            }
            PixelType::Int => {
                for &i in &order {
                    out.extend((value(i).snorm(32) as i32).to_ne_bytes());
                }
            }
            // BGR(A) in a component type: the elements move.
            _ => {
                for &i in &order {
                    out.extend_from_slice(raw(i));
                }
            }
        }
    }
    out
}

/// A LUMINANCE or LUMINANCE_ALPHA component glReadPixels reads as INT, as Mesa 22.3 packs
/// it: through floats, (GLint)(x · 2147483647.0f) — the constant a float, 2³¹, so the
/// product is exact and 1.0 overflows, which x86's truncating conversion gives as INT_MIN
/// (measured: L = 1.0 reads 0x80000000, 177/255 reads 0x58d8d900 where x · (2³¹ − 1)
/// would be 0x58d8d8d8). glGetTexImage and the other formats take [`Stored::snorm`]'s
/// rule, as Mesa does for them.
fn luminance_int(x: f32) -> i32 {
    let p = x * 2_147_483_647.0_f32;
    if p.is_nan() || !(-2_147_483_648.0..2_147_483_648.0).contains(&p) {
        i32::MIN
    } else {
        p as i32
    }
}

/// A LUMINANCE or LUMINANCE_ALPHA component read as UNSIGNED_INT (glReadPixels and
/// glGetTexImage alike), as Mesa 22.3 packs it: (GLuint)(x · 4294967295.0f), the constant
/// a float, 2³², the conversion x86's 64-bit truncation keeping the low 32 bits — so 1.0
/// reads 0 (measured), 177/255 0xb1b1b200.
fn luminance_uint(x: f32) -> u32 {
    let p = x * 4_294_967_295.0_f32;
    if p.is_nan() {
        0
    } else {
        p as i64 as u32
    }
}

/// One value read, as the storage held it.
#[derive(Clone, Copy)]
enum Stored {
    /// An unsigned normalised integer `u` of `bits` bits.
    Unorm {
        u: u32,
        bits: u32,
    },
    Float(f32),
}

impl Stored {
    fn of(f: f32, from: ReadFrom) -> Stored {
        match from {
            // f = u / 255 in f32: u is recovered exactly.
            ReadFrom::Unorm8 => Stored::read_unorm(f, 8),
            ReadFrom::Unorm16 => Stored::read_unorm(f, 16),
            ReadFrom::Float => Stored::Float(f),
        }
    }

    /// f = u / (2ᵇ − 1) in f32: u is recovered exactly.
    fn read_unorm(f: f32, bits: u32) -> Stored {
        let max = ((1u64 << bits) - 1) as f32;
        Stored::Unorm {
            u: (f.clamp(0.0, 1.0) * max).round() as u32,
            bits,
        }
    }

    /// As an unsigned field of `bits` bits. A field of up to 8 bits is packed from the
    /// value as 8 bits (Mesa packs such types from bytes: a 16-bit or 10-bit texel into
    /// 5_6_5 goes through its byte, measured), by Mesa's `unorm_to` rule; a wider field
    /// from 8 bits by that rule too, from anything else round(clamp(f, 0, 1) · (2ᵇ − 1)).
    fn unorm(self, bits: u32) -> u32 {
        let max = (1u64 << bits) - 1;
        match self {
            Stored::Unorm { u, bits: from } if bits <= 8 || from == 8 => {
                unorm_to(unorm_to(u, from, 8), 8, bits)
            }
            Stored::Float(f) if bits <= 8 => {
                unorm_to((unit(f) * 255.0).round_ties_even() as u32, 8, bits)
            }
            Stored::Unorm { u, bits: from } => {
                let f = u as f32 * (1.0 / ((1u64 << from) - 1) as f32);
                Stored::Float(f).unorm(bits)
            }
            Stored::Float(f) => (f64::from(unit(f)) * max as f64).round() as u32,
        }
    }

    /// As a signed element of `bits` bits. From an integer, Mesa's `_mesa_unorm_to_snorm`:
    /// the unsigned conversion to `bits` − 1 bits (255 → 2ⁿ⁻¹ − 1, never negative); from a
    /// float, round(clamp(f, −1, 1) · (2ⁿ⁻¹ − 1)), but for 32 bits Mesa's
    /// `_mesa_float_to_snorm`: the product with the f32 2³¹ (the nearest float to
    /// 2³¹ − 1) rounded half to even and wrapped, so 1.0 gives INT_MIN (measured: an RGBA4
    /// texel of 8/15 reads 1145324672 as INT, one of 15/15 −2147483648).
    fn snorm(self, bits: u32) -> i64 {
        match self {
            Stored::Unorm { u, bits: from } => i64::from(unorm_to(u, from, bits - 1)),
            Stored::Float(f) if bits == 32 && (-1.0..=1.0).contains(&f) => {
                let p = (f * 2_147_483_647.0_f32).round_ties_even();
                i64::from(p as i64 as i32)
            }
            Stored::Float(f) => snorm(f, (1i64 << (bits - 1)) - 1),
        }
    }
}

/// A stored float as an unsigned normalised value: clamped to [0, 1], NaN as 0.
fn unit(f: f32) -> f32 {
    if f.is_nan() {
        0.0
    } else {
        f.clamp(0.0, 1.0)
    }
}

/// An unsigned normalised `u` of `from` bits as `to` bits, by Mesa's integer rule
/// (`_mesa_unorm_to_unorm`): narrower ⌊(u·(2ᵗᵒ − 1) + 2ᶠʳᵒᵐ⁻¹ − 1) / (2ᶠʳᵒᵐ − 1)⌋, wider
/// its EXTEND_NORMALIZED_INT — u's bits repeated: 8 to 10 bits 4u + (u >> 6), 16 to 32
/// bits u·65537, 16 to 31 bits (u << 15) | (u >> 1).
fn unorm_to(u: u32, from: u32, to: u32) -> u32 {
    let max = |b: u32| (1u64 << b) - 1;
    let u = u64::from(u).min(max(from));
    let v = match to.cmp(&from) {
        std::cmp::Ordering::Less => (u * max(to) + (1u64 << (from - 1)) - 1) / max(from),
        std::cmp::Ordering::Equal => u,
        std::cmp::Ordering::Greater => extend(u, from, to),
    };
    v as u32
}

/// Mesa's EXTEND_NORMALIZED_INT(x, from, to): x shifted up to `to` bits, the gap below
/// filled with x's own top bits, again and again while the gap is wider than x.
fn extend(x: u64, from: u32, to: u32) -> u64 {
    let gap = to - from;
    let rest = if from >= gap {
        x >> (from - gap)
    } else {
        extend(x, from, gap)
    };
    (x << gap) | rest
}

/// One component `v` in a signed type, as glReadPixels and glGetTexImage store it from
/// float storage; in a packed type (whose fields [`from_model`] packs from a FLOAT read),
/// the FLOAT itself.
pub fn component_bytes(v: f32, ty: PixelType) -> Vec<u8> {
    match ty {
        PixelType::Byte => vec![snorm(v, 127) as i8 as u8],
        PixelType::Short => (snorm(v, 32767) as i16).to_ne_bytes().to_vec(),
        PixelType::Int => (snorm(v, i32::MAX as i64) as i32).to_ne_bytes().to_vec(),
        _ => v.to_ne_bytes().to_vec(),
    }
}

/// A signed element `v` of `bits` bits as a normalised float: v / (2^(bits−1) − 1), at
/// least −1.
pub fn snorm_to_float(v: i64, bits: u32) -> f64 {
    let max = ((1i64 << (bits - 1)) - 1) as f64;
    (v as f64 / max).max(-1.0)
}

/// The components of packed groups `data` of `p`, each field normalised through its
/// 8-bit value ([`field_to_unorm8`]), in the format's order.
pub fn packed_components(data: &[u8], p: PackedType) -> Vec<f64> {
    let fields = p.fields();
    let mut values = Vec::with_capacity(4);
    let mut out = Vec::with_capacity(data.len() / p.bytes() * fields.len());
    for g in data.chunks_exact(p.bytes()) {
        group_values(
            &mut values,
            g,
            PixelFormat::Rgba,
            PixelType::Packed(p),
            &fields,
        );
        out.extend(values.iter().map(|u| u / 255.0));
    }
    out
}

/// A depth d ∈ [0, 1] in a signed type as Mesa's `_mesa_pack_depth_span` stores it, with
/// its FLOAT_TO_BYTE, FLOAT_TO_SHORT and FLOAT_TO_INT: BYTE (⌊255·d⌋ − 1)/2 and SHORT
/// (⌊65535·d⌋ − 1)/2 in single precision, the division truncated towards zero (GL 1.5
/// Table 4.7's ((2ᵇ − 1)·d − 1)/2 truncated, but for the product truncated first), INT
/// ⌊(2³¹ − 1)·d⌋ in double precision. Measured: 0.5 stored in 24 bits reads 63, 16383
/// and 1073741951.
fn depth_signed(d: f32, ty: PixelType) -> Vec<u8> {
    let half = |max: f32| ((max * d) as i32 - 1) / 2;
    match ty {
        PixelType::Byte => vec![half(255.0) as i8 as u8],
        PixelType::Short => (half(65535.0) as i16).to_ne_bytes().to_vec(),
        _ => ((2147483647.0 * f64::from(d)) as i32)
            .to_ne_bytes()
            .to_vec(),
    }
}

fn read_f32(b: &[u8]) -> f32 {
    f32::from_ne_bytes([b[0], b[1], b[2], b[3]])
}

/// round(clamp(f, −1, 1) · max), half away from zero; NaN as 0.
fn snorm(f: f32, max: i64) -> i64 {
    let f = if f.is_nan() { 0.0 } else { f.clamp(-1.0, 1.0) };
    (f64::from(f) * max as f64).round() as i64
}

#[cfg(test)]
#[path = "pixel_types_tests.rs"]
mod tests;
