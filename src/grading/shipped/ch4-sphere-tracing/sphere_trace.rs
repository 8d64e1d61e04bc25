//! Exercise 4.2: the sphere-tracing loop.
//!
//! March along the ray o + t·d (d is unit length) through the distance
//! function `sdf`, starting at t = 0. Return `Some(t)` as soon as
//! |sdf(o + t d)| < `epsilon`; return `None` when t passes
//! `max_distance` or after `max_steps` evaluations of `sdf` without a hit.
//! The origin is outside (sdf(o) > 0).
//!
//! Grade it with: `cargo run --release --bin grade -- ch4`

use glam::Vec3;

/// The distance t to the first surface along the ray, if found.
pub fn sphere_trace(
    sdf: &dyn Fn(Vec3) -> f32,
    origin: Vec3,
    dir: Vec3,
    epsilon: f32,
    max_steps: u32,
    max_distance: f32,
) -> Option<f32> {
    // TODO: start at t = 0 and loop at most max_steps times.
    // TODO: evaluate d = sdf(origin + t * dir); if d < epsilon, you hit.
    // TODO: otherwise no surface is closer than d: step t += d, and stop
    //       once t > max_distance.
    todo!()
}
