//! Chapter 4's graders against wrong sphere tracers (each must fail with
//! its symptom) and other right ones (each must pass).

use glam::Vec3;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::grading::exercises::ch4;

/// How the tracers below differ from the book's.
#[derive(Clone, Copy, Default)]
struct Variant {
    /// Never gives up for the budget.
    no_budget: bool,
    /// One evaluation more than the budget (`steps <= max_steps`).
    one_over: bool,
    /// One evaluation fewer (stops when the next one would be the last).
    one_short: bool,
    /// Evaluates f twice per step (once to test, once to step) and counts
    /// steps, not evaluations.
    twice_per_step: bool,
    /// Compares |f| with march.epsilon.
    fixed_epsilon: bool,
    /// Marches on past max_distance.
    no_max_distance: bool,
    /// Returns the gradient as it is, facing the viewer or not.
    no_flip: bool,
    /// Returns the gradient without normalising it.
    unnormalised: bool,
    /// Normalises a zero gradient (NaN).
    no_fallback: bool,
    /// Keeps the point p and moves it by f dir, instead of o + t dir.
    walk_p: bool,
}

/// The lecture's sphere tracer and gradient normal, with the mistakes (or
/// other choices) of `v`.
fn trace(
    v: Variant,
    sdf: &dyn Fn(Vec3) -> f32,
    o: Vec3,
    d: Vec3,
    m: &March,
) -> Option<(f32, Vec3)> {
    let (t, p) = march(v, sdf, o, d, m)?;
    let h = m.epsilon_at(p).max(1e-4);
    let g = Vec3::new(
        sdf(p + Vec3::X * h) - sdf(p - Vec3::X * h),
        sdf(p + Vec3::Y * h) - sdf(p - Vec3::Y * h),
        sdf(p + Vec3::Z * h) - sdf(p - Vec3::Z * h),
    ) / (2.0 * h);
    let n = if v.unnormalised {
        g
    } else if v.no_fallback {
        g.normalize()
    } else {
        g.try_normalize().unwrap_or(-d)
    };
    Some((t, if n.dot(d) > 0.0 && !v.no_flip { -n } else { n }))
}

/// The lecture's loop: the hit's t and point.
fn march(
    v: Variant,
    sdf: &dyn Fn(Vec3) -> f32,
    o: Vec3,
    d: Vec3,
    m: &March,
) -> Option<(f32, Vec3)> {
    let (mut t, mut p) = (0.0f32, o);
    let mut f = sdf(o);
    let mut steps = 1;
    loop {
        if !v.walk_p {
            p = o + t * d;
        }
        let eps = if v.fixed_epsilon {
            m.epsilon
        } else {
            m.epsilon_at(p)
        };
        if f.abs() < eps {
            break;
        }
        if t > m.max_distance && !v.no_max_distance {
            return None;
        }
        let budget = if v.one_over {
            steps > m.max_steps
        } else if v.one_short {
            steps + 1 >= m.max_steps
        } else {
            steps >= m.max_steps
        };
        if budget && !v.no_budget {
            return None;
        }
        if v.twice_per_step {
            let _ = sdf(o + t * d);
        }
        t += f;
        p += f * d;
        f = sdf(if v.walk_p { p } else { o + t * d });
        steps += 1;
    }
    Some((t, p))
}

macro_rules! variant {
    ($name:ident, $($field:ident),*) => {
        fn $name(sdf: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, m: &March) -> Option<(f32, Vec3)> {
            trace(Variant { $($field: true,)* ..Variant::default() }, sdf, o, d, m)
        }
    };
}

variant!(lecture,);
variant!(no_budget, no_budget);
variant!(one_over, one_over);
variant!(one_short, one_short);
variant!(twice_per_step, twice_per_step);
variant!(fixed_epsilon, fixed_epsilon);
variant!(no_max_distance, no_max_distance);
variant!(no_flip, no_flip);
variant!(unnormalised, unnormalised);
variant!(no_fallback, no_fallback);
variant!(walk_p, walk_p);

