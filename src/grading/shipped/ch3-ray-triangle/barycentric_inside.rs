//! Exercise 3.2: the barycentric inside test.
//!
//! A point p in the plane of the triangle (p0, p1, p2) can be written as
//! p = p0 + u (p1 - p0) + v (p2 - p0). Return (u, v) when p is inside the
//! triangle or on its edges (u ≥ 0, v ≥ 0, u + v ≤ 1), else `None`. A
//! triangle with zero area has no inside.
//!
//! Grade it with: `cargo run --release --bin grade -- ch3`

use glam::Vec3;

/// The barycentric (u, v) of `p` if it lies inside the triangle.
pub fn barycentric_inside(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    // TODO: with e1 = p1 - p0, e2 = p2 - p0, q = p - p0 and N = e1 x e2,
    //       crossing q = u e1 + v e2 with e2 (or e1) isolates u (or v).
    // TODO: return None for a zero-area triangle or a point outside.
    todo!()
}
