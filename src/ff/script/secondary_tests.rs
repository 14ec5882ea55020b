//! GL 1.4's secondary colour and fog coordinate through the script reader and the model:
//! immediate mode, client arrays, glArrayElement, display lists, FOG_COORD_SRC and the
//! raster distance it gives. The pixels are compared with Mesa in `tests/c/secondary.c`.

use glam::Vec4;

use super::{parse, print};
use crate::ff::*;

fn draws(cmds: &[Command]) -> Vec<&Geometry> {
    cmds.iter()
        .filter_map(|c| match c {
            Command::Draw(g) => Some(&**g),
            _ => None,
        })
        .collect()
}

fn state_after(src: &str) -> FixedState {
    let mut s = FixedState::new();
    for c in parse(src).unwrap_or_else(|e| panic!("{e}")) {
        s.apply(&c).unwrap_or_else(|e| panic!("{e}"));
    }
    s
}

#[test]
fn a_pair_gives_secondary_colours_and_fog_coordinates_per_vertex() {
    // The first vertex comes before either call: it takes glBegin's values.
    let src = "glSecondaryColor3f(0.5, 0.5, 0.5);\n\
               glBegin(GL_LINES);\n\
               glVertex2f(0, 0);\n\
               glSecondaryColor3ub(255, 0, 51); glFogCoordf(-4);\n\
               glVertex2f(1, 0);\n\
               glFogCoorddEXT(2);\n\
               glEnd();\n";
    let cmds = parse(src).unwrap();
    let g = draws(&cmds)[0];
    assert_eq!(
        g.secondary_colors.as_deref(),
        Some(&[Vec4::new(0.5, 0.5, 0.5, 1.0), Vec4::new(1.0, 0.0, 0.2, 1.0)][..])
    );
    assert_eq!(g.fog_coords.as_deref(), Some(&[0.0, -4.0][..]));
    // What the pair left current follows the draw: the last secondary colour and the fog
    // coordinate set after the last vertex.
    let s = state_after(src);
    assert_eq!(s.current.secondary_color, Vec4::new(1.0, 0.0, 0.2, 1.0));
    assert_eq!(s.current.fog_coord, 2.0);
}

#[test]
fn arrays_and_array_elements_read_secondary_colours_and_fog_coordinates() {
    let src = "glVertexPointer(2, GL_FLOAT, 0, (GLfloat[]){0, 0, 1, 0, 1, 1});\n\
               glSecondaryColorPointer(4, GL_UNSIGNED_BYTE, 0, (GLubyte[]){255, 0, 0, 51, 0, 255, 0, 102, 0, 0, 255, 153});\n\
               glFogCoordPointerEXT(GL_DOUBLE, 0, (GLdouble[]){1.5, -2, 8});\n\
               glEnableClientState(GL_VERTEX_ARRAY);\n\
               glEnableClientState(GL_SECONDARY_COLOR_ARRAY);\n\
               glEnableClientState(GL_FOG_COORDINATE_ARRAY_EXT);\n\
               glDrawArrays(GL_TRIANGLES, 0, 3);\n\
               glArrayElement(1);\n";
    let cmds = parse(src).unwrap();
    let g = draws(&cmds)[0];
    assert_eq!(
        g.secondary_colors.as_ref().map(|c| c[2]),
        Some(Vec4::new(0.0, 0.0, 1.0, 0.6))
    );
    assert_eq!(g.fog_coords.as_deref(), Some(&[1.5, -2.0, 8.0][..]));
    // glArrayElement outside glBegin/glEnd sets the current values, alpha included.
    let s = state_after(src);
    assert_eq!(s.current.secondary_color, Vec4::new(0.0, 1.0, 0.0, 0.4));
    assert_eq!(s.current.fog_coord, -2.0);
    // Mesa's sizes and types.
    for bad in [
        "glSecondaryColorPointer(2, GL_FLOAT, 0, NULL);",
        "glSecondaryColorPointer(3, GL_FIXED, 0, NULL);",
        "glFogCoordPointer(GL_SHORT, 0, NULL);",
        "glFogCoordPointer(GL_FLOAT, -1, NULL);",
    ] {
        assert!(parse(bad).is_err(), "{bad}");
    }
}

#[test]
fn a_listed_pair_keeps_its_secondary_colours_and_leaves_its_values() {
    let src = "glNewList(1, GL_COMPILE);\n\
               glBegin(GL_TRIANGLES);\n\
               glSecondaryColor3f(1, 0, 0); glFogCoordf(3); glVertex2f(0, 0);\n\
               glSecondaryColor3f(0, 1, 0); glVertex2f(1, 0);\n\
               glFogCoordf(5); glVertex2f(0, 1);\n\
               glEnd();\n\
               glEndList();\n\
               glCallList(1); glCallList(1);\n";
    let cmds = parse(src).unwrap();
    let g = draws(&cmds);
    assert_eq!(g.len(), 2);
    assert_eq!(g[0].fog_coords.as_deref(), Some(&[3.0, 3.0, 5.0][..]));
    assert_eq!(
        g[1].secondary_colors.as_ref().map(|c| c[2]),
        Some(Vec4::new(0.0, 1.0, 0.0, 1.0))
    );
    let s = state_after(src);
    assert_eq!(s.current.secondary_color, Vec4::new(0.0, 1.0, 0.0, 1.0));
    assert_eq!(s.current.fog_coord, 5.0);
}

#[test]
fn the_fog_coordinate_source_reads_under_both_names_and_survives_a_pop() {
    let s = state_after(
        "glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);\n\
         glPushAttrib(GL_FOG_BIT);\n\
         glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);\n\
         glFogf(GL_FOG_START, 3);\n\
         glPopAttrib();\n",
    );
    // Mesa 22.3 restores the fog parameters but not the source.
    assert_eq!(s.fog.value.coord_source, FogCoordSource::FragmentDepth);
    assert_eq!(s.fog.value.start, 0.0);
    let err = parse("glFogi(GL_FOG_COORD_SRC, GL_ZERO);").unwrap_err();
    assert!(err.to_string().contains("GL_FRAGMENT_DEPTH"), "{err}");
    let printed = print(&[Command::Fog(FogParam::CoordSource(
        FogCoordSource::FogCoord,
    ))]);
    assert!(
        printed.contains("glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD)"),
        "{printed}"
    );
}

#[test]
fn the_raster_distance_is_the_fog_coordinate_under_fog_coord() {
    let src = "glFogCoordf(-5);\n\
               glRasterPos3f(0, 0, -0.5);\n";
    assert_eq!(state_after(src).raster.distance, 0.5);
    let fog = format!("glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);\n{src}");
    assert_eq!(state_after(&fog).raster.distance, -5.0);
    let window = format!("{fog}glWindowPos2i(1, 1);\n");
    assert_eq!(state_after(&window).raster.distance, -5.0);
    let depth = "glFogCoordf(-5);\nglWindowPos2i(1, 1);\n";
    assert_eq!(state_after(depth).raster.distance, 0.0);
}
