//! `bench --only abi`: the C library against Mesa's own OSMesa, through one unmodified C
//! program of the era (`benches/c/abi_bench.c`, see [`program`]) that renders a fixed
//! workload per mode — immediate mode, client arrays, display lists, buffer objects, and a
//! depth-texture shadow-map frame — into a 256×256 OSMesa buffer and prints each frame's
//! time (clear … glFinish).
//!
//! Runs are interleaved, Mesa then the layer, mode by mode, repeat by repeat, so that the
//! machine's noise (other builds, frequency steps) hits both alike. A run's figure is the
//! median of its frames after the first few (the first compiles programs and uploads), over
//! a short run and a long one ([`Span`]);
//! a row reports, per library, the median and range of those figures over the repeats, the
//! vertices and draw calls per second they mean, and the layer's median over Mesa's against
//! the target (≤ 1.0× for arrays, lists and buffers, ≤ 2.0× for immediate mode).
//!
//! **The heap.** Both libraries leave llvmpipe to free its binned scene at each clear and
//! allocate it again in the frame's draws; with glibc's default trim threshold (128 KiB,
//! raised only by freed mmapped chunks) the free gives the heap's top back to the kernel and
//! the draws fault it in again, page by page — measured with `perf`, 35–40% of the program's
//! thread on either library. Which allocation happens to lie at the heap's top decides how
//! much is given back, so that share differs from run to run and from library to library
//! and says nothing about either library's own work. Every mode is therefore run twice:
//! under the process's own heap settings ([`Heap::Glibc`], what a program gets) and with
//! trimming off for both libraries ([`Heap::Untrimmed`]), which compares the two
//! libraries' work alone.
//!
//! A fast time counts only from a run that drew the workload: the program exits non-zero
//! on a GL error or an image without it (a shadow frame without shadow), and here the two
//! libraries' last frames must agree within [`IMAGE_AGREEMENT`] of the pixels in what they
//! drew and what lies in shadow.

pub mod output;
pub mod program;

use serde::Serialize;

use crate::stats::Summary;
use crate::vocab::Named;

pub use output::RunOutput;
pub use program::{Libraries, Program};

/// Frames of each early run left out of its median.
pub const WARMUP_FRAMES: u32 = 3;
/// Frames of each early run that count.
pub const STEADY_FRAMES: u32 = 20;
/// Frames of each settled run left out of its median.
pub const SETTLING_FRAMES: u32 = 200;
/// Frames of each settled run that count.
pub const SETTLED_FRAMES: u32 = 200;

/// Which frames of a run its figure comes from.
///
/// llvmpipe draws a frame's bins on its rasterizer threads, and how many CPUs they get at
/// once depends on where the kernel has placed them. Mesa's OSMesa leaves that to the
/// kernel, which on a machine of two CPUs often queues both rasterizers on one CPU for the
/// first hundred or so frames (until its periodic balancing separates them); the layer
/// binds them one per CPU (`gpu::raster_threads`). A short render and a long one therefore
/// compare differently, and both are measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Span {
    /// Frames 4–23 of a 23-frame run: a short render, such as a test suite's.
    Early,
    /// Frames 201–400 of a 400-frame run: a long render, after the kernel has settled
    /// where the threads run. Measured under [`Heap::Untrimmed`] only, with a quarter of
    /// the repeats (rounded up): its runs are 17 times as long.
    Settled,
}

impl Span {
    pub const ALL: [Span; 2] = [Span::Early, Span::Settled];

    /// Frames a run of this span draws.
    pub fn frames(self) -> u32 {
        self.skipped() + self.counted()
    }

    /// Frames at the run's start left out of its median.
    pub fn skipped(self) -> u32 {
        match self {
            Span::Early => WARMUP_FRAMES,
            Span::Settled => SETTLING_FRAMES,
        }
    }

    /// Frames that count.
    pub fn counted(self) -> u32 {
        match self {
            Span::Early => STEADY_FRAMES,
            Span::Settled => SETTLED_FRAMES,
        }
    }

    /// The repeats a span gets when the bench asks for `repeats`.
    pub fn repeats(self, repeats: usize) -> usize {
        match self {
            Span::Early => repeats.max(1),
            Span::Settled => repeats.max(1).div_ceil(4),
        }
    }

