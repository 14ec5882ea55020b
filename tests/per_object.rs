//! The per-object error split (`metrics::per_object`, causes from `truth::shadow_causes`)
//! on real renders: every object that shows gets its line, the objects' counts add up to
//! the render's totals exactly, and a receiver that cannot shadow itself (the ground
//! plane) has no self-shadow while the shadow cast on it is counted as from others.
//! `compare` writes the same split for each of its rows (`results.json`, `objects.csv`).

use std::path::Path;
use std::process::Command;

use fixedfunc::render::{render, ImageSize, RenderOptions};
use fixedfunc::scene::Scene;
use fixedfunc::vocab::{PipelineKind, TechniqueId};

#[test]
fn objects_add_up_to_the_render_totals() {
    let scene = Scene::default_scene();
    for technique in [TechniqueId::DepthCompare, TechniqueId::Projective] {
        let options = RenderOptions {
            pipeline: PipelineKind::Emulate,
            technique: Some(technique),
            size: Some(ImageSize {
                width: 192,
                height: 144,
            }),
            frames: 1,
            ..RenderOptions::default()
        };
        let outcome = render(&scene, &options).unwrap_or_else(|e| panic!("{technique}: {e}"));
        let names: Vec<String> = outcome
            .objects
            .iter()
            .map(|e| fixedfunc::render::object_name(&scene, e.object))
            .collect();
        assert_eq!(names, ["ground", "sphere", "torus"], "{technique}");
        let wrong: u64 = outcome
            .objects
            .iter()
            .map(|e| e.lit.wrong + e.self_shadow().wrong + e.other_occluder.wrong)
            .sum();
        let pixels: u64 = outcome.objects.iter().map(|e| e.pixels()).sum();
        let all = outcome.metrics.all;
        assert_eq!((wrong, pixels), (all.wrong, all.pixels), "{technique}");
        let ground = &outcome.objects[0];
        assert_eq!(ground.self_shadow().pixels, 0, "{technique}");
        assert!(
            ground.other_occluder.pixels > 100,
            "{technique}: {ground:?}"
        );
        // The sphere's unlit half: attached shadow, its own.
        assert!(outcome.objects[1].faces_away.pixels > 50, "{technique}");
    }
}

/// A JSON count.
fn n(v: &serde_json::Value) -> u64 {
    v.as_u64().unwrap_or_else(|| panic!("not a count: {v}"))
}

#[test]
fn compare_writes_each_rows_split_and_it_adds_up_to_the_rows_figures() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("report");
    let scene_path = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/f35.toml");
    let run = Command::new(env!("CARGO_BIN_EXE_fixedfunc"))
        .args([
            "compare",
            scene_path,
            "--techniques",
            "occluder-planes,depth-compare",
        ])
        .args([
            "--pipeline",
            "emulate",
            "--size",
            "128x128",
            "--frames",
            "1",
            "--out",
        ])
        .arg(&out)
        .output()
        .expect("run fixedfunc");
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(stdout.contains("error by object"), "{stdout}");

    let json: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(out.join("results.json")).expect("results.json"),
    )
    .expect("valid JSON");
    let rows = json["rows"].as_array().expect("rows");
    assert_eq!(rows.len(), 2);
    // (technique, object) → (self-shadow, from others, lit) as (wrong, of).
    let mut split = Vec::new();
    for row in rows {
        let technique = row["technique"].as_str().expect("technique").to_string();
        let m = &row["measured"];
        let objects = m["objects"].as_array().expect("measured rows have objects");
        let names: Vec<&str> = objects.iter().filter_map(|o| o["name"].as_str()).collect();
        assert_eq!(names, ["ground", "f35"], "{technique}");
        let share = |o: &serde_json::Value, k: &str| (n(&o[k]["wrong"]), n(&o[k]["of"]));
        let (mut wrong, mut pixels) = (0, 0);
        for o in objects {
            let parts = [
                share(o, "self_shadow"),
                share(o, "from_others"),
                share(o, "lit"),
            ];
            wrong += parts.iter().map(|p| p.0).sum::<u64>();
            pixels += parts.iter().map(|p| p.1).sum::<u64>();
            let (away, own) = (share(o, "facing_away"), share(o, "own_occluder"));
            assert_eq!(parts[0], (away.0 + own.0, away.1 + own.1), "{technique}");
            split.push((technique.clone(), o["name"].clone(), parts));
        }
        let total = n(&m["false_shadow"]) + n(&m["missed_shadow"]) + n(&m["coverage"]);
        assert!(
            total > 0,
            "{technique}: a row without errors proves nothing"
        );
        assert_eq!(
            (wrong, pixels),
            (total, n(&m["geometry_pixels"])),
            "{technique}"
        );
        // The ground shadows nothing of its own; the aircraft shadows itself and the
        // ground.
        assert_eq!(share(&objects[0], "self_shadow").1, 0, "{technique}");
        assert!(share(&objects[0], "from_others").1 > 0, "{technique}");
        assert!(share(&objects[1], "own_occluder").1 > 0, "{technique}");
    }

    // objects.csv: the same counts, one line per row × object.
    let csv = std::fs::read_to_string(out.join("objects.csv")).expect("objects.csv");
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    let col = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("{name} in {header:?}"))
    };
    let lines: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(lines.len(), split.len(), "{csv}");
    for (l, (technique, name, parts)) in lines.iter().zip(&split) {
        assert_eq!(l[col("technique")], technique);
        assert_eq!(Some(l[col("object")]), name.as_str());
        let num = |k: &str| {
            l[col(k)]
                .parse::<u64>()
                .unwrap_or_else(|e| panic!("{k}: {e}"))
        };
        let got = [
            (num("self_shadow_wrong"), num("self_shadow_pixels")),
            (num("from_others_wrong"), num("from_others_pixels")),
            (num("lit_wrong"), num("lit_pixels")),
        ];
        assert_eq!(&got, parts, "{technique} {name}");
        // No pixels of a kind: no percent (empty), not 0 %.
        assert_eq!(l[col("self_shadow_percent")].is_empty(), parts[0].1 == 0);
    }

    let page = std::fs::read_to_string(out.join("report.html")).expect("report.html");
    assert!(page.contains("<h2>Error by object</h2>"));
    assert!(page.contains("href=\"objects.csv\""));

    // The rows' split is render's: the same scene, size and technique alone.
    let scene = Scene::load(Path::new(scene_path)).expect("f35.toml loads");
    let options = RenderOptions {
        pipeline: PipelineKind::Emulate,
        technique: Some(TechniqueId::OccluderPlanes),
        size: Some(ImageSize {
            width: 128,
            height: 128,
        }),
        frames: 1,
        ..RenderOptions::default()
    };
    let outcome = render(&scene, &options).expect("render");
    let rendered: Vec<_> = outcome
        .objects
        .iter()
        .map(|e| {
            let own = e.self_shadow();
            [
                (own.wrong, own.pixels),
                (e.other_occluder.wrong, e.other_occluder.pixels),
                (e.lit.wrong, e.lit.pixels),
            ]
        })
        .collect();
    let compared: Vec<_> = split
        .iter()
        .filter(|(t, _, _)| t == "occluder-planes")
        .map(|(_, _, parts)| *parts)
        .collect();
    assert_eq!(rendered, compared);
}
