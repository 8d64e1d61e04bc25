//! # raystep: rendering, step by step
//!
//! A renderer that follows one lecture on rendering (after CMU 15-462/662
//! and Foley's book) from a pinhole camera to Monte Carlo global
//! illumination. Each part of the lecture is a stage with its own binary,
//! book chapter, tests and exercises.
//!
//! ## The pipeline
//!
//! scene file (TOML) → [`scene::Scene`] (validated, holding only what the
//! scene uses) → a chapter's [`stage::Render`] → [`film::Film`] →
//! PNG/EXR, a [`report::Report`], and a terminal [`preview`].
//! The terminal UI (`src/tui/`, behind the default `tui` feature) drives
//! the same [`stage::Chapter`] boundary as the headless runs.
//!
//! | stage | chapter | module | binary | book page |
//! |---|---|---|---|---|
//! | projection | 1 | [`camera`], [`projection`] | `ch1` | `book/src/ch1-projection.md` |
//! | rasterization | 2 | [`raster`], [`mesh_check`] | `ch2` | `book/src/ch2-rasterization.md` |
//! | ray-triangle | 3 | [`ray`], [`triangle`], [`bvh`], [`watertight_fast`], [`spawn`], [`raytrace`] | `ch3` | `book/src/ch3-ray-triangle.md` |
//! | implicit surfaces | 4 | [`sdf`], [`sphere_tracing`] | `ch4` | `book/src/ch4-sphere-tracing.md` |
//! | reflection equation | 5 | [`radiometry`], [`warp`], [`light`], [`material`], [`world`], [`wide_bvh`], [`reflection`], [`plot`] | `ch5` | `book/src/ch5-reflection.md` |
//! | global illumination | 6 | [`material`], [`light`], [`world`], [`wide_bvh`], [`mis`], [`path_tracing`], [`plot`] | `ch6` | `book/src/ch6-global-illumination.md` |
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

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod ch1_projection;
pub mod ch2_rasterization;
pub mod ch3_ray_triangle;
pub mod ch4_implicit_surfaces;
pub mod ch5_reflection;
pub mod ch6_global_illumination;
pub mod chapters;
pub mod core;
pub mod grading;
pub mod scene;
#[cfg(feature = "tui")]
pub mod tui;

pub use crate::core::error::{Error, Result};
