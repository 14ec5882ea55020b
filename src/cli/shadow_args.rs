//! The shadow-map parameters every rendering command accepts, overriding the scene's
//! `[shadow]` table: map size, light depth bits, polygon offset, precision, filter,
//! readback rule, the projection techniques' modes, and `accumulate`'s light samples.

use clap::Args;
use fixedfunc::scene::{OccluderProgram, OffsetSetting, Scene, ShadowSettings};
use fixedfunc::vocab::{
    DepthBits, MapFilter, OffsetArg, PlanarMode, Precision, Projector, ReadbackRule,
};

/// `--map-size`, `--depth-bits`, `--offset`, `--precision`, `--filter`.
#[derive(Args, Debug, Clone, Default)]
pub struct ShadowArgs {
    /// Shadow map edge in texels (default: the scene's `map_size`).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=8192))]
    pub map_size: Option<u32>,
    /// Depth buffer of the light pass (default: the scene's `depth_bits`).
    #[arg(long, value_parser = super::named::named::<DepthBits>())]
    pub depth_bits: Option<DepthBits>,
    /// glPolygonOffset(FACTOR, UNITS) for the light pass, as FACTOR,UNITS; `none` for no
    /// offset, to see the acne (default: the scene's `polygon_offset`, else the
    /// technique's own, listed in the README).
    #[arg(long, value_name = "FACTOR,UNITS", value_parser = parse_offset)]
    pub offset: Option<OffsetArg>,
    /// Arithmetic of the emulated texture and combiner stages (default: the scene's).
    #[arg(long, value_parser = super::named::named::<Precision>())]
    pub precision: Option<Precision>,
    /// Shadow map filter (default: the scene's `filter`).
    #[arg(long, value_parser = super::named::named::<MapFilter>())]
    pub filter: Option<MapFilter>,
    /// How integer depth maps are read back: the driver's conversion, or FLOAT converted
    /// on the CPU by truncation or rounding (default: the scene's `readback`).
    #[arg(long, value_parser = super::named::named::<ReadbackRule>())]
    pub readback: Option<ReadbackRule>,
    /// How `planar` keeps its shadow off the receiver's depth: polygon offset or stencil
    /// alone (default: the scene's `planar_mode`).
    #[arg(long, value_parser = super::named::named::<PlanarMode>())]
    pub planar_mode: Option<PlanarMode>,
    /// `projective`'s projector: the light's perspective frustum, or the pseudo-depth
    /// projection that clips false shadows (default: the scene's `projector`).
    #[arg(long, value_parser = super::named::named::<Projector>())]
    pub projector: Option<Projector>,
    /// `accumulate`'s renders per frame, one from each stratified point of the area light
    /// (or direction of the sun's disc),
    /// 1 to 256 (default: the scene's `light_samples`, else 16).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=i64::from(ShadowSettings::MAX_LIGHT_SAMPLES)))]
    pub light_samples: Option<u32>,
    /// `occluder-planes`' form: fixed-function texgen, the thesis's shaders (`coleman`, the
    /// F-35 only) or a generated program (`generic`) (default: the scene's `program`).
    #[arg(long, value_parser = super::named::named::<OccluderProgram>())]
    pub occluder_program: Option<OccluderProgram>,
}

/// `FACTOR,UNITS` (finite numbers) or `none`, by the vocabulary's rule (clap shows its
/// message).
pub fn parse_offset(text: &str) -> Result<OffsetArg, String> {
    text.parse::<OffsetArg>().map_err(|e| e.to_string())
}

impl ShadowArgs {
    /// `scene` with every given parameter applied.
    pub fn apply(&self, scene: &mut Scene) {
        let s = &mut scene.shadow;
        if let Some(v) = self.map_size {
            s.map_size = v;
        }
        if let Some(v) = self.depth_bits {
            s.depth = v;
        }
        match self.offset {
            Some(OffsetArg::None) => s.polygon_offset = OffsetSetting::command_line(None),
            Some(OffsetArg::Offset(o)) => s.polygon_offset = OffsetSetting::command_line(Some(o)),
            None => {}
        }
        if let Some(v) = self.precision {
            s.precision = v;
        }
        if let Some(v) = self.filter {
            s.filter = v;
        }
        if let Some(v) = self.readback {
            s.readback = v;
        }
        if let Some(v) = self.planar_mode {
            s.planar_mode = v;
        }
        if let Some(v) = self.projector {
            s.projector = v;
        }
        if let Some(v) = self.light_samples {
            s.light_samples = v;
        }
        if let Some(v) = self.occluder_program {
            s.occluder_program = v;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fixedfunc::vocab::PolygonOffset;

    #[test]
    fn offsets_parse_or_say_what_is_expected() {
        assert_eq!(
            parse_offset("1, 4"),
            Ok(OffsetArg::Offset(PolygonOffset {
                factor: 1.0,
                units: 4.0
            }))
        );
        assert_eq!(parse_offset("none"), Ok(OffsetArg::None));
        for bad in ["1", "a,b", "1,NaN", "inf,1", ""] {
            let e = parse_offset(bad).unwrap_err();
            assert!(e.contains("FACTOR,UNITS"), "{bad}: {e}");
        }
    }
}
