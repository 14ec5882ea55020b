//! glMaterial inside glBegin/glEnd (GL 1.5 §2.14.3): each vertex is lit with the material
//! current when it was specified, as Mesa's native path lights it. The emulated path
//! carries the values the pair set as vertex attributes; the native path draws them as the
//! program gave them. Three panels (the fourth quarter is left empty): the diffuse colour
//! changed at every vertex of a smooth triangle; one quad per material inside a flat
//! GL_QUADS pair (split polygons keep their provoking vertex's material); shininess and
//! specular per vertex beside COLOR_MATERIAL tracking the diffuse colour. After each pair
//! the material state is the last values set.
//!
//! Not compared: back-face materials set per vertex under two-sided lighting. Mesa 22.3.6
//! draws them with only the red component per vertex (a strip whose back diffuse goes
//! from magenta to cyan is drawn cyan-to-white, measured with OSMesa); the layer lights
//! each vertex with its own back material (README, known deviations).

mod fidelity;
mod support;

use fidelity::{compare, probe_rgb, Frame};
use support::Tolerance;

const FRAME: Frame = Frame::new(128, 32);

const SCRIPT: &str = "\
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glOrtho(0, 4, 0, 1, -1, 1);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glEnable(GL_LIGHTING);
glEnable(GL_LIGHT0);
glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){0, 0, 1, 0});
glLightfv(GL_LIGHT0, GL_SPECULAR, (GLfloat[]){1, 1, 1, 1});
glNormal3f(0, 0, 1);
glBegin(GL_TRIANGLES);
glMaterialfv(GL_FRONT, GL_DIFFUSE, (GLfloat[]){1, 0, 0, 1});
glVertex2f(0.05, 0.05);
glMaterialfv(GL_FRONT, GL_DIFFUSE, (GLfloat[]){0, 1, 0, 1});
glVertex2f(0.95, 0.05);
glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, (GLfloat[]){0, 0, 1, 1});
glVertex2f(0.5, 0.95);
glEnd();
glShadeModel(GL_FLAT);
glBegin(GL_QUADS);
glMaterialfv(GL_FRONT, GL_DIFFUSE, (GLfloat[]){1, 1, 0, 1});
glVertex2f(1.05, 0.05); glVertex2f(1.45, 0.05); glVertex2f(1.45, 0.95); glVertex2f(1.05, 0.95);
glMaterialfv(GL_FRONT, GL_EMISSION, (GLfloat[]){0, 0.3, 0.6, 1});
glMaterialfv(GL_FRONT, GL_DIFFUSE, (GLfloat[]){0.2, 0.2, 0.2, 1});
glVertex2f(1.55, 0.05); glVertex2f(1.95, 0.05); glVertex2f(1.95, 0.95); glVertex2f(1.55, 0.95);
glEnd();
glShadeModel(GL_SMOOTH);
glMaterialfv(GL_FRONT, GL_EMISSION, (GLfloat[]){0, 0, 0, 1});
glEnable(GL_COLOR_MATERIAL);
glColorMaterial(GL_FRONT, GL_DIFFUSE);
glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){0.3, 0.2, 1, 0});
glBegin(GL_TRIANGLE_FAN);
glColor3f(0.3, 0.3, 0.8);
glMaterialfv(GL_FRONT, GL_SPECULAR, (GLfloat[]){1, 1, 1, 1});
glMaterialf(GL_FRONT, GL_SHININESS, 4);
glNormal3f(-0.3, -0.2, 1); glVertex2f(3.5, 0.5);
glMaterialf(GL_FRONT, GL_SHININESS, 60);
glNormal3f(0, 0, 1); glVertex2f(3.05, 0.05);
glColor3f(0.8, 0.3, 0.3);
glNormal3f(0.3, 0, 1); glVertex2f(3.95, 0.05);
glMaterialfv(GL_FRONT, GL_SPECULAR, (GLfloat[]){0, 0, 0, 1});
glNormal3f(0, 0.3, 1); glVertex2f(3.95, 0.95);
glNormal3f(-0.3, 0.3, 1); glVertex2f(3.05, 0.95);
glEnd();
";

