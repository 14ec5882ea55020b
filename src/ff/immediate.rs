//! Immediate mode: glBegin … glEnd with the vertex-attribute calls folded into one
//! `Command::Draw`, for either front end (scripts and the C library).
//!
//! An attribute called inside the pair becomes a per-vertex array; vertices before its
//! first call take the value current at glBegin (GL 1.5 §2.7: the current value is what
//! each vertex copies). Outside the pair an attribute call is a plain state command
//! (`Command::Color`…). A draw changes no state, so after it the values the pair left
//! current follow as their own commands, and the state after the commands equals GL's
//! after glEnd. Inside the
//! pair only the attribute calls and glMaterial are allowed (§2.6.3: anything else is
//! INVALID_OPERATION). A glMaterial inside the pair gives each vertex from the next on the
//! material it sets (§2.14.3, as Mesa lights it: per vertex), in per-vertex arrays of the
//! values it set (`VertexMaterials`); the material at glBegin fills the vertices before
//! it, and glEnd leaves the last values as the material state.

use std::sync::Arc;

use glam::{Vec3, Vec4};

use super::api::{Attrib, AttribCall, Entry};
use super::args::Args;
use super::client::Element;
use super::command::Command;
use super::fragment::Face;
use super::geometry::{Geometry, MaterialSlot, Primitive};
use super::glenum::Family;
use super::light::{MaterialParam, Materials};
use super::state::{CurrentValues, MAX_TEXTURE_UNITS};

/// The immediate-mode half of a front end: whether a glBegin is open, and what it holds.
#[derive(Debug, Default)]
pub struct Immediate {
    open: Option<Open>,
    /// The vertex count of the last pair: the arrays of the next are sized for it (a
    /// program draws the same shapes frame after frame).
    last_vertices: usize,
}

/// What a glBegin starts from, as the commands so far leave it: the current values each
/// vertex copies (GL 1.5 §2.7) and the material (§2.14.3), which a glMaterial inside the
/// pair makes per vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Start {
    pub current: CurrentValues,
    pub materials: Materials,
    /// LIST_BASE, which glCallLists adds to its names. A glPopAttrib(LIST_BIT) met in the
    /// same replay is not followed: the model restores the base when it applies the pop.
    pub list_base: u32,
}

impl Start {
    /// GL's initial values.
    pub const DEFAULT: Start = Start {
        current: CurrentValues::DEFAULT,
        materials: Materials::DEFAULT,
        list_base: 0,
    };

    /// The model's values.
    pub fn of(state: &super::state::FixedState) -> Start {
        Start {
            current: state.current,
            materials: state.materials,
            list_base: state.list_base,
        }
    }

    /// Follows a command emitted after this point (a display list's commands, met before
    /// the model applies them).
    pub fn follow(&mut self, cmd: &Command) {
        super::lists::follow(&mut self.current, cmd);
        match cmd {
            // An invalid value is refused by the model and changes nothing.
            Command::Material { face, param } => {
                let _ = self.materials.set(*face, *param);
            }
            Command::ListBase(base) => self.list_base = *base,
            _ => {}
        }
    }
}

/// A glBegin not yet ended.
#[derive(Debug)]
struct Open {
    geometry: Geometry,
    /// The current values at glBegin: what vertices before an attribute's first call get.
    begin: CurrentValues,
    /// The current values as the calls inside the pair have set them.
    current: CurrentValues,
    /// Attributes called inside the pair, by [`Attr::set`]'s slot: each gets an array at
    /// the next vertex, so a value set after the last vertex only stays current.
    called: [bool; SLOTS],
    /// Some attribute was called whose array the next vertex creates.
    pending: bool,
    /// Some texture unit has an array (the vertex loop over the units is skipped if not).
    texcoord_arrays: bool,
    /// The material at glBegin, and as the glMaterial calls inside the pair have set it.
    begin_materials: Materials,
    materials: Materials,
    /// The material slots set inside the pair (bits of `MaterialSlot::bit`).
    material_called: u16,
    /// The pair's glMaterial calls, in order: they follow the draw as state commands.
    material_calls: Vec<Command>,
}

