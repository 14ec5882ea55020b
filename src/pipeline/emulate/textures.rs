//! GL texture objects behind the model's texture names. After the model accepts a texture
//! command, the affected object is brought up to date from the model: level images
//! (legacy formats as R8/RG8 + swizzle, see `conv::tex_format`), parameters, and copies
//! from the bound framebuffer. Draws bind the objects the enabled units use.

use std::collections::HashMap;

use glow::HasContext;

use super::conv;
use crate::ff::{
    CompareMode, FixedState, TexLevel, TextureObject, TextureTarget, MAX_TEXTURE_LOD_BIAS,
};
use crate::pipeline::PipelineError;

/// Our key for a GL texture: (target, model name). Name 0 is each target's default texture.
/// A cube face's key is its cube map's (`TextureTarget::binding`).
type TextureId = (TextureTarget, u32);

/// The GL target an object is bound to.
fn gl_target(t: TextureTarget) -> u32 {
    match t {
        TextureTarget::Texture1D => glow::TEXTURE_1D,
        TextureTarget::Texture2D => glow::TEXTURE_2D,
        TextureTarget::Texture3D => glow::TEXTURE_3D,
        TextureTarget::CubeMap | TextureTarget::CubeFace(_) => glow::TEXTURE_CUBE_MAP,
    }
}

/// The GL target an image call names: a cube face's own, else the object's.
pub(super) fn gl_image_target(t: TextureTarget) -> u32 {
    match t {
        TextureTarget::CubeFace(f) => glow::TEXTURE_CUBE_MAP_POSITIVE_X + f.index() as u32,
        t => gl_target(t),
    }
}

#[derive(Default)]
pub struct Textures {
    objects: HashMap<TextureId, glow::Texture>,
    /// What is bound on each image unit, to skip redundant binds.
    bound: HashMap<u8, (TextureTarget, glow::Texture)>,
    /// The TEXTURE_LOD_BIAS each GL object was last given (absent: 0).
    lod_bias: HashMap<glow::Texture, f32>,
    pub uploads: u64,
    pub binds_skipped: u64,
}

impl Textures {
    fn object(
        &mut self,
        gl: &glow::Context,
        id: TextureId,
    ) -> Result<glow::Texture, PipelineError> {
        let id = (id.0.binding(), id.1);
        if let Some(t) = self.objects.get(&id) {
            return Ok(*t);
        }
        let t = unsafe { gl.create_texture() }.map_err(PipelineError::Object)?;
        self.objects.insert(id, t);
        Ok(t)
    }

    /// The GL name of the object for (target, model name), made if it is not yet.
    /// A name glGenTextures gave is an object only once bound: it is bound here on the
    /// scratch unit, so that a framebuffer can attach it.
    pub fn gl_name(&mut self, gl: &glow::Context, target: TextureTarget, name: u32) -> Option<u32> {
        self.edit(gl, (target, name)).ok()?;
        self.objects
            .get(&(target.binding(), name))
            .map(|t| t.0.get())
    }

    /// glGenerateMipmap of the active unit's texture bound to `target`.
    pub fn generate_mipmap(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        target: TextureTarget,
    ) -> Result<(), PipelineError> {
        let name = state.units[state.active_unit()].bound(target);
        let gl_t = self.edit(gl, (target, name))?;
        // MAX_LEVEL first: the model now holds levels 1…p, and GL generates only up to
        // MAX_LEVEL, which was the base level's when it was uploaded.
        if let Some(object) = state.texture(target, name) {
            apply_params(gl, gl_t, object);
        }
        unsafe { gl.generate_mipmap(gl_t) };
        Ok(())
    }

    /// Deletes the GL objects of these model names (the model has reverted the units bound
    /// to them to texture 0; draws bind from the model).
    pub fn delete(&mut self, gl: &glow::Context, names: &[u32]) {
        for name in names.iter().filter(|n| **n != 0) {
            for target in TextureTarget::ALL {
                if let Some(t) = self.objects.remove(&(target, *name)) {
                    self.bound.retain(|_, (_, b)| *b != t);
                    self.lod_bias.remove(&t);
                    unsafe { gl.delete_texture(t) };
                }
            }
        }
    }