#[test]
fn materials_set_inside_a_pair_light_each_vertex_as_on_mesa() {
    let tolerance = Tolerance {
        per_channel: 2,
        max_bad_pixels: 128 * 32 / 100,
    };
    for pair in compare("vertex-materials", SCRIPT, FRAME, tolerance) {
        let img = &pair.native.image;
        // The triangle's corners: red, green and blue diffuse over the blue ambient the
        // last glMaterial of the pair left for every vertex.
        probe_rgb(img, 4, 2, [226, 31, 18], 12);
        probe_rgb(img, 27, 2, [31, 226, 18], 12);
        probe_rgb(img, 16, 28, [4, 13, 239], 12);
        // Flat quads: yellow, then dark grey over a blue-green emission.
        probe_rgb(img, 40, 16, [255, 255, 51], 6);
        probe_rgb(img, 56, 16, [51, 128, 255], 6);
        // The fan's highlight, from the per-vertex specular and shininess.
        probe_rgb(img, 112, 16, [255, 251, 251], 12);
    }
}

#[test]
fn the_material_state_after_a_pair_is_the_last_set() {
    let script = "\
glBegin(GL_POINTS);
glMaterialfv(GL_FRONT, GL_DIFFUSE, (GLfloat[]){1, 0, 0, 1});
glVertex2f(0, 0);
glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (GLfloat[]){0, 0.5, 0, 1});
glMaterialf(GL_BACK, GL_SHININESS, 7);
glEnd();
";
    let mut state = fixedfunc::ff::FixedState::default();
    for command in fidelity::parse(script) {
        state.apply(&command).expect("the commands apply");
    }
    assert_eq!(
        state.materials.front.diffuse.to_array(),
        [0.0, 0.5, 0.0, 1.0]
    );
    assert_eq!(
        state.materials.back.diffuse.to_array(),
        [0.0, 0.5, 0.0, 1.0]
    );
    assert_eq!(state.materials.back.shininess, 7.0);
    assert_eq!(state.materials.front.shininess, 0.0);
}

#[test]
fn a_printed_pair_gives_its_vertices_the_same_materials() {
    // The trace of a C program prints what the library received (`ff::script::print`):
    // printed and read again, each draw's vertices carry the same materials.
    let draws = |commands: &[fixedfunc::ff::Command]| -> Vec<fixedfunc::ff::Geometry> {
        commands
            .iter()
            .filter_map(|c| match c {
                fixedfunc::ff::Command::Draw(g) => Some((**g).clone()),
                _ => None,
            })
            .collect()
    };
    let first = fidelity::parse(SCRIPT);
    let printed = fixedfunc::ff::script::print(&first);
    let again = fidelity::parse(&printed);
    let (a, b) = (draws(&first), draws(&again));
    assert_eq!(a.len(), b.len());
    assert!(a.iter().filter(|g| g.materials.is_some()).count() >= 3);
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.materials, y.materials, "printed:\n{printed}");
        assert_eq!(x.positions, y.positions);
    }
}

#[test]
fn non_finite_materials_set_inside_a_pair_light_as_on_mesa() {
    // A NaN and an infinite diffuse component, and a NaN emission, each set per vertex: the
    // vertex colour clamp (NaN to 1, +∞ to 1) must meet Mesa's on every vertex.
    let script = "\
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glOrtho(0, 1, 0, 1, -1, 1);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glEnable(GL_LIGHTING);
glEnable(GL_LIGHT0);
glNormal3f(0, 0, 1);
glBegin(GL_TRIANGLES);
glMaterialfv(GL_FRONT, GL_DIFFUSE, (GLfloat[]){NAN, 0, 0.5, 1});
glVertex2f(0.05, 0.05);
glMaterialfv(GL_FRONT, GL_DIFFUSE, (GLfloat[]){0, INFINITY, 0, 1});
glVertex2f(0.95, 0.05);
glMaterialfv(GL_FRONT, GL_EMISSION, (GLfloat[]){0, 0, NAN, 1});
glVertex2f(0.5, 0.95);
glEnd();
";
    let tolerance = Tolerance {
        per_channel: 2,
        max_bad_pixels: 32 * 32 / 100,
    };
    compare(
        "vertex-materials-nonfinite",
        script,
        Frame::new(32, 32),
        tolerance,
    );
}
