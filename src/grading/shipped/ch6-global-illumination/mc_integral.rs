//! Exercise 6.1: a Monte Carlo estimator of a 1D integral.
//!
//! Monte Carlo integration: draw points x with a known density p, and
//! average f(x) / p(x). On average that is the integral, whatever p is (as
//! long as it is not 0 where f is not), and the error falls as 1/√N.
//!
//! Contract (what the grader checks):
//! * estimate ∫ₐᵇ f(x) dx from the uniform numbers `u` (each in [0, 1)),
//!   one evaluation of f per number, at a point of [a, b] that is uniform
//!   there when the number is;
//! * unbiased: 64 independent estimates of 1,024 numbers each average to
//!   the integral within 5 standard errors, on five integrals (one zero on
//!   half its interval, one a narrow spike);
//! * with the spread of a plain uniform estimator (within a factor 2 of
//!   σ/√N);
//! * a constant integrates exactly, up to rounding (∫₋₁³ 2.5 dx = 10
//!   from any numbers, within 10⁻⁹).
//!
//! Hints: `cargo grade --hint ch6/mc_integral`.
//! Grade it with: `cargo grade ch6`

/// The Monte Carlo estimate of ∫ₐᵇ f(x) dx from the numbers `u`.
pub fn mc_integral(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    // TODO: the average of f(x) / p(x).
    todo!()
}
