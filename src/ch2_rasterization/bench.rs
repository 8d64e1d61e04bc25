//! The speed benchmark (`cargo run --release --bin ch2 -- --bench`): not a
//! test, a table of triangles/s and pixels/s to compare between commits.

use std::time::Instant;

use glam::Vec3;

use super::frame::render_frame;
use super::studies::test_camera;
use crate::core::error::{Error, Result};
use crate::core::format::{format_number, format_seconds};
use crate::core::report::Table;
use crate::scene::mesh::Mesh;
use crate::scene::{Material, Scene};

/// A wavy grid of about `triangles` triangles filling the view of
/// [`test_camera`] at depth 3.
pub fn procedural_mesh(triangles: usize) -> Mesh {
    let n = ((triangles as f64 / 2.0).sqrt().ceil() as u32).max(1);
    let (nx, ny) = (n, (triangles as u32 / 2).div_ceil(n));
    let mut positions = Vec::with_capacity(((nx + 1) * (ny + 1)) as usize);
    for j in 0..=ny {
        for i in 0..=nx {
            let (u, v) = (i as f32 / nx as f32, j as f32 / ny as f32);
            let (x, y) = (-3.4 + 6.8 * u, -2.0 + 4.0 * v);
            positions.push(Vec3::new(
                x,
                y,
                -3.0 + 0.2 * (7.0 * x).sin() * (5.0 * y).cos(),
            ));
        }
    }
    let mut tris = Vec::with_capacity((2 * nx * ny) as usize);
    let at = |i: u32, j: u32| j * (nx + 1) + i;
    for j in 0..ny {
        for i in 0..nx {
            tris.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            tris.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    Mesh::new("grid", positions, tris)
}

/// Renders the bunny scene (if given) and a procedural mesh of about 1M
/// triangles at 1920x1080, 1 spp, on each thread count; best of 3 frames.
pub fn run_bench(bunny: Option<Scene>, threads: &[usize], triangles: usize) -> Result<Table> {
    let (w, h) = (1920, 1080);
    let mut cases: Vec<(
        String,
        crate::ch1_projection::camera::Camera,
        Vec<Mesh>,
        Vec<Material>,
    )> = Vec::new();
    if let Some(scene) = bunny {
        let scene = scene.with_resolution(w, h)?;
        cases.push((
            scene.name.clone(),
            crate::ch1_projection::camera::Camera::new(scene.camera)?,
            scene.meshes,
            scene.materials,
        ));
    }
    cases.push((
        "procedural grid".into(),
        test_camera(w, h),
        vec![procedural_mesh(triangles)],
        vec![Material::default_grey()],
    ));
    let mut t = Table::new(
        "ch2 benchmark: setup + coverage + depth test + resolve, best of 3 frames",
        &[
            "scene",
            "triangles",
            "resolution",
            "spp",
            "threads",
            "time",
            "Mtriangles/s",
            "Mpixels/s",
            "covered samples",
        ],
    );
    for (name, cam, meshes, materials) in &cases {
        let tri_count: usize = meshes.iter().map(|m| m.triangles.len()).sum();
        for &n in threads {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| Error::Usage(format!("thread pool of {n}: {e}")))?;
            let mut best = f64::INFINITY;
            let mut covered = 0;
            for _ in 0..3 {
                let t0 = Instant::now();
                let frame = pool.install(|| render_frame(cam, meshes, materials, 1, 0, false))?;
                best = best.min(t0.elapsed().as_secs_f64());
                covered = frame
                    .buffer
                    .samples
                    .iter()
                    .filter(|s| s.is_covered())
                    .count();
            }
            t.row(vec![
                name.clone(),
                tri_count.to_string(),
                format!("{w}x{h}"),
                "1".into(),
                n.to_string(),
                format_seconds(best),
                format_number(tri_count as f64 / best / 1e6),
                format_number((w * h) as f64 / best / 1e6),
                covered.to_string(),
            ]);
        }
    }
    Ok(t)
}
