//! The stiff and extreme cases of chapter 4, each measured against an
//! analytic answer. The report lists them; tests assert them.

use glam::{DVec3, Quat, Vec2, Vec3};

use super::render::{march, Method};
use super::studies::ray_ellipsoid;
use crate::ch1_projection::camera::{Camera, CameraDesc};
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch4_implicit_surfaces::distance::{ScaleBound, Sdf};
use crate::ch4_implicit_surfaces::march::{sphere_trace, Ending, March};
use crate::ch4_implicit_surfaces::normal::{normal, NormalScheme};
use crate::core::format::format_number;
use crate::core::report::StabilityCase;

fn camera(eye: DVec3, target: DVec3, fov: f64, w: u32, h: u32) -> Camera {
    Camera::new(CameraDesc {
        eye,
        target,
        up: DVec3::Y,
        fov_degrees: fov,
        width: w,
        height: h,
    })
    .expect("a valid camera")
}

fn rays(cam: &Camera) -> impl Iterator<Item = Ray> + '_ {
    (0..cam.width * cam.height).map(move |i| {
        let (x, y) = (i % cam.width, i / cam.width);
        cam.ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5))
    })
}

/// Rays grazing a unit sphere: (share of the frame's rays that ran out of
/// a 64-step budget, steps taken by single rays passing 10⁻¹ … 10⁻⁶ above
/// the silhouette).
pub fn grazing() -> (f64, Vec<u32>) {
    let m = March {
        epsilon: 1e-4,
        max_steps: 64,
        max_distance: 20.0,
        step_factor: 1.0,
    };
    let f = |p: Vec3| p.length() - 1.0;
    let cam = camera(DVec3::new(0.0, 0.0, 4.0), DVec3::ZERO, 40.0, 128, 128);
    let (mut out, mut n) = (0usize, 0usize);
    for r in rays(&cam) {
        out += usize::from(sphere_trace(&f, &r, &m).ending == Ending::Budget);
        n += 1;
    }
    let steps = (1..=6)
        .map(|k| {
            let b = 1.0 + 10f32.powi(-k);
            let r = Ray::new(Vec3::new(-5.0, b, 0.0), Vec3::X).expect("unit");
            sphere_trace(
                &f,
                &r,
                &March {
                    max_steps: 10_000,
                    ..m
                },
            )
            .steps
        })
        .collect();
    (out as f64 / n as f64, steps)
}

/// The squeezed ellipsoid of the Lipschitz case: a unit sphere scaled by
/// (2, 0.2, 1).
pub const ELLIPSOID_SCALE: Vec3 = Vec3::new(2.0, 0.2, 1.0);

/// Pixels (of 96x72, seen from above) where sphere tracing the ellipsoid
/// disagrees with the analytic hit: a hole, a false hit, or a hit more
/// than 0.01 off. Returns (wrong pixels, steps that saw f change faster
/// than the ray moved, pixels).
pub fn ellipsoid_wrong_pixels(bound: ScaleBound, step_factor: f32) -> (usize, u64, usize) {
    let sdf = Sdf::ScaleAxes {
        factors: ELLIPSOID_SCALE,
        bound,
        of: Box::new(Sdf::Sphere { radius: 1.0 }),
    };
    let f = |p: Vec3| sdf.eval(p);
    let m = March {
        epsilon: 1e-4,
        max_steps: 2048,
        max_distance: 20.0,
        step_factor,
    };
    let cam = camera(DVec3::new(0.0, 2.0, 3.5), DVec3::ZERO, 50.0, 96, 72);
    let (mut wrong, mut over, mut n) = (0, 0, 0);
    for r in rays(&cam) {
        let trace = sphere_trace(&f, &r, &m);
        let exact = ray_ellipsoid(
            r.origin.as_dvec3(),
            r.dir.as_dvec3(),
            DVec3::ZERO,
            ELLIPSOID_SCALE.as_dvec3(),
        );
        over += (trace.oversteps + trace.lipschitz_violations) as u64;
        n += 1;
        let ok = match (trace.hit(), exact) {
            (Some(t), Some(e)) => (t as f64 - e).abs() < 1e-2,
            (None, None) => true,
            _ => false,
        };
        wrong += usize::from(!ok);
    }
    (wrong, over, n)
}

/// The plate of the thin-feature case: 2 x 1e-4 x 2, tilted 30° about x.
pub fn thin_plate() -> Sdf {
    Sdf::Rotate {
        rotation: Quat::from_rotation_x(30f32.to_radians()),
        of: Box::new(Sdf::Box {
            half_size: Vec3::new(1.0, 0.5e-4, 1.0),
        }),
    }
}

