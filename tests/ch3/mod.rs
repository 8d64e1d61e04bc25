//! Chapter 3: ray-triangle intersection and the BVH.

mod ray_triangle;
mod readable_bvh;
mod unit;
