//! Chapter 4's exercises and how each is graded.

use glam::{Vec2, Vec3};

use super::images;
use super::worst_of;
use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch4_implicit_surfaces::distance::scene_distance;
use crate::ch4_implicit_surfaces::march::{self, March};
use crate::ch4_implicit_surfaces::normal::{gradient_central, normal, NormalScheme};
use crate::ch4_implicit_surfaces::primitives::{sd_box, sd_sphere, sd_torus};
use crate::core::film::Film;
use crate::grading::exercise::{Check, Exercise};

/// The candidate types.
type SdfFn = fn(Vec3, Vec3, f32) -> f32;
type TraceFn = fn(&dyn Fn(Vec3) -> f32, Vec3, Vec3, f32, u32, f32) -> Option<f32>;
type NormalFn = fn(&dyn Fn(Vec3) -> f32, Vec3, f32) -> Vec3;
/// A distance function borrowed for a check.
type Dist<'a> = &'a dyn Fn(Vec3) -> f32;

/// Chapter 4's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 4,
            name: "sphere_sdf",
            file: "chapters/ch4-sphere-tracing/exercises/sphere_sdf.rs",
            hints: [
                "slide \"signed distance functions\": how far is a point from a sphere's surface, and what sign inside?",
                "the distance to the centre tells you almost everything; the surface is where it equals the radius.",
                "the distance to the centre, |p - center|, minus the radius",
            ],
            symptoms: &[],
            reference: || check_sphere_sdf(|p, c, r| sd_sphere(p - c, r)),
        },
        Exercise {
            chapter: 4,
            name: "sphere_trace",
            file: "chapters/ch4-sphere-tracing/exercises/sphere_trace.rs",
            hints: [
                "slide \"sphere tracing\": no surface is closer than the distance function says, so that distance is a safe step.",
                "count your steps: stop with a hit when the distance is below epsilon, and give up when the budget of steps or the maximum distance is used up.",
                "loop: d = sdf(o + t d); if d < ε return Some(t); t += d; if t > max_distance return None",
            ],
            symptoms: &[],
            reference: || check_sphere_trace(reference_trace),
        },
        Exercise {
            chapter: 4,
            name: "gradient_normal",
            file: "chapters/ch4-sphere-tracing/exercises/gradient_normal.rs",
            hints: [
                "slide \"the normal is the gradient of f\": estimate each partial derivative numerically.",
                "central differences: sample f a little ahead and a little behind along each axis, divide the difference by 2h, and normalise the vector.",
                "(f(p + h e_i) - f(p - h e_i)) / 2h per axis i, then normalize",
            ],
            symptoms: &[],
            reference: || check_gradient_normal(|f, p, h| gradient_central(f, p, h).normalize()),
        },
        Exercise {
            chapter: 4,
            name: "trace_scene",
            file: "chapters/ch4-sphere-tracing/exercises/trace_scene.rs",
            hints: [
                "slides \"sphere tracing\" and \"the normal is the gradient of f\": march with the distance as the step, count your evaluations, then differentiate f where you stopped.",
                "stop with a hit when |f(p)| < march.epsilon_at(p); give up when t > march.max_distance or after march.max_steps evaluations. The normal: central differences with h = max(ε, 1e-4), normalised (fall back to -dir), turned to face the viewer.",
                "t = 0; f0 = sdf(o); repeat at most max_steps times: p = o + t d, if |f| < eps_at(p) hit; if t > max_distance miss; t += f; f = sdf(o + t d). n = normalize(f(p+h x̂)-f(p-h x̂), …); if n·d > 0 { n = -n }",
            ],
            symptoms: &[],
            reference: || check_trace_scene(reference_trace_ray),
        },
    ]
}

/// The capstone's candidate: a camera ray to (t, unit normal facing the
/// viewer), or `None` for a miss.
pub type TraceRayFn = fn(&dyn Fn(Vec3) -> f32, Vec3, Vec3, &March) -> Option<(f32, Vec3)>;

/// raystep's answer to the capstone: chapter 4's sphere tracer and the
/// central-difference gradient.
pub fn reference_trace_ray(
    f: &dyn Fn(Vec3) -> f32,
    o: Vec3,
    d: Vec3,
    m: &March,
) -> Option<(f32, Vec3)> {
    crate::core::guard::reference("ch4/trace_scene");
    let ray = Ray::new(o, d).ok()?;
    let t = march::sphere_trace(f, &ray, m).hit()?;
    let p = ray.at(t);
    let h = m.epsilon_at(p).max(1e-4);
    let n = normal(f, p, h, NormalScheme::Central, -d);
    Some((t, if n.dot(d) > 0.0 { -n } else { n }))
}

