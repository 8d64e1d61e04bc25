//! Exercise 5.6: the solid angle of a triangle.
//!
//! Seen from a point p, a triangle casts a shadow on the unit sphere
//! around p: its corners land on the sphere, its edges become arcs of
//! great circles, and the shadow is a spherical triangle. Its area is the
//! solid angle Ω the triangle subtends at p, in steradians. A small
//! triangle far away covers about A cos θ / r²; an infinite plane, seen
//! from either side, covers half the sphere.
//!
//! Contract (what the grader checks):
//! * Ω ≥ 0 of the triangle `tri` seen from `p`, the same for either order
//!   (winding) of its corners;
//! * wherever p is: just above a large triangle (Ω near 2π), beside it in
//!   its plane (exactly 0 there), far away (a triangle 1000 times its size
//!   away), seen edge-on, and for slivers (1:1000); the answer does not
//!   change with where the scene sits (up to 10⁴ times its size from the
//!   origin) or its scale (10⁻³·⁵ to 10³ m);
//! * p on the triangle itself is not checked (Ω jumps from 2π to 0 there);
//! * to 10⁻⁴ relative to the exact Ω of your inputs (worked out in f64),
//!   widened only by what f32 rounding alone does: the change of the exact
//!   Ω when a corner moves by 10⁻⁶ of the longest edge ℓ₁, p by 10⁻⁶ of its
//!   distance to the farthest corner, or the plane tilts by
//!   10⁻⁶ ℓ₁ℓ₂/(2A) rad (ℓ₂ the second longest edge, A the area). That
//!   matters near an edge, for slivers and edge-on views, not for a small
//!   triangle far away seen from the front.
//!
//! Hints: `cargo grade --hint ch5/solid_angle`.
//! Grade it with: `cargo grade ch5`

use glam::Vec3;

/// The solid angle (sr) the triangle `tri` subtends at `p`.
pub fn solid_angle(p: Vec3, tri: [Vec3; 3]) -> f32 {
    // TODO: the area of the triangle's shadow on the unit sphere around p.
    todo!()
}
