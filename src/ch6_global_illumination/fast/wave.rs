//! The fast engine's path loop: a *wavefront*. Instead of following one
//! path from the camera to its end before starting the next, it starts a
//! few thousand paths at once and extends all of them by one bounce per
//! round:
//!
//! 1. every live path's ray finds its closest hit (the eight-wide tree);
//! 2. the hits are shaded eight at a time ([`shade8`](super::shade8::shade8)): the local frame,
//!    the light sample with its MIS weight, the cosine-weighted next
//!    direction and Russian roulette, each step one pass over eight lanes
//!    with no branch, so the compiler turns it into vector instructions;
//! 3. every shadow ray is traced, and the light it carries added.
//!
//! A round's paths all sit at the same bounce, so they draw the same
//! dimensions of their sampler: eight numbers per path per round
//! ([`PathSampler::eight_at`]), the very numbers
//! [`trace_path`](crate::ch6_global_illumination::integrator::trace_path)
//! draws one by one.
//!
//! The lanes run the lesson's formulas in the lesson's order, with one
//! exception: the cosine and sine of the disk mapping are polynomials
//! ([`sin_cos_quarter`](super::shade8::sin_cos_quarter)), since the C library's `sincosf` has no
//! eight-lane form. So the images match the readable loop's to a few
//! units in the last place per path, not byte for byte; tests check that
//! and the statistics against the stored references.
//!
//! It covers what the benchmark scenes are made of: diffuse (Lambertian)
//! surfaces, with MIS, no SDFs and at least one light (area lights are
//! sampled in the lanes, other kinds by the lesson's code, one lane at a
//! time); anything else goes to the lesson's loop ([`supports`]).

use glam::{Vec2, Vec3};

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::render::camera_sample;
use crate::ch3_ray_triangle::triangle::Hit;
use crate::ch4_implicit_surfaces::hit::Surface;
use crate::ch5_reflection::direct::Strategy;
use crate::ch5_reflection::light::Light;
use crate::ch5_reflection::material::Bsdf;
use crate::ch5_reflection::world::{Interaction, World};
use crate::ch6_global_illumination::integrator::{
    direct_light, sky_emission, surface_emission, Path, PathOut, PathSettings, PathStats,
};
use crate::ch6_global_illumination::layers::Contributions;
use crate::ch6_global_illumination::sampler::{PathSampler, SamplerKind};
use crate::ch6_global_illumination::vertex::Vertex;

use super::bvh8::Bvh8;
use super::level::Level;
use super::pick8::pick8;
use super::shade8::{In8, Out8, L};

/// Whether the wavefront loop renders `world` with `settings` exactly as
/// the lesson's loop would (in distribution): MIS, diffuse surfaces, at
/// least one light, no SDFs.
pub fn supports(world: &World, settings: &PathSettings) -> bool {
    settings.strategy == Strategy::Mis
        && world.sdfs.is_empty()
        && !world.lights.lights.is_empty()
        && world.bsdfs.iter().all(|b| matches!(b, Bsdf::Lambertian(_)))
}

/// The fast engine's tree, if `world`'s ray queries are answered by it
/// (the fast engine built it): then chapter 6 traces paths in waves.
pub fn engine_tree(world: &World) -> Option<&Bvh8> {
    world.mesh_queries()?.as_any()?.downcast_ref::<Bvh8>()
}

/// One path under way.
struct Lane {
    ray: Ray,
    path: Path,
    sampler: PathSampler,
    /// Where its light goes (index into the output).
    out: u32,
}

/// A shadow ray to test and the light it carries if nothing blocks it.
struct Shadow {
    test: ShadowTest,
    k: u32,
    contribution: Vec3,
    out: u32,
}

/// How a shadow ray is decided.
enum ShadowTest {
    /// Its two ends meet: nothing can block it.
    Visible,
    /// It has no origin (a surface point that is not finite).
    Blocked,
    /// Traced through the tree to `t_max` (made in the lanes).
    Trace(Ray, f32),
}

