//! The report's two studies: anti-aliasing error against run time (exact
//! coverage as the reference), and the stiff and extreme cases.

use std::time::Instant;

use glam::{DVec2, DVec3};

use super::coverage::rasterize;
use super::edge::from_fixed;
use super::exact::coverage_image;
use super::setup::{raster_triangle, ScreenTriangle};
use crate::ch1_projection::camera::{Camera, CameraDesc};
use crate::core::report::{ErrorTime, Measurement};

/// The study's test pattern: a star of `spokes` thin triangles around a
/// centre off the pixel grid, in a `size` x `size` image. The triangles do
/// not overlap, so exact coverage is a sum of areas.
pub fn star(size: u32, spokes: u32) -> Vec<ScreenTriangle> {
    let c = DVec2::new(size as f64 * 0.503, size as f64 * 0.497);
    let r = size as f64 * 0.47;
    let sectors = 2 * spokes;
    (0..spokes)
        .flat_map(|k| {
            let angle = |s: u32| std::f64::consts::TAU * (s as f64 + 0.13) / sectors as f64;
            let (a0, a1) = (angle(2 * k), angle(2 * k + 1));
            let p = |a: f64| c + r * DVec2::new(a.cos(), a.sin());
            raster_triangle([c, p(a0), p(a1)], k, size, size)
        })
        .collect()
}

/// Requirement 1 for chapter 2: RMSE of the per-pixel coverage against the
/// exact covered area, with the time per frame, for 1, 4, 16 and 64
/// stratified samples (and uniform jitter at 2, 8, 32 to compare).
pub fn error_against_time(seed: u64) -> ErrorTime {
    let size = 128;
    let tris = star(size, 24);
    // The reference uses the snapped vertices, so only sampling differs.
    let exact_tris: Vec<[DVec2; 3]> = tris.iter().map(|t| t.v.map(from_fixed)).collect();
    let exact = coverage_image(&exact_tris, size, size);
    let mut et = ErrorTime {
        reference: "exact area of each pixel covered by a 24-spoke star of triangles (polygon clipping in f64), 128x128".into(),
        error_name: "RMSE of coverage".into(),
        rows: Vec::new(),
        show_slopes: true,
    };
    let runs = [
        ("stratified", [1u32, 4, 16, 64].as_slice()),
        ("uniform jitter", [2u32, 8, 32].as_slice()),
    ];
    for (series, spps) in runs {
        for &spp in spps {
            let mut best = f64::INFINITY;
            let mut coverage = Vec::new();
            for _ in 0..3 {
                let t0 = Instant::now();
                let buf = rasterize(&tris, size, 0..size, spp, seed);
                coverage = buf.coverage();
                best = best.min(t0.elapsed().as_secs_f64());
            }
            let mse = coverage
                .iter()
                .zip(&exact)
                .map(|(a, b)| (a - b) * (a - b))
                .sum::<f64>()
                / exact.len() as f64;
            et.rows.push(Measurement {
                series: series.into(),
                variant: format!("{spp} spp"),
                seconds: best,
                samples: (size * size * spp) as u64,
                error: mse.sqrt(),
                notes: String::new(),
            });
        }
    }
    et
}

/// A small test camera at the origin looking down -z.
pub fn test_camera(width: u32, height: u32) -> Camera {
    Camera::new(CameraDesc {
        eye: DVec3::ZERO,
        target: DVec3::new(0.0, 0.0, -1.0),
        up: DVec3::Y,
        fov_degrees: 60.0,
        width,
        height,
    })
    .expect("a valid camera")
}

/// A fan of triangles around an off-grid point whose outer vertices walk
/// the border of a `w` x `h` screen: it tiles the screen exactly.
pub fn screen_fan(w: u32, h: u32) -> Vec<ScreenTriangle> {
    let (wf, hf) = (w as f64, h as f64);
    let mut border = Vec::new();
    for k in 0..10 {
        let t = k as f64 / 10.0 + 0.031 * (k % 3) as f64;
        border.push(DVec2::new(t * wf, 0.0));
    }
    for k in 0..8 {
        border.push(DVec2::new(
            wf,
            (k as f64 / 8.0 + 0.017 * (k % 2) as f64) * hf,
        ));
    }
    for k in 0..10 {
        border.push(DVec2::new(
            (1.0 - k as f64 / 10.0 - 0.023 * (k % 2) as f64) * wf,
            hf,
        ));
    }
    for k in 0..8 {
        border.push(DVec2::new(0.0, (1.0 - k as f64 / 8.0) * hf));
    }
    let c = DVec2::new(wf * 0.3713, hf * 0.5871);
    (0..border.len())
        .flat_map(|k| {
            raster_triangle(
                [c, border[k], border[(k + 1) % border.len()]],
                k as u32,
                w,
                h,
            )
        })
        .collect()
}

/// A grid of `nx` x `ny` cells over the screen, two triangles per cell,
/// inner vertices jittered off the pixel grid and diagonals alternating.
pub fn screen_grid(w: u32, h: u32, nx: u32, ny: u32) -> Vec<ScreenTriangle> {
    let vertex = |i: u32, j: u32| {
        let jitter = |k: u32, n: u32| {
            if k == 0 || k == n {
                0.0
            } else {
                (crate::core::sampling::random(7, (j * 1000 + i) as u64, k as u64, n as u64) as f64
                    - 0.5)
                    * 0.6
            }
        };
        DVec2::new(
            (i as f64 + jitter(i, nx)) * w as f64 / nx as f64,
            (j as f64 + jitter(j, ny)) * h as f64 / ny as f64,
        )
    };
    let mut tris = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            let (a, b, c, d) = (
                vertex(i, j),
                vertex(i + 1, j),
                vertex(i + 1, j + 1),
                vertex(i, j + 1),
            );
            let id = 2 * (j * nx + i);
            let pair = if (i + j) % 2 == 0 {
                [[a, b, c], [a, c, d]]
            } else {
                [[a, b, d], [b, c, d]]
            };
            tris.extend(raster_triangle(pair[0], id, w, h));
            tris.extend(raster_triangle(pair[1], id + 1, w, h));
        }
    }
    tris
}
