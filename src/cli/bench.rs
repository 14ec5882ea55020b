//! `fixedfunc bench`: repeated timings with medians, a progress bar while they run.

use fixedfunc::bench::abi::{self, AbiError, AbiMode, AbiRow, Heap, Span, Verdict};
use fixedfunc::bench::coleman::{ColemanRow, Entrant, INSTANCES};
use fixedfunc::bench::pipeline::BenchError;
use fixedfunc::bench::{context, pipeline, BenchGroup};
use fixedfunc::gpu::{Backend, Profile, VirtualDisplay};
use fixedfunc::vocab::{Named, Submission};
use std::io::IsTerminal;

use indicatif::ProgressBar;

use super::progress::CountBar;

use super::error::CliError;

/// The most repetitions `--repeats` takes. A median of 1000 runs moves by less than the
/// machine's own noise when more are added, so more would only lengthen the run, without
/// a word: each repeat renders every technique on both paths (the techniques group),
/// creates every backend's contexts (context), ray-casts the default scene and a million
/// triangles (truth) and runs a C program ten times (abi).
pub const MAX_REPEATS: usize = 1000;

/// `--repeats N`: 1 to [`MAX_REPEATS`]. Zero is refused rather than run once.
pub fn parse_repeats(text: &str) -> Result<usize, String> {
    let n: usize = text
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a whole number"))?;
    match n {
        0 => Err("0 repeats measure nothing: give 1 or more".to_string()),
        n if n > MAX_REPEATS => Err(format!(
            "at most {MAX_REPEATS} repeats: a median of {MAX_REPEATS} runs is already as \
             steady as the machine, and more would only make the run longer"
        )),
        n => Ok(n),
    }
}

pub fn run(only: Option<BenchGroup>, repeats: usize, json: bool) -> Result<(), CliError> {
    let groups: Vec<BenchGroup> = only.map_or(BenchGroup::ALL.to_vec(), |g| vec![g]);
    for group in groups {
        match group {
            BenchGroup::Context => run_context(repeats, json)?,
            BenchGroup::Pipeline => run_pipeline(repeats, json)?,
            BenchGroup::Truth => run_truth(repeats, json)?,
            BenchGroup::Techniques => run_techniques(repeats, json)?,
            BenchGroup::Abi => run_abi(repeats, json, only.is_none())?,
            BenchGroup::Coleman => run_coleman(repeats, json)?,
            BenchGroup::Soft => run_soft(repeats, json)?,
        }
    }
    Ok(())
}

fn run_context(repeats: usize, json: bool) -> Result<(), CliError> {
    let display = VirtualDisplay::start_if_needed();
    let mut backends = vec![Backend::Egl, Backend::OsMesa];
    match &display {
        Ok(_) => backends.push(Backend::Window),
        Err(e) => eprintln!("window backend skipped: {e}"),
    }
    let total = (backends.len() * Profile::ALL.len() * repeats.max(1)) as u64;
    let mut bar = CountBar::new("bench context", total, "contexts");
    let mut rows = Vec::new();
    for &backend in &backends {
        for profile in Profile::ALL {
            bar.set_what(format!("{backend} {}", profile.name()));
            match context::measure(backend, profile, repeats, || bar.inc()) {
                Ok(row) => rows.push(row),
                Err(e) => bar.println(&format!("{backend} {}: {e}", profile.name())),
            }
        }
    }
    bar.finish();
    if json {
        outln!("{}", serde_json::to_string_pretty(&rows)?)?;
        return Ok(());
    }
    outln!(
        "context: {} repeats each; milliseconds, median [min–max]",
        repeats.max(1)
    )?;
    outln!(
        "{:<8} {:<14} {:>26} {:>26}",
        "backend",
        "profile",
        "create",
        "first read-back frame"
    )?;
    for r in &rows {
        let fmt =
            |s: &fixedfunc::stats::Summary| format!("{:.2} [{:.2}–{:.2}]", s.median, s.min, s.max);
        outln!(
            "{:<8} {:<14} {:>26} {:>26}",
            r.backend.name(),
            r.profile.name(),
            fmt(&r.create_ms),
            fmt(&r.first_frame_ms)
        )?;
    }
    Ok(())
}

