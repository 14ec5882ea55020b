//! The error split by object: which shadow a technique gets wrong on each object, the
//! shadow the object casts on itself or the shadow other objects cast on it.
//!
//! The truth says, for each geometry pixel, what object it shows and why it is shadowed
//! ([`ShadowCauses`], made by `truth::shadow_causes`):
//! - [`Cause::FacesAway`]: the surface faces away from the light (n · L ≤ 0), the attached
//!   shadow every lit technique draws by lighting alone;
//! - [`Cause::OwnOccluder`]: it faces the light and the object's own geometry blocks the
//!   shadow ray (the object shadows itself, whatever else also blocks it);
//! - [`Cause::OtherOccluder`]: it faces the light and only other objects block it;
//! - [`Cause::Lit`], [`Cause::Background`].
//!
//! Self-shadow is FacesAway + OwnOccluder: what projective shadows cannot draw and occluder
//! planes are made for. For each object, [`per_object`] counts the truth's pixels of each
//! cause and the technique's misses among them (technique lit, or background, where the
//! truth is shadowed), and its false shadow on the truth's lit pixels. The counts of all
//! objects add up to [`super::compare`]'s totals over the same pixels (a test checks it).
//! With two objects, "shadow from others" on the ground is the shadow the other object
//! casts; with more, it is the shadow of all the others together.

use super::{Class, Mask, MetricsError};
use serde::Serialize;

/// Why a truth pixel is lit or shadowed (see the module note).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum Cause {
    Background,
    Lit,
    FacesAway,
    OwnOccluder,
    OtherOccluder,
}

/// Per pixel, row-major and top row first like [`Mask`]: the object seen (index into the
/// scene's objects; meaningless on background) and the cause of its light or shadow.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ShadowCauses {
    pub width: u32,
    pub height: u32,
    pub object: Vec<u32>,
    pub cause: Vec<Cause>,
}

/// Pixels of one cause and how many of them the technique got wrong.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct Tally {
    pub pixels: u64,
    pub wrong: u64,
}

impl Tally {
    fn add(&mut self, wrong: bool) {
        self.pixels += 1;
        self.wrong += u64::from(wrong);
    }

    /// 100 · wrong / pixels, 0 without pixels.
    pub fn percent(&self) -> f64 {
        if self.pixels == 0 {
            0.0
        } else {
            100.0 * self.wrong as f64 / self.pixels as f64
        }
    }
}

/// One object's share of the error.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct ObjectErrors {
    /// Index into the scene's objects.
    pub object: usize,
    /// Truth lit; wrong = the technique shadowed it or drew background.
    pub lit: Tally,
    /// Attached shadow; wrong = the technique lit it or drew background.
    pub faces_away: Tally,
    /// Shadow of the object's own geometry; wrong as for `faces_away`.
    pub own_occluder: Tally,
    /// Shadow of other objects only; wrong as for `faces_away`.
    pub other_occluder: Tally,
}

impl ObjectErrors {
    /// Attached and own-occluder shadow together: the object's self-shadow.
    pub fn self_shadow(&self) -> Tally {
        Tally {
            pixels: self.faces_away.pixels + self.own_occluder.pixels,
            wrong: self.faces_away.wrong + self.own_occluder.wrong,
        }
    }

    /// Truth geometry pixels of the object.
    pub fn pixels(&self) -> u64 {
        self.lit.pixels + self.self_shadow().pixels + self.other_occluder.pixels
    }
}

