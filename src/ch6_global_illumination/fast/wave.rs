//! The fast engine's path loop: a *wavefront*. Instead of following one
//! path from the camera to its end before starting the next, it starts a
//! few thousand paths at once and extends all of them by one bounce per
//! round:
//!
//! 1. every live path's ray finds its closest hit (the eight-wide tree);
//! 2. the hits are shaded eight at a time ([`shade8`]): the local frame,
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
//! ([`sin_cos_quarter`]), since the C library's `sincosf` has no
//! eight-lane form. So the images match the readable loop's to a few
//! units in the last place per path, not byte for byte; tests check that
//! and the statistics against the stored references.
//!
//! It covers what the benchmark scenes are made of: diffuse (Lambertian)
//! surfaces lit by area lights, with MIS, no SDFs and no sky; anything
//! else goes to the lesson's loop ([`supports`]).

use std::f32::consts::{FRAC_1_PI, PI};

use glam::Vec3;

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch5_reflection::direct::Strategy;
use crate::ch5_reflection::light::Light;
use crate::ch5_reflection::material::Bsdf;
use crate::ch5_reflection::world::{Interaction, World};
use crate::ch6_global_illumination::integrator::{
    sky_emission, surface_emission, Path, PathOut, PathSettings, PathStats,
};
use crate::ch6_global_illumination::sampler::PathSampler;

use super::bvh8::Bvh8;
use super::level::Level;

/// Lanes shaded together.
const L: usize = 8;

