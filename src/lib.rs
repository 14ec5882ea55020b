//! fixedfunc: the OpenGL 1.x fixed-function pipeline, emulated on a modern GL context and
//! checked against Mesa's own fixed-function path, to reproduce the classic shadow techniques
//! headless and measurably.
//!
//! Layers, lowest first (a module uses those below it, never those above):
//! `vocab` (the shared names: techniques, pipelines, depth formats, readback rules) and
//! `stats` (medians of timings) and `shaders` (the era's published shaders, ported to GLSL
//! and embedded from `shaders/`) → `gpu` (contexts, render targets, readback) → `ff`
//! (commands and the GL 1.x state model, no GL calls) → `mesh` → `scene` → `metrics` →
//! `truth` (pure) → `pipeline` → `abi` (the C library: OSMesa and the GL 1.x entry points
//! over the emulated pipeline) and `techniques` (plans of Commands) → `render` (a scene, judged
//! against the truth; open sessions interleaved in rounds) → `bench`, `study` (many
//! renders against one truth: compare, bias sweeps) → `report` (tables, plots, pages) →
//! `view` (the scene in a window, its settings on keys) → the `fixedfunc` CLI. `tests/layers.rs` reads the sources and fails on an import that
//! runs up this order.

pub mod abi;
pub mod bench;
pub mod ff;
pub mod gpu;
pub mod mesh;
pub mod metrics;
pub mod pipeline;
pub mod render;
pub mod report;
pub mod scene;
pub mod shaders;
pub mod stats;
pub mod study;
pub mod techniques;
pub mod truth;
pub mod view;
pub mod vocab;
