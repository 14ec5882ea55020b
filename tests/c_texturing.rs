//! Texturing as C programs written for Mesa's OSMesa exercise it (`tests/c/`), compiled
//! with `cc` against the real `GL/osmesa.h` and run on Mesa's `libOSMesa.so.8` and on the
//! layer's: what each prints (texels, errors, queried parameters) must be the same line
//! for line, and the images Mesa's exactly.

#[path = "c/harness.rs"]
mod harness;
mod support;

use std::path::{Path, PathBuf};

use harness::{compile, read_ppm, run, Library};
use image::RgbaImage;
use support::{assert_images_match, Tolerance};

fn work_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("c_texturing")
        .join(name);
    std::fs::create_dir_all(&dir).expect("the test folder can be made");
    dir
}

/// What `tests/c/NAME.c` printed and the image it wrote, on Mesa and on the layer.
fn texts_and_images(name: &str) -> [(String, RgbaImage); 2] {
    let dir = work_dir(name);
    let exe = dir.join(name);
    compile(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/c/{name}.c")),
        &exe,
    );
    [Library::Mesa, Library::Fixedfunc].map(|library| {
        let out = dir.join(format!("{library:?}.ppm"));
        let text = run(&exe, library, &[out.to_str().unwrap()]).stdout;
        (String::from_utf8_lossy(&text).into_owned(), read_ppm(&out))
    })
}

/// Mesa printed each of `lines` (the answers the program is built around), and the
/// layer printed what Mesa printed, line by line; the images are Mesa's exactly.
fn assert_as_on_mesa(name: &str, lines: &[&str]) {
    let [(mesa_text, mesa), (ours_text, ours)] = texts_and_images(name);
    for line in lines {
        assert!(
            mesa_text.contains(line),
            "Mesa did not print {line:?}:\n{mesa_text}"
        );
    }
    for (m, o) in mesa_text.lines().zip(ours_text.lines()) {
        assert_eq!(o, m, "{name}: a line differs from Mesa's");
    }
    assert_eq!(ours_text.lines().count(), mesa_text.lines().count());
    assert_images_match(name, &ours, &mesa, Tolerance::EXACT);
}

/// `tests/c/upload_bounds.c`: uploads whose sizes GL refuses, from a 64-byte array before
/// an unreadable page, fail with Mesa's errors without reading past the array (a read
/// would crash the program); the texture keeps what it held.
#[test]
fn uploads_of_refused_sizes_read_nothing() {
    assert_as_on_mesa(
        "upload_bounds",
        &[
            "2D width 16385                           err 0x501",
            "2D level 3 width 4096                    err 0x501",
            "sub-image 1000 wide into 4x4             err 0x501",
            "sub-image of a missing level             err 0x502",
            "DXT1 sub-image 256x256 into 8x8          err 0x501",
        ],
    );
}

/// `tests/c/border_formats.c`: the border colour taken as each base format takes a colour
/// (GL 1.5 §3.8.8): an ALPHA texture's border gives the border's alpha only, a
/// LUMINANCE_ALPHA one its red and alpha.
#[test]
fn border_colours_follow_the_base_format() {
    assert_as_on_mesa(
        "border_formats",
        &[
            "ALPHA border                         204 230 255  71 err 0x0",
            "LUMINANCE_ALPHA border               184 207 230  71 err 0x0",
            "ALPHA half border                    204 230 255  88 err 0x0",
        ],
    );
}

/// `tests/c/dot3_alpha.c`: DOT3_RGBA's alpha is the dot product scaled by ALPHA_SCALE,
/// its colour by RGB_SCALE (GL 1.5 §3.8.13).
#[test]
fn dot3_rgba_scales_alpha_by_alpha_scale() {
    assert_as_on_mesa(
        "dot3_alpha",
        &[
            "DOT3_RGBA ALPHA_SCALE 2              142 142 142 255 err 0x0",
            "DOT3_RGBA RGB_SCALE 4                255 255 255 142 err 0x0",
        ],
    );
}

/// `tests/c/level_formats.c`: levels whose internal formats are named differently (RGBA
/// and RGBA8, 4 and RGBA) make a mipmapped texture incomplete, as on Mesa.
#[test]
fn levels_named_in_other_formats_are_incomplete() {
    assert_as_on_mesa(
        "level_formats",
        &[
            "levels 0x1908 0x8058 filter 0x2700   51 102 153 204 err 0x0",
            "levels 0x0004 0x1908 filter 0x2700   51 102 153 204 err 0x0",
            "levels 0x1908 0x1908 filter 0x2700   51   0   0 204 err 0x0",
            "levels 0x1908 0x8058 filter 0x2600   51   0   0 204 err 0x0",
        ],
    );
}

/// `tests/c/tex_params.c`: TEXTURE_LOD_BIAS and TEXTURE_PRIORITY of the texture object
/// through every glTexParameter form and glPrioritizeTextures, queried as floats and
/// integers; the object's bias adds to the unit's.
#[test]
fn the_object_lod_bias_and_priority_are_kept() {
    assert_as_on_mesa(
        "tex_params",
        &[
            "glTexParameterf 1.25 0.25          bias 1.25 1 priority 0.25 536870911 err 0x0",
            "first texture                      bias 3 3 priority 0.75 1610612735 err 0x0",
            "object bias 1                        0 255   0 255 err 0x0",
            "object bias 1, unit bias -1        255   0   0 255 err 0x0",
        ],
    );
}

