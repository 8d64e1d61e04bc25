//! Exercise 5.3: the irradiance a point light delivers.
//!
//! An isotropic point light of intensity I (W/sr) sends the same power
//! into every steradian. A surface patch facing it catches the share of
//! the sphere around the light that the patch covers; a tilted patch
//! catches less (Lambert's law).
//!
//! Contract (what the grader checks, to 10⁻⁴ relative, per channel):
//! * the irradiance E (W/m²) at the surface point `p` of unit normal `n`
//!   from a point light of intensity `intensity` at `light`: the
//!   inverse-square law times Lambert's cosine law;
//! * a light behind the surface (the angle between n and the direction to
//!   the light above 90°) delivers exactly 0;
//! * at every scale: the light 10⁻⁶ to 10¹⁵ m from p, p up to 10⁴ times
//!   that from the origin, intensities from 10⁻¹⁵ to 10^38.5 W/sr (near
//!   f32's largest number, where E is still finite; I / r² need not be).
//!
//! Hints: `cargo grade --hint ch5/point_light`.
//! Grade it with: `cargo grade ch5`

use glam::Vec3;

/// Irradiance (W/m², per channel) at `p` from a point light.
pub fn point_light_irradiance(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    // TODO: the inverse-square law and Lambert's law.
    todo!()
}
