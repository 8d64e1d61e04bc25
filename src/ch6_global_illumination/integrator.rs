//! The path tracer: one light path per camera sample, built vertex by
//! vertex in a loop (no recursion, so no stack limit however long a path
//! gets). At each surface the path
//!
//! 1. adds what it sees emitted (weighted so no light is counted twice),
//! 2. samples a light (`direct_light`: next-event estimation, the
//!    "direct" partition of the lecture's path-tracing slide),
//! 3. samples the BSDF for the next direction (the "indirect" partition),
//! 4. and plays Russian roulette on its throughput.
//!
//! The lecture's ladder of four strategies ([`Strategy`], chapter 5's)
//! shares this one loop; only which directions are drawn and how emission
//! found by each is weighted differ.
//!
//! [`random_walk`](super::random_walk::random_walk) is the ladder's first rung on its own, without the
//! loop's options and bookkeeping, to be read first.
//!
//! **Bounce count.** Light that scattered at k + 1 surfaces between an
//! emitter and the camera has bounce count k: k = 0 is direct
//! illumination, and emitters the camera sees directly have none (layer
//! E). Every limit and counter here is such a k (`max_bounces`,
//! `rr_min_bounce`, [`SAFETY_BOUNCES`], [`random_walk`](super::random_walk::random_walk)'s `max_bounces`);
//! the only k + 1 is the index of k's layer slot
//! ([`slot_of`], after the slot of layer E).

use glam::{Vec2, Vec3};

use crate::ch3_ray_triangle::ray::Ray;
pub use crate::ch5_reflection::direct::Strategy;
use crate::ch5_reflection::material::Bsdf;
use crate::ch5_reflection::mis::power_heuristic;
use crate::ch5_reflection::world::{Interaction, World};

use super::layers::{slot_of, Contributions};
use super::path_events::{DirectLight, Emission, PathEvent};
use super::sampler::PathSampler;
pub use super::settings::{roulette_cannot_end, PathSettings, SAFETY_BOUNCES};
use super::vertex::{sample_direction, Step, Vertex};

/// Counts from tracing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PathStats {
    /// Paths traced.
    pub paths: u64,
    /// Rays cast: path segments and shadow rays.
    pub rays: u64,
    /// Contributions that were NaN or infinite, dropped and counted.
    pub nonfinite: u64,
    /// Paths ended by [`SAFETY_BOUNCES`] rather than by roulette.
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

/// Traces one path from the camera ray `ray`, adding its contributions to
/// `layers` (by bounce count, or summed; the pixel value is their sum).
// ANCHOR: trace_path
// ANCHOR: trace_path_find
pub fn trace_path(
    world: &World,
    mut ray: Ray,
    sampler: &mut PathSampler,
    settings: &PathSettings,
    layers: &mut impl Contributions,
    stats: &mut PathStats,
) {
    let mut out = PathOut { layers, stats };
    let mut path = Path::from_camera(&ray, settings.strategy, world);
    out.stats.paths += 1;
    loop {
        // 1. What the ray finds: the sky, or a surface and what it emits.
        out.stats.rays += 1;
        let Some(it) = world.intersect(&ray) else {
            out.add_sky(&path, ray.dir, sky_emission(world, ray.dir, &path));
            break;
        };
        out.add_emitted(&path, &it, surface_emission(world, &it, -ray.dir, &path));

        // The bounce count of light scattered here; the path ends at the limit.
        let k = path.k.map_or(0, |k| k + 1);
        if k > settings.bounce_limit() {
            out.stats.cut += u64::from(settings.max_bounces.is_none());
            break;
        }
        sampler.align();
        let Some(v) = Vertex::at(world, &it, -ray.dir) else {
            break; // a ray exactly in the surface's plane
        };
        // ANCHOR_END: trace_path_find

        // ANCHOR: trace_path_light
        // 2. Direct light: sample a light and cast a shadow ray.
        let (u_choose, u_light) = (sampler.next(), sampler.next2());
        if path.samples_lights && !v.delta {
            let direct = direct_light(world, &v, u_choose, u_light, &path, out.stats);
            out.add_direct(k, direct);
        }

        // 3. Indirect light: sample the next direction (BSDF or uniform).
        let (u_lobe, u_dir) = (sampler.next(), sampler.next2());
        let Some(step) = sample_direction(&v, u_lobe, u_dir, path.strategy) else {
            break;
        };
        path.scatter(&v, k, &step);
        out.layers.note(step.event(&v, path.beta)); // tell a listener (the inspector)
                                                    // ANCHOR_END: trace_path_light

        // ANCHOR: trace_path_roulette
        // 4. Russian roulette: survive with probability q, then divide by q.
        // q reads β without glass's η² (see `Path::eta_scale`).
        if k + 1 >= settings.rr_min_bounce {
            let s = settings.rr_scale_for(sampler.kind());
            let q = survival_probability(path.beta * path.eta_scale, s);
            let dies = sampler.next() >= q;
            out.layers.note(PathEvent::Roulette { q, survived: !dies }); // tell a listener (the inspector)
            if dies {
                break;
            }
            path.beta /= q;
        }

        match world.spawn(it.p, it.n, v.frame.to_world(step.wi)) {
            Some(r) => ray = r,
            None => break,
        }
    }
}
// ANCHOR_END: trace_path_roulette
// ANCHOR_END: trace_path

