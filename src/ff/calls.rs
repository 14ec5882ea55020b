//! From a call to its Command, written once for both front ends (see [`Args`]): one
//! converter per area, each returning `Ok(None)` for calls of other areas.

use super::api::{CType, Entry};
use super::args::{Args, LsbFirst};
use super::glenum::{Family, GlEnum};
use super::pixel_types;
use super::texture::level_from_float;
use super::*;

fn volume<A: Args>(c: &A) -> Result<ViewVolume, A::Error> {
    c.count(6)?;
    Ok(ViewVolume {
        left: c.f32(0)?,
        right: c.f32(1)?,
        bottom: c.f32(2)?,
        top: c.f32(3)?,
        near: c.f32(4)?,
        far: c.f32(5)?,
    })
}

/// The Command of every call that is not immediate mode (those are
/// [`Immediate`](super::immediate::Immediate)'s).
///
/// The areas are asked in turn, the one most of a frame's calls reach first (matrices,
/// enables, clears), then lighting and texturing; the variants (vector and integer forms
/// read as their scalar or float calls) come before the two areas whose calls they
/// answer in part, which get the rest.
pub fn command<A: Args>(c: &A) -> Result<Command, A::Error> {
    for area in [
        transform_and_fragment,
        super::calls_variants::variants,
        lighting,
        texturing,
        super::texture_calls::texture_calls,
        super::texture_volume::volume_calls,
        super::calls_compressed::compressed_calls,
        combiners,
        super::calls_attrib::attrib,
        super::calls_raster::raster,
        super::calls_framebuffer::framebuffer,
        super::calls_pixels::pixels,
        super::queries::command,
    ] {
        if let Some(cmd) = area(c)? {
            return Ok(cmd);
        }
    }
    Err(c.unsupported())
}

/// The calls a front end may convert and run at once when no glBegin/glEnd pair is open
/// and no display list is being compiled: each is the one Command [`command`] gives, with
/// no reply, and no front-end state (client arrays, lists, buffers, the immediate pair,
/// pixel storage) reads or changes it — the front end's routing would pass it through
/// unchanged. A frame repeats them, a transform and a material per object, so they skip
/// that routing (`benches/c/abi_bench.c`: 64 of a frame's ~90 calls).
pub fn direct(entry: Entry) -> bool {
    use Entry::*;
    matches!(
        entry,
        MatrixMode
            | LoadIdentity
            | LoadMatrixf
            | LoadMatrixd
            | MultMatrixf
            | MultMatrixd
            | Translatef
            | Translated
            | Rotatef
            | Rotated
            | Scalef
            | Scaled
            | PushMatrix
            | PopMatrix
            | Frustum
            | Ortho
            | Viewport
            | ShadeModel
            | Lightf
            | Lightfv
            | Lighti
            | Lightiv
            | LightModelf
            | LightModelfv
            | LightModeli
            | LightModeliv
            | Materialf
            | Materialfv
            | Materiali
            | Materialiv
            | Clear
            | ClearColor
            | ClearDepth
    )
}

fn clear_mask<A: Args>(c: &A) -> Result<ClearMask, A::Error> {
    const BITS: [&str; 4] = [
        "GL_COLOR_BUFFER_BIT",
        "GL_DEPTH_BUFFER_BIT",
        "GL_STENCIL_BUFFER_BIT",
        "GL_ACCUM_BUFFER_BIT",
    ];
    let mut m = ClearMask::default();
    for n in c.bits(0, &BITS)? {
        match n {
            "GL_COLOR_BUFFER_BIT" => m.color = true,
            "GL_DEPTH_BUFFER_BIT" => m.depth = true,
            "GL_ACCUM_BUFFER_BIT" => m.accum = true,
            _ => m.stencil = true,
        }
    }
    Ok(m)
}

fn capability<A: Args>(c: &A) -> Result<Capability, A::Error> {
    if let Ok(i) = c.family(0, Family::Light) {
        return Ok(Capability::Light(i));
    }
    if let Ok(i) = c.family(0, Family::ClipPlane) {
        return Ok(Capability::ClipPlane(i));
    }
    c.enm(0).map_err(|e| {
        let e = c.also_expected(e, "GL_LIGHT0..GL_LIGHT7");
        c.also_expected(e, "GL_CLIP_PLANE0..GL_CLIP_PLANE5")
    })
}