/// The attributes a pair tracks, each at its slot: colour (0), normal (1), one texture
/// coordinate per unit (from [`TEXCOORD0`]), the edge flag, the secondary colour, the
/// fog coordinate and the colour index (which draws nothing in RGBA: it gets no array).
pub const SLOTS: usize = 6 + MAX_TEXTURE_UNITS;
const COLOR: usize = 0;
const NORMAL: usize = 1;
const TEXCOORD0: usize = 2;
const EDGE_FLAG: usize = TEXCOORD0 + MAX_TEXTURE_UNITS;
const SECONDARY_COLOR: usize = EDGE_FLAG + 1;
const FOG_COORD: usize = EDGE_FLAG + 2;
const INDEX: usize = EDGE_FLAG + 3;

/// The most vertices a pair's arrays are sized for ahead of its calls.
const MAX_RESERVED_VERTICES: usize = 1 << 16;

/// A vertex attribute as an immediate-mode call sets it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Attr {
    Color(Vec4),
    Normal(Vec3),
    TexCoord(u8, Vec4),
    /// glEdgeFlag (GL 1.5 §2.6.2).
    EdgeFlag(bool),
    /// glSecondaryColor (GL 1.4 §2.7).
    SecondaryColor(Vec4),
    /// glFogCoord (GL 1.4 §2.7).
    FogCoord(f32),
    /// glIndex (`color_index`).
    Index(f32),
}

impl Attr {
    /// Makes this the current value in `current`; its slot among the [`SLOTS`], or `None`
    /// for a texture unit beyond MAX_TEXTURE_UNITS (nothing set).
    #[inline]
    pub fn set(self, current: &mut CurrentValues) -> Option<usize> {
        Some(match self {
            Attr::Color(v) => {
                current.color = v;
                COLOR
            }
            Attr::Normal(v) => {
                current.normal = v;
                NORMAL
            }
            Attr::TexCoord(unit, coord) => {
                let u = usize::from(unit);
                *current.texcoords.get_mut(u)? = coord;
                TEXCOORD0 + u
            }
            Attr::EdgeFlag(f) => {
                current.edge_flag = f;
                EDGE_FLAG
            }
            Attr::SecondaryColor(v) => {
                current.secondary_color = v;
                SECONDARY_COLOR
            }
            Attr::FogCoord(f) => {
                current.fog_coord = f;
                FOG_COORD
            }
            Attr::Index(c) => {
                current.index = c;
                INDEX
            }
        })
    }

    /// Whether the vertices of a pair carry this attribute (all but the colour index,
    /// which an RGBA buffer never reads).
    pub fn per_vertex(self) -> bool {
        !matches!(self, Attr::Index(_))
    }
}

/// One immediate-mode call with its values read: what a display list keeps of it.
#[derive(Clone, Debug, PartialEq)]
pub enum Op {
    Begin(Primitive),
    End,
    Vertex(Vec4),
    Attribute(Attr),
    /// glRect's corners (x1, y1, x2, y2).
    Rect([f32; 4]),
    /// glArrayElement's values.
    Element(Box<Element>),
    /// glMaterial inside the pair (a display list's compiled glMaterial met while a pair
    /// is open, or the call itself).
    Material(Face, MaterialParam),
}

/// The immediate-mode call `c` is, with its values read and converted; `None` for any
/// other call.
pub fn decode<A: Args>(c: &A) -> Result<Option<Op>, A::Error> {
    if let Some(form) = c.entry().attrib_call() {
        return family(c, form).map(Some);
    }
    Ok(match c.entry() {
        Entry::Begin => {
            c.count(1)?;
            Some(Op::Begin(c.enm(0)?))
        }
        Entry::End => {
            c.count(0)?;
            Some(Op::End)
        }
        // The flag is TRUE iff the GLboolean is 1, as Mesa keeps it (the value as a float,
        // TRUE when it equals 1.0; measured with tests/c/edgeflags.c: glEdgeFlagv of 2
        // leaves GL_EDGE_FLAG FALSE).
        Entry::EdgeFlag => {
            c.count(1)?;
            let on = match c.int(0) {
                Ok(v) => v == 1,
                Err(_) => c.boolean(0)?,
            };
            Some(Op::Attribute(Attr::EdgeFlag(on)))
        }
        Entry::EdgeFlagv => {
            c.count(1)?;
            let v = c.array_as(0, 1, super::api::CType::UByte)?;
            Some(Op::Attribute(Attr::EdgeFlag(v.first() == Some(&1.0))))
        }
        _ => None,
    })
}

