//! The framebuffer-object calls the C library answers itself, from the model
//! (`ff::framebuffer`): glGenFramebuffers and glGenRenderbuffers (names after the largest
//! generated or bound, as Mesa's name tables give them), glIsFramebuffer,
//! glIsRenderbuffer, glCheckFramebufferStatus and the two getters, with the errors Mesa
//! raises (`tests/c/fbo.c`).

use super::cargs::CArg;
use crate::ff::api::Entry;
use crate::ff::framebuffer::{
    texture_bits, Attached, AttachmentPoint, Bits, FramebufferTarget, MAX_COLOR_ATTACHMENTS,
};
use crate::ff::glenum::{gl, registry as r, GlEnum};
use crate::ff::{FixedState, GlErrorKind};

/// The names glGen* handed out so far (Mesa never hands a name out twice).
#[derive(Debug, Default)]
pub struct Generated {
    framebuffers: u32,
    renderbuffers: u32,
}

/// Whether this module answers `entry`.
pub fn handles(entry: Entry) -> bool {
    crate::ff::framebuffer::answered_by_front_end(entry)
}

fn int(args: &[CArg], i: usize) -> i64 {
    match args.get(i) {
        Some(CArg::Int(v)) => *v,
        _ => 0,
    }
}

fn write_ints(args: &[CArg], i: usize, values: &[i32]) {
    let Some(CArg::Ptr(p, _)) = args.get(i) else {
        return;
    };
    if p.is_null() {
        return;
    }
    for (k, v) in values.iter().enumerate() {
        // SAFETY: the program's array holds what the call writes (n names, one integer).
        unsafe { p.cast::<i32>().cast_mut().add(k).write_unaligned(*v) };
    }
}

/// Answers one call: the value it returns (0 for none).
pub fn answer(
    entry: Entry,
    args: &[CArg],
    state: &FixedState,
    generated: &mut Generated,
) -> Result<u32, GlErrorKind> {
    use Entry as E;
    let f = &state.framebuffers;
    match entry {
        E::GenFramebuffers | E::GenFramebuffersEXT => {
            let from = generated.framebuffers.max(f.max_framebuffer);
            generated.framebuffers = generate(args, from)?;
            Ok(0)
        }
        E::GenRenderbuffers | E::GenRenderbuffersEXT => {
            let from = generated.renderbuffers.max(f.max_renderbuffer);
            generated.renderbuffers = generate(args, from)?;
            Ok(0)
        }
        E::IsFramebuffer | E::IsFramebufferEXT => {
            let name = int(args, 0) as u32;
            Ok(u32::from(name != 0 && f.objects.contains_key(&name)))
        }
        E::IsRenderbuffer | E::IsRenderbufferEXT => {
            let name = int(args, 0) as u32;
            Ok(u32::from(name != 0 && f.renderbuffers.contains_key(&name)))
        }
        E::CheckFramebufferStatus | E::CheckFramebufferStatusEXT => {
            Ok(state.framebuffer_status(target(args)?).code())
        }
        E::GetRenderbufferParameteriv | E::GetRenderbufferParameterivEXT => {
            if int(args, 0) as u32 != r::RENDERBUFFER {
                return Err(GlErrorKind::InvalidEnum);
            }
            let rb = f
                .renderbuffers
                .get(&f.renderbuffer)
                .filter(|_| f.renderbuffer != 0)
                .ok_or(GlErrorKind::InvalidOperation)?;
            let b = if rb.width > 0 {
                rb.format.bits()
            } else {
                Bits::default()
            };
            let v = match int(args, 1) as u32 {
                r::RENDERBUFFER_WIDTH => rb.width,
                r::RENDERBUFFER_HEIGHT => rb.height,
                r::RENDERBUFFER_INTERNAL_FORMAT => gl(rb.format) as i32,
                r::RENDERBUFFER_SAMPLES => 0,
                pname => pname
                    .checked_sub(r::RENDERBUFFER_RED_SIZE)
                    .and_then(|o| size(o, b))
                    .ok_or(GlErrorKind::InvalidEnum)?,
            };
            write_ints(args, 2, &[v]);
            Ok(0)
        }
        _ => {
            let v = attachment_parameter(args, state)?;
            write_ints(args, 3, &[v]);
            Ok(0)
        }
    }
}

/// n names after `from` into the program's array; returns the last.
fn generate(args: &[CArg], from: u32) -> Result<u32, GlErrorKind> {
    let n = int(args, 0);
    if n < 0 {
        return Err(GlErrorKind::InvalidValue);
    }
    let last = u32::try_from(i64::from(from) + n).map_err(|_| GlErrorKind::InvalidValue)?;
    let names: Vec<i32> = (from + 1..=last).map(|v| v as i32).collect();
    write_ints(args, 1, &names);
    Ok(last)
}

fn target(args: &[CArg]) -> Result<FramebufferTarget, GlErrorKind> {
    FramebufferTarget::from_gl_value(int(args, 0) as u32).ok_or(GlErrorKind::InvalidEnum)
}

