//! The capstone, exercise 4.4: chapter 4's scene traced with the
//! student's sphere tracer, then the clauses of [`super::contract`].

use glam::{Vec2, Vec3};

use super::contract::{self, Probe};
use super::images;
use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch4_implicit_surfaces::distance::scene_distance;
use crate::ch4_implicit_surfaces::march::{self, March};
use crate::ch4_implicit_surfaces::normal::{normal, NormalScheme};
use crate::core::film::Film;
use crate::exercise::Check;

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
    // The normals as a picture, and the hits' distances.
    let render = |g: TraceRayFn| {
        let mut film = Film::new(w, h);
        let hits: Vec<Option<(f32, Vec3)>> = (0..w * h)
            .into_par_iter()
            .map(|i| {
                let ray = ray_at(i % w, i / w);
                if i % w == 0 {
                    crate::progress(format_args!(
                        "calling trace_scene on the camera rays of row {} of {h}",
                        i / w
                    ));
                }
                g(&sdf, ray.origin, ray.dir, &m)
            })
            .collect();
        film.pixels = hits
            .iter()
            .map(|hit| match hit {
                Some((_, n)) => *n * 0.5 + Vec3::splat(0.5),
                None => Vec3::ZERO,
            })
            .collect();
        (
            film,
            hits.into_iter().map(|h| h.map(|h| h.0)).collect::<Vec<_>>(),
        )
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
    // The scene's distance function counts nothing: its calls need not
    // cross between the processes (see `bridge::uncounted`).
    let (check, their_t, our_t) = crate::bridge::uncounted(|| {
        let (theirs, their_t) = render(f);
        let (ours, our_t) = crate::bridge::on_grader_pool(|| render(reference_trace_ray));
        let check = images::compare(theirs, ours, 0.02, 3e-3, "normal", &explain);
        (check, their_t, our_t)
    });
    if !check.passed() {
        // A clause below may say what went wrong.
        return match contract_failure(f) {
            Some((detail, Some(symptom))) => Check {
                detail: format!("{}; and {detail}", check.detail),
                ..check
            }
            .with_symptom(symptom),
            _ => check,
        };
    }
    // The depths too: a hit in the right place, not only the right normal.
    let worst = their_t
        .iter()
        .zip(&our_t)
        .map(|(a, b)| {
            match (*a, *b) {
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
    // The clauses a picture cannot show.
    match contract_failure(f) {
        Some((detail, symptom)) => Check {
            error: 1.0,
            detail: format!("the scene matches, but {detail}"),
            symptom,
            ..check
        },
        None => check,
    }
}

/// The first of `contract::cases` where `f` breaks the contract: what
/// happened, and the symptom if it is recognised.
pub fn contract_failure(f: TraceRayFn) -> Option<(String, Option<crate::Symptom>)> {
    contract::cases().into_iter().find_map(|case| {
        crate::progress(format_args!("calling trace_scene on {}", case.what));
        let answer = |g: TraceRayFn| {
            let probe = Probe::new(case.sdf);
            let hit = g(&|p| probe.eval(p), case.origin, case.dir, &case.march);
            (hit, probe.calls.get())
        };
        contract::judge(&case, answer(f), answer(reference_trace_ray), 6)
    })
}