    /// Binds the GL object for `id` on a scratch unit (the last one) for editing.
    pub(super) fn edit(&mut self, gl: &glow::Context, id: TextureId) -> Result<u32, PipelineError> {
        let t = self.object(gl, id)?;
        let target = gl_target(id.0);
        unsafe {
            gl.active_texture(glow::TEXTURE0 + SCRATCH_UNIT);
            gl.bind_texture(target, Some(t));
        }
        self.bound.remove(&(SCRATCH_UNIT as u8));
        Ok(target)
    }

    /// Uploads level `level` of the texture bound to `target` on the active unit.
    pub fn upload_level(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        target: TextureTarget,
        level: i32,
    ) -> Result<(), PipelineError> {
        let name = state.units[state.active_unit()].bound(target);
        let Some(object) = state.texture(target, name) else {
            return Ok(());
        };
        let Some(l) = object.level_in(target, level) else {
            return Ok(());
        };
        let gl_t = self.edit(gl, (target, name))?;
        upload(gl, gl_image_target(target), level, l, state);
        apply_params(gl, gl_t, object);
        generate_mipmap(gl, gl_t, object, level);
        self.uploads += 1;
        Ok(())
    }

    /// glTexSubImage2D (or glTexSubImage3D) into the active unit's 2D (3D) texture,
    /// straight from the command's bytes.
    pub fn sub_image(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        target: TextureTarget,
        t: &crate::ff::TexSubImage,
    ) -> Result<(), PipelineError> {
        let name = state.units[state.active_unit()].bound(target);
        let gl_t = self.edit(gl, (target, name))?;
        // NULL: no texel changes; a base level's mipmaps are derived again all the same.
        let Some(given) = &t.data else {
            if let Some(object) = state.texture(target, name) {
                generate_mipmap(gl, gl_t, object, t.level);
            }
            return Ok(());
        };
        let stored = super::texture_calls::stored_sub_image(state, target, name, t);
        let ((format, ty), bytes) = match &stored {
            Some((format, bytes)) => (*format, &bytes[..]),
            None => (
                (conv::pixel_format(t.format), conv::value(t.ty)),
                &given[..],
            ),
        };
        let data = glow::PixelUnpackData::Slice(Some(bytes));
        unsafe {
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
            match target {
                TextureTarget::Texture3D => gl.tex_sub_image_3d(
                    gl_t, t.level, t.x, t.y, t.z, t.width, t.height, t.depth, format, ty, data,
                ),
                _ => gl.tex_sub_image_2d(
                    gl_image_target(target),
                    t.level,
                    t.x,
                    t.y,
                    t.width,
                    t.height,
                    format,
                    ty,
                    data,
                ),
            }
        }
        if let Some(object) = state.texture(target, name) {
            generate_mipmap(gl, gl_t, object, t.level);
        }
        self.uploads += 1;
        Ok(())
    }

