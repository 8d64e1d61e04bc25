//! Exercise 3.1: intersect a ray with a plane.
//!
//! The ray is r(t) = o + t d; the plane is every point x with Nᵀx = c.
//! Return the t where the ray meets the plane, or `None` when the ray is
//! parallel to it (Nᵀd = 0). Do not worry about the sign of t here.
//!
//! Grade it with: `cargo run --release --bin grade -- ch3`

use glam::Vec3;

/// The ray parameter t where o + t d lies on the plane Nᵀx = c.
pub fn ray_plane(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    // TODO: substitute r(t) into the plane equation: Nᵀ(o + t d) = c.
    // TODO: solve for t; return None when Nᵀd is zero.
    todo!()
}
