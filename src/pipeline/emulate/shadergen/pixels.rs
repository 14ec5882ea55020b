//! The fragment code of a pixel rectangle (`key::PixelSource`). An image of glDrawPixels
//! or glCopyPixels is sampled with NEAREST at the texture coordinates the rasteriser
//! interpolated across its fan (`pixel_fan`: Mesa's quad, so the pixel of the image each
//! fragment gets is the one Mesa's gives it). A bitmap, never zoomed, is read with
//! texelFetch at p = ⌊x_f − x_0⌋, ⌊y_f − y_0⌋ for the fragment's window centre (x_f, y_f)
//! and the rectangle's corner (x_0, y_0) (GL 1.5 §3.7). No filtering or normalisation
//! touches the converted values either way.

use crate::pipeline::emulate::glsl::GlslWriter;
use crate::pipeline::emulate::key::PixelSource;
use crate::pipeline::emulate::uniforms::UniformSource;

/// Emits the image's effect on `primary` (declared already) or on the fragment.
pub fn emit(w: &mut GlslWriter, source: PixelSource) {
    let image = w.uniform_typed(UniformSource::PixelImage, "sampler2D");
    if source == PixelSource::Bitmap {
        let rect = w.uniform(UniformSource::PixelRect);
        w.line(format!(
            "ivec2 pixel = clamp(ivec2(floor(gl_FragCoord.xy - {rect}.xy)), ivec2(0), \
             textureSize({image}, 0) - 1);"
        ));
        w.line(format!("vec4 image = texelFetch({image}, pixel, 0);"));
    } else {
        w.declare("in vec2 v_pixel_st;");
        w.line(format!("vec4 image = texture({image}, v_pixel_st);"));
    }
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