    /// Whether this span is measured under `heap`.
    pub fn measured_under(self, heap: Heap) -> bool {
        self == Span::Early || heap == Heap::Untrimmed
    }

    /// The median of a run's counted frames.
    pub fn median(self, run: &RunOutput) -> Option<f64> {
        let counted = run.frame_ms.get(self.skipped() as usize..).unwrap_or(&[]);
        Summary::of(counted).map(|s| s.median)
    }
}

impl std::fmt::Display for Span {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(match self {
            Span::Early => "early",
            Span::Settled => "settled",
        })
    }
}

/// The (mode, heap, span) cases the bench measures for `modes`, `heaps` and `spans`:
/// mode by mode, heap by heap, span by span, where the span is measured under the heap.
pub fn cases(modes: &[AbiMode], heaps: &[Heap], spans: &[Span]) -> Vec<(AbiMode, Heap, Span)> {
    let mut all = Vec::new();
    for &m in modes {
        for &h in heaps {
            for &s in spans.iter().filter(|s| s.measured_under(h)) {
                all.push((m, h, s));
            }
        }
    }
    all
}
/// The program's buffer, in pixels (256×256).
pub const PIXELS: u64 = 256 * 256;
/// How far the two libraries' pixel counts (drawn, dark) may differ, as a fraction of the
/// image: 2%.
pub const IMAGE_AGREEMENT: f64 = 0.02;

/// What a run draws, through which of the era's paths.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum AbiMode {
    /// glBegin/glNormal3fv/glVertex3fv/glEnd.
    Immediate,
    /// Client vertex and normal arrays, glDrawElements.
    Arrays,
    /// A display list compiled from the immediate calls, glCallList.
    Lists,
    /// The arrays in GL 1.5 buffer objects.
    Buffers,
    /// Light pass, glCopyTexImage2D into a compared depth texture, eye pass with texgen.
    Shadow,
}

impl Named for AbiMode {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("immediate", AbiMode::Immediate),
        ("arrays", AbiMode::Arrays),
        ("lists", AbiMode::Lists),
        ("buffers", AbiMode::Buffers),
        ("shadow", AbiMode::Shadow),
    ];
}

impl std::fmt::Display for AbiMode {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl AbiMode {
    /// The largest ratio (the layer's frame over Mesa's) the project aims for, if any.
    pub fn target(self) -> Option<f64> {
        match self {
            AbiMode::Immediate => Some(2.0),
            AbiMode::Arrays | AbiMode::Lists | AbiMode::Buffers => Some(1.0),
            AbiMode::Shadow => None,
        }
    }
}

/// The heap settings a run's process has.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Heap {
    /// glibc's defaults (or whatever `GLIBC_TUNABLES` the bench was given).
    Glibc,
    /// glibc's trim threshold at [`UNTRIMMED_THRESHOLD`]: freeing at the heap's top gives
    /// nothing back to the kernel (`GLIBC_TUNABLES=glibc.malloc.trim_threshold=…`).
    Untrimmed,
}

/// The trim threshold of [`Heap::Untrimmed`]: 64 MiB, the most glibc's own dynamic rule
/// raises it to on 64-bit machines (twice its 32 MiB mmap-threshold ceiling).
pub const UNTRIMMED_THRESHOLD: u64 = 64 << 20;

impl Heap {
    pub const ALL: [Heap; 2] = [Heap::Glibc, Heap::Untrimmed];

    /// The `GLIBC_TUNABLES` a run under these settings gets, given the bench's own
    /// (`None`: the bench's own, unchanged). Tunables are `name=value` pairs joined by `:`;
    /// the last setting of a name wins.
    pub fn tunables(self, inherited: Option<&str>) -> Option<String> {
        match self {
            Heap::Glibc => None,
            Heap::Untrimmed => {
                let trim = format!("glibc.malloc.trim_threshold={UNTRIMMED_THRESHOLD}");
                Some(match inherited.filter(|t| !t.is_empty()) {
                    Some(t) => format!("{t}:{trim}"),
                    None => trim,
                })
            }
        }
    }
}