/// One call of the vertex-attribute families (glVertex, glColor, glNormal, glTexCoord,
/// glMultiTexCoord, glRect, glSecondaryColor, glFogCoord) in any of its variants: the values are converted to the
/// parameter type as C does, then colours and normals of integer types are normalised
/// (GL 1.5 Table 2.9); missing components take GL's defaults (z = 0, w = 1, q = 1,
/// alpha = 1).
fn family<A: Args>(c: &A, form: AttribCall) -> Result<Op, A::Error> {
    let from = usize::from(form.attrib == Attrib::MultiTexCoord);
    let (values, len) = attrib_values(c, form, from)?;
    let unit = match form.attrib {
        Attrib::MultiTexCoord => c.family(0, Family::Texture)?,
        _ => 0,
    };
    Ok(family_op(form, &values[..len], unit))
}

/// The call of `form` with its values `v` (already of the parameter type) and, for
/// glMultiTexCoord, its unit: integer colours and normals normalised (GL 1.5 Table 2.9),
/// missing components GL's defaults (z = 0, w = 1, q = 1, alpha = 1).
pub fn family_op(form: AttribCall, v: &[f64], unit: u8) -> Op {
    let mut c = DEFAULT_COMPONENTS;
    for (slot, x) in c.iter_mut().zip(v) {
        *slot = component(form, *x);
    }
    op_of(form.attrib, unit, c)
}

/// The components a family call leaves unsaid: (x, y, z, w) = (0, 0, 0, 1).
pub const DEFAULT_COMPONENTS: [f32; 4] = [0.0, 0.0, 0.0, 1.0];

/// One value of a family call as the attribute holds it: integer colours and normals
/// normalised (GL 1.5 Table 2.9; secondary colours as colours, GL 1.4 §2.7), everything
/// else as the float it is.
#[inline]
pub fn component(form: AttribCall, x: f64) -> f32 {
    if form.ty.is_integer()
        && matches!(
            form.attrib,
            Attrib::Color | Attrib::SecondaryColor | Attrib::Normal
        )
    {
        form.ty.normalized(x)
    } else {
        x as f32
    }
}

/// The Op of an attribute family with its components `c` (defaults filled in).
fn op_of(attrib: Attrib, unit: u8, c: [f32; 4]) -> Op {
    match attrib {
        Attrib::Vertex => Op::Vertex(Vec4::from_array(c)),
        // glRect's four values are all given.
        Attrib::Rect => Op::Rect(c),
        Attrib::Color => Op::Attribute(Attr::Color(Vec4::from_array(c))),
        // glNormal3 gives all three.
        Attrib::Normal => Op::Attribute(Attr::Normal(Vec3::new(c[0], c[1], c[2]))),
        Attrib::TexCoord => Op::Attribute(Attr::TexCoord(0, Vec4::from_array(c))),
        Attrib::MultiTexCoord => Op::Attribute(Attr::TexCoord(unit, Vec4::from_array(c))),
        // Three components given; alpha is the default 1.
        Attrib::SecondaryColor => Op::Attribute(Attr::SecondaryColor(Vec4::from_array(c))),
        Attrib::FogCoord => Op::Attribute(Attr::FogCoord(c[0])),
        Attrib::Index => Op::Attribute(Attr::Index(c[0])),
    }
}

/// A broken immediate-mode rule, in words (the front end makes it its error).
pub type Rule = &'static str;

impl Immediate {
    /// Whether a glBegin is open.
    pub fn is_open(&self) -> bool {
        self.open.is_some()
    }

    /// Abandons an open glBegin (a front end that stops mid-pair).
    pub fn reset(&mut self) {
        self.open = None;
    }

