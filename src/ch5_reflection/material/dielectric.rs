//! A smooth dielectric (glass, water): the lecture's "Transmission" slide.
//! At the boundary between two media light splits into a reflected part,
//! the Fresnel reflectance F, and a refracted part 1 - F bent by Snell's law
//! η_i sin θ_i = η_t sin θ_t. Past the critical angle (going from the denser
//! medium out) no refracted direction exists: total internal reflection,
//! F = 1. Nothing is absorbed.
//!
//! Both lobes are deltas, so [`Dielectric::sample`] picks one with
//! probability F (reflect) or 1 - F (refract); the Fresnel factor then
//! cancels against that probability and the weight is 1 for reflection and
//! the radiance scaling (η_o/η_i)² for refraction: radiance crossing into a
//! denser medium is compressed into a smaller solid angle, so L/η² is what
//! stays constant along a path (this is why a camera inside glass under a
//! uniform sky sees η² times the sky, see the tests).
//!
//! The outward normal (local +z) says which side is the glass: a direction
//! with z > 0 is outside (index 1), z < 0 inside (index `ior`).

use glam::Vec3;

use super::BsdfSample;

/// A smooth dielectric boundary between vacuum (outside) and a medium of
/// index of refraction `ior` (inside).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dielectric {
    /// The index of refraction η of the inside (1.5 for glass).
    pub ior: f32,
}

/// Fresnel reflectance of unpolarised light arriving at cos θ_i (≥ 0) and
/// leaving at cos θ_t (≥ 0), going from index `eta_i` to `eta_t`: the mean
/// of the s- and p-polarised reflectances.
// ANCHOR: fresnel
pub fn fresnel_dielectric(cos_i: f32, cos_t: f32, eta_i: f32, eta_t: f32) -> f32 {
    let r_s = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
    let r_p = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
    let f = 0.5 * (r_s * r_s + r_p * r_p);
    if f.is_finite() {
        f.clamp(0.0, 1.0)
    } else {
        1.0
    }
}
// ANCHOR_END: fresnel

/// Snell's law in the local frame: the refracted direction of `wo` (unit,
/// pointing away from the surface) through the boundary, where `eta` =
/// η on wo's side / η on the far side. `None` past the critical angle
/// (total internal reflection).
// ANCHOR: refract
pub fn refract_local(wo: Vec3, eta: f32) -> Option<Vec3> {
    let cos_o = wo.z.abs();
    let sin2_t = eta * eta * (1.0 - cos_o * cos_o).max(0.0);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    // The normal on wo's side; the refracted ray leaves on the other side.
    let n = Vec3::new(0.0, 0.0, 1.0f32.copysign(wo.z));
    Some((-eta * wo + (eta * cos_o - cos_t) * n).normalize())
}
// ANCHOR_END: refract

impl Dielectric {
    /// (F, η on wo's side / η on the far side) for light leaving towards
    /// `wo`; F = 1 under total internal reflection.
    pub fn fresnel(&self, wo: Vec3) -> (f32, f32) {
        let outside = wo.z > 0.0;
        let (eta_o, eta_far) = if outside {
            (1.0, self.ior)
        } else {
            (self.ior, 1.0)
        };
        let eta = eta_o / eta_far;
        let cos_o = wo.z.abs();
        let sin2_t = eta * eta * (1.0 - cos_o * cos_o).max(0.0);
        if sin2_t >= 1.0 {
            return (1.0, eta);
        }
        let cos_t = (1.0 - sin2_t).sqrt();
        (fresnel_dielectric(cos_o, cos_t, eta_o, eta_far), eta)
    }

    /// Reflects with probability F, else refracts; `u_lobe` in [0, 1)
    /// decides. Both lobes are deltas.
    // ANCHOR: dielectric_sample
    pub fn sample(&self, wo: Vec3, u_lobe: f32) -> Option<BsdfSample> {
        if wo.z == 0.0 {
            return None;
        }
        let (f, eta) = self.fresnel(wo);
        if u_lobe < f {
            // Reflection: F / P(reflect) = 1.
            return Some(BsdfSample {
                wi: Vec3::new(-wo.x, -wo.y, wo.z),
                f: Vec3::ZERO,
                pdf: 0.0,
                weight: Vec3::ONE,
                delta: true,
            });
        }
        let wi = refract_local(wo, eta)?;
        // (1 - F) / P(refract) = 1, times the radiance scaling (η_o/η_far)².
        Some(BsdfSample {
            wi,
            f: Vec3::ZERO,
            pdf: 0.0,
            weight: Vec3::splat(eta * eta),
            delta: true,
        })
    }
    // ANCHOR_END: dielectric_sample
}
