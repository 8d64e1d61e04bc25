//! Exercise 3.1, solved as a student would.

use glam::Vec3;

/// The ray parameter t where o + t d lies on the plane Nᵀx = c.
pub fn ray_plane(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let denom = n.dot(d);
    if denom == 0.0 {
        return None;
    }
    Some((c - n.dot(o)) / denom)
}
