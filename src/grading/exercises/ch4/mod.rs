//! Chapter 4's exercises and how each is graded.

use glam::Vec3;

use super::draws::{fold_drawn, worst_drawn, Draws};
use super::images;
use crate::cases::{self, v3, V3};
use crate::ch4_implicit_surfaces::normal::gradient_central;
use crate::ch4_implicit_surfaces::primitives::{sd_box, sd_sphere, sd_torus};
use crate::exercise::{Check, Exercise, Symptom};
use crate::exercises::{stateless, worse};

mod clauses;
mod contract;
mod contract_symptoms;
mod eyes;
mod gradient;
mod on_ray;
mod probe;
mod scene;
mod walls;
pub use contract::{
    Case, Clause, Probe, BUDGET_OFF_BY_ONE, FIXED_EPSILON, IGNORES_MAX_DISTANCE, INSIDE_HIT,
    NOT_FACING, NOT_UNIT, NO_BUDGET, ZERO_GRADIENT,
};
use eyes::{beyond_limit, eye_rays, sphere_hit};
pub use gradient::check_gradient_normal;
pub use scene::{check_trace_scene, contract_failure, reference_trace_ray, TraceRayFn};

/// The candidate types.
type SdfFn = fn(Vec3, Vec3, f32) -> f32;
/// A sphere-tracing loop as exercise 4.2 asks for it.
pub type TraceFn = fn(&dyn Fn(Vec3) -> f32, Vec3, Vec3, f32, u32, f32) -> Option<f32>;
pub(super) type NormalFn = fn(&dyn Fn(Vec3) -> f32, Vec3, f32) -> Vec3;

/// Chapter 4's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 4,
            name: "sphere_sdf",
            file: "chapters/ch4-sphere-tracing/exercises/sphere_sdf.rs",
            symptoms: &[UNSIGNED, CENTRE_IGNORED],
            reference: || check_sphere_sdf(|p, c, r| sd_sphere(p - c, r)),
        },
        Exercise {
            chapter: 4,
            name: "sphere_trace",
            file: "chapters/ch4-sphere-tracing/exercises/sphere_trace.rs",
            symptoms: &[
                NO_BUDGET,
                BUDGET_OFF_BY_ONE,
                IGNORES_MAX_DISTANCE,
                INSIDE_HIT,
            ],
            reference: || check_sphere_trace(reference_trace),
        },
        Exercise {
            chapter: 4,
            name: "gradient_normal",
            file: "chapters/ch4-sphere-tracing/exercises/gradient_normal.rs",
            symptoms: &[NOT_UNIT],
            reference: || check_gradient_normal(|f, p, h| gradient_central(f, p, h).normalize()),
        },
        Exercise {
            chapter: 4,
            name: "trace_scene",
            file: "chapters/ch4-sphere-tracing/exercises/trace_scene.rs",
            symptoms: &[
                NO_BUDGET,
                BUDGET_OFF_BY_ONE,
                IGNORES_MAX_DISTANCE,
                FIXED_EPSILON,
                NOT_UNIT,
                NOT_FACING,
                ZERO_GRADIENT,
                INSIDE_HIT,
            ],
            reference: || check_trace_scene(reference_trace_ray),
        },
    ]
}

/// Exercise 4.2's contract, clause by clause: ε as given everywhere (the
/// lesson's march, which scales ε with the distance from the world's
/// origin so that it never stands still, is trace_scene's reference).
fn reference_trace(
    f: &dyn Fn(Vec3) -> f32,
    o: Vec3,
    d: Vec3,
    epsilon: f32,
    max_steps: u32,
    max_distance: f32,
) -> Option<f32> {
    let mut t = 0.0f32;
    for _ in 0..max_steps {
        let v = f(o + t * d);
        if v.abs() < epsilon {
            return Some(t);
        }
        if t > max_distance {
            return None;
        }
        t += v;
    }
    None
}