/// Russian roulette's survival probability for the throughput `beta`
/// (without refraction's η²) and the scale `s`: q = min(1, s · max β).
/// The path then goes on with β / q, so on average it carries β: no bias
/// whatever s is; s only trades noise for time.
// ANCHOR: survival_probability
pub fn survival_probability(beta: Vec3, s: u32) -> f32 {
    (beta.max_element() * s as f32).min(1.0)
}
// ANCHOR_END: survival_probability

/// A path under way: how it is traced, its throughput, and what the
/// emission its current ray finds must know about the vertex it left.
#[derive(Clone)]
pub struct Path {
    strategy: Strategy,
    /// Whether vertices sample lights (then emission that a sampled
    /// direction finds is weighted against light sampling).
    samples_lights: bool,
    /// The throughput β.
    pub beta: Vec3,
    /// What refraction took out of β or put into it: refraction scales
    /// radiance by η², so inside glass β is smaller by (1/1.5)² although
    /// the light comes back on the way out. Russian roulette reads
    /// β · `eta_scale`, which has the scaling undone (pbrt's `etaScale`),
    /// so that a path is not ended more often for being inside glass.
    eta_scale: f32,
    /// The bounce count of light the current ray finds (`None`: the camera
    /// ray, whose emitters are layer E).
    pub k: Option<u32>,
    /// Whether the vertex the ray left is a delta (the camera counts as one).
    pub from_delta: bool,
    /// The pdf of the ray's direction there.
    pub from_pdf: f32,
    /// That vertex's position.
    pub from_p: Vec3,
    /// That vertex's normal on the path's side.
    pub from_n: Vec3,
}

impl Path {
    /// A path that starts with the camera ray `ray`.
    pub fn from_camera(ray: &Ray, strategy: Strategy, world: &World) -> Path {
        Path {
            strategy,
            samples_lights: strategy.samples_lights() && !world.lights.is_empty(),
            beta: Vec3::ONE,
            eta_scale: 1.0,
            k: None,
            from_delta: true,
            from_pdf: 0.0,
            from_p: ray.origin,
            from_n: Vec3::Z,
        }
    }

    /// How its vertices choose the next direction.
    pub fn strategy(&self) -> Strategy {
        self.strategy
    }

    /// Whether its vertices sample lights.
    pub fn samples_lights(&self) -> bool {
        self.samples_lights
    }

    /// What refraction took out of β or put into it (see the field).
    pub fn eta_scale(&self) -> f32 {
        self.eta_scale
    }

    /// Whether light sampling could have found what the current ray finds.
    fn weighs_emission(&self) -> bool {
        self.samples_lights && !self.from_delta
    }

    /// Goes on from `v` (where light of bounce count `k` scattered) along
    /// `step`.
    pub fn scatter(&mut self, v: &Vertex, k: u32, step: &Step) {
        self.beta *= step.weight;
        if let Bsdf::Dielectric(_) = v.bsdf {
            // Glass's weight is the radiance scaling alone (1 for
            // reflection, η² for refraction; F cancels): undone for roulette.
            self.eta_scale /= step.weight.x;
        }
        self.k = Some(k);
        self.from_delta = v.delta;
        self.from_pdf = step.pdf;
        self.from_p = v.it.p;
        self.from_n = v.n_side;
    }
}

/// Next-event estimation at `v`: choose a light with `u_choose`, a point
/// on it with `u_light`, and cast a shadow ray. `None` when there is no
/// light or the BSDF does not reflect towards the sample.
// ANCHOR: direct_light
// ANCHOR: direct_light_sample
pub fn direct_light(
    world: &World,
    v: &Vertex,
    u_choose: f32,
    u_light: Vec2,
    path: &Path,
    stats: &mut PathStats,
) -> Option<DirectLight> {
    let (i, p_choose) = world.lights.choose(u_choose)?;
    let ls = world.lights.lights[i].sample_li(v.it.p, v.n_side, u_light)?;
    let wi = v.frame.to_local(ls.wi);
    let f = v.bsdf.f(v.wo, wi);
    if f == Vec3::ZERO {
        return None;
    }
    stats.rays += 1;
    let pdf = ls.pdf * p_choose; // choosing the light, then the point
    let visible = world.unoccluded(v.it.p, v.it.n, ls.wi, ls.dist);
    // MIS weight against the BSDF having drawn the same direction.
    let weight = match visible {
        false => 0.0,
        true if ls.delta || path.strategy != Strategy::Mis => 1.0,
        true => power_heuristic(pdf, v.bsdf.pdf(v.wo, wi)),
    };
    let contribution = match visible {
        true => path.beta * f * ls.li * wi.z.abs() * (weight / pdf),
        false => Vec3::ZERO,
    };
    // ANCHOR_END: direct_light_sample
    // ANCHOR: direct_light_record
    let (li, cos) = (ls.li, wi.z.abs());
    Some(DirectLight {
        light: i,
        wi: ls.wi,
        f,
        li,
        pdf,
        cos,
        weight,
        visible,
        contribution,
    })
}
// ANCHOR_END: direct_light_record
// ANCHOR_END: direct_light