impl std::fmt::Display for Heap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(match self {
            Heap::Glibc => "glibc",
            Heap::Untrimmed => "untrimmed",
        })
    }
}

/// Which `libOSMesa.so.8` a run loads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Library {
    /// Mesa's own OSMesa (Debian: libosmesa6).
    Mesa,
    /// The layer's C library.
    Fixedfunc,
}

impl std::fmt::Display for Library {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Library::Mesa => "Mesa",
            Library::Fixedfunc => "fixedfunc",
        })
    }
}

/// Whether a row's ratio is within its mode's target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    Met,
    Missed,
    /// The mode has no target.
    None,
}

/// One library's figures for one mode, over the repeats.
#[derive(Clone, Debug, Serialize)]
pub struct LibraryFigures {
    pub library: Library,
    pub vendor: String,
    pub renderer: String,
    /// Each run's median steady frame, ms: their median, min and max.
    pub frame_ms: Summary,
    /// Vertices per second each run's median frame means, in millions.
    pub mvertices_per_s: Summary,
    /// Draw calls per second.
    pub draws_per_s: Summary,
}

/// One mode on both libraries, under one heap setting.
#[derive(Clone, Debug, Serialize)]
pub struct AbiRow {
    pub mode: AbiMode,
    pub heap: Heap,
    pub span: Span,
    pub vertices_per_frame: u64,
    pub draws_per_frame: u64,
    pub mesa: LibraryFigures,
    pub fixedfunc: LibraryFigures,
    /// The layer's median frame / Mesa's.
    pub ratio: f64,
    /// Per repeat, the layer's run over Mesa's run just before it (the two drawn under the
    /// same moment's machine): their median, min and max. On a shared machine whose speed
    /// drifts between runs, the steadier comparison of the two.
    pub paired: Summary,
    pub target: Option<f64>,
    pub verdict: Verdict,
}

/// Why the group could not run; a missing tool or library names its Debian package.
#[derive(Debug, thiserror::Error)]
pub enum AbiError {
    #[error(
        "cannot run the C compiler `{compiler}` ({reason}): install gcc and libosmesa6-dev \
         (apt-get install gcc libosmesa6-dev), or name another compiler in CC"
    )]
    CompilerMissing { compiler: String, reason: String },
    #[error(
        "Mesa's OSMesa header or library is missing: install gcc and libosmesa6-dev (apt-get \
         install gcc libosmesa6-dev; OSMesa is gone from Mesa ≥ 25.1, where this group cannot \
         run):\n{stderr}"
    )]
    HeaderMissing { stderr: String },
    #[error("`{compiler}` failed on abi_bench.c:\n{stderr}")]
    Compile { compiler: String, stderr: String },
    #[error(
        "Mesa's libOSMesa.so.8 cannot be loaded: install libosmesa6 (apt-get install \
         libosmesa6); OSMesa is gone from Mesa ≥ 25.1, so there is nothing to compare \
         against there:\n{stderr}"
    )]
    MesaMissing { stderr: String },
    #[error(
        "{path} is missing: build the library with `cargo build --release` (it is built with \
         the binary)",
        path = path.display()
    )]
    LibraryMissing { path: std::path::PathBuf },
    #[error("the {mode} run on {library} failed ({status}):\n{stderr}")]
    Failed {
        library: Library,
        mode: AbiMode,
        status: String,
        stderr: String,
    },
    #[error("the {mode} run on {library} took over {seconds} s and was killed:\n{stderr}")]
    Timeout {
        library: Library,
        mode: AbiMode,
        seconds: u64,
        stderr: String,
    },
    #[error("the {mode} run on {library}: {source}")]
    Run {
        library: Library,
        mode: AbiMode,
        #[source]
        source: Box<AbiError>,
    },
    #[error("line {line} `{text}`: {reason}")]
    Output {
        line: usize,
        text: String,
        reason: String,
    },
    #[error("the output ends without its `{missing}` record")]
    Incomplete { missing: &'static str },
    #[error(
        "the {mode} run meant for {library} ran on vendor `{vendor}` ({renderer}): the \
         loader took another libOSMesa.so.8 (LD_PRELOAD, or a folder in the loader's path)"
    )]
    WrongLibrary {
        library: Library,
        mode: AbiMode,
        vendor: String,
        renderer: String,
    },
    #[error(
        "the {mode} images differ: {what} pixels {mesa} on Mesa, {ours} on fixedfunc (more \
         than {percent}% of the image apart)",
        percent = IMAGE_AGREEMENT * 100.0
    )]
    ImagesDiffer {
        mode: AbiMode,
        what: &'static str,
        mesa: u64,
        ours: u64,
    },
    #[error("{what}: {reason}")]
    Io { what: String, reason: String },
}

