//! The fragment code of a pixel rectangle (`key::PixelSource`): the fragment's pixel of the
//! image is p = ⌊(x_f − x_0)/z_x⌋, ⌊(y_f − y_0)/z_y⌋ (a negative zoom: ⌈…⌉ − 1) for its
//! window centre (x_f, y_f), the
//! rectangle's corner (x_0, y_0) and zoom (GL 1.5 §3.6.4: group (n, m) covers
//! [x_0 + n·z_x, x_0 + (n + 1)·z_x) × …, either sign of zoom); the image is read with
//! texelFetch, so no filtering or normalisation touches the converted values.

use crate::pipeline::emulate::glsl::GlslWriter;
use crate::pipeline::emulate::key::PixelSource;
use crate::pipeline::emulate::uniforms::UniformSource;

/// Emits the image's effect on `primary` (declared already) or on the fragment.
pub fn emit(w: &mut GlslWriter, source: PixelSource) {
    let image = w.uniform_typed(UniformSource::PixelImage, "sampler2D");
    let rect = w.uniform(UniformSource::PixelRect);
    // A centre on a group boundary (t integral) goes to the group above for a positive
    // zoom, ⌊t⌋, and to the one below for a negative zoom, ⌈t⌉ − 1, as Mesa's rasteriser
    // puts it (measured with zoom −1.5: `tests/fidelity_pixels.rs`).
    w.line(format!(
        "vec2 t = (gl_FragCoord.xy - {rect}.xy) / {rect}.zw;"
    ));
    w.line(format!(
        "vec2 group = mix(floor(t), ceil(t) - 1.0, lessThan({rect}.zw, vec2(0.0)));"
    ));
    w.line(format!(
        "ivec2 pixel = clamp(ivec2(group), ivec2(0), textureSize({image}, 0) - 1);"
    ));
    w.line(format!("vec4 image = texelFetch({image}, pixel, 0);"));
    match source {
        PixelSource::Color => w.line("primary = image;"),
        PixelSource::Depth => w.line("gl_FragDepth = image.r;"),
        // The bitmap texture holds 0 or 1 per pixel.
        PixelSource::Bitmap => w.line("if (image.r == 0.0) discard;"),
        // The stencil image holds the 8-bit values as unorm8: s = round(255·r). A pass
        // keeps the pixels that have all its bits: those of its bit plane, or every pixel
        // for the pass of no bits that first sets the value to 0 (`pixels::stencil_pass`).
        PixelSource::StencilBit => {
            let bit = w.uniform(UniformSource::PixelStencilBit);
            w.line(format!(
                "if ((int(image.r * 255.0 + 0.5) & {bit}) != {bit}) discard;"
            ));
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::ff::FixedState;
    use crate::pipeline::emulate::key::{PixelSource, ShaderKey};
    use crate::pipeline::emulate::shadergen::generate;
    use crate::vocab::Precision;

    /// Each source changes the fragment code, and only the fragment code; no source, no
    /// image code.
    #[test]
    fn each_source_has_its_own_fragment_code() {
        let base = ShaderKey::from_state(&FixedState::new(), Precision::Float);
        let plain = generate(&base);
        assert!(!plain.fragment.contains("texelFetch"));
        let mut seen = vec![plain.fragment.clone()];
        for (source, line) in [
            (PixelSource::Color, "primary = image;"),
            (PixelSource::Depth, "gl_FragDepth = image.r;"),
            (PixelSource::Bitmap, "if (image.r == 0.0) discard;"),
            (
                PixelSource::StencilBit,
                "u_pixel_stencil_bit) != u_pixel_stencil_bit) discard;",
            ),
        ] {
            let mut key = base.clone();
            key.fragment.pixels = Some(source);
            let p = generate(&key);
            assert!(p.fragment.contains(line), "{source:?}:\n{}", p.fragment);
            assert_eq!(p.vertex, plain.vertex, "{source:?}");
            assert!(!seen.contains(&p.fragment), "{source:?}");
            seen.push(p.fragment);
        }
    }
}
