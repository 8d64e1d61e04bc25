//! The image of chapter 5: every pixel averages camera rays through
//! jittered positions, each ray's radiance from the reflection equation
//! ([`super::direct`]).

use glam::Vec3;
use rayon::prelude::*;

use super::direct::Estimator;
use super::shading_events::Counters;
use super::world::World;
use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::render::camera_sample;
use crate::core::sampling::Sampler;

/// Adds sample `sample` of every pixel of rows `rows` (all of them:
/// `0..cam.height`) to `sums`, rows in parallel, and
/// adds to `caught` how many values each pixel's sample left out for not
/// being finite (a light's term, or the whole sample);
/// every random number comes from (seed, pixel, sample), so the result
/// does not depend on the number of threads.
#[allow(clippy::too_many_arguments)]
// ANCHOR: render_pass
// ANCHOR: render_pass_sample
pub fn render_pass(
    world: &World,
    cam: &Camera,
    estimator: &Estimator,
    seed: u64,
    sample: u32,
    rows: std::ops::Range<u32>,
    sums: &mut [Vec3],
    caught: &mut [u32],
) -> Counters {
    let w = cam.width as usize;
    sums.par_chunks_mut(w)
        .zip(caught.par_chunks_mut(w))
        .zip(rows)
        .map(|((row, caught), y)| {
            let mut c = Counters::default();
            for (x, px) in row.iter_mut().enumerate() {
                let (mut s, ray) = camera_sample(cam, (x as u32, y), |pixel| {
                    Sampler::new(seed, pixel, sample as u64)
                });
                let caught_before = c.nonfinite;
                let l = estimator.radiance(world, &ray, &mut s, &mut c);
                // ANCHOR_END: render_pass_sample
                // ANCHOR: render_pass_sum
                if l.is_finite() {
                    *px += l;
                } else {
                    c.nonfinite += 1;
                }
                caught[x] += (c.nonfinite - caught_before) as u32;
            }
            c
        })
        .reduce(Counters::default, |mut a, b| {
            a += b;
            a
        })
}
// ANCHOR_END: render_pass_sum
// ANCHOR_END: render_pass
