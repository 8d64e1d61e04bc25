//! Exercise 5.7, solved: Φ = ∫ I falloff dω = 2π I ∫ falloff d(cos θ).
//! The inner cone gives 1 − cos θi; the smoothstep band, which rises from
//! 0 to 1 symmetrically, half its width, (cos θi − cos θo)/2. So
//! Φ = π I ((1 − cos θi) + (1 − cos θo)), each 1 − cos θ written as
//! 2 sin²(θ/2) so that a narrow cone keeps its digits.

use std::f32::consts::PI;

use glam::Vec3;

/// The power (W, per channel) of a spot light.
pub fn spot_power(intensity: Vec3, inner: f32, outer: f32) -> Vec3 {
    let one_minus_cos = |theta: f32| 2.0 * (theta / 2.0).sin().powi(2);
    intensity * (PI * (one_minus_cos(inner) + one_minus_cos(outer)))
}
