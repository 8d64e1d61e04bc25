//! Chapter 4: implicit surfaces and sphere tracing, and its exercises.

mod exercises;
mod sphere_tracing;
mod unit;
