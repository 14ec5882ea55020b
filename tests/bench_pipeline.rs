//! What the pipeline benchmark promises besides time: the emulated path compiles its
//! programs on the first frame only, and skips redundant state calls afterwards.

use fixedfunc::bench::pipeline::measure;
use fixedfunc::gpu::Backend;
use fixedfunc::vocab::PipelineKind;

#[test]
fn emulated_frames_after_the_first_compile_nothing() {
    let rows = measure(Backend::Egl, 3, || {}).expect("benchmark runs");
    assert_eq!(rows.len(), 2);
    let emulate = rows
        .iter()
        .find(|r| r.pipeline == PipelineKind::Emulate)
        .expect("emulate row");
    assert!(emulate.programs_compiled >= 1);
    assert_eq!(emulate.programs_after_first_frame, 0);
    assert!(emulate.counters.state_calls_skipped > emulate.counters.state_calls_sent);
    let native = rows
        .iter()
        .find(|r| r.pipeline == PipelineKind::Native)
        .expect("native row");
    assert_eq!(native.programs_compiled, 0);
    assert_eq!(native.counters.draws, emulate.counters.draws);
}