/// A size by its offset from the first size pname: RENDERBUFFER_RED_SIZE … _STENCIL_SIZE
/// and FRAMEBUFFER_ATTACHMENT_RED_SIZE … _STENCIL_SIZE are consecutive, in the order red,
/// green, blue, alpha, depth, stencil.
fn size(offset: u32, b: Bits) -> Option<i32> {
    let v = match offset {
        0 => b.red,
        1 => b.green,
        2 => b.blue,
        3 => b.alpha,
        4 => b.depth,
        5 => b.stencil,
        _ => return None,
    };
    Some(i32::from(v))
}

/// glGetFramebufferAttachmentParameteriv(target, attachment, pname).
fn attachment_parameter(args: &[CArg], state: &FixedState) -> Result<i32, GlErrorKind> {
    let f = &state.framebuffers;
    let target = target(args)?;
    let (attachment, pname) = (int(args, 1) as u32, int(args, 2) as u32);
    let name = f.bound(target);
    if name == 0 {
        // The window's buffers (GL 3.0 Table 4.12 names); COLOR_ATTACHMENTi is
        // INVALID_ENUM there, as Mesa answers.
        let window = [
            r::FRONT_LEFT,
            r::FRONT_RIGHT,
            r::BACK_LEFT,
            r::BACK_RIGHT,
            r::FRONT,
            r::BACK,
            r::DEPTH,
            r::STENCIL,
        ];
        if !window.contains(&attachment) {
            return Err(GlErrorKind::InvalidEnum);
        }
        return match pname {
            r::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE => Ok(r::FRAMEBUFFER_DEFAULT as i32),
            r::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME => Ok(0),
            _ => Err(GlErrorKind::InvalidEnum),
        };
    }
    let point = AttachmentPoint::from_gl_value(attachment).ok_or(GlErrorKind::InvalidEnum)?;
    if matches!(point, AttachmentPoint::Color(i) if i >= MAX_COLOR_ATTACHMENTS) {
        return Err(GlErrorKind::InvalidOperation);
    }
    let fb = f.objects.get(&name).ok_or(GlErrorKind::InvalidOperation)?;
    if point == AttachmentPoint::DepthStencil && fb.depth != fb.stencil {
        return Err(GlErrorKind::InvalidOperation);
    }
    let attached = fb.attachment(point);
    match (pname, attached) {
        (r::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, None) => Ok(r::NONE as i32),
        (r::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Some(Attached::Texture { .. })) => {
            Ok(r::TEXTURE as i32)
        }
        (r::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Some(Attached::Renderbuffer(_))) => {
            Ok(r::RENDERBUFFER as i32)
        }
        (r::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, None) => Ok(0),
        (r::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Some(Attached::Texture { name, .. })) => {
            Ok(name as i32)
        }
        (r::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Some(Attached::Renderbuffer(rb))) => Ok(rb as i32),
        (_, None) => Err(if known_pname(pname) {
            GlErrorKind::InvalidOperation
        } else {
            GlErrorKind::InvalidEnum
        }),
        (r::FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, Some(Attached::Texture { level, .. })) => {
            Ok(level)
        }
        // The face's own name (TEXTURE_CUBE_MAP_POSITIVE_X + i), 0 for other textures.
        (
            r::FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE,
            Some(Attached::Texture { target, .. }),
        ) => Ok(target.face().map_or(0, |f| {
            (r::TEXTURE_CUBE_MAP_POSITIVE_X + f.index() as u32) as i32
        })),
        // FRAMEBUFFER_ATTACHMENT_TEXTURE_3D_ZOFFSET_EXT is the same token.
        (r::FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, Some(Attached::Texture { layer, .. })) => {
            Ok(layer)
        }
        (p, Some(a)) => {
            let b = match a {
                Attached::Renderbuffer(rb) => f
                    .renderbuffers
                    .get(&rb)
                    .filter(|x| x.width > 0)
                    .map_or(Bits::default(), |x| x.format.bits()),
                Attached::Texture {
                    target: tt,
                    name,
                    level,
                    ..
                } => state
                    .texture(tt, name)
                    .and_then(|t| t.level(level))
                    .map_or(Bits::default(), |l| texture_bits(l.internal_format)),
            };
            p.checked_sub(r::FRAMEBUFFER_ATTACHMENT_RED_SIZE)
                .and_then(|o| size(o, b))
                .ok_or(GlErrorKind::InvalidEnum)
        }
    }
}

/// The attachment pnames this layer knows (a known one on an empty attachment is
/// INVALID_OPERATION, an unknown one INVALID_ENUM).
fn known_pname(pname: u32) -> bool {
    matches!(
        pname,
        r::FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL
            | r::FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE
            | r::FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER
    ) || (r::FRAMEBUFFER_ATTACHMENT_RED_SIZE..=r::FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE)
        .contains(&pname)
}