/// A thin plate 1e-4 thick against its analytic hits (slab test in the
/// plate's frame, f64): (wrong pixels of `method`, pixels the plate
/// covers). Wrong: a hole, a false hit, or more than 1e-3 off.
pub fn thin_plate_wrong_pixels(method: Method) -> (usize, usize) {
    let sdf = thin_plate();
    let f = |p: Vec3| sdf.eval(p);
    let m = March {
        epsilon: 1e-5,
        max_steps: 4096,
        max_distance: 10.0,
        step_factor: 1.0,
    };
    let rot = glam::DQuat::from_rotation_x(30f64.to_radians());
    let half = DVec3::new(1.0, 0.5e-4, 1.0);
    let cam = camera(DVec3::new(0.0, 0.0, 3.0), DVec3::ZERO, 50.0, 64, 48);
    let (mut wrong, mut covered) = (0, 0);
    for r in rays(&cam) {
        // Slab test in the plate's own frame.
        let o = rot.inverse() * r.origin.as_dvec3();
        let d = rot.inverse() * r.dir.as_dvec3();
        let t1 = (-half - o) / d;
        let t2 = (half - o) / d;
        let (near, far) = (t1.min(t2).max_element(), t1.max(t2).min_element());
        let exact = (near <= far && near > 0.0).then_some(near);
        covered += usize::from(exact.is_some());
        let trace = march(&f, &r, &m, method);
        let ok = match (trace.hit(), exact) {
            (Some(t), Some(e)) => (t as f64 - e).abs() < 1e-3,
            (None, None) => true,
            _ => false,
        };
        wrong += usize::from(!ok);
    }
    (wrong, covered)
}

/// A unit sphere at (1e5, 0, 0) seen from 4 units away. There the f32
/// spacing is 1/128, so ε grows to [`March::epsilon_at`] ≈ 0.1. Returns
/// (ε used, largest hit error where cos θ > 0.5, rays that ran out of
/// steps, hit/miss disagreements farther than 2ε from the silhouette,
/// rays).
pub fn far_from_origin() -> (f32, f64, usize, usize, usize) {
    let c = Vec3::new(1e5, 0.0, 0.0);
    let f = move |p: Vec3| (p - c).length() - 1.0;
    let m = March {
        epsilon: 1e-4,
        max_steps: 256,
        max_distance: 20.0,
        step_factor: 1.0,
    };
    let eps = m.epsilon_at(c);
    let cam = camera(
        DVec3::new(1e5, 0.0, 4.0),
        DVec3::new(1e5, 0.0, 0.0),
        40.0,
        32,
        32,
    );
    let (mut worst, mut budget, mut disagree, mut n) = (0.0f64, 0, 0, 0);
    for r in rays(&cam) {
        let trace = sphere_trace(&f, &r, &m);
        let (o, d) = (r.origin.as_dvec3(), r.dir.as_dvec3());
        let exact = ray_ellipsoid(o, d, c.as_dvec3(), DVec3::ONE);
        // How far the ray passes from the sphere (negative: through it).
        let rel = o - c.as_dvec3();
        let closest = (rel - d * rel.dot(d)).length() - 1.0;
        budget += usize::from(trace.ending == Ending::Budget);
        n += 1;
        match (trace.hit(), exact) {
            (Some(t), Some(e)) => {
                let normal = (o + d * e - c.as_dvec3()).normalize();
                if normal.dot(d).abs() > 0.5 {
                    worst = worst.max((t as f64 - e).abs());
                }
            }
            (None, None) => {}
            _ => disagree += usize::from(closest.abs() > 2.0 * eps as f64),
        }
    }
    (eps, worst, budget, disagree, n)
}

/// Rays from inside a sphere of radius 10 around the origin, from a
/// camera at (1, 2, 3): (largest |t − t_exact|, rays that knew they
/// started inside, rays).
pub fn camera_inside() -> (f64, usize, usize) {
    let f = |p: Vec3| p.length() - 10.0;
    let m = March::default();
    let cam = camera(DVec3::new(1.0, 2.0, 3.0), DVec3::ZERO, 90.0, 32, 24);
    let (mut worst, mut inside, mut n) = (0.0f64, 0, 0);
    for r in rays(&cam) {
        let trace = sphere_trace(&f, &r, &m);
        let exact = ray_ellipsoid(
            r.origin.as_dvec3(),
            r.dir.as_dvec3(),
            DVec3::ZERO,
            DVec3::splat(10.0),
        );
        inside += usize::from(trace.inside);
        n += 1;
        worst = worst.max(match (trace.hit(), exact) {
            (Some(t), Some(e)) => (t as f64 - e).abs(),
            _ => f64::INFINITY,
        });
    }
    (worst, inside, n)
}

