//! Exercise 5.2, solved: Malley's method with the polar disk map.

use glam::{Vec2, Vec3};

/// A cosine-distributed direction about +z and its solid-angle pdf.
pub fn cosine_hemisphere(u: Vec2) -> (Vec3, f32) {
    let r = u.x.sqrt();
    let phi = 2.0 * std::f32::consts::PI * u.y;
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    (Vec3::new(x, y, z), z / std::f32::consts::PI)
}
