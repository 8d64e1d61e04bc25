//! Capstone 6: the path loop, with next-event estimation and Russian
//! roulette.
//!
//! The rendering equation, estimated with one random path per call: from
//! the camera ray's first surface, the path carries a throughput β (the
//! product of f · cos θ / pdf of its bounces so far) and adds, at every
//! surface it reaches, a light sample weighted by β (direct light); then
//! it continues along one sampled direction (indirect light). Every
//! surface is Lambertian, with BRDF ρ/π. The scene offers:
//!
//! * `scene.first_hit(origin, dir)`: the first surface along the camera
//!   ray, with its point, normal (facing the path), albedo ρ and the
//!   radiance it emits back along the path;
//! * `scene.next_hit(&hit, wi)`: the next surface leaving `hit` along `wi`;
//! * `scene.sample_light(&hit, u)`: a direction to a point on the light,
//!   its distance, the radiance Le arriving along it (`li`) and its
//!   density per steradian (`None`: no sample, for instance where the
//!   light cannot be seen from that side);
//! * `scene.unoccluded(&hit, wi, dist)`: the shadow ray, the whole way
//!   to the light's point (it stops a hair short of the light by itself:
//!   give it the sample's own `wi` and `dist`);
//! * `scene.sample_cosine(&hit, u)`: a direction about the normal with
//!   density cos θ / π.
//!
//! `rng()` gives a fresh uniform number in [0, 1) at each call; use as
//! many as you like, in any order.
//!
//! Contract (what the grader checks):
//! * unbiased: in a closed furnace (the inside of a sphere of albedo ρ,
//!   emitting Le everywhere, both drawn anew for every grading run: every
//!   ray sees Le / (1 − ρ)) the mean of
//!   200,000 paths is within 5 standard errors (about 1%) of the answer,
//!   also where a light sample's density is far below 1 (10⁻¹² per
//!   steradian, say: a large light close by), and in the Cornell box each
//!   8 × 8 block agrees with the reference within 5 standard errors;
//! * the emission of the surface the camera sees, counted once; emission
//!   that a bounce finds is not added (the light sample counted it);
//! * a light sample (`sample_light`) at every surface the path reaches,
//!   drawn from two uniform numbers independent of each other, each with
//!   its shadow ray (`unoccluded`) before it counts;
//! * every bounce leaves on the side of the surface the path came from;
//! * nothing escapes a closed room: Russian roulette ends paths, with a
//!   survival probability taken from the throughput (so a survivor's
//!   throughput stays bounded) and survivors divided by it. No fixed
//!   maximum depth that cuts off light (a path over 1,000 bounces fails:
//!   the loop does not end);
//! * finite radiance (no inf, no NaN), whatever numbers of [0, 1)
//!   `rng()` gives, 0 included.
//!
//! Hints: `cargo grade --hint ch6/path_radiance`.
//! Grade it with: `cargo grade ch6`, and see it
//! render with `cargo run --release --bin ch6 -- --student`.

use glam::{Vec2, Vec3};
use raystep::grading::exercises::paths::PathScene;

/// The radiance arriving at the camera along the ray (W/(m²·sr)).
pub fn path_radiance(
    scene: &PathScene,
    origin: Vec3,
    dir: Vec3,
    rng: &mut dyn FnMut() -> f32,
) -> Vec3 {
    // TODO: the path loop.
    todo!()
}
