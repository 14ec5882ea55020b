//! Client vertex arrays (GL 1.5 §2.8): the pointers a program sets with glVertexPointer,
//! glNormalPointer, glColorPointer, glTexCoordPointer (per client-active unit) and
//! glEdgeFlagPointer (GLboolean elements, one per vertex: 0 is FALSE),
//! glSecondaryColorPointer and glFogCoordPointer (GL 1.4), glIndexPointer (read only by
//! glArrayElement, which sets the current index: an RGBA buffer draws no index), their
//! enables, and the draws that read them (glDrawArrays, glDrawElements,
//! glDrawRangeElements, glMultiDrawArrays, glMultiDrawElements, glArrayElement,
//! glInterleavedArrays). This is client state: it
//! belongs to the front end (a script or the C library), not to the server state the
//! pipelines execute; a draw reads the arrays when it is called and becomes one
//! `Command::Draw` whose geometry holds the values read.
//!
//! Reading follows GL's rules: element i of an array starts at `pointer + i × stride`
//! (stride 0: the elements are packed); colours and normals of integer types are
//! normalised (Table 2.9); a vertex with fewer than four coordinates gets z = 0, w = 1; a
//! texture coordinate gets t = r = 0, q = 1. An attribute whose array is disabled takes
//! the current value, as the model does for a missing array.

use std::borrow::Cow;
use std::sync::Arc;

use glam::{Vec3, Vec4};

use super::api::{CType, Entry};
use super::args::Args;
use super::buffers::{Bindings, Buffers};
use super::geometry::{Geometry, Primitive};
use super::glenum::Family;
use super::immediate::Attr;
use super::state::MAX_TEXTURE_UNITS;

/// Where an array's elements are.
#[derive(Clone, Debug, PartialEq)]
pub enum ArrayData {
    /// No pointer given yet (or NULL).
    Null,
    /// Bytes carried with the call (a script's compound literal).
    Bytes(Arc<[u8]>),
    /// An address in the calling program's memory (the C library).
    Address(usize),
    /// A byte offset into a buffer object (ff::buffers), captured when the pointer was
    /// given with the buffer bound (GL 1.5 §2.9.4).
    Buffer { name: u32, offset: usize },
    /// The offset of a pointer into a buffer object since deleted. GL reverts the array's
    /// buffer binding to 0 (GL 1.5 §2.9.1); Mesa keeps the offset, which glGetPointerv
    /// answers and a draw reads as an address in the program's memory (address 0x8 for
    /// offset 8: Mesa 22.3 crashes). The layer reads nothing there (a documented
    /// deviation: the program's undefined read is not repeated).
    Orphaned(usize),
}

/// Reads the memory an [`ArrayData`] names: a front end that holds addresses says how.
pub trait ClientMemory {
    /// `len` bytes from `offset`, or `None` when there are none.
    fn read<'d>(&self, data: &'d ArrayData, offset: usize, len: usize) -> Option<Cow<'d, [u8]>>;
}

/// Memory that holds only bytes given with the calls (scripts).
pub struct BytesOnly;

impl ClientMemory for BytesOnly {
    fn read<'d>(&self, data: &'d ArrayData, offset: usize, len: usize) -> Option<Cow<'d, [u8]>> {
        match data {
            ArrayData::Bytes(b) => b.get(offset..offset.checked_add(len)?).map(Cow::Borrowed),
            ArrayData::Null
            | ArrayData::Address(_)
            | ArrayData::Buffer { .. }
            | ArrayData::Orphaned(_) => None,
        }
    }
}

/// One array pointer and its enable. GL defaults: disabled, size 4 (normals 3), FLOAT,
/// stride 0, NULL.
#[derive(Clone, Debug, PartialEq)]
pub struct ArrayPointer {
    pub enabled: bool,
    pub size: i32,
    pub ty: CType,
    pub stride: i32,
    pub data: ArrayData,
}

impl ArrayPointer {
    fn new(size: i32) -> Self {
        ArrayPointer {
            enabled: false,
            size,
            ty: CType::Float,
            stride: 0,
            data: ArrayData::Null,
        }
    }

    /// (components per element, bytes per component, bytes from one element to the next):
    /// element i starts at i × stride (stride 0: the elements are packed).
    fn layout(&self) -> (usize, usize, usize) {
        let size = (self.size.max(0) as usize).min(4);
        let elem = ctype_size(self.ty);
        let stride = if self.stride > 0 {
            self.stride as usize
        } else {
            size * elem
        };
        (size, elem, stride)
    }

    /// The bytes a read of elements `which` spans, as (start, length): from the first
    /// element's start to the last one's end. `None` for no elements, or a span past the
    /// address space.
    fn span(&self, which: Vertices) -> Option<(usize, usize)> {
        let (size, elem, stride) = self.layout();
        let (lo, hi) = which.bounds()?;
        let start = lo.checked_mul(stride)?;
        let len = (hi - lo).checked_mul(stride)?.checked_add(size * elem)?;
        Some((start, len))
    }

