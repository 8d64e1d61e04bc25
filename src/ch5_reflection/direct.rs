//! The reflection equation, estimated at one surface point:
//!
//! L_r(x, ωr) = L_e(x, ωr) + Σ over lights ∫ f(x, ωi, ωr) L_i(x, ωi) cos θi dωi.
//!
//! Delta lights (point, spot, directional) reach x from one direction, so
//! their integral is one term, f · (I/d² or E) · cos θi, times a shadow
//! ray's verdict. Lights with extent (area lights, the environment) are
//! estimated by Monte Carlo, with one of four strategies ([`Strategy`]).
//! An ideal mirror has no integral either: it sees whatever its one
//! reflected ray sees, up to a bounded number of mirror bounces.

use glam::{Vec2, Vec3};

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch5_reflection::material::{Bsdf, Frame};
use crate::ch5_reflection::mis::power_heuristic;
use crate::ch5_reflection::warp::{uniform_hemisphere, UNIFORM_HEMISPHERE_PDF};
use crate::ch5_reflection::world::{Interaction, World};
use crate::core::sampling::Sampler;

/// The first rung of the ladder, to be read on its own: the radiance
/// arriving along a camera ray, with the reflection equation estimated by
/// *light sampling* alone. Whatever the ray hits adds its own emission and,
/// for each light, one sample: a point on the light (or the one direction
/// of a point, spot or directional light) and a shadow ray to it,
/// weighted f · L · cos θ / pdf. No BRDF sampling and no MIS.
///
/// This is [`Strategy::Light`] of [`Estimator::radiance`] without its
/// options: it draws the same random numbers in the same order, so on a
/// scene without mirrors the two give the same image up to rounding (a
/// test checks it), and both converge to the image of [`Strategy::Mis`].
/// An ideal mirror reflects light from one direction only, which no light
/// sample hits: here it stays black, where [`Estimator::radiance`] follows
/// its reflected ray.
// ANCHOR: direct_lighting
pub fn direct_lighting(world: &World, ray: &Ray, s: &mut Sampler) -> Vec3 {
    let Some(it) = world.intersect(ray) else {
        return world.lights.environment_radiance(ray.dir); // the sky, if any
    };
    let wo = -ray.dir;
    let bsdf = &world.bsdfs[it.material];
    let frame = Frame::from_normal(it.n);
    // The normal on the viewer's side (BRDFs are two-sided).
    let n = if wo.dot(it.n) < 0.0 { -it.n } else { it.n };
    let mut l = world.emitted(&it, wo);
    for light in &world.lights.lights {
        // A direction towards the light, the radiance it brings and its pdf
        // (per solid angle; 1 for a light with a single direction).
        let Some(ls) = light.sample_li(it.p, n, s.next2()) else {
            continue;
        };
        let cos = ls.wi.dot(n);
        if cos <= 0.0 || !world.unoccluded(it.p, it.n, ls.wi, ls.dist) {
            continue; // behind the surface, or in shadow
        }
        let f = bsdf.f(frame.to_local(wo), frame.to_local(ls.wi));
        l += f * ls.li * cos / ls.pdf;
    }
    l
}
// ANCHOR_END: direct_lighting

/// How the integral over lights with extent is estimated.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Strategy {
    /// A direction uniform over the hemisphere, pdf 1/(2π); the light is
    /// whatever the ray hits.
    Uniform,
    /// A direction from the BRDF (`Bsdf::sample`): cosine-weighted on a
    /// Lambertian surface, the lobe on glossy ones.
    Cosine,
    /// A point on each light (by area, or the sky by brightness), with a
    /// shadow ray.
    Light,
    /// One light sample and one BRDF sample, each weighted by the power
    /// heuristic.
    Mis,
}

impl Strategy {
    /// All four, in the order of the chapter's variants.
    pub const ALL: [Strategy; 4] = [
        Strategy::Uniform,
        Strategy::Cosine,
        Strategy::Light,
        Strategy::Mis,
    ];

