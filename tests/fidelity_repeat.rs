//! Repeated draws (`pipeline::emulate::repeat`) against Mesa's native path. One display list,
//! a lit, textured fan, is called fourteen times; between the calls the modelview and
//! projection matrices change (which the emulated path repeats: same program and pass, new
//! transform uniforms) and, in turn, each kind of state the repeat must not carry over: a
//! material (a uniform), blending (raster state), the polygon mode (the pass), lighting (the
//! key), the current colour, texturing and a texture matrix (the key). Tolerance: 1/255 on
//! every pixel (lit fans, rotated). The emulated run must have repeated exactly the draws
//! that only a matrix change separates from the one before.

mod fidelity;
mod support;

use fidelity::{compare, parse, run_one, Frame};
use fixedfunc::vocab::{PipelineKind, Precision};
use support::Tolerance;

const W: u32 = 128;
const H: u32 = 112;

/// The fan: a centre and 12 rim vertices of radius 1, normals tilted out by 45° at the rim,
/// texture coordinates from the positions.
fn fan() -> String {
    let mut s = String::from(
        "glNewList(1, GL_COMPILE);\nglBegin(GL_TRIANGLE_FAN);\n\
         glNormal3f(0, 0, 1);\nglTexCoord2f(0.5, 0.5);\nglVertex3f(0, 0, 0);\n",
    );
    for k in 0..=12 {
        let a = k as f32 * std::f32::consts::TAU / 12.0;
        let (x, y) = (a.cos(), a.sin());
        s += &format!(
            "glNormal3f({x}, {y}, 1);\nglTexCoord2f({}, {});\nglVertex3f({x}, {y}, 0);\n",
            0.5 + 0.5 * x,
            0.5 + 0.5 * y
        );
    }
    s + "glEnd();\nglEndList();\n"
}

/// The list drawn at (x, y) at radius 10, after `extra` on the modelview stack.
fn at(x: u32, y: u32, extra: &str) -> String {
    format!(
        "glPushMatrix();\nglTranslatef({x}, {y}, 0);\n{extra}glScalef(10, 10, 10);\n\
         glCallList(1);\nglPopMatrix();\n"
    )
}

fn script() -> String {
    let texture = "glBindTexture(GL_TEXTURE_2D, 1);\n\
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);\n\
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);\n\
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, \
        (GLubyte[]){255, 255, 255, 255, 40, 40, 40, 255, 40, 40, 40, 255, 255, 255, 255, 255});\n";
    let mut s = format!(
        "glClearColor(0, 0, 0, 1);\nglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);\n{}\
         glEnable(GL_LIGHTING);\nglEnable(GL_LIGHT0);\nglEnable(GL_NORMALIZE);\n\
         glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){{0.3, 0.4, 1, 0}});\n{}{texture}",
        fidelity::ortho(W, H),
        fan()
    );
    // Row 1: matrices only between the draws after the first.
    s += &at(16, 16, "");
    s += &at(40, 16, "glRotatef(40, 1, 0, 0);\n");
    s += &at(64, 16, "glRotatef(-60, 0, 1, 1);\n");
    s += "glMatrixMode(GL_PROJECTION);\nglPushMatrix();\nglTranslatef(0.05, 0, 0);\n\
          glMatrixMode(GL_MODELVIEW);\n";
    s += &at(88, 16, "");
    s += "glMatrixMode(GL_PROJECTION);\nglPopMatrix();\nglMatrixMode(GL_MODELVIEW);\n";
    // Row 2: a material, then blending, then the polygon mode, each followed by a repeat.
    s += "glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (GLfloat[]){0.9, 0.2, 0.1, 1});\n";
    s += &at(16, 44, "");
    s += &at(40, 44, "glRotatef(30, 0, 1, 0);\n");
    s += "glEnable(GL_BLEND);\nglBlendFunc(GL_ONE, GL_ONE);\n";
    s += &at(60, 44, "");
    s += "glDisable(GL_BLEND);\nglPolygonMode(GL_FRONT_AND_BACK, GL_LINE);\n";
    s += &at(88, 44, "");
    s += "glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);\n";
    // Row 3: unlit in a current colour, another colour, then textured.
    s += "glDisable(GL_LIGHTING);\nglColor3f(0.1, 0.8, 0.3);\n";
    s += &at(16, 72, "");
    s += "glColor3f(0.2, 0.3, 0.9);\n";
    s += &at(40, 72, "");
    s += "glEnable(GL_TEXTURE_2D);\n";
    s += &at(64, 72, "");
    // Row 4: a texture matrix (in the key), then the identity again.
    s += "glMatrixMode(GL_TEXTURE);\nglTranslatef(0.5, 0.25, 0);\nglMatrixMode(GL_MODELVIEW);\n";
    s += &at(16, 98, "");
    s += "glMatrixMode(GL_TEXTURE);\nglLoadIdentity();\nglMatrixMode(GL_MODELVIEW);\n";
    s += &at(40, 98, "");
    s += &at(64, 98, "glRotatef(20, 0, 0, 1);\n");
    s
}

#[test]
fn a_list_called_between_matrix_and_state_changes_draws_as_on_mesa() {
    let tol = Tolerance {
        per_channel: 1,
        max_bad_pixels: 0,
    };
    for pair in compare("repeat", &script(), Frame::new(W, H), tol) {
        let lit = pair
            .native
            .image
            .pixels()
            .filter(|p| p.0[..3] != [0, 0, 0])
            .count();
        assert!(
            lit > 12 * 150,
            "{}: the fans are drawn ({lit} pixels)",
            pair.backend
        );
    }
}

/// Draws 3 and 4 follow only matrix changes; so do 6 (after draw 5, which follows a
/// material) and 14 (after 13, which follows a texture matrix's return to the identity).
/// Draw 2 is not repeated: the list's first call leaves its last normal and texture
/// coordinate current (commands after its draw, as glEnd leaves them), which the repeat
/// does not look into. The other nine follow a change the repeat must not carry over.
#[test]
fn only_draws_after_matrix_changes_alone_are_repeated() {
    let commands = parse(&script());
    for backend in support::HEADLESS {
        let out = run_one(
            PipelineKind::Emulate,
            Precision::Float,
            backend,
            Frame::new(W, H),
            &commands,
        );
        assert_eq!(out.counters.draws, 14, "{backend}");
        assert_eq!(out.counters.repeated_draws, 4, "{backend}");
    }
}
