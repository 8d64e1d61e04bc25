//! Chapter 3 stage: ray tracing the first hit.
//!
//! For every pixel (and every sample in it) a primary ray leaves chapter
//! 1's camera, and the closest triangle along it is found, through the BVH
//! when the scene has meshes. The stage shows four views of that first hit:
//! its depth, the triangle's normal, the barycentric coordinates and the
//! triangle's id. Pixels are independent, so rows are traced in parallel
//! with rayon; every sample position comes from (seed, pixel, sample), so
//! the image is the same bytes on any number of threads.

use std::sync::Arc;
use std::time::Instant;

use glam::{Vec2, Vec3};
use rayon::prelude::*;

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::bvh::{closest_naive, Bvh, Triangles};
use crate::ch3_ray_triangle::triangle::{Hit, Intersector};
use crate::core::error::Result;
use crate::core::film::Film;
use crate::core::report::{format_number, format_seconds, Report};
use crate::core::sampling::{mix64, Sampler};
use crate::core::stage::{Chapter, Render, Settings, View};
use crate::scene::Scene;

/// The four views of chapter 3.
pub const VIEWS: &[View] = &[
    View {
        name: "depth",
        about: "distance to the first hit: near is bright, misses are black",
    },
    View {
        name: "normal",
        about: "the hit triangle's unit normal n, shown as (n + 1) / 2",
    },
    View {
        name: "barycentrics",
        about: "the hit's barycentric weights (1 - u - v, u, v) as red, green, blue",
    },
    View {
        name: "id",
        about: "one colour per triangle",
    },
];

/// What the stage traces against: the scene's triangles and, when there
/// are any, a BVH over them.
pub struct Geometry {
    /// Every triangle of the scene.
    pub triangles: Triangles,
    /// The BVH, or `None` when the scene has no triangles.
    pub bvh: Option<Bvh>,
    /// The range of distances from the eye to the scene's vertices, for
    /// shading depth.
    pub depth_range: (f32, f32),
}

impl Geometry {
    /// Flattens the scene's meshes and builds a BVH if there is anything to
    /// build it over.
    pub fn new(scene: &Scene) -> Geometry {
        let triangles = Triangles::from_meshes(&scene.meshes);
        let bvh = Bvh::build(&triangles.tris);
        let eye = scene.camera.desc.eye.as_vec3();
        let (mut near, mut far) = (f32::INFINITY, 0.0f32);
        for p in triangles.tris.iter().flatten() {
            let d = p.distance(eye);
            near = near.min(d);
            far = far.max(d);
        }
        Geometry {
            triangles,
            bvh,
            depth_range: (near.min(far), far),
        }
    }

    /// The closest hit along `ray`, through the BVH (or nothing at all
    /// when there is no geometry).
    pub fn closest(&self, ray: &crate::ch3_ray_triangle::ray::Ray) -> Option<Hit> {
        self.bvh
            .as_ref()
            .and_then(|b| b.closest(ray, f32::INFINITY, Intersector::Watertight))
    }
}

/// The colour of triangle `id` in the id view: a hash, so neighbours differ.
pub fn id_color(id: u32) -> Vec3 {
    let h = mix64(id as u64 + 1);
    let c = |s: u32| 0.2 + 0.8 * ((h >> s) & 0xff) as f32 / 255.0;
    Vec3::new(c(0), c(8), c(16))
}

/// The four view values of one first hit (or of a miss).
// ANCHOR: shade_views
pub fn shade(geometry: &Geometry, hit: Option<Hit>) -> [Vec3; 4] {
    let Some(hit) = hit else {
        return [Vec3::ZERO; 4];
    };
    let [p0, p1, p2] = geometry.triangles.tris[hit.triangle as usize];
    let n = (p1 - p0).cross(p2 - p0).normalize_or_zero();
    let (near, far) = geometry.depth_range;
    // Depth shaded by 1/t (as in chapter 1): 1 at the nearest vertex,
    // 0.15 at the farthest.
    let s = ((1.0 / hit.t - 1.0 / far) / (1.0 / near - 1.0 / far)).clamp(0.0, 1.0);
    let s = if s.is_finite() { s } else { 1.0 };
    [
        Vec3::splat(0.15 + 0.85 * s),
        (n + 1.0) * 0.5,
        hit.barycentrics(),
        id_color(hit.triangle),
    ]
}
// ANCHOR_END: shade_views

