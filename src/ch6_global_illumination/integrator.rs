//! The path tracer: one light path per camera sample, built vertex by
//! vertex in a loop (no recursion, so no stack limit however long a path
//! gets). At each surface the path
//!
//! 1. adds what it sees emitted (weighted so no light is counted twice),
//! 2. samples a light (next-event estimation, the "direct" partition of the
//!    lecture's path-tracing slide),
//! 3. samples the BSDF for the next direction (the "indirect" partition),
//! 4. and plays Russian roulette on its throughput.
//!
//! Four estimators, the lecture's ladder, share this one loop
//! ([`Estimator`]); only which directions are drawn and how emission found
//! by each strategy is weighted differ.
//!
//! [`random_walk`] is the ladder's first rung on its own, without the
//! loop's options and bookkeeping, to be read first.
//!
//! Every contribution is added to the *layer* of its bounce count: the
//! slot [`SLOT_EMITTED`] holds emitters seen directly (layer E), slot
//! `1 + k` light that scattered k + 1 times between emitter and camera
//! (k = 0 is direct illumination), and [`SLOT_BEYOND`] everything with
//! k > [`LAYERS_SHOWN`].

use glam::Vec3;

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch5_reflection::material::{Bsdf, Frame};
use crate::ch5_reflection::mis::power_heuristic;
use crate::ch5_reflection::warp::{uniform_hemisphere, UNIFORM_HEMISPHERE_PDF};
use crate::ch5_reflection::world::World;
use crate::core::sampling::Sampler;

use super::path_events::{Emission, LightSample, PathEvent, Scatter};
use super::sampler::PathSampler;

/// The highest bounce count k with a layer of its own.
pub const LAYERS_SHOWN: u32 = 16;
/// The layer slot of emitters seen directly (layer E).
pub const SLOT_EMITTED: usize = 0;
/// The slot of light with more than [`LAYERS_SHOWN`] bounces.
pub const SLOT_BEYOND: usize = LAYERS_SHOWN as usize + 2;
/// Slots per pixel: E, k = 0 ..= LAYERS_SHOWN, beyond.
pub const LAYER_SLOTS: usize = LAYERS_SHOWN as usize + 3;

/// The slot of light that scattered `scatterings` ≥ 1 times (bounce count
/// k = scatterings - 1).
#[inline]
pub fn slot_of(scatterings: u32) -> usize {
    (scatterings as usize).min(SLOT_BEYOND)
}

/// With "unlimited" bounces only Russian roulette ends a path; this many
/// scatterings end it anyway (counted in [`PathStats::cut`]), so a scene
/// of perfect mirrors cannot hang a render. With ρ = 0.999 the chance of
/// reaching it is about e^-65.
pub const SAFETY_SCATTERINGS: u32 = 1 << 16;

/// Whether Russian roulette can never end a path in `scene`: every
/// material keeps all the light it reflects in every channel (reflectance
/// 1, or glass), so the survival probability, the throughput's largest
/// channel, never drops below 1. Paths then end only by leaving the scene;
/// in a closed one, each runs to [`SAFETY_SCATTERINGS`].
pub fn roulette_cannot_end(scene: &crate::scene::Scene) -> bool {
    use crate::scene::file::MaterialKind;
    !scene.materials.is_empty()
        && scene
            .materials
            .iter()
            .all(|m| m.kind == MaterialKind::Glass || m.reflectance.min_element() >= 1.0)
}

/// The lecture's ladder of estimators, from the plainest to the best.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Estimator {
    /// Recursive Monte Carlo with uniform hemisphere directions: a random
    /// walk that only finds light by hitting it.
    UniformWalk,
    /// Directions drawn from the BSDF (cosine-weighted for Lambert): still
    /// finds light only by hitting it.
    BsdfSampling,
    /// Next-event estimation: every vertex samples a light; emitters hit by
    /// the walk count only when light sampling could not have found them
    /// (after a delta bounce, or an emitter no light sample reaches).
    LightSampling,
    /// Both strategies at every vertex, combined by the power heuristic.
    Mis,
}

impl Estimator {
    /// All four, in ladder order.
    pub const ALL: [Estimator; 4] = [
        Estimator::UniformWalk,
        Estimator::BsdfSampling,
        Estimator::LightSampling,
        Estimator::Mis,
    ];

