//! Image sizes written as `WxH` (`512x512`, `640×480`): both sides whole numbers in
//! [1, MAX_IMAGE_SIZE].

use std::fmt;
use std::str::FromStr;

use super::RenderError;

pub use crate::scene::MAX_IMAGE_SIZE;

/// Width and height of the rendered image, in pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ImageSize {
    pub width: u32,
    pub height: u32,
}

/// Why a size was refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum SizeProblem {
    #[error("expected WIDTHxHEIGHT in pixels, e.g. 512x512")]
    Format,
    #[error("width and height must be at least 1")]
    Zero,
    #[error("width and height must be at most {MAX_IMAGE_SIZE}")]
    TooLarge,
}

impl FromStr for ImageSize {
    type Err = RenderError;

    fn from_str(text: &str) -> Result<ImageSize, RenderError> {
        let fail = |problem| RenderError::Size {
            text: text.to_string(),
            problem,
        };
        let (w, h) = text
            .trim()
            .split_once(['x', 'X', '×'])
            .ok_or(fail(SizeProblem::Format))?;
        let side = |s: &str| -> Result<u32, RenderError> {
            let s = s.trim();
            if s.is_empty() || !s.bytes().all(|b| b.is_ascii_digit()) {
                return Err(fail(SizeProblem::Format));
            }
            // All digits: a parse failure can only be an overflow of u32.
            let v: u32 = s.parse().map_err(|_| fail(SizeProblem::TooLarge))?;
            match v {
                0 => Err(fail(SizeProblem::Zero)),
                v if v > MAX_IMAGE_SIZE => Err(fail(SizeProblem::TooLarge)),
                v => Ok(v),
            }
        };
        Ok(ImageSize {
            width: side(w)?,
            height: side(h)?,
        })
    }
}

impl fmt::Display for ImageSize {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}x{}", self.width, self.height)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes() {
        let ok = |s: &str| s.parse::<ImageSize>().ok().map(|z| (z.width, z.height));
        let problem = |s: &str| match s.parse::<ImageSize>() {
            Err(RenderError::Size { problem, .. }) => Some(problem),
            _ => None,
        };
        assert_eq!(ok("512x512"), Some((512, 512)));
        assert_eq!(ok("640×480"), Some((640, 480)));
        assert_eq!(ok(" 8192X1 "), Some((8192, 1)));
        for s in [
            "", "512", "x", "ax3", "3x", "-1x5", "1.5x2", "3x4x5", "+3x4",
        ] {
            assert_eq!(problem(s), Some(SizeProblem::Format), "{s:?}");
        }
        assert_eq!(problem("0x10"), Some(SizeProblem::Zero));
        assert_eq!(problem("10x0"), Some(SizeProblem::Zero));
        assert_eq!(problem("8193x10"), Some(SizeProblem::TooLarge));
        assert_eq!(problem("99999999999x10"), Some(SizeProblem::TooLarge));
    }
}
