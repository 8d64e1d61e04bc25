//! The lecture's "red semi-gloss paint": a diffuse base under a thin
//! glossy coat. The combination is a convex mix,
//!
//! f = (1 − k_s) · ρ/π + k_s · glossy(ρs = 1, n),
//!
//! so its albedo is at most (1 − k_s)·ρ + k_s ≤ 1 and it is reciprocal
//! because both parts are. The coat is white: highlights show the light's
//! colour, the base shows the paint's.
//!
//! Sampling picks a lobe with `u_lobe` (the coat with probability
//! [`SemiGloss::coat_probability`]) and then draws from it; the pdf is the
//! same mixture of both lobes' pdfs, whichever one drew the sample.

use std::f32::consts::FRAC_1_PI;

use glam::{Vec2, Vec3};

use super::glossy::{finish, Glossy};
use super::{same_hemisphere, BsdfSample};
use crate::ch5_reflection::warp::{cosine_hemisphere, cosine_hemisphere_pdf};

/// Diffuse base plus glossy coat.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SemiGloss {
    /// The base's albedo ρ.
    pub rho: Vec3,
    /// The coat's share k_s in [0, 1].
    pub ks: f32,
    /// The coat's exponent n.
    pub n: f32,
}

impl SemiGloss {
    fn coat(&self) -> Glossy {
        Glossy {
            rs: Vec3::ONE,
            n: self.n,
        }
    }

    /// How often sampling picks the coat: k_s kept within [0.1, 0.9] so
    /// neither lobe is starved (exactly 0 or 1 when a lobe is absent).
    pub fn coat_probability(&self) -> f32 {
        match self.ks {
            k if k <= 0.0 => 0.0,
            k if k >= 1.0 => 1.0,
            k => k.clamp(0.1, 0.9),
        }
    }

    /// (1 − k_s) ρ/π + k_s · coat.
    // ANCHOR: semigloss_f
    pub fn f(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        if !same_hemisphere(wo, wi) {
            return Vec3::ZERO;
        }
        (1.0 - self.ks) * self.rho * FRAC_1_PI + self.ks * self.coat().f(wo, wi)
    }
    // ANCHOR_END: semigloss_f

    /// The mixture of the cosine pdf and the coat's pdf.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        if !same_hemisphere(wo, wi) {
            return 0.0;
        }
        let p = self.coat_probability();
        (1.0 - p) * cosine_hemisphere_pdf(wi.z.abs()) + p * self.coat().pdf(wo, wi)
    }

    /// Picks a lobe by `u_lobe`, draws ωi from it.
    pub fn sample(&self, wo: Vec3, u: Vec2, u_lobe: f32) -> Option<BsdfSample> {
        let wi = if u_lobe < self.coat_probability() {
            super::glossy::sample_lobe(super::mirror::reflect_local(wo), self.n, u)
        } else {
            let mut wi = cosine_hemisphere(u);
            if wo.z < 0.0 {
                wi.z = -wi.z;
            }
            wi
        };
        finish(wo, wi, self.f(wo, wi), self.pdf(wo, wi))
    }
}