fn run_pipeline(frames: usize, json: bool) -> Result<(), CliError> {
    let frames = frames.max(2);
    let mut bar = CountBar::new("bench pipeline", 2 * frames as u64, "frames");
    bar.set_what("emulate vs native".into());
    let rows = pipeline::measure(Backend::Egl, frames, || bar.inc())?;
    bar.finish();
    if json {
        outln!("{}", serde_json::to_string_pretty(&rows)?)?;
        return Ok(());
    }
    outln!(
        "pipeline: one frame of the default scene (none), {frames} frames each, interleaved; \
         medians of frames 2..N [min–max]"
    )?;
    outln!(
        "{:<8} {:>24} {:>26} {:>9} {:>12} {:>12}",
        "path",
        "frame ms",
        "submit µs per draw",
        "programs",
        "after frame1",
        "sent/skipped"
    )?;
    for r in &rows {
        let fmt = |s: &fixedfunc::stats::Summary, d: usize| {
            format!("{:.d$} [{:.d$}–{:.d$}]", s.median, s.min, s.max)
        };
        outln!(
            "{:<8} {:>24} {:>26} {:>9} {:>12} {:>12}",
            format!("{:?}", r.pipeline).to_lowercase(),
            fmt(&r.frame_ms, 2),
            fmt(&r.submit_us_per_draw, 1),
            r.programs_compiled,
            r.programs_after_first_frame,
            format!(
                "{}/{}",
                r.counters.state_calls_sent, r.counters.state_calls_skipped
            )
        )?;
    }
    if let [e, n] = rows.as_slice() {
        outln!(
            "emulated / native frame time: {:.2}×",
            e.frame_ms.median / n.frame_ms.median
        )?;
    }
    Ok(())
}

fn run_truth(runs: usize, json: bool) -> Result<(), CliError> {
    use fixedfunc::scene::Scene;
    use fixedfunc::truth::{bench, TruthOptions};
    let runs = runs.clamp(1, 1000) as u32;
    let spinner = ProgressBar::new_spinner();
    // Off a terminal the spinner draws nothing: each part is announced on its own line.
    let say = |what: &str| {
        if std::io::stderr().is_terminal() {
            spinner.set_message(what.to_string());
        } else {
            eprintln!("bench truth: {what} ({runs} runs)");
        }
    };
    say("ray casting the default scene");
    spinner.enable_steady_tick(std::time::Duration::from_millis(100));
    let default = bench::throughput(&Scene::default_scene(), &TruthOptions::default(), runs)?;
    say("ray casting ~1M triangles");
    let million = bench::throughput(
        &bench::million_triangle_scene(),
        &TruthOptions::default(),
        runs,
    )?;
    spinner.finish_and_clear();
    let rows = [("default", default), ("~1M triangles", million)];
    if json {
        let v: Vec<_> = rows
            .iter()
            .map(|(n, t)| serde_json::json!({ "scene": n, "result": t }))
            .collect();
        outln!("{}", serde_json::to_string_pretty(&v)?)?;
        return Ok(());
    }
    outln!(
        "truth: median run of {runs}, {} threads",
        rayon::current_num_threads()
    )?;
    outln!(
        "{:<15} {:>10} {:>10} {:>12} {:>16} {:>16} {:>10}",
        "scene",
        "size",
        "triangles",
        "BVH ms",
        "primary rays/s",
        "shadow rays/s",
        "total ms"
    )?;
    for (name, t) in &rows {
        outln!(
            "{:<15} {:>10} {:>10} {:>12.1} {:>14.1} M {:>14.1} M {:>10.1}",
            name,
            format!("{}x{}", t.width, t.height),
            t.triangles,
            t.build_ms,
            t.primary_rays_per_s / 1e6,
            t.shadow_rays_per_s / 1e6,
            t.total_ms
        )?;
    }
    Ok(())
}