/// Runs each of `cases` (see [`cases`]) on each library, interleaved, as many times as its
/// span's share of `repeats`; `done` is told of each finished run. Rows come in the cases'
/// order.
pub fn measure(
    program: &Program,
    libraries: &Libraries,
    cases: &[(AbiMode, Heap, Span)],
    repeats: usize,
    mut done: impl FnMut(AbiMode, Heap, Span, Library),
) -> Result<Vec<AbiRow>, AbiError> {
    // runs[case][library]: each repeat's output.
    let mut runs: Vec<[Vec<RunOutput>; 2]> = cases.iter().map(|_| [vec![], vec![]]).collect();
    for repeat in 0..repeats.max(1) {
        for (c, &(mode, heap, span)) in cases.iter().enumerate() {
            if repeat >= span.repeats(repeats) {
                continue;
            }
            for (l, library) in [Library::Mesa, Library::Fixedfunc].into_iter().enumerate() {
                let out = program.run(libraries, library, mode, heap, span.frames(), None)?;
                runs[c][l].push(out);
                done(mode, heap, span, library);
            }
        }
    }
    cases
        .iter()
        .zip(runs)
        .map(|(&(mode, heap, span), [mesa, ours])| row(mode, heap, span, &mesa, &ours))
        .collect()
}

/// How many runs [`measure`] makes of `cases` for `repeats`.
pub fn run_count(cases: &[(AbiMode, Heap, Span)], repeats: usize) -> usize {
    cases.iter().map(|&(_, _, s)| 2 * s.repeats(repeats)).sum()
}

fn row(
    mode: AbiMode,
    heap: Heap,
    span: Span,
    mesa: &[RunOutput],
    ours: &[RunOutput],
) -> Result<AbiRow, AbiError> {
    let (Some(m), Some(o)) = (mesa.first(), ours.first()) else {
        return Err(AbiError::Incomplete { missing: "frame" });
    };
    agree(mode, m, o)?;
    let mesa_runs = mesa;
    let mesa = figures(Library::Mesa, span, mesa)?;
    let fixedfunc = figures(Library::Fixedfunc, span, ours)?;
    let ratio = fixedfunc.frame_ms.median / mesa.frame_ms.median;
    let pairs: Vec<f64> = mesa_runs
        .iter()
        .zip(ours)
        .filter_map(|(m, o)| Some(span.median(o)? / span.median(m)?))
        .collect();
    let paired = Summary::of(&pairs).ok_or(AbiError::Incomplete { missing: "frame" })?;
    let target = mode.target();
    let verdict = match target {
        None => Verdict::None,
        Some(t) if ratio <= t => Verdict::Met,
        Some(_) => Verdict::Missed,
    };
    Ok(AbiRow {
        mode,
        heap,
        span,
        vertices_per_frame: m.vertices,
        draws_per_frame: m.draws,
        mesa,
        fixedfunc,
        ratio,
        paired,
        target,
        verdict,
    })
}

/// Both libraries drew the same workload: the same counts, and drawn and dark pixels
/// within [`IMAGE_AGREEMENT`] of the image.
fn agree(mode: AbiMode, mesa: &RunOutput, ours: &RunOutput) -> Result<(), AbiError> {
    let differ = |what, m: u64, o: u64| AbiError::ImagesDiffer {
        mode,
        what,
        mesa: m,
        ours: o,
    };
    if (mesa.vertices, mesa.draws) != (ours.vertices, ours.draws) {
        return Err(differ("vertex", mesa.vertices, ours.vertices));
    }
    let limit = (IMAGE_AGREEMENT * PIXELS as f64) as u64;
    for (what, m, o) in [
        ("drawn", mesa.drawn, ours.drawn),
        ("dark", mesa.dark, ours.dark),
    ] {
        if m.abs_diff(o) > limit {
            return Err(differ(what, m, o));
        }
    }
    Ok(())
}

