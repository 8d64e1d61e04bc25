//! Marching along a ray r(t) = o + t d until f changes sign.
//!
//! * [`fixed_step`]: the lecture's first idea, a constant step Δ. Simple,
//!   but it steps over anything thinner than Δ and wastes steps in empty
//!   space.
//! * [`sphere_trace`]: step by f itself. If f never exceeds the distance
//!   to the surface, a ball of radius |f| around the current point holds
//!   no surface, so stepping |f| along the ray cannot cross it.
//! * [`over_relaxed`]: step ω·f (ω > 1), and fall back to the safe step
//!   when the ball of the new point and the ball of the old one no longer
//!   overlap, which is the sign that the long step may have crossed the
//!   surface.
//!
//! All three start with one evaluation at the origin: its sign says
//! whether the ray starts inside, and they then march on s·f with
//! s = sign(f(o)), so a ray from inside finds the way out.

use glam::Vec3;

use crate::ch3_ray_triangle::ray::Ray;

/// When to stop marching.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct March {
    /// A point with |f| < ε counts as on the surface.
    pub epsilon: f32,
    /// At most this many evaluations of f (the step budget).
    pub max_steps: u32,
    /// Give up beyond this t.
    pub max_distance: f32,
    /// Multiply every step by this (≤ 1 makes up for an f that
    /// overestimates: use 1/L for an f with ‖∇f‖ ≤ L).
    pub step_factor: f32,
}

impl Default for March {
    fn default() -> Self {
        March {
            epsilon: 1e-4,
            max_steps: 256,
            max_distance: 100.0,
            step_factor: 1.0,
        }
    }
}

impl March {
    /// These settings for a scene `unit` times the size they were chosen
    /// for ([`length_unit`](super::bounds::length_unit)): ε
    /// and the distance marched scale with it.
    pub fn scaled(self, unit: f32) -> March {
        March {
            epsilon: self.epsilon * unit,
            max_distance: self.max_distance * unit,
            ..self
        }
    }

    /// The ε used at `p`: the requested ε, or a few f32 spacings of p's
    /// coordinates when those are coarser (far from the origin a point
    /// cannot get closer to the surface than its own rounding).
    pub fn epsilon_at(&self, p: Vec3) -> f32 {
        self.epsilon.max(8.0 * f32::EPSILON * p.abs().max_element())
    }
}

/// How a march ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ending {
    /// |f| < ε: on the surface.
    Hit,
    /// t went past the maximum distance.
    Escaped,
    /// The step budget ran out first.
    Budget,
}

/// The result of one march.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trace {
    /// How it ended.
    pub ending: Ending,
    /// Where it stopped (the hit distance for a hit).
    pub t: f32,
    /// Evaluations of f, the one at the origin included.
    pub steps: u32,
    /// Whether the origin was inside (f(o) < 0): one evaluation tells.
    pub inside: bool,
    /// Steps that crossed the surface (the sign of f flipped): an f that
    /// overestimates, or an over-relaxed step that went too far.
    pub oversteps: u32,
    /// Steps over which f changed by more than the step length: evidence
    /// that f is not 1-Lipschitz, so its steps are not safe. (A step that
    /// jumps clean through a thin part flips no sign; this still sees it
    /// coming, since f falls faster than the ray moves.)
    pub lipschitz_violations: u32,
    /// f at the stopping point (the residual surface distance of a hit).
    pub residual: f32,
}

impl Trace {
    /// The hit distance, if it hit.
    pub fn hit(&self) -> Option<f32> {
        (self.ending == Ending::Hit).then_some(self.t)
    }
}

impl Trace {
    /// The start of every march: one evaluation at the ray's origin says
    /// whether it starts inside (f < 0). Returns the trace so far, the sign
    /// s that makes s·f positive on the ray's side, and f at the origin.
    fn start(f: &dyn Fn(Vec3) -> f32, ray: &Ray) -> (Trace, f32, f32) {
        let f0 = f(ray.origin);
        let trace = Trace {
            ending: Ending::Budget,
            t: 0.0,
            steps: 1,
            inside: f0 < 0.0,
            oversteps: 0,
            lipschitz_violations: 0,
            residual: f0,
        };
        (trace, if f0 < 0.0 { -1.0 } else { 1.0 }, f0)
    }
}

