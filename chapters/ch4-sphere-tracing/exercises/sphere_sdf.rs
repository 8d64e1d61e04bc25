//! Exercise 4.1: the signed distance function of a sphere.
//!
//! Contract (what the grader checks, to 1e-5):
//! * Return the signed distance from the point `p` to the surface of the
//!   sphere of radius `radius` around `center`: positive outside, zero on
//!   the surface, negative inside (minus the distance to the surface; at
//!   the centre, -radius).
//!
//! The idea: every point of the surface is the same distance from the
//! centre.
//!
//! Grade it with: `cargo grade ch4`

use glam::Vec3;

/// Signed distance from `p` to the sphere (`center`, `radius`).
pub fn sphere_sdf(p: Vec3, center: Vec3, radius: f32) -> f32 {
    // TODO: your code here (steps: `cargo grade --hint ch4/sphere_sdf`).
    todo!()
}
