//! A student's exercise files, one module each (`ch3::moller_trumbore`),
//! as the grader builds them: the grader writes the list of modules
//! (`$RAYSTEP_GRADE_MODULES`, a file of `#[path = …] pub mod …;` naming
//! copies of the exercise files it made, by content) and builds this crate
//! with `cargo build -p raystep-grade-child`. An exercise that does not
//! compile, or uses what an exercise may not, is replaced by its shipped
//! stub and reported.
//!
//! No `unsafe` code (which also refuses `#[no_mangle]` and
//! `#[export_name]`), no build script, and no dependency but glam and the
//! building blocks: the exercises cannot reach raystep's own solutions.

#![forbid(unsafe_code)]
#![allow(unused_variables, unused_imports, dead_code, unreachable_code)]
#![allow(clippy::all)]

include!(env!("RAYSTEP_GRADE_MODULES"));