/// The environment's radiance along `dir`, where a ray escaped, with its
/// weight against light sampling; `None` where it is black.
pub fn sky_emission(world: &World, dir: Vec3, path: &Path) -> Option<(Vec3, f32)> {
    let lights = &world.lights;
    let le = lights.environment_radiance(dir);
    if le == Vec3::ZERO {
        return None;
    }
    let w = match (lights.environment, path.weighs_emission()) {
        (Some(i), true) => emission_weight(
            path.strategy,
            path.from_pdf,
            lights.choose_pdf(i) * lights.environment_pdf(path.from_n, dir),
        ),
        _ => 1.0,
    };
    Some((le, w))
}

/// What the surface at `it` emits towards `wo` (back along the ray), with
/// its weight against light sampling; `None` where it emits nothing.
pub fn surface_emission(
    world: &World,
    it: &Interaction,
    wo: Vec3,
    path: &Path,
) -> Option<(Vec3, f32)> {
    let le = world.emitted(it, wo);
    if le == Vec3::ZERO {
        return None;
    }
    let w = match (world.area_light(it), path.weighs_emission()) {
        (Some((i, light)), true) => emission_weight(
            path.strategy,
            path.from_pdf,
            world.lights.choose_pdf(i) * light.pdf_li(path.from_p, it.p, it.n),
        ),
        _ => 1.0,
    };
    Some((le, w))
}

/// Where one path's contributions go, with its counts; every addition is
/// also told to a listener ([`Contributions::note`]).
pub struct PathOut<'a, C: Contributions> {
    /// Where its light goes.
    pub layers: &'a mut C,
    /// Its counts.
    pub stats: &'a mut PathStats,
}

impl<C: Contributions> PathOut<'_, C> {
    /// Adds `c` to the layer of bounce count `k` unless it is NaN or
    /// infinite (then counts it).
    #[inline(always)]
    pub fn add(&mut self, k: Option<u32>, c: Vec3) {
        if c.is_finite() {
            self.layers.add_to(slot_of(k), c);
        } else {
            self.stats.nonfinite += 1;
            self.layers.caught();
        }
    }

    /// The sky found by an escaped ray.
    pub fn add_sky(&mut self, path: &Path, dir: Vec3, sky: Option<(Vec3, f32)>) {
        let Some((le, weight)) = sky else {
            return;
        };
        let contribution = path.beta * le * weight;
        self.add(path.k, contribution);
        let emission = Emission {
            le,
            weight,
            contribution,
        };
        self.layers.note(PathEvent::Escaped { dir, emission });
    }

    /// A surface reached, and what it emits towards the path.
    pub fn add_emitted(&mut self, path: &Path, it: &Interaction, emitted: Option<(Vec3, f32)>) {
        self.layers.note(PathEvent::Hit {
            it,
            beta: path.beta,
        });
        let Some((le, weight)) = emitted else {
            return;
        };
        let contribution = path.beta * le * weight;
        self.add(path.k, contribution);
        self.layers.note(PathEvent::Emission(Emission {
            le,
            weight,
            contribution,
        }));
    }

    /// A light sample's contribution to bounce count `k`.
    pub fn add_direct(&mut self, k: u32, direct: Option<DirectLight>) {
        let Some(d) = direct else {
            return;
        };
        if d.visible {
            self.add(Some(k), d.contribution);
        }
        self.layers.note(PathEvent::Light(d));
    }
}

/// The weight of emission found by a BSDF-sampled direction of density
/// `pdf_bsdf` that light sampling would have drawn with `pdf_light`.
// ANCHOR: emission_weight
fn emission_weight(strategy: Strategy, pdf_bsdf: f32, pdf_light: f32) -> f32 {
    match strategy {
        // Light sampling already counted it.
        Strategy::Light if pdf_light > 0.0 => 0.0,
        Strategy::Mis => power_heuristic(pdf_bsdf, pdf_light),
        _ => 1.0,
    }
}
// ANCHOR_END: emission_weight
