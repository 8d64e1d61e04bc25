//! Glossy specular: most light leaves near the mirror direction, spread
//! into a lobe. The model is the *normalised* Phong lobe (Lewis 1994):
//!
//! f(ωo, ωi) = ρs · (n + 2) / (2π) · cosⁿ α,   α = angle(ωi, mirror of ωo).
//!
//! The factor (n + 2)/(2π) makes the lobe reflect exactly ρs at normal
//! incidence and less elsewhere (part of the lobe dips below the horizon),
//! so no exponent creates energy. cos α is symmetric in ωo and ωi (the
//! mirror map is its own inverse and keeps angles), so the BRDF is
//! reciprocal. Sampling draws ωi from the lobe itself, pdf = (n + 1)/(2π)
//! cosⁿ α, and fails when the drawn direction falls below the surface.

use std::f32::consts::PI;

use glam::{Vec2, Vec3};

use super::mirror::reflect_local;
use super::{same_hemisphere, BsdfSample, Frame};

/// cosⁿ of the angle between unit `a` and `w`, zero on the far side.
#[inline]
pub fn cos_power(a: Vec3, w: Vec3, n: f32) -> f32 {
    let c = a.dot(w).min(1.0);
    if c <= 0.0 {
        0.0
    } else {
        c.powf(n)
    }
}

/// The solid-angle pdf of [`sample_lobe`]: (n + 1)/(2π) cosⁿ α.
// ANCHOR: lobe
pub fn lobe_pdf(axis: Vec3, w: Vec3, n: f32) -> f32 {
    (n + 1.0) / (2.0 * PI) * cos_power(axis, w, n)
}

/// A direction around the unit `axis` with density ∝ cosⁿ α: cos α =
/// u₁^(1/(n+1)) inverts the lobe's cumulative distribution in cos α.
pub fn sample_lobe(axis: Vec3, n: f32, u: Vec2) -> Vec3 {
    let cos_a = u.x.powf(1.0 / (n + 1.0));
    let sin_a = (1.0 - cos_a * cos_a).max(0.0).sqrt();
    let phi = 2.0 * PI * u.y;
    let local = Vec3::new(sin_a * phi.cos(), sin_a * phi.sin(), cos_a);
    Frame::from_normal(axis).to_world(local).normalize_or(axis)
}
// ANCHOR_END: lobe

/// The normalised Phong lobe around the mirror direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Glossy {
    /// ρs: the fraction reflected at normal incidence.
    pub rs: Vec3,
    /// The exponent n ≥ 0: 0 is a broad cosine lobe, 10⁴ almost a mirror.
    pub n: f32,
}

impl Glossy {
    /// ρs (n + 2)/(2π) cosⁿ α on ωo's side.
    // ANCHOR: glossy_f
    pub fn f(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        if !same_hemisphere(wo, wi) {
            return Vec3::ZERO;
        }
        let norm = (self.n + 2.0) / (2.0 * PI);
        self.rs * (norm * cos_power(reflect_local(wo), wi, self.n))
    }
    // ANCHOR_END: glossy_f

    /// The lobe's pdf on ωo's side.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        if same_hemisphere(wo, wi) {
            lobe_pdf(reflect_local(wo), wi, self.n)
        } else {
            0.0
        }
    }

    /// ωi from the lobe; `None` when it lands below the surface.
    pub fn sample(&self, wo: Vec3, u: Vec2) -> Option<BsdfSample> {
        let wi = sample_lobe(reflect_local(wo), self.n, u);
        finish(wo, wi, self.f(wo, wi), self.pdf(wo, wi))
    }
}

/// A BSDF sample from (ωi, f, pdf), or `None` when the pdf is zero or
/// anything is not finite.
pub(crate) fn finish(wo: Vec3, wi: Vec3, f: Vec3, pdf: f32) -> Option<BsdfSample> {
    if !(pdf > 0.0 && pdf.is_finite() && f.is_finite() && same_hemisphere(wo, wi)) {
        return None;
    }
    let weight = f * wi.z.abs() / pdf;
    weight.is_finite().then_some(BsdfSample {
        wi,
        f,
        pdf,
        weight,
        delta: false,
    })
}
