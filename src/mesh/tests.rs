use super::*;
use glam::{Mat4, Vec3};
use std::path::Path;

/// Every triangle's geometric normal agrees with its vertices' normals (winding is CCW
/// seen from the side the normals point to).
fn windings_agree(mesh: &Mesh) -> bool {
    mesh.triangles.iter().all(|t| {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let face = (b - a).cross(c - a);
        let n: Vec3 = t.iter().map(|&i| mesh.normals[i as usize]).sum();
        face.dot(n) > 0.0
    })
}

#[test]
fn triangle_counts() {
    let cases: [(&str, Mesh, usize); 5] = [
        ("plane 1", plane(2.0, 1), 2),
        ("plane 8", plane(2.0, 8), 128),
        ("box", cuboid(Vec3::ONE), 12),
        ("sphere 16x8", sphere(1.0, 16, 8), 2 * 16 * 7),
        ("torus 24x12", torus(1.0, 0.3, 24, 12), 2 * 24 * 12),
    ];
    for (name, mesh, expected) in cases {
        assert_eq!(mesh.triangle_count(), expected, "{name}");
        assert_eq!(mesh.positions.len(), mesh.normals.len(), "{name}");
        assert!(
            windings_agree(&mesh),
            "{name}: winding disagrees with normals"
        );
    }
}

#[test]
fn closed_surfaces() {
    for (name, mesh) in [
        ("box", cuboid(Vec3::new(1.0, 2.0, 3.0))),
        ("sphere", sphere(1.0, 12, 6)),
        ("sphere coarse", sphere(2.0, 3, 2)),
        ("torus", torus(1.0, 0.25, 16, 8)),
        ("aircraft", aircraft(4.0)),
    ] {
        assert!(mesh.is_closed(), "{name} is not closed");
    }
    assert!(!plane(1.0, 4).is_closed(), "a plane has a border");
}

#[test]
fn zero_tessellation_is_raised_not_a_panic() {
    assert_eq!(plane(1.0, 0).triangle_count(), 2);
    assert_eq!(sphere(1.0, 0, 0).triangle_count(), 2 * 3);
    assert_eq!(torus(1.0, 0.1, 0, 0).triangle_count(), 18);
    assert!(teapot(1.0, 0).triangle_count() > 0);
}

#[test]
fn teapot_is_tessellated_from_32_patches() {
    let n = 6;
    let mesh = teapot(1.0, n);
    let all = 32 * 2 * (n * n) as usize;
    // Pole rows of the lid knob (4 patches, 2 poles each) and the bottom (4 patches) collapse.
    assert!(mesh.triangle_count() < all && mesh.triangle_count() > all - 12 * n as usize * 2);
    let (lo, hi) = mesh.bounds().expect("not empty");
    assert!(
        (hi.y - 3.15).abs() < 1e-4 && lo.y.abs() < 1e-4,
        "height {lo} {hi}"
    );
    assert!(
        (lo.x + 3.0).abs() < 0.05 && (hi.x - 3.4).abs() < 0.1,
        "handle to spout {lo} {hi}"
    );
    // Welded: the body's quadrant seams share vertices, so most edges have two triangles.
    assert!(mesh.normals.iter().all(|n| n.is_finite()));
    // Outward: the body's triangles face away from the axis.
    let outward = mesh
        .triangles
        .iter()
        .filter(|t| {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            let centre = (a + b + c) / 3.0;
            let radial = Vec3::new(centre.x, 0.0, centre.z);
            (b - a).cross(c - a).dot(radial) > 0.0
        })
        .count();
    assert!(
        outward * 10 > mesh.triangle_count() * 7,
        "{outward} outward"
    );
}

#[test]
fn transform_moves_positions_and_normals() {
    let m = Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0))
        * Mat4::from_scale(Vec3::new(2.0, 1.0, 1.0));
    let moved = sphere(1.0, 8, 4).transformed(&m);
    assert_eq!(moved.positions[0], Vec3::new(1.0, 3.0, 3.0));
    assert!(windings_agree(&moved));
    let mirrored = cuboid(Vec3::ONE).transformed(&Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0)));
    assert!(windings_agree(&mirrored), "a mirror keeps fronts in front");
}

#[test]
fn drop_degenerate_counts() {
    let mut mesh = Mesh {
        positions: vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::X * 2.0],
        normals: vec![Vec3::Z; 4],
        triangles: vec![[0, 1, 2], [0, 0, 1], [0, 1, 3], [0, 1, 9]],
    };
    assert_eq!(mesh.drop_degenerate(), 3);
    assert_eq!(mesh.triangles, vec![[0, 1, 2]]);
}

const QUAD_NO_NORMALS: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";