/// Traces one path per (camera ray, sampler) of `starts`, adding path i's
/// light to `outs[i]` (which must hold one entry per start): one sum, or
/// one per bounce layer.
pub fn trace_paths<C: Contributions>(
    world: &World,
    tree: &Bvh8,
    starts: impl Iterator<Item = (Ray, PathSampler)>,
    settings: &PathSettings,
    outs: &mut [C],
    stats: &mut PathStats,
) {
    let mut lanes: Vec<Lane> = starts
        .enumerate()
        .map(|(i, (ray, sampler))| Lane {
            path: Path::from_camera(&ray, settings.strategy, world),
            ray,
            sampler,
            out: i as u32,
        })
        .collect();
    stats.paths += lanes.len() as u64;
    let mut hits: Vec<Interaction> = Vec::with_capacity(lanes.len());
    let mut shaded: Vec<u32> = Vec::with_capacity(lanes.len());
    let mut shadows: Vec<Shadow> = Vec::with_capacity(lanes.len());
    // A round's rays and what the tree answers for them.
    let mut rays: Vec<Ray> = Vec::with_capacity(lanes.len());
    let mut found: Vec<Option<Hit>> = Vec::with_capacity(lanes.len());
    let mut shadow_rays: Vec<(Ray, f32)> = Vec::with_capacity(lanes.len());
    let mut blocked: Vec<bool> = Vec::with_capacity(lanes.len());
    let level = tree.level();
    let emissive: Vec<bool> = world.materials.iter().map(|m| m.is_emissive()).collect();
    let (mut input, mut o) = (Box::<In8>::default(), Box::<Out8>::default());
    // The paths still going (indices into `lanes`, which never move).
    let mut live: Vec<u32> = (0..lanes.len() as u32).collect();
    let mut alive = vec![false; lanes.len()];
    let mut k = 0u32;
    while !live.is_empty() {
        // 1. Closest hits; emission found; paths that leave or end.
        stats.rays += live.len() as u64;
        hits.clear();
        shaded.clear();
        let over_limit = k > settings.bounce_limit();
        rays.clear();
        rays.extend(live.iter().map(|&i| lanes[i as usize].ray));
        super::simd::closest_all(level, tree, &rays, &mut found);
        for (&i, hit) in live.iter().zip(&found) {
            let lane = &lanes[i as usize];
            let mut out = PathOut {
                layers: &mut outs[lane.out as usize],
                stats,
            };
            let Some(it) = hit.map(|hit| interaction(world, hit)) else {
                let sky = sky_emission(world, lane.ray.dir, &lane.path);
                out.add_sky(&lane.path, lane.ray.dir, sky);
                continue;
            };
            // Most surfaces emit nothing: no call to find that out.
            let emitted = match emissive[it.material] {
                true => surface_emission(world, &it, -lane.ray.dir, &lane.path),
                false => None,
            };
            out.add_emitted(&lane.path, &it, emitted);
            if over_limit {
                out.stats.cut += u64::from(settings.max_bounces.is_none());
                continue;
            }
            shaded.push(i);
            hits.push(it);
        }
        // 2. Shading, eight lanes at a time.
        shadows.clear();
        let roulette = k + 1 >= settings.rr_min_bounce;
        for (ids, its) in shaded.chunks(L).zip(hits.chunks(L)) {
            input.u = numbers(level, &lanes, ids, k);
            let lesson_light = gather(world, &lanes, (ids, its), roulette, &mut input);
            super::simd::shade8_at(level, &input, &mut o);
            for (j, (&i, it)) in ids.iter().zip(its).enumerate() {
                let lane = &mut lanes[i as usize];
                if lesson_light[j] {
                    // A point, spot, directional or sky light: the lesson's
                    // `direct_light`, shadow ray and all, one lane at a time.
                    if let Some(v) = Vertex::at(world, it, -lane.ray.dir) {
                        let mut out = PathOut {
                            layers: &mut outs[lane.out as usize],
                            stats,
                        };
                        let u = &input.u;
                        let u_light = Vec2::new(u[1][j], u[2][j]);
                        let direct =
                            direct_light(world, &v, u[0][j], u_light, &lane.path, out.stats);
                        out.add_direct(k, direct);
                    }
                }
                let shadows = (!lesson_light[j]).then_some(&mut shadows);
                alive[i as usize] = finish(lane, it, k, (&*o, j), stats, shadows);
            }
        }
        // 3. Shadow rays.
        shadow_rays.clear();
        shadow_rays.extend(shadows.iter().filter_map(|s| match s.test {
            ShadowTest::Trace(ray, t_max) => Some((ray, t_max)),
            _ => None,
        }));
        super::simd::occluded_all(level, tree, &shadow_rays, &mut blocked);
        let mut traced = blocked.iter();
        for s in &shadows {
            let visible = match s.test {
                ShadowTest::Visible => true,
                ShadowTest::Blocked => false,
                ShadowTest::Trace(..) => !traced.next().copied().unwrap_or(true),
            };
            if visible {
                let mut out = PathOut {
                    layers: &mut outs[s.out as usize],
                    stats,
                };
                out.add(Some(s.k), s.contribution);
            }
        }
        live.retain(|&i| std::mem::take(&mut alive[i as usize]));
        k += 1;
    }
}

