//! `fixedfunc shaders` and `fixedfunc replay` on the scripts in tests/scripts.

mod support;

use std::process::Command;

fn fixedfunc(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .args(args)
        .output()
        .expect("run fixedfunc");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

const ONE_UNIT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/scripts/one_unit.c");

#[test]
fn one_enabled_unit_generates_code_for_that_unit_only() {
    let (ok, out, err) = fixedfunc(&["shaders", ONE_UNIT]);
    assert!(ok, "{err}");
    assert!(out.contains("1 distinct program(s)"), "{out}");
    assert!(
        out.contains("uniform sampler2D u_tex2;") && out.contains("v_tc2"),
        "{out}"
    );
    for other in [0, 1, 3, 4, 5, 6, 7] {
        for name in [
            format!("u_tex{other}"),
            format!("v_tc{other}"),
            format!("a_texcoord{other}"),
            format!("u_texmat{other}"),
        ] {
            assert!(!out.contains(&name), "code for unit {other}: {name}\n{out}");
        }
    }
    // No lighting, no alpha test: none of their code either.
    assert!(
        !out.contains("u_light") && !out.contains("discard"),
        "{out}"
    );
}

#[test]
fn replay_writes_the_image_the_script_draws() {
    let out_png = support::output_dir().join("replay-one-unit.png");
    let out_str = out_png.to_str().expect("utf-8 path");
    let (ok, stdout, err) = fixedfunc(&["replay", ONE_UNIT, "--size", "4x4", "--out", out_str]);
    assert!(ok, "{err}");
    assert!(stdout.contains("1 draws, 1 programs compiled"), "{stdout}");
    let img = image::open(&out_png).expect("png").to_rgba8();
    // MODULATE of (1, 0.5, 1) by the luminance texels 0 (bottom left) and 255 (top right).
    support::probe(&img, 0, 3, [0, 0, 0, 255], 0);
    support::probe(&img, 3, 0, [255, 128, 255, 255], 1);
}

#[test]
fn a_bad_script_names_its_line_and_the_valid_values() {
    let dir = support::output_dir();
    let path = dir.join("bad-script.c");
    std::fs::write(
        &path,
        "glEnable(GL_LIGHTING);\nglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_SHINY);\n",
    )
    .expect("write script");
    let (ok, _, err) = fixedfunc(&[
        "replay",
        path.to_str().expect("utf-8"),
        "--out",
        "/dev/null",
    ]);
    assert!(!ok);
    assert!(err.contains("line 2") && err.contains("GL_SHINY"), "{err}");
    assert!(
        err.contains("GL_MODULATE") && err.contains("GL_COMBINE"),
        "{err}"
    );
    let (ok, _, err) = fixedfunc(&["replay", ONE_UNIT, "--size", "0x4"]);
    assert!(!ok && err.contains("at least 1"), "{err}");
}

#[test]
fn shaders_of_the_default_scene_frame_light_without_texturing() {
    let (ok, out, err) = fixedfunc(&["shaders"]);
    assert!(ok, "{err}");
    assert!(
        out.starts_with("the default scene (none): 1 distinct program(s)"),
        "{out}"
    );
    assert!(out.contains("u_light0_front_diffuse_product"), "{out}");
    assert!(!out.contains("sampler") && !out.contains("v_tc"), "{out}");
}

/// A GL error met while replaying goes to stderr with the script line that raised it, for
/// every error, not only the first.
#[test]
fn replay_names_the_line_of_each_gl_error() {
    let dir = support::output_dir();
    let script = dir.join("replay-errors.c");
    std::fs::write(
        &script,
        "#include <GL/gl.h>\nglLoadIdentity();\nglPopMatrix();\nglClearColor(0, 0, 0, 1);\nglLineWidth(-1);\n",
    )
    .expect("write script");
    let out_png = dir.join("replay-errors.png");
    let (ok, stdout, err) = fixedfunc(&[
        "replay",
        script.to_str().expect("utf-8"),
        "--size",
        "2x2",
        "--out",
        out_png.to_str().expect("utf-8"),
    ]);
    assert!(ok, "{err}");
    assert!(err.contains("replay-errors.c:3: glPopMatrix:"), "{err}");
    assert!(err.contains("replay-errors.c:5: glLineWidth:"), "{err}");
    assert!(!stdout.contains("GL error"), "{stdout}");
}

/// tests/scripts/every_call.c calls every implemented non-attribute entry point once;
/// `fixedfunc replay` runs it on both pipelines without a GL error.
#[test]
fn every_implemented_call_replays_without_a_gl_error() {
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/scripts/every_call.c");
    for pipeline in ["emulate", "native"] {
        let out_png = support::output_dir().join(format!("every-call-{pipeline}.png"));
        let out_str = out_png.to_str().expect("utf-8 path");
        let (ok, stdout, err) = fixedfunc(&[
            "replay",
            script,
            "--size",
            "8x8",
            "--pipeline",
            pipeline,
            "--out",
            out_str,
        ]);
        assert!(ok, "{pipeline}: {err}");
        assert!(stdout.contains("6 draws"), "{pipeline}: {stdout}");
        assert!(!err.contains("GL error"), "{pipeline}: {err}");
    }
}
