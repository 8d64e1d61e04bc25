//! Exercise 4.3, solved as a student would.

use glam::Vec3;

/// The unit normal ∇f/‖∇f‖ of `sdf` at `p`.
pub fn gradient_normal(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    let partial = |axis: Vec3| (sdf(p + axis * h) - sdf(p - axis * h)) / (2.0 * h);
    Vec3::new(partial(Vec3::X), partial(Vec3::Y), partial(Vec3::Z)).normalize()
}
