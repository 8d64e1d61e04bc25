//! The checks of every chapter's exercises, and what the grader knows about
//! each exercise (file, hints, reference). The exercises themselves, the
//! files students edit under `chapters/chN-…/exercises/`, are a crate of
//! their own (`chapters/Cargo.toml`, `raystep-exercises`) that calls these
//! checks with the student's functions: an edit there rebuilds only that
//! small crate, and an exercise that does not compile leaves the renderer,
//! the chapter binaries and the other exercises building.

use crate::exercise::Exercise;

pub mod bounce_layers;
pub mod ch1;
pub mod ch2;
pub mod ch3;
pub mod ch4;
pub mod ch5;
pub mod ch6;
pub mod draws;
pub mod images;
pub mod paths;
pub mod refraction;
pub mod stateless;
pub mod twins;

/// The largest |channel| of a colour or vector, +∞ where a channel is NaN.
/// glam's `max_element` passes over a NaN in some channels (the
/// comparisons it is made of are false for NaN), so an answer with one NaN
/// channel would read as close; a NaN must count as infinitely far off.
pub trait AbsMax {
    /// The scalar type.
    type Out;
    /// max |channel|, +∞ if any channel is NaN.
    fn abs_max(self) -> Self::Out;
}

/// [`AbsMax`] for glam's vectors of `f32` and of `f64`.
macro_rules! abs_max {
    ($($vector:ty => $scalar:ty),*) => {$(
        impl AbsMax for $vector {
            type Out = $scalar;
            fn abs_max(self) -> $scalar {
                match self.is_nan() {
                    true => <$scalar>::INFINITY,
                    false => self.abs().max_element(),
                }
            }
        }
    )*};
}

abs_max!(glam::Vec2 => f32, glam::Vec3 => f32, glam::DVec3 => f64);

/// The larger of two errors, +∞ if either is NaN (`f64::max` passes over
/// a NaN, so a NaN error beside a finite one would vanish).
pub fn worse(a: f64, b: f64) -> f64 {
    match a.is_nan() || b.is_nan() {
        true => f64::INFINITY,
        false => a.max(b),
    }
}

/// The case with the largest error over `(error, what)` pairs, a NaN
/// counting as infinite; `None` when no error is above 0. What a case
/// carries is the check's own (its description, its symptom).
pub(crate) fn worst<T>(cases: impl Iterator<Item = (f64, T)>) -> Option<(f64, T)> {
    let mut worst: Option<(f64, T)> = None;
    for (err, what) in cases {
        let err = if err.is_nan() { f64::INFINITY } else { err };
        if err > worst.as_ref().map_or(0.0, |w| w.0) {
            worst = Some((err, what));
        }
    }
    worst
}

/// [`worst`] over `(error, which case)` pairs, `(0, "all cases match")`
/// when none is above 0. Shared by the graders of chapters 4 to 6.
pub(crate) fn worst_of(cases: impl Iterator<Item = (f64, String)>) -> (f64, String) {
    worst(cases).unwrap_or_else(|| (0.0, "all cases match".into()))
}

/// Every exercise, in chapter order.
pub fn all() -> Vec<Exercise> {
    let mut all = ch1::exercises();
    all.extend(ch2::exercises());
    all.extend(ch3::exercises());
    all.extend(ch4::exercises());
    all.extend(ch5::exercises());
    all.extend(ch6::exercises());
    all
}
