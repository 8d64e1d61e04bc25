//! The ideal diffuse (Lambertian) BRDF: light leaves equally in every
//! direction, f = ρ/π, whatever ωo and ωi are.

use std::f32::consts::FRAC_1_PI;

use glam::{Vec2, Vec3};

use super::{same_hemisphere, BsdfSample};
use crate::ch5_reflection::warp::{cosine_hemisphere, cosine_hemisphere_pdf};

/// A Lambertian reflector of albedo ρ (each channel in [0, 1]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lambertian {
    /// The albedo ρ: the fraction of arriving power that is reflected.
    pub rho: Vec3,
}

impl Lambertian {
    /// f = ρ/π when ωi and ωo are on the same side, else 0.
    // ANCHOR: lambert_f
    pub fn f(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        if same_hemisphere(wo, wi) {
            self.rho * FRAC_1_PI
        } else {
            Vec3::ZERO
        }
    }
    // ANCHOR_END: lambert_f

    /// Cosine-weighted sampling's pdf, |cos θi| / π on ωo's side.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        if same_hemisphere(wo, wi) {
            cosine_hemisphere_pdf(wi.z.abs())
        } else {
            0.0
        }
    }

    /// A cosine-weighted direction on ωo's side; its weight f cos θ / pdf
    /// is exactly ρ.
    pub fn sample(&self, wo: Vec3, u: Vec2) -> Option<BsdfSample> {
        let mut wi = cosine_hemisphere(u);
        if wo.z < 0.0 {
            wi.z = -wi.z;
        }
        let pdf = self.pdf(wo, wi);
        (pdf > 0.0).then(|| BsdfSample {
            wi,
            f: self.f(wo, wi),
            pdf,
            weight: self.rho,
            delta: false,
        })
    }
}
