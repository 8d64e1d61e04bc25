//! What chapter 4's contract cases are made of ([`super::contract`]):
//! the clause each tests, one ray against one wall, and how a tracer's
//! answer to it is judged.

use glam::Vec3;

use super::contract_symptoms::*;
use crate::ch4_implicit_surfaces::march::March;
use crate::exercise::Symptom;

/// Which clause a case tests.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Clause {
    /// The step budget.
    Budget,
    /// The maximum distance.
    MaxDistance,
    /// The distance-scaled ε.
    ScaledEpsilon,
    /// The normal (unit length, facing the viewer, -dir where flat).
    Normal,
    /// A step that lands inside: a hit is |f| < ε, not f < ε.
    Overshoot,
    /// A curved surface's normal, where the difference step h matters
    /// (h = max(ε at p, 10⁻⁴)): hits agree to a few ε, normals to 0.02.
    Curved,
    /// A ray that skims a surface, f just above ε step after step, on its
    /// way to another: the march goes on while |f| ≥ ε.
    Skim,
    /// A ray marched on its own terms: nothing carried over from the ray
    /// before it, no limit that overflows.
    Fresh,
}

/// One ray against one wall.
#[derive(Clone, Copy, Debug)]
pub struct Case {
    /// What it is, for the message.
    pub what: &'static str,
    /// The clause it tests.
    pub clause: Clause,
    /// The distance function.
    pub sdf: fn(Vec3) -> f32,
    /// The ray.
    pub origin: Vec3,
    /// Its unit direction.
    pub dir: Vec3,
    /// The limits.
    pub march: March,
}

/// A tracer's answer: the hit (t, normal) or a miss, and the evaluations
/// it made.
pub type Answer = (Option<(f32, Vec3)>, u32);

/// How `got` differs from `want` on `case`: `None` when it agrees, else
/// what is wrong and the symptom, if one is recognised. A hit may make
/// `normal_calls` evaluations beyond the budget (6 for the normal of
/// trace_scene, 0 for sphere_trace). t must agree to
/// 1e-5 relative (the walls make every right tracer's steps exact, so
/// this only allows another order of the same arithmetic; the nearest
/// wrong answer, one step more or less, is 6e-5 away), the normal to 1e-3
/// (a wall's gradient comes out the same from every right tracer: along z
/// exactly, or for the far tilted wall from the same six exact points;
/// the nearest wrong one, unnormalised or turned, is 0.5 or 2 away).
pub fn judge(
    case: &Case,
    got: Answer,
    want: Answer,
    normal_calls: u32,
) -> Option<(String, Option<Symptom>)> {
    let m = case.march;
    let show = |(hit, calls): Answer| match hit {
        Some((t, n)) if normal_calls > 0 => {
            format!("a hit at t = {t} with normal {n} after {calls} evaluations")
        }
        Some((t, _)) => format!("a hit at t = {t} after {calls} evaluations"),
        None => format!("a miss after {calls} evaluations"),
    };
    let say = |symptom| {
        Some((
            format!(
                "{} (max_steps = {}, max_distance = {}, ε = {}): yours found {}, the reference {}",
                case.what,
                m.max_steps,
                m.max_distance,
                m.epsilon,
                show(got),
                show(want)
            ),
            symptom,
        ))
    };
    // Evaluations beyond the budget: a hit may add a few for its normal.
    let over = |calls: u32, extra: u32| calls > m.max_steps.saturating_add(extra);
    match (got.0, want.0) {
        (Some(_), None) if case.clause == Clause::MaxDistance => say(Some(IGNORES_MAX_DISTANCE)),
        (Some(_), None) if case.clause == Clause::Budget => {
            let by_one = !over(got.1, 1 + normal_calls);
            say(Some(if by_one { BUDGET_OFF_BY_ONE } else { NO_BUDGET }))
        }
        (None, Some(_)) if case.clause == Clause::Budget => say(Some(BUDGET_OFF_BY_ONE)),
        (None, None) if over(got.1, 1) => say(Some(NO_BUDGET)),
        (None, None) if over(got.1, 0) => say(Some(BUDGET_OFF_BY_ONE)),
        (None, None) => None,
        (Some((t, _)), Some((w, _))) if case.clause == Clause::ScaledEpsilon && t > w => {
            say(Some(FIXED_EPSILON))
        }
        (Some((t, _)), Some((w, _))) if case.clause == Clause::Overshoot && t != w => {
            say(Some(INSIDE_HIT))
        }
        (Some((t, n)), Some((w, wn))) if case.clause == Clause::Curved => {
            // Another order of the same arithmetic may stop elsewhere
            // within ε (and the rounding of f) of the surface: t to 10⁻³,
            // and the normal to 0.02, ten times what the truncation and
            // rounding of a right h can do.
            let same = (t - w).abs() <= 1e-3 * w.abs().max(1.0) && (n - wn).length() <= 0.02;
            (!same || over(got.1, normal_calls))
                .then(|| say(None))
                .flatten()
        }
        (None, Some(_)) if case.clause == Clause::ScaledEpsilon => say(Some(FIXED_EPSILON)),
        (Some((t, n)), Some((w, wn))) => {
            // Written so that a NaN t is not the same t.
            let same_t = (t - w).abs() <= 1e-5 * w.abs().max(1.0);
            if !same_t {
                return say(None);
            }
            if !n.is_finite() {
                return say(Some(ZERO_GRADIENT));
            }
            if (n - wn).length() <= 1e-3 {
                return over(got.1, normal_calls)
                    .then(|| say(Some(NO_BUDGET)))
                    .flatten();
            }
            if (n.length() - 1.0).abs() > 1e-3 {
                say(Some(NOT_UNIT))
            } else if (n + wn).length() <= 1e-3 {
                say(Some(NOT_FACING))
            } else {
                say(None)
            }
        }
        _ => say(None),
    }
}
