//! Exercise 4.3: the normal of an implicit surface from its gradient.
//!
//! The normal at a surface point p is ∇f / ‖∇f‖. Estimate each partial
//! derivative by central differences with step `h`:
//! ∂f/∂x ≈ (f(p + h x̂) − f(p − h x̂)) / 2h, and likewise for y and z.
//! Return the normalised gradient.
//!
//! Grade it with: `cargo run --release --bin grade -- ch4`

use glam::Vec3;

/// The unit normal ∇f/‖∇f‖ of `sdf` at `p`.
pub fn gradient_normal(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    // TODO: three central differences, one per axis.
    // TODO: normalise the gradient.
    todo!()
}
