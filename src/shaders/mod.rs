//! Historical shaders: published algorithms of the era, ported to GLSL 3.30 core and kept in
//! the top-level `shaders/` folder, one file per stage. Each file is embedded with
//! `include_str!`, so the binary needs no file at run time; [`historical`] lists them with
//! their stage and where they come from, and a test fails when a file of the folder is
//! missing from the list. A port keeps its source's structure, names, constants and order
//! of operations; each file's header says which lines it comes from and what changed.
//!
//! Coleman's occluder planes (thesis, 2006) hard-code the F-35's three shadow planes into
//! the vertex shader ("hard-coded as constants into the equations in the vertex shader
//! rather than passing the values as parameters", §5). [`F35_PLANES`] repeats them as data
//! for CPU models, and a test reads them back out of the GLSL, so the two cannot drift.
//! The planes follow the appendix's code where it differs from the text: a shadow
//! coordinate is (right · (q − o) / width, up · (q − o) / height) for the intersection q,
//! where the text's equation 8 writes o − q; the fins' right vector is (0, −1, 0) (the code's
//! `- distanceVec.y`), so right × up is the right fin's normal and the negated left fin's.

use glam::{Vec2, Vec3};

/// A shader stage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    Vertex,
    Fragment,
}

/// One embedded file of `shaders/`.
#[derive(Clone, Copy, Debug)]
pub struct HistoricalShader {
    /// Its path under `shaders/`, e.g. `coleman/occluder.vert`.
    pub name: &'static str,
    pub stage: Stage,
    /// The GLSL, `#version 330 core` first.
    pub source: &'static str,
    /// One line: the publication and the part of it the code comes from.
    pub origin: &'static str,
}

const HISTORICAL: &[HistoricalShader] = &[
    HistoricalShader {
        name: "coleman/occluder.vert",
        stage: Stage::Vertex,
        source: include_str!("../../shaders/coleman/occluder.vert"),
        origin: "C. R. Coleman, Fast Self-Shadowing Using Occluder Textures, M.S. thesis, \
                 Texas A&M University, 2006: Appendix A, Example Vertex Shader Source (Cg)",
    },
    HistoricalShader {
        name: "coleman/occluder.frag",
        stage: Stage::Fragment,
        source: include_str!("../../shaders/coleman/occluder.frag"),
        origin: "C. R. Coleman, Fast Self-Shadowing Using Occluder Textures, M.S. thesis, \
                 Texas A&M University, 2006: Appendix B, Example Fragment Shader Source (Cg)",
    },
    HistoricalShader {
        name: "eisemann/window.vert",
        stage: Stage::Vertex,
        source: include_str!("../../shaders/eisemann/window.vert"),
        origin: "E. Eisemann and X. Décoret, Occlusion Textures for Plausible Soft Shadows, \
                 Computer Graphics Forum 27(1), 2008: §3.2, a full-window pass per N-buffer level \
                 or summed-area-table step",
    },
    HistoricalShader {
        name: "eisemann/gauss.frag",
        stage: Stage::Fragment,
        source: include_str!("../../shaders/eisemann/gauss.frag"),
        origin: "E. Eisemann and X. Décoret, Occlusion Textures for Plausible Soft Shadows, \
                 Computer Graphics Forum 27(1), 2008: §3.5, sunlight's Gaussian instead of a box \
                 filter, as a Gaussian pyramid",
    },
    HistoricalShader {
        name: "eisemann/nbuffer.frag",
        stage: Stage::Fragment,
        source: include_str!("../../shaders/eisemann/nbuffer.frag"),
        origin: "E. Eisemann and X. Décoret, Occlusion Textures for Plausible Soft Shadows, \
                 Computer Graphics Forum 27(1), 2008: §3.2, N-buffers' dyadic construction",
    },
    HistoricalShader {
        name: "eisemann/sat.frag",
        stage: Stage::Fragment,
        source: include_str!("../../shaders/eisemann/sat.frag"),
        origin: "E. Eisemann and X. Décoret, Occlusion Textures for Plausible Soft Shadows, \
                 Computer Graphics Forum 27(1), 2008: §3.2, summed-area tables [Cro84] built by \
                 recursive doubling [HSC*05]",
    },
    HistoricalShader {
        name: "eisemann/slices.vert",
        stage: Stage::Vertex,
        source: include_str!("../../shaders/eisemann/slices.vert"),
        origin: "E. Eisemann and X. Décoret, Occlusion Textures for Plausible Soft Shadows, \
                 Computer Graphics Forum 27(1), 2008: §3.4 and Figure 5, the slicing view from a centre of projection behind the light",
    },
    HistoricalShader {
        name: "eisemann/slices.frag",
        stage: Stage::Fragment,
        source: include_str!("../../shaders/eisemann/slices.frag"),
        origin: "E. Eisemann and X. Décoret, Occlusion Textures for Plausible Soft Shadows, \
                 Computer Graphics Forum 27(1), 2008: §3.4, slices packed four to an RGBA texture; §3.4.1, the light-leak fix",
    },
    HistoricalShader {
        name: "eisemann/visibility.vert",
        stage: Stage::Vertex,
        source: include_str!("../../shaders/eisemann/visibility.vert"),
        origin: "E. Eisemann and X. Décoret, Occlusion Textures for Plausible Soft Shadows, \
                 Computer Graphics Forum 27(1), 2008: §3.5, the observer's pass: each fragment's position in the light's frame",
    },
    HistoricalShader {
        name: "eisemann/visibility.frag",
        stage: Stage::Fragment,
        source: include_str!("../../shaders/eisemann/visibility.frag"),
        origin: "E. Eisemann and X. Décoret, Occlusion Textures for Plausible Soft Shadows, \
                 Computer Graphics Forum 27(1), 2008: §3.1 equation 4, §3.2 prefiltering, §3.3 equation 5, §3.4.2 self shadowing",
    },
];