    /// The components of elements `which`, each over `default` and taken by `take` (a
    /// normalisation, or the float as it is); an element the memory does not hold is
    /// `default`. The span from the first to the last element named is read once, as GL
    /// reads an array, and decoded in place; only when the memory does not hold the whole
    /// span is each element read alone.
    fn components<T>(
        &self,
        mem: &dyn ClientMemory,
        which: Vertices,
        default: [f32; 4],
        take: impl Fn(f64) -> f32,
        make: impl Fn([f32; 4]) -> T,
    ) -> Vec<T> {
        let (size, elem, stride) = self.layout();
        let decode_one = |bytes: &[u8]| make(decode_element(self.ty, bytes, size, default, &take));
        let Some((lo, _)) = which.bounds() else {
            return Vec::new();
        };
        if let Some(bytes) = self
            .span(which)
            .and_then(|(start, len)| mem.read(&self.data, start, len))
        {
            let element = |i: usize| bytes.get((i - lo) * stride..(i - lo) * stride + size * elem);
            if let (CType::Float, Vertices::Run(..), true) = (self.ty, which, stride > 0) {
                // A run of elements `stride` apart: the span holds every one whole (it
                // ends with the last element's own bytes).
                return match size {
                    1 => float_run::<1, T>(&bytes, stride, default, &make),
                    2 => float_run::<2, T>(&bytes, stride, default, &make),
                    3 => float_run::<3, T>(&bytes, stride, default, &make),
                    _ => float_run::<4, T>(&bytes, stride, default, &make),
                };
            }
            if self.ty == CType::Float {
                // Every `take` is the identity on GLfloat (a float array is neither
                // normalised nor converted), so the components are copied bit for bit.
                return which
                    .iter()
                    .map(|i| element(i).map_or_else(|| make(default), |b| make(floats(b, default))))
                    .collect();
            }
            return which
                .iter()
                .map(|i| element(i).map_or_else(|| make(default), decode_one))
                .collect();
        }
        which
            .iter()
            .map(|i| {
                i.checked_mul(stride)
                    .and_then(|at| mem.read(&self.data, at, size * elem))
                    .map_or_else(|| make(default), |b| decode_one(&b))
            })
            .collect()
    }
}

/// The array elements a draw reads, in the order it reads them.
#[derive(Clone, Copy, Debug)]
enum Vertices<'a> {
    /// first, first + 1, …, end − 1 (glDrawArrays, and the elements glDrawElements'
    /// indices reach into).
    Run(usize, usize),
    /// These, in this order (glArrayElement).
    Each(&'a [usize]),
}

impl Vertices<'_> {
    /// The lowest and the highest element, or `None` for none.
    fn bounds(&self) -> Option<(usize, usize)> {
        match *self {
            Vertices::Run(first, end) => (first < end).then(|| (first, end - 1)),
            Vertices::Each(which) => which.iter().min().copied().zip(which.iter().max().copied()),
        }
    }

    fn is_empty(&self) -> bool {
        self.bounds().is_none()
    }

    fn iter(&self) -> impl Iterator<Item = usize> + '_ {
        let (run, each) = match *self {
            Vertices::Run(first, end) => (first..end, [].iter()),
            Vertices::Each(which) => (0..0, which.iter()),
        };
        run.chain(each.copied())
    }
}

fn ctype_size(t: CType) -> usize {
    match t {
        CType::Byte | CType::UByte => 1,
        CType::Short | CType::UShort => 2,
        CType::Int | CType::UInt | CType::Float => 4,
        CType::Double => 8,
    }
}

/// The first N GLfloats of each element of a run `stride` bytes apart, over `default`:
/// with N a constant each element is one fixed-size copy (this runs per vertex of every
/// client-array draw that is not a repeat).
fn float_run<const N: usize, T>(
    bytes: &[u8],
    stride: usize,
    default: [f32; 4],
    make: &impl Fn([f32; 4]) -> T,
) -> Vec<T> {
    bytes
        .chunks(stride)
        .map(|e| {
            let mut c = default;
            if let Some(e) = e.get(..4 * N) {
                for (k, slot) in c.iter_mut().enumerate().take(N) {
                    let at = 4 * k;
                    *slot = f32::from_ne_bytes([e[at], e[at + 1], e[at + 2], e[at + 3]]);
                }
            }
            make(c)
        })
        .collect()
}

/// The GLfloat components in `bytes` over `default` (up to four).
#[inline(always)]
fn floats(bytes: &[u8], mut default: [f32; 4]) -> [f32; 4] {
    for (slot, b) in default.iter_mut().zip(bytes.chunks_exact(4)) {
        *slot = f32::from_ne_bytes([b[0], b[1], b[2], b[3]]);
    }
    default
}

/// One element of `size` components of type `t` from `bytes` (at least that long), each
/// taken by `take` over `default`. The type is matched once per element, not per component.
#[inline]
fn decode_element(
    t: CType,
    bytes: &[u8],
    size: usize,
    default: [f32; 4],
    take: &impl Fn(f64) -> f32,
) -> [f32; 4] {
    #[inline(always)]
    fn each<const N: usize>(
        bytes: &[u8],
        size: usize,
        mut c: [f32; 4],
        read: impl Fn([u8; N]) -> f64,
        take: &impl Fn(f64) -> f32,
    ) -> [f32; 4] {
        for (slot, b) in c.iter_mut().zip(bytes.chunks_exact(N)).take(size) {
            if let Ok(b) = <[u8; N]>::try_from(b) {
                *slot = take(read(b));
            }
        }
        c
    }
    match t {
        CType::Byte => each(
            bytes,
            size,
            default,
            |b: [u8; 1]| f64::from(b[0] as i8),
            take,
        ),
        CType::UByte => each(bytes, size, default, |b: [u8; 1]| f64::from(b[0]), take),
        CType::Short => each(
            bytes,
            size,
            default,
            |b| f64::from(i16::from_ne_bytes(b)),
            take,
        ),
        CType::UShort => each(
            bytes,
            size,
            default,
            |b| f64::from(u16::from_ne_bytes(b)),
            take,
        ),
        CType::Int => each(
            bytes,
            size,
            default,
            |b| f64::from(i32::from_ne_bytes(b)),
            take,
        ),
        CType::UInt => each(
            bytes,
            size,
            default,
            |b| f64::from(u32::from_ne_bytes(b)),
            take,
        ),
        CType::Float => each(
            bytes,
            size,
            default,
            |b| f64::from(f32::from_ne_bytes(b)),
            take,
        ),
        CType::Double => each(bytes, size, default, f64::from_ne_bytes, take),
    }
}

