//! Chapter 6: global illumination.

pub mod accumulate;
pub mod bench;
pub mod cli;
pub mod figures;
pub mod integrator;
pub mod reference;
pub mod sampler;
pub mod scenes;
pub mod stage;
pub mod studies;