/// Every embedded shader; a program's stages in pipeline order.
pub fn historical() -> &'static [HistoricalShader] {
    HISTORICAL
}

/// The shader whose `name` is given, e.g. `coleman/occluder.frag`.
pub fn find(name: &str) -> Option<&'static HistoricalShader> {
    HISTORICAL.iter().find(|s| s.name == name)
}

/// A shadow plane: an occluder texture of `width` × `height` metres laid on the plane
/// through `origin` with `normal`, its s axis along `right` and its t axis along `up`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowPlane {
    pub name: &'static str,
    /// The sampler of `coleman/occluder.frag` that holds the plane's occluder texture.
    pub occluder: &'static str,
    pub origin: Vec3,
    pub normal: Vec3,
    pub up: Vec3,
    pub right: Vec3,
    pub width: f32,
    pub height: f32,
}

/// Where a ray toward the light meets a shadow plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowCoord {
    /// The occluder texture coordinate, before the fragment shader's saturate.
    pub st: Vec2,
    /// The ray parameter s_I: the intersection is p + s_I · L.
    pub s_i: f32,
}

impl ShadowCoord {
    /// The plane lies between the point and the light (s_I > 0), so its occluder counts;
    /// otherwise the fragment shader ignores the look-up (the "false shadow" test of §4.1).
    pub fn plane_between(self) -> bool {
        self.s_i > 0.0
    }
}

impl ShadowPlane {
    /// The shadow coordinate of model-space point `p` under a directional light toward unit
    /// `light`: s_I = n · (o − p) / (n · L) (equation 6), q = p + s_I · L, then
    /// (right · (q − o) / width, up · (q − o) / height) (equation 8, the appendix's sign).
    /// A light parallel to the plane gives a non-finite coordinate, as on the GPU.
    pub fn shadow_coord(&self, p: Vec3, light: Vec3) -> ShadowCoord {
        let s_i = self.normal.dot(self.origin - p) / self.normal.dot(light);
        let d = p + light * s_i - self.origin;
        ShadowCoord {
            st: Vec2::new(self.right.dot(d) / self.width, self.up.dot(d) / self.height),
            s_i,
        }
    }
}