/// Matrices, viewport, enables, per-fragment operations, clears and readback.
pub fn transform_and_fragment<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    let n = |k: usize| c.count(k);
    Ok(Some(match c.entry() {
        Entry::MatrixMode => n(1).and(c.enm(0)).map(Command::MatrixMode)?,
        Entry::LoadIdentity => n(0).map(|_| Command::LoadIdentity)?,
        Entry::LoadMatrixf | Entry::LoadMatrixd => n(1).and(c.mat4(0)).map(Command::LoadMatrix)?,
        Entry::MultMatrixf | Entry::MultMatrixd => n(1).and(c.mat4(0)).map(Command::MultMatrix)?,
        Entry::PushMatrix => n(0).map(|_| Command::PushMatrix)?,
        Entry::PopMatrix => n(0).map(|_| Command::PopMatrix)?,
        Entry::Translatef | Entry::Translated => {
            n(3).and(c.vec3_args(0)).map(Command::Translate)?
        }
        Entry::Scalef | Entry::Scaled => n(3).and(c.vec3_args(0)).map(Command::Scale)?,
        Entry::Rotatef | Entry::Rotated => {
            n(4)?;
            Command::Rotate {
                angle_deg: c.f32(0)?,
                axis: c.vec3_args(1)?,
            }
        }
        Entry::Frustum => Command::Frustum(volume(c)?),
        Entry::Ortho => Command::Ortho(volume(c)?),
        Entry::Viewport => {
            n(4)?;
            Command::Viewport(Viewport {
                x: c.i32(0)?,
                y: c.i32(1)?,
                width: c.i32(2)?,
                height: c.i32(3)?,
            })
        }
        Entry::DepthRange => n(2).map(|_| ()).and_then(|_| {
            Ok(Command::DepthRange {
                near: c.f32(0)?,
                far: c.f32(1)?,
            })
        })?,
        Entry::Enable => n(1).and(capability(c)).map(Command::Enable)?,
        Entry::Disable => n(1).and(capability(c)).map(Command::Disable)?,
        Entry::AlphaFunc => {
            n(2)?;
            Command::AlphaFunc {
                func: c.enm(0)?,
                reference: c.f32(1)?,
            }
        }
        Entry::DepthFunc => n(1).and(c.enm(0)).map(Command::DepthFunc)?,
        Entry::DepthMask => n(1).and(c.boolean(0)).map(Command::DepthMask)?,
        Entry::StencilFunc => {
            n(3)?;
            Command::StencilFunc {
                func: c.enm(0)?,
                reference: c.i32(1)?,
                mask: c.u32(2)?,
            }
        }
        Entry::StencilOp => {
            n(3)?;
            Command::StencilOp {
                fail: c.enm(0)?,
                depth_fail: c.enm(1)?,
                depth_pass: c.enm(2)?,
            }
        }
        Entry::StencilMask => n(1).and(c.u32(0)).map(Command::StencilMask)?,
        Entry::BlendFunc => {
            n(2)?;
            Command::BlendFunc {
                src: c.enm(0)?,
                dst: c.enm(1)?,
            }
        }
        Entry::ColorMask => {
            n(4)?;
            Command::ColorMask(ColorMask {
                r: c.boolean(0)?,
                g: c.boolean(1)?,
                b: c.boolean(2)?,
                a: c.boolean(3)?,
            })
        }
        Entry::PolygonOffset => {
            n(2)?;
            Command::PolygonOffset {
                factor: c.f32(0)?,
                units: c.f32(1)?,
            }
        }
        Entry::PolygonMode => {
            n(2)?;
            Command::PolygonMode {
                face: c.enm(0)?,
                mode: c.enm(1)?,
            }
        }
        Entry::CullFace => n(1).and(c.enm(0)).map(Command::CullFace)?,
        Entry::FrontFace => n(1).and(c.enm(0)).map(Command::FrontFace)?,
        Entry::LineWidth => n(1).and(c.f32(0)).map(Command::LineWidth)?,
        Entry::PointSize => n(1).and(c.f32(0)).map(Command::PointSize)?,
        Entry::Clear => n(1).and(clear_mask(c)).map(Command::Clear)?,
        Entry::ClearColor => n(4).and(c.vec4_args(0)).map(Command::ClearColor)?,
        Entry::ClearDepth => n(1).and(c.f64(0)).map(Command::ClearDepth)?,
        Entry::ClearStencil => n(1).and(c.i32(0)).map(Command::ClearStencil)?,
        Entry::ClearIndex => n(1).and(c.f32(0)).map(Command::ClearIndex)?,
        Entry::IndexMask => n(1).and(c.u32(0)).map(Command::IndexMask)?,
        // glSampleCoverage's GLboolean: any nonzero value inverts.
        Entry::SampleCoverage | Entry::SampleCoverageARB => {
            n(2)?;
            Command::SampleCoverage {
                value: c.f32(0)?,
                invert: c.boolean(1)?,
            }
        }
        Entry::ClearAccum => n(4).and(c.vec4_args(0)).map(Command::ClearAccum)?,
        Entry::Accum => n(2).and(c.enm(0)).and_then(|op| {
            let value = c.f32(1)?;
            Ok(Command::Accum { op, value })
        })?,
        Entry::ReadPixels => {
            n(7)?;
            // COLOR_INDEX is a format of GL 1.5, but an RGBA framebuffer holds no indices
            // to read: INVALID_OPERATION (Mesa measured alike), after a negative size's
            // INVALID_VALUE and a bad type's INVALID_ENUM (GL_BITMAP is a type of indices).
            if c.token(4)? == super::glenum::registry::COLOR_INDEX {
                let error = if c.i32(2)? < 0 || c.i32(3)? < 0 {
                    GlErrorKind::InvalidValue
                } else {
                    if c.token(5)? != super::glenum::registry::BITMAP {
                        let _: PixelType = c.enm(5)?;
                    }
                    GlErrorKind::InvalidOperation
                };
                return Ok(Some(Command::Raise {
                    error,
                    call: c.entry(),
                }));
            }
            let (format, ty) = (c.enm(4)?, c.enm(5)?);
            if let Some(refused) = pixel_types::refusal(c, format, ty) {
                return Ok(Some(refused));
            }
            Command::ReadPixels(ReadPixels {
                x: c.i32(0)?,
                y: c.i32(1)?,
                width: c.i32(2)?,
                height: c.i32(3)?,
                format,
                ty,
                slot: c.slot(6)?,
            })
        }
        _ => return Ok(None),
    }))
}