/// The GL token of an array's element type (for glGet of *_ARRAY_TYPE).
pub fn type_token(t: CType) -> &'static str {
    TYPE_NAMES
        .iter()
        .find(|(_, c)| *c == t)
        .map_or("GL_FLOAT", |(n, _)| n)
}

/// The element types of colour arrays (glColorPointer, glSecondaryColorPointer).
const COLOR_TYPES: [CType; 8] = [
    CType::Byte,
    CType::UByte,
    CType::Short,
    CType::UShort,
    CType::Int,
    CType::UInt,
    CType::Float,
    CType::Double,
];

const TYPE_NAMES: [(&str, CType); 8] = [
    ("GL_BYTE", CType::Byte),
    ("GL_UNSIGNED_BYTE", CType::UByte),
    ("GL_SHORT", CType::Short),
    ("GL_UNSIGNED_SHORT", CType::UShort),
    ("GL_INT", CType::Int),
    ("GL_UNSIGNED_INT", CType::UInt),
    ("GL_FLOAT", CType::Float),
    ("GL_DOUBLE", CType::Double),
];

/// The client arrays of a front end.
#[derive(Clone, Debug, PartialEq)]
pub struct ClientArrays {
    pub vertex: ArrayPointer,
    pub normal: ArrayPointer,
    pub color: ArrayPointer,
    pub texcoord: [ArrayPointer; MAX_TEXTURE_UNITS],
    /// glEdgeFlagPointer: size 1, type GLboolean (UNSIGNED_BYTE).
    pub edge_flag: ArrayPointer,
    /// glSecondaryColorPointer: size 3 or 4 (GL default 3; only RGB is drawn).
    pub secondary_color: ArrayPointer,
    /// glFogCoordPointer: size 1, FLOAT or DOUBLE.
    pub fog_coord: ArrayPointer,
    /// glIndexPointer: size 1.
    pub index: ArrayPointer,
    /// glClientActiveTexture: the unit glTexCoordPointer and the TEXTURE_COORD_ARRAY
    /// enable address. GL default: 0.
    pub client_active: u8,
    /// glLockArraysEXT's range (EXT_compiled_vertex_array), `None` when unlocked. A hint
    /// that the locked elements will not change: draws read the arrays as they are either
    /// way, as Mesa does, so only the queries and the errors see it.
    pub lock: Option<ArrayLock>,
}

/// The elements glLockArraysEXT locked: ARRAY_ELEMENT_LOCK_FIRST_EXT and _COUNT_EXT.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ArrayLock {
    pub first: i32,
    pub count: i32,
}

impl Default for ClientArrays {
    fn default() -> Self {
        ClientArrays {
            vertex: ArrayPointer::new(4),
            normal: ArrayPointer::new(3),
            color: ArrayPointer::new(4),
            texcoord: std::array::from_fn(|_| ArrayPointer::new(4)),
            edge_flag: ArrayPointer {
                ty: CType::UByte,
                ..ArrayPointer::new(1)
            },
            secondary_color: ArrayPointer::new(3),
            fog_coord: ArrayPointer::new(1),
            index: ArrayPointer::new(1),
            client_active: 0,
            lock: None,
        }
    }
}

/// What one element of the enabled arrays gives (glArrayElement).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Element {
    pub color: Option<Vec4>,
    pub normal: Option<Vec3>,
    pub texcoords: [Option<Vec4>; MAX_TEXTURE_UNITS],
    pub edge_flag: Option<bool>,
    pub secondary_color: Option<Vec4>,
    pub fog_coord: Option<f32>,
    pub index: Option<f32>,
    pub position: Option<Vec4>,
}

impl Element {
    /// The element's attribute values (all but the position), as the immediate-mode calls
    /// that set them.
    pub fn attributes(&self) -> impl Iterator<Item = Attr> + '_ {
        let units = self
            .texcoords
            .iter()
            .enumerate()
            .filter_map(|(u, t)| Some(Attr::TexCoord(u8::try_from(u).ok()?, (*t)?)));
        self.normal
            .map(Attr::Normal)
            .into_iter()
            .chain(self.color.map(Attr::Color))
            .chain(self.secondary_color.map(Attr::SecondaryColor))
            .chain(self.fog_coord.map(Attr::FogCoord))
            .chain(self.index.map(Attr::Index))
            .chain(units)
            .chain(self.edge_flag.map(Attr::EdgeFlag))
    }

    /// The values of element 0 of `g` (a one-vertex geometry).
    fn of(g: &Geometry) -> Element {
        let mut e = Element {
            color: Geometry::last(&g.colors),
            normal: Geometry::last(&g.normals),
            edge_flag: Geometry::last(&g.edge_flags),
            secondary_color: Geometry::last(&g.secondary_colors),
            fog_coord: Geometry::last(&g.fog_coords),
            ..Element::default()
        };
        for (u, t) in g.texcoords.iter().enumerate() {
            e.texcoords[u] = Geometry::last(t);
        }
        e
    }
}

