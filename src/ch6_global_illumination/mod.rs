//! Chapter 6: global illumination.

pub mod accumulate;
pub mod bench;
pub mod figures;
pub mod integrator;
pub mod reference;
pub mod report;
pub mod sampler;
pub mod scenes;
pub mod stability;
pub mod stage;
pub mod studies;
