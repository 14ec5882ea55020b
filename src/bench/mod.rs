//! Measurements behind `fixedfunc bench`: each group times real work repeatedly and reports
//! medians (with min and max), never a single run. Groups: `context` (creating each
//! backend's contexts and producing the first read-back frame) and `pipeline` (the same
//! frame through the emulated and the native path, interleaved), `truth` and `techniques`
//! (every shadow technique on both paths, split into light pass, readback + upload and eye
//! passes), `abi` (an OSMesa C program on the layer's C library against Mesa's own,
//! interleaved), `coleman` (Coleman's draw-time experiments with fleets of F-35s) and
//! `soft` (Eisemann & Décoret's claims: occlusion textures and the accumulation buffer,
//! time and visibility error against slices, texture size, prefilter, combination rule,
//! geometry and light size).

pub mod abi;
pub mod coleman;
pub mod context;
pub mod pipeline;
pub mod soft;
pub mod techniques;

/// Which measurements to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum BenchGroup {
    /// Context creation and the first read-back frame, per backend and profile.
    Context,
    /// One frame of the default scene through the emulated and the native pipeline.
    Pipeline,
    /// The CPU ground truth: rays per second on the default scene and on ~1M triangles.
    Truth,
    /// Every technique on the default scene, both paths, frame time split by pass kind.
    Techniques,
    /// The C library against Mesa's OSMesa: one C program, five drawing paths.
    Abi,
    /// Coleman's experiments: fleets of 1 to 200 F-35s, occluder planes against shadow
    /// maps and projective shadows, at three scales.
    Coleman,
    /// Eisemann & Décoret's claims: `occlusion-textures` and `accumulate`, time and
    /// visibility error against slices, texture size, prefilter, combination rule,
    /// geometry count and light size.
    Soft,
}

impl crate::vocab::Named for BenchGroup {
    const NAMES: &'static [(&'static str, Self)] = &[
        ("context", BenchGroup::Context),
        ("pipeline", BenchGroup::Pipeline),
        ("truth", BenchGroup::Truth),
        ("techniques", BenchGroup::Techniques),
        ("abi", BenchGroup::Abi),
        ("coleman", BenchGroup::Coleman),
        ("soft", BenchGroup::Soft),
    ];

    fn help(self) -> &'static str {
        match self {
            BenchGroup::Context => {
                "context creation and the first read-back frame, per backend and profile"
            }
            BenchGroup::Pipeline => "one frame of the default scene through both pipelines",
            BenchGroup::Truth => "the CPU ground truth: rays per second",
            BenchGroup::Techniques => {
                "every technique on the default scene, both paths, split by pass kind"
            }
            BenchGroup::Abi => {
                "an OSMesa C program on the C library against Mesa's OSMesa: immediate mode, \
                 arrays, lists, buffers, a shadow-map frame"
            }
            BenchGroup::Coleman => {
                "Coleman's experiments: 1 to 200 F-35s, occluder planes against depth-compare \
                 and projective, at three scales"
            }
            BenchGroup::Soft => {
                "Eisemann & Décoret's claims: occlusion textures and accumulate, time and \
                 visibility RMSE against slices, texture size, prefilter, combine rule, \
                 geometry and light size"
            }
        }
    }
}

impl BenchGroup {
    pub const ALL: [BenchGroup; 7] = [
        BenchGroup::Context,
        BenchGroup::Pipeline,
        BenchGroup::Truth,
        BenchGroup::Techniques,
        BenchGroup::Abi,
        BenchGroup::Coleman,
        BenchGroup::Soft,
    ];
}
