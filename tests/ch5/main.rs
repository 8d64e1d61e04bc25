//! Chapter 5: radiometry, BRDFs, the reflection equation, and its exercises.

#[path = "../common/mod.rs"]
mod common;

mod bsdf;
mod exercises;
mod ladder;
mod radiometry;
mod reflection;