/// What a client call did.
#[derive(Debug, PartialEq)]
pub enum ClientEffect {
    /// Client state changed; nothing to draw.
    State,
    /// A draw: the geometry read from the arrays (`None` when the vertex array is
    /// disabled or the count is 0: GL draws nothing).
    Draw(Option<Geometry>),
    /// glMultiDrawArrays / glMultiDrawElements: one draw per list, in order (GL 1.5
    /// §2.8: as that many glDrawArrays or glDrawElements), the empty ones left out; and
    /// whether the first list's count was 0, which Mesa draws differently when the call
    /// is executed ([`FirstCount`]).
    Draws(Vec<Geometry>, FirstCount),
    /// glArrayElement: the element's values, for immediate mode.
    Element(Element),
}

/// Whether a glMultiDraw* call's first count is 0. Executed, such a call draws nothing
/// at all on Mesa 22.3 (llvmpipe), whatever the later counts (measured: LINE_STRIP counts
/// {0, 4, 2} draw nothing, {4, 0, 2} both strips, {1, 4, 2} the 4-strip; drawcount 1
/// with count 0 nothing; glMultiDrawElements {0, 4} nothing): its draw takes the first
/// count for the whole call's. GL 1.5 §2.8 draws each list as glDrawArrays would; the
/// layer follows Mesa (a Mesa deviation). A display list keeps the non-empty draws and
/// draws them all when called, on Mesa as here.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FirstCount {
    Empty,
    NotEmpty,
}

impl FirstCount {
    fn of(counts: &[usize]) -> FirstCount {
        match counts.first() {
            Some(0) => FirstCount::Empty,
            _ => FirstCount::NotEmpty,
        }
    }
}

impl ClientArrays {
    /// The enable of the array `cap` names (VERTEX_ARRAY … FOG_COORD_ARRAY; the texture
    /// coordinates of the client active unit), None for another token.
    pub fn enable_of(&mut self, cap: u32) -> Option<&mut bool> {
        use super::glenum::registry as r;
        Some(match cap {
            r::VERTEX_ARRAY => &mut self.vertex.enabled,
            r::NORMAL_ARRAY => &mut self.normal.enabled,
            r::COLOR_ARRAY => &mut self.color.enabled,
            r::TEXTURE_COORD_ARRAY => &mut self.texcoord[usize::from(self.client_active)].enabled,
            r::EDGE_FLAG_ARRAY => &mut self.edge_flag.enabled,
            r::SECONDARY_COLOR_ARRAY => &mut self.secondary_color.enabled,
            r::FOG_COORD_ARRAY => &mut self.fog_coord.enabled,
            r::INDEX_ARRAY => &mut self.index.enabled,
            _ => return None,
        })
    }

    /// Whether `entry` is one of the client-array calls.
    pub fn handles(entry: Entry) -> bool {
        matches!(
            entry,
            Entry::VertexPointer
                | Entry::NormalPointer
                | Entry::ColorPointer
                | Entry::TexCoordPointer
                | Entry::EdgeFlagPointer
                | Entry::SecondaryColorPointer
                | Entry::SecondaryColorPointerEXT
                | Entry::FogCoordPointer
                | Entry::FogCoordPointerEXT
                | Entry::IndexPointer
                | Entry::ClientActiveTexture
                | Entry::ClientActiveTextureARB
                | Entry::EnableClientState
                | Entry::DisableClientState
                | Entry::DrawArrays
                | Entry::DrawElements
                | Entry::DrawRangeElements
                | Entry::MultiDrawArrays
                | Entry::MultiDrawElements
                | Entry::ArrayElement
                | Entry::InterleavedArrays
                | Entry::LockArraysEXT
                | Entry::UnlockArraysEXT
        )
    }