/// glLight's parameter names: the vectors, then the scalars.
pub(super) const LIGHT_PNAMES: &[&str] = &[
    "GL_AMBIENT",
    "GL_DIFFUSE",
    "GL_SPECULAR",
    "GL_POSITION",
    "GL_SPOT_DIRECTION",
    "GL_SPOT_EXPONENT",
    "GL_SPOT_CUTOFF",
    "GL_CONSTANT_ATTENUATION",
    "GL_LINEAR_ATTENUATION",
    "GL_QUADRATIC_ATTENUATION",
];
/// glMaterial's parameter names: the colours, the one scalar, and the colour-index
/// lighting's three indices.
pub(super) const MATERIAL_PNAMES: &[&str] = &[
    "GL_AMBIENT",
    "GL_DIFFUSE",
    "GL_AMBIENT_AND_DIFFUSE",
    "GL_SPECULAR",
    "GL_EMISSION",
    "GL_SHININESS",
    "GL_COLOR_INDEXES",
];

/// Lighting and materials.
pub fn lighting<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    Ok(Some(match c.entry() {
        Entry::Lightfv => {
            c.count(3)?;
            let light = c.family(0, Family::Light)?;
            let param = match c.pname(1, LIGHT_PNAMES)? {
                "GL_AMBIENT" => LightParam::Ambient(c.vec4_array(2)?),
                "GL_DIFFUSE" => LightParam::Diffuse(c.vec4_array(2)?),
                "GL_SPECULAR" => LightParam::Specular(c.vec4_array(2)?),
                "GL_POSITION" => LightParam::Position(c.vec4_array(2)?),
                "GL_SPOT_DIRECTION" => LightParam::SpotDirection(c.vec3_array(2)?),
                p => light_scalar(p, c.floats::<1>(2)?[0]),
            };
            Command::Light { light, param }
        }
        Entry::Lightf | Entry::Lighti => {
            c.count(3)?;
            let light = c.family(0, Family::Light)?;
            let pname = c.pname(1, LIGHT_PNAMES)?;
            let v = c.f32(2)?;
            // A vector parameter is (param, 0, 0, 0) (`first_of_four`); glLighti's colours
            // are then integers, mapped as glLightiv's.
            let color = || match c.entry() {
                Entry::Lighti => int_color_first(v),
                _ => first_of_four(v),
            };
            let param = match pname {
                "GL_AMBIENT" => LightParam::Ambient(color()),
                "GL_DIFFUSE" => LightParam::Diffuse(color()),
                "GL_SPECULAR" => LightParam::Specular(color()),
                "GL_POSITION" => LightParam::Position(first_of_four(v)),
                "GL_SPOT_DIRECTION" => LightParam::SpotDirection(first_of_four(v).truncate()),
                p => light_scalar(p, v),
            };
            Command::Light { light, param }
        }
        Entry::LightModelfv => {
            c.count(2)?;
            c.pname(0, &["GL_LIGHT_MODEL_AMBIENT"])?;
            Command::LightModel(LightModelParam::Ambient(c.vec4_array(1)?))
        }
        Entry::LightModeli | Entry::LightModelf => {
            c.count(2)?;
            let names = [
                "GL_LIGHT_MODEL_LOCAL_VIEWER",
                "GL_LIGHT_MODEL_TWO_SIDE",
                "GL_LIGHT_MODEL_COLOR_CONTROL",
                "GL_LIGHT_MODEL_AMBIENT",
            ];
            Command::LightModel(match c.pname(0, &names)? {
                "GL_LIGHT_MODEL_LOCAL_VIEWER" => LightModelParam::LocalViewer(c.boolean(1)?),
                "GL_LIGHT_MODEL_TWO_SIDE" => LightModelParam::TwoSide(c.boolean(1)?),
                "GL_LIGHT_MODEL_COLOR_CONTROL" => LightModelParam::ColorControl(c.enm(1)?),
                // (param, 0, 0, 0), as glLight's vector parameters above.
                _ => LightModelParam::Ambient(match c.entry() {
                    Entry::LightModeli => int_color_first(c.f32(1)?),
                    _ => first_of_four(c.f32(1)?),
                }),
            })
        }
        Entry::Materialfv => {
            c.count(3)?;
            let face = c.enm(0)?;
            let param = match c.pname(1, MATERIAL_PNAMES)? {
                "GL_SHININESS" => MaterialParam::Shininess(c.floats::<1>(2)?[0]),
                "GL_COLOR_INDEXES" => MaterialParam::ColorIndexes(c.vec3_array(2)?),
                p => material_vector(p, c.vec4_array(2)?),
            };
            Command::Material { face, param }
        }
        Entry::ColorMaterial => {
            c.count(2)?;
            Command::ColorMaterial {
                face: c.enm(0)?,
                mode: c.enm(1)?,
            }
        }
        Entry::ShadeModel => c.count(1).and(c.enm(0)).map(Command::ShadeModel)?,
        _ => return Ok(None),
    }))
}