/// The F-35's shadow planes of `coleman/occluder.vert`, in the order of its texture
/// coordinates 1, 2 and 3 (Appendix A, lines 575-607, 609-648 and 650-687 of the thesis's
/// plain-text edition). The digits are the appendix's code, as printed (f32 rounds
/// 0.91759448 as the GLSL compiler does). The z = 0 plane's origin is the texture's corner
/// of the code's comment, V0 = (−7.5, −5.315, 0); the text's equation 7 takes o = (0, 0, 0),
/// which gives the same s_I.
#[allow(clippy::excessive_precision)]
pub const F35_PLANES: [ShadowPlane; 3] = [
    ShadowPlane {
        name: "fuselage, wings and stabilisers (z = 0)",
        occluder: "shadowTEX",
        origin: Vec3::new(-7.5, -5.315, 0.0),
        normal: Vec3::Z,
        up: Vec3::Y,
        right: Vec3::X,
        width: 15.0,
        height: 15.0,
    },
    ShadowPlane {
        name: "right tail fin",
        occluder: "shadowTEX2",
        origin: Vec3::new(0.899235, -0.676381, -0.706742),
        normal: Vec3::new(-0.917594, 0.0, 0.397518),
        up: Vec3::new(0.3975177, 0.0, 0.91759448),
        right: Vec3::NEG_Y,
        width: 4.1218186,
        height: 4.1218186,
    },
    ShadowPlane {
        name: "left tail fin",
        occluder: "shadowTEX2",
        origin: Vec3::new(-0.899235, -0.676381, -0.706742),
        normal: Vec3::new(0.917594, 0.0, 0.397518),
        up: Vec3::new(-0.3975177, 0.0, 0.91759448),
        right: Vec3::NEG_Y,
        width: 4.1218186,
        height: 4.1218186,
    },
];

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;
    use std::path::Path;

    fn shader(name: &str) -> &'static str {
        find(name)
            .unwrap_or_else(|| panic!("{name} is embedded"))
            .source
    }

    /// Paths of the files under `dir`, relative to `root`, with `/` separators.
    fn files(root: &Path, dir: &Path, out: &mut BTreeSet<String>) {
        for entry in std::fs::read_dir(dir)
            .expect("shaders/ is readable")
            .flatten()
        {
            let path = entry.path();
            if path.is_dir() {
                files(root, &path, out);
            } else {
                let rel = path.strip_prefix(root).expect("under shaders/");
                let parts: Vec<_> = rel.iter().map(|p| p.to_string_lossy()).collect();
                out.insert(parts.join("/"));
            }
        }
    }

    #[test]
    fn every_file_of_the_shaders_folder_is_embedded_as_it_is() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
        let mut on_disk = BTreeSet::new();
        files(&root, &root, &mut on_disk);
        let listed: BTreeSet<String> = historical().iter().map(|s| s.name.into()).collect();
        assert_eq!(listed, on_disk);
        assert_eq!(listed.len(), historical().len(), "a name is listed twice");
        for s in historical() {
            let text = std::fs::read_to_string(root.join(s.name)).expect("readable");
            assert_eq!(s.source, text, "{}", s.name);
            assert!(s.source.starts_with("#version 330 core\n"), "{}", s.name);
            let stage = match s.name.rsplit('.').next() {
                Some("vert") => Stage::Vertex,
                Some("frag") => Stage::Fragment,
                other => panic!("{}: unknown extension {other:?}", s.name),
            };
            assert_eq!(s.stage, stage, "{}", s.name);
            assert!(
                !s.origin.is_empty() && !s.origin.contains('\n'),
                "{}",
                s.name
            );
        }
    }

    #[test]
    fn find_returns_the_named_shader_only() {
        assert_eq!(
            find("coleman/occluder.frag").map(|s| s.stage),
            Some(Stage::Fragment)
        );
        assert!(find("coleman/occluder").is_none());
        assert!(find("").is_none());
    }

    /// The float literals of every statement of `code` (comments removed) that assigns
    /// `lhs` (`lhs = …` or `type lhs = …`), in source order. A `-` directly before a
    /// literal that follows `(`, `,` or `=` is its sign.
    fn assigned(code: &str, lhs: &str) -> Vec<(String, Vec<f32>)> {
        let code: String = code
            .lines()
            .map(|l| l.split("//").next().unwrap_or(""))
            .collect::<Vec<_>>()
            .join("\n");
        let mut out = Vec::new();
        for statement in code.split(';') {
            let Some((left, right)) = statement.split_once('=') else {
                continue;
            };
            if left.split_whitespace().last() != Some(lhs) {
                continue;
            }
            let b = right.as_bytes();
            let mut numbers = Vec::new();
            let mut i = 0;
            while i < b.len() {
                let starts = b[i].is_ascii_digit()
                    && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'));
                if !starts {
                    i += 1;
                    continue;
                }
                let end = (i..b.len())
                    .find(|&j| !(b[j].is_ascii_digit() || b[j] == b'.'))
                    .unwrap_or(b.len());
                let value: f32 = right[i..end].parse().expect("a float literal");
                let before: String = right[..i].chars().rev().take(3).collect();
                let before = before.trim_start();
                let negative = before.starts_with('-')
                    && before[1..].trim_start().starts_with(['(', ',', '=']);
                numbers.push(if negative { -value } else { value });
                i = end;
            }
            out.push((right.trim().to_string(), numbers));
        }
        out
    }

    fn components(v: Vec3) -> Vec<f32> {
        v.to_array().to_vec()
    }

    #[test]
    fn f35_planes_are_the_numbers_of_the_vertex_shader() {
        let vert = shader("coleman/occluder.vert");
        let [z, right, left] = F35_PLANES;
        let numbers = |lhs: &str| -> Vec<Vec<f32>> {
            assigned(vert, lhs).into_iter().map(|(_, n)| n).collect()
        };
        // The z = 0 plane: sI = -pos.z / light.z, then (intersection - V0) / 15.
        let [(text, n)] = &assigned(vert, "intersection")[..] else {
            panic!("one assignment of intersection");
        };
        assert!(text.contains("(-IN.position.z/lightDirection_model.z)*lightDirection_model.xy"));
        assert_eq!((z.normal, z.right, z.up), (Vec3::Z, Vec3::X, Vec3::Y));
        assert!(n.is_empty());
        assert_eq!(
            numbers("normalizedTexCoord"),
            [vec![-z.origin.x, -z.origin.y, z.width]]
        );
        assert_eq!((z.origin.z, z.width), (0.0, z.height));
        // The fins, right then left.
        assert_eq!(
            numbers("N"),
            [components(right.normal), components(left.normal)]
        );
        assert_eq!(
            numbers("V0"),
            [components(right.origin), components(left.origin)]
        );
        assert_eq!(
            numbers("upVec"),
            [components(right.up), components(left.up)]
        );
        for (k, plane) in [(2, right), (3, left)] {
            assert_eq!(plane.right, Vec3::NEG_Y);
            let [(s, n)] = &assigned(vert, &format!("OUT.texcoord{k}.x"))[..] else {
                panic!("one assignment of texcoord{k}.x");
            };
            assert!(s.starts_with("- distanceVec.y /"), "{s}");
            assert_eq!(n, &[plane.width]);
            let [(t, n)] = &assigned(vert, &format!("OUT.texcoord{k}.y"))[..] else {
                panic!("one assignment of texcoord{k}.y");
            };
            assert!(t.starts_with("dot( distanceVec, upVec ) /"), "{t}");
            assert_eq!(n, &[plane.height]);
        }
    }

    #[test]
    fn each_plane_is_looked_up_in_its_occluder_with_its_texture_coordinate() {
        let frag = shader("coleman/occluder.frag");
        for (i, plane) in F35_PLANES.iter().enumerate() {
            let lookup = format!("texture( {}, clamp(IN.texcoord{}.xy", plane.occluder, i + 1);
            assert!(frag.contains(&lookup), "{}: {lookup}", plane.name);
            assert!(frag.contains(&format!("uniform sampler2D {};", plane.occluder)));
        }
    }

    /// The appendix's 6-8 digit constants are orthonormal to within 1e-5.
    #[test]
    fn f35_plane_axes_are_orthonormal() {
        for p in F35_PLANES {
            for v in [p.normal, p.up, p.right] {
                assert!((v.length() - 1.0).abs() < 1e-5, "{}: |{v}|", p.name);
            }
            assert!(p.normal.dot(p.up).abs() < 1e-5, "{}", p.name);
            assert!(p.normal.dot(p.right).abs() < 1e-5, "{}", p.name);
            assert!(p.up.dot(p.right).abs() < 1e-5, "{}", p.name);
            let handed = p.right.cross(p.up).dot(p.normal);
            assert!((handed.abs() - 1.0).abs() < 1e-5, "{}", p.name);
        }
        let [z, right, left] = F35_PLANES;
        assert!(z.right.cross(z.up).dot(z.normal) > 0.0);
        assert!(right.right.cross(right.up).dot(right.normal) > 0.0);
        assert!(left.right.cross(left.up).dot(left.normal) < 0.0, "mirrored");
    }

    #[test]
    fn a_point_on_a_plane_has_its_own_coordinates_and_the_sign_follows_the_light() {
        let light = Vec3::new(0.3, -0.2, 0.9).normalize();
        for p in F35_PLANES {
            let on = p.origin + p.right * (0.25 * p.width) + p.up * (0.75 * p.height);
            let c = p.shadow_coord(on, light);
            assert!(
                (c.st - Vec2::new(0.25, 0.75)).abs().max_element() < 1e-5,
                "{c:?}"
            );
            // Not quite 0: up · n is 5e-7 for the fins, and n · L is small for this light.
            assert!(c.s_i.abs() < 1e-4, "{}: {c:?}", p.name);
            // One metre off the plane on the side the light is not on: the plane is
            // between, and the ray meets it where it leaves `on` along the light.
            let side = -p.normal.dot(light).signum();
            let behind = p.shadow_coord(on + p.normal * side, light);
            assert!(behind.plane_between(), "{}: {behind:?}", p.name);
            let ahead = p.shadow_coord(on - p.normal * side, light);
            assert!(!ahead.plane_between(), "{}: {ahead:?}", p.name);
            let q = on + p.normal * side + light * behind.s_i;
            assert!(p.normal.dot(q - p.origin).abs() < 1e-5, "{}", p.name);
        }
    }
}
