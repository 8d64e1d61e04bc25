//! Exercise 4.3: the normal of an implicit surface from its gradient.
//!
//! Contract (what the grader checks, to 1e-3, on a sphere, a box and a
//! torus):
//! * Return the unit normal ∇f / ‖∇f‖ of `sdf` at `p`, each partial
//!   derivative estimated by central differences with step `h`.
//!
//! The idea: the normal is the direction in which f grows fastest, and a
//! derivative can be estimated from f itself, a little ahead and a little
//! behind.
//!
//! Grade it with: `cargo grade ch4`

use glam::Vec3;

/// The unit normal ∇f/‖∇f‖ of `sdf` at `p`.
pub fn gradient_normal(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    // TODO: your code here (steps: `cargo grade --hint ch4/gradient_normal`).
    todo!()
}