/// The eight numbers of vertex `k` of lanes `ids` (unused lanes repeat the
/// first), `u[d][lane]`, computed eight paths at a time (one path at a
/// time where Sobol points and independent numbers mix).
#[allow(clippy::needless_range_loop)]
fn numbers(level: Level, lanes: &[Lane], ids: &[u32], k: u32) -> [[f32; L]; 8] {
    let first = 4 + 8 * k as u64;
    let lane = |j: usize| &lanes[ids[if j < ids.len() { j } else { 0 }] as usize];
    let mut u = [[0.0; L]; 8];
    if let Some((sample, scramble)) = sobol_lanes(|j| &lane(j).sampler) {
        for half in 0..2 {
            let g = super::simd::sobol_group8_at(level, &sample, &scramble, first / 4 + half);
            u[4 * half as usize..4 * half as usize + 4].copy_from_slice(&g);
        }
    } else if (0..L).all(|j| lane(j).sampler.independent_prefix().is_some()) {
        let prefix: [u64; L] =
            std::array::from_fn(|j| lane(j).sampler.independent_prefix().unwrap_or(0));
        u = super::simd::independent8_at(level, &prefix, first);
    } else {
        // Sobol points and, past the tables, independent numbers mixed.
        for j in 0..L {
            let v = lane(j).sampler.eight_at(first);
            for d in 0..8 {
                u[d][j] = v[d];
            }
        }
    }
    u
}

/// The sample indices and pixel scrambles of eight samplers (`sampler(j)`
/// for lane j), when all of them draw Sobol points from the tables: what
/// [`sobol_group8_at`](super::simd::sobol_group8_at) needs to draw for them.
fn sobol_lanes<'a>(sampler: impl Fn(usize) -> &'a PathSampler) -> Option<([u32; L], [u64; L])> {
    let index: [Option<u32>; L] = std::array::from_fn(|j| sampler(j).sobol_index());
    index.iter().all(Option::is_some).then(|| {
        let sample = std::array::from_fn(|j| index[j].unwrap_or(0));
        (sample, std::array::from_fn(|j| sampler(j).pixel_scramble()))
    })
}

