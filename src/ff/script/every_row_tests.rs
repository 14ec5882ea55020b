//! Every row of the entry-point table is read by the script reader: the implemented calls
//! parse (tests/scripts/every_call.c holds one of each outside the vertex-attribute
//! families, whose variants are generated here from their names), and each left-out call
//! stops a script with an error naming it as not implemented.

use super::{parse, ScriptError};
use crate::ff::api::{Attrib, CType, Entry, Form};

const EVERY_CALL: &str = include_str!("../../../tests/scripts/every_call.c");

/// A call of an attribute-family variant, with arguments of its C type.
fn family_call(e: Entry) -> Option<String> {
    let a = e.attrib_call()?;
    let (ty, value) = match a.ty {
        CType::Byte => ("GLbyte", "1"),
        CType::UByte => ("GLubyte", "1"),
        CType::Short => ("GLshort", "1"),
        CType::UShort => ("GLushort", "1"),
        CType::Int => ("GLint", "1"),
        CType::UInt => ("GLuint", "1"),
        CType::Float => ("GLfloat", "0.5f"),
        CType::Double => ("GLdouble", "0.5"),
    };
    let values = vec![value; if a.attrib == Attrib::Rect { 2 } else { a.count }].join(", ");
    let args = match (a.attrib, a.vector) {
        (Attrib::Rect, true) => format!("({ty}[]){{{values}}}, ({ty}[]){{{values}}}"),
        (Attrib::Rect, false) => [value; 4].join(", "),
        (_, true) => format!("({ty}[]){{{values}}}"),
        (_, false) => values,
    };
    let args = match a.attrib {
        Attrib::MultiTexCoord => format!("GL_TEXTURE1, {args}"),
        _ => args,
    };
    let call = format!("{}({args});", e.name());
    Some(match a.attrib {
        Attrib::Rect => call,
        _ => format!("glBegin(GL_POINTS);\n{call}\nglEnd();"),
    })
}

/// A call of a raster-position variant (glRasterPos{2,3,4}{s,i,f,d}[v],
/// glWindowPos{2,3}{s,i,f,d}[v] and their ARB and MESA names), read from its name.
fn position_call(e: Entry) -> Option<String> {
    let name = e.name();
    let rest = name
        .strip_prefix("glRasterPos")
        .or_else(|| name.strip_prefix("glWindowPos"))?;
    let rest = rest
        .strip_suffix("ARB")
        .or_else(|| rest.strip_suffix("MESA"))
        .unwrap_or(rest);
    let count = rest.chars().next()?.to_digit(10)? as usize;
    let (ty, vector) = match rest[1..].strip_suffix('v') {
        Some(t) => (t, true),
        None => (&rest[1..], false),
    };
    let (c_ty, value) = match ty {
        "s" => ("GLshort", "1"),
        "i" => ("GLint", "1"),
        "f" => ("GLfloat", "0.5f"),
        "d" => ("GLdouble", "0.5"),
        _ => return None,
    };
    let values = vec![value; count].join(", ");
    Some(if vector {
        format!("{name}(({c_ty}[]){{{values}}});")
    } else {
        format!("{name}({values});")
    })
}

#[test]
fn every_implemented_row_parses_in_a_script() {
    let cmds = parse(EVERY_CALL).expect("every_call.c parses");
    assert!(cmds.len() > 100, "{} commands", cmds.len());
    let mut families = 0;
    for e in Entry::ALL.iter().filter(|e| e.form() == Form::Script) {
        match family_call(*e).or_else(|| position_call(*e)) {
            Some(src) => {
                families += 1;
                parse(&src).unwrap_or_else(|err| panic!("{src}: {err}"));
            }
            None => assert!(
                EVERY_CALL.contains(&format!("\n{}(", e.name())),
                "tests/scripts/every_call.c lacks {}",
                e.name()
            ),
        }
    }
    assert!(families > 150, "{families} family variants");
}

