//! Error against run time for chapter 3 (requirement 1): anti-aliasing
//! against a high-sample reference, and the naive loop against the BVH;
//! the speed of the three intersection tests; the procedural meshes the
//! studies use.

use std::time::Instant;

use glam::{DVec3, Vec3};

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::geometry::Geometry;
use crate::ch3_ray_triangle::obvhs_bvh::closest_naive;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::render::{render_views, render_views_naive};
use crate::ch3_ray_triangle::triangle::{intersect_f64, Intersector};
use crate::core::format::{format_number, format_seconds};
use crate::core::report::{ErrorTime, Measurement, Table};
use crate::core::sampling::random;
use crate::scene::camera::CameraDesc;
use crate::scene::mesh::Mesh;
use crate::scene::Scene;

/// How big the studies are: the report runs them in full, tests shrink them.
#[derive(Clone, Debug, PartialEq)]
pub struct StudySize {
    /// Rays aimed at edges and vertices per mesh in the leak test.
    pub leak_rays: u64,
    /// Triangle counts of the naive-vs-BVH comparison.
    pub triangle_counts: Vec<usize>,
    /// Largest rays x triangles the naive loop is allowed (else skipped).
    pub naive_budget: f64,
    /// Samples per pixel of the anti-aliasing series.
    pub spp: Vec<u32>,
    /// Samples per pixel of its reference.
    pub reference_spp: u32,
    /// Secondary rays per distance in the self-intersection test.
    pub spawn_rays: u64,
}

impl StudySize {
    /// The size the report uses.
    pub fn full() -> StudySize {
        StudySize {
            leak_rays: 1_000_000,
            triangle_counts: vec![10, 1_000, 100_000, 1_000_000],
            naive_budget: 5e8,
            spp: vec![1, 2, 4, 8, 16, 32, 64],
            reference_spp: 256,
            spawn_rays: 100_000,
        }
    }

    /// A size quick enough for debug-build tests.
    pub fn quick() -> StudySize {
        StudySize {
            leak_rays: 100_000,
            triangle_counts: vec![10, 1_000],
            naive_budget: 1e7,
            spp: vec![1, 4, 16],
            reference_spp: 64,
            spawn_rays: 10_000,
        }
    }

    /// Every kind of row and cell of the report's tables (a naive loop run
    /// and one skipped, every sample count) at a cost a debug-build test of
    /// the report's layout can afford: the naive loop is skipped above 10^6
    /// ray-triangle tests, the largest mesh has 10^5 triangles (a 7-digit
    /// count is narrower than its column's header) and few rays are shot.
    pub fn layout() -> StudySize {
        StudySize {
            naive_budget: 1e6,
            triangle_counts: vec![10, 1_000, 100_000],
            leak_rays: 10_000,
            spawn_rays: 1_000,
            ..StudySize::full()
        }
    }
}