/// Reads lanes `ids` (with their hits) into the eight-lane arrays `x`,
/// beside the numbers already there; unused lanes repeat the first one.
/// Returns which lanes chose a light that is not an area light: their
/// light fields are left as they were, and the lesson's code samples that
/// light instead (the lanes' shadow ray for them is not used).
#[allow(clippy::needless_range_loop)]
fn gather(
    world: &World,
    lanes: &[Lane],
    (ids, hits): (&[u32], &[Interaction]),
    roulette: bool,
    x: &mut In8,
) -> [bool; L] {
    let mut lesson_light = [false; L];
    for j in 0..L {
        let jj = if j < ids.len() { j } else { 0 };
        let lane = &lanes[ids[jj] as usize];
        let it = &hits[jj];
        let Bsdf::Lambertian(b) = &world.bsdfs[it.material] else {
            unreachable!("the wavefront loop only runs on diffuse scenes");
        };
        for a in 0..3 {
            x.d[a][j] = lane.ray.dir[a];
            x.p[a][j] = it.p[a];
            x.n[a][j] = it.n[a];
            x.rho[a][j] = b.rho[a];
            x.beta[a][j] = lane.path.beta[a];
        }
    }
    // The lights, then the triangles on them, each a short loop of its own:
    // a pick is a chain of dependent steps (count, load, divide), and the
    // processor overlaps eight independent chains only when they are near.
    let mut area = [None; L];
    for j in 0..L {
        let (i, p_choose) = world.lights.choose(x.u[0][j]).expect("a light");
        x.p_choose[j] = p_choose;
        match &world.lights.lights[i] {
            Light::Area(light) => area[j] = Some(light),
            _ => lesson_light[j] = true,
        }
    }
    // The triangle, as `AreaLight::sample_li` picks it: for all eight
    // lanes at once where they chose the same light.
    let same = area.iter().all(|a| match (a, area[0]) {
        (Some(a), Some(first)) => std::ptr::eq(*a, first),
        _ => false,
    });
    let picks: [(usize, f32); L] = match area[0].filter(|_| same).and_then(|l| pick8(l, &x.u[1])) {
        Some((t, ux)) => std::array::from_fn(|j| (t[j], ux[j])),
        None => std::array::from_fn(|j| area[j].map_or((0, 0.0), |light| light.pick(x.u[1][j]))),
    };
    for (j, (light, (t, ux))) in area.into_iter().zip(picks).enumerate() {
        let Some(light) = light else { continue };
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
    x.roulette = roulette;
    lesson_light
}

/// Writes lane `j`'s results back: its shadow ray (into `shadows`, unless
/// the lesson's code took care of the light: `None`), and the path going
/// on (`false` where it ends).
fn finish(
    lane: &mut Lane,
    it: &Interaction,
    k: u32,
    (o, j): (&Out8, usize),
    stats: &mut PathStats,
    shadows: Option<&mut Vec<Shadow>>,
) -> bool {
    if !o.valid[j] {
        return false;
    }
    let v3 = |a: &[[f32; L]; 3]| Vec3::new(a[0][j], a[1][j], a[2][j]);
    if let Some(shadows) = shadows.filter(|_| o.shadow[j]) {
        let test = if o.shadow_trace[j] {
            let ray = Ray {
                origin: v3(&o.shadow_o),
                dir: v3(&o.shadow_d),
            };
            ShadowTest::Trace(ray, o.shadow_t[j])
        } else if o.shadow_free[j] {
            ShadowTest::Visible
        } else {
            ShadowTest::Blocked
        };
        stats.rays += 1;
        shadows.push(Shadow {
            test,
            k,
            contribution: v3(&o.contribution),
            out: lane.out,
        });
    }
    if !o.step[j] || !o.survives[j] {
        return false;
    }
    let path = &mut lane.path;
    path.beta = v3(&o.beta);
    path.k = Some(k);
    path.from_delta = false;
    path.from_pdf = o.pdf[j];
    path.from_p = it.p;
    path.from_n = v3(&o.n_side);
    if !o.next_ok[j] {
        return false;
    }
    lane.ray = Ray {
        origin: v3(&o.next_o),
        dir: v3(&o.next_d),
    };
    true
}

/// What `World::intersect` makes of a hit the tree found (a scene without
/// SDFs).
#[inline]
fn interaction(world: &World, hit: Hit) -> Interaction {
    let k = hit.triangle as usize;
    let mesh = world.triangles.mesh[k] as usize;
    Interaction {
        t: hit.t,
        p: hit.point(world.triangles.tris[k]),
        n: world.normals[k],
        material: world.mesh_material[mesh],
        surface: Surface::Mesh(mesh),
    }
}

/// The camera rays and samplers of samples `first .. first + count` of
/// pixels `xs` of row `y`, in that order: what chapter 6's `camera_sample`
/// gives (chapter 3's, which hands the closure this same pixel index), with
/// the pixel positions of eight Sobol samples drawn at once
/// ([`sobol_group8_at`](super::simd::sobol_group8_at), the same bits).
pub fn camera_starts(
    camera: &Camera,
    level: Level,
    (kind, seed): (SamplerKind, u64),
    (xs, y): (std::ops::Range<usize>, usize),
    (first, count): (u32, u32),
) -> Vec<(Ray, PathSampler)> {
    let mut starts = Vec::with_capacity(xs.len() * count as usize);
    for x in xs {
        let pixel = (y * camera.width as usize + x) as u64;
        let one_by_one =
            |sampler: PathSampler| camera_sample(camera, (x as u32, y as u32), |_| sampler);
        let mut s = first;
        while s < first + count {
            if s + L as u32 > first + count {
                // The last few samples of the pixel.
                let (sampler, ray) = one_by_one(PathSampler::new(kind, seed, pixel, s as u64));
                starts.push((ray, sampler));
                s += 1;
                continue;
            }
            let samplers: [PathSampler; L] =
                std::array::from_fn(|j| PathSampler::new(kind, seed, pixel, (s + j as u32) as u64));
            s += L as u32;
            let Some((sample, scramble)) = sobol_lanes(|j| &samplers[j]) else {
                // Independent numbers, or Sobol indices past the tables.
                for sampler in samplers {
                    let (sampler, ray) = one_by_one(sampler);
                    starts.push((ray, sampler));
                }
                continue;
            };
            let g = super::simd::sobol_group8_at(level, &sample, &scramble, 0);
            for (j, mut sampler) in samplers.into_iter().enumerate() {
                // `jittered`: the pixel's corner plus the first two numbers.
                let raster = Vec2::new(x as f32, y as f32) + Vec2::new(g[0][j], g[1][j]);
                sampler.skip(2);
                starts.push((camera.ray(raster), sampler));
            }
        }
    }
    starts
}
