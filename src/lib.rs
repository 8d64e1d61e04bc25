//! # raystep: rendering, step by step
//!
//! A renderer that follows one lecture on rendering (after CMU 15-462/662
//! and Foley's book) from a pinhole camera to Monte Carlo global
//! illumination. This crate puts the project's crates under one name, the
//! one the binaries, the tests and the exercises use (`raystep::…`):
//!
//! | crate | folder | what |
//! |---|---|---|
//! | `raystep-lessons` | `src/` (root `src/lessons.rs`) | the six chapters, [`core`] and [`scene`]: what the book teaches |
//! | `raystep-fast` | `src/fast/` | the fast engine ([`fast`]) and the chapter registry ([`chapters`]) |
//! | `raystep-grading` | `src/grading/` | the exercises' grader ([`grading`]) |
//! | `raystep-tui` | `src/tui/` | the terminal UI (`tui`, the default `tui` feature) |
//! | `raystep` | `src/lib.rs` | this one: the names below, the fuzzer ([`fuzz`]) and the headless [`summary`] |
//!
//! Each depends only on those above it, so cargo builds the fast engine,
//! the grader and the UI side by side once the lessons are built, and the
//! release build optimises the grader and the UI less than the renderers.
//! `src/lessons.rs` says how a chapter's folder is laid out.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub use raystep_fast as fast;
pub use raystep_fast::chapters;
pub use raystep_grading as grading;
pub use raystep_lessons::{
    ch1_projection, ch2_rasterization, ch3_ray_triangle, ch4_implicit_surfaces, ch5_reflection,
    ch6_global_illumination, core, scene, Error, Result,
};
#[cfg(feature = "tui")]
pub use raystep_tui as tui;

pub mod fuzz;
pub mod summary;
