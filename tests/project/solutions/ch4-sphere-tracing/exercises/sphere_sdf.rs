//! Exercise 4.1, solved as a student would.

use glam::Vec3;

/// Signed distance from `p` to the sphere (`center`, `radius`).
pub fn sphere_sdf(p: Vec3, center: Vec3, radius: f32) -> f32 {
    (p - center).length() - radius
}
