//! Ray-caster throughput: the default scene at 512², a ~1M-triangle variant, and the
//! default scene lit by an area light (242 shadow rays per lit pixel).
//! Prints the phase figures of `truth::bench::throughput` (shadow rays/s is the target
//! figure) before criterion times whole truth runs.

use criterion::{criterion_group, criterion_main, Criterion};
use fixedfunc::scene::Scene;
use fixedfunc::truth::{bench, truth, TruthOptions};

fn truth_bench(c: &mut Criterion) {
    let scenes = [
        ("default 512²", Scene::default_scene()),
        ("1M triangles 512²", bench::million_triangle_scene()),
        ("area light 512²", bench::area_light_scene()),
    ];
    let options = TruthOptions::default();
    for (name, scene) in &scenes {
        match bench::throughput(scene, &options, 3) {
            Ok(t) => eprintln!(
                "{name}: {} triangles, build {:.1} ms, {:.2} M primary rays/s, {} shadow rays at {:.2} M/s, total {:.1} ms",
                t.triangles,
                t.build_ms,
                t.primary_rays_per_s / 1e6,
                t.shadow_rays,
                t.shadow_rays_per_s / 1e6,
                t.total_ms
            ),
            Err(e) => eprintln!("{name}: {e}"),
        }
    }
    let mut group = c.benchmark_group("truth");
    group.sample_size(10);
    for (name, scene) in &scenes {
        group.bench_function(*name, |b| b.iter(|| truth(scene, &options)));
    }
    group.finish();
}

criterion_group!(benches, truth_bench);
criterion_main!(benches);
