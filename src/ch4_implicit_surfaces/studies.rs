//! Error against run time: sphere tracing, over-relaxed sphere tracing and
//! the fixed-step march against the analytic hits of a sphere on a plane,
//! as ε, the step budget and the step length vary.

use std::time::Instant;

use glam::{DVec3, Vec3};

use super::render::{march, Method};
use crate::ch1_projection::camera::{Camera, CameraDesc};
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch4_implicit_surfaces::march::{Ending, March};
use crate::ch4_implicit_surfaces::primitives::{sd_plane, sd_sphere};
use crate::core::format::format_number;
use crate::core::report::{ErrorTime, Measurement};

/// The analytic scene: a unit sphere at the origin on the plane y = -1.
pub fn sphere_on_plane(p: Vec3) -> f32 {
    sd_sphere(p, 1.0).min(sd_plane(p, Vec3::Y, -1.0))
}

/// Where the ray first meets the unit sphere at `centre`·`scale` (an
/// ellipsoid with semi-axes `scale`), in f64: the ray is taken into the
/// space where the ellipsoid is the unit sphere, where t is unchanged.
pub fn ray_ellipsoid(o: DVec3, d: DVec3, centre: DVec3, scale: DVec3) -> Option<f64> {
    let (o, d) = ((o - centre) / scale, d / scale);
    let (a, b, c) = (d.dot(d), o.dot(d), o.dot(o) - 1.0);
    let disc = b * b - a * c;
    if disc < 0.0 {
        return None;
    }
    let q = disc.sqrt();
    // Nearest root in front: from outside the smaller, from inside the larger.
    [(-b - q) / a, (-b + q) / a].into_iter().find(|t| *t > 0.0)
}

/// Where the ray meets the plane n·p = h in front of it, in f64 (the
/// lecture's t = (h − n·o)/(n·d)).
pub fn ray_plane(o: DVec3, d: DVec3, n: DVec3, h: f64) -> Option<f64> {
    let nd = n.dot(d);
    let t = (h - n.dot(o)) / nd;
    (nd != 0.0 && t > 0.0 && t.is_finite()).then_some(t)
}

/// The analytic first hit in [`sphere_on_plane`].
pub fn analytic_hit(ray: &Ray) -> Option<f64> {
    let (o, d) = (ray.origin.as_dvec3(), ray.dir.as_dvec3());
    let s = ray_ellipsoid(o, d, DVec3::ZERO, DVec3::ONE);
    let p = ray_plane(o, d, DVec3::Y, -1.0);
    match (s, p) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// The camera of the study: 80x60, looking at the sphere from slightly
/// above so the plane reaches the horizon.
pub fn study_camera() -> Camera {
    Camera::new(CameraDesc {
        eye: DVec3::new(0.0, 0.6, 4.0),
        target: DVec3::new(0.0, -0.2, 0.0),
        up: DVec3::Y,
        fov_degrees: 50.0,
        width: 80,
        height: 60,
    })
    .expect("a valid camera")
}

/// Hit-distance errors of one frame against the analytic hits.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameError {
    /// Root-mean-square |t − t_exact| over the pixels the analytic ray hits.
    pub rmse: f64,
    /// The largest |t − t_exact|.
    pub max: f64,
    /// Pixels compared.
    pub pixels: usize,
    /// Of those, rays that ran out of steps (their error is how far they got short).
    pub budget: usize,
    /// Rays that hit where the analytic ray misses (grazing within ε).
    pub false_hits: usize,
    /// Evaluations of f.
    pub evaluations: u64,
}

/// Traces the study camera's frame with `method` and compares with the
/// analytic hits (pixels whose analytic hit lies beyond the maximum
/// distance are left out).
pub fn frame_error(m: &March, method: Method) -> FrameError {
    let cam = study_camera();
    let mut e = FrameError::default();
    let mut sum = 0.0;
    for y in 0..cam.height {
        for x in 0..cam.width {
            let ray = cam.ray(glam::Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
            let trace = march(&sphere_on_plane, &ray, m, method);
            e.evaluations += trace.steps as u64;
            match analytic_hit(&ray).filter(|t| *t < m.max_distance as f64) {
                Some(exact) => {
                    let got = match trace.ending {
                        Ending::Hit | Ending::Budget => trace.t as f64,
                        Ending::Escaped => m.max_distance as f64,
                    };
                    e.budget += usize::from(trace.ending == Ending::Budget);
                    let err = (got - exact).abs();
                    sum += err * err;
                    e.max = e.max.max(err);
                    e.pixels += 1;
                }
                None => e.false_hits += usize::from(trace.ending == Ending::Hit),
            }
        }
    }
    e.rmse = (sum / e.pixels.max(1) as f64).sqrt();
    e
}

/// The fastest of `runs` timings of `f`, and its last result.
fn best_of<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..runs {
        let t0 = Instant::now();
        out = Some(std::hint::black_box(f()));
        best = best.min(t0.elapsed().as_secs_f64());
    }
    (best, out.expect("runs > 0"))
}

/// The error-against-time table: four series.
// ANCHOR: error_against_time
pub fn error_against_time() -> ErrorTime {
    let mut et = ErrorTime {
        reference: "analytic ray-sphere and ray-plane hits (f64), 80x60 pixels".into(),
        error_name: "RMSE of hit distance".into(),
        rows: Vec::new(),
        show_slopes: true,
    };
    let base = March {
        epsilon: 1e-4,
        max_steps: 512,
        max_distance: 20.0,
        step_factor: 1.0,
    };
    // ANCHOR: error_time_series
    let mut runs: Vec<(String, String, March, Method)> = Vec::new();
    for eps in [1e-1, 1e-2, 1e-3, 1e-4, 1e-5] {
        let m = March {
            epsilon: eps,
            ..base
        };
        let v = format!("ε = {}", format_number(eps as f64));
        runs.push(("sphere tracing, ε".into(), v.clone(), m, Method::Plain));
        runs.push((
            "over-relaxed ω = 1.6, ε".into(),
            v,
            m,
            Method::OverRelaxed(1.6),
        ));
    }
    for budget in [4, 8, 16, 32, 64, 128] {
        let m = March {
            epsilon: 1e-5,
            max_steps: budget,
            ..base
        };
        let v = format!("budget {budget}");
        runs.push(("sphere tracing, budget".into(), v, m, Method::Plain));
    }
    // ANCHOR_END: error_time_series
    // ANCHOR: error_time_measure
    for delta in [0.2f32, 0.1, 0.05, 0.025, 0.0125] {
        let m = March {
            max_steps: (base.max_distance / delta) as u32 + 2,
            ..base
        };
        let v = format!("Δ = {delta}");
        runs.push(("fixed step, Δ".into(), v, m, Method::FixedStep(delta)));
    }
    for (series, variant, m, method) in runs {
        let (seconds, e) = best_of(3, || frame_error(&m, method));
        et.rows.push(Measurement {
            series,
            variant,
            seconds,
            samples: e.evaluations,
            error: e.rmse,
            notes: format!(
                "max {}; {} of {} out of steps; {} false hits",
                format_number(e.max),
                e.budget,
                e.pixels,
                e.false_hits
            ),
        });
    }
    et
}
// ANCHOR_END: error_time_measure
// ANCHOR_END: error_against_time
