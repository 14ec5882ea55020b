//! The converter of the raster-position and pixel-rectangle calls (`raster`, `pixels`):
//! glRasterPos and glWindowPos in every variant, glBitmap, glDrawPixels, glCopyPixels,
//! glPixelTransfer, glPixelMap and glPixelZoom; `Ok(None)` for calls of other areas.
//!
//! A rectangle's size is checked against [`MAX_RECT_PIXELS`] before its pixels are read, so
//! a program or script asking for 2³¹ pixels is refused without reading or allocating them.

use glam::Vec4;

use super::api::{CType, Entry};
use super::args::{Args, LsbFirst, PixelShape};
use super::pixel_map::{MapValues, PixelMap, MAX_PIXEL_MAP_TABLE};
use super::pixel_types;
use super::pixels::{
    Bitmap, CopyKind, CopyPixels, DrawPixels, PixelTransferParam, MAX_RECT_PIXELS,
};
use super::stipple::{LineStipple, PolygonStipple};
use super::Command;

/// Which position call a name is: glRasterPos{2,3,4} or glWindowPos{2,3} (with its ARB
/// and MESA names), its component count, C type and vector form.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct PositionCall {
    window: bool,
    count: usize,
    ty: CType,
    vector: bool,
}

fn position_call(e: Entry) -> Option<PositionCall> {
    let name = e.name();
    let name = name
        .strip_suffix("ARB")
        .or_else(|| name.strip_suffix("MESA"))
        .unwrap_or(name);
    let (window, rest) = match name.strip_prefix("glRasterPos") {
        Some(r) => (false, r),
        None => (true, name.strip_prefix("glWindowPos")?),
    };
    let count = rest.chars().next()?.to_digit(10)? as usize;
    let rest = &rest[1..];
    let (t, vector) = match rest.strip_suffix('v') {
        Some(t) => (t, true),
        None => (rest, false),
    };
    let ty = match t {
        "s" => CType::Short,
        "i" => CType::Int,
        "f" => CType::Float,
        "d" => CType::Double,
        _ => return None,
    };
    Some(PositionCall {
        window,
        count,
        ty,
        vector,
    })
}

/// The values of a position call, converted to its C type as C does, then to GLfloat (Mesa
/// keeps the raster position in floats); missing z = 0, w = 1.
fn position<A: Args>(c: &A, p: PositionCall) -> Result<Vec4, A::Error> {
    let values: Vec<f64> = if p.vector {
        c.count(1)?;
        c.array_f64(0, p.count)?
    } else {
        c.count(p.count)?;
        (0..p.count).map(|k| c.f64(k)).collect::<Result<_, _>>()?
    };
    let v = |k: usize, default: f32| values.get(k).map_or(default, |x| p.ty.convert(*x) as f32);
    Ok(Vec4::new(v(0, 0.0), v(1, 0.0), v(2, 0.0), v(3, 1.0)))
}

/// Refuses a rectangle beyond the budget before its data is read (negative sizes pass on
/// to the model, which records GL's INVALID_VALUE).
fn budget<A: Args>(c: &A, i: usize, width: i32, height: i32) -> Result<(), A::Error> {
    if width.max(0) as u64 * height.max(0) as u64 > MAX_RECT_PIXELS {
        return Err(c.bad(i, "a rectangle of at most 2^24 pixels"));
    }
    Ok(())
}

const TRANSFER: &[&str] = &[
    "GL_RED_SCALE",
    "GL_GREEN_SCALE",
    "GL_BLUE_SCALE",
    "GL_ALPHA_SCALE",
    "GL_RED_BIAS",
    "GL_GREEN_BIAS",
    "GL_BLUE_BIAS",
    "GL_ALPHA_BIAS",
    "GL_DEPTH_SCALE",
    "GL_DEPTH_BIAS",
    "GL_INDEX_SHIFT",
    "GL_INDEX_OFFSET",
    "GL_MAP_COLOR",
    "GL_MAP_STENCIL",
];

/// glPixelTransfer{f,i}: INDEX_SHIFT and INDEX_OFFSET truncate to integers, MAP_* are
/// booleans (≠ 0), as Mesa's glPixelTransferf reads them (glPixelTransferi passes its
/// integer as a float).
fn transfer<A: Args>(c: &A) -> Result<PixelTransferParam, A::Error> {
    use PixelTransferParam as P;
    c.count(2)?;
    let pname = c.pname(0, TRANSFER)?;
    let v = c.f32(1)?;
    let int = || if v.is_finite() { v.trunc() as i32 } else { 0 };
    Ok(match pname {
        "GL_RED_SCALE" => P::Scale(0, v),
        "GL_GREEN_SCALE" => P::Scale(1, v),
        "GL_BLUE_SCALE" => P::Scale(2, v),
        "GL_ALPHA_SCALE" => P::Scale(3, v),
        "GL_RED_BIAS" => P::Bias(0, v),
        "GL_GREEN_BIAS" => P::Bias(1, v),
        "GL_BLUE_BIAS" => P::Bias(2, v),
        "GL_ALPHA_BIAS" => P::Bias(3, v),
        "GL_DEPTH_SCALE" => P::DepthScale(v),
        "GL_DEPTH_BIAS" => P::DepthBias(v),
        "GL_INDEX_SHIFT" => P::IndexShift(int()),
        "GL_INDEX_OFFSET" => P::IndexOffset(int()),
        "GL_MAP_COLOR" => P::MapColor(v != 0.0),
        _ => P::MapStencil(v != 0.0),
    })
}

