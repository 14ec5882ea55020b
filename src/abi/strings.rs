//! glGetString: what the layer says it is. The extension string lists exactly what the
//! model emulates, so a program that tests for an extension before using it takes the path
//! the layer can render.

use std::ffi::CString;
use std::sync::OnceLock;

use glow::HasContext;

use super::cargs::CArg;
use crate::gpu::GpuContext;

/// The extensions whose state and commands the model holds.
pub const EXTENSIONS: &[&str] = &[
    "GL_ARB_multitexture",
    "GL_ARB_texture_env_add",
    "GL_ARB_texture_env_combine",
    "GL_ARB_texture_env_crossbar",
    "GL_ARB_texture_env_dot3",
    "GL_EXT_texture_env_combine",
    "GL_ARB_depth_texture",
    "GL_ARB_shadow",
    "GL_ARB_shadow_ambient",
    "GL_EXT_stencil_wrap",
    "GL_NV_register_combiners",
    "GL_SGIS_generate_mipmap",
    "GL_EXT_texture3D",
    "GL_ARB_texture_cube_map",
    "GL_EXT_texture_cube_map",
    "GL_EXT_framebuffer_blit",
    "GL_EXT_framebuffer_object",
    "GL_ARB_vertex_buffer_object",
    "GL_ARB_transpose_matrix",
    "GL_ARB_window_pos",
    "GL_ARB_occlusion_query",
    "GL_ARB_occlusion_query2",
    "GL_ARB_point_parameters",
    "GL_EXT_point_parameters",
    "GL_EXT_texture_edge_clamp",
    "GL_SGIS_texture_edge_clamp",
    "GL_ARB_texture_border_clamp",
    "GL_EXT_separate_specular_color",
    "GL_EXT_secondary_color",
    "GL_EXT_fog_coord",
    "GL_ARB_texture_mirrored_repeat",
    "GL_ARB_texture_compression",
    "GL_EXT_texture_compression_s3tc",
    "GL_EXT_bgra",
    "GL_EXT_abgr",
    "GL_EXT_packed_pixels",
    "GL_SGIS_texture_lod",
    "GL_EXT_texture_lod_bias",
    "GL_EXT_texture_filter_anisotropic",
    "GL_ARB_point_sprite",
    "GL_ARB_texture_non_power_of_two",
    // Earlier names of what GL 1.2–1.4 made core, which the model holds under those
    // (`tests/c/extensions.c`).
    "GL_APPLE_packed_pixels",
    "GL_ARB_multisample",
    "GL_EXT_blend_color",
    "GL_EXT_blend_func_separate",
    "GL_EXT_blend_minmax",
    "GL_EXT_blend_subtract",
    "GL_EXT_copy_texture",
    "GL_EXT_draw_range_elements",
    "GL_EXT_multi_draw_arrays",
    "GL_EXT_rescale_normal",
    "GL_EXT_shadow_funcs",
    "GL_EXT_subtexture",
    "GL_EXT_texture_env_add",
    "GL_EXT_texture_object",
    "GL_IBM_texture_mirrored_repeat",
    "GL_INGR_blend_func_separate",
    "GL_NV_blend_square",
    "GL_NV_texgen_reflection",
    "GL_SGIS_texture_border_clamp",
    "GL_EXT_compiled_vertex_array",
];

struct Strings {
    vendor: CString,
    renderer: CString,
    version: CString,
    extensions: CString,
}

fn strings(gpu: &GpuContext) -> &'static Strings {
    static STRINGS: OnceLock<Strings> = OnceLock::new();
    STRINGS.get_or_init(|| {
        let driver = unsafe { gpu.gl().get_parameter_string(glow::RENDERER) };
        let c = |s: String| CString::new(s.replace('\0', "")).unwrap_or_default();
        Strings {
            vendor: c("fixedfunc".into()),
            renderer: c(format!(
                "fixedfunc emulated fixed function on {driver} ({})",
                gpu.path()
            )),
            version: c(format!("1.5 fixedfunc {}", env!("CARGO_PKG_VERSION"))),
            extensions: c(EXTENSIONS.join(" ")),
        }
    })
}

/// The string for glGetString's name, or `None` (INVALID_ENUM).
pub fn get(args: &[CArg], gpu: &GpuContext) -> Option<*const u8> {
    let CArg::Int(name) = *args.first()? else {
        return None;
    };
    let s = strings(gpu);
    let text = match name as u32 {
        glow::VENDOR => &s.vendor,
        glow::RENDERER => &s.renderer,
        glow::VERSION => &s.version,
        glow::EXTENSIONS => &s.extensions,
        _ => return None,
    };
    Some(text.as_ptr().cast())
}