fn run_coleman(repeats: usize, json: bool) -> Result<(), CliError> {
    use fixedfunc::bench::coleman::{self, ENTRANTS, SCALES, SPREAD, SUBMISSIONS, SUBMITTED};
    let frames = repeats.max(1) as u64 + 1;
    let rounds = (SCALES.len() + INSTANCES.len()) as u64 * frames;
    let mut bar = CountBar::new("bench coleman", rounds, "rounds");
    bar.set_what("fleets of F-35s, interleaved".into());
    let (rows, mut skipped) = coleman::measure(repeats, || bar.inc())?;
    bar.set_what("immediate mode, display lists, buffers".into());
    let (submissions, also) = coleman::measure_submissions(repeats, &INSTANCES, || bar.inc())?;
    skipped.extend(also);
    bar.finish();
    if json {
        let value = serde_json::json!({
            "rows": rows,
            "submissions": submissions,
            "skipped": skipped,
        });
        outln!("{}", serde_json::to_string_pretty(&value)?)?;
        return Ok(());
    }
    outln!(
        "coleman: assets/f35.toml with {INSTANCES:?} aircraft over ±{SPREAD} m (seed {}), emulate, 512², maps each frame; {} steady frames, interleaved per scale; ms median [min–max]",
        coleman::SEED,
        repeats.max(1)
    )?;
    let columns: Vec<_> = ENTRANTS.iter().map(|e| (e.label(), *e, None)).collect();
    coleman_table(&rows, &columns, &SCALES)?;
    outln!()?;
    outln!(
        "coleman, his CPU-limit test: the ×1 fleets with the objects submitted in immediate mode (glBegin/glNormal3f/glVertex3f/glEnd), display lists (compiled once, glCallList) and buffers, through the C library's front; interleaved per fleet; ms median [min–max]"
    )?;
    let columns: Vec<_> = SUBMITTED
        .iter()
        .flat_map(|e| SUBMISSIONS.map(|s| (format!("{} {s}", e.label()), *e, Some(s))))
        .collect();
    coleman_table(&submissions, &columns, &[1.0])?;
    for s in &skipped {
        outln!(
            "skipped: {}{} ({}) with {} aircraft at ×{}: {}",
            s.technique,
            s.program.map(|p| format!("/{p}")).unwrap_or_default(),
            s.submission,
            s.instances,
            s.scale,
            s.reason
        )?;
    }
    Ok(())
}

/// One table of `bench --only coleman`: a line per scale and fleet, a cell per column (its
/// label, its entrant and, for the CPU-limit test, its submission).
fn coleman_table(
    rows: &[ColemanRow],
    columns: &[(String, Entrant, Option<Submission>)],
    scales: &[f32],
) -> Result<(), CliError> {
    let widths: Vec<usize> = columns
        .iter()
        .map(|(label, ..)| label.chars().count().max(30))
        .collect();
    let mut header = format!("{:<7} {:>9} {:>10}", "scale", "aircraft", "triangles");
    for ((label, ..), w) in columns.iter().zip(&widths) {
        header.push_str(&format!(" {label:>w$}"));
    }
    outln!("{header}")?;
    for &scale in scales {
        for instances in INSTANCES {
            let at = |r: &&ColemanRow| r.instances == instances && r.scale == scale;
            let mut line = format!(
                "×{scale:<6} {instances:>9} {:>10}",
                rows.iter().find(at).map_or(0, |r| r.triangles)
            );
            for ((_, e, s), w) in columns.iter().zip(&widths) {
                let cell = rows
                    .iter()
                    .filter(at)
                    .find(|r| {
                        r.technique == e.technique
                            && r.program == e.program.map(|p| p.name())
                            && s.is_none_or(|s| r.submission == s)
                    })
                    .map_or("—".to_string(), |r| {
                        format!(
                            "{:.2} [{:.2}–{:.2}]",
                            r.frame.median, r.frame.min, r.frame.max
                        )
                    });
                line.push_str(&format!(" {cell:>w$}"));
            }
            outln!("{line}")?;
        }
    }
    Ok(())
}

