//! Capstone 6: the path loop, with next-event estimation and Russian
//! roulette.
//!
//! The grader renders the Cornell box (`scenes/cornell-box.toml`) with one
//! call per camera sample and checks the image statistically against the
//! reference (Monte Carlo is never exact; a bias shows as a z-score).
//! Every surface is Lambertian, with BRDF ρ/π. The scene offers:
//!
//! * `scene.first_hit(origin, dir)`: the first surface along the camera
//!   ray, with its point, normal (facing the path), albedo ρ and the
//!   radiance it emits back along the path;
//! * `scene.next_hit(&hit, wi)`: the next surface leaving `hit` along `wi`;
//! * `scene.sample_light(&hit, u)`: a direction to a point on the light,
//!   its distance, the radiance Le arriving along it and its density per
//!   steradian;
//! * `scene.unoccluded(&hit, wi, dist)`: the shadow ray;
//! * `scene.sample_cosine(&hit, u)`: a direction about the normal with
//!   density cos θ / π.
//!
//! `rng()` gives a fresh uniform number in [0, 1) at each call.
//!
//! Build the path bounce by bounce in a loop: count the emission the
//! camera sees, then at every surface add one light sample (next-event
//! estimation) and continue along one sampled direction. There is no
//! fixed maximum depth: Russian roulette ends paths, and must not change
//! the expected value. Do not count emission twice.
//!
//! Grade it with: `cargo run --release --bin grade -- ch6`, and see it
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
    // TODO: the first hit (none: black), and the emission seen there.
    // TODO: loop over bounces with a throughput β, starting at 1:
    //       - next-event estimation: a light sample, its cos θ at the
    //         hit, the shadow ray; add β · f · Le · cos θ / pdf;
    //       - a cosine-sampled direction; update β by f · cos θ / pdf;
    //       - Russian roulette on β (after a bounce or two): survive with
    //         probability q, and keep the estimate unbiased;
    //       - move to the next hit (none: the path leaves the box).
    todo!()
}