    /// Converts one call, appending what it yields to `out`. `current` and `materials` are
    /// the model's (read at glBegin and by glRect: [`Start`]). Calls other than immediate mode go
    /// to [`calls::command`](super::calls::command).
    pub fn call<A: Args>(
        &mut self,
        c: &A,
        current: &CurrentValues,
        materials: &Materials,
        out: &mut Vec<Command>,
    ) -> Result<(), A::Error> {
        match decode(c)? {
            Some(op) => self
                .apply(&op, current, materials, out)
                .map_err(|rule| c.immediate(rule)),
            None => {
                let material = matches!(
                    c.entry(),
                    Entry::Materialf | Entry::Materialfv | Entry::Materiali | Entry::Materialiv
                );
                if let (Some(open), true) = (self.open.as_mut(), material) {
                    // glMaterial inside the pair: errors as outside it (a shininess beyond
                    // [0, 128] is INVALID_VALUE, Mesa measured alike), then per vertex.
                    if let Command::Material { face, param } = super::calls::command(c)? {
                        if let MaterialParam::Shininess(v) = param {
                            if super::light::shininess_refused(v) {
                                return Err(c.bad(2, "a shininess in [0, 128]"));
                            }
                        }
                        open.material(face, param);
                    }
                    return Ok(());
                }
                if self.open.is_some() {
                    return Err(
                        c.immediate("only vertex attributes are allowed inside glBegin/glEnd")
                    );
                }
                out.push(super::calls::command(c)?);
                Ok(())
            }
        }
    }

    /// A vertex or an attribute of family `attrib` inside the open pair, with its
    /// components `c` (defaults filled in): what [`apply`](Self::apply) does with the
    /// call's Op, for a front end's per-vertex path. `false` when no pair is open or the
    /// call is not one the pair takes this way (glRect; a unit beyond the texture units):
    /// the front end then takes its general path, which gives the error.
    #[inline]
    pub fn in_pair(&mut self, attrib: Attrib, unit: u8, c: [f32; 4]) -> bool {
        let Some(open) = &mut self.open else {
            return false;
        };
        match op_of(attrib, unit, c) {
            Op::Vertex(p) => {
                open.vertex(p);
                true
            }
            Op::Attribute(a) => open.attribute(a).is_ok(),
            _ => false,
        }
    }

    /// Applies one immediate-mode call.
    pub fn apply(
        &mut self,
        op: &Op,
        current: &CurrentValues,
        materials: &Materials,
        out: &mut Vec<Command>,
    ) -> Result<(), Rule> {
        match op {
            Op::Begin(p) => self.begin(*p, current, materials),
            Op::End => self.end(out),
            Op::Vertex(v) => self.vertex(*v),
            Op::Attribute(a) => self.attribute(*a, out),
            Op::Rect([x1, y1, x2, y2]) => {
                if self.open.is_some() {
                    return Err("glRect inside glBegin/glEnd");
                }
                // Mesa draws glRect as one GL_QUADS: (x1,y1) (x2,y1) (x2,y2) (x1,y2).
                self.begin(Primitive::Quads, current, materials)?;
                for (x, y) in [(x1, y1), (x2, y1), (x2, y2), (x1, y2)] {
                    self.vertex(Vec4::new(*x, *y, 0.0, 1.0))?;
                }
                self.end(out)
            }
            Op::Element(e) => self.array_element(e, out),
            Op::Material(face, param) => {
                let open = self
                    .open
                    .as_mut()
                    .ok_or("glMaterial outside glBegin/glEnd")?;
                open.material(*face, *param);
                Ok(())
            }
        }
    }

    /// glArrayElement: the element's attributes, then its vertex, as the immediate calls
    /// would give them (GL 1.5 §2.8). Outside glBegin/glEnd only the attributes take effect.
    fn array_element(&mut self, e: &Element, out: &mut Vec<Command>) -> Result<(), Rule> {
        for a in e.attributes() {
            self.attribute(a, out)?;
        }
        match (e.position, self.open.is_some()) {
            (Some(p), true) => self.vertex(p),
            _ => Ok(()),
        }
    }

    fn begin(
        &mut self,
        primitive: Primitive,
        current: &CurrentValues,
        materials: &Materials,
    ) -> Result<(), Rule> {
        if self.open.is_some() {
            return Err("glBegin inside glBegin/glEnd");
        }
        self.open = Some(Open {
            geometry: Geometry::new(primitive, Vec::with_capacity(self.last_vertices)),
            begin: *current,
            current: *current,
            called: [false; SLOTS],
            pending: false,
            texcoord_arrays: false,
            begin_materials: *materials,
            materials: *materials,
            material_called: 0,
            material_calls: Vec::new(),
        });
        Ok(())
    }

