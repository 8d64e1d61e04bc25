//! Chapter 4: implicit surfaces and sphere tracing, and its exercises.

#[path = "../common/mod.rs"]
mod common;

mod exercises;
mod sphere_tracing;
