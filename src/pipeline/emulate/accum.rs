//! The accumulation buffer on the emulated path. The values live beside the context as
//! `ff::accum::AccumBuffer` — Mesa's signed 16-bit arithmetic, exact, with its wrapping —
//! rather than in a GL texture: a core context has no 16-bit signed colour format whose
//! blending wraps as Mesa's stores do, and the ops are whole-buffer passes either way.
//! ACCUM and LOAD read the window's colour buffer (glReadPixels, RGBA8); RETURN merges the
//! returned colours into the colour buffer's current ones on the CPU — only inside the
//! scissor region and only the channels the colour mask enables (GL 1.5 §4.2.4: no other
//! per-fragment operation applies) — and blits the region back from a scratch framebuffer.
//! The scissor box limits every op and the clear.

use glow::HasContext;

use crate::ff::accum::{AccumBuffer, AccumOp, Region};
use crate::ff::FixedState;
use crate::pipeline::PipelineError;

/// The region the scissor box leaves of a `width` × `height` buffer.
pub fn region(state: &FixedState, width: usize, height: usize) -> Region {
    let all = Region {
        x: 0,
        y: 0,
        width,
        height,
    };
    match state.scissor.get() {
        Some(Some(b)) => {
            let x0 = b.x.max(0) as usize;
            let y0 = b.y.max(0) as usize;
            let x1 = (i64::from(b.x) + i64::from(b.width)).clamp(0, width as i64) as usize;
            let y1 = (i64::from(b.y) + i64::from(b.height)).clamp(0, height as i64) as usize;
            Region {
                x: x0.min(width),
                y: y0.min(height),
                width: x1.saturating_sub(x0),
                height: y1.saturating_sub(y0),
            }
        }
        _ => all,
    }
}

/// The bound read framebuffer's colours, RGBA8, bottom row first.
fn read_colour(gl: &glow::Context, width: usize, height: usize) -> Vec<u8> {
    let mut out = vec![0u8; width * height * 4];
    unsafe {
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
        gl.read_pixels(
            0,
            0,
            width as i32,
            height as i32,
            glow::RGBA,
            glow::UNSIGNED_BYTE,
            glow::PixelPackData::Slice(Some(&mut out)),
        );
    }
    out
}

/// glClear(ACCUM_BUFFER_BIT).
pub fn clear(buffer: &mut AccumBuffer, state: &FixedState) {
    let (w, h) = buffer.size();
    buffer.clear(region(state, w, h), state.clear.accum);
}

/// glAccum(op, value) on the model's bound framebuffers (the window: the model refuses
/// glAccum with an object bound).
pub fn accum(
    gl: &glow::Context,
    buffer: &mut AccumBuffer,
    state: &FixedState,
    op: AccumOp,
    value: f32,
) -> Result<(), PipelineError> {
    let (w, h) = buffer.size();
    let r = region(state, w, h);
    match op {
        AccumOp::Accum | AccumOp::Load => {
            let colour = read_colour(gl, w, h);
            buffer.apply(op, value, r, &colour);
        }
        AccumOp::Add | AccumOp::Mult => buffer.apply(op, value, r, &[]),
        AccumOp::Return => write_return(gl, buffer, state, value, r)?,
    }
    Ok(())
}

/// RETURN: the returned colours through the colour mask, inside `r`.
fn write_return(
    gl: &glow::Context,
    buffer: &AccumBuffer,
    state: &FixedState,
    value: f32,
    r: Region,
) -> Result<(), PipelineError> {
    if r.width == 0 || r.height == 0 {
        return Ok(());
    }
    let (w, h) = buffer.size();
    let mut image = read_colour(gl, w, h);
    let returned = buffer.returned(value);
    let m = state.color_mask;
    let mask = [m.r, m.g, m.b, m.a];
    for y in r.y..r.y + r.height {
        for x in r.x..r.x + r.width {
            let i = 4 * (y * w + x);
            for k in 0..4 {
                if mask[k] {
                    image[i + k] = returned[i + k];
                }
            }
        }
    }
    unsafe {
        let previous_read = gl.get_parameter_framebuffer(glow::READ_FRAMEBUFFER_BINDING);
        let tex = gl.create_texture().map_err(PipelineError::Object)?;
        let fbo = gl.create_framebuffer().map_err(PipelineError::Object)?;
        gl.active_texture(glow::TEXTURE0 + super::pixels::PIXEL_IMAGE_UNIT);
        gl.bind_texture(glow::TEXTURE_2D, Some(tex));
        gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
        gl.pixel_store_i32(glow::UNPACK_ROW_LENGTH, 0);
        gl.tex_image_2d(
            glow::TEXTURE_2D,
            0,
            glow::RGBA8 as i32,
            w as i32,
            h as i32,
            0,
            glow::RGBA,
            glow::UNSIGNED_BYTE,
            glow::PixelUnpackData::Slice(Some(&image)),
        );
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(fbo));
        gl.framebuffer_texture_2d(
            glow::READ_FRAMEBUFFER,
            glow::COLOR_ATTACHMENT0,
            glow::TEXTURE_2D,
            Some(tex),
            0,
        );
        gl.disable(glow::SCISSOR_TEST);
        gl.color_mask(true, true, true, true);
        let (x0, y0) = (r.x as i32, r.y as i32);
        let (x1, y1) = ((r.x + r.width) as i32, (r.y + r.height) as i32);
        gl.blit_framebuffer(
            x0,
            y0,
            x1,
            y1,
            x0,
            y0,
            x1,
            y1,
            glow::COLOR_BUFFER_BIT,
            glow::NEAREST,
        );
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, previous_read);
        gl.delete_framebuffer(fbo);
        gl.delete_texture(tex);
    }
    Ok(())
}
