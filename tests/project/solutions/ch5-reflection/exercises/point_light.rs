//! Exercise 5.3, solved: the inverse-square law times Lambert's law.

use glam::Vec3;

/// Irradiance (W/m², per channel) at `p` from a point light.
pub fn point_light_irradiance(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    let to = light - p;
    let r2 = to.length_squared();
    let cos = n.dot(to / r2.sqrt()).max(0.0);
    intensity * cos / r2
}
