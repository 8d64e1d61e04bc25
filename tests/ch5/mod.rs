//! Chapter 5: radiometry, BRDFs, the reflection equation, and its exercises.

mod bsdf;
mod exercises;
mod ladder;
mod radiometry;
mod reflection;
mod unit;
mod warp_test;
