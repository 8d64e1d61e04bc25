//! Exercise 3.3: Möller–Trumbore from the lecture's 3x3 system.
//!
//! A point on the triangle is p0 + u e1 + v e2 (e1 = p1 - p0, e2 = p2 - p0)
//! and a point on the ray is o + t d. Setting them equal gives
//!
//! ```text
//! [e1, e2, -d] (u, v, t)ᵀ = o - p0
//! ```
//!
//! Solve it with Cramer's rule and return (t, u, v) for a hit with u ≥ 0,
//! v ≥ 0, u + v ≤ 1 and t > 0; `None` otherwise (also when the determinant
//! is zero: the ray is parallel to the triangle, or it has no area).
//!
//! Grade it with: `cargo run --release --bin grade -- ch3`

use glam::Vec3;

/// (t, u, v) of the ray o + t d hitting the triangle, if it does.
pub fn moller_trumbore(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    // TODO: det[a, b, c] = a · (b x c). Compute det[e1, e2, -d].
    // TODO: replace one column at a time by s = o - p0 to get u, v and t.
    // TODO: reject hits outside the triangle or behind the origin.
    todo!()
}