    /// glVertex: a vertex with the current values of every attribute with an array.
    /// Outside glBegin/glEnd nothing, and no error: GL 1.5 §2.6.3 leaves such a vertex's
    /// effect undefined and Mesa ignores it (measured: no error, nothing drawn, the next
    /// primitive unchanged).
    fn vertex(&mut self, p: Vec4) -> Result<(), Rule> {
        if let Some(open) = self.open.as_mut() {
            open.vertex(p);
        }
        Ok(())
    }

    fn attribute(&mut self, attr: Attr, out: &mut Vec<Command>) -> Result<(), Rule> {
        let Some(open) = &mut self.open else {
            // Outside the pair: a state command (an invalid unit is the model's
            // INVALID_ENUM).
            out.push(match attr {
                Attr::Color(v) => Command::Color(v),
                Attr::Normal(v) => Command::Normal(v),
                Attr::TexCoord(unit, coord) => Command::TexCoord { unit, coord },
                Attr::EdgeFlag(f) => Command::EdgeFlag(f),
                Attr::SecondaryColor(v) => Command::SecondaryColor(v),
                Attr::FogCoord(f) => Command::FogCoord(f),
                Attr::Index(c) => Command::Index(c),
            });
            return Ok(());
        };
        open.attribute(attr)
    }

    /// glEnd: emits the Draw, then the current values the calls inside the pair left,
    /// where they differ from those at glBegin (a draw itself changes no state).
    fn end(&mut self, out: &mut Vec<Command>) -> Result<(), Rule> {
        let open = self.open.take().ok_or("glEnd without glBegin")?;
        self.last_vertices = open.geometry.positions.len().min(MAX_RESERVED_VERTICES);
        let (begin, cur) = (open.begin, open.current);
        out.push(Command::Draw(Arc::new(open.geometry)));
        changed_current(&begin, &cur, out);
        out.extend(open.material_calls);
        Ok(())
    }
}

/// The current values `now` holds that differ from `begin`, as the commands glEnd leaves
/// after its draw.
pub fn changed_current(begin: &CurrentValues, now: &CurrentValues, out: &mut Vec<Command>) {
    if begin.color != now.color {
        out.push(Command::Color(now.color));
    }
    if begin.normal != now.normal {
        out.push(Command::Normal(now.normal));
    }
    if begin.edge_flag != now.edge_flag {
        out.push(Command::EdgeFlag(now.edge_flag));
    }
    if begin.secondary_color != now.secondary_color {
        out.push(Command::SecondaryColor(now.secondary_color));
    }
    if begin.fog_coord.to_bits() != now.fog_coord.to_bits() {
        out.push(Command::FogCoord(now.fog_coord));
    }
    if begin.index.to_bits() != now.index.to_bits() {
        out.push(Command::Index(now.index));
    }
    for u in 0..MAX_TEXTURE_UNITS {
        if begin.texcoords[u] != now.texcoords[u] {
            out.push(Command::TexCoord {
                unit: u as u8,
                coord: now.texcoords[u],
            });
        }
    }
}

impl Open {
    /// A vertex with the current values of every attribute with an array.
    #[inline]
    fn vertex(&mut self, p: Vec4) {
        if self.pending {
            self.arrays_for_called();
        }
        let (cur, g) = (&self.current, &mut self.geometry);
        g.positions.push(p);
        if let Some(v) = &mut g.colors {
            v.push(cur.color);
        }
        if let Some(v) = &mut g.normals {
            v.push(cur.normal);
        }
        if let Some(v) = &mut g.edge_flags {
            v.push(cur.edge_flag);
        }
        if let Some(v) = &mut g.secondary_colors {
            v.push(cur.secondary_color);
        }
        if let Some(v) = &mut g.fog_coords {
            v.push(cur.fog_coord);
        }
        if self.texcoord_arrays {
            for (u, t) in g.texcoords.iter_mut().enumerate() {
                if let Some(v) = t {
                    v.push(cur.texcoords[u]);
                }
            }
        }
        if let Some(m) = &mut g.materials {
            for (slot, a) in MaterialSlot::ALL.into_iter().zip(m.arrays.iter_mut()) {
                if let Some(a) = a {
                    a.push(self.materials.value(slot));
                }
            }
        }
    }

