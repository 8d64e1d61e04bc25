//! Chapter 3: ray-triangle intersection and a BVH.

pub mod agreement;
pub mod bench;
pub mod bvh;
pub mod geometry;
pub mod leaks;
pub mod ray;
pub mod render;
pub mod report;
pub mod spawn;
pub mod stability;
pub mod stage;
pub mod studies;
pub mod triangle;
pub mod watertight_fast;
pub mod wide_bvh;