/// `tests/c/crossbar_sources.c`: a combine source naming a disabled or incomplete unit
/// reads (0, 0, 0, 0), as on Mesa (the spec leaves it undefined).
#[test]
fn a_crossbar_source_of_a_unit_off_reads_zero() {
    assert_as_on_mesa(
        "crossbar_sources",
        &[
            "TEXTURE1 enabled                      40 220 170 230 err 0x0",
            "TEXTURE1 disabled                      0   0   0   0 err 0x0",
            "TEXTURE1 incomplete                    0   0   0   0 err 0x0",
        ],
    );
}

/// `tests/c/sub_image_null.c`: glTexSubImage of a NULL pointer is checked as any call and
/// stores nothing, without an error of its own.
#[test]
fn sub_images_from_null_are_checked_and_store_nothing() {
    assert_as_on_mesa(
        "sub_image_null",
        &[
            "2D 2x2 from NULL                         err 0x0",
            "2D outside the level from NULL           err 0x501",
            "2D missing level from NULL               err 0x502",
            "1D 2 from NULL                           err 0x0",
            "3D 2x2x1 from NULL                       err 0x0",
        ],
    );
}

/// `tests/c/mipmaps_generated_late.c`: GENERATE_MIPMAP set after the base level exists
/// derives the levels at the next change of the base level.
#[test]
fn mipmaps_are_generated_when_the_flag_comes_after_the_image() {
    assert_as_on_mesa(
        "mipmaps_generated_late",
        &[
            "2D after a sub-image         level 4 width 1: 121 121 0 255 err 0x0",
            "level 2 drawn 88 8 0 255 err 0x0",
        ],
    );
}

/// `tests/c/proxy_tex.c`: glTexImage1D and glTexImage2D of PROXY_TEXTURE_1D, _2D and
/// _CUBE_MAP specify the proxy's level when the image fits (a border of 1 included) and
/// clear it without an error when not; no real texture changes, and a display list runs
/// the call at once.
#[test]
fn proxy_images_answer_whether_they_fit() {
    assert_as_on_mesa(
        "proxy_tex",
        &[
            "2D 64x32 RGB5                    64x32x1 b0 0x8050 r5 g5 a0 (64) err 0x0",
            "2D 100000x4                      0x0x0 b0 0x1908 r0 g0 a0 (0) err 0x0",
            "cube 64x32                       0x0x0 b0 0x1908 r0 g0 a0 (0) err 0x0",
            "2D 66x34 border 1                66x34x1 b1 0x1908 r8 g8 a8 (66) err 0x0",
            "2D proxy compiled                32x8x1 b0 0x8058 r8 g8 a8 (32) err 0x0",
            "real 2D after proxies            4x4x1 b0 0x1908 r8 g8 a8 (4) err 0x0",
        ],
    );
}

/// `tests/c/target_fallback.c`: with several texture targets enabled on a unit, the one
/// sampled is the highest-priority enabled target whose texture is complete, as Mesa draws
/// it (`FixedState::sampled_texture`; GL 1.5 §3.8.15 would turn the unit off when the
/// highest enabled target is incomplete), and the unit is off when none is.
#[test]
fn an_incomplete_higher_target_falls_back_to_a_complete_lower_one() {
    assert_as_on_mesa(
        "target_fallback",
        &[
            "2D, an empty cube map enabled              0 255   0  err 0x0",
            "2D incomplete over a complete 1D         255   0   0  err 0x0",
            "2D and 1D incomplete: the unit off         0   0 255  err 0x0",
        ],
    );
}

/// `tests/c/nan_texcoords.c`: a NaN or infinite texture coordinate at one vertex loses
/// only itself, as on Mesa: an identity texture matrix is left out of the vertex program
/// (`VertexUnitKey::matrix`), so 0·NaN does not spread to the other coordinates; a
/// translated texture matrix still applies.
#[test]
fn a_non_finite_texture_coordinate_spoils_only_itself() {
    assert_as_on_mesa(
        "nan_texcoords",
        &["s = NaN                         0 255   0    0 255   0  128 127   0  err 0x0"],
    );
}

/// `tests/c/texture_border.c`: an image given a border of 1 is stripped to its interior
/// at the call, as Mesa's state tracker strips it (a height of 2 kept whole), in
/// glTexImage1D/2D/3D and glCopyTexImage1D/2D; a proxy keeps its border; borders other
/// than 0 and 1, or wider than half a side, are INVALID_VALUE.
#[test]
fn texture_borders_are_stripped_as_on_mesa() {
    assert_as_on_mesa(
        "texture_border",
        &[
            "  level                                  w 4 h 4 border 0  err 0x0",
            "  texels                                 31ce28 38c750 3fc078 46b9a0 5ba428",
            "TexImage2D 4x2 border 1                  err 0x0",
            "  texels                                 07f828 0ef150 23dcc8 2ad500 | ee  err 0x0",
            "  proxy level                            w 6 h 6 border 1  err 0x0",
            "TexImage2D 6x1 border 1                  err 0x501",
        ],
    );
}