/// A vector parameter given through a scalar form (glLightf, glLightModelf, glTexGenf,
/// glTexEnvf, glFogf and their integer forms): Mesa passes the value on as the first of
/// four, the rest 0 (measured; GL 1.5 names only the scalars there).
pub(super) fn first_of_four(v: f32) -> glam::Vec4 {
    glam::Vec4::new(v, 0.0, 0.0, 0.0)
}

/// [`first_of_four`] as a colour of four signed integers, mapped as GL 1.5 Table 2.9 maps
/// them: (2c + 1)/(2³² − 1), so 0 is not quite 0 (Mesa's glLighti and glLightModeli).
fn int_color_first(v: f32) -> glam::Vec4 {
    first_of_four(v)
        .as_dvec4()
        .to_array()
        .map(|k| CType::Int.normalized(k))
        .into()
}

pub(super) fn light_scalar(pname: &str, v: f32) -> LightParam {
    match pname {
        "GL_SPOT_EXPONENT" => LightParam::SpotExponent(v),
        "GL_SPOT_CUTOFF" => LightParam::SpotCutoff(v),
        "GL_CONSTANT_ATTENUATION" => LightParam::ConstantAttenuation(v),
        "GL_LINEAR_ATTENUATION" => LightParam::LinearAttenuation(v),
        _ => LightParam::QuadraticAttenuation(v),
    }
}

pub(super) fn material_vector(pname: &str, v: glam::Vec4) -> MaterialParam {
    match pname {
        "GL_AMBIENT" => MaterialParam::Ambient(v),
        "GL_DIFFUSE" => MaterialParam::Diffuse(v),
        "GL_AMBIENT_AND_DIFFUSE" => MaterialParam::AmbientAndDiffuse(v),
        "GL_SPECULAR" => MaterialParam::Specular(v),
        _ => MaterialParam::Emission(v),
    }
}

const TEX_PARAMS: &[&str] = &[
    "GL_TEXTURE_MIN_FILTER",
    "GL_TEXTURE_MAG_FILTER",
    "GL_TEXTURE_WRAP_S",
    "GL_TEXTURE_WRAP_T",
    "GL_TEXTURE_WRAP_R",
    "GL_TEXTURE_COMPARE_MODE",
    "GL_TEXTURE_COMPARE_FUNC",
    "GL_DEPTH_TEXTURE_MODE",
    "GL_TEXTURE_COMPARE_FAIL_VALUE_ARB",
    "GL_GENERATE_MIPMAP",
    "GL_TEXTURE_BASE_LEVEL",
    "GL_TEXTURE_MAX_LEVEL",
    "GL_TEXTURE_MIN_LOD",
    "GL_TEXTURE_MAX_LOD",
    "GL_TEXTURE_LOD_BIAS",
    "GL_TEXTURE_PRIORITY",
    "GL_TEXTURE_MAX_ANISOTROPY_EXT",
];

const ENV_PARAMS: &[&str] = &[
    "GL_TEXTURE_ENV_MODE",
    "GL_COMBINE_RGB",
    "GL_COMBINE_ALPHA",
    "GL_SOURCE0_RGB",
    "GL_SOURCE1_RGB",
    "GL_SOURCE2_RGB",
    "GL_SOURCE0_ALPHA",
    "GL_SOURCE1_ALPHA",
    "GL_SOURCE2_ALPHA",
    "GL_OPERAND0_RGB",
    "GL_OPERAND1_RGB",
    "GL_OPERAND2_RGB",
    "GL_OPERAND0_ALPHA",
    "GL_OPERAND1_ALPHA",
    "GL_OPERAND2_ALPHA",
    "GL_RGB_SCALE",
    "GL_ALPHA_SCALE",
    // GL 1.5 spellings.
    "GL_SRC0_RGB",
    "GL_SRC1_RGB",
    "GL_SRC2_RGB",
    "GL_SRC0_ALPHA",
    "GL_SRC1_ALPHA",
    "GL_SRC2_ALPHA",
];

