//! A path's step past a vertex, outside the lanes of [`super::wave`]:
//! what the lanes computed, written back to the path (`finish`), and the
//! lesson's own steps for a vertex the lanes do not shade
//! (`lesson_vertex`).

use glam::{Vec2, Vec3};

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch5_reflection::world::{Interaction, World};
use crate::ch6_global_illumination::integrator::{direct_light, survival_probability, PathOut};
use crate::ch6_global_illumination::layers::Contributions;
use crate::ch6_global_illumination::vertex::{sample_direction, Vertex};

use super::gather8::Lane;
use super::lanes::W;
use super::shade8::{dim, Out8};

/// A vertex the lanes do not shade, where light of bounce count `k`
/// scatters: steps 2 to 4 of the lesson's `trace_path` (direct light, the
/// next direction, and roulette with the scale `roulette` holds, where it plays), with the
/// lesson's functions and this vertex's numbers, the ones `trace_path`
/// draws there. Returns whether the path goes on (then `lane.ray` is its
/// next ray).
pub(super) fn lesson_vertex<C: Contributions>(
    world: &World,
    lane: &mut Lane,
    it: &Interaction,
    k: u32,
    roulette: Option<u32>,
    out: &mut PathOut<'_, C>,
) -> bool {
    let Some(v) = Vertex::at(world, it, -lane.ray.dir) else {
        return false; // a ray exactly in the surface's plane
    };
    let path = &mut lane.path;
    let u = lane.sampler.eight_at(4 + 8 * u64::from(k));
    let u2 = |[a, b]: [usize; 2]| Vec2::new(u[a], u[b]);
    if path.samples_lights() && !v.delta {
        let direct = direct_light(world, &v, u[dim::CHOOSE], u2(dim::LIGHT), path, out.stats);
        out.add_direct(k, direct);
    }
    let Some(step) = sample_direction(&v, u[dim::LOBE], u2(dim::DIRECTION), path.strategy()) else {
        return false;
    };
    path.scatter(&v, k, &step);
    if let Some(s) = roulette {
        let q = survival_probability(path.beta * path.eta_scale(), s);
        if u[dim::ROULETTE] >= q {
            return false;
        }
        path.beta /= q;
    }
    match world.spawn(it.p, it.n, v.frame.to_world(step.wi)) {
        Some(ray) => {
            lane.ray = ray;
            true
        }
        None => false,
    }
}

/// Writes lane `j`'s path back: `false` where it ends (then what was
/// written is never read).
pub(super) fn finish(lane: &mut Lane, it: &Interaction, k: u32, o: &Out8, j: usize) -> bool {
    let v3 = |a: &[[f32; W]; 3]| Vec3::new(a[0][j], a[1][j], a[2][j]);
    let path = &mut lane.path;
    path.beta = v3(&o.beta);
    path.k = Some(k);
    path.from_delta = false;
    path.from_pdf = o.pdf[j];
    path.from_p = it.p;
    path.from_n = v3(&o.n_side);
    lane.ray = Ray {
        origin: v3(&o.next_o),
        dir: v3(&o.next_d),
    };
    o.valid[j] & o.step[j] & o.survives[j] & o.next_ok[j]
}