#[test]
fn obj_without_normals_gets_computed_ones() {
    let obj = load_obj_str(QUAD_NO_NORMALS, Path::new("quad.obj")).expect("loads");
    assert!(obj.computed_normals);
    assert_eq!(
        obj.mesh.triangles,
        vec![[0, 1, 2], [0, 2, 3]],
        "fan from v0"
    );
    assert!(obj
        .mesh
        .normals
        .iter()
        .all(|n| (*n - Vec3::Z).length() < 1e-6));
}

#[test]
fn obj_with_normals_keeps_them() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0.6 0.8\nf 1//1 2//1 3//1\n";
    let obj = load_obj_str(text, Path::new("tri.obj")).expect("loads");
    assert!(!obj.computed_normals);
    assert!(obj
        .mesh
        .normals
        .iter()
        .all(|n| (*n - Vec3::new(0.0, 0.6, 0.8)).length() < 1e-6));
}

#[test]
fn obj_negative_indices_and_pentagon_fan() {
    let text = "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf -5 -4 -3 -2 -1\n";
    let obj = load_obj_str(text, Path::new("pentagon.obj")).expect("loads");
    assert_eq!(obj.mesh.triangles, vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
    assert_eq!(obj.mesh.positions[4], Vec3::new(-1.0, 1.0, 0.0));
}

/// A crash of the obj fuzz target (`fuzz/run.sh obj`): tobj read the texture index -3,
/// with no texture coordinate above it, as 2⁶⁴ − 3 and overflowed multiplying it; index 0
/// it read as "no normal". Both are now refused at their line.
#[test]
fn obj_face_indices_that_name_nothing_are_refused() {
    let crash = "v 3 0 0\nv 1 0 0\nv 1 1 0\nvn 1 0 -1\nf 1//1 3/-3 -2\nvt 0 0\nf 1 2 3\n";
    let tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
    for (text, line, index, what) in [
        (crash.to_string(), 5, -3, ObjElement::TexCoord),
        (format!("{tri}f 1//1 2//1 3//0\n"), 6, 0, ObjElement::Normal),
        (format!("{tri}f 0 1 2\n"), 6, 0, ObjElement::Position),
        (format!("{tri}f -4 -2 -1\n"), 6, -4, ObjElement::Position),
        (
            format!("{tri}f 1/-2 2/1 3/1\n"),
            6,
            -2,
            ObjElement::TexCoord,
        ),
        (
            format!("{tri}f 1//6148914691236517206 2 3\n"),
            6,
            6148914691236517206,
            ObjElement::Normal,
        ),
    ] {
        match load_obj_str(&text, Path::new("i.obj")) {
            Err(e @ MeshError::BadIndex { .. }) => {
                let MeshError::BadIndex {
                    line: l,
                    index: i,
                    what: w,
                    ..
                } = &e
                else {
                    unreachable!()
                };
                assert_eq!((*l, *i, *w), (line, index, what), "{text}");
                assert!(e.to_string().contains(&format!("line {line}")), "{e}");
            }
            other => panic!("{text}: expected BadIndex, got {other:?}"),
        }
    }
    let fine = format!("{tri}f -3/-1/-1 -2/1/1 3/1/-1\n");
    assert!(load_obj_str(&fine, Path::new("ok.obj")).is_ok());
}

#[test]
fn obj_errors() {
    let none = load_obj_str("v 0 0 0\nv 1 0 0\n", Path::new("points.obj"));
    assert!(
        matches!(none, Err(MeshError::NoFaces { degenerate: 0, .. })),
        "{none:?}"
    );
    let flat = load_obj_str(
        "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n",
        Path::new("flat.obj"),
    );
    assert!(
        matches!(flat, Err(MeshError::NoFaces { degenerate: 1, .. })),
        "{flat:?}"
    );
    let bad = load_obj_str("v 0 0 0\nf 1 2 7\n", Path::new("bad.obj"));
    assert!(matches!(bad, Err(MeshError::Malformed { .. })), "{bad:?}");
    let missing = load_obj(Path::new("/nonexistent/x.obj"));
    assert!(
        matches!(missing, Err(MeshError::Unreadable { .. })),
        "{missing:?}"
    );
    let one_bad = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 2\n";
    let obj = load_obj_str(one_bad, Path::new("one.obj")).expect("loads");
    assert_eq!((obj.mesh.triangle_count(), obj.degenerate), (1, 1));
}

#[test]
fn geometry_is_indexed_triangles_with_w_one() {
    let mesh = sphere(1.0, 8, 4);
    let g = mesh.to_geometry();
    assert_eq!(g.primitive, crate::ff::Primitive::Triangles);
    assert_eq!(g.vertex_count(), 3 * mesh.triangle_count());
    assert!(g.positions.iter().all(|p| p.w == 1.0));
    assert_eq!(g.positions[5].truncate(), mesh.positions[5]);
    assert_eq!(g.normals.as_deref(), Some(&mesh.normals[..]));
    assert_eq!(
        g.indices.as_ref().map(|i| i[3..6].to_vec()),
        Some(mesh.triangles[1].to_vec())
    );
    assert!(g.validate().is_ok());
}
