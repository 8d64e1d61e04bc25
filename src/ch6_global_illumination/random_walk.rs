//! The first rung of chapter 6's ladder on its own: a uniform random walk,
//! the lecture's simplest path tracer, without the full loop's options and
//! bookkeeping ([`super::integrator`]). It counts bounces as the full loop
//! does (see the integrator's module doc).

use glam::Vec3;

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch5_reflection::material::Frame;
use crate::ch5_reflection::warp::{uniform_hemisphere, UNIFORM_HEMISPHERE_PDF};
use crate::ch5_reflection::world::World;
use crate::core::sampling::Sampler;

/// The lecture's simplest path tracer, to be read on its own: a *uniform
/// random walk*. From the camera, the path hits a surface, adds the light
/// that surface emits towards it, picks a direction uniformly over the
/// hemisphere, and goes on, its throughput β multiplied each time by
/// f · cos θ / pdf. Light is found only when the walk happens to hit an
/// emitter (or escapes to the sky). The walk gathers light of bounce count
/// at most `max_bounces` (it scatters at most `max_bounces` + 1 times), as
/// [`trace_path`](super::integrator::trace_path) does with the same `max_bounces`.
///
/// [`trace_path`](super::integrator::trace_path) with [`Strategy::Uniform`](crate::ch5_reflection::direct::Strategy::Uniform) draws its directions the
/// same way, but inside the full loop with its bookkeeping (light layers,
/// Sobol dimensions, Russian roulette), so its numbers and this function's
/// differ; a test checks that both converge to the image of the full MIS
/// loop. The random numbers here are plain independent ones.
// ANCHOR: random_walk
// ANCHOR: random_walk_hit
pub fn random_walk(world: &World, mut ray: Ray, max_bounces: u32, s: &mut Sampler) -> Vec3 {
    let mut l = Vec3::ZERO; // the radiance gathered so far
    let mut beta = Vec3::ONE; // the path's throughput
    let mut k = 0; // the bounce count of light scattered at the next surface
    loop {
        let Some(it) = world.intersect(&ray) else {
            // Escaped: the sky, if the scene has one.
            return l + beta * world.lights.environment_radiance(ray.dir);
        };
        // Light emitted towards the path by the surface it hit.
        l += beta * world.emitted(&it, -ray.dir);
        if k > max_bounces {
            return l;
        }
        k += 1;
        let bsdf = &world.bsdfs[it.material];
        let frame = Frame::from_normal(it.n);
        let wo = frame.to_local(-ray.dir);
        // ANCHOR_END: random_walk_hit
        // ANCHOR: random_walk_scatter
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
// ANCHOR_END: random_walk_scatter
// ANCHOR_END: random_walk
