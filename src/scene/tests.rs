//! Table tests of the scene errors: each bad input names its line, key and alternatives.

use super::*;
use crate::vocab::{DepthBits, OffsetSource, PolygonOffset, Precision, ReadbackRule, TechniqueId};
use std::path::Path;

fn parse(text: &str) -> Result<Scene, SceneError> {
    Scene::parse(text, Path::new("test.toml"))
}

const CAMERA: &str = "[camera]\neye = [0, 0, 5]\nat = [0, 0, 0]\nfovy = 45\nnear = 1\nfar = 10\n";

#[test]
fn default_file_equals_built_in() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets");
    let file = Scene::load(&dir.join("default.toml")).expect("default.toml loads");
    assert_eq!(file, Scene::default_scene());
}

#[test]
fn example_scenes_load() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets");
    for name in ["default", "teapot", "aircraft", "near-plane", "obj"] {
        let scene = Scene::load(&dir.join(format!("{name}.toml")))
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(
            !scene.objects.is_empty() && !scene.lights.is_empty(),
            "{name}"
        );
        assert!(scene.warnings.is_empty(), "{name}: {:?}", scene.warnings);
    }
}

#[test]
fn minimal_scene_takes_defaults() {
    let scene = parse(CAMERA).expect("parses");
    assert_eq!(scene.shadow, ShadowSettings::default());
    assert_eq!(scene.truth, TruthSettings::default());
    assert!(scene.objects.is_empty());
    assert_eq!(scene.image, Scene::default_scene().image);
}

