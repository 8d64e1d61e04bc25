//! Exercise 6.1, solved: uniform points, density 1/(b − a).

/// The Monte Carlo estimate of ∫ₐᵇ f(x) dx from the numbers `u`.
pub fn mc_integral(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    if u.is_empty() {
        return 0.0;
    }
    let pdf = 1.0 / (b - a);
    let sum: f64 = u.iter().map(|u| f(a + u * (b - a)) / pdf).sum();
    sum / u.len() as f64
}
