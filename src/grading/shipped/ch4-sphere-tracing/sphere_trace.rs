//! Exercise 4.2: the sphere-tracing loop.
//!
//! March along the ray o + t·d (d is unit length) through the distance
//! function `sdf`, starting at t = 0. The origin is outside (sdf(o) > 0).
//!
//! Contract (what the grader checks; it counts every call of `sdf`):
//! * every call of `sdf` is at a point of the ray: o + t·d for the t the
//!   march has reached, formed afresh (within 4 f32 ε · (|o| + t + |p|)
//!   of the ray, however many steps the march takes and however far from
//!   the world's origin it runs);
//! * `Some(t)` for the first t the march reaches where
//!   |sdf(o + t d)| < `epsilon` (hits to within ε of the true distance).
//! * `None` when t is beyond `max_distance` before a hit. The point a
//!   step reaches is tested for a hit first: a step that lands on a
//!   surface beyond `max_distance` has found it.
//! * The step budget: at most `max_steps` evaluations of `sdf` (at least
//!   one), the one at t = 0 included, every one of them tested for a hit;
//!   `None` when they are used up.
//!
//! The idea: no surface is closer to a point than the distance function
//! says there, so that distance is a step that cannot cross a surface.
//!
//! Grade it with: `cargo grade ch4`

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
    // TODO: your code here (steps: `cargo grade --hint ch4/sphere_trace`).
    todo!()
}