    /// glCopyTexImage2D from the bound read framebuffer into the active unit's 2D texture:
    /// a core copy where it keeps what GL keeps, else the rectangle read, transferred and
    /// stored on the CPU (`texel_store`; a core copy into ALPHA8's R8 would take red).
    pub fn copy_level(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        copy: &crate::ff::CopyTexImage,
    ) -> Result<(), PipelineError> {
        use crate::ff::texture::BaseFormat;
        let target = copy.target_2d();
        let name = state.units[state.active_unit()].bound(target);
        let f = copy.internal_format;
        let through_cpu = !f.is_depth()
            && (!state.pixel_transfer.colour_identity()
                || matches!(f.base(), BaseFormat::Alpha | BaseFormat::LuminanceAlpha));
        let rect = [copy.x, copy.y, copy.width, copy.height];
        let bytes = through_cpu.then(|| super::texture_calls::read_as_stored(gl, state, rect, f));
        let gl_t = self.edit(gl, (target, name))?;
        let internal = conv::stored_format(f, copy.requested);
        unsafe {
            match &bytes {
                Some(b) => {
                    let (format, ty, _) = super::texel_store::storage(f);
                    gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
                    gl.tex_image_2d(
                        gl_image_target(target),
                        copy.level,
                        internal as i32,
                        copy.width,
                        copy.height,
                        0,
                        format,
                        ty,
                        glow::PixelUnpackData::Slice(Some(b)),
                    );
                }
                None => gl.copy_tex_image_2d(
                    gl_image_target(target),
                    copy.level,
                    internal,
                    copy.x,
                    copy.y,
                    copy.width,
                    copy.height,
                    0,
                ),
            }
        }
        if let Some(object) = state.texture(target, name) {
            apply_params(gl, gl_t, object);
            generate_mipmap(gl, gl_t, object, copy.level);
        }
        self.uploads += 1;
        Ok(())
    }

    /// Re-sends every parameter of the active unit's `target` texture.
    pub fn sync_params(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        target: TextureTarget,
    ) -> Result<(), PipelineError> {
        let name = state.units[state.active_unit()].bound(target);
        if let Some(object) = state.texture(target, name) {
            let gl_t = self.edit(gl, (target, name))?;
            apply_params(gl, gl_t, object);
        }
        Ok(())
    }

    /// Re-sends the parameters of every texture bound on any unit that has a GL object:
    /// after glPopAttrib(TEXTURE_BIT) wrote saved parameters back into those objects.
    pub fn sync_bound_params(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
    ) -> Result<(), PipelineError> {
        for unit in &state.units {
            for target in TextureTarget::ALL {
                let id = (target, unit.bound(target));
                if let (true, Some(object)) =
                    (self.objects.contains_key(&id), state.texture(id.0, id.1))
                {
                    let gl_t = self.edit(gl, id)?;
                    apply_params(gl, gl_t, object);
                }
            }
        }
        Ok(())
    }

    /// Binds the textures of the enabled units before a draw.
    pub fn bind_units(
        &mut self,
        gl: &glow::Context,
        state: &FixedState,
        units: &[(u8, TextureTarget)],
    ) -> Result<(), PipelineError> {
        for &(unit, target) in units {
            let name = state.units[unit as usize].bound(target);
            let t = self.object(gl, (target, name))?;
            // The unit's TEXTURE_LOD_BIAS (GL 1.4) plus the object's, given to the core
            // object as its own bias. Mesa clamps each to ±MAX_TEXTURE_LOD_BIAS before
            // adding them (`util_quantize_lod_bias`; GL 1.4 §3.8.8 clamps the sum: object
            // bias 20 and unit bias −17 sample level 0 on Mesa, measured) and passes the sum
            // to llvmpipe's sampler the same way, a NaN as NaN (λ NaN reads as
            // magnification there and here). A texture bound on two units of different
            // biases takes the later unit's.
            let clamped = |b: f32| b.clamp(-MAX_TEXTURE_LOD_BIAS, MAX_TEXTURE_LOD_BIAS);
            let own = state
                .texture(target, name)
                .map_or(0.0, |o| o.params.lod_bias);
            let bias = clamped(state.units[unit as usize].env.lod_bias) + clamped(own);
            let new_bias =
                self.lod_bias.get(&t).copied().unwrap_or(0.0).to_bits() != bias.to_bits();
            if !new_bias && self.bound.get(&unit) == Some(&(target, t)) {
                self.binds_skipped += 1;
                continue;
            }
            unsafe {
                gl.active_texture(glow::TEXTURE0 + u32::from(unit));
                gl.bind_texture(gl_target(target), Some(t));
                if new_bias {
                    gl.tex_parameter_f32(gl_target(target), glow::TEXTURE_LOD_BIAS, bias);
                }
            }
            if new_bias {
                self.lod_bias.insert(t, bias);
            }
            self.bound.insert(unit, (target, t));
        }
        Ok(())
    }

