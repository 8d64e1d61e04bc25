//! `ch6 --bench`: the Cornell box at 256x256, 64 spp, up to 16 bounces,
//! MIS (or the estimator, bounce limit and roulette flags given), on the
//! current thread pool; seconds, paths/s, rays/s and RMSE
//! against the stored references, for both samplers.
//!
//! Two RMSEs are printed. The first is per pixel, against the stored
//! 256x256 reference (16,384 spp, so its own noise adds well under 1% to
//! the figure). The second is against the 64x64 reference the tests use,
//! after box-downsampling the render to 64x64 (each reference pixel
//! against the mean of the 4 x 4 render pixels it covers, which has the
//! same expectation); averaging 16 pixels divides the noise variance by
//! 16, so it is about a quarter of the first. The last column is the
//! per-pixel noise the render's own sample variance predicts, √(mean s²/n):
//! with independent numbers it should match the per-pixel RMSE (no bias);
//! with Sobol the true error is lower than this estimate.

use std::time::Instant;

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::obvhs_bvh::Bvh;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::render::camera_sample;
use crate::ch3_ray_triangle::triangle::Intersector;
use crate::ch5_reflection::material::Frame;
use crate::ch5_reflection::warp::cosine_hemisphere;
use crate::ch5_reflection::world::World;
use crate::core::format::format_number;
use crate::core::report::Table;
use crate::core::sampling::Sampler;
use crate::scene::Scene;

use super::accumulate::downsample;
use super::fast::bvh8::Bvh8;
use super::fast::level::Level;
use super::fast::Engine;
use super::integrator::PathSettings;
use super::reference::StoredReference;
use super::sampler::SamplerKind;
use super::studies::render_with;
use crate::ch5_reflection::world::RayQueries;

/// Runs the benchmark and returns its table.
pub fn bench(spp: u32, path: &PathSettings) -> crate::core::error::Result<Table> {
    let scene = Scene::builtin().with_resolution(256, 256)?;
    let per_pixel = StoredReference::for_scene_at(&scene, 256, 256);
    let small = StoredReference::for_scene(&scene);
    let threads = rayon::current_num_threads();
    let mut t = Table::new(
        &format!(
            "ch6 benchmark: Cornell box 256x256, {spp} spp, {}, {}, roulette after {} scatterings, \
             {threads} threads (targets: > 3.5M paths/s; RMSE²·s < 3e-4)",
            path.max_bounces
                .map_or("unlimited bounces".into(), |k| format!("up to {k} bounces")),
            path.strategy.name(),
            path.rr_min_bounce,
        ),
        &[
            "engine",
            "sampler",
            "seconds",
            "paths/s",
            "rays/s",
            "RMSE per pixel",
            "RMSE²·s",
            "RMSE at 64x64",
            "RMSE²·s",
            "noise from variance",
        ],
    );
    let runs = [Engine::Fast, Engine::Readable]
        .into_iter()
        .flat_map(|e| [(e, SamplerKind::Independent), (e, SamplerKind::Sobol)]);
    for (engine, sampler) in runs {
        let (acc, secs) = render_with(engine, &scene, path, sampler, (spp, 1), false);
        let var = acc.variance_of_mean();
        let noise = (var
            .pixels
            .iter()
            .map(|p| p.as_dvec3().element_sum())
            .sum::<f64>()
            / (3.0 * var.pixels.len() as f64))
            .sqrt();
        let mean = acc.mean();
        let full = per_pixel.as_ref().map(|r| mean.rmse(&r.mean));
        let down = small.as_ref().map(|r| {
            let f = acc.width / r.mean.width;
            downsample(&mean, f).rmse(&r.mean)
        });
        let e = |rmse: Option<f64>| -> (String, String) {
            (
                rmse.map_or("no reference".into(), format_number),
                rmse.map_or("-".into(), |e| format_number(e * e * secs)),
            )
        };
        let (full, full_eff) = e(full);
        let (down, down_eff) = e(down);
        t.row(vec![
            engine.name().into(),
            sampler.name().into(),
            format!("{secs:.3}"),
            format_number(acc.stats.paths as f64 / secs),
            format_number(acc.stats.rays as f64 / secs),
            full,
            full_eff,
            down,
            down_eff,
            format_number(noise),
        ]);
    }
    Ok(t)
}