/// A recursive tracer with its own evaluation count, and the normal by
/// the same central differences: another right one.
fn recursive(sdf: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, m: &March) -> Option<(f32, Vec3)> {
    fn go(
        sdf: &dyn Fn(Vec3) -> f32,
        o: Vec3,
        d: Vec3,
        m: &March,
        t: f32,
        used: u32,
    ) -> Option<f32> {
        let f = sdf(o + t * d);
        if f.abs() < m.epsilon_at(o + t * d) {
            Some(t)
        } else if t > m.max_distance || used + 1 >= m.max_steps {
            None
        } else {
            go(sdf, o, d, m, t + f, used + 1)
        }
    }
    let t = go(sdf, o, d, m, 0.0, 0)?;
    let p = o + t * d;
    let h = m.epsilon_at(p).max(1e-4);
    let axis = |e: Vec3| (sdf(p + e * h) - sdf(p - e * h)) / (2.0 * h);
    let n = Vec3::new(axis(Vec3::X), axis(Vec3::Y), axis(Vec3::Z))
        .try_normalize()
        .unwrap_or(-d);
    Some((t, if n.dot(d) > 0.0 { -n } else { n }))
}

fn fails_with(f: ch4::TraceRayFn, symptom: raystep::grading::Symptom) -> String {
    super::fails_naming(ch4::check_trace_scene(f), symptom, &ch4::exercises(), "")
}

#[test]
fn the_contract_cases_alone_judge_each_tracer() {
    // Quicker than the whole check: the clauses only.
    assert!(ch4::contract_failure(lecture).is_none());
    assert!(ch4::contract_failure(recursive).is_none());
    assert!(ch4::contract_failure(walk_p).is_none());
    for (name, f, symptom) in [
        ("no budget", no_budget as ch4::TraceRayFn, ch4::NO_BUDGET),
        ("one over", one_over, ch4::BUDGET_OFF_BY_ONE),
        ("one short", one_short, ch4::BUDGET_OFF_BY_ONE),
        ("twice per step", twice_per_step, ch4::NO_BUDGET),
        ("fixed ε", fixed_epsilon, ch4::FIXED_EPSILON),
        (
            "no max distance",
            no_max_distance,
            ch4::IGNORES_MAX_DISTANCE,
        ),
        ("no flip", no_flip, ch4::NOT_FACING),
        ("unnormalised", unnormalised, ch4::NOT_UNIT),
        ("no fallback", no_fallback, ch4::ZERO_GRADIENT),
    ] {
        let got = ch4::contract_failure(f);
        assert_eq!(
            got.as_ref().and_then(|g| g.1),
            Some(symptom),
            "{name}: {got:?}"
        );
    }
}

// The capstone's whole check: each wrong tracer fails, naming its
// mistake; each right one passes.

#[test]
fn a_tracer_without_a_step_budget_fails() {
    fails_with(no_budget, ch4::NO_BUDGET);
}

#[test]
fn a_budget_of_one_evaluation_more_fails() {
    let detail = fails_with(one_over, ch4::BUDGET_OFF_BY_ONE);
    assert!(
        detail.contains("max_steps = 5") && detail.contains("a miss after 6"),
        "{detail}"
    );
}

#[test]
fn a_budget_of_one_evaluation_fewer_fails() {
    let detail = fails_with(one_short, ch4::BUDGET_OFF_BY_ONE);
    assert!(detail.contains("max_steps = 14"), "{detail}");
}

#[test]
fn counting_steps_with_two_evaluations_each_fails() {
    fails_with(twice_per_step, ch4::NO_BUDGET);
}

#[test]
fn a_fixed_epsilon_fails() {
    let detail = fails_with(fixed_epsilon, ch4::FIXED_EPSILON);
    assert!(detail.contains("6,000 m"), "{detail}");
}

#[test]
fn marching_past_max_distance_fails() {
    fails_with(no_max_distance, ch4::IGNORES_MAX_DISTANCE);
}

#[test]
fn a_normal_facing_away_fails() {
    fails_with(no_flip, ch4::NOT_FACING);
}

#[test]
fn an_unnormalised_normal_fails() {
    fails_with(unnormalised, ch4::NOT_UNIT);
}