/// (name, scene text, expected line, words the message must contain)
const BAD: &[(&str, &str, usize, &[&str])] = &[
    ("syntax", "[camera\n", 1, &["test.toml:1"]),
    ("unknown field", "[camera]\neye = [0,0,5]\nat = [0,0,0]\nfov = 45\n", 4, &["fov", "fovy", "ortho"]),
    ("unknown table", "[lights]\n", 1, &["lights", "light", "object"]),
    ("wrong type", "[image]\nwidth = \"wide\"\n", 2, &["width"]),
    ("negative count", "[image]\nwidth = -3\n", 2, &["-3"]),
    ("zero width", "[image]\nwidth = 0\n", 2, &["image.width", "at least 1"]),
    ("unknown shape", "[[object]]\nshape = \"cone\"\n", 2, &["cone", "sphere", "teapot"]),
    ("unknown technique", "[shadow]\n\ntechnique = \"magic\"\n", 3, &["shadow.technique", "magic", "none"]),
    ("unknown precision", "[shadow]\nprecision = \"half\"\n", 2, &["half", "float", "fixed8"]),
    ("depth bits", "[shadow]\ndepth_bits = 8\n", 2, &["depth_bits", "16", "24", "32f"]),
    ("zero radius", "[[object]]\nshape = \"sphere\"\nradius = 0\n", 3, &["object[0].radius", "greater than zero"]),
    ("negative size", "[[object]]\nshape = \"plane\"\nsize = -2\n", 3, &["object[0].size", "-2"]),
    ("negative box", "[[object]]\nshape = \"box\"\nsize = [1, -1, 1]\n", 3, &["object[0].size"]),
    ("zero tessellation", "[[object]]\nshape = \"plane\"\ntessellation = 0\n", 3, &["tessellation", "at least 1"]),
    ("coarse sphere", "[[object]]\nshape = \"sphere\"\nslices = 2\n", 3, &["slices", "at least 3"]),
    ("key not for shape", "[[object]]\nshape = \"box\"\nradius = 1\n", 3, &["object[0].radius", "box", "size"]),
    ("shape and mesh", "[[object]]\nshape = \"box\"\nmesh = \"a.obj\"\n", 3, &["mesh", "shape"]),
    ("no shape", "\n[[object]]\ncolour = [1, 0, 0]\n", 2, &["object[0].shape", "mesh"]),
    ("nan", "[[object]]\nshape = \"sphere\"\nradius = nan\n", 3, &["radius", "finite"]),
    ("inf translate", "[[object]]\nshape = \"box\"\ntranslate = [0, inf, 0]\n", 3, &["translate", "finite"]),
    ("near >= far", "[camera]\neye = [0,0,5]\nat = [0,0,0]\nfovy = 45\nnear = 10\nfar = 10\n", 6, &["camera.far", "near (10)"]),
    ("fovy 180", "[camera]\neye = [0,0,5]\nat = [0,0,0]\nfovy = 180\nnear = 1\nfar = 10\n", 4, &["camera.fovy", "(0, 180)"]),
    ("fovy 0", "[camera]\neye = [0,0,5]\nat = [0,0,0]\nfovy = 0\nnear = 1\nfar = 10\n", 4, &["camera.fovy"]),
    ("up along view", "[camera]\neye = [0,5,0]\nat = [0,0,0]\nup = [0,1,0]\nfovy = 45\nnear = 1\nfar = 10\n", 4, &["camera.up", "parallel"]),
    ("eye at target", "[camera]\neye = [0,0,0]\nat = [0,0,0]\nfovy = 45\nnear = 1\nfar = 10\n", 3, &["camera.at", "camera.eye", "coincides"]),
    ("fovy and ortho", "[camera]\neye = [0,0,5]\nat = [0,0,0]\nfovy = 45\northo = { left = -1, right = 1, bottom = -1, top = 1 }\nnear = 1\nfar = 10\n", 4, &["ortho"]),
    ("empty ortho", "[camera]\neye = [0,0,5]\nat = [0,0,0]\northo = { left = 1, right = 1, bottom = -1, top = 1 }\nnear = 1\nfar = 10\n", 4, &["camera.ortho.right", "camera.ortho.left"]),
    ("light near >= far", "[[light]]\ntype = \"spot\"\nposition = [0,5,1]\nat = [0,0,0]\nnear = 30\nfar = 24\n", 6, &["light[0].far"]),
    ("light missing position", "[[light]]\ntype = \"point\"\nat = [0,0,0]\n", 1, &["light[0].position", "point light"]),
    ("light key not for type", "[[light]]\ntype = \"point\"\nposition = [0,5,1]\nat = [0,0,0]\ncutoff = 30\n", 5, &["light[0].cutoff", "point light", "position"]),
    ("unknown light type", "[[light]]\ntype = \"laser\"\n", 2, &["laser", "spot", "area"]),
    ("directional zero", "[[light]]\ntype = \"directional\"\ndirection = [0,0,0]\n", 3, &["direction", "zero"]),
    ("sun too wide", "[[light]]\ntype = \"directional\"\ndirection = [0,-1,0]\nangular_diameter = 45\n", 4, &["light[0].angular_diameter", "(0, 30] degrees", "not 45"]),
    ("sun of zero size", "[[light]]\ntype = \"directional\"\n\nangular_diameter = 0\ndirection = [0,-1,0]\n", 4, &["light[0].angular_diameter", "(0, 30]", "not 0"]),
    ("sun negative", "[[light]]\ntype = \"directional\"\ndirection = [0,-1,0]\nangular_diameter = -0.5\n", 4, &["angular_diameter", "not -0.5"]),
    ("sun nan", "[[light]]\ntype = \"directional\"\ndirection = [0,-1,0]\nangular_diameter = nan\n", 4, &["angular_diameter", "finite"]),
    ("sun size on a point light", "[[light]]\ntype = \"point\"\nposition = [0,5,1]\nat = [0,0,0]\nangular_diameter = 1\n", 5, &["light[0].angular_diameter", "point light", "position"]),
    ("sun size on an area light", "[[light]]\ntype = \"area\"\ncentre = [0,5,0]\nsize = [1,1]\nat = [0,0,0]\nangular_diameter = 1\n", 6, &["light[0].angular_diameter", "area light", "edge_u"]),
    ("area without at", "[[light]]\ntype = \"area\"\ncentre = [0,5,0]\nsize = [1,1]\n", 1, &["light[0].at"]),
    ("missing obj", "[[object]]\nmesh = \"does-not-exist.obj\"\n", 2, &["object[0].mesh", "does-not-exist.obj"]),
    ("shininess", "[[object]]\nshape = \"box\"\nshininess = 200\n", 3, &["shininess", "128"]),
    ("no truth samples", "[truth]\nsamples = 0\n", 2, &["truth.samples", "[1, 8192]", "not 0"]),
    ("too many truth samples", "[truth]\n\nsamples = 9000\n", 3, &["truth.samples", "[1, 8192]", "9000"]),
    ("negative truth samples", "[truth]\nsamples = -4\n", 2, &["samples", "-4"]),
    ("unknown truth key", "[truth]\nsample = 64\n", 2, &["sample", "samples"]),
];