/// Whether the wavefront loop renders `world` with `settings` exactly as
/// the lesson's loop would (in distribution): MIS, diffuse surfaces, area
/// lights only, no SDFs.
pub fn supports(world: &World, settings: &PathSettings) -> bool {
    settings.strategy == Strategy::Mis
        && world.sdfs.is_empty()
        && world.lights.environment.is_none()
        && !world.lights.lights.is_empty()
        && world
            .lights
            .lights
            .iter()
            .all(|l| matches!(l, Light::Area(_)))
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

/// A shadow ray to trace and the light it carries if nothing blocks it.
struct Shadow {
    p: Vec3,
    n: Vec3,
    wi: Vec3,
    dist: f32,
    k: u32,
    contribution: Vec3,
    out: u32,
}

/// Traces one path per (camera ray, sampler) of `starts`, adding path i's
/// light to `outs[i]` (which must hold one entry per start).
pub fn trace_paths(
    world: &World,
    level: Level,
    starts: impl Iterator<Item = (Ray, PathSampler)>,
    settings: &PathSettings,
    outs: &mut [Vec3],
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
    let mut k = 0u32;
    while !lanes.is_empty() {
        // 1. Closest hits; emission found; paths that leave or end.
        stats.rays += lanes.len() as u64;
        hits.clear();
        shaded.clear();
        let over_limit = k > settings.bounce_limit();
        for (i, lane) in lanes.iter().enumerate() {
            let mut out = PathOut {
                layers: &mut outs[lane.out as usize],
                stats,
            };
            let Some(it) = world.intersect(&lane.ray) else {
                let sky = sky_emission(world, lane.ray.dir, &lane.path);
                out.add_sky(&lane.path, lane.ray.dir, sky);
                continue;
            };
            let emitted = surface_emission(world, &it, -lane.ray.dir, &lane.path);
            out.add_emitted(&lane.path, &it, emitted);
            if over_limit {
                out.stats.cut += u64::from(settings.max_bounces.is_none());
                continue;
            }
            shaded.push(i as u32);
            hits.push(it);
        }
        // 2. Shading, eight lanes at a time.
        shadows.clear();
        let roulette = k + 1 >= settings.rr_min_bounce;
        let mut alive = vec![false; lanes.len()];
        for (ids, its) in shaded.chunks(L).zip(hits.chunks(L)) {
            let input = gather(world, &lanes, ids, its, k, roulette);
            let o = super::simd::shade8_at(level, &input);
            for (j, (&i, it)) in ids.iter().zip(its).enumerate() {
                let lane = &mut lanes[i as usize];
                alive[i as usize] = finish(world, lane, it, k, &o, j, stats, &mut shadows);
            }
        }
        // 3. Shadow rays.
        for s in &shadows {
            if world.unoccluded(s.p, s.n, s.wi, s.dist) {
                let mut out = PathOut {
                    layers: &mut outs[s.out as usize],
                    stats,
                };
                out.add(Some(s.k), s.contribution);
            }
        }
        let mut i = 0;
        lanes.retain(|_| {
            i += 1;
            alive[i - 1]
        });
        k += 1;
    }
}

/// What the lanes read: per lane the ray, the hit, the material, the
/// throughput, the vertex's random numbers and the light sample's
/// triangle (chosen by scalar code: a short search per lane).
#[derive(Default)]
pub(super) struct In8 {
    d: [[f32; L]; 3],
    p: [[f32; L]; 3],
    n: [[f32; L]; 3],
    rho: [[f32; L]; 3],
    beta: [[f32; L]; 3],
    u: [[f32; L]; 8],
    /// The light triangle's corners a, b, c.
    tri: [[[f32; L]; 3]; 3],
    n_light: [[f32; L]; 3],
    /// The position inside the chosen triangle, rescaled from u[1].
    ux: [f32; L],
    inv_area: [f32; L],
    p_choose: [f32; L],
    le: [[f32; L]; 3],
    two_sided: [bool; L],
    /// Whether roulette is played at this vertex.
    roulette: bool,
}

/// What the lanes give back.
#[derive(Default)]
pub(super) struct Out8 {
    /// wo.z ≠ 0: the ray is not in the surface's plane.
    valid: [bool; L],
    n_side: [[f32; L]; 3],
    /// A shadow ray is cast (the light sample exists and f ≠ 0).
    shadow: [bool; L],
    wi_light: [[f32; L]; 3],
    dist: [f32; L],
    contribution: [[f32; L]; 3],
    /// A next direction exists (pdf > 0, weight finite and non-zero).
    step: [bool; L],
    dir: [[f32; L]; 3],
    pdf: [f32; L],
    /// β after the step and roulette; whether the path survived it.
    beta: [[f32; L]; 3],
    survives: [bool; L],
}

/// Reads lanes `ids` (with their hits) into eight-lane arrays; unused
/// lanes repeat the first one.
fn gather(
    world: &World,
    lanes: &[Lane],
    ids: &[u32],
    hits: &[Interaction],
    k: u32,
    roulette: bool,
) -> In8 {
    let mut x = In8::default();
    for j in 0..L {
        let jj = if j < ids.len() { j } else { 0 };
        let lane = &lanes[ids[jj] as usize];
        let it = &hits[jj];
        let Bsdf::Lambertian(b) = &world.bsdfs[it.material] else {
            unreachable!("the wavefront loop only runs on diffuse scenes");
        };
        let u = lane.sampler.eight_at(4 + 8 * k as u64);
        for a in 0..3 {
            x.d[a][j] = lane.ray.dir[a];
            x.p[a][j] = it.p[a];
            x.n[a][j] = it.n[a];
            x.rho[a][j] = b.rho[a];
            x.beta[a][j] = lane.path.beta[a];
        }
        for (d, v) in u.iter().enumerate() {
            x.u[d][j] = *v;
        }
        // The light and its triangle, as `AreaLight::sample_li` picks them.
        let (i, p_choose) = world.lights.choose(u[0]).expect("a light");
        let Light::Area(light) = &world.lights.lights[i] else {
            unreachable!("area lights only");
        };
        let target = u[1] * light.area;
        let below = if light.cdf.len() <= 8 {
            light.cdf.iter().map(|c| (*c <= target) as usize).sum()
        } else {
            light.cdf.partition_point(|c| *c <= target)
        };
        let t = below.min(light.cdf.len() - 1);
        let lo = light.cdf[t.saturating_sub(1)] * f32::from(u8::from(t > 0));
        let width = light.cdf[t] - lo;
        x.ux[j] = if width > 0.0 {
            ((target - lo) / width).clamp(0.0, 1.0 - f32::EPSILON)
        } else {
            0.0
        };
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
        x.p_choose[j] = p_choose;
        x.two_sided[j] = light.two_sided;
    }
    x.roulette = roulette;
    x
}

/// Cosine and sine of φ in [-π/4, π/4] (Cephes' minimax polynomials,
/// within a couple of units in the last place of `f32::sin_cos`).
// ANCHOR: sin_cos_quarter
#[inline(always)]
pub fn sin_cos_quarter(phi: f32) -> (f32, f32) {
    let z = phi * phi;
    let s = ((-1.951_529_6e-4 * z + 8.332_161e-3) * z - 1.666_665_5e-1) * z * phi + phi;
    let c = ((2.443_315_7e-5 * z - 1.388_731_6e-3) * z + 4.166_664_6e-2) * z * z - 0.5 * z + 1.0;
    (c, s)
}
// ANCHOR_END: sin_cos_quarter

/// One vertex of eight paths: frame, light sample, MIS, next direction,
/// roulette. Each line is one pass over the lanes with selects in place of
/// branches.
#[inline(always)]
pub(super) fn shade8(x: &In8) -> Out8 {
    let mut o = Out8::default();
    for j in 0..L {
        let (nx, ny, nz) = (x.n[0][j], x.n[1][j], x.n[2][j]);
        // Frame::from_normal (Duff et al.).
        let sign = 1.0f32.copysign(nz);
        let a = -1.0 / (sign + nz);
        let b = nx * ny * a;
        let s = [1.0 + sign * nx * nx * a, sign * b, -sign * nx];
        let t = [b, sign + ny * ny * a, -ny];
        let n = [nx, ny, nz];
        let local = |v: [f32; 3]| {
            [
                v[0] * s[0] + v[1] * s[1] + v[2] * s[2],
                v[0] * t[0] + v[1] * t[1] + v[2] * t[2],
                v[0] * n[0] + v[1] * n[1] + v[2] * n[2],
            ]
        };
        let wo = local([-x.d[0][j], -x.d[1][j], -x.d[2][j]]);
        o.valid[j] = wo[2] != 0.0;
        let flip = if wo[2] > 0.0 { 1.0 } else { -1.0 };
        for a in 0..3 {
            o.n_side[a][j] = n[a] * flip;
        }
        let p = [x.p[0][j], x.p[1][j], x.p[2][j]];
        let beta = [x.beta[0][j], x.beta[1][j], x.beta[2][j]];
        let f_rho = [
            x.rho[0][j] * FRAC_1_PI,
            x.rho[1][j] * FRAC_1_PI,
            x.rho[2][j] * FRAC_1_PI,
        ];

        // The light sample: a uniform point y on the chosen triangle.
        let sq = x.ux[j].sqrt();
        let b1 = 1.0 - sq;
        let b2 = x.u[2][j] * sq;
        let b0 = 1.0 - b1 - b2;
        let mut to = [0.0; 3];
        for a in 0..3 {
            let y = b0 * x.tri[0][a][j] + b1 * x.tri[1][a][j] + b2 * x.tri[2][a][j];
            to[a] = y - p[a];
        }
        let dist = (to[0] * to[0] + to[1] * to[1] + to[2] * to[2]).sqrt();
        let nl = [x.n_light[0][j], x.n_light[1][j], x.n_light[2][j]];
        let wi = [to[0] / dist, to[1] / dist, to[2] / dist];
        let cos_l = nl[0] * wi[0] + nl[1] * wi[1] + nl[2] * wi[2];
        let faces = x.two_sided[j] | (nl[0] * -wi[0] + nl[1] * -wi[1] + nl[2] * -wi[2] > 0.0);
        let c = cos_l.abs();
        let pdf_area = x.inv_area[j] * dist * dist / c;
        let pdf_light = if (c > 0.0) & (pdf_area.abs() < f32::INFINITY) {
            pdf_area
        } else {
            0.0
        };
        let li_nonzero = faces & ((x.le[0][j] != 0.0) | (x.le[1][j] != 0.0) | (x.le[2][j] != 0.0));
        let has_sample = (dist > 0.0)
            & (dist < f32::INFINITY)
            & ((nl[0] != 0.0) | (nl[1] != 0.0) | (nl[2] != 0.0))
            & (pdf_light > 0.0)
            & li_nonzero;
        let wil = local(wi);
        let same = wo[2] * wil[2] > 0.0;
        let f = if same { f_rho } else { [0.0; 3] };
        let f_nonzero = (f[0] != 0.0) | (f[1] != 0.0) | (f[2] != 0.0);
        o.shadow[j] = o.valid[j] & has_sample & f_nonzero;
        let pdf = pdf_light * x.p_choose[j];
        let bsdf_pdf = if same {
            wil[2].abs().max(0.0) * FRAC_1_PI
        } else {
            0.0
        };
        let r = bsdf_pdf / pdf;
        // The power heuristic: 1 for an infinite pdf, 0 for NaN or ≤ 0.
        let heuristic = 1.0 / (1.0 + r * r);
        let weight = if pdf == f32::INFINITY {
            1.0
        } else if pdf > 0.0 {
            heuristic
        } else {
            0.0
        };
        let cos_i = wil[2].abs();
        for a in 0..3 {
            o.wi_light[a][j] = wi[a];
            o.contribution[a][j] = beta[a] * f[a] * x.le[a][j] * cos_i * (weight / pdf);
        }
        o.dist[j] = dist;

        // The next direction: cosine-weighted (concentric disk, lifted).
        let ox = 2.0 * x.u[4][j] - 1.0;
        let oy = 2.0 * x.u[5][j] - 1.0;
        let wide = ox.abs() > oy.abs();
        let (r_disk, ratio) = if wide { (ox, oy / ox) } else { (oy, ox / oy) };
        let (cphi, sphi) = sin_cos_quarter(0.25 * PI * ratio);
        // θ = φ (wide) or π/2 − φ: cos θ and sin θ swap.
        let (cos_t, sin_t) = if wide { (cphi, sphi) } else { (sphi, cphi) };
        let zero = (ox == 0.0) & (oy == 0.0);
        let dx = if zero { 0.0 } else { r_disk * cos_t };
        let dy = if zero { 0.0 } else { r_disk * sin_t };
        let z = (1.0 - (dx * dx + dy * dy)).max(0.0).sqrt();
        let z = if wo[2] < 0.0 { -z } else { z };
        let step_pdf = if wo[2] * z > 0.0 {
            z.abs().max(0.0) * FRAC_1_PI
        } else {
            0.0
        };
        let rho_ok = ((x.rho[0][j] != 0.0) | (x.rho[1][j] != 0.0) | (x.rho[2][j] != 0.0))
            & (x.rho[0][j].abs() < f32::INFINITY)
            & (x.rho[1][j].abs() < f32::INFINITY)
            & (x.rho[2][j].abs() < f32::INFINITY);
        o.step[j] = o.valid[j] & (step_pdf > 0.0) & rho_ok;
        o.pdf[j] = step_pdf;
        for a in 0..3 {
            o.dir[a][j] = s[a] * dx + t[a] * dy + n[a] * z;
        }
        // Throughput and Russian roulette.
        let nb = [
            beta[0] * x.rho[0][j],
            beta[1] * x.rho[1][j],
            beta[2] * x.rho[2][j],
        ];
        let q = nb[0].max(nb[1].max(nb[2])).min(1.0);
        let dies = x.roulette & (x.u[6][j] >= q);
        o.survives[j] = !dies;
        for a in 0..3 {
            o.beta[a][j] = if x.roulette { nb[a] / q } else { nb[a] };
        }
    }
    o
}

/// Writes lane `j`'s results back: its shadow ray, and the path going on
/// (`false` where it ends).
#[allow(clippy::too_many_arguments)]
fn finish(
    world: &World,
    lane: &mut Lane,
    it: &Interaction,
    k: u32,
    o: &Out8,
    j: usize,
    stats: &mut PathStats,
    shadows: &mut Vec<Shadow>,
) -> bool {
    if !o.valid[j] {
        return false;
    }
    let v3 = |a: &[[f32; L]; 3]| Vec3::new(a[0][j], a[1][j], a[2][j]);
    if o.shadow[j] {
        stats.rays += 1;
        shadows.push(Shadow {
            p: it.p,
            n: it.n,
            wi: v3(&o.wi_light),
            dist: o.dist[j],
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
    match world.spawn(it.p, it.n, v3(&o.dir)) {
        Some(ray) => {
            lane.ray = ray;
            true
        }
        None => false,
    }
}
