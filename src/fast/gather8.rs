//! What the lanes of [`super::wave`]'s shading read, gathered from up to
//! eight paths: the vertex's random numbers, eight paths at a time, and
//! the hits, materials, throughputs and light samples, lane by lane.

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch5_reflection::light::Light;
use crate::ch5_reflection::material::Bsdf;
use crate::ch5_reflection::world::{Interaction, World};
use crate::ch6_global_illumination::integrator::Path;
use crate::ch6_global_illumination::sampler::PathSampler;

use super::lanes::W;
use super::level::Level;
use super::shade8::{dim, In8};

/// One path under way.
pub(super) struct Lane {
    pub(super) ray: Ray,
    pub(super) path: Path,
    pub(super) sampler: PathSampler,
    /// Where its light goes (index into the output).
    pub(super) out: u32,
}

/// The eight numbers of vertex `k` of lanes `ids` (unused lanes repeat the
/// first), `u[d][lane]`, computed eight paths at a time (one path at a
/// time where Sobol points and independent numbers mix); only the
/// dimensions `wanted` (bit d), the others 0 (the mixed case makes all).
#[allow(clippy::needless_range_loop)]
pub(super) fn numbers(
    level: Level,
    lanes: &[Lane],
    ids: &[u32],
    k: u32,
    wanted: u8,
) -> [[f32; W]; dim::PER_VERTEX] {
    let first = 4 + 8 * k as u64;
    let lane = |j: usize| &lanes[ids[if j < ids.len() { j } else { 0 }] as usize];
    let mut u = [[0.0; W]; dim::PER_VERTEX];
    if let Some((sample, scramble)) = sobol_lanes(|j| &lane(j).sampler) {
        let [a, b] = super::simd::sobol_groups8_wanted_at(
            level,
            &sample,
            &scramble,
            first / 4,
            u32::from(wanted),
        );
        u[..4].copy_from_slice(&a);
        u[4..].copy_from_slice(&b);
    } else if (0..W).all(|j| lane(j).sampler.independent_prefix().is_some()) {
        let prefix: [u64; W] =
            std::array::from_fn(|j| lane(j).sampler.independent_prefix().unwrap_or(0));
        u = super::simd::independent8_wanted_at(level, &prefix, first, wanted);
    } else {
        // Sobol points and, past the tables, independent numbers mixed.
        for j in 0..W {
            let v = lane(j).sampler.eight_at(first);
            for d in 0..8 {
                u[d][j] = v[d];
            }
        }
    }
    u
}

/// Reads lanes `ids` (with their hits) into the eight-lane arrays `x`,
/// beside the numbers already there; unused lanes repeat the first one.
/// Returns which lanes chose a light that is not an area light: their
/// light fields are left as they were, and the lesson's code samples that
/// light instead (the lanes' shadow ray for them is not used).
#[allow(clippy::needless_range_loop)]
pub(super) fn gather(
    world: &World,
    level: Level,
    lanes: &[Lane],
    ids: &[u32],
    hits: &[Interaction],
    roulette: Option<u32>,
    x: &mut In8,
) -> [bool; W] {
    x.roulette = roulette.is_some();
    x.rr_scale = roulette.unwrap_or(1) as f32;
    let mut lesson_light = [false; W];
    for j in 0..W {
        let jj = if j < ids.len() { j } else { 0 };
        let lane = &lanes[ids[jj] as usize];
        let it = &hits[jj];
        let Bsdf::Lambertian(b) = &world.bsdfs[it.material] else {
            unreachable!("the lanes shade only diffuse vertices (Shade::in_lanes)");
        };
        for a in 0..3 {
            x.d[a][j] = lane.ray.dir[a];
            x.p[a][j] = it.p[a];
            x.n[a][j] = it.n[a];
            x.rho[a][j] = b.rho[a];
            x.beta[a][j] = lane.path.beta[a];
        }
    }
    // One area light, or eight lanes that chose the same one: its
    // triangles picked in the lanes.
    let lights = &world.lights.lights;
    if let [Light::Area(light)] = lights.as_slice() {
        if super::simd::fill_light8_at(level, light, world.lights.choose_pdf(0), x) {
            return lesson_light;
        }
    }
    // The lights, then the triangles on them, each a short loop of its own:
    // a pick is a chain of dependent steps (count, load, divide), and the
    // processor overlaps eight independent chains only when they are near.
    let mut area = [None; W];
    for j in 0..W {
        let (i, p_choose) = world.lights.choose(x.u[dim::CHOOSE][j]).expect("a light");
        x.p_choose[j] = p_choose;
        match &lights[i] {
            Light::Area(light) => area[j] = Some(light),
            _ => lesson_light[j] = true,
        }
    }
    // The triangle, as `AreaLight::sample_li` picks it.
    let same = area.iter().all(|a| match (a, area[0]) {
        (Some(a), Some(first)) => std::ptr::eq(*a, first),
        _ => false,
    });
    if let Some(light) = area[0].filter(|_| same) {
        if super::simd::fill_light8_at(level, light, x.p_choose[0], x) {
            return lesson_light;
        }
    }
    for (j, light) in area.into_iter().enumerate() {
        let Some(light) = light else { continue };
        let (t, ux) = light.pick(x.u[dim::LIGHT[0]][j]);
        x.ux[j] = ux;
        for (c, corner) in light.triangles[t].iter().enumerate() {
            for a in 0..3 {
                x.tri[c][a][j] = corner[a];
            }
        }
        for a in 0..3 {
            x.n_light[a][j] = light.normals[t][a];
            x.le[a][j] = light.le[a];
        }
        x.inv_area[j] = light.inv_area;
        x.two_sided[j] = light.two_sided;
    }
    lesson_light
}

/// The sample indices and pixel scrambles of eight samplers (`sampler(j)`
/// for lane j), when all of them draw Sobol points from the tables: what
/// [`sobol_groups8_at`](super::simd::sobol_groups8_at) needs to draw for them.
pub(super) fn sobol_lanes<'a>(
    sampler: impl Fn(usize) -> &'a PathSampler,
) -> Option<([u32; W], [u64; W])> {
    let (mut sample, mut scramble) = ([0; W], [0; W]);
    let mut all = true;
    for j in 0..W {
        let s = sampler(j);
        match s.sobol_index() {
            Some(i) => (sample[j], scramble[j]) = (i, s.pixel_scramble()),
            None => all = false,
        }
    }
    all.then_some((sample, scramble))
}
