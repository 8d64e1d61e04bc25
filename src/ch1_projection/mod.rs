//! Chapter 1: projection.

pub mod camera;
pub mod stage;
