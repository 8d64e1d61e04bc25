//! Exercise 3.3: Möller–Trumbore from the lecture's 3x3 system.
//!
//! A point on the triangle is p0 + u e1 + v e2 (e1 = p1 - p0, e2 = p2 - p0)
//! and a point on the ray is o + t d. Setting them equal gives
//!
//! ```text
//! [e1, e2, -d] (u, v, t)ᵀ = o - p0
//! ```
//!
//! Contract (what the grader checks: t to 1e-4 relative, u and v to 1e-4):
//! * Return `Some((t, u, v))` when the ray hits the triangle: u ≥ 0,
//!   v ≥ 0, u + v ≤ 1 and t > 0. t is in units of the `d` given (do not
//!   normalise it: with d twice as long, t halves). d is 10⁻²⁶ to 10²⁶
//!   long, the triangles 10⁻³·⁵ to 10³ across (the system's determinant
//!   stays a normal f32) and up to 10⁵ times their size from the world's
//!   origin, the ray starting near them.
//! * Return `None` otherwise: outside the triangle, behind the origin,
//!   and when the system's determinant is zero (the ray runs parallel to
//!   the triangle, or the triangle has no area).
//!
//! The idea: solve the 3x3 system with Cramer's rule, each unknown a
//! ratio of two determinants.
//!
//! Grade it with: `cargo grade ch3`

use glam::Vec3;

/// (t, u, v) of the ray o + t d hitting the triangle, if it does.
pub fn moller_trumbore(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    // TODO: your code here (steps: `cargo grade --hint ch3/moller_trumbore`).
    todo!()
}
