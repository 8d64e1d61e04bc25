//! One pixel's reflection equation, light by light: for the camera ray of
//! one sample, what each light adds at the point it hits, split into the
//! light-sampling term and the BRDF-sampling term (each with its MIS
//! weight). It draws the same random numbers in the same order as
//! [`Estimator::radiance`], so the terms add up to the render's value for
//! that sample (a test checks it).

use glam::Vec3;

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::render::camera_sample;
use crate::ch5_reflection::direct::{Counters, Estimator, Strategy};
use crate::ch5_reflection::material::Frame;
use crate::ch5_reflection::mis::power_heuristic;
use crate::ch5_reflection::warp::{uniform_hemisphere, UNIFORM_HEMISPHERE_PDF};
use crate::ch5_reflection::world::World;
use crate::core::sampling::Sampler;

/// What one light adds to the pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LightTerm {
    /// Index into the world's lights.
    pub light: usize,
    /// The light-sampling term (f L cos w / pdf; 0 in shadow).
    pub sampled: Vec3,
    /// Its MIS weight (1 for a delta light or light sampling alone).
    pub weight: f32,
    /// Whether the light sample was in shadow.
    pub shadowed: bool,
    /// The BRDF-sampling term that found this light, with its weight.
    pub found: Vec3,
    /// The weight of the BRDF-sampling term.
    pub found_weight: f32,
}

/// The story of one pixel's sample.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PixelLight {
    /// Whether the camera ray hit anything.
    pub hit: bool,
    /// Whether the surface is a mirror or glass (then no per-light split:
    /// the pixel shows what the reflected ray sees).
    pub delta: bool,
    /// Emission seen directly (or the sky for a miss).
    pub emitted: Vec3,
    /// Per light, in the world's order.
    pub lights: Vec<LightTerm>,
    /// What the BRDF-sampled direction found on an emitter that is no
    /// sampled light (an emissive SDF).
    pub other: Vec3,
    /// The radiance of the sample, as the render computes it.
    pub total: Vec3,
}

/// Sample `sample` of pixel (`x`, `y`), as chapter 5's render pass draws
/// it, light by light.
pub fn pixel_light(
    world: &World,
    camera: &Camera,
    est: &Estimator,
    seed: u64,
    (x, y): (u32, u32),
    sample: u32,
) -> PixelLight {
    let (mut s, ray) = camera_sample(camera, (x, y), |pixel| {
        Sampler::new(seed, pixel, sample as u64)
    });
    let mut c = Counters::default();
    let total = est.radiance(world, &ray, &mut s.clone(), &mut c);
    let mut out = PixelLight {
        total,
        ..PixelLight::default()
    };
    let Some(it) = world.intersect(&ray) else {
        out.emitted = world.lights.environment_radiance(ray.dir);
        return out;
    };
    out.hit = true;
    let wo = -ray.dir;
    let bsdf = &world.bsdfs[it.material];
    out.emitted = world.emitted(&it, wo);
    if bsdf.is_delta() {
        out.delta = true;
        return out;
    }
    let frame = Frame::from_normal(it.n);
    let wo_local = frame.to_local(wo);
    let n = if wo.dot(it.n) < 0.0 { -it.n } else { it.n };
    let samples_lights = est.strategy.samples_lights();
    let mut extended = false;
    for (i, light) in world.lights.lights.iter().enumerate() {
        let mut term = LightTerm {
            light: i,
            ..LightTerm::default()
        };
        let delta = light.is_delta();
        extended |= !delta;
        if delta || samples_lights {
            if let Some(ls) = light.sample_li(it.p, n, s.next2()) {
                let cos = ls.wi.dot(n);
                let wi_local = frame.to_local(ls.wi);
                let f = bsdf.f(wo_local, wi_local);
                if cos > 0.0 && f != Vec3::ZERO {
                    let visible = !est.shadow_rays || world.unoccluded(it.p, it.n, ls.wi, ls.dist);
                    term.shadowed = !visible;
                    if visible {
                        term.weight = if delta || est.strategy == Strategy::Light {
                            1.0
                        } else {
                            power_heuristic(ls.pdf, bsdf.pdf(wo_local, wi_local))
                        };
                        let v = f * ls.li * cos * (term.weight / ls.pdf);
                        term.sampled = if v.is_finite() { v } else { Vec3::ZERO };
                    }
                }
            }
        }
        out.lights.push(term);
    }
    if extended && est.strategy != Strategy::Light {
        // One direction from the hemisphere or the BRDF: whatever light it
        // finds gets the term.
        let (u, u_lobe) = (s.next2(), s.next());
        let sampled = if est.strategy == Strategy::Uniform {
            let mut w = uniform_hemisphere(u);
            if wo_local.z < 0.0 {
                w.z = -w.z;
            }
            Some((w, bsdf.f(wo_local, w), UNIFORM_HEMISPHERE_PDF))
        } else {
            bsdf.sample(wo_local, u, u_lobe).map(|b| (b.wi, b.f, b.pdf))
        };
        if let Some((wi_local, f, pdf)) = sampled.filter(|(_, f, p)| *f != Vec3::ZERO && *p > 0.0) {
            let wi = frame.to_world(wi_local);
            let cos = wi.dot(n);
            let next = world.spawn(it.p, it.n, wi);
            let hit = match (est.shadow_rays, next) {
                (true, Some(r)) => world.intersect(&r),
                _ => None,
            };
            // (light index if it is one, Le, light sampling's pdf)
            let found = match hit {
                None => (
                    world.lights.environment,
                    world.lights.environment_radiance(wi),
                    world.lights.environment_pdf(n, wi),
                ),
                Some(h) => match world.area_light(&h) {
                    Some((i, a)) => (Some(i), world.emitted(&h, -wi), a.pdf_li(it.p, h.p, h.n)),
                    None => (None, world.emitted(&h, -wi), 0.0),
                },
            };
            let (i, le, pdf_light) = found;
            if cos > 0.0 && le != Vec3::ZERO {
                let w = if est.strategy == Strategy::Mis {
                    power_heuristic(pdf, pdf_light)
                } else {
                    1.0
                };
                let v = f * le * cos * (w / pdf);
                let v = if v.is_finite() { v } else { Vec3::ZERO };
                match i.and_then(|i| out.lights.get_mut(i)) {
                    Some(t) => {
                        t.found = v;
                        t.found_weight = w;
                    }
                    None => out.other = v,
                }
            }
        }
    }
    out
}

impl PixelLight {
    /// Emission plus every light's terms.
    pub fn sum(&self) -> Vec3 {
        self.emitted
            + self.other
            + self
                .lights
                .iter()
                .map(|t| t.sampled + t.found)
                .sum::<Vec3>()
    }
}
