//! Exercise 3.1: intersect a ray with a plane.
//!
//! The ray is r(t) = o + t d; the plane is every point x with Nᵀx = c.
//!
//! Contract (what the grader checks, to 1e-4 relative):
//! * Return the t at which o + t d lies on the plane. Neither N nor d needs
//!   to be unit length: N may be 10⁻²⁶ to 10²⁵ long and d 10⁻¹² to 10³,
//!   and Nᵀd is 0 or a normal f32 number (2⁻¹²⁶ or more in size; |N|²
//!   need not be). t may be negative (a plane behind the origin): its
//!   sign is the caller's business.
//! * Return `None` when the ray runs parallel to the plane (Nᵀd = 0).
//!
//! The idea: a point of the ray is on the plane when it satisfies the
//! plane's equation, and that equation is linear in t.
//!
//! Grade it with: `cargo grade ch3`

use glam::Vec3;

/// The ray parameter t where o + t d lies on the plane Nᵀx = c.
pub fn ray_plane(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    // TODO: your code here (steps: `cargo grade --hint ch3/ray_plane`).
    todo!()
}
