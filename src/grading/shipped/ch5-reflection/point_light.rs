//! Exercise 5.3: the irradiance a point light delivers.
//!
//! An isotropic point light of intensity I (W/sr) at `light` lights the
//! surface point `p` (unit normal `n`) with E = I cos θ / r², where r is
//! the distance from p to the light and θ the angle between n and the
//! direction to the light: the inverse-square law times Lambert's cosine
//! law. A light behind the surface (cos θ < 0) delivers nothing.
//!
//! Grade it with: `cargo run --release --bin grade -- ch5`

use glam::Vec3;

/// Irradiance (W/m², per channel) at `p` from a point light.
pub fn point_light_irradiance(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    // TODO: the vector to the light, its length r and direction.
    // TODO: cos θ, clamped at zero.
    // TODO: I cos θ / r².
    todo!()
}
