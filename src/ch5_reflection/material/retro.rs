//! Retro-reflective: light goes back the way it came (road signs, cat's
//! eyes, the full moon). No mainstream renderer ships such a BRDF, so this
//! one is ours, built like the glossy lobe but around ωo instead of the
//! mirror direction:
//!
//! f(ωo, ωi) = ρ · (n + 2) / (2π) · cosⁿ β,   β = angle(ωi, ωo).
//!
//! For a viewer at ωo, the surface is brightest when the light sits right
//! behind the viewer. cos β = ωi · ωo is symmetric, so f is reciprocal; the
//! same normalisation as the glossy lobe reflects exactly ρ at normal
//! incidence and less at other angles (tests check both by Monte Carlo).

use std::f32::consts::PI;

use glam::{Vec2, Vec3};

use super::glossy::{cos_power, finish, lobe_pdf, sample_lobe};
use super::{same_hemisphere, BsdfSample};

/// A lobe around the direction back towards the viewer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Retro {
    /// ρ: the fraction reflected at normal incidence.
    pub rho: Vec3,
    /// The exponent n ≥ 0.
    pub n: f32,
}

impl Retro {
    /// ρ (n + 2)/(2π) cosⁿ β on ωo's side.
    // ANCHOR: retro_f
    pub fn f(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        if !same_hemisphere(wo, wi) {
            return Vec3::ZERO;
        }
        self.rho * ((self.n + 2.0) / (2.0 * PI) * cos_power(wo, wi, self.n))
    }
    // ANCHOR_END: retro_f

    /// The lobe's pdf around ωo, on ωo's side.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        if same_hemisphere(wo, wi) {
            lobe_pdf(wo, wi, self.n)
        } else {
            0.0
        }
    }

    /// ωi from the lobe around ωo; `None` below the surface.
    pub fn sample(&self, wo: Vec3, u: Vec2) -> Option<BsdfSample> {
        let wi = sample_lobe(wo, self.n, u);
        finish(wo, wi, self.f(wo, wi), self.pdf(wo, wi))
    }
}
