//! A display list's glBegin … glEnd pairs assembled once, at glEndList, into the
//! `Geometry` each glCallList draws — the same `Arc` every call, so a pipeline that keeps
//! uploaded geometry by its `Arc` uploads a list's vertices once (Mesa compiles a list
//! into a vertex buffer the same way).
//!
//! A pair's vertices copy the current values (GL 1.5 §2.7): an attribute called inside the
//! pair before its first vertex gives every vertex a value the list holds; an attribute not
//! called gets no array (the draw reads the current value); only an attribute first called
//! after a vertex gives the earlier vertices the value current at glBegin, which the list
//! does not know. A pair of that kind, a pair holding anything but vertex attributes, or a
//! texture unit beyond MAX_TEXTURE_UNITS stays as its calls. A pair called while a glBegin
//! is open (a list called inside glBegin/glEnd) runs as its calls, with their errors.

use std::sync::Arc;

use super::command::Command;
use super::geometry::Geometry;
use super::immediate::{Attr, Immediate, Op, SLOTS};
use super::light::Materials;
use super::lists::Item;
use super::state::CurrentValues;

/// One assembled glBegin … glEnd.
#[derive(Clone, Debug, PartialEq)]
pub struct Pair {
    /// What the pair draws, whatever is current when the list runs.
    pub geometry: Arc<Geometry>,
    /// The attributes the pair calls, each at the value it leaves it (one per slot).
    left: Vec<Attr>,
    /// The pair's calls, glBegin to glEnd.
    pub items: Vec<Item>,
}

impl Pair {
    /// The commands the pair's calls yield with `current` current at glBegin: the draw,
    /// then the values the pair changed (as glEnd emits them).
    pub fn replay(&self, current: &CurrentValues, out: &mut Vec<Command>) {
        out.push(Command::Draw(Arc::clone(&self.geometry)));
        let mut now = *current;
        for a in &self.left {
            a.set(&mut now);
        }
        super::immediate::changed_current(current, &now, out);
    }
}

/// The list's items with every pair that does not depend on glBegin's current values
/// assembled.
pub fn assemble(items: Vec<Item>) -> Vec<Item> {
    let mut out = Vec::with_capacity(items.len());
    let mut rest = items.into_iter().peekable();
    while let Some(item) = rest.next() {
        if !matches!(item, Item::Immediate(Op::Begin(_))) {
            out.push(item);
            continue;
        }
        let mut pair = vec![item];
        let mut ended = false;
        while let Some(next) = rest.peek() {
            let inside = matches!(
                next,
                Item::Immediate(Op::Vertex(_) | Op::Attribute(_) | Op::Element(_) | Op::End)
            );
            if !inside {
                break;
            }
            let end = matches!(next, Item::Immediate(Op::End));
            pair.extend(rest.next());
            if end {
                ended = true;
                break;
            }
        }
        match ended.then(|| assemble_pair(pair.clone())).flatten() {
            Some(p) => out.push(Item::Pair(Box::new(p))),
            None => out.extend(pair),
        }
    }
    out
}

