//! The exercise files of every chapter, compiled into the library so they
//! always build. Students edit the files under `chapters/chN-…/exercises/`;
//! `cargo run --release --bin grade` grades them (see [`crate::grading`]).

#![allow(unused_variables)]

use crate::grading::Exercise;

#[path = "../chapters/ch1-projection/exercises/mod.rs"]
pub mod ch1;

#[path = "../chapters/ch2-rasterization/exercises/mod.rs"]
pub mod ch2;

#[path = "../chapters/ch3-ray-triangle/exercises/mod.rs"]
pub mod ch3;

#[path = "../chapters/ch4-sphere-tracing/exercises/mod.rs"]
pub mod ch4;

#[path = "../chapters/ch5-reflection/exercises/mod.rs"]
pub mod ch5;
#[path = "../chapters/ch6-global-illumination/exercises/mod.rs"]
pub mod ch6;

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