/// The technique's errors on each object that shows in the image, in object order.
pub fn per_object(
    technique: &Mask,
    causes: &ShadowCauses,
) -> Result<Vec<ObjectErrors>, MetricsError> {
    if (technique.width, technique.height) != (causes.width, causes.height) {
        return Err(MetricsError::SizeMismatch {
            technique: (technique.width, technique.height),
            truth: (causes.width, causes.height),
        });
    }
    let mut objects: Vec<ObjectErrors> = Vec::new();
    for ((&m, &cause), &object) in technique.data.iter().zip(&causes.cause).zip(&causes.object) {
        if cause == Cause::Background {
            continue;
        }
        let object = object as usize;
        if objects.len() <= object {
            objects.resize_with(object + 1, ObjectErrors::default);
        }
        let e = &mut objects[object];
        let class = Class::of(m);
        match cause {
            Cause::Lit => e.lit.add(class != Class::Lit),
            Cause::FacesAway => e.faces_away.add(class != Class::Shadowed),
            Cause::OwnOccluder => e.own_occluder.add(class != Class::Shadowed),
            Cause::OtherOccluder => e.other_occluder.add(class != Class::Shadowed),
            Cause::Background => {}
        }
    }
    Ok(objects
        .into_iter()
        .enumerate()
        .map(|(i, e)| ObjectErrors { object: i, ..e })
        .filter(|e| e.pixels() > 0)
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::{compare, BACKGROUND, LIT, SHADOWED};

    fn causes(cause: Vec<Cause>, object: Vec<u32>) -> ShadowCauses {
        ShadowCauses {
            width: cause.len() as u32,
            height: 1,
            object,
            cause,
        }
    }

    #[test]
    fn each_cause_counts_its_own_misses() {
        use Cause::*;
        let c = causes(
            vec![
                Lit,
                Lit,
                FacesAway,
                OwnOccluder,
                OwnOccluder,
                OtherOccluder,
                Background,
            ],
            vec![0, 1, 0, 0, 0, 1, 0],
        );
        let technique = Mask {
            width: 7,
            height: 1,
            data: vec![SHADOWED, LIT, SHADOWED, LIT, BACKGROUND, LIT, LIT],
        };
        let e = per_object(&technique, &c).unwrap();
        assert_eq!(e.len(), 2);
        assert_eq!(
            e[0].lit,
            Tally {
                pixels: 1,
                wrong: 1
            }
        );
        assert_eq!(
            e[0].faces_away,
            Tally {
                pixels: 1,
                wrong: 0
            }
        );
        assert_eq!(
            e[0].own_occluder,
            Tally {
                pixels: 2,
                wrong: 2
            }
        );
        assert_eq!(
            e[0].self_shadow(),
            Tally {
                pixels: 3,
                wrong: 2
            }
        );
        assert_eq!(
            e[1].lit,
            Tally {
                pixels: 1,
                wrong: 0
            }
        );
        assert_eq!(
            e[1].other_occluder,
            Tally {
                pixels: 1,
                wrong: 1
            }
        );
        assert_eq!(e[1].object, 1);
        assert!((e[0].own_occluder.percent() - 100.0).abs() < 1e-12);
    }

    #[test]
    fn objects_add_up_to_the_totals() {
        use Cause::*;
        let cause = vec![
            Lit,
            FacesAway,
            OtherOccluder,
            OwnOccluder,
            Lit,
            Background,
            Lit,
        ];
        let truth = Mask {
            width: 7,
            height: 1,
            data: cause
                .iter()
                .map(|c| match c {
                    Lit => LIT,
                    Background => BACKGROUND,
                    _ => SHADOWED,
                })
                .collect(),
        };
        let technique = Mask {
            width: 7,
            height: 1,
            data: vec![SHADOWED, LIT, LIT, SHADOWED, BACKGROUND, LIT, 200],
        };
        let c = causes(cause, vec![2, 2, 0, 2, 0, 0, 2]);
        let split = per_object(&technique, &c).unwrap();
        let totals = compare(&technique, &truth, 0).unwrap().all;
        let wrong: u64 = split
            .iter()
            .map(|e| e.lit.wrong + e.self_shadow().wrong + e.other_occluder.wrong)
            .sum();
        let pixels: u64 = split.iter().map(ObjectErrors::pixels).sum();
        assert_eq!((wrong, pixels), (totals.wrong, totals.pixels));
        // Object 1 never shows: it is left out.
        assert_eq!(split.iter().map(|e| e.object).collect::<Vec<_>>(), [0, 2]);
    }

    #[test]
    fn sizes_must_agree() {
        let c = causes(vec![Cause::Lit], vec![0]);
        let technique = Mask::filled(2, 1, LIT);
        assert!(matches!(
            per_object(&technique, &c),
            Err(MetricsError::SizeMismatch { .. })
        ));
    }
}