#[test]
fn every_bad_input_names_its_line_and_alternatives() {
    for (name, text, line, words) in BAD {
        let err = match parse(text) {
            Ok(_) => panic!("{name}: accepted"),
            Err(e) => e,
        };
        let msg = err.to_string();
        let at = err
            .location()
            .unwrap_or_else(|| panic!("{name}: no location in {msg}"));
        assert_eq!(
            (at.file.as_str(), at.line),
            ("test.toml", *line),
            "{name}: {msg}"
        );
        for w in *words {
            assert!(msg.contains(w), "{name}: `{w}` missing from: {msg}");
        }
    }
}

#[test]
fn obj_files_resolve_relative_and_report_degenerate_faces() {
    let dir = tempfile::tempdir().expect("tempdir");
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\n";
    std::fs::write(dir.path().join("tri.obj"), obj).expect("write obj");
    std::fs::write(dir.path().join("empty.obj"), "v 0 0 0\n").expect("write obj");
    let origin = dir.path().join("scene.toml");
    let text = "[[object]]\nmesh = \"tri.obj\"\n";
    let scene = Scene::parse(text, &origin).expect("loads");
    assert_eq!(scene.objects[0].mesh.triangle_count(), 1);
    assert_eq!(scene.warnings.len(), 1);
    assert_eq!(
        scene.warnings[0].kind,
        WarningKind::DegenerateFaces { count: 1 }
    );
    assert_eq!(scene.warnings[0].at.line, 2);
    let err = Scene::parse("[[object]]\nmesh = \"empty.obj\"\n", &origin).expect_err("no faces");
    assert!(err.to_string().contains("no faces"), "{err}");
}

#[test]
fn technique_names_parse_into_ids_and_unknown_ones_list_every_name() {
    use crate::vocab::{Named, TechniqueId};
    for id in TechniqueId::all() {
        let text = format!("[shadow]\ntechnique = \"{}\"\n", id.name());
        assert_eq!(parse(&text).expect("known").shadow.technique, id);
    }
    let err = parse("[shadow]\ntechnique = \"shadow-volumes\"\n").unwrap_err();
    assert!(
        err.to_string().ends_with(&format!(
            "known techniques: {}",
            TechniqueId::names().join(", ")
        )),
        "{err}"
    );
}