/// Sphere tracing: step by the distance bound until it is below ε.
// ANCHOR: sphere_trace
// ANCHOR: sphere_trace_stop
pub fn sphere_trace(f: &dyn Fn(Vec3) -> f32, ray: &Ray, m: &March) -> Trace {
    // One evaluation at the origin tells inside from outside.
    let (mut trace, s, f0) = Trace::start(f, ray);
    let mut d = s * f0; // distance bound, positive on the ray's side
    loop {
        let p = ray.at(trace.t);
        if d.abs() < m.epsilon_at(p) {
            trace.ending = Ending::Hit;
            break;
        }
        if !d.is_finite() || trace.t > m.max_distance {
            trace.ending = Ending::Escaped;
            break;
        }
        if trace.steps >= m.max_steps {
            break; // out of budget
        }
        // ANCHOR_END: sphere_trace_stop
        // ANCHOR: sphere_trace_step
        // A ball of radius d around p holds no surface: step d (or back,
        // if the last step crossed it and d is negative).
        let t_before = trace.t;
        trace.t = (trace.t + d * m.step_factor).max(0.0);
        let next = s * f(ray.at(trace.t));
        trace.steps += 1;
        if next < 0.0 && d > 0.0 {
            trace.oversteps += 1;
        }
        // A 1-Lipschitz f cannot change faster than the ray moves.
        let moved = trace.t - t_before;
        if (next - d).abs() > 1.001 * moved.abs() + m.epsilon_at(p) {
            trace.lipschitz_violations += 1;
        }
        d = next;
        trace.residual = s * d;
    }
    trace
}
// ANCHOR_END: sphere_trace_step
// ANCHOR_END: sphere_trace

/// Over-relaxed sphere tracing (after Keinert et al. 2014): step ω·d, and
/// when the unbounding balls of two consecutive points stop overlapping
/// (d_prev + d < step), go back, take the safe step, and continue with
/// ω = 1.
// ANCHOR: over_relaxed
// ANCHOR: over_relaxed_back
pub fn over_relaxed(f: &dyn Fn(Vec3) -> f32, ray: &Ray, m: &March, omega: f32) -> Trace {
    let (mut trace, s, f0) = Trace::start(f, ray);
    let mut omega = omega.max(1.0);
    let (mut d, mut t_prev, mut d_prev) = (s * f0, 0.0f32, 0.0f32);
    loop {
        let p = ray.at(trace.t);
        let step = trace.t - t_prev;
        if omega > 1.0 && trace.steps > 1 && d_prev + d.abs() < step {
            // The balls do not overlap: the long step may have jumped over
            // the surface. Back to the previous point, safe step from there.
            trace.oversteps += 1;
            omega = 1.0;
            trace.t = t_prev + d_prev * m.step_factor;
            d = s * f(ray.at(trace.t));
            trace.steps += 1;
            trace.residual = s * d;
            t_prev = trace.t;
            d_prev = d.abs();
            continue;
        }
        // ANCHOR_END: over_relaxed_back
        // ANCHOR: over_relaxed_step
        if d.abs() < m.epsilon_at(p) {
            trace.ending = Ending::Hit;
            break;
        }
        if !d.is_finite() || trace.t > m.max_distance {
            trace.ending = Ending::Escaped;
            break;
        }
        if trace.steps >= m.max_steps {
            break;
        }
        t_prev = trace.t;
        d_prev = d.max(0.0);
        trace.t += omega * d * m.step_factor;
        d = s * f(ray.at(trace.t));
        trace.steps += 1;
        trace.residual = s * d;
    }
    trace
}
// ANCHOR_END: over_relaxed_step
// ANCHOR_END: over_relaxed

/// The naive march: constant steps Δ until f changes sign, then the zero
/// between the last two samples by linear interpolation.
// ANCHOR: fixed_step
pub fn fixed_step(f: &dyn Fn(Vec3) -> f32, ray: &Ray, delta: f32, m: &March) -> Trace {
    let (mut trace, s, f0) = Trace::start(f, ray);
    let mut d = s * f0;
    while trace.steps < m.max_steps {
        let t_next = trace.t + delta;
        if t_next > m.max_distance || !d.is_finite() {
            trace.ending = Ending::Escaped;
            return trace;
        }
        let d_next = s * f(ray.at(t_next));
        trace.steps += 1;
        if d_next <= 0.0 {
            // The sign changed between t and t + Δ: interpolate the zero.
            let w = if d - d_next > 0.0 {
                d / (d - d_next)
            } else {
                0.0
            };
            trace.t += w.clamp(0.0, 1.0) * delta;
            trace.ending = Ending::Hit;
            trace.residual = f(ray.at(trace.t));
            return trace;
        }
        trace.t = t_next;
        d = d_next;
        trace.residual = s * d;
    }
    trace
}
// ANCHOR_END: fixed_step
