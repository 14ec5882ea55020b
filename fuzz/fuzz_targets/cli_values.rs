//! The command line's value parsers, each given the same text: `--size WxH`, `--offset
//! F,U|none`, `--orbit camera:DEG`, sweep ranges `A..B[:steps]`, `--backend`, every named
//! value (`vocab::Named`) and comma-separated lists of them (`--depth-bits 16,24,32f`, as
//! clap splits them). The property: no panic, no abort, no hang; a refusal is an `Err` with
//! a message; what is accepted is in range (sizes, finite numbers, the steps a range
//! promises).

#![no_main]

use fixedfunc::gpu::Backend;
use fixedfunc::render::{ImageSize, Orbit, OrbitTarget, MAX_IMAGE_SIZE};
use fixedfunc::study::range::{SweepRange, MAX_STEPS};
use fixedfunc::vocab::{
    DepthBits, MapFilter, Named, OffsetArg, PipelineKind, PlanarMode, Precision, Projector,
    ReadbackRule, TechniqueId,
};
use libfuzzer_sys::fuzz_target;
use std::fmt::Display;
use std::str::FromStr;

fn parsed<T: FromStr>(text: &str) -> Option<T>
where
    T::Err: Display,
{
    match text.parse::<T>() {
        Ok(v) => Some(v),
        Err(e) => {
            assert!(
                !e.to_string().trim().is_empty(),
                "empty message for {text:?}"
            );
            None
        }
    }
}

/// A name either names a value whose printed name reads back as the same value, or none.
fn named<T: Named + std::fmt::Debug>(text: &str) {
    for part in std::iter::once(text).chain(text.split(',')) {
        if let Some(v) = T::from_name(part) {
            assert_eq!(T::from_name(v.name()), Some(v));
        }
    }
}

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let text = text.as_ref();
    if let Some(size) = parsed::<ImageSize>(text) {
        assert!((1..=MAX_IMAGE_SIZE).contains(&size.width));
        assert!((1..=MAX_IMAGE_SIZE).contains(&size.height));
    }
    if let Some(OffsetArg::Offset(o)) = parsed::<OffsetArg>(text) {
        assert!(o.factor.is_finite() && o.units.is_finite());
    }
    if let Some(orbit) = parsed::<Orbit>(text) {
        assert!(orbit.degrees_per_frame.is_finite());
    }
    if let Some(range) = parsed::<SweepRange>(text) {
        assert!(range.start.is_finite() && range.end.is_finite());
        assert!(range.start <= range.end && (1..=MAX_STEPS).contains(&range.steps));
        let values = range.values();
        assert_eq!(values.len(), range.steps as usize);
        assert!(values.iter().all(|v| v.is_finite()), "{range}: {values:?}");
    }
    let _ = parsed::<Backend>(text);
    named::<TechniqueId>(text);
    named::<PipelineKind>(text);
    named::<DepthBits>(text);
    named::<ReadbackRule>(text);
    named::<Precision>(text);
    named::<MapFilter>(text);
    named::<PlanarMode>(text);
    named::<Projector>(text);
    named::<OrbitTarget>(text);
    named::<Backend>(text);
});
