//! The one line of figures `fixedfunc render` prints: what ran, how wrong its mask is
//! against the truth, what a frame costs, and how much work the pipeline did.
//!
//! `none · emulate · egl · error 0.00% (false shadow 0, missed shadow 0) · 2.31 ms median
//! of 9 [2.10–2.80], cold 45.20 ms · 1 pass · 2 programs`; a shadow-map technique also says
//! which polygon offset it used and where it came from, after the backend:
//! `depth-compare · emulate · egl · offset 1,4 (technique default) · error …`.
//!
//! Error % = 100 · (false + missed + coverage) / truth geometry pixels (see `metrics`).
//! For an area light the error is followed by `visibility RMSE 0.034`: √(mean (v_tech −
//! v_truth)²) over the truth's geometry pixels, a hard mask counting as visibility 0 or 1
//! (`metrics::visibility_errors`) — printed with three decimals, for scripts to read.

use crate::vocab::{offset_text, OffsetSource, PipelineKind, PolygonOffset, TechniqueId};
use std::fmt;

use crate::gpu::Backend;

use super::{pipeline_name, FrameTimings};

/// `error 1.23% (false shadow 3, missed shadow 4)`: the part of the line scripts read the
/// error from (the viewer prints it alike).
pub fn error_text(wrong_percent: f64, false_shadow: u64, missed_shadow: u64) -> String {
    format!(
        "error {wrong_percent:.2}% (false shadow {false_shadow}, missed shadow {missed_shadow})"
    )
}

/// The figures of one render.
#[derive(Debug, Clone, PartialEq)]
pub struct Figures {
    pub technique: TechniqueId,
    pub pipeline: PipelineKind,
    pub backend: Backend,
    pub wrong_percent: f64,
    pub false_shadow: u64,
    pub missed_shadow: u64,
    pub timings: FrameTimings,
    pub passes: usize,
    pub programs: u64,
    /// Times the map passes ran.
    pub maps_made: u32,
    /// The visibility RMSE against an area light's truth; `None` for other lights.
    pub visibility_rmse: Option<f64>,
    /// The polygon offset and its source, for a technique that reads one.
    pub offset: Option<(Option<PolygonOffset>, OffsetSource)>,
}

impl fmt::Display for Figures {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} · {} · {} · ",
            self.technique,
            pipeline_name(self.pipeline),
            self.backend
        )?;
        if let Some((offset, source)) = self.offset {
            write!(f, "offset {} ({source}) · ", offset_text(offset))?;
        }
        write!(
            f,
            "{} · ",
            error_text(self.wrong_percent, self.false_shadow, self.missed_shadow)
        )?;
        if let Some(rmse) = self.visibility_rmse {
            write!(f, "visibility RMSE {rmse:.3} · ")?;
        }
        match self.timings.steady {
            Some(s) => write!(
                f,
                "{:.2} ms median of {} [{:.2}–{:.2}], cold {:.2} ms",
                s.median, s.samples, s.min, s.max, self.timings.cold_ms
            )?,
            None => write!(f, "{:.2} ms (one cold frame)", self.timings.cold_ms)?,
        }
        let plural = |n: u64| if n == 1 { "" } else { "s" };
        write!(
            f,
            " · {} pass{} · {} program{}",
            self.passes,
            if self.passes == 1 { "" } else { "es" },
            self.programs,
            plural(self.programs)
        )?;
        if self.maps_made > 0 {
            write!(
                f,
                " · {} map{} made",
                self.maps_made,
                plural(u64::from(self.maps_made))
            )?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn figures(steady: Vec<f64>) -> Figures {
        Figures {
            technique: TechniqueId::None,
            pipeline: PipelineKind::Emulate,
            backend: Backend::Egl,
            wrong_percent: 1.234,
            false_shadow: 3,
            missed_shadow: 4,
            timings: FrameTimings::new(40.0, steady),
            passes: 1,
            programs: 2,
            maps_made: 0,
            visibility_rmse: None,
            offset: None,
        }
    }

    #[test]
    fn an_area_light_adds_the_visibility_rmse_after_the_error() {
        let mut f = figures(vec![1.0]);
        f.visibility_rmse = Some(0.03449);
        assert!(f
            .to_string()
            .contains("missed shadow 4) · visibility RMSE 0.034 · 1.00 ms"));
    }

    #[test]
    fn one_line_with_every_figure() {
        assert_eq!(
            figures(vec![3.0, 1.0, 2.0]).to_string(),
            "none · emulate · egl · error 1.23% (false shadow 3, missed shadow 4) · \
             2.00 ms median of 3 [1.00–3.00], cold 40.00 ms · 1 pass · 2 programs"
        );
        let single = figures(Vec::new()).to_string();
        assert!(single.contains("40.00 ms (one cold frame)"), "{single}");
        assert!(!single.contains('\n'));
    }

    #[test]
    fn a_shadow_map_technique_names_its_offset_and_its_source() {
        let mut f = figures(vec![1.0]);
        f.technique = TechniqueId::DepthCompare;
        let kilgard = PolygonOffset {
            factor: 1.0,
            units: 4.0,
        };
        f.offset = Some((Some(kilgard), OffsetSource::TechniqueDefault));
        assert!(f
            .to_string()
            .starts_with("depth-compare · emulate · egl · offset 1,4 (technique default) · error"));
        f.offset = Some((None, OffsetSource::CommandLine));
        assert!(f.to_string().contains("· offset none (command line) ·"));
    }
}