    pub fn release(&mut self, gl: &glow::Context) {
        for (_, t) in self.objects.drain() {
            unsafe { gl.delete_texture(t) };
        }
        self.bound.clear();
        self.lod_bias.clear();
    }
}

/// The unit used to edit textures outside draws (never a fixed-function unit).
const SCRATCH_UNIT: u32 = 15;

/// Level `level` of `l`, its client bytes converted where the storage would hold
/// something else (`texel_store`, under the state's pixel transfer).
fn upload(gl: &glow::Context, target: u32, level: i32, l: &TexLevel, state: &FixedState) {
    let internal = conv::stored_format(l.internal_format, l.requested);
    let stored = l.data.as_ref().and_then(|d| {
        super::texel_store::stored_image(
            &d.bytes,
            d.format,
            d.ty,
            l.internal_format,
            &state.pixel_transfer,
            &state.pixel_maps,
        )
    });
    let (format, ty, bytes) = match (&l.data, &stored) {
        (Some(_), Some(b)) => {
            let (format, ty, _) = super::texel_store::storage(l.internal_format);
            (format, ty, Some(&b[..]))
        }
        (Some(d), None) => (
            conv::pixel_format(d.format),
            conv::value(d.ty),
            Some(&d.bytes[..]),
        ),
        // Storage only: any matching client format will do.
        (None, _) if l.internal_format.is_depth() => (glow::DEPTH_COMPONENT, glow::FLOAT, None),
        (None, _) => (glow::RED, glow::UNSIGNED_BYTE, None),
    };
    unsafe {
        gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
        match target {
            glow::TEXTURE_1D => gl.tex_image_1d(
                target,
                level,
                internal as i32,
                l.width,
                0,
                format,
                ty,
                glow::PixelUnpackData::Slice(bytes),
            ),
            // The images one after the other, the first (r = 0) first.
            glow::TEXTURE_3D => gl.tex_image_3d(
                target,
                level,
                internal as i32,
                l.width,
                l.height,
                l.depth,
                0,
                format,
                ty,
                glow::PixelUnpackData::Slice(bytes),
            ),
            _ => gl.tex_image_2d(
                target,
                level,
                internal as i32,
                l.width,
                l.height,
                0,
                format,
                ty,
                glow::PixelUnpackData::Slice(bytes),
            ),
        }
    }
}

/// GENERATE_MIPMAP (GL 1.4): a change to the base level rebuilds the levels above it. The
/// model has recorded those levels (`TextureObject::level_changed`); glGenerateMipmap makes
/// their texels, with MAX_LEVEL already covering them.
///
/// A cube map's faces are derived together once all six base levels are alike (core GL
/// refuses glGenerateMipmap of a cube that is not); until then the model's levels wait.
pub(super) fn generate_mipmap(gl: &glow::Context, target: u32, object: &TextureObject, level: i32) {
    let ready = match object.target {
        TextureTarget::CubeMap => object.faces_alike(),
        _ => object.base().is_some(),
    };
    if level == object.params.base_level && object.params.generate_mipmap && ready {
        // MAX_LEVEL first: the model now holds levels 1…p, which GL generates only up to
        // MAX_LEVEL, the highest level held when the parameters were last applied (level 0
        // alone when GENERATE_MIPMAP was set after the image).
        apply_params(gl, target, object);
        unsafe { gl.generate_mipmap(target) };
    }
}