/// A shape of a hand-worked case (`src/grading/cases.toml`).
#[derive(serde::Deserialize)]
#[serde(rename_all = "lowercase", deny_unknown_fields)]
pub(super) enum Shape {
    /// A sphere.
    Sphere { centre: V3, radius: f32 },
    /// A box, by its half sizes.
    Box { centre: V3, half: V3 },
    /// A torus around the y axis through the origin.
    Torus { major: f32, minor: f32 },
}

impl Shape {
    /// Its signed distance at `p`.
    pub(super) fn distance(&self, p: Vec3) -> f32 {
        match *self {
            Shape::Sphere { centre, radius } => sd_sphere(p - v3(centre), radius),
            Shape::Box { centre, half } => sd_box(p - v3(centre), v3(half)),
            Shape::Torus { major, minor } => sd_torus(p, major, minor),
        }
    }
}

/// A hand-worked value of the sphere's SDF.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct SdfCase {
    p: V3,
    centre: V3,
    radius: f32,
    expect: f32,
}

/// A hand-worked ray for the sphere-tracing loop: `expect` is t, left out
/// for a miss.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct TraceCase {
    sdf: Shape,
    o: V3,
    d: V3,
    expect: Option<f32>,
}

/// The sphere's SDF against values worked out by hand.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_sphere_sdf(f: SdfFn) -> Check {
    stateless::unless_changed(sphere_sdf_values(f), || {
        stateless::probes::sphere_sdf(f, |p, c, r| sd_sphere(p - c, r))
    })
}

/// [`check_sphere_sdf`]'s checks of the values.
fn sphere_sdf_values(f: SdfFn) -> Check {
    let hand = cases::worst("ch4/sphere_sdf", |case: &SdfCase| {
        let (p, c, r, want) = (v3(case.p), v3(case.centre), case.radius, case.expect);
        let got = f(p, c, r);
        (
            (got - want).abs() as f64,
            format!("p {p}, centre {c}, radius {r}: got {got}, expected {want}"),
        )
    });
    let (mut error, mut detail) = match hand {
        Ok(w) => w,
        Err(check) => return check,
    };
    // Drawn spheres from 10⁻³ to 10³ across, up to 10³ times that from the
    // origin, points inside, on and outside: to 10⁻⁵ of the radius and
    // the distance to the centre (what rounding allows).
    // A quarter of them asked at the point asked just before, about
    // another sphere around it (one point, several spheres: a scene's).
    let mut draws = Draws::new(41);
    // From a stream of their own, a tenth of the new centres within 10⁻⁶
    // to 10⁻³ of the origin (near it is not at it).
    let mut near_origin = Draws::new(141);
    let mut last: Option<Vec3> = None;
    // (Thousands of them: the answer after the 2,000th call counts as much
    // as the first.)
    let drawn = worst_drawn((0..draws.count(3000, 5000)).map(|_| {
        draws.next_case();
        near_origin.next_case();
        let r = draws.decades(-3.0, 3.0);
        // A third of the points within 10⁻⁶ to 10⁻² radii of the surface.
        let out = if draws.unit() < 1.0 / 3.0 {
            1.0 + draws.sign() * draws.decades(-6.0, -2.0)
        } else {
            draws.range(0.0, 3.0)
        };
        let (p, c) = match last.filter(|_| draws.unit() < 0.25) {
            Some(p) => (p, p - draws.direction() * r * out),
            None => {
                let placed = draws.place_for(r, 3.0);
                let c = match near_origin.unit() < 0.1 {
                    true => near_origin.direction() * near_origin.decades(-6.0, -3.0),
                    false => placed,
                };
                (c + draws.direction() * r * out, c)
            }
        };
        last = Some(p);
        let to = (p - c).as_dvec3().length();
        let want = to - r as f64;
        let got = f(p, c, r);
        (
            (got as f64 - want).abs() / (r as f64 + to),
            format!("p {p}, centre {c}, radius {r}: got {got}, expected {want}"),
        )
    }));
    fold_drawn(&mut error, &mut detail, drawn);
    // 1.5 inside a sphere of radius 2; 5 from its centre, 3 outside.
    let c = Vec3::new(1.0, 2.0, 3.0);
    let inside = f(Vec3::new(1.5, 2.0, 3.0), c, 2.0);
    let outside = f(Vec3::new(4.0, 6.0, 3.0), c, 2.0);
    let symptom = if error <= 1e-5 {
        None
    } else if (inside - 1.5).abs() < 1e-4 {
        Some(UNSIGNED)
    } else if (outside - (Vec3::new(4.0, 6.0, 3.0).length() - 2.0)).abs() < 1e-4 {
        Some(CENTRE_IGNORED)
    } else {
        None
    };
    Check {
        error,
        tolerance: 1e-5,
        detail,
        images: None,
        symptom,
    }
}