/// Texture units, objects, images, parameters, texgen and texenv.
pub fn texturing<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    Ok(Some(match c.entry() {
        Entry::ActiveTexture | Entry::ActiveTextureARB => c
            .count(1)
            .and(c.family(0, Family::Texture))
            .map(Command::ActiveTexture)?,
        Entry::DeleteTextures => {
            c.count(2)?;
            let n = c.i32(0)?;
            if n < 0 {
                return Err(c.bad(0, "a count of 0 or more"));
            }
            let names = c.array_as(1, n as usize, CType::UInt)?;
            Command::DeleteTextures(names.into_iter().map(|v| v as u32).collect())
        }
        Entry::BindTexture => {
            c.count(2)?;
            Command::BindTexture {
                target: bindable_target(c)?,
                name: c.u32(1)?,
            }
        }
        Entry::TexImage1D => {
            c.count(8)?;
            let proxy = c.pname(0, &["GL_PROXY_TEXTURE_1D"]).is_ok();
            if !proxy {
                target_is(c, TextureTarget::Texture1D)?;
            }
            let shape =
                super::index_pixels::image_shape(c, (c.i32(3)?, 1, None), 5, LsbFirst::Honoured)?;
            if let Some(refused) = pixel_types::refusal(c, shape.format, shape.ty) {
                return Ok(Some(refused));
            }
            let (format, ty, data) = pixel_types::model_tex_data(c, 7, shape)?;
            tex_image_or_proxy(
                proxy,
                1,
                TexImage {
                    requested: requested_format(c, 2),
                    target: TextureTarget::Texture1D,
                    level: c.i32(1)?,
                    internal_format: internal_format(c, 2)?,
                    width: shape.width,
                    height: 1,
                    depth: 1,
                    border: c.i32(4)?,
                    format,
                    ty,
                    data,
                },
            )
        }
        Entry::TexImage2D => {
            c.count(9)?;
            // A proxy names the target it stands for (GL 1.5 §3.8.11).
            let proxied = match c.pname(0, &["GL_PROXY_TEXTURE_2D", "GL_PROXY_TEXTURE_CUBE_MAP"]) {
                Ok("GL_PROXY_TEXTURE_2D") => Some(TextureTarget::Texture2D),
                Ok(_) => Some(TextureTarget::CubeMap),
                Err(_) => None,
            };
            let target = match proxied {
                Some(t) => t,
                None => image_2d_target(c)?,
            };
            let shape = super::index_pixels::image_shape(
                c,
                (c.i32(3)?, c.i32(4)?, None),
                6,
                LsbFirst::Honoured,
            )?;
            if let Some(refused) = pixel_types::refusal(c, shape.format, shape.ty) {
                return Ok(Some(refused));
            }
            let (format, ty, data) = pixel_types::model_tex_data(c, 8, shape)?;
            tex_image_or_proxy(
                proxied.is_some(),
                2,
                TexImage {
                    requested: requested_format(c, 2),
                    target,
                    level: c.i32(1)?,
                    internal_format: internal_format(c, 2)?,
                    width: shape.width,
                    height: shape.height,
                    depth: 1,
                    border: c.i32(5)?,
                    format,
                    ty,
                    data,
                },
            )
        }
        Entry::TexSubImage2D => {
            c.count(9)?;
            let target = image_2d_target(c)?;
            if let Some(refused) = super::texture_calls::sub_image_refusal(c, target, &[4, 5])? {
                return Ok(Some(refused));
            }
            let face = target.face();
            let shape = super::index_pixels::image_shape(
                c,
                (c.i32(4)?, c.i32(5)?, None),
                6,
                LsbFirst::Honoured,
            )?;
            if let Some(refused) = pixel_types::refusal(c, shape.format, shape.ty) {
                return Ok(Some(refused));
            }
            let (format, ty, data) = pixel_types::model_sub_texels(c, 8, shape)?;
            Command::TexSubImage2D(TexSubImage {
                face,
                level: c.i32(1)?,
                x: c.i32(2)?,
                y: c.i32(3)?,
                z: 0,
                width: shape.width,
                height: shape.height,
                depth: 1,
                format,
                ty,
                data,
            })
        }
        Entry::CopyTexImage2D => {
            c.count(8)?;
            let face = image_2d_target(c)?.face();
            let copy = CopyTexImage {
                face,
                requested: requested_format(c, 2),
                level: c.i32(1)?,
                // A component count is INVALID_ENUM here on Mesa 22.3 (tests/c/formats.c).
                internal_format: c.enm(2)?,
                x: c.i32(3)?,
                y: c.i32(4)?,
                width: c.i32(5)?,
                height: c.i32(6)?,
                border: c.i32(7)?,
            };
            Command::CopyTexImage2D(super::texture_border::strip_copy(copy, 2))
        }
        Entry::TexParameteri | Entry::TexParameterf => {
            c.count(3)?;
            Command::TexParameter {
                target: bindable_target(c)?,
                param: tex_param(c)?,
            }
        }
        Entry::TexParameterfv => {
            c.count(3)?;
            c.pname(1, &["GL_TEXTURE_BORDER_COLOR"])?;
            Command::TexParameter {
                target: bindable_target(c)?,
                param: TexParam::BorderColor(c.vec4_array(2)?),
            }
        }
        Entry::TexGeni | Entry::TexGenf | Entry::TexGend => {
            c.count(3)?;
            let pname = c.pname(
                1,
                &["GL_TEXTURE_GEN_MODE", "GL_OBJECT_PLANE", "GL_EYE_PLANE"],
            )?;
            let coord = c.enm(0)?;
            // A plane is (param, 0, 0, 0) (`first_of_four`; an eye plane is then carried by
            // the inverse modelview as ever).
            let plane = || c.f32(2).map(first_of_four);
            let param = match pname {
                "GL_OBJECT_PLANE" => TexGenParam::ObjectPlane(plane()?),
                "GL_EYE_PLANE" => TexGenParam::EyePlane(plane()?),
                _ => TexGenParam::Mode(c.enm(2)?),
            };
            Command::TexGen { coord, param }
        }
        Entry::TexGenfv | Entry::TexGendv | Entry::TexGeniv => {
            c.count(3)?;
            let coord = c.enm(0)?;
            let plane = c.vec4_array(2)?;
            let param = match c.pname(1, &["GL_OBJECT_PLANE", "GL_EYE_PLANE"])? {
                "GL_OBJECT_PLANE" => TexGenParam::ObjectPlane(plane),
                _ => TexGenParam::EyePlane(plane),
            };
            Command::TexGen { coord, param }
        }
        Entry::TexEnvi | Entry::TexEnvf => {
            c.count(3)?;
            // TEXTURE_ENV_COLOR is (param, 0, 0, 0) (`first_of_four`), glTexEnvi's integer
            // taken as a number, as Mesa takes it (measured: 2 is then clamped to 1).
            let env = c.pname(0, &["GL_TEXTURE_ENV"]).is_ok();
            if env && c.pname(1, &["GL_TEXTURE_ENV_COLOR"]).is_ok() {
                let color = first_of_four(c.f32(2)?);
                return Ok(Some(Command::TexEnv(TexEnvParam::Color(color))));
            }
            Command::TexEnv(env_scalar(c)?)
        }
        Entry::TexEnvfv => {
            c.count(3)?;
            c.pname(0, &["GL_TEXTURE_ENV"])?;
            c.pname(1, &["GL_TEXTURE_ENV_COLOR"])?;
            Command::TexEnv(TexEnvParam::Color(c.vec4_array(2)?))
        }
        _ => return Ok(None),
    }))
}

