//! The reflection equation, estimated at one surface point:
//!
//! L_r(x, ωr) = L_e(x, ωr) + Σ over lights ∫ f(x, ωi, ωr) L_i(x, ωi) cos θi dωi.
//!
//! Delta lights (point, spot, directional) reach x from one direction, so
//! their integral is one term, f · (I/d² or E) · cos θi, times a shadow
//! ray's verdict. Lights with extent (area lights, the environment) are
//! estimated by Monte Carlo, with one of four strategies ([`Strategy`],
//! the lecture's ladder, which chapter 6 climbs again along whole paths).
//! An ideal mirror has no integral either: it sees whatever its one
//! reflected ray sees, up to a bounded number of mirror bounces.

use glam::{Vec2, Vec3};

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch5_reflection::material::{Bsdf, Frame};
use crate::ch5_reflection::mis::power_heuristic;
use crate::ch5_reflection::warp::{uniform_hemisphere, UNIFORM_HEMISPHERE_PDF};
use crate::ch5_reflection::world::{Interaction, World};
use crate::core::sampling::Sampler;

use super::shading_events::{ShadingEvent, Tally};

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

/// How an integral of incoming light is sampled: the lecture's ladder,
/// from the plainest strategy to the best. Chapter 5 uses it for the lights
/// with extent at one surface point ([`Estimator`]); chapter 6 at every
/// vertex of a path ([`PathSettings`](crate::ch6_global_illumination::integrator::PathSettings)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Strategy {
    /// A direction uniform over the hemisphere, pdf 1/(2π); the light is
    /// whatever the ray hits.
    Uniform,
    /// A direction from the BSDF (`Bsdf::sample`): cosine-weighted on a
    /// Lambertian surface, the lobe on glossy ones; the light is whatever
    /// the ray hits.
    Bsdf,
    /// A point on each light (by area, or the sky by brightness), with a
    /// shadow ray (next-event estimation). In chapter 6 emitters the path
    /// hits count only where light sampling could not have found them.
    Light,
    /// One light sample and one BSDF sample, each weighted by the power
    /// heuristic.
    Mis,
}

impl Strategy {
    /// All four, in ladder order (the order of the chapters' variants).
    pub const ALL: [Strategy; 4] = [
        Strategy::Uniform,
        Strategy::Bsdf,
        Strategy::Light,
        Strategy::Mis,
    ];

    /// Short name, for tables, file names and the `--estimator` flag.
    pub fn name(self) -> &'static str {
        match self {
            Strategy::Uniform => "uniform",
            Strategy::Bsdf => "bsdf",
            Strategy::Light => "light",
            Strategy::Mis => "mis",
        }
    }

    /// Whether the strategy samples the lights (light sampling or MIS).
    pub fn samples_lights(self) -> bool {
        matches!(self, Strategy::Light | Strategy::Mis)
    }

    /// Whether the strategy samples a direction and looks for light there
    /// (every strategy but light sampling).
    pub fn samples_directions(self) -> bool {
        !matches!(self, Strategy::Light)
    }
}

/// The estimator of the reflection equation, with its settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimator {
    /// How lights with extent are sampled.
    pub strategy: Strategy,
    /// Mirror bounces followed before giving up (the rest is black).
    pub max_mirror_bounces: u32,
    /// Whether rays leave the shading point towards light: shadow rays to
    /// sampled lights, and the rays along sampled directions that look for
    /// emitters. `false` only for scenes where nothing can shadow anything
    /// (see [`scene_cannot_shadow`](super::shadowing::scene_cannot_shadow)):
    /// then every light sample counts as unblocked and every sampled
    /// direction as escaping to the sky, without tracing a ray.
    pub trace_light_rays: bool,
}

/// A surface point being shaded, with what every term there needs.
struct ShadingPoint<'a> {
    world: &'a World,
    it: &'a Interaction,
    bsdf: &'a Bsdf,
    frame: Frame,
    /// The direction towards the viewer, in the local frame.
    wo_local: Vec3,
    /// The normal on the viewer's side (BRDFs are two-sided).
    n: Vec3,
}

