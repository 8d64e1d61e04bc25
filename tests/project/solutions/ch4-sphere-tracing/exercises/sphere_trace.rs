//! Exercise 4.2, solved as a student would.

use glam::Vec3;

/// The distance t to the first surface along the ray, if found.
pub fn sphere_trace(
    sdf: &dyn Fn(Vec3) -> f32,
    origin: Vec3,
    dir: Vec3,
    epsilon: f32,
    max_steps: u32,
    max_distance: f32,
) -> Option<f32> {
    let mut t = 0.0;
    for _ in 0..max_steps {
        let d = sdf(origin + t * dir);
        if d.abs() < epsilon {
            return Some(t);
        }
        if t > max_distance {
            return None;
        }
        t += d;
    }
    None
}
