//! `ch6 --bench`: a scene (the Cornell box unless `--scene` names one)
//! at 256x256 (or `--width`/`--height`), 64 spp, up to 16 bounces, MIS
//! (or the estimator, bounce limit and roulette flags given), on the
//! current thread pool, with both engines; seconds, paths/s, rays per path
//! and RMSE against the stored references, for both samplers.
//!
//! Two RMSEs are printed. The first is per pixel, against the stored
//! reference of the scene at the render's size (16,384 spp, so its own
//! noise adds well under 1% to the figure). The second is against the
//! 64x64 reference the tests use, after box-downsampling the render to
//! 64x64 (each reference pixel against the mean of the 4 x 4 render pixels
//! it covers, which has the same expectation); averaging 16 pixels divides
//! the noise variance by 16, so it is about a quarter of the first. A scene
//! without a stored reference gets the command that makes one. The last
//! column is the per-pixel noise the render's own sample variance predicts,
//! √(mean s²/n): with independent numbers it should match the per-pixel
//! RMSE (no bias); with Sobol the true error is lower than this estimate.

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
use crate::core::table::{wrap, COLUMNS};
use crate::scene::Scene;

use super::bvh8::Bvh8;
use crate::ch5_reflection::world::RayQueries;
use crate::ch6_global_illumination::accumulate::downsample;
use crate::ch6_global_illumination::engine::{EngineChoice, PathEngine};
use crate::ch6_global_illumination::integrator::PathSettings;
use crate::ch6_global_illumination::reference::{reference_dir, scene_flag, StoredReference};
use crate::ch6_global_illumination::sampler::SamplerKind;
use crate::ch6_global_illumination::studies::render_with;

/// The benchmark's size when the command line names none.
pub const SIZE: (u32, u32) = (256, 256);