/// `bench --only soft`: one table per axis (`bench::soft`), skipped configurations in
/// their axis's table with the reason.
fn run_soft(repeats: usize, json: bool) -> Result<(), CliError> {
    use fixedfunc::bench::soft::{self, Axis, SceneId, Step};
    let entries = soft::plan();
    let mut bar = CountBar::new("bench soft", soft::steps(&entries, repeats), "steps");
    bar.set_what("ray-casting the first scene's truth".into());
    let frames = repeats.max(1) + 1;
    let measured = soft::measure(&entries, soft::IMAGE, repeats, |step| {
        bar.set_what(match step {
            Step::Truth { scene } => format!("{}: truth ray-cast", scene_label(scene)),
            Step::Round { scene, round } => {
                format!("{}: frame {round}/{frames} of each", scene_label(scene))
            }
        });
        bar.inc();
    });
    bar.finish();
    let (rows, skipped) = measured.map_err(soft_error)?;
    if json {
        let value = serde_json::json!({ "rows": rows, "skipped": skipped });
        outln!("{}", serde_json::to_string_pretty(&value)?)?;
        return Ok(());
    }
    outln!(
        "soft: Eisemann & Décoret's claims; emulate, {0}² image, maps remade each frame; {1} \
         steady frames after a cold one, interleaved per scene; ms median [min–max]; \
         visibility against the scene's truth (stratified, ray-cast once per scene): RMSE \
         over geometry pixels, over the penumbra (truth strictly between 0 and 1), max |d|",
        soft::IMAGE,
        repeats.max(1)
    )?;
    for axis in Axis::ALL {
        outln!()?;
        outln!("{}", axis.title())?;
        outln!(
            "{:<22} {:<19} {:<34} {:>9} {:>24} {:>8} {:>7} {:>9} {:>6}",
            "scene",
            "technique",
            "setting",
            "triangles",
            "frame ms",
            "cold ms",
            "RMSE",
            "penumbra",
            "max|d|"
        )?;
        for r in rows.iter().filter(|r| r.axis == axis) {
            let v = &r.visibility;
            outln!(
                "{:<22} {:<19} {:<34} {:>9} {:>24} {:>8.1} {:>7.4} {:>9} {:>6.3}",
                scene_label(r.scene),
                r.technique,
                r.setting.label(),
                r.triangles,
                format!(
                    "{:.2} [{:.2}–{:.2}]",
                    r.frame.median, r.frame.min, r.frame.max
                ),
                r.cold_ms,
                v.rmse,
                v.penumbra_rmse
                    .map_or("—".to_string(), |p| format!("{p:.4}")),
                v.max_abs
            )?;
        }
        for s in skipped.iter().filter(|s| s.axis == axis) {
            outln!(
                "{:<22} {:<19} {:<34} skipped: {}",
                scene_label(s.scene),
                s.technique,
                s.setting.label(),
                s.reason
            )?;
        }
        if axis == Axis::Geometry {
            // Cost growth with the geometry: the most copies' steady frame over one copy's.
            let (few, many) = (soft::COPIES[0], soft::COPIES[soft::COPIES.len() - 1]);
            let of = |copies, setting| {
                rows.iter().find(|r| {
                    r.axis == axis && r.scene == SceneId::Scaling { copies } && r.setting == setting
                })
            };
            for r in rows
                .iter()
                .filter(|r| r.axis == axis && r.scene == SceneId::Scaling { copies: few })
            {
                if let (Some(a), Some(b)) = (of(few, r.setting), of(many, r.setting)) {
                    outln!(
                        "{} {}: {many} copies / {few} copy = {:.2}× the frame time for {:.0}× \
                         the triangles",
                        r.technique,
                        r.setting.label(),
                        b.frame.median / a.frame.median,
                        b.triangles as f64 / a.triangles.max(1) as f64
                    )?;
                }
            }
        }
    }
    Ok(())
}

/// A scene as the soft tables name it: its file, and the light's scale when not 1.
fn scene_label(scene: fixedfunc::bench::soft::SceneId) -> String {
    use fixedfunc::bench::soft::SceneId;
    let file = scene.file();
    let file = file.trim_start_matches("assets/");
    match scene {
        SceneId::Soft { light_scale } if light_scale != 1.0 => {
            format!("{file} light ×{light_scale}")
        }
        _ => file.to_string(),
    }
}

