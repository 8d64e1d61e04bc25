//! Chapter 3: ray-triangle intersection and the BVH.

#[path = "../common/mod.rs"]
mod common;

mod ray_triangle;
mod readable_bvh;