/// Runs the benchmark on `scene` at its own size and returns its table,
/// then what the fast engine's loop was and, where `scene` has no stored
/// reference at that size, how to make one.
pub fn bench(spp: u32, path: &PathSettings, scene: &Scene) -> crate::core::error::Result<String> {
    let (width, height) = (scene.camera.width, scene.camera.height);
    let per_pixel = StoredReference::for_scene_at(scene, width, height);
    let small = StoredReference::for_scene(scene);
    let threads = rayon::current_num_threads();
    let mut t = Table::new(
        &format!(
            "ch6 benchmark: {} {width}x{height}, {spp} spp, {}, {}, roulette {}, \
             {threads} threads (targets on the Cornell box: > 3.5M paths/s; RMSE²·s < 3e-4)",
            scene.name,
            path.max_bounces
                .map_or("unlimited bounces".into(), |k| format!("up to {k} bounces")),
            path.strategy.name(),
            path.roulette_text(None),
        ),
        &[
            "engine sampler",
            "seconds",
            "paths/s",
            "rays/path",
            "RMSE per pixel",
            "RMSE²·s",
            "RMSE 64²",
            "RMSE²·s",
            "noise from variance",
        ],
    );
    let runs = [super::FAST, EngineChoice::READABLE]
        .into_iter()
        .flat_map(|e| [(e, SamplerKind::Independent), (e, SamplerKind::Sobol)]);
    for (engine, sampler) in runs {
        let (acc, secs) = render_with(engine, scene, path, sampler, (spp, 1), false);
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
                // "-" where there is no reference (a note under the table
                // says why): a wider cell would break the table into blocks.
                rmse.map_or("-".into(), format_number),
                rmse.map_or("-".into(), |e| format_number(e * e * secs)),
            )
        };
        let (full, full_eff) = e(full);
        let (down, down_eff) = e(down);
        t.row(vec![
            format!("{} {}", engine.name, sampler.name()),
            format!("{secs:.3}"),
            format_number(acc.stats.paths as f64 / secs),
            format!(
                "{:.2}",
                acc.stats.rays as f64 / acc.stats.paths.max(1) as f64
            ),
            full,
            full_eff,
            down,
            down_eff,
            format_number(noise),
        ]);
    }
    let mut text = t.to_text();
    let (used, left_out) = super::FastEngine::new(scene).notes(path);
    let notes = [("uses", used), ("leaves out", left_out)];
    for (what, note) in notes
        .iter()
        .flat_map(|(w, n)| n.iter().map(move |n| (w, n)))
    {
        let line = format!("The fast engine on {} {what} {note}.", scene.name);
        text.push_str(&wrap(&line, "", "  ", COLUMNS));
    }
    if small.is_none() {
        let line = format!(
            "No RMSE 64²: no 64x64 reference of {} is stored.",
            scene.name
        );
        text.push_str(&wrap(&line, "", "  ", COLUMNS));
    }
    if per_pixel.is_none() {
        let why = StoredReference::why_none(scene).unwrap_or_else(|| {
            format!(
                "{} holds none of {} at {width}x{height}",
                reference_dir().display(),
                scene.name
            )
        });
        let file = scene_flag(scene);
        let line = format!(
            "No RMSE per pixel: {why}. Make the reference once (16,384 spp: about 13 minutes for \
             the Cornell box on 2 cores) with"
        );
        text.push_str(&wrap(&line, "", "  ", COLUMNS));
        text.push_str(&format!(
            "  cargo run --release --bin ch6 -- --make-reference{file} --width {width} \
             --height {height} --spp 16384 --seed 1 --estimator mis --sampler independent\n",
        ));
    }
    Ok(text)
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
/// the readable engine's four-wide tree and the fast engine's eight-wide
/// one, on rays from the path tracer's own vertices in `scene` (bounce
/// rays: closest hit; shadow rays: occlusion).
pub fn query_bench(scene: &Scene) -> Table {
    let world = World::new(scene);
    let (bounce, shadow) = vertex_rays(&world, scene);
    let mut t = Table::new(
        &format!(
            "ray queries on {}, one thread, million queries per second (best of 5)",
            scene.name
        ),
        &[
            "query",
            "rays",
            "binary BVH (ch3)",
            "4-wide (readable)",
            "8-wide (fast)",
        ],
    );
    let tris = &world.triangles.tris;
    let (Some(bvh), Some(wide), Some(eight)) = (
        Bvh::build(tris),
        &world.wide,
        Bvh8::build(tris, super::simd::best()),
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

/// The Cornell box with a bumpy sphere of `rings` × `segments` × 2
/// triangles standing in it (white, radius about 0.35): the large mesh of
/// the per-scene benchmark.
pub fn cornell_with_large_mesh(rings: u32, segments: u32) -> Scene {
    let mut scene = Scene::builtin();
    let (r, s) = (rings.max(2), segments.max(3));
    let mut positions = Vec::with_capacity(((r + 1) * s) as usize);
    for i in 0..=r {
        let theta = std::f32::consts::PI * i as f32 / r as f32;
        for j in 0..s {
            let phi = std::f32::consts::TAU * j as f32 / s as f32;
            let radius = 0.35 * (1.0 + 0.05 * (7.0 * theta).sin() * (9.0 * phi).cos());
            let d = glam::Vec3::new(
                theta.sin() * phi.cos(),
                theta.cos(),
                theta.sin() * phi.sin(),
            );
            positions.push(glam::Vec3::new(-0.2, -0.6, 0.1) + radius * d);
        }
    }
    let mut triangles = Vec::with_capacity((2 * r * s) as usize);
    for i in 0..r {
        for j in 0..s {
            let (a, b) = (i * s + j, i * s + (j + 1) % s);
            let (c, d) = (a + s, b + s);
            triangles.push([a, c, b]);
            triangles.push([b, c, d]);
        }
    }
    let material = scene.meshes[0].material;
    scene.meshes.push(crate::scene::mesh::Mesh {
        name: "bumpy sphere".into(),
        positions,
        triangles,
        colors: None,
        material,
    });
    scene.name = "cornell-large-mesh".into();
    scene
}

/// `ch6 --bench-scenes`: paths per second of both engines on the Cornell
/// box (36 triangles), the bunny (3,674) and the Cornell box with a bumpy
/// sphere of 524,288 triangles, at 128x128 and `spp` samples per pixel,
/// on the current thread pool; the world's build time apart, and the
/// ratio of the engines' paths per second.
pub fn scenes_bench(spp: u32, path: &PathSettings) -> crate::core::error::Result<Table> {
    let root = crate::core::project_root();
    let scenes = [
        Scene::builtin(),
        Scene::load(&root.join("scenes/bunny.toml"))?,
        cornell_with_large_mesh(512, 512),
    ];
    let mut t = Table::new(
        &format!(
            "paths per second by scene and engine: 128x128, {spp} spp, {}, {} threads",
            path.strategy.name(),
            rayon::current_num_threads()
        ),
        &[
            "scene",
            "triangles",
            "build (fast / readable)",
            "paths/s fast",
            "readable",
            "ratio",
        ],
    );
    for scene in scenes {
        let scene = scene.with_resolution(128, 128)?;
        let camera = Camera::of(&scene);
        let mut rate = [0.0; 2];
        let mut build = [String::new(), String::new()];
        for (i, engine) in [super::FAST, EngineChoice::READABLE]
            .into_iter()
            .enumerate()
        {
            let t0 = Instant::now();
            let engine = engine.make(&scene);
            build[i] = crate::core::format::format_seconds(t0.elapsed().as_secs_f64());
            let mut acc =
                crate::ch6_global_illumination::accumulate::Accumulator::new(128, 128, false);
            let t1 = Instant::now();
            acc.add_samples(&*engine, &camera, path, SamplerKind::Sobol, 1, spp);
            rate[i] = acc.stats.paths as f64 / t1.elapsed().as_secs_f64();
        }
        t.row(vec![
            scene.name.clone(),
            scene.triangle_count().to_string(),
            format!("{} / {}", build[0], build[1]),
            format_number(rate[0]),
            format_number(rate[1]),
            format!("{:.2}", rate[0] / rate[1]),
        ]);
    }
    Ok(t)
}
