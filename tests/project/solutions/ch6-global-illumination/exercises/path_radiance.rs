//! Capstone 6, solved: the path loop with next-event estimation and
//! Russian roulette on the throughput.

use glam::{Vec2, Vec3};
use raystep::grading::exercises::paths::PathScene;

/// The radiance arriving at the camera along the ray (W/(m²·sr)).
pub fn path_radiance(
    scene: &PathScene,
    origin: Vec3,
    dir: Vec3,
    rng: &mut dyn FnMut() -> f32,
) -> Vec3 {
    let Some(mut hit) = scene.first_hit(origin, dir) else {
        return Vec3::ZERO;
    };
    // The emission the camera sees; later emission is the light samples'.
    let mut radiance = hit.emitted;
    let mut beta = Vec3::ONE;
    let mut bounces = 0;
    loop {
        let f = hit.albedo / std::f32::consts::PI;
        // Next-event estimation.
        if let Some(ls) = scene.sample_light(&hit, Vec2::new(rng(), rng())) {
            let cos = hit.n.dot(ls.wi);
            if cos > 0.0 && ls.pdf > 0.0 && scene.unoccluded(&hit, ls.wi, ls.dist) {
                radiance += beta * f * ls.li * cos / ls.pdf;
            }
        }
        // One cosine-sampled bounce.
        let (wi, pdf) = scene.sample_cosine(&hit, Vec2::new(rng(), rng()));
        if pdf <= 0.0 {
            break;
        }
        beta *= f * hit.n.dot(wi) / pdf;
        bounces += 1;
        // Russian roulette after the first bounce.
        if bounces > 1 {
            let q = beta.max_element().min(1.0);
            if rng() >= q {
                break;
            }
            beta /= q;
        }
        match scene.next_hit(&hit, wi) {
            Some(next) => hit = next,
            None => break,
        }
    }
    radiance
}
