//! Exercise 5.1, solved: the Lambertian BRDF.

use glam::Vec3;

/// f(ωo, ωi) of a Lambertian surface of albedo `rho`.
pub fn lambert_brdf(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3 {
    // Same side of the surface (two-sided): ρ/π, since ∫ cos θ dω = π.
    if wo.z * wi.z > 0.0 {
        rho / std::f32::consts::PI
    } else {
        Vec3::ZERO
    }
}