    /// glMaterial inside the pair: the material from the next vertex on. Out-of-range
    /// values are refused before (`Client::call`), as the model refuses them.
    fn material(&mut self, face: Face, param: MaterialParam) {
        if self.materials.set(face, param).is_err() {
            return;
        }
        self.material_calls.push(Command::Material { face, param });
        self.material_called |= MaterialSlot::ALL
            .into_iter()
            .filter(|slot| slot.set_by(face, param))
            .fold(0, |m, slot| m | 1 << slot.bit());
        self.pending = true;
    }

    /// An attribute inside the pair: the current value, and an array from the next vertex.
    #[inline]
    fn attribute(&mut self, attr: Attr) -> Result<(), Rule> {
        let index = attr
            .set(&mut self.current)
            .ok_or("texture unit beyond MAX_TEXTURE_UNITS")?;
        if attr.per_vertex() && !self.called[index] {
            self.called[index] = true;
            self.pending = true;
        }
        Ok(())
    }

    /// Creates the arrays of attributes called since glBegin, filled with the glBegin
    /// values for the vertices already emitted.
    fn arrays_for_called(&mut self) {
        self.pending = false;
        self.texcoord_arrays |= self.called[TEXCOORD0..EDGE_FLAG].iter().any(|c| *c);
        let n = self.geometry.positions.len();
        let g = &mut self.geometry;
        // Each new array is sized like the positions will be.
        let filled = |value| {
            let mut v = Vec::with_capacity(g.positions.capacity());
            v.resize(n, value);
            v
        };
        if self.called[COLOR] && g.colors.is_none() {
            g.colors = Some(filled(self.begin.color));
        }
        if self.called[SECONDARY_COLOR] && g.secondary_colors.is_none() {
            g.secondary_colors = Some(filled(self.begin.secondary_color));
        }
        if self.called[FOG_COORD] && g.fog_coords.is_none() {
            let mut v = Vec::with_capacity(g.positions.capacity());
            v.resize(n, self.begin.fog_coord);
            g.fog_coords = Some(v);
        }
        if self.called[NORMAL] && g.normals.is_none() {
            let mut v = Vec::with_capacity(g.positions.capacity());
            v.resize(n, self.begin.normal);
            g.normals = Some(v);
        }
        for (u, t) in g.texcoords.iter_mut().enumerate() {
            if self.called[TEXCOORD0 + u] && t.is_none() {
                *t = Some(filled(self.begin.texcoords[u]));
            }
        }
        if self.called[EDGE_FLAG] && g.edge_flags.is_none() {
            let mut v = Vec::with_capacity(g.positions.capacity());
            v.resize(n, self.begin.edge_flag);
            g.edge_flags = Some(v);
        }
        if self.material_called != 0 {
            let m = g.materials.get_or_insert_with(Box::default);
            for (slot, a) in MaterialSlot::ALL.into_iter().zip(m.arrays.iter_mut()) {
                if self.material_called & (1 << slot.bit()) != 0 && a.is_none() {
                    *a = Some(vec![self.begin_materials.value(slot); n]);
                }
            }
        }
    }
}

/// The values of an attribute-family call from argument `from` on: `count` scalars, or
/// one array (two for glRect's corners) of at least that many, each converted to the
/// parameter type as C converts an argument. At most four (a family's widest form), held
/// in place rather than allocated: this runs once per glVertex.
fn attrib_values<A: Args>(
    c: &A,
    form: AttribCall,
    from: usize,
) -> Result<([f64; 4], usize), A::Error> {
    let mut out = [0.0; 4];
    let count = form.count.min(4);
    if !form.vector {
        c.count(from + form.count)?;
        for (k, slot) in out.iter_mut().enumerate().take(count) {
            *slot = form.ty.convert(c.f64(from + k)?);
        }
        return Ok((out, count));
    }
    let arrays = if form.attrib == Attrib::Rect { 2 } else { 1 };
    c.count(from + arrays)?;
    let per = (form.count / arrays).min(4 / arrays);
    for k in 0..arrays {
        c.array_f64_into(from + k, &mut out[k * per..(k + 1) * per])?;
    }
    let len = per * arrays;
    for slot in &mut out[..len] {
        *slot = form.ty.convert(*slot);
    }
    Ok((out, len))
}
