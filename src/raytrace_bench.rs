//! Chapter 3's benchmark (`ch3 --bench`): BVH build time and ray
//! throughput (Mrays/s) for coherent (primary) and incoherent (random)
//! rays, closest hit and occlusion, on 1 and 2 threads, for raystep's stage
//! and for obvhs alone. It prints a table; nothing here is a test.

use std::time::Instant;

use glam::{DVec3, Vec3};
use rayon::prelude::*;

use crate::bvh::{Bvh, ObvhsAlone, Triangles};
use crate::camera::{Camera, CameraDesc};
use crate::mesh::Mesh;
use crate::ray::Ray;
use crate::raytrace_studies::{bunny, procedural_mesh};
use crate::report::{format_number, format_seconds, Table};
use crate::sampling::random;
use crate::triangle::Intersector;

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

/// Mrays/s of `f` over `rays` (best of 3), and how many rays it counted.
fn throughput(rays: &[Ray], f: &(dyn Fn(&Ray) -> bool + Sync)) -> (f64, usize) {
    let mut best = f64::INFINITY;
    let mut count = 0;
    for _ in 0..3 {
        let t0 = Instant::now();
        count = rays
            .par_chunks(256)
            .map(|c| c.iter().filter(|r| f(r)).count())
            .sum();
        best = best.min(t0.elapsed().as_secs_f64());
    }
    (rays.len() as f64 / best / 1e6, count)
}

/// Runs the benchmark and returns its table.
pub fn benchmark() -> Table {
    let mut t = Table::new(
        "ch3 benchmark: Mrays/s (best of 3), stage = raystep's BVH wrapper with the watertight test",
        &[
            "mesh",
            "triangles",
            "build (stage / obvhs)",
            "threads",
            "rays",
            "query",
            "stage",
            "stage, Möller–Trumbore",
            "obvhs alone",
            "stage / obvhs",
        ],
    );
    let meshes = [
        bunny(),
        procedural_mesh(100_000),
        procedural_mesh(1_000_000),
    ];
    for mesh in meshes {
        let tris = Triangles::from_meshes(std::slice::from_ref(&mesh));
        let bvh = Bvh::build(&tris.tris).expect("non-empty");
        let t0 = Instant::now();
        let alone = ObvhsAlone::build(&tris.tris);
        let alone_build = t0.elapsed().as_secs_f64();
        let batches = [
            ("primary", primary_rays(&framing_camera(&mesh, 640, 480))),
            ("random", random_rays(&mesh, 300_000)),
        ];
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a thread pool");
            for (kind, rays) in &batches {
                for query in ["closest", "occlusion"] {
                    let (stage, mt, obv) = pool.install(|| {
                        if query == "closest" {
                            let s = throughput(rays, &|r| {
                                bvh.closest(r, f32::INFINITY, Intersector::Watertight)
                                    .is_some()
                            });
                            let m = throughput(rays, &|r| {
                                bvh.closest(r, f32::INFINITY, Intersector::MollerTrumbore)
                                    .is_some()
                            });
                            let o = throughput(rays, &|r| alone.closest_t(r) < f32::INFINITY);
                            (s, m, o)
                        } else {
                            let s = throughput(rays, &|r| {
                                bvh.occluded(r, f32::INFINITY, Intersector::Watertight)
                            });
                            let m = throughput(rays, &|r| {
                                bvh.occluded(r, f32::INFINITY, Intersector::MollerTrumbore)
                            });
                            let o = throughput(rays, &|r| alone.occluded(r, f32::INFINITY));
                            (s, m, o)
                        }
                    });
                    t.row(vec![
                        mesh.name.clone(),
                        tris.tris.len().to_string(),
                        format!(
                            "{} / {}",
                            format_seconds(bvh.build_seconds),
                            format_seconds(alone_build)
                        ),
                        threads.to_string(),
                        format!("{kind} ({})", rays.len()),
                        format!("{query} ({} hit)", stage.1),
                        format_number(stage.0),
                        format_number(mt.0),
                        format_number(obv.0),
                        format!("{}", format_number(stage.0 / obv.0)),
                    ]);
                }
            }
        }
    }
    t
}
