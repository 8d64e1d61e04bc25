//! Exercise 5.1: the Lambertian (ideal diffuse) BRDF.
//!
//! An ideal diffuse surface of albedo ρ reflects the light it receives
//! equally in every direction, and reflects the fraction ρ of it in all:
//! energy conservation fixes its one constant.
//!
//! Contract (what the grader checks, exactly, to 10⁻⁵ relative):
//! * directions are unit vectors in the local shading frame, z the surface
//!   normal, both pointing away from the surface;
//! * when ωo and ωi are on the same side of the surface (z of the same
//!   sign, above or below: the BRDF is two-sided), f is the constant whose
//!   integral ∫ f cos θ dω over the hemisphere is ρ, per channel;
//! * on opposite sides, f = 0; and so when either direction lies in the
//!   surface's plane (z = 0 or −0): it is on neither side.
//! * one z may be as small as 10⁻³⁰, the other then no smaller than
//!   10⁻⁶: the product of the two stays within f32's range.
//!
//! Hints: `cargo grade --hint ch5/lambert_brdf`.
//! Grade it with: `cargo grade ch5`

use glam::Vec3;

/// f(ωo, ωi) of a Lambertian surface of albedo `rho`.
pub fn lambert_brdf(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3 {
    // TODO: the BRDF of an ideal diffuse surface.
    todo!()
}
