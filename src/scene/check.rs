//! Small checks shared by the table builders: each turns a spanned raw value into a
//! validated one or a `SceneError::Invalid` naming the key and its line.

use super::error::{Location, Problem, SceneError, SceneWarning};
use super::limits::{Limits, BYTES_PER_TRIANGLE};
use super::raw::{Numbers, S};
use glam::Vec3;
use std::ops::Range;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// What the builders need to know about the file being read.
pub(super) struct Ctx<'a> {
    pub text: &'a str,
    pub file: String,
    /// OBJ paths are resolved against this folder.
    pub base_dir: PathBuf,
    pub warnings: Vec<SceneWarning>,
    /// The budgets the scene is read under.
    pub limits: Limits,
}

pub(super) type Result<T> = std::result::Result<T, SceneError>;

impl<'a> Ctx<'a> {
    pub fn new(text: &'a str, file: &Path, limits: Limits) -> Ctx<'a> {
        Ctx {
            text,
            file: file.display().to_string(),
            base_dir: file.parent().map(Path::to_path_buf).unwrap_or_default(),
            warnings: Vec::new(),
            limits,
        }
    }

    pub fn at(&self, span: Range<usize>) -> Location {
        Location::of_offset(&self.file, self.text, span.start)
    }

    pub fn invalid(&self, span: Range<usize>, key: &str, problem: Problem) -> SceneError {
        SceneError::Invalid {
            at: self.at(span),
            key: key.to_string(),
            problem,
        }
    }

    pub fn finite(&self, v: &Spanned<f32>, key: &str) -> Result<f32> {
        let x = *v.get_ref();
        if x.is_finite() {
            Ok(x)
        } else {
            Err(self.invalid(v.span(), key, Problem::NotFinite))
        }
    }

    pub fn positive(&self, v: &Spanned<f32>, key: &str) -> Result<f32> {
        let x = self.finite(v, key)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(self.invalid(v.span(), key, Problem::NotPositive(x)))
        }
    }

    /// An optional number, `default` when absent.
    pub fn number(&self, v: &S<f32>, key: &str, default: f32) -> Result<f32> {
        v.as_ref().map_or(Ok(default), |v| self.finite(v, key))
    }

    /// An optional size, `default` when absent, > 0 when given.
    pub fn size(&self, v: &S<f32>, key: &str, default: f32) -> Result<f32> {
        v.as_ref().map_or(Ok(default), |v| self.positive(v, key))
    }

    /// An optional count, `default` when absent, at least `min` when given.
    pub fn count(&self, v: &S<u32>, key: &str, default: u32, min: u32) -> Result<u32> {
        match v {
            None => Ok(default),
            Some(v) if *v.get_ref() >= min => Ok(*v.get_ref()),
            Some(v) => Err(self.invalid(
                v.span(),
                key,
                Problem::TooSmall {
                    min,
                    value: *v.get_ref(),
                },
            )),
        }
    }

    /// Refuses an optional count above `max`.
    pub fn at_most(&self, v: &S<u32>, key: &str, max: u32) -> Result<()> {
        match v {
            Some(v) if *v.get_ref() > max => Err(self.invalid(
                v.span(),
                key,
                Problem::TooLarge {
                    max,
                    value: *v.get_ref(),
                },
            )),
            _ => Ok(()),
        }
    }

    pub fn vec3(&self, v: &Spanned<Numbers<3>>, key: &str) -> Result<Vec3> {
        let x = Vec3::from_array(v.get_ref().0);
        if x.is_finite() {
            Ok(x)
        } else {
            Err(self.invalid(v.span(), key, Problem::NotFinite))
        }
    }

    pub fn opt_vec3(&self, v: &S<Numbers<3>>, key: &str, default: Vec3) -> Result<Vec3> {
        v.as_ref().map_or(Ok(default), |v| self.vec3(v, key))
    }

    /// A vector that must not be zero (a direction or an axis).
    pub fn direction(&self, v: &Spanned<Numbers<3>>, key: &str) -> Result<Vec3> {
        let x = self.vec3(v, key)?;
        if x.length_squared() > 0.0 {
            Ok(x)
        } else {
            Err(self.invalid(v.span(), key, Problem::ZeroVector))
        }
    }

    /// Refuses `triangles` (the scene's running total, at the object `key` spanning
    /// `span`) when over the triangle budget or over the memory budget at
    /// `BYTES_PER_TRIANGLE` each.
    pub fn within_budget(&self, triangles: u64, span: Range<usize>, key: &str) -> Result<()> {
        let bytes = triangles.saturating_mul(BYTES_PER_TRIANGLE);
        if triangles <= self.limits.max_triangles && bytes <= self.limits.memory_bytes {
            return Ok(());
        }
        Err(self.invalid(
            span,
            key,
            Problem::OverBudget {
                triangles,
                bytes,
                max_triangles: self.limits.max_triangles,
                memory_bytes: self.limits.memory_bytes,
            },
        ))
    }

    /// A value `what` needs; its absence is reported at the enclosing table's span.
    pub fn required<'v, T>(
        &self,
        v: &'v S<T>,
        key: &str,
        what: &str,
        table: Range<usize>,
    ) -> Result<&'v Spanned<T>> {
        v.as_ref().ok_or_else(|| {
            self.invalid(
                table,
                key,
                Problem::Missing {
                    what: what.to_string(),
                },
            )
        })
    }

    /// Rejects keys present in `given` but not in `valid` (e.g. `radius` on a box).
    pub fn only(
        &self,
        given: &[(&'static str, Option<Range<usize>>)],
        valid: &[&'static str],
        what: &str,
        prefix: &str,
    ) -> Result<()> {
        for (key, span) in given {
            if let Some(span) = span {
                if !valid.contains(key) {
                    return Err(self.invalid(
                        span.clone(),
                        &format!("{prefix}{key}"),
                        Problem::NotUsedBy {
                            what: what.to_string(),
                            valid: valid.to_vec(),
                        },
                    ));
                }
            }
        }
        Ok(())
    }
}

/// The span of an optional spanned value, for `Ctx::only`.
pub(super) fn span_of<T>(v: &S<T>) -> Option<Range<usize>> {
    v.as_ref().map(Spanned::span)
}