#[test]
fn every_left_out_row_is_refused_by_name() {
    let left: Vec<Entry> = Entry::ALL
        .iter()
        .copied()
        .filter(|e| e.form() == Form::Left)
        .collect();
    assert!(left.contains(&Entry::RenderMode) && left.contains(&Entry::EvalMesh2));
    for e in left {
        let err = parse(&format!("glClear(0);\n{}();", e.name())).unwrap_err();
        assert_eq!(
            err,
            ScriptError::NotImplemented {
                line: 2,
                call: e.name()
            }
        );
        assert!(err.to_string().contains("not implemented"), "{err}");
    }
}

#[test]
fn a_bad_query_token_is_the_gl_error_a_c_program_gets() {
    use crate::ff::{Command, GlErrorKind};
    // GL_FOG_HINT is a GL token but no glGetTexEnv pname: INVALID_ENUM when run.
    let cmds = parse("glGetTexEnviv(GL_TEXTURE_ENV, GL_FOG_HINT, (GLint[]){0});").unwrap();
    assert_eq!(
        cmds,
        vec![Command::Raise {
            error: GlErrorKind::InvalidEnum,
            call: Entry::GetTexEnviv
        }]
    );
    // A name GL does not have is the script's own error.
    assert!(parse("glGetIntegerv(GL_NO_SUCH_TOKEN, (GLint[]){0});").is_err());
    // The client attribute stack's overflow is STACK_OVERFLOW.
    let pushes = "glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);\n".repeat(17);
    let cmds = parse(&pushes).unwrap();
    assert_eq!(
        cmds,
        vec![Command::Raise {
            error: GlErrorKind::StackOverflow,
            call: Entry::PushClientAttrib
        }]
    );
}

#[test]
fn pixel_literals_are_read_with_the_unpack_alignment() {
    use crate::ff::{Command, TexData};
    let rgb = |prefix: &str, values: &str| {
        let src = format!(
            "{prefix}glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 1, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, (GLubyte[]){{{values}}});"
        );
        match parse(&src).map(|c| c.into_iter().last()) {
            Ok(Some(Command::TexImage(t))) => match t.data {
                TexData::Bytes(b) => Ok(b.to_vec()),
                other => panic!("{other:?}"),
            },
            Ok(other) => panic!("{other:?}"),
            Err(e) => Err(e),
        }
    };
    // Alignment 4: the first row is padded by one byte.
    assert_eq!(
        rgb("", "1, 2, 3, 0, 4, 5, 6").unwrap(),
        vec![1, 2, 3, 4, 5, 6]
    );
    // Alignment 1: the rows are packed, the second starts at byte 3.
    assert_eq!(
        rgb(
            "glPixelStorei(GL_UNPACK_ALIGNMENT, 1);\n",
            "1, 2, 3, 4, 5, 6"
        )
        .unwrap(),
        vec![1, 2, 3, 4, 5, 6]
    );
    assert!(rgb("", "1, 2, 3, 4, 5, 6").is_err());
    // The printer pads the rows again: print and parse stay inverse.
    let cmds = parse(
        "glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 1, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, (GLubyte[]){1, 2, 3, 0, 4, 5, 6});",
    )
    .unwrap();
    assert_eq!(parse(&super::print(&cmds)).unwrap(), cmds);
    // Too few bytes for the padded rows: an error naming the alignment.
    let short = parse(
        "glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 1, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, (GLubyte[]){1, 2, 3, 4, 5, 6});",
    )
    .unwrap_err();
    assert!(short.to_string().contains("GL_UNPACK_ALIGNMENT"), "{short}");
}

#[test]
fn queries_and_readbacks_run_at_once_inside_a_list() {
    use crate::ff::Command;
    // GL 1.5 §5.4: glGetTexImage and glPushClientAttrib are not compiled; the list
    // holds only the copy.
    let cmds = parse(
        "glNewList(1, GL_COMPILE);\n\
         glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback_0);\n\
         glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);\n\
         glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1);\n\
         glEndList();\n\
         glPopClientAttrib();",
    )
    .unwrap();
    assert!(
        matches!(cmds.as_slice(), [Command::GetTexImage(g)] if g.slot == 0),
        "{cmds:?}"
    );
}