/// The raster position and pixel rectangles.
pub fn pixels<A: Args>(c: &A) -> Result<Option<Command>, A::Error> {
    if let Some(p) = position_call(c.entry()) {
        let v = position(c, p)?;
        return Ok(Some(if p.window {
            Command::WindowPos(v.truncate())
        } else {
            Command::RasterPos(v)
        }));
    }
    Ok(Some(match c.entry() {
        // The mask is unpacked as a 32×32 bitmap (§3.5.2), with the unpack parameters.
        Entry::PolygonStipple => {
            c.count(1)?;
            let shape = PixelShape::bitmap(32, 32);
            let bytes = c
                .pixels(0, shape)?
                .ok_or_else(|| c.bad(0, "a 32×32 mask"))?;
            Command::PolygonStipple(Box::new(
                PolygonStipple::from_bytes(&bytes).ok_or_else(|| c.bad(0, "a 32×32 mask"))?,
            ))
        }
        // GLushort: C converts the pattern modulo 2^16; the factor is clamped (§3.4.2).
        Entry::LineStipple => {
            c.count(2)?;
            Command::LineStipple(LineStipple::new(c.i32(0)?, c.int(1)? as u16))
        }
        Entry::Bitmap => {
            c.count(7)?;
            let (width, height) = (c.i32(0)?, c.i32(1)?);
            budget(c, 0, width, height)?;
            let shape = PixelShape::bitmap(width.max(0), height.max(0));
            Command::Bitmap(Bitmap {
                width,
                height,
                origin: (c.f32(2)?, c.f32(3)?),
                advance: (c.f32(4)?, c.f32(5)?),
                bits: c.pixels(6, shape)?,
            })
        }
        Entry::DrawPixels => {
            c.count(5)?;
            let (width, height) = (c.i32(0)?, c.i32(1)?);
            let shape = super::index_pixels::image_shape(
                c,
                (width.max(0), height.max(0), None),
                2,
                LsbFirst::Ignored,
            )?;
            budget(c, 0, width, height)?;
            if let Some(refused) = pixel_types::refusal(c, shape.format, shape.ty) {
                return Ok(Some(refused));
            }
            let (format, ty, data) = pixel_types::model_pixels(c, 4, shape)?;
            Command::DrawPixels(DrawPixels {
                width,
                height,
                format,
                ty,
                data: data.ok_or_else(|| c.bad(4, "a pixel array"))?,
            })
        }
        Entry::CopyPixels => {
            c.count(5)?;
            let kind = match c.pname(4, &["GL_COLOR", "GL_DEPTH", "GL_STENCIL"])? {
                "GL_COLOR" => CopyKind::Color,
                "GL_DEPTH" => CopyKind::Depth,
                _ => CopyKind::Stencil,
            };
            Command::CopyPixels(CopyPixels {
                x: c.i32(0)?,
                y: c.i32(1)?,
                width: c.i32(2)?,
                height: c.i32(3)?,
                kind,
            })
        }
        Entry::PixelTransferf | Entry::PixelTransferi => Command::PixelTransfer(transfer(c)?),
        Entry::PixelMapfv | Entry::PixelMapuiv | Entry::PixelMapusv => {
            c.count(3)?;
            // Mesa's order: the size (1..=MAX) before the map's name, before the values.
            let size = c.i32(1)?;
            if size < 1 || size as usize > MAX_PIXEL_MAP_TABLE {
                return Err(c.bad(1, "a size of 1 to GL_MAX_PIXEL_MAP_TABLE"));
            }
            let map = c.enm(0)?;
            let given = match c.entry() {
                Entry::PixelMapfv => MapValues::Float,
                Entry::PixelMapuiv => MapValues::UInt,
                _ => MapValues::UShort,
            };
            let raw = c.array_f64(2, size as usize)?;
            Command::PixelMap(
                PixelMap::new(map, &raw, given)
                    .map_err(|_| c.bad(1, "a power-of-two size for an I or S map"))?,
            )
        }
        Entry::PixelZoom => {
            c.count(2)?;
            Command::PixelZoom {
                x: c.f32(0)?,
                y: c.f32(1)?,
            }
        }
        _ => return Ok(None),
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_position_row_reads_its_variant() {
        let mut raster = 0;
        let mut window = 0;
        for e in Entry::ALL {
            let n = e.name();
            if n.starts_with("glRasterPos") || n.starts_with("glWindowPos") {
                let p = position_call(*e).unwrap_or_else(|| panic!("{n}"));
                if p.window {
                    window += 1;
                    assert!(p.count <= 3, "{n}");
                } else {
                    raster += 1;
                }
            }
        }
        assert_eq!((raster, window), (24, 48));
        let p = position_call(Entry::RasterPos3sv).unwrap();
        assert_eq!(
            (p.count, p.ty, p.vector, p.window),
            (3, CType::Short, true, false)
        );
        assert_eq!(position_call(Entry::Vertex3f), None);
    }
}
