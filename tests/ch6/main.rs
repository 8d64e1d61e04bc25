//! Chapter 6: global illumination, its exercises, and its terminal preview.

#[path = "../common/mod.rs"]
mod common;

mod global_illumination;
mod exercises;
#[cfg(feature = "tui")]
mod tui;
