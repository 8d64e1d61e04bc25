//! Chapter 4: implicit surfaces and sphere tracing.

pub mod bounds;
pub mod distance;
pub mod eikonal;
pub mod hit;
pub mod march;
pub mod normal;
pub mod operators;
pub mod primitives;
pub mod render;
pub mod report;
pub mod stability;
pub mod stage;
pub mod studies;
