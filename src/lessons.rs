//! # raystep's lessons: chapters 1 to 6 and what they stand on
//!
//! A renderer that follows one lecture on rendering (after CMU 15-462/662
//! and Foley's book) from a pinhole camera to Monte Carlo global
//! illumination. Each part of the lecture is a stage with its own binary,
//! book chapter, tests and exercises.
//!
//! ## The pipeline
//!
//! scene file (TOML) → [`scene::Scene`] (validated, holding only what the
//! scene uses) → a chapter's [`Render`](core::stage::Render) →
//! [`Film`](core::film::Film) → PNG/EXR, a [`Report`](core::report::Report),
//! and a terminal [`preview`](core::preview). The terminal UI (`src/tui/`,
//! behind the default `tui` feature) drives the same
//! [`Chapter`](core::stage::Chapter) boundary as the headless runs.
//!
//! ## Where things are
//!
//! One folder per chapter, each the same shape: `mod.rs` opens with the
//! chapter's slide → file table; then the lesson files (the slides'
//! algorithms, any fast version beside its readable twin); `stage.rs` (the
//! chapter as a [`Chapter`](core::stage::Chapter)); `report.rs`;
//! `studies.rs` (error against run time); `stability.rs` (stiff cases);
//! `bench.rs` where the chapter has a benchmark. Imports only go down: a
//! chapter uses the foundation and earlier chapters' lesson files, never
//! another chapter's stage, report, studies, stability or bench
//! (`tests/project/layout.rs` checks it).
//!
//! | chapter | lecture topic | folder | binary | book page |
//! |---|---|---|---|---|
//! | 1 | projection | [`ch1_projection`] | `ch1` | `book/src/ch1-projection.md` |
//! | 2 | rasterization | [`ch2_rasterization`] | `ch2` | `book/src/ch2-rasterization.md` |
//! | 3 | ray-triangle intersection and a BVH | [`ch3_ray_triangle`] | `ch3` | `book/src/ch3-ray-triangle.md` |
//! | 4 | implicit surfaces and sphere tracing | [`ch4_implicit_surfaces`] | `ch4` | `book/src/ch4-sphere-tracing.md` |
//! | 5 | the reflection equation | [`ch5_reflection`] | `ch5` | `book/src/ch5-reflection.md` |
//! | 6 | Monte Carlo global illumination | [`ch6_global_illumination`] | `ch6` | `book/src/ch6-global-illumination.md` |
//!
//! Below the chapters: [`core`] (film, report and plots, formatting,
//! sampling, the stage boundary, the headless runner) and [`scene`] (scene
//! files, meshes, the camera and SDF descriptions). Beside them, in crates
//! of their own that depend on this one: the fast engine (`src/fast/`,
//! with the chapter registry the front ends list), the grader
//! (`src/grading/`) and the terminal UI (`src/tui/`); the `raystep` crate
//! (`src/lib.rs`) puts them all under one name.
//!
//! The lecture's symbols and the names used here are listed side by side in
//! the book's notation table (`book/src/notation.md`).
//!
//! ## Conventions
//!
//! Right-handed; the camera looks down -z; the image plane is z = -1.
//! Renderer arithmetic is f32; f64 is used for exact references. Transforms
//! are named `a_from_b`. Colour is linear RGB until an 8-bit image is
//! written.

// The lessons hold no unsafe code (the fast engine's vector code is a
// crate of its own, `src/fast/`).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod ch1_projection;
pub mod ch2_rasterization;
pub mod ch3_ray_triangle;
pub mod ch4_implicit_surfaces;
pub mod ch5_reflection;
pub mod ch6_global_illumination;
pub mod core;
pub mod scene;

pub use crate::core::error::{Error, Result};
