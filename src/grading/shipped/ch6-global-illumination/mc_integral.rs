//! Exercise 6.1: a Monte Carlo estimator of a 1D integral.
//!
//! Estimate ∫ₐᵇ f(x) dx from the uniform numbers `u` (each in [0, 1)):
//! map each to a point x in [a, b], evaluate f there, and average
//! f(x) / p(x), where p is the density of x.
//!
//! Grade it with: `cargo run --release --bin grade -- ch6`

/// The Monte Carlo estimate of ∫ₐᵇ f(x) dx from the numbers `u`.
pub fn mc_integral(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    // TODO: x = a + u·(b - a) is uniform on [a, b]: what is its density p(x)?
    // TODO: return the mean of f(x) / p(x) over all the numbers.
    todo!()
}
