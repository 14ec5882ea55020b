//! `--size WxH`.

use super::error::CliError;

/// A target size from the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    pub width: u32,
    pub height: u32,
}

impl std::str::FromStr for Size {
    type Err = CliError;
    fn from_str(s: &str) -> Result<Size, CliError> {
        let bad = || CliError::Size {
            given: s.to_string(),
        };
        let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
        let side = |v: &str| {
            v.trim()
                .parse::<u32>()
                .ok()
                .filter(|n| (1..=16384).contains(n))
        };
        Ok(Size {
            width: side(w).ok_or_else(bad)?,
            height: side(h).ok_or_else(bad)?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::Size;

    #[test]
    fn sizes() {
        assert_eq!(
            "64x32".parse::<Size>().ok(),
            Some(Size {
                width: 64,
                height: 32
            })
        );
        for bad in ["0x4", "4", "ax4", "4x99999", "-1x2", ""] {
            assert!(bad.parse::<Size>().is_err(), "{bad}");
        }
    }
}