#[test]
fn shadow_table_values() {
    let text = "[shadow]\nmap_size = 512\ndepth_bits = \"32f\"\npolygon_offset = { factor = 1.5, units = 4 }\nprecision = \"fixed8\"\nreadback = \"round\"\n";
    let s = parse(text).expect("parses").shadow;
    assert_eq!(s.map_size, 512);
    assert_eq!(s.depth, DepthBits::D32F);
    assert_eq!(
        s.polygon_offset,
        OffsetSetting::Given {
            offset: Some(PolygonOffset {
                factor: 1.5,
                units: 4.0
            }),
            by: OffsetSource::Scene
        }
    );
    assert_eq!(s.offset_source(), OffsetSource::Scene);
    // Without a polygon_offset the technique's default applies.
    let d = parse("[shadow]\ntechnique = \"dual8\"\ndepth_bits = 16\n")
        .expect("parses")
        .shadow;
    assert_eq!(d.polygon_offset, OffsetSetting::TechniqueDefault);
    assert_eq!(d.offset_source(), OffsetSource::TechniqueDefault);
    assert_eq!(
        d.offset(),
        crate::vocab::default_offset(TechniqueId::Dual8, DepthBits::D16)
    );
    assert_eq!(
        (s.precision, s.readback),
        (
            Precision::Fixed8,
            ReadbackRule::Cpu(crate::vocab::DepthRule::Round)
        )
    );
    assert_eq!(
        parse("[shadow]\ndepth_bits = 16\n")
            .expect("16")
            .shadow
            .depth,
        DepthBits::D16
    );
}

#[test]
fn lights_of_every_kind() {
    let text = r#"
[[light]]
type = "point"
position = [0, 10, 0]
at = [0, 0, 0]
[[light]]
type = "directional"
direction = [0, -1, 0.5]
[[light]]
type = "area"
corner = [-1, 8, -1]
edge_u = [2, 0, 0]
edge_v = [0, 0, 2]
[[light]]
type = "area"
centre = [0, 8, 0]
size = [2, 1]
at = [0, 0, 0]
"#;
    let scene = parse(text).expect("parses");
    assert_eq!(scene.lights.len(), 4);
    assert_eq!(
        scene.lights[0].view.up,
        -glam::Vec3::Z,
        "looking down ±y picks −z as up"
    );
    let LightKind::Area {
        corner,
        edge_u,
        edge_v,
    } = scene.lights[3].kind
    else {
        panic!("area");
    };
    assert!((corner + 0.5 * (edge_u + edge_v) - glam::Vec3::new(0.0, 8.0, 0.0)).length() < 1e-5);
    assert!((edge_u.length() - 2.0).abs() < 1e-5 && (edge_v.length() - 1.0).abs() < 1e-5);
    assert_eq!(
        scene.lights[2].position(),
        Some(glam::Vec3::new(0.0, 8.0, 0.0))
    );
    // Without `angular_diameter` a directional light is hard.
    assert!(matches!(
        scene.lights[1].kind,
        LightKind::Directional {
            angular_diameter: 0.0,
            ..
        }
    ));
    assert!(scene.lights[1].sun().is_none() && !scene.lights[1].is_soft());
    assert!(scene.lights[2].is_soft() && !scene.lights[0].is_soft());
}

#[test]
fn a_sun_takes_its_angular_diameter_in_degrees_up_to_30() {
    let sun = |degrees: &str| {
        let text = format!(
            "[[light]]\ntype = \"directional\"\ndirection = [1, -2, 0]\nangular_diameter = {degrees}\n"
        );
        parse(&text).map(|s| s.lights[0])
    };
    let light = sun("0.53").expect("the real sun");
    let LightKind::Directional {
        direction,
        angular_diameter,
    } = light.kind
    else {
        panic!("a directional light: {:?}", light.kind);
    };
    assert!((angular_diameter - 0.53f32.to_radians()).abs() < 1e-7);
    let disc = light.sun().expect("a sun");
    assert_eq!(disc.angular_diameter, angular_diameter);
    assert!((disc.towards + direction.normalize()).length() < 1e-6);
    assert!(light.is_soft() && light.position().is_none());
    assert!(sun("30").is_ok(), "30° is the top of the range");
    assert!(sun("30.01").is_err());
    assert!(sun("1e-6").is_ok(), "any size above 0");
}

#[test]
fn no_input_panics() {
    // Truncations of a valid scene at every byte: errors, never panics.
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/default.toml"))
            .expect("read");
    for end in (0..text.len()).filter(|&i| text.is_char_boundary(i)) {
        let _ = parse(&text[..end]);
    }
}