    /// Runs one client-array call. GL errors: a size, stride or count out of range is
    /// INVALID_VALUE; a type or mode outside the set INVALID_ENUM (GL 1.5 §2.8).
    /// `bound` says which buffer objects pointers and indices are offsets into.
    pub fn call<A: Args>(
        &mut self,
        c: &A,
        mem: &dyn ClientMemory,
        bound: Bindings,
    ) -> Result<ClientEffect, A::Error> {
        match c.entry() {
            Entry::VertexPointer => {
                let p = self.pointer(
                    c,
                    0,
                    &[2, 3, 4],
                    &[CType::Short, CType::Int, CType::Float, CType::Double],
                    bound,
                )?;
                self.vertex = ArrayPointer {
                    enabled: self.vertex.enabled,
                    ..p
                };
            }
            Entry::NormalPointer => {
                let ty = self.array_type(
                    c,
                    0,
                    &[
                        CType::Byte,
                        CType::Short,
                        CType::Int,
                        CType::Float,
                        CType::Double,
                    ],
                )?;
                let stride = stride(c, 1)?;
                self.normal = ArrayPointer {
                    enabled: self.normal.enabled,
                    size: 3,
                    ty,
                    stride,
                    data: Buffers::source(c, 2, bound.array)?,
                };
            }
            Entry::ColorPointer => {
                let p = self.pointer(c, 0, &[3, 4], &COLOR_TYPES, bound)?;
                self.color = ArrayPointer {
                    enabled: self.color.enabled,
                    ..p
                };
            }
            Entry::TexCoordPointer => {
                let p = self.pointer(
                    c,
                    0,
                    &[1, 2, 3, 4],
                    &[CType::Short, CType::Int, CType::Float, CType::Double],
                    bound,
                )?;
                let unit = &mut self.texcoord[usize::from(self.client_active)];
                *unit = ArrayPointer {
                    enabled: unit.enabled,
                    ..p
                };
            }
            Entry::EdgeFlagPointer => {
                let stride = stride(c, 0)?;
                self.edge_flag = ArrayPointer {
                    enabled: self.edge_flag.enabled,
                    size: 1,
                    ty: CType::UByte,
                    stride,
                    data: Buffers::source(c, 1, bound.array)?,
                };
            }
            // Sizes 3 and 4, the colour types (Mesa 22.3 measured, tests/c/secondary.c).
            Entry::SecondaryColorPointer | Entry::SecondaryColorPointerEXT => {
                let p = self.pointer(c, 0, &[3, 4], &COLOR_TYPES, bound)?;
                self.secondary_color = ArrayPointer {
                    enabled: self.secondary_color.enabled,
                    ..p
                };
            }
            Entry::FogCoordPointer | Entry::FogCoordPointerEXT => {
                let ty = self.array_type(c, 0, &[CType::Float, CType::Double])?;
                let stride = stride(c, 1)?;
                self.fog_coord = ArrayPointer {
                    enabled: self.fog_coord.enabled,
                    size: 1,
                    ty,
                    stride,
                    data: Buffers::source(c, 2, bound.array)?,
                };
            }
            // UNSIGNED_BYTE, SHORT, INT, FLOAT, DOUBLE (GL 1.5 Table 2.4).
            Entry::IndexPointer => {
                let ty = self.array_type(
                    c,
                    0,
                    &[
                        CType::UByte,
                        CType::Short,
                        CType::Int,
                        CType::Float,
                        CType::Double,
                    ],
                )?;
                let stride = stride(c, 1)?;
                self.index = ArrayPointer {
                    enabled: self.index.enabled,
                    size: 1,
                    ty,
                    stride,
                    data: Buffers::source(c, 2, bound.array)?,
                };
            }
            Entry::ClientActiveTexture | Entry::ClientActiveTextureARB => {
                let unit = c.family(0, Family::Texture)?;
                if usize::from(unit) >= MAX_TEXTURE_UNITS {
                    return Err(c.unknown(0, vec!["GL_TEXTURE0..GL_TEXTURE7"]));
                }
                self.client_active = unit;
            }
            Entry::EnableClientState | Entry::DisableClientState => {
                let on = c.entry() == Entry::EnableClientState;
                let array = c.pname(
                    0,
                    &[
                        "GL_VERTEX_ARRAY",
                        "GL_NORMAL_ARRAY",
                        "GL_COLOR_ARRAY",
                        "GL_TEXTURE_COORD_ARRAY",
                        "GL_INDEX_ARRAY",
                        "GL_EDGE_FLAG_ARRAY",
                        "GL_SECONDARY_COLOR_ARRAY",
                        "GL_FOG_COORD_ARRAY",
                    ],
                )?;
                let cap = super::glenum::value_of(array);
                if let Some(enabled) = cap.and_then(|cap| self.enable_of(cap)) {
                    *enabled = on;
                }
            }
            Entry::DrawArrays => {
                let mode = c.enm(0)?;
                let first = c.i32(1)?;
                let count = c.i32(2)?;
                if count < 0 {
                    return Err(c.bad(2, "a count of 0 or more"));
                }
                // A first below 0 is no error (GL 1.5 defines none; Mesa raises none), but
                // what Mesa draws is no read of pointer + first · stride: its vertex fetch
                // takes the index as unsigned, past the array, and gives what its
                // out-of-bounds fetch gives (measured: element −1 of V + 1 as (0, 0), while
                // first −2 of V + 2 draws another shape again). The layer draws nothing
                // for it (a documented deviation), and reads nothing before the array.
                let Ok(first) = usize::try_from(first) else {
                    return Ok(ClientEffect::Draw(None));
                };
                let which = Vertices::Run(first, first + count as usize);
                return Ok(ClientEffect::Draw(self.geometry(mode, which, None, mem)));
            }
            Entry::DrawElements | Entry::DrawRangeElements => {
                let ranged = c.entry() == Entry::DrawRangeElements;
                let k = if ranged { 2 } else { 0 };
                let mode: Primitive = c.enm(0)?;
                if ranged && c.u32(2)? < c.u32(1)? {
                    return Err(c.bad(2, "end ≥ start"));
                }
                let count = c.i32(1 + k)?;
                if count < 0 {
                    return Err(c.bad(1 + k, "a count of 0 or more"));
                }
                let ty = index_type(c, 2 + k)?;
                // No indices are read for a count of 0: no draw, and no error even for a
                // NULL pointer (GL 1.5 §2.8; measured on Mesa).
                if count == 0 {
                    return Ok(ClientEffect::Draw(None));
                }
                // With a buffer bound to ELEMENT_ARRAY_BUFFER, `indices` is an offset
                // into it (GL 1.5 §2.9.5).
                let data = Buffers::source(c, 3 + k, bound.element)?;
                let indices = read_indices(mem, &data, count as usize, ty)
                    .ok_or_else(|| c.bad(3 + k, "indices"))?;
                return Ok(ClientEffect::Draw(self.indexed(mode, indices, mem)));
            }
            // Checked in Mesa's order (measured with tests/c/multidraw.c): a drawcount
            // below 0 is INVALID_VALUE before the mode (and the index type) are
            // INVALID_ENUM, a count below 0 INVALID_VALUE after them. A first index below 0
            // is no error, and that draw is left out, as glDrawArrays leaves it.
            Entry::MultiDrawArrays => {
                let n = draw_count(c, 3)?;
                let mode: Primitive = c.enm(0)?;
                let first = ints(c, 1, n)?;
                let counts = counts(c, 2, n)?;
                let first_count = FirstCount::of(&counts);
                let draws = first
                    .iter()
                    .zip(counts)
                    .filter(|(f, _)| **f >= 0.0)
                    .filter_map(|(f, k)| {
                        let which = Vertices::Run(*f as usize, *f as usize + k);
                        self.geometry(mode, which, None, mem)
                    })
                    .collect();
                return Ok(ClientEffect::Draws(draws, first_count));
            }
            Entry::MultiDrawElements => {
                let n = draw_count(c, 4)?;
                let mode: Primitive = c.enm(0)?;
                let ty = index_type(c, 2)?;
                let counts = counts(c, 1, n)?;
                let first_count = FirstCount::of(&counts);
                let lists = c.pointers(3, n, bound.element)?;
                let mut draws = Vec::with_capacity(n);
                for (data, k) in lists.iter().zip(counts) {
                    let indices =
                        read_indices(mem, data, k, ty).ok_or_else(|| c.bad(3, "indices"))?;
                    draws.extend(self.indexed(mode, indices, mem));
                }
                return Ok(ClientEffect::Draws(draws, first_count));
            }
            Entry::ArrayElement => {
                let i = c.i32(0)?;
                if i < 0 {
                    return Err(c.bad(0, "an index of 0 or more"));
                }
                return Ok(ClientEffect::Element(self.element(i as usize, mem)));
            }
            Entry::InterleavedArrays => self.interleaved(c, bound)?,
            // EXT_compiled_vertex_array, checked in Mesa's order (measured: first < 0 and
            // count ≤ 0 are INVALID_VALUE before a held lock is INVALID_OPERATION).
            Entry::LockArraysEXT => {
                let (first, count) = (c.i32(0)?, c.i32(1)?);
                if first < 0 {
                    return Err(c.bad(0, "a first element of 0 or more"));
                }
                if count <= 0 {
                    return Err(c.bad(1, "a count of 1 or more"));
                }
                if self.lock.is_some() {
                    return Err(c.immediate("the arrays are already locked"));
                }
                self.lock = Some(ArrayLock { first, count });
            }
            Entry::UnlockArraysEXT => {
                if self.lock.take().is_none() {
                    return Err(c.immediate("the arrays are not locked"));
                }
            }
            _ => return Err(c.unsupported()),
        }
        Ok(ClientEffect::State)
    }

