//! Exercise 4.1: the signed distance function of a sphere.
//!
//! Return the signed distance from the point `p` to the sphere of radius
//! `radius` around `center`: positive outside, zero on the surface,
//! negative inside (minus the distance to the surface).
//!
//! Grade it with: `cargo run --release --bin grade -- ch4`

use glam::Vec3;

/// Signed distance from `p` to the sphere (`center`, `radius`).
pub fn sphere_sdf(p: Vec3, center: Vec3, radius: f32) -> f32 {
    // TODO: how far is p from the centre?
    // TODO: the surface is `radius` away from the centre: subtract it.
    todo!()
}