fn figures(library: Library, span: Span, runs: &[RunOutput]) -> Result<LibraryFigures, AbiError> {
    let first = runs
        .first()
        .ok_or(AbiError::Incomplete { missing: "frame" })?;
    let frame_ms: Vec<f64> = runs.iter().filter_map(|r| span.median(r)).collect();
    // Per run: count / (median frame in seconds).
    let rate = |count: u64, scale: f64| -> Vec<f64> {
        frame_ms
            .iter()
            .map(|ms| count as f64 / (ms / 1e3) / scale)
            .collect()
    };
    let summary = |v: &[f64]| Summary::of(v).ok_or(AbiError::Incomplete { missing: "frame" });
    Ok(LibraryFigures {
        library,
        vendor: first.vendor.clone(),
        renderer: first.renderer.clone(),
        frame_ms: summary(&frame_ms)?,
        mvertices_per_s: summary(&rate(first.vertices, 1e6))?,
        draws_per_s: summary(&rate(first.draws, 1.0))?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settled_runs_are_measured_under_the_untrimmed_heap_with_a_quarter_of_the_repeats() {
        let cases = cases(&[AbiMode::Arrays, AbiMode::Lists], &Heap::ALL, &Span::ALL);
        assert_eq!(
            cases,
            vec![
                (AbiMode::Arrays, Heap::Glibc, Span::Early),
                (AbiMode::Arrays, Heap::Untrimmed, Span::Early),
                (AbiMode::Arrays, Heap::Untrimmed, Span::Settled),
                (AbiMode::Lists, Heap::Glibc, Span::Early),
                (AbiMode::Lists, Heap::Untrimmed, Span::Early),
                (AbiMode::Lists, Heap::Untrimmed, Span::Settled),
            ]
        );
        assert_eq!(
            (Span::Settled.repeats(1), Span::Settled.repeats(10)),
            (1, 3)
        );
        assert_eq!((Span::Early.repeats(0), Span::Early.repeats(10)), (1, 10));
        // Per repeat of 10: 4 early cases and 2 settled, each on two libraries.
        assert_eq!(run_count(&cases, 10), 2 * (4 * 10 + 2 * 3));
    }

    #[test]
    fn a_span_takes_the_median_of_the_frames_after_its_skipped_ones() {
        let run = |frames: Vec<f64>| RunOutput {
            vendor: String::new(),
            renderer: String::new(),
            mode: AbiMode::Arrays,
            vertices: 0,
            draws: 0,
            frame_ms: frames,
            drawn: 0,
            dark: 0,
            lit: 0,
            mean: [0.0; 3],
        };
        // Three warm-up frames left out: the median of 1, 2, 9.
        let early = run(vec![50.0, 40.0, 30.0, 1.0, 9.0, 2.0]);
        assert_eq!(Span::Early.median(&early), Some(2.0));
        assert_eq!(Span::Settled.median(&early), None, "too short a run");
        let mut frames = vec![100.0; SETTLING_FRAMES as usize];
        frames.extend([3.0, 1.0, 2.0]);
        assert_eq!(Span::Settled.median(&run(frames)), Some(2.0));
        assert_eq!(Span::Settled.frames(), 400);
    }

    #[test]
    fn an_untrimmed_run_raises_the_trim_threshold_after_the_inherited_tunables() {
        let trim = "glibc.malloc.trim_threshold=67108864";
        assert_eq!(Heap::Glibc.tunables(Some("glibc.malloc.arena_max=2")), None);
        assert_eq!(Heap::Untrimmed.tunables(None).as_deref(), Some(trim));
        assert_eq!(Heap::Untrimmed.tunables(Some("")).as_deref(), Some(trim));
        assert_eq!(
            Heap::Untrimmed
                .tunables(Some("glibc.malloc.trim_threshold=0"))
                .as_deref(),
            Some("glibc.malloc.trim_threshold=0:glibc.malloc.trim_threshold=67108864")
        );
    }
}