/// The capstone: chapter 4's scene of every shape (`sdf-shapes.toml`, at
/// 128 × 96) traced with the candidate, one ray per pixel, compared with
/// the reference in the normal view (n/2 + 1/2) and the depth. Exact but
/// for a few silhouette pixels where rounding decides (0.3 % may differ).
pub fn check_trace_scene(f: TraceRayFn) -> Check {
    use rayon::prelude::*;
    let scene = images::scene("sdf-shapes.toml");
    let camera = Camera::of(&scene)
        .with_resolution(128, 96)
        .expect("a valid camera");
    let objects = &scene.sdfs;
    let sdf = |p: Vec3| scene_distance(objects, p).0;
    let m = March::default();
    let (w, h) = (camera.width, camera.height);
    let ray_at = |x: u32, y: u32| camera.ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
    let render = |g: TraceRayFn| {
        let mut film = Film::new(w, h);
        film.pixels = (0..w * h)
            .into_par_iter()
            .map(|i| {
                let ray = ray_at(i % w, i / w);
                if i % w == 0 {
                    crate::grading::progress(format_args!(
                        "calling trace_scene on the camera rays of row {} of {h}",
                        i / w
                    ));
                }
                match g(&sdf, ray.origin, ray.dir, &m) {
                    Some((_, n)) => n * 0.5 + Vec3::splat(0.5),
                    None => Vec3::ZERO,
                }
            })
            .collect();
        film
    };
    let explain = |x: u32, y: u32| {
        let ray = ray_at(x, y);
        let show = |r: Option<(f32, Vec3)>| match r {
            Some((t, n)) => format!("a hit at t = {t:.4} m, normal {n:.3}"),
            None => "a miss".to_string(),
        };
        format!(
            "the ray from {:.2} along {:.3}: yours found {}, the reference {}",
            ray.origin,
            ray.dir,
            show(f(&sdf, ray.origin, ray.dir, &m)),
            show(reference_trace_ray(&sdf, ray.origin, ray.dir, &m))
        )
    };
    let check = images::compare(
        render(f),
        render(reference_trace_ray),
        0.02,
        3e-3,
        "normal",
        &explain,
    );
    if !check.passed() {
        return check;
    }
    // The depths too: a hit in the right place, not only the right normal.
    let worst = (0..w * h)
        .map(|i| {
            let ray = ray_at(i % w, i / w);
            let a = f(&sdf, ray.origin, ray.dir, &m).map(|r| r.0);
            let b = reference_trace_ray(&sdf, ray.origin, ray.dir, &m).map(|r| r.0);
            match (a, b) {
                (Some(a), Some(b)) => ((a - b).abs() / b.max(1.0)) as f64,
                (None, None) => 0.0,
                _ => 0.0, // counted by the image comparison above
            }
        })
        .fold(
            0.0f64,
            |a, b| if b.is_nan() { f64::INFINITY } else { a.max(b) },
        );
    if worst > 1e-3 {
        return Check {
            error: 1.0,
            detail: format!(
                "the normals match but a hit distance is off by {worst:.2e} (relative)"
            ),
            ..check
        };
    }
    check
}

fn reference_trace(
    f: &dyn Fn(Vec3) -> f32,
    o: Vec3,
    d: Vec3,
    epsilon: f32,
    max_steps: u32,
    max_distance: f32,
) -> Option<f32> {
    let ray = Ray::new(o, d).ok()?;
    let m = March {
        epsilon,
        max_steps,
        max_distance,
        step_factor: 1.0,
    };
    march::sphere_trace(f, &ray, &m).hit()
}

/// The sphere's SDF against values worked out by hand.
pub fn check_sphere_sdf(f: SdfFn) -> Check {
    let c = Vec3::new(1.0, 2.0, 3.0);
    let cases = [
        // Outside, on, and inside; the centre is -radius.
        (Vec3::new(4.0, 6.0, 3.0), c, 2.0, 3.0), // |(3, 4, 0)| = 5
        (Vec3::new(1.0, 2.0, 5.0), c, 2.0, 0.0),
        (Vec3::new(1.5, 2.0, 3.0), c, 2.0, -1.5),
        (c, c, 0.75, -0.75),
        (Vec3::new(0.0, 0.0, -10.0), Vec3::ZERO, 1.0, 9.0),
        (Vec3::new(2.0, 3.0, 6.0), Vec3::new(0.0, 0.0, 0.0), 1.0, 6.0), // |(2, 3, 6)| = 7
    ];
    let (error, detail) = worst_of(cases.into_iter().map(|(p, c, r, want)| {
        let got = f(p, c, r);
        (
            (got - want).abs() as f64,
            format!("p {p}, centre {c}, radius {r}: got {got}, expected {want}"),
        )
    }));
    Check {
        error,
        tolerance: 1e-5,
        detail,
        images: None,
        symptom: None,
    }
}