/// |p - c| - r made positive inside.
pub const UNSIGNED: Symptom = Symptom {
    name: "unsigned distance",
};
/// The distance from the origin, not from the centre.
pub const CENTRE_IGNORED: Symptom = Symptom {
    name: "centre ignored",
};

/// The sphere-tracing loop on a sphere, a box and a torus, against hits
/// worked out by hand and raystep's tracer; and rays that miss.
pub fn check_sphere_trace(f: TraceFn) -> Check {
    let sphere = |p: Vec3| sd_sphere(p, 1.0);
    let eps = 1e-4;
    let hand = cases::worst("ch4/sphere_trace", |case: &TraceCase| {
        let sdf = |p: Vec3| case.sdf.distance(p);
        let (o, d, want) = (v3(case.o), v3(case.d), case.expect);
        crate::progress(format_args!(
            "calling sphere_trace on the ray from {o} along {d} (ε = {eps}, 512 steps, max distance 50)"
        ));
        let got = f(&sdf, o, d, eps, 512, 50.0);
        let err = match (got, want) {
            // A hit at t = 0 is the first evaluation's: exactly 0.
            (Some(g), Some(0.0)) => g.abs() as f64,
            (Some(g), Some(w)) => worse((g - w).abs() as f64 - eps as f64, 0.0),
            (None, None) => 0.0,
            _ => f64::INFINITY,
        };
        (
            err,
            format!("ray from {o} along {d}: got {got:?}, expected {want:?}"),
        )
    });
    let (error, detail) = match hand {
        Ok(w) => w,
        Err(check) => return check,
    };
    // Drawn spheres from 10⁻² to 10² across, up to 100 times that from the
    // origin, ε a ten-thousandth of the radius, rays towards them (a hit
    // within 2ε/cos θ of the true one) and away (a miss), max_distance
    // 200 radii or just past the sphere.
    let (mut error, mut detail) = (error, detail);
    let mut draws = Draws::new(43);
    // From a stream of its own, the first and a tenth of the others 10⁵·⁵
    // to 10⁶·⁵ across (hits up to 10⁸ away: no distance is too far for
    // the march).
    let mut huge = Draws::new(243);
    let drawn = worst_drawn((0..draws.count(20, 60)).map(|k| {
        draws.next_case();
        huge.next_case();
        let r = draws.decades(-2.0, 2.0);
        let r = match huge.unit() < 0.1 || k == 0 {
            true => huge.decades(5.5, 6.5),
            false => r,
        };
        // Half of them with max_distance just past the sphere (1.5 times
        // its far side's distance) and the sphere 30 to 100 radii from the
        // world's origin: t, not the distance from the origin, is what
        // max_distance limits.
        let short = draws.unit() < 0.5;
        let centre = match short {
            true => draws.direction() * r * draws.decades(1.5, 2.0),
            false => draws.place_for(r, 2.0),
        };
        let from = draws.direction();
        let origin = centre + from * r * draws.range(1.5, 10.0);
        let towards = (centre + draws.in_cube() * r * 0.5 - origin).normalize();
        let dir = if draws.unit() < 0.2 { -towards } else { towards };
        let eps = r * 1e-4;
        let sdf = move |p: Vec3| (p - centre).length() - r;
        let want = sphere_hit(origin, dir, centre, r, eps);
        let max_distance = match short {
            false => 200.0 * r,
            true => 1.5 * ((origin - centre).length() + r),
        };
        let got = f(&sdf, origin, dir, eps, 4096, max_distance);
        let err = match (got, want) {
            (Some(g), Some((w, slack))) => worse((g as f64 - w).abs() - slack, 0.0) / r as f64,
            (None, None) => 0.0,
            _ => f64::INFINITY,
        };
        (
            err,
            format!(
                "a sphere of radius {r} at {centre}, ray from {origin} along {dir} (ε = {eps}, max_distance = {max_distance}): got {got:?}, expected {:?}",
                want.map(|w| w.0)
            ),
        )
    }));
    fold_drawn(&mut error, &mut detail, drawn);
    fold_drawn(&mut error, &mut detail, eye_rays(f));
    fold_drawn(&mut error, &mut detail, beyond_limit(f));
    fold_drawn(&mut error, &mut detail, on_ray::long_marches(f));
    // Any ε > 0 holds, however small: with ε = 10⁻³⁰ (whose square is 0
    // in f32) the first step from 5 away lands exactly on the unit sphere,
    // where f is 0.
    crate::progress("calling sphere_trace with ε = 1e-30 on a ray that lands on the sphere");
    let exact = f(
        &sphere,
        Vec3::new(0.0, 0.0, 5.0),
        Vec3::NEG_Z,
        1e-30,
        64,
        50.0,
    );
    if exact != Some(4.0) {
        return Check {
            error: f64::INFINITY,
            tolerance: 1e-5,
            detail: format!(
                "ε = 1e-30, the unit sphere straight ahead from (0, 0, 5): the first step lands \
                 on it (f = 0 < ε), a hit at t = 4; got {exact:?}"
            ),
            images: None,
            symptom: None,
        };
    }
    // The step budget is respected: a ray passing 5e-5 above the sphere
    // counts as a hit with ε = 1e-4, but not within 3 steps from 40 away
    // (it creeps along the silhouette).
    crate::progress("calling sphere_trace on a grazing ray with a budget of 3 steps");
    let budget = f(
        &sphere,
        Vec3::new(-40.0, 1.00005, 0.0),
        Vec3::X,
        eps,
        3,
        100.0,
    );
    if budget.is_some() {
        return Check {
            error: f64::INFINITY,
            tolerance: 1e-5,
            detail: format!("3 steps were enough to find a grazing hit 40 away: {budget:?}"),
            images: None,
            symptom: Some(NO_BUDGET),
        };
    }
    // The budget to the evaluation, and the maximum distance: counted.
    let clause = contract::cases().into_iter().find_map(|case| {
        if !matches!(
            case.clause,
            Clause::Budget | Clause::MaxDistance | Clause::Overshoot | Clause::Skim | Clause::Fresh
        ) {
            return None;
        }
        crate::progress(format_args!("calling sphere_trace on {}", case.what));
        let m = case.march;
        let answer = |g: TraceFn| {
            let probe = Probe::new(case.sdf);
            let hit = g(
                &|p| probe.eval(p),
                case.origin,
                case.dir,
                m.epsilon,
                m.max_steps,
                m.max_distance,
            );
            (hit.map(|t| (t, Vec3::Z)), probe.calls.get())
        };
        contract::judge(&case, answer(f), answer(reference_trace), 0)
    });
    match clause {
        Some((_, symptom)) if error > 1e-5 => Check {
            error,
            tolerance: 1e-5,
            detail,
            images: None,
            symptom,
        },
        Some((detail, symptom)) => Check {
            error: f64::INFINITY,
            tolerance: 1e-5,
            detail,
            images: None,
            symptom,
        },
        None => Check {
            error,
            tolerance: 1e-5,
            detail,
            images: None,
            symptom: None,
        },
    }
}