    /// A short name for tables and file names.
    pub fn name(self) -> &'static str {
        match self {
            Estimator::UniformWalk => "uniform",
            Estimator::BsdfSampling => "bsdf",
            Estimator::LightSampling => "light",
            Estimator::Mis => "mis",
        }
    }

    /// Whether every vertex samples a light (next-event estimation).
    pub fn samples_lights(self) -> bool {
        matches!(self, Estimator::LightSampling | Estimator::Mis)
    }
}

/// How paths are traced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PathSettings {
    /// Which estimator.
    pub estimator: Estimator,
    /// The largest bounce count k a path may contribute to (k + 1
    /// scatterings); `None`: unlimited, Russian roulette alone ends paths.
    pub max_bounces: Option<u32>,
    /// Russian roulette starts after this many scatterings.
    pub rr_min_scatterings: u32,
}

impl Default for PathSettings {
    fn default() -> Self {
        PathSettings {
            estimator: Estimator::Mis,
            max_bounces: Some(16),
            rr_min_scatterings: 1,
        }
    }
}

/// Counts from tracing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PathStats {
    /// Paths traced.
    pub paths: u64,
    /// Rays cast: path segments and shadow rays.
    pub rays: u64,
    /// Contributions that were NaN or infinite, dropped and counted.
    pub nonfinite: u64,
    /// Paths ended by [`SAFETY_SCATTERINGS`] rather than by roulette.
    pub cut: u64,
}

impl PathStats {
    /// Adds another tally.
    pub fn add(&mut self, o: &PathStats) {
        self.paths += o.paths;
        self.rays += o.rays;
        self.nonfinite += o.nonfinite;
        self.cut += o.cut;
    }
}

/// Where a path's contributions go: into the layer of their bounce count
/// (`[Vec3; LAYER_SLOTS]`), or, when only the final image is wanted,
/// straight into one sum (`Vec3`, with nothing per layer to clear or add).
pub trait Contributions {
    /// Adds `c`, which belongs to layer slot `slot`.
    fn add_to(&mut self, slot: usize, c: Vec3);