impl<'a> ShadingPoint<'a> {
    fn new(world: &'a World, it: &'a Interaction, wo: Vec3) -> Self {
        let frame = Frame::from_normal(it.n);
        ShadingPoint {
            world,
            it,
            bsdf: &world.bsdfs[it.material],
            frame,
            wo_local: frame.to_local(wo),
            n: if wo.dot(it.n) < 0.0 { -it.n } else { it.n },
        }
    }
}

/// `term` if it is finite; otherwise it is counted and dropped.
fn finite(term: Vec3, c: &mut impl Tally) -> Option<Vec3> {
    if term.is_finite() {
        Some(term)
    } else {
        c.counters().nonfinite += 1;
        None
    }
}

impl Estimator {
    /// Radiance arriving along `ray`: what it hits emits and reflects, or
    /// the environment if it escapes.
    // ANCHOR: radiance
    // ANCHOR: radiance_hit
    pub fn radiance(&self, world: &World, ray: &Ray, s: &mut Sampler, c: &mut impl Tally) -> Vec3 {
        self.radiance_at_depth(world, ray, s, c, 0)
    }

    fn radiance_at_depth(
        &self,
        world: &World,
        ray: &Ray,
        s: &mut Sampler,
        c: &mut impl Tally,
        depth: u32,
    ) -> Vec3 {
        let Some(it) = world.intersect(ray) else {
            let sky = world.lights.environment_radiance(ray.dir);
            c.note(ShadingEvent::Escaped { sky }); // tell a listener (the inspector)
            return sky;
        };
        // ANCHOR_END: radiance_hit
        // ANCHOR: radiance_mirror
        let wo = -ray.dir;
        let bsdf = &world.bsdfs[it.material];
        let mut l = world.emitted(&it, wo);
        c.note(ShadingEvent::hit(l, bsdf.is_delta())); // tell a listener (the inspector)
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
                    c.counters().mirror_bounces += 1;
                    l += b.weight * self.radiance_at_depth(world, &next, s, c, depth + 1);
                }
            }
            return l;
        }
        l + self.reflected(world, &it, wo, s, c)
    }
    // ANCHOR_END: radiance_mirror
    // ANCHOR_END: radiance

    /// The sum over lights of the reflection equation's integral at `it`
    /// towards `wo` (a non-delta BRDF): one term per light sampled, and one
    /// for a sampled direction.
    // ANCHOR: reflected
    // ANCHOR: reflected_lights
    pub fn reflected(
        &self,
        world: &World,
        it: &Interaction,
        wo: Vec3,
        s: &mut Sampler,
        c: &mut impl Tally,
    ) -> Vec3 {
        let at = ShadingPoint::new(world, it, wo);
        let mut sum = Vec3::ZERO;
        let mut extended = false; // any light with extent (area, sky)?
        for (i, light) in world.lights.lights.iter().enumerate() {
            let delta = light.is_delta();
            extended |= !delta;
            if !delta && !self.strategy.samples_lights() {
                continue;
            }
            // Sample the light: one term per delta light, one sample per
            // area light or environment.
            let u = s.next2();
            if let Some(term) = self.light_term(&at, i, u, c) {
                sum += term;
            }
        }
        // ANCHOR_END: reflected_lights
        // ANCHOR: reflected_direction
        if extended && self.strategy.samples_directions() {
            // Sample a direction and see what it finds.
            let u = s.next2();
            let u_lobe = s.next();
            if let Some(term) = self.direction_term(&at, u, u_lobe, c) {
                sum += term;
            }
        }
        sum
    }
    // ANCHOR_END: reflected_direction
    // ANCHOR_END: reflected

    /// One sample of light `i`: f L cos θ / pdf, MIS-weighted against a
    /// sampled direction under MIS; `None` where it adds nothing.
    // ANCHOR: light_term
    fn light_term(&self, at: &ShadingPoint, i: usize, u: Vec2, c: &mut impl Tally) -> Option<Vec3> {
        let light = &at.world.lights.lights[i];
        let ls = light.sample_li(at.it.p, at.n, u)?;
        let cos = ls.wi.dot(at.n);
        if cos <= 0.0 {
            return None; // the light is behind the surface
        }
        let wi_local = at.frame.to_local(ls.wi);
        let f = at.bsdf.f(at.wo_local, wi_local);
        if f == Vec3::ZERO {
            return None;
        }
        if !self.visible(at, ls.wi, ls.dist, c) {
            c.note(ShadingEvent::shadowed(i)); // tell a listener (the inspector)
            return None; // in shadow
        }
        let weight = if light.is_delta() || self.strategy == Strategy::Light {
            1.0
        } else {
            power_heuristic(ls.pdf, at.bsdf.pdf(at.wo_local, wi_local))
        };
        let term = finite(f * ls.li * cos * (weight / ls.pdf), c);
        c.note(ShadingEvent::light(i, term, weight)); // tell a listener (the inspector)
        term
    }
    // ANCHOR_END: light_term

    /// One direction from the uniform hemisphere or the BRDF: f L cos / pdf
    /// of what it finds, MIS-weighted against light sampling under MIS.
    // ANCHOR: direction_term
    // ANCHOR: direction_term_sample
    fn direction_term(
        &self,
        at: &ShadingPoint,
        u: Vec2,
        u_lobe: f32,
        c: &mut impl Tally,
    ) -> Option<Vec3> {
        let (wi_local, f, pdf) = if self.strategy == Strategy::Uniform {
            let mut w = uniform_hemisphere(u);
            if at.wo_local.z < 0.0 {
                w.z = -w.z;
            }
            (w, at.bsdf.f(at.wo_local, w), UNIFORM_HEMISPHERE_PDF)
        } else {
            let b = at.bsdf.sample(at.wo_local, u, u_lobe)?;
            (b.wi, b.f, b.pdf)
        };
        if f == Vec3::ZERO || pdf <= 0.0 {
            return None;
        }
        let wi = at.frame.to_world(wi_local);
        let cos = wi.dot(at.n);
        if cos <= 0.0 {
            return None;
        }
        // ANCHOR_END: direction_term_sample
        // ANCHOR: direction_term_weight
        // What does the ray see, and how likely was light sampling to
        // find it? Without occluders it can only escape.
        let (light, le, pdf_light) = self.found(at, wi, c)?;
        let weight = if self.strategy == Strategy::Mis {
            power_heuristic(pdf, pdf_light)
        } else {
            1.0
        };
        let term = finite(f * le * cos * (weight / pdf), c);
        c.note(ShadingEvent::found(light, term, weight)); // tell a listener (the inspector)
        term
    }
    // ANCHOR_END: direction_term_weight
    // ANCHOR_END: direction_term

    /// What a ray from `at` along `wi` finds: the light it is (if any), the
    /// radiance it brings, and light sampling's pdf for it; `None` for a
    /// surface that does not emit.
    fn found(
        &self,
        at: &ShadingPoint,
        wi: Vec3,
        c: &mut impl Tally,
    ) -> Option<(Option<usize>, Vec3, f32)> {
        let lights = &at.world.lights;
        let Some(hit) = self.trace(at, wi, c) else {
            return Some((
                lights.environment,
                lights.environment_radiance(wi),
                lights.environment_pdf(at.n, wi),
            ));
        };
        let le = at.world.emitted(&hit, -wi);
        if le == Vec3::ZERO {
            return None;
        }
        Some(match at.world.area_light(&hit) {
            Some((i, a)) => (Some(i), le, a.pdf_li(at.it.p, hit.p, hit.n)),
            None => (None, le, 0.0),
        })
    }

    fn trace(&self, at: &ShadingPoint, wi: Vec3, c: &mut impl Tally) -> Option<Interaction> {
        if !self.trace_light_rays {
            return None;
        }
        c.counters().direction_rays += 1;
        let world = at.world;
        world.intersect(&world.spawn(at.it.p, at.it.n, wi)?)
    }

    fn visible(&self, at: &ShadingPoint, wi: Vec3, dist: f32, c: &mut impl Tally) -> bool {
        if !self.trace_light_rays {
            return true;
        }
        c.counters().shadow_rays += 1;
        at.world.unoccluded(at.it.p, at.it.n, wi, dist)
    }
}