/// Rays like the path tracer's, from one path vertex per pixel of
/// `scene`: (bounce rays, shadow rays with their t_max).
fn vertex_rays(world: &World, scene: &Scene) -> (Vec<Ray>, Vec<(Ray, f32)>) {
    let camera = Camera::of(scene);
    let (w, h) = (camera.width, camera.height);
    let (mut bounce, mut shadow) = (Vec::new(), Vec::new());
    for pixel in 0..(w * h) as u64 {
        let (x, y) = ((pixel % w as u64) as u32, (pixel / w as u64) as u32);
        let (mut u, camera_ray) = camera_sample(&camera, (x, y), |p| Sampler::new(99, p, 0));
        let Some(it) = world.intersect(&camera_ray) else {
            continue;
        };
        let n = if it.n.dot(camera_ray.dir) > 0.0 {
            -it.n
        } else {
            it.n
        };
        let wi = Frame::from_normal(n).to_world(cosine_hemisphere(u.next2()));
        if let Some(r) = world.spawn(it.p, it.n, wi) {
            bounce.push(r);
        }
        if let Some(light) = world.lights.lights.first() {
            if let Some(ls) = light.sample_li(it.p, n, u.next2()) {
                if let Some(r) = world.spawn(it.p, it.n, ls.wi) {
                    shadow.push((r, ls.dist * (1.0 - 1e-4)));
                }
            }
        }
    }
    (bounce, shadow)
}

/// How many of `items` `query` says yes to.
fn count<T>(items: &[T], query: impl Fn(&T) -> bool) -> usize {
    items.iter().filter(|i| query(i)).count()
}

/// Million queries per second of `query` over `n` items, best of 5.
fn mqps(n: usize, query: &dyn Fn() -> usize) -> f64 {
    let mut best = f64::INFINITY;
    let mut check = 0;
    for _ in 0..5 {
        let t = Instant::now();
        check += query();
        best = best.min(t.elapsed().as_secs_f64());
    }
    std::hint::black_box(check);
    n as f64 / best / 1e6
}

/// The ray queries alone, on one thread: chapter 3's binary BVH against
/// the wide BVH the path tracer uses, on rays from the path tracer's own
/// vertices (bounce rays: closest hit; shadow rays: occlusion).
pub fn query_bench() -> Table {
    let scene = Scene::builtin();
    let world = World::new(&scene);
    let (bounce, shadow) = vertex_rays(&world, &scene);
    let mut t = Table::new(
        "ray queries on the Cornell box, one thread, million queries per second (best of 5)",
        &[
            "query",
            "rays",
            "binary BVH (ch3)",
            "4-wide BVH",
            "8-wide BVH (fast)",
        ],
    );
    let tris = &world.triangles.tris;
    let (Some(bvh), Some(wide), Some(eight)) = (
        Bvh::build(tris),
        &world.wide,
        Bvh8::build(tris, Level::detect()),
    ) else {
        return t;
    };
    let x = Intersector::Watertight;
    let rate = |n: usize, count: &dyn Fn() -> usize| format!("{:.2}", mqps(n, count));
    let (nb, ns) = (bounce.len(), shadow.len());
    t.row(vec![
        "closest hit (bounce rays)".into(),
        nb.to_string(),
        rate(nb, &|| {
            count(&bounce, |r| bvh.closest(r, f32::INFINITY, x).is_some())
        }),
        rate(nb, &|| {
            count(&bounce, |r| wide.closest(r, f32::INFINITY).is_some())
        }),
        rate(nb, &|| {
            count(&bounce, |r| eight.closest(r, f32::INFINITY).is_some())
        }),
    ]);
    t.row(vec![
        "occlusion (shadow rays)".into(),
        ns.to_string(),
        rate(ns, &|| count(&shadow, |(r, d)| bvh.occluded(r, *d, x))),
        rate(ns, &|| count(&shadow, |(r, d)| wide.occluded(r, *d))),
        rate(ns, &|| count(&shadow, |(r, d)| eight.occluded(r, *d))),
    ]);
    t
}