/// The soft group's failures as the CLI reports them. A scene or truth error keeps its
/// own variant; `NotAreaLight` and `NoScalingScene` name embedded scenes, which the
/// group's unit tests check, so they are reached only from a broken build.
fn soft_error(e: fixedfunc::bench::soft::SoftError) -> CliError {
    use fixedfunc::bench::soft::SoftError;
    match e {
        SoftError::Scene { source, .. } => CliError::Scene(*source),
        SoftError::Truth { source, .. } => CliError::Truth(source),
        e @ (SoftError::NotAreaLight { .. } | SoftError::NoScalingScene { .. }) => {
            CliError::Usage(format!("bench soft: {e}"))
        }
    }
}

fn run_techniques(repeats: usize, json: bool) -> Result<(), CliError> {
    let mut bar = CountBar::new("bench techniques", repeats.max(1) as u64 + 1, "rounds");
    bar.set_what("interleaved frames".into());
    let (rows, skipped) =
        fixedfunc::bench::techniques::measure(repeats, || bar.inc()).map_err(CliError::from)?;
    bar.finish();
    if json {
        let value = serde_json::json!({ "rows": rows, "skipped": skipped });
        outln!("{}", serde_json::to_string_pretty(&value)?)?;
        return Ok(());
    }
    outln!(
        "techniques: default scene, 512² image, 512² map; {} steady frames, interleaved; ms median [min–max]; the split from frames that make their maps; `static`: the steady frame when maps are made once",
        repeats.max(1)
    )?;
    outln!(
        "{:<22} {:<8} {:>8} {:>22} {:>7} {:>9} {:>7} {:>7} {:>8} {:>7} {:>6} {:>8}",
        "technique",
        "path",
        "cold",
        "frame (maps each)",
        "light",
        "read+load",
        "eye",
        "static",
        "emu/nat",
        "×none",
        "passes",
        "programs"
    )?;
    let opt = |s: Option<fixedfunc::stats::Summary>| {
        s.map_or("—".to_string(), |s| format!("{:.2}", s.median))
    };
    let ratio = |v: Option<f64>| v.map_or("—".to_string(), |v| format!("{v:.2}"));
    for r in &rows {
        outln!(
            "{:<22} {:<8} {:>8.2} {:>22} {:>7} {:>9} {:>7.2} {:>7} {:>8} {:>7} {:>6} {:>8}",
            r.technique,
            fixedfunc::render::pipeline_name(r.pipeline),
            r.cold_ms,
            format!(
                "{:.2} [{:.2}–{:.2}]",
                r.frame.median, r.frame.min, r.frame.max
            ),
            opt(r.light),
            opt(r.readback_upload),
            r.eye.median,
            opt(r.static_frame),
            ratio(r.emulate_vs_native),
            ratio(r.vs_none),
            r.passes,
            r.programs
        )?;
    }
    for s in &skipped {
        outln!(
            "skipped: {} on {}: {}",
            s.technique,
            fixedfunc::render::pipeline_name(s.pipeline),
            s.reason
        )?;
    }
    Ok(())
}

/// `bench --only abi`. Run with the other groups (no `--only`), a machine without the C
/// compiler, Mesa's OSMesa or the layer's library skips the group and says why; asked for
/// alone, that is an error.
fn run_abi(repeats: usize, json: bool, among_all: bool) -> Result<(), CliError> {
    match measure_abi(repeats) {
        Ok(rows) => print_abi(&rows, repeats, json),
        Err(
            e @ (AbiError::CompilerMissing { .. }
            | AbiError::HeaderMissing { .. }
            | AbiError::MesaMissing { .. }
            | AbiError::LibraryMissing { .. }),
        ) if among_all => {
            eprintln!("bench abi skipped: {e}");
            Ok(())
        }
        Err(e) => Err(BenchError::from(e).into()),
    }
}

fn measure_abi(repeats: usize) -> Result<Vec<AbiRow>, AbiError> {
    let folder = fixedfunc_folder().map_err(|e| AbiError::Io {
        what: "the C library's folder".into(),
        reason: e.to_string(),
    })?;
    let libraries = abi::Libraries {
        fixedfunc_dir: folder,
    };
    let cases = abi::cases(&AbiMode::all(), &Heap::ALL, &Span::ALL);
    let total = abi::run_count(&cases, repeats) as u64;
    let mut bar = CountBar::new("bench abi", total, "runs");
    bar.set_what("compiling abi_bench.c".into());
    let program = abi::Program::compile()?;
    let rows = abi::measure(
        &program,
        &libraries,
        &cases,
        repeats,
        |mode, heap, span, library| {
            bar.set_what(format!("{mode} ({heap} heap, {span}) on {library}"));
            bar.inc();
        },
    );
    bar.finish();
    rows
}