/// The named stiff and extreme cases.
pub fn stability_cases() -> Vec<StabilityCase> {
    let mut cases = Vec::new();
    let mut case = |name: &str, expected: &str, measured: String, ok: bool| {
        cases.push(StabilityCase::new(name, expected, measured, ok))
    };

    let (share, steps) = grazing();
    case(
        "rays grazing a sphere's silhouette (budget 64, ε 1e-4)",
        "at most 1% of the frame runs out of steps; steps grow as the ray passes closer",
        format!(
            "{:.3}% out of steps; steps at 1e-1 … 1e-6 above the silhouette: {steps:?}",
            100.0 * share
        ),
        share <= 0.01 && steps.iter().all(|s| *s < 10_000),
    );

    let (wrong, over, n) = ellipsoid_wrong_pixels(ScaleBound::Max, 1.0);
    let l = ELLIPSOID_SCALE.max_element() / ELLIPSOID_SCALE.min_element();
    let (fixed, over_fixed, _) = ellipsoid_wrong_pixels(ScaleBound::Max, 1.0 / l);
    let (safe, _, _) = ellipsoid_wrong_pixels(ScaleBound::Min, 1.0);
    case(
        "non-1-Lipschitz SDF: sphere scaled (2, 0.2, 1), distance × max scale (L = 10)",
        "overstepping leaves holes and is detected (f falls faster than the ray moves); step factor 1/L fixes them; × min scale is safe",
        format!(
            "{wrong} of {n} pixels wrong, {over} steps detected as unsafe; with step factor 1/{l}: {fixed} wrong ({over_fixed} detections); × min scale: {safe} wrong"
        ),
        wrong > 0 && over > 0 && fixed == 0 && safe == 0,
    );

    let (wrong_st, covered) = thin_plate_wrong_pixels(Method::Plain);
    let (wrong_fixed, _) = thin_plate_wrong_pixels(Method::FixedStep(0.01));
    let (wrong_or, _) = thin_plate_wrong_pixels(Method::OverRelaxed(1.9));
    case(
        "thin plate 1e-4 thick, tilted 30°",
        "sphere tracing and over-relaxed (ω 1.9, with its fallback) find it everywhere; \
         a fixed step of 0.01 steps over it",
        format!(
            "plate covers {covered} pixels; sphere tracing {wrong_st} wrong, over-relaxed {wrong_or} wrong, fixed step {wrong_fixed} wrong"
        ),
        covered > 0 && wrong_st == 0 && wrong_or == 0 && wrong_fixed * 2 > covered,
    );

    let (eps, worst, budget, disagree, n) = far_from_origin();
    case(
        "sphere 1e5 from the origin",
        "every ray ends; ε grows to 8·f32::EPSILON·|p| there (8 to 16 f32 spacings); hits within 2ε where cos θ > 0.5; \
         hit/miss differs only within 2ε of the silhouette",
        format!(
            "ε {}, largest error {}, {budget} of {n} out of steps, {disagree} disagreements away from the silhouette",
            format_number(eps as f64),
            format_number(worst)
        ),
        budget == 0 && worst < 2.0 * eps as f64 && disagree == 0,
    );

    let f = |p: Vec3| p.length() - 1.0;
    let r = Ray::new(Vec3::new(0.3, 0.2, 0.0), Vec3::X).expect("unit");
    let trace = sphere_trace(&f, &r, &March::default());
    // Exit of the unit sphere along +x from (0.3, 0.2, 0): x = √(1 − 0.04).
    let exact = (1.0f64 - 0.04).sqrt() - 0.3;
    case(
        "ray starting inside a unit sphere",
        "one evaluation says inside; the exit is found within ε",
        format!(
            "inside: {}, t = {}, exact {}",
            trace.inside,
            format_number(trace.t as f64),
            format_number(exact)
        ),
        trace.inside && trace.hit().is_some() && (trace.t as f64 - exact).abs() < 1e-3,
    );

    let (worst, inside, n) = camera_inside();
    case(
        "camera inside a sphere of radius 10",
        "every ray starts inside and finds the wall",
        format!(
            "{inside} of {n} inside, largest error {}",
            format_number(worst)
        ),
        inside == n && worst < 1e-3,
    );

    let nrm = normal(&f, Vec3::ZERO, 1e-3, NormalScheme::Central, Vec3::Y);
    case(
        "normal where the gradient vanishes (a sphere's centre)",
        "a finite fallback, not NaN",
        format!("{nrm}"),
        nrm.is_finite() && (nrm.length() - 1.0).abs() < 1e-6,
    );

    let nan_f = |p: Vec3| {
        if p.x > 2.0 {
            f32::NAN
        } else {
            p.length() - 0.5
        }
    };
    let r = Ray::new(Vec3::new(-5.0, 1.0, 0.0), Vec3::X).expect("unit");
    let trace = sphere_trace(&nan_f, &r, &March::default());
    case(
        "distance function that returns NaN",
        "the ray ends as a miss with a finite t",
        format!("{:?} at t = {}", trace.ending, trace.t),
        trace.ending == Ending::Escaped && trace.t.is_finite(),
    );
    cases
}