/// The sphere-tracing loop on a sphere, a box and a torus, against hits
/// worked out by hand and raystep's tracer; and rays that miss.
pub fn check_sphere_trace(f: TraceFn) -> Check {
    let sphere = |p: Vec3| sd_sphere(p, 1.0);
    let boxed = |p: Vec3| sd_box(p - Vec3::new(0.0, 0.0, -3.0), Vec3::splat(0.5));
    let torus = |p: Vec3| sd_torus(p, 2.0, 0.5);
    let eps = 1e-4;
    // (sdf, origin, direction, expected t or None)
    let cases: Vec<(Dist, Vec3, Vec3, Option<f32>)> = vec![
        (&sphere, Vec3::new(0.0, 0.0, 5.0), -Vec3::Z, Some(4.0)),
        (&sphere, Vec3::new(-4.0, 0.6, 0.0), Vec3::X, Some(4.0 - 0.8)),
        (&sphere, Vec3::new(0.0, 2.0, 5.0), -Vec3::Z, None),
        (&boxed, Vec3::ZERO, -Vec3::Z, Some(2.5)),
        (&boxed, Vec3::ZERO, Vec3::Z, None),
        // Down the torus's axis: through the hole, no hit.
        (&torus, Vec3::new(0.0, 5.0, 0.0), -Vec3::Y, None),
        // Along x through the tube: hits its outer side at x = 2.5.
        (&torus, Vec3::new(6.0, 0.0, 0.0), -Vec3::X, Some(3.5)),
    ];
    let (error, detail) = worst_of(cases.into_iter().map(|(sdf, o, d, want)| {
        crate::grading::progress(format_args!(
            "calling sphere_trace on the ray from {o} along {d} (ε = {eps}, 512 steps, max distance 50)"
        ));
        let got = f(sdf, o, d, eps, 512, 50.0);
        let err = match (got, want) {
            (Some(g), Some(w)) => ((g - w).abs() as f64 - eps as f64).max(0.0),
            (None, None) => 0.0,
            _ => f64::INFINITY,
        };
        (
            err,
            format!("ray from {o} along {d}: got {got:?}, expected {want:?}"),
        )
    }));
    // The step budget is respected: a ray passing 5e-5 above the sphere
    // counts as a hit with ε = 1e-4, but not within 3 steps from 40 away
    // (it creeps along the silhouette).
    crate::grading::progress("calling sphere_trace on a grazing ray with a budget of 3 steps");
    let budget = f(
        &sphere,
        Vec3::new(-40.0, 1.00005, 0.0),
        Vec3::X,
        eps,
        3,
        100.0,
    );
    let (error, detail) = if budget.is_some() {
        (
            f64::INFINITY,
            format!("3 steps were enough to find a grazing hit 40 away: {budget:?}"),
        )
    } else {
        (error, detail)
    };
    Check {
        error,
        tolerance: 1e-5,
        detail,
        images: None,
        symptom: None,
    }
}

/// Gradient normals of a sphere, a box face and a torus against their
/// exact normals.
pub fn check_gradient_normal(f: NormalFn) -> Check {
    let sphere = |p: Vec3| sd_sphere(p - Vec3::new(1.0, 0.0, 0.0), 2.0);
    let boxed = |p: Vec3| sd_box(p, Vec3::new(1.0, 2.0, 3.0));
    let torus = |p: Vec3| sd_torus(p, 2.0, 0.5);
    let s = 1.0 / 3f32.sqrt();
    let cases: Vec<(Dist, Vec3, Vec3)> = vec![
        (&sphere, Vec3::new(3.0, 0.0, 0.0), Vec3::X),
        (
            &sphere,
            Vec3::new(1.0, 0.0, 0.0) + Vec3::splat(2.0 * s),
            Vec3::splat(s),
        ),
        (&boxed, Vec3::new(0.2, 2.0, 0.5), Vec3::Y),
        (&boxed, Vec3::new(-1.0, 0.3, -0.4), -Vec3::X),
        (&torus, Vec3::new(0.0, 0.5, 2.0), Vec3::Y),
        (&torus, Vec3::new(-2.5, 0.0, 0.0), -Vec3::X),
    ];
    let (error, detail) = worst_of(cases.into_iter().map(|(sdf, p, want)| {
        let got = f(sdf, p, 1e-3);
        (
            (got - want).length() as f64,
            format!("at {p}: got {got}, expected {want}"),
        )
    }));
    Check {
        error,
        tolerance: 1e-3,
        detail,
        images: None,
        symptom: None,
    }
}