    fn array_type<A: Args>(&self, c: &A, i: usize, allowed: &[CType]) -> Result<CType, A::Error> {
        let names: Vec<&'static str> = TYPE_NAMES
            .iter()
            .filter(|(_, t)| allowed.contains(t))
            .map(|(n, _)| *n)
            .collect();
        let name = c.pname(i, &names)?;
        Ok(TYPE_NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, t)| *t)
            .unwrap_or(CType::Float))
    }

    /// glXPointer(size, type, stride, pointer).
    fn pointer<A: Args>(
        &self,
        c: &A,
        from: usize,
        sizes: &[i32],
        types: &[CType],
        bound: Bindings,
    ) -> Result<ArrayPointer, A::Error> {
        let size = c.i32(from)?;
        if !sizes.contains(&size) {
            return Err(c.bad(from, "a size the array allows"));
        }
        let ty = self.array_type(c, from + 1, types)?;
        let stride = stride(c, from + 2)?;
        Ok(ArrayPointer {
            enabled: false,
            size,
            ty,
            stride,
            data: Buffers::source(c, from + 3, bound.array)?,
        })
    }

    /// Pointers into buffer `name`, deleted, keep their offset and point nowhere
    /// ([`ArrayData::Orphaned`]): GL reverts the arrays' buffer bindings to 0 (GL 1.5
    /// §2.9.1), glGetPointerv still answers the offset, as on Mesa.
    pub fn forget_buffer(&mut self, name: u32) {
        for a in self.pointers_mut() {
            if let ArrayData::Buffer { name: n, offset } = a.data {
                if n == name {
                    a.data = ArrayData::Orphaned(offset);
                }
            }
        }
    }

    /// The buffers the arrays point into.
    pub fn buffer_names(&self) -> Vec<u32> {
        self.vertex_pointers()
            .chain(std::iter::once(&self.index))
            .filter_map(|a| match a.data {
                ArrayData::Buffer { name, .. } => Some(name),
                _ => None,
            })
            .collect()
    }

    fn pointers_mut(&mut self) -> impl Iterator<Item = &mut ArrayPointer> {
        [
            &mut self.vertex,
            &mut self.normal,
            &mut self.color,
            &mut self.edge_flag,
            &mut self.secondary_color,
            &mut self.fog_coord,
            &mut self.index,
        ]
        .into_iter()
        .chain(self.texcoord.iter_mut())
    }

    /// Every array but the colour-index one, which only glArrayElement reads.
    fn vertex_pointers(&self) -> impl Iterator<Item = &ArrayPointer> + '_ {
        [
            &self.vertex,
            &self.normal,
            &self.color,
            &self.edge_flag,
            &self.secondary_color,
            &self.fog_coord,
        ]
        .into_iter()
        .chain(self.texcoord.iter())
    }

    /// The arrays a draw reads: the enabled ones but the colour-index array.
    pub fn drawn(&self) -> impl Iterator<Item = &ArrayPointer> + '_ {
        self.vertex_pointers().filter(|a| a.enabled)
    }

    /// What a draw of elements `first..end` reads from each array it reads: the array's
    /// memory and the span of it, (start, length) in bytes.
    pub fn spans(
        &self,
        first: usize,
        end: usize,
    ) -> impl Iterator<Item = (&ArrayData, Option<(usize, usize)>)> + '_ {
        self.drawn()
            .map(move |a| (&a.data, a.span(Vertices::Run(first, end))))
    }

    /// The geometry of vertices `which` (each an element index), drawn through `indices`
    /// into them when given.
    fn geometry(
        &self,
        mode: Primitive,
        which: Vertices,
        indices: Option<Vec<u32>>,
        mem: &dyn ClientMemory,
    ) -> Option<Geometry> {
        if !self.vertex.enabled || which.is_empty() {
            return None;
        }
        const XYZW: [f32; 4] = [0.0, 0.0, 0.0, 1.0];
        let float = |x: f64| x as f32;
        let vec3 = |n: [f32; 4]| Vec3::new(n[0], n[1], n[2]);
        let positions = self
            .vertex
            .components(mem, which, XYZW, float, Vec4::from_array);
        let mut g = Geometry::new(mode, positions);
        if self.normal.enabled {
            let ty = self.normal.ty;
            let default = [0.0, 0.0, 1.0, 0.0];
            let normalized = |x| ty.normalized_array(x);
            g.normals = Some(
                self.normal
                    .components(mem, which, default, normalized, vec3),
            );
        }
        if self.color.enabled {
            let ty = self.color.ty;
            let normalized = |x| ty.normalized_array(x);
            let c = self
                .color
                .components(mem, which, XYZW, normalized, Vec4::from_array);
            g.colors = Some(c);
        }
        if self.secondary_color.enabled {
            let ty = self.secondary_color.ty;
            let normalized = |x| ty.normalized_array(x);
            g.secondary_colors = Some(self.secondary_color.components(
                mem,
                which,
                XYZW,
                normalized,
                Vec4::from_array,
            ));
        }
        if self.fog_coord.enabled {
            let first = |v: [f32; 4]| v[0];
            g.fog_coords = Some(self.fog_coord.components(mem, which, XYZW, float, first));
        }
        for (unit, t) in self.texcoord.iter().enumerate() {
            if t.enabled {
                g.texcoords[unit] = Some(t.components(mem, which, XYZW, float, Vec4::from_array));
            }
        }
        if self.edge_flag.enabled {
            // A GLboolean per vertex; an element the memory lacks is TRUE.
            let flag = |f: [f32; 4]| f[0] != 0.0;
            g.edge_flags = Some(self.edge_flag.components(mem, which, [1.0; 4], float, flag));
        }
        g.indices = indices;
        Some(g)
    }

    /// The geometry of `indices` into the arrays (glDrawElements).
    fn indexed(
        &self,
        mode: Primitive,
        indices: Vec<u32>,
        mem: &dyn ClientMemory,
    ) -> Option<Geometry> {
        let n = match indices.is_empty() {
            true => 0,
            false => super::geometry::max_index(&indices) as usize + 1,
        };
        self.geometry(mode, Vertices::Run(0, n), Some(indices), mem)
    }

    /// glArrayElement(i): the values of element i of every enabled array.
    fn element(&self, i: usize, mem: &dyn ClientMemory) -> Element {
        let index = self.index.enabled.then(|| {
            let first = |v: [f32; 4]| v[0];
            let v = self
                .index
                .components(mem, Vertices::Each(&[i]), [0.0; 4], |x| x as f32, first);
            v.first().copied().unwrap_or(0.0)
        });
        let Some(mut g) = self.geometry(Primitive::Points, Vertices::Each(&[i]), None, mem) else {
            // Without a vertex array the other arrays still set their current values.
            let mut with_vertex = self.clone();
            with_vertex.vertex.enabled = true;
            let mut e = with_vertex
                .geometry(Primitive::Points, Vertices::Each(&[i]), None, mem)
                .map_or_else(Element::default, |g| Element::of(&g));
            e.index = index;
            return e;
        };
        let mut e = Element::of(&g);
        e.index = index;
        e.position = g.positions.pop();
        e
    }

    /// glInterleavedArrays(format, stride, pointer): sets and enables the arrays the
    /// format names, disables the others — the edge-flag and colour-index arrays among
    /// them (GL 1.5 §2.8, Table 2.5) — on the client-active unit.
    fn interleaved<A: Args>(&mut self, c: &A, bound: Bindings) -> Result<(), A::Error> {
        // (name, texcoord size, colour size, colour type, normal, vertex size).
        const FORMATS: [(&str, i32, i32, CType, bool, i32); 14] = [
            ("GL_V2F", 0, 0, CType::Float, false, 2),
            ("GL_V3F", 0, 0, CType::Float, false, 3),
            ("GL_C4UB_V2F", 0, 4, CType::UByte, false, 2),
            ("GL_C4UB_V3F", 0, 4, CType::UByte, false, 3),
            ("GL_C3F_V3F", 0, 3, CType::Float, false, 3),
            ("GL_N3F_V3F", 0, 0, CType::Float, true, 3),
            ("GL_C4F_N3F_V3F", 0, 4, CType::Float, true, 3),
            ("GL_T2F_V3F", 2, 0, CType::Float, false, 3),
            ("GL_T4F_V4F", 4, 0, CType::Float, false, 4),
            ("GL_T2F_C4UB_V3F", 2, 4, CType::UByte, false, 3),
            ("GL_T2F_C3F_V3F", 2, 3, CType::Float, false, 3),
            ("GL_T2F_N3F_V3F", 2, 0, CType::Float, true, 3),
            ("GL_T2F_C4F_N3F_V3F", 2, 4, CType::Float, true, 3),
            ("GL_T4F_C4F_N3F_V4F", 4, 4, CType::Float, true, 4),
        ];
        let names: Vec<&'static str> = FORMATS.iter().map(|f| f.0).collect();
        let name = c.pname(0, &names)?;
        let &(_, tc, cc, cty, normal, vc) = FORMATS
            .iter()
            .find(|f| f.0 == name)
            .ok_or_else(|| c.unknown(0, names.clone()))?;
        let given = stride(c, 1)?;
        let data = Buffers::source(c, 2, bound.array)?;
        // Offsets in bytes: texcoord, colour, normal, vertex (floats are 4 bytes; a
        // C4UB colour takes 4 bytes).
        let colour_bytes = if cty == CType::UByte { 4 } else { 4 * cc };
        let oc = 4 * tc;
        let on = oc + colour_bytes * i32::from(cc > 0);
        let ov = on + 12 * i32::from(normal);
        let whole = ov + 4 * vc;
        let stride = if given == 0 { whole } else { given };
        let at = |offset: i32| match &data {
            ArrayData::Bytes(b) => ArrayData::Bytes(
                b.get(offset as usize..)
                    .map_or_else(|| Arc::from(Vec::new()), Arc::from),
            ),
            ArrayData::Address(a) => ArrayData::Address(a + offset as usize),
            ArrayData::Buffer { name, offset: o } => ArrayData::Buffer {
                name: *name,
                offset: o + offset as usize,
            },
            ArrayData::Orphaned(o) => ArrayData::Orphaned(o + offset as usize),
            ArrayData::Null => ArrayData::Null,
        };
        let make = |size: i32, ty: CType, offset: i32, on: bool| ArrayPointer {
            enabled: on,
            size,
            ty,
            stride,
            data: at(offset),
        };
        let unit = usize::from(self.client_active);
        self.texcoord[unit] = if tc > 0 {
            make(tc, CType::Float, 0, true)
        } else {
            ArrayPointer {
                enabled: false,
                ..self.texcoord[unit].clone()
            }
        };
        self.color = if cc > 0 {
            make(cc, cty, oc, true)
        } else {
            ArrayPointer {
                enabled: false,
                ..self.color.clone()
            }
        };
        self.normal = if normal {
            make(3, CType::Float, on, true)
        } else {
            ArrayPointer {
                enabled: false,
                ..self.normal.clone()
            }
        };
        self.vertex = make(vc, CType::Float, ov, true);
        self.edge_flag.enabled = false;
        self.index.enabled = false;
        Ok(())
    }
}