/// Argument 0 of a 2D image call: TEXTURE_2D or a cube map face (GL 1.3); TEXTURE_CUBE_MAP
/// itself is not an image target (INVALID_ENUM, as Mesa).
pub(crate) fn image_2d_target<A: Args>(c: &A) -> Result<TextureTarget, A::Error> {
    let t: TextureTarget = c.enm(0)?;
    match t {
        TextureTarget::Texture2D | TextureTarget::CubeFace(_) => Ok(t),
        // The names from the enum's own table, 2D first, then the faces in order.
        _ => Err(c.unknown(
            0,
            std::iter::once(TextureTarget::Texture2D)
                .chain(CubeFace::ALL.map(TextureTarget::CubeFace))
                .filter_map(GlEnum::gl_name)
                .collect(),
        )),
    }
}

/// A glTexImage of its target, or (`proxy`) of the proxy standing for it.
/// The command of a glTexImage of `dims` dimensions: a proxy keeps its border, an image
/// has it stripped (`texture_border`).
fn tex_image_or_proxy(proxy: bool, dims: usize, image: TexImage) -> Command {
    if proxy {
        Command::ProxyTexImage(image)
    } else {
        Command::TexImage(super::texture_border::strip_image(image, dims))
    }
}

/// Argument 0 of glBindTexture and glTexParameter: a bindable target (a cube face is
/// INVALID_ENUM, as Mesa).
fn bindable_target<A: Args>(c: &A) -> Result<TextureTarget, A::Error> {
    let t: TextureTarget = c.enm(0)?;
    if t.face().is_some() {
        return Err(c.unknown(
            0,
            TextureTarget::ALL
                .iter()
                .filter_map(|t| t.gl_name())
                .collect(),
        ));
    }
    Ok(t)
}

fn target_is<A: Args>(c: &A, want: TextureTarget) -> Result<(), A::Error> {
    let t: TextureTarget = c.enm(0)?;
    if t == want {
        Ok(())
    } else {
        Err(c.unknown(0, vec![want.gl_name().unwrap_or("GL_TEXTURE_2D")]))
    }
}

/// A glTexImage internal format: a token, or GL 1.0's component count 1, 2, 3 or 4
/// (LUMINANCE, LUMINANCE_ALPHA, RGB, RGBA); one that names none is INVALID_VALUE for a C
/// caller (Mesa's `_mesa_base_tex_format` check, measured for glTexImage2D and
/// glTexImage3D), the list of formats for a script.
pub(super) fn internal_format<A: Args>(c: &A, i: usize) -> Result<TexFormat, A::Error> {
    c.enm(i).or_else(|e| {
        component_count(c, i).ok_or_else(|| match c.deferred(&e) {
            Some(_) => c.bad(i, "a texture internal format"),
            None => e,
        })
    })
}

/// GL 1.0's internal formats by component count: 1 LUMINANCE, 2 LUMINANCE_ALPHA, 3 RGB,
/// 4 RGBA.
/// The internal format as the program named it (TEXTURE_INTERNAL_FORMAT answers it, as
/// Mesa does): a component count 1–4, or the token; `None` when it is the sized format's
/// own name (GL_RGBA8), which the level answers anyway.
pub(super) fn requested_format<A: Args>(c: &A, i: usize) -> Option<u32> {
    let named = match c.int(i) {
        Ok(v @ 1..=4) => Some(v as u32),
        _ => c.token(i).ok(),
    };
    let sized = internal_format(c, i).ok().and_then(|f| f.gl_value());
    named.filter(|v| Some(*v) != sized)
}

fn component_count<A: Args>(c: &A, i: usize) -> Option<TexFormat> {
    match c.int(i) {
        Ok(1) => Some(TexFormat::Luminance8),
        Ok(2) => Some(TexFormat::Luminance8Alpha8),
        Ok(3) => Some(TexFormat::Rgb8),
        Ok(4) => Some(TexFormat::Rgba8),
        _ => None,
    }
}