/// Where sample `sample` of pixel (x, y) lies in raster coordinates: the
/// pixel's centre with one sample per pixel, else a uniform random point.
pub fn sample_position(x: u32, y: u32, width: u32, spp: u32, seed: u64, sample: u32) -> Vec2 {
    let base = Vec2::new(x as f32, y as f32);
    if spp <= 1 {
        return base + 0.5;
    }
    let pixel = y as u64 * width as u64 + x as u64;
    base + Sampler::new(seed, pixel, sample as u64).next2()
}

/// Counts from tracing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraceStats {
    /// Primary rays traced.
    pub rays: u64,
    /// Rays that hit a triangle.
    pub hits: u64,
}

/// Sums the four views over samples `samples` of every pixel, tracing rows
/// in parallel: `trace` returns the first hit along a ray.
// ANCHOR: render_rows
pub fn render_sum(
    camera: &Camera,
    geometry: &Geometry,
    samples: std::ops::Range<u32>,
    spp: u32,
    seed: u64,
    trace: &(dyn Fn(&crate::ch3_ray_triangle::ray::Ray) -> Option<Hit> + Sync),
) -> (Vec<[Vec3; 4]>, TraceStats) {
    let (w, h) = (camera.width, camera.height);
    let mut sums = vec![[Vec3::ZERO; 4]; w as usize * h as usize];
    let hits: u64 = sums
        .par_chunks_mut(w as usize)
        .enumerate()
        .map(|(y, row)| {
            let mut hits = 0;
            for (x, px) in row.iter_mut().enumerate() {
                for s in samples.clone() {
                    let raster = sample_position(x as u32, y as u32, w, spp, seed, s);
                    let hit = trace(&camera.ray(raster));
                    hits += u64::from(hit.is_some());
                    for (acc, v) in px.iter_mut().zip(shade(geometry, hit)) {
                        *acc += v;
                    }
                }
            }
            hits
        })
        .sum();
    let rays = w as u64 * h as u64 * samples.len() as u64;
    (sums, TraceStats { rays, hits })
}
// ANCHOR_END: render_rows

/// Turns summed views into films by dividing by the sample count.
pub fn films_from_sums(camera: &Camera, sums: &[[Vec3; 4]], samples: u32) -> Vec<Film> {
    (0..4)
        .map(|v| {
            let mut f = Film::new(camera.width, camera.height);
            for (p, s) in f.pixels.iter_mut().zip(sums) {
                *p = s[v] / samples.max(1) as f32;
            }
            f
        })
        .collect()
}

/// Renders all four views with `spp` samples through the BVH.
pub fn render_views(camera: &Camera, geometry: &Geometry, spp: u32, seed: u64) -> Vec<Film> {
    let (sums, _) = render_sum(camera, geometry, 0..spp, spp, seed, &|r| {
        geometry.closest(r)
    });
    films_from_sums(camera, &sums, spp)
}

/// Renders the views with the naive loop over every triangle instead.
pub fn render_views_naive(camera: &Camera, geometry: &Geometry, spp: u32, seed: u64) -> Vec<Film> {
    let tris = &geometry.triangles.tris;
    let (sums, _) = render_sum(camera, geometry, 0..spp, spp, seed, &|r| {
        closest_naive(tris, r, f32::INFINITY, Intersector::Watertight)
    });
    films_from_sums(camera, &sums, spp)
}

/// Chapter 3 as a stage.
pub struct RayTriangle;

impl Chapter for RayTriangle {
    fn number(&self) -> u32 {
        3
    }
    fn slug(&self) -> &'static str {
        "ray-triangle"
    }
    fn title(&self) -> &'static str {
        "Ray-triangle intersection and a BVH"
    }
    fn views(&self) -> &'static [View] {
        VIEWS
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        let geometry = Geometry::new(&scene);
        let n = scene.camera.width as usize * scene.camera.height as usize;
        Ok(Box::new(RayTriangleRender {
            scene,
            settings: settings.clone(),
            geometry,
            sums: vec![[Vec3::ZERO; 4]; n],
            done: 0,
            stats: TraceStats::default(),
            seconds: 0.0,
        }))
    }
}

