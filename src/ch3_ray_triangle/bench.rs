//! Chapter 3's benchmark (`ch3 --bench`): BVH build time and ray
//! throughput (Mrays/s) for coherent (primary) and incoherent (random)
//! rays, closest hit and occlusion, on 1 and 2 threads, for raystep's stage,
//! for obvhs alone and (closest hit only) for the readable BVH. It prints a table; nothing here is a test.
//! `ch3 --bench bunny` (or `wavy`, or a triangle count such as `100000`)
//! keeps only the matching meshes.

use std::time::Instant;

use glam::{DVec3, Vec3};
use rayon::prelude::*;

use crate::ch1_projection::camera::{Camera, CameraDesc};
use crate::ch3_ray_triangle::leaks::bunny;
use crate::ch3_ray_triangle::obvhs_bvh::{Bvh, ObvhsAlone, Triangles};
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::readable_bvh::ReadableBvh;
use crate::ch3_ray_triangle::studies::procedural_mesh;
use crate::ch3_ray_triangle::triangle::{intersect_watertight, Intersector};
use crate::core::format::{format_number, format_seconds};
use crate::core::report::Table;
use crate::core::sampling::random;
use crate::scene::mesh::Mesh;

/// A camera that frames `mesh` from +z.
fn framing_camera(mesh: &Mesh, width: u32, height: u32) -> Camera {
    let (lo, hi) = mesh.positions.iter().fold(
        (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let centre = ((lo + hi) * 0.5).as_dvec3();
    let size = (hi - lo).length() as f64;
    Camera::new(CameraDesc {
        eye: centre + DVec3::new(0.2, 0.5, 1.4) * size,
        target: centre,
        up: DVec3::Y,
        fov_degrees: 40.0,
        width,
        height,
    })
    .expect("a valid camera")
}

/// Primary rays of `camera`, one per pixel centre.
fn primary_rays(camera: &Camera) -> Vec<Ray> {
    (0..camera.height)
        .flat_map(|y| {
            (0..camera.width)
                .map(move |x| camera.ray(glam::Vec2::new(x as f32 + 0.5, y as f32 + 0.5)))
        })
        .collect()
}

/// Rays from random points in the mesh's bounding box in random directions.
fn random_rays(mesh: &Mesh, n: u64) -> Vec<Ray> {
    let (lo, hi) = mesh.positions.iter().fold(
        (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    (0..n)
        .filter_map(|i| {
            let r = |d| random(1, i, 0, d);
            let o = lo + (hi - lo) * Vec3::new(r(0), r(1), r(2));
            let d = Vec3::new(r(3), r(4), r(5)) * 2.0 - 1.0;
            Ray::new(o, d).ok()
        })
        .collect()
}

/// Rounds of the throughput measurement: each query variant is timed once per round,
/// in turn, and its best round counts.
pub const ROUNDS: usize = 5;

/// A ray query to time: returns whether the ray hit (or was occluded).
type Query<'a> = &'a (dyn Fn(&Ray) -> bool + Sync);

/// Mrays/s of each of `queries` over `rays`, and how many rays each
/// counted. The variants take turns, [`ROUNDS`] times, and each keeps its
/// best time: on a machine shared with other work, a burst of load then
/// slows one round of every variant rather than all rounds of one.
fn throughput(rays: &[Ray], queries: &[Query]) -> Vec<(f64, usize)> {
    let mut best = vec![f64::INFINITY; queries.len()];
    let mut counts = vec![0; queries.len()];
    for _ in 0..ROUNDS {
        for (i, f) in queries.iter().enumerate() {
            let t0 = Instant::now();
            counts[i] = rays
                .par_chunks(256)
                .map(|c| c.iter().filter(|r| f(r)).count())
                .sum();
            best[i] = best[i].min(t0.elapsed().as_secs_f64());
        }
    }
    best.iter()
        .zip(counts)
        .map(|(t, n)| (rays.len() as f64 / t / 1e6, n))
        .collect()
}

/// Runs the benchmark and returns its table; `only` keeps the meshes whose
/// name contains it or whose triangle count it is (`ch3 --bench bunny`,
/// `ch3 --bench 100000`).
pub fn benchmark(only: Option<&str>) -> Table {
    let mut t = Table::new(
        &format!(
            "ch3 benchmark: Mrays/s (best of {ROUNDS}, variants interleaved); \
             stage = raystep's BVH with the fast watertight test"
        ),
        &[
            "mesh",
            "triangles",
            "build (stage / obvhs / readable)",
            "threads",
            "rays",
            "query",
            "stage",
            "stage, readable watertight",
            "stage, Möller–Trumbore",
            "obvhs alone",
            "readable BVH",
            "stage / obvhs",
        ],
    );
    let meshes = [
        bunny(),
        procedural_mesh(100_000),
        procedural_mesh(1_000_000),
    ];
    // A filter matches part of a mesh's name, or its exact triangle count.
    let wanted =
        |m: &Mesh| only.is_none_or(|o| m.name.contains(o) || m.triangles.len().to_string() == o);
    for mesh in meshes.into_iter().filter(wanted) {
        let tris = Triangles::from_meshes(std::slice::from_ref(&mesh));
        let bvh = Bvh::build(&tris.tris).expect("non-empty");
        let t0 = Instant::now();
        let alone = ObvhsAlone::build(&tris.tris);
        let alone_build = t0.elapsed().as_secs_f64();
        let t0 = Instant::now();
        let readable = ReadableBvh::build(&tris.tris);
        let readable_build = t0.elapsed().as_secs_f64();
        let batches = [
            ("primary", primary_rays(&framing_camera(&mesh, 640, 480))),
            ("random", random_rays(&mesh, 300_000)),
        ];
        let inf = f32::INFINITY;
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a thread pool");
            for (kind, rays) in &batches {
                for query in ["closest", "occlusion"] {
                    let r = pool.install(|| {
                        if query == "closest" {
                            throughput(
                                rays,
                                &[
                                    &|r| bvh.closest(r, inf, Intersector::Watertight).is_some(),
                                    &|r| bvh.closest_with(r, inf, intersect_watertight).is_some(),
                                    &|r| bvh.closest(r, inf, Intersector::MollerTrumbore).is_some(),
                                    &|r| alone.closest_t(r) < inf,
                                    &|r| readable.closest(r, inf).is_some(),
                                ],
                            )
                        } else {
                            throughput(
                                rays,
                                &[
                                    &|r| bvh.occluded(r, inf, Intersector::Watertight),
                                    &|r| bvh.occluded_with(r, inf, intersect_watertight),
                                    &|r| bvh.occluded(r, inf, Intersector::MollerTrumbore),
                                    &|r| alone.occluded(r, inf),
                                ],
                            )
                        }
                    });
                    t.row(vec![
                        mesh.name.clone(),
                        tris.tris.len().to_string(),
                        format!(
                            "{} / {} / {}",
                            format_seconds(bvh.build_seconds),
                            format_seconds(alone_build),
                            format_seconds(readable_build)
                        ),
                        threads.to_string(),
                        format!("{kind} ({})", rays.len()),
                        format!("{query} ({} hit)", r[0].1),
                        format_number(r[0].0),
                        format_number(r[1].0),
                        format_number(r[2].0),
                        format_number(r[3].0),
                        // The readable BVH has no occlusion query of its own.
                        r.get(4).map_or("-".into(), |q| format_number(q.0)),
                        format_number(r[0].0 / r[3].0),
                    ]);
                }
            }
        }
    }
    t
}