/// The folder `fixedfunc osmesa-dir` prints, beside this binary.
fn fixedfunc_folder() -> Result<std::path::PathBuf, CliError> {
    let exe = std::env::current_exe().map_err(|e| CliError::Osmesa(e.to_string()))?;
    let dir = exe
        .parent()
        .ok_or_else(|| CliError::Osmesa("the binary has no folder".into()))?;
    super::osmesa_dir::osmesa_folder(dir)
}

fn print_abi(rows: &[AbiRow], repeats: usize, json: bool) -> Result<(), CliError> {
    if json {
        outln!("{}", serde_json::to_string_pretty(rows)?)?;
        return Ok(());
    }
    outln!(
        "abi: benches/c/abi_bench.c (256×256 RGBA, 24 depth, 8 stencil) on Mesa's \
         libOSMesa.so.8 and on fixedfunc's, runs interleaved; per run its median frame; \
         medians [min–max] over the runs; paired = each repeat's fixedfunc run over the Mesa \
         run just before it"
    )?;
    outln!(
        "span: early = {} runs each of {} frames after {} (a short render); settled = {} \
         runs each of {} frames after {}, untrimmed heap only (a long render, once the \
         kernel has settled where llvmpipe's threads run)",
        Span::Early.repeats(repeats),
        abi::STEADY_FRAMES,
        abi::WARMUP_FRAMES,
        Span::Settled.repeats(repeats),
        abi::SETTLED_FRAMES,
        abi::SETTLING_FRAMES
    )?;
    outln!(
        "heap: glibc = the process's own settings (what a program gets); untrimmed = \
         GLIBC_TUNABLES=glibc.malloc.trim_threshold={} for both libraries, so that freeing \
         llvmpipe's scene at each clear gives no pages back to fault in again (the two \
         libraries' own work alone)",
        abi::UNTRIMMED_THRESHOLD
    )?;
    if let Some(r) = rows.first() {
        outln!(
            "Mesa: {} · fixedfunc: {}",
            r.mesa.renderer,
            r.fixedfunc.renderer
        )?;
    }
    outln!(
        "{:<10} {:<9} {:<7} {:>7} {:>5} {:>22} {:>22} {:>10} {:>18} {:>7} {:>15} {:>15} {:>9} {:>9}",
        "mode",
        "heap",
        "span",
        "verts",
        "draws",
        "Mesa frame ms",
        "fixedfunc frame ms",
        "ours/Mesa",
        "paired",
        "target",
        "Mesa Mvert/s",
        "ours Mvert/s",
        "Mesa dr/s",
        "ours dr/s"
    )?;
    let range =
        |s: &fixedfunc::stats::Summary| format!("{:.2} [{:.2}–{:.2}]", s.median, s.min, s.max);
    for r in rows {
        let target = match (r.target, r.verdict) {
            (Some(t), Verdict::Met) => format!("≤{t:.1} ✓"),
            (Some(t), _) => format!("≤{t:.1} ✗"),
            (None, _) => "—".to_string(),
        };
        outln!(
            "{:<10} {:<9} {:<7} {:>7} {:>5} {:>22} {:>22} {:>9.2}× {:>18} {:>7} {:>15.1} {:>15.1} {:>9.0} {:>9.0}",
            r.mode.name(),
            r.heap,
            r.span,
            r.vertices_per_frame,
            r.draws_per_frame,
            range(&r.mesa.frame_ms),
            range(&r.fixedfunc.frame_ms),
            r.ratio,
            range(&r.paired),
            target,
            r.mesa.mvertices_per_s.median,
            r.fixedfunc.mvertices_per_s.median,
            r.mesa.draws_per_s.median,
            r.fixedfunc.draws_per_s.median
        )?;
    }
    Ok(())
}
