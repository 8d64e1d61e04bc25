//! Error against run time for chapter 1 (requirement 1): the f32
//! projection against exact pixel positions, near and far.

use std::time::Instant;

use glam::{DVec3, Vec3};

use super::camera::Camera;
use crate::core::report::{ErrorTime, Measurement};

/// Points straight ahead at camera-space depth `depth`, one through each
/// cell of a 32x32 grid of pixels, with the pixel positions they must land
/// on (exact, from the construction).
pub(crate) fn points_at_depth(cam: &Camera, depth: f64) -> Vec<(DVec3, glam::DVec2)> {
    let d = &cam.desc;
    let back = (d.eye - d.target).normalize();
    let right = d.up.cross(back).normalize();
    let up = back.cross(right);
    let t = (d.fov_degrees.to_radians() * 0.5).tan();
    let aspect = d.width as f64 / d.height as f64;
    let mut pts = Vec::with_capacity(1024);
    for j in 0..32 {
        for i in 0..32 {
            let raster = glam::DVec2::new(
                (i as f64 + 0.5) / 32.0 * d.width as f64,
                (j as f64 + 0.5) / 32.0 * d.height as f64,
            );
            let u = (raster.x / d.width as f64 * 2.0 - 1.0) * aspect * t;
            let v = (1.0 - raster.y / d.height as f64 * 2.0) * t;
            let world = d.eye + (right * u + up * v - back) * depth;
            pts.push((world, raster));
        }
    }
    pts
}

/// Requirement 1 for chapter 1: the f32 projection against the exact pixel
/// positions, for points from 1e-3 to 1e7 in front of the camera, with the
/// time per batch of 1024 points next to the f64 reference's.
pub fn error_against_time(cam: &Camera) -> ErrorTime {
    let mut et = ErrorTime {
        reference: "exact pixel positions (points built in f64 to land on known pixels)".into(),
        error_name: "max error (px)".into(),
        rows: Vec::new(),
        show_slopes: false,
    };
    for k in -3..=7 {
        let depth = 10f64.powi(k);
        let pts = points_at_depth(cam, depth);
        let world32: Vec<Vec3> = pts.iter().map(|(w, _)| w.as_vec3()).collect();
        let time = |f: &dyn Fn() -> f64| {
            // Best of 5 runs of 20 batches: the least disturbed measurement.
            let mut best = f64::INFINITY;
            let mut err = 0.0;
            for _ in 0..5 {
                let t0 = Instant::now();
                for _ in 0..20 {
                    err = std::hint::black_box(f());
                }
                best = best.min(t0.elapsed().as_secs_f64() / 20.0);
            }
            (best, err)
        };
        let (s32, e32) = time(&|| {
            world32
                .iter()
                .zip(&pts)
                .map(|(w, (_, r))| match cam.project(*w) {
                    Some(p) => (p.as_dvec2() - *r).length(),
                    None => f64::INFINITY,
                })
                .fold(0.0, f64::max)
        });
        let (s64, e64) = time(&|| {
            pts.iter()
                .map(|(w, r)| match cam.project_f64(*w) {
                    Some(p) => (p - *r).length(),
                    None => f64::INFINITY,
                })
                .fold(0.0, f64::max)
        });
        let label = format!("depth 1e{k}");
        et.rows.push(Measurement {
            series: "f32 camera".into(),
            variant: label.clone(),
            seconds: s32,
            samples: pts.len() as u64,
            error: e32,
            notes: String::new(),
        });
        et.rows.push(Measurement {
            series: "f64 reference".into(),
            variant: label,
            seconds: s64,
            samples: pts.len() as u64,
            error: e64,
            notes: String::new(),
        });
    }
    et
}
