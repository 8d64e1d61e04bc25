//! The closed furnace of the path capstone's check: the inside of the unit
//! sphere, Lambertian with albedo ρ and emitting Le everywhere, and all of
//! it one light sampled uniformly by area. Nothing escapes, so only the
//! path loop's own decision (roulette, or a bug) ends a path, and the
//! answer is known: L = Le + ρ L, so L = Le / (1 − ρ) from every point in
//! every direction.
//!
//! The geometry is exact (a sphere, not a mesh), which makes light
//! sampling exact too: from a point of the sphere, cos θ at the point and
//! cos θl at the light are both d / 2 and the area is 4π, so
//! f · Le · cos θ / pdf_ω = (ρ/π) Le (d/2) (d/2) 4π / d² = ρ Le for every
//! sample. The only noise left is the roulette's.

use glam::{Vec2, Vec3};

use super::{Hit, LightSample};

/// The furnace's material.
pub(super) struct Furnace {
    pub albedo: Vec3,
    pub le: Vec3,
    /// A diagnostic: surfaces reached by a bounce report no emission (the
    /// light samples still see Le). A correct loop never adds it, so its
    /// answer does not change; one that counts emission twice loses the
    /// second count.
    pub hide_bounce_emission: bool,
    /// A diagnostic: the share of the light sampler's numbers (u.x below
    /// it) that find no sample (`None`, as a sampler choosing among
    /// lights may choose none), the others' density carrying that share,
    /// so the light samples are still unbiased. A loop that adds nothing
    /// where there is no sample keeps its answer.
    pub no_sample: f32,
    /// A diagnostic: the light samples' radiance and density both this
    /// times the furnace's (1: as they are). Their ratio, and so the light
    /// a sample brings, stays the same.
    pub light_scale: f32,
}

impl Furnace {
    /// The furnace of albedo `albedo` and emission `le`, no diagnostic on.
    pub fn new(albedo: Vec3, le: Vec3) -> Furnace {
        Furnace {
            albedo,
            le,
            hide_bounce_emission: false,
            no_sample: 0.0,
            light_scale: 1.0,
        }
    }

    fn at(&self, p: Vec3) -> Hit {
        // Back onto the sphere (no drift over a thousand bounces).
        let p = p.normalize();
        Hit {
            p,
            n: -p,
            albedo: self.albedo,
            emitted: self.le,
        }
    }

    /// The sphere seen from `o` inside it along the unit `d`.
    pub fn hit(&self, o: Vec3, d: Vec3) -> Option<Hit> {
        let b = o.dot(d);
        let c = o.length_squared() - 1.0;
        if c >= 0.0 {
            return None;
        }
        let t = -b + (b * b - c).sqrt();
        Some(self.at(o + t * d))
    }

    /// Leaving the surface point `at` along the unit `wi`: the chord, of
    /// length −2 p·wi; a direction out of the sphere finds nothing.
    pub fn next(&self, at: &Hit, wi: Vec3) -> Option<Hit> {
        let wi = wi.try_normalize()?;
        let t = -2.0 * at.p.dot(wi);
        let mut hit = (t > 1e-6).then(|| self.at(at.p + t * wi))?;
        if self.hide_bounce_emission {
            hit.emitted = Vec3::ZERO;
        }
        Some(hit)
    }

    /// A point uniform by area on the sphere (pdf_A = 1/4π), as a
    /// direction from `at` with its solid-angle density d² / (cos θl 4π).
    pub fn sample_light(&self, at: &Hit, u: Vec2) -> Option<LightSample> {
        if u.x < self.no_sample {
            return None;
        }
        let found = 1.0 - self.no_sample;
        let u = Vec2::new((u.x - self.no_sample) / found, u.y);
        let z = 1.0 - 2.0 * u.x;
        let r = (1.0 - z * z).max(0.0).sqrt();
        let phi = std::f32::consts::TAU * u.y;
        let y = Vec3::new(r * phi.cos(), r * phi.sin(), z);
        let to = y - at.p;
        let dist = to.length();
        if dist.is_nan() || dist <= 1e-6 {
            return None;
        }
        let wi = to / dist;
        // The light's normal at y points inwards, −y.
        let cos_l = y.dot(wi);
        if cos_l.is_nan() || cos_l <= 0.0 {
            return None;
        }
        let pdf = found * dist * dist / (cos_l * 4.0 * std::f32::consts::PI);
        Some(LightSample {
            wi,
            li: self.le * self.light_scale,
            pdf: pdf * self.light_scale,
            dist,
            delta: false,
        })
    }
}