struct RayTriangleRender {
    scene: Arc<Scene>,
    settings: Settings,
    geometry: Geometry,
    sums: Vec<[Vec3; 4]>,
    done: u32,
    stats: TraceStats,
    seconds: f64,
}

impl RayTriangleRender {
    fn planned(&self) -> u32 {
        self.settings.spp.max(1)
    }
}

impl Render for RayTriangleRender {
    /// One pass traces one sample of every pixel.
    fn pass(&mut self) -> bool {
        if self.done < self.planned() {
            let start = Instant::now();
            let g = &self.geometry;
            let (sums, stats) = render_sum(
                &self.scene.camera,
                g,
                self.done..self.done + 1,
                self.planned(),
                self.settings.seed,
                &|r| g.closest(r),
            );
            for (acc, s) in self.sums.iter_mut().zip(sums) {
                for (a, v) in acc.iter_mut().zip(s) {
                    *a += v;
                }
            }
            self.stats.rays += stats.rays;
            self.stats.hits += stats.hits;
            self.seconds += start.elapsed().as_secs_f64();
            self.done += 1;
        }
        self.done >= self.planned()
    }

    fn progress(&self) -> (u32, u32) {
        (self.done, self.planned())
    }

    /// Primary rays: pixels × samples done.
    fn rays(&self) -> u64 {
        self.stats.rays
    }

    fn view(&self, index: usize) -> Film {
        let films = films_from_sums(&self.scene.camera, &self.sums, self.done);
        let mut film = films
            .into_iter()
            .nth(index)
            .unwrap_or_else(|| Film::new(self.scene.camera.width, self.scene.camera.height));
        film.scrub_nonfinite();
        film
    }

    fn report(&self) -> Report {
        let nonfinite = films_from_sums(&self.scene.camera, &self.sums, self.done)
            .iter_mut()
            .map(Film::scrub_nonfinite)
            .sum();
        let mut report = chapter_report(
            &self.scene,
            &self.geometry,
            self.stats,
            self.seconds,
            self.done,
        );
        report.nonfinite_caught = nonfinite;
        if self.settings.studies {
            crate::ch3_ray_triangle::studies::add_studies(&mut report, &self.scene, &self.settings);
        }
        report
    }
}

/// The report without the studies: facts, and what was built or left out.
pub fn chapter_report(
    scene: &Scene,
    geometry: &Geometry,
    stats: TraceStats,
    seconds: f64,
    spp: u32,
) -> Report {
    let cam = &scene.camera;
    let mut report = Report {
        title: format!("ch3 ray-triangle: {}", scene.name),
        facts: vec![
            ("scene".into(), scene.source.clone()),
            (
                "image".into(),
                format!(
                    "{}x{} pixels, {spp} samples per pixel",
                    cam.width, cam.height
                ),
            ),
            (
                "triangles".into(),
                format!(
                    "{} in {} meshes",
                    geometry.triangles.tris.len(),
                    scene.meshes.len()
                ),
            ),
            (
                "primary rays".into(),
                format!(
                    "{} traced, {} hit ({}%)",
                    stats.rays,
                    stats.hits,
                    format_number(100.0 * stats.hits as f64 / stats.rays.max(1) as f64)
                ),
            ),
            (
                "render time".into(),
                format!(
                    "{} ({} Mrays/s)",
                    format_seconds(seconds),
                    format_number(stats.rays as f64 / seconds.max(1e-9) / 1e6)
                ),
            ),
        ],
        ..Report::default()
    };
    report
        .built
        .push("primary rays from the look-at camera".into());
    match &geometry.bvh {
        Some(b) => report.built.push(format!(
            "BVH (obvhs Bvh2) over {} triangles: {} nodes, built in {}",
            b.triangle_count(),
            b.node_count(),
            format_seconds(b.build_seconds)
        )),
        None => report
            .left_out
            .push("BVH: the scene has no triangles, so every ray misses".into()),
    }
    report
        .built
        .push("watertight ray-triangle test (Woop, Benthin, Wald)".into());
    report
        .left_out
        .push("shading: materials and lights are ignored; the views show the first hit".into());
    if !scene.lights.is_empty() {
        report.left_out.push(format!(
            "{} lights: visibility needs none",
            scene.lights.len()
        ));
    }
    report
        .left_out
        .push("secondary rays: only the studies spawn them".into());
    report
}