    /// Short name.
    pub fn name(self) -> &'static str {
        match self {
            Strategy::Uniform => "uniform",
            Strategy::Cosine => "cosine",
            Strategy::Light => "light",
            Strategy::Mis => "mis",
        }
    }

    /// Whether the strategy samples the lights (light sampling or MIS).
    pub fn samples_lights(self) -> bool {
        matches!(self, Strategy::Light | Strategy::Mis)
    }

    fn samples_directions(self) -> bool {
        !matches!(self, Strategy::Light)
    }
}

/// What one estimate cost and caught.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counters {
    /// Shadow rays traced towards sampled lights.
    pub shadow_rays: u64,
    /// Rays traced along sampled directions to find what they see.
    pub direction_rays: u64,
    /// Mirror bounces followed.
    pub mirror_bounces: u64,
    /// Terms that came out NaN or infinite and were dropped.
    pub nonfinite: u64,
}

impl std::ops::AddAssign for Counters {
    fn add_assign(&mut self, o: Counters) {
        self.shadow_rays += o.shadow_rays;
        self.direction_rays += o.direction_rays;
        self.mirror_bounces += o.mirror_bounces;
        self.nonfinite += o.nonfinite;
    }
}

/// The estimator's settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimator {
    /// How lights with extent are sampled.
    pub strategy: Strategy,
    /// Mirror bounces followed before giving up (the rest is black).
    pub max_mirror_bounces: u32,
    /// Whether to trace shadow rays; `false` only for scenes where nothing
    /// can shadow anything (see [`scene_cannot_shadow`](super::render::scene_cannot_shadow)).
    pub shadow_rays: bool,
}

impl Estimator {
    /// Radiance arriving along `ray`: what it hits emits and reflects, or
    /// the environment if it escapes.
    // ANCHOR: radiance
    pub fn radiance(&self, world: &World, ray: &Ray, s: &mut Sampler, c: &mut Counters) -> Vec3 {
        self.radiance_at_depth(world, ray, s, c, 0)
    }

    fn radiance_at_depth(
        &self,
        world: &World,
        ray: &Ray,
        s: &mut Sampler,
        c: &mut Counters,
        depth: u32,
    ) -> Vec3 {
        let Some(it) = world.intersect(ray) else {
            return world.lights.environment_radiance(ray.dir);
        };
        let wo = -ray.dir;
        let bsdf = &world.bsdfs[it.material];
        let mut l = world.emitted(&it, wo);
        if bsdf.is_delta() {
            // An ideal mirror: follow its one direction, a bounded number of times.
            if depth >= self.max_mirror_bounces {
                return l;
            }
            let frame = Frame::from_normal(it.n);
            let u = s.next2();
            let u_lobe = s.next();
            if let Some(b) = bsdf.sample(frame.to_local(wo), u, u_lobe) {
                let wi = frame.to_world(b.wi);
                if let Some(next) = world.spawn(it.p, it.n, wi) {
                    c.mirror_bounces += 1;
                    l += b.weight * self.radiance_at_depth(world, &next, s, c, depth + 1);
                }
            }
            return l;
        }
        l + self.reflected(world, &it, wo, s, c)
    }
    // ANCHOR_END: radiance