/// `items` (glBegin, vertex attributes, glEnd) as one pair, if their draw does not depend
/// on the values current at glBegin.
fn assemble_pair(items: Vec<Item>) -> Option<Pair> {
    let ops: Vec<&Op> = items
        .iter()
        .map(|i| match i {
            Item::Immediate(op) => Some(op),
            _ => None,
        })
        .collect::<Option<_>>()?;
    // The last value of each slot called.
    let mut left: [Option<Attr>; SLOTS] = [None; SLOTS];
    let mut vertices = 0usize;
    let mut set = |attr: Attr, vertices: usize| -> Option<()> {
        let mut scratch = CurrentValues::DEFAULT;
        let index = attr.set(&mut scratch)?;
        if attr.per_vertex() && left[index].is_none() && vertices > 0 {
            return None;
        }
        left[index] = Some(attr);
        Some(())
    };
    for op in &ops {
        match op {
            Op::Begin(_) | Op::End => {}
            Op::Vertex(_) => vertices += 1,
            Op::Attribute(a) => set(*a, vertices)?,
            Op::Element(e) => {
                for a in e.attributes() {
                    set(a, vertices)?;
                }
                if e.position.is_some() {
                    vertices += 1;
                }
            }
            // A material set inside the pair fills earlier vertices from glBegin's.
            Op::Rect(_) | Op::Material(..) => return None,
        }
    }
    // The vertices no longer depend on glBegin's values: assemble them from any.
    let mut immediate = Immediate::default();
    let mut draw = Vec::new();
    for op in &ops {
        immediate
            .apply(op, &CurrentValues::DEFAULT, &Materials::DEFAULT, &mut draw)
            .ok()?;
    }
    let geometry = match draw.into_iter().next()? {
        Command::Draw(g) => g,
        _ => return None,
    };
    Some(Pair {
        geometry,
        left: left.into_iter().flatten().collect(),
        items,
    })
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use glam::{Vec3, Vec4};

    use crate::ff::script::{draws, parse, ScriptError};
    use crate::ff::{Command, Geometry};

    const LIST: &str = "glNewList(1, GL_COMPILE);\n\
        glBegin(GL_TRIANGLES);\n\
        glNormal3f(0, 1, 0); glVertex3f(0, 0, 0);\n\
        glNormal3f(1, 0, 0); glVertex3f(1, 0, 0); glVertex3f(0, 1, 0);\n\
        glEnd();\n\
        glEndList();\n";

    #[test]
    fn a_list_draws_the_same_geometry_at_every_call_until_it_is_redefined() {
        let g = draws(&format!(
            "{LIST}glCallList(1); glCallList(1);\n{LIST}glCallList(1);"
        ));
        assert_eq!(g.len(), 3);
        assert!(
            Arc::ptr_eq(&g[0], &g[1]),
            "a second call draws what the first drew"
        );
        assert!(
            !Arc::ptr_eq(&g[1], &g[2]),
            "a redefined list draws its new geometry"
        );
        assert_eq!(
            g[0].normals.as_deref(),
            Some(&[Vec3::Y, Vec3::X, Vec3::X][..])
        );
    }

    #[test]
    fn a_pair_that_reads_glbegin_values_is_assembled_at_each_call() {
        // The colour is first called after a vertex: that vertex takes the current colour.
        let src = "glNewList(1, GL_COMPILE);\n\
            glBegin(GL_POINTS); glVertex2f(0, 0); glColor3f(1, 0, 0); glVertex2f(1, 0); glEnd();\n\
            glEndList();\n\
            glColor3f(0, 0, 1); glCallList(1); glColor3f(0, 1, 0); glCallList(1);";
        let g = draws(src);
        let first = |g: &Geometry| g.colors.as_ref().map(|c| c[0]);
        assert_eq!(first(&g[0]), Some(Vec4::new(0.0, 0.0, 1.0, 1.0)));
        assert_eq!(first(&g[1]), Some(Vec4::new(0.0, 1.0, 0.0, 1.0)));
    }

    #[test]
    fn an_assembled_pair_leaves_the_values_its_calls_leave() {
        let cmds = parse(&format!("{LIST}glNormal3f(1, 0, 0); glCallList(1);")).unwrap();
        // glEnd leaves only what differs from glBegin's values: the normal is (1, 0, 0)
        // both before and after, so no command follows the draw.
        assert!(matches!(cmds.last(), Some(Command::Draw(_))), "{cmds:?}");
        let cmds = parse(&format!("{LIST}glCallList(1);")).unwrap();
        assert_eq!(cmds.last(), Some(&Command::Normal(Vec3::X)));
    }

    #[test]
    fn a_list_called_inside_glbegin_runs_its_calls() {
        let src = "glNewList(1, GL_COMPILE);\n\
            glBegin(GL_POINTS); glVertex2f(0, 0); glEnd();\n\
            glEndList();\n\
            glBegin(GL_POINTS); glCallList(1); glEnd();";
        // The list's glBegin raises, its glEnd closes the open pair, so the last glEnd
        // has no glBegin.
        let err = parse(src).unwrap_err();
        assert!(
            matches!(err, ScriptError::Immediate { line: 4, .. }),
            "{err}"
        );
    }
}
