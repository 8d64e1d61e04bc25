//! Exercise 5.1: the Lambertian (ideal diffuse) BRDF.
//!
//! Directions are in the local shading frame: z is the surface normal, so
//! cos θ of a direction is its z component. Both point away from the
//! surface. An ideal diffuse surface of albedo ρ reflects light equally in
//! every direction: f(ωo, ωi) = ρ/π when ωo and ωi are on the same side of
//! the surface (z of the same sign), and 0 otherwise.
//!
//! Grade it with: `cargo run --release --bin grade -- ch5`

use glam::Vec3;

/// f(ωo, ωi) of a Lambertian surface of albedo `rho`.
pub fn lambert_brdf(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3 {
    // TODO: are wo and wi on the same side of the surface?
    // TODO: if so, ρ/π; if not, zero.
    todo!()
}
