//! Exercise 3.2: the barycentric inside test.
//!
//! A point p in the plane of the triangle (p0, p1, p2) can be written as
//! p = p0 + u (p1 - p0) + v (p2 - p0).
//!
//! Contract (what the grader checks: u and v to 1e-4; inside or outside
//! exactly, but for points within rounding of an edge; on triangles
//! 10⁻³·⁵ to 10³ across, up to 10⁴ times their size from the origin):
//! * Return `Some((u, v))` when p is inside the triangle, its edges and
//!   vertices included: u ≥ 0, v ≥ 0 and u + v ≤ 1. A point outside by
//!   less than 1e-4 is still outside.
//! * Return `None` for a point outside, and for a triangle with no area
//!   (its vertices on one line), which has no inside. A sliver has an
//!   inside however thin it is (1 : 10⁴ included): a test that squares
//!   the thinness, as the normal equations' determinant does, loses it in
//!   f32.
//!
//! The idea: p - p0 = u e1 + v e2 has two unknowns in a plane; a cross
//! product with one of the edges removes one of them.
//!
//! Grade it with: `cargo grade ch3`

use glam::Vec3;

/// The barycentric (u, v) of `p` if it lies inside the triangle.
pub fn barycentric_inside(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    // TODO: your code here (steps: `cargo grade --hint ch3/barycentric_inside`).
    todo!()
}
