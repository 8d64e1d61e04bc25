//! Ray casting a whole image: for every pixel (and every sample in it) a
//! primary ray leaves chapter 1's camera, and the closest triangle along it
//! is found, through the BVH or by the naive loop over every triangle.
//! Pixels are independent, so rows are traced in parallel with rayon; every
//! sample position comes from (seed, pixel, sample), so the image is the
//! same bytes on any number of threads.

use glam::{Vec2, Vec3};
use rayon::prelude::*;

use super::geometry::{shade, Geometry};
use super::obvhs_bvh::closest_naive;
use super::ray::Ray;
use super::triangle::{Hit, Intersector};
use crate::ch1_projection::camera::Camera;
use crate::core::film::Film;
use crate::core::sampling::{SampleNumbers, Sampler};

/// Where sample `sample` of pixel (x, y) lies in raster coordinates: the
/// pixel's centre with one sample per pixel, else a uniform random point.
pub fn sample_position(x: u32, y: u32, width: u32, spp: u32, seed: u64, sample: u32) -> Vec2 {
    let base = Vec2::new(x as f32, y as f32);
    if spp <= 1 {
        return base + 0.5;
    }
    let pixel = y as u64 * width as u64 + x as u64;
    jittered((x, y), &mut Sampler::new(seed, pixel, sample as u64))
}

/// Where in pixel (`x`, `y`) a sample lies: the pixel's corner moved by
/// the sample's next two numbers.
fn jittered((x, y): (u32, u32), sampler: &mut impl SampleNumbers) -> Vec2 {
    Vec2::new(x as f32, y as f32) + sampler.next2()
}

/// The sampler and the camera ray of one sample of pixel (`x`, `y`): the
/// sampler of that pixel (`sampler_of_pixel` is given the pixel's index,
/// row by row), whose first two numbers place the ray inside the pixel;
/// whoever traces the sample further goes on with the rest. The one
/// camera-sample prologue of chapters 5 and 6 (chapter 3's
/// [`sample_position`] jitters the same way).
pub fn camera_sample<S: SampleNumbers>(
    camera: &Camera,
    (x, y): (u32, u32),
    sampler_of_pixel: impl FnOnce(u64) -> S,
) -> (S, Ray) {
    let mut sampler = sampler_of_pixel(y as u64 * camera.width as u64 + x as u64);
    let raster = jittered((x, y), &mut sampler);
    (sampler, camera.ray(raster))
}

/// Counts from tracing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraceStats {
    /// Primary rays traced.
    pub rays: u64,
    /// Rays that hit a triangle.
    pub hits: u64,
}

/// Sums the four views over samples `samples` of every pixel in rows
/// `rows` (all of them: `0..camera.height`), tracing rows in parallel:
/// `trace` returns the first hit along a ray.
// ANCHOR: render_rows
pub fn render_sum(
    camera: &Camera,
    geometry: &Geometry,
    rows: std::ops::Range<u32>,
    samples: std::ops::Range<u32>,
    spp: u32,
    seed: u64,
    trace: &(dyn Fn(&Ray) -> Option<Hit> + Sync),
) -> (Vec<[Vec3; 4]>, TraceStats) {
    let w = camera.width;
    let mut sums = vec![[Vec3::ZERO; 4]; w as usize * rows.len()];
    let hits: u64 = sums
        .par_chunks_mut(w as usize)
        .zip(rows.clone())
        .map(|(row, y)| {
            let mut hits = 0;
            for (x, px) in row.iter_mut().enumerate() {
                for s in samples.clone() {
                    let raster = sample_position(x as u32, y, w, spp, seed, s);
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
    let rays = w as u64 * rows.len() as u64 * samples.len() as u64;
    (sums, TraceStats { rays, hits })
}
// ANCHOR_END: render_rows

/// Turns summed views into films by dividing by the sample count: films
/// of the camera's width and as many rows as `sums` holds.
pub fn films_from_sums(camera: &Camera, sums: &[[Vec3; 4]], samples: u32) -> Vec<Film> {
    let rows = sums.len() / camera.width.max(1) as usize;
    (0..4)
        .map(|v| {
            let mut f = Film::new(camera.width, rows as u32);
            for (p, s) in f.pixels.iter_mut().zip(sums) {
                *p = s[v] / samples.max(1) as f32;
            }
            f
        })
        .collect()
}

/// Renders all four views with `spp` samples through the BVH.
pub fn render_views(camera: &Camera, geometry: &Geometry, spp: u32, seed: u64) -> Vec<Film> {
    views_traced(camera, geometry, spp, seed, &|r| geometry.closest(r))
}

/// Renders the views with the naive loop over every triangle instead.
pub fn render_views_naive(camera: &Camera, geometry: &Geometry, spp: u32, seed: u64) -> Vec<Film> {
    let tris = &geometry.triangles.tris;
    views_traced(camera, geometry, spp, seed, &|r| {
        closest_naive(tris, r, f32::INFINITY, Intersector::Watertight)
    })
}

/// The four views of the whole image with `spp` samples, each ray's first
/// hit found by `trace`.
fn views_traced(
    camera: &Camera,
    geometry: &Geometry,
    spp: u32,
    seed: u64,
    trace: &(dyn Fn(&Ray) -> Option<Hit> + Sync),
) -> Vec<Film> {
    let (sums, _) = render_sum(camera, geometry, 0..camera.height, 0..spp, spp, seed, trace);
    films_from_sums(camera, &sums, spp)
}

/// What one primary ray found: the ray of sample `sample` of pixel
/// (`x`, `y`), placed as [`render_sum`] places it, and its first hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelHit {
    /// The primary ray.
    pub ray: Ray,
    /// Its closest hit (triangle, t, barycentrics), or a miss.
    pub hit: Option<Hit>,
    /// The scene mesh of the triangle hit.
    pub mesh: Option<usize>,
}

/// The primary ray of sample `sample` of pixel (`x`, `y`) in a render of
/// `spp` samples per pixel, traced through the BVH as the render does.
pub fn pixel_hit(
    camera: &Camera,
    geometry: &Geometry,
    (x, y): (u32, u32),
    spp: u32,
    seed: u64,
    sample: u32,
) -> PixelHit {
    let raster = sample_position(x, y, camera.width, spp, seed, sample);
    let ray = camera.ray(raster);
    let hit = geometry.closest(&ray);
    let mesh = hit.map(|h| geometry.triangles.mesh[h.triangle as usize] as usize);
    PixelHit { ray, hit, mesh }
}