/// The message of the error `text` gives, which must be at `line` of test.toml.
fn error_at(text: &str, line: usize) -> String {
    let err = parse(text).expect_err("refused");
    let msg = err.to_string();
    assert_eq!(
        err.location().map(|at| (at.file.as_str(), at.line)),
        Some(("test.toml", line)),
        "{msg}"
    );
    assert!(msg.starts_with(&format!("test.toml:{line}:")), "{msg}");
    msg
}

/// Item: `eye = [0, 9, 20, 1]` used to load as [0, 9, 20], the fourth value dropped.
#[test]
fn a_vector_with_four_values_is_refused_naming_the_field() {
    let msg = error_at(
        "[camera]\nat = [0, 0, 0]\neye = [0, 9, 20, 1]\nfovy = 40\nnear = 4\nfar = 50\n",
        3,
    );
    assert!(
        msg.contains("`eye`") && msg.contains("expected 3 values (x, y, z), found 4"),
        "{msg}"
    );
    let msg = error_at("[[object]]\nshape = \"box\"\ntranslate = [1, 2]\n", 3);
    assert!(
        msg.contains("`translate`") && msg.contains("found 2"),
        "{msg}"
    );
    let msg = error_at(
        "[[light]]\ntype = \"area\"\ncentre = [0, 5, 0]\nsize = [1, 2, 3]\nat = [0, 0, 0]\n",
        4,
    );
    assert!(
        msg.contains("`size`") && msg.contains("expected 2 values (width, height)"),
        "{msg}"
    );
    // Inside `rotate` (one table or a list of them) serde reports which form failed.
    error_at(
        "[[object]]\nshape = \"box\"\nrotate = { axis = [0, 1, 0, 0], degrees = 30 }\n",
        3,
    );
}

/// Item: `eye == at` used to say "`camera.at` must not be the zero vector".
#[test]
fn eye_equal_to_at_says_they_coincide() {
    let msg = error_at(
        "[camera]\neye = [1, 2, 3]\nat = [1, 2, 3]\nfovy = 40\nnear = 4\nfar = 50\n",
        3,
    );
    assert!(
        msg.contains("`camera.at` coincides with `camera.eye`") && !msg.contains("zero vector"),
        "{msg}"
    );
    let msg = error_at(
        "[[light]]\ntype = \"spot\"\nposition = [0, 5, 0]\nat = [0, 5, 0]\n",
        4,
    );
    assert!(
        msg.contains("`light[0].at` coincides with `light[0].position`"),
        "{msg}"
    );
    let msg = error_at(
        "[[light]]\ntype = \"area\"\ncentre = [0, 5, 0]\nsize = [1, 1]\nat = [0, 5, 0]\n",
        5,
    );
    assert!(msg.contains("coincides with `light[0].centre`"), "{msg}");
}

/// Item: parallel area-light edges used to be "the zero vector".
#[test]
fn parallel_area_light_edges_are_called_parallel() {
    let msg = error_at(
        "[[light]]\ntype = \"area\"\ncorner = [0, 5, 0]\nedge_u = [1, 0, 0]\nedge_v = [-2, 0, 0]\n",
        5,
    );
    assert!(
        msg.contains("`light[0].edge_v` is parallel to `light[0].edge_u`")
            && !msg.contains("zero vector"),
        "{msg}"
    );
}

/// Item: `right <= left` used to say "`camera.ortho` (1) must be less than (1)".
#[test]
fn orthographic_bounds_errors_name_the_fields() {
    let text = |bounds: &str| {
        format!("[camera]\neye = [0, 0, 5]\nat = [0, 0, 0]\nnear = 1\nfar = 10\northo = {{ {bounds} }}\n")
    };
    let msg = error_at(&text("left = 2, right = 1, bottom = -1, top = 1"), 6);
    assert!(
        msg.contains("`camera.ortho.right` (1) must be greater than `camera.ortho.left` (2)"),
        "{msg}"
    );
    let msg = error_at(&text("left = -1, right = 1, bottom = 3, top = 3"), 6);
    assert!(
        msg.contains("`camera.ortho.top` (3) must be greater than `camera.ortho.bottom` (3)"),
        "{msg}"
    );
    let msg = error_at(&text("left = nan, right = 1, bottom = -1, top = 1"), 6);
    assert!(
        msg.contains("`camera.ortho.left` must be a finite number"),
        "{msg}"
    );
}