/// The border colour the core texture is given so that sampling its border yields GL's:
/// TEXTURE_BORDER_COLOR taken as the level's base format takes a colour (GL 1.5 §3.8.8,
/// Table 3.15: ALPHA keeps A, LUMINANCE and INTENSITY R, LUMINANCE_ALPHA R and A), then
/// expanded as a texel (ALPHA (0, 0, 0, A)…). llvmpipe swizzles the border as it swizzles
/// texels (`conv::tex_format`), so the border is stored as a texel of the storage is:
/// channel k holds the kept component k (`texel_store::kept`), ALPHA8's R8 the border's
/// alpha. A depth texture's border is its first component, as given.
fn core_border(object: &TextureObject, border: glam::Vec4) -> [f32; 4] {
    let given = border.to_array();
    match object.format() {
        Some(f) if !f.is_depth() => {
            let mut core = given;
            for (k, c) in super::texel_store::kept(f.base()).iter().enumerate() {
                core[k] = given[*c];
            }
            core
        }
        _ => given,
    }
}

/// Every parameter, plus the swizzle of the level-0 format and the mipmap range. MAX_LEVEL
/// is the highest level the model holds: a texture the model calls complete
/// (`TextureObject::completeness`) is complete for GL too; one it calls incomplete is
/// never sampled (its unit leaves the key), whatever GL would make of it.
pub(super) fn apply_params(gl: &glow::Context, target: u32, object: &TextureObject) {
    let p = &object.params;
    // GL's range is the model's b..=q, cut at the last level the model holds (levels
    // outside the range, which GL 1.x ignores, would make core GL's texture incomplete).
    let held = object.levels.iter().rposition(Option::is_some).unwrap_or(0) as i32;
    let base_level = p.base_level;
    let max_level = object.last_level().min(held).max(base_level);
    let (_, swizzle) = object.format().map(conv::tex_format).unwrap_or((
        glow::RGBA8,
        [glow::RED, glow::GREEN, glow::BLUE, glow::ALPHA],
    ));
    let is_depth = object.format().is_some_and(|f| f.is_depth());
    unsafe {
        gl.tex_parameter_i32(
            target,
            glow::TEXTURE_MIN_FILTER,
            conv::value(p.min_filter) as i32,
        );
        gl.tex_parameter_i32(
            target,
            glow::TEXTURE_MAG_FILTER,
            conv::value(p.mag_filter) as i32,
        );
        gl.tex_parameter_i32(target, glow::TEXTURE_WRAP_S, conv::wrap(p.wrap_s) as i32);
        gl.tex_parameter_i32(target, glow::TEXTURE_WRAP_T, conv::wrap(p.wrap_t) as i32);
        gl.tex_parameter_i32(target, glow::TEXTURE_WRAP_R, conv::wrap(p.wrap_r) as i32);
        gl.tex_parameter_f32_slice(
            target,
            glow::TEXTURE_BORDER_COLOR,
            &core_border(object, p.border_color),
        );
        gl.tex_parameter_i32(target, glow::TEXTURE_BASE_LEVEL, base_level);
        gl.tex_parameter_i32(target, glow::TEXTURE_MAX_LEVEL, max_level);
        gl.tex_parameter_f32(target, glow::TEXTURE_MIN_LOD, p.min_lod);
        gl.tex_parameter_f32(target, glow::TEXTURE_MAX_LOD, p.max_lod);
        // llvmpipe filters anisotropically as Mesa's own fixed function does with it.
        gl.tex_parameter_f32(target, glow::TEXTURE_MAX_ANISOTROPY_EXT, p.max_anisotropy);
        let swizzle = swizzle.map(|s| s as i32);
        gl.tex_parameter_i32_slice(target, glow::TEXTURE_SWIZZLE_RGBA, &swizzle);
        if is_depth {
            let mode = match p.compare_mode {
                CompareMode::None => glow::NONE,
                CompareMode::CompareRToTexture => glow::COMPARE_REF_TO_TEXTURE,
            };
            gl.tex_parameter_i32(target, glow::TEXTURE_COMPARE_MODE, mode as i32);
            gl.tex_parameter_i32(
                target,
                glow::TEXTURE_COMPARE_FUNC,
                conv::value(p.compare_func) as i32,
            );
        }
    }
}
