//! Materials as BSDFs: how much of the light arriving from ωi leaves
//! towards ωo (chapter 5, the lecture's BRDF slides; chapter 6 adds
//! transmission).
//!
//! ## Conventions (one place for all of them)
//!
//! - Every BSDF works in a local [`Frame`] whose z axis is the surface's
//!   *outward* normal (a mesh's winding normal, an SDF's gradient), so
//!   cos θ of a direction is its z component.
//! - Both directions point away from the surface: ωo towards the viewer,
//!   ωi towards the light.
//! - Reflection BRDFs are two-sided: they reflect on whichever side ωo is
//!   on, and `f` is zero unless ωi is on that side too. Transmissive BSDFs
//!   (glass) use the outward normal to know whether the ray enters or leaves.
//! - `pdf` is in solid angle. Delta lobes (the ideal mirror) have no
//!   finite density: `sample` marks them with `delta = true` and returns
//!   f / pdf in `weight` directly; `f` and `pdf` of a delta lobe are 0.
//! - `sample` may fail (return `None`) when the drawn direction falls below
//!   the surface; the estimator then counts that sample as zero, which is
//!   unbiased because the pdf accounts for the lost mass.

pub mod dielectric;
pub mod frame;
pub mod glossy;
pub mod lambert;
pub mod mirror;
pub mod retro;
pub mod semigloss;

pub use frame::Frame;

use glam::{Vec2, Vec3};

use crate::scene::file::MaterialKind;
use crate::scene::Material;

/// A direction drawn from a BSDF.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BsdfSample {
    /// ωi in the local frame (unit length).
    pub wi: Vec3,
    /// The BSDF value f(ωo, ωi) (for a delta lobe: 0, see `weight`).
    pub f: Vec3,
    /// The pdf in solid angle (for a delta lobe: 0, see `weight`).
    pub pdf: f32,
    /// f · |cos θi| / pdf: what a path's throughput is multiplied by.
    pub weight: Vec3,
    /// Whether the direction came from a delta lobe (mirror, glass).
    pub delta: bool,
}

/// A BSDF: a closed set of models, an enum so the hot loop has no virtual
/// calls.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bsdf {
    /// Ideal diffuse: f = ρ/π.
    Lambertian(lambert::Lambertian),
    /// Ideal specular reflection: a delta lobe around the mirror direction.
    Mirror(mirror::Mirror),
    /// Glossy specular: a normalised Phong lobe around the mirror direction.
    Glossy(glossy::Glossy),
    /// Retro-reflective: a normalised lobe around the direction to the viewer.
    Retro(retro::Retro),
    /// Semi-gloss paint: diffuse base plus a white glossy coat.
    SemiGloss(semigloss::SemiGloss),
    /// Smooth glass: Fresnel reflection and Snell refraction, two deltas.
    Dielectric(dielectric::Dielectric),
}

impl Bsdf {
    /// The BSDF of a scene material.
    pub fn from_material(m: &Material) -> Bsdf {
        match m.kind {
            MaterialKind::Diffuse => Bsdf::Lambertian(lambert::Lambertian { rho: m.reflectance }),
            MaterialKind::Mirror => Bsdf::Mirror(mirror::Mirror { r: m.reflectance }),
            MaterialKind::Glossy => Bsdf::Glossy(glossy::Glossy {
                rs: m.reflectance,
                n: m.exponent,
            }),
            MaterialKind::Retroreflective => Bsdf::Retro(retro::Retro {
                rho: m.reflectance,
                n: m.exponent,
            }),
            MaterialKind::Semigloss => Bsdf::SemiGloss(semigloss::SemiGloss {
                rho: m.reflectance,
                ks: m.specular,
                n: m.exponent,
            }),
            MaterialKind::Glass => Bsdf::Dielectric(dielectric::Dielectric { ior: m.ior }),
        }
    }

    /// f(ωo, ωi), both local. Zero for delta lobes.
    pub fn f(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        match self {
            Bsdf::Lambertian(b) => b.f(wo, wi),
            Bsdf::Mirror(_) => Vec3::ZERO,
            Bsdf::Glossy(b) => b.f(wo, wi),
            Bsdf::Retro(b) => b.f(wo, wi),
            Bsdf::SemiGloss(b) => b.f(wo, wi),
            Bsdf::Dielectric(_) => Vec3::ZERO,
        }
    }

    /// The solid-angle pdf with which [`Bsdf::sample`] returns ωi given ωo.
    /// Zero for delta lobes.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        match self {
            Bsdf::Lambertian(b) => b.pdf(wo, wi),
            Bsdf::Mirror(_) => 0.0,
            Bsdf::Glossy(b) => b.pdf(wo, wi),
            Bsdf::Retro(b) => b.pdf(wo, wi),
            Bsdf::SemiGloss(b) => b.pdf(wo, wi),
            Bsdf::Dielectric(_) => 0.0,
        }
    }

    /// Draws ωi given ωo from two uniform numbers `u` (and `u_lobe` to pick
    /// a lobe in BSDFs with several).
    pub fn sample(&self, wo: Vec3, u: Vec2, u_lobe: f32) -> Option<BsdfSample> {
        match self {
            Bsdf::Lambertian(b) => b.sample(wo, u),
            Bsdf::Mirror(b) => b.sample(wo),
            Bsdf::Glossy(b) => b.sample(wo, u),
            Bsdf::Retro(b) => b.sample(wo, u),
            Bsdf::SemiGloss(b) => b.sample(wo, u, u_lobe),
            Bsdf::Dielectric(b) => b.sample(wo, u_lobe),
        }
    }

    /// Whether every lobe is a delta (then light sampling cannot help).
    pub fn is_delta(&self) -> bool {
        matches!(self, Bsdf::Mirror(_) | Bsdf::Dielectric(_))
    }
}

/// Whether two local directions lie on the same side of the surface.
#[inline]
pub fn same_hemisphere(a: Vec3, b: Vec3) -> bool {
    a.z * b.z > 0.0
}