/// A scalar glTexEnv: of target TEXTURE_ENV any of its parameters, of TEXTURE_FILTER_CONTROL
/// (GL 1.4) only TEXTURE_LOD_BIAS, of POINT_SPRITE (ARB_point_sprite) only COORD_REPLACE;
/// anything else INVALID_ENUM.
pub(super) fn env_scalar<A: Args>(c: &A) -> Result<TexEnvParam, A::Error> {
    match c.pname(
        0,
        &[
            "GL_TEXTURE_ENV",
            "GL_TEXTURE_FILTER_CONTROL",
            "GL_POINT_SPRITE",
        ],
    )? {
        "GL_TEXTURE_ENV" => tex_env(c),
        "GL_TEXTURE_FILTER_CONTROL" => {
            c.pname(1, &["GL_TEXTURE_LOD_BIAS"])?;
            Ok(TexEnvParam::LodBias(c.f32(2)?))
        }
        _ => {
            c.pname(1, &["GL_COORD_REPLACE"])?;
            // Mesa converts the value to an integer as C does (truncating: 0.5 is FALSE)
            // and takes TRUE or FALSE only; anything else is INVALID_VALUE (measured). A
            // script may write it as a token (GL_TRUE) or a number.
            let value = match c.token(2) {
                Ok(token) => f64::from(token),
                Err(_) => c.f64(2)?.trunc(),
            };
            if value == 0.0 || value == 1.0 {
                Ok(TexEnvParam::CoordReplace(value == 1.0))
            } else {
                Err(c.bad(2, "GL_TRUE or GL_FALSE"))
            }
        }
    }
}

pub(super) fn tex_param<A: Args>(c: &A) -> Result<TexParam, A::Error> {
    // A level or a boolean given as a float converts as the call converts a token
    // (glTexParameterf rounds, glTexParameterfv truncates).
    let integral = |v: f64| -> i32 {
        let rule = super::float_token::FloatToken::of(c.entry());
        level_from_float(rule.integer(v).unwrap_or(f64::NAN))
    };
    Ok(match c.pname(1, TEX_PARAMS)? {
        "GL_TEXTURE_MIN_FILTER" => TexParam::MinFilter(c.enm(2)?),
        "GL_TEXTURE_MAG_FILTER" => TexParam::MagFilter(c.enm(2)?),
        "GL_TEXTURE_WRAP_S" => TexParam::WrapS(c.enm(2)?),
        "GL_TEXTURE_WRAP_T" => TexParam::WrapT(c.enm(2)?),
        "GL_TEXTURE_WRAP_R" => TexParam::WrapR(c.enm(2)?),
        "GL_TEXTURE_COMPARE_MODE" => TexParam::CompareMode(c.enm(2)?),
        "GL_TEXTURE_COMPARE_FUNC" => TexParam::CompareFunc(c.enm(2)?),
        "GL_DEPTH_TEXTURE_MODE" => TexParam::DepthTextureMode(c.enm(2)?),
        "GL_TEXTURE_COMPARE_FAIL_VALUE_ARB" => TexParam::CompareFailValue(c.f32(2)?),
        "GL_TEXTURE_BASE_LEVEL" => TexParam::BaseLevel(integral(c.f64(2)?)),
        "GL_TEXTURE_MAX_LEVEL" => TexParam::MaxLevel(integral(c.f64(2)?)),
        "GL_TEXTURE_MIN_LOD" => TexParam::MinLod(c.f32(2)?),
        "GL_TEXTURE_MAX_LOD" => TexParam::MaxLod(c.f32(2)?),
        "GL_TEXTURE_LOD_BIAS" => TexParam::LodBias(c.f32(2)?),
        "GL_TEXTURE_PRIORITY" => TexParam::Priority(c.f32(2)?),
        "GL_TEXTURE_MAX_ANISOTROPY_EXT" => TexParam::MaxAnisotropy(c.f32(2)?),
        // A float is TRUE when its converted integer is not 0 (glTexParameterf(…, 0.25) is
        // FALSE on Mesa 22.3).
        _ => TexParam::GenerateMipmap(match c.entry() {
            Entry::TexParameterf | Entry::TexParameterfv => integral(c.f64(2)?) != 0,
            _ => c.boolean(2)?,
        }),
    })
}