#[test]
fn a_nan_normal_where_the_gradient_is_zero_fails() {
    fails_with(no_fallback, ch4::ZERO_GRADIENT);
}

fn passes(f: ch4::TraceRayFn) {
    let check = ch4::check_trace_scene(f);
    assert!(check.passed(), "{}", check.detail);
    assert_eq!(check.symptom, None);
}

#[test]
fn the_lectures_loop_passes() {
    passes(lecture);
}

#[test]
fn a_recursive_tracer_passes() {
    passes(recursive);
}

#[test]
fn walking_the_point_along_passes() {
    // p += f dir instead of o + t dir: other roundings in the scene, the
    // same steps on the walls.
    passes(walk_p);
}

// Exercise 4.2, the loop alone: the budget and the maximum distance.

macro_rules! loop_variant {
    ($name:ident, $($field:ident),*) => {
        /// The loop of exercise 4.2 (ε as given, not scaled with the
        /// distance from the origin) with the mistakes named.
        fn $name(
            sdf: &dyn Fn(Vec3) -> f32,
            o: Vec3,
            d: Vec3,
            epsilon: f32,
            max_steps: u32,
            max_distance: f32,
        ) -> Option<f32> {
            let m = March { epsilon, max_steps, max_distance, step_factor: 1.0 };
            let v = Variant { fixed_epsilon: true, $($field: true,)* ..Variant::default() };
            march(v, sdf, o, d, &m).map(|(t, _)| t)
        }
    };
}

loop_variant!(loop_lecture,);
loop_variant!(loop_one_over, one_over);
loop_variant!(loop_one_short, one_short);
loop_variant!(loop_no_max_distance, no_max_distance);
loop_variant!(loop_twice_per_step, twice_per_step);

#[test]
fn the_loop_exercise_names_its_budget_and_distance_mistakes() {
    let check = ch4::check_sphere_trace(loop_lecture);
    assert!(check.passed(), "{}", check.detail);
    // A for loop over the budget: another right one.
    let check = ch4::check_sphere_trace(|f, o, d, eps, steps, max| {
        let mut t = 0.0;
        for _ in 0..steps {
            let h = f(o + t * d);
            if h.abs() < eps {
                return Some(t);
            }
            if t > max {
                return None;
            }
            t += h;
        }
        None
    });
    assert!(check.passed(), "{}", check.detail);
    for (name, f, symptom) in [
        (
            "one over",
            loop_one_over as ch4::TraceFn,
            ch4::BUDGET_OFF_BY_ONE,
        ),
        ("one short", loop_one_short, ch4::BUDGET_OFF_BY_ONE),
        (
            "no max distance",
            loop_no_max_distance,
            ch4::IGNORES_MAX_DISTANCE,
        ),
        ("twice per step", loop_twice_per_step, ch4::NO_BUDGET),
    ] {
        let check = ch4::check_sphere_trace(f);
        assert!(!check.passed(), "{name}: {}", check.detail);
        assert_eq!(check.symptom, Some(symptom), "{name}: {}", check.detail);
    }
}

// Exercises 4.1 and 4.3: their common mistakes, named.

#[test]
fn an_unsigned_sphere_distance_fails() {
    let check = ch4::check_sphere_sdf(|p, c, r| ((p - c).length() - r).abs());
    assert!(!check.passed());
    assert_eq!(check.symptom, Some(ch4::UNSIGNED), "{}", check.detail);
}

#[test]
fn a_sphere_at_the_origin_fails() {
    let check = ch4::check_sphere_sdf(|p, _, r| p.length() - r);
    assert!(!check.passed());
    assert_eq!(check.symptom, Some(ch4::CENTRE_IGNORED), "{}", check.detail);
}

#[test]
fn an_unnormalised_gradient_fails() {
    let check = ch4::check_gradient_normal(|f, p, h| {
        let axis = |e: Vec3| (f(p + e * h) - f(p - e * h)) / h;
        Vec3::new(axis(Vec3::X), axis(Vec3::Y), axis(Vec3::Z))
    });
    assert!(!check.passed());
    assert_eq!(check.symptom, Some(ch4::NOT_UNIT), "{}", check.detail);
}
