//! The exercise files of every chapter, compiled into the library so they
//! always build. Students edit the files under `chapters/chN-…/exercises/`;
//! `cargo run --release --bin grade` grades them (see [`crate::grading`]).

#![allow(unused_variables)]

use crate::grading::exercise::Exercise;

#[path = "../../chapters/ch1-projection/exercises/mod.rs"]
pub mod ch1;

#[path = "../../chapters/ch2-rasterization/exercises/mod.rs"]
pub mod ch2;

#[path = "../../chapters/ch3-ray-triangle/exercises/mod.rs"]
pub mod ch3;

#[path = "../../chapters/ch4-sphere-tracing/exercises/mod.rs"]
pub mod ch4;

#[path = "../../chapters/ch5-reflection/exercises/mod.rs"]
pub mod ch5;
#[path = "../../chapters/ch6-global-illumination/exercises/mod.rs"]
pub mod ch6;

/// The worst error over `(error, which case)` pairs, a NaN counting as
/// infinite; `(0, "all cases match")` when none is above 0. Shared by the
/// graders of chapters 4 to 6.
pub(crate) fn worst_of(cases: impl Iterator<Item = (f64, String)>) -> (f64, String) {
    let mut worst = (0.0f64, String::from("all cases match"));
    for (err, what) in cases {
        let err = if err.is_nan() { f64::INFINITY } else { err };
        if err > worst.0 {
            worst = (err, what);
        }
    }
    worst
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
