//! Chapter 4's graders against wrong sphere tracers (each must fail with
//! its symptom) and other right ones (each must pass).

use glam::Vec3;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch4_implicit_surfaces::march::{self, March};
use raystep::ch4_implicit_surfaces::normal::gradient_central;
use raystep::grading::exercises::ch4;

/// Calls of chapter 4's reference solutions, by exercise, for the guard
/// test (`super::ch3::calling_a_reference_solution_fails`).
pub fn reference_calls() -> Vec<(&'static str, Box<dyn Fn()>)> {
    let sphere = |p: Vec3| p.length() - 1.0;
    let ray = Ray::new(Vec3::Z * 3.0, -Vec3::Z).unwrap();
    vec![
        (
            "ch4/sphere_trace",
            Box::new(move || {
                let _ = march::sphere_trace(&sphere, &ray, &March::default());
            }),
        ),
        (
            "ch4/gradient_normal",
            Box::new(move || {
                let _ = gradient_central(&sphere, Vec3::Z, 1e-3);
            }),
        ),
        (
            "ch4/trace_scene",
            Box::new(move || {
                let _ = ch4::reference_trace_ray(&sphere, ray.origin, ray.dir, &March::default());
            }),
        ),
    ]
}