/// Item: an image or a map larger than 8192 used to be blamed on "the light's map" when
/// rendered (and was accepted by the scene).
#[test]
fn an_image_larger_than_8192_is_refused_as_the_image() {
    let msg = error_at("[image]\nwidth = 512\nheight = 9000\n", 3);
    assert!(
        msg.contains("`image.height` must be at most 8192, not 9000"),
        "{msg}"
    );
    let msg = error_at("[shadow]\nmap_size = 16384\n", 2);
    assert!(
        msg.contains("`shadow.map_size` must be at most 8192"),
        "{msg}"
    );
}

/// Item: a tessellation of 5000 used to build 50 million triangles and abort at 6.5 GiB.
/// Refused from the parameters, at the object's line, with the figures and the flags.
#[test]
fn a_huge_tessellation_is_refused_with_the_figures() {
    let msg = error_at(
        "[[object]]\nshape = \"box\"\n[[object]]\nshape = \"plane\"\ntessellation = 5000\n",
        3,
    );
    assert!(
        msg.contains("`object[1]` would make the scene 50,000,012 triangles (≈ 14.0 GiB)")
            && msg.contains("the budget is 20,000,000 triangles and 8.0 GiB")
            && msg.contains("--max-triangles / --memory-budget"),
        "{msg}"
    );
    // Raised, the same scene's budget check passes (a smaller scene keeps the test light).
    let text = "[[object]]\nshape = \"plane\"\ntessellation = 300\n";
    let tight = Limits {
        max_triangles: 100_000,
        ..Limits::default()
    };
    let err = Scene::parse_with(text, Path::new("test.toml"), tight).expect_err("180,000");
    assert!(err.to_string().contains("180,000 triangles"), "{err}");
    let raised = Limits {
        max_triangles: 200_000,
        ..Limits::default()
    };
    let scene = Scene::parse_with(text, Path::new("test.toml"), raised).expect("raised");
    assert_eq!(scene.objects[0].mesh.triangle_count(), 180_000);
    assert_eq!(scene.limits, raised);
}

/// An OBJ's triangles count against the budget once read.
#[test]
fn obj_triangles_count_against_the_budget() {
    let dir = tempfile::tempdir().expect("tempdir");
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
    std::fs::write(dir.path().join("two.obj"), obj).expect("write obj");
    let origin = dir.path().join("scene.toml");
    let text = "[[object]]\nshape = \"box\"\n[[object]]\nmesh = \"two.obj\"\n";
    let limits = Limits {
        max_triangles: 13,
        ..Limits::default()
    };
    let err = Scene::parse_with(text, &origin, limits).expect_err("14 > 13");
    assert!(err.to_string().contains("14 triangles"), "{err}");
    assert!(Scene::parse_with(
        text,
        &origin,
        Limits {
            max_triangles: 14,
            ..limits
        }
    )
    .is_ok());
}

#[test]
fn truth_samples_are_read_and_bounded() {
    let scene = parse("[truth]\nsamples = 512\n").expect("parses");
    assert_eq!(scene.truth.samples, 512);
    for n in [1, TruthSettings::MAX_SAMPLES] {
        let scene = parse(&format!("[truth]\nsamples = {n}\n")).expect("in range");
        assert_eq!(scene.truth.samples, n);
    }
    assert_eq!(
        parse("[truth]\n").expect("parses").truth,
        TruthSettings::default(),
        "an empty [truth] takes the defaults"
    );
}
