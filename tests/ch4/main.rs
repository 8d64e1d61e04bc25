//! Chapter 4: implicit surfaces and sphere tracing, and its exercises.

#[path = "../common/mod.rs"]
mod common;

mod sphere_tracing;
mod exercises;