fn stride<A: Args>(c: &A, i: usize) -> Result<i32, A::Error> {
    let s = c.i32(i)?;
    if s < 0 {
        return Err(c.bad(i, "a stride of 0 or more"));
    }
    Ok(s)
}

/// `count` indices of type `ty` from `data`, or `None` when the memory does not hold them.
fn read_indices(
    mem: &dyn ClientMemory,
    data: &ArrayData,
    count: usize,
    ty: CType,
) -> Option<Vec<u32>> {
    let size = ctype_size(ty);
    let bytes = mem.read(data, 0, count.checked_mul(size)?)?;
    // The index types are UNSIGNED_BYTE, _SHORT and _INT (`index_type`), each read by its
    // own loop.
    Some(match ty {
        CType::UByte | CType::Byte => bytes.iter().map(|&b| u32::from(b)).collect(),
        // Aligned (as a program's GLushort array is), widened in one vectorised pass.
        CType::UShort | CType::Short => match bytemuck::try_cast_slice::<u8, u16>(&bytes) {
            Ok(shorts) => shorts.iter().map(|&i| u32::from(i)).collect(),
            Err(_) => bytes
                .chunks_exact(2)
                .map(|b| u32::from(u16::from_ne_bytes([b[0], b[1]])))
                .collect(),
        },
        _ => bytes
            .chunks_exact(4)
            .map(|b| u32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
            .collect(),
    })
}

/// glMultiDraw*'s drawcount: below 0 is INVALID_VALUE.
fn draw_count<A: Args>(c: &A, i: usize) -> Result<usize, A::Error> {
    let n = c.i32(i)?;
    if n < 0 {
        return Err(c.bad(i, "a draw count of 0 or more"));
    }
    Ok(n as usize)
}

/// `n` GLint or GLsizei values of an array argument (none read for `n` = 0).
fn ints<A: Args>(c: &A, i: usize, n: usize) -> Result<Vec<f64>, A::Error> {
    if n == 0 {
        return Ok(Vec::new());
    }
    c.array_as(i, n, CType::Int)
}

/// glMultiDraw*'s `n` counts: one below 0 is INVALID_VALUE.
fn counts<A: Args>(c: &A, i: usize, n: usize) -> Result<Vec<usize>, A::Error> {
    let counts = ints(c, i, n)?;
    if counts.iter().any(|k| *k < 0.0) {
        return Err(c.bad(i, "counts of 0 or more"));
    }
    Ok(counts.into_iter().map(|k| k as usize).collect())
}

/// glDrawElements' index type: UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT.
fn index_type<A: Args>(c: &A, i: usize) -> Result<CType, A::Error> {
    let name = c.pname(
        i,
        &["GL_UNSIGNED_BYTE", "GL_UNSIGNED_SHORT", "GL_UNSIGNED_INT"],
    )?;
    Ok(match name {
        "GL_UNSIGNED_BYTE" => CType::UByte,
        "GL_UNSIGNED_SHORT" => CType::UShort,
        _ => CType::UInt,
    })
}
