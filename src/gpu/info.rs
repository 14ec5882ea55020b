//! What a context offers: strings, limits, the depth and stencil bits each `DepthBits`
//! actually yields, and the extensions the shadow techniques rely on.

use glow::HasContext;
use serde::Serialize;

use super::{Backend, GpuContext, GpuError, Profile, RenderTarget, TargetSpec};
use crate::vocab::DepthBits;

/// The extensions the classic techniques rely on, and which technique uses each.
pub const SHADOW_EXTENSIONS: [(&str, &str); 14] = [
    ("GL_ARB_multitexture", "dual-texture comparisons"),
    ("GL_ARB_depth_texture", "depth-compare"),
    ("GL_ARB_shadow", "depth-compare"),
    ("GL_ARB_shadow_ambient", "depth-compare fail value"),
    ("GL_EXT_shadow_funcs", "depth-compare, all eight funcs"),
    ("GL_SGIX_shadow", "depth-compare (SGI original)"),
    ("GL_ARB_texture_env_combine", "dual8, multidigit16-combine"),
    ("GL_ARB_texture_env_crossbar", "combine TEXTUREn sources"),
    ("GL_ARB_texture_env_dot3", "combine DOT3"),
    ("GL_NV_register_combiners", "multidigit16"),
    ("GL_ARB_texture_border_clamp", "shadow-map borders"),
    ("GL_EXT_stencil_wrap", "planar, multidigit16"),
    ("GL_ARB_framebuffer_object", "render targets"),
    ("GL_ARB_depth_buffer_float", "32F depth"),
];

#[derive(Clone, Debug, Serialize)]
pub struct Limits {
    pub max_texture_size: i32,
    pub max_renderbuffer_size: i32,
    /// GL_MAX_TEXTURE_IMAGE_UNITS: fragment-shader samplers.
    pub max_texture_image_units: i32,
    /// GL_MAX_TEXTURE_UNITS: fixed-function units (compatibility profile only).
    pub max_fixed_function_units: Option<i32>,
    pub max_viewport: [i32; 2],
}

#[derive(Clone, Debug, Serialize)]
pub struct DepthReport {
    pub requested: DepthBits,
    pub stencil_requested: bool,
    /// Bits obtained, `None` when the target could not be made.
    pub depth_bits: Option<u32>,
    pub stencil_bits: Option<u32>,
    /// Why the target could not be made.
    pub error: Option<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct ExtensionReport {
    pub name: &'static str,
    pub used_by: &'static str,
    pub present: bool,
}

#[derive(Clone, Debug, Serialize)]
pub struct ContextInfo {
    pub backend: Backend,
    pub profile: Profile,
    pub path: String,
    pub vendor: String,
    pub renderer: String,
    pub version: String,
    pub glsl_version: String,
    pub limits: Limits,
    pub depth: Vec<DepthReport>,
    pub extensions: Vec<ExtensionReport>,
}

impl ContextInfo {
    /// Queries everything; creates (and deletes) a small target per depth format.
    pub fn query(ctx: &GpuContext) -> Result<ContextInfo, GpuError> {
        ctx.make_current()?;
        let gl = ctx.gl();
        let (vendor, renderer, version, glsl_version, limits) = unsafe {
            let mut viewport = [0i32; 2];
            gl.get_parameter_i32_slice(glow::MAX_VIEWPORT_DIMS, &mut viewport);
            let limits = Limits {
                max_texture_size: gl.get_parameter_i32(glow::MAX_TEXTURE_SIZE),
                max_renderbuffer_size: gl.get_parameter_i32(glow::MAX_RENDERBUFFER_SIZE),
                max_texture_image_units: gl.get_parameter_i32(glow::MAX_TEXTURE_IMAGE_UNITS),
                max_fixed_function_units: match ctx.profile() {
                    // GL_MAX_TEXTURE_UNITS (0x84E2) exists only with fixed function.
                    Profile::Compatibility => Some(gl.get_parameter_i32(0x84E2)),
                    Profile::Core33 => None,
                },
                max_viewport: viewport,
            };
            (
                gl.get_parameter_string(glow::VENDOR),
                gl.get_parameter_string(glow::RENDERER),
                gl.get_parameter_string(glow::VERSION),
                gl.get_parameter_string(glow::SHADING_LANGUAGE_VERSION),
                limits,
            )
        };
        ctx.check_error("glGet (context info)")?;
        let mut depth = Vec::new();
        for bits in DepthBits::ALL {
            for stencil in [false, true] {
                let spec = TargetSpec {
                    stencil,
                    ..TargetSpec::new(4, 4, bits)
                };
                let result = RenderTarget::new(ctx, spec).map(|t| {
                    let obtained = (t.depth_bits(), t.stencil_bits());
                    t.delete(ctx);
                    obtained
                });
                let (depth_bits, stencil_bits, error) = match result {
                    Ok((z, s)) => (Some(z), Some(s), None),
                    Err(e) => (None, None, Some(e.to_string())),
                };
                depth.push(DepthReport {
                    requested: bits,
                    stencil_requested: stencil,
                    depth_bits,
                    stencil_bits,
                    error,
                });
            }
        }
        let available = gl.supported_extensions();
        let extensions = SHADOW_EXTENSIONS
            .iter()
            .map(|&(name, used_by)| ExtensionReport {
                name,
                used_by,
                present: available.contains(name),
            })
            .collect();
        Ok(ContextInfo {
            backend: ctx.backend(),
            profile: ctx.profile(),
            path: ctx.path().to_string(),
            vendor,
            renderer,
            version,
            glsl_version,
            limits,
            depth,
            extensions,
        })
    }
}