/// A wavy height field over [-1, 1]² facing +z with exactly `n` triangles
/// (`n` rounded up to even): the procedural mesh of the speed studies.
pub fn procedural_mesh(n: usize) -> Mesh {
    let quads = n.div_ceil(2).max(1);
    // The most square grid rows x cols = quads.
    let rows = (1..=quads)
        .take_while(|r| r * r <= quads)
        .filter(|r| quads.is_multiple_of(*r))
        .last()
        .unwrap_or(1);
    let cols = quads / rows;
    let mut positions = Vec::with_capacity((rows + 1) * (cols + 1));
    for j in 0..=rows {
        for i in 0..=cols {
            let x = i as f32 / cols as f32 * 2.0 - 1.0;
            let y = j as f32 / rows as f32 * 2.0 - 1.0;
            let z = 0.15 * (3.0 * x).sin() * (2.0 * y).cos();
            positions.push(Vec3::new(x, y, z));
        }
    }
    let mut triangles = Vec::with_capacity(quads * 2);
    let at = |i: usize, j: usize| (j * (cols + 1) + i) as u32;
    for j in 0..rows {
        for i in 0..cols {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    Mesh::new("wavy grid", positions, triangles)
}

/// The camera the speed studies look at [`procedural_mesh`] with.
pub fn procedural_camera(width: u32, height: u32) -> CameraDesc {
    CameraDesc {
        eye: DVec3::new(0.0, -1.2, 2.2),
        target: DVec3::ZERO,
        up: DVec3::Y,
        fov_degrees: 50.0,
        width,
        height,
    }
}

/// A scene holding one mesh, seen by `camera`.
pub fn scene_of(mesh: Mesh, camera: CameraDesc) -> Scene {
    let mut scene = Scene::builtin();
    scene.name = mesh.name.clone();
    scene.source = "<procedural>".into();
    scene.camera = camera;
    scene.meshes = vec![mesh];
    scene.lights.clear();
    scene
}

/// Anti-aliasing: the depth view at 1..64 samples per pixel against a
/// high-sample reference of the same image (another seed).
pub fn error_against_time(scene: &Scene, spp: &[u32], reference_spp: u32, seed: u64) -> ErrorTime {
    let geometry = Geometry::new(scene);
    let camera = Camera::of(scene);
    let reference = &render_views(&camera, &geometry, reference_spp, seed ^ 0x5eed)[0];
    let mut et = ErrorTime {
        reference: format!("the depth view at {reference_spp} spp, another seed"),
        error_name: "RMSE".into(),
        rows: Vec::new(),
        show_slopes: true,
    };
    for &n in spp {
        let t0 = Instant::now();
        let films = render_views(&camera, &geometry, n, seed);
        let seconds = t0.elapsed().as_secs_f64();
        et.rows.push(Measurement {
            series: "anti-aliasing (BVH)".into(),
            variant: format!("{n} spp"),
            seconds,
            samples: n as u64 * films[0].pixels.len() as u64,
            error: films[0].rmse(reference),
            notes: String::new(),
        });
    }
    et
}

/// Naive loop against BVH on [`procedural_mesh`]es: time for the same
/// 64x48 depth image, and whether the two images are identical. The naive
/// loop is skipped when rays x triangles exceeds `naive_budget`.
pub fn naive_vs_bvh(counts: &[usize], naive_budget: f64) -> (Table, Vec<Measurement>) {
    let desc = procedural_camera(64, 48);
    let camera = Camera::new(desc).expect("the procedural camera is valid");
    let rays = (camera.width * camera.height) as f64;
    let mut t = Table::new(
        "Naive loop against BVH (64x48 depth image of a wavy grid, 1 spp)",
        &[
            "triangles",
            "naive",
            "BVH build",
            "BVH trace",
            "BVH total",
            "naive ÷ BVH total",
            "same image",
        ],
    );
    let mut rows = Vec::new();
    let mut crossover = None;
    for &n in counts {
        let scene = scene_of(procedural_mesh(n), desc);
        let geometry = Geometry::new(&scene);
        let build = geometry.bvh.as_ref().map_or(0.0, |b| b.build_seconds);
        let t0 = Instant::now();
        let bvh_films = render_views(&camera, &geometry, 1, 0);
        let trace = t0.elapsed().as_secs_f64();
        let tris = geometry.triangles.tris.len();
        let naive = (rays * tris as f64 <= naive_budget).then(|| {
            let t0 = Instant::now();
            let films = render_views_naive(&camera, &geometry, 1, 0);
            (t0.elapsed().as_secs_f64(), films)
        });
        let (naive_cell, speedup, same) = match &naive {
            Some((s, films)) => {
                if crossover.is_none() && build + trace < *s {
                    crossover = Some(tris);
                }
                rows.push(Measurement {
                    series: "naive loop".into(),
                    variant: format!("{tris} triangles"),
                    seconds: *s,
                    samples: rays as u64,
                    error: films[0].rmse(&bvh_films[0]),
                    notes: "error: RMSE against the BVH image".into(),
                });
                (
                    format_seconds(*s),
                    format!("{}x", format_number(s / (build + trace).max(1e-9))),
                    if films == &bvh_films { "yes" } else { "NO" }.to_string(),
                )
            }
            None => (
                format!("skipped (~{} tests)", format_number(rays * tris as f64)),
                "-".into(),
                "-".into(),
            ),
        };
        rows.push(Measurement {
            series: "BVH".into(),
            variant: format!("{tris} triangles"),
            seconds: trace,
            samples: rays as u64,
            error: 0.0,
            notes: format!("build {}", format_seconds(build)),
        });
        t.row(vec![
            tris.to_string(),
            naive_cell,
            format_seconds(build),
            format_seconds(trace),
            format_seconds(build + trace),
            speedup,
            same,
        ]);
    }
    t.title += &match crossover {
        Some(n) => format!("; in this run the BVH, build included, pays off from {n} triangles"),
        None => "; in this run the BVH, build included, did not pay off at these sizes".into(),
    };
    (t, rows)
}

/// Closest hits of the naive loop for a batch of rays (used by tests).
pub fn naive_hits(
    tris: &[[Vec3; 3]],
    rays: &[Ray],
    x: Intersector,
) -> Vec<Option<crate::ch3_ray_triangle::triangle::Hit>> {
    rays.iter()
        .map(|r| closest_naive(tris, r, f32::INFINITY, x))
        .collect()
}

/// The three tests side by side on `n` random ray-triangle pairs (about
/// half of them hits): time per test (best of 3) and how often each agrees
/// with the f64 solution of the 3x3 system on hit or miss.
pub fn intersector_speed(n: u64) -> Table {
    let pairs: Vec<(Ray, [Vec3; 3])> = (0..n)
        .filter_map(|i| {
            let r = |d| random(21, i, 0, d);
            let tri = [
                Vec3::new(r(0), r(1), r(2)) * 2.0 - 1.0,
                Vec3::new(r(3), r(4), r(5)) * 2.0 - 1.0,
                Vec3::new(r(6), r(7), r(8)) * 2.0 - 1.0,
            ];
            let origin = Vec3::new(r(9), r(10), r(11)) * 8.0 - 4.0;
            let target = Vec3::new(r(12), r(13), r(14)) - 0.5;
            Ray::new(origin, target - origin).ok().map(|ray| (ray, tri))
        })
        .collect();
    let reference: Vec<bool> = pairs
        .iter()
        .map(|(ray, tri)| {
            intersect_f64(
                ray.origin.as_dvec3(),
                ray.dir.as_dvec3(),
                tri.map(|p| p.as_dvec3()),
            )
            .is_some()
        })
        .collect();
    let mut t = Table::new(
        &format!(
            "The three ray-triangle tests on {} random rays (one thread)",
            pairs.len()
        ),
        &["test", "ns per test", "hits", "agree with f64 on hit/miss"],
    );
    for x in Intersector::ALL {
        let mut best = f64::INFINITY;
        let mut hits = Vec::new();
        for _ in 0..3 {
            let t0 = Instant::now();
            hits = pairs
                .iter()
                .map(|(ray, tri)| x.intersect(ray, *tri, 0.0, f32::INFINITY).is_some())
                .collect();
            best = best.min(t0.elapsed().as_secs_f64());
        }
        let agree = hits.iter().zip(&reference).filter(|(a, b)| a == b).count();
        t.row(vec![
            x.name().into(),
            format_number(best / pairs.len().max(1) as f64 * 1e9),
            hits.iter().filter(|h| **h).count().to_string(),
            format!("{agree} of {}", pairs.len()),
        ]);
    }
    t
}