    /// Hears about each step of the path. Does nothing (and costs nothing)
    /// unless a recorder ([`super::path_record`]) listens.
    #[inline(always)]
    fn note(&mut self, _event: PathEvent<'_>) {}
}

impl Contributions for [Vec3; LAYER_SLOTS] {
    #[inline(always)]
    fn add_to(&mut self, slot: usize, c: Vec3) {
        self[slot] += c;
    }
}

impl Contributions for Vec3 {
    #[inline(always)]
    fn add_to(&mut self, _slot: usize, c: Vec3) {
        *self += c;
    }
}

/// Adds `c` to slot `slot` unless it is NaN or infinite (then counts it).
#[inline(always)]
fn add(layers: &mut impl Contributions, slot: usize, c: Vec3, stats: &mut PathStats) {
    if c.is_finite() {
        layers.add_to(slot, c);
    } else {
        stats.nonfinite += 1;
    }
}

/// Traces one path from the camera ray `ray`, adding its contributions to
/// `layers` (by bounce count, or summed; the pixel value is their sum).
// ANCHOR: trace_path
pub fn trace_path(
    world: &World,
    mut ray: Ray,
    sampler: &mut PathSampler,
    settings: &PathSettings,
    layers: &mut impl Contributions,
    stats: &mut PathStats,
) {
    let estimator = settings.estimator;
    let max_scatterings = settings
        .max_bounces
        .map_or(SAFETY_SCATTERINGS, |k| k.saturating_add(1))
        .min(SAFETY_SCATTERINGS);
    let sample_lights = estimator.samples_lights() && !world.lights.is_empty();
    let mut beta = Vec3::ONE; // path throughput
    let mut scatterings = 0u32; // surfaces the path has scattered at
                                // About the previous vertex, for weighting emission the walk finds.
    let mut prev_delta = true; // the camera counts as a delta "vertex"
    let mut prev_pdf = 0.0f32;
    let mut prev_p = ray.origin;
    let mut prev_n = Vec3::Z;
    stats.paths += 1;

    loop {
        stats.rays += 1;
        let Some(it) = world.intersect(&ray) else {
            // Escaped: add the environment, weighted like an emitter hit.
            let le = world.lights.environment_radiance(ray.dir);
            if le != Vec3::ZERO {
                let w = match (world.lights.environment, sample_lights && !prev_delta) {
                    (Some(i), true) => emission_weight(
                        estimator,
                        prev_pdf,
                        world.lights.choose_pdf(i) * world.lights.environment_pdf(prev_n, ray.dir),
                    ),
                    _ => 1.0,
                };
                let c = beta * le * w;
                add(layers, slot_of(scatterings), c, stats);
                layers.note(PathEvent::Escaped {
                    dir: ray.dir,
                    emission: Emission {
                        le,
                        weight: w,
                        contribution: c,
                    },
                });
            }
            break;
        };
        let wo_world = -ray.dir;
        layers.note(PathEvent::Hit { it: &it, beta });

        // Add emitted light seen along the ray.
        let le = world.emitted(&it, wo_world);
        if le != Vec3::ZERO {
            let w = match (world.area_light(&it), sample_lights && !prev_delta) {
                (Some((i, light)), true) => emission_weight(
                    estimator,
                    prev_pdf,
                    world.lights.choose_pdf(i) * light.pdf_li(prev_p, it.p, it.n),
                ),
                _ => 1.0,
            };
            let c = beta * le * w;
            add(layers, slot_of(scatterings), c, stats);
            layers.note(PathEvent::Emission(Emission {
                le,
                weight: w,
                contribution: c,
            }));
        }

        // End the path at the bounce limit.
        if scatterings >= max_scatterings {
            if settings.max_bounces.is_none() {
                stats.cut += 1;
            }
            break;
        }
        scatterings += 1;
        sampler.align();

        let bsdf: &Bsdf = &world.bsdfs[it.material];
        let frame = Frame::from_normal(it.n);
        let wo = frame.to_local(wo_world);
        if wo.z == 0.0 {
            break;
        }
        // The normal on the side the path arrived from.
        let n_side = if wo.z > 0.0 { it.n } else { -it.n };
        let delta = bsdf.is_delta();

        // Sample a light (next-event estimation).
        let u_choose = sampler.get1();
        let u_light = sampler.get2();
        if sample_lights && !delta {
            if let Some((i, p_choose)) = world.lights.choose(u_choose) {
                if let Some(ls) = world.lights.lights[i].sample_li(it.p, n_side, u_light) {
                    let wi = frame.to_local(ls.wi);
                    let f = bsdf.f(wo, wi);
                    if f != Vec3::ZERO {
                        stats.rays += 1;
                        let pdf_light = ls.pdf * p_choose;
                        let visible = world.unoccluded(it.p, it.n, ls.wi, ls.dist);
                        let (mut w, mut c) = (0.0, Vec3::ZERO);
                        if visible {
                            w = if ls.delta || estimator != Estimator::Mis {
                                1.0
                            } else {
                                power_heuristic(pdf_light, bsdf.pdf(wo, wi))
                            };
                            c = beta * f * ls.li * wi.z.abs() * (w / pdf_light);
                            add(layers, slot_of(scatterings), c, stats);
                        }
                        layers.note(PathEvent::Light(LightSample {
                            light: i,
                            wi: ls.wi,
                            f,
                            li: ls.li,
                            pdf: pdf_light,
                            cos: wi.z.abs(),
                            weight: w,
                            visible,
                            contribution: c,
                        }));
                    }
                }
            }
        }

        // Sample the BSDF (or the uniform hemisphere) for the next direction.
        let u_lobe = sampler.get1();
        let u_dir = sampler.get2();
        let (wi, f, weight, pdf) = if estimator == Estimator::UniformWalk && !delta {
            let mut wi = uniform_hemisphere(u_dir);
            wi.z = wi.z.copysign(wo.z);
            let f = bsdf.f(wo, wi);
            let weight = f * wi.z.abs() / UNIFORM_HEMISPHERE_PDF;
            (wi, f, weight, UNIFORM_HEMISPHERE_PDF)
        } else {
            match bsdf.sample(wo, u_dir, u_lobe) {
                Some(s) => (s.wi, s.f, s.weight, s.pdf),
                None => break,
            }
        };
        if weight == Vec3::ZERO || !weight.is_finite() {
            break;
        }
        beta *= weight;
        prev_delta = delta;
        prev_pdf = pdf;
        prev_p = it.p;
        prev_n = n_side;
        let wi_world = frame.to_world(wi);
        layers.note(PathEvent::Scatter(Scatter {
            wi: wi_world,
            f,
            pdf,
            cos: wi.z.abs(),
            delta,
            beta,
        }));

        // Russian roulette: survive with probability q, then divide by q.
        if scatterings >= settings.rr_min_scatterings {
            let q = beta.max_element().min(1.0);
            let dies = sampler.get1() >= q;
            layers.note(PathEvent::Roulette { q, survived: !dies });
            if dies {
                break;
            }
            beta /= q;
        }

        match world.spawn(it.p, it.n, wi_world) {
            Some(r) => ray = r,
            None => break,
        }
    }
}
// ANCHOR_END: trace_path

/// The lecture's simplest path tracer, to be read on its own: a *uniform
/// random walk*. From the camera, the path hits a surface, adds the light
/// that surface emits towards it, picks a direction uniformly over the
/// hemisphere, and goes on, its throughput β multiplied each time by
/// f · cos θ / pdf. Light is found only when the walk happens to hit an
/// emitter (or escapes to the sky). A path scatters at most `max_depth`
/// times (the full loop's `max_bounces` k is `max_depth` k + 1).
///
/// [`trace_path`] with [`Estimator::UniformWalk`] draws its directions the
/// same way, but inside the full loop with its bookkeeping (light layers,
/// Sobol dimensions, Russian roulette), so its numbers and this function's
/// differ; a test checks that both converge to the image of the full MIS
/// loop. The random numbers here are plain independent ones.
// ANCHOR: random_walk
pub fn random_walk(world: &World, mut ray: Ray, max_depth: u32, s: &mut Sampler) -> Vec3 {
    let mut l = Vec3::ZERO; // the radiance gathered so far
    let mut beta = Vec3::ONE; // the path's throughput
    let mut depth = 0;
    loop {
        let Some(it) = world.intersect(&ray) else {
            // Escaped: the sky, if the scene has one.
            return l + beta * world.lights.environment_radiance(ray.dir);
        };
        // Light emitted towards the path by the surface it hit.
        l += beta * world.emitted(&it, -ray.dir);
        if depth == max_depth {
            return l;
        }
        depth += 1;
        let bsdf = &world.bsdfs[it.material];
        let frame = Frame::from_normal(it.n);
        let wo = frame.to_local(-ray.dir);
        let (wi, weight) = if bsdf.is_delta() {
            // A mirror or glass sends light into one direction only, which
            // a uniform direction never finds: take that direction.
            match bsdf.sample(wo, s.next2(), s.next()) {
                Some(b) => (b.wi, b.weight),
                None => return l,
            }
        } else {
            // A direction uniform over the hemisphere the path came from.
            let mut wi = uniform_hemisphere(s.next2());
            wi.z = wi.z.copysign(wo.z);
            (wi, bsdf.f(wo, wi) * wi.z.abs() / UNIFORM_HEMISPHERE_PDF)
        };
        if weight == Vec3::ZERO || !weight.is_finite() {
            return l; // the path carries no more light
        }
        beta *= weight;
        match world.spawn(it.p, it.n, frame.to_world(wi)) {
            Some(next) => ray = next,
            None => return l,
        }
    }
}
// ANCHOR_END: random_walk

/// The weight of emission found by a BSDF-sampled direction of density
/// `pdf_bsdf` that light sampling would have drawn with `pdf_light`.
// ANCHOR: emission_weight
fn emission_weight(estimator: Estimator, pdf_bsdf: f32, pdf_light: f32) -> f32 {
    match estimator {
        // Light sampling already counted it.
        Estimator::LightSampling if pdf_light > 0.0 => 0.0,
        Estimator::Mis => power_heuristic(pdf_bsdf, pdf_light),
        _ => 1.0,
    }
}
// ANCHOR_END: emission_weight
