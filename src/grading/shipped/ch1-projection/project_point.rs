//! Exercise 1.1: project a point with the lecture's pinhole model.
//!
//! The pinhole is at the origin and the image plane is z = -1. A point
//! p = (x, y, z) in front of the camera has z < 0. Return where the ray from
//! the pinhole through p meets the image plane, as (u, v); return `None` for
//! points that have no image.
//!
//! Grade it with: `cargo run --release --bin grade -- ch1`

use glam::{Vec2, Vec3};

/// Projects the camera-space point `p` onto the image plane z = -1.
pub fn project_point(p: Vec3) -> Option<Vec2> {
    // TODO: points on or behind the camera plane (z >= 0) have no image.
    // TODO: use similar triangles to find (u, v) on the plane z = -1.
    todo!()
}