    /// The sum over lights of the reflection equation's integral at `it`
    /// towards `wo` (a non-delta BRDF).
    // ANCHOR: reflected
    pub fn reflected(
        &self,
        world: &World,
        it: &Interaction,
        wo: Vec3,
        s: &mut Sampler,
        c: &mut Counters,
    ) -> Vec3 {
        let bsdf = &world.bsdfs[it.material];
        let frame = Frame::from_normal(it.n);
        let wo_local = frame.to_local(wo);
        // The normal on the viewer's side (BRDFs are two-sided).
        let n = if wo.dot(it.n) < 0.0 { -it.n } else { it.n };
        let mut sum = Vec3::ZERO;
        let mut add = |term: Vec3, c: &mut Counters| {
            if term.is_finite() {
                sum += term;
            } else {
                c.nonfinite += 1;
            }
        };
        let mut extended = false;
        for light in &world.lights.lights {
            let delta = light.is_delta();
            extended |= !delta;
            if !delta && !self.strategy.samples_lights() {
                continue;
            }
            // Sample the light: one term per delta light, one sample per
            // area light or environment.
            let u = s.next2();
            let Some(ls) = light.sample_li(it.p, n, u) else {
                continue;
            };
            let cos = ls.wi.dot(n);
            if cos <= 0.0 {
                continue;
            }
            let wi_local = frame.to_local(ls.wi);
            let f = bsdf.f(wo_local, wi_local);
            if f == Vec3::ZERO || !self.visible(world, it, ls.wi, ls.dist, c) {
                continue;
            }
            let weight = if delta || self.strategy == Strategy::Light {
                1.0
            } else {
                power_heuristic(ls.pdf, bsdf.pdf(wo_local, wi_local))
            };
            add(f * ls.li * cos * (weight / ls.pdf), c);
        }
        if extended && self.strategy.samples_directions() {
            // Sample a direction and see what it finds.
            let u = s.next2();
            let u_lobe = s.next();
            if let Some(term) =
                self.direction_sample(world, it, bsdf, &frame, wo_local, n, u, u_lobe, c)
            {
                add(term, c);
            }
        }
        sum
    }
    // ANCHOR_END: reflected

    /// One direction from the uniform hemisphere or the BRDF: f L cos / pdf
    /// of what it finds, MIS-weighted against light sampling under MIS.
    #[allow(clippy::too_many_arguments)]
    fn direction_sample(
        &self,
        world: &World,
        it: &Interaction,
        bsdf: &Bsdf,
        frame: &Frame,
        wo_local: Vec3,
        n: Vec3,
        u: Vec2,
        u_lobe: f32,
        c: &mut Counters,
    ) -> Option<Vec3> {
        let (wi_local, f, pdf) = if self.strategy == Strategy::Uniform {
            let mut w = uniform_hemisphere(u);
            if wo_local.z < 0.0 {
                w.z = -w.z;
            }
            (w, bsdf.f(wo_local, w), UNIFORM_HEMISPHERE_PDF)
        } else {
            let b = bsdf.sample(wo_local, u, u_lobe)?;
            (b.wi, b.f, b.pdf)
        };
        if f == Vec3::ZERO || pdf <= 0.0 {
            return None;
        }
        let wi = frame.to_world(wi_local);
        let cos = wi.dot(n);
        if cos <= 0.0 {
            return None;
        }
        // What does the ray see? Without occluders it can only escape.
        let (le, pdf_light) = match self.trace(world, it, wi, c) {
            None => (
                world.lights.environment_radiance(wi),
                world.lights.environment_pdf(n, wi),
            ),
            Some(hit) => {
                let le = world.emitted(&hit, -wi);
                if le == Vec3::ZERO {
                    return None;
                }
                let pdf_light = world
                    .area_light(&hit)
                    .map_or(0.0, |(_, a)| a.pdf_li(it.p, hit.p, hit.n));
                (le, pdf_light)
            }
        };
        let weight = if self.strategy == Strategy::Mis {
            power_heuristic(pdf, pdf_light)
        } else {
            1.0
        };
        Some(f * le * cos * (weight / pdf))
    }

    fn trace(
        &self,
        world: &World,
        it: &Interaction,
        wi: Vec3,
        c: &mut Counters,
    ) -> Option<Interaction> {
        if !self.shadow_rays {
            return None;
        }
        c.direction_rays += 1;
        world.intersect(&world.spawn(it.p, it.n, wi)?)
    }

    fn visible(
        &self,
        world: &World,
        it: &Interaction,
        wi: Vec3,
        dist: f32,
        c: &mut Counters,
    ) -> bool {
        if !self.shadow_rays {
            return true;
        }
        c.shadow_rays += 1;
        world.unoccluded(it.p, it.n, wi, dist)
    }
}