pub(super) fn tex_env<A: Args>(c: &A) -> Result<TexEnvParam, A::Error> {
    let pname = c.pname(1, ENV_PARAMS)?;
    // GL_SOURCE1_RGB, GL_SRC1_ALPHA, GL_OPERAND2_RGB: the first digit is the argument.
    let digit_arg = |p: &str| {
        let d = p.bytes().find(|b| b.is_ascii_digit());
        match d {
            Some(b'0') => CombineArg::Arg0,
            Some(b'1') => CombineArg::Arg1,
            _ => CombineArg::Arg2,
        }
    };
    let source = || -> Result<CombineSource, A::Error> {
        if let Ok(u) = c.family(2, Family::Texture) {
            return Ok(CombineSource::TextureUnit(u));
        }
        c.enm(2)
    };
    Ok(match pname {
        "GL_TEXTURE_ENV_MODE" => TexEnvParam::Mode(c.enm(2)?),
        "GL_COMBINE_RGB" => TexEnvParam::CombineRgb(c.enm(2)?),
        "GL_COMBINE_ALPHA" => TexEnvParam::CombineAlpha(c.enm(2)?),
        "GL_RGB_SCALE" => TexEnvParam::RgbScale(c.f32(2)?),
        "GL_ALPHA_SCALE" => TexEnvParam::AlphaScale(c.f32(2)?),
        p if p.starts_with("GL_OPERAND") && p.ends_with("_RGB") => {
            TexEnvParam::OperandRgb(digit_arg(p), c.enm(2)?)
        }
        p if p.starts_with("GL_OPERAND") => TexEnvParam::OperandAlpha(digit_arg(p), c.enm(2)?),
        p if p.ends_with("_RGB") => TexEnvParam::SourceRgb(digit_arg(p), source()?),
        p => TexEnvParam::SourceAlpha(digit_arg(p), source()?),
    })
}

fn register<A: Args>(c: &A, i: usize) -> Result<Register, A::Error> {
    if let Ok(u) = c.family(i, Family::Texture) {
        return Ok(Register::Texture(u));
    }
    c.enm(i)
}

fn input<A: Args>(c: &A, from: usize) -> Result<CombinerInput, A::Error> {
    Ok(CombinerInput {
        register: register(c, from)?,
        mapping: c.enm(from + 1)?,
        usage: c.enm(from + 2)?,
    })
}

/// NV_register_combiners.
pub fn combiners<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    Ok(Some(match c.entry() {
        Entry::CombinerParameteriNV => {
            c.count(2)?;
            Command::CombinerParameter(
                match c.pname(0, &["GL_NUM_GENERAL_COMBINERS_NV", "GL_COLOR_SUM_CLAMP_NV"])? {
                    "GL_NUM_GENERAL_COMBINERS_NV" => CombinerParam::NumGeneralCombiners(c.i32(1)?),
                    _ => CombinerParam::ColorSumClamp(c.boolean(1)?),
                },
            )
        }
        Entry::CombinerParameterfvNV => {
            c.count(2)?;
            let v = c.vec4_array(1)?;
            Command::CombinerParameter(
                match c.pname(0, &["GL_CONSTANT_COLOR0_NV", "GL_CONSTANT_COLOR1_NV"])? {
                    "GL_CONSTANT_COLOR0_NV" => CombinerParam::ConstantColor0(v),
                    _ => CombinerParam::ConstantColor1(v),
                },
            )
        }
        Entry::CombinerInputNV => {
            c.count(6)?;
            Command::CombinerInput {
                stage: c.family(0, Family::Combiner)?,
                portion: c.enm(1)?,
                variable: c.enm(2)?,
                input: input(c, 3)?,
            }
        }
        Entry::CombinerOutputNV => {
            c.count(10)?;
            Command::CombinerOutput {
                stage: c.family(0, Family::Combiner)?,
                portion: c.enm(1)?,
                output: CombinerOutput {
                    ab: register(c, 2)?,
                    cd: register(c, 3)?,
                    sum: register(c, 4)?,
                    scale: c.enm(5)?,
                    bias: c.enm(6)?,
                    ab_product: c.enm(7)?,
                    cd_product: c.enm(8)?,
                    sum_or_mux: c.enm(9)?,
                },
            }
        }
        Entry::FinalCombinerInputNV => {
            c.count(4)?;
            Command::FinalCombinerInput {
                variable: c.enm(0)?,
                input: input(c, 1)?,
            }
        }
        _ => return Ok(None),
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ff::buffers::Buffers;
    use crate::ff::client::ClientArrays;

    /// Every direct call is one the front end's routing passes through unchanged: no
    /// front-end state answers it, it is no vertex call, enable (client arrays), list or
    /// framebuffer-name call, and it returns nothing.
    #[test]
    fn direct_calls_route_nowhere_else() {
        let direct: Vec<Entry> = Entry::ALL.iter().copied().filter(|e| direct(*e)).collect();
        assert_eq!(direct.len(), 33);
        for e in direct {
            assert!(
                !crate::ff::front_state::handles(e),
                "{e:?}: front-end state"
            );
            assert!(!Buffers::handles(e), "{e:?}: buffer objects");
            assert!(!ClientArrays::handles(e), "{e:?}: client arrays");
            assert!(e.attrib_call().is_none(), "{e:?}: a vertex attribute");
            assert!(
                !crate::ff::framebuffer::answered_by_front_end(e),
                "{e:?}: framebuffer names"
            );
            assert_eq!(e.return_type(), "void", "{e:?}: a reply");
            assert!(
                !matches!(
                    e,
                    Entry::Begin
                        | Entry::End
                        | Entry::EdgeFlag
                        | Entry::EdgeFlagv
                        | Entry::Enable
                        | Entry::Disable
                        | Entry::NewList
                        | Entry::EndList
                        | Entry::GenLists
                        | Entry::DeleteLists
                        | Entry::IsList
                        | Entry::CallList
                        | Entry::CallLists
                        | Entry::ListBase
                ),
                "{e:?}: routed by the front end"
            );
        }
    }
}
